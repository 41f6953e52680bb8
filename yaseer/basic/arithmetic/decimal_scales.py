"""The scale caches of ``--arith decimal``'s compiled ``+ - * /`` (casio): the 12-digit
decimal result from the float result, with no decimal module, where that is sure.

Every number the decimal arithmetic holds is the nearest double to a decimal of at most
12 significant digits, from 1E-99 to 9.99999999999E+99 in size, or 0 (decimal_arith.py;
its entry points round what comes in: literals, READ, INPUT, VAL, RND, RAN#, a Python
area's values).  For two such doubles ``a`` and ``b`` (standing for the decimals ``A``
and ``B``) the compiled code (number_models.DecimalNumbers) computes, without a call::

    t = fl(fl(a op b) * S)          S = +-10**k, 0 <= k <= 22 (an exact double)
    n = (t + M) - M                 M = 1.5 * 2**52: t rounded to an integer (|t| < 2**51)

and gives ``fl(n / S)`` when ``0 < t < 10**12`` and either ``t == n`` (the exact test) or
``t >= 10**11`` and ``|t - n| < 1/2 - 2**-8`` (the band test); any other result takes
the decimal module's routine (:func:`writers`), which then keeps, for this operation,
the ``S`` of its result's decade (``x`` from ``10**e`` to ``10**(e+1)``: ``S`` =
``10**(11-e)``, with the result's sign) in a global of the area's namespace.  ``n / S``
is correctly rounded (two exact doubles), so it is the nearest double to the decimal
``n * 10**-k``; what remains is that this decimal is the 12-digit rounding (half up)
of the exact ``X = A op B``.

**The error.**  Write ``u = 2**-53``; each double is within ``u`` (relative) of what it
stands for (``a`` of ``A``, and every operation rounds to nearest).  For ``*`` and ``/``,
``t`` is ``X*S`` times four such factors: ``|t - X*S| <= 4.0001 u |X*S|``, and ``t <
10**12`` makes this below ``4.5e-4``.  For ``+`` and ``-`` the operands' own errors do
not shrink with the result: ``|t - X*S| <= u |S| (|A| + |B| + |X|) (1 + 2u) + u |t|``.
The compiled code makes sure ``|S a| < 10**13`` (a variable operand: the test ``l < a
< h`` on the first one, whose bounds the writer keeps with ``S``; a literal ``c``: the
writer keeps no ``S`` with ``|S c| > 10**13``); the other operand is then below
``10**13 + 10**12`` after scaling, and ``|t - X*S| <= 2.5e-3 < 2**-8``.  Call this
bound ``E`` (below ``2**-8`` in every case).

**The band test** (``10**11 <= t < 10**12``, ``|t - n| < 1/2 - 2**-8``): ``|X*S - n| <
1/2``, so ``n`` is the integer nearest ``X*S`` and no tie.  If ``X*S`` is in ``[10**11,
10**12)`` the 12-digit rounding of ``X`` is at the unit ``1/|S|``: it is ``n / S``.  If
``X*S`` lies just below ``10**11`` (within ``E``), ``X``'s 12 digits end a place lower and
``10 X S`` is within ``10 E < 1/2`` below ``10**12``: it rounds to ``10**12``, the value
``10**11 / S = n / S`` (``n`` is ``10**11``).  Just above ``10**12`` likewise (``n =
10**12``).

**The exact test** (``t`` a whole number, ``0 < t < 10**12``): ``|X*S| < 10**12``, so
the unit of ``X``'s 12 digits is ``10**-j / |S|`` for some ``j >= 0``, and the rounding
of ``X`` is ``t / S`` when ``|X*S - t| 10**j < 1/2``.  For ``*`` and ``/`` the error is
relative: ``4.0001 u |X*S| 10**j < 4.0001 u 10**12 < 1/2``.  For ``+`` and ``-``:
if ``|A| + |B| <= 1.25 |X|`` (no cancellation: one sign, or exponents two decades
apart, ``|X| >= 0.9 max``) the error is again relative (``3.3 u``).  Else the two
decades ``e_A, e_B`` differ by at most one, ``X`` is a multiple of the finer operand's
unit ``q = 10**(min(e_A, e_B) - 11)``, and the operands are below ``10**(min + 2) = q
10**13``: ``E <= 2.4e-3 q |S|``.  If ``q |S| >= 1`` then ``X*S`` is a whole number
within ``E < 1`` of ``t``: equal, and ``X`` (at most 12 digits) is its own rounding.
If ``q |S| = 10**-m < 1``, ``X*S`` and ``t`` are both multiples of ``10**-m`` within
``2.4e-3 * 10**-m`` of each other: equal again.

The range: ``S`` is kept only for results from 1E-11 to below 1E+12 (``k`` from 0 to
22), so a fast result is from 1E-22 to 1E+12 in size, never near the ends of the range
(1E-99, 1E+100), and never 0 (``t > 0``): an overflow, an underflow to 0, a result of
the other sign and a division by 0 (Python's ZeroDivisionError, the same BASIC error)
take the routine.  tests/test_decimal_scales.py compares the compiled code with the
routine on hundreds of thousands of operands.
"""

from __future__ import annotations

from bisect import bisect_right
from math import floor, frexp, log10, nan

MAGIC = 1.5 * 2.0 ** 52  # (t + MAGIC) - MAGIC: t rounded to a whole number (|t| < 2**51)
TOP = 1e12  # a scaled result below it has at most 12 digits before the point
BOTTOM = 1e11  # ... and from it on exactly 12 (the band test's decade)
BAND = 0.5 - 2.0 ** -8  # |t - n| below it: no rounding boundary within the error E
GUARD = 1e13  # |S a| below it for an operand of a sum: bounds the operands' own errors
# the largest scale of a sum with the number RND draws unrounded (number_models._drawn_sum): the
# number's distance from its 12-digit rounding, at most 0.5E-12, scaled, within 5E-4 (below)
DRAWN_SCALE = 1e9
_SCALES = {e: 10.0 ** (11 - e) for e in range(-11, 12)}  # exact doubles 10**0 .. 10**22
_POWERS = {e: 10.0 ** e for e in range(-12, 14)}  # the decades' ends (decimals of one digit)
# a binade's lowest decade: 2**(b-1) <= x < 2**b has floor(log10 x) this or one more
_LOW_DECADE = {b: floor((b - 1) * log10(2.0)) for b in range(-40, 42)}


def decade_scale(size: float) -> float:
    """``10**(11 - e)`` for ``10**e <= size < 10**(e+1)``, ``size`` from 1E-11 to below 1E+12
    (a double; the decade's powers of ten are compared as doubles, exact or the nearest)."""
    e = _LOW_DECADE[frexp(size)[1]]
    if size >= _POWERS[e + 1]:
        e += 1
    return _SCALES[e]


def scale(x: float) -> float:
    """``S`` of the decade of ``x`` (a nonzero own decimal from 1E-11 to below 1E+12),
    with its sign; NaN (a scale no value matches) for any other ``x``.  The decade's
    power of ten is a decimal of one digit, so comparing the doubles compares the
    decimals: the decade is the number of powers 1E-11 .. 1E+12 (as doubles, each the
    nearest to its decimal) at or below ``|x|``, one binary search in C (the writers call
    this on every result their site's scale missed; a search of 24 doubles costs about half
    of ``frexp``'s tuple and a table lookup by the binade)."""
    if x > 0.0:
        return _BY_EDGES[bisect_right(_EDGES, x)]
    return -_BY_EDGES[bisect_right(_EDGES, -x)]  # (0 and -0 give index 0: NaN; a NaN x: the last)


# the decades' lower ends 1E-11 .. 1E+12, and the scale of the decade starting at each (NaN below
# the first and from the last on): bisect_right(_EDGES, x) is the index of x's decade plus one
_EDGES = [_POWERS[e] for e in range(-11, 13)]
_BY_EDGES = [nan] + [_SCALES[e] for e in range(-11, 12)] + [nan]


def rounded_within(value: float, error: float):
    """The 12-digit rounding of every number within ``error`` of ``value``, when it is one
    (no rounding boundary in between) and lies from 1E-11 to below 1E+12 in size: as the
    nearest double; else None.  The scaled ``t`` (its product's rounding counted) and its
    reach must stay inside one decade and less than 1/2 from the whole number ``n`` nearest
    ``t``: then every number in reach rounds to ``n``, and ``n / S`` is the double (two exact
    doubles divided).  No halfway point is in reach, so rounding half up or half to even agree.
    The scale of the last value's decade (with its sign) is tried first: a function called
    in a loop mostly stays in one decade."""
    global _last_scale
    s = _last_scale
    t = value * s
    if not BOTTOM <= t < TOP:
        size = abs(value)
        if not 1e-11 <= size < 1e12:
            return None
        s = _last_scale = decade_scale(size) if value > 0 else -decade_scale(size)
        t = value * s
    reach = abs(error * s) + t * 2.3e-16
    if BOTTOM <= t - reach and t + reach < TOP:
        n = (t + MAGIC) - MAGIC
        if reach - 0.4999 < t - n < 0.4999 - reach:
            return n / s
    return None


_last_scale = 1e11  # (any scale: only a first guess, tested before it is used)


def writers(namespace: dict) -> dict:
    """The compiled code's ``_zd(name, routine, a, b)`` (``*`` and ``/``), ``_zdc(name,
    routine, a, b, c)`` (``+`` or ``-`` with a literal of size ``c``) and ``_zdg(name,
    routine, a, b)`` (``+`` or ``-`` of two variables, guarded on ``a``), for a result the
    cached scale did not give: the scale of the float result's own decade is kept in
    ``namespace[name]`` and tried at once (the same tests, in Python; a sum's guard with
    that scale); where they fail, ``routine(a, b)`` (decimal_arith's ``_dadd`` ...: its
    errors are raised) gives the result, and the scale of its decade is kept.  A scale
    that is NaN matches nothing; a result of 0 is never the tests' (any scale holds)."""
    add, subtract, multiply, divide = (namespace[name] for name in ("_dadd", "_dsub", "_dmul", "_ddiv13"))

    def retried(name, routine, a, b, fits=None):
        """The float path with the scale of the float result's decade (the compiled code's
        tests), else the routine; ``fits`` tests a scale (None: any scale fits, a product's or
        a quotient's)."""
        if type(a) is float and type(b) is float and b:
            # (the float operation written out: looking up float.__mul__ and calling it took about
            # an eighth of a missed product's machine instructions)
            r = (a * b if routine is multiply else a + b if routine is add else a - b if routine is subtract
                 else a / b if routine is divide else nan)
            s = scale(r)
            if s == s and (fits is None or fits(s)):
                namespace[name] = s
                t = r * s
                if 0.0 < t < TOP:
                    n = (t + MAGIC) - MAGIC
                    if n == t or t >= BOTTOM and -BAND < t - n < BAND:
                        return n / s
        result = routine(a, b)
        if result:
            s = scale(result)
            namespace[name] = s if s == s and (fits is None or fits(s)) else nan
        return result

    def with_constant(name, routine, a, b, c):
        return retried(name, routine, a, b, lambda s: abs(s) * c <= GUARD)

    def guarded(name, routine, a, b):
        return retried(name, routine, a, b, lambda s: guarded_fits(name, a, s))

    def drawn_sum(name, routine, a, v):
        """``a + RND`` for the number drawn ``v`` (the compiled code's ``_zdr``): ``v`` rounded to
        12 digits (``_d13``), then the sum as :func:`retried` gives it, whose scale is kept only up
        to :data:`DRAWN_SCALE` in size (the compiled code adds ``v`` itself, unrounded).

        **Why that is the sum with the rounded number.**  The compiled code's ``t`` is
        ``fl(fl(a + v) * S)``; the rounded number ``R`` differs from ``v`` by at most half its
        unit, ``0.5E-12`` (``v`` is below 1), and ``v`` itself is exact, so ``|t - X*S|`` is
        within the bound ``E`` of a sum (above: ``|S a|`` below ``10**13``, see below, the other
        operand ``v`` below 1 scaled below ``10**13``) plus ``0.5E-12 |S| <= 5E-4``: below ``3E-3 < 2**-8``,
        and the band test's argument gives ``n / S``, the 12-digit rounding of ``X = A + R``.
        The compiled code takes no exact test here (``t`` whole says nothing of ``X``), and no
        guard on ``a``: with ``|S|`` at most DRAWN_SCALE and ``0 <= v < 1`` the range test
        ``10**11 <= t < 10**12`` already bounds ``|S a|`` below ``10**12 + 10**9 + 1``."""
        def fits(s):
            return -DRAWN_SCALE <= s <= DRAWN_SCALE
        return retried(name, routine, a, namespace["_d13"](v), fits)

    def guarded_fits(name, a, s):
        bound = GUARD / abs(s)
        if -bound < a < bound:
            namespace[name] = nan  # (matches nothing until the bounds fit it)
            namespace[name + "l"], namespace[name + "h"] = -bound, bound
            return True
        return False

    return {"_zd": retried, "_zdc": with_constant, "_zdg": guarded, "_zdr": drawn_sum}


def initial(names) -> dict:
    """The namespace entries of the caches ``names`` before their first result: scales that
    match nothing (and a guard that lets nothing through)."""
    entries = {}
    for name in names:
        entries[name] = nan
        entries[name + "l"] = entries[name + "h"] = 0.0
    return entries
