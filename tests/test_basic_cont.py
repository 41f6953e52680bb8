"""CONT after Ctrl-C: a run broken any number of times and continued prints what it prints unbroken.

Ctrl-C is delivered as the terminal delivers it, to the machine's SIGINT handler,
from a timer, while the machine runs (``Machine.resumable_breaks``, as the session
sets it).  Each program is run once without a break (the reference), then again
with a break every few hundredths of a second and CONT after each, until it ends.
The programs put every kind of loop the compiler makes in the way: native FOR
loops in their three forms (counting passes, iterating values, testing each
pass), nested, fractional steps, an array element as the variable, a loop in a
subroutine (GOSUB returns renumbered), a block that jumps to itself, WHILE/WEND, READ/DATA,
and an error handler (every statement its own block).
"""

from __future__ import annotations

import io
import signal
import time

import pytest

from alarm_support import stop_alarm

from yaseer.basic.errors import BREAK, BasicError
from yaseer.basic.machine.machine import Machine

PROGRAMS = {
    "nested native loops": (
        "10 S=0: T=0\n20 FOR I=1 TO 700\n30 FOR J=1 TO 300: S=S+J*I: NEXT J\n"
        "40 FOR K=1 TO 200: T=T+1: NEXT K\n50 NEXT I\n60 PRINT S;T;I;J;K"),
    "fractional step": "10 FOR X=.1 TO 2500 STEP .01: S=S+X: NEXT X\n20 PRINT S;X",
    "element as the variable": "10 FOR A(2)=1 TO 150000: S=S+A(2)*2: NEXT\n20 PRINT S;A(2)",
    "a block that jumps to itself": "10 N=N+1: S=S+SQR(N): IF N<500000 THEN 10\n20 PRINT N;S",
    "a native loop in a subroutine, READ": (
        "10 FOR R=1 TO 60: READ D: GOSUB 100: IF R MOD 5=0 THEN RESTORE\n20 NEXT R: PRINT T;R;Q\n30 END\n"
        "100 FOR Q=1 TO 4000: T=T+D*Q-R: NEXT Q: RETURN\n200 DATA 3,1,4,1,5"),
    "printing as it goes": (
        "10 FOR I=1 TO 4000\n20 FOR J=1 TO 30: S=S+I MOD J: NEXT J: PRINT S;\n"
        "30 IF I MOD 8=0 THEN PRINT\n40 NEXT I\n50 PRINT"),
    "WHILE ... WEND": "10 WHILE N<150000: N=N+1: S=S+(N AND 3): WEND\n20 PRINT N;S",  # (casio's MOD: 16 bits)
    "an error handler": (
        "10 ON ERROR GOTO 100\n20 FOR I=1 TO 60000: X=I/(I MOD 7000): S=S+X: NEXT I\n30 PRINT S;E\n40 END\n"
        "100 E=E+1: RESUME NEXT"),
}


def _deliver_ctrl_c(signum, frame):
    """SIGALRM -> what SIGINT would do: call the machine's handler once it is installed
    (CONT may first compile the program again; the Ctrl-C then comes a little later)."""
    handler = signal.getsignal(signal.SIGINT)
    if callable(handler) and handler is not signal.default_int_handler:
        handler(signal.SIGINT, frame)
    else:
        signal.setitimer(signal.ITIMER_REAL, 0.005)


def run_with_breaks(program: str, every: float | None, dialect: str = "casio") -> tuple[str, int]:
    """The screen after running ``program`` to its end, and how many breaks it took.

    ``every``: seconds between Ctrl-Cs (None: no break).  Each break must be
    ``Break in <line>`` and resumable.
    """
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect=dialect)
    machine.resumable_breaks = True
    machine.load(program)
    breaks = 0
    action = machine.run
    previous = signal.signal(signal.SIGALRM, _deliver_ctrl_c)
    try:
        while True:
            if every is not None:
                signal.setitimer(signal.ITIMER_REAL, every)
            try:
                assert action() == "end"
                break
            except BasicError as error:
                assert error.code == BREAK and error.line is not None, str(error)
                assert machine.cont_point is not None  # CONT can go on
                breaks += 1
                action = machine.cont
            finally:
                signal.setitimer(signal.ITIMER_REAL, 0)
    finally:
        stop_alarm(previous)
    return screen.getvalue(), breaks


def broken_runs(program: str, dialect: str = "casio") -> tuple[str, str, int]:
    """The screen of an unbroken run, the screen of a run broken about 8 times, and how
    many breaks it took.  The breaks' spacing comes from the unbroken run's time; a
    machine whose load changes meanwhile may break fewer times, so the spacing is
    shortened (up to three times) until the run is broken at least twice."""
    started = time.perf_counter()
    reference, _ = run_with_breaks(program, None, dialect)
    every = max(0.002, (time.perf_counter() - started) / 8)
    for _ in range(4):
        output, breaks = run_with_breaks(program, every, dialect)
        if breaks >= 2:
            break
        every = max(0.001, every / 4)
    return reference, output, breaks


@pytest.mark.parametrize("name", list(PROGRAMS))
def test_broken_and_continued_run_prints_what_an_unbroken_run_prints(name):
    program = PROGRAMS[name]
    reference, output, breaks = broken_runs(program)
    assert breaks >= 2  # the program ran long enough to be broken and continued more than once
    assert output == reference


def test_gw_typed_variables_survive_breaks():
    """gw: integer, double and single locals (i_, d_, n_) are kept across Ctrl-C and CONT."""
    program = ("10 DEFINT I-K: DEFDBL D\n20 FOR I=1 TO 20000: D=D+I/3#: K=(K+I) MOD 7: S=S+.5\n"
               "30 N%=N%+1: IF N%>9999 THEN N%=0\n40 NEXT I\n50 PRINT D;K;I;S;N%")
    reference, output, breaks = broken_runs(program, "gw")
    assert breaks >= 2
    assert output == reference
    k = 0
    for i in range(1, 20001):
        k = (k + i) % 7
    # D: the sum of I/3 is 20000*20001/6; S: 20000 halves; N% wraps to 0 at 10000 and 20000
    assert reference == f" {20000 * 20001 // 6}  {k}  20001  10000  0 \n"


def test_the_reference_itself_is_right():
    """The nested-loop program's sums by closed formulas (so the comparison above compares right values)."""
    reference, _ = run_with_breaks(PROGRAMS["nested native loops"], None)
    s = sum(range(1, 301)) * sum(range(1, 701))
    assert [float(v) for v in reference.split()] == [pytest.approx(s, rel=1e-9), 700 * 200, 701, 301, 201]


def checked_break_points(sources) -> int:
    """Assert that every break point of the programs ``sources`` is ``_ln = n`` or
    ``continue``; how many there are."""
    import re

    from yaseer.basic.compile.compiler import compile_area
    from yaseer.basic.source.parser import parse_line
    from yaseer.basic.source.scanner import split_lines

    checked = 0
    for source in sources:
        compiled = compile_area([parse_line(n, text) for n, text, _ in split_lines(source)])
        prelude = len(compiled.pieces) - compiled.block_count
        for block, points in compiled.break_points.items():
            lines = compiled.pieces[prelude + block][1].splitlines()
            for number in points:
                assert re.fullmatch(r"_ln = \d+|continue", lines[number - 1].strip())
                checked += 1
    return checked


def test_break_points_are_lines_nothing_can_interrupt_half_way():
    """A break lands on ``_ln = n`` (the top of a native loop's pass) or ``continue`` only:
    no call, no loop test, so no statement is ever half done when it lands."""
    from pathlib import Path

    repo = Path(__file__).resolve().parents[1]
    sources = list(PROGRAMS.values()) + [p.read_text() for p in sorted((repo / "listings").glob("*.bas"))]
    assert checked_break_points(sources) > 10


@pytest.mark.parametrize("statement", ['INPUT "VALUE"; A', 'LINE INPUT "VALUE? "; A$: A=VAL(A$)'])
def test_ctrl_c_as_input_asks_is_a_break_and_cont_asks_again(statement):
    """The Ctrl-C comes while the question is being shown (before the line is read)."""
    import sys

    class Screen(io.StringIO):
        interrupt = True

        def write(self, text):
            super().write(text)
            if "VALUE?" in text and Screen.interrupt:
                Screen.interrupt = False
                machine._on_interrupt(signal.SIGINT, sys._getframe())  # what the terminal's Ctrl-C calls
            return len(text)

    screen = Screen()
    machine = Machine(screen=screen, input_stream=io.StringIO("7\n"))
    machine.resumable_breaks = True
    machine.load(f'10 S=5\n20 {statement}\n30 PRINT S+A')
    with pytest.raises(BasicError) as info:
        machine.run()
    assert str(info.value) == "Break in 20" and machine.cont_point is not None
    assert machine.cont() == "end"
    assert screen.getvalue() == "VALUE? VALUE? 7\n 12 \n"  # asked again after CONT
