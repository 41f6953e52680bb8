"""Record one scalar run of the linkage formulas as straight-line Python.

A ``GOSUB PROG n`` call runs the linkage code on Python numbers
(:data:`numerics.SCALAR`): named tuples, dataclasses, the force solver's forms
and plan, and a few hundred arithmetic operations.  The objects around the
arithmetic cost more than the arithmetic.  A :class:`Recorder` runs the same
code once on :class:`Traced` numbers, each holding its concrete value and a
variable name: every operation computes its value as usual and appends one line
``t12 = t7 * t3`` to the record; every decision the code takes on a traced value
(``if``, ``bool``) appends a *guard* that re-checks it.  The record compiles to
one function of the inputs whose results are exactly those of the scalar run
(the same operations on the same values in the same order), valid as long as
every guard holds: a guard that fails raises :class:`Retrace`, and the caller
runs the code again (recording a second variant).  The formulas are written
once; this only removes the objects around them.

A value the code would turn into a plain number (``float(t)``, ``int(t)``, a
dictionary key) cannot be recorded: :class:`NotTraceable`, and the caller runs
the plain scalar code instead.
"""

from __future__ import annotations

import cmath
import math
from types import SimpleNamespace

from yaseer.linkages import numerics


class Retrace(Exception):
    """A guard of a recorded function failed: these inputs take another path."""


class NotTraceable(Exception):
    """The code needed a traced value as a plain number (or asked not to be recorded)."""


_LITERALS = (bool, int, float, complex)


class Recorder:
    """The lines of one recording, the names it calls, and its inputs."""

    def __init__(self):
        self.lines: list[str] = []
        self.names: dict[str, object] = {"_Retrace": Retrace}
        self._count = 0
        self._known: dict[str, Traced] = {}  # expression -> the value that holds it (computed once)

    def operand(self, value) -> str:
        """The Python text of ``value`` in the record (a variable or a literal)."""
        if isinstance(value, Traced):
            return value.name
        if isinstance(value, _LITERALS) and (value == value) and abs(value) != math.inf:
            return repr(value)
        name = f"_k{len(self.names)}"  # inf, nan: bound by name
        self.names[name] = value
        return name

    def emit(self, value, expression: str) -> "Traced":
        """A traced value ``value`` computed by ``expression`` (an expression met
        before gives the value computed then: every expression is pure)."""
        known = self._known.get(expression)
        if known is not None:
            return known
        name = f"t{self._count}"
        self._count += 1
        self.lines.append(f"{name} = {expression}")
        traced = self._known[expression] = Traced(self, value, name)
        return traced

    def function(self, name: str, function) -> str:
        """Bind ``function`` under ``name`` in the compiled record."""
        self.names.setdefault(name, function)
        return name

    def guard(self, traced: "Traced", truth: bool) -> None:
        """Re-check at run time that ``traced`` is ``truth``."""
        self.lines.append(f"if {'not ' if truth else ''}{traced.name}: raise _Retrace")

    def compile(self, epilogue: list[str], label: str):
        """The record as a function ``run(_M)`` (``_M``: what the recorded lines
        read their inputs from): the recorded lines, then ``epilogue``."""
        text = "def run(_M):\n" + "".join(f"    {line}\n" for line in self.lines + epilogue)
        namespace = dict(self.names, __builtins__={"float": float, "complex": complex, "len": len, "abs": abs,
                                                    "isinstance": isinstance, "list": list, "str": str})
        exec(compile(text, f"<traced {label}>", "exec"), namespace)
        return namespace["run"]


def _value(x):
    return x.value if isinstance(x, Traced) else x


# Operations whose result is the traced operand itself (equal as a number; only
# the sign of a zero may differ): x * 1, x / 1, x + 0, x - 0 (and 1 * x, 0 + x).
_IDENTITIES = {("*", 1.0), ("/", 1.0), ("+", 0.0), ("-", 0.0)}
_LEFT_IDENTITIES = {("*", 1.0), ("+", 0.0)}


def _binary(symbol: str, operation):
    def forward(self, other):
        if isinstance(other, (Traced, *_LITERALS)):
            value = operation(self.value, _value(other))
            if type(other) in (int, float) and (symbol, other) in _IDENTITIES:
                return self
            if symbol == "**" and type(other) in (int, float) and other == 2:
                return self.recorder.emit(value, f"{self.name} * {self.name}")
            return self.recorder.emit(value, f"{self.name} {symbol} {self.recorder.operand(other)}")
        return NotImplemented

    def backward(self, other):
        if isinstance(other, _LITERALS):
            value = operation(other, self.value)
            if type(other) in (int, float) and (symbol, other) in _LEFT_IDENTITIES:
                return self
            return self.recorder.emit(value, f"{self.recorder.operand(other)} {symbol} {self.name}")
        return NotImplemented

    return forward, backward


class Traced:
    """A number of a recording: its concrete value and its variable's name."""

    __slots__ = ("recorder", "value", "name")
    math_namespace: SimpleNamespace  # numerics.math_for picks it (set below)

    def __init__(self, recorder: Recorder, value, name: str):
        self.recorder, self.value, self.name = recorder, value, name

    __add__, __radd__ = _binary("+", lambda a, b: a + b)
    __sub__, __rsub__ = _binary("-", lambda a, b: a - b)
    __mul__, __rmul__ = _binary("*", lambda a, b: a * b)
    __truediv__, __rtruediv__ = _binary("/", lambda a, b: a / b)
    __mod__, __rmod__ = _binary("%", lambda a, b: a % b)
    __pow__, __rpow__ = _binary("**", lambda a, b: a ** b)
    __lt__, _ = _binary("<", lambda a, b: a < b)
    __le__, _ = _binary("<=", lambda a, b: a <= b)
    __gt__, _ = _binary(">", lambda a, b: a > b)
    __ge__, _ = _binary(">=", lambda a, b: a >= b)
    __eq__, _ = _binary("==", lambda a, b: a == b)
    __ne__, _ = _binary("!=", lambda a, b: a != b)
    __and__, __rand__ = _binary("&", lambda a, b: a & b)
    __or__, __ror__ = _binary("|", lambda a, b: a | b)
    __hash__ = None  # type: ignore[assignment]  # never a dictionary key

    def __neg__(self):
        return self.recorder.emit(-self.value, f"-{self.name}")

    def __pos__(self):
        return self

    def __abs__(self):
        return self.recorder.emit(abs(self.value), f"abs({self.name})")

    @property
    def real(self):
        return self.recorder.emit(self.value.real, f"{self.name}.real")

    @property
    def imag(self):
        return self.recorder.emit(self.value.imag, f"{self.name}.imag")

    def __bool__(self) -> bool:
        truth = bool(self.value)
        self.recorder.guard(self, truth)
        return truth

    def _refuse(self, *_):
        raise NotTraceable(f"a traced value used as a plain number ({self.name})")

    __float__ = __int__ = __complex__ = __index__ = _refuse

    def __repr__(self) -> str:
        return f"Traced({self.name}={self.value!r})"


def _call(name: str, function):
    """``function`` (of :data:`numerics.SCALAR`) recorded as a call when an argument is traced."""

    def call(*args):
        if not any(isinstance(arg, Traced) for arg in args):
            return function(*args)
        recorder = next(arg.recorder for arg in args if isinstance(arg, Traced))
        value = function(*(_value(arg) for arg in args))
        callee = recorder.function(f"_{name}", function)
        return recorder.emit(value, f"{callee}({', '.join(recorder.operand(arg) for arg in args)})")

    return call


def _where(condition, yes, no):
    if not isinstance(condition, Traced):
        return yes if condition else no
    recorder = condition.recorder
    value = _value(yes) if condition.value else _value(no)
    return recorder.emit(value, f"({recorder.operand(yes)} if {condition.name} else {recorder.operand(no)})")


def _as(kind):
    def convert(value):
        if not isinstance(value, Traced):
            return kind(value)
        if isinstance(value.value, kind):
            return value
        return value.recorder.emit(kind(value.value), f"{kind.__name__}({value.name})")

    return convert


def _zero_like(value):
    return 0j if isinstance(_value(value), complex) else 0.0


_S = numerics.SCALAR

#: The :mod:`numerics` namespace of a recording.
TRACE = SimpleNamespace(
    scalar=True, pi=math.pi, float=_as(float), complex=_as(complex),
    **{name: _call(name, getattr(_S, name)) for name in
       ("sqrt", "cos", "sin", "arctan", "radians", "degrees", "angle", "unit", "unit_degrees", "isfinite")},
    exp=_call("exp", cmath.exp), maximum=_call("max", max),
    where=_where, any=lambda value: value, all=lambda value: value, real=lambda value: value.real,
    imag=lambda value: value.imag, zeros_like=_zero_like, ones_like=lambda value: 1.0,
)
Traced.math_namespace = TRACE
