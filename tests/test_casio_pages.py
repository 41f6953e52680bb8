"""The casio dialect's remaining reserved words, one test per page of the FX-850P/880P owner's
manual (urbancamo/urbancamo.github.io, casio-basic/doc/commands/*.md): each runs a program of
ours written after the page's format, explanation items and sample program; the expected
values come from the page's explanations or from Python (sums, strings, math), never from
yaseer.  (The other words' pages: tests/test_casio_words.py, tests/test_casio_machine.py.)
"""

from __future__ import annotations

import io
import math

import mpmath
import pytest

import yaseer
from test_basic_helpers import error_of, run_text, run_values
from yaseer.session import MachineEngine, Session


def run(program: str, keys: str | None = None, **options):
    return yaseer.run(program, input=keys, **options)


# ------------------------------------------------------------------ strings

def test_chr_string():  # CHR_STRING.md: a code's character, fractions truncated, 0 <= code < 256
    assert run_text("10 FOR K=70 TO 74: PRINT CHR$(K);: NEXT K: PRINT CHR$(66.9)\n") == "FGHIJB\n"
    assert error_of("10 A$=CHR$(256)") == "Illegal function call in 10"


def test_left_string():  # LEFT_STRING.md items 1-2: a count past the length gives the whole string
    text = "".join(chr(c) for c in range(ord("P"), ord("X")))
    assert run_text(f'10 A$="{text}": INPUT N: PRINT LEFT$(A$, N); LEFT$(A$, 99); LEN(LEFT$(A$, 0))\n',
                    input_stream=io.StringIO("3\n")).splitlines()[-1] == f"{text[:3]}{text} 0 "


def test_right_string():  # RIGHT_STRING.md items 1-2
    text = "MNOPQRS"
    assert run_text(f'10 A$="{text}": PRINT RIGHT$(A$, 2); "|"; RIGHT$(A$, 40); RIGHT$(A$, 2.9)\n') == \
        f"{text[-2:]}|{text}{text[-2:]}\n"


def test_mid_string():  # MID_STRING.md items 1-3: to the end when the count is left out or too big
    text = "ABCDEFGHIJ"
    program = f'10 A$="{text}": PRINT MID$(A$, 3, 2); "|"; MID$(A$, 6); "|"; MID$(A$, 8, 50); LEN(MID$(A$, 11))\n'
    assert run_text(program) == f"{text[2:4]}|{text[5:]}|{text[7:]} 0 \n"


def test_len():  # LEN.md: control codes and spaces count
    assert run_values('10 PRINT LEN("A B"+CHR$(1)+CHR$(31)); LEN("")\n') == [[5.0, 0.0]]


def test_str_string():  # STR_STRING.md item 2: a leading space for a positive value, "-" for a negative
    assert run_text('10 N=407: S$=STR$(N): PRINT "["; S$; "]"; MID$(S$, 2, 1); STR$(-2.5)\n') == "[ 407]4-2.5\n"


def test_val():  # VAL.md items 1-3: digits up to the first that is none; "" or a letter first: 0
    assert run_values('10 PRINT VAL("123A456"); VAL("X9"); VAL(""); VAL("12")+VAL("30")\n') == \
        [[123.0, 0.0, 0.0, 42.0]]


# ------------------------------------------------------------------ assignment, data, remarks

def test_let():  # LET.md items 2-3: LET may be left out; a string into a number, and back, is TM
    assert run_values("10 LET P = 6\n20 Q = 7\n30 PRINT P * Q\n") == [[42.0]]
    assert error_of('10 LET P = "6"') == "Type mismatch in 10"
    assert error_of("10 Q$ = 7") == "Type mismatch in 10"


def test_data():  # DATA.md items 1-2: items separated by commas, read in turn, RESTORE to a line
    program = '10 READ P$, Q\n20 RESTORE 50: READ R$\n30 PRINT P$ + "/" + R$; Q * 2\n40 DATA MAY 7, 21\n50 DATA END\n'
    assert run_text(program) == "MAY 7/END 42 \n"


def test_read():  # READ.md items 2-4: in line order, a 0 item ends our loop; a text into a number: TM
    items = [4, 9, 1, 6, 0]
    program = (f"10 READ X: IF X <> 0 THEN S = S + X: GOTO 10\n20 PRINT S\n"
               f"100 DATA {items[0]}, {items[1]}\n110 DATA {', '.join(map(str, items[2:]))}\n")
    assert run_values(program) == [[float(sum(items))]]
    assert error_of("10 READ A\n20 DATA FIVE") == "Type mismatch in 10"  # was GW's Syntax error in 20
    assert run_values("10 ON ERROR GOTO 30\n20 READ A\n25 DATA Z\n30 PRINT ERR; ERL: END\n") == [[19.0, 20.0]]


def test_rem():  # REM.md items 1-3: REM or ' ends the line's statements; REM right after a statement: SN
    assert run_text("10 PRINT 1: REM PRINT 2\n20 ' PRINT 3\n30 PRINT 4 ' PRINT 5\n") == " 1 \n 4 \n"
    assert error_of("10 PRINT 6 REM 7") == "Syntax error in 10"


# ------------------------------------------------------------------ control flow

def test_end():  # END.md items 1, 2, 4: ends the run; open files are closed (written out)
    assert run_text("10 FOR I = 1 TO 9\n20 IF I > 3 THEN END\n30 PRINT I;\n40 NEXT I\n") == " 1  2  3 "


def test_end_closes_the_files(tmp_path):  # END.md item 2
    assert run('10 OPEN "CAS0:E1" FOR OUTPUT AS #1: PRINT #1, "KEPT": END', files=tmp_path).error is None
    assert run('10 OPEN "CAS0:E1" FOR INPUT AS #1: INPUT #1, A$: PRINT A$', files=tmp_path).text == "KEPT\n"


def test_for_next_step():  # FOR_NEXT_STEP.md items 1, 6, 7, 8
    assert run_values("10 FOR I=3 TO 10 STEP 3: NEXT I: PRINT I\n") == [[12.0]]  # item 7: one step past
    assert run_text('10 FOR J=5 TO 1: PRINT "IN": NEXT J: PRINT "OUT"\n') == "OUT\n"  # item 1
    total = sum(i * j / 2 for i in range(1, 13, 3) for j in range(2, 9))  # J from 1 to 4 by 0.5
    assert run_values("10 FOR I=1 TO 12 STEP 3\n20 FOR J=1 TO 4 STEP 0.5\n30 S=S+I*J\n40 NEXT J,I\n50 PRINT S\n") \
        == [[total]]  # item 6: NEXT J,I
    assert run_text("10 FOR I=1 TO 3: GOTO 30\n20 NEXT I: PRINT I: END\n30 PRINT I;: GOTO 20\n") == " 1  2  3  4 \n"


def test_input_takes_a_numeric_expression():  # INPUT.md items 5, 7, 9; part-12-2 TM
    program = "10 B=5: INPUT A: PRINT A: GOTO 10"
    answers = ["3*4", "B+1", "SQR 2", "B", "7", ""]
    result = run(program, "".join(a + "\n" for a in answers))
    printed = [line for line in result.text.splitlines() if not line.startswith("?")]
    assert [float(x) for x in printed] == [12.0, 6.0, pytest.approx(math.sqrt(2), rel=1e-9), 5.0, 7.0, 7.0]
    assert run("10 INPUT A", '"X"\n').error == "Type mismatch in 10"  # item 5
    # a name is its variable (0 until assigned), not Python's infinity or NaN
    assert run("10 inf=2: INPUT A, B: PRINT A; B", "inf\nnan\n").text.splitlines()[-1] == " 2  0 "
    assert run("10 INPUT A: PRINT A", "1+\n2\n").text.count("?Redo from start") == 1
    assert "?Redo from start" in run("10 INPUT A: PRINT A", "3*4\n2\n", dialect="gw").text  # gw: a number only


def _loops(depth: int, names: str = "ABDEGHJKLMPQRSUVWXYZ") -> list[str]:
    """``depth`` nested one-pass FOR statements over distinct two-character names."""
    return [f"FOR {names[k % 20]}{k // 20} = 1 TO 1" for k in range(depth)]


def test_for_nests_29_levels():  # FOR_NEXT_STEP.md item 4, specifications.md: 29 FOR levels; a 30th is OM
    for depth in (29, 30):
        fors = _loops(depth)
        body = fors + ["C = C + 1"] + ["NEXT"] * depth + ["PRINT C"]
        by_lines = "".join(f"{10 * (n + 1)} {statement}\n" for n, statement in enumerate(body))
        expected = (None, " 1 \n") if depth == 29 else (f"Out of memory in {10 * depth}", "")  # the 30th FOR's line
        assert (run(by_lines).error, run(by_lines).text) == expected
        one_line = run("10 " + ": ".join(body))
        assert (one_line.error, one_line.text) == ((None, " 1 \n") if depth == 29 else ("Out of memory in 10", ""))
        assert run(by_lines, dialect="gw").text == " 1 \n"  # GW-BASIC's stack holds more
    # a FOR that re-opens its loop (a GOTO back to it) takes no new level: 100 passes in 2 levels
    assert run_text("10 FOR I=1 TO 100: FOR J=1 TO 2\n20 C=C+1: GOTO 40\n30 NEXT J\n40 NEXT I: PRINT C\n") == " 100 \n"
    # RETURN closes the loops its subroutine opened; a subroutine's FOR at the 30th level is OM
    inside = _loops(28)
    sub = "90 FOR Z=1 TO 1: FOR Y=1 TO 1: N=N+1: NEXT Y, Z: RETURN"
    assert run("10 " + ": ".join(inside + ["GOSUB 90"] + ["NEXT"] * 28 + ["PRINT N: END"]) + "\n" + sub).error == \
        "Out of memory in 90"
    assert run("10 " + ": ".join(_loops(27) + ["GOSUB 90"] + ["NEXT"] * 27 + ["PRINT N: END"]) + "\n" + sub).text == " 1 \n"
    # ON ERROR sees the OM error's code 1 (part-12-2-error-messages.md)
    assert run("5 ON ERROR GOTO 90\n10 " + ": ".join(_loops(30)) + "\n90 PRINT ERR: END").text == " 1 \n"


def test_gosub():  # GOSUB.md items 1, 3: nested subroutines; a missing line is the UL error
    program = ('10 GOSUB 40\n20 PRINT "C"\n30 END\n40 PRINT "A";\n50 GOSUB 70\n60 RETURN\n'
               '70 PRINT "B";\n80 RETURN\n')
    assert run_text(program) == "ABC\n"
    assert error_of("10 GOSUB 500") == "Undefined line number 500 in 10"


def test_gosub_to_a_program_area_is_a_level(tmp_path):  # GOSUB.md: GOSUB #n; item 2's 96 levels
    for levels, error in ((96, None), (97, "Out of memory in 10 (PROG 1)")):
        area = tmp_path / f"deep{levels}.bas"
        area.write_text(f"10 N=N+1: IF N<{levels} THEN GOSUB #1\n20 RETURN\n")
        result = run("10 GOSUB #1: PRINT N", prog={1: str(area)})
        assert (result.error, result.text) == (error, " 96 \n" if error is None else "")


def test_gosub_nests_96_levels():  # GOSUB.md item 2: up to 96 levels; beyond, the OM error (code 1)
    def deep(levels: int, **options):
        return run(f'10 GOSUB 20: PRINT "BACK"; N: END\n20 N=N+1: IF N<{levels} THEN GOSUB 20\n30 RETURN', **options)
    assert (deep(96).text, deep(96).error) == ("BACK 96 \n", None)
    assert deep(97).error == "Out of memory in 20"  # was BACK 97
    assert deep(97, dialect="gw").text == "BACK 97 \n"  # GW-BASIC's stack holds more
    assert run("10 ON ERROR GOTO 40\n20 GOSUB 30\n30 ON 1 GOSUB 30\n40 PRINT ERR; N: END").text == " 1  0 \n"
    # a subroutine that only returns, called at the 96th level, is the 97th
    assert run("10 GOSUB 20: END\n20 N=N+1: IF N<96 THEN GOSUB 20: RETURN\n30 GOSUB 90: RETURN\n90 RETURN").error == \
        "Out of memory in 30"


def test_return():  # RETURN.md items 1-2: back after the GOSUB; without one the GS error (code 25)
    assert run_text('10 GOSUB 30: PRINT "BACK": END\n30 PRINT "SUB";: RETURN\n') == "SUBBACK\n"
    assert error_of("10 RETURN") == "RETURN without GOSUB in 10"
    assert run_values("10 ON ERROR GOTO 30\n20 RETURN\n30 PRINT ERR: END\n") == [[25.0]]


def test_on_gosub():  # ON_GOSUB.md items 1-2: the k-th destination; below 1 or past the list: on
    program = ("10 FOR I=1 TO 30\n20 ON (I MOD 3)+1 GOSUB 100, 200, 300\n30 NEXT I\n40 PRINT A; B; C\n50 END\n"
               "100 A=A+I: RETURN\n200 B=B+I: RETURN\n300 C=C+I: RETURN\n")
    sums = [sum(i for i in range(1, 31) if i % 3 == r) for r in range(3)]
    assert run_values(program) == [[float(s) for s in sums]]
    assert run_text('10 ON 0 GOSUB 90: ON 4 GOSUB 90, 90: PRINT "ON": END\n90 PRINT "NO": RETURN\n') == "ON\n"


def test_stop():  # STOP.md items 1, 4: halts, variables kept; EXE (CONT) goes on
    shown = []
    session = Session(write=shown.append, engine=MachineEngine(shown.append))
    for line in ("10 FOR I=1 TO 5", "20 IF I=3 THEN STOP", "30 PRINT I;", "40 NEXT I", "RUN"):
        session.handle(line)
    assert "".join(shown) == " 1  2 \nBreak in 20\n"
    shown.clear()
    session.handle("PRINT I")
    session.handle("CONT")
    assert "".join(shown) == " 3 \n 3  4  5 \n"


def test_erl():  # ERL.md: the line the error happened in
    assert run_text('10 ON ERROR GOTO 40\n20 A = 1 / 0\n30 END\n40 PRINT "LINE"; ERL: RESUME 30\n') == "LINE 20 \n"


def test_err():  # ERR.md, part-12-2: the error's code (a division by zero: MA, 14)
    assert run_text('10 ON ERROR GOTO 40\n20 A = LOG(0)\n30 END\n40 PRINT "CODE"; ERR: RESUME 30\n') == "CODE 14 \n"


# ------------------------------------------------------------------ functions

def test_exp():  # EXP.md: e to the x, up to 230
    rows = run_values("10 INPUT N: PRINT EXP N; EXP(-1)\n", input_stream=io.StringIO("230\n"))
    assert abs(rows[-1][0] - float(mpmath.exp(230))) <= 1e-9 * float(mpmath.exp(230))
    assert abs(rows[-1][1] - math.exp(-1)) < 1e-10


def test_peek():  # PEEK.md: DEFSEG*16 + address; a negative address counts from 65536
    assert run_values("10 DEFSEG=0: POKE 65535, 99: POKE &H7000, 7\n20 PRINT PEEK(-1); PEEK(&H7000)\n") == \
        [[99.0, 7.0]]
    assert run_values("10 DEFSEG=3: POKE &H10, 42: DEFSEG=0: PRINT PEEK(3*16+16)\n") == [[42.0]]


# ------------------------------------------------------------------ keyboard and screen

def test_inkey_string():  # INKEY_STRING.md item 1: "" while no key is pressed, then the key
    program = '10 C$=INKEY$: IF C$="" THEN N=N+1: GOTO 10\n20 PRINT "KEY "; C$; N > 0\n'
    assert run(program, "Q").text == "KEY Q-1 \n"


def test_input_string():  # INPUT_STRING.md items 1, 3: n characters, not shown; our sample's code 4711
    program = '10 PRINT "CODE";\n20 C$=INPUT$(4)\n30 IF C$<>"4711" THEN 10\n40 PRINT: PRINT "OPEN"\n'
    assert run(program, "12344711").text == "CODECODE\nOPEN\n"


def test_locate():  # LOCATE.md: (0,0) the upper left, x to the right, y down; x < 32, y < 8
    result = run('10 CLS: LOCATE 4,1: PRINT "LOW";: LOCATE 0,0: PRINT "TOP";')
    assert result.screens[-1] == "TOP\n    LOW\n"
    assert run("10 LOCATE 32,0").error == "Illegal function call in 10"
    assert run("10 LOCATE 0,8").error == "Illegal function call in 10"


# ------------------------------------------------------------------ program listing to the printer

def test_llist():  # LLIST.md items 1-2: the range to the printer, nothing on the display
    printer = io.StringIO()
    result = run('10 PRINT "SHOWN"\n20 LLIST 20-30\n30 REM LAST\n40 REM NOT', printer=printer)
    assert result.text == "SHOWN\n"
    assert printer.getvalue().split("\n")[:2] == ["20 LLIST 20-30", "30 REM LAST"]


# ------------------------------------------------------------------ sequential files

def test_print_hash_and_input_hash(tmp_path):  # PRINT_HASH.md, INPUT_HASH.md items 2, 4
    program = ('10 OPEN "CAS0:SEQ" FOR OUTPUT AS #1\n20 PRINT #1, "  RED,BLUE": PRINT #1, " 12 34"\n30 CLOSE\n'
               '40 OPEN "CAS0:SEQ" FOR INPUT AS #1\n50 INPUT #1, A$, B$, X, Y\n60 CLOSE: PRINT A$; "|"; B$; X + Y\n')
    assert run(program, files=tmp_path).text == "RED|BLUE 46 \n"  # leading blanks dropped, a blank delimits numbers
    assert (tmp_path / "SEQ").read_bytes().startswith(b"  RED,BLUE\r\n")  # item 3: CR LF after the data


def test_eof(tmp_path):  # EOF.md items 1, 4: -1 after the last record; 0 for a file opened for output
    program = ('10 OPEN "CAS0:REC" FOR OUTPUT AS #1: PRINT #1, "A": PRINT #1, "B": PRINT EOF(1): CLOSE\n'
               '20 OPEN "CAS0:REC" FOR INPUT AS #1\n30 INPUT #1, A$: PRINT A$; EOF(1)\n40 IF NOT EOF(1) THEN 30\n'
               '50 CLOSE\n')
    assert run(program, files=tmp_path).text == " 0 \nA 0 \nB-1 \n"  # EOF(1) for output was Bad file mode


def test_close(tmp_path):  # CLOSE.md items 1-2: no error when nothing is open
    assert run("10 CLOSE: CLOSE: PRINT 1").text == " 1 \n"


# ------------------------------------------------------------------ the DATA BANK

BANK = '10 NEW#: WRITE# "OAK", 30: WRITE# "ELM", 12: WRITE# "ASH", 7\n'


def test_write_hash():  # WRITE_HASH.md: records of items at the pointer
    assert run(BANK + "20 LIST#").text == "1 OAK, 30\n2 ELM, 12\n3 ASH, 7\n"


def test_read_hash():  # READ_HASH.md: item after item, across records
    assert run(BANK + "20 RESTORE#: READ# A$, A, B$, B: PRINT A$; B$; A + B").text == "OAKELM 42 \n"


def test_restore_hash():  # RESTORE_HASH.md: to the next item beginning with the text
    assert run(BANK + '20 RESTORE#: RESTORE# "AS": READ# C$, C: PRINT C$; C').text == "ASH 7 \n"


def test_list_hash():  # LIST_HASH.md items 1-2: the records in sequence, each after its record number
    records = ["OAK, 30", "ELM, 12", "ASH, 7"]
    assert run(BANK + "20 LIST#").text.splitlines() == [f"{n} {r}" for n, r in enumerate(records, 1)]
    # part 5: the record number is the DATA BANK's line number: a record written later is listed later
    assert run(BANK + '20 WRITE# "FIR", 2: LIST#').text.splitlines()[-1] == "4 FIR, 2"


def test_new_hash():  # NEW_HASH.md item 1: all records cleared
    assert run(BANK + "20 NEW#: LIST#: RESTORE#: READ# A$").error == "Out of DATA in 20"


def test_save_hash_and_load_hash(tmp_path):  # SAVE_HASH.md items 1-3, LOAD_HASH.md items 1-2 (,M appends)
    program = BANK + '20 SAVE# "CAS0:TREES": NEW#: LOAD# "TREES": LOAD# "CAS0:TREES", M: LIST#'
    assert run(program, files=tmp_path).text.splitlines() == [f"{n} {r}" for n, r in enumerate(["OAK, 30", "ELM, 12", "ASH, 7"] * 2, 1)]


def test_llist_hash():  # LLIST_HASH.md items 1-3: the records to the printer; not with a password
    printer = io.StringIO()
    result = run(BANK + '20 LLIST#: PRINT "DONE"', printer=printer)
    assert (result.text, printer.getvalue()) == ("DONE\n", "1 OAK, 30\n2 ELM, 12\n3 ASH, 7\n")  # was a Syntax error
    assert run(BANK + '20 PASS "K": LLIST#').error == "Password protected in 20"


def test_cls():  # CLS.md: the screen cleared, the cursor at the home position; PRINT CHR$(12) the same
    assert run('10 PRINT "OLD";: LOCATE 5,1: PRINT "X";: CLS: PRINT "NEW";').screens[-1] == "NEW\n\n"
    assert run('10 LOCATE 3,1: PRINT "OLD";: PRINT CHR$(12);: PRINT "NEW";').screens[-1] == "NEW\n\n"
