"""The binade caches of the compiled code's single-precision operations.

A single result is cheap to round when its binade is known: inside ``[T, 2T)`` (T a
power of two) the nearest single of a double ``v`` is ``(v + M) - M`` with the "magic"
number ``M = 1.5 * 2**52 * u`` (``u = T * 2**-23``, the single's unit there: ``v + M``
lies in the binade of ``M``, whose unit is ``u``, and the sum is rounded half to even).
So the compiled code (number_models.py) keeps, for each ``+ - * /`` of singles it writes,
the constants of the binade its last result had, in five globals of the area's namespace
(``BASE`` plus ``h l m n k``): the bounds ``l <= v < h`` of the values they hold for, the
magic number ``m``, and the band ``n < v - (nearest) < k`` outside which the nearest single
is GW's result (module single_arith: a product's 28-bit rounding, a sum's carry).  A
result outside the bounds or the band takes the operation's general code, and then a
writer here sets the constants for that result's binade.

What a cached binade promises (each writer's docstring): its results lie inside MBF's
range, and a result of the fast path is the one GW-BASIC's routine gives.  The bounds
are written last and cleared first, so an interrupted writer leaves a cache that
matches nothing; a cache that does not fit the value only costs the general code.
"""

from __future__ import annotations

from math import frexp, inf, ldexp, nextafter

from yaseer.basic.arithmetic.single_arith import TINY

_MAGIC = 1.5 * 2.0 ** 52
_UNIT = 2.0 ** -23  # a single's unit over the leading power of two of its binade
_EXACT_ONLY = 5e-324  # the least double: -it < d < it only for d = 0


def _binade(value: float, highest: float) -> float | None:
    """The leading power of two ``T`` of ``value``'s binade, where ``T`` is from 2**-128 (MBF's
    least single) to ``highest``; else None (also for 0, infinities and NaN)."""
    if value != value or not value:
        return None
    top = ldexp(1.0, frexp(value)[1] - 1)
    return top if TINY <= top <= highest else None


def _signed_bounds(value: float, low: float, high: float) -> tuple[float, float]:
    """The bounds ``(l, h)`` of the magnitudes ``low <= |v| < high`` for values ``v`` of
    ``value``'s sign, written as ``l <= v < h``."""
    if value > 0:
        return low, high
    return nextafter(-high, 0.0), nextafter(-low, 0.0)


def sum_group(s: float, constant: float | None) -> tuple | None:
    """The cache of a ``+`` or ``-`` of two singles for the exact sum ``s`` (a double), or None.

    Its bounds hold the magnitudes from ``T`` to ``2T - u`` (leaving out the binade's
    largest single: ``$FADDS`` gives the power of two above it where the operands are
    that power and less than half its unit of the other sign, exponents 25 or more apart,
    single_arith.add), ``T`` up to 2**126 (no rounding leaves MBF's range).  In it an
    exact sum (a multiple of ``u``) is GW's, and so is the nearest single of a sum of two
    magnitudes of one sign outside the band: rounded up by 3/8 to 1/2 of a unit (where a
    carry's shift drops the sticky bit, single_arith.add).  The compiled code tests the
    signs (and takes any rounding where an operand lies in the bounds: no carry), unless
    one operand is a literal whose contribution (``constant``: its value, negated when
    subtracted) is given: then the other operand's sign and size follow from the sum's:

    * the constant of the sum's sign, at most ``T`` in size: the other operand lies in the
      sum's binade for sums from ``T + |constant|`` up (the bounds start there), so no
      carry came and any rounding is GW's (a band every nearest single is inside);
    * of the other sign, at most ``T``: the other operand is ``|constant|`` larger than the
      sum, in its binade for sums below ``2T - |constant|`` (the bounds end there), a
      difference with no normalising shift, GW's unless rounded up by more than ``u/4``;
    * else (the other operand's sign or binade unknown) a band that holds exact sums only."""
    top = _binade(s, 2.0 ** 126)
    if top is None:
        return None
    unit = top * _UNIT
    low, high = top, 2.0 * top - unit
    if constant is None:
        n, k = nextafter(-0.375 * unit, -inf), 0.5 * unit
    else:
        size = constant if constant > 0 else -constant
        if size > top:
            n, k = -_EXACT_ONLY, _EXACT_ONLY
        elif (constant > 0) == (s > 0):
            low = top + size
            if low - top < size:  # (the double sum rounded down: the next double up)
                low = nextafter(low, inf)
            n, k = -unit, unit
        else:
            end = 2.0 * top - size
            if 2.0 * top - end < size:  # (the double difference rounded up: the next double down)
                end = nextafter(end, -inf)
            high = min(high, end)
            n, k = nextafter(-0.25 * unit, -inf), 0.5 * unit
        if not low < high:
            return None
    if s < 0:
        n, k = -k, -n
    low, high = _signed_bounds(s, low, high)
    return high, low, _MAGIC * unit, n, k


def product_group(p: float) -> tuple | None:
    """The cache of a ``*`` of two singles for their exact product ``p``, or None: magnitudes
    from ``T`` to ``2T`` (``T`` up to 2**125: a product rounded up to ``2T`` stays in the
    range).  ``$FMULS`` gives the nearest single unless ``p`` lies from 1/2 to 5/8 of a unit
    above the single below it (single_arith.product): the band is the distance from the
    nearest single, signed toward zero, from -3/8 (included) to 1/2 of a unit; a product in
    the bounds outside it is the compiled code's single_arith.product_near_half."""
    top = _binade(p, 2.0 ** 125)
    if top is None:
        return None
    unit = top * _UNIT
    low, high = _signed_bounds(p, top, 2.0 * top)
    # (3/8 of a unit beyond p is still the nearest: the band's bound there is the double past it)
    if p > 0:
        return high, low, _MAGIC * unit, nextafter(-0.375 * unit, -inf), 0.5 * unit
    return high, low, _MAGIC * unit, -0.5 * unit, nextafter(0.375 * unit, inf)


def quotient_group(q: float) -> tuple | None:
    """The cache of a ``/`` of two singles for the double quotient ``q``, or None: magnitudes
    from ``T`` to ``2T``, ``T`` up to 2**125.  ``$FDIVS`` gives the nearest single, and the
    double is never half-way between two singles (single_arith.divide): no band."""
    top = _binade(q, 2.0 ** 125)
    if top is None:
        return None
    unit = top * _UNIT
    low, high = _signed_bounds(q, top, 2.0 * top)
    return high, low, _MAGIC * unit, 0.0, 0.0


def writers(namespace: dict) -> dict:
    """The compiled code's ``_zws(base, s, constant, result)``, ``_zwp(base, p, result)`` and
    ``_zwq(base, q, result)``: set the cache ``base`` in ``namespace`` for the value (see the
    groups above; none: a cache that matches nothing) and give ``result`` back."""

    def remember(base: str, group) -> None:
        namespace[base + "h"] = -inf  # matches nothing until the whole group is written
        if group is not None:
            high, low, magic, band_low, band_high = group
            namespace[base + "l"] = low
            namespace[base + "m"] = magic
            namespace[base + "n"] = band_low
            namespace[base + "k"] = band_high
            namespace[base + "h"] = high

    def sum_written(base, s, constant, result):
        if not s < namespace[base + "h"] or not s >= namespace[base + "l"]:  # (else: a sum outside the band)
            remember(base, sum_group(s, constant))
        return result

    def product_written(base, p, result):
        remember(base, product_group(p))
        return result

    def quotient_written(base, q, result):
        remember(base, quotient_group(q))
        return result

    return {"_zws": sum_written, "_zwp": product_written, "_zwq": quotient_written}
