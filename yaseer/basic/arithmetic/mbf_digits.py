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
from yaseer.basic.arithmetic.mbf_double_using import table_steps

_MILLION = 1000000.0  # $DP06's single part: $FOTNV's lower bound


def decimal_digits(x: float) -> tuple[int, int]:
    """``(n, power)`` with ``abs(x)`` shown as ``n * 10**power``, ``n`` of 7 digits (at
    most 8388608: the bracket stays below 2**23), for a nonzero single ``x``."""
    p, power = table_steps(mbf_double.parts(-x if x < 0 else x), mbf_double.single_rounded)
    y = mbf_double.nearest_float(p)  # a single: exact in a float
    if y < _MILLION:
        y = single_arith.product(y * 10.0)  # the exact product of 24 and 4 bits, rounded by $FMULS
        power -= 1
    whole = floor(y)
    if whole != y:
        whole = floor(single_arith.add(y, 0.5))
    return whole, power


def digit_string(x: float) -> tuple[str, int]:
    """:func:`decimal_digits` as PRINT uses them: (the digits without trailing zeros,
    the decimal exponent of the first digit)."""
    n, power = decimal_digits(x)
    shown = str(n)
    return shown.rstrip("0") or "0", power + len(shown) - 1
