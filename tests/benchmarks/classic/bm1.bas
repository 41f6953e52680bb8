10 REM Rugg/Feldman benchmark 1 (Kilobaud, June 1977): an empty FOR-NEXT loop
20 PRINT "S"
30 FOR K=1 TO 1000
40 NEXT K
50 PRINT "E";K
60 END
