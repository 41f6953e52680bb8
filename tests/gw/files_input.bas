10 OPEN "O", 1, "N.TXT": PRINT #1, "abc,12x,3 4, &H10,1D2,"; CHR$(34); "q,r"; CHR$(34); " tail,last": CLOSE
20 OPEN "I", 1, "N.TXT": INPUT #1, A, B, C, D, E, F, G$, H$: PRINT A; B; C; D; E; F; G$; "|"; H$
30 CLOSE
