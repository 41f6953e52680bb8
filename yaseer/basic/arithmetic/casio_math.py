"""The FX-850P/880P's own scientific functions, on Python floats (the casio dialect).

Each function follows its page of the owner's manual (commands/*.md): the ranges of
its arguments and the error beyond them.  An argument outside a function's range is
``Illegal function call`` (the manual's MA error: "argument exceeds allowable
calculation range"); a result beyond 9.999999999E+99 is ``Overflow`` (OV).

Angles are in the unit ANGLE chose: :data:`UNITS` gives, for ``"DEG"``, ``"RAD"``
and ``"GRA"``, the size of a right angle (90, pi/2, 100); in degrees and grads the
multiples of a right angle give exact sines and cosines (as runtime.sin_degrees).
"""

from __future__ import annotations

import math

from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL, OVERFLOW, error_for

LARGEST = 9.999999999999e99  # the Casio's range ends below 1E+100 (specifications)
RIGHT_ANGLE = {"DEG": 90.0, "RAD": math.pi / 2, "GRA": 100.0}  # one quarter turn in each unit
TO_RADIANS = {"DEG": math.pi / 180.0, "RAD": 1.0, "GRA": math.pi / 200.0}
# DMS$'s degree sign: the character code &HDF, the small circle of the Casio character set
# (part-12-1-character-code-table.md; shown as the half-width ﾟ): the table has no other
DEGREE_SIGN = "\xdf"
EXP_LIMIT = 230.2585092  # ln(1E+100) to the pages' ten digits: EXP's, HYP SIN's and HYP COS's argument
# The argument each function's page allows (commands/*.md), one row a helper the compiled code
# calls: helper -> (lowest, whether the lowest is allowed, highest, whether the highest is
# allowed, the error beyond).  Beyond them the function is the page's error in both
# arithmetics (binary keeps IEEE's range for + - * / on purpose, tests/test_scaled_mechanisms.py,
# not for the functions): where the result would leave the calculation range, OV
# (part-12-2: "value exceeds allowable calculation result or input range"), else MA
# ("argument exceeds allowable calculation range", yaseer's Illegal function call).  (SQR, LN,
# LOG, ASN, ACS, FACT, NCR, NPR, ROUND and HEX$ check their arguments in their own routines,
# which each arithmetic needs anyway.)
ARGUMENT_RANGES = {
    "_exp": (-math.inf, False, EXP_LIMIT, True, OVERFLOW),  # EXP.md: argument <= 230.2585092
    "_sinh": (-EXP_LIMIT, True, EXP_LIMIT, True, OVERFLOW),  # HYP_SIN_COS_TAN.md: |argument| <= 230.2585092
    "_cosh": (-EXP_LIMIT, True, EXP_LIMIT, True, OVERFLOW),
    "_asinh": (-5e99, False, 5e99, False, ILLEGAL_FUNCTION_CALL),  # HYP_ASN_ACS_ATN.md: |argument| < 5E+99
    "_acosh": (1.0, True, 5e99, False, ILLEGAL_FUNCTION_CALL),  # 1 <= argument < 5E+99
    "_atanh": (-1.0, False, 1.0, False, ILLEGAL_FUNCTION_CALL),  # -1 < argument < 1
}


def illegal() -> BasicError:
    return BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)


def overflow() -> BasicError:
    return BasicError("Overflow", OVERFLOW)


def _in_range(x: float) -> float:
    if abs(x) > LARGEST:
        raise overflow()
    return x


def _whole(x: float) -> int:
    """An argument that must be an integer (FACT, NCR, NPR): a fraction is an error."""
    if x != int(x):
        raise illegal()
    return int(x)


def log10(x: float) -> float:
    """LOG: the common logarithm (LOG_LN.md); 0 or below is an error."""
    if x <= 0:
        raise illegal()
    return math.log10(x)


def cube_root(x: float) -> float:
    """CUR: the real cube root, of a negative number too (CUR.md); an exact cube gives
    its exact root (CUR 27 is 3)."""
    if x == 0:
        return 0.0
    y = math.copysign(abs(x) ** (1.0 / 3.0), x)
    y -= (y * y * y - x) / (3.0 * y * y)  # one Newton step: the power is a few units off
    whole = float(round(y))
    return whole if whole * whole * whole == x else y


def frac(x: float) -> float:
    """FRAC: the fraction part, with the sign of x (FRAC.md)."""
    return math.fmod(x, 1.0)


def factorial(x: float) -> float:
    """FACT: x! for whole x in 0..69 (FACT.md); 70! passes 1E+100 (Overflow)."""
    n = _whole(x)
    if n < 0:
        raise illegal()
    if n > 69:
        raise overflow()
    return float(math.factorial(n))


def _n_r(n: float, r: float) -> tuple[int, int]:
    """NCR's and NPR's arguments: whole numbers with 0 <= r <= n < 1E10 (NCR.md, NPR.md)."""
    a, b = _whole(n), _whole(r)
    if not 0 <= b <= a or a >= 1e10:
        raise illegal()
    return a, b


def _checked_int(value: int) -> float:
    if value > LARGEST:
        raise overflow()
    return float(value)


def combinations(n: float, r: float) -> float:
    """NCR(n, r) = n! / (r! (n-r)!)."""
    a, b = _n_r(n, r)
    b = min(b, a - b)
    if b > 400:  # the binomial of so many terms is beyond 1E+100 once n > 800
        raise overflow()
    return _checked_int(math.comb(a, b))


def permutations(n: float, r: float) -> float:
    """NPR(n, r) = n! / (n-r)!."""
    a, b = _n_r(n, r)
    if b > 200 and a > 1:  # 201 factors of at least 2 pass 1E+60; of n >= 70, 1E+100
        if a >= 70 or b > 400:
            raise overflow()
    return _checked_int(math.perm(a, b))


def round_at(x: float, digit: float) -> float:
    """ROUND(x, d): x rounded half away from zero at the digit of 10^d, keeping multiples
    of 10^(d+1) (ROUND.md: 610.5765383 at -2 is 610.6); d is truncated, -100 < d < 100."""
    d = int(digit)
    if not -100 < d < 100:
        raise illegal()
    from decimal import ROUND_HALF_UP, Decimal

    step = Decimal(1).scaleb(d + 1)
    value = Decimal(repr(x)).quantize(step, rounding=ROUND_HALF_UP) if abs(d) < 90 else None
    if value is None:  # very large or small steps: the float arithmetic is exact enough
        unit = 10.0 ** (d + 1)
        return math.copysign(math.floor(abs(x) / unit + 0.5) * unit, x)
    return _in_range(float(value))


def from_sexagesimal(degrees: float, minutes: float = 0.0, seconds: float = 0.0) -> float:
    """DEG(d, m, s) = d + m/60 + s/3600 (DEG.md)."""
    return _in_range(degrees + minutes / 60.0 + seconds / 3600.0)


def to_sexagesimal(x: float) -> str:
    """DMS$(x): ``d°m's"`` (the degree sign the Casio's code &HDF) with the seconds to the display's 10 digits (DMS_STRING.md);
    from 1E6 on the minutes and seconds are left out and the absolute value is written."""
    from decimal import ROUND_HALF_UP, Decimal

    if abs(x) >= 1e100:
        raise illegal()
    if abs(x) >= 1e6:
        from yaseer.basic.arithmetic.formatting import number_to_text

        return number_to_text(abs(x)).strip()
    value = abs(Decimal(repr(x)))
    whole_digits = len(str(int(value))) if value >= 1 else 0
    seconds = (value * 3600).quantize(Decimal(1).scaleb(whole_digits - 10 + 4 if whole_digits > 4 else -6),
                                      rounding=ROUND_HALF_UP)
    degrees, rest = divmod(seconds, 3600)
    minutes, seconds = divmod(rest, 60)
    text = f"{int(degrees)}{DEGREE_SIGN}{int(minutes)}'{_plain(seconds)}\""
    return "-" + text if x < 0 else text


def _plain(d) -> str:
    """A decimal without exponent or trailing zeros (12.50 -> 12.5, 12.0 -> 12)."""
    text = format(d.normalize(), "f")
    return text.rstrip("0").rstrip(".") if "." in text else text


def formatted_number(x: float, style: str, digits: int) -> str:
    """A number as PRINT shows it after SET (SET.md): ``"F"`` with ``digits`` decimals
    (``SET F2``: `` 3.33``), ``"E"`` with ``digits`` significant digits in exponent form
    (``SET E2``: `` 3.3E+00``; E0 is ten), rounded half up; a leading blank or ``-``
    and a trailing blank, as without SET.  A number of more than 10 digits before
    the point keeps the display's own form."""
    from decimal import ROUND_HALF_UP, Decimal

    from yaseer.basic.arithmetic.formatting import number_to_text

    sign = "-" if x < 0 else " "
    value = abs(Decimal(repr(float(x))))
    if style == "F":
        text = format(value.quantize(Decimal(1).scaleb(-digits), rounding=ROUND_HALF_UP), "f")
        if len(text.split(".")[0]) > 10:
            return number_to_text(x)
        return sign + text + " "
    places = (digits or 10) - 1
    if value == 0:
        return sign + format(Decimal(0), f".{places}f") + "E+00 "
    exponent = value.adjusted()
    mantissa = value.scaleb(-exponent).quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_UP)
    if mantissa >= 10:  # 9.96 to two digits is 10: one more power of ten
        exponent += 1
        mantissa = (mantissa / 10).quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_UP)
    return f"{sign}{format(mantissa, 'f')}E{'-' if exponent < 0 else '+'}{abs(exponent):02d} "


def hex4(x: float) -> str:
    """HEX$(x): four hexadecimal digits of x truncated, -32769 < x < 65536; a negative
    x is written as x + 65536 (HEX_STRING.md: HEX$(-1) is FFFF)."""
    n = int(x)
    if not -32769 < n < 65536:
        raise illegal()
    return format(n % 65536, "04X")


# ------------------------------------------------------------------ hyperbolic functions

def ranged(namespace: dict) -> dict:
    """The helpers of :data:`ARGUMENT_RANGES` in ``namespace``, each checking its argument
    against its page's range before it computes."""
    return {name: _within(namespace[name], *bounds) for name, bounds in ARGUMENT_RANGES.items() if name in namespace}


def _within(f, low: float, low_allowed: bool, high: float, high_allowed: bool, code: int):
    def checked(x):
        if (low < x or low_allowed and x == low) and (x < high or high_allowed and x == high):
            return f(x)
        raise error_for(code)
    return checked


# ------------------------------------------------------------------ angles

class Angles:
    """The trigonometric functions in one angle unit (``"DEG"``, ``"RAD"``, ``"GRA"``)."""

    def __init__(self, unit: str):
        self.quarter = RIGHT_ANGLE[unit]
        self.to_radians = TO_RADIANS[unit]
        self.exact = unit != "RAD"

    def _quadrant(self, x: float):
        """The multiple of a right angle x is (0..3), when it is one exactly (DEG, GRA); else None."""
        if not self.exact:
            return None
        turns = x / self.quarter
        return int(turns) % 4 if turns == int(turns) else None

    def sin(self, x: float) -> float:
        k = self._quadrant(x)
        if k is not None:
            return (0.0, 1.0, 0.0, -1.0)[k]
        return math.sin(math.fmod(x, 4 * self.quarter) * self.to_radians)

    def cos(self, x: float) -> float:
        k = self._quadrant(x)
        if k is not None:
            return (1.0, 0.0, -1.0, 0.0)[k]
        return math.cos(math.fmod(x, 4 * self.quarter) * self.to_radians)

    def tan(self, x: float) -> float:
        k = self._quadrant(x)
        if k is not None:
            if k % 2:
                raise illegal()
            return 0.0
        return math.tan(math.fmod(x, 4 * self.quarter) * self.to_radians)

    def _from_radians(self, r: float) -> float:
        return r / self.to_radians

    def atn(self, x: float) -> float:
        return self._from_radians(math.atan(x))

    def asn(self, x: float) -> float:
        """ASN: -1 <= x <= 1, the result in -90..90 degrees (ASN_ACS_ATN.md)."""
        if not -1 <= x <= 1:
            raise illegal()
        return self.quarter * x if x in (-1.0, 1.0) else self._from_radians(math.asin(x))

    def acs(self, x: float) -> float:
        """ACS: -1 <= x <= 1, the result in 0..180 degrees."""
        if not -1 <= x <= 1:
            raise illegal()
        if x == 0:
            return self.quarter
        return 2 * self.quarter if x == -1 else self._from_radians(math.acos(x))

    def polar(self, x: float, y: float) -> tuple[float, float]:
        """POL(x, y): (r, theta), theta in (-180, 180] degrees (POL.md); |x| + |y| > 0."""
        if x == 0 and y == 0:
            raise illegal()
        if y == 0:
            return abs(x), (0.0 if x > 0 else 2 * self.quarter)
        if x == 0:
            return abs(y), math.copysign(self.quarter, y)
        return math.hypot(x, y), self._from_radians(math.atan2(y, x))

    def rectangular(self, r: float, theta: float) -> tuple[float, float]:
        """REC(r, theta): (r cos theta, r sin theta) (REC.md): 0 <= r < 1E100 and
        |theta| below 16 right angles (1440 degrees)."""
        if not 0 <= r < 1e100 or abs(theta) >= 16 * self.quarter:
            raise illegal()
        return r * self.cos(theta), r * self.sin(theta)


def asc(text: str) -> float:
    """ASC(s$): the code of the first character; 0 for a null string (ASC.md, item 2)."""
    return float(ord(text[0])) if text else 0.0


RUNTIME = {
    "_asc0": asc, "_log10": log10, "_cur": cube_root, "_frac": frac, "_fact": factorial, "_ncr": combinations,
    "_npr": permutations, "_round": round_at, "_degf": from_sexagesimal, "_dms": to_sexagesimal,
    "_hex4": hex4, "_sinh": math.sinh, "_cosh": math.cosh, "_tanh": math.tanh, "_asinh": math.asinh,
    "_acosh": math.acosh, "_atanh": math.atanh,
}


def angle_functions(unit: str) -> dict:
    """The compiled code's casio angle helpers in ``unit`` (binary arithmetic): ASN ACS POL
    REC, and in grads SIN COS TAN ATN too (degrees and radians keep runtime.py's)."""
    a = Angles(unit)
    helpers = {"_asn": a.asn, "_acs": a.acs, "_pol": a.polar, "_rec": a.rectangular}
    if unit == "GRA":
        helpers.update({"_sin": a.sin, "_cos": a.cos, "_tan": a.tan, "_atn": a.atn})
    return helpers
