"""Robustness: mutated paper listings and classic benchmarks never break the interpreter.

Each example mutates one seed program (the paper's calling listings in
listings/ and, as printed, in listings/paper/, PROG 5 as printed in programs/, the Rugg/Feldman and Ahl
benchmarks in tests/benchmarks/classic/) by deleting characters, swapping
tokens, planting huge numbers, nesting deeply, dropping lines or inserting
binary junk, inserting state-upsetting statements or garbling a PRINT USING format,
then runs it with the library programs bound.  Every run must
end normally or with one of the interpreter's own error lines naming a line
(``Syntax error in 40``, ``Break in 30`` ...); never a Python exception (nor
the interpreter's ``Internal error`` wrapper of one), never a hang: a run is
interrupted after ``RUN_SECONDS`` as Ctrl-C would, and must then stop with
``Break in N``.  Runs happen in an empty directory that must stay empty.

``YASEER_FUZZ_EXAMPLES`` sets the number of examples (default 60; a long run
by hand: e.g. 5000).  Hypothesis is derandomized, so CI runs are repeatable.
"""

from __future__ import annotations

import io
import os
import re
import signal
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from alarm_support import stop_alarm

from yaseer import binding
from yaseer.basic.errors import BasicError
from yaseer.basic.machine.machine import INTERNAL_ERROR, Machine

ROOT = Path(__file__).resolve().parent.parent
SEED_FILES = sorted(ROOT.glob("listings/*.bas")) + sorted((ROOT / "tests/benchmarks/classic").glob("*.bas"))
AS_PRINTED = sorted(ROOT.glob("listings/paper/*.bas"))  # the paper's text, misprints and all
PROG5 = (ROOT / "programs/prog5.bas").read_text()
SEEDS = [path.read_text(errors="replace") for path in SEED_FILES + AS_PRINTED]
RUN_SECONDS = 1.0
ERROR_LINE = re.compile(r" in \d+( \(PROG \d+\))?$")
# Finding F3 (docs/differential-findings.md): set to False to accept a bare "Break".
BREAK_NAMES_ITS_LINE = True
TOKEN = re.compile(r"[A-Za-z]+\$?|\d*\.?\d+(?:E[-+]?\d+)?|\S")

HUGE_NUMBERS = ["1E308", "9.9E307*10", "1E-320", "123456789012345678901234567890", "-1E38", "1E+999",
                "4294967296", "65536", ".0000000000000000001", "1E"]


class Budget:
    """Interrupts the run after ``seconds`` as Ctrl-C would: a SIGINT to this process."""

    def __init__(self, seconds: float):
        self.seconds = seconds

    def __enter__(self):
        self.previous = signal.signal(signal.SIGALRM, self._interrupt)
        signal.setitimer(signal.ITIMER_REAL, self.seconds)
        return self

    def _interrupt(self, _signum, _frame):
        os.kill(os.getpid(), signal.SIGINT)  # the machine's own SIGINT handler, or KeyboardInterrupt

    def __exit__(self, *exc):
        stop_alarm(self.previous)
        return False


def run_mutant(source: str, with_prog5: bool, seconds: float = RUN_SECONDS) -> str:
    """Run ``source`` (and the printed PROG 5 in area 5); return "ok" or the error line.

    Any exception other than a BasicError propagates (the test fails on it).  An
    interrupt that lands before the run loop (while loading or compiling) is retried
    once with ten times the time, so that a slow machine is not taken for a hang.
    """
    machine = Machine(screen=io.StringIO(), input_stream=io.StringIO(""))
    retry = False
    with Budget(seconds):
        try:
            machine.load(source)
            binding.install(machine)
            if with_prog5:
                machine.set_area(5, PROG5)
            machine.run()
        except KeyboardInterrupt:
            if seconds != RUN_SECONDS:
                raise AssertionError(f"still busy after {seconds} s outside the run loop (no Break line)") from None
            retry = True
        except BasicError as err:
            assert err.code != INTERNAL_ERROR, f"a Python exception inside: {err}"
            if err.line is None and err.message.startswith("Syntax error (no line number"):
                return str(err)  # the mutant's first line lost its number: there is no line to name
            text = str(err)
            if text == "Break" and not BREAK_NAMES_ITS_LINE:
                return text
            assert ERROR_LINE.search(text), f"error line names no line: {text!r}"
            return text
    if retry:
        return run_mutant(source, with_prog5, seconds=10 * RUN_SECONDS)
    return "ok"


# ---------------------------------------------------------------------------
# Mutations: each takes the program text and a Hypothesis data object
# ---------------------------------------------------------------------------

def _position(data, text: str) -> int:
    return data.draw(st.integers(0, max(len(text) - 1, 0)))


def delete_characters(text: str, data) -> str:
    at = _position(data, text)
    return text[:at] + text[at + data.draw(st.integers(1, 4)):]


def swap_tokens(text: str, data) -> str:
    spans = [m.span() for m in TOKEN.finditer(text)]
    if len(spans) < 2:
        return text
    i, j = sorted(data.draw(st.lists(st.integers(0, len(spans) - 1), min_size=2, max_size=2, unique=True)))
    (a0, a1), (b0, b1) = spans[i], spans[j]
    return text[:a0] + text[b0:b1] + text[a1:b0] + text[a0:a1] + text[b1:]


def huge_number(text: str, data) -> str:
    numbers = [m.span() for m in re.finditer(r"\d*\.?\d+", text)]
    if not numbers:
        return text
    start, end = data.draw(st.sampled_from(numbers))
    return text[:start] + data.draw(st.sampled_from(HUGE_NUMBERS)) + text[end:]


def deep_nesting(text: str, data) -> str:
    depth = data.draw(st.sampled_from([50, 200, 1000, 5000]))
    kind = data.draw(st.sampled_from(["parens", "minus", "for", "gosub", "if", "fn"]))
    lines = {
        "parens": f"3 X = {'(' * depth}1{')' * depth}",
        "minus": f"3 X = {'-' * depth}1",
        "for": "3 " + ": ".join(f"FOR J{k % 10} = 1 TO 1" for k in range(min(depth, 300))),
        "gosub": "3 GOSUB 3",
        "if": "3 " + "IF 1 THEN " * depth + "X = 1",
        "fn": "3 DEF FNA(X) = FNA(X) + 1: X = FNA(1)",
    }
    return lines[kind] + "\n" + text


def missing_line(text: str, data) -> str:
    lines = text.split("\n")
    del lines[data.draw(st.integers(0, len(lines) - 1))]
    return "\n".join(lines)


def binary_junk(text: str, data) -> str:
    junk = data.draw(st.binary(min_size=1, max_size=12)).decode("latin-1")
    at = _position(data, text)
    return text[:at] + junk + text[at:]


STATEMENTS = ["RETURN", "NEXT", "NEXT QQ", "GOSUB 1", "RESUME", "RESUME NEXT", "ON ERROR GOTO 20", "RESTORE 3",
              "READ X", "DIM L(5)", "CLEAR", "STOP", "END", "GOSUB PROG 9", "GOSUB PROG 5", "RAD", "DEG",
              "DEF FNA(X) = X / 0", "PRINT FNA(1)", "PRINT USING \"##.#^^^^\"; 1E300", "ON 3 GOTO 10, 20",
              "INPUT A", "X = L(-1)", "PRINT TAB(-1)", "PRINT MID$(\"ab\", 0)", "CLEAR 5", "RANDOMIZE"]


def insert_statement(text: str, data) -> str:
    """A statement that upsets the program's state, placed after a colon or as its own line."""
    statement = data.draw(st.sampled_from(STATEMENTS))
    colons = [m.start() for m in re.finditer(":", text)]
    if colons and data.draw(st.booleans()):
        at = data.draw(st.sampled_from(colons))
        return text[:at] + ": " + statement + text[at:]
    return f"{data.draw(st.integers(1, 120)) * 5} {statement}\n" + text


def garble_format(text: str, data) -> str:
    """Replace a string literal (often a PRINT USING format) by random format characters."""
    strings = [m.span() for m in re.finditer(r'"[^"\n]*"', text)]
    if not strings:
        return text
    start, end = data.draw(st.sampled_from(strings))
    body = data.draw(st.text(alphabet="#.,+-*$^!&\\ _%A", max_size=16))
    return text[:start] + '"' + body + '"' + text[end:]


MUTATIONS = [delete_characters, swap_tokens, huge_number, deep_nesting, missing_line, binary_junk,
             insert_statement, garble_format]


def example_count() -> int:
    return int(os.environ.get("YASEER_FUZZ_EXAMPLES", 60))


@settings(max_examples=example_count(), deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))
@given(data=st.data())
def test_mutated_programs_end_normally_or_with_a_basic_error_line(data, tmp_path_factory):
    seed_index = data.draw(st.integers(0, len(SEEDS) - 1), label="seed")
    source = SEEDS[seed_index]
    for mutation in data.draw(st.lists(st.sampled_from(MUTATIONS), min_size=1, max_size=3), label="mutations"):
        source = mutation(source, data)
    with_prog5 = data.draw(st.booleans(), label="prog5 from programs/")
    workdir = tmp_path_factory.mktemp("fuzz")
    before = Path.cwd()
    os.chdir(workdir)
    try:
        run_mutant(source, with_prog5)
    finally:
        os.chdir(before)
    assert list(workdir.iterdir()) == [], "the run wrote a file nobody named"


def test_budget_interrupts_an_endless_loop_with_a_break_line():
    assert run_mutant("10 FOR I = 1 TO 1E9: X = X + 1: NEXT\n", with_prog5=False) == "Break in 10"
    loop = "10 X = 1\n20 FOR I = 1 TO 1E9\n30 X = SIN(I)\n40 NEXT\n"
    assert run_mutant(loop, with_prog5=False) in ("Break in 30", "Break in 40")


def test_every_seed_runs_unmutated():
    """The seeds themselves run (the paper listings need the library programs bound)."""
    for path, source in zip(SEED_FILES, SEEDS):  # the working listings, not the as-printed ones
        outcome = run_mutant(source, with_prog5=False)
        assert outcome == "ok", f"{path.name}: {outcome}"
