"""AST -> Python: one program area becomes a set of Python functions, one per block.

A *block* is a run of statements that is entered only at its top: it starts at
a line some jump names (GOTO, GOSUB, THEN n, ON ... GOTO, RESUME n), at the
statement after a GOSUB or STOP (the return point), at the body of a FOR loop
that must be run through the FOR stack, or - in a program that uses RESUME or
RESUME NEXT - at every statement.  Each block is generated as Python source:

* scalars live in Python locals for the block's duration (loaded from the
  machine's scalar dict on entry, stored back in a ``finally``, and around every
  call out of the block: ``GOSUB PROG n``, ``FN``, ``CLEAR``);
* a FOR ... NEXT with no jump into or out of its body becomes a native
  ``while`` loop; a block that jumps back to its own start becomes
  ``while True`` with ``continue``;
* a block returns the number of the next block to run; the machine's run loop
  is ``while True: b = blocks[b]()``.

The variable ``_ln`` tracks the BASIC line for error messages.

With ``trace`` (TRON), the first statement of every line is preceded by
``_tr(n)``, which prints ``[n]``: a line is traced when execution reaches its
start (falling in from the line before, or by a jump), not when a NEXT or
RETURN comes back into its middle, as GW-BASIC traces.  The traced variant has
the same blocks as the plain one, so the machine can swap one for the other
while a program runs; the plain variant carries no cost for tracing.
"""

from __future__ import annotations

import math

from yaseer.basic import syntax_tree as ast
from yaseer.basic.blocks import data_statements, flatten, nodes, plan, scan_for_next, splits, walk_statements
from yaseer.basic.dialect import CASIO
from yaseer.basic.number_models import NUMERIC, RANGE_CHECKED, array_local, local_name, number_model
from yaseer.basic.compiled import MAX_STACK, CompiledArea  # noqa: F401  (re-exported)
from yaseer.basic.errors import (
    BasicError, FOR_WITHOUT_NEXT, OUT_OF_MEMORY, SYNTAX_ERROR, TYPE_MISMATCH, UNDEFINED_LINE,
    WEND_WITHOUT_WHILE, WHILE_WITHOUT_WEND,
)

_PY_RELATIONS = {"=": "==", "<>": "!=", "<": "<", ">": ">", "<=": "<=", ">=": ">="}

# name -> (argument kinds of each accepted form, result type, Python callable in the
# namespace); a kind is "n" number, "s" string, "x" either (FRE).
_FUNCTIONS = {
    "SIN": (("n",), "n", "_sin"), "COS": (("n",), "n", "_cos"), "TAN": (("n",), "n", "_tan"),
    "ATN": (("n",), "n", "_atn"), "SQR": (("n",), "n", "_sqrt"), "ABS": (("n",), "n", "abs"),
    "INT": (("n",), "n", "_floor"), "FIX": (("n",), "n", "_fix"), "SGN": (("n",), "n", "_sgn"),
    "EXP": (("n",), "n", "_exp"), "LOG": (("n",), "n", "_log"), "RND": (("", "n"), "n", "_rnd"),
    "LEN": (("s",), "n", "_len"), "STR$": (("n",), "s", "_strs"), "VAL": (("s",), "n", "_val"),
    "CHR$": (("n",), "s", "_chr"), "ASC": (("s",), "n", "_asc"),
    "CINT": (("n",), "n", "_cint"), "CSNG": (("n",), "n", "_csng"), "CDBL": (("n",), "n", "_cdbl"),
    "LEFT$": (("sn",), "s", "_left"), "RIGHT$": (("sn",), "s", "_right"),
    "MID$": (("sn", "snn"), "s", "_mid"),
    # GW-BASIC's (issue 12)
    "INSTR": (("ss", "nss"), "n", "_instr"), "STRING$": (("nn", "ns"), "s", "_string"),
    "SPACE$": (("n",), "s", "_space"), "HEX$": (("n",), "s", "_hex"), "OCT$": (("n",), "s", "_oct"),
    "MKI$": (("n",), "s", "_mki"), "MKS$": (("n",), "s", "_mks"), "MKD$": (("n",), "s", "_mkd"),
    "CVI": (("s",), "n", "_cvi"), "CVS": (("s",), "n", "_cvs"), "CVD": (("s",), "n", "_cvd"),
    "FRE": (("x",), "n", "_fre"), "POS": (("n",), "n", "_pos"), "LPOS": (("n",), "n", "_lpos"),
    "EOF": (("n",), "n", "_eof"), "LOF": (("n",), "n", "_lof"), "LOC": (("n",), "n", "_loc"),
    "INPUT$": (("n", "nn"), "s", "_input_chars"),
}

# Values without arguments: name -> (Python expression, "s" or None for the integer type).
_SYSTEM_VARIABLES = {
    "ERR": ("_M.err", None), "ERL": ("_M.erl", None), "TIMER": ("_timer()", "n"),
    "DATE$": ("_date()", "s"), "TIME$": ("_time()", "s"),
}


def _call_form(forms: tuple, kinds: list) -> str:
    """The form of a function that takes arguments of ``kinds`` ("s"/"n"): wrong count
    Syntax error, wrong types Type mismatch."""
    same_length = [form for form in forms if len(form) == len(kinds)]
    if not same_length:
        raise _syntax_error()
    for form in same_length:
        if all(want in ("x", kind) for want, kind in zip(form, kinds)):
            return form
    raise _type_mismatch()


class CompileError(BasicError):
    """A statement that cannot be compiled; it becomes a run-time error of its line."""


def _syntax_error() -> CompileError:
    return CompileError("Syntax error", SYNTAX_ERROR)


def _type_mismatch() -> CompileError:
    return CompileError("Type mismatch", TYPE_MISMATCH)




class _Block:
    def __init__(self, number: int):
        self.number = number
        self.code: list[tuple[int, str]] = []
        self.scalars: dict[str, bool] = {}  # name -> assigned in this block
        self.arrays: dict[str, int] = {}  # name -> number of dimensions
        self.first_line = None


class _BlockScope:
    """Variable references inside a block: Python locals."""

    def __init__(self, compiler: "AreaCompiler"):
        self.compiler = compiler
        self.uses_fn = False

    def scalar(self, name: str, write: bool = False) -> str:
        block = self.compiler.cur
        name = self.compiler.numbers.name(name)
        self.compiler.scalars.add(name)
        block.scalars[name] = block.scalars.get(name, False) or write
        return local_name(name)

    def array(self, name: str, ndim: int) -> str:
        block = self.compiler.cur
        name = self.compiler.numbers.name(name)
        block.arrays.setdefault(name, ndim)
        return array_local(name)


class _FnScope:
    """Variable references inside a DEF FN body: parameters are locals, the rest global."""

    def __init__(self, compiler: "AreaCompiler", params: list):
        self.compiler = compiler
        self.params = {compiler.numbers.name(p) for p in params}
        self.uses_fn = False

    def scalar(self, name: str, write: bool = False) -> str:
        name = self.compiler.numbers.name(name)
        if name in self.params:
            return "p" + local_name(name)
        self.compiler.scalars.add(name)
        return f"_S[{name!r}]"

    def array(self, name: str, ndim: int) -> str:
        return f"_arr({self.compiler.numbers.name(name)!r}, {ndim})"


def _is_relation(node) -> bool:
    if isinstance(node, ast.Binary):
        if node.op in _PY_RELATIONS:
            return True
        if node.op in ("AND", "OR"):
            return _is_relation(node.left) and _is_relation(node.right)
    if isinstance(node, ast.Unary) and node.op == "NOT":
        return _is_relation(node.operand)
    return False


def _is_constant(node) -> bool:
    return isinstance(node, ast.Num) or (isinstance(node, ast.Unary) and _is_constant(node.operand))


# What generated code calls that changes the GOSUB/FOR stack and goes on in the same block.
_STACK_CHANGES = ("_pop(", "_next_any(", "_clear(", "_call(", "_M.", "_gosub(", "_stk.")

_BOUNDED = frozenset({"RND", "SIN", "COS", "SGN"})  # results in [-1, 1]


def _is_small(node, single: bool = False) -> bool:
    """A constant, or a function whose result is at most 1 in size (RND, SIN, COS, SGN):
    added to a finite double it cannot give an infinity.  (``single``: the typed
    model, whose range ends at 1.7E+38: a constant below 1E+30 in size, less than half
    a unit of the largest single, cannot carry a sum beyond it.)"""
    if isinstance(node, ast.Call):
        return node.name in _BOUNDED
    if single:
        value = _constant_value(node)
        return value is not None and abs(value) < 1e30
    return _is_constant(node)


def _constant_value(node) -> float | None:
    """The value of a number literal, or of one with signs before it (``-1.5``); else None."""
    if isinstance(node, ast.Num):
        return float(node.value)
    if isinstance(node, ast.Unary) and node.op in "+-":
        value = _constant_value(node.operand)
        return None if value is None else (-value if node.op == "-" else value)
    return None


def _may_overflow(node, single: bool = False) -> bool:
    """Could this numeric expression produce inf from finite values?  (``single``: the
    typed model, where adding a constant may leave the single range too.)"""
    if isinstance(node, ast.Binary):
        if node.op in ("*", "/"):
            return True
        if node.op in ("+", "-") and not (_is_small(node.left, single) or _is_small(node.right, single)):
            return True
        return _may_overflow(node.left, single) or _may_overflow(node.right, single)
    if isinstance(node, ast.Unary):
        return _may_overflow(node.operand, single)
    if isinstance(node, ast.Call):
        return any(_may_overflow(a, single) for a in node.args)
    return isinstance(node, ast.FnCall)


def _too_deep(code: list) -> bool:
    """Would these generated lines pass Python's nesting limits (indents, parentheses)?"""
    for indent, text in code:
        if indent > 80:
            return True
        depth = 0
        for ch in text:
            if ch == "(":
                depth += 1
                if depth > 150:
                    return True
            elif ch == ")":
                depth -= 1
    return False


def _is_safe_item(item) -> bool:
    """A PRINT item whose evaluation cannot fail (so items may be evaluated together)."""
    return isinstance(item, (str, ast.Num, ast.Str, ast.Var))


def _print_chunks(parts: list) -> list:
    """PRINT items split so that each chunk holds one thing to evaluate (a value with the
    ``_NUMCOMMA`` mark before it, TAB or SPC) and the commas after it: each comma moves
    the cursor before the next item is evaluated, so a message that item prints
    (``Overflow``) lands where GW-BASIC prints it.  Leading commas are a chunk of their own."""
    chunks, current, evaluated = [], [], False
    for part in parts:
        if part != "_COMMA":
            if evaluated or (current and current[-1] == "_COMMA"):
                chunks.append(current)
                current, evaluated = [], False
            evaluated = part != "_NUMCOMMA"
        current.append(part)
    if current or not chunks:
        chunks.append(current)
    return chunks


def _simple_operand(code: str) -> bool:
    return code.replace("_", "a").replace("[", "").replace("]", "").isalnum()


class AreaCompiler:
    """Compiles the lines of one program area (see the module docstring)."""

    def __init__(self, lines: list, area: int = 0, direct: bool = False, entry_lines=(), trace: bool = False,
                 dynamic_loops=(), dialect=CASIO, def_types=None):
        self.area = area
        self.numbers = number_model(dialect, def_types)
        self.direct = direct
        self.trace = trace and not direct
        self.dynamic_loops = set(dynamic_loops)
        self.flat = flatten(lines)
        self.plan = plan(self.flat, entry_lines, self.dynamic_loops)
        self.line_first = {}
        for i, (number, _) in enumerate(self.flat):
            self.line_first.setdefault(number, i)
        self.entry_block = {idx: b for b, idx in enumerate(self.plan.entries)}
        self.blocks: list[_Block] = [_Block(b) for b in range(len(self.plan.entries))]
        self.block_next: dict[int, int] = {}
        self.while_block: dict[int, int] = {}  # id(WHILE in an IF branch) -> its block
        self.branch_after: dict[int, _Block] = {}  # id(WEND or NEXT in an IF branch) -> the block after it
        self.prelude: list[str] = []
        self.scalars: set[str] = set()
        self.cur: _Block | None = None
        self.indent = 0
        self.depth = 0  # IF nesting
        self.index = 0  # current top-level statement
        self.line = None
        self.temp = 0
        self.fn_count = 0
        self.data: list = []
        self.data_lines: dict = {}
        self.scope = _BlockScope(self)
        self.counting_vars: set[str] = set()  # native loop variables that stay >= 0
        self.idle_body = False  # the native loop being compiled has an empty body
        self.whole_index: dict[str, str] = {}  # constant loop variable -> local of its subscript
        self.open_loops: list[tuple] = []  # the native loops around the code being emitted
        self.break_infos: list[tuple] = []  # #BREAK#k markers: (BASIC line, open loops)
        self.break_points: dict[int, dict] = {}  # block -> {Python line: (BASIC line, open loops)}
        self.fn_params: dict[str, list] = {}  # DEF FN name -> parameter names
        # under OPTION BASE 1 a constant subscript 0 must go through the check
        self.lowest_fast_subscript = 1 if self.plan.option_base else 0

    # -- emission primitives
    def emit(self, text: str) -> None:
        self.cur.code.append((self.indent, text))

    def new_temp(self) -> str:
        self.temp += 1
        return f"_t{self.temp}"

    def new_block(self) -> _Block:
        block = _Block(len(self.blocks))
        self.blocks.append(block)
        return block

    def block_of_line(self, line: int) -> int | None:
        index = self.line_first.get(line)
        return None if index is None else self.entry_block[index]

    def jump(self, line: int) -> str:
        block = self.block_of_line(line)
        if block is None:
            if self.direct:
                return f"raise _DirectJump({line})"
            return f"raise _err('Undefined line number {line}', {UNDEFINED_LINE})"
        return f"return {block}"

    # -- expressions
    def expr(self, node, scope) -> tuple[str, str]:
        """(Python source, "n" or "s") for an expression node."""
        method = getattr(self, "expr_" + type(node).__name__)
        return method(node, scope)

    def numeric(self, node, scope) -> str:
        return self.typed(node, scope)[0]

    def typed(self, node, scope) -> tuple[str, str]:
        """(code, numeric type) of a numeric expression; a string is Type mismatch."""
        code, kind = self.expr(node, scope)
        if kind not in NUMERIC:
            raise _type_mismatch()
        return code, kind

    def kind_of(self, node) -> str:
        """The type of a variable, array element or FN reference (``"s"`` or numeric)."""
        if isinstance(node, (ast.Var, ast.Elem, ast.FnCall)):
            return self.numbers.kind(node.name)
        return ast.expr_type(node)

    def string(self, node, scope) -> str:
        code, kind = self.expr(node, scope)
        if kind != "s":
            raise _type_mismatch()
        return code

    def expr_Num(self, node, scope):
        return self.numbers.literal(node.value, node.kind)

    def expr_Str(self, node, scope):
        return repr(node.value), "s"

    def expr_Var(self, node, scope):
        return scope.scalar(node.name), self.kind_of(node)

    def expr_Elem(self, node, scope):
        return self.element(node, scope), self.kind_of(node)

    def element(self, node, scope) -> str:
        code = scope.array(node.name, len(node.indices))
        for index in node.indices:
            if isinstance(index, ast.Num) and index.value >= self.lowest_fast_subscript \
                    and index.value == int(index.value):
                code += f"[{int(index.value)}]"
            elif isinstance(index, ast.Var) and index.name in self.whole_index and isinstance(scope, _BlockScope):
                code += f"[{self.whole_index[index.name]}]"  # the subscript of a constant loop's value
            elif isinstance(index, ast.Var) and index.name in self.counting_vars and isinstance(scope, _BlockScope) \
                    and not self.plan.option_base:
                code += f"[int({scope.scalar(index.name)} + 0.5)]"  # a loop variable known to be >= 0
            else:
                code += f"[_ix({self.numeric(index, scope)})]"
        return code

    def expr_Unary(self, node, scope):
        operand, kind = self.typed(node.operand, scope)
        if node.op == "NOT":
            return self.numbers.logical_not(operand)
        return self.numbers.negate(operand, kind) if node.op == "-" else (operand, kind)

    def expr_Binary(self, node, scope):
        op = node.op
        left, lkind = self.expr(node.left, scope)
        right, rkind = self.expr(node.right, scope)
        if op in _PY_RELATIONS:
            if (lkind == "s") != (rkind == "s"):
                raise _type_mismatch()
            return self.numbers.truth(f"{left} {_PY_RELATIONS[op]} {right}")
        if op == "+" and lkind == "s" and rkind == "s":
            return f"_cat({left}, {right})", "s"
        if lkind not in NUMERIC or rkind not in NUMERIC:
            raise _type_mismatch()
        if op in ("+", "-", "*", "/"):
            # a left-leaning chain (A+B+C...) stays flat: Python groups + - and * / the same way
            group = ("+", "-") if op in ("+", "-") else ("*", "/")
            # (not a gw double's range-checked result, "(_w if ...)": number_models)
            if (isinstance(node.left, ast.Binary) and node.left.op in group and left.startswith("(")
                    and not left.startswith(RANGE_CHECKED)):
                left = left[1:-1]
            return self.numbers.arithmetic(op, left, lkind, right, rkind)
        if op == "^":
            if self.numbers.typed:
                return self.numbers.power(left, lkind, right, rkind)
            if (self.numbers.square_by_product and isinstance(node.right, ast.Num)
                    and node.right.value == 2.0 and _simple_operand(left)):
                return f"({left} * {left})", "n"
        return self.numbers.helper(op, left, right)

    def expr_Call(self, node, scope):
        forms, result, helper = _FUNCTIONS[node.name]
        args = list(node.args)
        if node.name == "RND" and (not args or (len(args) == 1 and (_constant_value(args[0]) or 0) > 0)):
            return self.numbers.call("RND", "_rndf", [], [], "n")  # the next number (the generator's drawer)
        form = _call_form(forms, [ast.expr_type(arg) for arg in args])
        codes, kinds = [], []
        for arg, want in zip(args, form):
            if want == "s" or (want == "x" and ast.expr_type(arg) == "s"):
                code, kind = self.string(arg, scope), "s"
            else:
                code, kind = self.typed(arg, scope)
            codes.append(self.numbers.printable(code, kind) if node.name == "STR$" else code)
            kinds.append(kind)
        return self.numbers.call(node.name, helper, codes, kinds, result)

    def expr_FnCall(self, node, scope):
        params = self.fn_params.get(self.numbers.name(node.name))
        if params is not None:  # a DEF FN of this area: check the call against it
            if len(params) != len(node.args):
                raise _syntax_error()
            for param, arg in zip(params, node.args):
                if (ast.expr_type(arg) == "s") != (self.numbers.kind(param) == "s"):
                    raise _type_mismatch()
        scope.uses_fn = True
        args = []
        for k, arg in enumerate(node.args):
            code, kind = self.expr(arg, scope)
            if params is not None and kind in NUMERIC:
                code = self.numbers.convert(code, kind, self.numbers.kind(params[k]))
            args.append(code)
        name = self.numbers.name(node.name)
        return f"_fn({name!r}, {len(node.args)})({', '.join(args)})", self.kind_of(node)

    def expr_SysVar(self, node, scope):
        if node.name == "PI":
            return repr(math.pi), "n"
        code, kind = _SYSTEM_VARIABLES[node.name]
        return code, kind or self.numbers.integer

    def condition(self, node, scope) -> str:
        """A Python boolean expression for an IF condition."""
        if isinstance(node, ast.Binary) and node.op in _PY_RELATIONS:
            left, lkind = self.expr(node.left, scope)
            right, rkind = self.expr(node.right, scope)
            if (lkind == "s") != (rkind == "s"):
                raise _type_mismatch()
            return f"{left} {_PY_RELATIONS[node.op]} {right}"
        if isinstance(node, ast.Binary) and node.op in ("AND", "OR") and _is_relation(node):
            word = node.op.lower()
            return f"({self.condition(node.left, scope)}) {word} ({self.condition(node.right, scope)})"
        if isinstance(node, ast.Unary) and node.op == "NOT" and _is_relation(node.operand):
            return f"not ({self.condition(node.operand, scope)})"
        return f"{self.numeric(node, scope)} != 0"

    # -- statements
    def statement(self, stmt) -> None:
        """Emit one statement; a compile error becomes a run-time raise of its line."""
        if isinstance(stmt, BasicError):
            self.emit(f"raise _err({stmt.message!r}, {stmt.code})")
            return
        mark = len(self.cur.code)
        block = self.cur
        scope = _BlockScope(self)
        try:
            getattr(self, "stmt_" + type(stmt).__name__)(stmt, scope)
        except (CompileError, RecursionError) as exc:
            err = exc if isinstance(exc, CompileError) else CompileError("Out of memory", OUT_OF_MEMORY)
            if self.cur is block:
                del block.code[mark:]
            self.emit(f"raise _err({err.message!r}, {err.code})")
            return
        if self.cur is block and _too_deep(block.code[mark:]):
            del block.code[mark:]  # Python could not compile it: the statement's own error
            self.emit(f"raise _err('Out of memory', {OUT_OF_MEMORY})")
            return
        if scope.uses_fn:
            block.code.insert(mark, (self.indent, "#FLUSH#"))

    def assign(self, target, value_code: str, value_kind: str, scope, check: bool) -> None:
        """Store ``value_code`` in a variable or element; ``check`` adds the Overflow test.

        A number is converted to the target's numeric type (GW-BASIC's types)."""
        target_kind = self.kind_of(target)
        if (target_kind == "s") != (value_kind == "s"):
            raise _type_mismatch()
        if value_kind != "s":
            value_code = self.numbers.convert(value_code, value_kind, target_kind)
        if isinstance(target, ast.Var):
            name = scope.scalar(target.name, write=True)
            if check:  # checked before the store: a trapped Overflow leaves the variable as it was
                self.emit(f"_t = {value_code}")
                self.emit(f"if _t - _t: _t = _ovf(_t, {target_kind!r})")
                value_code = "_t"
            self.emit(f"{name} = {value_code}")
            return
        element = self.element(target, scope)
        if check:
            self.emit(f"_t = {value_code}")
            self.emit(f"if _t - _t: _t = _ovf(_t, {target_kind!r})")
            value_code = "_t"
        self.emit(f"{element} = {value_code}")

    def stmt_Let(self, stmt, scope):
        code, kind = self.expr(stmt.value, scope)
        check = kind != "s" and _may_overflow(stmt.value, self.numbers.typed) and self.kind_of(stmt.target) != "%"
        self.assign(stmt.target, code, kind, scope, check)

    def stmt_Rem(self, stmt, scope):
        pass

    def stmt_Data(self, stmt, scope):
        pass

    def print_items(self, items, scope) -> tuple[list, bool]:
        """The Python parts of PRINT items (values, _COMMA, _Tab, _Spc) and whether a newline ends it."""
        parts = []
        for k, item in enumerate(items):
            if item == ",":
                parts.append("_COMMA")
            elif item == ";":
                continue
            elif isinstance(item, ast.Tab):
                parts.append(f"_Tab({self.numeric(item.column, scope)})")
            elif isinstance(item, ast.Spc):
                parts.append(f"_Spc({self.numeric(item.count, scope)})")
            else:
                try:
                    code, kind = self.expr(item, scope)
                except CompileError as err:  # e.g. Type mismatch: the items before it still print
                    parts.append(f"_fail({err.message!r}, {err.code})")
                    return parts, False
                if kind != "s" and items[k + 1:k + 2] == [","]:
                    parts.append("_NUMCOMMA")  # a number a comma follows (see Machine._blank_before_comma)
                parts.append(self.numbers.printable(code, kind))
        # a PRINT ending in a separator, TAB(n) or SPC(n) keeps the line open
        newline = not items or not (items[-1] in (",", ";") or isinstance(items[-1], (ast.Tab, ast.Spc)))
        return parts, newline

    def stmt_Print(self, stmt, scope):
        """PRINT / LPRINT [USING]: items are printed as they are evaluated, so an item
        that fails leaves the ones before it on the screen (as GW-BASIC does)."""
        device, pr, pru = 1 if stmt.printer else 0, "_pr", "_pru"
        if stmt.channel is not None:  # PRINT #n: the file's stream, found once
            device, pr, pru = self.new_temp(), "_prf", "_pruf"
            self.emit(f"{device} = _fout({self.numeric(stmt.channel, scope)})")
        parts, newline = self.print_items(stmt.items, scope)
        safe = all(_is_safe_item(item) for item in stmt.items)
        if stmt.using is None:
            chunks = _print_chunks(parts) if not safe else [parts]
            for k, chunk in enumerate(chunks):
                last = k == len(chunks) - 1
                values = "(" + "".join(p + ", " for p in chunk) + ")"
                self.emit(f"{pr}({device}, {values}, {newline and last}, {last})")
            return
        fmt = self.string(stmt.using, scope)
        parts = [p for p in parts if p not in ("_COMMA", "_NUMCOMMA") and not p.startswith(("_Tab(", "_Spc("))]
        if safe:
            values = "(" + "".join(p + ", " for p in parts) + ")"
            self.emit(f"{pru}({device}, {fmt}, {values}, {newline})")
            return
        self.emit("_u = []")
        self.emit("try:")
        for part in parts:
            self.emit(f"    _u.append({part})")
        self.emit("except BaseException:")
        self.emit(f"    {pru}({device}, {fmt}, _u, False)")
        self.emit("    raise")
        self.emit(f"{pru}({device}, {fmt}, _u, {newline})")

    def stmt_Goto(self, stmt, scope):
        self.emit(self.jump(stmt.target))

    def continuation(self) -> int:
        """The block where code after the current statement goes (a return point)."""
        if self.depth == 0:
            block = self.entry_block[self.index + 1]
            self.cur = None
            return block
        block = self.new_block()
        self.cur = block
        self.indent = 1
        self.emit(f"_ln = {self.line}")
        return block.number

    def stmt_Gosub(self, stmt, scope):
        if stmt.target in self.plan.bare_returns:
            # a subroutine that is a plain RETURN: push and pop in place (a full stack
            # is still Out of memory at the GOSUB; TRON still shows the RETURN's line)
            self.emit("#FULL#")  # the full-stack check (see block_source)
            if self.trace:
                self.emit(f"_tr({stmt.target})")
            return
        target = self.jump(stmt.target)
        block, indent = self.cur, self.indent
        ret = self.continuation()
        block.code.append((indent, f"if len(_stk) >= {MAX_STACK}: _oom()"))
        block.code.append((indent, f"_stk.append({ret})"))
        block.code.append((indent, target))

    def stmt_GosubProg(self, stmt, scope):
        self.emit("#FLUSH#")
        self.emit(f"_call({stmt.area}, _ln)")
        self.emit("#RELOAD#")

    def stmt_Return(self, stmt, scope):
        # the common case inline: a GOSUB's return block on top of the stack
        self.emit("if _stk and type(_stk[-1]) is int: return _stk.pop()")
        self.emit("return _return()")

    def stmt_OnJump(self, stmt, scope):
        selector = self.numeric(stmt.selector, scope)
        k = self.new_temp()
        self.emit(f"{k} = _on({selector}, {len(stmt.targets)})")
        jumps = [self.jump(t) for t in stmt.targets]
        if not stmt.gosub:
            for n, jump in enumerate(jumps, 1):
                self.emit(f"if {k} == {n}: {jump}")
            return
        block, indent = self.cur, self.indent
        self.emit(f"if {k}:")
        ret = self.continuation()
        block.code.append((indent + 1, f"_gosub({ret})"))
        for n, jump in enumerate(jumps, 1):
            block.code.append((indent + 1, f"if {k} == {n}: {jump}"))
        block.code.append((indent, f"return {ret}"))

    def stmt_OnError(self, stmt, scope):
        if stmt.target == 0:
            self.emit("_error_off()")
            return
        block = self.block_of_line(stmt.target)
        if block is None:
            self.emit(self.jump(stmt.target))
            return
        self.emit(f"_M.on_error = ({self.area}, {block})")

    def stmt_End(self, stmt, scope):
        self.emit("raise _END")

    def stmt_Stop(self, stmt, scope):
        block, indent = self.cur, self.indent
        ret = self.continuation()
        block.code.append((indent, f"_stop({ret})"))

    def stmt_Trace(self, stmt, scope):
        """TRON / TROFF: the machine swaps in the other variant; the next block is its."""
        block, indent = self.cur, self.indent
        ret = self.continuation()
        block.code.append((indent, f"_M.set_trace({stmt.on})"))
        block.code.append((indent, f"return {ret}"))

    def stmt_Cls(self, stmt, scope):
        self.emit("_M.clear_screen()")

    def stmt_Width(self, stmt, scope):
        if stmt.device is not None:
            if self.kind_of(stmt.device) != "s":
                raise _syntax_error()  # WIDTH n, rows: the screen rows are not emulated
            device = self.string(stmt.device, scope)
            self.emit(f"_M.set_device_width({device}, {self.numeric(stmt.columns, scope)})")
            return
        if self.kind_of(stmt.columns) == "s":
            raise _syntax_error()  # WIDTH "LPT1:" without its width
        self.emit(f"_M.set_width({self.numeric(stmt.columns, scope)}, {stmt.printer})")

    def stmt_Dim(self, stmt, scope):
        for name, sizes in stmt.arrays:
            name = self.numbers.name(name)
            codes = ", ".join(self.numeric(s, scope) for s in sizes)
            self.emit(f"_dim({name!r}, ({codes},))")
            self.emit(f"#ARRAY#{name}")

    def stmt_Clear(self, stmt, scope):
        if stmt.args:
            sizes = ", ".join("None" if a is None else self.numeric(a, scope) for a in stmt.args)
            self.emit(f"_clear_args({sizes})")
        self.emit("_clear()")
        self.emit("#RELOAD#")

    # -- GW-BASIC's statements (issue 12)
    def stmt_While(self, stmt, scope):
        found = self.plan.while_wend.get(id(stmt))
        if found is None:
            raise CompileError("WHILE without WEND", WHILE_WITHOUT_WEND)
        if self.depth:  # inside an IF branch: a block starts here, for WEND to come back to
            block, indent = self.cur, self.indent
            self.while_block[id(stmt)] = start = self.continuation()
            block.code.append((indent, f"return {start}"))
        self.emit(f"if not ({self.condition(stmt.condition, scope)}): return {self.after(*found).number}")

    def after(self, index: int, node) -> _Block:
        """The block where execution goes on after ``node`` (a WEND, or a NEXT a FOR that
        runs zero times goes on after) in statement ``index``: inside an IF branch, a
        block of its own that the rest of the branch is compiled into."""
        if node is self.flat[index][1]:
            return self.blocks[self.entry_block[index + 1]]
        block = self.branch_after.get(id(node))
        if block is None:
            block = self.branch_after[id(node)] = self.new_block()
        return block

    def continue_after(self, node, fall_through: bool) -> None:
        """Inside an IF branch: compile the rest of the branch into the block after
        ``node`` (see :meth:`after`), which the code so far enters if ``fall_through``."""
        block = self.after(self.index, node)
        if fall_through:
            self.emit(f"return {block.number}")
        self.cur, self.indent = block, 1
        self.emit(f"_ln = {self.line}")

    def stmt_Wend(self, stmt, scope):
        found = self.plan.wend_while.get(id(stmt))
        start = None
        if found is not None:
            index, loop = found
            start = self.entry_block[index] if loop is self.flat[index][1] else self.while_block.get(id(loop))
        if start is None:
            raise CompileError("WEND without WHILE", WEND_WITHOUT_WHILE)
        self.emit(f"return {start}")
        if self.depth:  # the rest of the IF branch goes on in the block after the WEND
            self.continue_after(stmt, fall_through=False)

    def stmt_Swap(self, stmt, scope):
        first, kind = self.expr(stmt.first, scope)
        second, other = self.expr(stmt.second, scope)
        if kind != other:
            raise _type_mismatch()
        t = self.new_temp()
        self.emit(f"{t} = {first}")
        self.assign(stmt.first, second, kind, scope, False)
        self.assign(stmt.second, t, kind, scope, False)

    def stmt_MidAssign(self, stmt, scope):
        target = self.string(stmt.target, scope)
        count = "None" if stmt.count is None else self.numeric(stmt.count, scope)
        code = f"_midset({target}, {self.numeric(stmt.start, scope)}, {count}, {self.string(stmt.value, scope)})"
        self.assign(stmt.target, code, "s", scope, False)

    def stmt_Erase(self, stmt, scope):
        for name in stmt.names:
            self.emit(f"_erase({self.numbers.name(name)!r})")

    def stmt_OptionBase(self, stmt, scope):
        self.emit(f"_option_base({stmt.base})")

    def stmt_LineInput(self, stmt, scope):
        if stmt.channel is not None:
            self.assign(stmt.target, f"_fline({self.numeric(stmt.channel, scope)})", "s", scope, False)
            return
        self.assign(stmt.target, f"_line_input({stmt.prompt!r}, {self.asking_again()})", "s", scope, False)

    def stmt_Write(self, stmt, scope):
        if stmt.channel is not None:
            stream = self.new_temp()
            self.emit(f"{stream} = _fout({self.numeric(stmt.channel, scope)})")
            self.emit(f"_writef({stream}, ({self.written_items(stmt.items, scope)}))")
            return
        self.emit(f"_write(0, ({self.written_items(stmt.items, scope)}))")

    # -- sequential files (files.py)
    def stmt_Open(self, stmt, scope):
        self.emit(f"_open({self.string(stmt.mode, scope)}, {self.numeric(stmt.number, scope)}, "
                  f"{self.string(stmt.name, scope)})")

    def stmt_Close(self, stmt, scope):
        self.emit(f"_close(({''.join(self.numeric(n, scope) + ', ' for n in stmt.numbers)}))")

    def stmt_Kill(self, stmt, scope):
        self.emit(f"_kill({self.string(stmt.name, scope)})")

    def stmt_Rename(self, stmt, scope):
        self.emit(f"_rename({self.string(stmt.old, scope)}, {self.string(stmt.new, scope)})")

    def stmt_Files(self, stmt, scope):
        self.emit(f"_files({'None' if stmt.pattern is None else self.string(stmt.pattern, scope)})")

    def written_items(self, items, scope) -> str:
        """WRITE's items as Python text pieces: strings in quotes, numbers as STR$ gives
        them without the blank (the caller joins them with commas)."""
        pieces = []
        for item in items:
            code, kind = self.expr(item, scope)
            if kind == "s":
                pieces.append(f"'\"' + {code} + '\"'")
            else:
                pieces.append(f"_strs({self.numbers.printable(code, kind)}).strip()")
        return "".join(piece + ", " for piece in pieces)

    def stmt_ReturnTo(self, stmt, scope):
        jump = self.jump(stmt.target)
        self.emit("_return()")
        self.emit(jump)

    def stmt_Read(self, stmt, scope):
        for target in stmt.targets:
            kind = "s" if self.kind_of(target) == "s" else self.numbers.widest
            self.assign(target, "_read_s()" if kind == "s" else "_read_n()", kind, scope,
                        self.numbers.typed and kind != "s")  # beyond the range: Overflow's policy

    def stmt_Restore(self, stmt, scope):
        if stmt.target is not None and stmt.target not in self.line_first:
            self.emit(f"raise _err('Undefined line number {stmt.target}', {UNDEFINED_LINE})")
            return
        self.emit(f"_restore({stmt.target!r})")

    def stmt_Input(self, stmt, scope):
        if stmt.channel is not None:  # INPUT #n: one field for each variable, stored at once
            channel = self.numeric(stmt.channel, scope)
            for target in stmt.targets:
                kind = self.kind_of(target)
                reader = "_fin_s" if kind == "s" else "_fin_n"
                self.assign(target, f"{reader}({channel})", "s" if kind == "s" else self.numbers.widest,
                            scope, self.numbers.typed and kind != "s")
            return
        kinds = "".join("s" if self.kind_of(t) == "s" else "n" for t in stmt.targets)
        values = self.new_temp()
        self.emit(f"{values} = _input({stmt.prompt!r}, {stmt.question_mark}, {kinds!r}, {self.asking_again()})")
        for n, target in enumerate(stmt.targets):
            self.assign(target, f"{values}[{n}]", "s" if kinds[n] == "s" else self.numbers.widest,
                        scope, self.numbers.typed and kinds[n] != "s")

    def asking_again(self) -> tuple | None:
        """For an INPUT or LINE INPUT that starts its block of area 0 (a top-level one):
        (that block, its line), where CONT after a Ctrl-C while it waits goes on, asking
        again (GW-BASIC); None for one inside an IF branch or another area."""
        if self.depth == 0 and self.index in self.entry_block and self.area == 0 and not self.direct:
            return self.cur.number, self.line
        return None

    def stmt_DefFn(self, stmt, scope):
        fn_scope = _FnScope(self, stmt.params)
        body, kind = self.expr(stmt.body, fn_scope)
        fn_kind = self.numbers.kind(stmt.name)
        if (kind == "s") != (fn_kind == "s"):
            raise _type_mismatch()
        if kind != "s":
            body = self.numbers.convert(body, kind, fn_kind)
        self.fn_count += 1
        fname = f"_fn_{self.fn_count}"
        params = ", ".join("p" + local_name(self.numbers.name(p)) for p in stmt.params)
        self.prelude.append(f"def {fname}({params}):\n    return {body}\n")
        self.emit(f"_M.fns[{self.numbers.name(stmt.name)!r}] = ({fname}, {len(stmt.params)})")

    def stmt_DefType(self, stmt, scope):
        pass  # applied to the whole program before compiling (number_models.TypedNumbers)

    def stmt_Resume(self, stmt, scope):
        if stmt.mode == "line":
            block = self.block_of_line(stmt.target)
            if block is None:
                self.emit(self.jump(stmt.target))
                return
            self.emit(f"return _resume_at({block})")
        else:
            self.emit(f"return _resume({stmt.mode == 'next'})")

    def stmt_Error(self, stmt, scope):
        self.emit(f"_error({self.numeric(stmt.code, scope)})")

    def stmt_Randomize(self, stmt, scope):
        seed = "None" if stmt.seed is None else self.numeric(stmt.seed, scope)
        self.emit(f"_randomize({seed}, {self.seed_kind(stmt.seed)!r})")

    def seed_kind(self, node) -> str:
        """The BASIC type RANDOMIZE sees its argument stored as (randomness.py): a
        variable's own type (``%`` ``!`` ``#``, DEF types included); an unsigned integer
        literal up to 32767 is ``%``, a double literal ``#``; any other expression ``!``
        (PC-BASIC 2.0.8 reads ``-1`` and ``0-1`` as singles here)."""
        if isinstance(node, ast.Num):
            if node.kind:  # gw: the literal's own type
                return node.kind
            return "%" if node.value == int(node.value) and 0 <= node.value <= 32767 else "!"
        if isinstance(node, (ast.Var, ast.Elem)):
            kind = self.kind_of(node)
            return kind if kind in ("%", "#") else "!"
        return "!"

    def stmt_Angle(self, stmt, scope):
        self.emit(f"_M.set_angle({stmt.mode!r})")

    def stmt_If(self, stmt, scope):
        cond = self.condition(stmt.condition, scope)
        branches = [b for b in (stmt.then, stmt.otherwise) if isinstance(b, list)]
        split = any(splits(s, self.plan.bare_returns) or isinstance(s, (ast.While, ast.Wend)) or self.zero_trip_target(s)
                    for b in branches for s in b)
        if not split:
            self.emit(f"if {cond}:")
            self.branch(stmt.then)
            if stmt.otherwise is not None:
                self.emit("else:")
                self.branch(stmt.otherwise)
            return
        if self.depth == 0:
            after = self.entry_block[self.index + 1]
            after_block = None
        else:
            after_block = self.new_block()
            after = after_block.number
        start, indent = self.cur, self.indent
        self.emit(f"if {cond}:")
        self.branch(stmt.then, after)
        self.cur, self.indent = start, indent
        self.emit("else:")
        if stmt.otherwise is not None:
            self.branch(stmt.otherwise, after)
        else:
            self.indent += 1
            self.emit(f"return {after}")
            self.indent -= 1
        self.cur, self.indent = after_block, 1
        if after_block is not None:
            self.emit(f"_ln = {self.line}")

    def branch(self, branch, after: int | None = None) -> None:
        """The statements of a THEN or ELSE, one indent deeper."""
        self.indent += 1
        self.depth += 1
        if isinstance(branch, int):
            self.emit(self.jump(branch))
        else:
            self.emit("pass")
            for stmt in branch:
                self.statement(stmt)
        if after is not None:
            self.block_next.setdefault(self.cur.number, after)
            self.emit(f"return {after}")
        self.depth -= 1
        self.indent -= 1

    # -- FOR / NEXT
    def loop_key(self, var) -> str:
        """The FOR-stack key of a control variable: ``I``, or ``A()`` for an element
        (gw: with its type character, ``I!``)."""
        name = self.numbers.name(var.name)
        return name if isinstance(var, ast.Var) else name + "()"

    def loop_var(self, var, scope) -> tuple[str, str]:
        """(Python target for the control variable, FOR-stack key)."""
        if self.kind_of(var) == "s":
            raise _type_mismatch()
        if isinstance(var, ast.Var):
            return scope.scalar(var.name, write=True), self.loop_key(var)
        return self.element(var, scope), self.loop_key(var)

    def stepping(self, var_node, var: str, step: str) -> str:
        """The code of ``var + step`` for a FOR variable (rounded to its type)."""
        return self.numbers.loop_helpers(self.kind_of(var_node))[1].format(var=var, step=step)

    def stmt_For(self, stmt, scope, native_next: int | None = None):
        kind = self.kind_of(stmt.var)
        if kind not in self.numbers.loop_types:
            raise _type_mismatch()
        convert = self.numbers.convert
        start = convert(*self.typed(stmt.start, scope), kind)
        limit = convert(*self.typed(stmt.stop, scope), kind)
        one = self.numbers.one()
        step = one if stmt.step is None else convert(*self.typed(stmt.step, scope), kind)
        var, key = self.loop_var(stmt.var, scope)
        n = self.new_temp()
        self.emit(f"_v{n} = {start}; _l{n} = {limit}; _s{n} = {step}")
        if isinstance(stmt.var, ast.Elem) and stmt.var.indices and not all(
                isinstance(i, ast.Num) for i in stmt.var.indices):
            raise _syntax_error()  # a computed subscript would be re-evaluated each pass
        self.emit(f"{var} = _v{n}")
        if native_next is not None:
            step_value = stmt.step.value if isinstance(stmt.step, ast.Num) else (
                1.0 if stmt.step is None else None)
            if step_value is not None and step_value > 0:
                test = f"{var} <= _l{n}"
            elif step_value is not None and step_value < 0:
                test = f"{var} >= _l{n}"
            else:
                test = f"({var} <= _l{n} if _s{n} >= 0.0 else {var} >= _l{n})"
            mode = self.loop_mode(stmt) if self.numbers.may_iterate(stmt, kind) else "while"
            if mode == "count":
                # the body neither reads nor changes the variable: count the passes
                self.emit(f"if {test}:")
                self.indent += 1
                self.emit(f"_it{n} = _fcount(_v{n}, _l{n}, _s{n})")
                if self.idle_body:  # an empty body: the passes are counted in C, in chunks
                    self.emit(f"_i{n} = 0")
                self.emit("try:")
                self.indent += 1
                self.emit(f"for _i{n} in {'_fidle(_it%s)' % n if self.idle_body else '_it%s' % n}:")
                return n, var, step_value, mode
            if mode == "constant":
                values, _ = self.constant_passes(stmt)
                self.emit(f"if {test}:")
                self.indent += 1
                first, last = self.loop_range
                indexing = any(isinstance(node, ast.Elem) and stmt.var in node.indices
                               for node in nodes([self.flat[k][1] for k in range(first + 1, last)]))
                if indexing and not self.plan.option_base and all(v == int(v) and 0 <= v < 2.0 ** 52 for v in values):
                    # the subscript of each value too: the body indexes arrays with it
                    self.whole_index[stmt.var.name] = f"_k{n}"
                    pairs = "".join(f"({int(v)}, {v!r}), " for v in values)
                    self.emit(f"for _k{n}, {var} in ({pairs}):")
                else:
                    self.emit(f"for {var} in ({''.join(f'{v!r}, ' for v in values)}):")
                return n, var, step_value, mode
            if mode == "values":
                # the body never changes the variable: iterate over its values
                self.emit(f"if {test}:")
                self.indent += 1
                self.emit(f"for {var} in {self.numbers.loop_helpers(kind)[0]}(_v{n}, _l{n}, _s{n}):")
                return n, var, step_value, mode
            self.emit(f"if {test}:")
            self.indent += 1
            self.emit(f"while {test}:")
            return n, var, step_value, mode
        body = self.entry_block.get(self.index + 1) if self.depth == 0 else None
        skip_index = self.plan.for_next.get(self.index) if self.depth == 0 else None
        if skip_index is None:
            skip_index = self.plan.branch_for_next.get(id(stmt))
        block, indent = self.cur, self.indent
        self.emit(f"if _v{n} <= _l{n} if _s{n} >= 0.0 else _v{n} >= _l{n}:")
        if body is None:
            body_block = self.continuation()
        else:
            body_block = body
            self.cur = None
        block.code.append((indent + 1, f"_for({key!r}, _l{n}, _s{n}, {body_block}, {self.bound_next(stmt)!r})"))
        block.code.append((indent + 1, f"return {body_block}"))
        # a loop that never runs leaves its variable at the start value (GW-BASIC's
        # source: FOR hands over to NEXTS in NEXT86.ASM with NXTFLG = 0; see compatibility.md)
        bound = self.bound_next(stmt)
        if bound:  # GW-BASIC: no NEXT, or one naming another loop, is an error; else go on after it
            block.code.append((indent, f"_M.bound_next({bound!r})"))
            after = self.after(bound[0], self.scanned_next(stmt)[1]).number
            block.code.append((indent, f"if _M.dialect.for_binds_next: return {after}"))
        elif bound is None:
            block.code.append((indent, "_M.bound_next(None)"))
        if skip_index is None:
            block.code.append((indent, f"raise _err('FOR without NEXT', {FOR_WITHOUT_NEXT})"))
        else:
            block.code.append((indent, f"return {self.entry_block[skip_index + 1]}"))
        return None

    def bound_next(self, stmt):
        """What GW-BASIC's FOR finds scanning for its NEXT (``Machine.for_push``):
        ``(statement index, line, names this loop?)``, None for no NEXT.  A FOR inside
        an IF branch scans on from itself through the rest of its IF statement."""
        found = self.scanned_next(stmt)
        if found is None:
            return None
        k, next_stmt = found
        return (k, self.flat[k][0], next_stmt.var is None or next_stmt.var == stmt.var)

    def scanned_next(self, stmt):
        """``(statement index, NEXT)`` that the FOR ``stmt``'s scan finds, or None."""
        return scan_for_next([s for _, s in self.flat], self.index + 1, stmt if self.depth else None)

    def zero_trip_target(self, stmt) -> bool:
        """Does ``stmt`` hold, in an IF branch, a NEXT that a zero-trip FOR goes on after?"""
        return any(id(s) in self.plan.branch_nexts for s in walk_statements(stmt, unreachable=False))

    def stmt_Next(self, stmt, scope):
        var = stmt.var
        if var is None and self.depth == 0 and self.index in self.plan.next_for:
            var = self.flat[self.plan.next_for[self.index]][1].var
        if var is None:
            self.emit("#FLUSH#")
            self.emit("if _next_any(): return _M.frame_body")
            self.emit("#RELOAD#")
        else:
            target, key = self.loop_var(var, scope)
            self.emit(f"_f = _next({key!r}, {self.index})")
            self.emit(f"{target} = {self.stepping(var, target, '_f.step')}")
            self.emit(f"if {target} <= _f.limit if _f.step >= 0.0 else {target} >= _f.limit: return _f.body")
            self.emit("_pop()")
        if id(stmt) in self.plan.branch_nexts:  # a zero-trip FOR goes on here, inside the branch
            self.continue_after(stmt, fall_through=True)

    def loop_mode(self, stmt) -> str:
        """How to run the native loop now being compiled.

        ``"while"``: test and add the step each pass (always right; used for a
        short loop with constant bounds, or when the body may change the variable);
        ``"constant"``: such a short loop in plain doubles iterates over a tuple of
        its values made at compile time (:meth:`constant_passes`), with each value's
        subscript beside it when all are whole numbers >= 0 and the body indexes
        an array with the variable;
        ``"values"``: ``for var in _frange(...)`` when nothing in the body can
        change the variable; ``"count"``: ``for _ in range(n)`` when the body does
        not even read it (the variable's value is set after the loop, or on an error).
        """
        if not self.iterable_loop(stmt.var):
            return "while"
        start, stop = _constant_value(stmt.start), _constant_value(stmt.stop)
        step = 1.0 if stmt.step is None else _constant_value(stmt.step)
        if start is not None and stop is not None and step and 0 <= (stop - start) / step < 16:
            return "constant" if self.constant_passes(stmt) else "while"
        first, last = self.loop_range
        body = [self.flat[k][1] for k in range(first + 1, last)]
        if any(isinstance(node, ast.FnCall) or node == stmt.var for node in nodes(body)):
            return "values"
        return "count"

    def counts_up_from_zero(self, stmt) -> bool:
        """Does the loop's variable stay >= 0 in its body (constant start >= 0, step > 0,
        never assigned there)?  Then it can index arrays without the subscript check."""
        start_ok = isinstance(stmt.start, ast.Num) and stmt.start.value >= 0
        step_ok = stmt.step is None or (isinstance(stmt.step, ast.Num) and stmt.step.value > 0)
        return start_ok and step_ok and self.iterable_loop(stmt.var)

    def iterable_loop(self, var) -> bool:
        """May the native loop now being compiled iterate instead of testing?

        Only when nothing in its body can change the control variable: it is a
        scalar, no statement assigns it, and nothing outside the block (an area,
        CLEAR) runs inside the loop.
        """
        if not isinstance(var, ast.Var):
            return False
        first, last = self.loop_range
        for k in range(first + 1, last):
            for s in walk_statements(self.flat[k][1]):
                if isinstance(s, (ast.GosubProg, ast.Clear)):
                    return False
                targets = []
                if isinstance(s, (ast.Let,)):
                    targets = [s.target]
                elif isinstance(s, (ast.Read, ast.Input)):
                    targets = s.targets
                elif isinstance(s, ast.For):
                    targets = [s.var]
                if var in targets:
                    return False
        return True

    # -- the program walk
    def set_line(self, number) -> None:
        if self.cur.first_line is None:
            self.cur.first_line = number
        self.emit(f"_ln = {number}")
        self.line = number

    def walk(self, start: int, stop: int) -> None:
        """Emit top-level statements ``start``..``stop-1``."""
        i = start
        while i < stop:
            number, stmt = self.flat[i]
            self.index = i
            if i in self.entry_block:
                if self.cur is not None:
                    self.emit(f"return {self.entry_block[i]}")
                self.cur = self.blocks[self.entry_block[i]]
                self.indent = 1
                self.line = None
                if self.plan.fine:
                    self.block_next[self.cur.number] = self.entry_block.get(
                        min(e for e in self.plan.entries if e > i))
            if number != self.line:
                self.set_line(number)
            self.trace_line(i)
            if i in self.plan.native:
                i = self.native_loop(i)
                continue
            self.statement(stmt)
            i += 1

    def trace_line(self, i: int) -> None:
        """TRON: print ``[n]`` where statement ``i`` starts its line ``n``."""
        number = self.flat[i][0]
        if self.trace and self.line_first[number] == i:
            self.emit(f"_tr({number})")

    def constant_passes(self, stmt) -> tuple[list, float] | None:
        """A short loop known at compile time: (the values of the variable, one per pass;
        its value after the loop), found by adding the step as the loop does.

        Only for a scalar FOR with constant bounds and fewer than 16 passes (the short
        loops :meth:`loop_mode` would run as ``while``, and those that never run) whose numbers are plain doubles
        stepped by a plain ``+`` (the casio dialect's); None for any other loop.
        """
        if self.numbers.typed or self.numbers.loop_helpers("n")[1] != "{var} + {step}":
            return None
        if not isinstance(stmt.var, ast.Var) or self.kind_of(stmt.var) == "s":
            return None
        value, limit = _constant_value(stmt.start), _constant_value(stmt.stop)
        step = 1.0 if stmt.step is None else _constant_value(stmt.step)
        if value is None or limit is None or step is None or not step or not (limit - value) / step < 16:  # (a loop that never runs is one too)
            return None
        values = []
        while (value <= limit) if step > 0 else (value >= limit):
            values.append(value)
            value = value + step
        return values, value

    def native_loop(self, i: int) -> int:
        """Emit FOR at ``i`` ... its NEXT as a Python while loop; the index after NEXT."""
        j = self.plan.native[i]
        stmt = self.flat[i][1]
        scope = _BlockScope(self)
        # nothing between FOR and NEXT (and no TRON line marks): a delay loop
        self.idle_body = j == i + 1 and not self.trace
        passes = self.constant_passes(stmt) if self.idle_body else None
        if passes is not None:  # a short delay loop: its variable's final value
            self.emit(f"{scope.scalar(stmt.var.name, write=True)} = {passes[1]!r}")
            self.line = None
            self.set_line(self.flat[j][0])
            return j + 1
        block, mark = self.cur, len(self.cur.code)
        self.loop_range = (i, j)
        try:
            n, var, step_value, mode = self.stmt_For(stmt, scope, native_next=j)
        except CompileError as err:
            del block.code[mark:]
            self.emit(f"raise _err({err.message!r}, {err.code})")
            return i + 1
        counting = self.counts_up_from_zero(stmt)
        if counting:
            self.counting_vars.add(stmt.var.name)
        self.indent += 1
        # The top of a pass is where a Ctrl-C may stop the loop so that CONT resumes it:
        # its line is the atomic ``_ln = n`` (nothing in it can be interrupted half-way).
        self.open_loops.append((i, self.loop_key(stmt.var), n, mode,
                                local_name(self.numbers.name(stmt.var.name)) if isinstance(stmt.var, ast.Var)
                                else None))
        self.emit(f"#BREAK#{len(self.break_infos)}")
        self.break_infos.append((self.flat[i + 1][0], tuple(self.open_loops)))
        self.line = None
        # (the line of the body's first statement, where a break lands; the FOR's for an empty body)
        self.set_line(self.flat[i + 1][0] if j > i + 1 else self.flat[i][0])
        body_mark = len(self.cur.code)
        self.walk(i + 1, j)
        self.trace_line(j)  # a NEXT that starts its line
        self.open_loops.pop()
        if len(self.cur.code) == body_mark:
            self.emit("pass")  # an empty body (a delay loop)
        if counting:
            self.counting_vars.discard(stmt.var.name)
        self.index = j  # (stepping cannot fail, so NEXT's line needs no marker in the loop)
        increment = repr(step_value) if step_value is not None and not self.numbers.typed else f"_s{n}"
        increment = self.stepping(stmt.var, var, increment)
        if mode == "count":
            self.indent -= 2
            self.emit("except BaseException:")
            self.emit(f"    {var} = _fvalue(_it{n}, _v{n}, _s{n}, _i{n})")
            self.emit("    raise")
            self.emit(f"{var} = _fafter(_it{n}, _v{n}, _s{n})")
        elif mode == "values":
            self.indent -= 1
            self.emit(f"{var} = {increment}")
        elif mode == "constant":
            self.indent -= 1
            self.emit(f"{var} = {self.constant_passes(stmt)[1]!r}")
            self.whole_index.pop(stmt.var.name, None)
        else:
            self.emit(f"{var} = {increment}")
            self.indent -= 1
        self.indent -= 1
        # a loop that never runs leaves its variable at the start value (see stmt_For)
        self.line = None
        self.set_line(self.flat[j][0])
        return j + 1

    # -- the whole area
    def compile(self) -> CompiledArea:
        """Generate every block of the area (DEF types, DATA and DEF FN collected first)."""
        self.numbers.set_types(s for _, stmt in self.flat if not isinstance(stmt, BasicError)
                               for s in walk_statements(stmt) if isinstance(s, ast.DefType))
        for i, (number, stmt) in enumerate(self.flat):
            for s in ([] if isinstance(stmt, BasicError) else data_statements(stmt)):
                self.data_lines.setdefault(number, len(self.data))
                self.data.extend((item, number) for item in split_data(s.text))
        for _, stmt in self.flat:
            for s in ([] if isinstance(stmt, BasicError) else walk_statements(stmt)):
                if isinstance(s, ast.DefFn):
                    self.fn_params.setdefault(self.numbers.name(s.name), s.params)
        self.walk(0, len(self.flat))
        end = self.entry_block[len(self.flat)]
        if self.cur is not None:
            self.emit(f"return {end}")
        self.cur = self.blocks[end]
        self.indent = 1
        self.set_line(self.flat[-1][0] if self.flat else 0)
        self.emit("raise _END")
        pieces = [(None, text) for text in self.prelude]
        pieces += [(b.first_line, self.block_source(b)) for b in self.blocks]
        source = "\n".join(text for _, text in pieces)
        line_blocks = {number: self.entry_block[i] for number, i in self.line_first.items()
                       if i in self.entry_block}
        return CompiledArea(
            source=source, pieces=pieces, block_count=len(self.blocks), line_blocks=line_blocks,
            block_next=self.block_next, data=self.data, data_lines=self.data_lines,
            scalars=set(self.scalars), first_line=self.flat[0][0] if self.flat else None,
            index_blocks=dict(self.entry_block), break_points=self.break_points,
            dynamic_loops=tuple(sorted(self.dynamic_loops)), def_types=self.numbers.def_types(),
        )

    def block_source(self, block: _Block) -> str:
        """The Python text of one block function.

        Its break points (see :class:`CompiledArea`) go to ``self.break_points``:
        the ``continue`` lines of a block that loops back to its own start, and the
        line marked ``#BREAK#k`` at the top of each native loop's pass.
        """
        points: dict[int, tuple] = {}
        pending = None  # a #BREAK# marker waiting for the line it marks
        names = sorted(block.scalars)
        written = [n for n in names if block.scalars[n]]
        load = "; ".join(f"{local_name(n)} = _S[{n!r}]" for n in names)
        load_arrays = "; ".join(f"{array_local(a)} = _A.get({a!r}) or _arr({a!r}, {d})"
                                for a, d in sorted(block.arrays.items()))
        store = "; ".join(f"_S[{n!r}] = {local_name(n)}" for n in written)
        loop_back = f"return {block.number}"
        self_loop = any(text == loop_back or text.endswith(": " + loop_back) for _, text in block.code)
        # A GOSUB compiled in place checks for a full stack.  Every push onto the stack
        # ends its block, so unless the block pops (a NEXT through the stack), clears
        # or calls out, the stack's length cannot change while the block runs: it is
        # measured once, as the block starts.
        full_check = f"if len(_stk) >= {MAX_STACK}: _oom()"
        if any(text == "#FULL#" for _, text in block.code) and not any(
                name in text for _, text in block.code for name in _STACK_CHANGES):
            full_check = "if _full: _oom()"
        base = 2 if self_loop else 1
        out = [f"def _b{block.number}():"]
        for text in (load, load_arrays):
            if text:
                out.append("    " + text)
        out.append("    _ln = None")
        if full_check == "if _full: _oom()":
            out.append(f"    _full = len(_stk) >= {MAX_STACK}")
        out.append("    try:")
        if self_loop:
            out.append("        while True:")
        for indent, text in block.code:
            pad = "    " * (indent + base)
            if text == "#FLUSH#":
                if store:
                    out.append(pad + store)
                continue
            if text == "#RELOAD#":
                for part in (load, load_arrays):
                    if part:
                        out.append(pad + part)
                continue
            if text.startswith("#ARRAY#"):
                name = text[7:]
                if name in block.arrays:
                    out.append(pad + f"{array_local(name)} = _A[{name!r}]")  # just dimensioned
                continue
            if text == "#FULL#":
                text = full_check
            if text.startswith("#BREAK#"):
                pending = self.break_infos[int(text[7:])]
                continue
            if self_loop and (text == loop_back or text.endswith(": " + loop_back)):
                if text != loop_back:  # "if c: return b": the continue on a line of its own
                    out.append(pad + text[: -len(loop_back) - 1])
                    pad += "    "
                points[len(out) + 1] = (block.first_line, ())  # (lines count from 1: def is 1)
                text = "continue"
            if pending is not None:
                points[len(out) + 1], pending = pending, None
            out.append(pad + text)
        if not block.code:
            out.append("    " * (1 + base) + "pass")
        out.append("    finally:")
        if store:
            out.append("        " + store)
        out.append("        _M.line = _ln")
        if points:
            self.break_points[block.number] = points
        return "\n".join(out) + "\n"


def split_data(text: str) -> list[str]:
    """The items of a DATA statement's text: commas outside quotes separate them."""
    items, current, quoted = [], [], False
    for ch in text:
        if ch == '"':
            quoted = not quoted
            current.append(ch)
        elif ch == "," and not quoted:
            items.append("".join(current).strip())
            current = []
        else:
            current.append(ch)
    items.append("".join(current).strip())
    return items


def compile_area(lines: list, area: int = 0, direct: bool = False, entry_lines=(),
                 trace: bool = False, dynamic_loops=(), dialect=CASIO, def_types=None) -> CompiledArea:
    """Compile an area's parsed lines (``syntax_tree.Line`` in line order) for ``dialect``.

    ``entry_lines`` are lines that must start a block although no jump names
    them (RUN n, or a GOTO typed in direct mode); ``trace`` compiles the TRON
    variant (see the module docstring); ``dynamic_loops`` are the statement
    indices of FOR loops to run through the FOR stack even where they could be
    native (CONT resumes a native loop broken by Ctrl-C that way).
    """
    return AreaCompiler(lines, area, direct, entry_lines, trace, dynamic_loops, dialect, def_types).compile()
