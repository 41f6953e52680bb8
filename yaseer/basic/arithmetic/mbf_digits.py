"""PRINT's digits of a single as GW-BASIC's output routine finds them (a double's:
:mod:`yaseer.basic.arithmetic.mbf_double_using`).

MATH1.ASM ``$FOFMT`` takes 7 digits from MATH2.ASM's ``$FOTNV`` and ``$FOTCV``:

* ``$FOTNV`` brackets the magnitude so that its 7 digits are its integer part.  While
  the table ``$FOTB`` (indexed by the exponent byte) names a power n other than 0, the
  number is made double, multiplied by the table's 10**n (``MDPTEN``: ``$FMULD``; for a
  negative n divided by 10**-n, ``DDIVFA``) and made single again (``$CSD``: its top 24
  bits, rounded up when the 25th is 1).  The table brings it to 2**19 .. 2**23; below
  10**6 it is multiplied by 10 in single precision (``$MUL10`` -> ``$MLSP``: ``$FMULS``).
* ``$FOTCV`` adds .5 (``$FADDH``: ``$FADDS``) unless the number is whole, and cuts the
  fraction (``$QINT``).

So the digits are those of the magnitude rounded twice or three times, not once:
``ATN(1.5)`` prints .9827938 and ``1E38`` 9.999999E+37, where PC-BASIC 2.0.8's
divisions by ten give .9827937 and 1E+38 (about 3% of random singles differ there).
"""

from __future__ import annotations

from math import floor

from yaseer.basic.arithmetic import mbf_double, single_arith
from yaseer.basic.arithmetic.mbf_double_using import field_digits, scientific_field_digits, table_steps

_MILLION = 1000000.0  # $DP06's single part: $FOTNV's lower bound


def bracket(x: float) -> tuple[float, int]:
    """``$FOTNV`` of a nonzero single ``x``: ``(y, power)``, ``y`` a single from 10**6 to
    2**23 (not yet whole) with ``abs(x)`` about ``y * 10**power``."""
    p, power = table_steps(mbf_double.parts(-x if x < 0 else x), mbf_double.single_rounded)
    y = mbf_double.nearest_float(p)  # a single: exact in a float
    if y < _MILLION:
        y = single_arith.product(y * 10.0)  # the exact product of 24 and 4 bits, rounded by $FMULS
        power -= 1
    return y, power


def rounded_whole(y: float) -> int:
    """``$FOTCV``'s whole number of a positive single ``y``: .5 added (``$FADDH``, a
    ``$FADDS``) unless ``y`` is whole, the fraction cut (``$QINT``)."""
    whole = floor(y)
    if whole != y:
        whole = floor(single_arith.add(y, 0.5))
    return whole


def decimal_digits(x: float) -> tuple[int, int]:
    """``(n, power)`` with ``abs(x)`` shown as ``n * 10**power``, ``n`` of 7 digits (at
    most 8388608: the bracket stays below 2**23), for a nonzero single ``x``."""
    y, power = bracket(x)
    return rounded_whole(y), power


def digit_string(x: float) -> tuple[str, int]:
    """:func:`decimal_digits` as PRINT uses them: (the digits without trailing zeros,
    the decimal exponent of the first digit)."""
    n, power = decimal_digits(x)
    shown = str(n)
    return shown.rstrip("0") or "0", power + len(shown) - 1


# PRINT USING (MATH2.ASM $PUF, MATH1.ASM $PUFE) rounds a single where its field ends, not
# its 7 digits: the bracket is divided by ten once per digit the field does not show
# ($DIV10: $MLSP, a $FMULS by the double 0.1 made single by $CSD), then rounded to a whole
# number.  So 1234564.6 shown with one digit fewer is 123456, not 123457 (the 7 digits
# 1234565 rounded again).

TENTH = 0.100000001490116119384765625  # $DPM01 made single ($CSD: 0xCCCCCD * 2**-27)


def _tenths(y: float, times: int) -> float:
    """``$DIV10`` ``times`` times on the single ``y`` > 0, for a caller that then rounds to
    a whole number (``$FOTCV``, or ``$VADDH`` and ``$VINT``): where that rounding is sure,
    the whole number it gives.  Each ``$FMULS`` by :data:`TENTH` is within 0.625 of a unit
    of 2**-23 (7.5e-8) of the exact product and TENTH within 1.5e-8 of 0.1, so the divided
    single is within ``times * 9e-8`` of ``z = y / 10**times``, and adding .5 moves it by at most
    1.2e-7 of the sum: when ``z``'s fraction is farther than ``(z + 1) (times + 2) 1.2e-7``
    from a half, rounding ``z`` gives the same whole number; else the steps are taken."""
    z = y * 10.0 ** -times
    whole = floor(z)
    off = z - whole - 0.5
    bound = (z + 1.0) * (times + 2) * 1.2e-7
    if off > bound:
        return whole + 1.0
    if off < -bound:
        return float(whole)
    for _ in range(times):
        y = single_arith.product(y * TENTH)
    return y


def _half_added_cut(y: float) -> int:
    return floor(single_arith.add(y, 0.5))


def fixed_digits(y: float, power: int, places: int) -> tuple[int, int]:
    """``$PUF``'s digits of a single bracketed as ``(y, power)`` (:func:`bracket`) for a
    fixed field of ``places`` decimals: ``(n, shown)``, the magnitude printed as
    ``n * 10**-shown`` (``shown`` <= ``places``: the field adds zeros)."""
    return field_digits(y, power, places, _tenths, rounded_whole)


def scientific_digits(y: float, power: int, digits: int) -> tuple[int, int]:
    """``$PUFE``'s digits of a single bracketed as ``(y, power)`` for a ``^^^^`` field
    showing ``digits`` (1 .. ) digits: ``(n, power)``, the magnitude printed as
    ``n * 10**power`` with ``n`` below 10**digits.  Fewer than 7: the excess divided off,
    .5 added and the fraction cut (``$VADDH``, ``$VINT``); a carry into a new digit
    divides by ten once more (then ``$FOTCV`` rounds)."""
    return scientific_field_digits(y, power, digits, 7, _tenths, _half_added_cut, rounded_whole, float)
