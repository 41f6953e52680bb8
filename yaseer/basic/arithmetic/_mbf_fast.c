/* GW-BASIC's transcendental functions in C: an optional accelerator of gw_transcendental.py.

   SIN, COS, TAN, ATN, LOG, EXP and a fractional power computed as gw_transcendental.py
   computes them (MATH1.ASM's $SIN, $COS, $TAN, $ATAN, $EXP, $FPWR; MATH2.ASM's $LOG,
   $POLY, $POLYX), bit for bit: values are C doubles holding Microsoft Binary Format
   singles, exactly as the Python floats of the Python module hold them, and every
   single-precision step rounds as single_arith.py's reference does:

   - $FMULS (product): single_arith.product transcribed (the same double operations:
     Veltkamp's split, then the 28-bit truncation rounded half to even, 1001 a half);
   - $FADDS (add): single_arith.working_sum and _rounded on the 32-bit register
     (mantissa and guard byte, its sticky bit), the Python fast paths' long way;
   - $FDIVS (divide): the nearest single (single_arith.nearest);
   - $POLY: Horner's rule of those steps (gw_transcendental.poly_steps);
   - the angle reduction of $SIN/$COS in 56-bit MBF double precision on integers
     (gw_transcendental._turns, _quarter_turn_added, _sine_of_turns; mbf_double's $SHRA).

   Each function object is made by bound(name, fallback): the Python function it
   accelerates is its `self`.  Whatever is unusual -- an argument that is not a single
   inside MBF's range (0 of LOG, NaN, infinities, doubles), a keyword argument, a
   result that overflows, a domain error, a division by zero -- is handed to that
   Python function with the same arguments, so the errors and the overflow policy
   stay the Python module's own.  tests/test_mbf_fast.py compares the two bit for bit.

   Build: setup.py, as an optional extension (no compiler: the Python functions alone).
   No contraction of a*b+c into fused multiply-adds (setup.py passes -ffp-contract=off):
   every double operation here must round as Python's does. */

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "_bound_routine.h"

/* Doubles must round as Python's floats do, each operation once to 53 bits: refuse to be
   built where the compiler evaluates in a wider format (x87), so that the Python
   functions serve there. */
#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "_mbf_fast needs double operations evaluated in double (FLT_EVAL_METHOD 0)"
#endif

#define TINY 0x1p-128  /* the least MBF single */
#define LIMIT 0x1p127  /* a rounded result this large overflows */
#define SAFE_LOW 0x1p-125  /* IEEE singles keep all 24 bits from 2**-126 up */

/* Doubles by their bits: every value here is a normal double (2**-260 .. 2**260), whose
   frexp and ldexp are these exact bit operations (libm's calls cost more than a step). */
static inline uint64_t bits_of(double x)
{
    uint64_t u;
    memcpy(&u, &x, sizeof u);
    return u;
}

static inline double of_bits(uint64_t u)
{
    double x;
    memcpy(&x, &u, sizeof x);
    return x;
}

/* 2**e, -1022 <= e <= 1023 */
static inline double pow2(int e)
{
    return of_bits((uint64_t)(e + 1023) << 52);
}

/* frexp's exponent of a normal nonzero x: x = m * 2**e, .5 <= |m| < 1 */
static inline int exponent_of(double x)
{
    return (int)((bits_of(x) >> 52) & 0x7FF) - 1022;
}

/* The 53-bit mantissa of a normal nonzero x, its top bit set: |x| = it * 2**(exponent_of(x) - 53) */
static inline uint64_t mantissa_of(double x)
{
    return (bits_of(x) & ((UINT64_C(1) << 52) - 1)) | (UINT64_C(1) << 52);
}

static inline int bit_length(uint64_t v)
{
#if defined(__GNUC__) || defined(__clang__)
    return v ? 64 - __builtin_clzll(v) : 0;
#else
    int n = 0;
    while (v) {
        v >>= 1;
        n++;
    }
    return n;
#endif
}

/* Set when a step leaves what this module handles (an overflow, a division by 0): the
   caller hands the whole call to the Python function. */
typedef struct {
    int unusual;
} Status;

/* ---------------------------------------------------------------- single steps */

static double mbf(uint32_t word)
{
    int exponent = (int)(word >> 24);
    if (!exponent)
        return 0.0;
    double value = ldexp((double)((word & 0x7FFFFF) | 0x800000), exponent - 152);
    return (word & 0x800000) ? -value : value;
}

/* single_arith.nearest: the nearest single, ties to even, in MBF's range */
static double nearest(double x)
{
    if (x >= SAFE_LOW || x <= -SAFE_LOW) {
        double r = (double)(float)x;
        if (-LIMIT < r && r < LIMIT)
            return r;
        return r < 0 ? -INFINITY : INFINITY;
    }
    if (x == 0.0 || x != x)
        return x + 0.0;
    int e;
    double m = frexp(x, &e);
    double q = m > 0 ? m * 16777216.0 : m * -16777216.0;
    double below = fmod(q, 1.0);
    q -= below;
    if (below > 0.5 || (below == 0.5 && fmod(q, 2.0) != 0.0))
        q += 1.0;
    double r = ldexp(q, e - 24);
    if (r < TINY)
        return 0.0;
    return x < 0 ? -r : r;
}

/* single_arith.product: $FMULS of the exact product p of two singles (or 0, or an
   infinity).  The product truncated to 28 bits, its low 4 rounding the 24 half to even
   with 1001 a half: up from 10/16 of a unit, or from 8/16 over an odd mantissa.  (The
   Python function returns the nearest single where that is the same, found with
   Veltkamp's split, which comes to the same.)  Below MBF's range 0, except what the
   Python function's nearest-single path keeps: a product from 10/16 of a unit below
   2**-128 up, whose nearest single is 2**-128. */
static double product(double p)
{
    if (p == 0.0)
        return 0.0;
    if (isinf(p))
        return p;
    /* the 24 bits and the 29 below them (p is a normal double: exact) */
    uint64_t whole = mantissa_of(p), q = whole >> 29, below = whole & ((UINT64_C(1) << 29) - 1);
    if (below >= (UINT64_C(5) << 26) || (below >= (UINT64_C(1) << 28) && (q & 1)))  /* 10/16; 8/16 */
        q += 1;
    if (-TINY < p && p < TINY) {
        if (q == 0x1000000 && below >= (UINT64_C(5) << 26))
            return p < 0 ? -TINY : TINY;
        return 0.0;
    }
    double r = (double)q * pow2(exponent_of(p) - 24);
    if (r >= LIMIT)
        return p < 0 ? -INFINITY : INFINITY;
    return p < 0 ? -r : r;
}

/* single_arith._rounded: $ROUNS of a normalised working number (exponent byte, 32-bit
   register): the guard byte's top three bits round the 24 half to even (its low five are
   dropped); 0 below the range, an infinity beyond it */
static double rounded(int exponent, uint64_t register_, int negative)
{
    if (register_ == 0 || exponent <= 0)
        return 0.0;
    uint64_t mantissa = register_ >> 8, guard = register_ & 0xE0;
    if (guard > 0x80 || (guard == 0x80 && (mantissa & 1))) {
        mantissa += 1;
        if (mantissa == 0x1000000) {
            mantissa = 0x800000;
            exponent += 1;
        }
    }
    if (exponent > 255)
        return negative ? -INFINITY : INFINITY;
    double value = (double)mantissa * pow2(exponent - 152);
    return negative ? -value : value;
}

/* single_arith.add: $FADDS by its register steps (single_arith.working_sum): the smaller
   operand shifted right into the 32-bit register a byte, then a bit, at a time with the
   sticky bit 0x20; added, or subtracted and normalised as $NORMS does */
static double add(double a, double b)
{
    if (a == 0.0)
        return b + 0.0;
    if (b == 0.0)
        return a + 0.0;
    if (a + b == 0.0)
        return 0.0;
    double small = a, large = b;
    if (fabs(a) > fabs(b)) {
        small = b;
        large = a;
    }
    /* single_arith.working_parts: exponent bytes and 32-bit working mantissas */
    int exponent = exponent_of(large) + 128;
    int shift = exponent - (exponent_of(small) + 128);
    uint64_t mantissa = mantissa_of(large) >> 21;
    int negative = large < 0;
    if (shift >= 25)
        return rounded(exponent, mantissa, negative);
    uint64_t r = mantissa_of(small) >> 21;
    if (shift >= 8) {
        int cut = shift & 0x18;
        r = (r >> cut) | ((r & ((UINT64_C(1) << (cut + 5)) - 1)) ? 0x20 : 0);
        shift &= 7;
    }
    for (; shift; shift--) {
        r >>= 1;
        if (r & 0x10)
            r |= 0x20;
    }
    if ((small < 0) == negative) {
        r += mantissa;
        if (r >= (UINT64_C(1) << 32)) {
            r >>= 1;
            exponent += 1;
        }
        return rounded(exponent, r, negative);
    }
    if (r >= mantissa) {
        if (r == mantissa)
            return 0.0;
        r -= mantissa;  /* (equal exponents: the smaller mantissa was the larger) */
        negative = !negative;
    } else {
        r = mantissa - r;
    }
    while (r < 0x1000000) {
        if (exponent <= 8)
            return 0.0;
        r <<= 8;
        exponent -= 8;
    }
    if (r < (UINT64_C(1) << 31)) {
        int s = 32 - bit_length(r);
        if (exponent <= s)
            return 0.0;
        r <<= s;
        exponent -= s;
    }
    return rounded(exponent, r, negative);
}

static double subtract(double a, double b)
{
    return add(a, -b);
}

/* single_arith.divide: $FDIVS, the nearest single; by 0 unusual */
static double divide(double a, double b, Status *status)
{
    if (b == 0.0) {
        status->unusual = 1;
        return 0.0;
    }
    return nearest(a / b);
}

/* gw_transcendental.poly_steps: $POLY, Horner's rule of $FMULS and $FADDS */
static double poly(double x, const double *coefficients, int count)
{
    double total = coefficients[0];
    for (int i = 1; i < count; i++)
        total = add(product(total * x), coefficients[i]);
    return total;
}

/* $POLYX: x * P(x*x) */
static double polyx(double x, const double *coefficients, int count)
{
    return product(poly(product(x * x), coefficients, count) * x);
}

/* ---------------------------------------------------------------- constants */

static double ONE = 1.0, TWO_PI, HALF_PI, SIXTH_PI, TAN_TWELFTH_PI, SQR3, LN2, LOG2_E;
static double SIN_COEFFICIENTS[5], ATN_REDUCTION[2], ATN_COEFFICIENTS[4], LOG_NUMERATOR[4],
    LOG_DENOMINATOR[4], EXP_COEFFICIENTS[7];

static void set_constants(void)
{
    static const uint32_t sin_words[] = {0x861ED7FB, 0x87992665, 0x87233458, 0x86A55DE1, 0x83490FDB};
    static const uint32_t atn_reduction[] = {0x815DB3D7, 0x81800000};
    static const uint32_t atn_words[] = {0x7E833562, 0x7E4C2450, 0x7FAAA979, 0x81000000};
    static const uint32_t log_p[] = {0x8319F79A, 0x83436324, 0x848DCD75, 0x82837FA9};
    static const uint32_t log_q[] = {0x81000000, 0x834DB0E2, 0x8311720A, 0x7F3504F4};
    static const uint32_t exp_words[] = {0x7459887C, 0x772697E0, 0x7A1E1DC4, 0x7C63505E, 0x7E75FE1A,
                                         0x80317218, 0x81000000};
    TWO_PI = mbf(0x83490FDB);
    HALF_PI = mbf(0x81490FDB);
    SIXTH_PI = mbf(0x80060A92);
    TAN_TWELFTH_PI = mbf(0x7F0930A2);
    SQR3 = mbf(0x815DB3D7);
    LN2 = mbf(0x80317218);
    LOG2_E = mbf(0x8138AA3B);
    for (int i = 0; i < 5; i++)
        SIN_COEFFICIENTS[i] = mbf(sin_words[i]);
    for (int i = 0; i < 2; i++)
        ATN_REDUCTION[i] = mbf(atn_reduction[i]);
    for (int i = 0; i < 4; i++) {
        ATN_COEFFICIENTS[i] = mbf(atn_words[i]);
        LOG_NUMERATOR[i] = mbf(log_p[i]);
        LOG_DENOMINATOR[i] = mbf(log_q[i]);
    }
    for (int i = 0; i < 7; i++)
        EXP_COEFFICIENTS[i] = mbf(exp_words[i]);
}

/* ---------------------------------------------------------------- SIN and COS */

/* A fraction of a turn: numerator / 2**bits (bits may exceed 64 for tiny angles; the
   numerator has at most 58 bits). */
typedef struct {
    uint64_t numerator;
    int bits;
} Turns;

static uint64_t shifted(uint64_t v, int n)
{
    return n >= 64 ? 0 : v >> n;
}

static uint64_t low_bits(uint64_t v, int n)
{
    return n >= 64 ? v : v & ((UINT64_C(1) << n) - 1);
}

#define INVERSE_TWO_PI UINT64_C(0xA2F9836E4E440B)  /* $IN2PI's 56 bits: 1/(2*pi) = it * 2**-58 */

/* gw_transcendental._turns: the fraction of x radians (x >= 0, a single) in turns, the
   product with 1/(2*pi) rounded half to even to 56 bits ($FMULD) */
static Turns turns_of(double x)
{
    Turns zero = {0, 2};
    if (x == 0.0)
        return zero;
    int e = exponent_of(x);
    uint64_t mantissa24 = mantissa_of(x) >> 29;  /* int(m * 2**24): the top 24 bits */
    /* the 80-bit product as high:low, each part below 2**52 of a 28-bit split */
    uint64_t inverse_high = INVERSE_TWO_PI >> 28, inverse_low = INVERSE_TWO_PI & ((UINT64_C(1) << 28) - 1);
    uint64_t part_low = mantissa24 * inverse_low;  /* < 2**52 */
    uint64_t part_high = mantissa24 * inverse_high;  /* < 2**52, weight 2**28 */
    /* full = part_high * 2**28 + part_low, as hi (bits 64 and up) and lo */
    uint64_t lo = (part_high << 28) + part_low;
    uint64_t hi = (part_high >> 36) + (lo < (part_high << 28) ? 1 : 0);
    int length = hi ? 64 + bit_length(hi) : bit_length(lo);
    int drop = length - 56;  /* 79 or 80 bits: drop 23 or 24 */
    uint64_t mantissa = (lo >> drop) | (hi << (64 - drop));
    uint64_t rest = lo & ((UINT64_C(1) << drop) - 1);
    uint64_t half = UINT64_C(1) << (drop - 1);
    if (rest > half || (rest == half && (mantissa & 1)))
        mantissa += 1;
    int bits = 82 - e - drop;
    if (bit_length(mantissa) - bits <= -128 || bits <= 0)
        return zero;
    if (bits < 2) {
        Turns t = {(mantissa & 1) << 1, 2};
        return t;
    }
    Turns t = {low_bits(mantissa, bits), bits};
    return t;
}

/* mbf_double.shifted_right: $SHRA of a 64-bit register, bytes first, then bits */
static uint64_t shifted_right(uint64_t reg, int shift)
{
    while (shift >= 8) {
        reg = (reg >> 8) | (reg & 0x20);
        shift -= 8;
    }
    while (shift) {
        reg >>= 1;
        if (reg & 0x10)
            reg |= 0x20;
        shift -= 1;
    }
    return reg;
}

/* gw_transcendental._quarter_turn_added: $FADDD of the fraction and $COS's quarter turn */
static Turns quarter_turn_added(Turns t)
{
    Turns quarter = {1, 2};
    if (!t.numerator)
        return quarter;
    if (shifted(t.numerator, t.bits - 2)) {
        Turns r = {t.numerator + (UINT64_C(1) << (t.bits - 2)), t.bits};
        return r;
    }
    int length = bit_length(t.numerator);
    int shift = t.bits - length - 1;
    if (shift >= 57)
        return quarter;
    uint64_t reg = t.numerator << (64 - length);
    reg = shifted_right(reg, shift);
    reg += UINT64_C(1) << 63;
    uint64_t guard = reg & 0xFF, mantissa = reg >> 8;
    if (guard >= 0x80) {
        mantissa += 1;
        if (guard == 0x80)
            mantissa &= ~(uint64_t)1;
    }
    Turns r = {mantissa, 57};
    return r;
}

/* gw_transcendental._sine_of_turns: SIN30 onwards */
static double sine_of_turns(Turns t)
{
    int bits = t.bits;
    uint64_t quadrant = shifted(t.numerator, bits - 2);
    uint64_t angle = low_bits(t.numerator, bits - 2);
    if (quadrant & 1)
        angle = (UINT64_C(1) << (bits - 2)) - angle;  /* (bits - 2 < 58 here: the numerator reaches it) */
    double x;
    if (!angle) {
        x = 0.0;
    } else {
        int extra = bit_length(angle) - 25;
        if (extra >= 0) {
            angle = ((angle >> extra) + 1) >> 1;  /* the top 24 bits, rounded up on the 25th */
            x = (double)angle * pow2(extra + 1 - bits);
        } else {
            x = (double)angle * pow2(-bits);
        }
    }
    double result;
    if (x < 1.220703125e-04)  /* 2**-13 */
        result = product(x * TWO_PI);
    else
        result = polyx(x, SIN_COEFFICIENTS, 5);
    return (quadrant >= 2 && result != 0.0) ? -result : result;
}

static double sin_single(double x)
{
    if (-9.765625e-04 < x && x < 9.765625e-04)  /* 2**-10 */
        return x + 0.0;
    double size = x < 0 ? -x : x;
    double result = sine_of_turns(turns_of(size));
    return (x < 0 && result != 0.0) ? -result : result;
}

static double cos_single(double x)
{
    double size = x < 0 ? -x : x;
    Turns t = quarter_turn_added(turns_of(size));
    t.numerator = low_bits(t.numerator, t.bits);
    return sine_of_turns(t);
}

/* ---------------------------------------------------------------- ATN, LOG, EXP */

static double atn_single(double x, Status *status)
{
    int negative = x < 0;
    double y = negative ? -x : x + 0.0;
    int inverted = y >= ONE;
    if (inverted)
        y = divide(ONE, y, status);
    int reduced = y >= TAN_TWELFTH_PI;
    if (reduced)
        y = divide(poly(y, ATN_REDUCTION, 2), add(y, SQR3), status);
    double result = polyx(y, ATN_COEFFICIENTS, 4);
    if (reduced)
        result = add(result, SIXTH_PI);
    if (inverted)
        result = subtract(HALF_PI, result);
    return (negative && result != 0.0) ? -result : result;
}

static double log_single(double x, Status *status)
{
    if (x <= 0) {  /* Illegal function call: the Python function raises it */
        status->unusual = 1;
        return 0.0;
    }
    if (x == 1.0)
        return 0.0;
    int e = exponent_of(x);
    double m = x * pow2(-e);
    double ratio = divide(poly(m, LOG_NUMERATOR, 4), poly(m, LOG_DENOMINATOR, 4), status);
    return product(add((double)e, ratio) * LN2);
}

static double exp_single(double x, Status *status)
{
    double y = product(x * LOG2_E);
    if (isinf(y)) {
        status->unusual = 1;
        return 0.0;
    }
    int exponent = y != 0.0 ? exponent_of(y) + 128 : 0;
    if (exponent < 104)
        return 1.0;
    if (exponent >= 136) {
        if (y < 0)
            return 0.0;
        status->unusual = 1;  /* overflow: the caller's policy */
        return 0.0;
    }
    double whole = floor(y);
    if (whole == 127.0) {
        status->unusual = 1;
        return 0.0;
    }
    double fraction = subtract(y, whole);
    double result = product(poly(fraction, EXP_COEFFICIENTS, 7) * pow2((int)whole));
    if (isinf(result))
        status->unusual = 1;
    return result;
}

/* gw_transcendental.power for x > 0 and y not an integer below 32768 in size (those
   multiply: the Python function); a power that overflows or underflows to 0 under a
   negative y is unusual */
static double power_single(double x, double y, Status *status)
{
    if (x <= 0 || y == 0.0) {
        status->unusual = 1;
        return 0.0;
    }
    double size = y < 0 ? -y : y;
    if (size < 32768 && size == floor(size)) {
        status->unusual = 1;
        return 0.0;
    }
    double result = exp_single(product(size * log_single(x, status)), status);
    if (status->unusual)
        return 0.0;
    if (y < 0) {
        if (result == 0.0) {
            status->unusual = 1;
            return 0.0;
        }
        return divide(ONE, result, status);
    }
    return result;
}

/* ---------------------------------------------------------------- Python objects */

/* The argument as a single inside MBF's range (0 included), or 0 returned: unusual. */
static int single_argument(PyObject *arg, double *value)
{
    double x;
    if (PyFloat_CheckExact(arg)) {
        x = PyFloat_AS_DOUBLE(arg);
    } else if (PyLong_CheckExact(arg)) {
        x = PyLong_AsDouble(arg);
        if (x == -1.0 && PyErr_Occurred()) {
            PyErr_Clear();
            return 0;
        }
    } else {
        return 0;
    }
    if (x == 0.0) {
        *value = 0.0;
        return 1;
    }
    double size = fabs(x);
    if (!(size >= TINY && size < LIMIT))  /* also NaN */
        return 0;
    if (bits_of(x) & ((UINT64_C(1) << 29) - 1))  /* more than 24 bits: not a single */
        return 0;
    *value = x;
    return 1;
}

typedef double (*Unary)(double, Status *);

static double sin_checked(double x, Status *status)
{
    (void)status;
    return sin_single(x);
}

static double cos_checked(double x, Status *status)
{
    (void)status;
    return cos_single(x);
}

static double tan_checked(double x, Status *status)
{
    return divide(sin_single(x), cos_single(x), status);
}

static PyObject *fallback(PyObject *python, PyObject *const *args, Py_ssize_t nargs, PyObject *kwnames)
{
    return PyObject_Vectorcall(python, args, (size_t)nargs, kwnames);
}

/* One argument (and, for EXP, the optional overflow callback the Python function takes). */
static PyObject *call_unary(Unary function, PyObject *python, PyObject *const *args, Py_ssize_t nargs,
                            PyObject *kwnames, Py_ssize_t most)
{
    double x;
    if (kwnames || nargs < 1 || nargs > most || !single_argument(args[0], &x))
        return fallback(python, args, nargs, kwnames);
    Status status = {0};
    double result = function(x, &status);
    if (status.unusual)
        return fallback(python, args, nargs, kwnames);
    return PyFloat_FromDouble(result);
}

/* fast_NAME: the Python-callable routine of FUNCTION, taking at most MOST positional arguments */
#define UNARY(name, function, most) \
    static PyObject *fast_##name(PyObject *self, PyObject *const *args, Py_ssize_t nargs, PyObject *kwnames) \
    { \
        return call_unary(function, self, args, nargs, kwnames, most); \
    }

UNARY(sin, sin_checked, 1)
UNARY(cos, cos_checked, 1)
UNARY(tan, tan_checked, 1)
UNARY(atn, atn_single, 1)
UNARY(log, log_single, 1)
UNARY(exp, exp_single, 2)

static PyObject *fast_power(PyObject *self, PyObject *const *args, Py_ssize_t nargs, PyObject *kwnames)
{
    double x, y;
    if (kwnames || nargs < 2 || nargs > 3 || !single_argument(args[0], &x) || !single_argument(args[1], &y))
        return fallback(self, args, nargs, kwnames);
    Status status = {0};
    double result = power_single(x, y, &status);
    if (status.unusual)
        return fallback(self, args, nargs, kwnames);
    return PyFloat_FromDouble(result);
}

#define ROUTINE(name, doc) \
    {#name, (PyCFunction)(void (*)(void))fast_##name, METH_FASTCALL | METH_KEYWORDS, doc}

static PyMethodDef routines[] = {
    ROUTINE(sin, "SIN as $SIN (gw_transcendental.sin), bit for bit."),
    ROUTINE(cos, "COS as $COS (gw_transcendental.cos), bit for bit."),
    ROUTINE(tan, "TAN as $TAN (gw_transcendental.tan), bit for bit."),
    ROUTINE(atn, "ATN as $ATAN (gw_transcendental.atn), bit for bit."),
    ROUTINE(log, "LOG as $LOG (gw_transcendental.log), bit for bit."),
    ROUTINE(exp, "EXP as $EXP (gw_transcendental.exp(x, overflow)), bit for bit."),
    ROUTINE(power, "x ^ y as $FPWR (gw_transcendental.power(x, y, overflow)), bit for bit."),
    {NULL, NULL, 0, NULL},
};

static PyObject *bound(PyObject *module, PyObject *args)
{
    (void)module;
    return bound_routine(routines, args);
}

/* The single steps themselves, for the tests (tests/test_mbf_fast.py compares them with
   single_arith's on their own). */
static PyObject *step_product(PyObject *module, PyObject *arg)
{
    (void)module;
    double p = PyFloat_AsDouble(arg);
    if (p == -1.0 && PyErr_Occurred())
        return NULL;
    return PyFloat_FromDouble(product(p));
}

static PyObject *step_add(PyObject *module, PyObject *const *args, Py_ssize_t nargs)
{
    (void)module;
    if (nargs != 2) {
        PyErr_SetString(PyExc_TypeError, "add(a, b) takes two singles");
        return NULL;
    }
    double a = PyFloat_AsDouble(args[0]), b = PyFloat_AsDouble(args[1]);
    if (PyErr_Occurred())
        return NULL;
    return PyFloat_FromDouble(add(a, b));
}

static PyMethodDef module_methods[] = {
    {"product", step_product, METH_O, "$FMULS of the exact product of two singles (single_arith.product)."},
    {"add", (PyCFunction)(void (*)(void))step_add, METH_FASTCALL,
     "$FADDS of two singles in MBF's range (single_arith.add)."},
    {"bound", bound, METH_VARARGS,
     "bound(name, python): the C routine `name` (sin cos tan atn log exp power) handing every "
     "unusual call to the Python function `python`, which computes the same values."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_mbf_fast",
    "GW-BASIC's single-precision SIN COS TAN ATN LOG EXP and ^ in C, bit for bit as "
    "gw_transcendental.py (an optional accelerator; see bound).",
    -1, module_methods, NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__mbf_fast(void)
{
    set_constants();
    PyObject *m = PyModule_Create(&module);
    if (m && PyModule_AddStringConstant(m, "ROUTINES", "sin cos tan atn log exp power") < 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
