"""GW-BASIC's DELETE range (yaseer/basic/source/line_ranges.py) as the source reads it:
GWMAIN.ASM SCNLIN makes a left-out first line 0 and a left-out last line 65530, FNDLIN finds
the first line from the first number on, then must find the last number exactly (GWLIST.ASM
DELETE: "MUST HAVE A MATCH ON THE UPPER BOUND", else FCERR), and the first line found must
come before the line after the last.  So a range ending on a missing line is ``Illegal
function call``; FIVEO.ASM CHAIN reads its DELETE option the same way.  A DELETE whose last
line is left out (``DELETE``, ``DELETE -``, ``DELETE 20-``) deletes to the program's end: a
real GW-BASIC 3.23 recorded ``DELETE 60-`` doing so (PC-BASIC's DELETE test), where the
source would refuse it; CHAIN's option keeps the exact match (PC-BASIC 2.0.8 agrees).

The expectations come from the source's steps written below over a list of line numbers
(:func:`source_delete`); PC-BASIC 2.0.8 deletes every line in such a range instead (and
everything for ``DELETE`` alone), so it is the reference only for the ranges where it and
the source agree: those ending on a line of the program.
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count, clean_output
from test_gw_files import pcbasic_run, yaseer_run
from test_gw_protected import gw_session, pc, typed  # noqa: F401 (pc: the fixture)

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

ABOVE_EVERY_LINE = 65530  # SCNLIN's upper bound when none is given


def source_delete(lines: list[int], first: int | None, last: int | None) -> list[int] | None:
    """The lines left after DELETE first-last as GWLIST.ASM DELETE runs it (None: Illegal
    function call).  ``find(n)``: FNDLIN's walk along the sorted lines: the index of the
    first line >= n, and whether it is n (the carry)."""
    def find(n: int) -> tuple[int, bool]:
        k = 0
        while k < len(lines) and lines[k] < n:
            k += 1
        return k, k < len(lines) and lines[k] == n

    start, _ = find(0 if first is None else first)
    if last is None:  # (the recorded machine: to the program's end)
        return lines[:start] if start < len(lines) else None
    end, exact = find(last)
    if not exact or not start < end + 1:  # JAE FCERRG; CMP BX,DX / JNAE
        return None
    return lines[:start] + lines[end + 1:]


def range_text(first: int | None, last: int | None, dash: bool) -> str:
    """``first-last`` (a single number without the dash)."""
    if not dash:
        return str(first)
    return ("" if first is None else str(first)) + "-" + ("" if last is None else str(last))


def random_range(rng: random.Random, lines: list[int]) -> tuple[int | None, int | None, bool]:
    """A DELETE range: numbers on lines, between them or beyond, either left out."""
    def number():
        return rng.choice([None, rng.choice(lines), rng.randint(1, lines[-1] + 20)])

    first, last = number(), number()
    dash = last is not None or rng.random() < 0.7
    if not dash:  # a single number: from it to it
        first = first if first is not None else rng.choice(lines)
        return first, first, False
    return first, last, dash


def test_generated_delete_ranges_in_the_session(pc, tmp_path):
    """Random programs and DELETE ranges typed in the session: the lines left (or the error)
    as the source's steps give them; where the range ends on a line (the source's only
    successful case), PC-BASIC 2.0.8's session shows the same."""
    pc_session, _ = pc
    rng = random.Random(base_seed() + 51)
    session, shown = gw_session(tmp_path)
    for _ in range(case_count(40)):
        lines = sorted(rng.sample(range(1, 120), rng.randint(1, 6)))
        first, last, dash = random_range(rng, lines)
        command = "DELETE " + range_text(first, last, dash)
        steps = ["NEW"] + [f"{n} PRINT {n}" for n in lines]
        typed(session, shown, steps)
        left = source_delete(lines, first, last)
        expected = "Illegal function call\n" if left is None else ""
        remaining = lines if left is None else left
        assert typed(session, shown, [command]) == expected, (lines, command)
        assert typed(session, shown, ["LIST"]) == "".join(f"{n} PRINT {n}\n" for n in remaining), (lines, command)
        if left is not None:
            for step in steps:
                pc_session.execute(step)
            assert clean_output(pc_session.execute(command)) == expected, (lines, command)
            assert clean_output(pc_session.execute("LIST")) == "".join(f"{n} PRINT {n}\n" for n in left)


@pytest.mark.parametrize("command", ["DELETE 20-25", "DELETE -25", "DELETE 10-40", "DELETE 30-20", "DELETE 25"])
def test_a_range_not_ending_on_a_line_is_refused(tmp_path, command):
    """In the session: Illegal function call and nothing deleted (PC-BASIC 2.0.8 deletes
    the lines in the others but 30-20 and 25)."""
    session, shown = gw_session(tmp_path)
    typed(session, shown, ["10 PRINT 1", "20 PRINT 2", "30 PRINT 3"])
    assert typed(session, shown, [command, "LIST"]) == "Illegal function call\n10 PRINT 1\n20 PRINT 2\n30 PRINT 3\n"


@pytest.mark.parametrize("command", ["DELETE", "DELETE -", "DELETE 20-", "DELETE 60-", "DELETE 25-"])
def test_an_open_range_deletes_to_the_end_as_recorded(tmp_path, command):
    """``DELETE 60-`` deleted lines 60 to the end on a real GW-BASIC (PC-BASIC's DELETE test);
    so does every range with its last line left out, from its first line found on."""
    session, shown = gw_session(tmp_path)
    typed(session, shown, ["10 PRINT 1", "20 PRINT 2", "30 PRINT 3"])
    first = int(command[7:-1] or 0) if command != "DELETE" else 0
    left = "".join(f"{n} PRINT {n // 10}\n" for n in (10, 20, 30) if n < first)
    expected = ("Illegal function call\n10 PRINT 1\n20 PRINT 2\n30 PRINT 3\n" if first > 30 else left)
    assert typed(session, shown, [command, "LIST"]) == expected


@pytest.mark.parametrize("command", ["DELETE 20-25", "DELETE -25"])
def test_a_program_s_delete_is_refused_the_same_way(tmp_path, command):
    """A program's DELETE: the error is the statement's (ON ERROR traps it, ERR 5; before,
    ``DELETE`` alone was Missing operand and the others deleted lines)."""
    source = f"10 ON ERROR GOTO 100\n20 {command}\n30 PRINT \"on\": END\n100 PRINT ERR; ERL: RESUME NEXT\n"
    assert yaseer_run(source, tmp_path) == " 5  20 \non\n"


def test_a_program_s_delete_ending_on_a_line_as_pcbasic(tmp_path):
    source = '10 PRINT 1\n20 DELETE 15-30\n30 PRINT 3\n'
    theirs, ours = tmp_path / "pc", tmp_path / "ya"
    theirs.mkdir()
    ours.mkdir()
    assert yaseer_run(source, ours) == pcbasic_run(source, theirs) == " 1 \n"


@pytest.mark.parametrize("option, shown", [
    ("DELETE 10-", "Illegal function call in 10\n"),  # PC-BASIC 2.0.8 agrees
    ("DELETE 20-25", "Illegal function call in 10\n"),  # PC-BASIC 2.0.8 agrees
    ("DELETE 20-30", "B\n"),
])
def test_chain_s_delete_range_ends_on_a_line(tmp_path, option, shown):
    """FIVEO.ASM CHAIN: "Must have exact match on end of range" (before, ``DELETE 10-`` ran B)."""
    (tmp_path / "B.BAS").write_bytes(b'10 PRINT "B"\r\n')
    source = f'10 CHAIN MERGE "B", 10, {option}\n20 PRINT 2\n30 PRINT 3\n'
    assert yaseer_run(source, tmp_path) == shown


@pytest.mark.parametrize("source", [
    '10 DELETE .-"A"\n', '10 PRINT 1\n20 DELETE .-"A"\n', "10 PRINT 1: DELETE .-A\n", "10 DELETE .*2\n",
    '10 LIST .-"A"\n', "10 LIST .+1\n", "10 RENUM .,.*2\n", "10 AUTO .-(1)\n", "10 GOSUB .+1\n",
    '10 ON ERROR GOTO 100\n20 DELETE .-"A"\n30 END\n100 PRINT ERR, ERL: RESUME NEXT\n'])
def test_the_current_line_period_before_other_text_is_a_syntax_error_as_pcbasic(tmp_path, source):
    # "." after a line word is the current line (GWMAIN.ASM LINSPC); followed by what no range
    # or line takes, the statement is Syntax error where it runs (an error ERR 2 a handler
    # sees), as PC-BASIC 2.0.8; reading it back as an expression once stopped with IndexError
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    assert yaseer_run(source, tmp_path / "a") == pcbasic_run(source, tmp_path / "b")


def test_a_slip_of_the_line_reader_is_the_line_s_internal_error_not_a_traceback(tmp_path, monkeypatch):
    # the reader's last guard (parser.parse_line): whatever escapes reading a line becomes
    # that line's one BASIC error, shown where the program reaches it
    from yaseer.basic.source import parser

    def slip(*args):
        raise IndexError("tuple index out of range")

    monkeypatch.setattr(parser, "_recover", slip)
    printed = yaseer_run('10 PRINT 1\n20 DELETE .-"SLIP"\n', tmp_path)  # (a line no other test reads: lines are cached)
    assert printed == " 1 \nInternal error (reading the line: IndexError: tuple index out of range) in 20\n"
