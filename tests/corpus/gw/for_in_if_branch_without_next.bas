10 REM A FOR inside an IF branch with no NEXT after it: FOR without NEXT when it runs
20 PRINT "START"
30 IF 1 THEN FOR I = 1 TO 3: PRINT I;
40 PRINT "X"
