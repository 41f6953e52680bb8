"""GW-BASIC reads a statement left to right and checks what it has read before it finds the
junk after it: the statement's good start runs, its own checks come first, then the Syntax
error (GWMAIN.ASM NEWSTT finds no statement's end).

- NOT where an operand stands after any operator (``13*NOT 7``, ``10^NOT 0``) takes what
  follows as far as a NOT at the start would (GWEVAL.ASM EVAL); casio keeps its Syntax error.
- OPTION BASE: the base it already is is no error, another after one has run (since the run
  or a CLEAR) is Duplicate Definition; ``OPTION BASE 1 X`` sets the base, then Syntax error
  (GWMAIN.ASM OPTION, BIMISC.ASM CLEARC).  A real GW-BASIC 3.23 counts an OPTION BASE of the
  base it already is as one that ran (PC-BASIC's recorded OPTION test; PC-BASIC 2.0.8 agrees).
- SWAP exchanges, DATE$ = checks its date, before the junk after them.
- PRINT prints an item before it finds that what follows is no item (``(1)%2``, ``LEFT $(``:
  LEFT is a variable there), but not an item an operator goes on with (``1 +``).
- NAME finds its old file before it reads AS (File not found, then a new name of another
  drive Rename across disks: GIODSK.ASM NAME); KEY reads its number (GETBYT) before its comma,
  KEY (n) ON/OFF/STOP is a key's trapping and ``KEY (n), s`` Syntax error (GWSTS.ASM KEYS,
  KEYSTT); a key beyond 1..10 given two characters is no error (recorded on a real GW-BASIC
  3.23 in PC-BASIC's KEY tests); WRITE # needs its comma.
- A function call whose arguments do not fit is read argument by argument, each checked
  before the ``,`` or ``)`` after it is looked for (BISTRS.ASM INSTR, STRNG$; GWEVAL.ASM
  ISFUN for LEFT$, RIGHT$, MID$; PARCHK for a function of one argument): ``INSTR(-1)``
  Illegal function call, ``LEFT$(1)`` Syntax error, ``INSTR(1, 2, 3, 4)`` Type mismatch.
- A call or an expression the text cuts short evaluates what it read first, in order:
  ``PRINT "A"; INSTR(-1`` prints A, then Illegal function call; ``X = 5 + LEFT$(1`` is Syntax
  error, not Type mismatch; a DEF FN body ``FNA(X) + PRINT`` calls FNA (Undefined user
  function) before its Missing operand.

Each case against PC-BASIC 2.0.8, which agrees with the recordings here."""

import pytest

from test_gw_files import both_runs, yaseer_run

HANDLER = '100 PRINT "E"; ERR; ERL: RESUME NEXT\n'

PROGRAMS = [
    '20 PRINT 13*NOT 7; 10^NOT 0; 1=NOT 1; 13-NOT 7+1; 13 MOD NOT 7; 13\\NOT 7; 2^NOT 1*3; -2*NOT 0\n',
    '20 OPTION BASE 0\n30 OPTION BASE 1\n40 CLEAR: ON ERROR GOTO 100\n50 OPTION BASE 1: OPTION BASE 1: PRINT "S"\n'
    '60 OPTION BASE 0\n70 CLEAR: ON ERROR GOTO 100: OPTION BASE 1 X\n80 OPTION BASE 0: PRINT "X"\n',
    '20 DIM A(3): OPTION BASE 0: PRINT "S"\n30 OPTION BASE 1\n',
    '20 A=1: B=2: C=3: SWAP A, B, C\n30 PRINT A; B; C\n40 SWAP A, B$,\n50 SWAP A, B X\n60 PRINT A; B; C\n',
    '20 DATE$ = "10" X\n30 DATE$ = "01-02-2003" X\n',
    '20 PRINT (1)%2\n30 PRINT "A"; LEFT $("AB", 1)\n40 PRINT 1; 2 LPRINT\n50 PRINT 1 +\n60 PRINT "B" 3 X\n',
    '20 PRINT INSTR(-1)\n30 PRINT INSTR(1)\n40 PRINT INSTR(0, "A", "B")\n50 PRINT INSTR(300)\n60 PRINT INSTR(40000)\n'
    '70 PRINT INSTR(1, 1)\n80 PRINT INSTR(1, 2, 3, 4)\n90 PRINT INSTR("A", "B", "C")\n95 PRINT INSTR("AB", 1)\n',
    '20 PRINT STRING$(-1)\n30 PRINT STRING$("A")\n40 PRINT STRING$(1, #2)\n50 PRINT STRING$(2, 3, 4)\n'
    '60 PRINT LEFT$(1)\n70 PRINT LEFT$(1, 1)\n80 PRINT LEFT$("A", "B")\n90 PRINT MID$("ABC", 0)\n'
    '95 PRINT MID$("ABC", 1, "A")\n96 PRINT RIGHT$("A", 1, 1)\n97 PRINT SIN(1, 2); CHR$("A")\n',
    '20 PRINT "A"; INSTR(-1\n30 PRINT "B"; STRING$("X"\n40 PRINT "C"; MID$("ABC", 1, "A"\n'
    '50 PRINT "D"; MID$("ABC", "A"\n60 X = 5 + LEFT$(1\n70 PRINT "E"; INSTR(\n80 PRINT "F"; LEFT$("AB", 1 X\n'
    '90 X = LEFT$(1\n95 PRINT "H"; FNZ(1) +\n',
    '20 DEF FNB(X) = FNA(X) + PRINT\n30 PRINT "A"; FNB(1)\n40 DEF FNA(X) = X: PRINT "B"; FNB(1)\n'
    '50 DEF FNC(X) = INSTR(-1\n60 PRINT "C"; FNC(1)\n',
    '15 OPEN "AF" FOR OUTPUT AS 1: CLOSE 1\n20 NAME "NOPE"\n30 NAME "NOPE" "B"\n40 NAME "NOPE" AS B\n'
    '50 NAME "AF" "B"\n60 NAME "AF" AS B\n70 NAME "AF" AS "BF" X\n80 NAME "AF" AS "CF"\n90 NAME "BF" AS "Z:DF"\n',
    '20 KEY A$\n30 KEY 1, "as": KEY 15, "as": KEY 15, "asdf"\n40 KEY (1) ON: KEY (1) OFF: KEY (1) STOP: PRINT "T"\n'
    '50 KEY (2), "x"\n60 KEY 1+1 STOP\n70 KEY 1, 2,\n80 KEY (1) STOP X\n90 KEY 255, "12": KEY 255, "1"\n'
    '95 KEY 300, "12"\n',
    '20 OPEN "O" FOR OUTPUT AS 1\n30 WRITE #1\n40 WRITE #1, 1\n'
    '50 CLOSE: OPEN "O" FOR INPUT AS 1: LINE INPUT #1, A$: PRINT A$\n',
]


# casio keeps its Syntax errors: the whole statement, the items before it printed
CASIO = [('10 PRINT 13*NOT 7\n', "Syntax error in 10\n"), ('10 PRINT -NOT 0; 1 AND NOT 0\n', " 1  1 \n"),
         ('10 PRINT "A"; LEFT$(1)\n', "A\nSyntax error in 10\n"),
         ('10 PRINT "A"; MID$("AB", 1, 2, 3)\n', "A\nSyntax error in 10\n")]


@pytest.mark.parametrize("program, casio", [(p, None) for p in PROGRAMS] + CASIO)
def test_a_statement_checks_what_it_read_before_the_junk_after_it(tmp_path, program, casio):
    if casio is not None:
        assert yaseer_run(program, tmp_path, "casio") == casio
        return
    source = '10 ON ERROR GOTO 100\n' + program + '99 END\n' + HANDLER
    ours, theirs, our_files, their_files = both_runs(source, tmp_path)
    assert (ours, our_files) == (theirs, their_files)
