"""Functions the compiled BASIC code calls: arithmetic with BASIC's errors, trig in
degrees or radians, the string functions.

Everything here works on Python floats (double precision) and str.  Errors are
raised as ``BasicError`` (or as the Python exception the machine maps: a
``ValueError`` from ``math`` is ``Illegal function call``).
"""

from __future__ import annotations

import math
import operator
from collections import deque
from itertools import repeat

from yaseer.basic.arithmetic.values import Wide, nearest_integer, to_int, to_single
from yaseer.basic.errors import (
    BasicError, DIVISION_BY_ZERO, ILLEGAL_FUNCTION_CALL, OVERFLOW, STRING_TOO_LONG,
)

_RADIANS_PER_DEGREE = math.pi / 180.0


def illegal_function_call() -> BasicError:
    return BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)


def byte_argument(k: int) -> int:
    """An argument GW-BASIC reads with GETBYT (already a whole number): 0..255, else Illegal
    function call."""
    if not 0 <= k <= 255:
        raise illegal_function_call()
    return k


def fail(message: str, code: int):
    """Raise the BASIC error ``message`` (a PRINT item the compiler found bad, reached at run time)."""
    raise BasicError(message, code)


def fail_after(_value, message: str, code: int):
    """Raise the BASIC error ``message`` once the value before it has been computed (an
    expression cut short after an operator: its operand is read first)."""
    raise BasicError(message, code)


def overflow() -> None:
    """Raise Overflow: a result beyond double range (the code checks ``x - x``)."""
    raise BasicError("Overflow", OVERFLOW)


def subscript(x: float) -> int:
    """An array subscript: rounded to the nearest integer, half away from zero (GW's
    INTIDX takes CINT's integer: values.nearest_integer, exact on a double's 56 bits).

    A negative subscript, -.5 among them, is ``Illegal function call`` (GWMAIN.ASM
    INTIDX, as PC-BASIC 2.0.8); one above the dimension is ``Subscript out of range``
    (an IndexError).
    """
    if x >= 0.5 and type(x) is not Wide:  # (the common case: x + 0.5 is exact, see nearest_integer)
        return int(x + 0.5)
    k = nearest_integer(x)
    if k < 0:
        raise illegal_function_call()
    return k


def subscript_truncated(x: float) -> int:
    """An array subscript on the Casio: its fraction disregarded (part 6, Arrays: "Fractions
    are disregarded"); below 0 is ``Subscript out of range`` (the BS error)."""
    k = int(x)
    if k < 0:
        raise IndexError("negative subscript")
    return k


def subscript_integer(x: float) -> int:
    """An array subscript where there are integers (gw): as :func:`subscript`, but made a
    16-bit integer first (GWMAIN.ASM INTIDX calls FRCINT: beyond -32768..32767 ``Overflow``,
    before the negative test; PC-BASIC 2.0.8 agrees)."""
    if 0.5 <= x < 32767.5 and type(x) is not Wide:
        return int(x + 0.5)
    k = to_int(x)
    if k < 0:
        raise illegal_function_call()
    return k


def from_one(read):
    """The subscript reader ``read`` under OPTION BASE 1: 0 is ``Subscript out of range``."""
    def subscript_from_one(x: float) -> int:
        k = read(x)
        if k == 0:
            raise IndexError("subscript 0 under OPTION BASE 1")
        return k
    return subscript_from_one


def cint(x: float) -> int:
    """Round to an integer for the logical operators, ON and CHR$ (half away from zero,
    exactly: values.nearest_integer)."""
    return nearest_integer(x)


def unsigned_word(x: float) -> int:
    """``x`` as GW-BASIC's unsigned 16-bit number 0..65535, as GWMAIN.ASM FRQINT makes it:
    a positive number from 32768 below 65536 is made a single and 65536 taken off before it
    is rounded to an integer (FRCINT), any other rounded as it is; a rounded value outside
    -32768..32767 is Overflow (so 32767.6 and -32768.6 are, 65535.6 is 0); -32768..-1 count
    from 65536."""
    if 32768.0 <= x < 65536.0:
        x = to_single(x) - 65536.0
    n = nearest_integer(x)
    if not -32768 <= n <= 32767:
        overflow()
    return n & 0xFFFF


def signed_word(n: int) -> int:
    """The low 16 bits of ``n`` read as a signed number -32768..32767 (a 16-bit register)."""
    n &= 0xFFFF
    return n - 0x10000 if n & 0x8000 else n


def power(a: float, b: float) -> float:
    """a ^ b; 0 ^ negative is Division by zero, negative ^ fraction Illegal function call."""
    try:
        return math.pow(a, b)
    except ValueError:
        if a == 0.0:
            raise BasicError("Division by zero", DIVISION_BY_ZERO) from None
        raise illegal_function_call() from None


def int_divide(a: float, b: float) -> float:
    """a \\ b: both rounded to integers, quotient truncated toward zero."""
    x, y = cint(a), cint(b)
    if y == 0:
        raise BasicError("Division by zero", DIVISION_BY_ZERO)
    q = abs(x) // abs(y)
    return float(q if (x >= 0) == (y >= 0) else -q)


def modulo(a: float, b: float) -> float:
    """a MOD b: both rounded to integers; the remainder has the sign of a."""
    x, y = cint(a), cint(b)
    if y == 0:
        raise BasicError("Division by zero", DIVISION_BY_ZERO)
    return float(math.fmod(x, y))


def logical_and(a: float, b: float) -> float:
    return float(cint(a) & cint(b))


def logical_or(a: float, b: float) -> float:
    return float(cint(a) | cint(b))


def logical_not(a: float) -> float:
    return float(~cint(a))


def sign(x: float) -> float:
    return 1.0 if x > 0 else (-1.0 if x < 0 else 0.0)


def floor(x: float) -> float:
    """INT: the largest integer not above x."""
    return float(math.floor(x))


def fix(x: float) -> float:
    """FIX: x with its fraction dropped (toward zero)."""
    return float(math.trunc(x))


_EXACT = 2.0 ** 52  # below this, integers and their sums are exact doubles


def _whole_passes(start: float, limit: float, step: float, exact: float) -> bool:
    """Are the loop's values, and the one after the last, whole numbers below ``exact``
    (where ``+ step`` is exact)?"""
    return (start == int(start) and step == int(step) and step != 0
            and abs(start) < exact and abs(step) < exact and abs(limit) + abs(step) < exact)


def float_range(start: float, limit: float, step: float, exact: float = _EXACT, add=operator.add):
    """The values a FOR variable takes, as floats, exactly as repeated ``+ step`` gives them.

    The caller has checked that the first pass runs.  Whole numbers below ``exact``
    (2**52 for doubles, 2**24 for singles) use a C-level ``range``; anything else adds
    the step one pass at a time with ``add`` (a single's: single_arith.add).
    """
    if _whole_passes(start, limit, step, exact):
        first, stride = int(start), int(step)
        if stride > 0:
            count = (math.floor(limit) - first) // stride
            return map(float, range(first, first + count * stride + 1, stride))
        count = (first - math.ceil(limit)) // -stride
        return map(float, range(first, first + count * stride - 1, stride))
    return _accumulate(start, limit, step, add)


_SINGLE_EXACT = 2.0 ** 24  # below this, whole singles and their sums are exact


def single_loop_helpers() -> dict:
    """The compiled code's ``_frange`` and ``_fcount`` for single-precision FOR variables:
    a ``range`` only where every value is a whole number below 2**24; elsewhere each
    ``+ step`` rounds as GW-BASIC's ``$FADDS`` (single_arith.add)."""
    from functools import partial

    from yaseer.basic.arithmetic.single_arith import add

    return {"_frange": partial(float_range, exact=_SINGLE_EXACT, add=add),
            "_fcount": partial(pass_counter, exact=_SINGLE_EXACT, add=add)}


class _Accumulator:
    """Counts the passes of a FOR loop with fractional values; ``value`` is the variable."""

    __slots__ = ("value", "limit", "step", "add")

    def __init__(self, value: float, limit: float, step: float, add=operator.add):
        self.value, self.limit, self.step, self.add = value, limit, step, add

    def __iter__(self):
        step, limit, add = self.step, self.limit, self.add
        passes = 0
        while (self.value <= limit) if step >= 0 else (self.value >= limit):
            yield passes
            passes += 1
            self.value = add(self.value, step)


def pass_counter(start: float, limit: float, step: float, exact: float = _EXACT, add=operator.add):
    """An iterable with one item per pass of a FOR loop whose body ignores its variable.

    Whole numbers below ``exact`` give a ``range`` (see :func:`float_range`); see
    :func:`counted_value` for the variable.
    """
    if _whole_passes(start, limit, step, exact):
        first, stride = int(start), int(step)
        if stride > 0:
            return range((math.floor(limit) - first) // stride + 1)
        return range((first - math.ceil(limit)) // -stride + 1)
    return _Accumulator(start, limit, step, add)


IDLE_CHUNK = 1 << 20  # passes of an empty loop counted in one C call (about a millisecond)
_consume = deque(maxlen=0).extend


def idle_passes(passes):
    """The passes of a FOR loop whose body is empty (a delay loop), counted in C.

    ``passes`` is a :func:`pass_counter`.  For a ``range`` the passes are counted
    IDLE_CHUNK at a time by a C-level iterator; yields the index of the first pass
    of each chunk (the top of a pass where Ctrl-C may break, see
    :func:`counted_value`).  An accumulating counter yields every pass as before.
    """
    if type(passes) is not range:
        yield from passes
        return
    total = len(passes)
    for first in range(0, total, IDLE_CHUNK):
        yield first
        _consume(repeat(None, min(IDLE_CHUNK, total - first)))


def counted_value(passes, start: float, step: float, index: int) -> float:
    """The FOR variable during pass ``index`` of a :func:`pass_counter` loop."""
    if type(passes) is range:
        return start + index * step
    return passes.value


def counted_final(passes, start: float, step: float) -> float:
    """The FOR variable after a :func:`pass_counter` loop (one step past the limit)."""
    if type(passes) is range:
        return start + len(passes) * step
    return passes.value


def _accumulate(value: float, limit: float, step: float, add=operator.add):
    if step >= 0:
        while value <= limit:
            yield value
            value = add(value, step)
    else:
        while value >= limit:
            yield value
            value = add(value, step)


# ------------------------------------------------------------------ trigonometry
# In degree mode angles are reduced to [0, 360) first, and the multiples of 90
# degrees give exact values (a 10-digit pocket computer shows COS 90 = 0), so
# the paper's formulas divide by an exact zero there, as on the real machine.

_EXACT_SIN = {0.0: 0.0, 90.0: 1.0, 180.0: 0.0, 270.0: -1.0}
_EXACT_COS = {0.0: 1.0, 90.0: 0.0, 180.0: -1.0, 270.0: 0.0}


_sin, _cos = math.sin, math.cos


def sin_degrees(x: float) -> float:
    r = x % 360.0
    if r % 90.0:  # (not a multiple of 90 degrees: the common case, one test)
        return _sin(r * _RADIANS_PER_DEGREE)
    exact = _EXACT_SIN.get(r)
    return _sin(r * _RADIANS_PER_DEGREE) if exact is None else exact


def cos_degrees(x: float) -> float:
    r = x % 360.0
    if r % 90.0:
        return _cos(r * _RADIANS_PER_DEGREE)
    exact = _EXACT_COS.get(r)
    return _cos(r * _RADIANS_PER_DEGREE) if exact is None else exact


def tan_degrees(x: float) -> float:
    r = x % 180.0
    if r == 0.0:
        return 0.0
    if r == 90.0:
        raise illegal_function_call()
    return math.tan(r * _RADIANS_PER_DEGREE)


def atn_degrees(x: float) -> float:
    """ATN in degrees, in (-90, 90)."""
    return math.degrees(math.atan(x))


# ------------------------------------------------------------------ strings


def limited(text: str, longest: int) -> str:
    """``text``, or ``String too long`` when it has over ``longest`` characters (the
    dialect's ``string_length``): every string a program is given is held to it."""
    if len(text) > longest:
        raise BasicError("String too long", STRING_TOO_LONG)
    return text


def concatenation(longest: int):
    """``+`` of two strings where a string holds at most ``longest`` characters."""
    def concat(a: str, b: str) -> str:
        text = a + b
        if len(text) > longest:
            raise BasicError("String too long", STRING_TOO_LONG)
        return text
    return concat


def left(s: str, n: float) -> str:
    k = cint(n)
    if k < 0:
        raise illegal_function_call()
    return s[:k]


def right(s: str, n: float) -> str:
    k = cint(n)
    if k < 0:
        raise illegal_function_call()
    return s[max(len(s) - k, 0):]  # RIGHT$("abc", 5) is "abc"


def mid(s: str, start: float, n: float | None = None) -> str:
    i = cint(start)
    if i < 1:
        raise illegal_function_call()
    if n is None:
        return s[i - 1:]
    k = cint(n)
    if k < 0:
        raise illegal_function_call()
    return s[i - 1:i - 1 + k]


def chr_dollar(n: float) -> str:
    k = cint(n)
    if not 0 <= k <= 255:
        raise illegal_function_call()
    return chr(k)


def asc(s: str) -> float:
    if not s:
        raise illegal_function_call()
    return float(ord(s[0]))
