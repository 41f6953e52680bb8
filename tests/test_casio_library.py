"""Becker's FX-850P/880P library programs, run with our own keys, against independent values.

The library is not in this repository: set ``YASEER_CASIO_LIBRARY`` to a local copy of
its ``sources`` folder (github urbancamo/casio-basic, src/main/basic/MB-Casio-Basic-Library).
Each case types its inputs as the program asks for them (a line break is EXE; ``\\x1f``
is the cursor-down key the programs read to show the next root or value) and reads the
number the LCD shows after a label; the expected value is a closed form or mpmath's.  The
programs round their results themselves (``ROUND(x, LOG(ABS x)-7)`` keeps 6 or 7
significant digits, the distributions' ``-6`` 5 or 6: ROUND's page rounds *at* the digit
given), so the tolerance is that rounding, or the method's accuracy where it is coarser.
"""

from __future__ import annotations

import math
import re
from fractions import Fraction

import pytest

import yaseer
from casio_library import ENVIRONMENT, library

mpmath = pytest.importorskip("mpmath")

LIBRARY = library()
if LIBRARY is None:
    pytest.skip(f"{ENVIRONMENT} does not name the library's sources folder", allow_module_level=True)
DOWN = "\x1f"  # the cursor-down key (code 31)
NUMBER = r"(-?(?:\d+\.?\d*|\.\d+)(?:E[-+]?\d+)?)"


def screens(program: str, keys: str) -> list[str]:
    result = yaseer.run(LIBRARY / f"{program}.bas", input=keys, files=LIBRARY)
    # the keys are over while it waits for the next one (in a subprogram's area too: "(PROG 1000)")
    assert result.error is None or result.error.startswith(f"Input past end in {result.line}"), result.error
    return result.screens


def shown(program: str, keys: str, label: str) -> list[float]:
    """Every number shown after ``label`` (a regular expression) on the program's screens, in order."""
    values = []
    for screen in screens(program, keys):
        for match in re.finditer(label + r"\s*" + NUMBER, screen):
            values.append(float(match.group(1)))
    assert values, f"{program}: nothing shown after {label!r}"
    return values


def first(program: str, keys: str, label: str) -> float:
    return shown(program, keys, label)[0]


pi = math.pi
CLOSED_FORMS = [  # program, keys, label, value (exact closed form), relative tolerance
    ("LIB5615", "2\n", "Area =", 4 * pi, 1e-9),  # circle, r=2
    ("LIB5630", "2\n3\n", "Area =", 6 * pi, 1e-9),  # ellipse a=2, b=3
    ("LIB5650", "2\n", "Surface =", 16 * pi, 1e-9),  # sphere r=2
    ("LIB5700", "3\n", "Volume =", 36 * pi, 1e-9),  # sphere r=3
    ("LIB5715", "2\n5\n", "Volume =", 20 * pi, 1e-9),  # cylinder r=2, h=5
    ("LIB5720", "3\n4\n", "Volume =", 12 * pi, 1e-9),  # cone r=3, h=4
    ("LIB5745", "1\n2\n3\n", "Volume =", 8 * pi, 1e-9),  # ellipsoid 1, 2, 3
    ("LIB5605", "3\n5\n2\n", "Area =", 8.0, 1e-12),  # trapezoid (3+5)*2/2
    ("LIB5600", "3" "3\n4\n5\n", "Area =", 6.0, 1e-9),  # Heron's formula, the 3-4-5 triangle
    ("LIB5610", "2" "3\n4\n30\n", "Area =", 6.0, 1e-9),  # 3*4*sin 30 degrees
    ("LIB5620", "2" "2\n90\n", "Area =", pi, 1e-9),  # sector r=2, 90 degrees
    ("LIB5625", "2\n1\n", "Area =", (2 - math.sin(2)) / 2, 1e-9),  # segment l=2, r=1 (radians)
    ("LIB5250", "5\n", r"\) =", 24.0, 1e-12),  # Gamma(5) = 4!
    ("LIB5200", "1" "x^2\n0\n1\n", r"dx =", 1 / 3, 5e-6),  # Romberg: integral of x^2 over [0,1]
]


@pytest.mark.parametrize("program, keys, label, value, tolerance", CLOSED_FORMS,
                         ids=[case[0] for case in CLOSED_FORMS])
def test_closed_forms(program, keys, label, value, tolerance):
    assert first(program, keys, label) == pytest.approx(value, rel=tolerance)


def test_gamma_of_a_half_is_the_root_of_pi():
    # the program's series, rounded to 8 digits
    assert first("LIB5250", "0.5\n", r"\) =") == pytest.approx(math.sqrt(pi), rel=5e-6)


def test_greatest_common_measure_and_least_common_multiple():
    screen = "".join(screens("LIB5020", "84\n360\n"))
    assert float(re.search(r"G\.C\.M\.=\s*" + NUMBER, screen).group(1)) == math.gcd(84, 360)
    assert float(re.search(r"L\.C\.M\.=\s*" + NUMBER, screen).group(1)) == 84 * 360 // math.gcd(84, 360)


def test_prime_factors_multiply_back_to_the_base():
    screen = [s for s in screens("LIB5010", "360360\n") if "^" in s or "*" in s][0]
    factors = screen.split("=", 1)[1].replace("\n", "").split("*")  # the row wraps onto the next
    product = 1
    for factor in factors:
        base, _, power = factor.strip().partition("^")
        assert all(int(base) % d for d in range(2, int(int(base) ** 0.5) + 1))  # each base a prime
        product *= int(base) ** int(power or 1)
    assert product == 360360


def test_quadratic_roots():
    roots = shown("LIB5050", "1\n-3\n2\n" + DOWN, "[αβ] =")
    assert sorted(roots) == [1.0, 2.0]


def test_cubic_with_three_real_roots():
    roots = shown("LIB5060", "1\n-6\n11\n-6\n" + DOWN + DOWN, "[αβγ] =")
    assert sorted(roots) == pytest.approx([1.0, 2.0, 3.0], rel=1e-8)


def test_simultaneous_equations():
    # 2x + y = 5, x - y = 1: x = 2, y = 1 (Gauss-Jordan)
    solution = shown("LIB5040", "2\n" "2\n1\n5\n" "1\n-1\n1\n" + DOWN, r"x\d =")
    assert solution[-2:] == pytest.approx([2.0, 1.0], rel=1e-8)  # the last screen: x1 and x2


def test_straight_line_through_two_points():
    # (1,2) and (3,6): y = 2x + 0
    assert shown("LIB5510", "1\n2\n3\n6\n" + DOWN, "[ab] =")[-2:] == [2.0, 0.0]


def test_circle_through_three_points():
    # (0,0), (2,0), (0,2): centre (1,1), radius sqrt 2
    a, b, r = shown("LIB5550", "0\n0\n2\n0\n0\n2\n" + DOWN + DOWN, "[abr] =")[-3:]
    assert (a, b) == (1.0, 1.0) and r == pytest.approx(math.sqrt(2), rel=1e-9)


def test_regular_polygon_radii():
    # a square of area 16: inscribed circle 2, circumscribed 2*sqrt 2, side 4
    r, big_r, side = shown("LIB5750", "16\n4\n" + DOWN + DOWN, "(?:inside|outside|side) =")[-3:]
    assert (r, big_r, side) == pytest.approx((2.0, 2 * math.sqrt(2), 4.0), rel=5e-6)


BESSEL = [  # program, n, x, label, mpmath's value
    ("LIB5260", 0, 1, "J=", mpmath.besselj(0, 1)),
    ("LIB5260", 3, 2.5, "J=", mpmath.besselj(3, 2.5)),
    ("LIB5270", 1, 2, "Y=", mpmath.bessely(1, 2)),
    ("LIB5280", 1, 1, "I=", mpmath.besseli(1, 1)),
    ("LIB5290", 0, 1, "K=", mpmath.besselk(0, 1)),
    ("LIB5290", 2, 3, "K=", mpmath.besselk(2, 3)),
]


@pytest.mark.parametrize("program, n, x, label, value", BESSEL, ids=[f"{c[0]}-{c[1]}-{c[2]}" for c in BESSEL])
def test_bessel_functions(program, n, x, label, value):
    # J, Y, I by recurrences, K by polynomial approximations; 6 or 7 digits shown
    assert first(program, f"{n}\n{x}\n", label) == pytest.approx(float(value), rel=5e-6)


def upper_t(n: int, x: float) -> float:
    return float(mpmath.betainc(n / 2, 0.5, 0, n / (n + x * x), regularized=True) / 2)


def upper_f(n: int, m: int, x: float) -> float:
    return float(mpmath.betainc(m / 2, n / 2, 0, m / (m + n * x), regularized=True))


def binomial_tail(n: int, p: Fraction, x: int) -> float:
    return float(sum(math.comb(n, k) * p ** k * (1 - p) ** (n - k) for k in range(x, n + 1)))


def hypergeometric_tail(big_n: int, big_m: int, n: int, x: int) -> float:
    total = math.comb(big_n, n)
    return float(sum(Fraction(math.comb(big_m, k) * math.comb(big_n - big_m, n - k), total)
                     for k in range(x, min(n, big_m) + 1)))


DISTRIBUTIONS = [  # program, keys, label, value, relative tolerance (5 or 6 digits shown; the method's accuracy)
    ("LIB6210", "1.96\n", "p=", float(mpmath.ncdf(-1.96)), 5e-5),  # normal, upper tail
    ("LIB6220", "4\n5\n", "p=", float(mpmath.gammainc(2, 2.5, regularized=True)), 5e-5),  # chi-square, 4 df
    ("LIB6220", "3\n2\n", "p=", float(mpmath.gammainc(1.5, 1, regularized=True)), 5e-5),  # chi-square, 3 df
    ("LIB6230", "10\n2\n", "p=", upper_t(10, 2), 5e-5),  # Student's t, 10 df
    ("LIB6230", "5\n1.5\n", "p=", upper_t(5, 1.5), 5e-5),
    ("LIB6240", "4\n10\n3\n", "p=", upper_f(4, 10, 3), 5e-5),  # F(4, 10)
    ("LIB6240", "3\n7\n2\n", "p=", upper_f(3, 7, 2), 5e-5),  # F(3, 7): both odd
    ("LIB6310", "10\n0.3\n4\n", "p=", binomial_tail(10, Fraction(3, 10), 4), 5e-5),  # binomial, P(X >= 4)
    ("LIB6320", "2\n3\n", "p=", 1 - math.exp(-2) * (1 + 2 + 2), 5e-5),  # Poisson, P(X >= 3)
    ("LIB6330", "20\n7\n5\n2\n", "p=", hypergeometric_tail(20, 7, 5, 2), 5e-5),  # hypergeometric
    ("LIB6410", "0.025\n", "x=", float(-mpmath.sqrt(2) * mpmath.erfinv(2 * 0.025 - 1)), 5e-5),  # normal point
    ("LIB6420", "4\n0.05\n", "x²=",  # chi-square point, 4 df: the x with upper probability .05
     float(mpmath.findroot(lambda t: mpmath.gammainc(2, t / 2, regularized=True) - 0.05, 9)), 5e-5),
]


@pytest.mark.parametrize("program, keys, label, value, tolerance", DISTRIBUTIONS,
                         ids=[f"{c[0]}-{c[1].strip()}".replace("\n", ",") for c in DISTRIBUTIONS])
def test_distributions(program, keys, label, value, tolerance):
    assert first(program, keys, label) == pytest.approx(value, rel=tolerance)



# ------------------------------------------------------------------ tests of hypotheses
def comparisons(program: str, keys: str) -> list[tuple[float, str, float, str]]:
    """The last screen's comparisons ``a <op> x [: verdict]`` of a test of hypotheses."""
    rows = re.findall(NUMBER + r"\s*([<>≤≥])\s*" + NUMBER + r"(?:\s*:\s*(Accept|Reject))?", screens(program, keys)[-1])
    assert rows, f"{program}: no comparison shown"
    return [(float(a), op, float(x), verdict) for a, op, x, verdict in rows]


def quantile(upper, p: float, start: float) -> float:
    """The x whose upper probability ``upper(x)`` is ``p`` (mpmath's root finder)."""
    return float(mpmath.findroot(lambda t: upper(t) - p, start))


def chi_square_upper(n: int):
    return lambda x: mpmath.gammainc(n / 2, x / 2, mpmath.inf, regularized=True)


SHOWN = 5e-4  # the programs show a statistic and its critical value to 4 significant digits (ROUND(z, LOG(ABSz)-5))
UNKNOWN_VARIANCE = "N0\n25\n0.5\n1\n5\n"  # mu0 = 0, n = 25, mean 0.5, variance 1: t = 2.5, 24 degrees of freedom
HYPOTHESES = [  # program, keys, the statistic, the critical value, its side ("<" left, ">" right or two-sided)
    ("LIB6720", UNKNOWN_VARIANCE, 2.5, quantile(lambda t: upper_t(24, t), 0.025, 2), ">"),
    ("LIB6721", UNKNOWN_VARIANCE, 2.5, quantile(lambda t: upper_t(24, t), 0.05, 2), ">"),
    ("LIB6722", UNKNOWN_VARIANCE, 2.5, -quantile(lambda t: upper_t(24, t), 0.05, 2), "<"),
    # variance: sigma0^2 = 4, n = 20, S = 95: S / sigma0^2 against chi-square with 19 degrees of freedom
    ("LIB6731", "N4\n20\n95\n5\n", 95 / 4, quantile(chi_square_upper(19), 0.05, 30), ">"),
    ("LIB6732", "N4\n20\n95\n5\n", 95 / 4, quantile(chi_square_upper(19), 0.95, 10), "<"),
    # variance ratio V1/V2 = 4/2 against F(9, 11), upper 2.5 %
    ("LIB6740", "NN10\n4\n12\n2\n5\n", 2.0, quantile(lambda t: upper_f(9, 11, t), 0.025, 3.5), ">"),
    # mean difference: t = (5 - 4) / sqrt((1/10 + 1/12) (20 + 30) / 20), 20 degrees of freedom
    ("LIB6750", "NN10\n5\n20\n12\n4\n30\n5\n", 1 / math.sqrt((1 / 10 + 1 / 12) * 50 / 20),
     quantile(lambda t: upper_t(20, t), 0.025, 2), ">"),
    # ratio: (60 - 100 * 0.5) / sqrt(100 * 0.5 * 0.5) = 2 against the normal 2.5 % point
    ("LIB6760", "0.5\n100\n60\n5\n", 2.0, float(-mpmath.sqrt(2) * mpmath.erfinv(2 * 0.025 - 1)), ">"),
    # ratio difference: pooled v = 110/220
    ("LIB6770", "100\n60\n120\n50\n5\n", (0.6 - 50 / 120) / math.sqrt(0.5 * 0.5 * (1 / 100 + 1 / 120)),
     float(-mpmath.sqrt(2) * mpmath.erfinv(2 * 0.025 - 1)), ">"),
    # mean, variance known: mu0 = 0, sigma 1, n = 25, mean 0.5: z = 2.5, two-sided and one-sided
    ("LIB6710", "N0\n1\n25\n0.5\n5\n", 2.5, float(-mpmath.sqrt(2) * mpmath.erfinv(2 * 0.025 - 1)), ">"),
    ("LIB6711", "N0\n1\n25\n0.5\n5\n", 2.5, float(-mpmath.sqrt(2) * mpmath.erfinv(2 * 0.05 - 1)), ">"),
    ("LIB6712", "N0\n1\n25\n0.5\n5\n", 2.5, float(mpmath.sqrt(2) * mpmath.erfinv(2 * 0.05 - 1)), "<"),
    # the one-sided forms of the variance ratio, mean difference, ratio and ratio difference tests
    ("LIB6741", "NN10\n4\n12\n2\n5\n", 2.0, quantile(lambda t: upper_f(9, 11, t), 0.05, 3), ">"),
    ("LIB6742", "NN10\n4\n12\n2\n5\n", 2.0, quantile(lambda t: upper_f(9, 11, t), 0.95, 0.3), "<"),
    ("LIB6751", "NN10\n5\n20\n12\n4\n30\n5\n", 1 / math.sqrt((1 / 10 + 1 / 12) * 50 / 20),
     quantile(lambda t: upper_t(20, t), 0.05, 2), ">"),
    ("LIB6752", "NN10\n5\n20\n12\n4\n30\n5\n", 1 / math.sqrt((1 / 10 + 1 / 12) * 50 / 20),
     -quantile(lambda t: upper_t(20, t), 0.05, 2), "<"),
    ("LIB6761", "0.5\n100\n60\n5\n", 2.0, float(-mpmath.sqrt(2) * mpmath.erfinv(2 * 0.05 - 1)), ">"),
    ("LIB6762", "0.5\n100\n60\n5\n", 2.0, float(mpmath.sqrt(2) * mpmath.erfinv(2 * 0.05 - 1)), "<"),
    ("LIB6771", "100\n60\n120\n50\n5\n", (0.6 - 50 / 120) / math.sqrt(0.5 * 0.5 * (1 / 100 + 1 / 120)),
     float(-mpmath.sqrt(2) * mpmath.erfinv(2 * 0.05 - 1)), ">"),
    ("LIB6772", "100\n60\n120\n50\n5\n", (0.6 - 50 / 120) / math.sqrt(0.5 * 0.5 * (1 / 100 + 1 / 120)),
     float(mpmath.sqrt(2) * mpmath.erfinv(2 * 0.05 - 1)), "<"),
]


@pytest.mark.parametrize("program, keys, statistic, critical, side", HYPOTHESES, ids=[c[0] for c in HYPOTHESES])
def test_tests_of_hypotheses(program, keys, statistic, critical, side):
    a, op, x, verdict = comparisons(program, keys)[-1]
    assert a == pytest.approx(statistic, rel=SHOWN) and x == pytest.approx(critical, rel=SHOWN)
    rejected = statistic > critical if side == ">" else statistic < critical
    assert verdict == ("Reject" if rejected else "Accept")


def test_two_sided_variance_test_shows_both_critical_values():
    (a1, _, upper, _), (a2, _, lower, verdict) = comparisons("LIB6730", "N4\n20\n95\n5\n")
    assert a1 == a2 == pytest.approx(95 / 4, rel=SHOWN)
    assert upper == pytest.approx(quantile(chi_square_upper(19), 0.025, 30), rel=SHOWN)
    assert lower == pytest.approx(quantile(chi_square_upper(19), 0.975, 9), rel=SHOWN)
    assert verdict == "Accept"


# ------------------------------------------------------------------ statistics and regressions
def listed(program: str, keys: str) -> dict[str, float]:
    """The statistics a program lists (``NAME :symbol = value``), by name."""
    found = {}
    for screen in screens(program, keys):
        for name, value in re.findall(r"(?m)^([A-Z0-9]+)\s*:[^=\n]*=\s*" + NUMBER, screen):
            found[name] = float(value)
    return found


DATA = [2, 4, 4, 4, 5, 5, 7, 9]


def test_single_variable_statistics():
    keys = "I" + "".join(f"{x}\n" for x in DATA) + "\nL" + DOWN * 5
    shown_values = listed("LIB6500", keys)
    mean = Fraction(sum(DATA), len(DATA))
    squares = sum((x - mean) ** 2 for x in DATA)
    assert shown_values["CNT"] == len(DATA) and shown_values["SUMX"] == sum(DATA)
    assert shown_values["SUMX2"] == sum(x * x for x in DATA) and shown_values["MEANX"] == mean
    assert shown_values["SDXN"] == pytest.approx(math.sqrt(squares / len(DATA)), rel=1e-9)
    assert shown_values["SDX"] == pytest.approx(math.sqrt(squares / (len(DATA) - 1)), rel=1e-9)


REGRESSIONS = [  # program, points on the curve, a, b (the curve's closed form)
    ("LIB6510", [(1, 2), (2, 4), (3, 6), (4, 8)], 0.0, 2.0),  # y = a + b x
    ("LIB6520", [(1, 1), (2, 2), (4, 3), (8, 4)], 1.0, 1 / math.log(2)),  # y = a + b ln x
    ("LIB6530", [(1, 2), (2, 4), (3, 8), (4, 16)], 1.0, 2.0),  # y = a b^x
    ("LIB6540", [(1, 3), (2, 12), (3, 27), (4, 48)], 3.0, 2.0),  # y = a x^b
]


@pytest.mark.parametrize("program, points, a, b", REGRESSIONS, ids=[c[0] for c in REGRESSIONS])
def test_regressions_recover_the_curve(program, points, a, b):
    keys = "I" + "".join(f"{x}\n{y}\n" for x, y in points) + "\nL" + DOWN * 14
    shown_values = listed(program, keys)
    assert shown_values["COR"] == pytest.approx(1.0, rel=1e-9)
    a_shown = shown_values.get("LRA", shown_values.get("RA"))
    b_shown = shown_values.get("LRB", shown_values.get("RB"))
    assert a_shown == pytest.approx(a, rel=1e-9, abs=1e-9) and b_shown == pytest.approx(b, rel=1e-9)


# ------------------------------------------------------------------ matrices, complex numbers, bases, geometry
def test_determinant_of_a_3_by_3_matrix():
    rows = [[2, 0, 1], [1, 3, 2], [1, 1, 2]]
    keys = "A3\n3\n" + "".join(f"{v}\n" for row in rows for v in row) + "D"
    (a, b, c), (d, e, f), (g, h, i) = (map(Fraction, row) for row in rows)
    exact = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    assert first("LIB5100", keys, "Determinant A =") == pytest.approx(float(exact), rel=1e-9)


def test_complex_product_and_polar_form():
    product = complex(3, 4) * complex(1, 2)
    shown_values = re.findall(NUMBER + r"\s*([+-])\s*" + NUMBER + "i", "".join(screens("LIB5300", "A3\n4\n*1\n2\n")))
    real, sign, imaginary = shown_values[-1]  # A = 3+4i first, then A*B
    assert complex(float(real), float(sign + imaginary)) == product
    assert first("LIB5300", "A3\n4\nG", "r =") == abs(complex(3, 4))
    assert first("LIB5300", "A3\n4\nG", "θ =") == pytest.approx(math.degrees(math.atan2(4, 3)), rel=5e-9)


def test_binary_and_hexadecimal_forms():
    assert re.search(r"\[HEX\] 0*FF\b", "".join(screens("LIB5350", "I255\nH")))
    assert f"{255:032b}" in "".join(screens("LIB5350", "I255\nB"))


def test_area_of_a_regular_hexagon_from_its_inscribed_radius():
    assert first("LIB5635", "16\n1\n", "Area =") == pytest.approx(2 * math.sqrt(3), rel=1e-9)


def test_regular_polyhedra():
    # a cube of edge 2 (its page's first solid): r = 1, R = sqrt 3, S = 24, V = 8
    values = shown("LIB5760", "212\n\r\r\r\r", "(?:inside|outside|surface|volume) =")
    assert values[-4:] == pytest.approx([1.0, math.sqrt(3), 24.0, 8.0], rel=1e-9)
    # a dodecahedron from its surface S = 100 (the line the machine reads with a parenthesis left open)
    s5 = math.sqrt(5)
    edge = math.sqrt(100 / (3 * math.sqrt(25 + 10 * s5)))
    volume = shown("LIB5760", "4" "4" "100\n" + "\r" * 4, "volume =")[-1]
    assert volume == pytest.approx((15 + 7 * s5) / 4 * edge ** 3, rel=1e-9)


# ------------------------------------------------------------------ equations, interpolation, geometry
def test_newton_and_bisection_find_the_roots():
    # x = ROUND(x, INT LOG e - 1) with e = 1E-7: seven decimals (ROUND.md rounds at the digit of 10^-8)
    assert first("LIB5080", "1x^2-2\n1\n", "x =") == pytest.approx(math.sqrt(2), abs=5e-8)
    root = float(mpmath.findroot(lambda x: x ** 3 - x - 2, 1.5))
    assert first("LIB5090", "1x^3-x-2\n1\n2\n", "x =") == pytest.approx(root, abs=1.5e-7)  # bisection to 1E-7


def test_runge_kutta_step_of_the_exponential():
    h = Fraction(1, 10)  # one classical fourth-order step of dy/dx = y from y(0) = 1: the Taylor terms to h^4
    step = 1 + h + h ** 2 / 2 + h ** 3 / 6 + h ** 4 / 24
    assert first("LIB5220", "y\n0\n1\n0.1\n\r", r"y\(\.1\) =") == pytest.approx(float(step), rel=1e-9)


def test_lagrange_interpolation_of_a_parabola():
    assert first("LIB5230", "23\n1\n1\n2\n4\n3\n9\n12.5\n", "y=") == 6.25  # through (1,1) (2,4) (3,9): x^2


LINES_AND_CIRCLES = [  # program, keys, label, closed form
    ("LIB5520", "0\n1\n", "θ =", 45.0),  # the angle between y = 0x + b and y = 1x + d
    ("LIB5530", "1\n0\n0\n2\n", "d =", math.sqrt(2)),  # (0, 2) from y = x
    ("LIB5540", "1\n0\n90\n\r", "Y =", 1.0),  # (1, 0) turned a right angle
    ("LIB5560", "0\n0\n3\n5\n0\n", "length =", 4.0),  # from (5, 0) to the circle of radius 3: 3-4-5
    ("LIB5570", "0\n0\n3\n5\n0\n\r\r\r", "d =", 15 / 4),  # its tangent touches at (9/5, 12/5): y = -3x/4 + 15/4
]

SOLIDS = [  # program, keys (in the screen formula's order), label, closed form
    ("LIB5655", "1\n3\n4\n5\n", "Surface =", 35 * pi),  # zone of a sphere r 5 between radii 3 and 4 (h 1), bases too
    ("LIB5660", "5\n2\n", "Surface =", 40 * pi),  # spherical sector r 5, h 2: cap 2 pi r h + cone pi r sqrt(h(2r-h))
    ("LIB5665", "2\n3\n", "Surface =", 20 * pi),  # cylinder r 2, h 3
    ("LIB5670", "3\n4\n", "Surface =", 24 * pi),  # cone r 3, h 4 (slant 5)
    ("LIB5675", "1\n4\n4\n", "Surface =", 42 * pi),  # frustum r 1, R 4, h 4 (slant 5), both bases
    ("LIB5705", "3\n4\n1\n", "Volume =", 76 * pi / 6),  # zone of a sphere, radii 3 and 4, h 1
    ("LIB5710", "3\n2\n", "Volume =", 12 * pi),  # spherical sector r 3, h 2: 2 pi r^2 h / 3
    ("LIB5725", "1\n2\n3\n", "Volume =", 7 * pi),  # frustum of a cone r 1, R 2, h 3
    ("LIB5730", "4\n3\n2\n6\n", "Volume =", 30.0),  # wedge a 4, b 3, c 2, h 6
    ("LIB5735", "3\n4\n5\n", "Volume =", 20.0),  # pyramid 3 x 4, h 5
    ("LIB5740", "4\n4\n1\n1\n3\n", "Volume =", 21.0),  # frustum of a square pyramid 4 x 4 to 1 x 1, h 3
]


@pytest.mark.parametrize("program, keys, label, value", LINES_AND_CIRCLES + SOLIDS,
                         ids=[c[0] for c in LINES_AND_CIRCLES + SOLIDS])
def test_geometry(program, keys, label, value):
    assert first(program, keys, label) == pytest.approx(value, rel=1e-9)


# ------------------------------------------------------------------ percentage points and interval estimates
def normal_point(p: float) -> float:
    """The x the standard normal exceeds with probability ``p``."""
    return float(-mpmath.sqrt(2) * mpmath.erfinv(2 * p - 1))


def t_point(n: int, p: float) -> float:
    return quantile(lambda t: upper_t(n, t), p, 2)


def f_point(n: int, m: int, p: float) -> float:
    return quantile(lambda t: upper_f(n, m, t), p, 2)


def chi_point(n: int, p: float) -> float:
    return quantile(chi_square_upper(n), p, n)


def test_percentage_points_of_t_and_f():
    # the x with upper probability p: t with 10 degrees of freedom, F(4, 10)
    assert first("LIB6430", "10\n0.05\n", "x=") == pytest.approx(t_point(10, 0.05), rel=SHOWN)
    assert first("LIB6440", "4\n10\n0.05\n", "x=") == pytest.approx(f_point(4, 10, 0.05), rel=SHOWN)


def interval(program: str, keys: str) -> tuple[float, float]:
    """The last screen's confidence interval ``a < parameter < b``."""
    found = re.findall(NUMBER + r"\s*<\s*\S+\s*<\s*" + NUMBER, screens(program, keys)[-1])
    assert found, f"{program}: no interval shown"
    return float(found[-1][0]), float(found[-1][1])


Z975 = normal_point(0.025)
INTERVALS = [  # program, keys (Y/N: no new data; then the figures; 95 %), the interval (closed forms, mpmath)
    # mean, variance known: n = 25, mean 10, sigma 2
    ("LIB6610", "N25\n10\n2\n95\n", (10 - Z975 * 2 / 5, 10 + Z975 * 2 / 5)),
    # mean, variance unknown: n = 25, mean 10, unbiased variance 2: t with 24 degrees of freedom
    ("LIB6620", "N25\n10\n2\n95\n", (10 - t_point(24, 0.025) * math.sqrt(2 / 25),
                                      10 + t_point(24, 0.025) * math.sqrt(2 / 25))),
    # variance from n = 25 and the sum of squares S = 4: S / chi-square(24) points
    ("LIB6630", "N25\n4\n95\n", (4 / chi_point(24, 0.025), 4 / chi_point(24, 0.975))),
    ("LIB6640", "N25\n4\n95\n", (math.sqrt(4 / chi_point(24, 0.025)), math.sqrt(4 / chi_point(24, 0.975)))),
    # variance ratio sigma2^2/sigma1^2: n1 = 25, V1 = 4, n2 = 20, V2 = 9
    ("LIB6650", "NN25\n4\n20\n9\n95\n", (9 / 4 / f_point(19, 24, 0.025), 9 / 4 * f_point(24, 19, 0.025))),
    # mean difference: n1 = 5, mean 10, S1 = 2; n2 = 20, mean 9, S2 = 3; pooled (2 + 3) / 23
    ("LIB6660", "NN5\n10\n2\n20\n9\n3\n95\n",
     (1 - t_point(23, 0.025) * math.sqrt(5 / 23 * (1 / 5 + 1 / 20)), 1 + t_point(23, 0.025) * math.sqrt(5 / 23 * (1 / 5 + 1 / 20)))),
    # ratio: 30 of 100
    ("LIB6670", "100\n30\n95\n", (0.3 - Z975 * math.sqrt(0.3 * 0.7 / 100), 0.3 + Z975 * math.sqrt(0.3 * 0.7 / 100))),
    # ratio difference: 30 of 100 against 20 of 80
    ("LIB6680", "100\n30\n80\n20\n95\n", (0.05 - Z975 * math.sqrt(0.21 / 100 + 0.1875 / 80),
                                           0.05 + Z975 * math.sqrt(0.21 / 100 + 0.1875 / 80))),
]


@pytest.mark.parametrize("program, keys, expected", INTERVALS, ids=[c[0] for c in INTERVALS])
def test_interval_estimates(program, keys, expected):
    # shown to 4 significant digits (the programs' ROUND)
    low, high = interval(program, keys)
    assert low == pytest.approx(expected[0], rel=SHOWN) and high == pytest.approx(expected[1], rel=SHOWN)


# The metric conversions (LIB5950-5980) leave for the CAL mode with EXE, which asks for the
# value and shows the converted one.  The units' definitions (international yard and pound,
# 1959: the inch 2.54 cm, the foot 12 inches, the yard 3 feet, the mile 1760 yards, the pound
# 453.59237 g, the ounce 1/16 pound; the acre 4840 square yards) give the exact factor; the
# programs' factors have 6 significant digits.
INCH, FOOT, YARD = Fraction(254, 100), Fraction(254 * 12, 100), Fraction(254 * 36, 100)  # in cm
MILE, POUND = 1760 * YARD, Fraction(45359237, 100000)  # cm, g
CONVERSIONS = [  # program, the record (1 the first shown), value typed, label of the result, exact value
    ("LIB5950", 2, 10, r"X\[in\]=", 10 / INCH),
    ("LIB5950", 5, 100000, r"X\[mile\]=", 100000 / MILE),
    ("LIB5950", 14, 36, r"X\[yd\]=", 36 * INCH / YARD),
    ("LIB5950", 26, 1, r"X\[cm\]=", MILE),
    ("LIB5960", 2, 10000, r"X\[acre\]=", 10000 / (4840 * (YARD / 100) ** 2)),
    ("LIB5970", 2, 1000, r"X\[in³\]=", 1000 / INCH ** 3),
    ("LIB5980", 2, 100, r"X\[oz\]=", 100 / (POUND / 16)),
    ("LIB5980", 3, 1000, r"X\[lb\]=", 1000 / POUND),
]


@pytest.mark.parametrize("program, record, typed, label, exact", CONVERSIONS,
                         ids=[f"{c[0]}-{c[1]}" for c in CONVERSIONS])
def test_metric_conversions_in_the_cal_mode(program, record, typed, label, exact):
    keys = DOWN * (record - 1) + "\n" + f"{typed}\n"
    assert first(program, keys, label) == pytest.approx(float(exact), rel=2e-6)


def test_the_memory_calculator_evaluates_what_is_typed():
    # LIB1000: an expression typed, EXE shows its value, M+ (the cursor-right key) adds it to
    # the memory; exact in fractions
    last = screens("LIB1000", "7*6-5/4\n")[-1]
    assert float(last.splitlines()[1].split()[0]) == float(Fraction(7 * 6) - Fraction(5, 4))
    last = screens("LIB1000", "2^10/8\x1c3*7\x1c")[-1]
    values = [float(v) for v in last.splitlines()[1].split()]
    assert values == [21.0, float(Fraction(2 ** 10, 8) + 21)]  # the last value; the memory 128 + 21
