10 REM Rugg/Feldman benchmark 2: a counting loop made of IF ... THEN and a line number
20 PRINT "S"
30 K=0
40 K=K+1
50 IF K<1000 THEN 40
60 PRINT "E";K
70 END
