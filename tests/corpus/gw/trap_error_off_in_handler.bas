10 REM issue 12: ON ERROR GOTO 0 in a handler stops with the pending error
20 ON ERROR GOTO 100
30 PRINT "a";
40 X=1/0: PRINT "after"
50 PRINT "fifty"
60 END
100 PRINT "h";ERR;ERL
110 ON ERROR GOTO 0
120 PRINT "not here"
