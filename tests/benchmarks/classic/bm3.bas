10 REM Rugg/Feldman benchmark 3: benchmark 2 plus arithmetic on variables only
20 PRINT "S"
30 K=0
40 K=K+1
50 LET A=K/K*K+K-K
60 IF K<1000 THEN 40
70 PRINT "E";K;A
80 END
