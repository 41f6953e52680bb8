"""GW-BASIC's single-precision arithmetic: how Microsoft Binary Format rounds.

A GW-BASIC single is a 24-bit mantissa and an exponent byte (Microsoft Binary
Format, MBF); yaseer holds it in a Python float, exactly.  GW-BASIC's routines
(MATH1.ASM, MATH2.ASM of Microsoft's published source) work on the 24 bits and a
guard byte, and do not always give the nearest single.  The functions here give
GW-BASIC's result:

* ``+ -`` (:func:`add`, :func:`subtract`): MATH1.ASM's ``$FADDS`` register by register
  (:func:`working_sum`, :func:`_rounded`): the smaller operand's mantissa shifted right
  into a 32-bit register whose low byte is the guard byte, whole bytes first, the bits
  shifted out kept as a sticky bit; then normalised (``$NORMS``) and rounded from the
  guard byte's top three bits (``$ROUNS``), with float fast paths where the nearest
  single is provably that result.  (PC-BASIC 2.0.8 keeps no sticky bit: about 0.4% of
  its sums differ; the source, and the recorded sums of PC-BASIC's test suite, decide.)
* ``*`` (:func:`product`, ``$FMULS``) step for step as PC-BASIC 2.0.8 reproduces it,
  which the differential tests compare against bit for bit: the product is truncated
  to 28 bits; the 4 bits below the mantissa round half to even, ``1001`` counting as a
  half (``$ROUNS`` keeps the guard byte's top 3 bits: 0x80..0x9F is a tie).
* ``/`` (:func:`divide`, ``$FDIVS``): the nearest single, ties to even: the
  routine rounds with a sticky bit from the remainder.  (PC-BASIC's division
  shifts the divisor right and loses its low bits: about 1% of its quotients are
  one unit off; the source decides, docs/compatibility.md.)
* SQR (``$SQR``: bit by bit, 24 bits and a rounding bit): the nearest single.
* ``^`` (:func:`power`, ``$FPWR``): an integral exponent below 32768 in size
  multiplies by binary powering (Knuth's algorithm A, each step ``$FMULS``; a
  negative one divides 1 by the result); any other is ``EXP(Y*LOG(X))``.
* LOG, EXP, SIN, COS, TAN, ATN and ``^`` with a fractional exponent: GW-BASIC
  evaluates Hart's polynomials in single precision, whose last bit yaseer does not
  reproduce; yaseer gives the nearest single to the true value (:func:`nearest`).
* A double made single (:func:`from_double`, ``$CSD``): rounded half up on the
  guard byte's top bit.
* PRINT's digits: :mod:`yaseer.basic.arithmetic.mbf_digits` (with this module's ``$FMULS`` and ``$FADDS``).

The range is MBF's: exponent byte 1..255, values 2**-128 .. (1 - 2**-24) * 2**127.
A result below it is 0; one at or beyond 2**127 is infinite with its sign, which
the compiled code hands to the dialect's overflow policy (arith_policy.py).

Working numbers are ``(exponent byte, mantissa)`` with the value
``mantissa * 2**(exponent - 160)``: a 32-bit mantissa whose top bit is set.
"""

from __future__ import annotations

import struct
from math import frexp, inf, ldexp

_TOP = 1 << 32  # a 32-bit working mantissa is below this
_HALF_TOP = 1 << 31  # ... and, normalised, at least this
TINY = 2.0 ** -128  # the least MBF single; anything smaller is 0
LIMIT = 2.0 ** 127  # a rounded result this large overflows (exponent byte 256)
LARGEST = (1 - 2.0 ** -24) * 2.0 ** 127  # the largest single, 1.701412E+38
_SAFE_LOW = 2.0 ** -125  # IEEE singles keep all 24 bits from 2**-126 up
# A constant below this in size, added to a single, cannot carry the sum beyond the
# range: it is less than half a unit of the largest single (2**103, about 1E+31).
SMALL_CONSTANT = 1e30
_pack, _unpack = struct.Struct("f").pack, struct.Struct("f").unpack


def nearest(x) -> float:
    """``x`` rounded to the nearest single, ties to even, in MBF's range (below
    2**-128: 0; from 2**127: an infinity).  NaN and infinities pass through."""
    if _SAFE_LOW <= x or x <= -_SAFE_LOW:
        try:
            r = _unpack(_pack(x))[0]
        except OverflowError:
            return -inf if x < 0 else inf
        if -LIMIT < r < LIMIT:
            return r
        return -inf if r < 0 else inf
    if not x or x != x:
        return x + 0.0
    m, e = frexp(x)  # below IEEE single's normal range: round the 24 bits here
    q = m * 16777216.0 if m > 0 else m * -16777216.0
    below = q % 1.0
    q -= below
    if below > 0.5 or (below == 0.5 and q % 2.0):
        q += 1.0
    r = ldexp(q, e - 24)
    if r < TINY:
        return 0.0
    return -r if x < 0 else r


def working_parts(x, width: int = 32) -> tuple[int, int]:
    """A nonzero number's (exponent byte, ``width``-bit working mantissa): for a single
    and width 32 the low byte is 0; width 64 holds a double's 53 bits exactly."""
    m, e = frexp(abs(x))
    return e + 128, int(ldexp(m, width))


def add(a, b) -> float:
    """``a + b`` of two singles (or integers), rounded as GW-BASIC's ``$FADDS``.

    The long way is :func:`working_sum` and :func:`_rounded`, the routine's register steps
    on integers.  The fast paths, where the exponents differ by at most 29 (the sum is
    exact in a Python float), return the nearest single of the exact sum (Veltkamp's
    split ``cut``) where that is provably ``$FADDS``'s result; ``t`` below is how far the
    exact sum lies beyond ``cut`` (:func:`_units_below`: positive where ``cut`` is nearer
    zero), in units of the result's last place ``u``:

    * a sum that needs at most 24 bits (``cut`` is the sum): no bit is rounded away;
    * two magnitudes of one sign: the guard byte and its sticky bit round as the exact sum
      does, except after a carry out of the larger operand's binade, whose shift drops the
      sticky bit: a guard byte that was ``0100...`` with bits below reads as a tie, so GW
      rounds half to even where the nearest rounds up from ``t`` in (-1/2, -3/8).  Without
      a carry (the larger operand at least the sum's leading power of two) every ``t`` but
      a tie is the nearest's; with one, ``-3/8 <= t < 1/2``;
    * two signs, exponents at most 3 apart: no bit of the smaller operand leaves the
      register or reaches the sticky bit, so the difference is exact before rounding;
    * two signs, the difference in the larger operand's binade (no normalising shift): the
      register holds the smaller operand cut to a multiple of 64 of its 256ths, plus 32
      (the sticky bit) and up to 31 below it (bits the sticky bit shifted down), where it
      lost bits; the difference's guard byte, its low 5 bits dropped, then rounds as the
      exact difference does unless it reads as a tie that the exact one is above, that is
      ``t`` in (-1/2, -1/4).  So ``-1/4 <= t < 1/2``.

    Everything else (a normalising shift after a difference, which brings the dropped
    bits into the guard byte; exponents 25 or more apart, where ``$FADDS`` returns the
    larger operand as it is; the range's ends) goes the long way."""
    if not a:
        return b + 0.0
    if not b:
        return a + 0.0
    total = a + b
    if not total:
        return 0.0
    x = a if a > 0 else -a
    y = b if b > 0 else -b
    if (total >= _SAFE_LOW or total <= -_SAFE_LOW) and (x * 536870912.0 >= y if x <= y else y * 536870912.0 >= x):
        split = total * 536870913.0
        cut = split - (split - total)
        if -LIMIT < cut < LIMIT:
            if cut == total:
                return total
            q = total * 4503599627370497.0  # (see _units_below, written out here: the common path)
            top = q - 0.9999999999999999 * q
            below = (total - cut) / top * 8388608.0
            if (a > 0) == (b > 0):
                if -0.375 <= below < 0.5 or -0.5 < below < 0.5 and (x if x > y else y) >= (top if top > 0 else -top):
                    return cut
            elif -0.5 < below < 0.5 and (x * 8.0 >= y if x <= y else y * 8.0 >= x):
                return cut
            elif -0.25 <= below < 0.5 and (x if x > y else y) < (top + top if top > 0 else -top - top):
                return cut
    small, large = (a, b) if x <= y else (b, a)
    small_exponent, small_mantissa = working_parts(small)
    exponent, mantissa = working_parts(large)
    return _rounded(*working_sum(small_exponent, small_mantissa, small < 0, exponent, mantissa, large < 0))


def rounded_parts(exponent: int, register: int) -> tuple[int, int]:
    """``$ROUNS`` on a normalised working number: its 24-bit mantissa and exponent byte after
    the guard byte's top three bits round it half to even (the low five are dropped)."""
    mantissa = register >> 8
    guard = register & 0xE0
    if guard > 0x80 or (guard == 0x80 and mantissa & 1):
        mantissa += 1
        if mantissa == 0x1000000:
            return 0x800000, exponent + 1
    return mantissa, exponent


def _rounded(exponent: int, register: int, negative: bool) -> float:
    """A normalised working number (:func:`working_sum`'s) rounded by ``$ROUNS``
    (:func:`rounded_parts`): 0 below the range (a register of 0, an exponent byte of 0 or
    less), an infinity beyond it."""
    if not register or exponent <= 0:
        return 0.0
    mantissa, exponent = rounded_parts(exponent, register)
    if exponent > 255:
        return -inf if negative else inf
    value = ldexp(mantissa, exponent - 152)
    return -value if negative else value


def working_sum(small_exponent: int, small_mantissa: int, small_negative: bool,
                exponent: int, mantissa: int, negative: bool) -> tuple[int, int, bool]:
    """``$FADDS``'s register steps on two working numbers (:func:`working_parts`: exponent
    byte and 32-bit mantissa, the low byte 0), the second the larger in magnitude (or of
    the larger exponent): the (exponent byte, 32-bit register, sign) that ``$ROUNS``
    (:func:`_rounded`) rounds, normalised; a register of 0 for 0.

    The smaller operand is shifted right into the 32-bit register (its low byte the guard
    byte) by the exponents' difference: none of it if that is 25 or more (the larger
    operand is the result, as it is); else a byte at a time while 8 or more bits remain
    (the bits that fall out, and the new guard byte's low five, set its sticky bit 0x20),
    then a bit at a time (after each shift, a 1 in bit 0x10 sets 0x20).  Of one sign the
    registers add; a carry out of 32 bits shifts the sum right once (the sticky bit moves
    to 0x10, which rounding ignores) and adds one to the exponent (beyond 255: an
    overflow, left to :func:`_rounded`).  Of two signs the smaller register is subtracted
    and the difference normalised as ``$NORMS`` does: a byte at a time while the top byte
    is 0 (0 where the exponent byte is 8 or less), then a bit at a time (0 where the
    exponent byte reaches 0); the bits below the guard byte's top three shift up with it."""
    shift = exponent - small_exponent
    if shift >= 25:
        return exponent, mantissa, negative
    register = small_mantissa
    if shift >= 8:
        cut = shift & 0x18
        register = (register >> cut) | (0x20 if register & ((1 << (cut + 5)) - 1) else 0)
        shift &= 7
    while shift:
        register >>= 1
        if register & 0x10:
            register |= 0x20
        shift -= 1
    if small_negative == negative:
        register += mantissa
        if register >= _TOP:
            register >>= 1
            exponent += 1
        return exponent, register, negative
    register = mantissa - register
    if register <= 0:
        if not register:
            return exponent, 0, negative
        register = -register  # (equal exponents: the smaller mantissa was the larger)
        negative = not negative
    while register < 0x1000000:
        if exponent <= 8:
            return exponent, 0, negative
        register <<= 8
        exponent -= 8
    if register < _HALF_TOP:
        shift = 32 - register.bit_length()
        if exponent <= shift:
            return exponent, 0, negative
        register <<= shift
        exponent -= shift
    return exponent, register, negative


def subtract(a, b) -> float:
    """``a - b`` of two singles (or integers), as GW-BASIC's ``$FSUBS``."""
    return add(a, -b)


def _units_below(x, cut) -> float:
    """How far ``x`` lies from its 24-bit cut ``cut`` (a rounding of ``x`` to 24 bits:
    within one unit of its last place), in units of that place, signed so that a
    positive value means ``cut`` is nearer zero than ``x``.  Float operations only:
    ``q - (1 - 2**-53) * q`` with ``q = x * (2**52 + 1)`` is the largest power of two
    not above ``|x|`` with ``x``'s sign (Rump, Ogita and Oishi's ufp), whose 2**-23 is
    the unit; every step is exact."""
    q = x * 4503599627370497.0
    return (x - cut) / (q - 0.9999999999999999 * q) * 8388608.0


def product(p) -> float:
    """The single GW-BASIC's ``$FMULS`` gives for the exact product ``p`` of two singles
    (or integers; any product of two values of at most 24 bits is exact in a Python
    float): ``p`` truncated to 28 bits, whose 4 low bits round the 24 half to even
    (``1001`` counts as a half): up when the part below the 24 bits is at least
    10/16 of a unit, or at least 8/16 over an odd mantissa.  That is the nearest
    single unless that part is from 8/16 to 10/16: the nearest, found with float
    operations (Veltkamp's split and :func:`_units_below`), is returned at once
    outside that band and inside the range; the band and the edges go the long way."""
    split = p * 536870913.0  # Veltkamp: ``cut`` is p rounded to 24 bits (to nearest)
    cut = split - (split - p)
    if TINY <= cut < LIMIT or -LIMIT < cut <= -TINY:
        if -0.375 <= _units_below(p, cut) < 0.5:  # GW's rounding is the nearest outside [0.5, 0.625)
            return cut
    if -TINY < p < TINY:
        return 0.0
    if p in (inf, -inf):  # a power's product after an overflow
        return p
    m, e = frexp(p)
    q = m * 16777216.0 if m > 0 else m * -16777216.0  # the 24 bits and the rest, exact
    below = q % 1.0
    q -= below
    if below >= 0.625 or (below >= 0.5 and q % 2.0):
        q += 1.0
    r = ldexp(q, e - 24)
    if r >= LIMIT:
        return -inf if p < 0 else inf
    return -r if p < 0 else r


def product_near_half(p, cut) -> float:
    """:func:`product` of ``p`` where its nearest single ``cut`` (in MBF's range) lies
    between 3/8 and 1/2 of a unit beyond ``p``, or exactly half a unit from it: the 24
    bits below ``p`` round up (to ``cut``) when odd, for a half when even (the round
    half to even of ``$FMULS``'s 28 bits, ``1001`` being a half).  So the result is
    ``cut`` when its mantissa is even (also a power of two above ``p``'s binade), else the
    single next to ``cut`` on ``p``'s side."""
    m, e = frexp(cut)
    if not (m * 16777216.0) % 2.0:
        return cut
    unit = ldexp(1.0, e - 24)
    return cut - unit if cut > p else cut + unit


def multiply(a, b) -> float:
    """``a * b`` of two singles (or integers), as GW-BASIC's ``$FMULS``."""
    return product(a * b)


def divide(a, b) -> float:
    """``a / b`` of two singles (or integers), as GW-BASIC's ``$FDIVS``: the nearest
    single (the quotient of two 24-bit mantissas is never exactly halfway unless
    exact, so the double quotient rounds as the exact one).  ``b`` = 0 raises
    ZeroDivisionError (the caller applies the policy)."""
    if not b:
        raise ZeroDivisionError("division by zero")
    return nearest(a / b)


def from_double(x) -> float:
    """A double made single (CSNG, or stored in a single variable), as GW-BASIC's
    ``$CSD``: the top 24 bits of the mantissa, rounded up when the next bit is 1."""
    if not x:
        return 0.0
    if x != x or x in (inf, -inf):  # already beyond the range: the caller's overflow check
        return x
    m, e = frexp(x)
    q = m * 16777216.0 if m > 0 else m * -16777216.0
    q += 0.5
    q -= q % 1.0
    if e + 128 <= 0:
        return 0.0
    r = ldexp(q, e - 24)
    if r >= LIMIT:
        return -inf if x < 0 else inf
    return -r if x < 0 else r


# A single-precision function's value (SQR, SIN, LOG, EXP, ``^`` with a fractional
# exponent) from its IEEE double result: the nearest single (module docstring).
function_result = nearest


def power_by_integer(x, n: int, overflow=None) -> float:
    """``x ^ n`` for an integral ``n`` below 32768 in size, as GW-BASIC's ``$FPWR``
    (XTON): Knuth's binary powering (``Y = 1, Z = x``; per bit of ``n`` from the lowest:
    ``Y = Y*Z`` when it is 1, then, while bits remain, ``Z = Z*Z``), each product
    rounded as ``$FMULS``; for a negative ``n``, 1 divided by ``x ^ -n`` (``$FDIVS``),
    and Overflow when ``x ^ -n`` underflowed to 0.  ``n`` = 0 gives 1; 0 to a negative
    power raises ZeroDivisionError.

    ``overflow(negative)``: ``$FPWR`` sets the once-only overflow mode, so the first
    product beyond the range calls it (the message, or the trapped error) and every
    one goes on with the signed largest single (``$OVFLS``).  Without it, an overflow
    gives an infinity."""
    count = int(n)
    told = False

    def times(p):
        nonlocal told
        r = product(p)
        if r - r == 0 or overflow is None:
            return r
        if not told:
            told = True
            overflow(r < 0)
        return -LARGEST if r < 0 else LARGEST

    y, z = None, x + 0.0  # y None: still 1 (1 * Z is exact: the first product is Z itself)
    bits = -count if count < 0 else count
    while bits:
        if bits & 1:
            y = z if y is None else times(y * z)
        bits >>= 1
        if bits:
            z = times(z * z)
    if y is None:
        return 1.0
    if count >= 0:
        return y
    if y == 0 and x and overflow is not None:  # (GW tests the FAC's exponent before it inverts; 0 itself: $DIV0S)
        negative = x < 0 and count % 2 == 1
        if not told:
            overflow(negative)
        return -LARGEST if negative else LARGEST
    return divide(1.0, y)
def is_integral_power(n) -> bool:
    """Does GW-BASIC's ``$FPWR`` raise to ``n`` by multiplying (``n`` integral, |n| < 32768)?"""
    return -32768 < n < 32768 and n == int(n)
