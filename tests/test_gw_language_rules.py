"""GW-BASIC's rules for statements that run (issue 24's language items) against PC-BASIC
2.0.8 where it agrees with GW-BASIC's source, and against the source where they differ
(docs/compatibility.md names the routine): a FOR that finds no NEXT leaves its variable
as it was (GWMAIN.ASM FOR keeps the start value aside until NXTSCN has found the NEXT),
the messages are the table's texts, ...
"""

from __future__ import annotations

import io

import pytest

from test_differential_support import PcBasic
from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


@pytest.fixture(scope="module")
def pc():
    session = PcBasic()
    yield session
    session.close()


AGREED = {
    # FOR keeps its start value aside until its NEXT is found (GWMAIN.ASM FOR, NXTSCN)
    "for without next leaves the variable": (
        "10 ON ERROR GOTO 100\n20 I=5: FOR I=1 TO 3\n30 PRINT I\n40 J=7: FOR J=1 TO 2: NEXT K\n"
        "50 PRINT J: END\n100 PRINT ERR; ERL; I; J: RESUME NEXT\n"),
    "for without next in a branch": "10 I=5: IF 1 THEN FOR I=1 TO 3\n",
    # the message table's texts
    "undefined line": "10 GOTO 50\n",
    "undefined line by gosub": "10 GOSUB 50\n",
    "undefined line by then": "10 IF 1 THEN 50\n",
    "restore to a missing line": "10 RESTORE 50\n",
    "duplicate definition": "10 DIM A(2): DIM A(3)\n",
    # relations with blanks inside (GWEVAL.ASM collects < = > skipping blanks)
    "spaced relations": ('10 A=3: B=2\n20 IF A = > B THEN PRINT "ge"\n30 IF B < = A THEN PRINT "le"\n'
                         '40 IF A >  < B THEN PRINT "ne"\n50 PRINT A = > 3, A < > 3\n'),
    # [ ] for a subscript's parentheses, nowhere else
    "bracket subscripts": "10 DIM A[3]: A[2]=5: PRINT A[2]; A(2); A[2); A(2]\n20 PRINT [1+2]\n",
    "brackets are no parentheses": "10 PRINT (1+2]\n",
    # a statement runs left to right: what it printed stays before its error
    "print items before a bad one": '10 PRINT "a"; ERL(\n',
    "print items before a bad expression": '10 PRINT "b", 5; 1+\n',
    "print using literal before its error": '10 PRINT USING "abc";1\n',
    "write items before a bad one": ('10 ON ERROR GOTO 100: WRITE 1, "A",\n20 WRITE 2, 3 +\n30 PRINT "x": END\n'
                                      '100 PRINT ERR; ERL: RESUME NEXT\n'),
    "print using a string into a number field": '10 PRINT USING "x##y##"; 5; "s"\n',
    # PRINT ... USING after other items; a single's 7 digits are what USING rounds
    "using after items": '10 PRINT "X="; USING "##.#"; 3.14159\n20 PRINT 1, USING "#"; 2\n',
    "using rounds the single's digits": ('10 PRINT USING "#.##"; 2.675; 1.005; 0.125#; 2.675#\n'
                                          '20 PRINT USING "#.##########"; 1/3\n'),
    # WEND looks for its WHILE's entry on the stack (GWMAIN.ASM WEND): a GOTO into the loop's
    # body reaches a WEND whose loop is not running
    "while entered by goto": '10 I = 0: GOTO 40\n30 WHILE I < 3\n40 PRINT "IN"; I: I = I + 1\n50 WEND\n60 PRINT "DONE"\n',
    "while left and entered again": ('10 WHILE I < 2: I = I + 1: WEND\n20 J = J + 1: IF J < 3 THEN 40\n30 END\n'
                                     '40 PRINT "IN"; J: WEND\n'),
    "while running when entered by goto": ('10 WHILE I < 3: I = I + 1: IF I = 1 THEN 30\n20 PRINT "A";\n'
                                           '30 PRINT I;: WEND\n'),
    # arguments made 16-bit integers before the byte check (MATH1.ASM CONINT: FRCINT, then FC)
    "counts of 32768 and above overflow": ('10 ON ERROR GOTO 100\n20 PRINT CHR$(32768)\n30 PRINT SPACE$(40000)\n'
                                           '40 X = 32768: PRINT STRING$(X, 65)\n50 PRINT LEFT$("ABC", 32768)\n'
                                           '60 PRINT LEFT$("ABC", 300); MID$("ABC", 256)\n70 PRINT RIGHT$("ABC", -1)\n'
                                           '80 END\n100 PRINT ERR; ERL: RESUME NEXT\n'),
    # a statement's integer arguments made 16-bit integers first (GWEVAL.ASM GETBYT, GETIN2
    # and GWMAIN.ASM INTIDX call FRCINT; GIO86.ASM's record length too): Overflow
    "integer arguments of 32768 and above overflow": (
        '10 ON ERROR GOTO 200\n20 ERROR 32768\n30 ON 32768 GOTO 10\n40 WIDTH 32768\n50 CLOSE 32768\n'
        '60 PRINT INPUT$(32768)\n70 DIM A(32768)\n80 B(32768) = 1\n90 OPEN "R", 1, "X.DAT", 32768\n'
        '100 ERROR -32769\n110 ON -32769 GOSUB 10\n120 DIM C(-32769)\n130 PRINT B(-32769); B(40000.7)\n'
        '150 WIDTH "LPT1:", -40000: PRINT INPUT$(1, 32768)\n160 PRINT B(32767)\n170 END\n'
        '200 PRINT ERR; ERL: RESUME NEXT\n'),
    # ... and the screen's, the keys' and the file functions' (GETBYT): LOCATE, COLOR, SCREEN,
    # KEY n, EOF, LOC, LOF, LPOS; POS takes any number without an error
    "screen and file arguments of 32768 and above overflow": (
        '10 ON ERROR GOTO 200\n20 LOCATE 32768\n30 LOCATE 1, 32768\n40 COLOR 32768\n50 COLOR 7, 32768\n'
        '60 X = EOF(32768)\n70 X = LOC(32768)\n80 X = LOF(32768)\n90 X = LPOS(32768)\n100 SCREEN 32768\n'
        '110 KEY 32768, "A"\n120 LOCATE -32769\n130 X = EOF(-32769)\n140 KEY -32769, "A"\n'
        '150 X = POS(32768)\n160 END\n200 PRINT ERR; ERL: RESUME NEXT\n'),
    "subscripts from one of 32768 and above overflow": (
        '10 OPTION BASE 1: ON ERROR GOTO 200\n20 DIM D(3): D(32768) = 1\n30 PRINT D(-32768.6); D(0)\n'
        '40 END\n200 PRINT ERR; ERL: RESUME NEXT\n'),
    # ON n GOTO/GOSUB skips as many line numbers as n needs and jumps; a selector that picks
    # none reads them all, then the statement must end (GWMAIN.ASM NTONGS, LOOPON; GOTO2)
    "on goto reads the line numbers it needs": (
        '10 ON ERROR GOTO 200\n20 ON 1 GOTO 30,\n30 ON 0 GOTO\n40 ON 1 GOSUB 300, XYZ: PRINT "after"\n'
        '50 ON 0 GOSUB: PRINT "fell"\n60 ON 1 GOTO 70 + 3\n70 ON 5 GOTO 20,,30\n80 ON 2 GOTO 20,,30\n'
        '90 ON 3 GOTO 20,30 XYZ\n100 ON 0 GOTO 20 + 3\n110 ON 2 GOTO 120,"A"\n120 ON 1 GOTO 130,"A"\n'
        '130 ON 3 GOTO 20,30,\n140 ON 0 GOTO 20 ELSE PRINT "E"\n150 END\n'
        '200 PRINT ERR; ERL: RESUME NEXT\n300 PRINT "sub": RETURN\n'),
    # a keyword alone: LINE INPUT wants its variable (GWMAIN.ASM LINE: PTRGET), DATE$ = and
    # TIME$ = a formula (GWSTS.ASM PRSDAT, PRSTIM: FRMEVL)
    "line input alone": '10 LINE INPUT\n',
    # DEF wants FN, SEG or USR, no operand (GWEVAL.ASM DEF: SYNCHR for SEG's letters)
    "def alone": '10 DEF\n20 PRINT "no"\n',
    # DEF SEG [= s] sets the segment PEEK and POKE would use, DEF USR[n] = a a machine-code
    # routine's address (GWEVAL.ASM DEF, DEFUSR: FRMQNT, an unsigned 16-bit number); USR
    # cannot run machine code: Illegal function call after its argument is read
    "def seg and def usr": ('10 ON ERROR GOTO 100\n20 DEF SEG: DEF SEG = &HB800: DEF SEG=-1: DEF SEG = 65535.4\n'
                            '30 DEFSEG = 7: PRINT DEFSEG; SEG\n40 DEF USR0 = &H1000: DEF USR = 5: DEF USR9 = -32768\n'
                            '50 DEF SEG = 65536\n60 DEF USR3 = 70000!\n70 DEF SEG = "A"\n80 X = USR5(2)\n'
                            '90 X = USR("A"): END\n100 PRINT ERR; ERL: RESUME NEXT\n'),
    "def usr with two digits": '10 DEF USR10 = 5\n',
    "usr of a bad argument": '10 X = USR(1 / 0) + USR(LOG(-1))\n',
    "def alone trapped": '10 ON ERROR GOTO 100\n20 DEF: PRINT "no"\n30 END\n100 PRINT ERR; ERL: RESUME NEXT\n',
    "date$ = alone": '10 DATE$ =\n',
    "time$ = alone": '10 TIME$=\n',
    # DATE$ = and TIME$ = set the clock, read back (GWSTS.ASM DATES, TIMES, PRSDAT, PRSTIM)
    "the clock set": ('10 TIME$ = "12:00:00": PRINT LEFT$(TIME$, 5)\n20 DATE$ = "2-29-2000": PRINT DATE$\n'
                      '30 DATE$ = "1/2/77": PRINT DATE$: TIME$ = "7": PRINT LEFT$(TIME$, 5)\n'
                      '40 DATE$ = "12-31-99": PRINT DATE$\n'),
    "the clock's texts refused": (
        '10 ON ERROR GOTO 200\n20 TIME$ = 5\n30 TIME$ = "25:00"\n40 TIME$ = ""\n50 TIME$ = "12:60"\n'
        '60 TIME$ = "12-00"\n70 DATE$ = "2-32-2000"\n80 DATE$ = "1/2/1977"\n90 DATE$ = "1/2"\n'
        '100 DATE$ = "13-01-1990"\n110 DATE$ = "01-01-2100"\n120 DATE$ = "0-1-1990"\n130 ERR = 1\n'
        '140 END\n200 PRINT ERR; ERL: RESUME NEXT\n'),
    # an ELSE that no IF owns is skipped as REM to the line's end (GWMAIN.ASM ELSES; the
    # cruncher puts a colon before every ELSE, so one after a statement ends it)
    "else alone": ('10 ELSE PRINT "x"\n20 PRINT "y": ELSE PRINT "x"\n30 PRINT "a" ELSE PRINT "x"\n'
                   '40 X = 1 ELSE )\n50 GOTO 70 ELSE PRINT "x"\n60 PRINT "no"\n70 FOR I = 1 TO 2 ELSE PRINT "x"\n'
                   '80 PRINT I; X: NEXT: ON 0 GOTO 60 ELSE 60\n90 IF 0 THEN PRINT "t" ELSE PRINT "e" ELSE PRINT "f"\n'),
    # checks made before the rest is read: RESUME tests for a handler (GWMAIN.ASM RESUME,
    # ONEFLG), WHILE scans for its WEND (FIVEO.ASM WHILE, WNDSCN) before FRMEVL
    "resume x outside a handler": '10 RESUME X\n',
    "resume x trapped outside a handler": '10 ON ERROR GOTO 100\n20 RESUME "A"\n30 END\n100 PRINT ERR; ERL: END\n',
    "resume x inside a handler": '10 ON ERROR GOTO 100\n20 ERROR 5\n30 PRINT "after": END\n100 PRINT "h": RESUME X\n',
    "while alone": '10 PRINT "a": WHILE: PRINT "b"\n20 PRINT "c"\n',
    "while alone with its wend": '10 WHILE\n20 WEND\n',
    "while cut with its wend": '10 WHILE 1+\n20 WEND\n',
    "while cut": '10 WHILE 1+\n',
    # a DEF FN with no = : the rest of the statement skipped as DATA, the call's Syntax error
    # (GWEVAL.ASM DEF, FNDOER)
    "bare def fn": '10 DEF FNA\n20 PRINT "ok"\n',
    "bare def fn and a statement": '10 DEF FNA: PRINT "same"\n20 PRINT "ok"\n',
    "bare def fn called": '10 DEF FNA\n20 PRINT FNA\n',
    "bare def fn called, trapped": ('10 ON ERROR GOTO 100\n20 DEF FNA: PRINT "d"\n30 X = FNA: PRINT "after"\n'
                                    '40 DEF FNB$: PRINT FNB$(2)\n50 END\n100 PRINT ERR; ERL: RESUME NEXT\n'),
    # RETURN reads a line number's digits, else returns plainly (GWMAIN.ASM RETURN, GOTO's LINGET)
    "return with a string": '10 GOSUB 30: PRINT "BACK": END\n30 PRINT "IN": RETURN "1": PRINT "AFTER"\n',
    "return with a name": '10 GOSUB 30: PRINT "BACK": END\n30 PRINT "IN": RETURN X\n',
    "return with a sum": '10 GOSUB 30: PRINT "BACK": END\n30 PRINT "IN": RETURN 1+1\n',
    "randomize a string": '10 A$ = "5": RANDOMIZE A$: PRINT RND\n',
    "if with a comma": '10 IF 1, THEN PRINT "Y"\n20 IF 1, GOTO 40\n30 END\n40 PRINT "G": IF 0, THEN 50 ELSE PRINT "E"\n50 IF 1, PRINT "N"\n',
    "go sub with two blanks": '10 GO  SUB 30: END\n30 PRINT "IN": RETURN\n',
    "go to with blanks": '10 GO  TO 30\n20 GO SUB 40: END\n30 PRINT "IN": GOTO 20\n40 PRINT "SUB": RETURN\n',
    "sign before not": '10 PRINT -NOT 1; -NOT 1 + 1; 2 * -NOT 0; +NOT 5\n',
    "lpos of no printer": '10 PRINT LPOS(3); LPOS(2)\n20 PRINT LPOS(-1)\n',
    "lpos past the printers": '10 PRINT LPOS(4)\n',
    # a branch is read only when it runs (GWMAIN.ASM IF skips to ELSE or the line's end)
    "a bad branch not taken": '10 IF 1 > 2 THEN EXIT FOR\n20 PRINT "RUNS"\n30 IF 2 > 1 THEN EXIT FOR\n40 PRINT "NOT"\n',
    "a bad else taken": '10 PRINT "A": IF 0 THEN PRINT "X" ELSE )\n20 PRINT "B"\n',
    "a bad then, a good else": '10 IF 0 THEN ( ELSE PRINT "E"\n20 PRINT "B"\n',
    "a branch bad after a statement": '10 IF 1 THEN PRINT 1: )\n20 PRINT "B"\n',
    "a jump and a bad else": '10 IF 0 THEN 20 ELSE PRINT "Q": (\n20 PRINT "B"\n',
    # DEF FN's body is read when the function is called (GWMAIN.ASM DEF skips it)
    "def fn body read when called": '10 DEF FNA(X) = X + : PRINT "DEF OK"\n20 PRINT FNA(1)\n',
    "def fn body of the wrong type": '10 DEF FNB(X) = X + "A": PRINT "DEF OK"\n20 PRINT FNB(1)\n',
    "def fn string of a number": '10 DEF FNC$(X) = X: PRINT "OK"\n20 PRINT FNC$(1)\n',
    "def fn never called": '10 DEF FND(X) = X )\n20 PRINT "B"\n',
    # LET reads its target before the = (PTRGET first): DIMA$(20) is the array DIMA$
    "dima$(20)": '10 DIMA$(20): PRINT "OK"\n',
    "dima(20),b$(3)": '10 DIMA(20),B$(3): PRINT "OK"\n',
    "dima$(5)": '10 DIMA$(5): PRINT "OK"\n',
    "dima$ trapped": '10 ON ERROR GOTO 30\n20 DIMB$(11): PRINT "NO": END\n30 PRINT ERR; ERL: RESUME NEXT\n',
    # a PRINT USING field that does not fit the row starts the next one
    "using field past the row": ('10 PRINT USING "##.##"; 1; 2; 3: PRINT TAB(75); : PRINT USING "####.##"; 1.5\n'
                                 '20 PRINT TAB(78);: PRINT USING "&"; "HELLO"\n30 PRINT TAB(74);: PRINT USING "AB#.#"; 1\n'),
    # control codes on the screen: BEL moves nothing, CHR$(0) one column, TAB to the next 8
    "control codes move the column": ('5 CLS\n10 PRINT "AB"; CHR$(7); CHR$(0); "C";: X = POS(0): PRINT: PRINT X\n'
                                      '20 PRINT "A"; CHR$(9); "B";: Y = POS(0): PRINT: PRINT Y\n'
                                      '30 PRINT STRING$(80, "*"); CHR$(13); "Z"\n'),
    # MID$ = copies byte by byte into the target (BISTRS.ASM LHSMID, MID$LP): the target
    # itself as the value overlaps; a MID$() of it is a copy
    # MID$ = with a count of 0 changes nothing, its start not compared with the length
    # (BISTRS.ASM LHSMID returns on a zero count first)
    "mid$ = with a count of 0": ('10 A$ = "AB": MID$(A$, 5, 0) = "X": MID$(A$, 2, 0) = "Q": PRINT A$\n'
                                 '20 MID$(A$, 5) = "X"\n'),
    "mid$ onto itself": ('10 A$ = "ABCDEFGH": MID$(A$, 3) = A$: PRINT A$\n20 B$ = "HELLO": MID$(B$, 2, 3) = MID$(B$, 1)\n'
                         '30 C$ = "WXYZ": MID$(C$, 2) = C$: D$ = "1234": MID$(D$, 1, 2) = D$: PRINT B$; " "; C$; " "; D$\n'),
}


@pytest.mark.parametrize("name", list(AGREED))
def test_agrees_with_pcbasic(pc, tmp_path, name):
    source = AGREED[name]
    pc.statement("ON ERROR GOTO 0")
    assert yaseer_run(source, tmp_path) == pc.program(source)


# Statements on open files: PC-BASIC runs them in a directory of their own
FILE_AGREED = {
    # ... and WIDTH #'s and FIELD's: the file first (GIO86.ASM FILWID: PRFNUM, FDBPTR; DSKCOM.ASM
    # FIELD: FILSCN), then each width (GETWDT, GTBYTC: GETBYT) and, in FIELD, its variable
    "file and field widths of 32768 and above overflow": (
        '10 ON ERROR GOTO 200\n20 OPEN "O", 1, "W.TXT": OPEN "R", 3, "R.DAT", 64\n30 WIDTH #1, 40000\n'
        '40 WIDTH #1, 32768\n50 WIDTH #1, 256\n60 WIDTH #2, 40000\n70 WIDTH #1, -32769\n80 WIDTH #40000, 5\n'
        '90 FIELD #3, 40000 AS A$\n100 FIELD #3, 32768 AS A$\n110 FIELD #3, 256 AS A$\n120 FIELD #3, -32769 AS A$\n'
        '130 FIELD #2, 40000 AS A$\n140 FIELD #3, 10 AS A$, 40000 AS B$\n150 FIELD #3, 40000 AS A\n'
        '160 FIELD #40000, 5 AS A\n170 END\n200 PRINT ERR; ERL: RESUME NEXT\n'),
    "file and field widths read after the file": (
        '10 ON ERROR GOTO 200\n20 OPEN "O", 1, "W.TXT": OPEN "R", 3, "R.DAT", 64\n30 WIDTH #2, "A"\n'
        '40 WIDTH #1, "A"\n50 FIELD #2, "A" AS A$\n60 FIELD #2, 5 AS A\n70 FIELD #3, "A" AS A$\n'
        '80 FIELD #3, 300 AS A\n90 FIELD #1, 5 AS A\n100 WIDTH #0, "A"\n110 FIELD #0, 5 AS A\n'
        '120 END\n200 PRINT ERR; ERL: RESUME NEXT\n'),
    # GET and PUT find the file (open, random) before they read the record number (GIO86.ASM
    # DPUTG: POFNUM, FDBPTR, the MD_RND check, then ADRGET); INPUT # and LINE INPUT # before
    # a variable's subscripts (GWMAIN.ASM FILSTI, DSKCOM.ASM DLINE: FILINP first, then PTRGET
    # for each variable); FIELD before its widths (FILSCN, then GTBYTC)
    "get, put, input # and field find the file first": (
        '10 ON ERROR GOTO 200\n20 OPEN "O", 1, "W.TXT": OPEN "R", 3, "R.DAT", 16\n30 GET #1, ABS("X")\n'
        '40 PUT #1, ABS("X")\n50 GET #2, 1/0\n60 PUT #2, ABS("X")\n70 INPUT #1, A, B(ABS("X"))\n'
        '80 LINE INPUT #1, A$(ABS("X"))\n90 GET #3, ABS("X")\n100 FIELD #2, ABS("X") AS A$\n'
        '110 FIELD #1, 1/0 AS A$\n120 INPUT #2, A(ABS("X"))\n130 LINE INPUT #3, A$(ABS("X"))\n140 END\n'
        '200 PRINT ERR; ERL: RESUME NEXT\n'),
    "get finds the file before a division by zero": '10 PRINT "a": GET #2, 1/0\n20 PRINT "b"\n',
    # WRITE # writes each item and its comma before it reads the next (FIVEO.ASM WRITE)
    "write # items before a bad one": (
        '10 OPEN "O", 1, "W.TXT": ON ERROR GOTO 100: WRITE #1, 1, "B",\n'
        '20 CLOSE: OPEN "I", 1, "W.TXT": LINE INPUT #1, A$: PRINT A$: END\n100 RESUME NEXT\n'),
    # a ; between WRITE's items writes a comma, as a comma does (FIVEO.ASM WRITE: WASEMI)
    "write # items separated by semicolons": (
        '10 OPEN "O", 1, "W.TXT": WRITE #1, 1;"B";-2.5, 3: WRITE 4;"C"\n'
        '20 CLOSE: OPEN "I", 1, "W.TXT": LINE INPUT #1, A$: PRINT A$: END\n'),
    # an INPUT$ cut inside its file number finds the file (open for output: Bad file mode)
    "input$ cut after an output file's number": (
        '10 ON ERROR GOTO 100: OPEN "O", 1, "W.TXT"\n20 A$ = INPUT$(1, #1\n30 A$ = INPUT$(1, 1\n'
        '40 END\n100 PRINT ERR; ERL: RESUME NEXT\n'),
    # FIELD fields each variable in turn: those before the one that fails keep their fields
    "field keeps the variables before a bad width": (
        '10 ON ERROR GOTO 200\n20 OPEN "R", 1, "R.DAT", 64\n30 FIELD #1, 10 AS A$, 300 AS B$\n'
        '40 LSET A$ = "XYZ": PRINT LEN(A$); "["; A$; "]"\n50 FIELD #1, 5 AS C$, 40000 AS D\n'
        '60 LSET C$ = "Q": PRINT LEN(C$)\n70 FIELD #1, 5 AS B$, 6 AS C$, 7 AS D\n'
        '80 LSET C$ = "Q": PRINT LEN(B$); LEN(C$)\n90 END\n200 PRINT ERR; ERL: RESUME NEXT\n'),
}


@pytest.mark.parametrize("name", list(FILE_AGREED))
def test_file_statements_agree_with_pcbasic(tmp_path, name):
    source = FILE_AGREED[name]
    theirs, ours = tmp_path / "pc", tmp_path / "ya"
    theirs.mkdir()
    ours.mkdir()
    assert yaseer_run(source, ours) == pcbasic_run(source, theirs)


# Statements cut after each of their tokens: the error each cut gives (Syntax error where
# the statement's own scan wants a name or a line number, Missing operand where an
# expression must start: GWEVAL.ASM EVAL's MOERR), as PC-BASIC 2.0.8 reports it.
CUT_STATEMENTS = [
    'PRINT 1+2*3', 'GOTO 100', 'GOSUB 100', 'IF A=1 THEN 100 ELSE 100', 'FOR I=1 TO 3 STEP 1: NEXT I',
    'DIM A(3), B$(2)', 'X=ABS(-3)+LEN("AB")', 'READ X', 'LET Y=2', 'SWAP A, B',
    'WIDTH 80', 'RESTORE 100', 'CLEAR 100', 'ERROR 5', 'CLOSE #1', 'KILL "X"',
    'ERASE A', 'OPTION BASE 1', 'RESUME NEXT', 'A$=MID$("ABC",2,1)', 'PRINT USING "##";5',
    'X=INSTR(1,"AB","B")', 'X=NOT 1', 'X=-1', 'X=(1+2)', 'X=2^3', 'X=5 MOD 2', 'X=5\\2', 'ON ERROR GOTO 100',
    'DEFINT A-C', 'RETURN 100', 'X=1 AND 2', 'OPEN "O", #1, "F"', 'OPEN "F" FOR OUTPUT AS #1', 'X=FRE(0)',
    'X=VAL("5")', 'X=STRING$(3,65)', 'LSET A$="X"', 'X=A(1)', 'X=A(1,2)', 'DEF FNA(X)=X',
    # the file statements find their file before they read on (GIO86.ASM FILGET, FILWID,
    # DPUTG; DSKCOM.ASM FIELD: FILSCN), the file here not open
    'PRINT #1, USING "##"; 5', 'LINE INPUT #1, A$', 'WRITE #1, 5', 'FIELD #1, 5 AS A$', 'FIELD 1, 5 AS A$',
    'GET #1, 1', 'PUT #1, 1', 'WIDTH #1, 80',
    # WRITE prints each item and its comma before it reads the next (FIVEO.ASM WRITE), a ;
    # between items as a comma
    'WRITE 1, "A", 3', 'WRITE 1;"A";3', 'WRITE #1, 1;2', 'WRITE 1 X, 2',
    # the MID$ statement checks its start and count as it reads them (BISTRS.ASM LHSMID)
    'MID$(A$,0,1)=5', 'MID$(A$,2,1)="X"',
    # INPUT$ finds its file before its ) (DSKCOM.ASM FIXINP: FILSCN)
    'X$=INPUT$(1,#1)', 'X$=INPUT$(1,1)',
    # RENUM's increment: digits or none, none read as 0 (GWMAIN.ASM RESEQ: LINGET)
    'RENUM 10,20,30',
    # the screen's statements (compared on the screen's rows) and the printer's (on its text)
    'LOCATE 1,2,1', 'LOCATE ,,1,5,7', 'COLOR 7,0,0', 'COLOR ,1', 'CLS 0', 'KEY OFF', 'KEY 1, "A"',
    'SCREEN 0,0,0', 'LPRINT 1;2', 'LPRINT USING "##";5', 'LPRINT 1,"A";',
    # INPUT asks and reads its answer (an Enter) before it reads its names (GWMAIN.ASM INPUT:
    # SINLIN, then PTRGTN); INPUT # finds its file first; LINE INPUT reads its name first
    'INPUT #1, A', 'INPUT;"Q";A, B', 'INPUT "Q", A', 'LINE INPUT;"Q";A$',
    # DEF reads S, E, G letter by letter, then an = and a number if anything follows
    # (GWEVAL.ASM DEF); DEF USR its one-digit number (SCNUSR); USR its ( and argument (USRFN)
    'DEF SEG = 47104', 'DEF SEG', 'DEF USR0 = 4096', 'DEF USR = 5', 'X = USR0(1)', 'X = USR(1)',
]
# Cuts where PC-BASIC 2.0.8 differs from GW-BASIC's source, which decides:
SOURCE_DECIDED = {
    # GWMAIN.ASM LINE goes to GENGRP.ASM GLINE, which wants a point's ( first (SCAND's SYNCHR);
    # PC-BASIC refuses a graphics statement on the text screen first (Illegal function call)
    "LINE": "Syntax error in 10\n",
    # FIVEO.ASM WRITE prints an item, then its SYNCHR wants a comma (or ;) before it prints
    # one: an item followed by anything else prints without its comma (PC-BASIC prints it)
    "WRITE 1 X": "1\nSyntax error in 10\n",
    "WRITE 1 X,": "1\nSyntax error in 10\n",
    # BISTRS.ASM LHSMID: SYNCHR for its ( (PC-BASIC reports the line after);
    "MID$": "Syntax error in 10\n",
    # MIDRST's SYNCHR for the , or ), FRMEQL's for the =, FRMEVL's Missing operand: the
    # start is compared with the length only after the value (PC-BASIC compares it first)
    "MID$(A$,2": "Syntax error in 10\n",
    "MID$(A$,2,1": "Syntax error in 10\n",
    "MID$(A$,2,1)": "Syntax error in 10\n",
    "MID$(A$,2,1)=": "Missing operand in 10\n",
    # a start of 0 is refused as GETBYT reads it, before the count (PC-BASIC reads the count)
    "MID$(A$,0,": "Illegal function call in 10\n",
}


def _cuts(statement: str) -> list[str]:
    import re

    ends = [m.end() for m in re.finditer(r'[A-Z$]+|\d+|"[^"]*"|\S', statement)]
    return [statement[:end] for end in ends[:-1]]


@pytest.fixture(scope="module")
def printing_pc(tmp_path_factory):
    """A PC-BASIC session whose printer (LPT1:) writes to a file: (session, the file)."""
    paper = tmp_path_factory.mktemp("lpt1") / "lpt1.txt"
    session = PcBasic(devices={"LPT1:": f"FILE:{paper}"})
    yield session, paper
    session.close()


def _screen_text(rows: list[str]) -> str:
    """Screen rows as lines, the blank rows below the last written one dropped."""
    while rows and not rows[-1]:
        rows = rows[:-1]
    return "".join(row + "\n" for row in rows)


def pcbasic_cut(session: PcBasic, paper, source: str, keys: str = "\n") -> tuple[str, str]:
    """(the screen's rows, what the printer printed) after PC-BASIC runs ``source`` from a
    cleared screen with ``keys`` waiting on the keyboard (one Enter; what is left of them
    taken away afterwards)."""
    from test_differential_gw_screen import RESET

    session.statement("CLOSE: ON ERROR GOTO 0: " + RESET)
    printed = paper.stat().st_size if paper.exists() else 0
    session._session.press_keys(keys.replace("\n", "\r"))
    session.program(source)
    rows = session._session.get_chars(as_type=bytes)
    session.statement('WHILE INKEY$ <> "": WEND')
    # (PC-BASIC draws the cursor after an error message as a cell of code 255)
    screen = _screen_text(["".join(chr(b[0]) if b else " " for b in row).rstrip(" \xff") for row in rows])
    return screen, paper.read_bytes()[printed:].decode("latin-1").replace("\r\n", "\n")


def yaseer_cut(source: str, directory, keys: str = "\n") -> tuple[str, str]:
    """(the screen's rows, the printer's text) after yaseer runs ``source``: an error message
    written on the screen as GW-BASIC writes it, the keys ``keys``."""
    from yaseer.basic.dialects.dialect import GW
    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.machine import Machine

    paper = io.StringIO()
    machine = Machine(screen=io.StringIO(), printer=paper, dialect=GW, angle="rad", files=directory,
                      input_stream=io.StringIO(keys))
    machine.load(source)
    try:
        machine.run()
    except BasicError as err:
        machine.end_line()
        machine.screen.write(str(err) + "\n")
    machine.screen.catch_up()
    return _screen_text([GW.charset.codes(line) for line in machine.display.lines()]), paper.getvalue()


def test_cut_statements_give_pcbasics_errors(printing_pc, tmp_path):
    """Each cut compared on the screen's rows (a LOCATE's column shows there, as does the
    error's message) and on the printer's text (LPRINT's goes to the printer, not the screen)."""
    session, paper = printing_pc
    found = []
    for statement in CUT_STATEMENTS:
        for text in _cuts(statement):
            source = f"10 {text}\n20 PRINT \"ok\"\n100 RETURN\n"
            ours = yaseer_cut(source, tmp_path)
            theirs = (SOURCE_DECIDED[text], "") if text in SOURCE_DECIDED else pcbasic_cut(session, paper, source)
            if theirs != ours:
                found.append((text, theirs, ours))
    assert not found, found


INPUT_KEPT_ROW = {
    # INPUT; and LINE INPUT; leave the cursor after the answer (GWMAIN.ASM INPUT and LINE
    # INPUT call SCNSEM for the semicolon); a list cut short is asked and answered first
    "input; keeps the row": ('10 INPUT;A: PRINT "x"; A\n20 INPUT;"Q";B$, C: PRINT "y"; B$; C\n', "5\nab, 7\n"),
    "line input; keeps the row": ('10 LINE INPUT;"L? ";A$: PRINT "z"; A$\n20 LINE INPUT;B$: PRINT "w"\n', "hi, x\nq\n"),
    "input cut after an answer": ('10 INPUT "Q", A,\n', "12\n"),
    "input cut, trapped": ('10 ON ERROR GOTO 100\n20 INPUT;\n30 PRINT "n": END\n100 PRINT ERR; ERL: RESUME NEXT\n', "1\n"),
}


@pytest.mark.parametrize("name", list(INPUT_KEPT_ROW))
def test_input_forms_with_keys_as_pcbasic(printing_pc, tmp_path, name):
    source, keys = INPUT_KEPT_ROW[name]
    session, paper = printing_pc
    assert yaseer_cut(source, tmp_path, keys) == pcbasic_cut(session, paper, source, keys)


@pytest.mark.parametrize("name", list(INPUT_KEPT_ROW))
def test_casio_refuses_gws_input_forms(tmp_path, name):
    """The Casio's INPUT has no semicolon first and wants its names (INPUT.md)."""
    source, keys = INPUT_KEPT_ROW[name]
    if "ON ERROR" in source:
        return
    assert yaseer_run(source, tmp_path, "casio") == "Syntax error in 10\n"


def test_def_seg_below_its_range_overflows(tmp_path):
    """GWMAIN.ASM FRQINT takes -32768..65535 (FRMQNT for DEF SEG): -32769 is Overflow.
    (PC-BASIC 2.0.8 sets the segment silently.)"""
    assert yaseer_run("10 DEF SEG = -32769\n", tmp_path) == "Overflow in 10\n"


@pytest.mark.parametrize("text", ["LINE", "LINE X", "LINE @", "LINE STEP", "LINE , 1"])
def test_a_graphics_line_without_its_point_is_a_syntax_error(tmp_path, text):
    """LINE that is not LINE INPUT is the graphics LINE (GWMAIN.ASM LINE jumps to GLINE), which
    reads its first point before it draws anything: GENGRP.ASM GLINE, SCAN1 (an ``@`` skipped),
    SCAND (a STEP skipped) and SYNCHR for the ``(``.  (PC-BASIC 2.0.8 refuses the statement on
    the text screen first: Illegal function call.)"""
    assert yaseer_run(f"10 {text}\n20 PRINT \"no\"\n", tmp_path) == "Syntax error in 10\n"


def test_stop_leaves_its_break_on_a_new_row(pc):
    """PC-BASIC 2.0.8 prints ``A`` then ``Break in 10`` on the next row; yaseer run prints the
    Break on standard error, after ending the open row of standard output."""
    from yaseer.api import run

    source = '10 PRINT "A";: STOP\n20 PRINT "B"\n'
    result = run(source, dialect="gw")
    assert (result.status, result.line) == ("stop", 10)
    assert result.text + f"Break in {result.line}\n" == pc.program(source)


def test_line_input_keeps_a_lone_line_feed_as_the_source_reads_it(tmp_path):
    """DSKCOM.ASM DLINE: LINE INPUT # ends at a CR (a LF after it consumed); a LF after no
    CR is stored, and so is a CR right after it; INPUT # of an unquoted string drops the LF
    and reads on through such a CR.  (PC-BASIC 2.0.8 ends both at the LF.)"""
    (tmp_path / "D.TXT").write_bytes(b"ab\ncd\r\nef\n\r\ngh\r\nx\ny\r\n\x1a")
    source = ('10 OPEN "I", 1, "D.TXT": LINE INPUT #1, A$: LINE INPUT #1, B$: INPUT #1, C$\n'
              '20 PRINT LEN(A$); LEN(B$); C$; EOF(1); INSTR(A$, CHR$(10)); INSTR(B$, CHR$(13))\n')
    assert yaseer_run(source, tmp_path) == " 5  7 xy-1  3  4 \n"


def test_input_of_a_number_reads_on_through_a_lone_line_feed(tmp_path):
    """DSKCOM.ASM LPISLF keeps a LF in a number's text (only a string field drops it) and skips
    a CR right after it; FIN then steps over the LF (CHRGTR): ``12<LF>34`` is 1234.  An empty
    line before a field is an empty field (INPDOR skips only blanks before one).
    (PC-BASIC 2.0.8 ends the number at the LF: 12 and 34.)"""
    (tmp_path / "N.TXT").write_bytes(b"12\n34\r\n5\n\r6\r\n\r\n7\r\n")
    source = '10 OPEN "I", 1, "N.TXT": INPUT #1, A, B, C, D: PRINT A; B; C; D\n'
    assert yaseer_run(source, tmp_path) == " 1234  56  0  7 \n"


def test_line_input_reads_at_most_255_characters(tmp_path):
    """DSKCOM.ASM DLINE fills a 255-character buffer; the rest is the next line (PC-BASIC 2.0.8: the same)."""
    (tmp_path / "L.TXT").write_bytes(b"x" * 300 + b"\r\n")
    source = '10 OPEN "I", 1, "L.TXT": LINE INPUT #1, A$: LINE INPUT #1, B$: PRINT LEN(A$); LEN(B$)\n'
    assert yaseer_run(source, tmp_path) == " 255  45 \n"


@pytest.mark.parametrize("source, expected", [
    ("10 PRINT &O 7 7; & 1 7; &O1 7\n", " 63  15  15 \n"),  # OCTCNS reads octal digits with CHRGTR
    ("10 PRINT & H1F; &H 1F\n", " 31  0  1  0 \n"),  # the H with CHRGTR, hex digits byte by byte
    ("10 PRINT 1 E - 2; 1 E + 2\n", " .01  100 \n"),  # $FINEX reads the sign and digits with CHRGTR
    ("10 PRINT 1 2 %; 2 E; 3 D\n", " 12  2  3 \n"),  # FN400 eats the %; an E or D with no digits
    ("10 PRINT &O8\n", "Syntax error in 10\n"),  # OCTCNS: 8 is a digit but not an octal one (CONERR)
    ("10 IF 0 THEN PRINT 1 ELSE PRINT 2: PRINT 1 EQV 2\n", " 2 \n-4 \n"),  # $CHKEL: ELSE, EQV
])
def test_blanks_inside_numbers_as_the_source_reads_them(tmp_path, source, expected):
    """Where PC-BASIC 2.0.8 differs (it stops at the blank in these, and fails on ``&O 7 7``),
    GW's source decides: GWEVAL.ASM OCTCNS, MATH1.ASM FIN, MATH2.ASM $FINEX."""
    assert yaseer_run(source, tmp_path) == expected


@pytest.mark.parametrize("source, expected", [
    ('10 OPEN "O", 1, "X": PRINT EOF(1)\n', "Bad file mode in 10\n"),  # GIODSK.ASM DSKEOF: output mode
    ('10 PRINT EOF(-1)\n', "Illegal function call in 10\n"),  # a file number is a byte (PC-BASIC agrees)
    ('10 CLOSE 5: PRINT 1\n', " 1 \n"),  # a number not open: nothing (PC-BASIC agrees)
    ('10 CLOSE 300\n', "Illegal function call in 10\n"),
])
def test_file_number_errors(tmp_path, source, expected):
    assert yaseer_run(source, tmp_path) == expected


def test_file_width_as_getwdt_checks_it(tmp_path):
    """WIDTH #n, w takes 0..255 (GIO86.ASM FILWID; 255, the disk's own width, never starts a
    new line; PC-BASIC 2.0.8 refuses 255).  GETWDT refuses 0, but a real GW-BASIC 3.23 took it
    (PC-BASIC's recorded WIDTH test), as PC-BASIC 2.0.8 does."""
    source = ('10 OPEN "O", 1, "W.TXT": WIDTH #1, 255: PRINT #1, STRING$(200, "a"); STRING$(100, "b")\n'
              '20 CLOSE: ON ERROR GOTO 50\n30 WIDTH #1, 5\n40 OPEN "O", 1, "W.TXT": WIDTH #1, 0: END\n'
              '50 PRINT ERR; ERL: RESUME NEXT\n')
    assert yaseer_run(source, tmp_path) == " 52  30 \n"
    assert (tmp_path / "W.TXT").read_bytes() == b"\x1a"
    source = '10 OPEN "O", 1, "W.TXT": WIDTH #1, 255: PRINT #1, STRING$(200, "a"); STRING$(100, "b")\n'
    yaseer_run(source, tmp_path)
    assert (tmp_path / "W.TXT").read_bytes() == b"a" * 200 + b"b" * 100 + b"\r\n\x1a"


def test_the_clock_reads_its_texts_as_the_source_does(tmp_path):
    """GWSTS.ASM PRSTIM takes ``.`` as a separator too and PRSTIM and PRSDAT do not read
    what follows their last number (PC-BASIC 2.0.8 refuses both); the clock set goes on
    from the time set (an offset the machine keeps: machine/clock.py)."""
    source = ('10 TIME$ = "1:2:3.45x": PRINT LEFT$(TIME$, 5)\n20 DATE$ = "1/2/80x": PRINT DATE$\n'
              '30 TIME$ = "13:58:59.5": PRINT LEFT$(TIME$, 2); INT(TIMER / 3600)\n'
              '40 TIME$ = "12": T = TIMER: PRINT T >= 43200 AND T < 43260\n')
    assert yaseer_run(source, tmp_path) == "01:02\n01-02-1980\n13 13 \n-1 \n"


def test_a_while_whose_condition_fails_is_no_loop(tmp_path):
    """FIVEO.ASM WHILE pushes the $WHILE mark only after FRMEVL: after a trapped error in
    the condition, RESUME NEXT reaches a WEND whose loop is not running (``WEND without
    WHILE``; PC-BASIC 2.0.8 evaluates the WHILE again)."""
    source = '10 ON ERROR GOTO 100\n20 WHILE\n30 WEND: PRINT "n": END\n100 PRINT ERR; ERL: RESUME NEXT\n'
    assert yaseer_run(source, tmp_path) == " 22  20 \n 30  30 \nn\n"


def test_a_def_fn_skips_what_follows_its_parameters(tmp_path):
    """GWEVAL.ASM DEF reads the name and a parenthesised parameter list, then goes to DATA
    (skips to the statement's end) whatever follows; the call finds no ``=`` (FNDOER's
    SYNCHR): ``Syntax error`` where it is called.  (PC-BASIC 2.0.8 refuses the DEF itself.)"""
    source = '10 DEF FNA(X) JUNK: PRINT "same"\n20 DEF FNB X = 1: PRINT "too"\n30 PRINT FNA(1)\n'
    assert yaseer_run(source, tmp_path) == "same\ntoo\nSyntax error in 30\n"


def test_date_set_takes_days_1_to_31_of_every_month_of_1980_to_2099():
    """DATE$ = as a real GW-BASIC 3.23 took it in PC-BASIC's recorded faulty_DATE test (its
    DOS's set-date call): any day 1..31 of a month 1..12 of 1980..2099 (``02-30-2000`` too),
    the 32nd refused, and a year before 1980 (PRSDAT's 1978 and 1979 too)."""
    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.clock import calendar_date

    for year in (1980, 1999, 2000, 2077, 2099):
        for month in range(1, 13):
            assert calendar_date(f"{month:02d}-31-{year}") == (year, month, 31)
            with pytest.raises(BasicError, match="Illegal function call"):
                calendar_date(f"{month:02d}-32-{year}")
    for text in ("1-1-78", "1-1-1979", "1-1-2100", "13-1-1990", "0-1-1990", "1-0-1990"):
        with pytest.raises(BasicError, match="Illegal function call"):
            calendar_date(text)


@pytest.mark.parametrize("statement, expected", [
    ('MID$(A$,0)=5', "Illegal function call in 10\n"),  # the start checked before the value's type
    ('MID$(A$,1,300)=5', "Illegal function call in 10\n"),  # the count too
    ('MID$(A$,1)=5', "Type mismatch in 10\n"),  # a good start and count: the value's type
    ('MID$(A$,5)=5', "Type mismatch in 10\n"),  # ... before the start is compared with the length
    ('MID$(A$,0', "Illegal function call in 10\n"),  # read only so far: its start checked
    ('MID$(A$,1,300', "Illegal function call in 10\n"),
    ('MID$(A,0', "Type mismatch in 10\n"),  # the target must be a string first (CHKSTR)
])
def test_the_mid_statement_checks_its_start_and_count_as_it_reads_them(tmp_path, statement, expected):
    """BISTRS.ASM LHSMID: PTRGET and CHKSTR for the target, GETBYT for the start (0 Illegal
    function call) and the count, FRMEQL for the value, FRESTR for its type, then the count
    of 0 and the start against the length."""
    assert yaseer_run(f'10 A$="AB": {statement}\n20 PRINT "no"\n', tmp_path) == expected


def test_write_separates_items_by_semicolons_and_stops_at_anything_else(tmp_path):
    """FIVEO.ASM WRITE: a ; is a comma (WASEMI prints one), and after an item anything but a
    separator is SYNCHR's Syntax error, the item printed without a comma (PC-BASIC 2.0.8
    prints the comma: the source decides)."""
    assert yaseer_run('10 WRITE 1;"A";2: WRITE 3 X\n', tmp_path) == '1,"A",2\n3\nSyntax error in 10\n'


def test_renum_reads_a_missing_increment_as_zero(tmp_path):
    """GWMAIN.ASM RESEQ: after a second comma LINGET reads the increment, 0 where no digits
    follow, which it refuses (Illegal function call); PC-BASIC 2.0.8 agrees."""
    source = '10 RENUM 100,,\n20 PRINT "no"\n'
    assert yaseer_run(source, tmp_path) == pcbasic_run(source, tmp_path) == "Illegal function call in 10\n"



@pytest.mark.parametrize("text", ["A%(1, 0) = 4", "READ A%(1, 0)", 'B$(2, 1) = "X"', "A%(1, 0, 2) = 1"])
def test_an_element_of_more_subscripts_than_its_array_is_out_of_range(tmp_path, text):
    """The recorded PALETUSI test: READ A%(I, 0) into a one-dimensional A% is Subscript out
    of range (9), as reading such an element is (PC-BASIC 2.0.8 agrees)."""
    source = f"10 DIM A%(16), B$(5): A%(1) = 3\n20 {text}\n30 DATA 5\n"
    assert yaseer_run(source, tmp_path) == "Subscript out of range in 20\n"
