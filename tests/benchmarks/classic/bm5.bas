10 REM Rugg/Feldman benchmark 5: benchmark 4 plus a call of an empty subroutine
20 PRINT "S"
30 K=0
40 K=K+1
50 LET A=K/2*3+4-5
60 GOSUB 1000
70 IF K<1000 THEN 40
80 PRINT "E";K;A
90 END
1000 RETURN
