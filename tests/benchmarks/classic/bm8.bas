10 REM Benchmark 8 (J. Coll, Personal Computer World 1978): power, logarithm and sine
20 PRINT "S"
30 K=0
40 K=K+1
50 A=K^2
60 B=LOG(K)
70 C=SIN(K)
80 IF K<1000 THEN 40
90 PRINT "E";K;A;B;C
100 END
