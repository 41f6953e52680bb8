10 REM RIGHT$ with a count beyond the string's length (yaseer cut the string: "bc")
20 A$ = "abc"
30 PRINT RIGHT$(A$, 5); "|"; RIGHT$(A$, 3); "|"; RIGHT$(A$, 4); "|"; RIGHT$("", 2); "|"; RIGHT$(A$, 0); "|"
