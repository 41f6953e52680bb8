"""PRINT USING's digits of a GW-BASIC double, step by step as its output routines find them.

MATH2.ASM's ``$FOTNV`` brackets the double so that its 16 printable digits are its
integer part, in MBF double precision (:mod:`mbf_double`'s ``$FMULD``/``$FDIVD``):

* while the table ``$FOTB`` (MATH1.ASM, indexed by the exponent byte) gives a power n
  other than 0, the number is multiplied by the table's 10**n (``MDPTEN``: ``$FMULD``;
  for a negative n divided by 10**-n, ``DDIVFA``); the table brings the number to
  2**19 .. 2**23;
* below 10**6 it is multiplied by 10 (``$MUL10``), then by 10**9 (``$FMULD``); above
  the table's ``HIDBL`` (9999999999999999.25) it is "divided" by ten (``$DIV10``,
  which multiplies by the double nearest 0.1, ``$DPM01``).

The number is then ``bracketed * 10**power``.  For a field that shows fewer digits,
``$PUF`` (fixed point) and ``$PUFE`` (``^^^^``) call ``$DIV10`` once per digit too many,
each a rounded product by 0.1, and ``$FOTCV`` rounds to a whole number by adding .5
(``$DADDH``, a ``$FADDD``) when the number is not whole and cutting the fraction;
``$PUFE`` adds .5 and cuts itself (``$VADDH``, ``$VINT``) and, when that carried into a
new digit, divides by ten once more.  A double is a tuple (negative, exponent byte,
56-bit mantissa) as in :mod:`mbf_double`; only magnitudes are formatted here.
"""

from __future__ import annotations

from yaseer.basic.arithmetic import mbf_double

# $FOTB: the power of ten $FOTNV applies for each exponent byte (0 from byte 148 to 151)
FOTB = (  # by exponent byte, 0 .. 255
    38, 38, 38, 38, 38, 38, 38, 38, 38, 38, 38, 38, 38, 38, 38, 38,
    38, 38, 38, 38, 38, 38, 38, 38, 38, 37, 37, 37, 36, 36, 36, 35,
    35, 35, 34, 34, 34, 34, 33, 33, 33, 32, 32, 32, 31, 31, 31, 31,
    30, 30, 30, 29, 29, 29, 29, 28, 28, 28, 27, 27, 27, 26, 26, 26,
    25, 25, 25, 25, 24, 24, 24, 23, 23, 23, 23, 22, 22, 22, 22, 21,
    21, 21, 20, 20, 20, 19, 19, 19, 19, 18, 18, 18, 17, 17, 17, 16,
    16, 16, 16, 15, 15, 15, 14, 14, 14, 13, 13, 13, 13, 12, 12, 12,
    11, 11, 11, 10, 10, 10, 10, 9, 9, 9, 8, 8, 8, 7, 7, 7,
    6, 6, 6, 6, 5, 5, 5, 4, 4, 4, 3, 3, 3, 3, 2, 2,
    2, 1, 1, 1, 0, 0, 0, 0, -1, -1, -1, -2, -2, -2, -3, -3,
    -3, -3, -4, -4, -4, -5, -5, -5, -6, -6, -6, -6, -7, -7, -7, -8,
    -8, -8, -9, -9, -9, -9, -10, -10, -10, -11, -11, -11, -12, -12, -12, -12,
    -13, -13, -13, -14, -14, -14, -15, -15, -15, -15, -16, -16, -16, -17, -17, -17,
    -18, -18, -18, -18, -19, -19, -19, -20, -20, -20, -21, -21, -21, -21, -22, -22,
    -22, -23, -23, -23, -24, -24, -24, -25, -25, -25, -25, -26, -26, -26, -27, -27,
    -27, -28, -28, -28, -28, -29, -29, -29, -30, -30, -30, -31, -31, -31, -31, -32,
)

TENTH = (False, 125, 0xCCCCCCCCCCCCCD)  # $DPM01: the double nearest 0.1, rounded up
HALF = (False, 128, 1 << 55)  # $DHALF
HIDBL = (False, 182, 39999999999999997)  # 9999999999999999.25: the largest $FOTCV may add .5 to
_MILLION = mbf_double.power_of_ten(6)
_TEN = mbf_double.power_of_ten(1)
_BILLION = mbf_double.power_of_ten(9)


def table_steps(p: tuple[bool, int, int], rounded=None) -> tuple[tuple[bool, int, int], int]:
    """``$FOTNV``'s walk by the ``$FOTB`` table from the nonnegative double ``p``: each step
    multiplies or divides by the table's power of ten for ``p``'s exponent byte (``rounded``,
    if given, applied to each result: a single's ``$CSD``); ``(p, power)`` once the table
    says 0, with the original ``p`` about ``p * 10**power``."""
    power = 0
    while True:
        n = FOTB[p[1]]
        if not n:
            return p, power
        power -= n
        p = mbf_double.multiply(p, mbf_double.power_of_ten(n)) if n > 0 else \
            mbf_double.divide(p, mbf_double.power_of_ten(-n))
        if rounded is not None:
            p = rounded(p)


def bracketed(p: tuple[bool, int, int]) -> tuple[tuple[bool, int, int], int]:
    """``$FOTNV`` of a nonzero double's magnitude ``p``: ``(b, power)``, ``b`` about 10**15 ..
    10**16 and ``abs(p)`` about ``b * 10**power`` (module docstring)."""
    p, power = table_steps((False, p[1], p[2]))
    if mbf_double.compare(p, _MILLION) < 0:
        p = mbf_double.multiply(p, _TEN)
        power -= 1
    p = mbf_double.multiply(p, _BILLION)
    power -= 9
    if mbf_double.compare(p, HIDBL) > 0:
        p = mbf_double.multiply(p, TENTH)
        power += 1
    return p, power


def _tenths(p: tuple[bool, int, int], times: int) -> tuple[bool, int, int]:
    """``$DIV10`` ``times`` times: each a ``$FMULD`` by :data:`TENTH`."""
    for _ in range(times):
        p = mbf_double.multiply(p, TENTH)
    return p


def _whole(p: tuple[bool, int, int]) -> int:
    """The whole number below a positive double (``$DINT``, ``$FTDNT``: the fraction cut)."""
    _, exponent, mantissa = p
    if not exponent:
        return 0
    shift = exponent - 184
    return mantissa << shift if shift >= 0 else mantissa >> -shift


def _rounded_whole(p: tuple[bool, int, int]) -> int:
    """``$FOTCV``'s integer: a positive double plus .5 (``$DADDH``) unless it is whole, cut."""
    whole = _whole(p)
    if mbf_double.compare(p, mbf_double.from_integer(whole)) == 0:
        return whole
    return _whole(mbf_double.add(p, HALF))


def field_digits(b, power: int, places: int, tenths, rounded_whole) -> tuple[int, int]:
    """``$PUF``'s steps for a fixed field of ``places`` decimals on a bracket ``b`` (the
    magnitude about ``b * 10**power``; a double's or a single's, with its ``tenths(b, k)``,
    ``$DIV10`` k times, and its ``rounded_whole``, ``$FOTCV``): ``(n, shown)``, the
    magnitude printed as ``n * 10**-shown`` (``shown`` <= ``places``: the field adds zeros)."""
    if power >= 0:
        return rounded_whole(b) * 10 ** power, 0
    excess = -(places + power)  # digits right of the point beyond the field's
    if excess > 0:
        return rounded_whole(tenths(b, excess)), places
    return rounded_whole(b), -power


def scientific_field_digits(b, power: int, digits: int, printable: int, tenths, half_added_cut,
                            rounded_whole, number) -> tuple[int, int]:
    """``$PUFE``'s steps for a ``^^^^`` field showing ``digits`` digits on a bracket ``b`` of
    ``printable`` digits (16 or 7), with the type's ``tenths`` and ``rounded_whole`` (see
    :func:`field_digits`), ``half_added_cut`` (``$VADDH``, ``$VINT``) and ``number`` (a whole
    number as the type): ``(n, power)``, the magnitude printed as ``n * 10**power``."""
    excess = printable - digits
    if excess <= 0:
        return rounded_whole(b) * 10 ** -excess, power + excess
    n = half_added_cut(tenths(b, excess))
    power += excess
    if n >= 10 ** digits:  # the rounding carried into a new digit: one more $DIV10
        n = rounded_whole(tenths(number(n), 1))
        power += 1
    return n, power


def _half_added_cut(p: tuple[bool, int, int]) -> int:
    return _whole(mbf_double.add(p, HALF))


def fixed_digits(p: tuple[bool, int, int], places: int) -> tuple[int, int]:
    """``$PUF``'s digits of a nonzero double's magnitude for a field of ``places``
    decimals (from 10**16 up: its 16 digits and zeros): ``(n, shown)`` with the magnitude printed as ``n * 10**-shown``
    (``shown`` <= ``places``: the field adds zeros after the 16 digits)."""
    return field_digits(*bracketed(p), places, _tenths, _rounded_whole)


def scientific_digits(p: tuple[bool, int, int], digits: int) -> tuple[int, int]:
    """``$PUFE``'s digits of a nonzero double's magnitude for a ``^^^^`` field showing
    ``digits`` digits: ``(n, power)``, the magnitude printed as ``n * 10**power`` with
    ``n`` below 10**digits (zeros after 16 digits)."""
    return scientific_field_digits(*bracketed(p), digits, 16, _tenths, _half_added_cut, _rounded_whole,
                                   mbf_double.from_integer)


def printed_digits(p: tuple[bool, int, int]) -> tuple[int, int]:
    """PRINT's (and STR$'s) 16 digits of a nonzero double's magnitude, as ``$FOFMT`` finds
    them (MATH1.ASM): ``$FOTNV``'s bracket rounded to a whole number by ``$FOTCV``;
    ``(n, power)``, the magnitude about ``n * 10**power``, ``n`` of 16 digits."""
    b, power = bracketed(p)
    return _rounded_whole(b), power
