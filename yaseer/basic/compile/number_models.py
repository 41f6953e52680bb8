"""How the compiler writes numbers: the dialect's number model, at compile time.

The compiler asks its model for the Python code of literals, arithmetic,
conversions and function results, and for the static type of every numeric
expression; :func:`number_model` picks the model from ``Dialect.typed_numbers``.

* :class:`PlainNumbers` (casio): one numeric type ``"n"``, a Python float;
  the code is what yaseer has always generated.
* :class:`TypedNumbers` (gw): types ``"%"`` (16-bit integer), ``"!"``
  (single, the default), ``"#"`` (double), ``"?"`` (VAL's: single or double as its
  text says, known when it runs: :mod:`yaseer.basic.machine.val_numbers`); ``"s"`` is a string in both.  A name
  without a type character gets its letter's type from DEFINT/DEFSNG/DEFDBL/
  DEFSTR (collected from the whole program before compiling, in program order:
  yaseer treats them as declarations, where GW-BASIC runs them as statements).
  Run-time helpers are in :mod:`yaseer.basic.arithmetic.values`.
"""

from __future__ import annotations

from yaseer.basic.arithmetic.single_arith import SMALL_CONSTANT

NUMERIC = frozenset("n%!#?")
_RANK = {"%": 0, "!": 1, "?": 1.5, "#": 2}


def local_name(name: str) -> str:
    """The Python local of scalar ``name``: ``n_QQ`` for QQ or QQ!, ``s_A`` for A$,
    ``i_A`` for A%, ``d_A`` for A# (a ``.`` in a GW name becomes ``_``)."""
    prefix = {"$": "s_", "%": "i_", "#": "d_", "!": "n_"}.get(name[-1])
    if prefix is None:
        return "n_" + name.replace(".", "_")
    return prefix + name[:-1].replace(".", "_")


def array_local(name: str) -> str:
    """The Python local holding array ``name`` (``a_``, ``b_`` for strings, ``ai_``, ``ad_``)."""
    prefix = {"$": "b_", "%": "ai_", "#": "ad_", "!": "a_"}.get(name[-1])
    if prefix is None:
        return "a_" + name.replace(".", "_")
    return prefix + name[:-1].replace(".", "_")


def initial_value(name: str):
    """A variable's value before it is assigned: "" for strings, 0 for ``%``, else 0.0."""
    last = name[-1]
    if last == "$":
        return ""
    return 0 if last == "%" else 0.0


class PlainNumbers:
    """The pocket computer's numbers: every value a double, type ``"n"``."""

    typed = False
    square_by_product = True  # X^2 may compile to X*X (exact in binary)
    loop_types = frozenset("n")  # the types a FOR variable may have
    widest = "n"  # the type of a number read by READ or INPUT (converted to the target's)
    integer = "n"  # the type of ERR, ERL

    def set_types(self, statements) -> None:
        """No DEF types in this model."""

    def def_types(self) -> dict:
        """letter -> type character set by DEF statements (none here)."""
        return {}

    def name(self, name: str) -> str:
        return name

    def kind(self, name: str) -> str:
        return "s" if name.endswith("$") else "n"

    def literal(self, value, kind: str) -> tuple[str, str]:
        return repr(float(value)), "n"

    def arithmetic(self, op: str, left: str, lkind: str, right: str, rkind: str) -> tuple[str, str]:
        """``+ - * /`` (plain Python operators on floats)."""
        return f"({left} {op} {right})", "n"

    def helper(self, op: str, left: str, right: str) -> tuple[str, str]:
        """``^ \\ MOD AND OR XOR EQV IMP`` through the runtime helpers."""
        names = {"^": "_pow", "\\": "_idiv", "MOD": "_mod", "AND": "_and", "OR": "_or",
                 "XOR": "_xor", "EQV": "_eqv", "IMP": "_imp"}
        return f"{names[op]}({left}, {right})", "n"

    def negate(self, operand: str, kind: str) -> tuple[str, str]:
        return f"(-{operand})", "n"

    def logical_not(self, operand: str) -> tuple[str, str]:
        return f"_not({operand})", "n"

    def truth(self, condition: str) -> tuple[str, str]:
        """-1 or 0 from a Python boolean."""
        return f"(-1.0 if {condition} else 0.0)", "n"

    def convert(self, code: str, source: str, target: str) -> str:
        return code

    def call(self, name: str, helper: str, codes: list[str], kinds: list[str], result: str) -> tuple[str, str]:
        """A built-in function call: ``helper`` (its runtime callable) applied to ``codes``
        (arguments of types ``kinds``); ``result`` is "s" or "n" from the function table."""
        return f"{helper}({', '.join(codes)})", result

    def printable(self, code: str, kind: str) -> str:
        return code

    def one(self) -> str:
        return "1.0"

    def loop_helpers(self, kind: str) -> tuple[str, str]:
        """(values helper, increment template) of a FOR loop over a variable of ``kind``."""
        return "_frange", "{var} + {step}"

    def may_iterate(self, stmt, kind: str) -> bool:
        """May a native loop iterate (count or values mode) rather than add the step itself?"""
        return True


class TypedNumbers(PlainNumbers):
    """GW-BASIC's typed numbers (see the module docstring)."""

    typed = True
    loop_types = frozenset("%!")  # FOR D# is Type mismatch in GW-BASIC (checked with PC-BASIC)
    widest = "#"
    integer = "%"
    _SUFFIX = {"INT": "%", "SNG": "!", "DBL": "#", "STR": "$"}
    # result types of the built-in functions: None keeps the argument's type
    _RESULTS = {
        "SIN": "!", "COS": "!", "TAN": "!", "ATN": "!", "SQR": "!", "EXP": "!", "LOG": "!",
        "RND": "!", "VAL": "?", "ABS": None, "INT": None, "FIX": None, "SGN": "%", "LEN": "%",
        "ASC": "%", "CINT": "%", "CSNG": "!", "CDBL": "#", "CVD": "#",
    }

    # functions GW-BASIC computes in single precision from an argument made single
    _SINGLE_FUNCTIONS = frozenset(("SIN", "COS", "TAN", "ATN", "SQR", "EXP", "LOG"))

    def __init__(self, def_types=None):
        self.letters: dict[str, str] = dict(def_types or {})

    def def_types(self) -> dict:
        return dict(self.letters)

    def set_types(self, statements) -> None:
        """Apply the program's DEFINT/DEFSNG/DEFDBL/DEFSTR statements (in order)."""
        for stmt in statements:
            for first, last in stmt.ranges:
                for code in range(ord(first), ord(last) + 1):
                    self.letters[chr(code)] = self._SUFFIX[stmt.kind]

    def name(self, name: str) -> str:
        if name[-1] in "$%!#":
            return name
        return name + self.letters.get(name[0], "!")

    def kind(self, name: str) -> str:
        last = self.name(name)[-1]
        return "s" if last == "$" else last

    def literal(self, value, kind: str) -> tuple[str, str]:
        if kind == "%":
            return repr(int(value)), "%"
        return repr(float(value)), kind or "#"

    def arithmetic(self, op: str, left: str, lkind: str, right: str, rkind: str) -> tuple[str, str]:
        kind = lkind if _RANK[lkind] >= _RANK[rkind] else rkind
        if kind == "?":  # VAL's with a single or integer: the type VAL's text gave (val_numbers.py)
            return (f"_vdv({left}, {right})" if op == "/" else f"_vop({op!r}, {left}, {right})"), "?"
        if op == "/":  # through the dialect's division-by-zero policy (arith_policy.py)
            if kind == "#":
                return f"_ddv({left}, {right})", "#"
            return f"_dv({left}, {right})", "!"
        if kind == "%":
            return f"_ia({left} {op} {right})", "%"
        if kind == "!":  # rounded as GW-BASIC's MBF routines round (single_arith.py)
            if op == "*":
                return f"_sp({left} * {right})", "!"
            helper = "_sadd" if op == "+" else "_ssub"
            if _plain_operand(left) and _plain_operand(right) and (_small_literal(left) or _small_literal(right)):
                # the tight loop's A=A+1: a sum that needs at most 24 bits is GW's result
                # (and cannot leave the range); tested inline by Veltkamp's split, which
                # gives the sum cut to 24 bits (no Python frame); any other through the helper
                return (f"(_sv if (_sv := {left} {op} {right}) == (_sc := _sv * 536870913.0) - (_sc - _sv) "
                        f"else {helper}({left}, {right}))"), "!"
            return f"{helper}({left}, {right})", "!"
        return _in_double_range(f"{left} {op} {right}"), "#"

    def helper(self, op: str, left: str, right: str) -> tuple[str, str]:
        names = {"\\": "_idiv", "MOD": "_mod", "AND": "_and", "OR": "_or", "XOR": "_xor",
                 "EQV": "_eqv", "IMP": "_imp"}
        return f"{names[op]}({left}, {right})", "%"

    def power(self, left: str, lkind: str, right: str, rkind: str) -> tuple[str, str]:
        """``^``: single precision, also of doubles (GW-BASIC's ``$FPWR`` makes both
        operands single: ``2#^.5`` is 1.414214); ``_spow`` in arith_policy.py."""
        return f"_spow({self.convert(left, lkind, '!')}, {self.convert(right, rkind, '!')})", "!"

    def negate(self, operand: str, kind: str) -> tuple[str, str]:
        if kind == "%":
            return f"_ia(-{operand})", "%"
        if kind == "?":
            return f"_vneg({operand})", "?"
        return f"(-{operand})", kind

    def logical_not(self, operand: str) -> tuple[str, str]:
        return f"_not({operand})", "%"

    def truth(self, condition: str) -> tuple[str, str]:
        return f"(-1 if {condition} else 0)", "%"

    def convert(self, code: str, source: str, target: str) -> str:
        """``code`` (of type ``source``) as a value of type ``target``.

        To ``%``: CINT with the 16-bit check, unless ``code`` is an integer variable or
        literal (an integer expression may have overflowed into single precision)."""
        if target == "%":
            if source == "%" and (code.startswith("i_") and code[2:].isidentifier() or _is_int_literal(code)):
                return code
            if code.startswith("_ia(") and code.endswith(")"):
                code = code[4:-1]  # to_int checks the 16-bit range itself
            return f"_ci({code})"
        if source == target or target == "#" or source == "%":
            return code
        return f"_sfd({code})"

    def call(self, name: str, helper: str, codes: list[str], kinds: list[str], result: str) -> tuple[str, str]:
        code = f"{helper}({', '.join(codes)})"
        if result == "s":
            return code, "s"
        kind = self._RESULTS.get(name, "!")
        if kind is None:  # ABS INT FIX keep the argument's type
            kind = kinds[0]
            if kind == "%":
                return (f"_ia({code})" if name == "ABS" else codes[0]), "%"
            if kind == "?":
                return f"_vlike({code}, {codes[0]})", "?"
            return code, kind
        if kind == "!":
            if name in self._SINGLE_FUNCTIONS and kinds and kinds[0] in "#?":  # computed on the single
                code = f"{helper}({', '.join([self.convert(codes[0], '#', '!')] + codes[1:])})"
            return f"_sfn({code})", "!"
        return code, kind

    def printable(self, code: str, kind: str) -> str:
        return f"_dbl({code})" if kind == "#" else code

    def one(self) -> str:
        return "1"

    def loop_helpers(self, kind: str) -> tuple[str, str]:
        if kind == "%":
            return "_irange", "_ci({var} + {step})"
        if kind == "!":
            return "_frange", "_sadd({var}, {step})"
        return "_frange", "_dk({var} + {step})"

    def may_iterate(self, stmt, kind: str) -> bool:
        """Single-precision loops iterate only over whole numbers (exact in single
        precision); any other must round each ``+ STEP``, so it adds the step itself."""
        if kind != "!":
            return True
        from yaseer.basic.source import syntax_tree as ast
        def whole(node) -> bool:
            return node is None or (isinstance(node, ast.Num) and float(node.value).is_integer())
        return whole(stmt.start) and whole(stmt.step)


RANGE_CHECKED = "(_w if "  # how the code of a range-checked double result starts


def _in_double_range(code: str) -> str:
    """``code`` (a double result) kept in MBF's range, 1.7D+38 (``values.DOUBLE_LARGEST``):
    beyond it ``_dk`` gives the overflow policy's value.  The test is inline (a
    chained comparison, no call: twice as fast in a double loop); ``_w`` is a scratch
    local, each use read before the next assignment."""
    return f"{RANGE_CHECKED}{-2.0 ** 127!r} <= (_w := {code}) <= {2.0 ** 127!r} else _dk(_w))"


def _small_literal(code: str) -> bool:
    """Is ``code`` a number literal below 1E+30 (far below a single's unit at 1.7E+38)?"""
    try:
        value = abs(float(code))
    except ValueError:
        return False
    # below SMALL_CONSTANT (far below a single's unit at 1.7E+38) and, unless 0, at
    # least 2**-100 (a nonzero exact sum with it is at least 2**-124, inside MBF's range)
    return value < SMALL_CONSTANT and (value == 0 or value >= 2.0 ** -100)


def _plain_operand(code: str) -> bool:
    """Is ``code`` a local name or a literal (free to evaluate twice)?"""
    return code.isidentifier() or _small_literal(code)


def _is_int_literal(code: str) -> bool:
    return code.lstrip("-").isdigit()


class DecimalNumbers(PlainNumbers):
    """``--arith decimal`` (casio): floats that stand for 13-digit decimals; ``+ - * /``,
    ``^``, literals and FOR steps through yaseer/basic/arithmetic/decimal_arith.py."""

    square_by_product = False
    _OPERATIONS = {"+": "_dadd", "-": "_dsub", "*": "_dmul", "/": "_ddiv13"}

    def literal(self, value, kind: str) -> tuple[str, str]:
        from yaseer.basic.arithmetic.decimal_arith import rounded

        return repr(rounded(float(value))), "n"

    def arithmetic(self, op: str, left: str, lkind: str, right: str, rkind: str) -> tuple[str, str]:
        return f"{self._OPERATIONS[op]}({left}, {right})", "n"

    def loop_helpers(self, kind: str) -> tuple[str, str]:
        return "_frange", "_dadd({var}, {step})"

    def may_iterate(self, stmt, kind: str) -> bool:
        """Only whole-number loops iterate (exact in both arithmetics); any other adds
        its step in decimal each pass."""
        from yaseer.basic.source import syntax_tree as ast
        def whole(node) -> bool:
            return node is None or (isinstance(node, ast.Num) and float(node.value).is_integer())
        return whole(stmt.start) and whole(stmt.step)


def number_model(dialect, def_types=None) -> PlainNumbers:
    """A fresh model for compiling one area in ``dialect`` (gw: starting from the letter
    types ``def_types`` a program's DEF statements set, for direct statements)."""
    if dialect.typed_numbers:
        return TypedNumbers(def_types)
    return DecimalNumbers() if dialect.arithmetic == "decimal" else PlainNumbers()
