"""GW-BASIC's double precision on its own 56-bit mantissas (MBF doubles).

A GW-BASIC double is 8 bytes: a 56-bit mantissa (its top bit implied, the sign in
its place) and an exponent byte, the value ``mantissa * 2**(exponent - 184)``.  A
Python float holds 53 bits, so here a double is ``(negative, exponent, mantissa)``:
``exponent`` the MBF byte (0 for zero, 1..255), ``mantissa`` 56 bits with its top bit
set.  The routines work as MATH1.ASM/MATH2.ASM do, on a 64-bit register (the 56 bits
and a guard byte) that ``$ROUND`` (MATH2.ASM) rounds: it adds 0x80 to the guard
byte, carrying into the mantissa, and clears the mantissa's last bit when the guard
byte was exactly 0x80 (half to even).

* ``+ -`` (:func:`add`, ``$FADDD``/``$FSUBD``): the operand with the smaller exponent is
  shifted right in its register by ``$SHRA`` (whole bytes first, keeping of a dropped
  guard byte only its bit 5, the sticky bit ST; then bit by bit, a 1 shifted out of bit
  5 setting it again); a shift of 57 bits or more leaves the larger operand as it is.
  A carry out of the sum shifts it right one bit; a difference is normalised
  (``$NORMD``); then ``$ROUND``.
* ``*`` (:func:`multiply`, ``$FMULD``): the 64 top bits of the exact product, ST set
  in the guard byte when any bit below them is 1, normalised by one bit, ``$ROUND``:
  the exact product rounded half to even to 56 bits.
* ``/`` (:func:`divide`, ``$FDIVD``): 64 bits of quotient of the halved dividend by
  long division, bit 0 set when a remainder is left, normalised, ``$ROUND``: the
  exact quotient rounded half to even.

A result beyond exponent byte 255 raises :class:`Overflow` (the caller applies
``$OVFLS``'s policy); one below byte 1 is 0.
"""

from __future__ import annotations

from math import frexp, ldexp

ZERO = (False, 0, 0)
_BIT63 = 1 << 63
_TOP64 = 1 << 64


class Overflow(ArithmeticError):
    """A double result beyond MBF's range (exponent byte 256 or more)."""

    def __init__(self, negative: bool):
        super().__init__("Overflow")
        self.negative = negative


def parts(x: float) -> tuple[bool, int, int]:
    """A float (inside MBF's range) as ``(negative, exponent byte, 56-bit mantissa)``: exact."""
    if not x:
        return ZERO
    m, e = frexp(x)
    if e > 127:  # 2**127, yaseer's float for the largest double: MBF's largest
        return x < 0, 255, (1 << 56) - 1
    if e < -127:  # below MBF's range
        return ZERO
    return x < 0, e + 128, int((m if m > 0 else -m) * 9007199254740992.0) << 3


def nearest_float(p: tuple[bool, int, int]) -> float:
    """The float nearest to a double (half to even; exact when its last 3 bits are 0)."""
    negative, exponent, mantissa = p
    if not exponent:
        return 0.0
    value = ldexp(float(mantissa), exponent - 184)
    return -value if negative else value


def exact_in_float(p: tuple[bool, int, int]) -> bool:
    """Does a float hold the double exactly (its mantissa's last 3 bits are 0)?"""
    return not p[2] & 7


def _rounded(negative: bool, exponent: int, register: int) -> tuple[bool, int, int]:
    """``$ROUND`` of a normalised 64-bit register (mantissa and guard byte)."""
    register += 0x80
    if register >= _TOP64:
        register >>= 1
        exponent += 1
    mantissa = register >> 8
    if not register & 0xFF:  # the guard byte was 0x80: a tie, made even
        mantissa &= ~1
    if exponent > 255:
        raise Overflow(negative)
    if exponent <= 0:
        return ZERO
    return negative, exponent, mantissa


def shifted_right(register: int, shift: int) -> int:
    """``$SHRA``: a 64-bit register shifted right ``shift`` (< 57) bits, bytes first
    (a dropped guard byte leaves only its bit 5 behind), then bits (a bit reaching bit 4
    sets bit 5, the sticky bit ST)."""
    while shift >= 8:
        register = (register >> 8) | (register & 0x20)
        shift -= 8
    while shift:
        register >>= 1
        if register & 0x10:
            register |= 0x20
        shift -= 1
    return register


def add(a: tuple[bool, int, int], b: tuple[bool, int, int]) -> tuple[bool, int, int]:
    """``a + b`` as ``$FADDD`` (module docstring)."""
    if not b[1]:
        return a
    if not a[1]:
        return b
    if a[1] < b[1]:
        a, b = b, a
    negative, exponent, mantissa = a
    shift = exponent - b[1]
    if shift >= 57:
        return a
    register = mantissa << 8
    other = shifted_right(b[2] << 8, shift) if shift else b[2] << 8
    if negative == b[0]:
        register += other
        if register >= _TOP64:
            register >>= 1
            exponent += 1
            if exponent > 255:
                raise Overflow(negative)
        return _rounded(negative, exponent, register)
    register -= other
    if register < 0:  # the smaller exponent's operand was the larger: the two's complement
        register = -register
        negative = not negative
    if not register:
        return ZERO
    shift = 64 - register.bit_length()  # $NORMD
    return _rounded(negative, exponent - shift, register << shift)


def negate(a: tuple[bool, int, int]) -> tuple[bool, int, int]:
    return (not a[0], a[1], a[2]) if a[1] else a


def subtract(a, b) -> tuple[bool, int, int]:
    """``a - b`` (``$FSUBD``: the sign of ``b`` flipped, then ``$FADDD``)."""
    return add(a, negate(b))


def _nearest(negative: bool, exponent: int, value: int, shift: int) -> tuple[bool, int, int]:
    """``value >> shift`` (56 or 57 bits) rounded half to even to 56 bits, MBF byte ``exponent``."""
    mantissa, rest = value >> shift, value & ((1 << shift) - 1)
    half = 1 << (shift - 1)
    if rest > half or (rest == half and mantissa & 1):
        mantissa += 1
        if mantissa >> 56:
            mantissa >>= 1
            exponent += 1
    if exponent > 255:
        raise Overflow(negative)
    if exponent <= 0:
        return ZERO
    return negative, exponent, mantissa


def multiply(a, b) -> tuple[bool, int, int]:
    """``a * b`` as ``$FMULD``: the exact product rounded half to even to 56 bits."""
    if not a[1] or not b[1]:
        return ZERO
    product = a[2] * b[2]  # 2**110 .. 2**112
    negative = a[0] != b[0]
    if product >> 111:
        return _nearest(negative, a[1] + b[1] - 128, product, 56)
    return _nearest(negative, a[1] + b[1] - 129, product, 55)


def divide(a, b) -> tuple[bool, int, int]:
    """``a / b`` as ``$FDIVD``: the exact quotient rounded half to even to 56 bits.
    ``b`` = 0 raises ZeroDivisionError (the caller applies ``$DIV0S``'s policy)."""
    if not b[1]:
        raise ZeroDivisionError("division by zero")
    if not a[1]:
        return ZERO
    negative = a[0] != b[0]
    quotient, rest = divmod(a[2] << 64, b[2])  # 2**63 .. 2**65: 64 or 65 bits
    quotient = quotient << 1 | (1 if rest else 0)  # the remainder as a sticky bit below
    if quotient >> 65:
        return _nearest(negative, a[1] - b[1] + 129, quotient, 10)
    return _nearest(negative, a[1] - b[1] + 128, quotient, 9)


def compare(a, b) -> int:
    """-1, 0 or 1 as ``a`` is below, equal to or above ``b``."""
    ka = (a[1], a[2]) if a[1] else (0, 0)
    kb = (b[1], b[2]) if b[1] else (0, 0)
    if not ka[0] and not kb[0]:
        return 0
    sa = -1 if a[0] and ka[0] else (1 if ka[0] else 0)
    sb = -1 if b[0] and kb[0] else (1 if kb[0] else 0)
    if sa != sb:
        return -1 if sa < sb else 1
    if ka == kb:
        return 0
    return (1 if ka > kb else -1) * sa


def to_bytes(p) -> bytes:
    """MKD$'s 8 bytes: 7 of mantissa (low first; the top bit of the last the sign) and the exponent."""
    negative, exponent, mantissa = p
    if not exponent:
        return bytes(8)
    mantissa &= ~(1 << 55)
    if negative:
        mantissa |= 1 << 55
    return mantissa.to_bytes(7, "little") + bytes((exponent,))


def from_bytes(data: bytes) -> tuple[bool, int, int]:
    """CVD of 8 bytes (an exponent byte of 0 is zero, whatever the mantissa)."""
    exponent = data[7]
    if not exponent:
        return ZERO
    mantissa = int.from_bytes(data[:7], "little")
    return bool(mantissa >> 55), exponent, mantissa | (1 << 55)


def from_integer(whole: int) -> tuple[bool, int, int]:
    """A whole number of at most 56 significant bits (or exact in them) as a double."""
    if not whole:
        return ZERO
    magnitude = -whole if whole < 0 else whole
    size = magnitude.bit_length()
    mantissa = magnitude << (56 - size) if size <= 56 else magnitude >> (size - 56)
    return whole < 0, size + 128, mantissa


def _nearest_power_of_ten(n: int) -> tuple[bool, int, int]:
    """10**n (n >= 0) rounded half to even to 56 bits."""
    numerator = 10 ** n
    size = numerator.bit_length()
    if size <= 56:
        return from_integer(numerator)
    mantissa, rest = numerator >> (size - 56), numerator & ((1 << (size - 56)) - 1)
    half = 1 << (size - 57)
    if rest > half or (rest == half and mantissa & 1):
        mantissa += 1  # (10**n is never 2**56 - 1 times a power of two: no carry out)
    return False, size + 128, mantissa


# MATH1.ASM's table of powers of ten $DP00..: 10**0 to 10**38 as doubles, exact up to
# 10**24 (5**24 < 2**56), the nearest 56 bits beyond (checked against the table's bytes)
_POWERS = [_nearest_power_of_ten(n) for n in range(39)]
_TEN = _POWERS[1]
_EXACT_DIGITS = 1 << 56  # digits read so far below this: their value is exact


def power_of_ten(n: int) -> tuple[bool, int, int]:
    """10**n (0 <= n <= 38) as GW's table of powers of ten holds it."""
    return _POWERS[n]


def from_decimal(digits: int, power: int) -> tuple[bool, int, int]:
    """The double GW-BASIC's number reader gives ``digits * 10**power`` (``digits``: all
    the digits typed, as an integer; ``power``: the exponent less the digits after the
    point), step by step as ``$FIN`` makes it (MATH1.ASM, MATH2.ASM):

    * ``$FIDIG`` takes the digits one by one, the number so far times ten (``$FMULD``
      by 10) plus the digit (``$FADDD``): exact while below 2**56 (16 digits and some
      17), then each step rounds;
    * ``$FINE``/``MDPTEN`` apply the power once: times 10**power (``$FMULD``) up to
      10**38 (beyond: Overflow), divided by 10**-power (``$FDIVD``) down to 10**-38, below
      that divided by 10**(-power - 38) and then by 10**38, below 10**-76 zero.  The
      powers are the table's (:func:`power_of_ten`).

    Up to 16 digits and powers up to 10**24 this is the exact value rounded once; beyond,
    a second rounding may make the last bit differ from the nearest.  Raises
    :class:`Overflow` beyond the range; below it 0."""
    if not digits:
        return ZERO
    if digits < _EXACT_DIGITS:
        number = from_integer(digits)
    else:
        text = str(digits)
        exact, used = 0, 0
        while exact * 10 + int(text[used]) < _EXACT_DIGITS:
            exact, used = exact * 10 + int(text[used]), used + 1
        number = from_integer(exact)
        for digit in text[used:]:
            number = add(multiply(number, _TEN), from_integer(int(digit)))
    return scaled_by_power_of_ten(number, power)


def scaled_by_power_of_ten(number: tuple[bool, int, int], power: int) -> tuple[bool, int, int]:
    """``MDPTEN`` (MATH1.ASM): ``number`` times 10**power by one ``$FMULD`` by the table's
    power (up to 10**38; beyond: :class:`Overflow` unless ``number`` is 0), or divided by
    10**-power (``$FDIVD``), below 10**-38 by 10**(-power - 38) and then by 10**38,
    below 10**-76 zero."""
    if power > 0:
        if power > 38:
            if not number[1]:
                return ZERO
            raise Overflow(number[0])
        return multiply(number, _POWERS[power])
    if power < -76:
        return ZERO
    if power < -38:
        number = divide(number, _POWERS[-power - 38])
        power = -38
    return divide(number, _POWERS[-power]) if power else number


def single_rounded(p: tuple[bool, int, int]) -> tuple[bool, int, int]:
    """``$CSD`` (MATH2.ASM): a double made single, its top 24 bits rounded up when the 25th
    is 1 (``$ROUNM`` with bit 6 of the guard byte set: no tie to even), as a double again;
    :class:`Overflow` when the rounding carries beyond exponent byte 255."""
    negative, exponent, mantissa = p
    if not exponent:
        return ZERO
    top = (mantissa >> 32) + (mantissa >> 31 & 1)
    if top >> 24:
        top >>= 1
        exponent += 1
        if exponent > 255:
            raise Overflow(negative)
    return negative, exponent, top << 32
