/* --arith decimal's + - * /, SQR, LN, LOG, EXP and `local + RND` in C: an optional
   accelerator of the compiled code's scale caches (decimal_scales.py, decimal_calls.py).

   Every number the decimal arithmetic holds is the nearest double to a decimal of at most
   12 significant digits (decimal_arith.py).  For such operands each routine here computes
   the float result r of the operation (or the float function's value v), takes the scale
   S = +-10**k (0 <= k <= 22, an exact double, the sign of r) of r's own decade, and gives
   fl(n / S) for the whole number n nearest t = fl(r * S) when the tests of decimal_scales.py
   (+ - * /: 0 < t < 10**12 and t == n, or t >= 10**11 and |t - n| < 1/2 - 2**-8) or of
   decimal_calls.py (the functions and the drawn sum: 10**11 <= t < 10**12 and the band test,
   |S| at most the function's largest scale) hold.  Those modules prove that the value is
   then the decimal routine's result (the 12-digit rounding, half up, of the exact result at
   the operands' decimals) for any such S: this is the scale caches' own float path, with the
   scale of the result's decade instead of a cached one (what their writers try after a
   miss), so no call misses for a change of decade.  A sum or a difference keeps the
   proof's guard: |S a| and |S b| below 10**13.

   Whatever the tests do not settle -- an operand that is not a float, a result of 0, NaN or
   an infinity, a decade outside 1E-11 .. 1E+12, a division by zero, a result near a rounding
   boundary -- is handed to the Python routine the function object was bound to (its
   `self`, decimal_arith's add, subtract, multiply, divide, sqrt, log, log10, exp, or the
   drawn sum's rounding of the number then add), with the same arguments: the errors, the
   overflow and the underflow stay decimal_arith's own.  tests/test_decimal_fast.py compares
   every routine with the decimal module and with the Python routines.

   Build: setup.py, as an optional extension (no compiler: the compiled code's inline scale
   caches serve, decimal_fast.py).  No contraction of a*b+c into fused multiply-adds
   (setup.py passes -ffp-contract=off): every double operation here rounds as Python's. */

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <float.h>
#include <math.h>
#include <string.h>
#include "_bound_routine.h"

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "_decimal_fast needs double operations evaluated in double (FLT_EVAL_METHOD 0)"
#endif

#define MAGIC 6755399441055744.0        /* 1.5 * 2**52: (t + MAGIC) - MAGIC rounds t (|t| < 2**51) */
#define TOP 1e12                        /* decimal_scales.TOP */
#define BOTTOM 1e11                     /* decimal_scales.BOTTOM */
#define BAND (0.5 - 0.00390625)         /* decimal_scales.BAND: 1/2 - 2**-8 */
#define GUARD 1e13                      /* decimal_scales.GUARD */
#define DRAWN_SCALE 1e9                 /* decimal_scales.DRAWN_SCALE */

/* 10**0 .. 10**22: exact doubles (the scales) */
static const double SCALES[23] = {
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
};

/* the decades' lower ends 1E-11 .. 1E+12 as the nearest doubles (EDGES[i] is 10**(i - 11)) */
static const double EDGES[24] = {
    1e-11, 1e-10, 1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1, 1e0,
    1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12,
};

/* The scale 10**(11 - e) of the decade 10**e <= |x| < 10**(e+1) with x's sign, for |x| from
   1E-11 to below 1E+12; 0 for any other x (0, NaN, infinities, beyond those decades).  The
   decade is a guess from the binary exponent, corrected by one comparison each way: any
   scale the tests accept gives the same value (the proof holds for every S), so the choice
   decides only how often the Python routine is called. */
static inline double decade_scale(double x)
{
    double size = fabs(x);
    if (!(size >= EDGES[0] && size < EDGES[23]))
        return 0.0;
    int binary;
    frexp(size, &binary);                      /* 2**(binary-1) <= size < 2**binary */
    int e = (int)floor((binary - 1) * 0.30102999566398120);
    if (e < -11)
        e = -11;
    if (e > 11)
        e = 11;
    while (e < 11 && size >= EDGES[e + 12])
        e++;
    while (e > -11 && size < EDGES[e + 11])
        e--;
    double s = SCALES[11 - e];
    return x < 0.0 ? -s : s;
}

/* decimal_scales' tests of a scaled result t: the exact test or the band test */
static inline int settled(double t, double *n)
{
    if (!(t > 0.0 && t < TOP))
        return 0;
    *n = (t + MAGIC) - MAGIC;
    return *n == t || (t >= BOTTOM && t - *n > -BAND && t - *n < BAND);
}

/* decimal_calls' test (the band test alone, t from 10**11 up) */
static inline int banded(double t, double *n)
{
    if (!(t >= BOTTOM && t < TOP))
        return 0;
    *n = (t + MAGIC) - MAGIC;
    return t - *n > -BAND && t - *n < BAND;
}

static PyObject *fallback(PyObject *python, PyObject *const *args, Py_ssize_t nargs)
{
    return PyObject_Vectorcall(python, args, nargs, NULL);
}

enum { ADD, SUBTRACT, MULTIPLY, DIVIDE };

static inline PyObject *arithmetic(int op, PyObject *python, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 2 || !PyFloat_CheckExact(args[0]) || !PyFloat_CheckExact(args[1]))
        return fallback(python, args, nargs);
    double a = PyFloat_AS_DOUBLE(args[0]), b = PyFloat_AS_DOUBLE(args[1]), r;
    switch (op) {
    case ADD: r = a + b; break;
    case SUBTRACT: r = a - b; break;
    case MULTIPLY: r = a * b; break;
    default:
        if (b == 0.0)
            return fallback(python, args, nargs);
        r = a / b;
    }
    double s = decade_scale(r), n;
    if (s != 0.0 && (op >= MULTIPLY || (fabs(a) * fabs(s) < GUARD && fabs(b) * fabs(s) < GUARD))
            && settled(r * s, &n))
        return PyFloat_FromDouble(n / s);
    return fallback(python, args, nargs);
}

#define ARITHMETIC(name, op) \
    static PyObject *fast_##name(PyObject *self, PyObject *const *args, Py_ssize_t nargs) \
    { \
        return arithmetic(op, self, args, nargs); \
    }

ARITHMETIC(add, ADD)
ARITHMETIC(subtract, SUBTRACT)
ARITHMETIC(multiply, MULTIPLY)
ARITHMETIC(divide, DIVIDE)

/* `a + v`, v the number RND drew (from 0 up to below 1, unrounded): the sum of a and v rounded
   to 12 digits, with |S| at most DRAWN_SCALE and the band test (decimal_scales.writers'
   drawn_sum proves it is the sum of a and v's 12-digit rounding); else the Python function
   (a, v) -> add(a, rounded(v)). */
static PyObject *fast_drawn_sum(PyObject *self, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 2 || !PyFloat_CheckExact(args[0]) || !PyFloat_CheckExact(args[1]))
        return fallback(self, args, nargs);
    double v = PyFloat_AS_DOUBLE(args[1]);
    if (!(v >= 0.0 && v < 1.0))
        return fallback(self, args, nargs);
    double r = PyFloat_AS_DOUBLE(args[0]) + v;
    double s = decade_scale(r), n;
    if (s != 0.0 && s >= -DRAWN_SCALE && s <= DRAWN_SCALE && banded(r * s, &n))
        return PyFloat_FromDouble(n / s);
    return fallback(self, args, nargs);
}

/* The float functions with decimal_calls' bounds: the value at x, or NaN where the float
   function does not apply (as the compiled code's forms: SQR of more than 0, LN and LOG of 0
   to 1E+100, EXP of -20 to 20), and the largest scale (decimal_calls.LARGEST_SCALE). */
enum { SQRT, LOG, LOG10, EXP };

static inline PyObject *function(int which, PyObject *python, PyObject *const *args, Py_ssize_t nargs)
{
    if (nargs != 1 || !PyFloat_CheckExact(args[0]))
        return fallback(python, args, nargs);
    double x = PyFloat_AS_DOUBLE(args[0]), v, largest;
    switch (which) {
    case SQRT:
        if (!(x > 0.0))
            return fallback(python, args, nargs);
        v = sqrt(x);
        largest = 1e22;
        break;
    case LOG:
    case LOG10:
        if (!(x > 0.0 && x < 1e100))
            return fallback(python, args, nargs);
        v = which == LOG ? log(x) : log10(x);
        largest = 1e12;
        break;
    default:
        if (!(x > -20.0 && x < 20.0))
            return fallback(python, args, nargs);
        v = exp(x);
        largest = 1e22;
    }
    double s = decade_scale(v), n;
    if (s != 0.0 && s >= -largest && s <= largest && banded(v * s, &n))
        return PyFloat_FromDouble(n / s);
    return fallback(python, args, nargs);
}

#define FUNCTION(name, which) \
    static PyObject *fast_##name(PyObject *self, PyObject *const *args, Py_ssize_t nargs) \
    { \
        return function(which, self, args, nargs); \
    }

FUNCTION(sqrt, SQRT)
FUNCTION(log, LOG)
FUNCTION(log10, LOG10)
FUNCTION(exp, EXP)

#define ROUTINE(name, doc) {#name, (PyCFunction)(void (*)(void))fast_##name, METH_FASTCALL, doc}

static PyMethodDef routines[] = {
    ROUTINE(add, "a + b rounded to 12 digits (decimal_arith.add), bit for bit."),
    ROUTINE(subtract, "a - b rounded to 12 digits (decimal_arith.subtract), bit for bit."),
    ROUTINE(multiply, "a * b rounded to 12 digits (decimal_arith.multiply), bit for bit."),
    ROUTINE(divide, "a / b rounded to 12 digits (decimal_arith.divide), bit for bit."),
    ROUTINE(drawn_sum, "a + v (v drawn by RND, unrounded) as add(a, rounded(v)), bit for bit."),
    ROUTINE(sqrt, "SQR rounded to 12 digits (decimal_arith.sqrt), bit for bit."),
    ROUTINE(log, "LN rounded to 12 digits (decimal_arith.log), bit for bit."),
    ROUTINE(log10, "LOG rounded to 12 digits (decimal_arith.log10), bit for bit."),
    ROUTINE(exp, "EXP rounded to 12 digits (decimal_arith.exp), bit for bit."),
    {NULL, NULL, 0, NULL},
};

static PyObject *bound(PyObject *module, PyObject *args)
{
    (void)module;
    return bound_routine(routines, args);
}

/* the decade's scale itself, for the tests */
static PyObject *step_scale(PyObject *module, PyObject *arg)
{
    (void)module;
    double x = PyFloat_AsDouble(arg);
    if (x == -1.0 && PyErr_Occurred())
        return NULL;
    return PyFloat_FromDouble(decade_scale(x));
}

static PyMethodDef module_methods[] = {
    {"scale", step_scale, METH_O,
     "The scale 10**(11 - e) of x's decade with x's sign (x from 1E-11 to below 1E+12 in size), else 0."},
    {"bound", bound, METH_VARARGS,
     "bound(name, python): the C routine `name` handing every call its tests do not settle to "
     "the Python function `python`, which computes the same values."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_decimal_fast",
    "--arith decimal's + - * /, SQR, LN, LOG, EXP and local + RND in C, bit for bit as "
    "decimal_arith.py (an optional accelerator; see bound).",
    -1, module_methods, NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__decimal_fast(void)
{
    PyObject *m = PyModule_Create(&module);
    if (m && PyModule_AddStringConstant(m, "ROUTINES",
                                        "add subtract multiply divide drawn_sum sqrt log log10 exp") < 0) {
        Py_DECREF(m);
        return NULL;
    }
    return m;
}
