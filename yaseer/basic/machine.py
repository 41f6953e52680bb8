"""The BASIC machine: variables, arrays, program areas, the run loop, and I/O.

A :class:`Machine` holds the state a pocket computer holds: scalars (a dict
name -> float or str), arrays (name -> list, nested for more than one
dimension), the GOSUB/FOR stack, the program areas (area 0 is the listing;
``GOSUB PROG n`` runs area n, a Python callable or another BASIC program that
shares the variables), the screen and printer streams.

Typical use::

    m = Machine()
    m.load(text)          # area 0; lines are kept as line -> text
    m.run()               # compiles on RUN, raises BasicError on an error
    m.execute_direct("PRINT A")

Python program areas use ``array(name)``, ``scalar(name)``, ``set_scalar``.
"""

from __future__ import annotations

import contextlib
import math
import signal
import sys
from functools import lru_cache

from yaseer.basic import (
    arith_policy, dialect as dialects, formatting, gwfunctions, numbers, program_cache, runtime, val_numbers,
)
from yaseer.basic.number_models import initial_value
from yaseer.basic.files import FileTable, Sandbox
from yaseer.basic.compiled import MAX_STACK, CompiledArea  # MAX_STACK: GOSUB returns + open FOR loops together
from yaseer.basic.errors import (
    BasicError, OutputError, BAD_FILE_NAME, BREAK, CANT_CONTINUE, DIVISION_BY_ZERO, DUPLICATE_DEFINITION, FILE_NOT_FOUND, FOR_WITHOUT_NEXT,
    ILLEGAL_FUNCTION_CALL, NEXT_WITHOUT_FOR, OUT_OF_DATA, OUT_OF_MEMORY, OVERFLOW,
    RESUME_WITHOUT_ERROR, RETURN_WITHOUT_GOSUB, SUBSCRIPT_OUT_OF_RANGE, SYNTAX_ERROR,
    UNDEFINED_PROGRAM_AREA, UNDEFINED_USER_FUNCTION,
)
from yaseer.basic.scanner import entry_messages, split_lines
from yaseer.basic.screen import DEVICE_WIDTHS, SCREEN_WIDTHS, OutputStream

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up, issue 15)
    from typing import Callable, TextIO


# Resource limits (each exceeded limit is "Out of memory in N").
MAX_AREA_DEPTH = 100  # GOSUB PROG nesting
MAX_ARRAY_ELEMENTS = 2_000_000  # per array
MAX_TOTAL_ELEMENTS = 8_000_000  # all arrays together (about 64 MB)
INPUT_PAST_END = 62
INTERNAL_ERROR = 51



class ProgramEnd(BaseException):
    """END, or the program ran off its last line."""


class ProgramStop(BaseException):
    """STOP: ``area`` and ``block`` are where CONT resumes."""

    def __init__(self, area: int, block: int, line):
        super().__init__("Break")
        self.area, self.block, self.line = area, block, line


class BreakPoint(ProgramStop):
    """Ctrl-C landed where CONT can resume (see ``Machine.resumable_breaks``).

    ``block`` of ``area`` is where to go on; ``loops`` the native FOR loops that
    were open there, outermost first, as ``(FOR index, FOR-stack key, value,
    limit, step)`` (value None for an array element, which holds its own);
    ``depth`` the GOSUB PROG nesting it happened at (only 0 is resumable).
    """

    def __init__(self, area: int, block: int, line, loops: tuple = (), depth: int = 0):
        super().__init__(area, block, line)
        self.loops, self.depth = loops, depth


class DirectJump(BaseException):
    """GOTO/THEN n typed in direct mode: continue the program at line n."""

    def __init__(self, line: int):
        super().__init__(line)
        self.line = line


class _AreaReturn:
    """Marks the GOSUB stack where a BASIC program area was entered."""


AREA_MARK = _AreaReturn()


class ForFrame:
    """An open FOR loop; ``next_id`` is the NEXT statement it is bound to (GW-BASIC),
    or None where any NEXT of its variable continues it."""

    __slots__ = ("key", "limit", "step", "body", "next_id")

    def __init__(self, key, limit, step, body, next_id=None):
        self.key, self.limit, self.step, self.body = key, limit, step, body
        self.next_id = next_id


class Tab:
    __slots__ = ("column",)

    def __init__(self, column):
        self.column = column


class Spc:
    __slots__ = ("count",)

    def __init__(self, count):
        self.count = count


COMMA = object()
NUMBER_THEN_COMMA = object()  # marks a PRINT number a comma follows (GW's blank rule)

END = ProgramEnd()


def to_basic_error(exc: BaseException) -> BasicError:
    """The BASIC error for an exception raised inside compiled code or a Python area."""
    if isinstance(exc, BasicError):
        return exc
    if isinstance(exc, KeyboardInterrupt):
        return BasicError("Break", BREAK)
    if isinstance(exc, ZeroDivisionError):
        return BasicError("Division by zero", DIVISION_BY_ZERO)
    if isinstance(exc, OverflowError):
        return BasicError("Overflow", OVERFLOW)
    if isinstance(exc, (RecursionError, MemoryError)):
        return BasicError("Out of memory", OUT_OF_MEMORY)
    if isinstance(exc, ValueError):
        return BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    if isinstance(exc, IndexError):
        return BasicError("Subscript out of range", SUBSCRIPT_OUT_OF_RANGE)
    if isinstance(exc, TypeError) and "subscript" in str(exc):
        return BasicError("Subscript out of range", SUBSCRIPT_OUT_OF_RANGE)
    return BasicError(f"Internal error ({type(exc).__name__}: {exc})", INTERNAL_ERROR)


@lru_cache(maxsize=4096)
def _parse_cached(number: int, text: str, dialect):
    from yaseer.basic.parser import parse_line  # here: a program read from the cache needs no parser

    return parse_line(number, text, dialect)


def _new_array(dims: tuple, fill):
    if len(dims) == 1:
        return [fill] * (dims[0] + 1)
    return [_new_array(dims[1:], fill) for _ in range(dims[0] + 1)]


class _AreaRuntime:
    """Per-area state the compiled code reaches: DATA pointer."""

    def __init__(self, machine: "Machine", number: int, compiled: CompiledArea):
        self.machine = machine
        self.number = number
        self.compiled = compiled
        self.data_index = 0

    def read_item(self) -> tuple[str, int]:
        data = self.compiled.data
        if self.data_index >= len(data):
            raise BasicError("Out of DATA", OUT_OF_DATA)
        item = data[self.data_index]
        self.data_index += 1
        return item

    def read_number(self) -> float:
        text, line = self.read_item()
        try:
            value = gwfunctions.number_field(text, self.machine.dialect.largest_number)
        except BasicError as err:
            raise err.at(line, self.number) from None
        if value is None:
            raise BasicError("Syntax error", SYNTAX_ERROR).at(line, self.number)
        return value

    def read_string(self) -> str:
        """The next DATA item as a string: a quoted item is the text between its quotes
        (an unclosed quote runs to the end); anything after the closing quote is a
        Syntax error in the DATA line (GW-BASIC)."""
        text, line = self.read_item()
        if not text.startswith('"'):
            return text
        end = text.find('"', 1)
        if end < 0:
            return text[1:]
        if text[end + 1:].strip():
            raise BasicError("Syntax error", SYNTAX_ERROR).at(line, self.number)
        return text[1:end]

    def restore(self, line) -> None:
        if line is None:
            self.data_index = 0
            return
        later = [i for number, i in self.compiled.data_lines.items() if number >= line]
        self.data_index = min(later) if later else len(self.compiled.data)


class Machine:
    """A pocket-computer BASIC machine (see the module docstring)."""

    def __init__(self, screen: TextIO | None = None, printer: TextIO | None = None,
                 output_format: str = "text", angle: str | None = None, input_stream: TextIO | None = None,
                 dialect: "str | dialects.Dialect" = "casio", files=None):
        # The dialect (scanner rules, number model, print rules, error policy, start-up
        # state: see dialect.py); ``angle`` overrides its start-up unit ("deg"/"rad").
        self.dialect = dialects.get_dialect(dialect)
        self.def_types: dict = {}  # gw: letter -> type character of the last DEF statements
        self.arith = arith_policy.ArithmeticPolicy(self)  # division by zero, overflow: stop or go on
        # how PRINT shows a number: typed (GW: integers, 7-digit singles, 16-digit D doubles) or not
        self._printed_number, self._number_text = (
            (_same, numbers.number_to_text) if self.dialect.typed_numbers else (_as_number, formatting.number_to_text))
        self.screen = OutputStream(screen if screen is not None else sys.stdout, self.dialect.width)
        self.printer = OutputStream(printer if printer is not None else self.screen.stream,
                                    self.dialect.printer_width, moves_items=False)
        if printer is None:
            self.printer = self.screen
        self.streams = (self.screen, self.printer)
        self.csv = output_format == "csv"
        self.default_angle = (angle or self.dialect.angle).upper()[:3]
        self.input_stream = input_stream
        self.programs: dict[int, dict[int, str]] = {}
        self.python_areas: dict[int, Callable] = {}
        self.compiled: dict[int, CompiledArea] = {}
        self.runtimes: dict[int, _AreaRuntime] = {}
        self.namespaces: dict[int, dict] = {}
        self.scalars: dict[str, object] = {}
        self.arrays: dict[str, list] = {}
        self.array_dims: dict[str, tuple] = {}
        self.explicit_arrays: set[str] = set()
        self.stack: list = []
        self.fns: dict[str, tuple] = {}
        self.line = None
        self.on_error = None
        self.in_handler = False
        self.pending_error = None  # the error a handler is running for
        self.err = 0.0
        self.erl = 0.0
        self.error_point = None
        self.cont_point = None
        self.area_depth = 0
        self.frame_body = 0
        self.angle = self.default_angle
        self.random = self.dialect.random()
        self._extra_entries: set[int] = set()
        self.array_elements = 0  # elements in all arrays (MAX_TOTAL_ELEMENTS)
        # Called as hook(machine, n) after every GOSUB PROG n returns (e.g. to record a
        # mechanism's positions for an animation); machine.line is the calling line.
        self.area_hooks: list[Callable] = []
        # Called as hook(device, values) when a printed line ends (device 0 PRINT, 1 LPRINT;
        # values: the numbers (float) and strings the line printed, in order). Only
        # collected while a hook is registered (yaseer.api keeps the printed rows).
        self.line_hooks: list[Callable] = []
        self._line_values: tuple[list, list] = ([], [])
        self.tracing = False  # TRON: lines run are shown as [n]
        self.subscript_base = 0  # OPTION BASE
        # the program's sequential files, all in one directory (``files``; default the current one)
        self.files = FileTable(Sandbox(files))
        # Ctrl-C stops a run where CONT can resume it exactly (the session wants this;
        # ``yaseer run`` stops at once): see _on_interrupt.
        self.resumable_breaks = False
        self._break_armed = None  # (compiled area, its real blocks) while a Ctrl-C waits to land
        self._reading_input = False
        # CLS: called to clear the screen (the session clears a terminal); None: nothing to clear
        self.on_clear_screen: Callable[[], object] | None = None

    # ------------------------------------------------------------ programs
    def load(self, text: str, area: int = 0, entered: bool = True) -> None:
        """Replace area ``area``'s program by the listing ``text`` (line -> text).

        ``entered``: the lines are entered now, so the messages GW-BASIC prints when
        it reads a line are shown (``Overflow`` of a literal: :func:`scanner.entry_messages`);
        False for lines entered before (the session hands its typed program over at RUN)."""
        program: dict[int, str] = {}
        for number, statement_text, _ in split_lines(text):
            if statement_text:
                program[number] = statement_text
                if entered:
                    self.show_messages(entry_messages(statement_text, self.dialect))
            else:
                program.pop(number, None)
        self.programs[area] = program
        self.python_areas.pop(area, None)
        self._invalidate(area)

    def set_line(self, number: int, text: str, area: int = 0) -> None:
        """Enter (or, with empty text, delete) one program line, as typed."""
        program = self.programs.setdefault(area, {})
        if text.strip():
            program[number] = text.strip()
        else:
            program.pop(number, None)
        self._invalidate(area)

    def show_messages(self, messages: list[str]) -> None:
        """Print each message on a row of its own, as GW-BASIC does where it reads a line
        (not in ``--format csv``, whose rows are values)."""
        for message in messages:
            if not self.csv:
                self.screen.write(message)
                self.screen.new_row()

    def set_area(self, n: int, area) -> None:
        """Bind program area ``n`` to a Python callable ``area(machine)`` or BASIC text."""
        if callable(area):
            self.python_areas[n] = area
            self.programs.pop(n, None)
            self._invalidate(n)
        else:
            self.load(area, n)

    def _invalidate(self, area: int) -> None:
        self.compiled.pop(area, None)
        self.namespaces.pop(area, None)
        self.runtimes.pop(area, None)
        if area == 0:
            self.cont_point = None

    def _compiled(self, area: int) -> CompiledArea:
        compiled = self.compiled.get(area)
        if compiled is None:
            extra = tuple(self._extra_entries) if area == 0 else ()
            compiled = self._compile(area, self.programs.get(area, {}), entry_lines=extra)
        return compiled

    def _compile(self, area, program: dict, direct: bool = False, entry_lines=(), dynamic_loops=()) -> CompiledArea:
        """Parse, compile and exec one area's program (line -> text); returns the CompiledArea.

        A program area (not a direct statement) is looked up first in the on-disk
        cache of compiled programs (:mod:`yaseer.basic.program_cache`) and stored
        there after a compile (not the TRON variant, see ``set_trace``, nor one with
        ``dynamic_loops``, see ``cont``)."""
        plain = not (direct or self.tracing or dynamic_loops)
        entry = program_cache.key(area, program, entry_lines, self.dialect) if plain else None
        cached = program_cache.load(entry) if entry else None
        if cached is not None:
            compiled, codes = cached
        else:
            from yaseer.basic.compiler import compile_area

            lines = [_parse_cached(number, text, self.dialect) for number, text in sorted(program.items())]
            compiled = compile_area(lines, area if isinstance(area, int) else 0, direct=direct,
                                    entry_lines=entry_lines, trace=self.tracing, dynamic_loops=dynamic_loops,
                                    dialect=self.dialect, def_types=self.def_types if direct else None)
            codes = [None] * len(compiled.pieces)
        runtime_state = _AreaRuntime(self, area, compiled)
        namespace = self._namespace(area, runtime_state)
        codes = [self._exec_piece(text, first_line, area, namespace, code)
                 for (first_line, text), code in zip(compiled.pieces, codes)]
        if entry and cached is None:
            program_cache.store(entry, compiled, codes)
        compiled.blocks = [namespace[f"_b{b}"] for b in range(compiled.block_count)]
        if direct or area == 0:  # DEF types hold for the direct statements that follow
            self.def_types = dict(compiled.def_types)
        for name in compiled.scalars:
            self.scalars.setdefault(name, initial_value(name))
        if not direct:
            self.compiled[area] = compiled
            self.runtimes[area] = runtime_state
            self.namespaces[area] = namespace
        return compiled

    def _exec_piece(self, text: str, first_line, area, namespace: dict, code=None):
        """Compile (unless ``code`` is given) and run one generated function
        definition; one too complex for Python becomes an error.  Returns its code
        object (None for such a function)."""
        try:
            if code is None:
                code = compile(text, f"<BASIC area {area}>", "exec")
            exec(code, namespace)
            return code
        except SyntaxError as exc:
            if "too many" not in str(exc) and "nested" not in str(exc):
                raise BasicError(f"Internal error (generated code: {exc})", INTERNAL_ERROR) from None
        except (RecursionError, MemoryError):
            pass
        exec(self._stub(text, first_line), namespace)
        return None

    @staticmethod
    def _stub(text: str, first_line) -> str:
        """A block Python cannot compile (nested too deeply): it raises Out of memory."""
        name = text.split("(", 1)[0].split()[-1]
        return (f"def {name}(*_):\n    _M.line = {first_line!r}\n"
                f"    raise _err('Out of memory', {OUT_OF_MEMORY})\n")

    def _namespace(self, area, rt: _AreaRuntime) -> dict:
        """The globals the generated code of ``area`` runs with: the machine's state and helpers."""
        ns = {
            "__builtins__": {"abs": abs, "len": len, "float": float, "map": map, "range": range, "type": type, "int": int,
                             "BaseException": BaseException},
            "_M": self, "_S": self.scalars, "_A": self.arrays, "_arr": self.array_nd, "_ix": runtime.subscript,
            "_ovf": self.arith.overflowed, "_fail": runtime.fail, "_err": BasicError, "_END": END, "_DirectJump": DirectJump,
            "_pr": self.print_items, "_pru": self.print_using, "_COMMA": COMMA, "_NUMCOMMA": NUMBER_THEN_COMMA, "_Tab": Tab, "_Spc": Spc,
            "_gosub": self.gosub, "_return": self.gosub_return, "_stk": self.stack,
            "_oom": self._out_of_memory, "_call": self.call_area,
            "_on": self.on_index, "_for": self.for_push, "_next": self.next_frame,
            "_pop": self.stack.pop, "_next_any": self.next_any, "_stop": self._stopper(area),
            "_dim": self.dim, "_clear": self.clear, "_read_n": rt.read_number,
            "_read_s": rt.read_string, "_restore": rt.restore, "_input": self.input_values,
            "_fn": self.user_function, "_resume": self.resume, "_resume_at": self.resume_at,
            "_error_off": self.error_trapping_off, "_error": self.raise_error,
            "_randomize": self.randomize, "_rnd": self.rnd, "_rndf": self._first_draw,
            "_sqrt": math.sqrt, "_floor": runtime.floor, "_fix": runtime.fix, "_sgn": runtime.sign,
            "_exp": math.exp, "_log": math.log, "_len": lambda s: float(len(s)),
            "_strs": formatting.str_dollar, "_val": gwfunctions.val, "_chr": runtime.chr_dollar,
            "_asc": runtime.asc, "_left": runtime.left, "_right": runtime.right, "_mid": runtime.mid,
            "_cat": runtime.concat, "_pow": runtime.power, "_idiv": runtime.int_divide,
            "_mod": runtime.modulo, "_and": runtime.logical_and, "_or": runtime.logical_or,
            "_not": runtime.logical_not, "_frange": runtime.float_range,
            "_fcount": runtime.pass_counter, "_fidle": runtime.idle_passes, "_fvalue": runtime.counted_value,
            "_fafter": runtime.counted_final, "_tr": self.trace_line, "_cint": lambda x: float(runtime.cint(x)),
            "_csng": float, "_cdbl": float,
        }
        ns.update(self._gw_functions())
        if self.dialect.typed_numbers:
            ns.update(numbers.RUNTIME)
            ns.update(arith_policy.helpers(self.arith, ns["_idiv"], ns["_mod"], ns["_pow"]))
            ns.update(val_numbers.helpers(self.arith, ns, self.dialect.largest_number))
        ns.update(self._trig_functions())
        if self.dialect.arithmetic == "decimal":
            from yaseer.basic import decimal_arith  # here: only --arith decimal loads the decimal module

            ns.update(decimal_arith.RUNTIME)
            ns.update(self._trig_functions())
        self.namespaces[area] = ns
        return ns

    def _gw_functions(self) -> dict:
        """The namespace entries of GW-BASIC's statements and functions (issue 12)."""
        g = gwfunctions
        return {
            "_instr": g.instr, "_string": g.string_dollar, "_space": g.space_dollar,
            "_hex": g.hex_dollar, "_oct": g.oct_dollar, "_mki": g.mki, "_mks": g.mks, "_mkd": g.mkd,
            "_cvi": g.cvi, "_cvs": g.cvs, "_cvd": g.cvd, "_timer": g.timer, "_date": g.date_dollar,
            "_time": g.time_dollar, "_xor": g.logical_xor, "_eqv": g.logical_eqv,
            "_imp": g.logical_imp, "_midset": g.mid_assign, "_fre": self.free_memory,
            "_pos": lambda _: float(self.screen.column + 1),
            "_lpos": lambda _: float(self.printer.column + 1),
            "_erase": self.erase, "_option_base": self.option_base, "_line_input": self.line_input,
            "_write": self.write_values, "_clear_args": _check_clear_arguments,
            # sequential files (files.py)
            "_open": self.files.open, "_close": self.files.close, "_kill": self.files.kill,
            "_rename": self.files.sandbox.rename, "_files": self.list_files,
            "_fout": lambda n: self.files.get(n).output(), "_prf": self.print_to,
            "_pruf": self.print_using_to, "_writef": self.write_to,
            "_fin_n": self.file_number, "_fin_s": lambda n: self.files.get(n).read_field(False),
            "_fline": lambda n: self.files.get(n).read_line(),
            "_eof": lambda n: -1.0 if self.files.get(n).at_end() else 0.0,
            "_lof": lambda n: float(self.files.get(n).length()),
            "_loc": lambda n: float(self.files.get(n).records()),
            "_input_chars": self.input_chars,
        }

    def _trig_functions(self) -> dict:
        if self.dialect.arithmetic == "decimal":
            from yaseer.basic import decimal_arith

            return decimal_arith.trig_functions(self.angle != "RAD")
        if self.angle == "RAD":
            return {"_sin": math.sin, "_cos": math.cos, "_tan": math.tan, "_atn": math.atan}
        return {"_sin": runtime.sin_degrees, "_cos": runtime.cos_degrees,
                "_tan": runtime.tan_degrees, "_atn": runtime.atn_degrees}

    def set_trace(self, on: bool) -> None:
        """TRON / TROFF: swap every compiled area's blocks for its traced (or plain) variant.

        The variants have the same blocks, so a running program goes on in the
        new variant from its next block (TRON and TROFF end their block).
        """
        if on == self.tracing:
            return
        self.tracing = on
        from yaseer.basic.compiler import compile_area

        for area, compiled in list(self.compiled.items()):
            extra = tuple(self._extra_entries) if area == 0 else ()
            lines = [_parse_cached(number, text, self.dialect)
                     for number, text in sorted(self.programs.get(area, {}).items())]
            variant = compile_area(lines, area, entry_lines=extra, trace=on, dynamic_loops=compiled.dynamic_loops,
                                   dialect=self.dialect)
            namespace = self.namespaces[area]
            for first_line, text in variant.pieces:
                self._exec_piece(text, first_line, area, namespace)
            armed = self._break_armed
            blocks = armed[1] if armed is not None and armed[0] is compiled else compiled.blocks
            blocks[:] = [namespace[f"_b{b}"] for b in range(variant.block_count)]

    def trace_line(self, number: int) -> None:
        """TRON's ``[n]`` as line ``n`` starts (on the screen, like PRINT without a newline)."""
        self.screen.write(f"[{number}]")

    def clear_screen(self) -> None:
        """CLS: clear the screen if the screen can be cleared; the next PRINT starts at column 1."""
        if self.on_clear_screen is not None:
            self.on_clear_screen()
        self.screen.column = 0

    def set_width(self, columns, printer: bool = False) -> None:
        """WIDTH n: the screen's width, 40 or 80 columns as GW-BASIC's text screen has
        (any other n is Illegal function call); PRINT wraps there from now on.
        WIDTH LPRINT n: the printer's, 0..255 (0 acts as 1, 255 never wraps, as
        PC-BASIC 2.0.8 has it); nothing changes while LPRINT goes to the screen."""
        n = runtime.cint(columns)
        if printer:
            if not 0 <= n <= 255:
                raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
            if self.printer is not self.screen:
                self.printer.width = None if n == 255 else max(n, 1)
            return
        if n not in SCREEN_WIDTHS:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.screen.width = n

    def set_device_width(self, device: str, columns) -> None:
        """WIDTH "dev", n: ``LPT1:`` is WIDTH LPRINT n (GW-BASIC's source, GIOLPT.ASM
        ``LPTSWD``, sets the width LPRINT wraps at), ``SCRN:`` WIDTH n; the other devices
        GW-BASIC has take 0..255 and change nothing yaseer shows (``KYBD:`` refuses it,
        Illegal function call); any other text is ``Bad file name``."""
        action = DEVICE_WIDTHS.get(device.upper())
        if action is None:
            raise BasicError("Bad file name", BAD_FILE_NAME)
        if action == "screen":
            self.set_width(columns)
        elif action == "printer":
            self.set_width(columns, printer=True)
        elif action == "refused" or not 0 <= runtime.cint(columns) <= 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)

    def set_angle(self, mode: str) -> None:
        """DEG or RAD: the unit SIN, COS, TAN take and ATN returns."""
        self.angle = mode.upper()[:3]
        functions = self._trig_functions()
        for ns in list(self.namespaces.values()):
            ns.update(functions)

    # ------------------------------------------------------------ variables (the Python-area API)
    def scalar(self, name: str):
        """The value of scalar ``name`` (0.0, or "" for a string, if unset)."""
        name = name.upper()
        return self.scalars.get(name, initial_value(name))

    def set_scalar(self, name: str, value) -> None:
        name = name.upper()
        self.scalars[name] = str(value) if name.endswith("$") else float(value)

    def array(self, name: str) -> list:
        """The 1-D array ``name`` as a mutable list indexed by subscript."""
        return self.array_nd(name.upper(), 1)

    def array_nd(self, name: str, ndim: int) -> list:
        """Array ``name``; created with its implicit dimension(s) if the program has none."""
        found = self.arrays.get(name)
        if found is not None:
            return found
        dims = (self.dialect.implicit_size(name, ndim),) * ndim
        self._reserve(name, dims)
        created = _new_array(dims, initial_value(name))
        self.arrays[name] = created
        self.array_dims[name] = dims
        return created

    def _reserve(self, name: str, dims: tuple) -> None:
        """Check the array limits for ``name`` with ``dims`` (replacing its old size)."""
        count = math.prod(d + 1 for d in dims)
        old = self.array_dims.get(name)
        total = self.array_elements + count - (math.prod(d + 1 for d in old) if old else 0)
        if count > MAX_ARRAY_ELEMENTS or total > MAX_TOTAL_ELEMENTS:
            raise BasicError("Out of memory", OUT_OF_MEMORY)
        self.array_elements = total

    def dim(self, name: str, sizes: tuple) -> None:
        """DIM name(sizes): replaces an implicit array; a second DIM is an error."""
        if name in self.explicit_arrays:
            raise BasicError("Duplicate definition", DUPLICATE_DEFINITION)
        dims = tuple(runtime.cint(s) for s in sizes)
        if any(d < 0 for d in dims):
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self._reserve(name, dims)
        self.arrays[name] = _new_array(dims, initial_value(name))
        self.array_dims[name] = dims
        self.explicit_arrays.add(name)

    def erase(self, name: str) -> None:
        """ERASE name: forget the array (a later DIM may size it again); not there: Illegal function call."""
        dims = self.array_dims.get(name)
        if name not in self.arrays or dims is None:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.array_elements -= math.prod(d + 1 for d in dims)
        del self.arrays[name], self.array_dims[name]
        self.explicit_arrays.discard(name)

    def option_base(self, base: int) -> None:
        """OPTION BASE 0 or 1: the lowest subscript; once an array exists: Duplicate Definition."""
        if self.arrays:
            raise BasicError("Duplicate Definition", DUPLICATE_DEFINITION)
        self.set_subscript_base(base)

    def set_subscript_base(self, base: int) -> None:
        self.subscript_base = base
        check = runtime.subscript if base == 0 else runtime.subscript_from_one
        for ns in list(self.namespaces.values()):
            ns["_ix"] = check

    def free_memory(self, _any) -> float:
        """FRE(x): bytes left in the array budget (8 bytes an element), whatever x is."""
        return float(8 * (MAX_TOTAL_ELEMENTS - self.array_elements))

    def clear(self) -> None:
        """CLEAR: every variable to 0 or "", arrays back to their implicit state, no FN."""
        for name in self.scalars:
            self.scalars[name] = initial_value(name)
        self.arrays.clear()
        self.array_dims.clear()
        self.array_elements = 0
        self.explicit_arrays.clear()
        self.fns.clear()
        for rt in self.runtimes.values():
            rt.data_index = 0

    # ------------------------------------------------------------ control flow
    @staticmethod
    def _out_of_memory() -> None:
        raise BasicError("Out of memory", OUT_OF_MEMORY)

    def gosub(self, return_block: int) -> None:
        """GOSUB: remember the block to come back to (the generated code inlines this)."""
        if len(self.stack) >= MAX_STACK:
            raise BasicError("Out of memory", OUT_OF_MEMORY)
        self.stack.append(return_block)

    def gosub_return(self) -> int:
        """RETURN: the block to go back to (-2 ends a BASIC area); FOR loops opened since the GOSUB close."""
        stack = self.stack
        while stack:
            top = stack[-1]
            if top is AREA_MARK:
                return -2
            stack.pop()
            if type(top) is int:
                return top
        raise BasicError("RETURN without GOSUB", RETURN_WITHOUT_GOSUB)

    def for_push(self, key: str, limit: float, step: float, body: int, bound=False) -> None:
        """FOR (through the stack): open a loop over ``key`` whose body starts at block ``body``.

        ``bound`` is what GW-BASIC's FOR finds scanning for its NEXT (see
        ``blocks.scan_for_next``): ``(NEXT id, its line, names this loop?)`` or None
        for no NEXT.  In a dialect with ``Dialect.for_binds_next`` the loop is bound
        to that NEXT, and no NEXT (``FOR without NEXT``) or one naming another
        variable (``NEXT without FOR`` in its line) is an error now.
        """
        next_id = self.bound_next(bound)
        stack = self.stack
        for k in range(len(stack) - 1, -1, -1):
            frame = stack[k]
            if type(frame) is not ForFrame:
                break
            if frame.key == key:  # re-entering a loop: drop it and the loops inside it
                del stack[k:]
                break
        if len(stack) >= MAX_STACK:
            raise BasicError("Out of memory", OUT_OF_MEMORY)
        stack.append(ForFrame(key, limit, step, body, next_id))

    def bound_next(self, bound):
        """The NEXT a FOR is bound to (None: not bound), raising GW-BASIC's errors for
        what its scan found (see :meth:`for_push`); also run by a FOR that loops zero times."""
        if not self.dialect.for_binds_next or bound is False:
            return None
        if bound is None:
            raise BasicError("FOR without NEXT", FOR_WITHOUT_NEXT)
        next_id, next_line, names_this = bound
        if not names_this:
            raise BasicError("NEXT without FOR", NEXT_WITHOUT_FOR).at(next_line)
        return next_id

    def next_frame(self, key: str, next_id=None) -> ForFrame:
        """NEXT ``key``: its loop's frame, closing the loops opened inside it; a loop
        bound to another NEXT (GW-BASIC) is ``NEXT without FOR``."""
        stack = self.stack
        while stack:
            top = stack[-1]
            if type(top) is not ForFrame:
                break
            if top.key == key:
                if top.next_id is not None and next_id is not None and top.next_id != next_id:
                    break
                return top
            stack.pop()
        raise BasicError("NEXT without FOR", NEXT_WITHOUT_FOR)

    def next_any(self) -> bool:
        """NEXT with no name whose FOR the compiler could not see: step the innermost loop."""
        if not self.stack or type(self.stack[-1]) is not ForFrame or self.stack[-1].key.endswith("()"):
            raise BasicError("NEXT without FOR", NEXT_WITHOUT_FOR)
        frame = self.stack[-1]
        value = numbers.stepped(frame.key, self.scalars[frame.key], frame.step)
        self.scalars[frame.key] = value
        if (value <= frame.limit) if frame.step >= 0 else (value >= frame.limit):
            self.frame_body = frame.body
            return True
        self.stack.pop()
        return False

    def on_index(self, selector: float, count: int) -> int:
        """ON x GOTO: the 1-based branch, or 0 to fall through; below 0 is an error."""
        k = runtime.cint(selector)
        if k < 0 or k > 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        return k if k <= count else 0

    def user_function(self, name: str, nargs: int):
        """FN ``name``: the compiled function DEF FN made, called with ``nargs`` arguments."""
        entry = self.fns.get(name)
        if entry is None:
            raise BasicError("Undefined user function", UNDEFINED_USER_FUNCTION)
        function, expected = entry
        if expected != nargs:
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return function

    def _stopper(self, area):
        def stop(block: int) -> None:
            raise ProgramStop(area, block, self.line)
        return stop

    def call_area(self, n: int, line=None) -> None:
        """GOSUB PROG n (at BASIC ``line``): run program area n and come back."""
        self.line = line
        python_area = self.python_areas.get(n)
        if python_area is not None:
            python_area(self)
        else:
            self._call_basic_area(n)
        for hook in self.area_hooks:
            self.line = line
            hook(self, n)

    def _call_basic_area(self, n: int) -> None:
        """Run BASIC program area ``n`` until its RETURN (its own line numbers, shared variables)."""
        if n not in self.programs:
            raise BasicError(f"Undefined program area {n}", UNDEFINED_PROGRAM_AREA)
        if self.area_depth >= MAX_AREA_DEPTH:
            raise BasicError("Out of memory", OUT_OF_MEMORY)
        compiled = self._compiled(n)
        mark = len(self.stack)
        self.stack.append(AREA_MARK)
        self.area_depth += 1
        try:
            self._run_area(n, compiled, 0)
        finally:
            self.area_depth -= 1
            del self.stack[mark:]

    # ------------------------------------------------------------ errors
    def resume(self, next_statement: bool) -> int:
        """RESUME / RESUME NEXT: the block of the failed statement, or of the one after it."""
        if not self.in_handler:
            raise _resume_without_error()
        area, block = self.error_point
        self.in_handler = False
        self.err = 0.0
        if next_statement:
            return self._compiled(area).block_next.get(block, block + 1)
        return block

    def resume_at(self, block: int) -> int:
        """RESUME n: leave the error handler and go to ``block``."""
        if not self.in_handler:
            raise _resume_without_error()
        self.in_handler = False
        self.err = 0.0
        return block

    def error_trapping_off(self) -> None:
        """ON ERROR GOTO 0: no more trapping; inside a handler the pending error stops the run."""
        self.on_error = None
        if self.in_handler:
            raise self.pending_error

    @staticmethod
    def raise_error(code: float) -> None:
        """ERROR n: raise error n (1..255; anything else is Illegal function call)."""
        n = runtime.cint(code)
        if not 1 <= n <= 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        raise BasicError.of_code(n)

    def _trap(self, err: BasicError, area: int, block: int) -> int | None:
        """The handler block for ``err`` if ON ERROR GOTO of this area catches it."""
        if self.on_error is None or self.in_handler or err.code == BREAK or not err.trappable:
            return None
        handler_area, handler_block = self.on_error
        if handler_area != area:
            return None
        self.err = float(err.code)
        self.erl = float(err.line or 0)
        for stream in self.streams:
            stream.row = []
        self.in_handler = True
        self.pending_error = err
        self.error_point = (area, block)
        return handler_block

    # ------------------------------------------------------------ the run loop
    def _run_area(self, area: int, compiled: CompiledArea, block: int) -> None:
        """Run ``area`` from ``block`` until its RETURN (areas) or END (raises ProgramEnd)."""
        blocks = compiled.blocks
        b = block
        while True:
            try:
                while b >= 0:
                    b = blocks[b]()
                return
            except (ProgramEnd, ProgramStop, DirectJump, BrokenPipeError, OutputError):
                raise
            except BaseException as exc:  # noqa: BLE001 - every error becomes a BASIC error
                err = to_basic_error(exc)
                err.at(self.line, area)
                target = self._trap(err, area, b)
                if target is None:
                    raise err from None
                b = target

    def reset(self) -> None:
        """The state RUN starts from: no variables, empty stack, the default angle unit."""
        self.clear()
        self.stack.clear()
        self.on_error = None
        self.in_handler = False
        self.err = self.erl = 0.0
        self.cont_point = None
        self.area_depth = 0
        self.set_angle(self.default_angle)
        self.set_subscript_base(0)
        self.files.close()
        self.random.reset()

    def run(self, line: int | None = None) -> str:
        """RUN (from ``line``): returns "end" or "stop"; raises BasicError on an error."""
        if self.compiled.get(0) is not None and self.compiled[0].dynamic_loops:
            self._invalidate(0)  # the variant CONT made after a Ctrl-C: back to native loops
        compiled = self._compiled(0)
        for area in self.programs:
            self._compiled(area)
        self.reset()
        block = 0
        if line is not None:
            block = self._line_block(line)
        return self._execute(0, block)

    def _line_block(self, line: int) -> int:
        """The block that starts at ``line`` of area 0 (recompiling so that one does)."""
        if line not in self.programs.get(0, {}):
            raise BasicError(f"Undefined line number {line}", 8)
        block = self._compiled(0).line_blocks.get(line)
        if block is None:
            self._extra_entries.add(line)
            self._compile(0, self.programs[0], entry_lines=tuple(self._extra_entries))
            block = self._compiled(0).line_blocks[line]
        return block

    def _on_interrupt(self, signum, frame) -> None:
        """SIGINT while running: arm a resumable break, or note the line and variables and break.

        With ``resumable_breaks`` the first Ctrl-C lets the run go on to the next
        point where CONT can resume it exactly (:meth:`_arm_break`); a second
        Ctrl-C before it lands, or one while INPUT waits for a line, breaks at once.

        (A ``continue`` back-edge in Python 3.11 lets KeyboardInterrupt bypass the
        block's ``finally``, so the line and the locals are read from the frame here.)
        """
        if self.resumable_breaks and self._break_armed is None and not self._reading_input:
            if self._arm_break(frame):
                return
        while frame is not None:
            if frame.f_globals.get("_M") is self and "_ln" in frame.f_locals:
                self.line = frame.f_locals["_ln"]
                for local, value in frame.f_locals.items():
                    for name in _scalar_names(local):
                        if name in self.scalars:
                            self.scalars[name] = value
                break
            frame = frame.f_back
        raise KeyboardInterrupt

    def _arm_break(self, frame) -> bool:
        """Make the run stop at the next point CONT can resume from exactly; False if none.

        Those points are: the start of any block of area 0 (every block function is
        swapped for a stub that raises :class:`BreakPoint`, until the break lands),
        and, inside the block running now, its compiled break points (the top of a
        native loop's pass, the back-jump of a block looping to itself), reached
        through a line trace on that frame alone.  Their lines hold nothing that
        can be interrupted half-way, so no statement is ever run twice or skipped.
        """
        compiled = self.compiled.get(0)
        if compiled is None or not compiled.blocks:
            return False
        self._break_armed = (compiled, list(compiled.blocks))
        prelude = len(compiled.pieces) - compiled.block_count
        compiled.blocks[:] = [self._break_stub(b, compiled.pieces[prelude + b][0])
                              for b in range(compiled.block_count)]
        namespace = self.namespaces.get(0)
        while frame is not None:
            if frame.f_globals is namespace and frame.f_code.co_name.startswith("_b"):
                block = int(frame.f_code.co_name[2:])
                points = compiled.break_points.get(block)
                if points and sys.gettrace() is None:
                    frame.f_trace = self._break_tracer(block, points)
                    frame.f_trace_lines = True
                    sys.settrace(_no_call_trace)  # line events reach f_trace only while tracing is on
                break
            frame = frame.f_back
        return True

    def _break_stub(self, block: int, line):
        def stub():
            raise BreakPoint(0, block, self.line if line is None else line, (), self.area_depth)
        return stub

    def _break_tracer(self, block: int, points: dict):
        def trace(frame, event, arg):
            if event == "line":
                point = points.get(frame.f_lineno)
                if point is not None:
                    line, loops = point
                    raise BreakPoint(0, block, line, _loop_states(frame.f_locals, loops), self.area_depth)
            return trace
        return trace

    def _disarm_break(self) -> None:
        """Put the real blocks back and stop the line trace (the break landed, or the run ended)."""
        if self._break_armed is not None:
            compiled, blocks = self._break_armed
            compiled.blocks[:] = blocks
            self._break_armed = None
            if sys.gettrace() is _no_call_trace:
                sys.settrace(None)

    def _execute(self, area: int, block: int) -> str:
        self.cont_point = None
        try:
            with _interrupt_handler(self._on_interrupt):
                return self._execute_loop(area, block)
        finally:
            self._disarm_break()

    def _execute_loop(self, area: int, block: int) -> str:
        stopped = False
        try:
            self._run_area(area, self._compiled(area), block)
        except ProgramEnd:
            return "end"
        except BreakPoint as stop:
            self._disarm_break()
            if stop.area == 0 and stop.depth == 0:
                self.cont_point = (0, stop.block, stop.loops)
            self.area_depth = 0
            self.line = stop.line
            raise BasicError("Break", BREAK).at(stop.line) from None
        except ProgramStop as stop:
            if stop.area == 0 and self.area_depth == 0:
                self.cont_point = (stop.area, stop.block)
            self.area_depth = 0
            stopped = True
            return "stop"
        except KeyboardInterrupt:
            raise BasicError("Break", BREAK).at(self.line) from None
        finally:
            if not stopped:  # END, the last line or an error closes the files (STOP keeps them)
                self.files.close()
            if self.csv:  # a last line left open (PRINT A;) is still a row
                self.end_line()
            self.flush()
        return "end"

    def cont(self) -> str:
        """CONT after STOP, or after a Ctrl-C that landed at a resumable point."""
        if self.cont_point is None:
            raise BasicError("Can't continue", CANT_CONTINUE)
        area, block, *loops = self.cont_point
        if loops and loops[0]:
            block = self._resume_loops(loops[0])
        return self._execute(area, block)

    def _resume_loops(self, loops: tuple) -> int:
        """Reopen native loops broken at the top of a pass; the block to go on at.

        Area 0 is compiled again with those loops run through the FOR stack (every
        block of the old compile keeps an equivalent: the stack's return blocks are
        renumbered), their frames are pushed with the values they had, and the run
        goes on at the innermost loop's body, exactly where the pass would have begun.
        """
        old, old_runtime = self._compiled(0), self.runtimes.get(0)
        forced = tuple(sorted(set(old.dynamic_loops) | {loop[0] for loop in loops}))
        new = self._compile(0, self.programs.get(0, {}), entry_lines=tuple(self._extra_entries),
                            dynamic_loops=forced)
        if old_runtime is not None:
            self.runtimes[0].data_index = old_runtime.data_index
        self._renumber_blocks(_block_mapping(old, new))
        body = 0
        for index, key, value, limit, step in loops:
            body = new.index_blocks[index + 1]
            if value is not None:
                self.scalars[key] = value
            self.stack.append(ForFrame(key, limit, step, body))
        return body

    def _renumber_blocks(self, mapping: dict) -> None:
        """Area 0's block numbers held by the machine (GOSUB returns, FOR bodies, the error handler)."""
        for k, item in enumerate(self.stack):
            if type(item) is int:
                self.stack[k] = mapping.get(item, item)
            elif type(item) is ForFrame:
                item.body = mapping.get(item.body, item.body)
        for name in ("on_error", "error_point"):
            point = getattr(self, name)
            if point is not None and point[0] == 0:
                setattr(self, name, (0, mapping.get(point[1], point[1])))

    def execute_direct(self, text: str) -> str:
        """Run statements typed without a line number against the same variables."""
        self.show_messages(entry_messages(text, self.dialect))
        compiled = self._compile("direct", {0: text}, direct=True)
        self.namespaces.pop("direct", None)
        try:
            self.line = None
            try:
                self._run_area(0, compiled, 0)
            except BasicError as err:
                if err.line == 0:
                    err.line = None
                raise
            return "end"
        except ProgramEnd:
            return "end"
        except ProgramStop:
            return "stop"
        except DirectJump as jump:
            return self._execute(0, self._line_block(jump.line))
        finally:
            if self.csv:  # a last line left open (PRINT A;) is still a row
                self.end_line()
            self.flush()

    # ------------------------------------------------------------ I/O
    def print_items(self, device: int, items: tuple, newline: bool, end: bool = True) -> None:
        """PRINT / LPRINT: values, comma zones, TAB and SPC; ``newline`` ends the line.

        A statement may print in several calls; ``end`` marks its last.  In csv
        output a row is a printed line: the values of every PRINT up to the one
        that ends the line (so rows of one kind have one length).
        """
        stream = self.streams[device]
        if self.line_hooks:
            self._note_values(device, [_printed_value(v) for v in items if not isinstance(v, (Tab, Spc))
                                       and v is not COMMA and v is not NUMBER_THEN_COMMA], newline)
        if self.csv:
            for v in items:
                if type(v) is not float and type(v) is not str:
                    v = _as_number(v)
                if type(v) is float:
                    if v - v:
                        runtime.overflow()
                    stream.row.append(repr(v))
                elif type(v) is str:
                    stream.row.append(v)
            if end and newline:
                self._csv_row(stream)
            return
        self._lay_out(stream, items, newline)

    def _lay_out(self, stream: OutputStream, items: tuple, newline: bool) -> None:
        """PRINT's items as text on ``stream`` (the screen, the printer or a file)."""
        comma_follows = False
        for item in items:
            kind = type(item)
            if kind is not float and kind is not str and isinstance(item, (int, float)):
                # casio: e.g. a numpy float a Python area stored; gw: an integer or a double
                item, kind = self._printed_number(item), float
            if kind is float:
                if item - item:
                    item = self.arith.overflowed(item, "#" if isinstance(item, numbers.Double) else "!")
                text = self._number_text(item)
                if comma_follows:
                    text = self._blank_before_comma(stream, text)
                    comma_follows = False
                stream.item(text)
            elif kind is str:
                stream.item(item)
            elif item is COMMA:
                stream.comma(self.dialect.zone)
            elif item is NUMBER_THEN_COMMA:
                comma_follows = self.dialect.comma_trims_number
            elif kind is Tab:
                column = runtime.cint(item.column)
                if column > 255 and stream.width is None:
                    raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
                stream.tab(column)
            elif kind is Spc:
                count = runtime.cint(item.count)
                if (count < 0 or count > 255) and stream.width is None:
                    raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
                stream.spc(count)
        if newline:
            stream.write("\n")

    def _blank_before_comma(self, stream: OutputStream, text: str) -> str:
        """A number a comma follows loses its trailing blank when it would end just
        before a zone (so the comma moves one column, not a whole zone): GW-BASIC's
        PRINT code, GIO86.ASM ``MODCOM``; PC-BASIC 2.0.8 keeps the blank."""
        zone, width = self.dialect.zone, stream.width
        end = stream.column + len(text) - 1  # the column after the number without its blank
        if width is not None and width >= zone and end >= zone * (width // zone - 1):
            return text
        return text[:-1] if (end + 1) % zone == 0 else text

    def print_using(self, device: int, fmt: str, values: tuple, newline: bool) -> None:
        """PRINT USING fmt; values (the format rules live in ``formatting.using``)."""
        stream = self.streams[device]
        values = [v if type(v) is float or type(v) is str else _as_number(v) for v in values]
        for v in values:
            if type(v) is float and v - v:
                runtime.overflow()
        if self.line_hooks:
            self._note_values(device, values, newline)
        if self.csv:
            stream.row.extend(repr(v) if type(v) is float else v for v in values)
            if newline:
                self._csv_row(stream)
            return
        stream.write(formatting.using(fmt, values))
        if newline:
            stream.write("\n")

    def _note_values(self, device: int, values: list, newline) -> None:
        """Collect a printed line's values; at its end hand them to the line hooks."""
        line = self._line_values[device]
        line.extend(values)
        if newline:
            printed = line.copy()
            line.clear()
            for hook in self.line_hooks:
                hook(device, printed)

    def _csv_row(self, stream: OutputStream) -> None:
        """Write the csv row of the line ``stream`` was printing (its values so far)."""
        import csv  # here: only --format csv and INPUT need it (start-up)

        writer = csv.writer(stream.stream, lineterminator="\n")
        writer.writerow(stream.row)
        stream.row = []
        stream.column = 0

    def input_values(self, prompt, question_mark: bool, kinds: str, again: tuple | None = None) -> list:
        """INPUT: prompt, read one line, split at commas; wrong values ask again.

        ``again``: (the block of area 0 this INPUT starts, its line); see :meth:`_read_line`.
        """
        while True:
            line = self._read_line((prompt or "") + ("? " if question_mark or prompt is None else ""), again)
            values = _parse_input(line, kinds, self.dialect.largest_number)
            if values is not None:
                return values
            self.screen.write("?Redo from start\n")

    def line_input(self, prompt, again: tuple | None = None) -> str:
        """LINE INPUT ["prompt";] a$: the whole line, commas and quotes included (its
        trailing blanks dropped, as GW-BASIC's screen editor drops them); ``again``
        as for INPUT (see :meth:`_read_line`)."""
        return self._read_line(prompt or "", again).rstrip(" ")

    def _read_line(self, prompt: str, again: tuple | None = None) -> str:
        """Show ``prompt``, read one line of input (without its line end); the end of
        the input is ``Input past end``.

        ``again``: (a block of area 0 that starts with this statement, its line); with
        ``resumable_breaks`` a Ctrl-C while the line is awaited (or one that came just
        before) is a break that CONT resumes by running that block: asking again, as
        GW-BASIC does.  Otherwise a Ctrl-C here breaks at once.
        """
        stream = self.input_stream if self.input_stream is not None else sys.stdin
        self._reading_input = True  # a Ctrl-C now breaks at once
        try:
            if self._break_armed is not None and again is not None:
                raise KeyboardInterrupt  # a Ctrl-C came just before: the break lands here
            self.screen.write(prompt)
            self.screen.flush()
            line = stream.readline()
        except KeyboardInterrupt:
            if again is None or not self.resumable_breaks:
                raise
            raise BreakPoint(0, again[0], again[1], (), self.area_depth) from None
        finally:
            self._reading_input = False
        if not line:
            raise BasicError("Input past end", INPUT_PAST_END)
        if self.input_stream is not None:
            self.screen.write(line if line.endswith("\n") else line + "\n")
        else:
            self.screen.column = 0
        return line.rstrip("\r\n")

    # ------------------------------------------------------------ files (files.py)
    def print_to(self, stream, items: tuple, newline: bool, end: bool = True) -> None:
        """PRINT #n: the items laid out on the file's stream as on the screen (no csv, no hooks)."""
        self._lay_out(stream, items, newline)

    def print_using_to(self, stream, fmt: str, values: tuple, newline: bool) -> None:
        """PRINT #n, USING."""
        stream.write(formatting.using(fmt, [v if type(v) is float or type(v) is str else _as_number(v)
                                            for v in values]))
        if newline:
            stream.write("\n")

    def write_to(self, stream, pieces: tuple) -> None:
        """WRITE #n."""
        stream.write(",".join(pieces) + "\n")

    def file_number(self, n) -> float:
        """INPUT #n into a numeric variable: one field, read as GW-BASIC reads numbers."""
        return gwfunctions.val(self.files.get(n).read_field(True), self.dialect.largest_number)

    def input_chars(self, count, n=None) -> str:
        """INPUT$(count[, #n]): ``count`` characters of the file (or of the input)."""
        k = runtime.cint(count)
        if not 1 <= k <= 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if n is not None:
            return self.files.get(n).read_chars(k)
        stream = self.input_stream if self.input_stream is not None else sys.stdin
        text = stream.read(k)
        if len(text) < k:
            raise BasicError("Input past end", INPUT_PAST_END)
        return text

    def list_files(self, pattern) -> None:
        """FILES [pattern]: GW-BASIC's listing: the directory (``C:\\``, the sandbox as
        a drive's root), the matching entries in as many columns of 18 as the width
        has 20s, the disk's bytes free, an empty line; nothing matching is ``File not
        found`` after the directory line (as PC-BASIC 2.0.8 prints it)."""
        sandbox = self.files.sandbox
        entries = sandbox.directory(pattern)
        self.print_items(0, ("C:\\",), True)
        if not entries:
            raise BasicError("File not found", FILE_NOT_FOUND)
        columns = max(1, (self.screen.width or 80) // 20)
        for k in range(0, len(entries), columns):
            self.print_items(0, (" ".join(entries[k:k + columns]),), True)
        self.print_items(0, (f" {sandbox.free_bytes()} Bytes free",), True)
        self.print_items(0, (), True)

    def write_values(self, device: int, pieces: tuple) -> None:
        """WRITE: the items (already as text: strings quoted, numbers without blanks)
        separated by commas, then the line end."""
        self.print_items(device, (",".join(pieces),), True)

    def rnd(self, x: float = 1.0) -> float:
        """RND(x): x > 0 the next number, 0 the last again, x < 0 reseeds with x first."""
        return self.random.rnd(x)

    def _first_draw(self) -> float:
        """RND's next number, the first time an area draws one: from then on each area's
        ``_rndf`` (RND and RND(x) with a constant x > 0) is the generator's own drawer."""
        draw = self.random.drawer()
        for namespace in self.namespaces.values():
            namespace["_rndf"] = draw
        return draw()

    def randomize(self, seed, kind: str = "!") -> None:
        """RANDOMIZE seed; ``kind`` is the seed's type ("%", "!", "#", see yaseer.basic.randomness).

        Without a seed a generator with a ``seed_prompt`` (GW-BASIC's) asks for one
        on the screen and reads it as INPUT does, rounded to an integer.
        """
        if seed is None and self.random.seed_prompt is not None:
            seed, kind = runtime.cint(self.input_values(self.random.seed_prompt, False, "n")[0]), "%"
            if not -32768 <= seed <= 32767:
                runtime.overflow()
        self.random.randomize(seed, kind)

    def end_line(self) -> None:
        """Finish a partly printed line (before an error message, as MS-BASIC does; csv: its row)."""
        if self.csv:
            for stream in dict.fromkeys(self.streams):
                if stream.row:
                    self._csv_row(stream)
        elif self.screen.column:
            self.screen.new_row()

    def flush(self) -> None:
        for stream in self.streams:
            try:
                stream.flush()
            except (OSError, ValueError):
                pass


def _no_call_trace(frame, event, arg):
    """The thread's trace function while a break is armed: no other frame is traced."""
    return None


def _loop_states(local: dict, loops: tuple) -> tuple:
    """``(FOR index, key, value, limit, step)`` of each native loop open in a block's frame.

    ``loops`` are the compiler's descriptions (see ``CompiledArea.break_points``);
    ``local`` the frame's locals at the top of a pass.
    """
    states = []
    for index, key, n, mode, name in loops:
        limit, step = local[f"_l{n}"], local[f"_s{n}"]
        if mode == "count":
            value = runtime.counted_value(local[f"_it{n}"], local[f"_v{n}"], step, local[f"_i{n}"])
        else:
            value = local[name] if name else None
        states.append((index, key, value, limit, step))
    return tuple(states)


def _block_mapping(old: CompiledArea, new: CompiledArea) -> dict:
    """Old block number -> new, for two compiles of one program that differ only in loops
    made dynamic (which adds block entries and no other blocks)."""
    old_entries, new_entries = len(old.index_blocks), len(new.index_blocks)
    if old.block_count - old_entries != new.block_count - new_entries:
        raise BasicError("Can't continue", CANT_CONTINUE)
    mapping = {block: new.index_blocks[index] for index, block in old.index_blocks.items()}
    for block in range(old_entries, old.block_count):
        mapping[block] = block - old_entries + new_entries
    return mapping


@contextlib.contextmanager
def _interrupt_handler(handler):
    """Use ``handler`` for SIGINT while running, if Python's default one is in place."""
    try:
        installed = signal.getsignal(signal.SIGINT) is signal.default_int_handler
        if installed:
            signal.signal(signal.SIGINT, handler)
    except ValueError:  # not the main thread
        installed = False
    try:
        yield
    finally:
        if installed:
            signal.signal(signal.SIGINT, signal.default_int_handler)


def _printed_value(value):
    """A printed item as a line hook sees it: str stays, any number becomes a float."""
    return value if type(value) is str else float(value)


def _resume_without_error() -> BasicError:
    """RESUME outside an error handler: it stops the run even under ON ERROR GOTO (GW-BASIC)."""
    err = BasicError("RESUME without error", RESUME_WITHOUT_ERROR)
    err.trappable = False
    return err


_LOCAL_SUFFIXES = {"n_": ("", "!"), "s_": ("$",), "i_": ("%",), "d_": ("#",)}


def _scalar_names(local: str) -> tuple:
    """The scalar names a compiled block's Python local may hold (number_models.local_name):
    ``n_A`` is A (casio) or A! (gw), ``i_A`` A%, ``d_A`` A#, ``s_A`` A$."""
    suffixes = _LOCAL_SUFFIXES.get(local[:2])
    if suffixes is None or not local[2:3].isalpha():
        return ()
    return tuple(local[2:] + suffix for suffix in suffixes)


def _same(value):
    return value


def _check_clear_arguments(*sizes) -> None:
    """CLEAR n, m, k: the memory sizes are not used; a negative first one is Illegal function call."""
    if sizes and sizes[0] is not None and sizes[0] < 0:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)


def _as_number(value):
    """A number some Python area stored (int, numpy float) as a Python float; else as is."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value)
    return value


def _parse_input(text: str, kinds: str, largest: float | None = None):
    """The values of one INPUT line for targets of ``kinds`` ("n"/"s"), or None to redo
    (``largest``: see gwfunctions.read_number)."""
    import csv

    reader = csv.reader([text], skipinitialspace=True)
    fields = next(reader, None) or [""]  # an empty answer is one empty value: 0 or ""
    if len(fields) != len(kinds):
        return None
    values = []
    for field_text, kind in zip(fields, kinds):
        if kind == "s":
            values.append(field_text)
            continue
        try:
            value = gwfunctions.number_field(field_text, largest)
        except BasicError:  # beyond the double range
            return None
        if value is None:
            return None
        values.append(value)
    return values
