"""Resource limits end a run with a period-style error naming the line, not a Python crash.

GOSUB depth, FOR nesting, recursion through DEF FN, array size, string length and
expression nesting each have a limit (issue 8); a program that reaches it stops with
``Out of memory in N`` / ``String too long in N`` like the machines of the period did.
"""

from __future__ import annotations

import pytest
from test_fuzz_listings import run_mutant

import yaseer


@pytest.mark.parametrize(
    "source, expected",
    [
        ("10 GOSUB 10\n", "Out of memory in 10"),  # unbounded GOSUB depth
        ("10 X = X + 1: FOR I = 1 TO 2: GOSUB 10\n", "Out of memory in 10"),  # FOR frames piling up
        ("10 DEF FNA(X) = FNA(X) + 1: PRINT FNA(1)\n", "Out of memory in 10"),  # recursion in DEF FN
        ("10 DIM A(3000000)\n", "Out of memory in 10"),
        ("10 DIM A(1000, 1000, 1000)\n", "Out of memory in 10"),
        ('10 A$ = "x": FOR I = 1 TO 9: A$ = A$ + A$: NEXT\n', "String too long in 10"),
        ("10 PRINT 1\n20 X = " + "-" * 5000 + "1\n", "Out of memory in 20"),
        ("10 PRINT 1\n20 X = " + "NOT " * 3000 + "1\n", "Out of memory in 20"),
        ("10 X = 1E308 * 10\n", "Overflow in 10"),
        ('10 A$ = "' + "x" * 256 + '"\n', "String too long in 10"),  # a literal one over 255
        ("10 READ A$\n20 DATA " + "y" * 256 + "\n", "String too long in 20"),  # DATA: named at its line
        ('10 LINE INPUT A$\n', "Input past end in 10"),  # (nothing typed)
        ('10 OPEN "I", 1, STRING$(200, 233)\n', "Bad file name in 10"),  # a name part of 400 UTF-8 bytes
        ('10 KILL STRING$(130, 233)\n', "Bad file name in 10"),  # 260 bytes
    ],
)
def test_limit_is_a_basic_error_naming_the_line(source, expected):
    assert run_mutant(source, with_prog5=False) == expected


def test_same_variable_for_loop_reentered_by_goto_reuses_its_frame():
    """MS-BASIC replaces the frame of a FOR on the same variable: this loops, it does not fill memory."""
    outcome = run_mutant("10 N = N + 1: FOR I = 1 TO 2\n20 GOTO 10\n", with_prog5=False)
    assert outcome in ("Break in 10", "Break in 20")  # wherever the interrupt lands


def test_the_largest_allowed_array_works():
    # gw's arrays end at GW-BASIC's 64 KB segment (test_gw_memory), casio's at the FX-850P's
    # 8192-byte variable area (CLEAR.md: test_casio_words), both before yaseer's own budget
    for source in ('10 DIM A(14000): A(14000) = 1: PRINT A(14000)\n',
                   '10 DIM A$(14000): A$(14000) = "x": PRINT A$(14000)\n'):
        result = yaseer.run(source, dialect="gw")
        assert result.error is None, result.error
    assert yaseer.run('10 DIM A(30000)\n', dialect="gw").error == "Out of memory in 10"
    # a size beyond 32767 is no integer: GWMAIN.ASM DIM's INTIDX calls FRCINT (PC-BASIC 2.0.8 agrees)
    assert yaseer.run('10 DIM A(1999999)\n', dialect="gw").error == "Overflow in 10"
    assert run_mutant('10 DIM A(1999999)\n', with_prog5=False) == "Out of memory in 10"


def test_arrays_of_full_strings_stay_inside_the_budget():
    """A string element takes its share of what it can hold (8 + 255 bytes): four arrays of two
    million strings once took 2.5 GB while FRE said 0; now the first is Out of memory."""
    program = "10 DIM A$(1999999), B$(1999999), C$(1999999), D$(1999999)\n"
    assert run_mutant(program, with_prog5=False) == "Out of memory in 10"
    # the budget itself (casio: its 8 KB first); gw's sizes are integers (beyond 32767 Overflow)
    program = "10 DIM A$(1999, 999), B$(1999, 999), C$(1999, 999), D$(1999, 999)\n"
    assert yaseer.run(program, dialect="gw").error == "Out of memory in 10"
    # FRE tells each machine's own memory, not this budget: GW's free bytes (test_gw_memory)
    # and the FX-850P's variable area (test_casio_words).


@pytest.mark.parametrize("limit", ["1E9", "1E12", "1E300"])
def test_a_long_empty_loop_runs_until_interrupted_not_out_of_memory(limit):
    """A loop's pass count is not a memory size (one committed state said Out of memory here).
    An empty body is counted in C, in chunks: 1E9 passes may end before the interrupt
    (seconds on a quiet machine); 1E12 cannot."""
    outcome = run_mutant(f"10 FOR I = 1 TO {limit}: NEXT\n", with_prog5=False)
    assert outcome in (("Break in 10", "ok") if limit == "1E9" else ("Break in 10",))


def test_a_listing_over_the_bound_is_out_of_memory_before_parsing():
    """A 5 MB listing once took 142 s and 2.6 GB to compile; over 256 KiB nothing is parsed.  A
    listing just under the bound runs."""
    import yaseer
    from yaseer.basic.machine.machine import MAX_LISTING_CHARACTERS

    line = "10 PRINT 1\n"
    over = line * (MAX_LISTING_CHARACTERS // len(line) + 1)
    assert yaseer.run(over).error == "Out of memory"
    under = "".join(f"{n} X = {n}\n" for n in range(1, 16000))
    assert len(under) < MAX_LISTING_CHARACTERS and yaseer.run(under + "16000 PRINT X\n").text == " 15999 \n"


def test_code_that_would_take_python_too_long_to_compile_is_out_of_memory():
    """gw single-precision arithmetic is rounded inline: a line of 40 operations is 20 kB of
    Python (about 2 MB of the compiler's memory); 250 of them are refused before Python compiles."""
    import yaseer

    line = "X = " + " + ".join(f"A{j} * B{j}" for j in range(20))
    listing = "".join(f"{10 * n} {line}\n" for n in range(1, 251))
    assert yaseer.run(listing, dialect="gw").error == "Out of memory"
    assert yaseer.run(listing, dialect="casio").error is None  # the same text in casio is plain Python


@pytest.mark.parametrize("statement", ['CHAIN "BIG.BAS"', 'RUN "BIG.BAS"', 'LOAD "BIG.BAS", R'])
def test_a_chained_listing_over_the_bound_is_out_of_memory(tmp_path, statement):
    import yaseer
    from yaseer.basic.machine.machine import MAX_LISTING_CHARACTERS

    (tmp_path / "BIG.BAS").write_text("".join(f"{n} X = {n}\n" for n in range(1, 40000)))
    assert (tmp_path / "BIG.BAS").stat().st_size > MAX_LISTING_CHARACTERS
    result = yaseer.run(f"10 {statement}\n", dialect="gw", files=tmp_path)
    assert result.error is not None and result.error.startswith("Out of memory"), result.error
