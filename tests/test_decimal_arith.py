"""``--arith decimal`` (casio): 12-digit decimal arithmetic (the FX-850P manual: a 12-digit mantissa inside) (yaseer/basic/arithmetic/decimal_arith.py).

Checked against independent computations: exact rationals (``fractions``) rounded
half up to 12 significant digits by a function of this file, and mpmath at 40
digits for SQR, EXP, LOG and the trigonometric functions.
"""

from __future__ import annotations

import io
import math
import random
from fractions import Fraction

import mpmath
import pytest

from yaseer.basic.arithmetic import decimal_arith as D
from yaseer.basic.dialects.dialect import CASIO
from yaseer.basic.machine.machine import Machine

DECIMAL = CASIO._replace(arithmetic="decimal")


def round12(value: Fraction) -> float:
    """``value`` rounded half up (away from zero) to 12 significant digits, as a float."""
    if value == 0:
        return 0.0
    sign = -1 if value < 0 else 1
    value = abs(value)
    exponent = math.floor(math.log10(value))  # may be one off for values near a power of ten:
    while value >= Fraction(10) ** (exponent + 1):
        exponent += 1
    while value < Fraction(10) ** exponent:
        exponent -= 1
    scale = Fraction(10) ** (11 - exponent)
    digits = math.floor(value * scale + Fraction(1, 2))
    return sign * float(Fraction(digits) / scale)


# each arithmetic operation by name, beside its exact result on Fractions
EXACT_OPERATIONS = [
    ("add", lambda a, b: a + b), ("subtract", lambda a, b: a - b),
    ("multiply", lambda a, b: a * b), ("divide", lambda a, b: a / b),
]


def random_decimal(rng: random.Random) -> Fraction:
    """A decimal of 1..12 significant digits between 1e-6 and 1e7 (either sign)."""
    digits = rng.randint(1, 12)
    mantissa = rng.randint(10 ** (digits - 1), 10 ** digits - 1)
    value = Fraction(mantissa, 10 ** rng.randint(0, 12))
    return -value if rng.random() < 0.3 else value


@pytest.mark.parametrize("name, exact", EXACT_OPERATIONS)
def test_operations_round_the_exact_result_to_12_digits(name, exact):
    rng = random.Random(13)
    operation = getattr(D, name)
    for _ in range(2000):
        a, b = random_decimal(rng), random_decimal(rng)
        assert operation(float(a), float(b)) == round12(exact(a, b)), (a, b)


def random_eighths(rng: random.Random) -> Fraction:
    """Counts up to 1E10 and multiples of 1/8 below 1E9 in size (at most 12 digits; either
    sign, zero included), and now and then a decimal that is neither: the operands of loops."""
    if rng.random() < 0.1:
        return random_decimal(rng)
    size = rng.choice([10, 1000, 10**6, 10**9 - 1, 10**9, 10**10])
    if rng.random() < 0.5 and size < 10**9:
        return Fraction(rng.randint(-8 * size, 8 * size), 8)
    return Fraction(rng.randint(-size, size))


@pytest.mark.parametrize("name, exact", EXACT_OPERATIONS)
def test_counts_and_fractions_of_eighths_round_as_any_other_decimal(name, exact):
    # the operands for which the arithmetic takes its short cut (multiples of 1/8 below
    # 1E9) and their neighbours: the same exactly rounded results
    rng = random.Random(8)
    operation = getattr(D, name)
    for _ in range(4000):
        a, b = random_eighths(rng), random_eighths(rng)
        if b == 0 and name == "divide":
            continue
        expected = round12(exact(a, b))
        assert operation(float(a), float(b)) == expected, (a, b)
    for a, b in [(0.5, 0.25), (-0.125, 8.0), (999999999.875, 0.125), (1e9 - 1, 1.0), (3.0, 7.0), (1.0, 3.0),
                 (999999999.125, 1.0), (-999999999.875, 2.0)]:  # (13 digits: rounded to 12)
        assert operation(a, b) == round12(exact(Fraction(a), Fraction(b))), (a, b)


def test_a_square_is_the_exact_square_rounded_once():
    rng = random.Random(2)
    for _ in range(2000):
        a = random_eighths(rng)
        assert D.power(float(a), 2.0) == round12(a * a), a


def test_signed_zeros_are_the_decimal_modules():
    for a, b in [(0.0, -0.0), (-0.0, -0.0), (-0.0, 0.0), (0.0, -5.0), (-0.0, 5.0), (2.0, -2.0)]:
        for name in ("add", "subtract", "multiply", "divide"):
            if name == "divide" and b == 0:
                continue
            got = getattr(D, name)(a, b)
            decimal_result = float(getattr(D.CONTEXT, name)(D.dec(a), D.dec(b)))
            assert math.copysign(1.0, got) == math.copysign(1.0, decimal_result) and got == decimal_result, \
                (name, a, b)


@pytest.mark.parametrize("function", ["sqrt", "exp", "log", "log10", "sin", "cos", "tan", "atn"])
def test_functions_agree_with_mpmath_to_12_digits(function):
    mpmath.mp.dps = 40
    rng = random.Random(7)
    mismatches = 0
    for _ in range(300):
        x = Fraction(rng.randint(1, 10 ** 7), 10 ** rng.randint(0, 5))
        if function in ("exp",):
            x = x / 10 ** 5
        if function == "tan" and (x % 180) in (90,):
            continue
        arg = mpmath.mpf(x.numerator) / x.denominator
        degrees = arg * mpmath.pi / 180
        reference = {"sqrt": lambda: mpmath.sqrt(arg), "exp": lambda: mpmath.exp(arg),
                     "log": lambda: mpmath.log(arg), "log10": lambda: mpmath.log10(arg),
                     "sin": lambda: mpmath.sin(degrees),
                     "cos": lambda: mpmath.cos(degrees), "tan": lambda: mpmath.tan(degrees),
                     "atn": lambda: mpmath.atan(arg) * 180 / mpmath.pi}[function]()
        ours = getattr(D, function)(float(x))
        expected = round12(Fraction(mpmath.nstr(reference, 35, min_fixed=-40, max_fixed=40)))
        if abs(reference) < mpmath.mpf("1e-20"):
            expected = 0.0
        mismatches += ours != expected
    assert mismatches == 0


EDGES = ["1", "2", "7", "89", "91", "179.9999999999", "180.0000000001", "0.000001", "359.9999999", "1000",
         "123456789.1234", "1.000000000001", "0.9999999999999", "45", "30", "60", "0.5", "3.1415926",
         "99999.99999999", "1E-7", "2.718281828459"]


@pytest.mark.parametrize("function", ["sqrt", "exp", "log", "log10", "sin", "cos", "sin radians", "cos radians"])
def test_functions_at_the_edges_agree_with_mpmath(function):
    # where the float functions lose digits (near zeros of SIN and COS, LOG near 1,
    # large angles) and the counts of BM8: the decimal result, correctly rounded
    mpmath.mp.dps = 40
    name, _, unit = function.partition(" ")
    for text in EDGES + [str(k) for k in range(1, 1001, 7)]:
        for sign in (1, -1):
            x = Fraction(format(float(Fraction(text)), ".12g")) * sign  # (read in as 12 digits)
            if name in ("sqrt", "log", "log10") and x <= 0 or name == "exp" and abs(x) > 200:
                continue
            arg = mpmath.mpf(x.numerator) / x.denominator
            angle = arg if unit else arg * mpmath.pi / 180
            reference = {"sqrt": mpmath.sqrt, "exp": mpmath.exp, "log": mpmath.log, "log10": mpmath.log10,
                         "sin": mpmath.sin, "cos": mpmath.cos}[name](arg if name in ("sqrt", "exp", "log", "log10")
                                                                     else angle)
            expected = round12(Fraction(mpmath.nstr(reference, 35, min_fixed=-40, max_fixed=40)))
            if name in ("sin", "cos") and not unit and x % 90 == 0:
                expected = round(float(reference))  # exact at right angles, as the manual's degree mode
            ours = getattr(D, name)(float(x), not unit) if name in ("sin", "cos") else getattr(D, name)(float(x))
            assert ours == expected, (function, text, sign)


def test_the_common_logarithm_near_its_rounding_halfway_points():
    # operands whose LOG lies within a few units of the 15th digit of a point halfway between
    # two 12-digit results (the float function cannot tell there), and powers of ten (exact):
    # the decimal module's correctly rounded result every time
    mpmath.mp.dps = 50
    rng = random.Random(22)
    cases = [10.0 ** k for k in range(-20, 21)]
    for _ in range(3000):
        halfway = mpmath.mpf(rng.randint(10 ** 11, 10 ** 12 - 1)) + mpmath.mpf("0.5")
        target = halfway * mpmath.mpf(10) ** rng.randint(-12, -10)  # LOG between 0.1 and 10
        x = float(format(float(mpmath.power(10, target)), ".12g"))
        cases += [x, float(format(x * (1 + 1e-11), ".12g")), float(format(x * (1 - 1e-11), ".12g"))]
    for x in cases:
        expected = float(D.CONTEXT.log10(D.dec(x)))
        assert D.log10(x) == expected, x


def run(program: str, dialect=DECIMAL) -> str:
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect=dialect)
    machine.load(program)
    machine.run()
    return screen.getvalue()


def test_tenths_add_up_exactly():
    program = "10 X = 1: FOR K = 1 TO 10: X = X - .1: NEXT K: PRINT X; X = 0\n"
    assert run(program) == " 0 -1 \n"
    assert run(program, CASIO) == " 1.387778781E-16  0 \n"  # binary doubles, as today


def test_the_paper_loop_lands_on_its_limit():
    program = "10 FOR T = .1 TO 360.1 STEP 20: N = N + 1: L = T: NEXT T: PRINT N; L = 360.1; (1/3)*3 - 1\n"
    assert run(program) == " 19 -1 -1E-12 \n"


def test_exact_right_angles_and_ten_digit_display():
    assert run("10 PRINT COS(90); SIN(180); SIN(30); 2/3\n") == " 0  0  .5  .6666666667 \n"


def test_overflow_beyond_the_casio_range():
    machine = Machine(screen=io.StringIO(), dialect=DECIMAL)
    machine.load("10 X = 1E60 * 1E60\n")
    with pytest.raises(Exception, match="Overflow"):
        machine.run()


def test_run_option(tmp_path, capsys):
    from yaseer.cli import main

    listing = tmp_path / "tenths.bas"
    listing.write_text("10 X = 1: FOR K = 1 TO 10: X = X - .1: NEXT K: PRINT X\n")
    assert main(["run", "--arith", "decimal", str(listing)]) == 0
    assert capsys.readouterr().out == " 0 \n"


def test_the_casio_range_ends_below_1e100_and_starts_at_1e_99():
    """specifications.md: ±1E-99 .. ±9.999999999E+99 and 0, 12 digits inside."""
    assert run("10 X = 9.99999999999E+99: PRINT X; 1E-99; 1E-99 / 10; -1E-50 * 1E-50\n") == \
        " 1E+100  1E-99  0  0 \n"  # (the 12-digit largest number shows rounded to 10 digits)
    with pytest.raises(Exception, match="Overflow"):
        run("10 X = 9.99999999999E+99 * 10\n")


def test_a_result_is_rounded_to_twelve_digits_before_the_range_takes_it():
    # the exact product 9.99999999999E-100 has 12 digits and lies below 1E-99: 0, as the quotient of
    # the same 12-digit value is; 1.00000000000181E-99 rounds to 1E-99 and stays
    assert run("10 PRINT 3E-50 * 3.33333333333E-50; 1E-99 / 1.00000000001; -3E-50 * 3.33333333333E-50\n") == \
        " 0  0  0 \n"
    assert run("10 PRINT 3.16227766017E-50 ^ 2; 3.16227766016E-50 ^ 2\n") == " 1E-99  0 \n"
    assert D.multiply(3e-50, 3.33333333333e-50) == 0.0 and D.multiply(5e-50, 2e-50) == 1e-99


def test_pi_inside_has_eleven_digits():
    """PI.md: 3.1415926536 inside, 3.141592654 on the display."""
    assert run("10 PRINT PI; PI - 3.1415926536; PI * 1E10 - 31415926536\n") == " 3.141592654  0  0 \n"
