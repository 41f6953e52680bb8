"""GW-BASIC's transcendental functions, step by step as its math package computes them.

GW-BASIC evaluates SIN, COS, TAN, ATN, LOG, EXP and ``^`` with a fractional (or
large) exponent in single precision with Hart's polynomials (MATH1.ASM: ``$SIN``,
``$COS``, ``$TAN``, ``$ATAN``, ``$EXP``, ``$FPWR``; MATH2.ASM: ``$LOG``, ``$POLY``,
``$POLYX``).  Every step is one of the package's single-precision operations,
whose rounding :mod:`yaseer.basic.single_arith` gives (``$FADDS`` :func:`add`,
``$FMULS`` :func:`product`, ``$FDIVS`` :func:`divide`, ``$CSD``
:func:`from_double`), so the last bit is GW's and not the nearest single to the
true value (``ATN(1)`` is .7853983, the true value rounds to .7853982).
The polynomials' steps run on integer mantissas (:mod:`mbf_integers`, the same
roundings without a call per step); :func:`poly_steps` is their reference.

SIN, COS and TAN reduce their argument in MBF double precision (56-bit
mantissas): the angle times a 56-bit 1/(2*pi) (``$FMULD``: the exact product
rounded half to even), its fraction (exact), for COS plus a quarter turn
(``$FADDD``, which truncates the smaller operand as it aligns it).
:func:`_turns` and :func:`_quarter_turn_added` do those steps on integers.

Values are Python floats holding singles (24-bit mantissas, MBF's range).  A
result beyond the range is handed to ``overflow(negative)`` (GW-BASIC's
``$OVFLS``: the caller's policy prints ``Overflow`` and gives the largest single,
or raises); by default it is an infinity.  A domain error raises ValueError
(GW's ``Illegal function call``), zero to a negative power and a TAN whose
cosine is 0 raise ZeroDivisionError (``Division by zero``).
"""

from __future__ import annotations

from itertools import islice
from math import floor, frexp, inf, ldexp

from yaseer.basic.arithmetic import mbf_floats, mbf_integers
from yaseer.basic.arithmetic.mbf_double import shifted_right
from yaseer.basic.arithmetic.single_arith import add, divide, from_double, power_by_integer, product, subtract


def _mbf(word: int) -> float:
    """A single from its four MBF bytes read as one number, exponent byte first
    (``0x81000000`` is 1.0): exponent byte, sign bit, 23 mantissa bits below the
    hidden one."""
    exponent = word >> 24
    if not exponent:
        return 0.0
    mantissa = (word & 0x7FFFFF) | 0x800000
    value = ldexp(mantissa, exponent - 152)
    return -value if word & 0x800000 else value


def _exponent_byte(x: float) -> int:
    """The MBF exponent byte of a single (0 for zero): ``x`` = m * 2**(byte - 128), 0.5 <= m < 1."""
    return frexp(x)[1] + 128 if x else 0


# Constants of MATH1.ASM's table (CON86) and of the routines' immediate operands.
_ONE = 1.0
_TWO_PI = _mbf(0x83490FDB)  # 6.283185
_HALF_PI = _mbf(0x81490FDB)  # 1.570796
_SIXTH_PI = _mbf(0x80060A92)  # .5235988
_TAN_TWELFTH_PI = _mbf(0x7F0930A2)  # .2679492
_SQR3 = _mbf(0x815DB3D7)  # 1.732051
_LN2 = _mbf(0x80317218)  # .6931472
_LOG2_E = _mbf(0x8138AA3B)  # 1.442695

# Polynomial coefficients, highest power first (as $POLY reads them).
_SIN_COEFFICIENTS = tuple(map(_mbf, (  # Hart 3341, in turns: sin(2*pi*t) = t * P(t*t)
    0x861ED7FB,  # 39.71092
    0x87992665,  # -76.57498
    0x87233458,  # 81.60223
    0x86A55DE1,  # -41.34168
    0x83490FDB,  # 6.283185
)))
_ATN_REDUCTION = tuple(map(_mbf, (0x815DB3D7, 0x81800000)))  # x*SQR(3) - 1
_ATN_COEFFICIENTS = tuple(map(_mbf, (  # Hart 4940: atn(x) = x * P(x*x)
    0x7E833562,  # -.1281333
    0x7E4C2450,  # .1993573
    0x7FAAA979,  # -.3333324
    0x81000000,  # 1
)))
_LOG_NUMERATOR = tuple(map(_mbf, (  # Hart 2524: log2(m) = P(m) / Q(m), .5 <= m < 1
    0x8319F79A,  # 4.811475
    0x83436324,  # 6.105852
    0x848DCD75,  # -8.86266
    0x82837FA9,  # -2.054667
)))
_LOG_DENOMINATOR = tuple(map(_mbf, (
    0x81000000,  # 1
    0x834DB0E2,  # 6.427842
    0x8311720A,  # 4.545171
    0x7F3504F4,  # .3535534
)))
_EXP_COEFFICIENTS = tuple(map(_mbf, (  # Hart 1302: 2**z, 0 <= z < 1
    0x7459887C,  # 2.074558E-04
    0x772697E0,  # 1.271006E-03
    0x7A1E1DC4,  # 9.650651E-03
    0x7C63505E,  # .05549657
    0x7E75FE1A,  # .2402271
    0x80317218,  # .6931472
    0x81000000,  # 1
)))


# The coefficients as mbf_floats' plans and mbf_integers' integer pairs, by the identity of their tuple.
_POLYNOMIALS = (_SIN_COEFFICIENTS, _ATN_REDUCTION, _ATN_COEFFICIENTS, _LOG_NUMERATOR, _LOG_DENOMINATOR,
                _EXP_COEFFICIENTS)
_PLANS = {id(c): mbf_floats.plan(c) for c in _POLYNOMIALS}
_PARTS = {id(c): mbf_integers.coefficient_parts(c) for c in _POLYNOMIALS}
_SIN_PLAN = _PLANS[id(_SIN_COEFFICIENTS)]


def poly_steps(x: float, coefficients) -> float:
    """``$POLY`` step by step: Horner's rule from the highest coefficient, each step
    ``$FMULS`` then ``$FADDS`` (single_arith); the reference of :func:`_poly`."""
    total = coefficients[0]
    for c in coefficients[1:]:
        total = add(product(total * x), c)
    return total


def _poly(x: float, coefficients) -> float:
    """``$POLY`` (``x`` >= 0, as every caller's is): the same steps on floats
    (mbf_floats.poly, for ``x`` from 2**-60 to 1) or on integers (mbf_integers.poly), or
    :func:`poly_steps` where those hand it back."""
    if mbf_floats.LEAST_ARGUMENT <= x <= 1.0:
        result = mbf_floats.poly(x, _PLANS[id(coefficients)])
        if result is not None:
            return result
    result = mbf_integers.poly(x, _PARTS[id(coefficients)])
    return poly_steps(x, coefficients) if result is None else result


def _polyx(x: float, coefficients) -> float:
    """``$POLYX``: ``x * P(x*x)``, each product ``$FMULS`` (mbf_floats.poly's odd form for
    ``x`` from 2**-30 to 1, where every step stays well inside the range)."""
    if 9.313225746154785e-10 <= x <= 1.0:  # 2**-30
        value = mbf_floats.poly(x, _PLANS[id(coefficients)], True)
        if value is not None:
            return value
    return product(_poly(product(x * x), coefficients) * x)


# The angle reduction of $SIN and $COS (RR, RR1, RR2, RR3) in MBF double precision,
# here on integers: a fraction of a turn is ``(numerator, bits)``, numerator / 2**bits.
_INVERSE_TWO_PI = 0xA2F9836E4E440B  # $IN2PI's 56-bit mantissa: 1/(2*pi) = it * 2**-58


def _turns(x: float) -> tuple[int, int]:
    """``RR``: the fraction of ``x`` radians (``x`` > 0) in whole turns.  The product
    with 1/(2*pi) is ``$FMULD``'s (the exact product rounded half to even to 56 bits);
    taking its integer part away (``$DINT``, ``$FSUBD``) is exact."""
    if not x:
        return 0, 2
    m, e = frexp(x)
    full = int(m * 16777216.0) * _INVERSE_TWO_PI  # * 2**(e - 82): 79 or 80 bits
    drop = full.bit_length() - 56
    mantissa, rest = full >> drop, full & ((1 << drop) - 1)
    half = 1 << (drop - 1)
    if rest > half or (rest == half and mantissa & 1):
        mantissa += 1
    bits = 82 - e - drop
    if mantissa.bit_length() - bits <= -128 or bits <= 0:  # below MBF's range ($AEXPS), or whole
        return 0, 2
    if bits < 2:
        return (mantissa & 1) << 1, 2
    return mantissa & ((1 << bits) - 1), bits


def _quarter_turn_added(numerator: int, bits: int) -> tuple[int, int]:
    """``$FADDD`` of a fraction of a turn and the quarter turn ``$COS`` adds.  From a
    quarter up the quarter's one bit is shifted and the sum is exact; below it the
    fraction is shifted right in the 64-bit register (mantissa and guard byte) by
    ``$SHRA``: whole bytes first, keeping of a dropped byte only its bit 5 as the
    sticky bit, then bit by bit, a bit shifted into bit 4 setting bit 5; then
    ``$ROUND`` rounds the guard byte half to even."""
    if not numerator:
        return 1, 2
    if numerator >> (bits - 2):
        return numerator + (1 << (bits - 2)), bits
    length = numerator.bit_length()
    register = numerator << (64 - length)  # the fraction's mantissa and a zero guard byte
    shift = bits - length - 1  # its exponent below the quarter's
    if shift >= 57:
        return 1, 2
    register = shifted_right(register, shift)
    register += 1 << 63
    guard, mantissa = register & 0xFF, register >> 8
    if guard >= 0x80:
        mantissa += 1
        if guard == 0x80:
            mantissa &= ~1
    return mantissa, 57  # the quarter's exponent: 0.25 is 2**55 / 2**57


def _sine_of_turns(numerator: int, bits: int) -> float:
    """``SIN30`` onwards: the sine of ``numerator / 2**bits`` turns (below one turn).
    Four times it (the exponent byte plus 2) splits into the quadrant (``RR3``) and the
    angle in it; in quadrants 1 and 3 the angle is taken from a quarter turn (``$FSUBD``,
    exact here); a quarter of it (the exponent byte minus 2) made single (``$CSD``:
    the 25th bit rounds up) is the argument of Hart 3341 (below 2**-13: times 2*pi)."""
    quadrant = numerator >> (bits - 2)
    angle = numerator & ((1 << (bits - 2)) - 1)  # / 2**(bits - 2): a fraction of a quadrant
    if quadrant & 1:
        angle = (1 << (bits - 2)) - angle
    if not angle:
        t = 0.0
    else:
        extra = angle.bit_length() - 25
        if extra >= 0:
            angle = (angle >> extra) + 1 >> 1  # the top 24 bits, rounded up on the 25th
            t = ldexp(angle, extra + 1 - bits)
        else:
            t = ldexp(angle, -bits)
    if t < 1.220703125e-04:  # 2**-13
        result = product(t * _TWO_PI)
    else:
        result = _polyx(t, _SIN_COEFFICIENTS)
    return -result if quadrant >= 2 and result else result


# 1/(2*pi) of $IN2PI in two parts of 28 bits, so that a single times either is exact in a double
_INVERSE_TWO_PI_HIGH = ldexp(_INVERSE_TWO_PI >> 28, -30)
_INVERSE_TWO_PI_LOW = ldexp(_INVERSE_TWO_PI & ((1 << 28) - 1), -58)
_REDUCED_ABOVE = 2.0 ** -20  # (a quarter angle below it in size: the integer steps)
_UFP = 4503599627370497.0  # 2**52 + 1: q - (1 - 2**-53) * q is the leading power of two of a (q = a * _UFP)
_HALF_UNIT_MAGIC = 1.5 * 2.0 ** 29  # times a leading power of two: the magic number of its unit
_HALF_UNIT = 2.0 ** -53 / 1.5  # the magic number times this: half its unit


def _quarter_angle(x: float, quarter: float) -> tuple[float, bool] | None:
    """The fast path of RR/SIN30 on floats: for ``x`` (a single, 2**-10 <= x < 2**20) plus
    ``quarter`` quarter turns (0 for SIN, 1 for COS), the single ``t`` (turns, below a
    quarter) that $SIN's polynomial gets and whether the sine is negated (quadrants 2
    and 3); None where the float value of the reduced angle lies too near a point where
    the rounding to 24 bits changes (or below 2**-20): the integer steps decide there.

    ``x`` times the two 28-bit halves of 1/(2*pi) are exact; the fraction of the first
    is exact, the sum with the second and the quarter turn are off by at most 2**-50
    quarter turns, and MBF's 56-bit rounding of the product ($FMULD) and of the quarter
    turn's sum ($FADDD) by at most x * 2**-53 quarter turns.  $CSD rounds the angle in
    its quadrant half up to 24 bits: where the float angle is farther than that bound
    from a half unit, the exact one rounds the same way (to the nearest)."""
    high = x * _INVERSE_TWO_PI_HIGH
    turns = (high % 1.0 + x * _INVERSE_TWO_PI_LOW) * 4.0 + quarter  # in quarter turns
    quadrant = 0
    while turns >= 1.0:
        turns -= 1.0
        quadrant += 1
    if quadrant & 1:
        turns = 1.0 - turns
    if turns < _REDUCED_ABOVE:
        return None
    q = turns * _UFP
    magic = (q - 0.9999999999999999 * q) * _HALF_UNIT_MAGIC
    rounded = (turns + magic) - magic
    off = turns - rounded
    bound = magic * _HALF_UNIT - (x + 16.0) * 2.0 ** -50  # half a unit less the error
    if -bound < off < bound:
        return rounded * 0.25, quadrant & 2 == 2
    return None


def _sine_of_quarter(t: float, negative: bool) -> float:
    """``SIN30``'s end: the sine of ``t`` turns (a single below a quarter) by Hart 3341 (below
    2**-13: times 2*pi), negated when ``negative``."""
    if t < 1.220703125e-04:  # 2**-13
        result = product(t * _TWO_PI)
    else:  # (t from 2**-13 to 1/4: mbf_floats' odd form, unless a sum is 0)
        result = mbf_floats.poly(t, _SIN_PLAN, True)
        if result is None:
            result = _polyx(t, _SIN_COEFFICIENTS)
    return -result if negative and result else result


def sin(x) -> float:
    """SIN as ``$SIN``: below 2**-10 in size the argument itself; else the sine of the
    angle reduced to a quarter turn, by Hart 3341, with the sign of ``x``."""
    if -9.765625e-04 < x < 9.765625e-04:  # 2**-10
        return x + 0.0
    size = -x if x < 0 else x
    reduced = _quarter_angle(size, 0.0) if size < 1048576.0 else None
    result = _sine_of_turns(*_turns(size)) if reduced is None else _sine_of_quarter(*reduced)
    return -result if x < 0 and result else result


def cos(x) -> float:
    """COS as ``$COS``: the sine of the reduced angle plus a quarter turn (a double sum)."""
    size = -x if x < 0 else x
    if 9.765625e-04 <= size < 1048576.0:
        reduced = _quarter_angle(size, 1.0)
        if reduced is not None:
            return _sine_of_quarter(*reduced)
    numerator, bits = _quarter_turn_added(*_turns(size))
    return _sine_of_turns(numerator & ((1 << bits) - 1), bits)


def tan(x) -> float:
    """TAN as ``$TAN``: ``$SIN`` divided by ``$COS`` (``$FDIVS``); a cosine of 0 raises
    ZeroDivisionError."""
    return divide(sin(x), cos(x))


def atn(x) -> float:
    """ATN as ``$ATAN``: for ``x`` >= 1, pi/2 - ATN(1/x); above tan(pi/12), pi/6 +
    ATN((x*SQR(3) - 1) / (x + SQR(3))); the rest by Hart 4940; odd."""
    negative = x < 0
    y = -x if negative else x + 0.0
    inverted = y >= _ONE
    if inverted:
        y = divide(_ONE, y)
    shifted = y >= _TAN_TWELFTH_PI
    if shifted:
        y = divide(_poly(y, _ATN_REDUCTION), add(y, _SQR3))
    result = _polyx(y, _ATN_COEFFICIENTS)
    if shifted:
        result = add(result, _SIXTH_PI)
    if inverted:
        result = subtract(_HALF_PI, result)
    return -result if negative and result else result


def log(x) -> float:
    """LOG as ``$LOG``: ``x`` = m * 2**e (.5 <= m < 1); (e + P(m)/Q(m)) * LN(2) by Hart
    2524; LOG(1) is 0.  ``x`` <= 0 raises ValueError."""
    if x <= 0:
        raise ValueError("LOG of a number not above 0")
    if x == 1:
        return 0.0
    m, e = frexp(x)
    ratio = _LOG_RATIOS.get(m)
    if ratio is None:
        if len(_LOG_RATIOS) >= _LOG_MEMO_SIZE:
            for old in list(islice(_LOG_RATIOS, _LOG_MEMO_SIZE // 4)):  # the oldest quarter
                del _LOG_RATIOS[old]
        ratio = _LOG_RATIOS[m] = divide(_poly(m, _LOG_NUMERATOR), _poly(m, _LOG_DENOMINATOR))
    return product(add(float(e), ratio) * _LN2)


# $LOG's P(m)/Q(m) by the mantissa m (x and 2x share it: a loop over whole numbers finds half
# of them here, K/2's ratio made K/4 numbers earlier).  When full the oldest quarter goes (a
# dict keeps its order of insertion), so a loop up to K keeps hitting while K/4 is below the
# size: BM8 up to K = 131072 (about 3 MB at most)
_LOG_RATIOS: dict[float, float] = {}
_LOG_MEMO_SIZE = 32768


def _overflowed(negative: bool) -> float:
    return -inf if negative else inf


def exp(x, overflow=_overflowed) -> float:
    """EXP as ``$EXP``: y = x*LOG2(e); 2**y as 2**INT(y) times Hart 1302's 2**(y - INT(y));
    |y| below 2**-25: 1; from 128 up: overflow, from -128 down: 0."""
    y = product(x * _LOG2_E)
    if y in (inf, -inf):
        return overflow(False)
    exponent = _exponent_byte(y)
    if exponent < 104:
        return 1.0
    if exponent >= 136:
        return 0.0 if y < 0 else overflow(False)
    whole = floor(y)
    if whole == 127:  # 2**127 has no exponent byte
        return overflow(False)
    fraction = subtract(y, float(whole))
    result = product(_poly(fraction, _EXP_COEFFICIENTS) * ldexp(1.0, whole))
    return overflow(False) if result == inf else result


def power(x, y, overflow=_overflowed) -> float:
    """``x ^ y`` of two singles as ``$FPWR``.

    ``y`` = 0: 1.  ``x`` = 0: 0, or ZeroDivisionError for ``y`` < 0.  A negative ``x``
    needs an integral ``y`` below 2**24 in size (else ValueError).  A negative ``y``:
    1 / ``x ^ -y`` (a power that underflowed to 0 overflows instead, signed as the
    power would be).  An integral ``y`` below 32768: binary powering (``XTON``,
    :func:`single_arith.power_by_integer`); any other: EXP(y * LOG(|x|)), negated for a
    negative ``x`` and odd ``y``."""
    if not y:
        return 1.0
    if not x:
        if y < 0:
            raise ZeroDivisionError("zero to a negative power")
        return 0.0
    if x < 0 and (_exponent_byte(y) >= 153 or y != floor(y)):
        raise ValueError("negative number to a fractional power")
    if y < 0:
        result = _positive_power(x, -y, overflow)
        if not result:
            return overflow(x < 0 and floor(-y) % 2 == 1)
        return divide(_ONE, result)
    return _positive_power(x, y, overflow)


def _positive_power(x: float, y: float, overflow) -> float:
    if y < 32768 and y == floor(y):
        result = power_by_integer(x, int(y))
        if result in (inf, -inf):
            return overflow(result < 0)
        return result
    odd = x < 0 and floor(y) % 2 == 1
    result = exp(product(y * log(-x if x < 0 else x)), overflow)
    return -result if odd else result
