"""A reference for GW-BASIC's single-precision addition, written for the tests only.

This follows the register steps of ``$FADDS``/``$FSUBS`` (MATH1.ASM of Microsoft's
published GW-BASIC source), ``$NORMS`` and ``$ROUNS`` (MATH2.ASM) one register at a time,
on 8- and 16-bit integers, the way the 8086 would: the larger operand's mantissa in
AL:SI, the smaller's in BL:DX with an overflow (guard) byte AH; byte moves while 8 or
more bits remain to shift (the guard byte that falls out, or low five bits of the new
one, set its sticky bit 0x20), then single right shifts (a 1 in bit 0x10 after a shift
sets 0x20); the mantissas added or subtracted (the guard byte taking part, with its
borrow); normalised left a byte or a bit at a time; rounded from the guard byte's top
three bits, half to even.  The source's numbers are octal: ``CMP CX,31`` is 25.

It is deliberately slow and literal, so that it shares nothing with
yaseer.basic.arithmetic.single_arith, the code it checks.  Numbers are MBF singles as
4 bytes (low mantissa, middle, sign and high mantissa, exponent), or Python floats
converted exactly.
"""

from __future__ import annotations

from fractions import Fraction
from math import copysign, frexp, inf, ldexp

OVERFLOW = "overflow"  # what fadds returns where $FADDS jumps to $OVFLS


def is_single(x: float) -> bool:
    """Is ``x`` 0 or a single of MBF's range (24 bits, 2**-128 up to below 2**127)?"""
    if x == 0:
        return True
    if not 2.0 ** -128 <= abs(x) < 2.0 ** 127:
        return False
    m, e = frexp(abs(x))
    return ldexp(m, 24).is_integer()


def to_mbf(x: float) -> bytes:
    """A float holding a single (24 bits, in MBF's range) as its 4 MBF bytes."""
    if x == 0:
        return bytes(4)
    m, e = frexp(abs(x))
    mantissa = int(ldexp(m, 24))
    assert mantissa < 1 << 24 and ldexp(mantissa, e - 24) == abs(x), x
    exponent = e + 128
    assert 1 <= exponent <= 255, x
    high = (mantissa >> 16) & 0x7F | (0x80 if x < 0 else 0)
    return bytes((mantissa & 0xFF, (mantissa >> 8) & 0xFF, high, exponent))


def from_mbf(b: bytes) -> float:
    """The value of 4 MBF bytes."""
    if b[3] == 0:
        return 0.0
    mantissa = b[0] | b[1] << 8 | (b[2] | 0x80) << 16
    value = ldexp(mantissa, b[3] - 152)
    return -value if b[2] & 0x80 else value


def fadds(bxdx: bytes, fac: bytes) -> bytes | str:
    """``$FADDS``: (BXDX) + (FAC) as MBF bytes, or OVERFLOW."""
    dx = bxdx[0] | bxdx[1] << 8
    bl, bh = bxdx[2], bxdx[3]
    if bh == 0:
        return bytes(fac)
    if fac[3] == 0:
        return bytes(bxdx)
    si = fac[0] | fac[1] << 8
    al, ah = fac[2], fac[3]
    fac_exponent, fac_sign = ah, al  # $FAC and $FAC+1
    cl = ah - bh
    if cl < 0:  # (BXDX) is the larger: it goes to the FAC, the registers swap
        cl = -cl
        fac_exponent, fac_sign = bh, bl
        al, ah, bl, bh = bl, bh, al, ah
        dx, si = si, dx
    subtracting = (al ^ bl) & 0x80
    al |= 0x80
    bl |= 0x80
    ah = 0
    cx = cl
    while cx:
        if cx >= 25:  # the smaller is negligible: the larger, as it is
            out = (al & 0x7F) | (fac_sign & 0x80)
            return bytes((si & 0xFF, si >> 8, out, fac_exponent))
        if cx >= 8:  # a byte move
            lost = ah
            ah = dx & 0xFF
            if lost:
                ah |= 0x20
            dx = (dx >> 8) | (bl << 8)
            bl = 0
            cx -= 8
            if ah & 0x1F:
                ah |= 0x20
            continue
        while cx:  # single shifts of BL:DX:AH
            carry = bl & 1
            bl >>= 1
            carry2 = dx & 1
            dx = (dx >> 1) | (carry << 15)
            ah = (ah >> 1) | (carry2 << 7)
            if ah & 0x10:
                ah |= 0x20
            cx -= 1
    if subtracting:
        borrow = 1 if ah else 0
        ah = (0 - ah) & 0xFF
        value = si - dx - borrow
        borrow = 1 if value < 0 else 0
        dx = value & 0xFFFF
        value = al - bl - borrow
        borrow = 1 if value < 0 else 0
        bl = value & 0xFF
        if borrow:  # the FAC was not the larger: negate the 32 bits and the sign
            fac_sign ^= 0xFF
            whole = (bl << 24 | dx << 8 | ah) ^ 0xFFFFFFFF
            whole = (whole + 1) & 0xFFFFFFFF
            bl, dx, ah = whole >> 24, (whole >> 8) & 0xFFFF, whole & 0xFF
        return _norms(bl, dx, ah, fac_exponent, fac_sign)
    total = dx + si
    dx = total & 0xFFFF
    total = bl + al + (total >> 16)
    bl = total & 0xFF
    if total > 0xFF:  # carried out of the high byte: one more in the exponent
        fac_exponent = (fac_exponent + 1) & 0xFF
        if fac_exponent == 0:
            return OVERFLOW
        ah = (ah >> 1) | (dx & 1) << 7
        dx = (dx >> 1) | (bl & 1) << 15
        bl = (bl >> 1) | 0x80
    return _rouns(bl, dx, ah, fac_exponent, fac_sign)


def fsubs(bxdx: bytes, fac: bytes) -> bytes | str:
    """``$FSUBS``: (BXDX) - (FAC)."""
    if fac[3] == 0:
        return bytes(bxdx)
    return fadds(bxdx, bytes((fac[0], fac[1], fac[2] ^ 0x80, fac[3])))


def _norms(bl: int, dx: int, ah: int, exponent: int, sign: int) -> bytes | str:
    """``$NORMS``: shift BL:DX:AH left until BL's top bit is set (a byte at a time while BL
    is 0, at most 4 times; an exponent that would reach 0 or below gives 0)."""
    bh = exponent
    count = 4
    while True:
        if bl & 0x80:
            return _rouns(bl, dx, ah, bh, sign)
        if bl:
            whole = (bl << 24 | dx << 8 | ah) << 1
            bl, dx, ah = (whole >> 24) & 0xFF, (whole >> 8) & 0xFFFF, whole & 0xFF
            bh -= 1
            if bh == 0:
                return bytes(4)
            continue
        bh -= 8
        if bh <= 0:
            return bytes(4)
        bl, dx, ah = dx >> 8, ((dx & 0xFF) << 8) | ah, 0
        count -= 1
        if count == 0:
            return bytes(4)


def _rouns(bl: int, dx: int, ah: int, exponent: int, sign: int) -> bytes | str:
    """``$ROUNS``: keep the guard byte's top three bits, add 0x80; on a carry add one to
    the mantissa, clearing its low bit where the guard byte was exactly 0x80 (half to even)."""
    ah &= 0xE0
    ah += 0x80
    if ah > 0xFF:
        tie = (ah & 0xFF) == 0
        dx = (dx + 1) & 0xFFFF
        if dx:
            if tie:
                dx &= 0xFFFE
        else:
            bl = (bl + 1) & 0xFF
            if bl == 0:
                bl = 0x80
                exponent += 1
                if exponent > 0xFF:
                    return OVERFLOW
    return bytes((dx & 0xFF, dx >> 8, (bl & 0x7F) | (sign & 0x80), exponent))


def add(a: float, b: float) -> float:
    """``a + b`` of two singles (floats), as ``$FADDS`` with ``a`` in the FAC; an overflow
    (only two operands of one sign can overflow) an infinity of their sign."""
    r = fadds(to_mbf(b), to_mbf(a))
    return copysign(inf, a) if r == OVERFLOW else from_mbf(r)


def subtract(a: float, b: float) -> float:
    """``a - b``, as ``$FSUBS`` (which negates the FAC, here ``b``, and adds)."""
    r = fsubs(to_mbf(a), to_mbf(b))
    return copysign(inf, a) if r == OVERFLOW else from_mbf(r)


def exact(a: float, b: float) -> Fraction:
    """The exact sum, for comparisons."""
    return Fraction(a) + Fraction(b)
