"""The optional C accelerator of gw's SIN COS TAN ATN LOG EXP and ``^`` (yaseer/basic/
arithmetic/_mbf_fast.c) against the Python functions it accelerates (gw_transcendental.py).

The Python functions are the reference (tests/test_gw_transcendental.py checks them
against real GW-BASIC's printed digits and an implementation on fractions); the C ones
must give the same singles bit for bit (compared as the bits of the floats, so that 0
and -0 differ), raise the same errors and call the same overflow handler, on every
integer up to 100000 in size, on random MBF singles of the whole range, and on the
edges of each routine.  The reference tests of test_gw_transcendental.py are run on the
C functions too.

The module is built by ``pip install`` where a C compiler is found (setup.py: an
optional extension); CI's machine has gcc, so CI runs these.  Where it is not built the
comparisons skip, saying so once, and the tests of the pure-Python path
(tests/test_mbf_fast_fallback.py) still run.
"""

from __future__ import annotations

import math
import random
import struct
from fractions import Fraction

import pytest

from yaseer.basic.arithmetic import gw_transcendental as gw, single_arith

try:
    from yaseer.basic.arithmetic import _mbf_fast
except ImportError:  # not built: no C compiler where yaseer was installed
    pytest.skip("the C accelerator _mbf_fast is not built here (no C compiler at install): only the Python "
                "functions run (tests/test_mbf_fast_fallback.py)", allow_module_level=True)

NAMES = ("sin", "cos", "tan", "atn", "log", "exp")
TINY = 2.0 ** -128  # the least MBF single
LARGEST = (1 - 2.0 ** -24) * 2.0 ** 127


def fast(name: str):
    """The C routine ``name`` bound to the Python function (as arith_policy.gw_routines binds it)."""
    return _mbf_fast.bound(name, getattr(gw, name))


def outcome(function, *args):
    """What a call gives: the float's 64 bits (0 and -0 apart), or the type of the error raised."""
    try:
        value = function(*args)
    except (ValueError, ZeroDivisionError, OverflowError) as error:
        return type(error)
    return struct.pack("<d", value) if isinstance(value, float) else value


def differing(name: str, arguments) -> list:
    """The arguments on which the C routine and the Python function differ (at most 10)."""
    python, c = getattr(gw, name), fast(name)
    bad = []
    for x in arguments:
        if outcome(python, x) != outcome(c, x):
            bad.append((x, python(x) if outcome(python, x).__class__ is bytes else outcome(python, x), outcome(c, x)))
            if len(bad) >= 10:
                break
    return bad


def mbf_single(word: int) -> float:
    """The single of four MBF bytes read as one number, exponent byte first (0x81000000 is 1)."""
    exponent = word >> 24
    if not exponent:
        return 0.0
    value = math.ldexp((word & 0x7FFFFF) | 0x800000, exponent - 152)
    return -value if word & 0x800000 else value


def neighbours(x: float, count: int) -> list[float]:
    """``x`` (a single) and the ``count`` singles on each side of it."""
    m, e = math.frexp(x)
    mantissa, exponent = int(m * 2 ** 24), e - 24
    return [math.ldexp(mantissa + k, exponent) for k in range(-count, count + 1)]


# ---------------------------------------------------------------- bit for bit


@pytest.mark.parametrize("name", NAMES)
def test_every_whole_number_up_to_100000(name):
    """The integers 1..100000 and their negatives (LOG's negatives: the Python function's error)."""
    arguments = [float(k) for k in range(1, 100001)]
    assert differing(name, arguments + [-x for x in arguments]) == []


@pytest.mark.parametrize("name", NAMES)
def test_random_singles_of_the_whole_range(name):
    """Random MBF patterns: 32 random bits (every exponent byte alike, both signs: most are
    huge or tiny), and random mantissas with exponents where the routines branch most
    (2**-40 to 2**40)."""
    rng = random.Random(f"mbf {name}")
    arguments = [mbf_single(rng.getrandbits(32)) for _ in range(100000)]
    arguments += [mbf_single(rng.randint(88, 168) << 24 | rng.getrandbits(24)) for _ in range(100000)]
    assert differing(name, arguments) == []


def edge_arguments() -> list[float]:
    """0, the least and largest singles, the routines' thresholds and their neighbours (SIN's
    2**-10 and the Python function's 2**20, the 2**-13 of the reduced angle, ATN's 1 and
    tan(pi/12), EXP's overflow and underflow at +-88.7, 2**-25 and 2**7 of EXP's y), the
    singles nearest to multiples of pi/2 and pi/6 and their neighbours, and arguments that
    are not singles (doubles, integers beyond 24 bits, NaN, infinities)."""
    points = [TINY, LARGEST, 1.0, 0.5, 2.0 ** -10, 2.0 ** 20, 2.0 ** -13, 2.0 ** -13 * 2 * math.pi,
              gw._TAN_TWELFTH_PI, 88.72283935546875, 88.0, 89.0, 2.0 ** -25 / 1.4426950408889634,
              2.0 ** 24, 2.0 ** 63, 2.0 ** 100]
    points += [single_arith.nearest(k * math.pi / 2) for k in range(1, 400)]
    points += [single_arith.nearest(k * math.pi / 6) for k in range(1, 100)]
    points += [single_arith.nearest(k * math.pi / 2) for k in (10 ** 5, 10 ** 6, 12345678, 10 ** 9, 10 ** 12)]
    arguments = [0.0, -0.0]
    for point in points:
        arguments += neighbours(point, 3 if point > 1e6 else 40)
    arguments += [-x for x in arguments]
    arguments += [0.1, 1 / 3, -2.5e-39, 1e-300, 1e300, 2.0 ** 127, -2.0 ** 127, math.inf, -math.inf, math.nan,
                  3, -7, 2 ** 25 + 1, 10 ** 40, True]
    return arguments


@pytest.mark.parametrize("name", NAMES)
def test_edges(name):
    assert differing(name, edge_arguments()) == []


def test_errors_and_overflows_are_the_python_functions():
    """An unusual call goes to the Python function: LOG of 0 and negatives is its ValueError,
    EXP's overflow calls the handler given (from y = x*LOG2(e) >= 127 on) or gives an
    infinity, a power's errors and overflows are its own."""
    log, exp, power = fast("log"), fast("exp"), fast("power")
    for x in (0.0, -0.0, -1.0, -TINY, -LARGEST):
        with pytest.raises(ValueError):
            log(x)
    told = []
    assert exp(100.0, lambda negative: told.append(negative) or 7.0) == 7.0 and told == [False]
    assert exp(88.0) == gw.exp(88.0) and exp(89.0) == math.inf and exp(-89.0) == 0.0
    with pytest.raises(ZeroDivisionError):
        power(0.0, -0.5)
    with pytest.raises(ValueError):
        power(-8.0, 1 / 3)
    assert power(-2.0, 40000.0, lambda negative: negative) is False
    assert power(2.0, 200.5, lambda negative: "overflow") == "overflow"
    assert outcome(power, 2.0, -200.5) == outcome(gw.power, 2.0, -200.5)


def test_a_tan_whose_cosine_is_0_raises_as_the_python_one():
    """Where $COS gives 0 (a huge argument whose fraction of a turn is a quarter) TAN divides
    by 0: ZeroDivisionError, which arith_policy turns into Division by zero."""
    rng = random.Random("cos 0")
    arguments = (math.ldexp(rng.getrandbits(23) | 0x800000, rng.randint(30, 34)) for _ in range(2000))
    zeros = [x for x in arguments if gw.cos(x) == 0.0]  # (2**54 to 2**58: about a third)
    assert len(zeros) > 100
    for x in zeros:
        with pytest.raises(ZeroDivisionError):
            fast("tan")(x)


def test_fractional_powers():
    """``x ^ y`` of random singles (the C routine takes positive x and y not an integer below
    32768; the rest goes to the Python function)."""
    rng = random.Random("power")
    python, c = gw.power, fast("power")
    pairs = [(mbf_single(rng.randint(100, 156) << 24 | rng.getrandbits(24)),
              mbf_single(rng.randint(120, 140) << 24 | rng.getrandbits(24))) for _ in range(30000)]
    pairs += [(float(rng.randint(-50, 50)), rng.choice([0.5, -0.5, 2.0, 3.0, -3.0, 0.0, 1.5, 40000.0, -40000.5]))
              for _ in range(2000)]
    bad = [(x, y) for x, y in pairs if outcome(python, x, y) != outcome(c, x, y)]
    assert bad == []


def test_the_single_steps_are_single_arith():
    """The C $FMULS and $FADDS on their own: random singles of the whole range, products near
    the range's ends and sums that cancel or lose bits, as single_arith gives them."""
    rng = random.Random("steps")

    def single(low=1, high=255):
        mantissa = rng.choice([rng.getrandbits(23) | 0x800000, 0x800000, 0xFFFFFF, 0x800001])
        value = math.ldexp(mantissa, rng.randint(low, high) - 152)
        return -value if rng.random() < 0.5 else value

    bad = []
    for _ in range(100000):
        a, b = single(), single()
        if outcome(single_arith.product, a * b) != outcome(_mbf_fast.product, a * b):
            bad.append(("*", a, b))
        c = single_arith.nearest(-a * (1 + rng.choice([1, -1]) * 2.0 ** -rng.randint(1, 40)))
        d = single_arith.nearest(a * 2.0 ** rng.randint(-30, 30))
        for x, y in ((a, b), (a, c), (a, d), (a, -d)):
            if y and TINY <= abs(y) < 2.0 ** 127 and outcome(single_arith.add, x, y) != outcome(_mbf_fast.add, x, y):
                bad.append(("+", x, y))
    assert bad == []


# ---------------------------------------------------------------- the references on the C routines


def test_the_c_routines_print_what_gw_basic_printed():
    """test_gw_transcendental's 57 values printed by real GW-BASIC, from the C routines."""
    from test_gw_transcendental import RECORDED

    from yaseer.basic.arithmetic.values import str_dollar

    for name, (function, arguments, printed) in RECORDED.items():
        c = fast(function.__name__)
        assert [str_dollar(c(single_arith.nearest(x))).strip() for x in arguments] == printed.split(), name


def test_the_c_routines_follow_the_algorithm_on_fractions():
    """test_gw_transcendental's second implementation (MATH1.ASM's steps on exact fractions)."""
    from test_gw_transcendental import (random_singles, reference_atn, reference_cos, reference_exp,
                                        reference_log, reference_sin)

    for name, reference, low, high in (("sin", reference_sin, -12, 40), ("cos", reference_cos, -12, 40),
                                       ("atn", reference_atn, -20, 20), ("log", reference_log, -120, 120),
                                       ("exp", reference_exp, -20, 6)):
        c = fast(name)
        for x in random_singles(17, 200, low, high):
            x = abs(x) if name == "log" else x
            assert c(x) == float(reference(Fraction(x))), (name, x)
