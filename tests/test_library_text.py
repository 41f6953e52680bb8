"""LIST of an untouched library area: what the program computes, typed on a real pseudo-terminal.

The text names the program's inputs, equations and outputs by array element; every
element it names must be one the contract (docs/contract.md, its own tables, written
from the paper) gives that program, and every position and rate output the contract
lists must be named, so the text cannot drift from what the program reads and writes.
The equations are checked against the program by evaluating them at one position.
"""

from __future__ import annotations

import cmath
import math
import re
from pathlib import Path

import pytest

from yaseer.library_text import LIBRARY_TEXT

ROOT = Path(__file__).resolve().parents[1]
ELEMENT = r"\b[A-Z]\(\d+\)"


def contract_elements(program: int) -> tuple[set[str], set[str]]:
    """(every element docs/contract.md names for ``program``, its position and rate outputs)."""
    text = (ROOT / "docs" / "contract.md").read_text()
    start = text.index(f"## Program {program}:")
    end = text.index("\n## ", start + 1)
    section = text[start:end]
    named, outputs = set(), set()
    for row in section.splitlines():
        if not row.startswith("| `"):
            continue
        cells = [cell.strip() for cell in row.strip("|").split("|")]
        elements = set(re.findall(ELEMENT, cells[0]))
        named |= elements
        if cells[-1] in ("position", "rate"):
            outputs |= elements
    return named, outputs


@pytest.mark.parametrize("program", [1, 2, 3, 5])
def test_the_text_names_only_the_programs_elements_and_all_its_kinematic_outputs(program):
    named, outputs = contract_elements(program)
    shown = set(re.findall(ELEMENT, LIBRARY_TEXT[program]))
    assert shown - named == set()
    assert outputs - shown == set()


def u(degrees: float) -> complex:
    return cmath.exp(1j * math.radians(degrees))


def test_the_four_bar_equations_listed_give_what_prog_2_computes():
    """PROG 2's listed position and rate equations, evaluated here with complex numbers."""
    import yaseer

    result = yaseer.run("10 L(11) = 100: T(11) = 10: L(12) = 40: T(12) = 70: W(5) = 3: A(5) = -2\n"
                        "20 L(13) = 120: L(14) = 80: D(2) = 0: E(2) = 0: GOSUB PROG 2\n"
                        "30 PRINT T(13); T(14); W(6); W(7); A(6); A(7)\n")
    t13, t14, w6, w7, a6, a7 = result.rows[0]
    a, b, c, w, alpha = 40.0, 120.0, 80.0, 3.0, -2.0
    A, Bo = a * u(70), 100 * u(10)
    d = abs(Bo - A)
    x = (b * b - c * c + d * d) / (2 * d)
    h = math.sqrt(b * b - x * x)
    along = (Bo - A) / d
    B = A + x * along + h * 1j * along
    assert math.degrees(cmath.phase(B - A)) == pytest.approx(t13, abs=1e-9)
    assert math.degrees(cmath.phase(Bo - B)) == pytest.approx(t14, abs=1e-9)
    A1 = a * w * 1j * u(70)
    A2 = (-a * w * w) * u(70) + (a * alpha) * 1j * u(70)

    def solve(p: complex, q: complex, rhs: complex) -> tuple[float, float]:  # s*p + t*q = rhs, s and t real
        det = p.real * q.imag - p.imag * q.real
        return (rhs.real * q.imag - rhs.imag * q.real) / det, (p.real * rhs.imag - p.imag * rhs.real) / det

    W6, W7 = solve(1j * (B - A), 1j * (Bo - B), -A1)
    assert (W6, W7) == pytest.approx((w6, w7), rel=1e-9)
    A6, A7 = solve(1j * (B - A), 1j * (Bo - B), -A2 + W6 ** 2 * (B - A) + W7 ** 2 * (Bo - B))
    assert (A6, A7) == pytest.approx((a6, a7), rel=1e-9)


def test_list_of_a_library_area_on_a_terminal(tmp_path):
    from test_interactive import Terminal

    terminal = Terminal(tmp_path)
    terminal.type("PROG 2")
    shown = terminal.type("LIST")
    assert shown.startswith("PROG 2: the four-bar AoABBo")
    assert "x  = (b^2 - c^2 + d^2) / (2*d)" in shown and "gives W(6), W(7)" in shown
    terminal.type("10 RETURN")
    assert terminal.type("LIST") == "10 RETURN\n"  # typed lines replace it
    terminal.type("NEW")
    assert terminal.type("LIST").startswith("PROG 2: the four-bar")  # NEW brings it back
    terminal.close()


def test_stop_typed_in_direct_mode_says_break_without_a_line(tmp_path):
    """PC-BASIC 2.0.8 (GW-BASIC) prints ``Break`` for a direct STOP and ``Break in 20`` in a program."""
    from test_interactive import Terminal

    terminal = Terminal(tmp_path)
    assert terminal.type("STOP") == "Break\n"
    terminal.type("10 PRINT 1")
    terminal.type("20 STOP")
    assert terminal.type("RUN") == " 1 \nBreak in 20\n"
    assert terminal.type("GOTO 10") == " 1 \nBreak in 20\n"  # a program line reached from direct mode
    terminal.close()
