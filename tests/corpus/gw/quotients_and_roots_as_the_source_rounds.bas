10 REM / and SQR give the nearest single: MATH1.ASM $FDIVS rounds with a sticky bit
20 REM from the remainder, $SQR computes 24 bits and a rounding bit (PC-BASIC differs)
30 PRINT 1 / 3.8377; 84286! / .524
40 PRINT SQR(2); SQR(10); SQR(15)
