"""GW-BASIC's single-precision polynomial steps on floats (the fast path of
gw_transcendental.py's ``$POLY``).

``$POLY`` evaluates Horner's rule from the highest coefficient, each step a
``$FMULS`` and a ``$FADDS`` (single_arith.product and single_arith.add give their
roundings).  Here each step is a few exact float64 operations and a cheap rounding:

* ``$FMULS``: the product of two singles is exact in a double; Veltkamp's split
  gives its nearest single, which is GW's result outside a band of 1/8 of a unit
  (single_arith.product); inside it, single_arith.product_near_half.
* ``$FADDS`` of the product ``P`` and the coefficient ``c`` where ``|P| < |c|`` (the
  usual case: each coefficient is larger than the product added to it), with the
  coefficient's constants computed once (:func:`plan`): its unit ``u`` and "magic"
  numbers ``1.5 * 2**52 * q`` whose sum with a value rounds it half to even to a
  multiple of ``q``.  The exact sum rounded so is GW's result where single_arith.add's
  fast paths show it is: of one sign, without a carry (rounded at ``u``), or after one
  (at ``2u``) unless it rounds up by more than 3/8 of ``2u``; of two signs, a difference
  that keeps the coefficient's binade unless it rounds up by more than ``u/4``.
* A product larger than the coefficient (the usual case in LOG's polynomials) takes the
  same steps in the product's binade: its leading power of two found by the ufp of
  Rump, Ogita and Oishi, the magic numbers of its unit and twice it.
* Every other case (a product as large as the coefficient or 2**29 times larger, a sum
  near those bounds, a difference that leaves the binade) is single_arith.add itself: the
  results are the same by construction.

The caller keeps the argument where no step can leave MBF's range (``x`` at least
:data:`LEAST_ARGUMENT`, at most 1, coefficients below 100 in size).
"""

from __future__ import annotations

from math import frexp, ldexp

from yaseer.basic.arithmetic.single_arith import add, product, product_near_half

LEAST_ARGUMENT = 2.0 ** -60  # below it the caller takes the integer steps (products leave the range)
_SPLIT = 536870913.0  # 2**29 + 1: Veltkamp's split to 24 bits (the nearest single)
_UFP = 4503599627370497.0  # 2**52 + 1: q - (1 - 2**-53) * q is the leading power of two of p (q = p * _UFP)
_UFP_LOW = 0.9999999999999999
_MAGIC = 1.5 * 2.0 ** 52  # (v + _MAGIC * q) - _MAGIC * q: v rounded half to even to a multiple of q
# $FMULS's result is the nearest single where p's distance below it, over p's leading power
# of two, lies in [-3/8, 1/2) units of 2**-23 (single_arith.product)
_PRODUCT_LOW, _PRODUCT_HIGH = -0.375 * 2.0 ** -23, 0.5 * 2.0 ** -23
# times a leading power of two T: the magic numbers of its unit u = T * 2**-23 and of 2u, and the carry's band
_HALF_MAGIC = _MAGIC * 2.0 ** -23
_MAGIC_2U = _MAGIC * 2.0 ** -22
_CARRIED = 0.75 * 2.0 ** -23  # a sum after a carry rounded up by more than 3/8 of 2u: single_arith.add
_QUARTER = 0.25 * 2.0 ** -23  # a difference rounded up by more than u/4: single_arith.add


def _coefficient_plan(c: float) -> tuple:
    """The constants of one ``$FADDS`` with the coefficient ``c`` (nonzero), see the module
    docstring: (c, |c|, c < 0, c > 0, its leading power of two U, 2U, 4U, its unit u, the
    magic numbers of u and 2u, and the bounds 3/4 u and 1/4 u of a rounding up)."""
    size = abs(c)
    top = ldexp(1.0, frexp(size)[1] - 1)
    unit = top * 2.0 ** -23
    return (c, size, c < 0, c > 0, top, 2.0 * top, 4.0 * top, unit, _MAGIC * unit, _MAGIC * 2.0 * unit,
            0.75 * unit, 0.25 * unit)


def plan(coefficients) -> tuple:
    """A polynomial's single coefficients (highest power first) for :func:`poly`."""
    return coefficients[0], tuple(_coefficient_plan(c) for c in coefficients[1:])


def fmuls(p: float) -> float:
    """``$FMULS`` of the exact product ``p`` of two singles (nonzero, well inside MBF's range)."""
    split = p * _SPLIT
    cut = split - (split - p)
    q = p * _UFP
    if _PRODUCT_LOW <= (p - cut) / (q - _UFP_LOW * q) < _PRODUCT_HIGH:
        return cut
    return product_near_half(p, cut)


def poly(x: float, planned: tuple, odd: bool = False) -> float | None:
    """``$POLY`` of ``x`` (a single, :data:`LEAST_ARGUMENT` <= x <= 1) over ``planned``
    (from :func:`plan`): Horner's rule, each step ``$FMULS`` and ``$FADDS`` as GW-BASIC
    rounds them; None where a sum is 0 (the caller takes the integer steps).  ``odd``:
    ``$POLYX`` instead, ``x * P(x*x)`` (``x`` from 2**-30 to 1), each product ``$FMULS``."""
    total, steps = planned
    outer = x
    if odd:
        x = fmuls(x * x)
    for c, large, negative, positive, top, top2, top4, unit, magic_unit, magic_2unit, carried, quarter in steps:
        p = total * x
        # $FMULS (fmuls, written out)
        split = p * _SPLIT
        cut = split - (split - p)
        q = p * _UFP
        if not _PRODUCT_LOW <= (p - cut) / (q - _UFP_LOW * q) < _PRODUCT_HIGH:
            cut = product_near_half(p, cut)
        # $FADDS of the product and the coefficient, on magnitudes: the larger one's register
        if cut < 0:
            small = -cut
            same = negative
        else:
            small = cut
            same = positive
        if small >= large:  # the product is the larger (or as large): its binade, the same tests
            if small == large or large * 536870912.0 < small:  # (equal: 0 or exact; far apart: add's own)
                total = add(cut, c)
                if not total:
                    return None
                continue
            q = small * _UFP
            ptop = q - _UFP_LOW * q
            if same:
                s = small + large
                if s < 2.0 * ptop:
                    magic = ptop * _HALF_MAGIC
                    r = (s + magic) - magic
                else:
                    magic = ptop * _MAGIC_2U
                    r = (s + magic) - magic
                    if s >= 4.0 * ptop or r - s > ptop * _CARRIED:
                        total = add(cut, c)
                        continue
            else:
                s = small - large
                magic = ptop * _HALF_MAGIC
                r = (s + magic) - magic
                if s < ptop or r - s > ptop * _QUARTER:
                    total = add(cut, c)
                    if not total:
                        return None
                    continue
            total = -r if cut < 0 else r
            continue
        if same:
            s = large + small
            if s < top2:  # no carry: the exact sum rounded half to even
                r = (s + magic_unit) - magic_unit
            else:  # a carry: the nearest at 2u, unless it rounds up by 3/8 to 1/2 of 2u
                r = (s + magic_2unit) - magic_2unit
                if s >= top4 or r - s > carried:
                    total = add(cut, c)
                    continue
        else:  # a difference in the coefficient's binade, not rounded up by more than u/4
            s = large - small
            r = (s + magic_unit) - magic_unit
            if s < top or r - s > quarter:
                total = add(cut, c)
                continue
        total = -r if negative else r
    if not odd:
        return total
    if 9.313225746154785e-10 <= total <= 1073741824.0:  # 2**-30 to 2**30: well inside the range
        return fmuls(total * outer)
    return product(total * outer)
