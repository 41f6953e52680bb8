10 REM issue 12: text after a quoted DATA item is a Syntax error in the DATA line
20 READ A$, B$: PRINT A$; "|"; B$
30 READ C$: PRINT C$
40 READ D$: PRINT D$
50 DATA "one", "two" , "three"x
60 DATA "four"
