10 REM issue 12: a line that does not parse is its own statement under RESUME NEXT
20 ON ERROR GOTO 100
30 X=SQR(-1)
40 PRINT ABS(
50 PRINT "fifty": Y=1/0: PRINT "after"
60 PRINT 1+*2: PRINT "skipped"
70 PRINT "seventy"
80 END
100 PRINT ERR;ERL: RESUME NEXT
