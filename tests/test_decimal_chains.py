"""Chains of ``--arith decimal`` results that leave their decade at every pass (the loops of Ahl's
benchmark from N = 101 to 130: square roots from three decades down to one, squares back up,
their negatives, running sums) against Python's decimal module computing the same chains step by
step with the calculator's context written anew (12 digits, half up), and against the routines
alone: the scale caches' writers (decimal_scales.writers) take every decade change; a writer
keeping a scale one unit off fails the comparison."""

from __future__ import annotations

from decimal import ROUND_HALF_UP, Context, Decimal

from yaseer.basic.arithmetic import decimal_scales
from test_decimal_scales import _results

CONTEXT = Context(prec=12, rounding=ROUND_HALF_UP, Emax=99, Emin=-99)

AHL_CHAINS = """10 DIM Y(29,31): S=0: T=0
20 FOR N=101 TO 130: A=N: P=N-101: K=0
30 FOR I=1 TO 10: A=SQR(A): Y(P,K)=A: K=K+1: NEXT I
40 FOR I=1 TO 10: A=A*A: Y(P,K)=A: K=K+1: B=-A*A: Y(P,K)=B: K=K+1: NEXT I
50 S=S+A: T=T-A*7: Y(P,K)=S: Y(P,K+1)=T
60 NEXT N
"""


def chain_reference() -> list:
    """Y() of :data:`AHL_CHAINS` computed with the decimal module, step by step."""
    values, s, t = [], Decimal(0), Decimal(0)
    for n in range(101, 131):
        a = Decimal(n)
        for _ in range(10):
            a = CONTEXT.sqrt(a)  # (never a tie: a 13-digit root ending in 5 squares to 26 digits)
            values.append(a)
        for _ in range(10):
            a = CONTEXT.multiply(a, a)
            values += [a, CONTEXT.minus(CONTEXT.multiply(a, a))]
        s = CONTEXT.add(s, a)
        t = CONTEXT.subtract(t, CONTEXT.multiply(a, Decimal(7)))
        values += [s, t]
    return [repr(float(v)) for v in values]


def test_chains_across_decades_are_the_decimal_modules(monkeypatch):
    want = chain_reference()
    assert _results(AHL_CHAINS, True, monkeypatch) == want
    assert _results(AHL_CHAINS, False, monkeypatch) == want


def test_a_writer_keeping_a_scale_one_unit_off_is_found(monkeypatch):
    scale = decimal_scales.scale
    monkeypatch.setattr(decimal_scales, "scale", lambda x: scale(x) * (1.0 + 2.0 ** -52))
    assert _results(AHL_CHAINS, True, monkeypatch) != chain_reference()
