/* A recorded path (yaseer/linkages/tracing.py) run as a program of double operations.

   A recorded path is a Python function of a few hundred lines of float and complex arithmetic
   between element reads and element writes.  yaseer/linkages/straight_line.py translates its text
   into the instructions of this module: each names registers of one array of doubles (a complex
   value takes two: its real part, then its imaginary part), and each computes what the Python
   operation computes, bit for bit, on the values it can take without raising:

   - + - * of floats are the C operations (built with -ffp-contract=off: no fused multiply-add);
     / and % refuse a zero divisor; % adds the divisor where fmod's remainder has the other sign
     and gives a zero the divisor's sign (float_rem of floatobject.c);
   - complex + - * are the part formulas of complexobject.c's _Py_c_sum, _Py_c_diff and _Py_c_prod
     (a float operand is the complex number (x, 0.0) first, as CPython 3.11-3.13 make it);
     complex / and abs call _Py_c_quot and _Py_c_abs themselves;
   - x ** 2 of a float is pow(|x|, 2.0) for a normal, finite result (float_pow), else refused;
   - math.sqrt, cos, sin, atan, atan2, ulp, cmath.rect and the unit length ldexp(1.0, frexp(x)[1])
     compute what mathmodule.c and cmathmodule.c compute for finite arguments; any other argument
     is refused.

   A refused operation, an input that is not a float, an array too short, a guard that fails:
   the run stops before any output is written (the writes are the program's last instructions)
   and the path's Python function runs instead, from the start, and does what it does (its
   outputs, a Retrace, an error).  So a run of a program either writes exactly what the Python
   function writes or leaves the whole call to it.

   Programs come from the translator; each is checked here as a whole before it is used (every
   register, array, name and jump in range), so a damaged one is refused, never run. */

#define PY_SSIZE_T_CLEAN
#include <Python.h>
#include <math.h>
#include <float.h>
#include <errno.h>
#include <string.h>

enum {
    OP_READ,        /* d = float element b of array a (exact float, in range), else refuse */
    OP_SCALAR,      /* d = scalar a of _M.scalars (0.0 when absent; an exact float), else refuse */
    OP_MOVE,        /* d = a */
    OP_MOVE2,       /* d, d+1 = a, a+1 */
    OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_MOD,
    OP_NEG, OP_ABS, OP_SQUARE,
    OP_CADD, OP_CSUB, OP_CMUL, OP_CDIV, OP_CNEG, OP_CABS,
    OP_FLOAT2C,     /* d, d+1 = a, 0.0 */
    OP_LT, OP_LE, OP_GT, OP_GE, OP_EQ, OP_NE,
    OP_CEQ, OP_CNE,
    OP_TRUTH,       /* d = a != 0.0 (NaN is true) */
    OP_NOT,         /* d = not a */
    OP_AND, OP_OR,  /* d = a and b, a or b (truths) */
    OP_SQRT, OP_COS, OP_SIN, OP_ATAN, OP_ATAN2, OP_ISFINITE, OP_ULP, OP_UNIT_EXACT,
    OP_RECT,        /* d, d+1 = cmath.rect(a, b) */
    OP_QUADRANT,    /* d, d+1 = the exact unit of angle a (degrees) when a is a quadrant's angle; b = found */
    OP_JUMP_IF_NOT, /* if not a: go to instruction d */
    OP_JUMP,        /* go to instruction d */
    OP_REFUSE_IF,   /* if a: refuse */
    OP_FINITE_ALL,  /* refuse unless registers extra[a .. a+b) are all finite */
    OP_CHECK_LENGTH,/* refuse unless array a has an element b */
    OP_CHECK_FLOAT, /* refuse unless element b of array a is a float */
    OP_WRITE,       /* element b of array a = register d (a new float) */
    OP_SET_SCALAR,  /* _M.set_scalar(names[a], register d) */
    OP_COUNT
};

#define WIDTH 4  /* ints an instruction: operation, d, a, b */
#define ARRAYS 64  /* arrays a program may name (a run holds them in a fixed table) */

typedef struct {
    PyObject_HEAD
    PyObject *fallback;     /* the path's Python function */
    PyObject *translate;    /* called once, without arguments: the program's parts (a dict) or None */
    Py_ssize_t warm;        /* calls left to the fallback before the translation */
    int state;              /* WARMING, RUNNING (a program), PLAIN (no program: the fallback alone) */
    int *code;              /* instructions, WIDTH ints each */
    Py_ssize_t length;      /* instructions */
    Py_ssize_t first_write; /* the first WRITE or SET_SCALAR: only they follow it */
    int *extra;             /* register lists (OP_FINITE_ALL) */
    Py_ssize_t extra_length;
    double *registers;      /* constants in place, the rest written before read */
    Py_ssize_t register_count;
    PyObject *arrays;       /* tuple of str: the arrays' names, looked up in _M.arrays */
    PyObject *scalars;      /* tuple of str: the scalars' names (OP_SCALAR, OP_SET_SCALAR) */
    double *quadrants;      /* (angle, real, imag) triples */
    Py_ssize_t quadrant_count;
    int plain_numbers;      /* refuse a machine whose dialect says typed_numbers */
    int busy;               /* a run in progress (a call back into it runs the fallback) */
    PyObject *error;        /* why the translation's program was refused (None: it was not) */
    Py_ssize_t runs, refused;
} PathObject;

enum { WARMING, RUNNING, PLAIN };

static PyObject *attr_arrays, *attr_scalars, *attr_dialect, *attr_typed_numbers, *attr_set_scalar;

static void
path_dealloc(PathObject *self)
{
    Py_XDECREF(self->fallback);
    Py_XDECREF(self->translate);
    Py_XDECREF(self->error);
    Py_XDECREF(self->arrays);
    Py_XDECREF(self->scalars);
    PyMem_Free(self->code);
    PyMem_Free(self->extra);
    PyMem_Free(self->registers);
    PyMem_Free(self->quadrants);
    Py_TYPE(self)->tp_free((PyObject *)self);
}

/* the float_rem of floatobject.c for a nonzero divisor */
static double
python_mod(double x, double y)
{
    double mod = fmod(x, y);
    if (mod) {
        if ((y < 0) != (mod < 0))
            mod += y;
    }
    else {
        mod = copysign(0.0, y);
    }
    return mod;
}

static volatile double square_exponent = 2.0;

/* x ** 2 of float_pow, where it gives a normal finite number without raising: 0 (refused) else 1 */
static int
python_square(double x, double *result)
{
    double r;
    if (!isfinite(x))
        return 0;
    if (x == 0.0) {
        *result = 0.0;  /* an even power of a zero: +0.0 */
        return 1;
    }
    errno = 0;
    /* the exponent is read at run time: a compiler turns pow(x, 2.0) into x * x, which is correctly
       rounded where the C library's pow (Python's x ** 2) may be a unit in the last place off */
    r = pow(fabs(x), square_exponent);
    if (errno != 0 || !isfinite(r) || fabs(r) < DBL_MIN)
        return 0;
    *result = r;
    return 1;
}

/* math.ulp of a finite x */
static double
python_ulp(double x)
{
    double next;
    x = fabs(x);
    next = nextafter(x, INFINITY);
    if (isinf(next)) {
        next = nextafter(x, -INFINITY);
        return x - next;
    }
    return next - x;
}

/* Run the program on machine m: 1 done, 0 refused (nothing written), -1 a Python error. */
static int
run(PathObject *self, PyObject *m)
{
    PyObject *lists[ARRAYS];
    PyObject *arrays_dict = NULL, *scalars_dict = NULL;
    Py_ssize_t narrays = PyTuple_GET_SIZE(self->arrays), k, held = 0;
    double *r = self->registers;
    const int *code = self->code;
    Py_ssize_t pc = 0, length = self->length;
    int result = 0;

    if (self->plain_numbers) {
        PyObject *dialect = PyObject_GetAttr(m, attr_dialect);
        if (dialect == NULL) {
            if (!PyErr_ExceptionMatches(PyExc_AttributeError))
                return -1;
            PyErr_Clear();
        }
        else {
            PyObject *typed = PyObject_GetAttr(dialect, attr_typed_numbers);
            int truth;
            Py_DECREF(dialect);
            if (typed == NULL) {
                PyErr_Clear();
                return 0;
            }
            truth = PyObject_IsTrue(typed);
            Py_DECREF(typed);
            if (truth != 0) {
                PyErr_Clear();
                return 0;
            }
        }
    }
    arrays_dict = PyObject_GetAttr(m, attr_arrays);
    if (arrays_dict == NULL) {
        PyErr_Clear();
        return 0;
    }
    if (!PyDict_CheckExact(arrays_dict))
        goto done;
    for (k = 0; k < narrays; k++) {
        PyObject *list = PyDict_GetItemWithError(arrays_dict, PyTuple_GET_ITEM(self->arrays, k));
        if (list == NULL || !PyList_CheckExact(list)) {
            PyErr_Clear();
            goto done;
        }
        Py_INCREF(list);  /* held: set_scalar runs Python code before the run ends */
        lists[held++] = list;
    }
    if (PyTuple_GET_SIZE(self->scalars)) {
        scalars_dict = PyObject_GetAttr(m, attr_scalars);
        if (scalars_dict == NULL) {
            PyErr_Clear();
            goto done;
        }
        if (!PyDict_CheckExact(scalars_dict))
            goto done;
    }

    while (pc < length) {
        const int *at = code + pc * WIDTH;
        int d = at[1], a = at[2], b = at[3];
        if (pc == self->first_write) {
            /* every element written exists (the program checked them; a list may have changed since) */
            Py_ssize_t w;
            for (w = pc; w < length; w++) {
                const int *write = code + w * WIDTH;
                if (write[0] == OP_WRITE && write[3] >= PyList_GET_SIZE(lists[write[2]]))
                    goto done;
            }
        }
        pc++;
        switch (at[0]) {
        case OP_READ: {
            PyObject *list = lists[a], *item;
            if (b >= PyList_GET_SIZE(list))
                goto done;
            item = PyList_GET_ITEM(list, b);
            if (!PyFloat_CheckExact(item))
                goto done;
            r[d] = PyFloat_AS_DOUBLE(item);
            break;
        }
        case OP_SCALAR: {
            PyObject *item = PyDict_GetItemWithError(scalars_dict, PyTuple_GET_ITEM(self->scalars, a));
            if (item == NULL) {
                if (PyErr_Occurred()) {
                    PyErr_Clear();
                    goto done;
                }
                r[d] = 0.0;
            }
            else if (PyFloat_CheckExact(item)) {
                r[d] = PyFloat_AS_DOUBLE(item);
            }
            else {
                goto done;
            }
            break;
        }
        case OP_MOVE: r[d] = r[a]; break;
        case OP_MOVE2: r[d] = r[a]; r[d + 1] = r[a + 1]; break;
        case OP_ADD: r[d] = r[a] + r[b]; break;
        case OP_SUB: r[d] = r[a] - r[b]; break;
        case OP_MUL: r[d] = r[a] * r[b]; break;
        case OP_DIV:
            if (r[b] == 0.0)
                goto done;
            r[d] = r[a] / r[b];
            break;
        case OP_MOD:
            if (r[b] == 0.0)
                goto done;
            r[d] = python_mod(r[a], r[b]);
            break;
        case OP_NEG: r[d] = -r[a]; break;
        case OP_ABS: r[d] = fabs(r[a]); break;
        case OP_SQUARE:
            if (!python_square(r[a], &r[d]))
                goto done;
            break;
        case OP_CADD: {
            double re = r[a] + r[b], im = r[a + 1] + r[b + 1];
            r[d] = re; r[d + 1] = im;
            break;
        }
        case OP_CSUB: {
            double re = r[a] - r[b], im = r[a + 1] - r[b + 1];
            r[d] = re; r[d + 1] = im;
            break;
        }
        case OP_CMUL: {
            double re = r[a] * r[b] - r[a + 1] * r[b + 1];
            double im = r[a] * r[b + 1] + r[a + 1] * r[b];
            r[d] = re; r[d + 1] = im;
            break;
        }
        case OP_CDIV: {
            Py_complex x, y, q;
            if (r[b] == 0.0 && r[b + 1] == 0.0)
                goto done;
            x.real = r[a]; x.imag = r[a + 1];
            y.real = r[b]; y.imag = r[b + 1];
            errno = 0;
            q = _Py_c_quot(x, y);
            if (errno != 0)
                goto done;
            r[d] = q.real; r[d + 1] = q.imag;
            break;
        }
        case OP_CNEG: {
            double re = -r[a], im = -r[a + 1];
            r[d] = re; r[d + 1] = im;
            break;
        }
        case OP_CABS: {
            Py_complex x;
            double value;
            x.real = r[a]; x.imag = r[a + 1];
            errno = 0;
            value = _Py_c_abs(x);
            if (errno != 0 || !isfinite(value))
                goto done;
            r[d] = value;
            break;
        }
        case OP_FLOAT2C: {
            double re = r[a];
            r[d] = re; r[d + 1] = 0.0;
            break;
        }
        case OP_LT: r[d] = r[a] < r[b]; break;
        case OP_LE: r[d] = r[a] <= r[b]; break;
        case OP_GT: r[d] = r[a] > r[b]; break;
        case OP_GE: r[d] = r[a] >= r[b]; break;
        case OP_EQ: r[d] = r[a] == r[b]; break;
        case OP_NE: r[d] = r[a] != r[b]; break;
        case OP_CEQ: r[d] = r[a] == r[b] && r[a + 1] == r[b + 1]; break;
        case OP_CNE: r[d] = !(r[a] == r[b] && r[a + 1] == r[b + 1]); break;
        case OP_TRUTH: r[d] = r[a] != 0.0; break;
        case OP_NOT: r[d] = !(r[a] != 0.0); break;
        case OP_AND: r[d] = (r[a] != 0.0) && (r[b] != 0.0); break;
        case OP_OR: r[d] = (r[a] != 0.0) || (r[b] != 0.0); break;
        case OP_SQRT:
            if (!isfinite(r[a]) || r[a] < 0.0)
                goto done;
            r[d] = sqrt(r[a]);
            break;
        case OP_COS:
            if (!isfinite(r[a]))
                goto done;
            r[d] = cos(r[a]);
            break;
        case OP_SIN:
            if (!isfinite(r[a]))
                goto done;
            r[d] = sin(r[a]);
            break;
        case OP_ATAN:
            if (!isfinite(r[a]))
                goto done;
            r[d] = atan(r[a]);
            break;
        case OP_ATAN2: {
            double y = r[a], x = r[b];
            if (!isfinite(y) || !isfinite(x))
                goto done;
            if (y == 0.0)  /* mathmodule.c's m_atan2: the zeros' cases by their signs */
                r[d] = copysign(1.0, x) == 1.0 ? copysign(0.0, y) : copysign(Py_MATH_PI, y);
            else
                r[d] = atan2(y, x);
            break;
        }
        case OP_ISFINITE: r[d] = isfinite(r[a]) ? 1.0 : 0.0; break;
        case OP_ULP:
            if (!isfinite(r[a]))
                goto done;
            r[d] = python_ulp(r[a]);
            break;
        case OP_UNIT_EXACT: {
            int exponent;
            double value;
            if (!isfinite(r[a]))
                goto done;
            (void)frexp(r[a], &exponent);
            value = ldexp(1.0, exponent);
            if (!isfinite(value))
                goto done;
            r[d] = value;
            break;
        }
        case OP_RECT: {
            double length = r[a], phi = r[b];
            if (!isfinite(length) || !isfinite(phi))
                goto done;
            if (phi == 0.0) {  /* cmathmodule.c's rect: the zero angle's own case */
                r[d] = length;
                r[d + 1] = length * phi;
            }
            else {
                double re = length * cos(phi), im = length * sin(phi);
                r[d] = re; r[d + 1] = im;
            }
            break;
        }
        case OP_QUADRANT: {
            Py_ssize_t q;
            double angle = r[a];
            r[b] = 0.0;
            for (q = 0; q < self->quadrant_count; q++) {
                if (self->quadrants[3 * q] == angle) {
                    r[d] = self->quadrants[3 * q + 1];
                    r[d + 1] = self->quadrants[3 * q + 2];
                    r[b] = 1.0;
                    break;
                }
            }
            break;
        }
        case OP_JUMP_IF_NOT:
            if (!(r[a] != 0.0))
                pc = d;
            break;
        case OP_JUMP: pc = d; break;
        case OP_REFUSE_IF:
            if (r[a] != 0.0)
                goto done;
            break;
        case OP_FINITE_ALL: {
            int j;
            for (j = 0; j < b; j++)
                if (!isfinite(r[self->extra[a + j]]))
                    goto done;
            break;
        }
        case OP_CHECK_LENGTH:
            if (b >= PyList_GET_SIZE(lists[a]))
                goto done;
            break;
        case OP_CHECK_FLOAT:  /* (a float's subclass might subtract otherwise: left to the Python function) */
            if (b >= PyList_GET_SIZE(lists[a]) || !PyFloat_CheckExact(PyList_GET_ITEM(lists[a], b)))
                goto done;
            break;
        case OP_WRITE: {
            PyObject *value, *old;
            if (b >= PyList_GET_SIZE(lists[a])) {  /* set_scalar's Python code shortened it */
                PyErr_SetString(PyExc_RuntimeError, "an array changed while a recorded path wrote it");
                result = -1;
                goto done;
            }
            value = PyFloat_FromDouble(r[d]);
            if (value == NULL) {
                result = -1;
                goto done;
            }
            old = PyList_GET_ITEM(lists[a], b);
            PyList_SET_ITEM(lists[a], b, value);
            Py_DECREF(old);
            break;
        }
        case OP_SET_SCALAR: {
            PyObject *value = PyFloat_FromDouble(r[d]), *answer;
            if (value == NULL) {
                result = -1;
                goto done;
            }
            answer = PyObject_CallMethodObjArgs(m, attr_set_scalar, PyTuple_GET_ITEM(self->scalars, a), value, NULL);
            Py_DECREF(value);
            if (answer == NULL) {
                result = -1;
                goto done;
            }
            Py_DECREF(answer);
            break;
        }
        default:
            goto done;  /* cannot happen: checked when made */
        }
    }
    result = 1;
done:
    for (k = 0; k < held; k++)
        Py_DECREF(lists[k]);
    Py_XDECREF(scalars_dict);
    Py_DECREF(arrays_dict);
    return result;
}

static int load(PathObject *self);

static PyObject *
path_call(PathObject *self, PyObject *args, PyObject *kwargs)
{
    PyObject *m;
    int done;
    if (kwargs != NULL && PyDict_GET_SIZE(kwargs)) {
        PyErr_SetString(PyExc_TypeError, "a recorded path takes the machine alone");
        return NULL;
    }
    if (!PyArg_UnpackTuple(args, "path", 1, 1, &m))
        return NULL;
    if (self->state == WARMING) {
        if (self->warm > 0) {
            self->warm--;
            return PyObject_CallOneArg(self->fallback, m);
        }
        int loaded = load(self);
        if (loaded == -2)
            return NULL;  /* a KeyboardInterrupt during the translation: raised; translated at a later call */
        self->state = loaded == 0 ? RUNNING : PLAIN;
        Py_CLEAR(self->translate);
    }
    if (self->state != RUNNING || self->busy)
        return PyObject_CallOneArg(self->fallback, m);
    self->busy = 1;
    done = run(self, m);
    self->busy = 0;
    if (done < 0)
        return NULL;
    if (done) {
        self->runs++;
        Py_RETURN_NONE;
    }
    self->refused++;
    return PyObject_CallOneArg(self->fallback, m);
}

/* An int of a sequence (the program's parts), -1 with an error set where it is none. */
static int
small_int(PyObject *item, long below)
{
    long value = PyLong_Check(item) ? PyLong_AsLong(item) : -1;
    if (value == -1 && PyErr_Occurred())
        return -1;
    if (value < 0 || value >= below) {
        PyErr_SetString(PyExc_ValueError, "a recorded path's program names a part it does not have");
        return -1;
    }
    return (int)value;
}

/* The registers each operation writes (its destination d: 0, 1 or 2) and reads as a, b
   (0: not a register, 1: a float, 2: a complex pair). */
static const signed char SHAPE[OP_COUNT][3] = {
    [OP_READ] = {1, 0, 0}, [OP_SCALAR] = {1, 0, 0}, [OP_MOVE] = {1, 1, 0}, [OP_MOVE2] = {2, 2, 0},
    [OP_ADD] = {1, 1, 1}, [OP_SUB] = {1, 1, 1}, [OP_MUL] = {1, 1, 1}, [OP_DIV] = {1, 1, 1}, [OP_MOD] = {1, 1, 1},
    [OP_NEG] = {1, 1, 0}, [OP_ABS] = {1, 1, 0}, [OP_SQUARE] = {1, 1, 0},
    [OP_CADD] = {2, 2, 2}, [OP_CSUB] = {2, 2, 2}, [OP_CMUL] = {2, 2, 2}, [OP_CDIV] = {2, 2, 2},
    [OP_CNEG] = {2, 2, 0}, [OP_CABS] = {1, 2, 0}, [OP_FLOAT2C] = {2, 1, 0},
    [OP_LT] = {1, 1, 1}, [OP_LE] = {1, 1, 1}, [OP_GT] = {1, 1, 1}, [OP_GE] = {1, 1, 1}, [OP_EQ] = {1, 1, 1},
    [OP_NE] = {1, 1, 1}, [OP_CEQ] = {1, 2, 2}, [OP_CNE] = {1, 2, 2},
    [OP_TRUTH] = {1, 1, 0}, [OP_NOT] = {1, 1, 0}, [OP_AND] = {1, 1, 1}, [OP_OR] = {1, 1, 1},
    [OP_SQRT] = {1, 1, 0}, [OP_COS] = {1, 1, 0}, [OP_SIN] = {1, 1, 0}, [OP_ATAN] = {1, 1, 0},
    [OP_ATAN2] = {1, 1, 1}, [OP_ISFINITE] = {1, 1, 0}, [OP_ULP] = {1, 1, 0}, [OP_UNIT_EXACT] = {1, 1, 0},
    [OP_RECT] = {2, 1, 1}, [OP_QUADRANT] = {2, 1, 1},
    [OP_JUMP_IF_NOT] = {0, 1, 0}, [OP_JUMP] = {0, 0, 0}, [OP_REFUSE_IF] = {0, 1, 0},
    [OP_FINITE_ALL] = {0, 0, 0}, [OP_CHECK_LENGTH] = {0, 0, 0}, [OP_CHECK_FLOAT] = {0, 0, 0},
    [OP_WRITE] = {0, 0, 0}, [OP_SET_SCALAR] = {0, 0, 0},
};

static int
register_fits(int index, int width, Py_ssize_t count)
{
    return width == 0 || (index >= 0 && index + width <= count);
}

/* Check every instruction's parts against the program's sizes: 0 good, -1 (an error set) not. */
static int
check_program(PathObject *self)
{
    Py_ssize_t k, narrays = PyTuple_GET_SIZE(self->arrays), nscalars = PyTuple_GET_SIZE(self->scalars);
    self->first_write = self->length;
    for (k = 0; k < self->length; k++) {
        int op = self->code[k * WIDTH];
        if (op == OP_WRITE || op == OP_SET_SCALAR) {
            if (self->first_write == self->length)
                self->first_write = k;
        }
        else if (self->first_write < self->length) {
            PyErr_Format(PyExc_ValueError, "a recorded path's program computes after a write (instruction %zd)", k);
            return -1;
        }
    }
    for (k = 0; k < self->length; k++) {
        const int *at = self->code + k * WIDTH;
        int op = at[0], d = at[1], a = at[2], b = at[3], good = 1;
        if (op < 0 || op >= OP_COUNT)
            good = 0;
        else {
            const signed char *shape = SHAPE[op];
            good = register_fits(d, shape[0], self->register_count) && register_fits(a, shape[1], self->register_count)
                   && register_fits(b, shape[2], self->register_count);
            switch (op) {
            case OP_READ: case OP_CHECK_LENGTH: case OP_CHECK_FLOAT:
                good = good && a >= 0 && a < narrays && b >= 0;
                break;
            case OP_WRITE:
                good = good && a >= 0 && a < narrays && b >= 0 && register_fits(d, 1, self->register_count);
                break;
            case OP_SCALAR:
                good = good && a >= 0 && a < nscalars;
                break;
            case OP_SET_SCALAR:
                good = good && a >= 0 && a < nscalars && register_fits(d, 1, self->register_count);
                break;
            case OP_JUMP: case OP_JUMP_IF_NOT:  /* forward only (every run ends), never past a write */
                good = good && d > k && d <= self->first_write;
                break;
            case OP_FINITE_ALL: {
                int j;
                good = a >= 0 && b >= 0 && (Py_ssize_t)a + b <= self->extra_length;
                for (j = 0; good && j < b; j++)
                    good = register_fits(self->extra[a + j], 1, self->register_count);
                break;
            }
            default:
                break;
            }
        }
        if (!good) {
            PyErr_Format(PyExc_ValueError, "a recorded path's program is damaged at instruction %zd", k);
            return -1;
        }
    }
    return 0;
}

/* One part's item as an int below a bound (fill's ``ints``) or a double (``ints`` NULL): 0, or -1
   with an error set. */
static int
item_of(PyObject *item, long below, int *ints, double *doubles)
{
    if (ints != NULL) {
        int value = small_int(item, below);
        if (value < 0)
            return -1;
        *ints = value;
        return 0;
    }
    if (!PyFloat_CheckExact(item)) {
        PyErr_SetString(PyExc_TypeError, "a recorded path's numbers must be floats");
        return -1;
    }
    *doubles = PyFloat_AS_DOUBLE(item);
    return 0;
}

/* A part of a program, a sequence, as a new array of ints (``ints``, each below ``below``) or of
   doubles (``doubles``): 0, or -1 with an error set. */
static int
fill(PyObject *sequence, int **ints, double **doubles, Py_ssize_t *count, long below)
{
    Py_ssize_t k, n;
    void *out;
    PyObject *fast = PySequence_Fast(sequence, "a recorded path's program part must be a sequence");
    if (fast == NULL)
        return -1;
    n = PySequence_Fast_GET_SIZE(fast);
    out = PyMem_Calloc(n ? n : 1, ints != NULL ? sizeof(int) : sizeof(double));
    if (out == NULL) {
        Py_DECREF(fast);
        PyErr_NoMemory();
        return -1;
    }
    if (ints != NULL)
        *ints = out;
    else
        *doubles = out;
    for (k = 0; k < n; k++) {
        if (item_of(PySequence_Fast_GET_ITEM(fast, k), below, ints != NULL ? (int *)out + k : NULL,
                    ints != NULL ? NULL : (double *)out + k) < 0) {
            Py_DECREF(fast);
            return -1;
        }
    }
    *count = n;
    Py_DECREF(fast);
    return 0;
}

static int
names_tuple(PyObject *value, PyObject **out)
{
    Py_ssize_t k;
    if (!PyTuple_CheckExact(value)) {
        PyErr_SetString(PyExc_TypeError, "a recorded path's names must be a tuple");
        return -1;
    }
    for (k = 0; k < PyTuple_GET_SIZE(value); k++) {
        if (!PyUnicode_CheckExact(PyTuple_GET_ITEM(value, k))) {
            PyErr_SetString(PyExc_TypeError, "a recorded path's names must be strings");
            return -1;
        }
    }
    Py_INCREF(value);
    Py_XSETREF(*out, value);
    return 0;
}

/* The program the translation gives, checked as a whole: 0 loaded, -1 none (no program, or a
   damaged one: the fallback runs every call; the error is cleared), -2 the translation was
   interrupted (KeyboardInterrupt and the like stay raised). */
static int
load(PathObject *self)
{
    PyObject *parts = PyObject_CallNoArgs(self->translate);
    Py_ssize_t code_ints;
    int plain_numbers;
    static const char *keys[] = {"code", "extra", "registers", "arrays", "scalars", "quadrants", "plain_numbers"};
    PyObject *values[7];
    int k;
    PyMem_Free(self->code);  /* (a translation interrupted before may have filled some) */
    PyMem_Free(self->extra);
    PyMem_Free(self->registers);
    PyMem_Free(self->quadrants);
    self->code = self->extra = NULL;
    self->registers = self->quadrants = NULL;
    if (parts == NULL || parts == Py_None || !PyDict_Check(parts))
        goto fail;
    for (k = 0; k < 7; k++) {
        values[k] = PyDict_GetItemString(parts, keys[k]);
        if (values[k] == NULL)
            goto fail;
    }
    plain_numbers = PyObject_IsTrue(values[6]);
    if (plain_numbers < 0)
        goto fail;
    self->plain_numbers = plain_numbers;
    if (fill(values[0], &self->code, NULL, &code_ints, 1L << 30) < 0
        || fill(values[1], &self->extra, NULL, &self->extra_length, 1L << 30) < 0
        || fill(values[2], NULL, &self->registers, &self->register_count, 0) < 0
        || names_tuple(values[3], &self->arrays) < 0 || names_tuple(values[4], &self->scalars) < 0
        || fill(values[5], NULL, &self->quadrants, &self->quadrant_count, 0) < 0)
        goto fail;
    if (code_ints % WIDTH || self->quadrant_count % 3 || PyTuple_GET_SIZE(self->arrays) > ARRAYS) {
        PyErr_SetString(PyExc_ValueError, "a recorded path's program has a part of the wrong size");
        goto fail;
    }
    self->length = code_ints / WIDTH;
    self->quadrant_count /= 3;
    if (check_program(self) < 0)
        goto fail;
    Py_DECREF(parts);
    return 0;
fail:
    Py_XDECREF(parts);
    if (PyErr_Occurred() && !PyErr_ExceptionMatches(PyExc_Exception))
        return -2;  /* KeyboardInterrupt, SystemExit: not the translation's failure, the caller's to raise */
    if (PyErr_Occurred()) {
        /* kept for the tests (Path.error); a run goes on with the fallback */
        PyObject *type, *value, *traceback;
        PyErr_Fetch(&type, &value, &traceback);
        Py_XDECREF(type);
        Py_XDECREF(traceback);
        Py_XSETREF(self->error, value);
    }
    return -1;
}

/* Path(fallback, translate, warm) */
static PyObject *
path_new(PyTypeObject *type, PyObject *args, PyObject *kwargs)
{
    PyObject *fallback, *translate;
    Py_ssize_t warm;
    PathObject *self;
    static char *keywords[] = {"fallback", "translate", "warm", NULL};
    if (!PyArg_ParseTupleAndKeywords(args, kwargs, "OOn:Path", keywords, &fallback, &translate, &warm))
        return NULL;
    if (!PyCallable_Check(fallback) || !PyCallable_Check(translate)) {
        PyErr_SetString(PyExc_TypeError, "a recorded path's fallback and translation must be callable");
        return NULL;
    }
    self = (PathObject *)type->tp_alloc(type, 0);
    if (self == NULL)
        return NULL;
    Py_INCREF(fallback);
    self->fallback = fallback;
    Py_INCREF(translate);
    self->translate = translate;
    self->warm = warm < 0 ? 0 : warm;
    self->state = WARMING;
    self->arrays = PyTuple_New(0);
    self->scalars = PyTuple_New(0);
    if (self->arrays == NULL || self->scalars == NULL) {
        Py_DECREF(self);
        return NULL;
    }
    return (PyObject *)self;
}

static PyObject *
path_get_fallback(PathObject *self, void *closure)
{
    Py_INCREF(self->fallback);
    return self->fallback;
}

static PyObject *
path_get_counts(PathObject *self, void *closure)
{
    return Py_BuildValue("(nn)", self->runs, self->refused);
}

static PyObject *
path_get_state(PathObject *self, void *closure)
{
    static const char *names[] = {"warming", "running", "plain"};
    return PyUnicode_FromString(names[self->state]);
}

static PyObject *
path_get_error(PathObject *self, void *closure)
{
    PyObject *error = self->error ? self->error : Py_None;
    Py_INCREF(error);
    return error;
}

static PyGetSetDef path_getset[] = {
    {"state", (getter)path_get_state, NULL, "warming, running (its program) or plain (the fallback alone)", NULL},
    {"error", (getter)path_get_error, NULL, "why its program was refused, or None", NULL},
    {"fallback", (getter)path_get_fallback, NULL, "the path's Python function", NULL},
    {"counts", (getter)path_get_counts, NULL, "(runs done here, runs left to the Python function)", NULL},
    {NULL},
};

static PyTypeObject PathType = {
    PyVarObject_HEAD_INIT(NULL, 0)
    .tp_name = "yaseer.linkages._straight_fast.Path",
    .tp_basicsize = sizeof(PathObject),
    .tp_dealloc = (destructor)path_dealloc,
    .tp_call = (ternaryfunc)path_call,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A recorded path run as a program of double operations (see the module's source).",
    .tp_new = path_new,
    .tp_getset = path_getset,
};

static struct PyModuleDef module = {
    PyModuleDef_HEAD_INIT, "_straight_fast", "Recorded paths run as programs of double operations.", -1, NULL,
};

PyMODINIT_FUNC
PyInit__straight_fast(void)
{
    PyObject *m;
    if (PyType_Ready(&PathType) < 0)
        return NULL;
    attr_arrays = PyUnicode_InternFromString("arrays");
    attr_scalars = PyUnicode_InternFromString("scalars");
    attr_dialect = PyUnicode_InternFromString("dialect");
    attr_typed_numbers = PyUnicode_InternFromString("typed_numbers");
    attr_set_scalar = PyUnicode_InternFromString("set_scalar");
    if (!attr_arrays || !attr_scalars || !attr_dialect || !attr_typed_numbers || !attr_set_scalar)
        return NULL;
    m = PyModule_Create(&module);
    if (m == NULL)
        return NULL;
    Py_INCREF(&PathType);
    if (PyModule_AddObject(m, "Path", (PyObject *)&PathType) < 0
        || PyModule_AddIntConstant(m, "WIDTH", WIDTH) < 0 || PyModule_AddIntConstant(m, "ARRAYS", ARRAYS) < 0) {
        Py_DECREF(m);
        return NULL;
    }
    {
        static const char *names[OP_COUNT] = {
            "READ", "SCALAR", "MOVE", "MOVE2", "ADD", "SUB", "MUL", "DIV", "MOD", "NEG", "ABS", "SQUARE",
            "CADD", "CSUB", "CMUL", "CDIV", "CNEG", "CABS", "FLOAT2C", "LT", "LE", "GT", "GE", "EQ", "NE",
            "CEQ", "CNE", "TRUTH", "NOT", "AND", "OR", "SQRT", "COS", "SIN", "ATAN", "ATAN2", "ISFINITE",
            "ULP", "UNIT_EXACT", "RECT", "QUADRANT", "JUMP_IF_NOT", "JUMP", "REFUSE_IF", "FINITE_ALL",
            "CHECK_LENGTH", "CHECK_FLOAT", "WRITE", "SET_SCALAR",
        };
        PyObject *ops = PyDict_New();
        int k;
        if (ops == NULL) {
            Py_DECREF(m);
            return NULL;
        }
        for (k = 0; k < OP_COUNT; k++) {
            PyObject *number = PyLong_FromLong(k);
            if (number == NULL || PyDict_SetItemString(ops, names[k], number) < 0) {
                Py_XDECREF(number);
                Py_DECREF(ops);
                Py_DECREF(m);
                return NULL;
            }
            Py_DECREF(number);
        }
        if (PyModule_AddObject(m, "OPERATIONS", ops) < 0) {
            Py_DECREF(ops);
            Py_DECREF(m);
            return NULL;
        }
    }
    return m;
}
