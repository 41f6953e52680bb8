10 REM issue 12: RESUME outside a handler stops the run even when errors are trapped
20 ON ERROR GOTO 100
30 PRINT "a"
40 RESUME
50 PRINT "x"
100 PRINT "h";ERR;ERL: END
