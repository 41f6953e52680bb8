"""The compiled SQR, LN, LOG, EXP, SIN, COS and RND of ``--arith decimal`` (number_models.
DecimalNumbers.call, their proof in yaseer/basic/arithmetic/decimal_calls.py) against mpmath
at 40 digits rounded half up to 12 digits, on the argument's 12-digit decimal, and against
decimal_arith's routine (the code before the inline path) on every argument: thousands of
generated arguments per function and unit, among them the hard ones (near 1 for LN and LOG,
angles near the zeros of SIN and COS, large whole angles, fractions beyond a turn, perfect
squares, the range's ends).  Each family counts the results the inline path gave, so that a
path never taken fails; planted bugs (a wider band, a larger scale, a raw sine of any angle)
must be caught."""

from __future__ import annotations

import math
import random
from fractions import Fraction

import mpmath
import pytest

from yaseer.basic.arithmetic import decimal_arith, decimal_calls
from yaseer.basic.compile.number_models import DecimalNumbers
from yaseer.basic.errors import BasicError

MP_FUNCTIONS = {"_sqrt": mpmath.sqrt, "_log": mpmath.log, "_log10": mpmath.log10, "_exp": mpmath.exp,
                "_sin": mpmath.sin, "_cos": mpmath.cos}
TURN = {"DEG": 360, "GRA": 400, "RAD": None}


def round12(value: Fraction) -> float:
    """``value`` rounded half up (away from zero) to 12 significant digits, as a float."""
    if value == 0:
        return 0.0
    sign = -1 if value < 0 else 1
    value = abs(value)
    exponent = math.floor(math.log10(value))
    while value >= Fraction(10) ** (exponent + 1):
        exponent += 1
    while value < Fraction(10) ** exponent:
        exponent -= 1
    scale = Fraction(10) ** (11 - exponent)
    return sign * float(Fraction(math.floor(value * scale + Fraction(1, 2))) / scale)


def reference(helper: str, x: float, unit: str = "DEG"):
    """mpmath's value of the function at ``x``'s 12-digit decimal rounded to 12 digits; None at a
    right angle (the arithmetic's value is exact there)."""
    mpmath.mp.dps = 40
    d = Fraction(format(x, ".12g"))
    arg = mpmath.mpf(d.numerator) / d.denominator
    if helper in ("_sin", "_cos"):
        if unit == "GRA":  # (the FX-850P's grads are 0.9 degree: the degrees rounded to 12 digits)
            d = Fraction(format(round12(d * Fraction(9, 10)), ".12g"))
            arg = mpmath.mpf(d.numerator) / d.denominator
        if unit != "RAD" and d % 90 == 0:
            return None
        arg = arg * mpmath.pi / 180 if unit != "RAD" else arg
    value = MP_FUNCTIONS[helper](arg)
    if value == 0:
        return 0.0
    exact = Fraction(mpmath.nstr(value, 38, min_fixed=-400, max_fixed=400))
    return round12(exact)


class Site:
    """One compiled call of ``helper`` on the local ``x`` with its cache, counting the results its
    inline path gave."""

    def __init__(self, helper: str, unit: str = "DEG", mutate=None):
        model = DecimalNumbers()
        code, _ = model.call(helper, helper, ["x"] if helper != "_rndf" else [], ["n"], "n")
        if mutate is not None:
            code = mutate(code)
        self.namespace = {**decimal_arith.RUNTIME, **decimal_arith.trig_functions(unit)}
        self.namespace.update({name: math.nan for name in model.cache_bases})
        self.namespace.update(decimal_calls.helpers(self.namespace))
        self.routine = self.namespace[helper if helper != "_rndf" else "_d13"]
        self.slow = self.routines = 0
        writer = self.namespace["_zdf"]

        def counted(*args):
            self.slow += 1
            return writer(*args)

        def counted_routine(*args):
            self.routines += 1
            return self.routine(*args)
        self.namespace["_zdf"] = counted
        self.namespace[helper if helper != "_rndf" else "_d13"] = counted_routine
        exec(f"def run(x):\n    return {code}\n", self.namespace)
        self.run = self.namespace["run"]
        self.calls = 0

    def __call__(self, x: float):
        self.calls += 1
        return self.run(x)

    @property
    def fast(self) -> int:
        return self.calls - self.slow


def own(x: float) -> float:
    return float(format(x, ".12g"))


def arguments(helper: str, unit: str, rng: random.Random) -> list[float]:
    """Generated own decimals for ``helper``: mostly in a few decades in turn (a loop's
    arguments), with the hard cases among them."""
    values = []
    if helper == "_sqrt":
        for _ in range(1500):
            values.append(own(rng.uniform(1, 10) * 10.0 ** rng.randint(-30, 30)))
        values += [float(k * k) for k in range(1, 300)] + [own(k * k * 1e-6) for k in range(1, 200)]
        values += [9.99999999999e99, 1e-99, 0.0, -4.0]
    elif helper in ("_log", "_log10"):
        for _ in range(1200):
            values.append(own(rng.uniform(1, 10) * 10.0 ** rng.randint(-40, 40)))
        values += [own(1 + k * 1e-11) for k in range(-60, 60)] + [own(1 + k * 1e-6) for k in range(-60, 60)]
        values += [10.0 ** k for k in range(-20, 21)] + [float(k) for k in range(1, 400)]
        values += [9.99999999999e99, 1e-99, 0.0, -1.0]
    elif helper == "_exp":
        for _ in range(1500):
            values.append(own(rng.uniform(-25, 25)))
        values += [float(k) for k in range(-30, 31)] + [own(k * 1e-9) for k in range(-50, 50)]
    elif helper in ("_sin", "_cos"):
        turn = TURN[unit] or 6.283185307179586
        for _ in range(800):
            values.append(own(rng.uniform(-turn, turn)))
        for _ in range(300):
            values.append(float(rng.randint(-10 ** 6, 10 ** 6)))
        for _ in range(200):
            values.append(own(rng.randint(-10 ** 14, 10 ** 14)))
        for _ in range(200):
            values.append(own(rng.uniform(-1e6, 1e6)))  # a fraction beyond a turn: the routine
        if unit != "RAD":
            quarter = TURN[unit] // 4
            for k in range(-12, 13):
                for off in (0.0, 1e-9, -1e-9, 1e-5, -1e-5, 0.01, -0.01):
                    values.append(own(k * quarter + off))
        else:
            for k in range(-6, 7):
                for off in (1e-6, -1e-6, 1e-3):
                    values.append(own(k * math.pi + off))
    return sorted(values)


CASES = [("_sqrt", "DEG"), ("_log", "DEG"), ("_log10", "DEG"), ("_exp", "DEG"),
         ("_sin", "DEG"), ("_cos", "DEG"), ("_sin", "GRA"), ("_cos", "GRA"), ("_sin", "RAD"), ("_cos", "RAD")]


def outcome(function, x):
    try:
        return function(x)
    except BasicError as exc:
        return ("error", exc.code)


@pytest.mark.parametrize("helper, unit", CASES)
def test_inline_function_is_mpmaths_rounding_and_the_routines(helper, unit):
    rng = random.Random(hash((helper, unit)) & 0xFFFF)
    site = Site(helper, unit)
    checked = 0
    for x in arguments(helper, unit, rng):
        got = outcome(site, x)
        assert got == outcome(site.routine, x), (helper, unit, x, got)
        # (a whole angle in radians from 1E+9 up: the routine's 25-digit reduction by 2 pi loses
        # digits there, as it did before; the inline path leaves those to it)
        if unit == "RAD" and abs(x) >= 1e9:
            continue
        if type(got) is float and x > 0 or helper in ("_exp", "_sin", "_cos"):
            expected = reference(helper, x, unit)
            if expected is not None and abs(expected) >= 1e-99:
                assert got == expected, (helper, unit, x, got, expected)
                checked += 1
    assert checked > 1000
    if unit == "GRA":  # (the routine rounds the angle in degrees to 12 digits first: no float value)
        assert site.routines == site.calls
        return
    # the inline path is common (runs of one decade), the routine takes the hard arguments
    assert site.fast > site.calls * 0.3 and site.routines < site.calls * 0.5, (site.fast, site.routines, site.calls)


def test_rnd_is_the_number_drawn_rounded_to_12_digits():
    site = Site("_rndf")
    rng = random.Random(5)
    drawn = [rng.random() for _ in range(20000)]
    # halfway between 12-digit decimals: 13 digits ending in 5, exactly a double (k / 2**13)
    drawn += [k / 8192 for k in range(1, 8192)]
    drawn += [1e-5, 0.0999999999999999, 0.1, 0.0, 0.9999999999999999, 2.0 ** -40]
    values = iter(drawn)
    site.namespace["_rndr"] = lambda: next(values)
    for v in drawn:
        assert site(None) == float(format(v, ".12g")) == decimal_arith.rounded(v), v
    assert site.fast > site.calls * 0.6 and site.routines > 100  # (the halfway cases take the routine)


def test_rnd_near_its_decades_ends_against_the_decimal_module():
    """RND's inline rounding at the ends of its two scaled ranges (0.1 up with 1E+12, 0.01 up to
    0.1 with 1E+13): the doubles next to 0.01, 0.1 and 1 and draws within half a unit of them,
    whose rounding is 0.01, 0.1 or 1 (the scaled value reaches 1E+12).  Reference: the exact
    double rounded to 12 digits by the decimal module (half to even, as ``_d13``: the
    halfway cases are exact doubles)."""
    from decimal import ROUND_HALF_EVEN, Context, Decimal

    context = Context(prec=12, rounding=ROUND_HALF_EVEN)
    drawn = []
    for edge in (0.01, 0.1, 1.0):
        below = above = edge
        for _ in range(200):
            below, above = math.nextafter(below, 0.0), math.nextafter(above, 2.0)
            drawn += [below] + ([above] if above < 1.0 else [])
        for k in range(1, 400):  # within half a unit of the edge (the 12th digit's), both sides
            drawn += [edge * (1 - k * 1.3e-15), edge * (1 + k * 1.3e-15)] if edge < 1.0 else [edge * (1 - k * 1.3e-15)]
    rng = random.Random(11)
    drawn += [rng.uniform(0.01, 0.1) for _ in range(5000)] + [rng.uniform(0.0, 0.01) for _ in range(500)]
    site = Site("_rndf")
    values = iter(drawn)
    site.namespace["_rndr"] = lambda: next(values)
    for v in drawn:
        expected = float(context.plus(Decimal(v)))
        assert site(None) == expected == decimal_arith.rounded(v), v
    scaled = [v for v in drawn if 0.01 <= v < 1.0]
    assert site.fast > len(scaled) * 0.9, (site.fast, len(scaled))  # both scaled ranges are taken
    assert site.slow >= 500  # (below 0.01: the routine)


@pytest.mark.parametrize("helper, unit, mutate", [
    ("_log", "DEG", lambda code: code.replace(", 1000000000000.0))", ", 1e+22))")),  # any scale near LN(1)
    ("_log10", "DEG", lambda code: code.replace(", 1000000000000.0))", ", 1e+22))")),
    ("_sin", "DEG", lambda code: code.replace("-0.49609375 <", "-0.5 <").replace("< 0.49609375", "< 0.5")),
])
def test_planted_bugs_are_caught(helper, unit, mutate):
    site = Site(helper, unit, mutate)
    rng = random.Random(3)
    wrong = 0
    xs = arguments(helper, unit, rng)
    if helper == "_sin":  # many values that the band test's margin turns away
        xs = [own(rng.uniform(0, 360)) for _ in range(20000)]
    for x in xs:
        got = outcome(site, x)
        expected = reference(helper, x, unit) if type(got) is float else None
        wrong += expected is not None and got != expected
    assert wrong > 0


def test_a_fraction_of_a_degree_beyond_a_turn_takes_the_routine():
    """The float sine of such an angle (its distance from its decimal moves it too far) would
    give wrong digits: the inline code leaves every one to the routine."""
    rng = random.Random(11)
    site = Site("_sin")
    wrong = 0
    for _ in range(400):
        x = own(rng.uniform(1e8, 1e9))
        float_value = math.sin(math.fmod(x, 360.0) * (math.pi / 180.0))
        expected = reference("_sin", x)
        wrong += own(float_value) != expected
        assert site(x) == expected
    assert wrong > 0 and site.routines == site.calls


def test_inline_functions_in_a_program_change_unit_with_angle():
    import io

    from yaseer.basic.dialects.dialect import CASIO
    from yaseer.basic.machine.machine import Machine

    program = ("10 FOR K=1 TO 40: A(K)=SIN(K*9): NEXT K\n20 ANGLE 1\n"
               "30 FOR K=1 TO 40: B(K)=SIN(K/10): C(K)=SQR(K)+LN(K)+LOG(K)+EXP(K/10)+COS(K): D(K)=RND(1): NEXT K\n")
    machine = Machine(screen=io.StringIO(), printer=io.StringIO(), dialect=CASIO.with_arithmetic("decimal"))
    machine.load("5 DIM A(40),B(40),C(40),D(40)\n" + program)
    machine.run()
    arrays = machine.arrays
    for k in range(1, 41):
        assert arrays["A"][k] == (decimal_arith.sin(k * 9.0)), k
        assert arrays["B"][k] == decimal_arith.trig_functions("RAD")["_sin"](own(k / 10)), k
        parts = [decimal_arith.sqrt(k), decimal_arith.log(k), decimal_arith.log10(k),
                 decimal_arith.exp(own(k / 10)), decimal_arith.trig_functions("RAD")["_cos"](float(k))]
        total = parts[0]
        for part in parts[1:]:
            total = decimal_arith.add(total, part)
        assert arrays["C"][k] == total, k
        assert arrays["D"][k] == own(arrays["D"][k]) and 0 <= arrays["D"][k] < 1


@pytest.mark.parametrize("helper", ["_sin", "_cos"])
def test_whole_degrees_come_from_the_table_of_the_routines_results(helper):
    """SIN and COS of a whole angle in degrees below 1E+9 in size take the table of the whole
    degrees (decimal_arith.WholeDegrees): mpmath's value rounded to 12 digits and the routine's
    result at the angle itself, over several turns either side, right angles, large angles and
    the ends of the table's range, with no call of the cache's writer."""
    rng = random.Random(22)
    xs = [float(k) for k in range(-1100, 1101)]
    xs += [float(rng.randint(-10 ** 9 + 1, 10 ** 9 - 1)) for _ in range(1500)]
    xs += [float(k * 90 + d) for k in (-11111110, -4, 4, 11111110) for d in (-1, 0, 1)]
    xs += [999999999.0, -999999999.0, 999999720.0, -0.0]
    site = Site(helper, "DEG")
    for x in xs:
        got = site(x)
        assert got == site.routine(x), (helper, x, got)
        expected = reference(helper, x)
        if expected is None:  # a right angle: exactly 0, 1 or -1
            expected = float(round(getattr(math, helper[1:])(math.radians(x % 360.0))))
        assert got == expected, (helper, x, got, expected)
    assert site.slow == 0
    for x in (1e9, -1e9, 1e12, 12345678901.0):  # beyond the table's range: as before (routine or band test)
        assert site(x) == site.routine(x)
    assert site.slow > 0


@pytest.mark.parametrize("helper", ["_sqrt", "_log", "_log10", "_exp", "_sin", "_cos"])
def test_a_function_site_keeps_two_decades(helper):
    """A function site tries its second scale (the one its cache held before the writer last
    changed it) before the writer: arguments whose values move between two decades (a square
    root of numbers from 1 to 1000, as Ahl's benchmark takes them) call the writer only while
    the site learns them, and every result is mpmath's value rounded to 12 digits.  Each value's
    decade's ends (both sides of the power of ten), negative values (SIN, COS, LN below 1),
    0, the routine's errors and the range's ends in between; a planted bug (a result of the
    second scale divided by the first) fails."""
    rng = random.Random(41)
    pairs = {"_sqrt": (own(rng.uniform(30.0, 99.0)), own(rng.uniform(100.0, 999.0))),
             "_log": (own(rng.uniform(1.2, 2.7)), own(rng.uniform(2.8, 9e3))),
             "_log10": (own(rng.uniform(1.3, 9.9)), own(rng.uniform(11.0, 9e8))),
             "_exp": (own(rng.uniform(0.1, 2.3)), own(rng.uniform(2.31, 4.6))),
             "_sin": (own(rng.uniform(5.8, 60.0)), own(rng.uniform(185.8, 240.0))),
             "_cos": (own(rng.uniform(0.5, 84.0)), own(rng.uniform(95.0, 174.0)))}
    edges = {"_sqrt": [100.0, own(99.9999999999), own(100.000000001), 1e-99, 9.99999999999e99, 0.0],
             "_log": [own(math.e), own(math.e * (1 + 1e-12)), own(1 / math.e), 0.5, 1e-99, 9.99999999999e99],
             "_log10": [10.0, own(9.99999999999), own(10.0000000001), 0.01, 1e-99, 9.99999999999e99],
             "_exp": [own(math.log(10)), own(math.log(10) * (1 + 1e-12)), -4.0, 0.0, 230.0, -230.0],
             "_sin": [own(math.degrees(math.asin(0.1))), own(5.73917047726), -30.0, 0.0, 1e-99, 210.5],
             "_cos": [own(math.degrees(math.acos(0.1))), own(84.2608295227), 120.5, 0.0, 1e-99, -95.5]}
    site = Site(helper)
    arguments_ = []
    for _ in range(40):  # a loop's arguments: one decade of values, then the other, in turn
        first, second = pairs[helper]
        arguments_ += [own(first * (1 + rng.uniform(-0.01, 0.01))) for _ in range(5)]
        arguments_ += [own(second * (1 + rng.uniform(-0.01, 0.01))) for _ in range(5)]
    for x in arguments_:
        assert site(x) == reference(helper, x), (helper, x)
    # the two decades learnt, then the writer only near a rounding boundary (about 1 in 128 values;
    # with one scale it was called at each of the 79 changes of decade)
    assert site.slow <= 12, site.slow
    for x in edges[helper] + arguments_[:20]:
        expected = reference(helper, x) if helper != "_sqrt" or x >= 0 else None
        if expected is not None and abs(expected) < 1e-99:
            expected = 0.0  # (below 1E-99 the calculator's 0)
        try:
            got = site(x)
        except BasicError:
            got = "error"
            with pytest.raises(BasicError):
                site.routine(x)
        else:
            assert got == site.routine(x)
        if got != "error" and expected is not None:
            assert got == expected, (helper, x, got, expected)
    planted = Site(helper, mutate=lambda code: code.replace("_dn / _D1b if", "_dn / _D1 if"))  # the wrong scale
    assert any(planted(x) != reference(helper, x) for x in arguments_)


def drawn_sum_site():
    """``a + RND`` compiled (number_models.DecimalNumbers._drawn_sum) on the local ``a``, with the
    drawn numbers from ``site["drawn"]`` and a count of the writer's calls."""
    from yaseer.basic.arithmetic import decimal_scales

    model = DecimalNumbers()
    draw, _ = model.call("RND", "_rndf", [], [], "n")
    code, _ = model.arithmetic("+", "a", "n", draw, "n")
    assert "_zdr(" in code and "_d13" not in code  # fused: the number drawn is not rounded first
    namespace = {**decimal_arith.RUNTIME, **decimal_scales.initial(model.cache_bases)}
    namespace.update(decimal_scales.writers(namespace))
    writer = namespace["_zdr"]
    site = {"slow": 0, "drawn": iter(())}

    def counted(*args):
        site["slow"] += 1
        return writer(*args)
    namespace.update({"_zdr": counted, "_rndr": lambda: next(site["drawn"])})
    exec(f"def run(a):\n    return {code}\n", namespace)
    site["run"] = namespace["run"]
    return site


def test_a_fused_sum_lists_only_the_caches_its_code_writes():
    """The rounded number's code is dropped where the sum takes the number unrounded: its cache
    is not among the model's caches (they are the ones the code's writers name)."""
    from yaseer.basic.compile.number_models import _SCALE_WRITTEN

    model = DecimalNumbers()
    draw, _ = model.call("RND", "_rndf", [], [], "n")
    code, _ = model.arithmetic("+", "a", "n", draw, "n")
    other, _ = model.call("RND", "_rndf", [], [], "n")  # an RND left alone keeps its cache
    assert sorted(model.cache_bases) == sorted(set(_SCALE_WRITTEN.findall(code + other)))
    assert len(model.cache_bases) == 2


def test_a_sum_with_rnd_is_the_sum_with_the_rounded_number():
    """``a + RND`` (the number drawn added unrounded, one rounding) against the sum of ``a`` and
    the number rounded to 12 digits: decimal_arith's add of ``_d13``'s number (the code before),
    and the decimal module (the number's exact double rounded half to even to 12 digits, the
    sum of the two decimals rounded half up to 12): running sums from 0 and from -50 (Ahl's
    R = R + RND(1) passes through every decade up from 1E-1 and across 0), and sums of
    generated decades, signs and numbers, the halfway numbers k / 8192 among them."""
    from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Context, Decimal

    drawn_context = Context(prec=12, rounding=ROUND_HALF_EVEN)
    sum_context = Context(prec=12, rounding=ROUND_HALF_UP)

    def reference(a, v):
        exact = sum_context.add(Decimal(format(a, ".12g")), drawn_context.plus(Decimal(v)))
        return float(exact)

    rng = random.Random(23)
    site = drawn_sum_site()
    calls = 0
    for start in (0.0, -50.0, 999.5):
        a = start
        numbers = [rng.random() for _ in range(6000)] + [k / 8192 for k in range(1, 8192, 7)]
        site["drawn"] = iter(numbers)
        for v in numbers:
            result = site["run"](a)
            expected = decimal_arith.add(a, decimal_arith.rounded(v))
            assert result == expected == reference(a, v), (a, v)
            a = result
            calls += 1
    pairs = [(own(rng.choice((1, -1)) * rng.uniform(1, 10) * 10.0 ** rng.randrange(-3, 13)), rng.random())
             for _ in range(20000)]
    pairs += [(own(rng.uniform(100, 2000)), k / 8192) for k in range(1, 8192)]
    site["drawn"] = iter(v for _, v in pairs)
    for a, v in pairs:
        assert site["run"](a) == decimal_arith.add(a, decimal_arith.rounded(v)) == reference(a, v), (a, v)
        calls += 1
    assert site["slow"] < calls * 0.6, (site["slow"], calls)  # the fused path is taken


def test_a_sum_with_rnd_needs_no_guard_on_the_local():
    """The fused ``a + RND`` tests no bounds on ``a`` (a sum of two variables does: ``_D<n>l <
    a < _D<n>h``): with the number drawn in [0, 1) and the scale at most DRAWN_SCALE, the range
    test bounds ``a``.  Against the decimal module (the number rounded half to even to 12 digits,
    the sum half up) on the locals where a missing bound could show: 0, -0, locals just below 0
    that the number carries across it, every decade's ends from 1E-12 to 1E+12 and next to the
    sums' decades' ends, both signs, locals from which the sum's scale is the largest kept
    (1E+9: sums from 100 up), the largest scale's neighbours, and the range's ends."""
    from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Context, Decimal

    drawn_context = Context(prec=12, rounding=ROUND_HALF_EVEN)
    sum_context = Context(prec=12, rounding=ROUND_HALF_UP, Emax=99)

    def reference(a, v):
        return float(sum_context.add(Decimal(format(a, ".12g")), drawn_context.plus(Decimal(v))))

    model = DecimalNumbers()
    draw, _ = model.call("RND", "_rndf", [], [], "n")
    code, _ = model.arithmetic("+", "a", "n", draw, "n")
    (cache,) = model.cache_bases
    assert f"{cache}l" not in code and f"{cache}h" not in code
    rng = random.Random(29)
    locals_ = [0.0, -0.0, -1e-12, -0.5, -0.999999999999, 9.99999999999e99, -9.99999999999e99, 1e-99, -1e-99]
    for e in range(-12, 13):
        for m in (1.0, 9.99999999999, 9.9999999999, 5.0, 1.00000000001):
            locals_ += [own(m * 10.0 ** e), own(-m * 10.0 ** e)]
    locals_ += [own(rng.uniform(99.0, 101.0)) for _ in range(300)] + [own(-rng.uniform(0.0, 1.0)) for _ in range(300)]
    numbers = [0.0, 0.5, 1 - 2.0 ** -53, 2.0 ** -53, 0.0999999999995, 0.00999999999995] + [rng.random() for _ in range(40)]
    site = drawn_sum_site()
    pairs = [(a, v) for a in locals_ for v in numbers]
    site["drawn"] = iter(v for _, v in pairs * 2)
    for a, v in pairs * 2:  # twice: the second time the site's cache holds a scale from the first
        assert site["run"](a) == decimal_arith.add(a, decimal_arith.rounded(v)) == reference(a, v), (a, v)
    assert site["slow"] < len(pairs) * 2 * 0.9, site["slow"]  # the fused path is taken


def test_a_sum_with_rnd_keeps_no_scale_beyond_its_bound():
    """A planted bug: the drawn number's distance from its rounding is only small enough up to
    the scale 1E+9 (sums from 100 up); a site that keeps larger scales gives wrong sums."""
    from yaseer.basic.arithmetic import decimal_scales

    original = decimal_scales.DRAWN_SCALE
    decimal_scales.DRAWN_SCALE = 1e13
    try:
        site = drawn_sum_site()
        rng = random.Random(3)
        pairs = [(own(rng.uniform(0.1, 1.0)), rng.random()) for _ in range(20000)]
        site["drawn"] = iter(v for _, v in pairs)
        wrong = sum(site["run"](a) != decimal_arith.add(a, decimal_arith.rounded(v)) for a, v in pairs)
    finally:
        decimal_scales.DRAWN_SCALE = original
    assert wrong > 0
