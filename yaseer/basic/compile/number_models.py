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
  DEFSTR: applied to the whole program before compiling where that gives the types GW-BASIC's
  statements give as they run (blocks.types_fixed), else one variant per table reached.
  Run-time helpers are in :mod:`yaseer.basic.arithmetic.values`.
"""

from __future__ import annotations


from yaseer.basic.arithmetic.single_arith import LIMIT, SMALL_CONSTANT, TINY
from yaseer.patterns import Pattern

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


_TYPE_LETTERS = str.maketrans("%!#$", "isdt")  # a type character as a letter of a Python name


def variant_function(name: str, table: dict, result: str = "") -> str:
    """The Python name of DEF FN function ``name`` in the variant of an area compiled for the
    DEF type table ``table`` (letter -> type character): ``_fn_1_ssis...``, a letter per A..Z;
    ``result``: the type character the function had when its DEF ran (``$ % ! #``), a last
    letter (``_fn_1_ssis..._t``)."""
    letters = "".join(table.get(chr(c), "!") for c in range(65, 91)).translate(_TYPE_LETTERS)
    return f"{name}_{letters}" + (f"_{result.translate(_TYPE_LETTERS)}" if result else "")


class PlainNumbers:
    """The pocket computer's numbers: every value a double, type ``"n"``."""

    typed = False
    tests_inline = False  # (TypedNumbers: single results tested inline; off, only helper calls)
    kinds_in_range = frozenset()  # types whose every operation keeps its result in the range itself
    square_by_product = True  # X^2 may compile to X*X (exact in binary)
    loop_types = frozenset("n")  # the types a FOR variable may have
    widest = "n"  # the type of a number read by READ or INPUT (converted to the target's)
    integer = "n"  # the type of ERR, ERL
    single = "n"  # the type of TIMER
    pi = repr(3.141592653589793)  # PI: the double nearest to pi
    cache_bases = ()  # (TypedNumbers: the binade caches its code uses)
    whole_steps_below = None  # a short constant loop is run at compile time: any (None), or whole values below this
    site_salt = ""

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

    def stored(self, code: str, source: str, target: str) -> str:
        """``code`` converted to be stored in a variable of type ``target``."""
        return self.convert(code, source, target)

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

    def stepped(self, kind: str, var: str, step: str) -> str:
        """The code of a FOR variable ``var`` of ``kind`` plus its ``step``."""
        return self.loop_helpers(kind)[1].format(var=var, step=step)

    def may_iterate(self, stmt, kind: str) -> bool:
        """May a native loop iterate (count or values mode) rather than add the step itself?"""
        return True


class TypedNumbers(PlainNumbers):
    """GW-BASIC's typed numbers (see the module docstring)."""

    typed = True
    # a single: the inline paths give values in MBF's range, the helpers they fall back on
    # give the policy's value where GW's operation overflows (arith_policy.helpers); a
    # double: its + - * / (values.double_operations through the policy, the inline sum
    # tested for the range) and its sources (literals, CDBL, CVD, INT ...) likewise: a
    # statement needs no overflow test of its own (a DEF FN's value is not known here)
    kinds_in_range = frozenset("!#")
    loop_types = frozenset("%!")  # FOR D# is Type mismatch in GW-BASIC (checked with PC-BASIC)
    whole_steps_below = 2.0 ** 24  # (a single sum of whole numbers below 2**24 is exact: GW's sum is the double's)
    widest = "#"
    integer = "%"
    single = "!"
    _SUFFIX = {"INT": "%", "SNG": "!", "DBL": "#", "STR": "$"}
    # result types of the built-in functions: None keeps the argument's type
    _RESULTS = {
        "SIN": "!", "COS": "!", "TAN": "!", "ATN": "!", "SQR": "!", "EXP": "!", "LOG": "!",
        "RND": "!", "VAL": "?", "ABS": None, "INT": None, "FIX": None, "SGN": "%", "LEN": "%",
        "ASC": "%", "CINT": "%", "CSNG": "!", "CDBL": "#", "CVD": "#", "SCREEN": "%",
    }

    # functions GW-BASIC computes in single precision from an argument made single
    _SINGLE_FUNCTIONS = frozenset(("SIN", "COS", "TAN", "ATN", "SQR", "EXP", "LOG"))
    # ... of which these give a single already (GW's steps, gw_transcendental.py; a value beyond
    # the range is the policy's or an infinity, which the statement's overflow check takes)
    _STEPPED_FUNCTIONS = frozenset(("SIN", "COS", "TAN", "ATN", "EXP", "LOG"))

    def __init__(self, def_types=None):
        self.letters: dict[str, str] = dict(def_types or {})
        self._temps = 0
        self.tests_inline = True
        self.site_salt = ""  # in the cache names: apart from the other variants' in one namespace
        self.cache_bases: list[str] = []  # the binade caches written (see _cached)
        self.caching = True  # (off: the general code alone)

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
        if hasattr(value, "parts"):  # a double of 56 bits (values.Wide): from its bytes
            from yaseer.basic.arithmetic.mbf_double import to_bytes
            return f"_wd({to_bytes(value.parts).hex()!r})", "#"
        return repr(float(value)), kind or "#"

    def arithmetic(self, op: str, left: str, lkind: str, right: str, rkind: str) -> tuple[str, str]:
        kind = lkind if _RANK[lkind] >= _RANK[rkind] else rkind
        if kind == "?":  # VAL's with a single or integer: the type VAL's text gave (val_numbers.py)
            return (f"_vdv({left}, {right})" if op == "/" else f"_vop({op!r}, {left}, {right})"), "?"
        if op == "/":  # through the dialect's division-by-zero policy (arith_policy.py); of integers: single
            return (f"_ddv({left}, {right})", "#") if kind == "#" else (self._single(op, left, right), "!")
        if kind == "%":
            return f"_ia({left} {op} {right})", "%"
        if kind == "!":  # rounded as GW-BASIC's MBF routines round (single_arith.py)
            return self._single(op, left, right), "!"
        return self._double(op, left, right), "#"

    def _double(self, op: str, left: str, right: str) -> str:
        """The code of a double ``left op right`` (``+ - *``) on GW's 56-bit doubles:
        arith_policy's ``_dad _dsb _dml`` (a float fast path inside, the routines of
        mbf_double.py otherwise).  A sum or difference of two floats is tested inline
        first: where both operands are floats (not ``values.Wide``), the float result is
        exact (Dekker: each operand given back by the other difference) and inside MBF's
        range, it is GW's result, for no routine rounds anything.  Each operand is
        evaluated once, in order (scratch locals as in :meth:`_single`)."""
        helper = _DOUBLE_OPERATIONS[op]
        if not self.tests_inline or op == "*":
            return f"{helper}({left}, {right})"
        first, kept = "", []
        for code, scratch in ((left, "_x"), (right, "_y")):
            if _plain_operand(code):
                kept.append(code)
            else:
                name = f"{scratch}{self._temp()}"
                first += f"({name} := {code}) is {name} and "
                kept.append(name)
        a, b = kept
        guards = "".join(f"type({x}) is not _WD and " for x in (a, b) if not _small_literal(x))
        exact = (f"(_w := {a} + {b}) - {a} == {b} and _w - {b} == {a}" if op == "+"
                 else f"(_w := {a} - {b}) + {b} == {a} and {a} - _w == {b}")
        in_range = f"({2.0 ** -128!r} <= abs(_w) < {2.0 ** 127!r} or not _w)"
        return f"{RANGE_CHECKED[0]}{first}{guards}{exact} and {in_range} else {helper}({a}, {b}))"

    def _temp(self) -> int:
        """A fresh number for the scratch locals of one operation (``_x{n}``, ``_y{n}``)."""
        self._temps += 1
        return self._temps

    def _single(self, op: str, left: str, right: str) -> str:
        """The code of a single ``left op right`` (``+ - * /``), rounded as GW-BASIC rounds,
        tested inline where it can be, with no Python frame (see :func:`_tested`).

        A result that needs at most 24 bits and lies in MBF's range is GW's result: the
        routines round nothing when no bit is lost (a product of two singles is exact in a
        double, and so is a quotient that a double holds in 24 bits; a sum whose double is
        24 bits is GW's sum, see ``single_arith.add``).  A product or a quotient that needs
        rounding is the nearest single, found inline too, outside the cases where GW's
        rounding differs from it or cannot be told from it at a glance, and so is a sum of
        two numbers of one sign; those cases and the other sums go to the helper.  The range test is left out where it
        cannot fail: a sum with a constant below ``SMALL_CONSTANT`` (module single_arith).
        Each operand is evaluated once, in order: one that is not a local or a literal is
        kept in a scratch local for the helper.

        Where it can be, the result goes through a binade cache first (:meth:`_cached`)."""
        if not self.tests_inline:  # the helpers alone (their calls nest least)
            return {"*": f"_sp({left} * {right})", "/": f"_dv({left}, {right})",
                    "+": f"_sadd({left}, {right})", "-": f"_ssub({left}, {right})"}[op]
        # an integer literal written as a float: the same value, and float with float is
        # Python's fast (specialised) operation
        left, right = (repr(float(code)) if _is_int_literal(code) else code for code in (left, right))
        if op == "*":  # the exact product: the helper rounds it
            general = lambda value: _tested(value, "_sp(_sv)", _PRODUCT_BAND, banded="_spb(_sv, _sh)")
            # (in the cache's bounds and outside the band: the rounding near half a unit, single_arith.product_near_half)
            return self._cached("p", f"{left} * {right}", "{c}n < _sv - (_sh := (_sv + {c}m) - {c}m) < {c}k",
                                general, banded="_spb(_sv, _sh)")
        if op == "/":  # through the dialect's division-by-zero policy (arith_policy.py) when not tested
            if not _plain_operand(right):
                return f"_dv({left}, {right})"
            kept, first = left, ""
            if not _plain_operand(left):  # evaluated first, whatever the divisor
                kept = f"_x{self._temp()}"
                first = f"({kept} := {left}) is {kept} and "
            divisor = "" if _small_literal(right) and float(right) else f"{right} and "  # 0: the policy's
            # a quotient is GW's nearest single, and its double is never halfway between two
            # singles (single_arith.divide): the double's cut is the result wherever it is in range
            # (by a literal of at least 1 in size it cannot overflow: only the bottom is tested)
            at_least_one = _small_literal(right) and abs(float(right)) >= 1.0
            general = lambda value: _cut_or(value, f"_dv({kept}, {right})", at_least_one)
            # (a single in the range is not 0: the rounded value is a true condition)
            return self._cached("q", f"{first}{divisor}{kept} / {right}", "(_sh := (_sv + {c}m) - {c}m)", general)
        helper = "_sadd" if op == "+" else "_ssub"
        small = _small_literal(left) or _small_literal(right)
        first = second = a = b = None
        if _plain_operand(left) and _plain_operand(right):
            first, second, a, b = left, right, left, right
        else:
            n = self._temp()
            first, a = (left, left) if _plain_operand(left) else (f"(_x{n} := {left})", f"_x{n}")
            second, b = (right, right) if _plain_operand(right) else (f"(_y{n} := {right})", f"_y{n}")
        # a sum of two numbers of one sign (whatever their exponents: single_arith.add) that is not
        # near halfway is the nearest single; with a small constant (see _small_literal) an
        # inexact sum is inside the range, and the constant's sign is known here
        same_sign = f"{_one_sign(a, b, op == '+')} and {_SUM_BAND}"
        general = lambda value: _tested(value, f"{helper}({a}, {b})", same_sign, in_range=not small)
        # in a cached binade (binade_cache.sum_group): an exact sum is GW's; an inexact one where
        # the magnitudes add (a literal's sign the cache's bounds imply) outside the band, or
        # whatever its rounding where an operand lies in the sum's binade (no carry)
        constant = _constant_added(a, b, op == "+")
        if constant is not None:  # (an exact sum is inside the band)
            test = "{c}n < _sv - (_sh := (_sv + {c}m) - {c}m) < {c}k"
        else:
            # (0, an exact sum's distance, is inside every band: the band first, then the signs
            # or an exact sum; outside it the signs and an operand in the bounds)
            other = b if op == "+" else f"-{b}"
            one_sign = f"{a} * {b} {'>' if op == '+' else '<'} 0"
            test = (f"({{c}}n < _sv - (_sh := (_sv + {{c}}m) - {{c}}m) < {{c}}k and ({one_sign} or _sh == _sv) "
                    f"or {one_sign} and ({{c}}l <= {a} < {{c}}h or {{c}}l <= {other} < {{c}}h))")
        return self._cached("s", f"{first} {op} {second}", test, general, constant)

    def _cached(self, kind: str, value: str, test: str, general, constant=False,
                banded: str | None = None) -> str:
        """The code of a single ``+ - * /`` through a binade cache (module binade_cache): the
        double ``_sv`` (``value``) inside the cache's bounds, passing ``test`` (code with
        ``{c}`` for the cache's name), gives ``_sh``, its nearest single; any other takes
        ``general(value code)`` (here: ``_sv``), whose result the writer ``_zw<kind>`` passes on
        after it set the cache for ``_sv``'s binade (``constant``: see binade_cache.sum_group).
        ``banded``: the code of a value inside the bounds that fails ``test``."""
        if not self.caching:
            return general(value)
        cache = f"_Z{kind}{self.site_salt}{self._temp()}"
        self.cache_bases.append(cache)
        extra = "" if constant is False else f"{constant!r}, "
        inside = f"(_sv := {value}) < {cache}h and _sv >= {cache}l"
        written = f"_zw{kind}({cache!r}, _sv, {extra}{general('_sv')})"
        if banded is not None:
            return f"((_sh if {test.format(c=cache)} else {banded}) if {inside} else {written})"
        return f"(_sh if {inside} and {test.format(c=cache)} else {written})"

    def cache_prelude(self, source: str) -> str:
        """The module code that sets the binade caches ``source`` writes to match nothing."""
        used = sorted(set(_CACHE_WRITTEN.findall(source)))
        return "".join(f"{base}h = -1e999\n" for base in used)

    def helper(self, op: str, left: str, right: str) -> tuple[str, str]:
        names = {"\\": "_idiv", "MOD": "_mod", "AND": "_and", "OR": "_or", "XOR": "_xor",
                 "EQV": "_eqv", "IMP": "_imp"}
        return f"{names[op]}({left}, {right})", "%"

    def power(self, left: str, lkind: str, right: str, rkind: str, whole: bool = False) -> tuple[str, str]:
        """``^``: single precision, also of doubles (GW-BASIC's ``$FPWR`` makes both
        operands single: ``2#^.5`` is 1.414214); ``_spow`` in arith_policy.py.  ``whole``:
        ``left`` is a single variable known to hold a whole number (a FOR variable)."""
        left, right = self.convert(left, lkind, '!'), self.convert(right, rkind, '!')
        if right in ("2", "2.0") and self.tests_inline and whole and lkind == "!" and left.isidentifier():
            # the square of a whole number is whole: up to 2**24 it is exact, 0 or at least 1
            split = _cut_in_range("(_sc := _sv * 536870913.0)")
            return (f"(_sv if (_sv := {left} * {left}) <= 16777216.0 else "
                    f"((_sh if {_PRODUCT_BAND} else _spb(_sv, _sh)) if {split} else _spow({left}, 2.0)))"), "!"
        if right in ("2", "2.0") and self.tests_inline:  # $FPWR's X^2 is one $FMULS, X*X: exact products inline (see _single)
            first = kept = left
            if not _plain_operand(left):
                kept = f"_x{self._temp()}"
                first = f"({kept} := {left}) is {kept} and {kept}"
            # (in the range, the product's own rounding near half a unit: single_arith.product_near_half)
            return _tested(f"{first} * {kept}", f"_spow({kept}, 2.0)", _PRODUCT_BAND, banded="_spb(_sv, _sh)"), "!"
        return f"_spow({left}, {right})", "!"

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
        if source == "%" and target == "!":
            # a single holds a float even when its value is whole: PRINT and STR$ show
            # 16777216 in a single as 1.677722E+07 (they tell the types apart by the value)
            return repr(float(code)) if _is_int_literal(code) else f"float({code})"
        if source == target or target == "#" or source == "%":
            return code
        return f"_sfd({code})"

    def stored(self, code: str, source: str, target: str) -> str:
        """An integer literal stored in a single or double variable is a float from the start
        (``K=0``): sums with it then stay floats, without mixing int and float."""
        if source == "%" and target != "%" and _is_int_literal(code):
            return repr(float(int(code)))
        return self.convert(code, source, target)

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
            if name == "RND":  # already a single: the generator's 24-bit state over 2**24 (randomness.py)
                if kinds and kinds[0] in "#?":  # its argument made a single first: beyond it Overflow (MATH1.ASM RND: FRCSNG)
                    code = f"{helper}({self.convert(codes[0], '#', '!')})"
                return code, "!"
            if name == "CVS":  # already a single: its 4 bytes (a -0.0 kept: gwfunctions._signed_zero)
                return code, "!"
            if name in self._SINGLE_FUNCTIONS and kinds and kinds[0] in "#?":  # computed on the single
                code = f"{helper}({', '.join([self.convert(codes[0], '#', '!')] + codes[1:])})"
            if name in self._STEPPED_FUNCTIONS and self.tests_inline:
                return code, "!"
            # the nearest single (single_arith.function_result), found inline where it is clear
            split = f"(_sc := (_sv := {code}) * 536870913.0)"
            # a single's square root is never halfway between singles (the square of a 25-bit odd
            # number needs 48 bits), nor is its double: any cut of it is the nearest
            if not self.tests_inline:
                return f"_sfn({code})", "!"
            if name == "SQR":  # of a single from 2**-128 to 2**127: a cut in the range, or 0
                return f"({split} - (_sc - _sv) or 0.0)", "!"
            return f"(_sh if {_cut_in_range(split)} and {_NEAREST_BAND} else _sfn(_sv))", "!"
        return code, kind

    def printable(self, code: str, kind: str) -> str:
        return f"_dbl({code})" if kind == "#" else code

    def one(self) -> str:
        return "1"

    def loop_helpers(self, kind: str) -> tuple[str, str]:
        if kind == "%":
            return "_irange", "_ci({var} + {step})"
        if kind == "!":  # NEXT's sum rounded as any single sum, tested inline first (see _single)
            return "_frange", self._single("+", "_VAR", "_STEP").replace("_VAR", "{var}").replace("_STEP", "{step}")
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


# The tests of a single result ``_sv`` written into the compiled code (see _tested).
_IN_RANGE = f"({TINY!r} <= _sv < {LIMIT!r} or {-LIMIT!r} < _sv <= {-TINY!r})"


def _cut_in_range(split: str | None = None) -> str:
    """Is ``_sh``, ``_sv`` cut to 24 bits (from its ``split``, ``_sv * (2**29 + 1)``; None: ``_sh``
    is that cut already), in MBF's range?"""
    cut = "_sh" if split is None else f"(_sh := {split} - (_sc - _sv))"
    return f"({TINY!r} <= {cut} < {LIMIT!r} or {-LIMIT!r} < _sh <= {-TINY!r})"


# how far ``_sv`` is from its cut ``_sh``, in units of 2**-23 of its leading power of two
# (single_arith._units_below without the last scaling)
_BELOW = "(_sv - _sh) / ((_sq := _sv * 4503599627370497.0) - 0.9999999999999999 * _sq)"
# where the cut is GW's result: not halfway (and, for a product, outside GW's band of 0.5 to 0.625
# units above the cut, where its 28-bit product rounds otherwise: single_arith.product)
_NEAREST_BAND = f"{-0.5 * 2.0 ** -23!r} < {_BELOW} < {0.5 * 2.0 ** -23!r}"
_PRODUCT_BAND = f"{-0.375 * 2.0 ** -23!r} <= {_BELOW} < {0.5 * 2.0 ** -23!r}"
# (a sum of one sign: not rounded up by 3/8 to 1/2 of a unit, where the shift after a carry
# drops $FADDS's sticky bit and GW rounds half to even: single_arith.add)
_SUM_BAND = f"{-0.375 * 2.0 ** -23!r} <= {_BELOW} < {0.5 * 2.0 ** -23!r}"


def _cut_or(value: str, helper: str, no_overflow: bool = False) -> str:
    """The code of a single result that is the nearest single to ``value`` (a double never
    halfway between two singles): its cut, where that is in MBF's range, else ``helper``
    (``no_overflow``: ``value`` cannot be beyond the largest single, only its bottom is tested)."""
    split = f"(_sc := {'_sv' if value == '_sv' else f'(_sv := {value})'} * 536870913.0)"
    if no_overflow:
        return f"(_sh if (_sh := {split} - (_sc - _sv)) >= {TINY!r} or _sh <= {-TINY!r} else {helper})"
    return f"(_sh if {_cut_in_range(split)} else {helper})"


def _one_sign(a: str, b: str, plus: bool) -> str:
    """The test that ``a + b`` (``plus``) or ``a - b`` adds two magnitudes of one sign: with a
    literal operand, a test of the other operand's sign alone."""
    for this, other in ((b, a), (a, b)):
        if _small_literal(this):
            return f"{other} {'>' if (float(this) > 0) == plus else '<='} 0"
    return f"({a} > 0) {'==' if plus else '!='} ({b} > 0)"


def _constant_added(a: str, b: str, plus: bool) -> float | None:
    """The literal's contribution to ``a + b`` (``plus``) or ``a - b``: its value, negated when
    subtracted; None without a literal."""
    if _small_literal(b):
        return float(b) if plus else -float(b)
    return float(a) if _small_literal(a) else None


def _tested(value: str, helper: str, band: str | None = None, in_range: bool = True,
            banded: str | None = None) -> str:
    """The code of a single result: ``value`` (a double) where it is GW's result, else ``helper``
    (code reading ``_sv``, the double, or the scratch locals of the operands).

    First: does ``_sv`` need at most 24 bits (Veltkamp's split, ``v * (2**29 + 1)``, gives
    ``v`` cut to 24 bits; three float operations) and lie in MBF's range (``in_range``)?
    Then, with a ``band``: that cut ``_sh``, in the range (unless ``in_range`` is off: where
    the range cannot be left), where ``_sv`` lies inside the band around it (``banded``: the
    code for a cut in the range outside the band; else ``helper``).  Scratch locals
    ``_sv _sc _sh _sq`` are each read before anything else can assign them."""
    computed = "_sv" if value == "_sv" else f"(_sv := {value})"
    exact = f"{computed} == (_sh := (_sc := _sv * 536870913.0) - (_sc - _sv))"
    if in_range:
        exact += f" and {_IN_RANGE}"
    if band is not None and banded is not None:
        helper = f"((_sh if {band} else {banded}) if {_cut_in_range()} else {helper})"
    elif band is not None:
        helper = f"(_sh if {_cut_in_range() + ' and ' if in_range else ''}{band} else {helper})"
    return f"(_sv if {exact} else {helper})"

# how a range-checked double's, a tested single's and a scaled decimal's code start
RANGE_CHECKED = ("(_w if ", "(_sv if ", "(_sh if ", "((_sh if ", "(_dn / ")
"""(Their parentheses hold a conditional expression: a chain like ``A+B+C`` may not drop them.)"""


_DOUBLE_OPERATIONS = {"+": "_dad", "-": "_dsb", "*": "_dml"}


def _in_double_range(code: str) -> str:
    """``code`` (a double result) kept in MBF's range, 1.7D+38 (``values.DOUBLE_LARGEST``):
    beyond it ``_dk`` gives the overflow policy's value.  The test is inline (a
    chained comparison, no call: twice as fast in a double loop); ``_w`` is a scratch
    local, each use read before the next assignment."""
    return f"{RANGE_CHECKED[0]}{-2.0 ** 127!r} <= (_w := {code}) <= {2.0 ** 127!r} else _dk(_w))"


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
    """``--arith decimal`` (casio): floats that stand for 12-digit decimals; ``+ - * /``,
    ``^``, literals and FOR steps through yaseer/basic/arithmetic/decimal_arith.py.

    Each ``+ - * /`` is written inline first: the float result scaled by its operation's
    cached power of ten, kept where it is surely the 12-digit decimal's
    (yaseer/basic/arithmetic/decimal_scales.py, whose docstring proves it), else the
    routine of decimal_arith through the cache's writer.  ``accelerated`` (number_model: where
    the C module decimal_fast.py names is built): those operations, SQR, LN, LOG, EXP and a
    local plus RND call its routines instead, the same tests with the scale of the result's own
    decade (no cache to miss)."""

    square_by_product = True  # X^2 is decimal_arith.power's product X*X, rounded once
    pi = "3.1415926536"  # PI inside the FX-850P: 11 digits (PI.md; shown 3.141592654)
    _OPERATIONS = {"+": "_dadd", "-": "_dsub", "*": "_dmul", "/": "_ddiv13"}
    # the C routines (decimal_fast.NAMES) of the operations and functions, where built
    _ACCELERATED = {"+": "_zcadd", "-": "_zcsub", "*": "_zcmul", "/": "_zcdiv",
                    "_sqrt": "_zcsqrt", "_log": "_zclog", "_log10": "_zclog10", "_exp": "_zcexp"}

    def __init__(self):
        self._temps = 0
        self._exact: dict[str, tuple] = {}  # code with an exact form -> (its tree, its scaled code)
        self.cache_bases: list[str] = []  # the scale caches written (see _scaled)
        self._draws: dict[str, str] = {}  # the code of RND's rounded number -> its cache (see _drawn_sum)
        self.caching = True  # (off: the routines alone)
        self.accelerated = False  # the C routines instead of the inline caches (decimal_fast.py; number_model)

    def literal(self, value, kind: str) -> tuple[str, str]:
        from yaseer.basic.arithmetic.decimal_arith import rounded

        return repr(rounded(float(value))), "n"

    def arithmetic(self, op: str, left: str, lkind: str, right: str, rkind: str) -> tuple[str, str]:
        """``left op right``: its float code where a test of its variables shows every step
        is exact (:func:`_exact_form`), else inline through a scale cache (:meth:`_scaled`)."""
        if not self.caching:
            return f"{self._OPERATIONS[op]}({left}, {right})", "n"
        if op == "+" and left.isidentifier():
            draw = self._draws.get(right) or self._draws.get(f"({right})")
            if draw is not None:
                if draw in self.cache_bases:  # (the rounded number's code, and its cache, go unused)
                    self.cache_bases.remove(draw)
                return self._drawn_sum(left), "n"
        (left_tree, left_scaled), (right_tree, right_scaled) = self._operand(left), self._operand(right)
        if left_tree is not None and right_tree is not None:
            tree = (op, left_tree, right_tree)
            exact = _exact_form(tree)
            if exact is not None:
                scaled = self._scaled(op, left_scaled, right_scaled)
                # a C routine's call costs less than the test of a local (a range and a remainder):
                # the exact form where it saves at least two calls a tested local
                if self.accelerated and _operations(tree) < max(2, 2 * len(_locals_of(tree))):
                    code = scaled
                else:
                    code = f"({exact[0]} if {exact[1]} else {scaled})"
                self._exact[code] = (tree, scaled)
                return code, "n"
        return self._scaled(op, left, right), "n"

    def _operand(self, code: str) -> tuple[tuple | None, str]:
        """(the expression tree of operand ``code`` for :func:`_exact_form`, or None; the code
        of its scaled form): a local, a literal, or an operation this model wrote with an
        exact form (its code may have lost its outer parentheses in a chain)."""
        for form in (code, f"({code})"):
            found = self._exact.get(form)
            if found is not None:
                return found
        if code.isidentifier():
            return ("var", code), code
        if _small_literal(code):
            return ("num", float(code)), code
        return None, code

    def _scaled(self, op: str, left: str, right: str) -> str:
        """The code of ``left op right`` through a scale cache ``_D<n>`` (decimal_scales.py):
        ``_dt`` the scaled float result, ``_dn`` it rounded to a whole number; a sum of two
        operands that are not literals tests the first one against the cache's bounds
        ``_D<n>l``, ``_D<n>h``.  Each operand is evaluated once, in order (a scratch local
        ``_x<n>``, ``_y<n>`` keeps one that is not a local or a literal for the writer)."""
        from yaseer.basic.arithmetic.decimal_scales import BAND, BOTTOM, MAGIC, TOP

        if self.accelerated:  # the C routine: the same tests with the scale of the result's decade
            return f"{self._ACCELERATED[op]}({left}, {right})"
        self._temps += 1
        n = self._temps
        cache = f"_D{self.site_salt}{n}"
        self.cache_bases.append(cache)
        first, a = (left, left) if _plain_operand(left) else (f"(_x{n} := {left})", f"_x{n}")
        second, b = (right, right) if _plain_operand(right) else (f"(_y{n} := {right})", f"_y{n}")
        routine = self._OPERATIONS[op]
        guard = ""
        if op in "*/":
            written = f"_zd({cache!r}, {routine}, {a}, {b})"
        else:
            constants = [abs(float(x)) for x in (a, b) if _small_literal(x)]
            if constants:
                written = f"_zdc({cache!r}, {routine}, {a}, {b}, {max(constants)!r})"
            else:
                guard = f" and {cache}l < {a} < {cache}h"
                written = f"_zdg({cache!r}, {routine}, {a}, {b})"
        return (f"(_dn / {cache} if 0.0 < (_dt := ({first} {op} {second}) * {cache}) < {TOP!r}{guard} and "
                f"((_dn := _dt + {MAGIC!r} - {MAGIC!r}) == _dt or _dt >= {BOTTOM!r} and "
                f"{-BAND!r} < _dt - _dn < {BAND!r}) else {written})")

    def _drawn_sum(self, local: str) -> str:
        """``local + RND``: the sum of the local and the number drawn, rounded once through a
        scale cache ``_D<n>`` (decimal_scales.DRAWN_SCALE bounds its scale: its docstring proves
        this is the sum of the local and the number drawn rounded to 12 digits), else the writer
        ``_zdr``, which rounds the number drawn (``_d13``) and adds it with ``_dadd``.  The local
        is read before the number is drawn, as in ``local + RND`` unfused.

        No guard on the local (a sum of two variables tests ``l < a < h``): the range test
        implies it here.  The number drawn ``v`` is from 0 up to below 1 and ``|S|`` at most
        DRAWN_SCALE (1E+9), so ``10**11 <= t < 10**12`` gives ``|S a| <= |t| + |S v| + (t's
        rounding) < 10**12 + 10**9 + 1``, inside the guard's ``10**13`` (decimal_scales.GUARD)."""
        from yaseer.basic.arithmetic.decimal_scales import BAND, BOTTOM, MAGIC, TOP

        if self.accelerated:  # (the local is read before the number is drawn: arguments in order)
            return f"_zcrnd({local}, _rndr())"
        self._temps += 1
        cache = f"_D{self.site_salt}{self._temps}"
        self.cache_bases.append(cache)
        return (f"(_dn / {cache} if {BOTTOM!r} <= (_dt := ({local} + (_dv := _rndr())) * {cache}) < {TOP!r} and "
                f"{-BAND!r} < _dt - (_dn := _dt + {MAGIC!r} - {MAGIC!r}) < {BAND!r} else "
                f"_zdr({cache!r}, _dadd, {local}, _dv))")

    def cache_prelude(self, source: str) -> str:
        """The module code that sets the caches ``source`` writes to match nothing."""
        used = sorted(set(_SCALE_WRITTEN.findall(source)))
        return "".join(f"{name} = {name}b = 1e999 - 1e999\n{name}l = {name}h = 0.0\n" for name in used)

    # the float value of a function the compiled code rounds through a scale cache
    # (decimal_calls.py): {x} the argument, {first} its first evaluation
    _FLOAT_CALLS = {
        "_sqrt": "(_msqrt({x}) if {first} > 0.0 else _nan)",
        "_log": "(_mlog({x}) if 0.0 < {first} < 1e100 else _nan)",
        "_log10": "(_mlog10({x}) if 0.0 < {first} < 1e100 else _nan)",
        "_exp": "(_mexp({x}) if -20.0 < {first} < 20.0 else _nan)",
        "_sin": "(_msin(_mfmod({x}, _Tu) * _Ru) if -_Fu < {first} < _Fu or not {x} % 1.0 and -_Wu < {x} < _Wu else _nan)",
        "_cos": "(_mcos(_mfmod({x}, _Tu) * _Ru) if -_Fu < {first} < _Fu or not {x} % 1.0 and -_Wu < {x} < _Wu else _nan)",
    }

    # SIN and COS of a whole angle in degrees below decimal_calls.WHOLE_TABLE_LIMIT (``_Xu``):
    # the table of the routine's results at the angle's remainder by a turn (decimal_arith.WholeDegrees)
    _WHOLE_DEGREES = {"_sin": "_SDs", "_cos": "_SDc"}

    def call(self, name: str, helper: str, codes: list[str], kinds: list[str], result: str) -> tuple[str, str]:
        """SQR LN LOG EXP SIN COS and RND's next number inline: the float function's value
        through a scale cache ``_D<n>`` (decimal_calls.py proves it for any scale the writer
        keeps), then through the site's second scale ``_D<n>b`` (the one ``_D<n>`` had before the
        writer last changed it), else decimal_arith's routine through the cache's writer
        ``_zdf``; SIN and COS of a whole angle in degrees first from the table of the whole
        degrees (:data:`_WHOLE_DEGREES`)."""
        from yaseer.basic.arithmetic.decimal_calls import LARGEST_SCALE
        from yaseer.basic.arithmetic.decimal_scales import BAND, BOTTOM, MAGIC, TOP

        if self.caching and self.accelerated and helper in self._ACCELERATED and len(codes) == 1:
            return f"{self._ACCELERATED[helper]}({codes[0]})", "n"
        form = self._FLOAT_CALLS.get(helper)
        if not self.caching or (form is None and helper != "_rndf") or len(codes) != (helper != "_rndf"):
            return super().call(name, helper, codes, kinds, result)
        self._temps += 1
        n = self._temps
        cache = f"_D{self.site_salt}{n}"
        self.cache_bases.append(cache)
        if helper == "_rndf":  # the number drawn, rounded as ``_d13`` (decimal_arith.rounded) rounds it
            code = _drawn_rounded(cache)
            self._draws[code] = cache
            return code, "n"
        else:
            x = codes[0]
            first = x if _plain_operand(x) else f"(_x{n} := {x})"
            x = x if _plain_operand(x) else f"_x{n}"
            table = self._WHOLE_DEGREES.get(helper)
            self.cache_bases.append(f"{cache}b")  # (the site's second scale: a name its code reads)
            scaled = f"(_dv := {form.format(x=x, first=x if table else first)}) * {cache}"
            cache_value, routine = cache, helper
        band = f"{-BAND!r} < _dt - (_dn := _dt + {MAGIC!r} - {MAGIC!r}) < {BAND!r}"
        code = (f"(_dn / {cache_value} if {BOTTOM!r} <= (_dt := {scaled}) < {TOP!r} and {band} else "
                f"_dn / {cache}b if {BOTTOM!r} <= (_dt := _dv * {cache}b) < {TOP!r} and {band} else "
                f"_zdf({cache!r}, {routine}, {x}, _dv, {LARGEST_SCALE[helper]!r}))")
        if table:  # a whole angle in degrees: the routine's result from a table
            code = f"({table}[{x} % 360.0] if -_Xu < {first} < _Xu and not {x} % 1.0 else {code})"
        return code, "n"

    whole_steps_below = 1e12  # (a sum of whole numbers below 1E+12 is exact in 12 digits)

    def loop_helpers(self, kind: str) -> tuple[str, str]:
        return "_frange", "_dadd({var}, {step})"

    def stepped(self, kind: str, var: str, step: str) -> str:
        """``var + step`` inline (:meth:`_scaled`)."""
        return self._scaled("+", var, step) if self.caching else super().stepped(kind, var, step)

    def may_iterate(self, stmt, kind: str) -> bool:
        """Only whole-number loops iterate (exact in both arithmetics); any other adds
        its step in decimal each pass."""
        from yaseer.basic.source import syntax_tree as ast
        def whole(node) -> bool:
            return node is None or (isinstance(node, ast.Num) and float(node.value).is_integer())
        return whole(stmt.start) and whole(stmt.step)


def _drawn_rounded(cache: str) -> str:
    """The code of RND's next number rounded to 12 digits (decimal_calls.py's band test with the
    scale of the number's decade, no cache): ``v`` from 0.1 up with the scale 1E+12, else from
    0.01 up (below 0.1) with 1E+13, else ``_zdf`` (the routine ``_d13``, its site ``cache``).

    A number drawn is below 1 (random.random and GwRandom's state over its period), so no
    test of the scaled ``t`` is needed: the doubles compare as the decimals (0.1, 0.01 and 1 are
    decimals of one digit), so ``v`` from 0.1 up (below 1) gives ``t = fl(v * 1E+12)`` from
    ``fl(fl(0.1) * 1E+12) = 1E+11`` up to ``1E+12`` (rounding is monotone), and ``v`` from 0.01
    below 0.1 gives ``t = fl(v * 1E+13)`` in the same range.  ``v`` is the exact value rounded
    (``E`` is ``t``'s own rounding, below ``2**-13``), so the band test's argument in
    decimal_scales.py holds: ``n / S`` is ``v`` rounded to 12 digits; at ``t = 1E+12`` (``v``
    within half a unit below 1 or 0.1) ``n`` is ``1E+12`` and ``n / S`` is 1 or 0.1, ``v``'s
    rounding up, which the old decade test sent to the routine for the same double.  Never at
    a tie (the band), so rounding half up and half to even agree with ``_d13``'s."""
    from yaseer.basic.arithmetic.decimal_calls import LARGEST_SCALE
    from yaseer.basic.arithmetic.decimal_scales import BAND, MAGIC

    def banded(scale: float) -> str:
        return (f"{-BAND!r} < (_dt := _dv * {scale!r}) - (_dn := _dt + {MAGIC!r} - {MAGIC!r}) < {BAND!r}")
    return (f"(_dn / {1e12!r} if (_dv := _rndr()) >= 0.1 and {banded(1e12)} else "
            f"_dn / {1e13!r} if 0.01 <= _dv < 0.1 and {banded(1e13)} else "
            f"_zdf({cache!r}, _d13, _dv, _dv, {LARGEST_SCALE['_rndf']!r}))")


def _exact_form(tree) -> tuple[str, str] | None:
    """(float code, test code) of an expression ``tree`` of ``+ - * /`` over locals and
    literals whose float code is decimal_arith's result wherever the test holds; None if none.

    The test: each local is a whole number below a bound ``B`` in size (the largest of a few
    round numbers that works).  Then every step's value, as every operand's, is a multiple of
    1/8 below 1E+9 in size (:func:`_dyadic`), which is where decimal_arith's ``add``,
    ``subtract``, ``multiply`` and ``divide`` give the float operation's own result (their
    small-number path, exact in both arithmetics): the float code computes what their
    composition computes, bit for bit, signed zeros and division by zero included."""
    names = sorted(_locals_of(tree))
    for bound in _WHOLE_BOUNDS:
        if _dyadic(tree, bound) is not None:
            break
    else:
        return None
    test = " and ".join(f"{-bound!r} < {name} < {bound!r} and not {name} % 1.0" for name in names) or "True"
    return _float_code(tree), test


# the bounds tried for the locals of an exact form, largest first: m * 10**e
_WHOLE_BOUNDS = sorted((m * 10.0 ** e for m in range(1, 10) for e in range(9)), reverse=True)
_EIGHTHS_LIMIT = 1e9  # decimal_arith's small-number path: multiples of 1/8 below 1E+9


def _dyadic(tree, bound: float) -> tuple[int, float] | None:
    """(d, m): the value of ``tree`` is a multiple of 2**-d (d at most 3) below m in size when
    its locals are whole numbers below ``bound``; None where that is not shown (a step beyond
    1E+9 or finer than 1/8, a division by anything but a power of two or the dividend itself)."""
    kind = tree[0]
    if kind == "var":
        return 0, bound
    if kind == "num":
        value = tree[1]
        for d in range(4):
            if (value * 2 ** d) % 1.0 == 0.0 and abs(value) < _EIGHTHS_LIMIT:
                return d, abs(value)
        return None
    op, left, right = tree
    if op == "/" and left == right and left[0] == "var":
        return 0, 1.0  # x / x is 1 (or, for 0, the division by zero of both)
    a = _dyadic(left, bound)
    b = _dyadic(right, bound)
    if a is None or b is None:
        return None
    if op in "+-":
        d, size = max(a[0], b[0]), a[1] + b[1]
    elif op == "*":
        d, size = a[0] + b[0], a[1] * b[1]
    elif right[0] == "num" and right[1] in (1.0, 2.0, 4.0, 8.0):
        d, size = a[0] + (1.0, 2.0, 4.0, 8.0).index(right[1]), a[1] / right[1]
    else:
        return None
    return (d, size) if d <= 3 and size < _EIGHTHS_LIMIT else None


def _operations(tree) -> int:
    """The number of operations of an expression ``tree``."""
    return 0 if tree[0] in ("var", "num") else 1 + _operations(tree[1]) + _operations(tree[2])


def _locals_of(tree) -> set:
    if tree[0] == "var":
        return {tree[1]}
    if tree[0] == "num":
        return set()
    return _locals_of(tree[1]) | _locals_of(tree[2])


def _float_code(tree) -> str:
    if tree[0] == "var":
        return tree[1]
    if tree[0] == "num":
        return repr(tree[1])
    return f"({_float_code(tree[1])} {tree[0]} {_float_code(tree[2])})"


_CACHE_WRITTEN = Pattern(r"_zw[spq]\('(\w+)'")  # a binade cache's name where its writer is called
_SCALE_WRITTEN = Pattern(r"_zd[cgfr]?\('(\w+)'")  # a scale cache's name where its writer is called


def number_model(dialect, def_types=None) -> PlainNumbers:
    """A fresh model for compiling one area in ``dialect`` (gw: starting from the letter
    types ``def_types`` a program's DEF statements set, for direct statements)."""
    if dialect.typed_numbers:
        return TypedNumbers(def_types)
    if dialect.arithmetic == "decimal":
        from yaseer.basic.arithmetic.decimal_fast import accelerated

        model = DecimalNumbers()
        model.accelerated = accelerated()
        return model
    return PlainNumbers()
