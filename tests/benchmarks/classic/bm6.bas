10 REM Rugg/Feldman benchmark 6: benchmark 5 plus an empty inner loop of five passes
20 PRINT "S"
30 K=0
40 DIM M(5)
50 K=K+1
60 LET A=K/2*3+4-5
70 GOSUB 1000
80 FOR L=1 TO 5
90 NEXT L
100 IF K<1000 THEN 50
110 PRINT "E";K;A
120 END
1000 RETURN
