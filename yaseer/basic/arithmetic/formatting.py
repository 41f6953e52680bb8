"""How numbers and strings appear on the screen: PRINT, STR$ and PRINT USING.

Plain PRINT and STR$
--------------------
A number is shown with up to 10 significant digits (the 10-digit display of
the pocket computers), a leading space (or ``-``) and, for PRINT, a trailing
space.  The value is first rounded to 10 significant digits (round half to
even on the exact binary value, as Python's ``%.9e`` does); trailing zeros
are dropped.  With ``d`` the remaining significant digits and ``e`` the
decimal exponent of the first digit (``x = d.ddd * 10**e``), the number is
written in E notation when

* ``e >= 10`` (it would need more than 10 digits before the point), or
* ``len(d) - e > 11`` (it would need more than 11 places after the point),

which is MS-BASIC's rule with its 7 single-precision digits replaced by 10.
Fixed notation drops the leading zero (``.5``, ``-.0625``).  E notation is
``1.5E+12``: one digit, the point only if more digits follow, ``E``, a sign
and at least two exponent digits (``1E-100`` for very small doubles; GW-BASIC
would write ``D`` for a double, yaseer always writes ``E``).

PRINT USING
-----------
Microsoft BASIC semantics.  The format string is a sequence of literal text
and fields:

* numeric: ``#`` digit positions, ``.`` the decimal point, ``,`` (left of the
  point) thousands separators, a leading ``+`` (sign always shown) or a
  trailing ``+`` / ``-`` (sign after the number), ``**`` asterisk fill,
  ``$$`` floating dollar sign, ``**$`` both, ``^^^^`` / ``^^^^^`` E notation
  with two / three exponent digits.  ``###.###.##`` is the two fields
  ``###.###`` and ``.##``.
* string: ``!`` first character, ``\\  \\`` (n spaces) the first n+2
  characters padded with spaces, ``&`` the whole string.
* ``_`` prints the next character literally; any other character is literal.

A number too wide for its field is printed in full after a ``%``.  The format
is reused from its start while values remain; output stops at the first field
after the last value.  A string for a numeric field (or a number for a string
field) is ``Type mismatch``; a format without any field is ``Illegal function
call``.  Rounding is half away from zero on the shortest decimal text that
reads back as the same double (``repr``), so ``2.675`` shows as ``2.68`` as
the user who typed it expects.
"""

from __future__ import annotations

import math
from functools import lru_cache
from collections import namedtuple  # the format's fields (not dataclasses or typing: start-up time)

from yaseer.basic.errors import ILLEGAL_FUNCTION_CALL, OVERFLOW, TYPE_MISMATCH, BasicError

SIGNIFICANT_DIGITS = 10  # a 10-digit pocket-computer display


TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from typing import Sequence, Union

    Value = Union[float, int, str]
    Token = Union["Literal", "StringField", "NumericField"]


# ---------------------------------------------------------------------------
# Plain PRINT and STR$
# ---------------------------------------------------------------------------

def _check_finite(x: float) -> None:
    """Infinite or NaN values cannot be shown: the period's ``Overflow``."""
    if not math.isfinite(x):
        raise BasicError("Overflow", OVERFLOW)


def _significant_digits(x: float, digits: int) -> tuple[str, int]:
    """``abs(x)`` rounded to ``digits`` significant digits, trailing zeros dropped.

    Returns ``(digit_string, exponent)`` with ``abs(x) ~ 0.d1d2... * 10 ** (exponent + 1)``,
    i.e. ``exponent`` is the power of ten of the first digit.  ``x`` is non-zero.
    """
    mantissa, exponent = f"{abs(x):.{digits - 1}e}".split("e")
    digit_string = mantissa.replace(".", "").rstrip("0") or "0"
    return digit_string, int(exponent)


def _e_notation(digit_string: str, exponent: int, marker: str = "E", min_exponent_digits: int = 2) -> str:
    """``d.ddd`` E sign exponent, the point only when more digits follow."""
    mantissa = digit_string[0] + ("." + digit_string[1:] if len(digit_string) > 1 else "")
    sign = "-" if exponent < 0 else "+"
    return f"{mantissa}{marker}{sign}{abs(exponent):0{min_exponent_digits}d}"


def _fixed_notation(digit_string: str, exponent: int) -> str:
    """Plain decimal notation without a leading zero: ``123.5``, ``.0625``, ``1200``."""
    point = exponent + 1  # digits before the decimal point
    if point >= len(digit_string):
        return digit_string + "0" * (point - len(digit_string))
    if point > 0:
        return digit_string[:point] + "." + digit_string[point:]
    return "." + "0" * (-point) + digit_string


def _unsigned_text(x: float) -> str:
    """``abs(x)`` as PRINT shows it, without sign or spaces."""
    if x == 0:
        return "0"
    if x.is_integer() and abs(x) < 1e10:  # the common case (counters, indices), same text, faster
        return str(int(abs(x)))
    digit_string, exponent = _significant_digits(x, SIGNIFICANT_DIGITS)
    needs_e = exponent >= SIGNIFICANT_DIGITS or len(digit_string) - exponent > SIGNIFICANT_DIGITS + 1
    if needs_e:
        return _e_notation(digit_string, exponent)
    return _fixed_notation(digit_string, exponent)


def str_dollar(x: float) -> str:
    """STR$(x): a leading space (or minus), up to 10 significant digits, no trailing space."""
    x = float(x)
    _check_finite(x)
    sign = "-" if x < 0 else " "
    return sign + _unsigned_text(x)


def number_to_text(x: float) -> str:
    """How PRINT shows a number: STR$ form plus a trailing space."""
    return str_dollar(x) + " "


# ---------------------------------------------------------------------------
# PRINT USING: the format string
# ---------------------------------------------------------------------------

class Literal(namedtuple("Literal", "text")):
    """Text copied to the output as it is (``text``: str)."""

    __slots__ = ()


class StringField(namedtuple("StringField", "width")):
    """``!`` (width 1), ``\\  \\`` (width n+2) or ``&`` (width ``None``: the whole string)."""

    __slots__ = ()


class NumericField(namedtuple("NumericField", "positions decimals point comma fill dollar sign exponent_digits")):
    """A numeric field of a PRINT USING format.

    ``positions`` (int) counts the places left of the decimal point (``#``, the two
    of ``**`` or ``$$``, the three of ``**$``, and the commas); ``decimals`` (int)
    the ``#`` after it; ``point`` and ``comma`` (bool) whether the field has them;
    ``fill`` ``"*"`` or ``" "``; ``dollar`` (bool) a ``$`` before the number;
    ``sign`` is ``"lead+"``, ``"trail+"``, ``"trail-"`` or ``""`` (a minus then
    takes one of the positions); ``exponent_digits`` 0 (fixed notation), 2
    (``^^^^``) or 3 (``^^^^^``).
    """

    __slots__ = ()


def _count(fmt: str, i: int, chars: str) -> int:
    """How many characters from ``chars`` follow one another in ``fmt`` from ``i``."""
    j = i
    while j < len(fmt) and fmt[j] in chars:
        j += 1
    return j - i


def _numeric_start(fmt: str, i: int) -> bool:
    """Whether a numeric field (without a leading ``+``) starts at ``fmt[i]``."""
    rest = fmt[i:]
    return rest.startswith(("#", "**", "$$")) or rest.startswith(".#")


def _parse_numeric(fmt: str, i: int) -> tuple[NumericField, int]:
    """Read the numeric field starting at ``fmt[i]``; return it and the index after it."""
    sign = ""
    if fmt[i] == "+":
        sign = "lead+"
        i += 1
    fill, dollar, positions = " ", False, 0
    if fmt.startswith("**$", i):
        fill, dollar, positions, i = "*", True, 3, i + 3
    elif fmt.startswith("**", i):
        fill, positions, i = "*", 2, i + 2
    elif fmt.startswith("$$", i):
        dollar, positions, i = True, 2, i + 2
    comma = False
    while i < len(fmt) and fmt[i] in "#,":
        comma = comma or fmt[i] == ","
        positions += 1
        i += 1
    point, decimals = False, 0
    if i < len(fmt) and fmt[i] == ".":
        point = True
        decimals = _count(fmt, i + 1, "#")
        i += 1 + decimals
    exponent_digits = 0
    carets = _count(fmt, i, "^")
    if carets >= 4:
        exponent_digits = 3 if carets >= 5 else 2
        i += 5 if carets >= 5 else 4
    if not sign and i < len(fmt) and fmt[i] in "+-":
        sign = "trail" + fmt[i]
        i += 1
    field = NumericField(positions, decimals, point, comma, fill, dollar, sign, exponent_digits)
    return field, i


def _parse_backslash(fmt: str, i: int) -> tuple[StringField | None, int]:
    """``\\`` + spaces + ``\\`` at ``fmt[i]``: the field and the index after it, or ``None``."""
    spaces = _count(fmt, i + 1, " ")
    close = i + 1 + spaces
    if close < len(fmt) and fmt[close] == "\\":
        return StringField(spaces + 2), close + 1
    return None, i


def parse_format(fmt: str) -> list[Token]:
    """Split a PRINT USING format into literals and fields (adjacent literals merged)."""
    tokens: list[Token] = []
    literal: list[str] = []
    i = 0

    def flush() -> None:
        if literal:
            tokens.append(Literal("".join(literal)))
            literal.clear()

    while i < len(fmt):
        char = fmt[i]
        field: Token | None = None
        if char == "_":
            literal.append(fmt[i + 1] if i + 1 < len(fmt) else "_")
            i += 2
            continue
        if char == "!":
            field, i = StringField(1), i + 1
        elif char == "&":
            field, i = StringField(None), i + 1
        elif char == "\\":
            field, i = _parse_backslash(fmt, i)
        elif _numeric_start(fmt, i) or (char == "+" and _numeric_start(fmt, i + 1)):
            field, i = _parse_numeric(fmt, i)
        if field is None:
            literal.append(char)
            i += 1
            continue
        flush()
        tokens.append(field)
    flush()
    return tokens


@lru_cache(maxsize=256)
def _parsed(fmt: str) -> tuple[Token, ...]:
    """``parse_format`` remembered: a listing prints with the same few formats in its loop."""
    return tuple(parse_format(fmt))


# ---------------------------------------------------------------------------
# PRINT USING: the fields
# ---------------------------------------------------------------------------

# decimal is imported by the functions below, at the first PRINT USING of a number:
# a run that never formats one does not load it (start-up time).

@lru_cache(maxsize=None)
def _wide():
    """The decimal context PRINT USING rounds in: enough digits for any double written
    out in full (1.8E308 has 309) plus its decimals."""
    from decimal import Context

    return Context(prec=800, Emax=1000, Emin=-1000)


class Shown(float):
    """A gw double on its way to PRINT USING, with its exact 56-bit value (``parts``, as
    mbf_double's), from which :func:`_bracketed` finds the digits the field shows; from
    10**16 up also ``free`` (see :class:`Single`)."""

    __slots__ = ("parts", "free")


class Single(float):
    """A gw single on its way to PRINT USING: its value is that of its 7 digits (PRINT's),
    ``bracket`` MATH2.ASM's ``$FOTNV`` of its binary value (``(y, power)``, see
    mbf_digits.bracket) from which a field finds the digits it shows (``$PUF``,
    ``$PUFE``); ``free``, set only where ``$PUF`` finds it too large for a fixed field:
    the text ``$FOUT`` (PRINT's free format) gives its magnitude.  A fixed field then
    shows ``%``, a blank and that text."""

    __slots__ = ("bracket", "free")


def _bracketed(parts, places: int):
    """``abs`` of a 56-bit double rounded to ``places`` decimals, at most 16 significant
    digits (zeros after them), as MATH2.ASM's ``$PUF`` finds them (``$FOTNV``'s table
    steps, a ``$DIV10`` a digit too many, ``$FOTCV``'s half added: mbf_double_using;
    from 10**16 up the 16 digits and zeros, for a double that carries no ``free`` text)."""
    from decimal import Decimal

    from yaseer.basic.arithmetic import mbf_double_using

    _, exponent, mantissa = parts
    if not exponent:
        return Decimal(0).scaleb(-places)
    digits, shown = mbf_double_using.fixed_digits((False, exponent, mantissa), places)
    return Decimal(digits).scaleb(-shown)


def _decimal(x: float):
    """``abs(x)`` as a ``decimal.Decimal``: a :class:`Shown`'s 16 digits, else the
    shortest decimal that reads back as the float."""
    from decimal import Decimal

    if type(x) is Shown:
        return _bracketed(x.parts, 99)
    return Decimal(repr(abs(float(x))))


def _rounded_half_up(x: float, decimals: int) -> tuple[str, str]:
    """The whole and fraction digits of ``abs(x)`` (finite) rounded half up to ``decimals``
    places: the shortest decimal that reads back as the float, rounded in integers.  The
    digits ``Decimal(repr(abs(x))).quantize(..., ROUND_HALF_UP)`` gives, without importing
    :mod:`decimal` (a tenth of a paper example's start-up) for PRINT USING's every fixed field."""
    text = repr(abs(float(x)))
    mantissa, _, power = text.partition("e")
    whole, _, fraction = mantissa.partition(".")
    digits = int(whole + fraction)
    exponent = (int(power) if power else 0) - len(fraction)  # abs(x) == digits * 10**exponent
    if exponent >= -decimals:
        digits *= 10 ** (exponent + decimals)
    else:
        unit = 10 ** (-decimals - exponent)
        digits, rest = divmod(digits, unit)
        digits += 2 * rest >= unit
    shown = str(digits).rjust(decimals + 1, "0")
    return shown[:len(shown) - decimals], shown[len(shown) - decimals:]


def _group_thousands(digits: str) -> str:
    """``1234567`` -> ``1,234,567``."""
    head = len(digits) % 3 or 3
    groups = [digits[:head]] + [digits[k:k + 3] for k in range(head, len(digits), 3)]
    return ",".join(groups)


def _fixed_body(x: float, field: NumericField) -> str:
    """Digits, commas and point of ``abs(x)`` for a fixed-notation field.

    The integer part ``0`` is left out before the point (``.50``); the field
    puts it back when there is room (see :func:`format_number`).  A non-zero
    value that rounds to zero keeps its ``0`` (``-0.00``), as in GW-BASIC.
    """
    if type(x) is Shown or type(x) is Single:
        from decimal import Decimal, localcontext

        with localcontext(_wide()):
            if type(x) is Shown:
                rounded = _bracketed(x.parts, field.decimals).quantize(Decimal(1).scaleb(-field.decimals))
            else:  # $PUF: the bracket divided down to the field's decimals, then rounded
                from yaseer.basic.arithmetic import mbf_digits

                digits, shown = mbf_digits.fixed_digits(*x.bracket, field.decimals)
                rounded = Decimal(digits).scaleb(-shown).quantize(Decimal(1).scaleb(-field.decimals))
        whole, _, fraction = f"{rounded:f}".partition(".")
    else:
        whole, fraction = _rounded_half_up(x, field.decimals)
    if field.comma:
        whole = _group_thousands(whole)
    if whole == "0" and field.point and (x == 0 or fraction.strip("0")):  # 0.xx, not rounded to 0
        whole = ""
    return whole + ("." + fraction if field.point else "")


def _scientific_digits_before(field: NumericField) -> int:
    """Mantissa digits left of the point: one position is kept for the sign unless the field has one."""
    return max(field.positions - (0 if field.sign else 1), 0)


def _scientific_body(x: float, field: NumericField) -> str:
    """Mantissa and exponent of ``abs(x)`` for a ``^^^^`` field: ``1.25E+01``, ``.13E+02``, ``E+00``
    (``D`` for a gw double, :class:`Shown`).

    Zero shows no digit left of the point (GW-BASIC prints ``  E+00`` for
    ``##^^^^``); with no mantissa digit at all only the exponent is shown.  A double
    zero in a field without a point shows one ``0`` (``   0D+00`` for ``####^^^^``: a
    real GW-BASIC 3.23 so, the recorded unsorted/USING test of PC-BASIC's suite, and
    PC-BASIC 2.0.8; a single's ``    E+00`` beside it).
    """
    if x == 0:
        mantissa, exponent = ("." + "0" * field.decimals) if field.point else ("0" if type(x) is Shown else ""), 0
    else:
        from decimal import localcontext

        with localcontext(_wide()):
            mantissa, exponent = _scientific_parts(x, field)
    sign = "-" if exponent < 0 else "+"
    marker = "D" if type(x) is Shown else "E"  # MATH1.ASM $PUEXP: D for a double
    return f"{mantissa}{marker}{sign}{abs(exponent):0{field.exponent_digits}d}"


def _scientific_parts(x: float, field: NumericField) -> tuple[str, int]:
    """Mantissa text and power of ten of non-zero ``abs(x)`` for a ``^^^^`` field."""
    from decimal import ROUND_HALF_UP, Decimal

    before = _scientific_digits_before(field)
    if type(x) is Shown and x.parts[1] and before + field.decimals:  # a double: $PUFE's digits
        from yaseer.basic.arithmetic import mbf_double_using

        digits, power = mbf_double_using.scientific_digits(x.parts, before + field.decimals)
        value = Decimal(digits).scaleb(power)
    elif type(x) is Single and before + field.decimals:  # a single: $PUFE's digits
        from yaseer.basic.arithmetic import mbf_digits

        digits, power = mbf_digits.scientific_digits(*x.bracket, before + field.decimals)
        value = Decimal(digits).scaleb(power)
    else:
        value = _decimal(x)
    quantum = Decimal(1).scaleb(-field.decimals)
    exponent = value.adjusted() + 1 - before
    scaled = value.scaleb(-exponent).quantize(quantum, rounding=ROUND_HALF_UP)
    if scaled >= Decimal(10) ** before and before + field.decimals > 0:
        exponent += 1  # rounding carried into a new digit: 9.996 -> 10.00 -> 1.000E+01
        scaled = value.scaleb(-exponent).quantize(quantum, rounding=ROUND_HALF_UP)
    whole, _, fraction = f"{scaled:f}".partition(".")
    whole = whole if before else ""
    return whole + ("." + fraction if field.point else ""), exponent


def _field_width(field: NumericField) -> int:
    """Characters the field occupies in the format (and the output, when it fits)."""
    width = field.positions + field.decimals + (1 if field.point else 0)
    width += 2 + field.exponent_digits if field.exponent_digits else 0
    return width + (1 if field.sign else 0)


def format_number(x: float, field: NumericField) -> str:
    """One number in one numeric field; ``%`` + the full number when it does not fit.

    (An exponent of three digits in a ``^^^^`` field, possible only for
    doubles beyond 1E+99, also counts as not fitting.)

    The sign goes before the ``$`` and the digits (``**-$3.50``), or after
    the number for a trailing ``+`` / ``-``.  Without a sign in the field a
    minus takes one of the digit positions.  A leading ``0`` is put before
    ``.`` when the field has room for it and no ``$``.
    """
    _check_finite(x)
    free = getattr(x, "free", None)
    if free is not None and not field.exponent_digits:
        # MATH2.ASM $PUF: from 10**16 up (a single: $DP16's top four bytes) $FOUT's free
        # format after a % and a blank; PUFOUT made the number positive before, so a
        # minus, a +, $, ** and a trailing sign are not shown
        return "% " + free
    negative = x < 0
    body = _scientific_body(x, field) if field.exponent_digits else _fixed_body(x, field)
    lead = ""
    if field.sign == "lead+":
        lead = "-" if negative else "+"
    elif not field.sign and negative:
        lead = "-"
    trail = ""
    if field.sign.startswith("trail"):
        trail = "-" if negative else ("+" if field.sign == "trail+" else " ")
    dollar = "$" if field.dollar else ""
    room = _field_width(field) - len(trail)
    if body.startswith(".") and not dollar and len(lead + body) < room:
        body = "0" + body
    text = lead + dollar + body
    if len(text) > room or _exponent_overflows(body, field):
        return "%" + text + trail
    return text.rjust(room, field.fill) + trail


def _exponent_overflows(body: str, field: NumericField) -> bool:
    """Whether an E-notation exponent needs more digits than the field's ``^`` give it."""
    return bool(field.exponent_digits) and len(body.replace("D", "E").split("E")[1]) - 1 > field.exponent_digits


def format_string(s: str, field: StringField) -> str:
    """One string in one string field: cut or padded to the field's width."""
    if field.width is None:
        return s
    return s[:field.width].ljust(field.width)


def _format_value(value: Value, field: StringField | NumericField) -> str:
    """A value in a field, or ``Type mismatch`` when their kinds differ."""
    is_string = isinstance(value, str)
    if isinstance(field, StringField) != is_string:
        raise BasicError("Type mismatch", TYPE_MISMATCH)
    if is_string:
        return format_string(value, field)
    return format_number(value if type(value) is Shown or type(value) is Single else float(value), field)


def field_digits(field: NumericField) -> int:
    """A numeric field's digit positions as GW-BASIC's PRINT USING scanner counts them
    (BIPRTU.ASM, NUMNUM to ENDNUS): the positions before the point (``#``, commas, the two
    of ``**`` or ``$$``, the three of ``**$``), a leading ``+``, the point and the ``#``
    after it; not ``^^^^`` nor a trailing sign."""
    return field.positions + field.decimals + field.point + (field.sign == "lead+")


class UsingCursor:
    """A PRINT USING format read as GW-BASIC's BIPRTU.ASM reads it, one field at a time: the
    literal text before a field is printed before its value is evaluated, each value is
    formatted (and printed) before the next one is evaluated.

    :meth:`literals` gives the literal text up to the next field; :meth:`field` one value in
    that field.  A format without a field is ``Illegal function call`` once its text is
    printed (BIPRTU.ASM ``REUSST``: the format ended and no value was printed), before any
    value is evaluated; the error carries that text as ``printed``.
    """

    __slots__ = ("tokens", "position", "most_digits")

    def __init__(self, fmt: str, most_digits: int | None = None):
        tokens = self.tokens = _parsed(fmt)
        if all(type(token) is Literal for token in tokens):
            error = BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
            error.printed = "".join(token.text for token in tokens)
            raise error
        self.position = 0  # the token read next
        self.most_digits = most_digits

    def literals(self, more: bool) -> str:
        """The literal text from here to the next field; at the end of the format, while
        ``more`` values remain, the format is read again from its start (else it stops)."""
        tokens, position = self.tokens, self.position
        text = ""
        while True:
            if position == len(tokens):
                if not more:
                    break
                position = 0
            token = tokens[position]
            if type(token) is not Literal:
                break
            text += token.text
            position += 1
        self.position = position
        return text

    def field(self, value: Value) -> str:
        """``value`` in the field reached (see :meth:`literals`); a numeric field of more than
        ``most_digits`` digit positions (:func:`field_digits`; None: no limit) is ``Illegal
        function call`` whatever the value (BIPRTU.ASM checks after FRMEVL, before PUFOUT
        looks at the type: ``CMP AL,25``)."""
        token = self.tokens[self.position]
        most = self.most_digits
        if most is not None and type(token) is NumericField and field_digits(token) > most:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        text = _format_value(value, token)
        self.position += 1
        return text


def using(fmt: str, values: Sequence[float | str], pieces: bool = False, most_digits: int | None = None):
    """PRINT USING fmt; values — the text printed (no newline); with ``pieces`` the list of
    its parts as (text, is a field) pairs (a field that does not fit the row moves to the next).
    A numeric field of more than ``most_digits`` digit positions (:func:`field_digits`; None:
    no limit) is ``Illegal function call`` when a value reaches it, whatever the value
    (BIPRTU.ASM checks after FRMEVL, before PUFOUT looks at the type: ``CMP AL,25``).

    The format is reused from its start while values remain; after the last
    value, literal text is copied up to the next field or the end of the format
    (the fields read as :class:`UsingCursor` reads them, all values at once: the
    fast path where evaluating the values cannot fail nor be seen).
    An error (a format without a field, a string for a numeric field) carries the
    text printed before it as ``printed``: GW-BASIC prints as it goes
    (``PRINT USING "abc"; 1`` prints ``abc``, then ``Illegal function call``).
    """
    tokens = _parsed(fmt)
    if not any(not isinstance(token, Literal) for token in tokens):
        error = BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        error.printed = "".join(token.text for token in tokens)
        raise error
    out: list[str] = []
    fields: list[int] = []  # where in ``out`` the fields are
    next_value = 0
    position = 0
    while True:
        token = tokens[position]
        if isinstance(token, Literal):
            out.append(token.text)
        elif next_value == len(values):
            break
        else:
            try:
                if most_digits is not None and type(token) is NumericField and field_digits(token) > most_digits:
                    raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
                out.append(_format_value(values[next_value], token))
            except BasicError as error:
                error.printed = "".join(out)
                raise
            fields.append(len(out) - 1)
            next_value += 1
        position += 1
        if position == len(tokens):
            if next_value == len(values):
                break
            position = 0
    if pieces:
        marked = set(fields)
        return [(text, k in marked) for k, text in enumerate(out)]
    return "".join(out)
