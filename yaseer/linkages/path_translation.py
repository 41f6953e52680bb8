"""The translation of a recorded path's Python text into the program of double operations that
:mod:`yaseer.linkages._straight_fast` runs (see :mod:`yaseer.linkages.straight_line`).

:func:`translate` walks the text's :mod:`ast`: each value of the text gets registers (a float or
a truth one, a complex number two: real, imaginary), each operation an instruction, each guard an
instruction refusing the call where its test holds, each output's check and write an instruction.
Constants live in registers of their own, set once.  What it does not know raises
:class:`Untranslatable` and the path keeps its Python function alone.
"""

from __future__ import annotations

import ast
import cmath
import math

from yaseer.linkages import numerics


class Untranslatable(Exception):
    """The text holds something the program cannot express."""


_FLOAT, _COMPLEX, _BOOL = "f", "c", "b"
_WIDTH = {_FLOAT: 1, _COMPLEX: 2, _BOOL: 1}
_FLOAT_OPERATIONS = {ast.Add: "ADD", ast.Sub: "SUB", ast.Mult: "MUL", ast.Div: "DIV", ast.Mod: "MOD"}
_COMPLEX_OPERATIONS = {ast.Add: "CADD", ast.Sub: "CSUB", ast.Mult: "CMUL", ast.Div: "CDIV"}
_COMPARISONS = {ast.Lt: "LT", ast.LtE: "LE", ast.Gt: "GT", ast.GtE: "GE", ast.Eq: "EQ", ast.NotEq: "NE"}
# the functions of one float a path calls, by the name it calls them under, and their instructions
_CALLS = {"_sqrt": (math.sqrt, "SQRT"), "_cos": (math.cos, "COS"), "_sin": (math.sin, "SIN"),
          "_arctan": (math.atan, "ATAN"), "_isfinite": (math.isfinite, "ISFINITE"), "_ulp": (math.ulp, "ULP")}


def _is_zero(node) -> bool:
    """Whether ``node`` is the literal 0.0 (a positive zero)."""
    return (isinstance(node, ast.Constant) and type(node.value) is float and node.value == 0.0
            and math.copysign(1.0, node.value) == 1.0)


def _called(node, name: str) -> bool:
    return isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id == name and not node.keywords


def _array_name(node) -> str:
    """``X`` of ``_a_X``."""
    if isinstance(node, ast.Name) and node.id.startswith("_a_"):
        return node.id[3:]
    raise Untranslatable(ast.dump(node)[:80])


def _element(node) -> tuple[str, int]:
    """(array, index) of ``_a_X[i]``."""
    if (isinstance(node, ast.Subscript) and isinstance(node.slice, ast.Constant)
            and type(node.slice.value) is int and node.slice.value >= 0):
        return _array_name(node.value), node.slice.value
    raise Untranslatable(ast.dump(node)[:80])


def _read(node):
    """(array, index) of an element read, ``_a_X[i] - 0.0`` or ``_float(_a_X[i])``, else None."""
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Sub) and _is_zero(node.right) \
            and isinstance(node.left, ast.Subscript):
        return _element(node.left)
    if _called(node, "_float") and len(node.args) == 1 and isinstance(node.args[0], ast.Subscript):
        return _element(node.args[0])
    return None


def _scalar_read(node):
    """The name of a scalar read, ``_M.scalars.get('G', 0.0) - 0.0`` or in ``float()``, else None."""
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Sub) and _is_zero(node.right):
        inner = node.left
    elif _called(node, "float") and len(node.args) == 1:
        inner = node.args[0]
    else:
        return None
    if (isinstance(inner, ast.Call) and isinstance(inner.func, ast.Attribute) and inner.func.attr == "get"
            and isinstance(inner.func.value, ast.Attribute) and inner.func.value.attr == "scalars"
            and isinstance(inner.func.value.value, ast.Name) and inner.func.value.value.id == "_M"
            and len(inner.args) == 2 and isinstance(inner.args[0], ast.Constant) and type(inner.args[0].value) is str
            and _is_zero(inner.args[1]) and not inner.keywords):
        return inner.args[0].value
    return None


class _Program:
    """The instructions being written, the registers and the names they use."""

    def __init__(self, names: dict, operations: dict):
        self.names, self.ops = names, operations
        self.code: list[int] = []
        self.extra: list[int] = []
        self.registers: list[float] = []
        self.arrays: list[str] = []
        self.scalars: list[str] = []
        self.values: dict[str, tuple[int, str]] = {}  # a variable of the text -> its register, kind
        self._constants: dict[tuple, int] = {}
        self.writing = False  # an output was written: nothing may refuse after it
        self.plain_numbers = False  # the text refuses a machine whose numbers are typed

    def emit(self, operation: str, d: int = 0, a: int = 0, b: int = 0) -> int:
        """Append an instruction; its number."""
        if self.writing and operation not in ("WRITE", "SET_SCALAR"):
            raise Untranslatable("an operation after an output's write")
        self.code += [self.ops[operation], d, a, b]
        return len(self.code) // 4 - 1

    def here(self) -> int:
        """The number of the next instruction (a jump's target)."""
        return len(self.code) // 4

    def aim(self, jump: int) -> None:
        """Make instruction ``jump`` go to the next instruction."""
        self.code[jump * 4 + 1] = self.here()

    def new(self, kind: str) -> int:
        self.registers += [0.0] * _WIDTH[kind]
        return len(self.registers) - _WIDTH[kind]

    def constant(self, value) -> tuple[int, str]:
        if type(value) is complex:
            parts, kind = (value.real, value.imag), _COMPLEX
        elif type(value) in (int, bool) and abs(value) <= 2 ** 53:
            parts, kind = (float(value),), _FLOAT
        elif type(value) is float:
            parts, kind = (value,), _FLOAT
        else:
            raise Untranslatable(f"a constant {value!r}")
        key = (kind, *(part.hex() for part in parts))
        if key not in self._constants:
            self._constants[key] = len(self.registers)
            self.registers += list(parts)
        return self._constants[key], kind

    def array(self, name: str) -> int:
        if name not in self.arrays:
            self.arrays.append(name)
        return self.arrays.index(name)

    def scalar(self, name: str) -> int:
        if name not in self.scalars:
            self.scalars.append(name)
        return self.scalars.index(name)


class _Translator:
    """The statements and expressions of a path's text as instructions of a :class:`_Program`."""

    def __init__(self, program: _Program):
        self.p = program

    def _bound(self, name: str, function) -> None:
        """Refuse a call of ``name`` unless the path binds it to ``function`` itself."""
        if self.p.names.get(name) is not function:
            raise Untranslatable(f"{name} is not {function!r}")

    # -- expressions: each gives (register, kind) ----------------------------------------------
    def value(self, node) -> tuple[int, str]:
        p = self.p
        if isinstance(node, ast.Name):
            if node.id in p.values:
                return p.values[node.id]
            if node.id.startswith("_k") and node.id in p.names:
                return p.constant(p.names[node.id])
            raise Untranslatable(f"the name {node.id}")
        if isinstance(node, ast.Constant):
            return p.constant(node.value)
        read = _read(node)
        if read is not None:
            d = p.new(_FLOAT)
            p.emit("READ", d, p.array(read[0]), read[1])
            return d, _FLOAT
        scalar = _scalar_read(node)
        if scalar is not None:
            d = p.new(_FLOAT)
            p.emit("SCALAR", d, p.scalar(scalar))
            return d, _FLOAT
        if isinstance(node, ast.BinOp):
            return self.binary(node)
        if isinstance(node, ast.UnaryOp):
            return self.unary(node)
        if isinstance(node, ast.Compare):
            return self.compare(node)
        if isinstance(node, ast.BoolOp):
            return self.boolean(node)
        if isinstance(node, ast.IfExp):
            return self.choice(node)
        if isinstance(node, ast.Attribute) and node.attr in ("real", "imag"):
            register, kind = self.value(node.value)
            if kind == _COMPLEX:
                return register + (node.attr == "imag"), _FLOAT
            if kind == _FLOAT:
                return (register, _FLOAT) if node.attr == "real" else p.constant(0.0)
            raise Untranslatable("a part of a truth")
        if isinstance(node, ast.Call):
            return self.call(node)
        raise Untranslatable(ast.dump(node)[:80])

    def as_complex(self, register: int, kind: str) -> int:
        """The complex register of a value: a float ``x`` is made (x, 0.0), as CPython does
        before an operation with a complex number."""
        if kind == _COMPLEX:
            return register
        if kind != _FLOAT:
            raise Untranslatable("a truth in complex arithmetic")
        d = self.p.new(_COMPLEX)
        self.p.emit("FLOAT2C", d, register)
        return d

    def binary(self, node) -> tuple[int, str]:
        p = self.p
        if isinstance(node.op, ast.Pow):
            base, kind = self.value(node.left)
            if not (kind == _FLOAT and isinstance(node.right, ast.Constant) and type(node.right.value) is int
                    and node.right.value == 2):
                raise Untranslatable("a power other than a float's square")
            d = p.new(_FLOAT)
            p.emit("SQUARE", d, base)
            return d, _FLOAT
        (a, left), (b, right) = self.value(node.left), self.value(node.right)
        if _BOOL in (left, right):
            raise Untranslatable("arithmetic of a truth")
        if left == right == _FLOAT:
            operation = _FLOAT_OPERATIONS.get(type(node.op))
            if operation is None:
                raise Untranslatable(ast.dump(node.op))
            d = p.new(_FLOAT)
            p.emit(operation, d, a, b)
            return d, _FLOAT
        operation = _COMPLEX_OPERATIONS.get(type(node.op))
        if operation is None:
            raise Untranslatable(f"complex {ast.dump(node.op)}")
        a, b = self.as_complex(a, left), self.as_complex(b, right)
        d = p.new(_COMPLEX)
        p.emit(operation, d, a, b)
        return d, _COMPLEX

    def unary(self, node) -> tuple[int, str]:
        p = self.p
        register, kind = self.value(node.operand)
        if isinstance(node.op, ast.USub) and kind != _BOOL:
            d = p.new(kind)
            p.emit("NEG" if kind == _FLOAT else "CNEG", d, register)
            return d, kind
        if isinstance(node.op, ast.Not):
            d = p.new(_BOOL)
            if kind == _COMPLEX:
                p.emit("CEQ", d, register, p.constant(0j)[0])
            else:
                p.emit("NOT", d, register)
            return d, _BOOL
        raise Untranslatable(ast.dump(node.op))

    def truth(self, node) -> int:
        """The register holding the truth of ``node`` (as ``bool()`` of it)."""
        register, kind = self.value(node)
        if kind == _BOOL:
            return register
        d = self.p.new(_BOOL)
        if kind == _FLOAT:
            self.p.emit("TRUTH", d, register)
        else:
            self.p.emit("CNE", d, register, self.p.constant(0j)[0])
        return d

    def compare(self, node) -> tuple[int, str]:
        p = self.p
        result = None
        left = self.value(node.left)
        for op, right_node in zip(node.ops, node.comparators):
            right = self.value(right_node)
            d = p.new(_BOOL)
            if left[1] == right[1] == _FLOAT:
                operation = _COMPARISONS.get(type(op))
                if operation is None:
                    raise Untranslatable(ast.dump(op))
                p.emit(operation, d, left[0], right[0])
            elif isinstance(op, (ast.Eq, ast.NotEq)) and _BOOL not in (left[1], right[1]):
                p.emit("CEQ" if isinstance(op, ast.Eq) else "CNE", d, self.as_complex(*left), self.as_complex(*right))
            else:
                raise Untranslatable("a comparison of these kinds")
            if result is None:
                result = d
            else:  # a chain a < b < c: both tests (each operand is computed once; none raises)
                both = p.new(_BOOL)
                p.emit("AND", both, result, d)
                result = both
            left = right
        return result, _BOOL

    def boolean(self, node) -> tuple[int, str]:
        p = self.p
        # the quadrant's exact unit, else the rect call: (_quadrant(x) or _rect(1.0, y))
        if (isinstance(node.op, ast.Or) and len(node.values) == 2 and _called(node.values[0], "_quadrant")
                and len(node.values[0].args) == 1):
            bound = p.names.get("_quadrant")
            if getattr(bound, "__self__", None) is not numerics.QUADRANTS or getattr(bound, "__name__", "") != "get":
                raise Untranslatable("_quadrant is not the quadrants' get")
            angle, kind = self.value(node.values[0].args[0])
            if kind != _FLOAT:
                raise Untranslatable("a quadrant of a complex number")
            d, found, missing = p.new(_COMPLEX), p.new(_BOOL), p.new(_BOOL)
            p.emit("QUADRANT", d, angle, found)
            p.emit("NOT", missing, found)
            over = p.emit("JUMP_IF_NOT", 0, missing)  # found: the rect call is not made
            value, kind = self.value(node.values[1])
            p.emit("MOVE2", d, self.as_complex(value, kind))
            p.aim(over)
            return d, _COMPLEX
        # a test of truths, evaluated whole: its operands are comparisons and truths, which raise nothing
        parts = []
        for value in node.values:
            register, kind = self.value(value)
            if kind != _BOOL:
                raise Untranslatable("and/or of values that are not truths")
            parts.append(register)
        result = parts[0]
        for part in parts[1:]:
            d = p.new(_BOOL)
            p.emit("AND" if isinstance(node.op, ast.And) else "OR", d, result, part)
            result = d
        return result, _BOOL

    def choice(self, node) -> tuple[int, str]:
        """``(a if c else b)``: only the branch taken is computed."""
        p = self.p
        condition = self.truth(node.test)
        to_else = p.emit("JUMP_IF_NOT", 0, condition)
        yes, kind = self.value(node.body)
        if kind == _BOOL:
            raise Untranslatable("a choice of truths")
        d = p.new(kind)
        move = "MOVE" if kind == _FLOAT else "MOVE2"
        p.emit(move, d, yes)
        to_end = p.emit("JUMP")
        p.aim(to_else)
        no, no_kind = self.value(node.orelse)
        if no_kind != kind:
            raise Untranslatable("a choice of two kinds")
        p.emit(move, d, no)
        p.aim(to_end)
        return d, kind

    def call(self, node) -> tuple[int, str]:
        p = self.p
        if node.keywords or not isinstance(node.func, ast.Name):
            raise Untranslatable(ast.dump(node)[:80])
        name, args = node.func.id, node.args
        if name == "abs" and len(args) == 1:
            register, kind = self.value(args[0])
            if kind == _BOOL:
                raise Untranslatable("abs of a truth")
            d = p.new(_FLOAT)
            p.emit("ABS" if kind == _FLOAT else "CABS", d, register)
            return d, _FLOAT
        if name in ("float", "_float") and len(args) == 1:
            register, kind = self.value(args[0])
            if kind != _FLOAT:
                raise Untranslatable("float() of a complex number or a truth")
            return register, _FLOAT
        if name == "complex" and len(args) == 1:
            return self.as_complex(*self.value(args[0])), _COMPLEX
        if name in _CALLS and len(args) == 1:
            function, operation = _CALLS[name]
            self._bound(name, function)
            register, kind = self.value(args[0])
            if kind != _FLOAT:
                raise Untranslatable(f"{name} of a complex number or a truth")
            result = _BOOL if operation == "ISFINITE" else _FLOAT
            d = p.new(result)
            p.emit(operation, d, register)
            return d, result
        if name in ("_atan2", "_rect") and len(args) == 2:
            self._bound(name, math.atan2 if name == "_atan2" else cmath.rect)
            (a, a_kind), (b, b_kind) = self.value(args[0]), self.value(args[1])
            if a_kind != _FLOAT or b_kind != _FLOAT:
                raise Untranslatable(f"{name} of a complex number or a truth")
            result = _FLOAT if name == "_atan2" else _COMPLEX
            d = p.new(result)
            p.emit("ATAN2" if name == "_atan2" else "RECT", d, a, b)
            return d, result
        if name == "_ldexp" and len(args) == 2:
            # ldexp(1.0, frexp(x)[1]): the power of two just above x's magnitude
            one, frexp = args
            if not (isinstance(one, ast.Constant) and type(one.value) is float and one.value == 1.0
                    and isinstance(frexp, ast.Subscript) and isinstance(frexp.slice, ast.Constant)
                    and type(frexp.slice.value) is int and frexp.slice.value == 1
                    and _called(frexp.value, "_frexp") and len(frexp.value.args) == 1):
                raise Untranslatable("another ldexp")
            self._bound("_ldexp", math.ldexp)
            self._bound("_frexp", math.frexp)
            register, kind = self.value(frexp.value.args[0])
            if kind != _FLOAT:
                raise Untranslatable("frexp of a complex number")
            d = p.new(_FLOAT)
            p.emit("UNIT_EXACT", d, register)
            return d, _FLOAT
        raise Untranslatable(f"a call of {name}")

    # -- statements ------------------------------------------------------------------------------
    def statement(self, node) -> None:
        p = self.p
        if isinstance(node, ast.Assign) and len(node.targets) == 1:
            target = node.targets[0]
            if isinstance(target, ast.Name):
                if target.id in ("_arrays", "_ready", "_dialect") or target.id.startswith("_a_"):
                    return  # the accelerator fetches the arrays itself (and refuses a machine missing one)
                p.values[target.id] = self.value(node.value)
                return
            if isinstance(target, ast.Subscript):
                array, index = _element(target)
                register, kind = self.value(node.value)
                if kind != _FLOAT:
                    raise Untranslatable("an output that is not a float")
                p.writing = True
                p.emit("WRITE", register, p.array(array), index)
                return
        if isinstance(node, ast.If):
            return self.guard(node)
        if isinstance(node, ast.Try):
            return self.attempt(node)
        if (isinstance(node, ast.Expr) and isinstance(node.value, ast.Call)
                and isinstance(node.value.func, ast.Attribute) and node.value.func.attr == "set_scalar"
                and isinstance(node.value.func.value, ast.Name) and node.value.func.value.id == "_M"
                and len(node.value.args) == 2 and not node.value.keywords
                and isinstance(node.value.args[0], ast.Constant) and type(node.value.args[0].value) is str):
            register, kind = self.value(node.value.args[1])
            if kind != _FLOAT:
                raise Untranslatable("an output that is not a float")
            p.writing = True
            p.emit("SET_SCALAR", register, p.scalar(node.value.args[0].value))
            return
        raise Untranslatable(ast.dump(node)[:80])

    def guard(self, node) -> None:
        """``if test: raise ...`` (the call refused where the test holds), ``if not _ready: ...``
        (nothing: the accelerator refuses a machine missing an array) and the dialect's test."""
        if node.orelse:
            raise Untranslatable("an if with an else")
        test = node.test
        if (isinstance(test, ast.UnaryOp) and isinstance(test.op, ast.Not) and isinstance(test.operand, ast.Name)
                and test.operand.id == "_ready"):
            return
        if (isinstance(test, ast.Attribute) and test.attr == "typed_numbers" and isinstance(test.value, ast.Name)
                and test.value.id == "_dialect"):
            self.p.plain_numbers = True
            return
        if len(node.body) != 1 or not isinstance(node.body[0], ast.Raise):
            raise Untranslatable("an if that does more than raise")
        finite = self._finiteness(test)
        if finite is not None:
            start = len(self.p.extra)
            self.p.extra += finite
            self.p.emit("FINITE_ALL", 0, start, len(finite))
            return
        self.p.emit("REFUSE_IF", 0, self.truth(test))

    def _finiteness(self, test):
        """The registers of ``not _isfinite(a + b + ...) and not _all(_map(_isfinite, (a, b, ...)))``
        (true exactly when one of them is not finite), else None."""
        if not (isinstance(test, ast.BoolOp) and isinstance(test.op, ast.And) and len(test.values) == 2):
            return None
        first, second = test.values
        if not (isinstance(first, ast.UnaryOp) and isinstance(first.op, ast.Not) and _called(first.operand, "_isfinite")
                and isinstance(second, ast.UnaryOp) and isinstance(second.op, ast.Not)
                and _called(second.operand, "_all") and len(second.operand.args) == 1
                and _called(second.operand.args[0], "_map")):
            return None
        mapped = second.operand.args[0].args
        if not (len(mapped) == 2 and isinstance(mapped[0], ast.Name) and mapped[0].id == "_isfinite"
                and isinstance(mapped[1], ast.Tuple)):
            return None
        self._bound("_isfinite", math.isfinite)
        if self.p.names.get("_all") is not all or self.p.names.get("_map") is not map:
            raise Untranslatable("_all or _map is not the builtin")
        registers = []
        for element in mapped[1].elts:
            register, kind = self.value(element)
            if kind != _FLOAT:
                raise Untranslatable("a finiteness test of a complex number")
            registers.append(register)
        return registers

    def attempt(self, node) -> None:
        """The ``try`` blocks of a path: the arrays' fetch, the dialect's look-up, and the outputs'
        checks (each element written exists; each is a number)."""
        handled = {handler.type.id for handler in node.handlers if isinstance(handler.type, ast.Name)}
        body = node.body
        if handled == {"KeyError"} and all(isinstance(s, ast.Assign) and isinstance(s.targets[0], ast.Name)
                                           and s.targets[0].id.startswith("_a_") for s in body):
            return  # the arrays fetched together (the accelerator fetches them, every one must exist)
        if (handled == {"AttributeError"} and len(body) == 1 and isinstance(body[0], ast.Assign)
                and isinstance(body[0].targets[0], ast.Name) and body[0].targets[0].id == "_dialect"):
            return  # the dialect (its test follows)
        if handled == {"IndexError"} and all(isinstance(s, ast.Expr) and isinstance(s.value, ast.Subscript) for s in body):
            for s in body:
                array, index = _element(s.value)
                self.p.emit("CHECK_LENGTH", 0, self.p.array(array), index)
            return
        if handled == {"TypeError"} and all(isinstance(s, ast.Expr) and _read(s.value) for s in body):
            for s in body:
                array, index = _read(s.value)
                self.p.emit("CHECK_FLOAT", 0, self.p.array(array), index)
            return
        raise Untranslatable("another try")


def translate(text: str, names: dict, operations: dict) -> dict | None:
    """The program of the path whose function ``run(_M)`` is ``text`` with the globals ``names``
    (the parts of the accelerator's program by name; ``operations``: the accelerator's
    instruction numbers by name), or None where it holds something the program cannot express."""
    try:
        tree = ast.parse(text)
    except SyntaxError:
        return None
    if not (len(tree.body) == 1 and isinstance(tree.body[0], ast.FunctionDef) and len(tree.body[0].body) == 1
            and isinstance(tree.body[0].body[0], ast.Try)):
        return None
    program = _Program(names, operations)
    translator = _Translator(program)
    try:
        for statement in tree.body[0].body[0].body:
            translator.statement(statement)
    except (Untranslatable, KeyError, RecursionError):
        return None
    if not program.writing:  # (a program naming more arrays than the accelerator holds it refuses itself)
        return None
    quadrants = [part for angle, unit in sorted(numerics.QUADRANTS.items()) for part in (float(angle), unit.real, unit.imag)]
    return dict(code=program.code, extra=program.extra, registers=program.registers, arrays=tuple(program.arrays),
                scalars=tuple(program.scalars), quadrants=quadrants, plain_numbers=program.plain_numbers)
