10 REM Typed numbers: once misread by yaseer's gw dialect (tests/test_differential_gw_types.py)
20 ON ERROR GOTO 900
30 PRINT -32768% * 0%; -32768% XOR 27149%
40 PRINT -90095.2872; 1.23456789; 1D-5; 1E-5
50 DEFDBL W: W = 40.51: PRINT W; W * 2
60 DEFSTR V: V = "S": PRINT V; V * 2
70 A% = 200: B% = 200: PRINT A% * B%; 32767 + 1
80 A% = 32767: A% = A% + 1
90 PRINT CINT(2.5); CINT(-2.5); 7 \ 2; -7 MOD 2; 5 EQV 3
100 END
900 PRINT "E"; ERR; ERL: RESUME NEXT
