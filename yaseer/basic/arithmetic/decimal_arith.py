"""``--arith decimal``: the Casio FX-850P family's arithmetic, 12 decimal digits inside.

The pocket computers compute in BCD with a 12-digit mantissa and show 10 digits
(the FX-850P manual's specifications and part 6, "Numeric Value Precision"),
so ``1 - 10*.1`` is exactly 0 and ``FOR T = .1 TO 360.1 STEP 20`` reaches 360.1
exactly.  yaseer keeps every value a Python float (so arrays, FOR loops, PRINT and
the program areas work unchanged) but every value is the nearest float to a
12-significant-digit decimal: each operation reads its operands back as those
decimals (:func:`dec`, exact because 12 digits < 15), computes in the decimal
module with 12 digits (:data:`CONTEXT`, rounding half up as a calculator does),
and stores the float of the result.  The range is the manual's: a result of 1E+100
or more is ``Overflow``, one below 1E-99 in size is 0.

SQR, EXP, LOG and ``^`` are correctly rounded by the decimal module; SIN, COS,
TAN and ATN are computed with 25 digits (Taylor series after an exact reduction of
the angle) and then rounded to 12.  In degrees (and grads) the multiples of a right
angle give exact values, as in the binary arithmetic.
"""

from __future__ import annotations

import math
from functools import partial
from decimal import ROUND_HALF_UP, Context, Decimal, Overflow as DecimalOverflow

from yaseer.basic.arithmetic.decimal_calls import angle_functions
from yaseer.basic.arithmetic.decimal_scales import rounded_within
from yaseer.basic.errors import BasicError, DIVISION_BY_ZERO, ILLEGAL_FUNCTION_CALL, OVERFLOW

DIGITS = 12  # inside; the display shows 10 (formatting.number_to_text)
SMALLEST = Decimal("1E-99")  # below it in size a result is 0 (the specifications' range)
# Emin far below the range: a result is rounded to 12 digits first, wherever it lies, and then
# a result below 1E-99 is 0 (_checked), as a 12-digit mantissa with an exponent from -99 has it.
# With Emin=-99 the decimal module would round a result under 1E-99 to fewer digits (a
# subnormal, at a fixed 1E-110): 3E-50 * 3.33333333333E-50, 9.99999999999E-100 in 12 digits,
# became 1E-99 where a quotient of the same 12-digit value became 0.
CONTEXT = Context(prec=DIGITS, rounding=ROUND_HALF_UP, Emax=99, Emin=-999,
                  traps=[DecimalOverflow])
_WIDE = Context(prec=25, rounding=ROUND_HALF_UP)  # trig is computed with 12 guard digits
_PI = Decimal("3.14159265358979323846264338327950288")


def dec(x) -> Decimal:
    """The 12-digit decimal a float stands for (a float from outside is rounded to 12 digits)."""
    return Decimal(format(x, ".12g"))


def _checked(operation, *args) -> float:
    try:
        result = operation(*args)
    except DecimalOverflow:
        raise BasicError("Overflow", OVERFLOW) from None
    return float(result) if abs(result) >= SMALLEST else 0.0


# A multiple of 1/8 below 1E9 in size is exactly its own decimal (at most 9 + 3
# digits) and exactly a float.  The sum or difference of two such numbers is another
# (exact in both arithmetics), and so is a product or quotient that is again a multiple
# of 1/8 below 1E9 (its binary value is then exact, so it is the decimal result):
# loop counters, counts and halves take these few float operations instead of the
# decimal module's conversions (about 20 times their cost).  The results are the
# decimal arithmetic's to the last digit (at most 12 digits: also with DIGITS = 12).
_SMALL = 1e9


def add(a, b) -> float:
    if -_SMALL < a < _SMALL and -_SMALL < b < _SMALL and not (a * 8.0 % 1.0 or b * 8.0 % 1.0):
        total = a + b
        if -_SMALL < total < _SMALL:  # (from 1E9 on, 9 + 3 digits could need rounding to 12)
            return float(total)
    return _checked(CONTEXT.add, dec(a), dec(b))


def subtract(a, b) -> float:
    if -_SMALL < a < _SMALL and -_SMALL < b < _SMALL and not (a * 8.0 % 1.0 or b * 8.0 % 1.0):
        difference = a - b
        if -_SMALL < difference < _SMALL:
            return float(difference)
    return _checked(CONTEXT.subtract, dec(a), dec(b))


def multiply(a, b) -> float:
    if -_SMALL < a < _SMALL and -_SMALL < b < _SMALL and not (a * 8.0 % 1.0 or b * 8.0 % 1.0):
        product = a * b  # exact when it is below 1E9: the multiples of 1/64 below 1E9 are floats
        if -_SMALL < product < _SMALL and not product * 8.0 % 1.0:
            return float(product)
    return _checked(CONTEXT.multiply, dec(a), dec(b))


def divide(a, b) -> float:
    if b == 0:
        raise BasicError("Division by zero", DIVISION_BY_ZERO)
    if -_SMALL < a < _SMALL and -_SMALL < b < _SMALL and not (a * 8.0 % 1.0 or b * 8.0 % 1.0):
        quotient = a / b
        # quotient * b is exact (both multiples of 1/8, product near a, below 1E9):
        # equal to a only when the quotient is exact
        if -_SMALL < quotient < _SMALL and not quotient * 8.0 % 1.0 and quotient * b == a:
            return float(quotient)
    return _checked(CONTEXT.divide, dec(a), dec(b))


def rounded(x) -> float:
    """Any value (a literal, READ, INPUT, a Python area's result) as a 12-digit decimal:
    :func:`dec`'s decimal (the one every operation reads the value as), as a float, 0
    below 1E-99 in size, ``Overflow`` from 1E+100 on (without the decimal module: the
    nearest double of a decimal is monotone in it, so the doubles compare as the decimals)."""
    if x != x or x in (math.inf, -math.inf):
        return x
    value = float(format(x, ".12g"))
    if -1e100 < value < 1e100:
        return value if value >= 1e-99 or value <= -1e-99 else 0.0
    raise BasicError("Overflow", OVERFLOW)


def power(a, b) -> float:
    """a ^ b: 0 ^ negative is Division by zero, negative ^ fraction Illegal function call."""
    if b == 2:  # the exact square rounded once: the product a * a
        return multiply(a, a)
    da, db = dec(a), dec(b)
    if da == 0 and db < 0:
        raise BasicError("Division by zero", DIVISION_BY_ZERO)
    if da < 0 and db != db.to_integral_value():
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    if db == db.to_integral_value() and abs(db) <= 1000:
        return _checked(CONTEXT.power, da, int(db))
    return _checked(CONTEXT.power, da, db)


# SQR, EXP, LOG, SIN and COS from the float functions, where that gives the decimal
# result for sure: the float function's value is within a known error of the exact
# value for the decimal operand (the float's own error and the operand's distance
# from its decimal); when every number that close rounds to the same DIGITS digits, that
# is the correctly rounded result the decimal module gives, at a twentieth of its cost
# (a few in a thousand lie too near a rounding boundary and take the decimal module).

def _own_decimal(x) -> bool:
    """Is ``x`` the nearest float to its decimal (every value the arithmetic makes is)?  A whole
    number below 1E+12 in size is (it is its decimal, of at most 12 digits), without formatting."""
    if -1e12 < x < 1e12 and x % 1.0 == 0.0:
        return True
    return x == x and abs(x) != math.inf and float(format(x, _OWN_FORMAT)) == x


def _off_own(x, per_unit: float) -> float:
    """How far an own decimal's angle ``x`` may be from its decimal, times ``per_unit``: 0 for a
    whole number below 1E+15 (its double is its decimal: the decimal's digits after the point
    would be more than half the double's unit away), else half the double's unit, ``x * 2**-53``
    (``per_unit`` then carries the 1.1e-16 and the angle's unit)."""
    return 0.0 if x % 1.0 == 0.0 and -1e15 < x < 1e15 else abs(x) * per_unit


def _surely(value: float, error: float):
    """``value`` rounded to DIGITS digits as a float when every number within ``error``
    of it rounds to the same, else None.  (The ends' roundings agree only when no
    halfway point lies between them, so half up and half even agree there.)"""
    found = rounded_within(value, error)  # the common decades: the scaled float's whole number
    if found is not None or 1e-11 <= abs(value) < 1e12:
        return found
    if not 1e-90 < abs(value) < 1e90:
        return None
    low = format(value - error, _DIGITS_FORMAT)
    return float(low) if low == format(value + error, _DIGITS_FORMAT) else None


_DIGITS_FORMAT = f".{DIGITS - 1}e"  # DIGITS significant digits
_OWN_FORMAT = f".{DIGITS}g"


def sqrt(x) -> float:
    if x > 0 and _own_decimal(x):
        value = math.sqrt(x)
        found = _surely(value, value * 4e-16)
        if found is not None:
            return found
    d = dec(x)
    if d < 0:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    return _checked(CONTEXT.sqrt, d)


def exp(x) -> float:
    if -200.0 < x < 200.0 and _own_decimal(x):
        value = math.exp(x)
        found = _surely(value, value * (abs(x) * 1.2e-16 + 5e-16))
        if found is not None:
            return found
    return _checked(CONTEXT.exp, dec(x))


def log(x) -> float:
    if x > 0 and _own_decimal(x):
        value = math.log(x)
        found = _surely(value, abs(value) * 5e-16 + 2.5e-16)
        if found is not None:
            return found
    d = dec(x)
    if d <= 0:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    return _checked(CONTEXT.ln, d)


def _float_sine_or_cosine(x, degrees: bool, which: int):
    """SIN (``which`` 0) or COS (1) of ``x`` from the float functions when sure (see
    :func:`_surely`), else None (also at multiples of 90 degrees, which are exact).

    In degrees the angle is first brought to at most 45 degrees with exact float
    steps (a remainder, and differences within a factor of two of each other), so
    the float angle in radians is off by a few parts in 10^16 of itself."""
    if not _own_decimal(x) or abs(x) > 1e9 or (degrees and x % 90.0 == 0.0):
        return None
    if not degrees:
        value = math.cos(x) if which else math.sin(x)
        return _surely(value, _off_own(x, 1.2e-16) + 4e-16 + abs(value) * 4e-16)
    angle = math.fmod(x, 360.0)
    if angle > 180.0:
        angle -= 360.0
    elif angle < -180.0:
        angle += 360.0
    sign = 1.0
    if angle < 0.0:
        angle = -angle
        sign = 1.0 if which else -1.0  # cos is even, sin odd
    if angle > 90.0:
        angle = 180.0 - angle
        sign = -sign if which else sign  # cos(180 - a) = -cos a, sin(180 - a) = sin a
    if angle > 45.0:  # the other function of the complement
        angle, which = 90.0 - angle, 1 - which
    value = sign * (math.cos(math.radians(angle)) if which else math.sin(math.radians(angle)))
    return _surely(value, abs(value) * 6e-16 + _off_own(x, 2.2e-18))


def log10(x) -> float:
    """The Casio's LOG (the common logarithm), correctly rounded (from the float function where
    sure, as :func:`log`: its error is at most 2 units in the last place, and the operand's
    distance from its decimal moves the logarithm by at most 5e-17)."""
    if x > 0 and _own_decimal(x):
        value = math.log10(x)
        found = _surely(value, abs(value) * 5e-16 + 2.5e-16)
        if found is not None:
            return found
    d = dec(x)
    if d <= 0:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    return _checked(CONTEXT.log10, d)


def held(x):
    """A number Python code stores (a Python area, the API) as the program holds it: a
    12-digit decimal (:func:`rounded`); one of 1E+100 or more in size, an infinity or NaN as
    it is (the operation that reads it gives the Overflow)."""
    return rounded(x) if -9.999999999995e99 < x < 9.999999999995e99 else x


def rounding(f):
    """``f`` with its numeric result rounded to 12 digits (:func:`rounded`): of a tuple (POL's
    and REC's pair, INPUT's list of values) each number; strings and None (an INPUT item left as it
    was) as they are."""
    def rounded_call(*args):
        value = f(*args)
        if type(value) in (tuple, list):
            return type(value)(v if v is None or type(v) is str else rounded(v) for v in value)
        return value if value is None or type(value) is str else rounded(value)
    return rounded_call


def rounding_all(functions: dict) -> dict:
    """``functions`` (name -> callable) with each numeric result rounded to 12 digits."""
    return {name: rounding(f) for name, f in functions.items()}


# The compiled code's helpers that bring numbers in from outside the arithmetic (READ, INPUT,
# INPUT#, VAL, RND, RAN#): each gives 12-digit decimals, as the calculator stores them, so
# that every value the program holds is one (the compiled + - * / rely on it: decimal_scales.py)
ENTERING = ("_read_n", "_input", "_fin_n", "_val", "_rnd", "_rndf", "_ran")


# ------------------------------------------------------------------ trigonometry

def _sin_cos_radians(r: Decimal) -> tuple[Decimal, Decimal]:
    """sin and cos of ``r`` (|r| <= pi/4 after reduction) with 25 digits, by their series."""
    ctx = _WIDE
    r2 = ctx.multiply(r, r)
    sin_sum, cos_sum = r, Decimal(1)
    sin_term, cos_term = r, Decimal(1)
    k = 1
    while True:
        sin_term = ctx.divide(ctx.multiply(-sin_term, r2), (2 * k) * (2 * k + 1))
        cos_term = ctx.divide(ctx.multiply(-cos_term, r2), (2 * k - 1) * (2 * k))
        if abs(sin_term) < Decimal("1e-30") and abs(cos_term) < Decimal("1e-30"):
            return sin_sum, cos_sum
        sin_sum, cos_sum = ctx.add(sin_sum, sin_term), ctx.add(cos_sum, cos_term)
        k += 1


def _sin_cos(angle: Decimal, degrees: bool) -> tuple[Decimal, Decimal]:
    """sin and cos of ``angle`` (degrees or radians) with 25 digits; the reduction to
    octants is exact in degrees (a decimal remainder)."""
    ctx = _WIDE
    if degrees:
        turn, quarter = Decimal(360), Decimal(90)
        a = angle % turn
        to_radians = ctx.divide(_PI, 180)
    else:
        turn, quarter = ctx.multiply(_PI, 2), ctx.divide(_PI, 2)
        a = ctx.subtract(angle, ctx.multiply(turn, (angle / turn).to_integral_value(rounding="ROUND_FLOOR")))
        to_radians = Decimal(1)
    if a < 0:
        a = ctx.add(a, turn)
    k = int(ctx.divide(a, quarter).to_integral_value(rounding="ROUND_HALF_EVEN")) % 4
    rest = ctx.subtract(a, ctx.multiply(quarter, int(ctx.divide(a, quarter).to_integral_value(rounding="ROUND_HALF_EVEN"))))
    s, c = _sin_cos_radians(ctx.multiply(rest, to_radians))
    return [(s, c), (c, -s), (-s, -c), (-c, s)][k]


def _exact_quadrant(d: Decimal, degrees: bool):
    """(sin, cos) exactly at multiples of 90 degrees, else None."""
    if degrees and d % 90 == 0:
        return [(0, 1), (1, 0), (0, -1), (-1, 0)][int(d % 360) // 90]
    return None


def _sine_or_cosine(x, degrees: bool, which: int) -> float:
    """SIN (``which`` 0) or COS (1) of ``x``, rounded to 12 digits."""
    found = _float_sine_or_cosine(x, degrees, which)
    if found is not None:
        return found
    d = dec(x)
    exact = _exact_quadrant(d, degrees)
    if exact is not None:
        return float(exact[which])
    return _checked(CONTEXT.plus, _sin_cos(d, degrees)[which])


def sin(x, degrees: bool = True) -> float:
    return _sine_or_cosine(x, degrees, 0)


def cos(x, degrees: bool = True) -> float:
    return _sine_or_cosine(x, degrees, 1)


def tan(x, degrees: bool = True) -> float:
    d = dec(x)
    exact = _exact_quadrant(d, degrees)
    if exact is not None:
        if exact[1] == 0:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        return 0.0
    s, c = _sin_cos(d, degrees)
    return _checked(CONTEXT.plus, _WIDE.divide(s, c))


def _atan_radians(d: Decimal) -> Decimal:
    """atan with 25 digits: halve the argument three times (atan x = 2 atan(x / (1 +
    sqrt(1 + x^2)))), then the series."""
    ctx = _WIDE
    negative = d < 0
    x = abs(d)
    invert = x > 1
    if invert:
        x = ctx.divide(1, x)
    for _ in range(3):
        x = ctx.divide(x, ctx.add(1, ctx.sqrt(ctx.add(1, ctx.multiply(x, x)))))
    x2, term, total, k = ctx.multiply(x, x), x, x, 1
    while abs(term) > Decimal("1e-30"):
        term = ctx.multiply(-term, x2)
        total = ctx.add(total, ctx.divide(term, 2 * k + 1))
        k += 1
    result = ctx.multiply(total, 8)
    if invert:
        result = ctx.subtract(ctx.divide(_PI, 2), result)
    return -result if negative else result


def atn(x, degrees: bool = True) -> float:
    r = _atan_radians(dec(x))
    if degrees:
        r = _WIDE.divide(_WIDE.multiply(r, 180), _PI)
    return _checked(CONTEXT.plus, r)


class WholeDegrees(dict):
    """SIN (``which`` 0) or COS (1) of the whole angles 0 to 359 degrees (float keys), each the
    routine's result (:func:`_sine_or_cosine`), computed when first asked for.

    The compiled code looks up ``x % 360.0`` for a whole ``x`` below 1E+9 in size
    (decimal_calls.WHOLE_TABLE_LIMIT): the remainder of a whole double is exact, and the
    routine's result at ``x`` is its result at that remainder ``r``, step for step.  Its float
    path takes ``fmod(x, 360)`` (``x``, or ``r`` or ``r - 360``: the same angle after its own
    reduction to -180..180), tests ``x % 90`` (the same for both) and bounds the error with
    ``_off_own`` (0 for both, whole numbers); its decimal path reduces the decimal by 360 exactly
    to the same ``a`` from 0 up, and its right angles (``_exact_quadrant``) index a list of four
    by ``d % 360 // 90``, the same entry from both."""

    def __init__(self, which: int):
        super().__init__()
        self.which = which

    def __missing__(self, angle: float) -> float:
        value = self[angle] = _sine_or_cosine(angle, True, self.which)
        return value


WHOLE_SINES, WHOLE_COSINES = WholeDegrees(0), WholeDegrees(1)  # (shared: the values never change)


def trig_functions(unit: str) -> dict:
    """The compiled code's ``_sin _cos _tan _atn`` (and the bounds of the float SIN and COS its
    inline code tries first: decimal_calls.py) in decimal arithmetic, in ``unit``
    ("DEG", "RAD" or "GRA": a grad is 0.9 degree, exactly in decimal)."""
    tables = {"_SDs": WHOLE_SINES, "_SDc": WHOLE_COSINES}  # (used in degrees only: angle_functions' _Xu)
    if unit == "GRA":
        return {**angle_functions(unit), **tables, "_sin": lambda x: sin(multiply(x, 0.9)), "_cos": lambda x: cos(multiply(x, 0.9)),
                "_tan": lambda x: tan(multiply(x, 0.9)), "_atn": lambda x: divide(atn(x), 0.9)}
    degrees = unit != "RAD"
    return {**angle_functions(unit), **tables, "_sin": partial(_sine_or_cosine, degrees=degrees, which=0),
            "_cos": partial(_sine_or_cosine, degrees=degrees, which=1),
            "_tan": lambda x: tan(x, degrees), "_atn": lambda x: atn(x, degrees)}


RUNTIME = {
    "_dadd": add, "_dsub": subtract, "_dmul": multiply, "_ddiv13": divide, "_d13": rounded,
    "_pow": power, "_sqrt": sqrt, "_exp": exp, "_log": log, "_log10": log10,
}
