"""The C accelerator of ``--arith decimal`` (yaseer/basic/arithmetic/_decimal_fast.c, through
decimal_fast.py) against an independent reference: Python's decimal module with the Casio's rule
as docs/compatibility.md states it (12 significant digits, rounded half up, 0 below 1E-99 in
size, Overflow from 1E+100 on), computed here from the operands' decimals, and, for SQR, LN,
LOG and EXP, mpmath's value at 40 digits rounded half up to 12 (test_decimal_calls.reference).
Operands are 12-digit decimals (the values the arithmetic holds) drawn by hypothesis and by a
seeded sweep: random ones over the whole range, ties (a 13th digit 5 exactly: products with
5, 0.5, 2.5; sums of decades one and two apart), the decades' ends (1, 999999999999 and their
neighbours), cancellation, huge and tiny exponents with their overflow and underflow.  Every
result must also be decimal_arith's routine's (the code the inline caches compute), bit for
bit, and most must come from the C tests themselves (a fallback counted), so a path never
taken fails.  The machine's compiled code calls the routines (Ahl's chains against the decimal
module here; generated statements against the routines alone in test_decimal_scales.py)."""

from __future__ import annotations

import io
import random
from decimal import ROUND_HALF_EVEN, ROUND_HALF_UP, Context, Decimal, Overflow as DecimalOverflow

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from yaseer.basic.arithmetic import decimal_arith, decimal_fast
from yaseer.basic.errors import BasicError

fast = pytest.importorskip("yaseer.basic.arithmetic._decimal_fast")

# 12 digits wherever the result lies, then the range (reference() makes one below 1E-99 0): Emin far
# below -99, or the decimal module rounds a result under 1E-99 to fewer digits first
REFERENCE = Context(prec=12, rounding=ROUND_HALF_UP, Emax=99, Emin=-999, traps=[DecimalOverflow])
EVEN = Context(prec=12, rounding=ROUND_HALF_EVEN, Emax=99, Emin=-999, traps=[DecimalOverflow])
OPERATIONS = {"add": "add", "subtract": "subtract", "multiply": "multiply", "divide": "divide"}


def reference(op: str, a: Decimal, b: Decimal, context=REFERENCE):
    """The Casio's result of ``a op b`` as a float, or "Overflow" / "Division by zero"."""
    if op == "divide" and b == 0:
        return "Division by zero"
    try:
        exact = getattr(context, op)(a, b)
    except DecimalOverflow:
        return "Overflow"
    return float(exact) if abs(exact) >= Decimal("1E-99") else 0.0


class Counted:
    """The C routine bound to decimal_arith's, counting the calls its tests left to the routine."""

    def __init__(self, name: str, python):
        self.fallbacks = 0

        def counted(*args):
            self.fallbacks += 1
            return python(*args)
        self.routine = fast.bound(name, counted)
        self.python = python

    def __call__(self, *args):
        try:
            return self.routine(*args)
        except BasicError as error:
            return error.args[0] if error.args else str(error)


def outcome(function, *args):
    try:
        return function(*args)
    except BasicError as error:
        return error.args[0] if error.args else str(error)


ROUTINES = {"add": decimal_arith.add, "subtract": decimal_arith.subtract, "multiply": decimal_arith.multiply,
            "divide": decimal_arith.divide}


def check(op: str, counted: Counted, a: Decimal, b: Decimal) -> None:
    assert len(a.normalize().as_tuple().digits) <= 12 and len(b.normalize().as_tuple().digits) <= 12
    x, y = float(a), float(b)
    got = counted(x, y)
    want = reference(op, a, b)
    assert got == want and type(got) is type(want), (op, a, b, got, want)  # (0.0 == -0.0: the Casio has one 0)
    assert repr(got) == repr(outcome(ROUTINES[op], x, y)), (op, a, b)  # bit for bit, a zero's sign too


def decimal_of(mantissa: int, exponent: int, negative: bool = False) -> Decimal | None:
    """``mantissa`` (at most 12 digits) times 10**``exponent`` inside the range, else None."""
    value = Decimal(mantissa).scaleb(exponent)
    if negative:
        value = -value
    if value and not Decimal("1E-99") <= abs(value) < Decimal("1E100"):
        return None
    return value


MANTISSAS = st.one_of(
    st.integers(1, 10 ** 12 - 1),
    st.sampled_from([1, 5, 25, 125, 999999999999, 999999999995, 100000000001, 500000000000, 123456789012,
                     999999999999 // 3, 10 ** 11, 10 ** 11 - 1, 10 ** 11 + 1, 15, 35, 333333333333]),
)
EXPONENTS = st.one_of(st.integers(-20, 12), st.integers(-110, 99))


@st.composite
def decimals(draw):
    while True:
        value = decimal_of(draw(MANTISSAS), draw(EXPONENTS), draw(st.booleans()))
        if value is not None:
            return value


@st.composite
def related(draw):
    """(a, b): independent, or b one or two decades below a with a 5 (ties of a sum), b a
    neighbour of a (cancellation), b a small multiple of 1/2 (ties of a product)."""
    a = draw(decimals())
    kind = draw(st.integers(0, 3))
    if kind == 0:
        return a, draw(decimals())
    if kind == 1:
        shift = draw(st.integers(1, 3))
        b = decimal_of(draw(st.integers(1, 10 ** 12 - 1)) // 10 * 10 + 5, a.adjusted() - 11 - shift + 1,
                       draw(st.booleans()))
    elif kind == 2:
        try:
            b = REFERENCE.plus(a + draw(st.integers(-3, 3)) * Decimal(1).scaleb(a.adjusted() - 11))  # (12 digits)
        except DecimalOverflow:  # a neighbour of 9.99999999999E99 beyond the reference's range
            b = a
        b = b if b == 0 or Decimal("1E-99") <= abs(b) < Decimal("1E100") else a
    else:
        b = draw(st.sampled_from([Decimal("0.5"), Decimal(5), Decimal("2.5"), Decimal("0.25"), Decimal("1.5"),
                                  Decimal("0.2"), Decimal(8), Decimal(3), Decimal("0.1")]))
    return a, (b if b is not None else a)


@pytest.mark.parametrize("op", OPERATIONS)
@settings(max_examples=1500, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(pair=related())
def test_operation_is_the_decimal_modules_and_the_routines(op, pair):
    a, b = pair
    counted = Counted(op, ROUTINES[op])
    check(op, counted, a, b)
    check(op, counted, b, a)


def sweep(op: str, seed: int, count: int):
    """(the share of results from 1E-11 to below 1E+12 in size that the C tests left to the
    routine, the ties met) over a seeded sweep of the kinds :func:`related` draws, checking each
    result, mostly in the decades the C tests take."""
    rng = random.Random(seed)
    counted = Counted(op, ROUTINES[op])
    ties = reached = missed = 0
    for _ in range(count):
        e = rng.randint(-14, 13) if rng.random() < 0.9 else rng.randint(-105, 99)
        a = decimal_of(rng.randint(1, 10 ** 12 - 1) if rng.random() < 0.8 else rng.choice([1, 10 ** 12 - 1, 5]),
                       e - 11, rng.random() < 0.3)
        kind = rng.randint(0, 3)
        if a is None:
            continue
        if kind == 0:
            b = decimal_of(rng.randint(1, 10 ** 12 - 1), rng.randint(-14, 13) - 11, rng.random() < 0.3)
        elif kind == 1:
            b = decimal_of(rng.randint(1, 10 ** 11) * 10 + 5, a.adjusted() - 11 - rng.randint(1, 3) + 1 - 1,
                           rng.random() < 0.5)
        elif kind == 2:
            b = REFERENCE.plus(a + rng.randint(-3, 3) * Decimal(1).scaleb(a.adjusted() - 11))
        else:
            b = Decimal(rng.choice(["0.5", "5", "2.5", "0.25", "1.5", "0.2", "8", "3", "7", "0.1"]))
        if b is None or (b and not Decimal("1E-99") <= abs(b) < Decimal("1E100")):
            continue
        before = counted.fallbacks
        check(op, counted, a, b)
        want = reference(op, a, b)
        if type(want) is float and 1e-11 <= abs(want) < 1e12:
            reached += 1
            missed += counted.fallbacks - before
        if want != reference(op, a, b, EVEN):
            ties += 1
    return missed / reached, ties


@pytest.mark.parametrize("op", OPERATIONS)
def test_a_sweep_settles_most_in_c_and_meets_ties(op):
    missed, ties = sweep(op, 22, 20000)
    # (the ties and a difference of neighbours, cancelling beyond the guard, take the routine: a
    # quarter of the subtractions are of neighbours)
    assert missed < (0.3 if op == "subtract" else 0.15), missed
    assert ties > (20 if op != "divide" else 0)  # half up, not half to even, decided there


def test_edges_of_the_decades_and_the_range():
    values = [Decimal(1).scaleb(e) for e in range(-99, 100)]
    values += [Decimal(10 ** 12 - 1).scaleb(e - 11) for e in range(-99, 100)]
    values += [Decimal("9.99999999999E99"), Decimal("1E-99"), Decimal("5E-100") * 2, Decimal("0.1"),
               Decimal("0.3"), Decimal("0.7"), Decimal(3), Decimal(0)]
    values = [v for v in values if v == 0 or Decimal("1E-99") <= abs(v) < Decimal("1E100")]
    for op in OPERATIONS:
        counted = Counted(op, ROUTINES[op])
        for a in values:
            for b in (Decimal(1), Decimal("0.1"), Decimal(3), Decimal("-7"), Decimal("1E-11"), Decimal("1E11"),
                      Decimal(10 ** 12 - 1), Decimal("9.99999999999E99"), Decimal("1E-99"), Decimal(0), a):
                check(op, counted, a, b)
                check(op, counted, -a, b)


def test_operands_that_are_not_floats_take_the_routine():
    counted = Counted("add", decimal_arith.add)
    assert counted(1, 2.5) == 3.5 and counted.fallbacks == 1
    assert counted(0.1, 0.2) == 0.3 and counted.fallbacks == 1


# ------------------------------------------------------------------ SQR LN LOG EXP and RND sums

def own_decimal(x: float) -> float:
    return float(format(x, ".12g"))


FUNCTIONS = {"sqrt": decimal_arith.sqrt, "log": decimal_arith.log, "log10": decimal_arith.log10,
             "exp": decimal_arith.exp}


@pytest.mark.parametrize("name", FUNCTIONS)
def test_function_is_mpmaths_rounding_and_the_routines(name):
    from test_decimal_calls import reference as mp_reference

    rng = random.Random(name)
    counted = Counted(name, FUNCTIONS[name])
    values = [own_decimal(rng.uniform(1, 10) * 10.0 ** rng.randint(-30, 30)) for _ in range(1500)]
    if name == "exp":
        values = [own_decimal(rng.uniform(-25, 25)) for _ in range(1500)] + [float(k) for k in range(-30, 31)]
    values += [float(k * k) for k in range(1, 200)] + [own_decimal(1 + k * 1e-11) for k in range(-40, 40)]
    values += [10.0 ** k for k in range(-20, 21)] + [1e-99, 9.99999999999e99, 0.0, -1.0, -4.0]
    for x in values:
        got = counted(x)
        want = outcome(FUNCTIONS[name], x)
        assert repr(got) == repr(want), (name, x)
        if type(want) is float and (name != "exp" or abs(x) <= 200):
            assert got == mp_reference("_" + name, x), (name, x)
    assert counted.fallbacks < len(values) * 0.3


def test_drawn_sum_is_the_sum_with_the_rounded_number():
    rng = random.Random(5)
    counted = Counted("drawn_sum", decimal_fast.drawn_sum(decimal_arith.add, decimal_arith.rounded))
    locals_ = [0.0, -0.0, 1.0, 999.0, 1000.0, 123.456789012, -5.5, 1e-12, 1e9, 99999999999.0, 1e12,
               -999999999999.0, 0.999999999999]
    reached = missed = 0
    for _ in range(30000):
        a = rng.choice(locals_) if rng.random() < 0.2 else own_decimal(rng.uniform(-1, 1) * 10.0 ** rng.randint(-3, 12))
        v = rng.random() if rng.random() < 0.9 else rng.randint(0, 8191) / 8192
        before = counted.fallbacks
        got = counted(a, v)
        want = reference("add", Decimal(format(a, ".12g")), Decimal(format(v, ".12g")))
        assert got == want, (a, v)
        assert repr(got) == repr(decimal_arith.add(a, decimal_arith.rounded(v))), (a, v)
        if 100 <= abs(want) < 1e12:  # (below 100 the scale would pass DRAWN_SCALE: the routine)
            reached += 1
            missed += counted.fallbacks - before
    assert missed < reached * 0.02, (missed, reached)


# ------------------------------------------------------------------ the compiled code

def test_the_compiled_code_calls_the_routines():
    from yaseer.basic.compile.number_models import number_model
    from yaseer.basic.dialects.dialect import CASIO

    model = number_model(CASIO.with_arithmetic("decimal"))
    assert model.accelerated
    assert model.arithmetic("*", "n_A", "n", "0.1", "n")[0] == "_zcmul(n_A, 0.1)"
    assert model.call("SQR", "_sqrt", ["n_A"], ["n"], "n")[0] == "_zcsqrt(n_A)"
    assert model.arithmetic("+", "n_K", "n", "1.0", "n")[0] == "_zcadd(n_K, 1.0)"  # (a call costs less than a test)
    chain = model.arithmetic("*", model.arithmetic("/", "n_K", "n", "2.0", "n")[0], "n", "3.0", "n")[0]
    assert chain.startswith("(((n_K / 2.0) * 3.0) if ")  # (one test saves two calls)
    assert not model.cache_bases


def test_without_the_module_the_inline_caches(monkeypatch):
    from yaseer.basic.compile.number_models import number_model
    from yaseer.basic.dialects.dialect import CASIO

    monkeypatch.setenv("YASEER_PURE_PYTHON", "1")
    model = number_model(CASIO.with_arithmetic("decimal"))
    assert not model.accelerated and "_zd(" in model.arithmetic("*", "n_A", "n", "n_B", "n")[0]


def test_the_cache_key_tells_the_two_apart(monkeypatch, tmp_path):
    from yaseer.basic.compile import program_cache
    from yaseer.basic.dialects.dialect import CASIO

    monkeypatch.setenv("YASEER_CACHE_DIR", str(tmp_path))
    dialect = CASIO.with_arithmetic("decimal")
    with_c = program_cache.key(0, {10: "A=B*C"}, (), dialect)
    monkeypatch.setenv("YASEER_PURE_PYTHON", "1")
    inline = program_cache.key(0, {10: "A=B*C"}, (), dialect)
    assert with_c and inline and with_c != inline


def test_ahls_chains_through_the_machine(monkeypatch):
    from test_decimal_chains import AHL_CHAINS, chain_reference
    from test_decimal_scales import run

    monkeypatch.setenv("YASEER_CACHE_DIR", "")
    _, machine = run(AHL_CHAINS)
    assert [repr(v) for row in machine.arrays["Y"] for v in row] == chain_reference()
