"""The scale caches of ``--arith decimal``'s compiled SQR, LN, LOG, EXP, SIN, COS and RND
(casio): the 12-digit decimal result from the float function's value, with no decimal
module and no call of decimal_arith, where that is sure.

The compiled code (number_models.DecimalNumbers.call) computes the float value ``v`` of the
function (``math.sqrt`` and friends, SIN and COS within :func:`angle_functions`' bounds, or the
generator's next number for RND), and with the call site's cached scale ``S`` (``+-10**k``,
an exact double, the sign of the last result's)::

    t = fl(v * S)          n = (t + M) - M   (t rounded to a whole number, M = 1.5 * 2**52)

(for RND ``S`` is not a cache's but the scale of the decade from 0.1 up, or from 0.01 up for a
number below 0.1) gives ``fl(n / S)`` when ``10**11 <= t < 10**12`` and ``|t - n| < 1/2 - 2**-8`` (the band
test of decimal_scales.py); any other value goes to :func:`writers`' ``_zdf``, which tries
the scale of ``v``'s own decade, else calls decimal_arith's routine, and keeps the scale of
the result's decade for the site (never one above the function's :data:`LARGEST_SCALE` in
size).  A NaN ``v`` (the compiled code's value where the float function does not apply:
SQR or LN of 0 or less, a large angle with a fraction) fails every test.

SIN and COS of a whole angle in degrees below 1E+9 in size (:data:`WHOLE_TABLE_LIMIT`) take
neither: their result is looked up in a table of the routine's own results at the whole
degrees 0..359 (decimal_arith.WholeDegrees, whose docstring shows the routine gives the same
result at an angle and at its remainder by a turn).  Those are the sites whose values often
fall below 0.1 (a scale of 1E+13, beyond what the float sine's error allows).

**Why the result is the routine's.**  Every number the arithmetic holds is the nearest
double ``x`` to a decimal ``D`` of at most 12 digits (decimal_scales.py): ``x = D (1 + d)``
with ``|d| <= u = 2**-53``.  Let ``X`` be the exact value of the function at ``D`` (what
the routine rounds correctly to 12 digits).  If ``|v - X| |S| <= 2**-8 - 2**-13``, then
``|t - X S| < 2**-8`` (``t < 2**40``, so ``fl`` moves it by at most ``2**-13``), and the band
test's argument in decimal_scales.py (including the ends of the decade) shows that ``n / S``
is ``X`` rounded to 12 digits; no halfway point lies within reach, so rounding half up and
half to even agree.  The bounds on ``|v - X|`` (the float functions' own errors as
decimal_arith.py already assumes them: ``math.log`` and ``math.log10`` within ``5e-16 |v| +
2.5e-16`` with the operand's distance from ``D`` included, ``math.sin``/``math.cos`` within
``4e-16 + 4e-16 |v|``, ``math.exp`` within ``5e-16 |v|``, ``math.sqrt`` correctly rounded)::

    SQR    |v - X| <= 1.5 u |X|                 any scale: 1.5 u 10**12 < 1.7e-4
    RND    v is X (the number drawn is what is rounded)
    EXP    |x| < 20: 20 u + 5e-16 < 2.8e-15 of |X|      any scale: 2.8e-3
    LN LOG x below 1E+100: 5e-16 |v| + 2.5e-16     |S| <= 10**12 (|v| >= 0.1): 7.5e-4
    SIN COS in degrees: the remainder r of x by a turn (360) is exact, its
           angle in radians fl(r * fl(pi/180)) within 2.0001 u 2 pi < 1.4e-15; x's distance
           from D moves the angle by at most u |x| pi/180: nothing for a whole x below 1E+15
           (then x is D), below 7e-16 for |x| below a turn; with the sine's own error
           below 2.9e-15                        |S| <= 10**12: 2.9e-3
    SIN COS in radians, |x| < 10 or a whole x below 1E+9: u |x| + 8e-16 < 1.9e-15,
                                                |S| <= 10**12: 1.9e-3

all below ``2**-8 - 2**-13 = 3.78e-3``.  (In grads the routine first rounds the angle in
degrees to 12 digits, as decimal_arith.trig_functions does: the float value is NaN there.)  tests/test_decimal_calls.py compares the compiled
functions with mpmath's values rounded to 12 digits and with the routines.
"""

from __future__ import annotations

from math import cos, exp, fmod, inf, log, log10, nan, pi, sin, sqrt

from yaseer.basic.arithmetic.decimal_scales import BAND, BOTTOM, MAGIC, TOP, scale

# the largest scale a site of each function keeps (the bounds above)
LARGEST_SCALE = {"_sqrt": 1e22, "_exp": 1e22, "_rndf": 1e22, "_log": 1e12, "_log10": 1e12,
                 "_sin": 1e12, "_cos": 1e12}

EXP_LIMIT = 20.0  # |x| below it: EXP's float value is close enough (the bound above)
WHOLE_LIMIT = 1e15  # a whole angle below it is its decimal: any size of turn is reduced exactly
RADIAN_LIMIT = 10.0  # an angle in radians with a fraction: below it in size
# a whole angle in degrees below it in size: SIN and COS from a table of the routine's results for
# the whole angles 0..359 (decimal_arith.WholeDegrees; the routine reduces such an angle exactly,
# its float path up to 1E+9: the reduced angle gives the same steps and the same result)
WHOLE_TABLE_LIMIT = 1e9
# a whole angle in radians: below it in size (beyond, decimal_arith's routine reduces by a 25-digit
# 2 pi, as it did before the inline path: its values there stay what they were)
WHOLE_RADIAN_LIMIT = 1e9


def angle_functions(unit: str) -> dict:
    """The constants of the compiled code's float SIN and COS in ``unit`` ("DEG", "RAD", "GRA"):
    ``_msin(_mfmod(x, _Tu) * _Ru)`` where ``-_Fu < x < _Fu`` or ``x`` is whole below ``_Wu`` in
    size (the bounds above), else NaN (always in grads); before that, a whole ``x`` below ``_Xu``
    in size (degrees only: 0 in radians and grads) takes its result from the table of the whole
    degrees (``_SDs[x % 360.0]``, :data:`WHOLE_TABLE_LIMIT`).  In radians the turn is infinite:
    ``fmod(x, inf)`` is ``x`` (a finite ``x``: the bounds come first)."""
    if unit == "RAD":
        return {"_Tu": inf, "_Ru": 1.0, "_Fu": RADIAN_LIMIT, "_Wu": WHOLE_RADIAN_LIMIT, "_Xu": 0.0}
    if unit == "GRA":  # (decimal_arith's grads are degrees rounded to 12 digits first: the routine)
        return {"_Tu": 360.0, "_Ru": pi / 180.0, "_Fu": 0.0, "_Wu": 0.0, "_Xu": 0.0}
    return {"_Tu": 360.0, "_Ru": pi / 180.0, "_Fu": 360.0, "_Wu": WHOLE_LIMIT, "_Xu": WHOLE_TABLE_LIMIT}


def helpers(namespace: dict) -> dict:
    """The compiled code's float functions (``_msqrt`` ...; the bounds of SIN and COS depend on
    the angle unit: :func:`angle_functions`) and ``_zdf(name, routine, x, v, largest)``: for a value ``v`` of the
    function at ``x`` neither of the site's cached scales gave, the band test with the scale of
    ``v``'s own decade (kept for the site), else ``routine(x)`` (decimal_arith's, whose
    errors are raised; for RND ``x`` is the number drawn and the routine rounds it), whose
    decade's scale is kept, or NaN (matches nothing) beyond ``largest``.  The scale a new one
    replaces stays as the site's second (``namespace[name + "b"]``), which the compiled code
    tries before calling ``_zdf``: a function whose values move between two decades (a square
    root of numbers from 1 to 1000) keeps both and calls ``_zdf`` only for a third."""

    def function(name, routine, x, v, largest):
        s = scale(v)  # (NaN for a NaN v: every test below fails)
        if -largest <= s <= largest:
            keep(name, s)
            t = v * s
            if BOTTOM <= t < TOP:
                n = t + MAGIC - MAGIC
                if -BAND < t - n < BAND:
                    return n / s
        result = routine(x)
        if result:
            s = scale(result)
            keep(name, s if -largest <= s <= largest else nan)
        return result

    def keep(name, s):
        """The site's scale is ``s`` from now on; the one it replaces becomes its second."""
        old = namespace[name]
        if old != s:
            namespace[name + "b"] = old
            namespace[name] = s

    return {"_zdf": function, "_msqrt": sqrt, "_mlog": log, "_mlog10": log10, "_mexp": exp, "_msin": sin,
            "_mcos": cos, "_mfmod": fmod, "_nan": nan}
