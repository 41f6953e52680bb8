"""Whole programs against PC-BASIC 2.0.8: generated ones, and the corpus of failures found.

yaseer runs in radians (``angle="rad"``, as ``yaseer run --angle rad``) since
GW-BASIC has no degrees.  *Exact* programs must print the same bytes;
*numeric* ones the same text with numbers within 1e-6 relative (see
test_differential_programgen.py).  ``YASEER_DIFF_PROGRAMS`` sets how many
programs a run generates (40 by default); ``YASEER_DIFF_SEED`` the seed.

The corpus (tests/corpus/*.bas) holds the programs on which yaseer once
differed from PC-BASIC, each with PC-BASIC's output in ``NAME.expected``
(recorded by ``python tests/test_differential_programs.py --record``; a single whose
PC-BASIC digits are not the source's prints the source's, see test_differential_support).  Open findings
wait in tests/corpus/pending/; ``--pending`` tells which of them yaseer now gets right.
Where Microsoft's GW-BASIC source decides against PC-BASIC, ``NAME.expected`` holds
the source's output, ``NAME.pcbasic`` PC-BASIC's, and the program's REM lines name
the source file and routine (docs/compatibility.md).
"""

from __future__ import annotations

import math
import os
import random
import sys
from pathlib import Path

import pytest

from test_differential_programgen import LONG_LINE, random_program
from test_differential_support import (
    PcBasic,
    base_seed,
    basic_number,
    numbers_and_text,
    outputs_agree,
    run_yaseer,
    screen_rows,
)

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

CORPUS = Path(__file__).parent / "corpus"
CORPUS_CASES = sorted(CORPUS.glob("*.bas"))
GW_CORPUS_CASES = sorted((CORPUS / "gw").glob("*.bas"))  # run with --dialect gw (GW-BASIC's own rules)


def program_count() -> int:
    return int(os.environ.get("YASEER_DIFF_PROGRAMS", 40))


def too_wide(output: str) -> bool:
    """Whether PC-BASIC's 80-column screen may have wrapped a line (yaseer never wraps)."""
    return max(len(line) for line in output.split("\n")) >= LONG_LINE


def test_generated_programs_match_pcbasic(pc):
    rng = random.Random(base_seed())
    compared, differing = 0, []
    while compared < program_count():
        numeric = compared % 3 == 0
        source = random_program(rng, numeric=numeric).source()
        theirs = pc.program(source)
        if too_wide(theirs):
            continue
        compared += 1
        ours = run_yaseer(source)
        if not outputs_agree(ours, theirs, tolerant=numeric):
            differing.append((source, theirs, ours))
    assert not differing, f"{len(differing)} of {compared} differ; first:\n" + "\n".join(differing[0])


def random_angle(rng: random.Random) -> float:
    """Degrees: multiples of 30 and 45 (where yaseer's exact trig matters), integers, quarters."""
    kind = rng.random()
    if kind < 0.3:
        return float(rng.choice([30, 45, 60, 90, 120, 135, 180, 270, 360]) * rng.choice([-2, -1, 1, 2]))
    if kind < 0.7:
        return float(rng.randint(-720, 720))
    return rng.randint(-2880, 2880) / 4


def test_degree_mode_matches_pcbasic_double_radians():
    """yaseer's default degrees against PC-BASIC in double precision, converting with P = ATN(1#)/45."""
    rng = random.Random(base_seed() + 2)
    pc = PcBasic(double=True)
    ours_lines, theirs_lines = [], []
    for k in range(30):
        angle = random_angle(rng)
        ratio = rng.choice([-4, -1, -0.5, 0, 0.25, 1, 3, 1000])
        tangent = "" if angle % 180 == 90 else f"; TAN({angle})"
        ours_lines.append(f"{10 + 10 * k} PRINT SIN({angle}); COS({angle}){tangent}; ATN({ratio})")
        tangent = "" if not tangent else f"; TAN({angle}# * P)"
        theirs_lines.append(f"{10 + 10 * k} PRINT SIN({angle}# * P); COS({angle}# * P){tangent}; ATN({ratio}#) / P")
    ours = run_yaseer("\n".join(ours_lines) + "\n", angle="deg")
    theirs = pc.program("5 DEFDBL A-Z: P = ATN(1#) / 45#\n" + "\n".join(theirs_lines))
    pc.close()
    our_numbers, our_text = numbers_and_text(ours)
    their_numbers, their_text = numbers_and_text(theirs)
    assert our_text == their_text
    assert len(our_numbers) == len(their_numbers) >= 30 * 3
    far = [(a, b) for a, b in zip(our_numbers, their_numbers) if not math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-9)]
    assert not far, far[:5]


LITERALS = [0.1, 0.25, 0.3, 1.5, 2, 3, 7, 10, 12.75, 100, 0.007]
FUNCTIONS = {
    "SQR": lambda x: math.sqrt(x) if x >= 0 else None,
    "EXP": lambda x: math.exp(x) if x < 40 else None,
    "LOG": lambda x: math.log(x) if x > 0 else None,
    "SIN": math.sin, "COS": math.cos, "ATN": math.atan, "ABS": abs,
}


def real_expression(rng: random.Random, depth: int) -> tuple[str, str, float, float]:
    """An expression on decimal literals: yaseer's text, PC-BASIC's (double literals ``#``), its value, and
    the largest magnitude met on the way (the scale of rounding errors)."""
    if depth == 0 or rng.random() < 0.2:
        value = float(rng.choice(LITERALS))
        text = repr(value)  # the shortest text that reads back as this double: 0.1, 12.75, 2.0
        return text, text + "#", value, abs(value)
    kind = rng.random()
    if kind < 0.3:
        name = rng.choice(sorted(FUNCTIONS))
        inner_y, inner_pc, inner, scale = real_expression(rng, depth - 1)
        value = FUNCTIONS[name](inner)
        if value is None:
            raise ValueError(name)
        return f"{name}({inner_y})", f"{name}({inner_pc})", value, max(scale, abs(value))
    op = rng.choice("+-*/^")
    left_y, left_pc, left, left_scale = real_expression(rng, depth - 1)
    if op == "^":
        exponent = rng.choice([2, 3, 0.5, -1])
        if left <= 0 and exponent == 0.5 or left == 0:
            raise ValueError("power")
        right_y = right_pc = basic_number(exponent)
        right, right_scale = float(exponent), 1.0
    else:
        right_y, right_pc, right, right_scale = real_expression(rng, depth - 1)
    if op == "/" and abs(right) < 1e-6:
        raise ValueError("division")
    value = {"+": lambda: left + right, "-": lambda: left - right, "*": lambda: left * right,
             "/": lambda: left / right, "^": lambda: left ** right}[op]()
    scale = max(left_scale, right_scale, abs(value))
    return f"({left_y} {op} {right_y})", f"({left_pc} {op} {right_pc})", value, scale


def test_real_arithmetic_matches_pcbasic_double_precision():
    """Decimal literals, + - * / ^ and SQR EXP LOG SIN COS ATN ABS: yaseer's 10 digits against PC-BASIC's
    double precision (DEFDBL, ``#`` literals, /D functions) within 1e-9 of the computation's scale."""
    rng = random.Random(base_seed() + 3)
    ours_lines, theirs_lines, scales = [], [], []
    while len(ours_lines) < 40:
        try:
            ours_text, theirs_text, value, scale = real_expression(rng, rng.randint(1, 4))
        except (ValueError, OverflowError, ZeroDivisionError):
            continue
        if not 1e-6 < abs(value) < 1e30 or scale > 1e30:
            continue
        number = 10 * (len(ours_lines) + 1)
        ours_lines.append(f"{number} PRINT {ours_text}")
        theirs_lines.append(f"{number} PRINT {theirs_text}")
        scales.append(scale)
    ours = run_yaseer("\n".join(ours_lines) + "\n", angle="rad")
    pc = PcBasic(double=True)
    theirs = pc.program("5 DEFDBL A-Z\n" + "\n".join(theirs_lines))
    pc.close()
    our_numbers, _ = numbers_and_text(ours)
    their_numbers, _ = numbers_and_text(theirs)
    assert len(our_numbers) == len(their_numbers) == len(scales), (ours, theirs)
    far = [(line, a, b) for line, a, b, scale in zip(ours_lines, our_numbers, their_numbers, scales)
           if abs(a - b) > 1e-9 * max(abs(a), abs(b)) + 1e-12 * scale]
    assert not far, far[:5]


def test_comparison_sees_a_difference():
    """The comparator is not vacuous: a changed digit or word is a difference."""
    assert not outputs_agree(" 1  2 \n", " 1  3 \n", tolerant=False)
    assert not outputs_agree(" .3333333 \n", " .3333334 \n", tolerant=False)
    assert outputs_agree(" .3333333 \n", " .3333333333 \n", tolerant=True)
    assert not outputs_agree(" .3333 \n", " .3333333333 \n", tolerant=True)
    assert not outputs_agree("in1 \n", "in2 \n", tolerant=True)


@pytest.mark.parametrize("case", CORPUS_CASES, ids=[case.stem for case in CORPUS_CASES])
def test_corpus_program_matches_recorded_pcbasic_output(case):
    expected = case.with_suffix(".expected").read_text()
    assert run_yaseer(case.read_text()) == expected


@pytest.mark.parametrize("case", GW_CORPUS_CASES, ids=[case.stem for case in GW_CORPUS_CASES])
def test_gw_corpus_program_matches_recorded_pcbasic_output(case):
    expected = case.with_suffix(".expected").read_text()
    assert run_yaseer(case.read_text(), angle=None, dialect="gw") == expected


def recorded_output(session, case) -> str:
    """PC-BASIC's output of a corpus program; for gw its screen rows (80 columns), the
    way yaseer's gw screen writes them (see screen_rows)."""
    if case in GW_CORPUS_CASES:  # PC-BASIC keeps these from one run to the next (RUN resets them in GW-BASIC)
        session.statement("WIDTH 80")
        session.statement("ON ERROR GOTO 0")
    out = session.program(case.read_text())
    return screen_rows(out) if case in GW_CORPUS_CASES else out


def test_corpus_expectations_are_pcbasic_output(pc):
    """The recorded outputs are really PC-BASIC's (not edited by hand), or - where the
    GW-BASIC source decides otherwise - PC-BASIC really prints the recorded ``.pcbasic``;
    where a single PC-BASIC prints has other digits than the source's steps, ``.expected``
    is PC-BASIC's output with the source's digits (the oracle ``pc``, see
    test_differential_support)."""
    assert CORPUS_CASES and GW_CORPUS_CASES, "the corpus is empty"
    own = PcBasic(source_digits=False)
    try:
        for case in CORPUS_CASES + GW_CORPUS_CASES:
            pcbasic = case.with_suffix(".pcbasic")
            expected = pcbasic if pcbasic.exists() else case.with_suffix(".expected")
            theirs = recorded_output(own, case)
            assert theirs == expected.read_text(), case.name
            if pcbasic.exists():
                assert case.with_suffix(".expected").read_text() != pcbasic.read_text(), case.name
            with_source_digits = recorded_output(pc, case)
            if with_source_digits != theirs:
                assert case.with_suffix(".expected").read_text() == with_source_digits, case.name
    finally:
        own.close()


def record() -> None:
    """Write NAME.expected for every corpus program that lacks one, from PC-BASIC."""
    session = PcBasic()
    for case in CORPUS_CASES + GW_CORPUS_CASES:
        target = case.with_suffix(".expected")
        if not target.exists():
            target.write_text(recorded_output(session, case))
            print("recorded", target)


def pending_status() -> None:
    """For each open finding in tests/corpus/pending/: does yaseer now print PC-BASIC's output?"""
    for case in sorted((CORPUS / "pending").glob("*.bas")):
        expected = case.with_suffix(".expected").read_text()
        verdict = "FIXED (move it to tests/corpus/)" if run_yaseer(case.read_text()) == expected else "still differs"
        print(f"{case.name}: {verdict}")


if __name__ == "__main__":
    if "--record" in sys.argv:
        record()
    if "--pending" in sys.argv:
        pending_status()
