"""GW-BASIC's single-precision arithmetic (yaseer/basic/arithmetic/single_arith.py) against
independent references:

* ``+ -``: tests/fadds_reference.py, a transcription of ``$FADDS``'s 8086 registers
  (MATH1.ASM), bit for bit, on random operands and on constructed near-tie cases;
  PC-BASIC 2.0.8's ``Single`` differs from the source in about 0.4% of sums (it keeps no
  sticky bit as ``$FADDS`` does), so it is no reference for them;
* ``*``: PC-BASIC 2.0.8's own MBF classes (its ``Single`` reproduces GW's ``$FMULS``), bit
  for bit;
* PRINT's digits: PC-BASIC's where they are those of the source's ``$FOFMT`` steps, else
  those steps redone on fractions (tests/single_digits_support.py);
* ``/`` and SQR: the exact rational quotient and integer square root rounded to
  the nearest 24 bits (GW's ``$FDIVS`` and ``$SQR`` round so; PC-BASIC does not);
* integer powers: Knuth's binary powering written here over PC-BASIC's multiply;
* a double made single: the exact value rounded half up on the 25th bit (``$CSD``);
* the compiled code's inline sum (``A=A+1``) against the helper it stands for.
"""

from __future__ import annotations

import io
import math
import random
import struct
from decimal import Decimal
from fractions import Fraction

import fadds_reference
import pytest

from yaseer.basic.arithmetic import single_arith as sa
from yaseer.basic.machine.machine import Machine

pcbasic_numbers = pytest.importorskip("pcbasic.basic.values.numbers")
pcbasic_values = pytest.importorskip("pcbasic.basic.values.values")

VALUES = pcbasic_values.Values(None, False)
CASES = 20000


def pc_single(x: float):
    """PC-BASIC's Single holding ``x`` (a single) exactly, built from its MBF bytes."""
    if x == 0:
        return pcbasic_numbers.Single(None, VALUES).from_bytes(b"\0\0\0\0")
    m, e = math.frexp(abs(x))
    mantissa = int(m * 2 ** 24)
    assert mantissa * 2.0 ** (e - 24) == abs(x)
    bits = (mantissa & 0x7FFFFF) | ((x < 0) << 23)
    return pcbasic_numbers.Single(None, VALUES).from_bytes(bytes([bits & 255, (bits >> 8) & 255, bits >> 16, e + 128]))


def pc_result(operation) -> float:
    try:
        return operation().to_value()
    except OverflowError:
        return math.inf


def random_single(rng: random.Random) -> float:
    """Singles of many shapes: full mantissas at many scales, short ones, near 1."""
    kind = rng.random()
    if kind < 0.35:
        x = math.ldexp(rng.randrange(1 << 23, 1 << 24), rng.randrange(-40, 40))
    elif kind < 0.55:
        x = float(rng.randrange(1, 1 << 12)) * 2.0 ** rng.randrange(-6, 6)
    elif kind < 0.65:
        x = math.ldexp(rng.randrange(1 << 23, 1 << 24), rng.randrange(-145, 100))
    else:
        x = math.ldexp(rng.randrange(1 << 23, 1 << 24), rng.randrange(-26, -18))
    return -x if rng.random() < 0.5 else x


def pairs(seed: int, count: int = CASES):
    rng = random.Random(seed)
    for _ in range(count):
        a = random_single(rng)
        b = rng.choice([random_single(rng), random_single(rng), random_single(rng), 1.0, -1.0, 0.5, 3.0, a, -a])
        yield a, b


def nearest_single(value: Fraction) -> float:
    """The exact ``value`` rounded to 24 bits, ties to even (an independent rounding)."""
    if value == 0:
        return 0.0
    sign = -1 if value < 0 else 1
    value = abs(value)
    exponent = value.numerator.bit_length() - value.denominator.bit_length()
    while Fraction(2) ** exponent > value:
        exponent -= 1
    while Fraction(2) ** (exponent + 1) <= value:
        exponent += 1
    scaled = value / Fraction(2) ** (exponent - 23)  # in [2**23, 2**24)
    whole = scaled.numerator // scaled.denominator
    rest = scaled - whole
    if rest > Fraction(1, 2) or (rest == Fraction(1, 2) and whole % 2):
        whole += 1
    result = math.ldexp(whole, exponent - 23)
    return sign * (math.inf if result >= 2.0 ** 127 else result)


@pytest.mark.parametrize("seed", [1, 2])
def test_add_subtract_are_the_sources_and_multiply_pcbasics_bit_for_bit(seed):
    """``+ -`` against the transcription of ``$FADDS`` (PC-BASIC 2.0.8's sums differ from it
    in some of these: counted, not asserted), ``*`` against PC-BASIC's ``$FMULS``."""
    differs_from_ieee = pc_differs = 0
    for a, b in pairs(seed):
        A, B = pc_single(a), pc_single(b)
        for ours, source, theirs, exact in (
            (sa.add(a, b), fadds_reference.add(a, b), pc_result(lambda: A.clone().iadd(B)), a + b),
            (sa.subtract(a, b), fadds_reference.subtract(a, b), pc_result(lambda: A.clone().isub(B)), a - b),
            (sa.multiply(a, b), None, pc_result(lambda: A.clone().imul(B)), a * b),
        ):
            ours = math.inf if abs(ours) == math.inf else ours
            theirs = math.inf if abs(theirs) >= 1.7e38 else theirs
            if source is None:
                assert ours == theirs, (a, b, ours, theirs)
            else:
                assert ours == source, (a, b, ours, source)
                pc_differs += ours != theirs and abs(ours) != math.inf
            differs_from_ieee += ours != struct.unpack("f", struct.pack("f", exact))[0] if abs(exact) < 3e38 else 0
    assert differs_from_ieee > 100  # the cases do reach GW's own rounding
    assert pc_differs > 0  # (and PC-BASIC's sums are not the source's everywhere)


def test_products_near_half_a_unit_are_pcbasics():
    """single_arith.product_near_half (the compiled code's products whose nearest single is
    3/8 to 1/2 of a unit beyond them, or half a unit from them) against PC-BASIC's $FMULS:
    products of random mantissas (long and short) kept only when they fall there."""
    rng = random.Random(11)
    reached = 0
    while reached < 3000:
        a = math.ldexp(rng.randrange(1 << 23, 1 << 24), rng.randrange(-60, 40)) * rng.choice([1, -1])
        b = math.ldexp(rng.randrange(1 << 23, 1 << 24) if rng.random() < 0.7 else rng.randrange(1, 1 << 12),
                       rng.randrange(-60, 40)) * rng.choice([1, -1])
        p = a * b
        cut = nearest_single(Fraction(p))
        below = (abs(Fraction(p)) - abs(Fraction(cut))) / Fraction(2) ** (math.frexp(p)[1] - 24)  # units of p's binade
        if not (-Fraction(1, 2) <= below < -Fraction(3, 8) or below == Fraction(1, 2)):
            continue
        reached += 1
        assert sa.product_near_half(p, cut) == pc_result(lambda: pc_single(a).imul(pc_single(b))) == sa.product(p)


def test_sums_near_a_tie_after_the_carry_are_the_sources():
    """An addition whose carry shifts the sum right drops the sticky bit: a guard byte of
    ``0100 0000`` with bits below it becomes exactly half (IEEE rounds up, GW half to even).
    Constructed, not left to chance, against the transcription of ``$FADDS``."""
    rng = random.Random(9)
    reached = 0
    for _ in range(20000):
        large = float(rng.randrange((1 << 24) - 3000, 1 << 24))
        small = math.ldexp(rng.randrange(1 << 23, 1 << 24) | 1, -rng.choice([7, 8, 9, 10, 12]))
        if rng.random() < 0.5:
            large, small = -large, -small
        source = fadds_reference.add(large, small)
        assert sa.add(large, small) == source
        reached += source != struct.unpack("f", struct.pack("f", large + small))[0]
    assert reached > 0


def _long_way(a: float, b: float) -> float:
    """``$FADDS`` on integer working numbers (single_arith.working_sum and _rounded)."""
    small, large = (a, b) if abs(a) <= abs(b) else (b, a)
    small_exponent, small_mantissa = sa.working_parts(small)
    exponent, mantissa = sa.working_parts(large)
    return sa._rounded(*sa.working_sum(small_exponent, small_mantissa, small < 0, exponent, mantissa, large < 0))


def test_differences_are_the_register_steps():
    """add (its float fast paths and its long way on integers) against the transcription of
    ``$FADDS`` for operands of opposite signs: the smaller operand every number of binades
    below (its bits shifted out of the 32-bit register through the sticky bit), guard bytes
    of every kind, differences that cancel into lower binades, and the range's low end."""
    rng = random.Random(31)
    guard_rule = 0
    for k in range(12000):
        exponent = rng.randrange(-126, 100) if k % 7 else rng.randrange(-128, -110)
        large = math.ldexp(rng.randrange(1 << 23, 1 << 24) if k % 5 else (1 << 23) + rng.randrange(4), exponent)
        shift = rng.randrange(0, 34)
        bits = rng.choice([24, 24, 12, 5, 1])
        small = math.ldexp(rng.randrange(1 << (bits - 1), 1 << bits), exponent + 24 - bits - shift)
        if small >= large or small < sa.TINY:  # (both singles of MBF's range)
            continue
        a, b = (large, -small) if rng.random() < 0.5 else (-large, small)
        if rng.random() < 0.5:
            a, b = b, a
        expected = fadds_reference.add(a, b)
        assert _long_way(a, b) == expected, (a, b)
        assert sa.add(a, b) == expected, (a, b)
        guard_rule += expected != nearest_single(Fraction(a) + Fraction(b))
    assert guard_rule > 300  # (GW other than the nearest single)


def test_differences_near_half_a_unit_are_the_register_steps():
    """add's float rule for a difference that keeps the larger operand's binade (the
    nearest single, from 1/4 of a unit below it to 1/2 above) against the transcription
    of ``$FADDS`` and add's own integer register steps: the smaller operand 4 to 31 binades below (bits shifted out), its
    low byte set to the patterns around a guard byte of 0x80, 0xA0 and 0xC0, and larger
    operands next to a power of two (differences that leave its binade go the long way)."""
    rng = random.Random(41)
    reached = 0
    for k in range(40000):
        high = (1 << 23) + rng.randrange(64) if k % 3 == 0 else rng.randrange(1 << 23, 1 << 24)
        large = math.ldexp(high, rng.randrange(-40, 40))
        low = rng.choice([0x80, 0x7F, 0x81, 0xA0, 0x9F, 0xA1, 0xC0, 0xBF, 0xC1, 0x40, 0x3F, rng.randrange(256)])
        small = math.ldexp((rng.randrange(1 << 15, 1 << 16) << 8) | low, math.frexp(large)[1] - 24 - rng.randrange(4, 32))
        a, b = (large, -small) if rng.random() < 0.5 else (-small, large)
        if rng.random() < 0.5:
            a, b = -a, -b
        expected = fadds_reference.add(a, b)
        assert sa.add(a, b) == expected == _long_way(a, b), (a, b)
        reached += expected != nearest_single(Fraction(a) + Fraction(b))
    assert reached > 1000  # (GW's rounding, not the nearest, is what these reach)


def test_division_is_the_nearest_single_as_the_source_rounds():
    pc_differs = 0
    for a, b in pairs(3, 8000):
        if not b:
            continue
        expected = nearest_single(Fraction(a) / Fraction(b))
        got = sa.divide(a, b)
        if abs(expected) < 2.0 ** -128:
            expected = 0.0
        assert got == expected or (abs(got) == math.inf and abs(expected) == math.inf), (a, b)
        pc_differs += got != pc_result(lambda: pc_single(a).clone().idiv(pc_single(b)))
    assert pc_differs > 0  # the documented difference from PC-BASIC is real (F-MBF)


def test_division_by_zero_is_left_to_the_policy():
    with pytest.raises(ZeroDivisionError):
        sa.divide(1.0, 0.0)


def test_square_root_is_the_nearest_single():
    rng = random.Random(4)
    for _ in range(5000):
        x = abs(random_single(rng))
        if x < 2.0 ** -100:
            continue
        m, e = math.frexp(x)
        mantissa, exponent = int(m * 2 ** 24), e - 24
        if exponent % 2:
            mantissa, exponent = mantissa * 2, exponent - 1
        root = math.isqrt(mantissa << 60)  # sqrt(mantissa) * 2**30, truncated
        exact_below = Fraction(root, 2 ** 30)  # the root is never exactly a tie unless exact
        expected = nearest_single(exact_below * Fraction(2) ** (exponent // 2)
                                  + (Fraction(1, 2 ** 31) * Fraction(2) ** (exponent // 2)
                                     if root * root != mantissa << 60 else 0))
        assert sa.function_result(math.sqrt(x)) == expected, x
    assert sa.function_result(math.sqrt(2.0)) == math.ldexp(0xB504F3, -23)  # prints 1.414214


def knuth_power_with_pcbasic(x: float, n: int) -> float:
    """x ^ n by Knuth's algorithm A, each product PC-BASIC's MBF multiply."""
    y, z = pc_single(1.0), pc_single(x)
    bits = abs(n)
    while bits:
        if bits & 1:
            y = y.clone().imul(z)
        bits >>= 1
        if bits:
            z = z.clone().imul(z)
    value = y.to_value()
    return nearest_single(Fraction(1) / Fraction(value)) if n < 0 else value


def test_integer_powers_multiply_by_binary_powering():
    rng = random.Random(5)
    for _ in range(3000):
        x = random_single(rng)
        if not 2.0 ** -20 < abs(x) < 2.0 ** 20:
            continue
        n = rng.choice([0, 1, 2, 3, 4, 5, 6, 7, 9, 12, -1, -2, -3, -7])
        if abs(math.log2(abs(x)) * n) > 120:
            continue
        assert sa.power_by_integer(x, n) == knuth_power_with_pcbasic(x, n), (x, n)
        if 0 <= n <= 5:  # PC-BASIC's own ^ by an integer agrees up to 5 (its recursion differs beyond)
            theirs = pc_single(x).clone().ipow_int(pcbasic_numbers.Integer(None, VALUES).from_int(n))
            assert sa.power_by_integer(x, n) == theirs.to_value()
    assert sa.is_integral_power(2.0) and sa.is_integral_power(-3) and not sa.is_integral_power(0.5)
    assert not sa.is_integral_power(40000.0)


def test_a_double_made_single_rounds_half_up_on_the_25th_bit():
    rng = random.Random(6)
    for _ in range(5000):
        x = rng.uniform(-1e6, 1e6) * 2.0 ** rng.randrange(-30, 30)
        if not x:
            continue
        m, e = math.frexp(abs(x))
        scaled = Fraction(abs(x)) / Fraction(2) ** (e - 24)
        whole = scaled.numerator // scaled.denominator
        whole += scaled - whole >= Fraction(1, 2)
        assert sa.from_double(x) == math.copysign(math.ldexp(whole, e - 24), x), x
    half = 1.0 + 2.0 ** -24  # exactly half a unit above 1: up, where IEEE rounds to even
    assert sa.from_double(half) == 1.0 + 2.0 ** -23


def test_print_digits_are_pcbasics_where_they_are_the_sources():
    """PRINT's text of generated singles is PC-BASIC's where PC-BASIC's 7 digits are those of
    the source's steps (most), else it shows the source's digits (MATH1.ASM ``$FOFMT``: the
    reference on fractions, tests/single_digits_support.py)."""
    from single_digits_support import pc_prints_the_source, source_digits

    from yaseer.basic.arithmetic.values import str_dollar

    rng = random.Random(7)
    compared = differing_in_pcbasic = 0
    for _ in range(20000):
        x = random_single(rng) if rng.random() < 0.7 else sa.nearest(rng.randint(1, 10 ** 7) / 10 ** rng.randint(0, 8))
        if not x or abs(x) < 2.0 ** -120 or abs(x) > 2.0 ** 120:
            continue
        compared += 1
        ours = str_dollar(x)
        if pc_prints_the_source(x):
            assert ours == pc_single(x).to_str(True, False).decode(), x
        else:
            differing_in_pcbasic += 1
            n, power = source_digits(abs(Fraction(x)))
            assert Decimal(ours.strip().lstrip("-")) == Decimal(n).scaleb(power), x
    assert 0 < differing_in_pcbasic < 0.05 * compared
    # $FOTNV multiplies by 10 with $FMULS (8251576.25: a tie, to even), $FOTCV adds .5;
    # PC-BASIC rounds its guard byte first and prints 825157.7
    assert str_dollar(825157.625) == " 825157.6"


def test_print_digits_of_every_binade_are_the_sources_steps():
    """Every exponent byte of MBF's range (1 .. 255: 2**-128 up to the largest single), 40
    mantissas each, the extremes among them: the digits are those of the source's steps
    on fractions (tests/single_digits_support.py)."""
    from single_digits_support import source_digits

    from yaseer.basic.arithmetic.mbf_digits import decimal_digits

    rng = random.Random(8)
    for byte in range(1, 256):
        for mantissa in [1 << 23, (1 << 24) - 1] + [rng.randrange(1 << 23, 1 << 24) for _ in range(38)]:
            x = math.ldexp(mantissa, byte - 128 - 24)
            assert decimal_digits(x) == decimal_digits(-x) == source_digits(Fraction(x)), (byte, mantissa)


def test_the_range_ends_as_mbfs():
    assert sa.multiply(2.0 ** 100, 2.0 ** 30) == math.inf
    assert sa.multiply(-(2.0 ** 100), 2.0 ** 30) == -math.inf
    assert sa.multiply(2.0 ** -100, 2.0 ** -30) == 0.0
    assert sa.add(2.0 ** 126, 2.0 ** 126) == math.inf
    assert sa.divide(2.0 ** -100, 2.0 ** 40) == 0.0
    assert sa.nearest(1.5 * 2.0 ** -128) == 1.5 * 2.0 ** -128  # below IEEE's normal range, all 24 bits
    assert sa.nearest(2.0 ** -129) == 0.0


def run_gw(text: str) -> str:
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect="gw")
    machine.load(text)
    machine.run()
    return screen.getvalue()


def run_in_parts(lines: list[str], size: int) -> dict:
    """Run ``lines`` in gw as programs of ``size`` lines each (a program of them all would
    not fit in GW-BASIC's 64 KB): line -> the machine that ran it."""
    machines = {}
    for start in range(0, len(lines), size):
        machine = Machine(screen=io.StringIO(), dialect="gw")
        machine.load("\n".join(lines[start:start + size]) + "\n")
        machine.run()
        machines.update((line, machine) for line in lines[start:start + size])
    return machines


def test_the_inline_sum_of_the_compiled_code_is_the_helpers():
    """``A=A+c`` with a small constant is tested inline (a sum of at most 24 bits is
    GW's); every other sum goes to ``add``: the two must agree."""
    rng = random.Random(8)
    values = [random_single(rng) for _ in range(60)] + [0.0, 16777215.0, 16777216.0, -16777216.0, 0.1, 1e30]
    constants = ["1", "-1", "2.5", ".1", "1000000!", "3E+20"]
    lines = []
    for k, v in enumerate(values):
        c = constants[k % len(constants)]
        lines.append(f"{10 + k} A!={v:.9E}: B!=A!+{c}: C!={c}: D!=A!+C!: PRINT B!=D!; B!-D!")
    text = "\n".join(lines) + "\n"
    assert run_gw(text).split() == ["-1", "0"] * len(values)


COMPILED = {  # an expression of singles A! and B!, and what the helpers make of it
    "A!*B!": lambda a, b: sa.multiply(a, b),
    "A!/B!": lambda a, b: sa.divide(a, b),
    "A!+B!": lambda a, b: sa.add(a, b),
    "A!-B!": lambda a, b: sa.subtract(a, b),
    "A!^2": lambda a, b: sa.power_by_integer(a, 2),
    "SQR(ABS(A!))": lambda a, b: sa.nearest(math.sqrt(abs(a))),
    "(A!*B!)+(A!/B!)*3": lambda a, b: sa.add(sa.multiply(a, b), sa.multiply(sa.divide(a, b), 3.0)),
    "(A!-B!)^2-A!*(B!+1)": lambda a, b: sa.subtract(sa.power_by_integer(sa.subtract(a, b), 2),
                                                    sa.multiply(a, sa.add(b, 1.0))),
}


def test_the_compiled_code_gives_what_the_helpers_give():
    """``+ - * /``, ``X^2`` and SQR between singles, as the compiled code computes them
    (tested inline where it can be: number_models._tested), give what the helpers give
    (each checked against PC-BASIC or the exact value above), on operands of every shape:
    plain, through scratch locals, and products in GW's own rounding band."""
    rng = random.Random(9)
    lines = []
    for k in range(400):
        a, b = random_single(rng), rng.choice([random_single(rng), random_single(rng), 3.0, 0.1, -7.5])
        if not 1e-18 < abs(a) < 1e18 or not 1e-18 < abs(b) < 1e18:
            continue  # (the range's ends are test_the_range_ends_as_mbfs's)
        results = ": ".join(f"R{k}X{n}!={expression.replace('A!', f'A{k}!').replace('B!', f'B{k}!')}"
                            for n, expression in enumerate(COMPILED))
        lines.append(f"{10 + k} A{k}!={a:.9E}: B{k}!={b:.9E}: {results}")
    machines = run_in_parts(lines, 40)
    checked = banded = 0
    for line in lines:
        k = int(line.split()[0]) - 10
        machine = machines[line]
        a, b = machine.scalars[f"A{k}!"], machine.scalars[f"B{k}!"]  # as the literals were read
        for n, helper in enumerate(COMPILED.values()):
            assert machine.scalars[f"R{k}X{n}!"] == helper(a, b), (a, b, list(COMPILED)[n])
            checked += 1
        banded += sa.multiply(a, b) != sa.nearest(a * b)  # GW's product rounding is not the nearest
    assert checked > 2400 and banded > 5
    code = "".join(machine.compiled[0].source for machine in set(machines.values()))
    assert "_sv if" in code and "_sh if" in code and "(_sc - _sv) or 0.0)" in code  # the inline tests are there


def test_compiled_sums_near_a_tie_after_the_carry_are_the_helpers():
    """Sums of singles whose exponents are close, as the compiled code tests them inline,
    against the transcription of ``$FADDS``: among them sums 1/512 of a unit from halfway,
    where GW's carry rounds otherwise than the nearest (test_sums_near_a_tie_after_the_carry_are_the_sources)."""
    rng = random.Random(10)
    lines, near_tie = [], 0
    for k in range(2000):
        exponent = rng.randrange(-30, 10)
        if k % 2:  # a carry that shifts out a 1 below a guard byte of 0x80: 1/512 of a unit above halfway
            m = rng.randrange((1 << 24) - (1 << 15), 1 << 24)
            n = rng.randrange((1 << 24) - m, (1 << 16) - 2)
            n += (m + n + 1) % 2  # m + n odd
            a, b = math.ldexp(m, exponent), math.ldexp(256 * n + 1, exponent - 8)
        else:
            a = math.ldexp(rng.randrange(1 << 23, 1 << 24), exponent)
            b = math.ldexp(rng.randrange(1 << 23, 1 << 24), exponent - rng.randrange(0, 12))
        a, b = (-a, -b) if rng.random() < 0.5 else (a, b)
        b = -b if rng.random() < 0.3 else b
        near_tie += (math.frexp(a + b)[0] * 16777216.0) % 1.0 in (0.501953125, 0.498046875)
        lines.append(f"{10 + k} A{k}!={a:.9E}: B{k}!={b:.9E}: S{k}!=A{k}!+B{k}!: D{k}!=A{k}!-B{k}!")
    machines = run_in_parts(lines, 200)
    for k in range(len(lines)):
        machine = machines[lines[k]]
        a, b = machine.scalars[f"A{k}!"], machine.scalars[f"B{k}!"]
        assert (machine.scalars[f"S{k}!"], machine.scalars[f"D{k}!"]) == (
            fadds_reference.add(a, b), fadds_reference.subtract(a, b)), (a, b)
    assert near_tie > 100


def test_an_expression_too_deep_for_the_inline_tests_is_the_helpers():
    """Nested 55 deep, the inline tests would pass Python's nesting limit: the statement is
    compiled with the helper calls alone, and still gives what they give."""
    expression, value = "A!", 1.0
    for _ in range(55):
        expression, value = f"({expression}*1.5!+.1!)", sa.add(sa.multiply(value, 1.5), sa.nearest(0.1))
    machine = Machine(screen=io.StringIO(), dialect="gw")
    machine.load(f"10 A!=1: B!={expression}\n")
    machine.run()
    assert machine.scalars["B!"] == value
    assert "_sadd(_sp(" in machine.compiled[0].source


def test_a_widened_single_prints_pcbasics_sixteen_digits():
    """A double holding a single (``B#=A!``, CDBL) or an integer is exact in GW's 56 bits:
    its 16 digits are those of GW's output routine (PC-BASIC's ``Double`` where its digits
    are the source's, tests/test_mbf_double.py; else the source's), which differ from the
    exactly rounded decimal in about 2% of such values."""
    from test_mbf_double import pc_agrees_with_the_source, source_digits
    from test_mbf_double_whole import encoded
    from yaseer.basic.arithmetic.values import Double, str_dollar

    rng = random.Random(10)
    differs_from_exact = 0
    for _ in range(20000):
        x = random_single(rng) if rng.random() < 0.8 else float(rng.randint(-10 ** 7, 10 ** 7))
        if not x or abs(x) < 2.0 ** -100 or abs(x) > 2.0 ** 100:
            continue
        theirs = pcbasic_numbers.Double(None, VALUES).from_single(pc_single(x)).to_str(True, False).decode()
        data = encoded(Fraction(x))
        if pc_agrees_with_the_source(data):
            assert str_dollar(Double(x)) == theirs, x
        else:
            n, power = source_digits(data)
            assert Decimal(str_dollar(Double(x)).strip().lstrip("-").replace("D", "E")) == Decimal(n).scaleb(power), x
        exact = format(Decimal(abs(x)), ".16g").lstrip("0")
        differs_from_exact += "E" not in theirs and "e" not in exact and theirs.strip().lstrip("-").rstrip("0").rstrip(".") != exact.rstrip("0").rstrip(".")
    assert differs_from_exact > 0  # the routine's digits are not simply the exact value's
    assert str_dollar(Double(9.625066757202148)) == " 9.625066757202149"


@pytest.mark.parametrize("power", [1.0, -1.0, 2.0 ** 58, -4.0, 2.0 ** -100, 16777216.0, -16777216.0])
def test_a_power_of_two_less_half_its_unit(power):
    """``$FADDS`` with exponents 24 apart shifts the smaller operand into the guard byte
    (0x80, nothing lost) and normalises the difference: 1 - 2**-24 is .99999994, exact
    (PC-BASIC 2.0.8 gives 1).  With exponents 25 or more apart the larger operand is the
    result as it is: 1 - 1.5 * 2**-25 is 1, where the nearest single is .99999994."""
    half_unit = -power * 2.0 ** -24
    assert sa.add(power, half_unit) == power + half_unit == sa.add(half_unit, power)
    assert sa.subtract(power, -half_unit) == power + half_unit == fadds_reference.add(power, half_unit)
    assert pc_result(lambda: pc_single(power).iadd(pc_single(half_unit))) == power  # (PC-BASIC: not the source)
    assert sa.add(power, 2 * half_unit) == power + 2 * half_unit  # a whole unit is subtracted
    below = 0.75 * half_unit  # exponents 25 apart
    assert sa.add(power, below) == power == fadds_reference.add(power, below) == sa.subtract(power, -below)
    assert nearest_single(Fraction(power) + Fraction(below)) == power + half_unit
