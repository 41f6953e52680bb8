"""GW-BASIC's string and conversion functions, for both dialects (the clock's: clock.py).

Strings are Python ``str`` whose characters stand for bytes (``chr(0)``..``chr(255)``).
Numbers come in and go out as Python floats.  Errors are GW-BASIC's: a count or
character code out of range is ``Illegal function call``, a value that does not fit
its integer or binary format ``Overflow``.

Also here: :func:`read_number`, the one reader of numbers typed as text (VAL, INPUT,
READ of DATA items), which follows GW-BASIC's rules and not Python's float syntax
(``"1_2"``, ``"inf"``, ``"nan"`` are not numbers).
"""

from __future__ import annotations

import math

from yaseer.basic.arithmetic import mbf_double, values
from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL, OVERFLOW
from yaseer.basic.machine.runtime import cint
from yaseer.patterns import Pattern

TYPE_CHECKING = False
if TYPE_CHECKING:
    from yaseer.basic.arithmetic.values import NumberReading

_MAX_DOUBLE = 1.7976931348623157e308


def _illegal() -> BasicError:
    return BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)


def _overflow() -> BasicError:
    return BasicError("Overflow", OVERFLOW)


def _count(n: float, low: int = 0, high: int = 255) -> int:
    """A count or code argument: made a 16-bit integer first (beyond -32768..32767
    Overflow: GETBYT calls FRCINT before it checks the byte, MATH1.ASM CONINT), then
    ``low``..``high`` or Illegal function call."""
    k = cint(n)
    if not low <= k <= high:
        raise _illegal() if -32768 <= k <= 32767 else _overflow()
    return k


def byte_argument(n: float, low: int = 0) -> int:
    """A statement's byte argument as GETBYT reads it (MID$'s start, ``low`` 1, and count;
    INPUT$'s count): ``low``..255, else Illegal function call (Overflow beyond a 16-bit
    integer)."""
    return _count(n, low)


def _integer(n: float) -> int:
    """A 16-bit integer argument (-32768..32767), else Overflow."""
    k = cint(n)
    if not -32768 <= k <= 32767:
        raise _overflow()
    return k


# ------------------------------------------------------------------ strings


def instr(*args) -> float:
    """INSTR([start,] s, t): the 1-based position of t in s from ``start``, 0 if absent.

    An empty t is found at ``start`` when start <= LEN(s) (GW-BASIC); start 1..255.
    """
    start, s, t = args if len(args) == 3 else (1.0, *args)
    k = _count(start, 1, 255)
    if k > len(s):
        return 0.0
    return float(s.find(t, k - 1) + 1)


def string_dollar(n: float, fill) -> str:
    """STRING$(n, code) or STRING$(n, s): n copies of a character (s: its first)."""
    k = _count(n)
    if isinstance(fill, str):
        return fill[:1] * k  # an empty string gives "" (PC-BASIC)
    return chr(_count(fill)) * k


def space_dollar(n: float) -> str:
    return " " * _count(n)


# LEFT$ RIGHT$ MID$ CHR$ with GW's byte arguments (0..255; the Casio's take any count)
def left_dollar(s: str, n: float) -> str:
    return s[:_count(n)]


def right_dollar(s: str, n: float) -> str:
    return s[max(len(s) - _count(n), 0):]


def mid_dollar(s: str, start: float, n: float | None = None) -> str:
    i = _count(start, 1)
    return s[i - 1:] if n is None else s[i - 1:i - 1 + _count(n)]


def chr_dollar(n: float) -> str:
    return chr(_count(n))


BYTE_ARGUMENTS = {"_left": left_dollar, "_right": right_dollar, "_mid": mid_dollar, "_chr": chr_dollar}


def _unsigned_word(n: float) -> int:
    """HEX$/OCT$ argument: -65536..65535, taken modulo 2^16 (-1 is FFFF)."""
    k = cint(n)
    if not -65536 <= k <= 65535:
        raise _overflow()
    return k & 0xFFFF


def hex_dollar(n: float) -> str:
    return format(_unsigned_word(n), "X")


def oct_dollar(n: float) -> str:
    return format(_unsigned_word(n), "o")


# ------------------------------------------------------------------ binary formats
# MKI$: a 16-bit two's-complement integer, low byte first.  MKS$ / MKD$: Microsoft
# Binary Format, the mantissa's bytes low first, then the exponent byte:
#   value = 0.1mmm...(binary) * 2^(exponent - 128), the mantissa's leading 1 not
#   stored (its place holds the sign bit); exponent byte 0 means the value 0.
# Single: 24-bit mantissa (3 bytes), double: 56-bit mantissa (7 bytes).


def _bytes_to_str(data) -> str:
    return "".join(map(chr, data))


def _str_to_bytes(s: str, size: int) -> bytes:
    if len(s) < size:
        raise _illegal()
    return bytes(ord(ch) & 0xFF for ch in s[:size])


def mki(n: float) -> str:
    return _bytes_to_str(_integer(n).to_bytes(2, "little", signed=True))


def cvi(s: str) -> float:
    return float(int.from_bytes(_str_to_bytes(s, 2), "little", signed=True))


def _to_mbf(x: float, mantissa_bits: int) -> bytes:
    """``x`` in Microsoft Binary Format with a ``mantissa_bits`` mantissa (rounded half up).
    A zero is all zero bytes; -0.0 has the sign bit (see :func:`_signed_zero`)."""
    size = mantissa_bits // 8 + 1
    if x == 0:
        return _signed_zero(x, size)
    m, e = math.frexp(abs(x))  # abs(x) = m * 2**e, 0.5 <= m < 1
    mantissa = math.floor(m * 2 ** mantissa_bits + 0.5)
    if mantissa >= 2 ** mantissa_bits:  # rounding carried into a new leading bit
        mantissa >>= 1
        e += 1
    exponent = e + 128
    if exponent > 255:
        raise _overflow()
    if exponent <= 0:
        return bytes(size)  # below the smallest MBF number: 0
    mantissa &= ~(1 << (mantissa_bits - 1))  # the implicit leading 1 ...
    if x < 0:
        mantissa |= 1 << (mantissa_bits - 1)  # ... makes room for the sign
    return mantissa.to_bytes(size - 1, "little") + bytes((exponent,))


def _signed_zero(x: float, size: int) -> bytes:
    """The ``size`` bytes of zero ``x``: GW-BASIC negates a single or double by flipping its
    sign bit, a zero's too (MATH1.ASM ``$NEG``: XOR of the sign byte), so ``-Z!`` of a zero is
    a zero whose bytes hold the sign (MKS$ gives 00 00 80 00: the recorded unsorted/NEGZERO
    test of PC-BASIC's suite); yaseer's -0.0 is that zero, 0.0 the one with no sign."""
    if math.copysign(1.0, x) > 0:
        return bytes(size)
    return bytes(size - 2) + b"\x80\x00"


class HeldBytes(float):
    """A zero single or double whose other bytes are not a zero's: an exponent byte of 0 with
    mantissa bytes set, as CVS/CVD of any string or GET into a ``!`` or ``#`` array makes one.
    GW-BASIC keeps a variable's bytes as they came (CVS moves them into the accumulator,
    MATH1.ASM ``$FCVS``... an assignment copies them; GENGRP.ASM's GET writes the pixels'
    bytes into the array), and its arithmetic reads an exponent byte of 0 as 0 (``$FADDS``,
    ``$FOUT``...): the value is 0 (the sign bit's zero as :func:`_from_mbf` gives it) and MKS$,
    MKD$, PUT and PEEK give the bytes back (``raw``; a single's four made a double's eight by MATH2.ASM
    ``$CDS``, which zeroes the four bytes below), and negation flips the sign bit alone."""

    __slots__ = ("raw",)

    def __new__(cls, value: float, raw: bytes):
        held = super().__new__(cls, value)
        held.raw = raw
        return held

    def __neg__(self) -> "HeldBytes":
        """The sign bit flipped, the other bytes kept (MATH1.ASM ``$NEG`` XORs the sign byte)."""
        raw = bytearray(self.raw)
        raw[-2] ^= 0x80
        return HeldBytes(-float(self), bytes(raw))


def _zero_of(data: bytes) -> float:
    """The zero of bytes ``data`` whose exponent byte is 0 (the sign bit kept: CVS of MKS$(-Z!)):
    a plain zero where they are a zero's bytes, else a :class:`HeldBytes` keeping them."""
    zero = -0.0 if data[-2] & 0x80 else 0.0
    if data == _signed_zero(zero, len(data)):
        return zero
    return HeldBytes(zero, bytes(data))


def _from_mbf(data: bytes) -> float:
    exponent = data[-1]
    if exponent == 0:  # zero, whatever the mantissa (its bytes kept)
        return _zero_of(data)
    bits = 8 * (len(data) - 1)
    mantissa = int.from_bytes(data[:-1], "little")
    negative = mantissa >> (bits - 1)
    mantissa |= 1 << (bits - 1)
    value = math.ldexp(mantissa, exponent - 128 - bits)
    return -value if negative else value


def mks(x: float) -> str:
    if type(x) is HeldBytes and len(x.raw) == 4:
        return _bytes_to_str(x.raw)
    return _bytes_to_str(_to_mbf(x, 24))


def mkd(x: float) -> str:
    """MKD$: the 8 bytes of a double (a Wide's own 56 bits; -0.0's sign: :func:`_signed_zero`)."""
    if type(x) is HeldBytes:  # a single's bytes made a double's: four zero bytes below (MATH2.ASM $CDS)
        return _bytes_to_str(x.raw if len(x.raw) == 8 else bytes(4) + x.raw)
    if x == 0:
        return _bytes_to_str(_signed_zero(x, 8))
    return _bytes_to_str(mbf_double.to_bytes(values.double_parts(x)))


def cvs(s: str) -> float:
    return _from_mbf(_str_to_bytes(s, 4))


def cvd(s: str) -> float:
    """CVD: the double of 8 bytes, all 56 bits of it (a Wide where a float cannot hold them)."""
    data = _str_to_bytes(s, 8)
    if not data[7]:  # zero, its sign and bytes kept (as _from_mbf)
        return _zero_of(data)
    return values.double_of(mbf_double.from_bytes(data))


# ------------------------------------------------------------------ reading numbers

_BLANKS = " \t\n"
_DECIMAL = Pattern(r"([+-]?)(\d*)(?:\.([\d.]*))?")  # points after the first are skipped
_EXPONENT = Pattern(r"[ED]([+-]?)(\d*)")
_RADIX = {"H": (16, "0123456789ABCDEF"), "O": (8, "01234567")}


def read_number(text: str, reading: NumberReading | None = None) -> tuple[float, int]:
    """The number at the start of ``text`` as GW-BASIC reads it, and where it ends.

    Blanks (space, tab, line feed) anywhere in it are skipped (``"1 2"`` is 12);
    then an optional sign, digits with one optional point, an optional exponent
    ``E`` or ``D`` with sign and digits (an exponent without digits is 0), or
    ``&H`` hexadecimal / ``&O`` or ``&`` octal (16-bit, ``&HFFFF`` is -1).  Points
    after the first are skipped (``"1.2.3"`` is 1.23, as PC-BASIC reads it).  What
    follows the number is not read: ``"1_2"`` is 1.  No number at all is (0, 0).
    Without ``reading`` (the dialect's ``number_reading``) the value is the IEEE double
    the digits name and beyond its range ``Overflow``; with one (GW's: MBF_READING) the
    digits are read by its ``from_digits`` (GW's ``$FIN``: 56-bit MBF doubles) and a
    number beyond its ``largest`` is an infinity of its sign instead, which the caller
    passes to the dialect's overflow policy (yaseer/basic/arithmetic/arith_policy.py).
    """
    value, end, _, _ = _read(text, reading)
    return value, end


# CHR$(28), CHR$(29), CHR$(31): the bytes that mark a constant inside a tokenised line
# (GWMAIN.ASM INTCON, SNGCON, DBLCON), which the number reader's CHRGTR takes as such
_CONSTANT_TOKENS = frozenset("\x1c\x1d\x1f")


def val_typed(text: str, reading: NumberReading | None) -> tuple[float, str]:
    """VAL in gw: the number (:func:`read_number`) and its type as GW-BASIC's VAL gives
    them.  VAL reads with ``FINDBL`` (BISTRS.ASM VAL; MATH1.ASM ``$FINDB``, the reader's
    forced-double entry): a double, whatever the digits, exponent letter or ``#``
    (``VAL("1.1")`` is the double 1.1); only a ``!`` after the number makes it single
    (``$FINS``), whose value is the one GW's conversion gives (``values.single_literal``).
    ``&H``/``&O`` numbers are GW's integers (``OCTCNS``), kept as singles of the same value.
    Beyond the range infinite.  A decimal number followed by CHR$(28), CHR$(29) or
    CHR$(31) (blanks between allowed) is 0: the reader's CHRGTR meets an embedded
    constant's token there (GWMAIN.ASM ``CHRCON``), and a real GW-BASIC 3.23 gives 0
    (``VAL("1" + CHR$(28) + "2")``: the recorded unsorted/VAL test of PC-BASIC's suite;
    PC-BASIC 2.0.8 agrees)."""
    value, end, kind, literal = _read(text, reading)
    if not literal:
        return value, "!"
    after = text[end:].lstrip(_BLANKS)[:1]
    if after in _CONSTANT_TOKENS:
        return 0.0, "#"
    if after != "!":
        return value, "#"
    if 0.0 < abs(value) < math.inf:
        from yaseer.basic.arithmetic.values import single_literal, to_single

        value = math.copysign(to_single(single_literal(literal, forced=True)), value)
    return value, "!"


def _read(text: str, reading: NumberReading | None) -> tuple[float, int, str, str]:
    """(value, end, type, the decimal literal's digits as ``values.single_literal`` reads
    them, "" for ``&H``/``&O``) of the number at the start of ``text``."""
    packed, where = [], []  # the characters without blanks, and their positions
    for k, ch in enumerate(text):
        if ch not in _BLANKS:
            packed.append(ch.upper())
            where.append(k)
    s = "".join(packed)
    if s.startswith("&"):
        value, used = _read_radix(s)
        kind, literal = "!", ""
    else:
        value, used, kind, literal = _read_decimal(s, reading)
    end = where[used - 1] + 1 if used else 0
    return value, end, kind, literal


def _read_decimal(s: str, reading: NumberReading | None = None) -> tuple[float, int, str, str]:
    match = _DECIMAL.match(s)
    sign, whole, fraction = match.group(1), match.group(2), (match.group(3) or "").replace(".", "")
    if not whole and not fraction:
        return 0.0, 0, "!", ""
    used = match.end()
    exponent = 0
    found = _EXPONENT.match(s, used)
    if found:
        exponent = int(found.group(2) or "0") * (-1 if found.group(1) == "-" else 1)
        used = found.end()
    digits = (whole + fraction).lstrip("0") or "0"
    if digits != "0" and len(digits) - len(fraction) + exponent > 310:
        value = math.inf
    else:
        value = abs(float(f"{whole or '0'}.{fraction or '0'}e{max(min(exponent, 400), -400)}"))
        if 0.0 < value < math.inf and reading is not None:
            value = reading.from_digits(whole, fraction, exponent)
    if value > (_MAX_DOUBLE if reading is None else reading.largest):
        if reading is None:
            raise _overflow()
        value = math.inf
    from yaseer.basic.source.scanner import SINGLE_DIGITS, significant_digits

    after = s[used:used + 1]
    double = (found is not None and found.group(0)[0] == "D") or after == "#" or (
        after != "!" and significant_digits(whole, fraction) > SINGLE_DIGITS)
    literal = f"{whole or '0'}.{fraction}E{exponent}"
    return (-value if sign == "-" else value), used, "#" if double else "!", literal


def _read_radix(s: str) -> tuple[float, int]:
    used = 1
    base, digits = _RADIX["O"]
    if s[1:2] in _RADIX:
        base, digits = _RADIX[s[1]]
        used = 2
    start = used
    while used < len(s) and s[used] in digits:
        used += 1
    value = int(s[start:used], base) if used > start else 0
    if value > 0xFFFF:
        raise _overflow()
    return float(value - 0x10000 if value > 0x7FFF else value), used


def val(s: str, reading: NumberReading | None = None) -> float:
    """VAL: the number at the start of ``s`` (see :func:`read_number`), 0 if none."""
    return read_number(s, reading)[0]


def number_field(text: str, reading: NumberReading | None = None) -> float | None:
    """A whole INPUT or DATA field as a number, or None if it is not exactly one number
    (blanks around and inside it allowed; an empty field is 0; ``reading`` as in
    :func:`read_number`)."""
    if not text.strip(_BLANKS):
        return 0.0
    value, end = read_number(text, reading)
    if end == 0 or text[end:].strip(_BLANKS):
        return None
    return value


def mid_assign(target: str, start: float, count, value: str, overlapping: bool = False) -> str:
    """MID$(target, start[, count]) = value: ``target`` with characters from ``start``
    replaced by those of ``value`` (at most ``count``, never past the end of ``target``).

    ``overlapping``: the value is the target variable itself, whose bytes GW-BASIC copies
    one by one from its start while it overwrites them (BISTRS.ASM LHSMID, its loop
    MID$LP): ``MID$(A$, 3) = A$`` of "ABCDEFGH" is "ABABABAB", as PC-BASIC 2.0.8 prints."""
    i = _count(start, 1, 255)
    most = None if count is None else _count(count)
    if most == 0:  # LHSMID returns on a count of 0 before it compares start and length
        return target
    if i > len(target):
        raise _illegal()
    n = len(value) if most is None else min(most, len(value))
    n = min(n, len(target) - i + 1)
    if overlapping:
        cells = list(target)
        for k in range(n):
            cells[i - 1 + k] = cells[k]
        return "".join(cells)
    return target[:i - 1] + value[:n] + target[i - 1 + n:]


def logical_xor(a: float, b: float) -> float:
    return float(cint(a) ^ cint(b))


def logical_eqv(a: float, b: float) -> float:
    return float(~(cint(a) ^ cint(b)))


def logical_imp(a: float, b: float) -> float:
    return float(~cint(a) | cint(b))
