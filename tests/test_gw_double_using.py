"""PRINT USING's digits of a gw double as MATH2.ASM's output routines find them.

``$FOTNV`` brackets the double into 16 whole digits by the powers of ten its table
``$FOTB`` names for the exponent byte (each step a rounded ``$FMULD``, or ``DDIVFA`` for
a negative power), then 10 below 10**6, then 10**9, then 0.1 above ``HIDBL``; ``$PUF``
and ``$PUFE`` multiply by the double nearest 0.1 (``$DIV10``) once per digit the field
does not show, and ``$FOTCV``/``$VADDH`` add .5 (a rounded ``$FADDD``) and cut.  The
reference here is that sequence on exact rationals (fractions), each step rounded half
to even to 56 bits, apart from the routine under test (mbf_double's integer registers).
PC-BASIC 2.0.8 brackets by tens instead, so it differs in the last digit now and then
(``(56057#/4630)*73#`` with sixteen places: GW ...708, PC-BASIC ...709): it is the
reference of the layout (sign, zeros, ``%``) where its digits are the source's.
The values come from their 8 bytes (CVD): no reading stands between.
"""

from __future__ import annotations

import math
import random
import re
from decimal import Decimal
from fractions import Fraction

import pytest

from test_differential_support import base_seed, case_count, run_gw
from test_mbf_double_whole import basic_bytes, encoded, exact
from yaseer.basic.arithmetic.mbf_double_using import FOTB

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def scaled_to_bits(x: Fraction, bits: int) -> tuple[Fraction, Fraction]:
    """``(x * scale, scale)`` for ``x`` > 0 and the power of two ``scale`` that puts ``bits``
    significant bits before the point."""
    top = x.numerator.bit_length() - x.denominator.bit_length()
    if Fraction(2) ** top > x:
        top -= 1
    scale = Fraction(2) ** (bits - 1 - top)
    return x * scale, scale


def r56(x: Fraction) -> Fraction:
    """``x`` > 0 rounded half to even to 56 significant bits."""
    scaled, scale = scaled_to_bits(x, 56)
    whole = math.floor(scaled)
    rest = scaled - whole
    if rest > Fraction(1, 2) or (rest == Fraction(1, 2) and whole % 2):
        whole += 1
    return whole / scale


def exponent_byte(x: Fraction) -> int:
    top = x.numerator.bit_length() - x.denominator.bit_length()
    if Fraction(2) ** top > x:
        top -= 1
    return top + 129


TENTH = r56(Fraction(1, 10))
HIDBL = Fraction(39999999999999997, 4)


def bracket(x: Fraction) -> tuple[Fraction, int]:
    power = 0
    while FOTB[exponent_byte(x)]:
        n = FOTB[exponent_byte(x)]
        power -= n
        x = r56(x * r56(Fraction(10) ** n)) if n > 0 else r56(x / r56(Fraction(10) ** -n))
    if x < 10 ** 6:
        x, power = r56(x * 10), power - 1
    x, power = r56(x * 10 ** 9), power - 9
    if x > HIDBL:
        x, power = r56(x * TENTH), power + 1
    return x, power


def tenths(x: Fraction, times: int) -> Fraction:
    for _ in range(times):
        x = r56(x * TENTH)
    return x


def fotcv(x: Fraction) -> int:
    return int(x) if x.denominator == 1 else math.floor(r56(x + Fraction(1, 2)))


def fixed_value(x: Fraction, places: int) -> Decimal:
    """The magnitude ``$PUF`` prints for ``places`` decimals."""
    b, power = bracket(x)
    if power >= 0:
        return Decimal(fotcv(b)).scaleb(power)
    excess = -(places + power)
    if excess > 0:
        return Decimal(fotcv(tenths(b, excess))).scaleb(-places)
    return Decimal(fotcv(b)).scaleb(power)


def scientific_value(x: Fraction, digits: int) -> Decimal:
    """The magnitude ``$PUFE`` prints with ``digits`` digits."""
    b, power = bracket(x)
    if digits >= 16:
        return Decimal(fotcv(b)).scaleb(power)
    b = tenths(b, 16 - digits)
    power += 16 - digits
    n = math.floor(r56(b + Fraction(1, 2)))
    if n >= 10 ** digits:
        n, power = fotcv(r56(n * TENTH)), power + 1
    return Decimal(n).scaleb(power)


def printed_value(text: str) -> Decimal:
    """The magnitude a PRINT USING field shows (``%``, sign, commas, ``D`` exponent)."""
    body = text.strip().lstrip("%").replace(",", "").replace("D", "E").lstrip("+-")
    return Decimal(body.rstrip("+-"))


def random_double(rng: random.Random) -> bytes:
    mantissa = rng.getrandbits(56)
    if rng.random() < 0.2:
        mantissa &= ~((1 << rng.randint(0, 50)) - 1)
    return mantissa.to_bytes(7, "little") + bytes((rng.randint(70, 183),))


def random_field(rng: random.Random) -> tuple[str, int, bool]:
    """A field, the digits it shows (decimals; for ``^^^^`` all of them), and whether it is ``^^^^``."""
    if rng.random() < 0.5:
        places = rng.randint(0, 16)
        before = rng.randint(1, min(8, 23 - places))  # GW's fields hold 24 digit positions and the point
        return "#" * before + "." + "#" * places, places, False
    before, places = rng.randint(2, 9), rng.randint(0, 14)
    return "#" * before + ("." + "#" * places if places else "") + "^^^^", before - 1 + places, True


KNOWN = [  # (statement, value) where PC-BASIC's tens and the source's table differ
    ('PRINT USING "#.################"; (56057#/4630)*73#', "883.8360691144708"),
    ('PRINT USING "########.#########^^^^"; (26728#/9127)*37#', "1083527.993864358E-04"),
]


def cases(count: int) -> list[tuple[bytes, str, int, bool]]:
    rng = random.Random(base_seed() + 61)
    return [(random_double(rng), *random_field(rng)) for _ in range(count)]


def program(rows) -> str:
    return "".join(f'{10 + 10 * k} PRINT USING "{field}"; CVD({basic_bytes(data)})\n'
                   for k, (data, field, _, _) in enumerate(rows))


def expected(data: bytes, digits: int, scientific: bool) -> Decimal:
    x = abs(exact(data))
    return scientific_value(x, digits) if scientific else fixed_value(x, digits)


def test_known_cases_follow_the_source_not_pcbasic():
    for statement, value in KNOWN:
        assert printed_value(run_gw(f"10 {statement}\n")) == Decimal(value)


def test_print_using_of_a_double_takes_the_sources_steps():
    """Generated 56-bit doubles from 1E-18 to 1E+16 in fixed and ``^^^^`` fields: the value
    printed is the reference's, digit for digit."""
    rows = cases(case_count(400))
    printed = run_gw(program(rows)).splitlines()
    assert len(printed) == len(rows)
    bad = [(field, exact(data), text) for (data, field, digits, sci), text in zip(rows, printed)
           if printed_value(text) != expected(data, digits, sci)]
    assert not bad, f"{len(bad)} of {len(rows)} differ, e.g. {bad[:3]}"


def test_print_using_of_a_double_as_pcbasic_where_it_agrees_with_the_source(pc):
    """The same fields in PC-BASIC 2.0.8: where its digits are the source's, the whole text
    is yaseer's; and they are so in most cases.  (A fixed field from 10**16 up is the
    source's free format, not PC-BASIC's layout: tests/test_gw_using_free_format.py.)"""
    rows = cases(case_count(400))
    ours = run_gw(program(rows)).splitlines()
    theirs = pc.program(program(rows)).replace("\r", "").splitlines()
    assert len(ours) == len(theirs) == len(rows)
    agreeing = [(a, b) for (data, _, digits, sci), a, b in zip(rows, theirs, ours)
                if re.fullmatch(r"[ %+\-0-9.,D]*", a) and printed_value(a) == expected(data, digits, sci)
                and (sci or abs(exact(data)) < 10 ** 16)]
    assert len(agreeing) >= 0.8 * len(rows)
    bad = [(a, b) for a, b in agreeing if a != b]
    assert not bad, f"{len(bad)} of {len(agreeing)} differ, e.g. {bad[:3]}"


def test_the_table_brings_every_binade_near_a_million():
    """``$FOTB`` (transcribed from MATH1.ASM): 0 exactly for 2**19 .. 2**23, and for every
    other exponent byte a power that lands the binade's numbers within a factor 16 of
    2**19 .. 2**23 (or takes the largest step, 10**38, toward it)."""
    for byte, n in enumerate(FOTB):
        low, high = Fraction(2) ** (byte - 129), Fraction(2) ** (byte - 128)
        assert (n == 0) == (148 <= byte <= 151)
        if n:
            moved_low, moved_high = low * Fraction(10) ** n, high * Fraction(10) ** n
            assert n == 38 or (Fraction(2) ** 15 <= moved_low and moved_high <= Fraction(2) ** 27), (byte, n)
