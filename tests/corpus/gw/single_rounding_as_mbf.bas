10 REM singles round as GW-BASIC's MBF routines round, not as IEEE's nearest
12 REM 825157.625 prints 825157.6: MATH2.ASM $FOTNV times 10 by $FMULS (a tie, to even), $FOTCV adds .5.
14 REM PC-BASIC 2.0.8 rounds its guard byte first and prints 825157.7: the source decides.
20 PRINT 3452.1 * .044498; 477.3032 * 1489569!
30 PRINT 9517 - 1.726; 586428! - 664.58
40 A = 825056!: B = 101.6: PRINT A + B
50 ON ERROR GOTO 100
60 PRINT -32768 \ -1
70 END
100 PRINT "ERR"; ERR; ERL: RESUME NEXT
