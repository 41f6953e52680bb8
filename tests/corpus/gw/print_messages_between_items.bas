10 REM Overflow and Division by zero messages are printed where each PRINT item is evaluated,
12 REM after the commas before it have moved the cursor
20 A = 1E+38: B# = 1D+38: Z = 0
30 PRINT B# * 10, B# * 100; A * 1000
40 PRINT 1, A * A; 2
50 PRINT "X"; A * -10; "Y"; 1 / Z; "W"
60 PRINT , A * 10
70 PRINT TAB(5); A * 10; TAB(40); -1 / Z; SPC(3); B# * 10
80 PRINT 12345678, -B# * 10, B# * B#, 3
90 PRINT "Q", A * 10;
100 PRINT "END"
