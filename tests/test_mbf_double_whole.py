"""gw doubles made whole: INT, FIX, CINT, integer assignment and subscripts on all 56 bits,
and PRINT USING's exponent letter of a double.

References: exact rationals (fractions) for what the source computes exactly - MATH2.ASM
``$DINT`` shifts a double's fraction bits out of its 56-bit mantissa (a negative
magnitude less 1 before, plus 1 after: the floor), MATH1.ASM ``FIXER`` is INT of the
magnitude with the sign put back, MATH2.ASM ``$CINC``/``$CIND`` (CINT, FRCINT: integer
assignment, GWMAIN.ASM INTIDX's subscripts) add to the whole part the one bit shifted
out below it, the half - and PC-BASIC 2.0.8 where it computes the same.  The values come
from their 8 bytes (CVD), so no reading or arithmetic stands between the test and the
routine under test.
"""

from __future__ import annotations

import math
import random
from fractions import Fraction

import pytest

from test_differential_support import base_seed, case_count, run_gw

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def exact(data: bytes) -> Fraction:
    """The value of 8 MBF double bytes: 7 mantissa bytes, low first (the top bit of the
    last the sign, the implied 1 in its place), then the exponent byte (value
    ``mantissa * 2**(exponent - 184)``; exponent 0 is zero)."""
    if not data[7]:
        return Fraction(0)
    mantissa = int.from_bytes(data[:7], "little")
    magnitude = Fraction(mantissa | 1 << 55) * Fraction(2) ** (data[7] - 184)
    return -magnitude if mantissa >> 55 else magnitude


def encoded(x: Fraction) -> bytes:
    """The 8 MBF bytes of ``x``, which must have at most 56 significant bits."""
    if not x:
        return bytes(8)
    magnitude = abs(x)
    exponent = 0
    while magnitude >= 2 ** exponent:
        exponent += 1
    while magnitude < Fraction(2) ** (exponent - 1):
        exponent -= 1
    mantissa = magnitude * Fraction(2) ** (56 - exponent)
    assert mantissa.denominator == 1, "more than 56 bits"
    bits = mantissa.numerator & ~(1 << 55) | (1 << 55 if x < 0 else 0)
    return bits.to_bytes(7, "little") + bytes((exponent + 128,))


def half_away(x: Fraction) -> int:
    whole = math.floor(abs(x) + Fraction(1, 2))
    return -whole if x < 0 else whole


def basic_bytes(data: bytes) -> str:
    return "+".join(f"CHR$({byte})" for byte in data)


def bytes_printed(expression: str) -> str:
    return f'FOR K=1 TO 8: PRINT ASC(MID$(MKD$({expression}),K,1));: NEXT: PRINT'


def random_around_units(rng: random.Random) -> bytes:
    """A double whose units' bit lies inside its mantissa or just beyond it: from 2**44 to
    2**62, a random mantissa (sometimes few bits), either sign."""
    mantissa = rng.getrandbits(56)
    if rng.random() < 0.3:
        mantissa &= ~((1 << rng.randint(0, 55)) - 1)
    return mantissa.to_bytes(7, "little") + bytes((rng.randint(173, 191),))


def whole_cases(count: int) -> list[bytes]:
    rng = random.Random(base_seed() + 41)
    cases = [encoded(Fraction(2 ** 55 + 1)), encoded(-Fraction(2 ** 55 + 1)), encoded(Fraction(2 ** 54) + Fraction(1, 2)),
             encoded(-Fraction(2 ** 54) - Fraction(1, 2)), encoded(Fraction(2 ** 53 + 1) + Fraction(1, 4))]
    return cases + [random_around_units(rng) for _ in range(count)]


def whole_program(cases: list[bytes]) -> str:
    lines = []
    for k, data in enumerate(cases):
        lines.append(f"{10 + 10 * k} A#=CVD({basic_bytes(data)}): "
                     f"{bytes_printed('INT(A#)')}: {bytes_printed('FIX(A#)')}")
    return "\n".join(lines) + "\n"


def whole_expected(cases: list[bytes]) -> str:
    rows = []
    for data in cases:
        x = exact(data)
        for result in (math.floor(x), math.trunc(x)):
            rows.append("".join(f" {byte} " for byte in encoded(Fraction(result))) + "\n")
    return "".join(rows)


def test_int_and_fix_of_doubles_above_2_to_53_keep_all_56_bits():
    """``A# = 2#^55: A# = A# + 1: PRINT INT(A#) - 2#^55`` prints 1 as in GW-BASIC (0 when INT
    gave the nearest IEEE double); INT and FIX of doubles from 2**44 to 2**62, their
    bytes against the exact floor and truncation."""
    cases = whole_cases(case_count(150))
    assert run_gw(whole_program(cases)) == whole_expected(cases)
    assert run_gw("10 A#=2#^55: A#=A#+1: PRINT INT(A#)-2#^55; FIX(-A#)+2#^55; INT(-A#)+2#^55\n") == " 1 -1 -1 \n"


def test_int_and_fix_of_doubles_as_pcbasic(pc):
    """PC-BASIC 2.0.8 computes INT and FIX of a double as the source does: it gives the
    same bytes as the exact rationals (the reference of the test above) on the same cases."""
    cases = whole_cases(case_count(150))
    assert pc.program(whole_program(cases)).replace("\r", "") == whole_expected(cases)


def near_halves() -> list[Fraction]:
    """Doubles at, just below and just above a half of the 56th bit's and the IEEE 53rd
    bit's size, of either sign, from 0 to 10."""
    values = []
    for whole in range(0, 11):
        size = max(whole, 1).bit_length()  # bits of the whole part: the rest are fraction bits
        for bits in (53, 54, 55, 56):  # a step of the last of ``bits`` significant bits
            step = Fraction(1, 2 ** (bits - size))
            for x in (whole + Fraction(1, 2) - step, whole + Fraction(1, 2), whole + Fraction(1, 2) + step):
                values += [x, -x]
    return [x for x in values if x]


def cint_program(values: list[Fraction]) -> str:
    lines = ["10 DIM X(11): FOR K=0 TO 11: X(K)=K*10: NEXT: ON ERROR GOTO 30000"]
    for k, x in enumerate(values):
        lines.append(f"{20 + 10 * k} A#=CVD({basic_bytes(encoded(x))}): PRINT CINT(A#);: I%=A#: PRINT I%;: PRINT X(A#)")
    lines += ['29999 END', '30000 PRINT "E";ERR: RESUME NEXT']
    return "\n".join(lines) + "\n"


def test_cint_integer_assignment_and_subscripts_round_the_exact_value():
    """CINT, ``I% = A#`` and ``X(A#)`` round half away from zero on the double's exact value
    (the bit worth a half decides, $CINC/$CIND): .5 - 2**-54 is 0, not 1 (IEEE's
    ``x + .5`` rounds up), nor does a 56-bit value a 56th bit below a half round up; a
    subscript of -.5 is -1, so Illegal function call (INTIDX)."""
    values = near_halves()
    ours = run_gw(cint_program(values))
    assert ours == _row_text(values)


def _row_text(values: list[Fraction]) -> str:
    """The rows cint_program prints: CINT, the integer variable, the element or ``E 5``."""
    rows = []
    for x in values:
        n = half_away(x)
        number = lambda v: f"{v}" if v < 0 else f" {v}"
        row = f"{number(n)} {number(n)} "
        row += f"{number(n * 10)} " if n >= 0 else "E 5 "
        rows.append(row + "\n")
    return "".join(rows)


def test_cint_agrees_with_pcbasic_where_it_computes_as_the_source(pc):
    """PC-BASIC 2.0.8 rounds the same values as the exact rationals (its CINT of a double
    reads the whole value too): the reference above, checked on the same program."""
    values = near_halves()
    assert pc.program(cint_program(values)).replace("\r", "") == _row_text(values)


def test_print_using_exponent_of_a_double_is_d(pc):
    """PRINT USING's ``^^^^`` writes ``D`` for a double (MATH1.ASM $PUEXP asks the type:
    ``E`` for a single, ``D`` for a double), as PC-BASIC 2.0.8: generated quotients,
    products and literals in generated fields, singles beside them."""
    rng = random.Random(base_seed() + 43)
    statements = ['PRINT USING "#.##^^^^"; 1.5#; 1.5; 0#; -1D-20; 2#/3; 365424D-29; -1D-35']
    for _ in range(case_count(60)):
        before, after = rng.randint(0, 4), rng.randint(0, 8)
        field = ("+" if rng.random() < 0.2 else "") + "#" * max(before, 1) + ("." + "#" * after if after else "") + "^^^^"
        a, b = rng.randint(1, 999999), rng.randint(3, 9999)
        value = rng.choice([f"{a}#/{b}", f"-{a}#*{b}", f"{a}D{rng.randint(-30, 30)}", f"{a}!/{b}"])
        statements.append(f'PRINT USING "{field} "; {value}')
    source = "\n".join(f"{10 + 10 * k} {text}" for k, text in enumerate(statements)) + "\n"
    ours = run_gw(source)
    assert "D+" in ours and "E+" in ours
    assert ours == pc.program(source).replace("\r", "")
