10 REM A FOR loop that runs zero times leaves the variable at its start: GW-BASIC's source
15 REM (NEXT86.ASM, NEXTS with NXTFLG=0) decides; PC-BASIC 2.0.8 prints 11 and 4.5 (.pcbasic)
20 FOR I = 10 TO 1: PRINT "never": NEXT I
30 PRINT I
40 FOR J = 3 TO -0.5 STEP 1.5
50 PRINT "never"
60 NEXT J
70 PRINT J
