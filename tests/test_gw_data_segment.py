"""gw's data segment from the program up (machine/data_segment.py): VARPTR and VARPTR$ of
simple variables and array elements, PEEK of the program text, the variable and array
tables, the strings, and GW's pointers to them (&H30 TXTTAB, &H358 VARTAB, &H35A ARYTAB,
&H35C STREND, &H2C the top of memory).

The numbers are those the recordings of a real GW-BASIC 3.23 in PC-BASIC's test suite show
(the program at 4718; a variable's 4-byte header before its value; the first string ending
at 65021; an array's header with its size, dimension count and counts; a DEF FN's entry
pointing after its name), and PC-BASIC 2.0.8, which lays the segment out the same way, is
the differential reference for each program here.
"""

from __future__ import annotations

import pytest

from test_gw_files import both_runs, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def _files_alike(source: str, tmp_path) -> list[str]:
    """Run ``source`` in both; O.TXT's rows, asserted equal to PC-BASIC's."""
    _, _, ours, theirs = both_runs(source, tmp_path)
    assert ours == theirs
    return ours["O.TXT"].decode("latin-1").split("\r\n")


SCALARS = """\
10 OPEN "O.TXT" FOR OUTPUT AS 1
20 Q% = -2: ZETA = 1.5: D# = 1 / 3: S$ = "ab" + "c": LONGNAME% = 7
30 PRINT #1, PEEK(&H30) + 256 * PEEK(&H31); PEEK(&H358) + 256 * PEEK(&H359)
40 PRINT #1, VARPTR(Q%); VARPTR(ZETA); VARPTR(D#); VARPTR(S$); VARPTR(LONGNAME%)
50 FOR I = VARPTR(Q%) - 4 TO VARPTR(LONGNAME%) + 1: PRINT #1, PEEK(I);: NEXT: PRINT #1,
60 P = PEEK(VARPTR(S$) + 1) + 256 * PEEK(VARPTR(S$) + 2): PRINT #1, P; CHR$(PEEK(P)); CHR$(PEEK(P + 2))
70 CLOSE
"""


def test_simple_variables_lie_after_the_program_in_the_order_they_were_made(tmp_path):
    """VARTAB follows the program's text (TXTTAB 4718, GWMAIN.ASM); each variable a header
    (type, two letters, the count of the others with bit 7 set) and its value: an integer
    low byte first, a single and a double in Microsoft's binary format, a string's
    descriptor pointing at its characters at the top of the string space (65021 down)."""
    rows = _files_alike(SCALARS, tmp_path)
    assert rows[0].split()[0] == "4718"
    addresses = [int(x) for x in rows[1].split()]
    assert [b - a for a, b in zip(addresses, addresses[1:])] == [2 + 6, 4 + 4, 8 + 4, 3 + 10]  # (ZETA: 2 more letters)
    assert rows[2].split()[:6] == ["2", "81", "0", "0", "254", "255"]  # Q%: type 2, "Q", -2
    assert rows[3].split() == [str(65021 - 3), "ac"]


ARRAYS = """\
10 OPEN "O.TXT" FOR OUTPUT AS 1: P = 0: Q = 0: I = 0
20 DIM B%(2): B%(1) = 5: B%(2) = -1: X = 1: C!(3) = 2
30 PRINT #1, PEEK(&H35A) + 256 * PEEK(&H35B); PEEK(&H35C) + 256 * PEEK(&H35D)
40 PRINT #1, VARPTR(B%(0)); VARPTR(B%(1)); VARPTR(C!(3)); ASC(VARPTR$(C!(1))); ASC(VARPTR$(B%(0)))
50 P = VARPTR(B%(0)) - 9: Q = VARPTR(B%(2)) + 1: FOR I = P TO Q: PRINT #1, PEEK(I);: NEXT: PRINT #1,
60 ERASE B%: PRINT #1, VARPTR(C!(3)); VARPTR(X)
70 CLOSE
"""


def test_arrays_lie_after_the_variables(tmp_path):
    """ARYTAB after the simple variables (a variable made after an array moves the arrays
    up); an array's header: name, the bytes after the size word, the dimension count and
    each dimension's element count; its elements; ERASE moves the later arrays down."""
    rows = _files_alike(ARRAYS, tmp_path)
    first = [int(x) for x in rows[1].split()]
    assert first[1] - first[0] == 2 and first[3:] == [4, 2]
    assert rows[2].split() == ["2", "66", "0", "0", "9", "0", "1", "3", "0", "0", "0", "5", "0", "255", "255"]
    assert int(rows[3].split()[0]) == first[2] - 9 - 6  # C! moved down over B%'s 15 bytes


def test_a_two_dimensional_array_counts_the_last_dimension_first(tmp_path):
    """BIPTRG.ASM ISARY stores the element counts as it pops the subscripts it pushed: the
    last dimension's first; the elements run with the first subscript fastest (PC-BASIC
    2.0.8 stores the first dimension's count first: the source decides)."""
    source = """\
10 I = 0: DIM B%(2, 1): B%(1, 0) = 5: B%(2, 1) = 9: P = VARPTR(B%(0, 0))
20 PRINT VARPTR(B%(1, 0)) - P; VARPTR(B%(0, 1)) - P
30 FOR I = P - 5 TO P + 11: PRINT PEEK(I);: NEXT
"""
    rows = yaseer_run(source, tmp_path).split("\n")
    assert rows[0].split() == ["2", "6"]
    assert rows[1].split() == ["2", "2", "0", "3", "0", "0", "0", "5", "0", "0", "0", "0", "0", "0", "0", "9", "0"]


UNMADE = """\
10 OPEN "O.TXT" FOR OUTPUT AS 1: ON ERROR GOTO 100
20 PRINT #1, VARPTR(A)
30 PRINT #1, VARPTR(B(10)); VARPTR(B(11))
40 PRINT #1, VARPTR$(C$)
50 C$ = "": PRINT #1, VARPTR(C$) > 0
60 CLOSE: END
100 PRINT #1, "error"; ERR; ERL: RESUME NEXT
"""


def test_varptr_of_a_variable_not_made_is_illegal_function_call(tmp_path):
    """PTRGET makes no simple variable for VARPTR: Illegal function call (recorded:
    VARPTR_on_undefined_variables); an element's array is made (10 entries), a subscript
    beyond it Subscript out of range; an assignment of "" makes the variable."""
    rows = _files_alike(UNMADE, tmp_path)
    assert rows[0] == "error 5  20 "
    assert rows[1].endswith(" error 9  30 ")  # B(10) printed, then B(11)
    assert rows[2] == "error 5  40 "
    assert rows[3] == "-1 "


FUNCTIONS = """\
10 OPEN "O.TXT" FOR OUTPUT AS 1
20 K = 3: DEF FNQ%(Y) = Y * 2: Z = 4
30 P = VARPTR(K) + 4: FOR I = P TO P + 7: PRINT #1, PEEK(I);: NEXT: PRINT #1,
40 A = PEEK(P + 4) + 256 * PEEK(P + 5): PRINT #1, CHR$(PEEK(A)); CHR$(PEEK(A + 1)); VARPTR(Z) - VARPTR(K)
50 CLOSE
"""


def test_a_def_fn_is_an_entry_among_the_variables(tmp_path):
    """DEF FN makes an entry where it runs (GWEVAL.ASM DEF, GETFNM): its first letter with
    bit 7 set, of the function's type, holding the address of the text after its name in
    the DEF statement (recorded: PEEKFN)."""
    rows = _files_alike(FUNCTIONS, tmp_path)
    assert rows[0].split()[:4] == ["2", str(ord("Q") | 128), "0", "0"]
    assert rows[1] == "(Y 22 "  # FNQ%'s 6 bytes, then Y: the DEF made its parameter (SCNLIS)


def test_the_pointers_follow_the_program_and_its_variables(tmp_path):
    """&H358, &H35A, &H35C move as the variables and arrays are made (recorded:
    data_segment_current_pointers, MID$_statement_on_unallocated_scalar_and_array); the
    top of memory at &H2C is 65534."""
    source = """\
10 OPEN "O.TXT" FOR OUTPUT AS 1: GOSUB 100: A = 1: GOSUB 100: DIM B(1): GOSUB 100: CLOSE: END
100 PRINT #1, PEEK(&H2C) + 256 * PEEK(&H2D); PEEK(&H358) + 256 * PEEK(&H359);
110 PRINT #1, PEEK(&H35A) + 256 * PEEK(&H35B); PEEK(&H35C) + 256 * PEEK(&H35D): RETURN
"""
    rows = [[int(x) for x in row.split()] for row in _files_alike(source, tmp_path)[:3]]
    assert rows[0][0] == 65534
    assert rows[1][2] - rows[0][2] == 8  # A: header and a single
    assert rows[2][3] - rows[1][3] == 4 + 2 + 1 + 2 + 2 * 4


def test_lset_of_a_variable_holding_a_literal_copies_it_to_the_string_space(tmp_path):
    """DSKCOM.ASM LSET: a variable pointing into the program text gets a string of its own
    (FRE drops by its length, recorded: CODESTR); a second LSET writes into that one."""
    source = """\
10 OPEN "O.TXT" FOR OUTPUT AS 1: A$ = "12345": F = FRE(0)
20 LSET A$ = "abcde": PRINT #1, F - FRE(0); PEEK(VARPTR(A$) + 2)
30 LSET A$ = "xy": PRINT #1, F - FRE(0); PEEK(VARPTR(A$) + 1) + 256 * PEEK(VARPTR(A$) + 2); A$
40 CLOSE
"""
    rows = _files_alike(source, tmp_path)
    assert rows[0] == " 5  253 "
    assert rows[1] == f" 5  {65021 - 5} xy   "


def test_casio_has_no_varptr(tmp_path):
    """The Casio has no VARPTR: its word stays unsupported there."""
    assert "VARPTR" in yaseer_run("10 PRINT VARPTR(A)\n", tmp_path, dialect="casio")


GARBAGE = """\
10 OPEN "O.TXT" FOR OUTPUT AS 1: A$ = "ab" + "c": B$ = "de" + "f": GOSUB 100
20 A$ = "gh" + "ij": GOSUB 100
30 X = FRE(""): GOSUB 100: CLOSE: END
100 PRINT #1, PEEK(VARPTR(A$) + 1) + 256 * PEEK(VARPTR(A$) + 2); PEEK(VARPTR(B$) + 1) + 256 * PEEK(VARPTR(B$) + 2)
110 RETURN
"""


def test_a_new_string_goes_below_the_garbage_until_a_collection_moves_them_up(tmp_path):
    """Each new string lies at FRETOP, below the strings and the garbage before it
    (BISTRS.ASM GETSPA); FRE("") collects the garbage, moving the strings kept up to the
    top in the order they lay (GARBAG; recorded: DEFFNGRB, STRGARBG)."""
    rows = [[int(x) for x in row.split()] for row in _files_alike(GARBAGE, tmp_path)[:3]]
    assert rows[0] == [65021 - 3, 65021 - 6]
    assert rows[1] == [65021 - 10, 65021 - 6]
    assert rows[2] == [65021 - 3 - 4, 65021 - 3]


def test_chain_copies_a_common_literal_below_the_other_strings(tmp_path):
    """CHAIN keeps the variables, not the old program's text: a COMMON string that was a
    literal there gets a copy in the string space, below the others (recorded: STRCOMN)."""
    (tmp_path / "NEXT.BAS").write_text(
        '10 OPEN "O.TXT" FOR OUTPUT AS 1\n'
        '20 PRINT #1, PEEK(VARPTR(A$) + 1) + 256 * PEEK(VARPTR(A$) + 2); PEEK(VARPTR(B$) + 1) + 256 * PEEK(VARPTR(B$) + 2)\n'
        '30 CLOSE\n')
    source = '10 COMMON A$, B$\n20 A$ = "lit": B$ = "mad" + "e": CHAIN "NEXT.BAS"\n'
    assert yaseer_run(source, tmp_path) == ""
    assert (tmp_path / "O.TXT").read_bytes().split() == [str(65021 - 4 - 3).encode(), str(65021 - 4).encode(), b"\x1a"]


@pytest.mark.parametrize("statement, expected", [
    ("A% = 1: P$ = VARPTR$(A%): PRINT ASC(P$); CVI(MID$(P$, 2)) = VARPTR(A%)", " 2 -1 \n"),
    ("PRINT VARPTR$(", "Syntax error in 10\n"),
    ('PRINT VARPTR$("ABC")', "Syntax error in 10\n"),
    ("PRINT VARPTR$(1)", "Syntax error in 10\n"),
    ("PRINT VARPTR$(A, 1)", "Syntax error in 10\n"),
    ("PRINT VARPTR$", "Syntax error in 10\n"),
])
def test_varptr_dollar_reads_a_variable_as_varptr_does(tmp_path, statement, expected):
    """VARPTR$ is VARPTR's string: the type byte and the address, low byte first
    (GWEVAL.ASM VARPTR); its argument must be a variable, else Syntax error, cut short too
    (recorded: unsorted/VARPTR, lines 1050-1340)."""
    assert yaseer_run(f"10 {statement}\n", tmp_path) == expected
