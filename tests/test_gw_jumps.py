"""GW-BASIC's jumps as the real machine runs them: which NEXT steps a loop, what GOSUB, ON x
GOTO/GOSUB, RETURN and RESTORE check before what follows them is read.

* A FOR keeps the place of the NEXT its scan found (GWMAIN.ASM FOR, NXTSCN); a NEXT
  elsewhere, named or not, is ``NEXT without FOR`` (NEXT86.ASM NEXTC compares the text
  pointers), as the recordings of PC-BASIC's test suite show (a loop whose scan finds a
  NEXT inside an IF branch and whose body jumps past it).
  A bad NEXT is read as far as its names go (NEXT86.ASM: one name at a time, LOOPDN
  reads the comma); an unowned ELSE's remark still holds text the scan reads (NXTSCN takes
  the word after ELSE as a statement's start).
* WHILE scans for its WEND, evaluates its condition and makes its entry before it reads on
  (FIVEO.ASM WHILE, FNWEND); WEND with more after it is a Syntax error (FIVEO.ASM WEND).
* IF takes GOTO where THEN may stand and runs a statement where no line number follows
  (GWMAIN.ASM IFS, DOCOND); PRINT prints each item, comma and semicolon as it reads them, so a
  word that starts no item ends it after the comma (``PRINT 50, IF``).
* GOSUB makes room on the stack, reads the line and only then pushes; a missing line's
  error, trapped, leaves nothing on the stack (GWMAIN.ASM GOSUB; the error handler's SAVSTK).
* ``ON x`` with no GOTO or GOSUB reads x as GETBYT does (Illegal function call outside
  0..255) before the Syntax error (GWMAIN.ASM NTONGS).
* RETURN takes its GOSUB off the stack before it reads on: ``RETURN 40,`` is RETURN
  without GOSUB with none, a jump to 40 with one (GWMAIN.ASM RETURN, GOTO's LINGET).
* RESTORE reads the digits after it as a line that must exist (none: line 0) and sets the
  DATA pointer before the rest of the statement is read (BIMISC.ASM RESTORE).

Each program's expected output is PC-BASIC 2.0.8's (it agrees with the recordings here);
the tests compare with PC-BASIC too.
"""

from __future__ import annotations

import pytest

from test_differential_support import PcBasic, run_yaseer

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

TRAP = "100 PRINT \"err\"; ERR; ERL: RESUME NEXT\n"

CASES = {
    # the loop's NEXT is the one in line 50's branch: the plain NEXT of line 60 is no loop's
    "next_elsewhere": ("10 ON ERROR GOTO 100\n20 FOR I=1 TO 3\n30 PRINT I\n40 GOTO 60\n"
                       "50 IF I=1 THEN NEXT\n60 NEXT\n70 PRINT \"end\"; I: END\n" + TRAP,
                       " 1 \nerr 1  60 \nend 1 \n"),
    "named_next_elsewhere": ("10 ON ERROR GOTO 100\n20 FOR I=1 TO 3: PRINT I: GOTO 40\n"
                             "30 IF I THEN NEXT I\n40 NEXT I\n50 PRINT \"end\": END\n" + TRAP,
                             " 1 \nerr 1  40 \nend\n"),
    # the loop's own NEXT, reached by a jump, steps it
    "own_next_by_jump": ("10 FOR I=1 TO 3: PRINT I;: GOTO 30\n20 PRINT \"x\"\n30 NEXT\n40 PRINT \"end\"\n",
                         " 1  2  3 end\n"),
    # NEXT J, I reads one name at a time: both loops run, then what follows is the error;
    # a FOR whose scan stops at a name that does not read fails its first test there
    "next_read_as_far": ("10 ON ERROR GOTO 100\n20 FOR I=1 TO 2\n30 FOR J=1 TO 2\n40 PRINT I; J\n"
                         "50 NEXT J, I PRINT\n60 FOR A=1 TO 10 STEP 2: NEXT \"A\"\n65 PRINT A\n"
                         "70 FOR A=1 TO 3: PRINT A;: NEXT A,\n"
                         "80 FOR B=1 TO 2: FOR C=1 TO 2: PRINT B; C;: NEXT C, 2\n90 END\n" + TRAP,
                         " 1  1 \n 1  2 \n 2  1 \n 2  2 \nerr 2  50 \nerr 2  60 \nerr 2  60 \n 0 \n"
                         " 1  2  3 err 1  70 \nerr 2  80 \n 0  1  0  2 err 2  80 \n"),
    "next_of_a_string": ("10 ON ERROR GOTO 100\n20 FOR A$=\"1\" TO \"2\": NEXT A$\n30 END\n" + TRAP,
                         "err 13  20 \nerr 1  20 \n"),
    # an unowned ELSE skips its line, but the FOR's scan finds the NEXT after it
    "next_after_else": ("10 ON ERROR GOTO 100\n20 FOR I=1 TO 3: PRINT I;: GOTO 40\n30 ELSE NEXT\n40 NEXT\n"
                        "50 END\n" + TRAP, " 1 err 1  40 \n"),
    # WHILE evaluates its condition and makes its entry before what follows is read; WEND
    # with more after it is a Syntax error, but still the WEND a WHILE's scan finds
    "while_wend_with_more": ("10 ON ERROR GOTO 100\n20 A=1: WHILE A < 20 PRINT\n30 PRINT A;: A = A*3\n40 WEND\n"
                             "50 B=0: WHILE B < 2\n60 PRINT \"b\"; B;: B = B+1\n70 WEND B\n"
                             "80 WHILE 0 X: PRINT \"no\"\n85 WEND\n90 PRINT \"end\": END\n" + TRAP,
                             "err 2  20 \n 1 err 2  20 \n 3 err 2  20 \n 9 b 0 err 2  70 \nend\n"),
    # IF c GOTO without a line number is IF c THEN; a PRINT cut short by a word that starts no
    # item has printed the comma or semicolon before the word
    "if_goto_statement": ("10 ON ERROR GOTO 100\n20 IF 1 GOTO PRINT \"a\"\n30 IF 0 GOTO PRINT \"b\" ELSE PRINT \"c\"\n"
                          "40 IF 1, GOTO A=5: PRINT A\n50 PRINT 50, IF 0 THEN 60\n60 PRINT 60; THEN\n"
                          "70 PRINT \"x\", TO\n80 END\n" + TRAP,
                          "a\nc\n 5 \n 50           err 2  50 \n 60 err 2  60 \nx             err 2  70 \n"),
    # a FOR of a variable another FOR statement's loop already runs opens a loop of its own
    # (GWMAIN.ASM FOR's LPFORM drops only its own statement's entry); jumps out of loops,
    # RETURN from one, NEXT in a branch
    "loops_and_jumps": ('10 ON ERROR GOTO 100\n20 FOR I=1 TO 3: PRINT "o";: FOR I=1 TO 2: PRINT "i";: NEXT I: NEXT I\n30 PRINT: PRINT I\n40 FOR J=1 TO 2: FOR K=1 TO 2: PRINT J;K;: IF K=1 THEN GOTO 60\n50 NEXT K\n60 NEXT J\n70 PRINT: FOR L=1 TO 3: GOSUB 90: NEXT L: PRINT "end": END\n90 FOR M=1 TO 2: PRINT L; M;: IF M=2 THEN RETURN\n95 NEXT M: PRINT "x": RETURN\n100 PRINT "err"; ERR; ERL: RESUME NEXT\n',
                        'oii\n 4 \n 1  1  2  1 \n 1  1  1  2  2  1  2  2  3  1  3  2 end\n'),
    "loops_and_errors": ('10 ON ERROR GOTO 100\n20 FOR I = 1 TO 2: GOSUB 60: PRINT "r"; I;: NEXT I\n30 PRINT: FOR I = 1 TO 3: FOR J = 1 TO 3: IF J = 2 THEN NEXT I\n40 PRINT I; J;: NEXT J: PRINT "x";: NEXT I\n50 PRINT: GOTO 80\n60 FOR J = 1 TO 5: IF J = 2 THEN RETURN\n70 NEXT J\n80 FOR K = 1 TO 2: PRINT "k"; K;\n85 NEXT K, K\n90 PRINT "end": END\n100 PRINT "err"; ERR; ERL: RESUME NEXT\n',
                         'r 1 r 2 \nerr 1  40 \nerr 1  30 \nerr 1  30 \n 3  2 err 1  40 \nxerr 1  40 \n\nk 1 k 2 err 1  85 \nend\n'),
    # RESUME NEXT after an error in a NEXT inside an IF branch goes on after that NEXT
    "resume_after_next_in_branch": ('10 ON ERROR GOTO 100\n20 FOR I = 1 TO 3: FOR J = 1 TO 3: IF J = 0 THEN NEXT I\n30 PRINT "30"; I; J: NEXT J\n40 PRINT "40"; I; J: END\n100 PRINT "err"; ERR; ERL: N = N + 1: IF N > 8 THEN END ELSE RESUME NEXT\n',
                                    'err 1  30 \nerr 1  20 \nerr 1  20 \n30 0  0 \nerr 1  30 \n40 0  0 \n'),
    "gosub_missing_line": ("10 ON ERROR GOTO 100\n20 GOSUB 50\n30 PRINT \"back\": END\n"
                           "50 GOSUB 70\n55 PRINT \"55\": RETURN\n" + TRAP,
                           "err 8  50 \n55\nback\n"),
    "on_gosub_missing_line": ("10 ON ERROR GOTO 100\n20 A=2: GOSUB 50\n30 PRINT \"back\": END\n"
                              "50 ON A GOSUB 60, 70\n55 PRINT \"55\": RETURN\n60 PRINT \"60\": RETURN\n" + TRAP,
                              "err 8  50 \n55\nback\n"),
    "on_without_goto": ("10 ON ERROR GOTO 100\n20 FOR A = -1 TO 2: ON A: PRINT \"x\";: NEXT\n"
                        "25 FOR A = 255 TO 256: ON A THEN 10: NEXT\n"
                        "30 A=300: ON A, 2: A=32768: ON A+: A=3: ON A GOTO\n40 END\n"
                        "100 PRINT \"err\"; ERR; ERL; A: RESUME NEXT\n",
                        "err 5  20 -1 \nxerr 2  20  0 \nxerr 2  20  1 \nxerr 2  20  2 \nxerr 2  25  255 \n"
                        "err 5  25  256 \nerr 5  30  300 \nerr 22  30  32768 \n"),
    "return_with_more": ("10 ON ERROR GOTO 100\n20 RETURN 40,\n25 RETURN \"1\"\n26 RETURN X\n30 GOSUB 50\n"
                         "35 PRINT \"back\"\n40 PRINT 40: IF Z THEN END\n"
                         "45 Z=1: GOSUB 70: PRINT \"b70\": GOSUB 80: PRINT \"b80\": END\n"
                         "50 RETURN 40,\n70 RETURN \"1\"\n80 RETURN 40 X\n" + TRAP,
                         "err 3  20 \nerr 3  25 \nerr 3  26 \n 40 \nb70\n 40 \n"),
    "restore_with_more": ("10 ON ERROR GOTO 100\n20 DATA 1,2,3\n30 READ A: PRINT A\n"
                          "40 RESTORE DATA: READ A: PRINT A\n50 RESTORE \"1\": READ A: PRINT A\n"
                          "60 RESTORE 20, 30: READ A: PRINT A\n70 RESTORE 5: READ A: PRINT A\n"
                          "80 RESTORE 20 X: READ A: PRINT A\n90 RESTORE A: END\n" + TRAP,
                          " 1 \nerr 8  40 \n 2 \nerr 8  50 \n 3 \nerr 2  60 \n 1 \nerr 8  70 \n 2 \n"
                          "err 2  80 \n 1 \nerr 8  90 \n"),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_jumps_as_gw_basic_runs_them(name):
    program, expected = CASES[name]
    assert run_yaseer(program, dialect="gw") == expected


def test_the_expected_outputs_are_pc_basic_s():
    pc = PcBasic()
    try:
        for name, (program, expected) in CASES.items():
            assert pc.program(program) == expected, name
    finally:
        pc.close()


def test_the_casio_keeps_its_unbound_next():
    """The casio steps the innermost loop at any NEXT (no scan binds it: ``Dialect.for_binds_next``)."""
    program = "10 FOR I=1 TO 3\n20 PRINT I;\n30 GOTO 50\n40 IF I=1 THEN NEXT\n50 NEXT\n60 PRINT \"end\"\n"
    assert run_yaseer(program, dialect="casio") == " 1  2  3 end\n"
