10 REM the file's column: CR resets it, control codes do not move it, it counts in a byte
20 OPEN "O", 1, "COLS.TXT"
30 PRINT #1, "A"; CHR$(13); "B"; CHR$(10); "C"; CHR$(8); "D"; CHR$(0); "E"; CHR$(28); TAB(12); "T"
40 PRINT #1, STRING$(250, "x"); "yyyyyyyyyy"; TAB(5); "Z"
50 PRINT #1, STRING$(250, "x"); "yyyyyyyyyy", "Q"
60 REM WIDTH #n: an item that does not fit starts a new line; nothing breaks a line
70 WIDTH #1, 10
80 PRINT #1, "ABCDEFGH"; "IJKL"; 123; "MN", "OP"
90 PRINT #1, "ABCDEFGHIJKLMNO"; "P"
100 PRINT #1, "AB"; TAB(15); "Q"; SPC(12); "R"
110 PRINT #1, 1; 2; 3; 4; 5
120 PRINT #1, "ABCDEFGHIJ"; "X"
130 WRITE #1, "ABCDEFGH", 12345
140 CLOSE 1
150 OPEN "I", 1, "COLS.TXT": PRINT LOF(1): CLOSE 1
180 ON ERROR GOTO 220
190 WIDTH #1, 10
200 OPEN "O", 2, "W.TXT": WIDTH #2, 300
210 END
220 PRINT "ERROR"; ERR; ERL: RESUME NEXT
