10 REM David Ahl's benchmark with one statement per line (the form bwbasic runs)
20 FOR N=1 TO 100
30 A=N
40 FOR I=1 TO 10
50 A=SQR(A)
60 R=R+RND(1)
70 NEXT I
80 FOR I=1 TO 10
90 A=A^2
100 R=R+RND(1)
110 NEXT I
120 S=S+A
130 NEXT N
140 PRINT ABS(1010-S/5)
150 PRINT ABS(1000-R)
160 END
