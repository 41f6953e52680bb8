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
import re
from types import SimpleNamespace

from yaseer.linkages import numerics


class Retrace(Exception):
    """A guard of a recorded function failed: these inputs take another path."""


class NotTraceable(Exception):
    """The code needed a traced value as a plain number (or asked not to be recorded)."""


_LITERALS = (bool, int, float, complex)


class Guard:
    """A guard line of a recording (``if ...: raise _Retrace``) and, when its test
    reads nothing but inputs, ``key``: the Python text of what it tests (a call
    can then be matched to the path it takes before running one,
    :mod:`yaseer.linkages.recordings`)."""

    __slots__ = ("line", "key")

    def __init__(self, line: str, key: str | None = None):
        self.line, self.key = line, key

    def __str__(self) -> str:
        return self.line


def _spelled(value) -> bool:
    """Whether the text ``repr(value)`` compiles to ``value`` itself, signed zeros included: a
    complex number's does not always (``-1j`` is -(1j), whose real part is -0.0; ``(-0-1j)``
    is 0 - 1j, whose real part is 0.0)."""
    if type(value) is not complex:
        return True
    same = eval(compile(repr(value), "<literal>", "eval"), {"__builtins__": {}})
    return all(a == b and math.copysign(1.0, a) == math.copysign(1.0, b)
               for a, b in ((same.real, value.real), (same.imag, value.imag)))


class Recorder:
    """The lines of one recording, the names it calls, and its inputs."""

    def __init__(self):
        self.lines: list[str | Guard] = []
        self.names: dict[str, object] = {"_Retrace": Retrace}
        self._count = 0
        self._known: dict[str, Traced] = {}  # expression -> the value that holds it (computed once)
        self._constants: dict[tuple, str] = {}  # a number bound by name -> its name

    def operand(self, value) -> str:
        """The Python text of ``value`` in the record (a variable or a literal)."""
        if isinstance(value, Traced):
            return value.name
        if isinstance(value, _LITERALS) and (value == value) and abs(value) != math.inf and _spelled(value):
            return repr(value)
        # inf, nan, a complex its text does not give: bound by name, one name a number (so that
        # the same operation on it is recorded once)
        key = (type(value), *(part.hex() if isinstance(part, float) else repr(part)
                              for part in ((value.real, value.imag) if isinstance(value, complex) else (value,))))
        name = self._constants.get(key)
        if name is None:
            name = self._constants[key] = f"_k{len(self.names)}"
            self.names[name] = value
        return name

    def emit(self, value, expression: str, source: str | None = None) -> "Traced":
        """A traced value ``value`` computed by ``expression`` (an expression met
        before gives the value computed then: every expression is pure).
        ``source``: the same value as Python text reading inputs alone, where it is
        one (an input read, or an input compared with a literal)."""
        known = self._known.get(expression)
        if known is not None:
            return known
        name = f"t{self._count}"
        self._count += 1
        self.lines.append(f"{name} = {expression}")
        traced = self._known[expression] = Traced(self, value, name, source)
        return traced

    def read(self, value, expression: str) -> "Traced":
        """A traced input ``value`` read by ``expression`` (the recorded function's argument ``_M``)."""
        traced = self.emit(value, expression, expression)
        traced.leaf = True
        return traced

    def pin(self, subject: str, value) -> None:
        """Re-check at run time that the input ``subject`` (Python text) equals ``value``."""
        self.lines.append(Guard(f"if {subject} != {value!r}: raise _Retrace", subject))

    def at_most(self, subject: str, value) -> None:
        """Re-check at run time that the input ``subject`` (Python text) is at most ``value``."""
        self.lines.append(Guard(f"if {subject} > {value!r}: raise _Retrace", subject))

    def function(self, name: str, function) -> str:
        """Bind ``function`` under ``name`` in the compiled record."""
        self.names.setdefault(name, function)
        return name

    def guard(self, traced: "Traced", truth: bool) -> None:
        """Re-check at run time that ``traced`` is ``truth``."""
        key = f"bool({traced.source})" if traced.source is not None else None
        self.lines.append(Guard(f"if {'not ' if truth else ''}{traced.name}: raise _Retrace", key))

    def keys(self) -> tuple[str, ...]:
        """The tests of the guards that read inputs alone, in order (see :class:`Guard`)."""
        return tuple(dict.fromkeys(line.key for line in self.lines if isinstance(line, Guard) and line.key))

    def compile(self, epilogue: list[str], label: str, plain_numbers: bool = False):
        """The record as a function ``run(_M)`` (``_M``: what the recorded lines
        read their inputs from): the recorded lines, then ``epilogue``.

        ``plain_numbers``: the machine recorded on keeps no number of a float subclass with
        arithmetic of its own (its dialect has no ``typed_numbers``, or it has no dialect: gw's
        doubles are such numbers).  Its
        elements are then read as ``x - 0.0`` rather than ``float(x)``: the same float for a
        float (-0.0 and NaN too) and for an int or a bool, an OverflowError where ``float``
        raises one, in a third fewer instructions; a string, which ``float`` would parse, or a
        row raises TypeError, and the call is left to the plain code (Retrace).  Such a record
        refuses a machine whose numbers are typed (:func:`_batched_fetches`).

        The lines are compiled as recorded but for rewritings that keep every value
        and every guard: the reads of one array are made together where the first
        of them was (:func:`_batched_reads`), the arrays are looked up together at the
        start where they all exist (:func:`_batched_fetches`), runs of finiteness guards
        become one guard (:func:`_batched_finite_guards`), values nothing uses are not computed
        where computing them could raise nothing (:func:`_without_dead_lines`), a value
        used once is computed where it is used (:func:`_fused`), and the values share a
        few variables (:func:`_registers`: a frame of hundreds of locals costs every
        call its clearing).  The function's ``text`` is its Python text."""
        lines = _batched_finite_guards(_batched_reads(_float_parts(_once(self.lines) + epilogue, self.names),
                                                      _SUBTRACTED if plain_numbers else _CONVERTED))
        if plain_numbers:  # a scalar read as an element is (float() is a call)
            lines = [_SCALAR_READ.sub(r"\1 - 0.0", line) for line in lines]
        lines = _batched_fetches(_registers(_fused(_without_dead_lines(lines))), plain_numbers)
        # an element read of an array shorter than at the recording raises IndexError: these
        # inputs take another path (the plain code reads 0 beyond the dimension)
        refused = "(IndexError, TypeError)" if plain_numbers else "IndexError"
        text = ("def run(_M):\n  try:\n" + "".join("    " + line.replace("\n", "\n    ") + "\n" for line in lines)
                + f"  except {refused}:\n    raise _Retrace from None\n")
        names = namespace(self.names)
        exec(compile(text, f"<traced {label}>", "exec"), names)
        run = names["run"]
        run.text = text  # what straight_line translates (and the on-disk cache keeps)
        return run


# what a machine without a dialect (a stand-in with arrays and scalars alone) holds: plain numbers
_NO_DIALECT = SimpleNamespace(typed_numbers=False)


def namespace(names: dict) -> dict:
    """The globals of a compiled record: its ``names`` (:attr:`Recorder.names`), the few helpers
    every record may call and the only builtins it may (:mod:`yaseer.linkages.recording_cache`
    gives a stored record the same)."""
    return dict(names, _all=all, _map=map, _float=float, _no_dialect=_NO_DIALECT,
                __builtins__={"float": float, "complex": complex, "len": len, "abs": abs, "getattr": getattr,
                              "isinstance": isinstance, "list": list, "str": str,
                              "KeyError": KeyError, "IndexError": IndexError, "TypeError": TypeError,
                              "AttributeError": AttributeError})


def _once(lines: list) -> list[str]:
    """The recorded ``lines`` as text, a guard met before left out (values are never
    assigned twice: the same test of the same values, passed already)."""
    seen: set[str] = set()
    out = []
    for line in lines:
        text = str(line)
        if isinstance(line, Guard):
            if text in seen:
                continue
            seen.add(text)
        out.append(text)
    return out


_FLOAT, _COMPLEX = "float", "complex"
_TYPED = (  # what a recorded expression computes, whatever the values: its type from its operands'
    (r"float\(.*|abs\((t\d+)\)|_(?:sqrt|cos|sin|arctan|radians|degrees|atan2|ldexp)\(.*|\(_ulp\(.*"
     r"|(t\d+)\.(?:real|imag)",
     lambda kinds: _FLOAT if all(kind in (_FLOAT, _COMPLEX) for kind in kinds) else None),
    (r"(?:complex|_rect|_exp)\(.*|\(_quadrant\(.*", lambda kinds: _COMPLEX),
    # a power with a whole exponent: a float's is a float, a complex number's a complex number
    (r"(t\d+) \*\* \d+", lambda kinds: kinds[0] if kinds[0] in (_FLOAT, _COMPLEX) else None),
    (r"({0}) [-+*/%] ({0})|-({0})|\(({0}) if .* else ({0})\)".format(r"t\d+|_k\d+|-?[\d.]+(?:e[-+]?\d+)?j?|\([-\d.+e]+j\)"),
     lambda kinds: (None if None in kinds or not kinds else _COMPLEX if _COMPLEX in kinds else _FLOAT)),
)


def _kind(operand: str, kinds: dict):
    """The type of operand ``operand`` (a recorded value, a number bound by name or a literal),
    None when unknown."""
    if operand[0] in "t_":
        return kinds.get(operand)
    return _COMPLEX if operand.endswith("j") or operand.endswith("j)") else _FLOAT


def _float_parts(lines: list[str], names: dict) -> list[str]:
    """``lines`` without reading the parts of a value that is a float by the operations that
    made it (``x.real`` is ``x`` itself, ``x.imag`` is 0.0): the type of every value follows
    from its operation's operands' (an input is read as ``float(...)``); a power's depends on
    its values, and it and anything not listed in :data:`_TYPED` is of no known type."""
    patterns = [(re.compile(pattern + "$"), rule) for pattern, rule in _TYPED]
    kinds: dict[str, str | None] = {name: {float: _FLOAT, complex: _COMPLEX}.get(type(value))
                                    for name, value in names.items() if name.startswith("_k")}
    same: dict[str, str] = {}  # a float's part -> the text that is the same number
    out = []
    for line in lines:
        if same:
            line = _NAME.sub(lambda m: same.get(m.group(0), m.group(0)), line)
        found = _DEFINED.match(line)
        if not found or ", " in found.group(1):
            out.append(line)
            continue
        name, expression = found.groups()
        part = re.fullmatch(r"(t\d+)\.(real|imag)", expression)
        if part and kinds.get(part.group(1)) == _FLOAT:
            same[name], kinds[name] = (part.group(1) if part.group(2) == "real" else "0.0"), _FLOAT
            continue
        kinds[name] = None
        for pattern, rule in patterns:
            typed = pattern.match(expression)
            if typed:
                kinds[name] = rule([_kind(operand, kinds) for operand in typed.groups() if operand])
                break
        out.append(line)
    return out


class _Pattern:
    """A regular expression compiled at its first use: a run whose paths are all kept on disk
    (:mod:`yaseer.linkages.recording_cache`) records nothing and never needs one (compiling
    these cost every start that called a library program about 2 ms)."""

    def __init__(self, pattern: str) -> None:
        self.pattern = pattern

    def __getattr__(self, name: str):
        compiled = re.compile(self.pattern)
        self.match, self.findall, self.sub = compiled.match, compiled.findall, compiled.sub
        return getattr(compiled, name)


_READ = _Pattern(r"(t\d+) = float\((_a_\w+)\[(\d+)\]\)$")
_SCALAR_READ = _Pattern(r"(?<= = )float\((_M\.scalars\.get\('\w+', 0\.0\))\)$")  # binding's scalar read
_CONVERTED = "_float({}[{}])"  # an element read (array, index) as float() makes it a float
_SUBTRACTED = "{}[{}] - 0.0"  # ... as a subtraction makes it one (Recorder.compile's plain_numbers)


def _batched_reads(lines: list[str], form: str = _CONVERTED) -> list[str]:
    """``lines`` with every element read of an array (``tN = float(_a_X[i])``) moved to
    the first read of that array, one line each (a subscript of a list and a conversion of a
    float cost least as separate steps: one C call reading them all and ``map(float, ...)``
    cost a call three times as much).  Reads are pure and the array's length guard
    comes before its first read, so moving a read earlier changes nothing but time."""
    reads: dict[str, list[tuple[str, str]]] = {}
    for line in lines:
        found = _READ.match(line)
        if found:
            reads.setdefault(found.group(2), []).append((found.group(1), found.group(3)))
    out = []
    for line in lines:
        found = _READ.match(line)
        if not found:
            out.append(line)
            continue
        elements = reads.pop(found.group(2), None)
        if elements is None:  # already read with the first
            continue
        out += [f"{name} = {form.format(found.group(2), index)}" for name, index in elements]
    return out


_NAME = _Pattern(r"\bt\d+\b")
_DEFINED = _Pattern(r"^((?:t\d+, )*t\d+) = (.*)$")
_OPERAND = r"(?:t\d+|-?[\d.]+(?:e[-+]?\d+)?j?|\(-?[\d.]+[-+][\d.]+j\))"
# Expressions that raise nothing whatever the numbers (no division, no call, no abs):
# + - * and comparisons of two operands, a negation, a part of a complex number, a choice.
_HARMLESS = _Pattern(rf"^(?:{_OPERAND} (?:[-+*]|[<>]=?|[=!]=) {_OPERAND}|-t\d+|t\d+\.(?:real|imag)"
                     rf"|\({_OPERAND} if {_OPERAND}(?: [<>] {_OPERAND})? else {_OPERAND}\))$")


def _without_dead_lines(lines: list[str]) -> list[str]:
    """``lines`` without the harmless lines (:data:`_HARMLESS`) whose value nothing uses."""
    while True:
        used: dict[str, int] = {}
        for line in lines:
            found = _DEFINED.match(line)
            for name in _NAME.findall(found.group(2) if found else line):
                used[name] = used.get(name, 0) + 1
        kept = []
        for line in lines:
            found = _DEFINED.match(line)
            if found and "," not in found.group(1) and found.group(1) not in used and _HARMLESS.match(found.group(2)):
                continue
            kept.append(line)
        if len(kept) == len(lines):
            return lines
        lines = kept


_NESTING = 40  # parentheses a fused line may hold (the parser allows 200)


def _fused(lines: list[str]) -> list[str]:
    """``lines`` with each value used by one later line only computed inside that line
    (``t5 = t3 * t4`` and ``t6 = t5 - t2`` become ``t6 = (t3 * t4) - t2``): the same
    operations on the same values, without storing and loading the value between them.
    A value is only ever moved later, past guards: where a guard then fails first, the
    plain code run instead computes the value itself (and raises what it would)."""
    uses: dict[str, int] = {}
    for line in lines:
        found = _DEFINED.match(line)
        for name in _NAME.findall(found.group(2) if found else line):
            uses[name] = uses.get(name, 0) + 1
    pending: dict[str, str] = {}  # single-use value -> its expression, not yet written
    out = []
    for line in lines:
        found = _DEFINED.match(line)
        head, body = (f"{found.group(1)} = ", found.group(2)) if found else ("", line)
        body = _NAME.sub(lambda m: f"({pending.pop(m.group(0))})" if m.group(0) in pending else m.group(0), body)
        if (found and "," not in found.group(1) and uses.get(found.group(1)) == 1
                and body.count("(") < _NESTING and "_a_" not in body and "_M" not in body):  # reads stay in place
            pending[found.group(1)] = body
            continue
        out.append(head + body)
    if pending:  # used by nothing after (cannot happen: every value written is used)
        raise ValueError(f"values never used: {', '.join(pending)}")
    return out


def _registers(lines: list[str]) -> list[str]:
    """``lines`` with the recorded values ``tN`` renamed to as few variables ``vK`` as
    they need: a variable is taken again once the value it held is used no more (the
    right-hand side of a line is evaluated before its names are bound)."""
    last: dict[str, int] = {}
    for number, line in enumerate(lines):
        for name in _NAME.findall(line):
            last[name] = number
    free: list[str] = []
    count = 0
    register: dict[str, str] = {}
    out = []
    for number, line in enumerate(lines):
        found = _DEFINED.match(line)
        targets = found.group(1).split(", ") if found else []
        used = _NAME.findall(found.group(2) if found else line)
        text = _NAME.sub(lambda m: register[m.group(0)], found.group(2) if found else line)
        for name in dict.fromkeys(used):
            if last[name] == number and name not in targets:
                free.append(register[name])
        for name in targets:
            if free:
                register[name] = free.pop()
            else:
                register[name] = f"v{count}"
                count += 1
        if found:
            text = f"{', '.join(register[name] for name in targets)} = {text}"
        for name in targets:
            if last[name] == number:  # never used: its variable is free again at once
                free.append(register[name])
        out.append(text)
    return out


_FETCH = _Pattern(r"(_a_\w+) = _arrays\.get\(('\w+')\) or _M\.array\('\w+'\)$")


def _batched_fetches(lines: list[str], plain_numbers: bool = False) -> list[str]:
    """``lines`` with the arrays' look-ups (``_a_X = _arrays.get('X') or _M.array('X')``, each
    a method call) made first, all together, as subscripts of the dictionary of arrays; each
    look-up in its place is then made only where one of the arrays did not exist yet (the
    machine makes an array at its first use: it is made where the recorded call made it).
    ``plain_numbers`` (:meth:`Recorder.compile`): a machine whose numbers are typed is refused."""
    fetches = [found.groups() for found in map(_FETCH.match, lines) if found]
    if not fetches:
        return lines
    together = "; ".join(f"{array} = _arrays[{key}]" for array, key in fetches)
    together += "\nexcept KeyError: _ready = False"
    out = []
    for line in lines:
        if _FETCH.match(line):
            out.append(f"if not _ready: {line}")
        else:
            out.append(line)
        if line == "_arrays = _M.arrays":
            out.append(f"try: {together}\nelse: _ready = True")
            if plain_numbers:
                # (an attribute read in a try costs a third of a call of getattr)
                out.append("try: _dialect = _M.dialect\nexcept AttributeError: _dialect = _no_dialect")
                out.append("if _dialect.typed_numbers: raise _Retrace")
    return out


def not_finite(values: list[str]) -> str:
    """The Python test that one of ``values`` (texts of float values) is not finite: their sum
    is finite only if each is (an inf or a NaN makes it inf or NaN); where the sum overflows,
    each value is looked at."""
    if len(values) == 1:
        return f"not _isfinite({values[0]})"
    return f"not _isfinite({' + '.join(values)}) and not _all(_map(_isfinite, ({', '.join(values)},)))"


_FINITE = _Pattern(r"(t\d+) = _isfinite\((\w+)\)$")


def _batched_finite_guards(lines: list[str]) -> list[str]:
    """``lines`` with each run of ``tN = _isfinite(x)`` + ``if not tN: raise _Retrace``
    pairs (tN used nowhere else) made one guard over all the values."""
    used: dict[str, int] = {}
    for line in lines:
        for name in re.findall(r"\bt\d+\b", line):
            used[name] = used.get(name, 0) + 1
    out: list[str] = []
    run: list[str] = []
    k = 0
    while k < len(lines):
        found = _FINITE.match(lines[k])
        if (found and k + 1 < len(lines) and lines[k + 1] == f"if not {found.group(1)}: raise _Retrace"
                and used[found.group(1)] == 2):
            run.append(found.group(2))
            k += 2
            continue
        if run:
            out.append(f"if {not_finite(run)}: raise _Retrace")
            run = []
        out.append(lines[k])
        k += 1
    if run:
        out.append(f"if {not_finite(run)}: raise _Retrace")
    return out


def _value(x):
    return x.value if isinstance(x, Traced) else x


# Operations whose result is the traced float itself, bit for bit, whatever it holds at a later
# call: x * 1, x / 1, x - 0 (a positive zero) and 1 * x.  Not x + 0 nor 0 + x (-0.0 + 0.0 is
# +0.0), nor x - (-0.0), nor any of a complex number (its zero parts' signs change, and an
# infinite part times the 0.0 of 1's imaginary part is NaN).
_IDENTITIES = {("*", 1.0), ("/", 1.0), ("-", 0.0)}
_LEFT_IDENTITIES = {("*", 1.0)}


def _identity(value, symbol: str, other, identities) -> bool:
    """Whether ``value <symbol> other`` (or ``other <symbol> value``) is ``value`` itself for
    every float ``value`` (see :data:`_IDENTITIES`)."""
    return (type(value) is float and type(other) in (int, float) and (symbol, other) in identities
            and math.copysign(1.0, other) > 0)


_COMPARISONS = {"<", "<=", ">", ">=", "==", "!="}


def _binary(symbol: str, operation):
    def forward(self, other):
        if isinstance(other, (Traced, *_LITERALS)):
            value = operation(self.value, _value(other))
            if _identity(self.value, symbol, other, _IDENTITIES):
                return self
            if symbol == "*" and type(other) is float and other == -1.0 and type(self.value) is float:
                return -self  # x * -1.0 is -x for a float (not for a complex: its zero parts' signs)
            # x ** 2 stays a power: libm's pow, which the plain code calls, is not always the
            # correctly rounded x * x (0x1.f450b0d1e5574p-2 squared: pow gives ...296cp-3, the product ...296bp-3)
            operand = self.recorder.operand(other)
            source = None
            if symbol in _COMPARISONS and self.leaf and (type(other) in (int, float) or getattr(other, "leaf", False)):
                source = f"({self.source} {symbol} {other.source if isinstance(other, Traced) else operand})"
            return self.recorder.emit(value, f"{self.name} {symbol} {operand}", source)
        return NotImplemented

    def backward(self, other):
        if isinstance(other, _LITERALS):
            value = operation(other, self.value)
            if _identity(self.value, symbol, other, _LEFT_IDENTITIES):
                return self
            if symbol == "*" and type(other) is float and other == -1.0 and type(self.value) is float:
                return -self
            return self.recorder.emit(value, f"{self.recorder.operand(other)} {symbol} {self.name}")
        return NotImplemented

    return forward, backward


class Traced:
    """A number of a recording: its concrete value and its variable's name;
    ``source``: the Python text computing it from the inputs alone, where it is an
    input (``leaf``) or an input compared with a literal or another input (else None)."""

    __slots__ = ("recorder", "value", "name", "source", "leaf", "negated")
    math_namespace: SimpleNamespace  # numerics.math_for picks it (set below)

    def __init__(self, recorder: Recorder, value, name: str, source: str | None = None):
        self.recorder, self.value, self.name, self.source, self.leaf = recorder, value, name, source, False
        self.negated = None  # the value this one is the negation of (-(-x) is recorded as x)

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
        if self.negated is not None:  # -(-x) is x exactly
            return self.negated
        negative = self.recorder.emit(-self.value, f"-{self.name}")
        if negative.negated is None and negative is not self:
            negative.negated = self
        return negative

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


def _scales() -> dict[str, float]:
    """math.radians and math.degrees as the factor each multiplies its float by: CPython's
    mathmodule.c computes ``x * degToRad`` and ``x * radToDeg``, the doubles pi/180 and 180/pi,
    and nothing else (no range check).  A product costs a record a third of the call; a Python
    whose functions give other bits at a few probes (signed zero, infinities, the largest
    float, a subnormal) keeps the calls."""
    factors = {"radians": math.pi / 180.0, "degrees": 180.0 / math.pi}
    probes = (0.0, -0.0, 1.0, -123.456, 1e300, -1.7976931348623157e308, 5e-324, math.inf, -math.inf, 359.99999)
    same = all(getattr(math, name)(x).hex() == (x * factor).hex()
               for name, factor in factors.items() for x in probes)
    return factors if same else {}


_SCALES = _scales()


def _call(name: str, function):
    """``function`` (of :data:`numerics.SCALAR`) recorded as a call when an argument is traced
    (radians and degrees of a float: the product they compute, :func:`_scales`)."""
    scale = _SCALES.get(name)

    def call(*args):
        if not any(isinstance(arg, Traced) for arg in args):
            return function(*args)
        recorder = next(arg.recorder for arg in args if isinstance(arg, Traced))
        value = function(*(_value(arg) for arg in args))
        if scale is not None and len(args) == 1 and type(args[0].value) is float:
            return recorder.emit(value, f"{args[0].name} * {scale!r}")
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


def _maximum(a, b):
    """max(a, b) recorded inline: ``b if b > a else a`` is what max does (NaN and
    signed zeros included), without a call."""
    if not isinstance(a, Traced) and not isinstance(b, Traced):
        return max(a, b)
    recorder = (a if isinstance(a, Traced) else b).recorder
    first, second = recorder.operand(a), recorder.operand(b)
    return recorder.emit(max(_value(a), _value(b)), f"({second} if {second} > {first} else {first})")


def _unit(angle):
    """u(angle) recorded as the C call that numerics.SCALAR.unit wraps (cmath.rect(1.0, angle))."""
    if not isinstance(angle, Traced):
        return _S.unit(angle)
    callee = angle.recorder.function("_rect", BOUND["_rect"])
    return angle.recorder.emit(_S.unit(angle.value), f"{callee}(1.0, {angle.name})")


def _angle(vector):
    """The angle of a complex number recorded as numerics.SCALAR.angle computes it (atan2 of its parts)."""
    if not isinstance(vector, Traced):
        return _S.angle(vector)
    callee = vector.recorder.function("_atan2", BOUND["_atan2"])
    return vector.recorder.emit(_S.angle(vector.value), f"{callee}({vector.name}.imag, {vector.name}.real)")


def _unit_degrees(angle):
    """numerics.SCALAR.unit_degrees recorded as the expression it evaluates (the quadrants' exact
    values, else the C call of u(radians)), without a Python call."""
    if not isinstance(angle, Traced):
        return _S.unit_degrees(angle)
    recorder = angle.recorder
    quadrant, rect = (recorder.function(name, BOUND[name]) for name in ("_quadrant", "_rect"))
    if "radians" in _SCALES and type(angle.value) is float:
        radians = f"{angle.name} * {_SCALES['radians']!r}"
    else:
        radians = f"{recorder.function('_radians', BOUND['_radians'])}({angle.name})"
    # every quadrant's value is a nonzero complex number: ``or`` takes it when there is one
    return recorder.emit(_S.unit_degrees(angle.value),
                         f"({quadrant}({angle.name} % 360.0) or {rect}(1.0, {radians}))")


def _unit_of(length):
    """numerics.SCALAR.unit_of recorded as its two C calls (ldexp(1.0, frexp(length)[1])), without a Python call."""
    if not isinstance(length, Traced):
        return _S.unit_of(length)
    recorder = length.recorder
    ldexp, frexp = recorder.function("_ldexp", BOUND["_ldexp"]), recorder.function("_frexp", BOUND["_frexp"])
    exact = f"{ldexp}(1.0, {frexp}({length.name})[1])"
    if type(length.value) is not float:
        return recorder.emit(_S.unit_of(length.value), exact)
    # A normal float x below 2**1023 lies in [2**(e-1), 2**e) with e = frexp(x)[1], and its ulp
    # is 2**(e-53): ulp(x) * 2**53 is 2**e exactly, in two C operations where frexp builds a
    # tuple and ldexp is a second call (a subnormal, zero, a negative, inf, NaN and from 2**1023
    # on, where ldexp raises OverflowError, take the two calls)
    ulp = recorder.function("_ulp", BOUND["_ulp"])
    x = length.name
    return recorder.emit(_S.unit_of(length.value),
                         f"({ulp}({x}) * {_TWO_53!r} if {_SMALLEST_NORMAL!r} <= {x} < {_TWO_1023!r} else {exact})")


_TWO_53, _SMALLEST_NORMAL, _TWO_1023 = 2.0 ** 53, 2.0 ** -1022, 2.0 ** 1023


_S = numerics.SCALAR
_CALLED = {**{name: getattr(_S, name) for name in
              ("sqrt", "cos", "sin", "arctan", "radians", "degrees", "isfinite")}, "exp": cmath.exp}

#: Every function a record calls, under the name it has there (:meth:`Recorder.function`), and the
#: exception its guards raise: a record's names are these and literals.
BOUND = {**{f"_{name}": function for name, function in _CALLED.items()}, "_rect": cmath.rect,
         "_atan2": math.atan2, "_ldexp": math.ldexp, "_frexp": math.frexp, "_ulp": math.ulp,
         "_quadrant": numerics.QUADRANTS.get, "_Retrace": Retrace}

#: The :mod:`numerics` namespace of a recording.
TRACE = SimpleNamespace(
    scalar=True, pi=math.pi, float=_as(float), complex=_as(complex),
    **{name: _call(name, function) for name, function in _CALLED.items()},
    maximum=_maximum, unit=_unit, unit_degrees=_unit_degrees, angle=_angle, unit_of=_unit_of,
    where=_where, any=lambda value: value, all=lambda value: value, real=lambda value: value.real,
    imag=lambda value: value.imag, zeros_like=_zero_like, ones_like=lambda value: 1.0,
)
Traced.math_namespace = TRACE
