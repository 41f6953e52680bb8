10 REM A FOR loop that runs zero times leaves the variable one STEP past its start in GW-BASIC
20 FOR I = 10 TO 1: PRINT "never": NEXT I
30 PRINT I
40 FOR J = 3 TO -0.5 STEP 1.5
50 PRINT "never"
60 NEXT J
70 PRINT J
