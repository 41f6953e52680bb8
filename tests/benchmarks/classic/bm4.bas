10 REM Rugg/Feldman benchmark 4: benchmark 3 with numeric constants in the expression
20 PRINT "S"
30 K=0
40 K=K+1
50 LET A=K/2*3+4-5
60 IF K<1000 THEN 40
70 PRINT "E";K;A
80 END
