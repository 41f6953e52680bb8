"""The FX-850P/880P's own statements and the functions that need the machine: a mixin
of :class:`~yaseer.basic.machine.Machine` (the casio dialect's words,
yaseer/basic/dialects/casio.py, compile to calls of these methods).

Each method follows its page of the owner's manual (commands/*.md).  The machine
keeps what the pocket computer keeps: the angle unit, the segment DEFSEG set and
the bytes POKE wrote (a dictionary of 20-bit addresses, which PEEK reads back), the
password, the output format SET chose, whether PRINT also goes to the printer
(MODE 7), and the last RAN#.
"""

from __future__ import annotations

import functools

from yaseer.basic.arithmetic import formatting
from yaseer.basic.arithmetic import casio_math
from yaseer.basic.dialects import casio
from yaseer.basic.compile.number_models import initial_value
from yaseer.basic.machine import io_statements, runtime, string_space
from yaseer.basic.errors import (
    BasicError, OUT_OF_MEMORY, OVERFLOW, PASSWORD_PROTECTED, SYNTAX_ERROR, TYPE_MISMATCH, not_emulated,
)
from yaseer.patterns import Pattern

ANGLE_UNITS = ("DEG", "RAD", "GRA")  # ANGLE 0, 1, 2 (ANGLE.md)
MODE_ANGLES = {4: "DEG", 5: "RAD", 6: "GRA"}  # the MODE key's angle units (ANGLE.md, item 4)
PRINTER_ON, PRINTER_OFF = 7, 8  # MODE 7 / MODE 8 (part 7, "PRT ON mode")
VARLIST_COLUMN = 8  # VARLIST.md shows the names in columns of 8 on the 32-column display
# FRE's memory (bytes): the FX-880P's standard RAM with its 3 KB system area
# (specifications.md) and the variable area ALL RESET sets (CLEAR.md's table: 8192 on the
# FX-880P; a program cannot change it, CLEAR.md item 3).
RAM_BYTES = 32 * 1024
SYSTEM_BYTES = 3 * 1024
VARIABLE_AREA = casio.VARIABLE_AREA


def _whole_in(x: float, low: int, high: int) -> int:
    """``x`` truncated to an integer, which must be in low..high (else Illegal function call)."""
    n = int(x)
    if not low <= n <= high:
        raise casio_math.illegal()
    return n


def _operand16(x: float) -> float:
    """An operand of ``¥`` and MOD: truncated, in -32768..32767 (MOD.md), else Overflow."""
    n = int(x)
    if not -32768 <= n <= 32767:
        raise BasicError("Overflow", OVERFLOW)
    return float(n)


def int_divide(a: float, b: float) -> float:
    """a ¥ b on the truncated operands (part 6, Arithmetic Operators: -15 ¥ 7 is -2)."""
    return runtime.int_divide(_operand16(a), _operand16(b))


def modulo(a: float, b: float) -> float:
    """a MOD b on the truncated operands, the sign of the dividend (MOD.md: -15 MOD 7 is -1)."""
    return runtime.modulo(_operand16(a), _operand16(b))


# The string functions' counts, truncated to integers in the pages' ranges (else Illegal
# function call): CHR_STRING.md 0 <= code < 256, LEFT_STRING.md and RIGHT_STRING.md
# 0 <= count < 256, MID_STRING.md 1 <= position < 256 and 0 <= count < 256; yaseer's common
# runtime rounds them (runtime.cint).
def chr_dollar(code: float) -> str:
    return chr(_whole_in(code, 0, 255))


def left_dollar(s: str, n: float) -> str:
    return s[:_whole_in(n, 0, 255)]


def right_dollar(s: str, n: float) -> str:
    k = _whole_in(n, 0, 255)
    return s[len(s) - k:] if k < len(s) else s


def mid_dollar(s: str, start: float, n: float | None = None) -> str:
    i = _whole_in(start, 1, 255) - 1
    return s[i:] if n is None else s[i:i + _whole_in(n, 0, 255)]


STRING_FUNCTIONS = {"_chr": chr_dollar, "_left": left_dollar, "_right": right_dollar, "_mid": mid_dollar}


# The operators whose operands the Casio truncates (part 6: "Fractions are truncated in
# ¥ and MOD"; logical operations: "operands truncated to integers"), where yaseer's
# common runtime rounds them (runtime.cint).
OPERATORS = {
    "_idiv": int_divide, "_mod": modulo,
    "_and": lambda a, b: float(int(a) & int(b)), "_or": lambda a, b: float(int(a) | int(b)),
    "_xor": lambda a, b: float(int(a) ^ int(b)), "_not": lambda a: float(~int(a)),
}


class CasioWords:
    """The casio statements' and machine functions' methods (see the module docstring)."""

    def init_casio_words(self) -> None:
        # (DEFSEG's ``segment`` and POKE's ``memory`` are the console's: console.py, PEEK)
        self.password_set: str | None = None
        self.print_echo = False  # MODE 7: PRINT also prints on the printer
        self.last_ran = 0.5
        self.string_slack = 0  # bytes of the variable area surely free for strings (string_room)
        self.err_codes = self.dialect.words.err_values if self.dialect.words else {}
        if self.dialect.words:
            self.system_memory = self.dialect.words.system_memory

    # -- statements
    def set_angle_number(self, n: float) -> None:
        """ANGLE n: 0 degrees, 1 radians, 2 grads (n truncated; 0 <= n < 3)."""
        self.set_angle(ANGLE_UNITS[_whole_in(n, 0, 2)])

    def beep(self, tone: float = 0.0) -> None:
        """BEEP [0|1]: the buzzer, a low or a high tone.  yaseer has no buzzer: a terminal
        hears its bell; output to a file or a pipe is left as it is.  A drawn screen that
        changed since it was last shown is shown (the beep calls the user to the LCD: LIB0400's
        ``NG RAM 1`` before its endless BEEP loop)."""
        if self.display is not None and self.display.changed:
            self.show_screen()
        self.ring_bell()

    def ring_bell(self) -> None:
        """The terminal's bell, where standard output is one (gw's BEEP: the PC's speaker);
        output to a file or a pipe is left as it is."""
        stream = self.screen.stream
        isatty = getattr(stream, "isatty", None)
        if isatty is not None and isatty():
            stream.write("\a")
            stream.flush()

    def define_segment(self, segment: float) -> None:
        """DEFSEG = s: the segment PEEK and POKE add (times 16) to their addresses;
        -32768 <= s < 65536, a negative segment counts from 65536."""
        self.segment = _whole_in(segment, -32768, 65535) % 65536

    def poke(self, offset: float, data: float) -> None:
        """POKE a, d: the byte d (0..255, truncated) at address a of the segment."""
        self.memory[self._address(offset)] = _whole_in(data, 0, 255)  # (the address as PEEK's: console.py)

    def password(self, text: str) -> None:
        """PASS "word": registers the password (its first 8 characters), or cancels it when
        it is the one registered; another one is the PR error."""
        word = text[:8]
        if not word:
            raise casio_math.illegal()
        if self.password_set is None:
            self.password_set = word
        elif word == self.password_set:
            self.password_set = None
        else:
            raise BasicError("Wrong password", PASSWORD_PROTECTED)

    def mode(self, n: float) -> None:
        """MODE 4, 5, 6: degrees, radians, grads; MODE 7 / MODE 8: PRINT also on the
        printer, or not.  The other modes are keyboard modes (CAL, BASIC, ...) or the
        machine's own routines: Illegal function call in a program."""
        k = int(n)
        if k in MODE_ANGLES:
            self.set_angle(MODE_ANGLES[k])
        elif k in (PRINTER_ON, PRINTER_OFF):
            self.print_echo = k == PRINTER_ON
        else:
            raise casio_math.illegal()

    def calc_jump(self) -> None:
        """CALCJMP: the program ends and the CAL mode executes the formula CALC$ holds, as its
        CALC key does (part 5, the data bank example: the display cleared, ``X?`` asks for
        the formula's variable).  Each variable of the right-hand side is asked for in the
        order it first appears, as its name and a ``[...]`` comment written after it
        (``x[cm]?``); EXE alone keeps its value (as INPUT, INPUT.md item 7).  The value is
        assigned to the left-hand side and shown as ``X[in]= 3.93701``; EXE runs the formula
        again (the run ends when the keys do, or at BRK).  The manual's part 4 (formula
        storage) is empty in its text: the comment and the repetition follow the library's
        use (LIB5950-5980: formulas such as ``X[in]=.393701*x[cm]``)."""
        left, left_label, right, asked = _formula(self.scalar("CALC$"), self.dialect)
        compiled = _valf_code(right, self.dialect)
        while True:
            self.clear_screen()
            for name, label in asked:
                while True:
                    line = self._read_line(label + "?").strip()
                    if not line:
                        break
                    values = _number_answer(line, self.dialect)
                    if values is not None:
                        self.set_scalar(name, values)
                        break
            value = self._evaluated(compiled)
            if left is not None:
                self.set_scalar(left, value)
            self.print_items(0, ((left_label + "=",) if left is not None else ()) + (value,), False)
            self._read_line("")  # the result stays until EXE, which executes the formula again

    def pb_tape(self, name: str = "") -> None:
        """PBLOAD, PBGET: a PB-100 series tape (not emulated: see not_emulated)."""
        raise not_emulated("PBLOAD/PBGET: reading PB-100 series tapes")

    def pb_memory(self, n: float) -> None:
        """DEFM n: the PB-100 series' memory declaration (not emulated: see not_emulated)."""
        raise not_emulated("DEFM: the PB-100 series' memory declaration")

    def rom_routine(self, number: float, *args) -> None:
        """MODE n(...): a machine-code routine of the ROM.  The manual does not describe them.
        MODE 33 is emulated as LIB1000 (the memory calculator) uses it after EXE: the text of
        the cursor's line (from its first column through the rows it wrapped into, trailing
        blanks dropped) becomes CALC$, which the program evaluates with VALF.  Any other
        routine ends the run with one line (see not_emulated)."""
        if int(number) != self.dialect.words.line_to_calc or self.display is None:
            raise not_emulated(f"MODE {int(number)}(...): a machine-code routine of the ROM")
        display = self.display
        self.set_scalar("CALC$", display.logical_line_from(0, display.row()).rstrip(" "))

    def variable_list(self) -> None:
        """VARLIST: the names of the variables (as they were written, in the order of their
        characters) and of the arrays (with ``()``), in columns of 8, four to a line of the
        32-column display."""
        names = sorted(self.scalars) + [name + "()" for name in sorted(self.arrays)]
        width = 4 * VARLIST_COLUMN
        line = ""
        for name in names:
            cell = name.ljust(VARLIST_COLUMN * -(-len(name) // VARLIST_COLUMN))
            if len(line) + len(cell) > width:
                self.print_items(0, (line.rstrip(),), True)
                line = ""
            line += cell
        if line:
            self.print_items(0, (line.rstrip(),), True)

    def set_format(self, style: str, digits: int) -> None:
        """SET F n (n decimals), SET E n (n significant digits, E0 ten), SET N (neither):
        how PRINT and LPRINT show numbers from now on (SET.md)."""
        if style == "N":
            self._number_text = formatting.number_to_text
        else:
            self._number_text = functools.partial(casio_math.formatted_number, style=style, digits=digits)

    # -- functions that need the machine
    def free_area(self, n: float) -> float:
        """FRE n (FRE.md; n truncated, 0..3): 0 the unused bytes of the variable area, 1 the
        unused bytes of the program and DATA BANK area, 2 the whole variable area; 3 (in the
        page's range, not explained there) the whole program and DATA BANK area.  Bytes are
        counted as part 6 counts them ("Counting Bytes used by Variables", "Calculating
        Program Length": keywords at their spelled length, where the machine stores 2)."""
        k = _whole_in(n, 0, 3)
        if k == 0:
            return float(max(VARIABLE_AREA - self.variable_bytes(), 0))
        if k == 2:
            return float(VARIABLE_AREA)
        area = RAM_BYTES - SYSTEM_BYTES - VARIABLE_AREA
        if k == 3:
            return float(area)
        bank = self.__dict__.get("_data_bank")
        used = sum(2 + 1 + len(text) + 1 for lines in self.programs.values() for text in lines.values())
        used += len(self.programs) + (sum(len(r) + 1 for r in bank.records) if bank else 0)
        return float(max(area - used, 0))

    def string_room(self, new: str, old: str) -> str:
        """``_sroom``: a string ``new`` stored in place of ``old`` (an array element's old
        text counts as ""), returned; when the variables would then take more than the
        variable area: Out of memory (OM), the variable unchanged.  Part 6 counts a string's
        length + 1 (CLEAR.md, FRE 2: 8192 bytes).  ``string_slack`` is the bytes surely still
        free: each growth takes from it and only when it runs out are the variables counted
        (with the running block's locals, not stored back yet), so a loop of small strings
        counts them rarely."""
        grown = len(new) - len(old)
        if grown > 0:
            self.string_slack -= grown
            if self.string_slack < 0:
                free = VARIABLE_AREA - self.variable_bytes(string_space.block_locals()) - grown
                self.string_slack = max(free, 0)
                if free < 0:
                    raise BasicError("Out of memory", OUT_OF_MEMORY)
        return new

    def variable_bytes(self, block_locals: dict | None = None) -> int:
        """The bytes the variables take in the variable area (part 6: a number name + 12, a
        string name + 4 and its length + 1; an array name + 4, 8 a number or 1 a string (and
        its length) an element, 2 a dimension, and 1 more for numbers); ``block_locals``: the
        running block's scalars, not stored back yet."""
        used = 0
        for name, value in self.scalars_with(block_locals).items():
            used += len(name) + (4 + len(value) + 1 if name.endswith("$") else 12)
        for name, dims in self.array_dims.items():
            elements = 1
            for d in dims:
                elements *= d + 1
            if name.endswith("$"):
                used += len(name) + 4 + elements + 2 * len(dims) + sum(len(t) for t in _flat(self.arrays[name]))
            else:
                used += len(name) + 4 + 8 * elements + 2 * len(dims) + 1
        return used

    def ran(self, x: float | None = None) -> float:
        """RAN#(x) (RAN_HASH.md): x > 0 the next number of the table RUN restarts (the same
        series at every run), 0 the last number again, x < 0 or no argument a number from
        the random table (a generator the system seeds); always 0 < value < 1."""
        import random  # here: a run without random numbers does not load it (start-up)

        if x is not None and x > 0:
            value = self.random.rnd(1.0)
        elif x == 0:
            return self.last_ran
        else:
            value = random.random()  # the random table: Python's generator, seeded by the system
        while value == 0.0:
            value = random.random()
        self.last_ran = value
        return value

    def valf(self, text: str) -> float:
        """VALF(s$): the numeric expression ``s$`` evaluated with the variables as they are
        (VALF.md); a VALF inside it is Illegal function call, a string Type mismatch."""
        return self._evaluated(_valf_code(text, self.dialect))

    def input_expression(self, text: str) -> list | None:
        """INPUT's answer for a numeric variable that is no number: ``[value]`` of the numeric
        expression typed (INPUT.md item 9), evaluated as VALF evaluates one (in the run's
        arithmetic); a string is Type mismatch (item 5); None for an answer that does not
        read as an expression (asked again)."""
        try:
            value = self.valf(text)
        except BasicError as err:
            if err.code == SYNTAX_ERROR:
                return None
            raise
        return [value]

    def _evaluated(self, compiled: tuple) -> float:
        """The value of ``compiled`` (:func:`_valf_code`'s code and the scalars it reads) with
        the variables as they are; a variable the program never named is made (0, or "")."""
        code, names = compiled
        for name in names:
            if name not in self.scalars:
                self.scalars[name] = initial_value(name)
        namespace = self.namespaces.get(0) or next(iter(self.namespaces.values()))
        return eval(code, namespace)  # noqa: S307 - code the compiler generated from BASIC


def _formula(text: str, dialect) -> tuple:
    """A CAL-mode formula ``left=right`` (or an expression alone) read as (the left-hand
    variable or None, its label, the right-hand expression, [(variable, label), ...] of the
    right-hand side in the order they first appear).  A label is the variable's name with
    the ``[...]`` comment written after it; the expression is read without the comments."""
    from yaseer.basic.source import syntax_tree as ast

    labels = {}
    for match in _COMMENTED.finditer(text):
        labels.setdefault(match.group(1), match.group(0))
    plain = _COMMENTED.sub(r"\1", text)
    left, equals, right = plain.partition("=")
    if not equals or not _NAME.fullmatch(left.strip()):
        left, right = None, plain
    else:
        left = left.strip()
    names = dict.fromkeys(n.name for n in _nodes(_expression(right, dialect)) if isinstance(n, ast.Var))
    asked = [(name, labels.get(name, name)) for name in names if not name.endswith("$")]
    left_label = labels.get(left, left) if left is not None else ""
    return left, left_label, right, asked


# A variable name with the comment in brackets written after it (``x[cm]``), and a name alone.
_COMMENTED = Pattern(r"([A-Za-z][A-Za-z0-9]*)(\[[^\]]*\])")
_NAME = Pattern(r"[A-Za-z][A-Za-z0-9]*")


def _expression(text: str, dialect):
    """The syntax tree of the BASIC expression ``text`` (read as the value of an assignment);
    anything else is a Syntax error."""
    from yaseer.basic.source import syntax_tree as ast
    from yaseer.basic.source.parser import parse_statements

    try:
        statements = parse_statements("X=" + text, dialect)
    except BasicError:
        raise BasicError("Syntax error", SYNTAX_ERROR) from None
    if len(statements) != 1 or not isinstance(statements[0], ast.Let):
        raise BasicError("Syntax error", SYNTAX_ERROR)
    return statements[0].value


def _number_answer(line: str, dialect) -> float | None:
    """The number typed for a formula's variable (INPUT's reading of one number), or None."""
    values = io_statements.parse_input(line, "n", dialect.number_reading, dialect.string_length)
    return None if values is None else values[0]


def _flat(array):
    """The elements of a (nested) array."""
    for item in array:
        if isinstance(item, list):
            yield from _flat(item)
        else:
            yield item


@functools.lru_cache(maxsize=256)
def _valf_code(text: str, dialect) -> tuple[str, tuple[str, ...]]:
    """The Python expression VALF evaluates for the BASIC expression ``text``, and the
    names of the scalars it reads."""
    from yaseer.basic.source import syntax_tree as ast
    from yaseer.basic.compile.expressions import FnScope
    from yaseer.basic.compile.compiler import AreaCompiler

    node = _expression(text, dialect)
    if any(isinstance(n, ast.Call) and n.name == "VALF" for n in _nodes(node)):
        raise casio_math.illegal()
    compiler = AreaCompiler([], direct=True, dialect=dialect)
    code, kind = compiler.expr(node, FnScope(compiler, []))
    if kind == "s":
        raise BasicError("Type mismatch", TYPE_MISMATCH)
    return code, tuple(sorted(compiler.scalars))


def _nodes(node):
    """``node`` and every expression node inside it."""
    yield node
    for name in getattr(node, "_fields", ()):
        value = getattr(node, name)
        for part in value if isinstance(value, (list, tuple)) else (value,):
            if hasattr(part, "_fields"):
                yield from _nodes(part)
