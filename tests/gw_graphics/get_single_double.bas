10 REM GET into single and double arrays keeps the pixels' bytes; PUT, MKS$, MKD$, PRINT of them
20 SCREEN 1: PSET (0,0),3: PSET (2,0),2: PSET (1,1),1: PSET (3,1),3
30 DIM A(10), D#(5): GET (0,0)-(3,1), A: GET (0,0)-(3,1), D#
40 PUT (10,10), A: PUT (20,20), D#
50 FOR Y = 0 TO 1: FOR X = 0 TO 3: PRINT POINT(10+X,10+Y); POINT(20+X,20+Y);: NEXT: NEXT: PRINT
60 FOR K = 0 TO 1: B$ = MKS$(A(K)): FOR I = 1 TO 4: PRINT ASC(MID$(B$,I,1));: NEXT: PRINT A(K): NEXT
70 B$ = MKD$(D#(0)): FOR I = 1 TO 8: PRINT ASC(MID$(B$,I,1));: NEXT: PRINT D#(0)
80 C = A(1): B$ = MKS$(C): PRINT ASC(B$); C; C + 1; MKS$(C + 0) = MKS$(0)
90 E = CVS(CHR$(1) + CHR$(2) + CHR$(131) + CHR$(0)): B$ = MKS$(E): PRINT E; ASC(B$); ASC(MID$(B$,3)); -E
100 F# = CVD(STRING$(7, 5) + CHR$(0)): B$ = MKD$(F#): PRINT F#; ASC(B$); ASC(MID$(B$,7))
