"""PRINT's 7 digits of a gw single: a reference built on the GW-BASIC source's steps,
PC-BASIC 2.0.8's own digits, and a shim that makes a PC-BASIC session print the
source's digits where its own are not the source's.

This module holds no tests.

The reference (:func:`source_digits`) redoes MATH1.ASM ``$FOFMT``'s steps on exact
rationals, apart from the code under test (yaseer's mbf_digits works on MBF registers
and floats):

* ``$FOTNV``: while the table ``$FOTB`` names a power n for the exponent byte, the
  single is made double, multiplied by the double nearest 10**n (``MDPTEN``; ``$FMULD``
  rounds the exact product half to even to 56 bits; a negative n divides, ``DDIVFA``,
  rounded so too) and made single by ``$CSD`` (the top 24 bits, up when the 25th is 1);
  below 10**6 it is multiplied by 10 in single precision (``$MUL10`` -> ``$FMULS``: the
  exact 28-bit product, whose guard byte ``$ROUNS`` masks to its top 3 bits and rounds
  by adding 0x80, a carry that leaves 0 being a tie to even);
* ``$FOTCV``: .5 added by ``$FADDS`` unless the number is whole (exact there: the
  number lies in 10**6 .. 2**23, its unit at most 1/2), the fraction cut.

PC-BASIC 2.0.8 divides by ten instead and rounds its guard byte between, so about 3% of
random singles get another 7th digit there (``1E38`` prints 1E+38, the source's steps
9.999999E+37).  :func:`source_single_digits` is the shim that the differential oracle
(test_differential_support.PcBasic) runs PC-BASIC under: a PRINT of a single whose
PC-BASIC digits are the reference's prints PC-BASIC's own text; one whose digits differ
prints the reference's digits in PC-BASIC's layout, and is recorded.
"""

from __future__ import annotations

import functools
import math
from contextlib import contextmanager
from fractions import Fraction

from test_gw_double_using import exponent_byte, r56, scaled_to_bits
from test_gw_single_literals import csd
from yaseer.basic.arithmetic.mbf_double_using import FOTB

SINGLE_DIGITS = 7


def fmuls_by_ten(y: Fraction) -> Fraction:
    """``$FMULS`` of a single ``y`` > 0 by 10: the exact product's 24 bits and guard byte,
    ``$ROUNS``: the guard byte's top 3 bits plus 0x80; a carry rounds up, and a carry
    leaving 0 (a guard byte 0x80..0x9F) makes the mantissa even."""
    scaled, scale = scaled_to_bits(y * 10, 24)
    whole = math.floor(scaled)
    guard = math.floor((scaled - whole) * 256) & 0xE0
    if guard > 0x80 or (guard == 0x80 and whole % 2):
        whole += 1
    return whole / scale


@functools.lru_cache(maxsize=None)
def table_power(n: int) -> Fraction:
    """The table's 10**n (``$DP00`` ..): the double nearest it."""
    return r56(Fraction(10) ** n)


def source_bracket(x: Fraction) -> tuple[Fraction, int]:
    """``$FOTNV`` of the single ``x`` > 0 by the source's steps (module docstring):
    ``(y, power)``, ``y`` a single from 10**6 to 2**23, ``x`` about ``y * 10**power``."""
    power = 0
    while FOTB[exponent_byte(x)]:
        n = FOTB[exponent_byte(x)]
        power -= n
        x = csd(r56(x * table_power(n)) if n > 0 else r56(x / table_power(-n)))
    if x < 10 ** 6:
        x, power = fmuls_by_ten(x), power - 1
    return x, power


def source_digits(x: Fraction) -> tuple[int, int]:
    """``(n, power)``: PRINT shows the single ``x`` > 0 as the 7 digits of ``n`` times
    ``10**power`` by the source's steps (module docstring)."""
    x, power = source_bracket(x)
    if x.denominator != 1:
        x = x + Fraction(1, 2)
    return math.floor(x), power


@functools.lru_cache(maxsize=None)
def _pc_values():
    from pcbasic.basic.values import values

    return values.Values(None, False)


def pc_single(x: float):
    """PC-BASIC's Single holding the single ``x`` (nonzero) exactly, from its MBF bytes."""
    from pcbasic.basic.values import numbers

    m, e = math.frexp(abs(x))
    mantissa = int(m * 2 ** 24)
    bits = (mantissa & 0x7FFFFF) | ((x < 0) << 23)
    data = bytes([bits & 255, (bits >> 8) & 255, bits >> 16, e + 128])
    return numbers.Single(None, _pc_values()).from_bytes(data)


def pc_digits(x: float) -> tuple[int, int]:
    """PC-BASIC 2.0.8's 7 digits of the single ``x`` (nonzero): ``(n, power)`` of its magnitude."""
    n, power = pc_single(x).to_decimal(SINGLE_DIGITS)
    return abs(n), power


def pc_prints_the_source(x: float) -> bool:
    """Are PC-BASIC's 7 digits of the single ``x`` those of the source's steps?"""
    return not x or pc_digits(x) == source_digits(abs(Fraction(x)))


@contextmanager
def source_single_digits(differing: list | None = None):
    """PC-BASIC's singles print the source's 7 digits while the block runs: its
    ``Single.to_decimal`` for 7 digits (PRINT, STR$, WRITE, a PRINT USING field's first
    step) returns its own digits where they are the reference's, else the reference's,
    appending ``(value, PC-BASIC's, the source's)`` to ``differing``.  Fewer digits (a
    PRINT USING field's rounding) stay PC-BASIC's."""
    from pcbasic.basic.values import numbers

    own = numbers.Single.to_decimal
    had_own = "to_decimal" in vars(numbers.Single)

    def to_decimal(self, digits):
        theirs = own(self, digits)
        if digits < self.digits or self.is_zero():
            return theirs
        value = self.to_value()
        n, power = source_digits(abs(Fraction(value)))
        if (abs(theirs[0]), theirs[1]) == (n, power):
            return theirs
        if differing is not None:
            differing.append((value, theirs, (n, power)))
        return (-n if value < 0 else n), power

    numbers.Single.to_decimal = to_decimal
    try:
        yield
    finally:
        if had_own:
            numbers.Single.to_decimal = own
        else:
            del numbers.Single.to_decimal


class SourceDigitsSession:
    """A ``pcbasic.Session`` whose ``execute`` runs under :func:`source_single_digits`
    (for tests that drive a session of their own); everything else is the session's."""

    def __init__(self, session) -> None:
        self._session = session

    def execute(self, text):
        with source_single_digits():
            return self._session.execute(text)

    def __getattr__(self, name):
        return getattr(self._session, name)
