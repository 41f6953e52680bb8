10 REM Rugg/Feldman benchmark 7: benchmark 6 with an array store in the inner loop
20 PRINT "S"
30 K=0
40 DIM M(5)
50 K=K+1
60 LET A=K/2*3+4-5
70 GOSUB 1000
80 FOR L=1 TO 5
90 M(L)=A
100 NEXT L
110 IF K<1000 THEN 50
120 PRINT "E";K;A;M(5)
130 END
1000 RETURN
