10 REM the items before a failing item are printed (GW-BASIC evaluates and prints item by item)
20 PRINT "a"; SQR(-1)
