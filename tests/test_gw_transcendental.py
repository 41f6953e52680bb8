"""GW-BASIC's SIN, COS, TAN, ATN, LOG, EXP and fractional powers (gw_transcendental.py).

Three independent references:

* values printed by real GW-BASIC, recorded by PC-BASIC's test suite
  (robhagemans/pcbasic, tests/basic/unsorted/{ATN,COS,SIN,TAN,EXP,LOG}/model/OUTPUT.TXT;
  PC-BASIC itself prints other digits for a third of them) and the issue's
  ``ATN(1)`` = .7853983;
* a second implementation written here from the algorithm as MATH1.ASM and
  MATH2.ASM describe it, over exact fractions: the constants decoded from the
  source's octal byte tables, the double-precision reduction rounded as
  fractions, each single step rounded with the MBF rule it names;
* mpmath: every result within a few units of the last place of the true value.
"""

from __future__ import annotations

import math
import random
from fractions import Fraction

import fadds_reference
import mpmath
import pytest

from yaseer.basic.arithmetic import gw_transcendental as gw
from yaseer.basic.arithmetic import single_arith
from yaseer.basic.arithmetic.values import SINGLE_LARGEST, str_dollar

# ---------------------------------------------------------------- real GW-BASIC

_ARGUMENTS = (-1, 1, -1.5, 1.5, -150, 150, 0, 256, 32768, 65536, SINGLE_LARGEST)
RECORDED = {
    "ATN": (gw.atn, _ARGUMENTS, "-.7853983 .7853983 -.9827938 .9827938 -1.56413 1.56413 0 1.56689 "
                                "1.570766 1.570781 1.570796"),
    "COS": (gw.cos, _ARGUMENTS, ".5403023 .5403023 7.073721E-02 7.073721E-02 .6992508 .6992508 1 "
                                "-3.979076E-02 .3729378 -.7218348 1"),
    "SIN": (gw.sin, _ARGUMENTS, "-.841471 .841471 -.9974951 .9974951 .7148765 -.7148765 0 -.9992081 "
                                ".9278564 .6920655 0"),
    "TAN": (gw.tan, _ARGUMENTS, "-1.557408 1.557408 -14.10142 14.10142 1.022346 -1.022346 0 25.11156 "
                                "2.487965 -.9587588 0"),
    "EXP": (gw.exp, (-1, 1, -1.5, 1.5, -150, 0), ".3678795 2.718282 .2231302 4.481689 0 1"),
    "LOG": (gw.log, (1, 1.5, 150, 256, 32768, 65536, SINGLE_LARGEST),
            "0 .4054651 5.010636 5.545178 10.39721 11.09036 88.02969"),
}


def _recorded_cases():
    for name, (function, arguments, printed) in RECORDED.items():
        for argument, text in zip(arguments, printed.split()):
            yield pytest.param(function, argument, text, id=f"{name}({argument:g})")


@pytest.mark.parametrize(("function", "argument", "printed"), list(_recorded_cases()))
def test_prints_what_gw_basic_printed(function, argument, printed):
    """All 57 recorded values, digit for digit: the function's single as the source computes
    it, printed by the source's ``$FOFMT`` steps (mbf_digits; PC-BASIC's tens print
    ``ATN(1.5)`` .9827937, ``COS(1)`` .5403024, ``SIN(65536)`` .6920654)."""
    assert str_dollar(function(single_arith.nearest(argument))).strip() == printed


def test_atn_of_one_is_the_real_machines():
    assert str_dollar(gw.atn(1.0)) == " .7853983"


# ---------------------------------------------------------------- a second implementation
# Constants as MATH1.ASM's CON86 table lists them: four octal bytes, low mantissa byte
# first, exponent byte last; the top bit of the third byte is the sign.

def mbf(*octal_bytes) -> Fraction:
    low, middle, high, exponent = octal_bytes
    if exponent == 0:
        return Fraction(0)
    mantissa = ((high | 0x80) << 16) | (middle << 8) | low
    value = Fraction(mantissa, 1 << 24) * Fraction(2) ** (exponent - 128)
    return -value if high & 0x80 else value


SINE = [mbf(0o373, 0o327, 0o036, 0o206), mbf(0o145, 0o046, 0o231, 0o207), mbf(0o130, 0o064, 0o043, 0o207),
        mbf(0o341, 0o135, 0o245, 0o206), mbf(0o333, 0o017, 0o111, 0o203)]
ARCTANGENT = [mbf(0o142, 0o065, 0o203, 0o176), mbf(0o120, 0o044, 0o114, 0o176), mbf(0o171, 0o251, 0o252, 0o177),
              mbf(0, 0, 0, 0o201)]
LOG_P = [mbf(0o232, 0o367, 0o031, 0o203), mbf(0o044, 0o143, 0o103, 0o203), mbf(0o165, 0o315, 0o215, 0o204),
         mbf(0o251, 0o177, 0o203, 0o202)]
LOG_Q = [mbf(0, 0, 0, 0o201), mbf(0o342, 0o260, 0o115, 0o203), mbf(0o012, 0o162, 0o021, 0o203),
         mbf(0o364, 0o004, 0o065, 0o177)]
EXPONENTIAL = [mbf(0o174, 0o210, 0o131, 0o164), mbf(0o340, 0o227, 0o046, 0o167), mbf(0o304, 0o035, 0o036, 0o172),
               mbf(0o136, 0o120, 0o143, 0o174), mbf(0o032, 0o376, 0o165, 0o176), mbf(0o030, 0o162, 0o061, 0o200),
               mbf(0, 0, 0, 0o201)]
# Immediate operands of the routines (MOV DX / MOV BX pairs, octal).
TWO_PI = mbf(0o333, 0o017, 0o111, 0o203)
HALF_PI = mbf(0o333, 0o017, 0o111, 0o201)
SIXTH_PI = mbf(0o222, 0o012, 0o006, 0o200)
TAN_TWELFTH_PI = mbf(0o242, 0o060, 0o011, 0o177)
SQR3 = mbf(0o327, 0o263, 0o135, 0o201)
LN2 = mbf(0o030, 0o162, 0o061, 0o200)
LOG2_E = mbf(0o073, 0o252, 0o070, 0o201)
# $IN2PI: eight bytes, a double
INVERSE_TWO_PI = Fraction(int.from_bytes(bytes([0o013, 0o104, 0o116, 0o156, 0o203, 0o371, 0o042 | 0x80]), "little"),
                          1 << 56) * Fraction(2) ** (0o176 - 128)


def split(value: Fraction, bits: int):
    """(units, rest, scale): |value| = (units + rest) * scale, units of ``bits`` bits, 0 <= rest < 1."""
    magnitude = abs(value)
    exponent = math.floor(math.log2(magnitude))
    while Fraction(2) ** exponent > magnitude:
        exponent -= 1
    while Fraction(2) ** (exponent + 1) <= magnitude:
        exponent += 1
    scale = Fraction(2) ** (exponent + 1 - bits)
    units = magnitude // scale
    return units, magnitude / scale - units, scale


def rounded(value: Fraction, bits: int, up) -> Fraction:
    """``value`` cut to ``bits`` bits, one unit added where ``up(rest, units)`` says."""
    if value == 0:
        return value
    units, rest, scale = split(value, bits)
    if up(rest, units):
        units += 1
    return (units * scale) * (1 if value > 0 else -1)


def nearest_even(rest, units):
    return rest > Fraction(1, 2) or (rest == Fraction(1, 2) and units % 2 == 1)


def fmuls(a: Fraction, b: Fraction) -> Fraction:
    """$FMULS: the product's 3 bits below the mantissa decide; 100 is a tie (to even)."""
    return rounded(a * b, 24, lambda rest, units: rest >= Fraction(5, 8) or (rest >= Fraction(1, 2) and units % 2))


def fadds(a: Fraction, b: Fraction) -> Fraction:
    """$FADDS: its shifting and sticky bits are single_arith's (checked bit for bit against PC-BASIC)."""
    return Fraction(single_arith.add(float(a), float(b)))


def fdivs(a: Fraction, b: Fraction) -> Fraction:
    """$FDIVS: long division with a sticky remainder bit: the nearest single."""
    return rounded(a / b, 24, nearest_even)


def csd(value: Fraction) -> Fraction:
    """$CSD: the 25th bit rounds up."""
    return rounded(value, 24, lambda rest, units: rest >= Fraction(1, 2))


def horner(x, coefficients):
    total = coefficients[0]
    for c in coefficients[1:]:
        total = fadds(fmuls(total, x), c)
    return total


def odd_polynomial(x, coefficients):
    return fmuls(horner(fmuls(x, x), coefficients), x)


def fraction_part(value: Fraction) -> Fraction:
    return value - math.floor(value)


def sine_of_turns(turns: Fraction) -> Fraction:
    quarters = 4 * turns
    quadrant = math.floor(quarters)
    angle = quarters - quadrant
    if quadrant % 2:
        angle = 1 - angle
    t = csd(angle / 4)
    value = fmuls(t, TWO_PI) if t < Fraction(1, 8192) else odd_polynomial(t, SINE)
    return -value if quadrant >= 2 else value


def turns_of(x: Fraction) -> Fraction:
    return fraction_part(rounded(abs(x) * INVERSE_TWO_PI, 56, nearest_even)) if x else Fraction(0)


def reference_sin(x: Fraction) -> Fraction:
    if abs(x) < Fraction(1, 1024):
        return x
    value = sine_of_turns(turns_of(x))
    return -value if x < 0 else value


def reference_cos(x: Fraction) -> Fraction:
    turns = turns_of(x)
    return sine_of_turns(fraction_part(rounded(turns + Fraction(1, 4), 56, nearest_even)))


def reference_atn(x: Fraction) -> Fraction:
    y = abs(x)
    inverted = y >= 1
    if inverted:
        y = fdivs(Fraction(1), y)
    shifted = y >= TAN_TWELFTH_PI
    if shifted:
        y = fdivs(fadds(fmuls(SQR3, y), Fraction(-1)), fadds(y, SQR3))
    value = odd_polynomial(y, ARCTANGENT)
    if shifted:
        value = fadds(value, SIXTH_PI)
    if inverted:
        value = fadds(HALF_PI, -value)
    return -value if x < 0 else value


def reference_log(x: Fraction) -> Fraction:
    if x == 1:
        return Fraction(0)
    exponent = 0
    m = x
    while m >= 1:
        m, exponent = m / 2, exponent + 1
    while m < Fraction(1, 2):
        m, exponent = m * 2, exponent - 1
    return fmuls(fadds(Fraction(exponent), fdivs(horner(m, LOG_P), horner(m, LOG_Q))), LN2)


def reference_exp(x: Fraction) -> Fraction:
    y = fmuls(x, LOG2_E)
    if abs(y) < Fraction(1, 1 << 25):
        return Fraction(1)
    whole = math.floor(y)
    return fmuls(horner(fadds(y, Fraction(-whole)), EXPONENTIAL), Fraction(2) ** whole)


def random_singles(seed: int, count: int, low: int, high: int):
    rng = random.Random(seed)
    for _ in range(count):
        x = single_arith.nearest(rng.uniform(0.5, 1.0) * 2.0 ** rng.randint(low, high))
        yield -x if rng.random() < 0.5 else x


@pytest.mark.parametrize(("function", "reference", "low", "high"), [
    (gw.sin, reference_sin, -12, 40), (gw.cos, reference_cos, -12, 40), (gw.atn, reference_atn, -20, 20),
])
def test_trigonometry_follows_the_algorithm(function, reference, low, high):
    for x in random_singles(7, 400, low, high):
        assert function(x) == float(reference(Fraction(x))), x


def test_tan_is_sine_over_cosine():
    for x in random_singles(8, 300, -12, 20):
        expected = fdivs(reference_sin(Fraction(x)), reference_cos(Fraction(x)))
        assert gw.tan(x) == float(expected), x


def test_log_follows_the_algorithm():
    for x in random_singles(9, 400, -120, 120):
        assert gw.log(abs(x)) == float(reference_log(Fraction(abs(x)))), x


def test_exp_follows_the_algorithm():
    for x in random_singles(10, 400, -20, 6):
        assert gw.exp(x) == float(reference_exp(Fraction(x))), x


def test_fractional_power_is_exp_of_log():
    for x in random_singles(11, 200, -10, 10):
        y = single_arith.nearest(random.Random(x).uniform(-3, 3))
        expected = reference_exp(fmuls(Fraction(y), reference_log(Fraction(abs(x)))))
        if y < 0:
            expected = fdivs(Fraction(1), reference_exp(fmuls(Fraction(-y), reference_log(Fraction(abs(x))))))
        if x < 0:
            with pytest.raises(ValueError):
                gw.power(x, y)
        else:
            assert gw.power(x, y) == float(expected), (x, y)


# ---------------------------------------------------------------- the fast steps
# gw_transcendental's $POLY runs on floats (mbf_floats.poly) or on integer mantissas
# (mbf_integers.poly); its step-by-step form on single_arith's product and add (poly_steps)
# is the reference both must equal.

POLYNOMIALS = {"SIN": gw._SIN_COEFFICIENTS, "ATN reduction": gw._ATN_REDUCTION, "ATN": gw._ATN_COEFFICIENTS,
               "LOG numerator": gw._LOG_NUMERATOR, "LOG denominator": gw._LOG_DENOMINATOR,
               "EXP": gw._EXP_COEFFICIENTS}


def polynomial_arguments(name: str, low: int = -128) -> list[float]:
    """Every binade from 2**low to 4 an argument of the functions reaches (ATN's x*x down to
    the least single), and within a binade mantissas of every kind: random, and next to a
    power of two (where products and sums carry or cancel)."""
    rng = random.Random(name)
    arguments = [0.0, single_arith.TINY, 1.0, 0.5]
    for _ in range(6000):
        binade = 2.0 ** rng.randint(low, 2)
        arguments.append(single_arith.nearest(rng.uniform(0.5, 1.0) * binade))
        arguments.append(binade * (1 - 2.0 ** -24 * rng.randint(1, 64)))
        arguments.append(binade * (0.5 + 2.0 ** -24 * rng.randint(1, 64)))
    return arguments


@pytest.mark.parametrize("name", list(POLYNOMIALS))
def test_integer_polynomial_equals_the_steps(name):
    from yaseer.basic.arithmetic import mbf_integers

    coefficients = POLYNOMIALS[name]
    parts = mbf_integers.coefficient_parts(coefficients)
    handed_back = 0
    for x in polynomial_arguments(name):
        fast = mbf_integers.poly(x, parts)
        handed_back += fast is None and x >= 2.0 ** -100
        assert fast is None or fast == gw.poly_steps(x, coefficients), (name, x)
    assert not handed_back  # only near the range's end are the steps handed back


@pytest.mark.parametrize("name", list(POLYNOMIALS))
def test_float_polynomial_equals_the_steps(name):
    """mbf_floats.poly over its whole domain (2**-60 to 1), and where the functions call it:
    SIN's t*t (up to 1/16), LOG's mantissas (1/2 to 1), EXP's fractions, ATN's reduced x."""
    from yaseer.basic.arithmetic import mbf_floats

    coefficients = POLYNOMIALS[name]
    planned = mbf_floats.plan(coefficients)
    rng = random.Random(name + " where called")
    arguments = [x for x in polynomial_arguments(name, -60) if mbf_floats.LEAST_ARGUMENT <= x <= 1.0]
    arguments += [single_arith.nearest(rng.uniform(0.5, 1.0)) for _ in range(3000)]
    arguments += [single_arith.nearest(rng.uniform(0.0, 1.0) ** 2) for _ in range(3000)]
    arguments += [1.0 - 2.0 ** -24 * k for k in range(1, 200)] + [0.5 + 2.0 ** -24 * k for k in range(200)]
    handed_back = 0
    for x in arguments:
        fast = mbf_floats.poly(x, planned)
        handed_back += fast is None
        assert fast is None or fast == gw.poly_steps(x, coefficients), (name, x)
        if x >= 2.0 ** -30:  # $POLYX, x * P(x*x), its products $FMULS
            odd = mbf_floats.poly(x, planned, True)
            handed_back += odd is None
            assert odd is None or odd == single_arith.product(gw.poly_steps(single_arith.product(x * x),
                                                                             coefficients) * x), (name, x)
    assert handed_back <= len(arguments) // 1000  # only a sum of exactly 0 is handed back


def _reduced_by_integers(x: float, quarter: bool):
    """RR and SIN30's reduction on integers (gw_transcendental's reference): (t, negated)."""
    numerator, bits = gw._turns(x)
    if quarter:
        numerator, bits = gw._quarter_turn_added(numerator, bits)
        numerator &= (1 << bits) - 1
    quadrant = numerator >> (bits - 2)
    angle = numerator & ((1 << (bits - 2)) - 1)
    if quadrant & 1:
        angle = (1 << (bits - 2)) - angle
    extra = angle.bit_length() - 25
    if extra >= 0:
        return math.ldexp((angle >> extra) + 1 >> 1, extra + 1 - bits), quadrant >= 2
    return math.ldexp(angle, -bits), quadrant >= 2


def test_float_reduction_equals_the_integer_steps():
    """_quarter_angle (floats) gives the integer reduction's angle wherever it does not hand
    the argument back: whole numbers, random singles of every binade it takes, and angles
    next to a multiple of a quarter turn (where the reduced angle is small and the rounding
    to 24 bits is finest)."""
    rng = random.Random(8)
    arguments = [float(k) for k in range(1, 3000)] + [float(k) for k in range(1048000, 1048576)]
    arguments += [single_arith.nearest(rng.uniform(0.5, 1.0) * 2.0 ** rng.randint(-10, 19)) for _ in range(8000)]
    arguments += [single_arith.nearest(math.pi / 2 * rng.randint(1, 600000) * (1 + rng.uniform(-1e-6, 1e-6)))
                  for _ in range(4000)]
    handed_back = 0
    for x in arguments:
        if not 2.0 ** -10 <= x < 2.0 ** 20:
            continue
        for quarter in (False, True):
            fast = gw._quarter_angle(x, float(quarter))
            handed_back += fast is None
            assert fast is None or fast == _reduced_by_integers(x, quarter), (x, quarter)
    assert handed_back < len(arguments) // 10  # (the angles next to a quarter turn are handed back)


class _Forgetful(dict):
    """A memo that never remembers (the LOG memo defeated)."""

    def get(self, key, default=None):
        return default


def test_functions_equal_their_step_by_step_form(monkeypatch):
    from yaseer.basic.arithmetic import mbf_floats, mbf_integers

    functions = (gw.sin, gw.cos, gw.tan, gw.atn, lambda x: gw.log(abs(x)) if x else 0.0,
                 lambda x: gw.exp(x if abs(x) < 80 else x / 2.0 ** 20))
    arguments = list(random_singles(12, 3000, -30, 30)) + [float(k) for k in range(-300, 3000)]
    arguments += [float(k) for k in range(1, 3000)]  # again: LOG's memo now holds their mantissas
    fast = [[f(x) for x in arguments] for f in functions]
    # every fast path defeated: $POLY step by step, each sum the register steps of the tests'
    # own $FADDS (tests/fadds_reference.py), the reduction on integers, no memo
    monkeypatch.setattr(mbf_floats, "poly", lambda x, planned, odd=False: None)
    monkeypatch.setattr(mbf_floats, "fmuls", single_arith.product)
    monkeypatch.setattr(mbf_integers, "poly", lambda x, parts: None)
    monkeypatch.setattr(gw, "add", fadds_reference.add)
    monkeypatch.setattr(gw, "subtract", fadds_reference.subtract)
    monkeypatch.setattr(gw, "_quarter_angle", lambda x, quarter: None)
    monkeypatch.setattr(gw, "_LOG_RATIOS", _Forgetful())
    assert fast == [[f(x) for x in arguments] for f in functions]


# ---------------------------------------------------------------- close to the truth


def units_off(value: float, true, least=0.0) -> float:
    """|value - true| in units of the last place of a single as large as ``true``
    (or as ``least``, if larger)."""
    size = max(abs(float(true)), least)
    exponent = math.frexp(size)[1] if size else -126
    return float(abs(mpmath.mpf(value) - true) / mpmath.mpf(2) ** (exponent - 24))


@pytest.mark.parametrize(("function", "truth", "low", "high"), [
    (gw.sin, mpmath.sin, -8, 6), (gw.cos, mpmath.cos, -8, 6), (gw.atn, mpmath.atan, -20, 20),
])
def test_trigonometry_within_a_few_units_of_the_truth(function, truth, low, high):
    mpmath.mp.prec = 80
    worst = max(units_off(function(x), truth(mpmath.mpf(x))) for x in random_singles(12, 1000, low, high))
    assert worst <= 4


def test_exp_within_a_few_units_of_the_truth():
    """EXP's argument is multiplied by LOG2(e) first: the product's rounding grows with |x|."""
    mpmath.mp.prec = 80
    worst = max(units_off(gw.exp(x), mpmath.exp(mpmath.mpf(x))) / (1 + abs(x))
                for x in random_singles(12, 1000, -10, 6))
    assert worst <= 2


def test_log_within_a_few_units_of_the_truth():
    """Near 1 the polynomial's quotient cancels: the error is a few units of the last place of 1."""
    mpmath.mp.prec = 80
    worst = max(units_off(gw.log(abs(x)), mpmath.log(mpmath.mpf(abs(x))), least=1.0)
                for x in random_singles(13, 1000, -100, 100) if abs(x) != 1)
    assert worst <= 2


# ---------------------------------------------------------------- edges


def test_small_and_huge_arguments():
    tiny = single_arith.nearest(9e-4)
    assert gw.sin(tiny) == tiny  # below 2**-10: the argument itself
    assert gw.sin(SINGLE_LARGEST) == 0.0 and gw.cos(SINGLE_LARGEST) == 1.0  # no fraction of a turn left
    assert gw.cos(0.0) == 1.0 and gw.sin(0.0) == 0.0 and gw.atn(0.0) == 0.0
    assert gw.exp(0.0) == 1.0 and gw.log(1.0) == 0.0


def test_domain_and_range_errors():
    with pytest.raises(ValueError):
        gw.log(0.0)
    with pytest.raises(ValueError):
        gw.log(-2.0)
    assert gw.exp(89.0) == math.inf  # 2**128 has no single
    assert gw.exp(-89.0) == 0.0
    assert gw.exp(100.0, overflow=lambda negative: -1.0 if negative else 1.0) == 1.0
    with pytest.raises(ZeroDivisionError):
        gw.power(0.0, -0.5)
    with pytest.raises(ValueError):
        gw.power(-8.0, 1 / 3)
    assert gw.power(0.0, 0.5) == 0.0 and gw.power(5.0, 0.0) == 1.0
    assert gw.power(-2.0, 3.0) == -8.0  # integral: multiplied
    assert gw.power(-2.0, 40000.0, overflow=lambda negative: negative) is False  # even: positive overflow


# ---------------------------------------------------------------- in a program


def test_a_gw_program_prints_the_machines_digits():
    from test_differential_support import run_gw

    assert run_gw("10 PRINT ATN(1); 4*ATN(1); COS(1.5); TAN(1.5#)\n") == " .7853983  3.141593  7.073721E-02  14.10142 \n"
    assert run_gw("10 PRINT EXP(100): PRINT EXP(-100); LOG(1)\n") == "Overflow\n 1.701412E+38 \n 0  0 \n"
    assert run_gw("10 ON ERROR GOTO 30: PRINT LOG(0)\n20 END\n30 PRINT ERR: RESUME 20\n") == " 5 \n"
    half = Fraction(single_arith.nearest(0.5))
    root = reference_exp(fmuls(half, reference_log(Fraction(2))))  # the source's steps
    inverse = fdivs(Fraction(1), reference_exp(fmuls(half, reference_log(Fraction(4)))))
    expected = f"{str_dollar(float(root))} -512 {str_dollar(float(inverse))} \n"
    assert run_gw("10 PRINT 2^.5; (-8)^3; 4^-.5\n") == expected


def test_the_log_memo_forgets_its_oldest_quarter(monkeypatch):
    """The LOG memo keeps at most its size, dropping the oldest quarter when full (a loop over
    whole numbers still finds K/2's ratio at K), and its values are the memo-less ones."""
    monkeypatch.setattr(gw, "_LOG_RATIOS", {})
    monkeypatch.setattr(gw, "_LOG_MEMO_SIZE", 16)
    odd = [float(k) for k in range(3, 200, 2)]
    remembered = [gw.log(x) for x in odd]
    assert len(gw._LOG_RATIOS) <= 16
    assert math.frexp(odd[-1])[0] in gw._LOG_RATIOS and math.frexp(odd[0])[0] not in gw._LOG_RATIOS
    monkeypatch.setattr(gw, "_LOG_RATIOS", _Forgetful())
    assert remembered == [gw.log(x) for x in odd]
