"""The compiled single ``+ - * /`` through their binade caches (arithmetic/binade_cache.py)
give what single_arith's routines give, bit for bit, over many operands that hit a cache,
miss it, change binade, sit on a binade's edges or near half a unit.

Each operation is compiled by the gw number model into a Python function and called in one
namespace for a whole sequence of operands, so the caches carry from call to call as in a
loop; the reference for ``+ -`` is tests/fadds_reference.py (``$FADDS``'s registers), for
``* /`` single_arith (``multiply``, ``divide``: ``$FMULS``, ``$FDIVS``, compared with PC-BASIC elsewhere), with an overflow
giving the signed largest single as GW's continuing policy does.
"""

from __future__ import annotations

import random
from math import inf, ldexp, nextafter

import fadds_reference
import pytest

from yaseer.basic.arithmetic import arith_policy, binade_cache, single_arith, values
from yaseer.basic.compile.number_models import TypedNumbers

LARGEST = single_arith.LARGEST


class _Continuing:
    """GW's policy without a screen: the signed largest single (division by zero too)."""

    def result(self, code, negative=False, kind="!"):
        return -LARGEST if negative else LARGEST


def _compiled(source: str, operands: str = "n_A, n_B", inline: bool = True, caching: bool = True):
    """``source`` (an expression over n_A and n_B) as a function, in a namespace with the
    compiled code's helpers and the caches' first values (``inline``, ``caching``: the
    number model's switches: tests inline, binade caches)."""
    numbers = TypedNumbers()
    numbers.site_salt = "x"
    numbers.tests_inline = inline
    numbers.caching = caching
    left, op, right = source.split(" ")
    code = numbers._single(op, left, right)
    namespace = {"__builtins__": {"type": type, "abs": abs, "float": float}}
    namespace.update(values.RUNTIME)
    namespace.update(arith_policy.helpers(_Continuing(), None, None, None))
    namespace.update(binade_cache.writers(namespace))
    for base in numbers.cache_bases:
        namespace[base + "h"] = -inf
    exec(f"def f({operands}):\n    return {code}\n", namespace)
    return namespace["f"], code


def _reference(op: str, a: float, b: float) -> float:
    """single_arith's routine; for a sum of two singles in MBF's range the tests' own
    transcription of $FADDS's registers."""
    routines = {"+": single_arith.add, "-": single_arith.subtract, "/": single_arith.divide,
                "*": single_arith.multiply}
    if op in "+-" and fadds_reference.is_single(a) and fadds_reference.is_single(b):
        routines = {"+": fadds_reference.add, "-": fadds_reference.subtract}
    r = routines[op](a, b)
    return r if r - r == 0 else (-LARGEST if r < 0 else LARGEST)


def _single(rng: random.Random, exponent: int) -> float:
    """A random single of about 2**exponent, either sign; often few bits or all ones."""
    kind = rng.random()
    if kind < 0.15:
        mantissa = rng.choice((1 << 23, (1 << 24) - 1, (1 << 23) + 1, 3 << 22))
    elif kind < 0.35:
        mantissa = rng.randrange(1, 1 << 8) << 16 | (1 << 23)
    else:
        mantissa = rng.randrange(1 << 23, 1 << 24)
    value = ldexp(mantissa, exponent - 23)
    return -value if rng.random() < 0.3 else value


def _operands(rng: random.Random, count: int):
    """Pairs in runs: one binade for a while (the cache hits), then a jump; exponents near
    each other (carries, cancellation, half a unit apart) and far apart, near MBF's ends."""
    pairs = []
    while len(pairs) < count:
        base = rng.choice((rng.randrange(-20, 21), rng.randrange(-127, 127), -126, 124, 125, 126))
        spread = rng.choice((0, 1, 3, 8, 25, 30))
        for _ in range(rng.randrange(1, 60)):
            a = _single(rng, base)
            b = _single(rng, max(-128, min(126, base - rng.randrange(0, spread + 1))))
            if rng.random() < 0.05:  # a power of two and half its unit, of the other sign
                a = ldexp(1.0, base)
                b = -ldexp(1.0, base - 24)
            elif rng.random() < 0.05 and base < 126:  # a carry that shifts out a 1 below a guard byte 0x80
                top = rng.randrange((1 << 24) - (1 << 15), 1 << 24)
                low = (rng.randrange(1 << 23, 1 << 24) & ~0x1FF) | ((0x101 - ((top & 1) << 8)) & 0x1FF)
                a, b = ldexp(top, base - 23), ldexp(low, base - 31)
                if rng.random() < 0.5:
                    a, b = -a, -b
            pairs.append((a, b) if rng.random() < 0.5 else (b, a))
    return pairs[:count]


@pytest.mark.parametrize("source", ["n_A + n_B", "n_A - n_B", "n_A * n_B", "n_A / n_B"])
def test_cached_operation_is_single_arith_bit_for_bit(source):
    rng = random.Random(source)
    f, code = _compiled(source)
    assert "_Z" in code  # (the cached form was written)
    op = source.split(" ")[1]
    pairs = _operands(rng, 60000)
    # a walk: each result the next left operand (as in A=A+B), where it stays in the range
    a = 1.0
    for _, b in pairs[:20000]:
        pairs.append((a, b))
        r = _reference(op, a, b)
        a = r if 2.0 ** -100 < abs(r) < 2.0 ** 100 else _single(rng, 0)
    wrong = []
    for a, b in pairs:
        if op == "/" and not b:
            continue
        got, want = f(a, b), _reference(op, a, b)
        if got != want or (got == 0 and want == 0 and str(got) != str(want)):
            wrong.append((a, b, got, want))
    assert not wrong[:5], f"{len(wrong)} of {len(pairs)} differ"


@pytest.mark.parametrize("source", ["n_A + 0.10000000149011612", "n_A - 0.10000000149011612",
                                    "0.10000000149011612 - n_A", "n_A + -3.0", "n_A - 1.0", "n_A * 1.100000023841858",
                                    "n_A / 3.0", "n_A / -7.0", "n_A / 0.10000000149011612", "n_A + 0.0"])
def test_cached_operation_with_a_literal(source):
    rng = random.Random(source)
    f, code = _compiled(source, "n_A")
    left, op, right = source.split(" ")
    literal = float(right) if left == "n_A" else float(left)
    values = []
    a = 0.0
    for _ in range(40000):  # walks (accumulations) and jumps
        if rng.random() < 0.02:
            a = _single(rng, rng.randrange(-30, 30))
        values.append(a)
        a = _reference(op, a, literal) if left == "n_A" else _reference(op, literal, a)
        if not 2.0 ** -100 < abs(a) < 2.0 ** 100:
            a = _single(rng, 0)
    values += [_single(rng, e) for e in range(-128, 127) for _ in range(20)]
    values += [ldexp(1.0, e) + d for e in range(-10, 10) for d in (0.0, ldexp(1.0, e - 24), -ldexp(1.0, e - 24))]
    wrong = []
    for a in values:
        got = f(a)
        want = _reference(op, a, literal) if left == "n_A" else _reference(op, literal, a)
        if got != want:
            wrong.append((a, got, want))
    assert not wrong[:5], f"{len(wrong)} of {len(values)} differ"


def test_a_cache_is_only_for_its_binade():
    """The groups' bounds: a sum's leave out the binade's largest single; a literal's sign
    and size bound a sum's; nothing near the top of the range or below its bottom."""
    high, low, magic, band_low, band_high = binade_cache.sum_group(1.5, None)
    unit = 2.0 ** -23
    assert (low, high) == (1.0, 2.0 - unit)
    # $FADDS: after a carry, a sum rounded up by 3/8 to 1/2 of a unit is GW's tie (half to even)
    assert band_low == nextafter(-0.375 * unit, -inf) and band_high == 0.5 * unit
    assert (1.75 + magic) - magic == 1.75 and (1.0 + 2.0 ** -25 + magic) - magic == 1.0
    high, low, *_ = binade_cache.sum_group(-1.5, None)
    assert low <= -1.0 < high and not low <= -(2.0 - 2.0 ** -23) and low <= -(2.0 - 2.0 ** -22)
    # a literal of the sum's sign: the other operand in the sum's binade from 1 + .1 up, no carry
    high, low, magic, band_low, band_high = binade_cache.sum_group(1.5, 0.1)
    assert (low, high) == (1.1, 2.0 - unit) and (band_low, band_high) == (-unit, unit)
    # of the other sign: the other operand .1 larger, in the binade below 2 - .1, no normalising shift
    high, low, magic, band_low, band_high = binade_cache.sum_group(1.5, -0.1)
    assert (low, high) == (1.0, 1.9) and band_low == nextafter(-0.25 * unit, -inf) and band_high == 0.5 * unit
    assert binade_cache.sum_group(1.5, 3.0)[4] == 5e-324  # it could be either
    assert binade_cache.sum_group(2.0 ** 126 * 1.5, None) is not None
    assert binade_cache.sum_group(2.0 ** 127, None) is None
    assert binade_cache.product_group(2.0 ** 126) is None and binade_cache.quotient_group(2.0 ** 126) is None
    assert binade_cache.sum_group(2.0 ** -129, None) is None and binade_cache.sum_group(0.0, None) is None


def test_a_large_area_goes_without_caches(monkeypatch, tmp_path):
    """Beyond compiler.CACHED_CODE_LIMIT characters an area is compiled again without the
    caches (they add about a third to the code), and computes the same."""
    from yaseer.basic.compile import compiler
    from yaseer.basic.machine.machine import Machine
    import io

    program = "10 A=1.5: FOR I=1 TO 300: A=A*1.0001+I/3-.1: NEXT: PRINT A\n"
    printed = []
    for limit in (compiler.CACHED_CODE_LIMIT, 100):
        monkeypatch.setattr(compiler, "CACHED_CODE_LIMIT", limit)
        monkeypatch.setenv("YASEER_CACHE_DIR", str(tmp_path / str(limit)))  # (no compiled program kept)
        screen = io.StringIO()
        machine = Machine(screen=screen, dialect="gw")
        machine.load(program)
        machine.run()
        printed.append(screen.getvalue())
        assert ("_zws(" in machine.compiled[0].source) == (limit > 100)
    assert printed[0] == printed[1] and printed[0].strip()
