"""gw single-precision literals as GW-BASIC's number reader makes them (MATH1.ASM ``$FIN``,
MATH2.ASM ``$FIDIG``, MATH1.ASM ``$FINE``/``MDPTEN``).

Up to seven digits the number so far is a single, exact (times ten by ``$MUL10``, the
digit added by ``$FADDS``); from the eighth digit on a double (``$FMULD``, ``$FADDD``),
made single by ``$CSD`` (its top 24 bits, rounded up when the 25th is 1) where the
literal is single (``E``, ``!``).  The power of ten (the exponent less the digits after
the point) is applied once: the single made double, times the table's 10**n (``$FMULD``,
n up to 38) or divided by 10**-n (``DDIVFA``; below 10**-38 two divisions), made single
by ``$CSD``.  The reference here takes those steps on exact fractions (each double step
rounded half to even to 56 bits, the table's powers so rounded), apart from the routine
under test (mbf_double's integer registers).  PC-BASIC 2.0.8 multiplies or divides by
ten step by step instead and rounds a tie to even, so about 4% of literals of up to
seven digits with an exponent differ in the last bit (``720E8``: GW 72000004096,
PC-BASIC 71999995904; ``134E-29``); where it agrees, its bytes are asserted too.
"""

from __future__ import annotations

import math
import random
import re
from fractions import Fraction

import pytest

from test_differential_support import base_seed, case_count, run_gw
from test_gw_double_using import r56, scaled_to_bits

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

LARGEST = Fraction(2 ** 24 - 1) * Fraction(2) ** (127 - 24)  # MBF's largest single
SMALLEST = Fraction(2) ** -128  # MBF's smallest: exponent byte 1, mantissa .5


def csd(x: Fraction) -> Fraction:
    """``$CSD``: ``x`` > 0 to 24 bits, rounded up when the 25th bit is 1."""
    scaled, scale = scaled_to_bits(x, 24)
    whole = math.floor(scaled)
    if scaled - whole >= Fraction(1, 2):
        whole += 1
    return whole / scale


def accumulated(digits: str) -> Fraction:
    """``$FIDIG``: the digits' value, exact as a single up to seven digits, then step by
    step in double precision, ``$CSD`` at the end."""
    value = Fraction(int(digits[:7]))
    if len(digits) <= 7:
        return value
    for digit in digits[7:]:
        value = r56(r56(value * 10) + int(digit)) if value else Fraction(int(digit))
    return csd(value)


def reference(digits: str, power: int) -> Fraction | None:
    """The single ``$FIN`` reads for ``digits`` (no leading zero) times 10**power; None beyond
    the range (Overflow), 0 below it."""
    value = accumulated(digits)
    if power > 38:
        return None
    if power > 0:
        value = csd(r56(value * r56(Fraction(10) ** power)))
    elif power < -76:
        return Fraction(0)
    elif power < 0:
        if power < -38:
            value = r56(value / r56(Fraction(10) ** (-power - 38)))
            power = -38
        value = r56(value / r56(Fraction(10) ** -power))
        if value < SMALLEST:
            return Fraction(0)
        value = csd(value)
    if value > LARGEST:
        return None
    return value if value >= SMALLEST else Fraction(0)


def single_bytes(x: Fraction) -> list[int]:
    """MKS$'s four bytes of a positive single: three mantissa bytes (low first, the top
    bit the sign's place) and the exponent byte."""
    if not x:
        return [0, 0, 0, 0]
    top = x.numerator.bit_length() - x.denominator.bit_length()
    if Fraction(2) ** top > x:
        top -= 1
    mantissa = x * Fraction(2) ** (23 - top)
    assert mantissa.denominator == 1
    m = mantissa.numerator & 0x7FFFFF
    return [m & 0xFF, m >> 8 & 0xFF, m >> 16, top + 129]


def random_literal(rng: random.Random) -> tuple[str, str, int]:
    """(the literal, its digits, its power of ten) for a single: up to seven digits with
    an ``E`` exponent or without one, eight or nine with ``!`` (with ``E`` they are a
    double: ``$FINEX`` keeps a number already double)."""
    count = rng.choice([1, 2, 3, 4, 5, 6, 7, 7, 7, 8, 9])
    digits = str(rng.randint(10 ** (count - 1), 10 ** count - 1))
    point = rng.randint(0, count)
    mark = "!" if count > 7 else rng.choice("EE!.")
    exponent = rng.randint(-44, 37 - count) if mark == "E" else 0
    text = digits[:point] + ("." + digits[point:] if point < count or mark == "." else "")
    text += f"E{exponent}" if mark == "E" else ("!" if mark == "!" else "")
    return text, digits, exponent - (count - point)


def literal_program(literals: list[str]) -> str:
    return "".join(f"{10 + 10 * k} FOR K=1 TO 4: PRINT ASC(MID$(MKS$({text}),K,1));: NEXT: PRINT\n"
                   for k, text in enumerate(literals))


def literal_cases(count: int) -> list[tuple[str, str, int]]:
    rng = random.Random(base_seed() + 71)
    cases = []
    while len(cases) < count:
        text, digits, power = random_literal(rng)
        if reference(digits, power) is not None:
            cases.append((text, digits, power))
    return cases


def expected_rows(cases) -> list[str]:
    return ["".join(f" {b} " for b in single_bytes(reference(digits, power))) for _, digits, power in cases]


def test_known_literals_round_as_the_source():
    assert run_gw("10 PRINT 720E8 = 72000004096#; 67545.7E3 = 67545704#; 720E8 - 72000004096#\n") == "-1 -1  0 \n"
    digits_134 = single_bytes(reference("134", -29))
    assert run_gw(literal_program(["134E-29"])) == "".join(f" {b} " for b in digits_134) + "\n"


def test_single_literals_take_the_sources_steps():
    """Generated literals of 1 to 9 digits, with an exponent, ``!`` or a point alone:
    their MKS$ bytes are the reference's."""
    cases = literal_cases(case_count(400))
    rows = run_gw(literal_program([text for text, _, _ in cases])).splitlines()
    bad = [(text, row, want) for (text, _, _), row, want in zip(cases, rows, expected_rows(cases)) if row != want]
    assert len(rows) == len(cases) and not bad, f"{len(bad)} of {len(cases)} differ, e.g. {bad[:3]}"


def test_single_literals_as_pcbasic_where_it_reads_as_the_source(pc):
    """PC-BASIC 2.0.8 gives the same bytes for most of them; where it does, yaseer's are its."""
    cases = literal_cases(case_count(400))
    source = literal_program([text for text, _, _ in cases])
    theirs = pc.program(source).replace("\r", "").splitlines()
    ours = run_gw(source).splitlines()
    wanted = expected_rows(cases)
    agreeing = [(a, b) for a, b, want in zip(theirs, ours, wanted) if a == want]
    assert len(agreeing) >= 0.8 * len(cases)
    assert all(a == b for a, b in agreeing)


_LITERAL = re.compile(r"(?<![\w.$])(\d+\.?\d*|\.\d+)(E[-+]?\d+)?(!?)(?![\w.#%])", re.IGNORECASE)


def pcbasic_reads_as_the_source(text: str) -> bool:
    """Does PC-BASIC 2.0.8 read every single-precision literal in ``text`` (a BASIC
    statement; a ``"..."`` string's digits count too, as VAL's) as the source's steps
    above do?  Its tens step by step differ for about 4% of those with a fraction or an
    exponent, which tests comparing whole programs with PC-BASIC leave out."""
    from pcbasic.basic.values import numbers

    from test_mbf_double import _Values

    for match in _LITERAL.finditer(text):
        literal = match.group(0)
        is_double, mantissa, exp10 = numbers.str_to_decimal(literal.encode())
        if is_double or not mantissa or (not match.group(2) and "." not in literal and not match.group(3)):
            continue  # a double, zero, or a whole number (an integer or exact)
        digits = str(mantissa) if match.group(3) else str(mantissa).rstrip("0")
        ours = reference(digits, exp10 + len(str(mantissa)) - len(digits))
        try:
            theirs = numbers.Single(None, _Values()).from_decimal(mantissa, exp10).to_value()
        except OverflowError:
            theirs = None
        if ours is None and theirs is None:  # beyond the range in both
            continue
        if ours is None or theirs is None or Fraction(theirs) != ours:
            return False
    return True
