"""GW-BASIC's number model at run time: 16-bit integers, single and double precision.

The compiled code of a typed dialect (``Dialect.typed_numbers``) calls these.
A value's Python type carries its BASIC type where the printed text depends on it:

* ``%`` integer: a Python ``int`` in -32768..32767.  ``+ - *`` of two integers
  that leave that range give a single-precision result (GW-BASIC does the same:
  ``PRINT 200*200`` shows 40000); storing a value outside it in an integer
  variable, or using it where an integer is needed (``\\``, ``MOD``, ``AND``
  ...), is ``Overflow``.
* ``!`` single precision: a Python ``float`` holding a 24-bit mantissa exactly
  (GW-BASIC's Microsoft Binary Format); every single-precision result is rounded
  as GW-BASIC's routines round (:mod:`yaseer.basic.arithmetic.single_arith`).  MBF's range
  ends at 1.7E+38 (IEEE's at 3.4E+38): beyond it a result is Overflow.
* ``#`` double precision: a Python ``float`` (53-bit mantissa; MBF doubles have
  56, so the 16th digit may differ), within :data:`DOUBLE_LARGEST` (MBF's range;
  ``+ - * /`` results beyond it go to the overflow policy through ``_dk``).  Wrapped in :class:`Double` only on its
  way to PRINT or STR$, so that it shows 16 digits and ``D`` exponents.

Rounding to an integer (CINT, assignment to ``%``) is half away from zero, as
GW-BASIC (checked with PC-BASIC: ``CINT(2.5)`` is 3, ``CINT(-2.5)`` is -3).
"""

from __future__ import annotations

import functools
import math
import struct
from collections import namedtuple

from yaseer.basic.arithmetic import mbf_digits, mbf_double, mbf_double_using, single_arith
from yaseer.basic.errors import BasicError, DIVISION_BY_ZERO, OVERFLOW

INT_MIN, INT_MAX = -32768, 32767
SINGLE_DIGITS = 7  # significant digits PRINT shows of a single-precision number
DOUBLE_DIGITS = 16  # ... of a double-precision number

_SINGLE = struct.Struct("f")
_pack, _unpack = _SINGLE.pack, _SINGLE.unpack

SINGLE_LARGEST = (1 - 2.0 ** -24) * 2.0 ** 127  # 1.701412E+38, the end of MBF's single range
# MBF's double range ends there too, at (1 - 2**-56) * 2**127, whose nearest Python
# float is 2**127 (printed 1.701411834604692D+38, as GW-BASIC prints it)
DOUBLE_LARGEST = 2.0 ** 127
MBF_SMALLEST = 2.0 ** -128  # the least MBF single or double (exponent byte 1); below it: 0


def to_single(x) -> float:
    """``x`` rounded to the nearest IEEE single-precision value (as a Python float).

    Beyond GW-BASIC's single range (MBF: 1.701412E+38) the result is infinite; the
    compiled code's overflow checks (``x - x``) pass that to the dialect's overflow
    policy (yaseer/basic/arithmetic/arith_policy.py).
    """
    try:
        r = _unpack(_pack(x))[0]
    except OverflowError:  # beyond IEEE single too
        return math.copysign(math.inf, x)
    if -SINGLE_LARGEST <= r <= SINGLE_LARGEST or r != r:
        return r
    return math.copysign(math.inf, r)


def single_literal(text: str, forced: bool = False) -> float:
    """The single GW-BASIC reads for a literal's digits ``text`` (``736.43455``, ``1.5E3``);
    ``forced``: the literal ends in ``!`` (``$FINS``), else zeros ending its fraction are
    left out (such a literal is a single only as PC-BASIC 2.0.8 counts its digits; the
    source's double made single gives the same value)."""
    digits, _, exponent = text.upper().replace("D", "E").partition("E")
    whole, _, fraction = digits.partition(".")
    if not forced:
        fraction = fraction.rstrip("0")
    mantissa = int(whole + fraction or "0")
    exp10 = int(exponent) if exponent.strip("+-") else 0
    return mbf_single(mantissa, exp10 - len(fraction)) if mantissa else 0.0


def mbf_single(mantissa: int, exp10: int) -> float:
    """The single GW-BASIC reads for the literal ``mantissa`` * 10 ** ``exp10``
    (``mantissa`` > 0: all the digits typed, as an integer), as ``$FIN`` makes it: up to
    seven digits the number so far is an exact single (MATH2.ASM ``$FIDIG``), from the
    eighth a double (mbf_double.from_decimal's steps) made single by ``$CSD``; the power
    of ten applied once in double precision (MATH1.ASM ``$FINE``/``MDPTEN``: times or
    divided by the table's 10**n, :func:`mbf_double.scaled_by_power_of_ten`) and made
    single by ``$CSD`` (the 25th bit rounds up: ``720E8`` is 72000004096, where the
    nearest single to the exact value, a tie, is even below it).  Beyond the range: an
    infinity (the caller's Overflow)."""
    try:
        if mantissa < 10_000_000:
            p = mbf_double.from_integer(mantissa)
        else:
            p = mbf_double.single_rounded(mbf_double.from_decimal(mantissa, 0))
        if exp10:
            p = mbf_double.single_rounded(mbf_double.scaled_by_power_of_ten(p, exp10))
    except mbf_double.Overflow:
        return math.inf
    return mbf_double.nearest_float(p)


def _overflow() -> BasicError:
    return BasicError("Overflow", OVERFLOW)


def int_result(x):
    """The result of ``+ - *`` (or unary minus, ABS) on integers: ``x`` itself when it
    fits in 16 bits, else ``x`` as single precision (GW-BASIC multiplies integers in
    single precision: a product beyond 24 bits rounds as ``$FMULS``; a sum is exact)."""
    if INT_MIN <= x <= INT_MAX:
        return x
    return single_arith.product(float(x))


def nearest_integer(x) -> int:
    """``x`` rounded half away from zero, exactly: GW's CINT (MATH2.ASM ``$CINC``/``$CIND``)
    shifts the magnitude's whole part out of the mantissa and adds the last bit shifted
    out, the one worth a half, so only the value decides (a double within a 56th bit
    below a half rounds down).  ``x + 0.5`` rounded first would round up
    .49999999999999994 (IEEE) or a :class:`Wide` just below a half (56 bits)."""
    if type(x) is Wide:
        negative, exponent, mantissa = x.parts
        shift = 184 - exponent
        whole = mantissa << -shift if shift <= 0 else (mantissa + (1 << (shift - 1))) >> shift
        return -whole if negative else whole
    if x >= 0.5:  # x + 0.5 is exact below 2**52, or rounds without passing a whole number
        return int(x + 0.5)
    if x > -0.5:
        return 0
    return -int(-x + 0.5)


def to_int(x) -> int:
    """CINT: ``x`` rounded half away from zero (:func:`nearest_integer`); ``Overflow``
    outside -32768..32767."""
    if type(x) is int:
        if INT_MIN <= x <= INT_MAX:
            return x
        raise _overflow()
    if x != x:
        raise _overflow()
    r = nearest_integer(x)
    if INT_MIN <= r <= INT_MAX:
        return r
    raise _overflow()


def int_divide(a, b) -> int:
    """``a \\ b``: both rounded to integers, the quotient truncated toward zero."""
    x, y = to_int(a), to_int(b)
    if y == 0:
        raise BasicError("Division by zero", DIVISION_BY_ZERO)
    q = abs(x) // abs(y)
    return to_int(q if (x >= 0) == (y >= 0) else -q)  # -32768 \ -1 is Overflow


def int_modulo(a, b) -> int:
    """``a MOD b``: both rounded to integers; the remainder has the sign of ``a``."""
    x, y = to_int(a), to_int(b)
    if y == 0:
        raise BasicError("Division by zero", DIVISION_BY_ZERO)
    return int(math.fmod(x, y))


def logical_and(a, b) -> int:
    return to_int(a) & to_int(b)


def logical_or(a, b) -> int:
    return to_int(a) | to_int(b)


def logical_xor(a, b) -> int:
    return to_int(a) ^ to_int(b)


def logical_eqv(a, b) -> int:
    return ~(to_int(a) ^ to_int(b))


def logical_imp(a, b) -> int:
    return ~to_int(a) | to_int(b)


def logical_not(a) -> int:
    return ~to_int(a)


def int_range(start: int, limit, step: int):
    """The values of an integer FOR variable (the first pass is known to run)."""
    if step > 0:
        return range(start, math.floor(limit) + 1, step)
    return range(start, math.ceil(limit) - 1, step)


def sign(x) -> int:
    return 1 if x > 0 else (-1 if x < 0 else 0)


def stepped(name: str, value, step):
    """A FOR variable ``name`` of ``value`` after ``+ step``, in its type (``I!`` single, ``I%`` integer
    with Overflow past 32767; an untyped casio name unchanged)."""
    last = name[-1]
    if last == "!":
        return single_arith.add(value, step)
    return to_int(value + step) if last == "%" else value + step


class Double(float):
    """A double-precision value on its way to PRINT or STR$ (shows 16 digits, ``D``)."""

    __slots__ = ()


def double_parts(x) -> tuple[bool, int, int]:
    """A double's exact 56-bit value (mbf_double's parts): a :class:`Wide`'s own, else
    the float's (an integer's or a single's value is exact in it; 2**127, the policy's
    largest double, stands for MBF's largest)."""
    return x.parts if type(x) is Wide else mbf_double.parts(x)


def double_of(p: tuple[bool, int, int]) -> float:
    """A double result from its 56-bit value: a float where one holds it (whole numbers
    and short binary fractions), else a :class:`Wide`."""
    if not p[2] & 7:
        return mbf_double.nearest_float(p)
    wide = Wide(mbf_double.nearest_float(p))
    wide.parts = p
    return wide


def _low_bits(shift: int) -> list[int]:
    """The 6 low bits ``$SHRA``'s bit steps leave after ``shift`` (1..7) steps, for each
    value of the register's low ``6 + shift`` bits (the bits above move down untouched):
    each step shifts right one bit and sets bit 5, the sticky bit ST, when bit 4 is 1."""
    table = []
    for low in range(64 << shift):
        register = low
        for _ in range(shift):
            register >>= 1
            if register & 0x10:
                register |= 0x20
        table.append(register & 0x3F)
    return table


# $SHRA's byte steps keep of each dropped byte its bit 5 only: the bits of the register
# that set ST after ``n`` byte steps; its bit steps by table (built at a shift's first use).
_BYTE_STICKY = [sum(0x20 << 8 * k for k in range(n)) for n in range(8)]
_LOW_BITS: list = [None] * 8


def double_operations(overflow, by_zero):
    """The double ``+ - * /`` (``_dad _dsb _dml _ddv``) of two operands (floats, which
    every double yaseer holds is exactly, or :class:`Wide`), each mbf_double's routine
    (``$FADDD``, ``$FSUBD``, ``$FMULD``, ``$FDIVD``) on the exact 56-bit values written
    out in one frame: they run on every fractional double of a gw program, where a call
    costs more than the work (tests/test_mbf_double.py holds them to the routines bit for
    bit).  Two floats whose exact result a float holds inside MBF's range take a float
    path first (no routine rounds anything there).  A result beyond the range is
    ``overflow(negative)``, one below it 0; a division by 0 is ``by_zero(a)``."""
    frexp, parts, wide = math.frexp, mbf_double.parts, Wide
    scale = [2.0 ** (exponent - 184) for exponent in range(256)]
    two56, limit, tiny, split = 2.0 ** 56, 2.0 ** 127, 2.0 ** -128, 134217729.0
    byte_sticky, low_bits = _BYTE_STICKY, _LOW_BITS

    known: dict = {}  # the parts of the first floats seen (a program's constants among them)

    def operand(x):
        """A float's parts (mbf_double.parts, the common case written out)."""
        p = known.get(x)
        if p is None:
            m, e = frexp(x)
            if -128 < e < 128 and m:
                p = (True, e + 128, int(-m * two56)) if m < 0 else (False, e + 128, int(m * two56))
            else:
                p = parts(x)
            if len(known) < 256:
                known[x] = p
        return p

    def made(negative: bool, exponent: int, mantissa: int):
        """The result (values.double_of) of a rounded mantissa."""
        if exponent > 255:
            return overflow(negative)
        if exponent <= 0:
            return 0.0
        value = mantissa * scale[exponent]  # (the int made a float, rounded half to even, then scaled exactly)
        if negative:
            value = -value
        if not mantissa & 7:
            return value
        result = wide(value)
        result.parts = (negative, exponent, mantissa)
        return result

    def nearest(negative: bool, exponent: int, mantissa: int, rest: int, half: int):
        """The result of a mantissa with ``rest`` below it (``half`` its half unit),
        rounded half to even (mbf_double._nearest)."""
        if rest > half or (rest == half and mantissa & 1):
            mantissa += 1
            if mantissa >> 56:
                mantissa >>= 1
                exponent += 1
        return made(negative, exponent, mantissa)

    def add(a, b, flip: bool = False):
        if type(a) is not wide and type(b) is not wide:
            s = a - b if flip else a + b  # exact when both operands come back (Dekker)
            if ((s + b == a and a - s == b) if flip else (s - a == b and s - b == a)) and (
                    tiny <= s < limit or -limit < s <= -tiny or not s):
                return s
            na, ea, ma = operand(a)
            nb, eb, mb = operand(b)
        else:
            na, ea, ma = a.parts if type(a) is wide else operand(a)
            nb, eb, mb = b.parts if type(b) is wide else operand(b)
        if flip:
            nb = not nb
        if not eb:
            return made(na, ea, ma) if ea else 0.0
        if not ea:
            return made(nb, eb, mb)
        if ea < eb:
            na, ea, ma, nb, eb, mb = nb, eb, mb, na, ea, ma
        shift = ea - eb
        if shift >= 57:
            return made(na, ea, ma)
        register, other = ma << 8, mb << 8
        if shift >= 8:  # $SHRA
            other = (other >> (shift & ~7)) | (0x20 if other & byte_sticky[shift >> 3] else 0)
            shift &= 7
        if shift:
            table = low_bits[shift]
            if table is None:
                table = low_bits[shift] = _low_bits(shift)
            other = (other >> shift) & ~0x3F | table[other & ((64 << shift) - 1)]
        if na == nb:
            register += other
            if register >> 64:
                register >>= 1
                ea += 1
        else:
            register -= other
            if register < 0:
                register, na = -register, not na
            if not register:
                return 0.0
            shift = 64 - register.bit_length()  # $NORMD
            register <<= shift
            ea -= shift
        register += 0x80  # $ROUND
        if register >> 64:
            register >>= 1
            ea += 1
        mantissa = register >> 8
        if not register & 0xFF:
            mantissa &= ~1
        return made(na, ea, mantissa)

    def subtract(a, b):
        return add(a, b, True)

    def multiply(a, b):
        if type(a) is not wide and type(b) is not wide:
            p = a * b  # exact when both factors have at most 26 bits (Veltkamp's split)
            if (a == (c := a * split) - (c - a) and b == (c := b * split) - (c - b)
                    and (tiny <= p < limit or -limit < p <= -tiny or not p)):
                return p
        na, ea, ma = a.parts if type(a) is wide else operand(a)
        nb, eb, mb = b.parts if type(b) is wide else operand(b)
        if not ea or not eb:
            return 0.0
        product = ma * mb  # 2**110 .. 2**112
        if product >> 111:
            exponent, mantissa, rest, half = ea + eb - 128, product >> 56, product & 0xFFFFFFFFFFFFFF, 1 << 55
        else:
            exponent, mantissa, rest, half = ea + eb - 129, product >> 55, product & 0x7FFFFFFFFFFFFF, 1 << 54
        return nearest(na != nb, exponent, mantissa, rest, half)

    def divide(a, b):
        if type(a) is not wide and type(b) is not wide:
            if not b:
                return by_zero(a)
            q = a / b  # exact when the quotient and the divisor have at most 26 bits and give a back
            if (q * b == a and q == (c := q * split) - (c - q) and b == (c := b * split) - (c - b)
                    and (tiny <= q < limit or -limit < q <= -tiny or not q)):
                return q
        na, ea, ma = a.parts if type(a) is wide else operand(a)
        nb, eb, mb = b.parts if type(b) is wide else operand(b)
        if not eb:
            return by_zero(a)
        if not ea:
            return 0.0
        quotient, rest = divmod(ma << 64, mb)  # 64 or 65 bits, then the remainder as a sticky bit
        if quotient >> 64:
            exponent, mantissa, rest = ea - eb + 129, quotient >> 9, (quotient & 0x1FF) << 1 | (rest != 0)
            half = 0x200
        else:
            exponent, mantissa, rest = ea - eb + 128, quotient >> 8, (quotient & 0xFF) << 1 | (rest != 0)
            half = 0x100
        return nearest(na != nb, exponent, mantissa, rest, half)

    return add, subtract, multiply, divide


def _infinity(negative: bool) -> float:
    return -math.inf if negative else math.inf


def _no_quotient(a) -> float:
    raise ZeroDivisionError("division by zero")




class Wide(Double):
    """A double whose 56-bit MBF value (``parts``) no float holds.  As a float it is the
    nearest one (what functions that take a float see); ``+ - * /``, comparisons, INT,
    FIX and ``int()`` work on the exact value."""

    __slots__ = ("parts",)

    def __add__(self, other):
        return double_add(self, other)

    def __radd__(self, other):
        return double_add(other, self)

    def __sub__(self, other):
        if other is self:  # the compiled code's overflow test, ``x - x``: 0 for any finite value
            return 0.0
        return double_subtract(self, other)

    def __rsub__(self, other):
        return double_subtract(other, self)

    def __mul__(self, other):
        return double_multiply(self, other)

    def __rmul__(self, other):
        return double_multiply(other, self)

    def __truediv__(self, other):
        return double_divide(self, other)

    def __rtruediv__(self, other):
        return double_divide(other, self)

    def __neg__(self):
        return double_of(mbf_double.negate(self.parts))

    def __pos__(self):
        return self

    def __abs__(self):
        return double_of((False,) + self.parts[1:])

    def _compared(self, other):
        """-1, 0 or 1 against a number; None against an infinity or NaN (compared as floats)."""
        if type(other) is not Wide and not -math.inf < other < math.inf:
            return None
        return mbf_double.compare(self.parts, double_parts(other))

    def __eq__(self, other):
        if not isinstance(other, (int, float)):
            return False
        c = self._compared(other)
        return float.__eq__(self, other) if c is None else c == 0

    def __ne__(self, other):
        return not self.__eq__(other)

    def __lt__(self, other):
        c = self._compared(other)
        return float.__lt__(self, other) if c is None else c < 0

    def __le__(self, other):
        c = self._compared(other)
        return float.__le__(self, other) if c is None else c <= 0

    def __gt__(self, other):
        c = self._compared(other)
        return float.__gt__(self, other) if c is None else c > 0

    def __ge__(self, other):
        c = self._compared(other)
        return float.__ge__(self, other) if c is None else c >= 0

    __hash__ = float.__hash__

    def _whole(self) -> tuple[int, bool]:
        """The magnitude's whole part and whether a fraction is left."""
        _, exponent, mantissa = self.parts
        shift = 184 - exponent
        if shift <= 0:
            return mantissa << -shift, False
        return mantissa >> shift, bool(mantissa & ((1 << shift) - 1))

    def __trunc__(self):
        whole, _ = self._whole()
        return -whole if self.parts[0] else whole

    __int__ = __trunc__

    def __floor__(self):
        whole, fraction = self._whole()
        return -whole - fraction if self.parts[0] else whole

    def __ceil__(self):
        whole, fraction = self._whole()
        return -whole if self.parts[0] else whole + fraction


# Beyond the range an infinity with its sign (the compiled code's checks hand it to the
# overflow policy); by 0 ZeroDivisionError (for the caller's policy).
double_add, double_subtract, double_multiply, double_divide = double_operations(_infinity, _no_quotient)


def double_from_decimal(whole: str, fraction: str, exponent: int) -> float:
    """The double GW's number reader gives the decimal ``whole.fraction E exponent``
    (digit strings; mbf_double.from_decimal, ``$FIN``'s steps): a float or a
    :class:`Wide`; beyond the range an infinity."""
    try:
        return double_of(mbf_double.from_decimal(int(whole + fraction or "0"), exponent - len(fraction)))
    except mbf_double.Overflow:
        return math.inf


class NumberReading(namedtuple("NumberReading", "largest from_digits")):
    """How VAL, INPUT, READ and the other readers of typed numbers read digits where the
    range is not IEEE's: ``largest`` is the range's end (beyond it an infinity of the
    number's sign, which the caller hands to the dialect's overflow policy), and
    ``from_digits(whole, fraction, exponent)`` the value the digits name in the machine's
    own number format.  A dialect without one reads the IEEE double the digits name and
    calls a number beyond 1.8E+308 ``Overflow``."""

    __slots__ = ()

    def __repr__(self) -> str:  # the same in every process: it keys the compiled-program cache
        return f"NumberReading({self.largest!r}, {self.from_digits.__module__}.{self.from_digits.__qualname__})"


MBF_READING = NumberReading(DOUBLE_LARGEST, double_from_decimal)  # GW's $FIN, up to 2**127


@functools.lru_cache(maxsize=4096)
def wide_literal(data: str) -> float:
    """A double literal's value from its 8 MBF bytes in hexadecimal (``_wd`` in the
    compiled code, where a Wide literal cannot be a Python constant)."""
    return double_of(mbf_double.from_bytes(bytes.fromhex(data)))


def single_of_double(x) -> float:
    """A double made single (``$CSD``: its top 24 bits, rounded up when the 25th is 1),
    from a :class:`Wide`'s 56 bits (single_arith.from_double for a float)."""
    if type(x) is not Wide:
        return single_arith.from_double(x)
    negative, exponent, mantissa = x.parts
    r = math.ldexp((mantissa >> 32) + (mantissa >> 31 & 1), exponent - 152)
    if r >= single_arith.LIMIT:
        return -math.inf if negative else math.inf
    return -r if negative else r


def _whole_double(whole: int) -> float:
    """A whole number of at most 56 significant bits as a double (a float below 2**53, else
    :func:`double_of` of its exact parts)."""
    if -9007199254740992 <= whole <= 9007199254740992:
        return float(whole)
    return double_of(mbf_double.from_integer(whole))


def whole_floor(x) -> float:
    """INT of a single or a double: the largest whole number not above ``x``, on a
    :class:`Wide`'s 56 bits (MATH2.ASM ``$DINT``: the fraction's bits shifted out of the
    mantissa, a negative number's magnitude less 1 first and plus 1 after), so that
    ``INT(2#^55 + 1)`` keeps its last bit."""
    if type(x) is Wide:
        return _whole_double(math.floor(x))
    return float(math.floor(x))


def whole_fix(x) -> float:
    """FIX: ``x`` with its fraction dropped, on a :class:`Wide`'s 56 bits (MATH1.ASM
    ``FIXER``: INT of the magnitude, the sign put back)."""
    if type(x) is Wide:
        return _whole_double(math.trunc(x))
    return float(math.trunc(x))


def printed_double(x) -> "Double":
    """A double on its way to PRINT or STR$ (``_dbl``): a Wide as it is, a float marked."""
    return x if type(x) is Wide else Double(x)


def _single_digits(x: float) -> tuple[str, int]:
    """``abs(x)`` (single precision) to 7 significant digits as GW-BASIC's ``$FOFMT``
    finds them (:func:`yaseer.basic.arithmetic.mbf_digits.decimal_digits`: ``$FOTNV``'s
    table of powers of ten in double precision, ``$CSD`` after each, ``$FOTCV``'s half
    added: ``1/3`` shows as ``.3333334``, ``ATN(1.5)`` as ``.9827938``).  Returns (digit
    string without trailing zeros, exponent of the first digit)."""
    return mbf_digits.digit_string(x)


def _double_digits(x: float) -> tuple[str, int]:
    """``abs(x)`` (double precision) to at most 16 significant digits as GW's output
    routine finds them from the 56 bits (MATH1.ASM ``$FOFMT``: ``$FOTNV``'s bracket by its
    table of powers of ten, ``$FOTCV``'s half added, :func:`mbf_double_using.printed_digits`):
    a :class:`Wide`'s own, a float's exactly (every double yaseer holds is an MBF value:
    read to the nearest 56 bits, or the result of GW's routines).  ``CDBL(1.1)`` is
    1.100000023841858, ``1# / 3`` .3333333333333333, ``12345670# / 3`` 4115223.333333333."""
    p = x.parts if type(x) is Wide else mbf_double.parts(x)
    n, power = mbf_double_using.printed_digits(p)
    return str(n).rstrip("0") or "0", power + len(str(n)) - 1


def unsigned_text(x, digits: int, marker: str) -> str:
    """``abs(x)`` as GW-BASIC's PRINT shows a number with ``digits`` (7 or 16) significant digits.

    Fixed notation unless the number needs more than ``digits`` places before the
    point or more than ``digits + 1`` after it; E (D for doubles) notation is
    ``1.5E+12``.  No leading zero: ``.5``.
    """
    if x == 0:
        return "0"
    d, e = _single_digits(x) if digits == SINGLE_DIGITS else _double_digits(x)
    if e >= digits or len(d) - e > digits + 1:
        mantissa = d[0] + ("." + d[1:] if len(d) > 1 else "")
        return f"{mantissa}{marker}{'-' if e < 0 else '+'}{abs(e):02d}"
    point = e + 1
    if point >= len(d):
        return d + "0" * (point - len(d))
    if point > 0:
        return d[:point] + "." + d[point:]
    return "." + "0" * (-point) + d


def str_dollar(x) -> str:
    """STR$ of a typed value: sign or space, then the digits of its type."""
    if type(x) is int:
        return str(x) if x < 0 else " " + str(x)
    if not math.isfinite(x):
        raise _overflow()
    sign_text = "-" if x < 0 else " "
    if type(x) is Double or type(x) is Wide:
        return sign_text + unsigned_text(x, DOUBLE_DIGITS, "D")
    return sign_text + unsigned_text(x, SINGLE_DIGITS, "E")


def number_to_text(x) -> str:
    """How PRINT shows a typed number: STR$ form plus a trailing space."""
    return str_dollar(x) + " "


# The names the typed compiled code calls (merged into the machine's namespace over
# the plain ones; see number_models.TypedNumbers for which code uses which).
RUNTIME = {
    "_ia": int_result, "_ci": to_int, "_dbl": printed_double, "_wd": wide_literal, "_WD": Wide, "_irange": int_range,
    "_idiv": int_divide, "_mod": int_modulo, "_and": logical_and, "_or": logical_or,
    "_xor": logical_xor, "_eqv": logical_eqv, "_imp": logical_imp, "_not": logical_not,
    "_sgn": sign, "_len": len, "_strs": str_dollar, "_floor": whole_floor, "_fix": whole_fix,
    "_cint": to_int, "_csng": single_arith.from_double, "_cdbl": float,
    "_sadd": single_arith.add, "_ssub": single_arith.subtract, "_sp": single_arith.product,
    "_spb": single_arith.product_near_half,
    "_sfd": single_arith.from_double, "_sfn": single_arith.function_result,
}
