10 REM David Ahl's benchmark (Creative Computing, November 1983): square roots
20 REM and squares that should cancel, and a sum of random numbers
30 FOR N=1 TO 100: A=N
40 FOR I=1 TO 10
50 A=SQR(A): R=R+RND(1)
60 NEXT I
70 FOR I=1 TO 10
80 A=A^2: R=R+RND(1)
90 NEXT I
100 S=S+A: NEXT N
110 PRINT ABS(1010-S/5)
120 PRINT ABS(1000-R)
130 END
