"""The compiled ``+ - * /`` of ``--arith decimal`` (number_models.DecimalNumbers, their proof in
yaseer/basic/arithmetic/decimal_scales.py) against the decimal module computing the same
operation on the operands' 12-digit decimals, on hundreds of thousands of operands: the
decades' ends, halfway cases (13th digit 5: half up), carries to a new decade, cancellation,
the range's ends 1E-99 and 9.99999999999E+99, overflow and underflow, division by zero.
The reference is Python's decimal module with the calculator's context (12 digits, half up,
exponents to 99), not the code under test; each family also counts how many results the
inline path gave, so that a family the fast path never reaches fails."""

from __future__ import annotations

import io
import math
import random
from decimal import Decimal, Overflow as DecimalOverflow

import pytest

from yaseer.basic.arithmetic import decimal_arith, decimal_scales
from yaseer.basic.compile.number_models import DecimalNumbers
from yaseer.basic.errors import DIVISION_BY_ZERO, OVERFLOW, BasicError
from yaseer.basic.machine.signals import to_basic_error

CONTEXT = decimal_arith.CONTEXT  # 12 digits, ROUND_HALF_UP, Emax 99: the calculator's (its own test checks)
OPERATIONS = {"+": CONTEXT.add, "-": CONTEXT.subtract, "*": CONTEXT.multiply, "/": CONTEXT.divide}


def reference(op: str, a: float, b: float):
    """The 12-digit result of ``a op b`` on the decimals the doubles stand for, or the error code."""
    da, db = Decimal(format(a, ".12g")), Decimal(format(b, ".12g"))
    if op == "/" and db == 0:
        return ("error", DIVISION_BY_ZERO)
    try:
        result = OPERATIONS[op](da, db)
    except DecimalOverflow:
        return ("error", OVERFLOW)
    return 0.0 if abs(result) < Decimal("1E-99") else float(result)


def own(x: float) -> float:
    """The nearest double to ``x``'s 12-digit decimal (what every held value is)."""
    return float(format(x, ".12g"))


class Site:
    """One compiled operation ``a op b`` (operands as locals, or ``b`` a literal) with its
    cache, counting the results its inline path gave."""

    def __init__(self, op: str, literal: float | None = None, mutate=None):
        model = DecimalNumbers()
        right = "b" if literal is None else repr(literal)
        code = model._scaled(op, "a", right)
        if mutate is not None:
            code = mutate(code)
        self.namespace = {**decimal_arith.RUNTIME, **decimal_scales.initial(model.cache_bases)}
        self.namespace.update(decimal_scales.writers(self.namespace))
        self.slow = 0
        for name in ("_zd", "_zdc", "_zdg"):
            writer = self.namespace[name]
            self.namespace[name] = self._counting(writer)
        exec(f"def run(a, b):\n    return {code}\n", self.namespace)
        self.run = self.namespace["run"]
        self.calls = 0

    def _counting(self, writer):
        def counted(*args):
            self.slow += 1
            return writer(*args)
        return counted

    def __call__(self, a: float, b: float):
        self.calls += 1
        try:
            return self.run(a, b)
        except (BasicError, ZeroDivisionError) as exc:
            return ("error", to_basic_error(exc).code)

    @property
    def fast(self) -> int:
        return self.calls - self.slow


def check(site: Site, pairs, literal: float | None = None) -> None:
    """Every pair through ``site`` equals the reference (bit for bit, and the same error)."""
    for a, b in pairs:
        b = literal if literal is not None else b
        got, want = site(a, b), reference(site_op(site), a, b)
        # (0 == -0: an exact product with 0 may keep the sign, as decimal_arith's own small-number path
        # does; the inline path never gives 0, test_zero_as_the_routine)
        assert got == want and type(got) is type(want), (site_op(site), a, b, got, want)


def site_op(site: Site) -> str:
    return site.op


def make(op: str, literal=None, mutate=None) -> Site:
    site = Site(op, literal, mutate)
    site.op = op
    return site


def decimal12(rng: random.Random, low: int, high: int) -> float:
    """A random 12-digit decimal (random sign) with a decimal exponent from ``low`` to ``high``."""
    mantissa = rng.randrange(10 ** 11, 10 ** 12)
    value = float(f"{mantissa}e{rng.randint(low, high) - 11}")
    return -value if rng.random() < 0.5 else value


def short(rng: random.Random, digits: int, low: int, high: int) -> float:
    """A decimal of at most ``digits`` digits: the values of counters, halves, prices."""
    value = float(f"{rng.randrange(1, 10 ** digits)}e{rng.randint(low, high)}")
    return -value if rng.random() < 0.3 else value


FAMILIES = {
    # operands of any size and sign, many outside the cached decades
    "wide": lambda rng: (decimal12(rng, -99, 99), decimal12(rng, -99, 99)),
    # operands from the decades the inline path covers: mostly inexact results (band test)
    "decades": lambda rng: (decimal12(rng, -12, 12), decimal12(rng, -12, 12)),
    # one decade: carries into the next decade and borrows from it
    "one decade": lambda rng: (decimal12(rng, 2, 2), decimal12(rng, 2, 2)),
    # short decimals: exact results (the exact test), sums of different scales
    "short": lambda rng: (short(rng, 4, -6, 4), short(rng, 3, -4, 3)),
    # halfway: an odd 12-digit mantissa and a half or a five (the 13th digit 5, rounded up)
    "halfway": lambda rng: (float(f"{rng.randrange(10 ** 11, 10 ** 12) | 1}e{rng.randint(-8, 8)}"),
                            rng.choice((0.5, 5.0, -0.5, 0.05, 2.0, 0.2, 50.0, 1.5))),
    # carries: nines plus a unit of the last place (or a little less / more)
    "carries": lambda rng: (float(f"{10 ** 12 - rng.randrange(1, 50)}e{rng.randint(-20, 20)}"),
                            float(f"{rng.randrange(1, 100)}e{rng.randint(-40, 20)}")),
    # cancellation: operands that agree in most digits
    "cancellation": lambda rng: ((lambda m, e: (float(f"{m}e{e}"),
                                                float(f"{m + rng.randrange(-10 ** rng.randint(0, 11), 10 ** rng.randint(0, 11))}e{e}")))
                                 (rng.randrange(10 ** 11, 10 ** 12), rng.randint(-20, 20))),
    # the range's ends: overflow, underflow to 0
    "ends": lambda rng: (rng.choice((9.99999999999e99, -9.99999999999e99, 1e-99, -1e-99, 5e99, 1.00000000001e-99,
                                     decimal12(rng, 95, 99), decimal12(rng, -99, -95))),
                         rng.choice((10.0, 0.1, 2.0, 0.5, 1e-99, 9.99999999999e99, 1.0, -1.0, 0.0,
                                     decimal12(rng, -5, 5)))),
}


@pytest.mark.parametrize("op", ["+", "-", "*", "/"])
@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_inline_operation_equals_the_decimal_module(op, family):
    rng = random.Random(f"{op}{family}")
    make_pair = FAMILIES[family]
    pairs = [tuple(own(x) for x in make_pair(rng)) for _ in range(6000)]
    site = make(op)
    check(site, pairs)
    # a pair again and again (the cache then holds its scale: the inline path answers)
    repeated = make(op)
    check(repeated, [pair for pair in pairs[:1500] for _ in range(3)])
    # (a cancelling sum takes the routine by design: its operands are beyond the guard)
    if family not in ("wide", "ends") and not (family == "cancellation" and op in "+-"):
        assert repeated.fast > 500, (family, repeated.fast)


@pytest.mark.parametrize("op", ["+", "-", "*", "/"])
def test_operation_with_a_literal(op):
    """``A op c`` with a literal: the writer keeps no scale with ``|S c| > 1E13``."""
    rng = random.Random(op)
    for literal in (1.0, 0.5, 3.0, 0.1, 1e-9, 123456789012.0, 4.5e11, 1e12, 7e-12, 0.333333333333):
        site = make(op, literal)
        pairs = [(own(x), None) for x in
                 [decimal12(rng, -13, 13) for _ in range(1500)] + [short(rng, 5, -5, 5) for _ in range(1500)]
                 + [literal * k for k in range(-200, 200)] + [-literal * (1 + 10 ** -k) for k in range(1, 13)]]
        check(site, pairs, literal)
        if literal in (1.0, 0.5, 3.0, 0.1):  # (with the others many results leave the cached decades)
            assert site.fast > 500, (op, literal, site.fast)


def test_counters_across_decades():
    """K = K + 1 and K / 2 over many decades (the cache follows the result's decade)."""
    add, half, triple = make("+", 1.0), make("/", 2.0), make("*")
    k = 0.0
    for _ in range(30000):
        want = reference("+", k, 1.0)
        k = add(k, 1.0)
        assert k == want
        assert half(k, 2.0) == reference("/", k, 2.0)
        assert triple(k, 3.0) == reference("*", k, 3.0)
    for k in [10.0 ** e - 1 for e in range(1, 13)] + [10.0 ** e for e in range(-11, 13)]:
        assert add(own(k), 1.0) == reference("+", own(k), 1.0)
    assert add.fast > 29000 and half.fast > 29000


def test_zero_as_the_routine():
    """A result of 0 is the routine's, sign and all (the inline path never gives 0)."""
    routines = {"*": decimal_arith.multiply, "-": decimal_arith.subtract, "+": decimal_arith.add}
    for op, pairs in (("*", [(2.0, 3.0), (-2.0, 0.0), (-2.0, 3.0), (0.0, -5.0), (-0.0, 5.0), (-1e20, 0.0)]),
                      ("-", [(1.5, 0.75), (1.5, 1.5), (-1e-11, -1e-11), (-1.5, 0.75), (123.456, 123.456)]),
                      ("+", [(1.5, -1.5), (-0.0, 0.0), (-0.0, -0.0), (2.0, 1.0), (1e30, -1e30)])):
        site = make(op)
        for a, b in pairs * 2:
            assert str(site(a, b)) == str(routines[op](a, b)), (op, a, b)


def test_errors_as_the_routine():
    """Division by zero (Python's ZeroDivisionError in the inline code) and overflow give the
    routine's BASIC errors."""
    divide, multiply = make("/"), make("*")
    assert divide(1.0, 0.0) == ("error", DIVISION_BY_ZERO)
    assert divide(0.0, 0.0) == ("error", DIVISION_BY_ZERO)
    assert multiply(9.99999999999e99, 10.0) == ("error", OVERFLOW)
    assert multiply(1e-99, 0.1) == 0.0
    assert make("+")(9.99999999999e99, 1e88) == ("error", OVERFLOW)


@pytest.mark.parametrize("mutation", [
    ("0.49609375", "0.4999999"),  # a band that ignores the error
    (" and _D1l < a < _D1h", ""),  # no guard on a sum's operands
])
def test_the_comparison_finds_a_planted_bug(mutation):
    """The families above catch a fast path without its band or its guard."""
    old, new = mutation
    rng = random.Random(7)
    found = False
    for op in ("+", "-", "*", "/"):
        site = make(op, mutate=lambda code: code.replace(old, new))
        for family in ("halfway", "cancellation", "decades"):
            pairs = [tuple(own(x) for x in FAMILIES[family](rng)) for _ in range(3000)]
            for a, b in pairs * 2:
                if site(a, b) != reference(op, a, b):
                    found = True
                    break
    assert found


def test_scale_of_decades():
    assert decimal_scales.scale(1.0) == 1e11 and decimal_scales.scale(9.99999999999) == 1e11
    assert decimal_scales.scale(-10.0) == -1e10 and decimal_scales.scale(1e-11) == 1e22
    assert decimal_scales.scale(999999999999.0) == 1.0
    for x in (1e12, 9.99999999999e-12, 0.0, 1e99):
        assert decimal_scales.scale(x) != decimal_scales.scale(x)  # NaN: no scale


def test_scale_is_the_decade_of_the_decimal_each_double_stands_for():
    """decimal_scales.scale (one binary search over the decades' powers of ten) against the
    decimal module: the decade of the shortest decimal that reads back as the double (a held
    value's own decimal; ``Decimal.adjusted``), ``10**(11 - e)`` with the value's sign for the
    decades 1E-11 .. 1E+11, else NaN.  Every power of ten from 1E-14 to 1E+14 as a double and the
    doubles next to it on both sides, both signs, 0 and -0, infinities, NaN, the range's ends
    1E-99 and 9.99999999999E+99, and 12-digit decimals of every decade in between."""
    def expected(x: float) -> float:
        if x != x or x in (math.inf, -math.inf) or x == 0.0:
            return math.nan
        e = Decimal(repr(x)).adjusted()
        if not -11 <= e <= 11:
            return math.nan
        return math.copysign(float(10 ** (11 - e)), x)

    rng = random.Random(11)
    values = [0.0, -0.0, math.inf, -math.inf, math.nan, 1e-99, 9.99999999999e99, 5e-324, 1.7976931348623157e308]
    for e in range(-14, 15):
        power = float(f"1e{e}")
        values += [power, math.nextafter(power, 0.0), math.nextafter(power, math.inf)]
        values += [own(rng.uniform(1.0, 10.0) * power) for _ in range(200)]
        values += [float(f"9.99999999999e{e}"), float(f"1.00000000001e{e}")]
    values += [-x for x in values]
    for x in values:
        got, want = decimal_scales.scale(x), expected(x)
        assert got == want or (got != got and want != want), (x, got, want)


def run(program: str, stdin: str = "") -> tuple[str, object]:
    from yaseer.basic.dialects.dialect import CASIO
    from yaseer.basic.machine.machine import Machine

    screen = io.StringIO()
    machine = Machine(screen=screen, printer=io.StringIO(), dialect=CASIO.with_arithmetic("decimal"),
                      input_stream=io.StringIO(stdin))
    machine.load(program)
    machine.run()
    return screen.getvalue(), machine


def test_numbers_entering_are_12_digit_decimals():
    """READ, INPUT, VAL, RND and RAN# give 12-digit decimals (the calculator stores 12 digits),
    so the inline arithmetic's operands always stand for themselves; their arithmetic is the
    decimal arithmetic of those decimals, as before."""
    _, machine = run('10 READ A: INPUT B: C=VAL("0.1234567890123456"): D=RND(1): E=RAN#: F=RND\n'
                     '20 G=A*3: H=B+1E-13: I=C*1E15\n30 DATA 0.1234567890126\n', "2.00000000000049\n")
    values = {name: machine.scalar(name) for name in "ABCDEFGHI"}
    for name, value in values.items():
        assert own(value) == value, (name, value)
    assert values["A"] == 0.123456789013 and values["B"] == 2.0 and values["C"] == 0.123456789012
    assert values["G"] == 0.370370367039 and values["H"] == 2.0 and values["I"] == 123456789012000.0


def test_a_program_in_decimal():
    """Sums that binary gets wrong; a square by the product; the overflow of a square."""
    out, machine = run("10 A=0: FOR I=1 TO 10: A=A+.1: NEXT: B=1-10*.1: C=(1/3)*3: D=1.00000000001^2\n"
                       "20 E=1E50: F=0: ON ERROR GOTO 40: F=E^2\n30 END\n40 F=-1: RESUME 30\n")
    assert machine.scalar("A") == 1.0 and machine.scalar("B") == 0.0 and machine.scalar("C") == 0.999999999999
    assert machine.scalar("D") == 1.00000000002 and machine.scalar("F") == -1.0


def test_rounded_within_is_the_rounding_of_every_number_in_reach():
    """decimal_scales.rounded_within (SQR, EXP, LOG, SIN, COS from the float functions): where it
    answers, both ends of the reach round (by the decimal module, half up) to its answer;
    and it answers for most values."""
    rng = random.Random(11)
    answered = 0
    for _ in range(60000):
        value = float(f"{rng.randrange(10 ** 15, 10 ** 16)}e{rng.randint(-27, -5)}") * rng.choice((1, -1))
        if rng.random() < 0.2:  # near a rounding boundary: a 12-digit decimal and a half unit
            value = float(f"{rng.randrange(10 ** 11, 10 ** 12)}5e{rng.randint(-23, -1)}")
        error = abs(value) * rng.choice((4e-16, 6e-16, 1e-15, 1e-14, 1e-13))
        found = decimal_scales.rounded_within(value, error)
        if found is None:
            continue
        answered += 1
        for end in (Decimal(value) - Decimal(error) * Decimal("1.0001"), Decimal(value) + Decimal(error) * Decimal("1.0001")):
            assert float(CONTEXT.plus(end)) == found, (value, error, found)
    assert answered > 30000


@pytest.mark.parametrize("function", ["sin", "cos"])
@pytest.mark.parametrize("degrees", [True, False])
def test_sine_and_cosine_of_whole_numbers_against_mpmath(function, degrees):
    """A whole angle is its own decimal exactly: the float path's bound has no term for the
    angle's distance from its decimal (BM8's SIN(K)); the result is mpmath's, rounded half up
    to 12 digits."""
    import mpmath

    mpmath.mp.dps = 50
    rng = random.Random(function + str(degrees))
    angles = list(range(1, 3000)) + [rng.randrange(1, 10 ** rng.randint(4, 9)) for _ in range(3000)]
    for k in angles:
        for x in (k, -k):
            arg = mpmath.mpf(x) * mpmath.pi / 180 if degrees else mpmath.mpf(x)
            exact = (mpmath.sin if function == "sin" else mpmath.cos)(arg)
            if degrees and x % 90 == 0:
                continue  # (exact at right angles: test_decimal_arith)
            expected = float(CONTEXT.plus(Decimal(mpmath.nstr(exact, 40, min_fixed=-60, max_fixed=60))))
            assert getattr(decimal_arith, function)(float(x), degrees) == expected, (function, degrees, x)


def _expression(rng: random.Random, depth: int) -> str:
    """A random BASIC expression of + - * / over A, B, C, K and literals (no division by 0)."""
    if depth == 0 or rng.random() < 0.25:
        return rng.choice(["A", "B", "C", "K", "K", "2", "3", "4", "5", ".5", ".125", "8", "1E3", "0.1", "7"])
    op = rng.choice("+-*/")
    left = _expression(rng, depth - 1)
    if op == "/":
        right = rng.choice(["2", "4", "8", "3", ".5", "K", "A", left if left in "ABCK" else "2"])
    else:
        right = _expression(rng, depth - 1)
    return f"({left}{op}{right})"


def _results(program: str, caching: bool, monkeypatch, inline: bool = True) -> list:
    """Y() after ``program``, compiled with the inline paths (``caching``) or the routines alone;
    ``inline``: the inline caches, else the C routines where built (test_decimal_fast.py)."""
    monkeypatch.setenv("YASEER_CACHE_DIR", "")  # (the compiled-program cache does not tell the two apart)
    monkeypatch.setenv("YASEER_PURE_PYTHON", "1" if inline else "")
    original = DecimalNumbers.__init__

    def init(self):
        original(self)
        self.caching = caching
    monkeypatch.setattr(DecimalNumbers, "__init__", init)
    try:
        _, machine = run(program)
    finally:
        monkeypatch.setattr(DecimalNumbers, "__init__", original)
    return [repr(v) for row in machine.arrays["Y"] for v in row]


@pytest.mark.parametrize("inline", [True, False])
@pytest.mark.parametrize("seed", range(12))
def test_compiled_statements_equal_the_routines(monkeypatch, seed, inline):
    """Whole statements (their exact float forms where their variables are whole and small, the
    scale caches elsewhere) give the values decimal_arith's routines give, bit for bit, over
    values that pass and fail the tests: whole numbers at and beyond the bounds, halves,
    tenths, negatives, large and small numbers; with the inline caches and with the C routines
    (``inline`` False, where built: arithmetic/_decimal_fast.c)."""
    rng = random.Random(seed)
    values = [1, 2, 3, 7, -5, 999, 1000, 12345, 31622, 31623, 99999, 123456789, 599999999, 600000000,
              899999999, 900000000, 999999999, 1000000000, 2.5, -0.5, 0.1, 0.125, 1234.5678, 1e-5, 3e11,
              -123456789012, 0.333333333333, 9.99999999999e20]
    rows = 20
    expressions = [_expression(rng, 3) for _ in range(40)]
    lines = [f"10 DIM Y({rows},{len(expressions)})", f"20 FOR R=1 TO {rows}: READ A,B,C,K"]
    lines += [f"{30 + i} Y(R,{i})={e}" for i, e in enumerate(expressions)]
    lines.append(f"{30 + len(expressions)} NEXT R")
    # (half of them whole numbers of any size up to 1E+10: the exact forms' bounds are round numbers)
    data = [(rng.choice(values) if rng.random() < 0.5 else rng.randrange(1, 10 ** rng.randint(1, 10)))
            * rng.choice((1, 1, -1)) for _ in range(4 * rows)]
    lines += [f"{1000 + i} DATA {','.join(repr(float(v)) for v in data[i:i + 8])}" for i in range(0, len(data), 8)]
    program = "\n".join(lines) + "\n"
    fast, routines = _results(program, True, monkeypatch, inline), _results(program, False, monkeypatch)
    assert fast == routines
