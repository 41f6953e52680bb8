"""Seeded generator of whole BASIC programs in the subset yaseer and GW-BASIC share.

This module holds no tests.  A program is built from independent *blocks*
(FOR/NEXT, nested GOSUB, IF/ELSE chains, ON GOTO / ON GOSUB, DATA/READ/RESTORE,
string functions, expressions, PRINT USING, DEF FN, ON ERROR) laid out in
their own line ranges, then ``END`` and the subroutines.

Variable names are one letter (or a letter and a digit), since yaseer reads
keywords inside runs of letters as the pocket computers did (``TO`` in a name
would be the keyword).  Two kinds of program:

* *exact*: every value printed is a dyadic rational with at most 7 significant
  digits, so single-precision GW-BASIC and double-precision yaseer must print
  the same bytes.  The generator evaluates each expression exactly (with
  ``Fraction``, MS-BASIC semantics) and regenerates it otherwise.
* *numeric*: division, SQR, SIN, COS, ATN, EXP, LOG in radians; numbers are
  compared within 1e-6 relative (plus 1e-6 absolute where GW-BASIC's single
  precision cancels).
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from fractions import Fraction

from test_differential_support import basic_number, random_format, random_string, significant_digits

SCALARS = "ABCDEFGHJKMNPQRSUVWXYZ"

# Constructs where yaseer is known to differ from GW-BASIC (docs/differential-findings.md);
# switch one on to reproduce its finding.
# F2: after a loop that runs zero times the variable holds its start value (GW-BASIC's
# source, NEXT86.ASM); PC-BASIC 2.0.8 gives start + STEP: a known, deliberate difference.
ZERO_TRIP_LOOPS = False
ERR_AFTER_RESUME = True  # F11: ERR is not reset to 0 by RESUME
LONG_LINE = 60  # programs whose PC-BASIC output has a line this long are drawn again (80-column wrap)  # no I (loops), no L, O, T (keyword starts look-alikes)


class Unsuitable(Exception):
    """The expression's value cannot be printed identically by both BASICs; draw another."""


@dataclass
class Program:
    """Lines being built: main-line blocks, subroutines and DATA, each with its own numbers."""

    main: list[str] = field(default_factory=list)
    subs: list[str] = field(default_factory=list)
    next_main: int = 10
    next_sub: int = 5000
    numeric: bool = False
    arrays: set[str] = field(default_factory=set)
    final: str = "END"  # or STOP (then "Break in N")

    def line(self, text: str) -> int:
        number = self.next_main
        self.main.append(f"{number} {text}")
        self.next_main += 10
        return number

    def reserve(self) -> int:
        """The number the next main line will get."""
        return self.next_main

    def sub(self, texts: list[str]) -> int:
        """Place a subroutine (its lines in order); return its first line number."""
        first = self.next_sub
        for text in texts:
            self.subs.append(f"{self.next_sub} {text}")
            self.next_sub += 10
        self.next_sub += 100 - self.next_sub % 100
        return first

    def source(self) -> str:
        return "\n".join(self.main + [f"{self.next_main} {self.final}"] + self.subs) + "\n"


# ---------------------------------------------------------------------------
# Exact expressions (MS-BASIC semantics evaluated with Fraction)
# ---------------------------------------------------------------------------

def _bool(value: bool) -> Fraction:
    return Fraction(-1 if value else 0)


def _require_int(value: Fraction) -> int:
    if value.denominator != 1 or abs(value) > 32767:
        raise Unsuitable()
    return int(value)


def _binary(op: str, a: Fraction, b: Fraction) -> Fraction:
    if op == "+":
        return a + b
    if op == "-":
        return a - b
    if op == "*":
        return a * b
    if op == "/":
        if b == 0:
            raise Unsuitable()
        return a / b
    if op == "^":
        if a == 0 and b <= 0:
            raise Unsuitable()
        return a ** int(b)
    if op in ("\\", "MOD"):
        x, y = _require_int(a), _require_int(b)
        if y == 0:
            raise Unsuitable()
        quotient = abs(x) // abs(y) * (1 if (x >= 0) == (y >= 0) else -1)
        return Fraction(quotient) if op == "\\" else Fraction(x - quotient * y)
    if op in ("AND", "OR"):
        x, y = _require_int(a), _require_int(b)
        return Fraction(x & y if op == "AND" else x | y)
    relations = {"=": a == b, "<>": a != b, "<": a < b, ">": a > b, "<=": a <= b, ">=": a >= b}
    return _bool(relations[op])


PRECEDENCE = {"OR": 1, "AND": 2, "NOT": 3, "=": 4, "<>": 4, "<": 4, ">": 4, "<=": 4, ">=": 4,
              "+": 5, "-": 5, "MOD": 6, "\\": 7, "*": 8, "/": 8, "NEG": 9, "^": 10}


def random_expression(rng: random.Random, depth: int, names: dict[str, Fraction]) -> tuple[str, Fraction, int]:
    """A random expression: its text, exact value and precedence of its top operator.

    Parentheses are added only where precedence needs them (and at random), so
    the printed text exercises the precedence rules.
    """
    if depth == 0 or rng.random() < 0.25:
        if names and rng.random() < 0.4:
            name = rng.choice(sorted(names))
            return name, names[name], 99
        value = Fraction(rng.choice([0, 1, 2, 3, 4, 5, 7, 8, 10, 12, 25, 100])) / rng.choice([1, 1, 1, 2, 4])
        return basic_number(float(value)), value, 99
    op = rng.choice(["+", "-", "*", "*", "/", "^", "\\", "MOD", "NEG", "NOT", "AND", "OR",
                     "=", "<>", "<", ">", "<=", ">="])
    if op in ("NEG", "NOT"):
        text, value, prec = random_expression(rng, depth - 1, names)
        own = PRECEDENCE[op]
        if prec < own or (op == "NEG" and prec == own):
            text = f"({text})"
        if op == "NEG":
            return f"-{text}", -value, own
        return f"NOT {text}", Fraction(~_require_int(value)), own
    left, lvalue, lprec = random_expression(rng, depth - 1, names)
    if op == "^":
        right, rvalue, rprec = basic_number(rng.choice([0, 1, 2, 3])), None, 99
        rvalue = Fraction(right)
    else:
        right, rvalue, rprec = random_expression(rng, depth - 1, names)
    own = PRECEDENCE[op]
    # ^ binds tighter than unary minus: a negative base needs parentheses
    if lprec < own or (op == "^" and lprec == PRECEDENCE["NEG"]) or rng.random() < 0.15:
        left = f"({left})"
    if rprec <= own or rng.random() < 0.15:
        right = f"({right})"
    value = _binary(op, lvalue, rvalue)
    if not printable_exactly(value):
        raise Unsuitable()  # every intermediate result exact in single precision too
    return f"{left} {op} {right}", value, own


def printable_exactly(value: Fraction) -> bool:
    """Dyadic, at most 7 significant digits, not too large: both BASICs print the same bytes."""
    denominator = value.denominator
    return (denominator & (denominator - 1)) == 0 and significant_digits(value) <= 7 and abs(value) < 1e6


def exact_expression(rng: random.Random, depth: int, names: dict[str, Fraction] | None = None) -> tuple[str, Fraction]:
    """An expression whose value both BASICs compute and print exactly."""
    while True:
        try:
            text, value, _ = random_expression(rng, depth, names or {})
        except (Unsuitable, ZeroDivisionError, OverflowError):
            continue
        if printable_exactly(value):
            return text, value


# ---------------------------------------------------------------------------
# Blocks
# ---------------------------------------------------------------------------

def small_number(rng: random.Random) -> Fraction:
    return Fraction(rng.randint(-6, 12)) / rng.choice([1, 1, 2, 4])


def for_block(rng: random.Random, prog: Program) -> None:
    """FOR/NEXT with odd bounds and steps; the variable's value after the loop."""
    start, stop = small_number(rng), small_number(rng)
    step = rng.choice([Fraction(1), Fraction(2), Fraction(3), Fraction(-1), Fraction(-2), Fraction(1, 2),
                       Fraction(-1, 4), Fraction(3, 2), Fraction(3, 4), Fraction(-5, 2)])
    if abs((stop - start) / step) > 9:  # GW-BASIC wraps lines at 80 columns, yaseer does not
        quarters = math.ceil(abs(stop - start) / 9 * 4)  # a dyadic step of at most 9 passes
        step = Fraction(quarters, 4) * (1 if step > 0 else -1)
    if not ZERO_TRIP_LOOPS and (stop - start) * step < 0:
        step = -step
    var = rng.choice("IJK")
    step_text = "" if step == 1 and rng.random() < 0.5 else f" STEP {basic_number(float(step))}"
    head = f"FOR {var} = {basic_number(float(start))} TO {basic_number(float(stop))}{step_text}"
    if rng.random() < 0.5:
        prog.line(f"{head}: PRINT {var};: NEXT {var}: PRINT: PRINT {var}")
        return
    inner = "M" if var != "M" else "N"
    prog.line(head)
    prog.line(f"PRINT {var};")
    # A loop run zero times skips to its NEXT; GW-BASIC then chokes on "NEXT M, I", so only the
    # form "NEXT M: NEXT" gets zero-trip inner loops.
    combined = rng.random() < 0.5
    fewest = 1 if combined or not ZERO_TRIP_LOOPS else 0
    prog.line(f"FOR {inner} = 1 TO {rng.randint(fewest, 3)}: PRINT \"*\";")
    prog.line(f"NEXT {inner}, {var}" if combined else f"NEXT {inner}: NEXT")
    prog.line(f"PRINT: PRINT {var}; {inner}")


def gosub_block(rng: random.Random, prog: Program) -> None:
    """A chain of nested GOSUBs, each printing on the way in and out."""
    depth = rng.randint(1, 4)
    target = None
    for level in range(depth, 0, -1):
        call = [f"GOSUB {target}"] if target else []
        body = [f'PRINT "in{level}";'] + call + [f"R = R + {level}", f'PRINT "out{level}";', "RETURN"]
        target = prog.sub(body)
    prog.line(f"R = 0: GOSUB {target}: PRINT R")


def if_block(rng: random.Random, prog: Program) -> None:
    """IF / ELSE IF chains, several statements after THEN, THEN line-number."""
    value = rng.randint(-3, 8)
    prog.line(f"X = {value}")
    a, b = sorted(rng.sample(range(-2, 7), 2))
    prog.line(f'IF X > {b} THEN PRINT "big": PRINT X ELSE IF X > {a} THEN PRINT "mid" ELSE PRINT "low"')
    cond = f"X >= {a} AND X <= {b}" if rng.random() < 0.5 else f"X < {a} OR NOT X < {b}"
    skip = prog.reserve() + 20
    prog.line(f"IF {cond} THEN {skip}")
    prog.line('PRINT "not taken"')
    prog.line(f'IF X = {value} THEN PRINT "eq"; ELSE PRINT "ne";')
    prog.line('PRINT "after"')


def on_goto_block(rng: random.Random, prog: Program) -> None:
    """ON K GOTO / ON K GOSUB for K below, inside and above the list."""
    n = rng.randint(1, 4)
    if rng.random() < 0.5:
        targets = [prog.sub([f'PRINT "s{i}";', "RETURN"]) for i in range(1, n + 1)]
        prog.line(f"FOR K = 0 TO {n + 1}: ON K GOSUB {', '.join(map(str, targets))}: PRINT K;: NEXT K: PRINT")
        return
    first = prog.reserve()
    # layout: first: FOR..; ON..GOTO; fallthrough; n target lines; last: NEXT
    last = first + 10 * (n + 3)
    targets = [first + 20 + 10 * i for i in range(1, n + 1)]
    prog.line(f"FOR K = 0 TO {n + 1}")
    prog.line(f"ON K GOTO {', '.join(map(str, targets))}")
    prog.line(f'PRINT "none";: GOTO {last}')
    for i in range(1, n + 1):
        prog.line(f'PRINT "t{i}";: GOTO {last}')
    prog.line("NEXT K: PRINT")


def data_value(rng: random.Random) -> tuple[str, str]:
    """A DATA item and its kind ("n" / "s")."""
    if rng.random() < 0.6:
        return basic_number(float(small_number(rng))), "n"
    text = random_string(rng).strip() or "x"
    return f'"{text}"', "s"


def data_block(rng: random.Random, prog: Program) -> None:
    """DATA (in the main line, skipped over), READ, RESTORE to it, READ again."""
    items = [data_value(rng) for _ in range(rng.randint(1, 6))]
    first_data = prog.line("DATA " + ", ".join(text for text, _ in items))
    if rng.random() < 0.5:
        prog.line(f"DATA {basic_number(float(small_number(rng)))}")
    prog.line(f"RESTORE {first_data}")
    names = [f"S{i}$" if kind == "s" else f"V{i}" for i, (_, kind) in enumerate(items)]
    prog.line("READ " + ", ".join(names))
    prog.line("PRINT " + "; ".join(names))
    prog.line(f"RESTORE {first_data}: READ {names[0]}: PRINT {names[0]}")


def string_block(rng: random.Random, prog: Program) -> None:
    """LEFT$ RIGHT$ MID$ LEN CHR$ ASC STR$ VAL, concatenation and comparison."""
    a = random_string(rng) or "abc"
    b = random_string(rng)
    n = rng.randint(0, len(a) + 2)
    start = rng.randint(1, len(a) + 2)
    prog.line(f'A$ = "{a}": B$ = "{b}"')
    prog.line(f'PRINT LEFT$(A$, {n}); "|"; RIGHT$(A$, {n}); "|"; MID$(A$, {start}); "|"; MID$(A$, {start}, {n})')
    prog.line(f'PRINT LEN(A$ + B$); ASC(A$); CHR$({rng.randint(65, 90)}); "|"; A$ + B$ + "!"')
    number = basic_number(float(small_number(rng)))
    prog.line(f'PRINT STR$({number}); VAL("{number}"); VAL(" 12.5xyz"); VAL("")')
    prog.line("PRINT A$ < B$; A$ = B$; A$ > B$; A$ <> A$ + \"\"")


def expression_block(rng: random.Random, prog: Program) -> None:
    """Operator precedence: random expressions printed with their variables."""
    names: dict[str, Fraction] = {}
    for _ in range(rng.randint(1, 3)):
        name = rng.choice(SCALARS) + rng.choice(["", "1", "2"])
        text, value = exact_expression(rng, 2, names)
        names[name] = value
        prog.line(f"{name} = {text}")
    parts = [exact_expression(rng, rng.randint(1, 4), names)[0] for _ in range(rng.randint(1, 3))]
    prog.line("PRINT " + "; ".join(parts))


def using_block(rng: random.Random, prog: Program) -> None:
    """PRINT USING with a random format and matching values."""
    from test_differential_support import random_using_case, using_statement

    fmt, values = random_using_case(rng)
    prog.line(using_statement(fmt, values))


def def_fn_block(rng: random.Random, prog: Program) -> None:
    """DEF FN with a parameter that shadows a variable."""
    k = rng.randint(-3, 5)
    prog.line(f"X = {k}: DEF FNA(X) = X * X + {rng.randint(0, 9)}")
    prog.line(f"PRINT FNA({rng.randint(-4, 4)}); FNA(X + 1); X")


def on_error_block(rng: random.Random, prog: Program) -> None:
    """ON ERROR GOTO with RESUME NEXT: a subscript out of range (G has the implicit 10) is trapped."""
    handler = prog.sub(["PRINT \"err\"; ERR; ERL", "RESUME NEXT"])
    prog.line(f"ON ERROR GOTO {handler}")
    prog.line(f"G({rng.randint(11, 15)}) = 1: PRINT \"resumed\"")
    prog.line("ON ERROR GOTO 0")


def functions_block(rng: random.Random, prog: Program) -> None:
    """INT FIX SGN ABS of dyadic values, PRINT zones (,), TAB and SPC, ON with a fraction."""
    values = [basic_number(float(small_number(rng) + Fraction(rng.choice([0, 1, 3]), 8))) for _ in range(3)]
    prog.line(f"W = {values[0]}: PRINT INT(W); FIX(W); SGN(W); ABS(W), INT({values[1]}), FIX(-{values[2]})")
    prog.line(f'PRINT "a"; TAB({rng.randint(1, 20)}); "b"; SPC({rng.randint(0, 5)}); "c",, "d"')
    target = prog.sub(['PRINT "one";', "RETURN"])
    second = prog.sub(['PRINT "two";', "RETURN"])
    prog.line(f"ON {rng.choice(['1.4', '1.5', '1.6', '2.4', '0.4'])} GOSUB {target}, {second}: PRINT")


def control_block(rng: random.Random, prog: Program) -> None:
    """GOTO out of a FOR loop and back in, GOSUB from inside a loop, NEXT without a name, IF...THEN n ELSE m."""
    sub = prog.sub(['PRINT "g";', "IF J = 2 THEN RETURN", 'PRINT "h";', "RETURN"])
    prog.line(f"FOR J = 1 TO {rng.randint(1, 4)}: GOSUB {sub}: NEXT: PRINT J")
    first = prog.reserve()
    prog.line(f"FOR J = 1 TO 5: IF J = {rng.randint(1, 6)} THEN {first + 20}")
    prog.line(f"PRINT J;: NEXT J: PRINT \"all\": GOTO {first + 30}")
    prog.line('PRINT "left at"; J')
    w = rng.randint(-2, 3)
    prog.line(f"W = {w}: IF W THEN {first + 50} ELSE {first + 60}")
    prog.line('PRINT "zero": GOTO 1')  # never reached
    prog.line(f"IF W > 0 THEN PRINT \"pos\" ELSE IF W < 0 THEN PRINT \"neg\" ELSE PRINT \"nil\"")
    prog.main[-2] = prog.main[-2].replace("GOTO 1", f"GOTO {first + 70}")
    prog.line(f"PRINT \"x\" \"y\"; -0; 2 ^ 3 ^ 2; -2 ^ 2; 2 ^ -1; {rng.randint(1, 9)},")
    prog.line("PRINT , \"z\"")


def data_layout_block(rng: random.Random, prog: Program) -> None:
    """READ across DATA lines, empty items, unquoted strings with inner blanks, RESTORE without a line."""
    prog.line("RESTORE")
    prog.line(f"DATA {rng.randint(-9, 9)}, abc def ,, \"q,r\"")
    prog.line(f"DATA {basic_number(float(small_number(rng)))}")
    prog.line("RESTORE " + str(prog.next_main - 20))
    prog.line("READ P, P1$, P2$, P3$, P4: PRINT P; \"[\"; P1$; \"][\"; P2$; \"][\"; P3$; \"]\"; P4")


ARRAY_NAMES = "BCDEFHJK"  # not A (the paper's implicit A(53)), G (ON ERROR block), nor the loop letters


def array_block(rng: random.Random, prog: Program) -> None:
    """DIM, a FOR loop filling an array, READ into elements, a 2-D array, a sum."""
    free = [name for name in ARRAY_NAMES if name not in prog.arrays]
    if len(free) < 2:
        return
    one, two = free[0], free[1]
    prog.arrays.update((one, two))
    size = rng.randint(3, 12)
    scale = rng.choice([1, 2, 3])
    prog.line(f"DIM {one}({size}), {two}(2, 3)")
    prog.line(f"FOR K = 0 TO {size}: {one}(K) = K * {scale} - {rng.randint(0, 5)}: NEXT K")
    items = [basic_number(float(small_number(rng))) for _ in range(3)]
    data_line = prog.line("DATA " + ", ".join(items))
    prog.line(f"RESTORE {data_line}: READ {one}(1), {two}(2, 3), {two}(0, 0)")
    prog.line(f"S = 0: FOR K = {size} TO 0 STEP -1: S = S + {one}(K): NEXT: PRINT S; {two}(2, 3); {two}(0, 0); {two}(1, 1)")


def error_block(rng: random.Random, prog: Program) -> None:
    """An error inside a subroutine, trapped; RESUME to a line; ERR and ERL; the trap switched off."""
    after = prog.reserve() + 20
    handler = prog.sub(['PRINT "E"; ERR; ERL;', f"RESUME {after}"])
    failing = prog.sub(["PRINT \"s\";", f"X = ASC(\"\")" if rng.random() < 0.5 else "X = SQR(-1)",
                        'PRINT "not here"', "RETURN"])
    prog.line(f"ON ERROR GOTO {handler}")
    prog.line(f"GOSUB {failing}")
    prog.line(f'PRINT "back"; {"ERR; " if ERR_AFTER_RESUME else ""}ERL: ON ERROR GOTO 0')


def zone_block(rng: random.Random, prog: Program) -> None:
    """Comma zones after strings of every length, TAB behind the cursor, a trailing comma."""
    # at most 12 characters a word: GW-BASIC's comma wraps to a new line past the
    # 80-column screen's last full zone, yaseer has no screen width
    words = ['"' + "x" * rng.randint(0, 12) + '"' for _ in range(3)]
    prog.line(f"PRINT {words[0]}, {words[1]}; {words[2]},")
    prog.line(f'PRINT TAB({rng.randint(1, 30)}); "t"; TAB({rng.randint(1, 30)}); "u"; SPC({rng.randint(0, 9)}); 5')


EXACT_BLOCKS = [for_block, gosub_block, if_block, on_goto_block, data_block, string_block,
                expression_block, using_block, def_fn_block, on_error_block, functions_block, control_block,
                data_layout_block, array_block, error_block, zone_block]


# ---------------------------------------------------------------------------
# Numeric blocks: compared within 1e-6
# ---------------------------------------------------------------------------

FUNCTIONS = {
    "SQR": (lambda x: math.sqrt(abs(x)) if x >= 0 else None),
    "SIN": math.sin, "COS": math.cos, "ATN": math.atan,
    "EXP": (lambda x: math.exp(x) if x < 20 else None),
    "LOG": (lambda x: math.log(x) if x > 0 else None),
}


def numeric_block(rng: random.Random, prog: Program) -> None:
    """Quotients and transcendental functions, printed to full precision."""
    x = rng.randint(1, 40) / rng.choice([1, 4, 8])
    y = rng.choice([3, 7, 9, 11, -6])
    prog.line(f"X = {basic_number(x)}: Y = {y}")
    name = rng.choice(sorted(FUNCTIONS))
    prog.line(f"PRINT X / Y; {name}(X); SQR(X * X + Y * Y); ATN(Y / X)")
    prog.line(f"Z = 0: FOR I = 1 TO {rng.randint(2, 9)}: Z = Z + 1 / I: NEXT I: PRINT Z")


def random_program(rng: random.Random, numeric: bool = False) -> Program:
    """A program of 3-7 blocks (exact ones, and numeric ones if ``numeric``)."""
    prog = Program(numeric=numeric)
    blocks = EXACT_BLOCKS + ([numeric_block] * 4 if numeric else [])
    for _ in range(rng.randint(3, 7)):
        rng.choice(blocks)(rng, prog)
    if rng.random() < 0.1:
        prog.final = "STOP"
    return prog
