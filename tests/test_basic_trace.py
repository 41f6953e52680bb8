"""TRON / TROFF: the trace, against PC-BASIC 2.0.8 on the same programs.

All the programs run in one PC-BASIC session.  Values are small integers, which
both dialects print alike.  casio traces the
same lines in the same order in the FX-850P's form (TRON.md: the program area and the
line, ``P0-10``, on a row of its own; from a string, no key to wait for).  The plain
compile (TRON off) must carry no trace code.
"""

from __future__ import annotations

import io
import re

import pytest

from test_basic_helpers import run_text
from test_differential_support import core

from yaseer.basic.compile.compiler import compile_area
from yaseer.basic.source.parser import parse_line

PROGRAMS = [
    # a FOR loop over lines (native), its NEXT on its own line
    "10 FOR I=1 TO 2\n20 PRINT I\n30 NEXT I\n40 END",
    # a one-line loop, GOSUB into a line, RETURN into the middle of a line
    '10 FOR I=1 TO 2: PRINT I;: NEXT I\n20 GOSUB 50: PRINT "B"\n30 END\n50 PRINT "S": RETURN',
    # a jump back to its own line
    "10 A=1\n20 IF A<3 THEN A=A+1: GOTO 20\n30 PRINT A",
    # TRON and TROFF in the middle of lines
    "10 PRINT 5\n20 TRON: PRINT 6\n30 PRINT 7: TROFF: PRINT 8\n40 PRINT 9",
    # nested loops, the inner one dynamic (a GOSUB in it), a RETURN to the end of a line
    "10 FOR I=1 TO 2\n20 FOR J=1 TO 2: GOSUB 100\n30 NEXT J, I\n40 END\n100 PRINT I*10+J;\n110 RETURN",
    # ON ... GOTO, IF ... THEN line ELSE line, a zero-trip loop
    "10 K=2\n20 ON K GOTO 30,40\n30 PRINT 30\n40 IF K=2 THEN 60 ELSE 50\n50 PRINT 50\n"
    "60 FOR Q=5 TO 1: PRINT Q: NEXT Q\n70 PRINT 70",
    # an error trapped by ON ERROR GOTO, RESUME NEXT
    "10 ON ERROR GOTO 100\n20 X=1/0\n30 PRINT ERR\n40 END\n100 PRINT 100: RESUME NEXT",
]


def casio_form(gw_trace: str) -> str:
    """PC-BASIC's ``[n]`` marks written as the Casio shows them: ``P0-n`` on a row of its own."""
    out = []
    for piece in re.split(r"(\[\d+\])", gw_trace):
        if re.fullmatch(r"\[\d+\]", piece):
            if out and not out[-1].endswith("\n"):
                out.append("\n")
            out.append(f"P0-{piece[1:-1]}\n")
        elif piece:
            out.append(piece)
    return "".join(out)


@pytest.mark.parametrize("program", PROGRAMS)
def test_trace_matches_pcbasic(pc, program):
    traced = "1 TRON\n" + program + "\n9999 TROFF"
    # PC-BASIC leaves the line of the last [n] open; the comparison ignores final newlines
    # (casio's MS-BASIC core: its ERR is the Casio manual's code, tests/test_casio_words.py;
    # gw's [n] is compared on a terminal in tests/test_interactive_classroom.py)
    expected = casio_form(pc.program(traced))
    assert run_text(traced, dialect=core("casio")).rstrip("\n") == expected.rstrip("\n")


def test_tron_off_leaves_no_trace_in_the_compiled_code():
    lines = [parse_line(n, text) for n, text in ((10, "FOR I=1 TO 9"), (20, "X=X+I"), (30, "NEXT I"))]
    plain, traced = compile_area(lines), compile_area(lines, trace=True)
    assert "_tr(" not in plain.source
    assert [n for n in (10, 20, 30) if f"_tr({n})" in traced.source] == [10, 20, 30]
    assert plain.block_count == traced.block_count  # the machine swaps one for the other in place


def test_tron_survives_until_troff_and_is_shown_with_print():
    assert run_text("10 TRON\n20 PRINT 1;\n30 PRINT 2", dialect="gw") == "[20] 1 [30] 2 \n"
    # casio (TRON.md): the area and line on a row of their own, the output after them
    assert run_text("10 TRON\n20 PRINT 1;\n30 PRINT 2") == "P0-20\n 1 \nP0-30\n 2 \n"


def test_casio_trace_names_the_program_area():
    # TRON.md: "P0 represents currently specified program area"; PROG 2's lines show as P2-n
    from yaseer.basic.machine.machine import Machine

    screen = io.StringIO()
    machine = Machine(screen=screen)
    machine.set_area(2, "10 PRINT 7\n20 RETURN")
    machine.load("10 TRON\n20 GOSUB PROG 2\n30 PRINT 8")
    machine.run()
    assert screen.getvalue() == "P0-20\nP2-10\n 7 \nP2-20\nP0-30\n 8 \n"


def test_casio_trace_names_a_program_file_by_its_name(tmp_path):
    # a program file run by GOSUB "name" (the library's form) has no P area: its name shows
    (tmp_path / "SUB.bas").write_text("10 PRINT 5: RETURN\n")
    assert run_text('10 TRON\n20 GOSUB "SUB"\n30 END', files=tmp_path) == "P0-20\nSUB-10\n 5 \nP0-30\n"
