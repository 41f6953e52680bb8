"""GW-BASIC's error codes and the order of its checks, as a real GW-BASIC 3.23 recorded them in
PC-BASIC's test suite (github robhagemans/pcbasic, tests/basic: each test's ``model/`` files).
Our own small programs, each naming the recording and the source routine it follows."""

from __future__ import annotations

from test_differential_support import run_gw

TRAP = "\n900 PRINT ERR; ERL: RESUME NEXT"


def test_rnd_of_a_double_beyond_single_range_is_overflow():
    # recorded unsorted/RND1: RND of the largest MBF double is error 6; MATH2.ASM $RND works on
    # a single, so the argument is made one first (FRCSNG), which overflows.
    out = run_gw("10 ON ERROR GOTO 900\n20 PRINT RND(1.701411834604692D+38)\n30 X# = 1.70141183D+38: PRINT RND(X#)"
                 "\n40 PRINT RND(1D+38) > 0\n50 END" + TRAP)
    assert out == " 6  20 \n 6  30 \n-1 \n"


def test_clear_reads_its_places_one_by_one_with_gw_basics_errors():
    # recorded unsorted/CLEARERR (BIMISC.ASM CLEAR): n by INTID2 (negative Illegal function call,
    # beyond 16 bits Overflow), m and k by GETMPM (0 Illegal function call), m above 65534 Out of
    # memory; an empty last place after a comma and a fourth place are Syntax errors (where the
    # published source would clear); a CLEAR that fails clears nothing (A keeps 7, the trap stays).
    source = """10 ON ERROR GOTO 900
20 A = 7
30 CLEAR -5
40 CLEAR 40000
50 CLEAR 1, 0
60 CLEAR , 1000, 0
70 CLEAR 3, 65535
80 CLEAR 2,
90 CLEAR ,,
100 CLEAR 1, 2000, 300, 4
110 CLEAR -1,
120 PRINT A
130 CLEAR , 65534, 512
140 PRINT A: END""" + TRAP
    assert run_gw(source) == (" 5  30 \n 6  40 \n 5  50 \n 5  60 \n 7  70 \n 2  80 \n 2  90 \n 2  100 \n"
                              " 5  110 \n 7 \n 0 \n")


def test_clear_stack_size_beyond_what_the_segment_can_give_is_out_of_memory():
    # the published source, BIMISC.ASM CLEART (no recording checks it): a stack of at most
    # 2 * NUMLEV + 20 = 240 bytes (OEM.H), or one reaching the top of memory, is Out of memory
    source = "10 ON ERROR GOTO 900\n20 CLEAR ,,240\n30 CLEAR , 30000, 30000\n40 CLEAR ,,241: PRINT \"ok\": END" + TRAP
    assert run_gw(source) == " 7  20 \n 7  30 \nok\n"


def test_numbers_after_erl_are_line_numbers_digits_only():
    # recorded unsorted/ERL: after ERL (a word of GWMAIN.ASM CRUNCH's LINRES list) a number is
    # crunched as a line number by LINGET, digits only up to 65529, up to the next word, name or
    # colon: ERL(2.5) is ERL then (2 .5), a Syntax error once ERL is printed; ERL(40000) is ERL then
    # 40000; ERL(65530) is (6553 0) and ERL(1E2) is (1 E2), Syntax errors.  PC-BASIC 2.0.8 agrees.
    source = """10 ON ERROR GOTO 900
20 PRINT ERL(2.5)
30 PRINT ERL(40000)
40 PRINT ERL(65530)
50 PRINT ERL(1E2)
60 A = ERL: B = 1.5: PRINT A; B: IF ERL = 50 THEN PRINT 2.5 ELSE 70
70 END""" + TRAP
    assert run_gw(source) == " 0  2  20 \n 20  40000 \n 20  2  40 \n 40  2  50 \n 50  1.5 \n 2.5 \n"


def test_a_file_function_cut_before_its_parenthesis_checks_the_file_first(tmp_path, monkeypatch):
    # recorded unsorted/FILEXPR: VARPTR(#n and IOCTL$(#n without the ")" find the file first
    # (VARPTR: GWEVAL.ASM GTBYTC, GETPTR: blocks 0..3, beyond Bad file number; IOCTL$: an open
    # file), then the missing ")" is a Syntax error; IOCTL$(#1) of a disk file is Illegal
    # function call, as the recorded IOCTL$ test shows.
    source = """10 ON ERROR GOTO 900
20 OPEN "A.TXT" FOR OUTPUT AS 2
30 PRINT VARPTR(#3
40 PRINT VARPTR(#5
50 PRINT IOCTL$(#2
60 PRINT IOCTL$(#0
70 PRINT IOCTL$(#3
80 PRINT IOCTL$(#2)
90 CLOSE: KILL "A.TXT": END""" + TRAP
    monkeypatch.chdir(tmp_path)
    assert run_gw(source) == " 2  30 \n 52  40 \n 2  50 \n 52  60 \n 52  70 \n 5  80 \n"


def test_varptr_cut_after_its_parenthesis_is_syntax_error():
    # GWEVAL.ASM VARPTR: after "(" PTRGTN must find a name, else SNERR (not the Missing
    # operand of an expression cut short); PC-BASIC 2.0.8 agrees
    assert run_gw("10 ON ERROR GOTO 900\n20 PRINT VARPTR(\n30 PRINT 1; VARPTR(\n40 END" + TRAP) == " 2  20 \n 1  2  30 \n"


def test_date_set_refuses_years_before_1980_and_shows_a_day_beyond_its_month_as_set():
    # recorded gwbasic/faulty_DATE: two-digit 78 and 79 (GWSTS.ASM PRSDAT: 19yy) and 1979 are
    # error 5 (DOS's set-date call), 32 days too, while 02-30-2000 is taken and DATE$ shows it
    source = """10 ON ERROR GOTO 900
20 DATE$ = "06-15-79"
30 DATE$ = "6/15/1979"
40 DATE$ = "4-32-1990"
50 DATE$ = "02-31-2001": PRINT DATE$
60 DATE$ = "7-4-80": PRINT DATE$
70 END""" + TRAP
    assert run_gw(source) == " 5  20 \n 5  30 \n 5  40 \n02-31-2001\n07-04-1980\n"
