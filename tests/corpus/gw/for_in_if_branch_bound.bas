10 REM A FOR inside an IF branch is bound to the NEXT its scan finds, as at top level
20 IF 1 THEN FOR K = 1 TO 2: FOR J = 1 TO 2: PRINT K * J;: NEXT J, K: PRINT "R"
30 IF 0 THEN PRINT 1 ELSE FOR L = 1 TO 2: PRINT L;
40 NEXT: PRINT "Q"
50 IF 1 THEN FOR I = 1 TO 3: PRINT I;: IF I = 2 THEN GOTO 80
60 NEXT I
70 END
80 NEXT I: PRINT "Y"
