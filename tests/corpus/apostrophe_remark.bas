10 REM an apostrophe remark straight after a statement (no colon)
20 X = 1 ' set X
30 PRINT X ' show it
