"""GW-BASIC's single-precision polynomial steps on integer mantissas (the fast path of
gw_transcendental.py's ``$POLY``).

``$POLY`` evaluates Horner's rule from the highest coefficient, each step a
``$FMULS`` (the product truncated to 28 bits, the 4 below the mantissa rounding half
to even with ``1001`` a half) and a ``$FADDS`` (single_arith.working_sum's steps:
the smaller operand shifted right in a 32-bit register, then normalised and rounded
half to even on the guard byte).  Here a single is a pair of integers
``(mantissa, exponent)`` with the value ``mantissa * 2**exponent``, ``|mantissa|``
24 bits with its top bit set (or 0), and the steps are written out inline with no
call and no float between them for the product; the sum is single_arith's register
steps (working_sum, rounded_parts) on the integers: the same rounding as
single_arith.product and single_arith.add, faster than those where they take their
long ways (sums of opposite signs far apart, as small arguments make them).  A step whose exponent leaves the middle
of MBF's range (where the range's ends would need testing) hands the whole
polynomial back to the caller's step-by-step reference (None is returned).
"""

from __future__ import annotations

from math import frexp, ldexp

from yaseer.basic.arithmetic.single_arith import rounded_parts, working_sum

# A step's exponent (of the 24-bit mantissa) outside these, and the polynomial goes the
# reference way: MBF's range is 2**-128 (exponent -152) to 2**127 (exponent 103).
_LOWEST, _HIGHEST = -140, 90


def parts(x: float) -> tuple[int, int]:
    """A single's ``(mantissa, exponent)``: ``x == mantissa * 2**exponent``, the mantissa
    a signed 24-bit integer (0 for 0)."""
    if not x:
        return 0, 0
    m, e = frexp(x)
    return int(m * 16777216.0), e - 24


def coefficient_parts(coefficients) -> tuple[tuple[int, int, bool], ...]:
    """A polynomial's single coefficients (highest power first) as ``(magnitude,
    exponent, negative)``: the value is ``magnitude * 2**exponent``, negated when
    ``negative``."""
    return tuple((abs(m), e, m < 0) for m, e in map(parts, coefficients))


def poly(x: float, coefficients: tuple[tuple[int, int, bool], ...]) -> float | None:
    """``$POLY`` of ``x`` (a single, at least 0) over ``coefficients`` (from
    :func:`coefficient_parts`): Horner's rule, each product and sum rounded as GW-BASIC's
    ``$FMULS`` and ``$FADDS``; None where a step leaves the middle of the range."""
    m, e, negative = coefficients[0]
    if not x:  # every product is 0, and 0 + c is c
        m, e, negative = coefficients[-1]
        return ldexp(-m if negative else m, e)
    fm, fe = frexp(x)
    xm, xe = int(fm * 16777216.0), fe - 24
    for c, ce, c_negative in coefficients[1:]:
        if not m:  # 0 * x + c
            m, e, negative = c, ce, c_negative
            continue
        # $FMULS: the 47- or 48-bit product cut to 28 bits; its low 4 round the 24 up
        # from 10/16, or from 8/16 over an odd mantissa
        p = m * xm
        if p >= 0x800000000000:
            m = p >> 20
            e += xe + 24
        else:
            m = p >> 19
            e += xe + 23
        m = (m + 6 + (m >> 3 & 2)) >> 4
        if m == 0x1000000:
            m = 0x800000
            e += 1
        if e <= _LOWEST or e >= _HIGHEST:
            return None
        # $FADDS of (m, e) and the coefficient: the larger one's 32-bit register (its
        # mantissa and a guard byte), the smaller shifted right into it (single_arith.working_sum)
        if e > ce or (e == ce and m > c):
            exponent, register, negative = working_sum(ce + 152, c << 8, c_negative, e + 152, m << 8, negative)
        else:
            exponent, register, negative = working_sum(e + 152, m << 8, negative, ce + 152, c << 8, c_negative)
        if not register:
            m = 0
            continue
        m, e = rounded_parts(exponent, register)
        e -= 152
    return ldexp(-m if negative else m, e)
