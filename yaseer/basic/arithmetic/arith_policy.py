"""What a division by zero or an overflow does: the dialect's run-time error policy.

``Dialect.on_division_by_zero`` and ``Dialect.on_overflow`` are ``"stop"`` (the
Casio: the run stops with the error, which ON ERROR may trap) or ``"continue"``
(GW-BASIC): unless ON ERROR is set, the message (``Division by zero`` or
``Overflow``) is printed where the cursor is, followed by a line end, and the
operation's result is the largest number of its type with the right sign, so the
program goes on.  With ON ERROR set the error is trapped as any other.

Microsoft's source, MATH1.ASM: ``$DIV0S``/``$OVFLS`` call ``DOINF`` (the signed
largest value: ``$INFPD``/``$INFMD``, positive for zero to a negative power) and
then ``DV010``, which traps through ``TRAPER`` when ON ERROR is set and else
prints the message with ``$STPRN`` and a carriage return and line feed.

:class:`ArithmeticPolicy` holds the machine-side half; :func:`helpers` gives the
compiled code's ``/`` and the wrapped ``\\``, ``MOD``, ``^`` and ``EXP`` of a
dialect whose policy continues.  :func:`gw_routines` is the table of GW-BASIC's
single-precision SIN, COS, TAN, ATN, LOG, EXP and ``^``: the optional C accelerator's
where it is built (the same values, bit for bit), else gw_transcendental's.
"""

from __future__ import annotations

from yaseer.accelerators import PURE_PYTHON, pure_python  # noqa: F401  (the switch of every accelerator)
from yaseer.basic.errors import BasicError, DIVISION_BY_ZERO, OVERFLOW
from yaseer.basic.arithmetic import values
from yaseer.basic.arithmetic.values import DOUBLE_LARGEST, SINGLE_LARGEST

# The largest values of Microsoft Binary Format (exponent byte 255, mantissa all ones):
# single (1 - 2**-24) * 2**127 = 1.701412E+38; double (1 - 2**-56) * 2**127, whose
# nearest Python float is 2**127 (printed 1.701411834604692D+38, as GW-BASIC does).
LARGEST = {"!": SINGLE_LARGEST, "#": DOUBLE_LARGEST}
MESSAGES = {DIVISION_BY_ZERO: "Division by zero", OVERFLOW: "Overflow"}


class ArithmeticPolicy:
    """The run-time half of the policy: ``machine`` gives the dialect, ON ERROR and the screen."""

    def __init__(self, machine):
        self.machine = machine

    def result(self, code: int, negative: bool = False, kind: str = "!") -> float:
        """The value an operation that failed with ``code`` gives, or the raised error."""
        machine = self.machine
        dialect = machine.dialect
        policy = dialect.on_division_by_zero if code == DIVISION_BY_ZERO else dialect.on_overflow
        if policy != "continue" or machine.on_error is not None:
            raise BasicError(MESSAGES[code], code)
        if not machine.csv:
            machine.screen.write(MESSAGES[code])
            machine.screen.new_row()
        largest = LARGEST.get(kind, LARGEST["!"])
        return -largest if negative else largest

    def overflowed(self, value, kind: str = "!") -> float:
        """A stored or printed value beyond the number range (infinite or not a number)."""
        return self.result(OVERFLOW, value < 0, kind)


def helpers(policy: ArithmeticPolicy, int_divide, int_modulo, power) -> dict:
    """The compiled code's helpers for a typed dialect: ``_dk`` (a double ``+ - *``
    result, or VAL's, kept in MBF's range: beyond it the policy's value), the single
    routines the compiled code's fast paths fall back on (``_sadd _ssub _sp _smul _sfd
    _csng _sfn``: an overflow goes to the policy at that operation), ``_dv`` and
    ``_ddv`` (single and double ``/``), ``_spow`` (``^``, single precision), and
    ``\\`` ``MOD`` ``^`` that give the policy's value instead of failing, and the
    transcendental functions (:func:`transcendental_functions`).  (A
    ``\\`` or ``MOD`` by zero gives a single 1.701412E+38 with the dividend's sign, as
    PC-BASIC 2.0.8 shows.)"""
    from yaseer.basic.arithmetic import single_arith
    result = policy.result
    transcendental = transcendental_functions(policy)
    gw_power = gw_routines()["power"]

    def single_overflow(negative: bool) -> float:
        return result(OVERFLOW, negative, "!")

    # Each single routine calls $OVFLS itself (MATH1.ASM): the message comes at the
    # operation, and the next operation works on the signed largest single (or the error
    # is trapped there).  The inline fast paths only give results inside the range; these
    # are the slow paths they hand everything else to.  (``_spb``, a product rounded
    # toward zero from a single in the range, cannot leave it.)
    def checked(operation):
        """A one-operand single routine whose result beyond MBF's range is the policy's."""
        def run(x):
            r = operation(x)
            return r if r - r == 0 else single_overflow(r < 0)
        return run

    def checked2(operation):
        """The same for a two-operand routine."""
        def run(a, b):
            r = operation(a, b)
            return r if r - r == 0 else single_overflow(r < 0)
        return run

    def single_divide(a, b):
        """``/`` of singles (``$FDIVS``): by zero ``$DIV0S``, beyond the range ``$OVFLS``."""
        try:
            r = single_arith.divide(a, b)
        except ZeroDivisionError:
            return result(DIVISION_BY_ZERO, a < 0, "!")
        return r if r - r == 0 else single_overflow(r < 0)

    def double(x):
        if -DOUBLE_LARGEST <= x <= DOUBLE_LARGEST:
            return x
        return result(OVERFLOW, x < 0, "#")

    # A double + - * / (values.double_operations: MATH1.ASM/MATH2.ASM's $FADDD, $FMULD,
    # $FDIVD on the 56-bit mantissas), beyond the range or by 0 the policy's value.
    double_add, double_subtract, double_multiply, double_divide = values.double_operations(
        lambda negative: result(OVERFLOW, negative, "#"), lambda a: result(DIVISION_BY_ZERO, a < 0, "#"))

    def divider(quotient, kind: str):
        """``/`` of the type ``kind`` (``"!"`` or ``"#"``) by ``quotient(a, b)``."""
        def divide(a, b):
            try:
                return quotient(a, b)
            except ZeroDivisionError:
                return result(DIVISION_BY_ZERO, a < 0, kind)
        return divide

    def single_power(a, b):
        """``a ^ b`` of two singles as GW-BASIC's ``$FPWR``: an integral exponent
        multiplies (single_arith.py), any other is EXP(b * LOG(a)) as GW computes them
        (gw_transcendental.py)."""
        if single_arith.is_integral_power(b):
            try:
                return single_arith.power_by_integer(a, b, single_overflow)
            except ZeroDivisionError:
                return result(DIVISION_BY_ZERO, False, "!")  # zero to a negative power: positive
        try:
            return gw_power(a, b, single_overflow)
        except ZeroDivisionError:
            return result(DIVISION_BY_ZERO, False, "!")

    def by_integer(operation):
        """``\\`` or MOD: a division by zero gives the policy's value."""
        def run(a, b):
            try:
                return operation(a, b)
            except BasicError as err:
                if err.code != DIVISION_BY_ZERO:
                    raise
                return result(DIVISION_BY_ZERO, a < 0, "!")
        return run

    largest = DOUBLE_LARGEST  # GW-BASIC's doubles end where its singles do

    def raise_to(a, b):
        try:
            r = power(a, b)
            if -largest <= r <= largest or r != r:
                return r
            return result(OVERFLOW, r < 0, "!")
        except BasicError as err:
            if err.code != DIVISION_BY_ZERO:
                raise
            return result(DIVISION_BY_ZERO, False, "!")  # zero to a negative power: positive
        except OverflowError:
            return result(OVERFLOW, a < 0 and float(b).is_integer() and int(b) % 2 == 1, "!")

    singles = {"_sadd": checked2(single_arith.add), "_ssub": checked2(single_arith.subtract),
               "_sp": checked(single_arith.product),
               "_smul": checked2(single_arith.multiply), "_sfd": checked(values.single_of_double),
               "_csng": checked(values.single_of_double), "_sfn": checked(single_arith.function_result)}
    return {**singles, "_dk": double, "_dv": single_divide, "_ddv": double_divide,
            "_dad": double_add, "_dsb": double_subtract, "_dml": double_multiply,
            "_idiv": by_integer(int_divide), "_mod": by_integer(int_modulo), "_pow": raise_to,
            "_spow": single_power, **transcendental}


def transcendental_functions(policy: ArithmeticPolicy) -> dict:
    """The compiled code's ``_sin _cos _tan _atn _log _exp`` for a typed dialect:
    GW-BASIC's single-precision routines step by step (:func:`gw_routines`), an
    overflow (EXP) or a TAN whose cosine is 0 through the policy."""
    routines = gw_routines()
    result = policy.result
    gw_exp, gw_tan, gw_sin = routines["exp"], routines["tan"], routines["sin"]

    def exp(x):
        return gw_exp(x, lambda negative: result(OVERFLOW, negative, "!"))

    def tan(x):
        try:
            return gw_tan(x)
        except ZeroDivisionError:  # $FDIVS by 0: the infinity has the sine's sign
            return result(DIVISION_BY_ZERO, gw_sin(x) < 0, "!")

    return {"_sin": gw_sin, "_cos": routines["cos"], "_tan": tan,
            "_atn": routines["atn"], "_log": routines["log"], "_exp": exp}


GW_ROUTINES = ("sin", "cos", "tan", "atn", "log", "exp", "power")
"""gw_transcendental's functions that the C accelerator (``_mbf_fast``) computes too."""



def gw_routines() -> dict:
    """GW-BASIC's single-precision routines by name (:data:`GW_ROUTINES`; ``exp`` and
    ``power`` take the overflow handler gw_transcendental's take): the C accelerator's
    when it was built (setup.py; an optional extension) and :data:`PURE_PYTHON` is not
    set, else gw_transcendental's.  Each C routine computes the Python function's value
    bit for bit (tests/test_mbf_fast.py) and hands every unusual call (an error, an
    overflow, an argument that is not a single in MBF's range) to that Python function,
    so the errors are the Python module's own."""
    from yaseer.basic.arithmetic import gw_transcendental

    python = {name: getattr(gw_transcendental, name) for name in GW_ROUTINES}
    if pure_python():
        return python
    try:
        from yaseer.basic.arithmetic import _mbf_fast
    except ImportError:  # not built (no C compiler where yaseer was installed)
        return python
    return {name: _mbf_fast.bound(name, function) for name, function in python.items()}
