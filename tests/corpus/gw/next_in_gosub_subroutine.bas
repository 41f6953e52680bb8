10 REM A NEXT in a subroutine GOSUB called from the loop body: GW-BASIC's source decides.
12 REM NEXT86.ASM NEXT calls FNDFOR (GWMAIN.ASM), which skips WHILE entries but stops at
14 REM the GOSUB entry above the FOR: NEXT without FOR. PC-BASIC 2.0.8 continues the loop.
20 FOR I = 1 TO 3
30 PRINT I;
40 GOSUB 100
50 PRINT "BACK"
60 END
100 NEXT I
110 PRINT "AFTER"
120 RETURN
