"""Expressions -> Python: the half of the area compiler that turns expression nodes into
Python source (``AreaCompiler`` in compiler.py mixes it in).

Every expression compiles to ``(Python source, kind)``: kind ``"s"`` for a string,
else the numeric type the number model (number_models.py) gives it.  Here too are the
tables of built-in functions and system variables, the scopes that name variables
(Python locals in a block, globals and parameters in a DEF FN body), and the
predicates on expression nodes that let the statements skip checks (a constant, a
relation, an expression that cannot overflow).
"""

from __future__ import annotations

import math

from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.compile.number_models import NUMERIC, RANGE_CHECKED, array_local, local_name
from yaseer.basic.errors import BasicError, STRING_TOO_LONG, SYNTAX_ERROR, TYPE_MISMATCH
from yaseer.basic.arithmetic.single_arith import SMALL_CONSTANT
from yaseer.basic.arithmetic.values import INT_MAX


_PY_RELATIONS = {"=": "==", "<>": "!=", "<": "<", ">": ">", "<=": "<=", ">=": ">="}

# name -> (argument kinds of each accepted form, result type, Python callable in the
# namespace); a kind is "n" number, "i" an integer argument (see integer), "s" string,
# "x" either (FRE).
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
    # GW-BASIC's own functions
    "INSTR": (("ss", "nss"), "n", "_instr"), "STRING$": (("nn", "ns"), "s", "_string"),
    "SPACE$": (("n",), "s", "_space"), "HEX$": (("n",), "s", "_hex"), "OCT$": (("n",), "s", "_oct"),
    "MKI$": (("n",), "s", "_mki"), "MKS$": (("n",), "s", "_mks"), "MKD$": (("n",), "s", "_mkd"),
    "CVI": (("s",), "n", "_cvi"), "CVS": (("s",), "n", "_cvs"), "CVD": (("s",), "n", "_cvd"),
    "FRE": (("x",), "n", "_fre"), "POS": (("x",), "n", "_pos"), "LPOS": (("i",), "n", "_lpos"),
    "EOF": (("i",), "n", "_eof"), "LOF": (("i",), "n", "_lof"), "LOC": (("i",), "n", "_loc"),
    "INPUT$": (("i", "ii"), "s", "_input_chars"),
    "PEEK": (("n",), "n", "_peek"), "USR": (("x",), "n", "_usr"),
    "SCREEN": (("nn", "nnn"), "n", "_M.screen_char"),
}

# the functions that use a string argument up without making a string of it (gw's string
# space gives a temporary's bytes back: BISTRS.ASM LEN1, STRCMP, INSTR and STRNG$ call FRESTR)
_USING_UP = frozenset({"LEN", "ASC", "VAL", "INSTR", "STRING$", "CVI", "CVS", "CVD"})

# Values without arguments: name -> (Python expression, "s", "!" for the single type (a
# double made one) or None for the integer type).
_SYSTEM_VARIABLES = {
    "ERR": ("_M.err", None), "ERL": ("_M.erl", None), "TIMER": ("_timer()", "!"),
    "DATE$": ("_date()", "s"), "TIME$": ("_time()", "s"), "INKEY$": ("_inkey()", "s"),
    "CSRLIN": ("_M.cursor_row()", None),
}


_CUTS = (ast.CutCall, ast.CutExpression)  # expressions the text cuts short: they raise when reached


def _call_form(forms: tuple, kinds: list) -> str:
    """The form of a function that takes arguments of ``kinds`` ("s"/"n"): wrong count
    Syntax error, wrong types Type mismatch."""
    same_length = [form for form in forms if len(form) == len(kinds)]
    if not same_length:
        raise syntax_error()
    for form in same_length:
        if all(want in ("x", kind) or (want, kind) == ("i", "n") for want, kind in zip(form, kinds)):
            return form
    raise type_mismatch()


def _read_in_order(name: str, forms: tuple, readings: tuple) -> bool:
    """Whether a call of ``name`` that does not fit it is read argument by argument, where the
    dialect reads so (``Dialect.argument_readings``): the functions with a reading of their
    own (machine/argument_reading.py) and those of one argument."""
    return bool(readings) and (name in readings or all(len(form) == 1 for form in forms))


class CompileError(BasicError):
    """A statement that cannot be compiled; it becomes a run-time error of its line."""


def syntax_error() -> CompileError:
    return CompileError("Syntax error", SYNTAX_ERROR)


def type_mismatch() -> CompileError:
    return CompileError("Type mismatch", TYPE_MISMATCH)


# How the test of a making starts (compiler.made).
MAKING = "if _f and "


class BlockScope:
    """Variable references inside a block: Python locals."""

    def __init__(self, compiler: "ExpressionCompiler"):
        self.compiler = compiler
        self.uses_fn = False

    def scalar(self, name: str, write: bool = False) -> str:
        block = self.compiler.cur
        name = self.compiler.numbers.name(name)
        self.compiler.scalars.add(name)
        block.scalars[name] = block.scalars.get(name, False) or write
        return local_name(name)

    def array(self, name: str, ndim: int, made: bool = False) -> str:
        """The local of array ``name``; ``made``: the code has made it just before (LET)."""
        block = self.compiler.cur
        name = self.compiler.numbers.name(name)
        block.arrays.setdefault(name, ndim)
        local = array_local(name)
        if self.compiler.counts_made and not made:  # made where it is first used, not as the block starts
            self.compiler.note_making(name + "()")  # (compiler.made: the block's flag waits for it too)
            return f"({local} or ({local} := _arr({name!r}, {ndim})))"
        return local


class FnScope:
    """Variable references inside a DEF FN body: parameters are locals, the rest global."""

    def __init__(self, compiler: "ExpressionCompiler", params: list):
        self.compiler = compiler
        self.params = {compiler.numbers.name(p) for p in params}
        self.uses_fn = False

    def scalar(self, name: str, write: bool = False) -> str:
        name = self.compiler.numbers.name(name)
        if name in self.params:
            return "p" + local_name(name)
        self.compiler.scalars.add(name)
        return f"_S[{name!r}]"

    def array(self, name: str, ndim: int, made: bool = False) -> str:
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


def _without_effects(node) -> bool:
    """Can evaluating ``node`` neither draw RND, call anything nor fail (relations,
    AND/OR/NOT of scalar variables and literals only)?"""
    if isinstance(node, (ast.Num, ast.Str, ast.Var)):
        return True
    if isinstance(node, ast.Binary) and (node.op in _PY_RELATIONS or node.op in ("AND", "OR")):
        return _without_effects(node.left) and _without_effects(node.right)
    return isinstance(node, ast.Unary) and node.op == "NOT" and _without_effects(node.operand)


def _is_constant(node) -> bool:
    return isinstance(node, ast.Num) or (isinstance(node, ast.Unary) and _is_constant(node.operand))


_BOUNDED = frozenset({"RND", "SIN", "COS", "SGN"})  # results in [-1, 1]


def _is_small(node, single: bool = False) -> bool:
    """A constant, or a function whose result is at most 1 in size (RND, SIN, COS, SGN):
    added to a finite double it cannot give an infinity.  (``single``: the typed
    model, whose range ends at 1.7E+38: a constant below SMALL_CONSTANT, less than half
    a unit of the largest single, cannot carry a sum beyond it.)"""
    if isinstance(node, ast.Call):
        return node.name in _BOUNDED
    if single:
        value = constant_value(node)
        return value is not None and abs(value) < SMALL_CONSTANT
    return _is_constant(node)


def constant_value(node) -> float | None:
    """The value of a number literal, or of one with signs before it (``-1.5``); else None."""
    if isinstance(node, ast.Num):
        return float(node.value)
    if isinstance(node, ast.Unary) and node.op in "+-":
        value = constant_value(node.operand)
        return None if value is None else (-value if node.op == "-" else value)
    return None


def may_overflow(node, single: bool = False) -> bool:
    """Could this numeric expression produce inf from finite values?  (``single``: the
    typed model, where adding a constant may leave the single range too.)"""
    if isinstance(node, ast.Binary):
        if node.op in ("*", "/"):
            return True
        if node.op in ("+", "-") and not (_is_small(node.left, single) or _is_small(node.right, single)):
            return True
        return may_overflow(node.left, single) or may_overflow(node.right, single)
    if isinstance(node, ast.Unary):
        return may_overflow(node.operand, single)
    if isinstance(node, ast.Call):
        return any(may_overflow(a, single) for a in node.args)
    return isinstance(node, ast.FnCall)


def calls_fn(node) -> bool:
    """Does this expression's value come (in part) from a DEF FN?"""
    if isinstance(node, ast.FnCall):
        return True
    if isinstance(node, ast.Binary):
        return calls_fn(node.left) or calls_fn(node.right)
    if isinstance(node, ast.Unary):
        return calls_fn(node.operand)
    return isinstance(node, ast.Call) and any(calls_fn(a) for a in node.args)


def makes_string(node, named=None) -> bool:
    """Can evaluating ``node`` make a new string (take string space, maybe collect)?
    (``named``: the type of a name, as for ``syntax_tree.expr_type``.)"""
    if isinstance(node, (ast.Call, ast.SysVar)) and node.name.endswith("$"):
        return True
    if isinstance(node, ast.FnCall) or (isinstance(node, ast.Binary) and node.op == "+"
                                         and ast.expr_type(node, named) == "s"):
        return True
    if isinstance(node, ast.Binary):
        return makes_string(node.left, named) or makes_string(node.right, named)
    if isinstance(node, ast.Unary):
        return makes_string(node.operand, named)
    return isinstance(node, (ast.Call, ast.Elem)) and any(
        makes_string(arg, named) for arg in (node.args if isinstance(node, ast.Call) else node.indices))


def _temporary(node, named=None) -> bool:
    """Is ``node``'s value a string an operation made (not a variable's or a literal)?"""
    return ast.expr_type(node, named) == "s" and not isinstance(node, (ast.Str, ast.Var, ast.Elem))


_MAKERS = frozenset(helper for _, result, helper in _FUNCTIONS.values() if result == "s") | {"_cat"}


def _used_at_once(node, code: str) -> str:
    """``code`` of a new string used up as soon as it is made: the making function's
    ``_u`` form (it needs the room, a collection if there is none, but leaves the count as
    it was: machine/string_space.py), else ``_drop`` of it."""
    helper = code[:code.find("(")]
    if helper in _MAKERS and isinstance(node, (ast.Call, ast.Binary)):
        return f"{helper}_u{code[len(helper):]}"
    return f"_drop({code})"


def _simple_operand(code: str) -> bool:
    return code.replace("_", "a").replace("[", "").replace("]", "").isalnum()


class ExpressionCompiler:
    """The expression methods of ``AreaCompiler`` (they use its ``numbers``, ``plan``,
    ``fn_params``, ``string_length`` and the native-loop facts ``whole_index`` and
    ``counting_vars``)."""

    def held(self, nodes, codes: list, used_up: bool = False) -> int:
        """Hold each temporary string of ``nodes`` (their Python ``codes``, changed in place)
        while a later one can make a string, so that a collection then keeps it (gw's
        string space, machine/string_space.py); the number held (``_free`` lets them go).
        ``used_up``: the operation makes no string of them, so each gives its bytes back
        when it is the last made (``_drop`` now, ``_release`` for those held)."""
        if not self.counts_strings:
            return 0
        held = 0
        named = self.numbers.kind
        for k, node in enumerate(nodes):
            if not _temporary(node, named):
                continue
            if any(makes_string(later, named) for later in nodes[k + 1:]):
                codes[k] = f"_hold({codes[k]})"
                held += 1
            elif used_up:
                codes[k] = _used_at_once(node, codes[k])
        return held

    def let_go(self, code: str, held: int, used_up: bool = False) -> str:
        """``code`` letting its ``held`` temporaries go (see :meth:`held`)."""
        if not held:
            return code
        return f"{'_release' if used_up else '_free'}({code}{'' if held == 1 else f', {held}'})"

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
            raise type_mismatch()
        return code, kind

    def integer(self, node, scope) -> str:
        """An integer argument (a count, a code, a file or record length, a selector): in a
        dialect with integers made one as CINT makes it (GW's GETBYT, GETIN2 and the
        statements that take a word call FRCINT first, GWEVAL.ASM: beyond -32768..32767
        ``Overflow`` before any range of their own), else the number as it is."""
        code, kind = self.typed(node, scope)
        return self.numbers.convert(code, kind, "%")

    def when_reached(self, make) -> str:
        """The code ``make()`` compiles, or where it finds an error (a string where a number
        must be) code raising that error when the program gets there: a statement that
        checks other things first (a file number) raises those first."""
        try:
            return make()
        except CompileError as err:
            return f"_fail({err.message!r}, {err.code})"

    def kind_of(self, node) -> str:
        """The type of a variable, array element or FN reference (``"s"`` or numeric)."""
        if isinstance(node, (ast.Var, ast.Elem, ast.FnCall)):
            return self.numbers.kind(node.name)
        return ast.expr_type(node, self.numbers.kind)

    def type_of(self, node) -> str:
        """``"s"`` or ``"n"``: the type of expression ``node``, its names typed as the
        DEF types of this compile make them (gw's DEFSTR)."""
        return ast.expr_type(node, self.numbers.kind)

    def string(self, node, scope) -> str:
        code, kind = self.expr(node, scope)
        if kind != "s":
            raise type_mismatch()
        return code

    def expr_Num(self, node, scope):
        return self.numbers.literal(node.value, node.kind)

    def expr_Str(self, node, scope):
        if len(node.value) > self.string_length:  # an error where the literal is used, as for a string built too long
            return f"_fail('String too long', {STRING_TOO_LONG})", "s"
        return repr(node.value), "s"

    def expr_Var(self, node, scope):
        return scope.scalar(node.name), self.kind_of(node)

    def expr_Elem(self, node, scope):
        return self.element(node, scope), self.kind_of(node)

    def element(self, node, scope, made: bool = False) -> str:
        """The Python target of array element ``node``; ``made``: the array was made just before."""
        code = scope.array(node.name, len(node.indices), made)
        return code + "".join(f"[{index}]" for index in self.subscripts(node, scope))

    def subscripts(self, node, scope) -> list[str]:
        """The Python subscripts (list indices) of array element ``node``, one a dimension."""
        codes = []
        for index in node.indices:
            if isinstance(index, ast.Num) and self.lowest_fast_subscript <= index.value <= INT_MAX \
                    and index.value == int(index.value):
                codes.append(str(int(index.value)))
            elif isinstance(index, ast.Var) and index.name in self.whole_index and isinstance(scope, BlockScope):
                codes.append(self.whole_index[index.name])  # the subscript of a constant loop's value
            elif isinstance(index, ast.Var) and index.name in self.counting_vars and isinstance(scope, BlockScope) \
                    and not self.plan.option_base:
                rounding = "" if self.words.truncates else " + 0.5"
                codes.append(f"int({scope.scalar(index.name)}{rounding})")  # a loop variable known to be >= 0
            else:
                codes.append(f"_ix({self.numeric(index, scope)})")
        return codes

    def expr_Unary(self, node, scope):
        if node.op != "NOT" and self.numbers.typed:
            operand, kind = self.expr(node.operand, scope)
            if kind == "s":  # GW's $VNEG flips a sign bit beside a string's descriptor: the string
                return operand, kind
        operand, kind = self.typed(node.operand, scope)
        if node.op == "NOT":
            return self.numbers.logical_not(operand)
        return self.numbers.negate(operand, kind) if node.op == "-" else (operand, kind)

    def expr_Binary(self, node, scope):
        op = node.op
        left, lkind = self.expr(node.left, scope)
        right, rkind = self.expr(node.right, scope)
        if isinstance(node.right, _CUTS) or isinstance(node.left, _CUTS):
            return f"({left}, {right})[0]", lkind  # both read in order, the cut raising: no types to match
        if lkind == "s" and rkind == "s" and (op in _PY_RELATIONS or op == "+"):
            codes = [left, right]
            relation = op in _PY_RELATIONS
            held = self.held([node.left, node.right], codes, used_up=relation)
            if relation:
                return self.numbers.truth(self.let_go(f"{codes[0]} {_PY_RELATIONS[op]} {codes[1]}", held, True))
            if held:  # (the sum lets its held left side go itself)
                return f"_cath({codes[0]}, {codes[1]})", "s"
            return f"_cat({codes[0]}, {codes[1]})", "s"
        if op in _PY_RELATIONS:
            if (lkind == "s") != (rkind == "s"):
                raise type_mismatch()
            return self.numbers.truth(f"{left} {_PY_RELATIONS[op]} {right}")
        if lkind not in NUMERIC or rkind not in NUMERIC:
            raise type_mismatch()
        if op in ("+", "-", "*", "/"):
            # a left-leaning chain (A+B+C...) stays flat: Python groups + - and * / the same way
            group = ("+", "-") if op in ("+", "-") else ("*", "/")
            # (not a gw double's range-checked or a single's tested result, "(_w if ...)": number_models)
            if (isinstance(node.left, ast.Binary) and node.left.op in group and left.startswith("(")
                    and not left.startswith(RANGE_CHECKED)):
                left = left[1:-1]
            return self.numbers.arithmetic(op, left, lkind, right, rkind)
        if op == "^":
            if self.numbers.typed:
                whole = (isinstance(node.left, ast.Var) and node.left.name in self.whole_vars
                         and isinstance(scope, BlockScope))
                return self.numbers.power(left, lkind, right, rkind, whole)
            if (self.numbers.square_by_product and isinstance(node.right, ast.Num)
                    and node.right.value == 2.0 and _simple_operand(left)):
                return self.numbers.arithmetic("*", left, lkind, left, lkind)
        return self.numbers.helper(op, left, right)

    def expr_Call(self, node, scope):
        own = self.own_functions.get(node.name)  # the dialect's own words (dialects/casio.py)
        forms, result, helper = own[1:] if own else _FUNCTIONS[node.name]
        args = list(node.args)
        if forms == ("v",):  # VARPTR(variable): a variable's name (and an element's subscripts), not its value
            if len(args) != 1 or not isinstance(args[0], (ast.Var, ast.Elem)):
                raise syntax_error()
            codes = [repr(self.numbers.name(args[0].name))]
            if isinstance(args[0], ast.Elem):
                codes.append("(" + "".join(self.typed(i, scope)[0] + ", " for i in args[0].indices) + ")")
            return self.numbers.call(node.name, helper, codes, ["s"] * len(codes), result)
        # RND, or RND(x) with a constant x > 0 that a single holds (a larger one is Overflow
        # as it is made a single: the general call below)
        if node.name == "RND" and (not args or (len(args) == 1 and 0 < (constant_value(args[0]) or 0) < 1e38)):
            return self.numbers.call("RND", "_rndf", [], [], "n")  # the next number (the generator's drawer)
        if node.name in ast.KEEPS_STRINGS and self.numbers.typed and len(args) == 1 and self.type_of(args[0]) == "s":
            return self.string(args[0], scope), "s"
        try:
            form = _call_form(forms, [self.type_of(arg) for arg in args])
        except CompileError as err:
            if (own and node.name not in self.reads_arguments_in_order) \
                    or not _read_in_order(node.name, forms, self.reads_arguments_in_order):
                raise
            return self.read_in_order(node, scope, err.message, err.code, ".close()"), (
                "s" if result == "s" else self.numbers.integer)
        codes, kinds = [], []
        for arg, want in zip(args, form):
            if want == "s" or (want == "x" and self.type_of(arg) == "s"):
                code, kind = self.string(arg, scope), "s"
            elif want == "i":
                code, kind = self.integer(arg, scope), "%"
            else:
                code, kind = self.typed(arg, scope)
            codes.append(self.numbers.printable(code, kind) if node.name == "STR$" else code)
            kinds.append(kind)
        if (own and node.name in self.words.reads_variables) or node.name == "FRE":
            scope.uses_fn = True  # VALF and FRE read the variables: the block's values are stored first
        if own and node.name in self.words.sets_x_y:
            return self.pair_to_x_y(f"{helper}({', '.join(codes)})", scope), "n"
        used_up = node.name in _USING_UP
        held = self.held(args, codes, used_up)
        if held:
            code, kind = self.numbers.call(node.name, helper, codes, kinds, result)
            return self.let_go(code, held, used_up), kind
        return self.numbers.call(node.name, helper, codes, kinds, result)

    def read_in_order(self, node, scope, message: str, code: int, end: str) -> str:
        """A call whose arguments do not fit its function, as GW-BASIC reads it: each argument
        evaluated and checked in turn, ``end`` (``.close()`` or a cut) raising what comes then
        (machine/argument_reading.py); ``message``, ``code``: the error should the reading
        accept it all."""
        checks = getattr(self.device_words, "argument_checks", {}).get(node.name, ()) if self.device_words else ()
        codes = [self.expr(arg, scope)[0] for arg in node.args]
        codes = [f"{checks[k]}({code})" if k < len(checks) else code for k, code in enumerate(codes)]
        reads = "".join(f".a({code})" for code in codes)
        return f"_rd({node.name!r}, {message!r}, {code}){reads}{end}"

    def expr_CutCall(self, node, scope):
        """A call the text cuts short (``INSTR(-1``, ``MID$("A", 1, "B"``): its arguments read
        in order, then the cut's error where the reading meets it."""
        end = f".cut({node.after_comma}, {node.error.message!r}, {node.error.code})"
        own = self.own_functions.get(node.name)  # (token type, forms, result, helper)
        forms, result = own[1:3] if own else _FUNCTIONS.get(node.name, (None, "n"))[:2]
        if forms == ("v",):  # VARPTR(: a variable's name must follow (GWEVAL.ASM VARPTR: PTRGTN)
            raise syntax_error()
        if forms is None or not _read_in_order(node.name, forms, self.reads_arguments_in_order):
            raise CompileError(node.error.message, node.error.code)
        return self.read_in_order(node, scope, "Syntax error", SYNTAX_ERROR, end), (
            "s" if result == "s" else self.numbers.integer)

    def expr_CutExpression(self, node, scope):
        """What an expression cut short after an operator read (evaluated), then its error."""
        code, kind = self.expr(node.read, scope)
        return f"_fail_after({code}, {node.error.message!r}, {node.error.code})", kind

    def pair_to_x_y(self, pair: str, scope) -> str:
        """POL and REC (POL.md, REC.md): the pair ``pair`` is computed, its values go to
        the variables X and Y, and the first is the function's value."""
        if isinstance(scope, FnScope):  # the Casio has no DEF FN; its body cannot set variables
            raise syntax_error()
        x, y = scope.scalar("X", write=True), scope.scalar("Y", write=True)
        temp = self.new_temp()
        return f"({x} := ({temp} := {pair})[0], {y} := {temp}[1])[0]"

    def expr_FnCall(self, node, scope):
        params = self.fn_params.get(self.numbers.name(node.name))
        if params is not None:  # a DEF FN of this area: check the call against it
            if len(params) != len(node.args):
                raise syntax_error()
            for param, arg in zip(params, node.args):
                if (self.type_of(arg) == "s") != (self.numbers.kind(param) == "s"):
                    raise type_mismatch()
        scope.uses_fn = True
        args = []
        for k, arg in enumerate(node.args):
            code, kind = self.expr(arg, scope)
            if params is not None and kind in NUMERIC:
                code = self.numbers.convert(code, kind, self.numbers.kind(params[k]))
            args.append(code)
        name = self.numbers.name(node.name)
        held = self.held(list(node.args), args)
        return self.let_go(f"_fn({name!r}, {len(node.args)})({', '.join(args)})", held), self.kind_of(node)

    def expr_FilePointer(self, node, scope):
        """``WORD(#n)`` (VARPTR(#n)): the dialect's function of a file number, else Syntax error."""
        helper = self.device_words.file_functions.get(node.name) if self.device_words else None
        if helper is None:
            raise syntax_error()
        if self.type_of(node.number) == "s":
            raise type_mismatch()
        result = "s" if node.name.endswith("$") else "n"
        return self.numbers.call(node.name, helper, [self.numeric(node.number, scope)], ["n"], result)

    def expr_CutFileCall(self, node, scope):
        """``WORD(#n`` cut before its ``)``: n read and its file checked as the word checks it
        (gw_words.FILE_CHECKS), then the cut's error; a word without such a check: the error."""
        check = self.device_words.file_checks.get(node.name) if self.device_words else None
        if check is None:
            raise CompileError(node.error.message, node.error.code)
        if ast.expr_type(node.number) == "s":
            raise type_mismatch()
        kind = "s" if node.name.endswith("$") else self.numbers.integer
        return f"_fail_after({check}({self.numeric(node.number, scope)}), {node.error.message!r}, {node.error.code})", kind

    def expr_SysVar(self, node, scope):
        if node.name == "PI":
            return self.numbers.pi, "n"
        code, kind = _SYSTEM_VARIABLES.get(node.name) or self.device_words.system_values[node.name]
        if kind == "!":
            return self.numbers.convert(code, "#", "!"), self.numbers.single
        return code, kind or self.numbers.integer

    def condition(self, node, scope) -> str:
        """A Python boolean expression for an IF condition."""
        if isinstance(node, ast.Binary) and node.op in _PY_RELATIONS:
            left, lkind = self.expr(node.left, scope)
            right, rkind = self.expr(node.right, scope)
            if (lkind == "s") != (rkind == "s"):
                raise type_mismatch()
            codes = [left, right]
            if lkind == "s":
                held = self.held([node.left, node.right], codes, used_up=True)
                return self.let_go(f"{codes[0]} {_PY_RELATIONS[node.op]} {codes[1]}", held, True)
            return f"{left} {_PY_RELATIONS[node.op]} {right}"
        if isinstance(node, ast.Binary) and node.op in ("AND", "OR") and _is_relation(node):
            # AND and OR are operators, not control flow: both sides run (an RND or an
            # error on the right happens whatever the left gives); Python's short-cut
            # words only where the right side can have no effect
            word = node.op.lower() if _without_effects(node.right) else {"AND": "&", "OR": "|"}[node.op]
            return f"({self.condition(node.left, scope)}) {word} ({self.condition(node.right, scope)})"
        if isinstance(node, ast.Unary) and node.op == "NOT" and _is_relation(node.operand):
            return f"not ({self.condition(node.operand, scope)})"
        return f"{self.numeric(node, scope)} != 0"
