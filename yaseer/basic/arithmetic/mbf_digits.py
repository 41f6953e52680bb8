"""PRINT's digits of a single as GW-BASIC's output routine finds them (a double's:
:mod:`yaseer.basic.arithmetic.mbf_double_using`).

The number, as a working number of its format (a 32-bit mantissa for a single, 64
bits for a double: the 24 or 56 bits and a guard byte; see
:mod:`yaseer.basic.arithmetic.single_arith`), is brought between the largest values of its
format below 10**(n-1) and 10**n (n = 7 or 16 digits) by dividing and multiplying
by ten in working precision; its guard byte is rounded half up after each of the
two loops, then it is rounded half up to an integer of n digits.  This is the
routine as PC-BASIC 2.0.8 reproduces it (``Float.to_decimal``), which the
differential tests compare against: ``825157.625!`` shows as 825157.7 (the guard
byte is rounded before the last digit is).
"""

from __future__ import annotations

from collections import namedtuple

from yaseer.basic.arithmetic.single_arith import working_parts, working_quotient, working_sum

Format = namedtuple("Format", "width bits digits top bottom ten")
Format.__doc__ = """An MBF format's working numbers: ``width`` bits of working mantissa,
``bits`` of mantissa, ``digits`` printed; ``top`` and ``bottom`` the largest values
below 10**digits and 10**(digits-1), ``ten`` 10, as working numbers."""


def _below_power_of_ten(power: int, bits: int, width: int) -> tuple[int, int]:
    """The largest value of ``bits`` mantissa bits below 10**power, as a working number."""
    e = (10 ** power).bit_length()  # 10**power lies in [2**(e-1), 2**e)
    return e + 128, ((10 ** power << (bits - e)) - 1) << (width - bits)


def _format(width: int, bits: int, digits: int) -> Format:
    return Format(width, bits, digits, _below_power_of_ten(digits, bits, width),
                  _below_power_of_ten(digits - 1, bits, width), working_parts(10.0, width))


SINGLE = _format(32, 24, 7)


def decimal_digits(x, form: Format = SINGLE) -> tuple[int, int]:
    """``(n, power)`` with ``abs(x)`` shown as ``n * 10**power``, ``n`` of
    ``form.digits`` digits, for a nonzero ``x`` that ``form`` holds exactly."""
    return decimal_digits_of(*working_parts(x, form.width), form)


def decimal_digits_of(exponent: int, mantissa: int, form: Format = SINGLE) -> tuple[int, int]:
    """:func:`decimal_digits` of a nonzero working number (exponent byte, ``form.width``-bit
    mantissa): a double's 56 bits and a zero guard byte."""
    width = form.width
    top, half_top = 1 << width, 1 << (width - 1)
    power = 0
    while (exponent, mantissa) > form.top:
        exponent, mantissa = working_quotient(exponent, mantissa, *form.ten, width=width)
        if mantissa < half_top:
            shift = width - mantissa.bit_length()
            mantissa <<= shift
            exponent -= shift
        power += 1
    exponent, mantissa = _carried(exponent, mantissa, top)
    while (exponent, mantissa) < form.bottom:
        exponent, mantissa, _ = working_sum(exponent + 1, mantissa, False, exponent + 3, mantissa, False, top)
        power -= 1
    exponent, mantissa = _carried(exponent, mantissa, top)
    shift = exponent - (128 + form.bits)
    mantissa = mantissa << shift if shift > 0 else mantissa >> -shift
    if mantissa & 0x80:
        mantissa += 0x80
    return mantissa >> 8, power


def digit_string(x, form: Format = SINGLE) -> tuple[str, int]:
    """:func:`decimal_digits` as PRINT uses them: (the digits without trailing zeros,
    the decimal exponent of the first digit)."""
    return _shown(*decimal_digits(x, form), form)


def digit_string_of(exponent: int, mantissa: int, form: Format = SINGLE) -> tuple[str, int]:
    """:func:`digit_string` of a working number (see :func:`decimal_digits_of`)."""
    return _shown(*decimal_digits_of(exponent, mantissa, form), form)


def _shown(n: int, power: int, form: Format) -> tuple[str, int]:
    return str(n).rjust(form.digits, "0").rstrip("0") or "0", power + form.digits - 1


def _carried(exponent: int, mantissa: int, top: int) -> tuple[int, int]:
    """A working number's guard byte rounded half up into its mantissa (and cleared)."""
    if mantissa & 0xFF > 0x7F:
        mantissa += 0x100
        if mantissa >= top:
            exponent += 1
            mantissa >>= 1
    return exponent, mantissa & ~0xFF
