10 REM an error inside the handler is not trapped again
20 ON ERROR GOTO 100
30 X=1/0
40 END
100 PRINT "h";ERR;ERL: ERROR 300
