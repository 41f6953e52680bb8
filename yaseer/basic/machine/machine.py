"""The BASIC machine: the coordinator of a run.

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

This module keeps the programs (load, compile, the namespace the generated code
runs with), the program areas, the run loop and RND; the machine's other jobs are
mixins of their own modules in this wing, on the same state:

* :mod:`.variables` - scalars and arrays (the Python-area API), DIM, ERASE, CLEAR;
* :mod:`.stack` - the GOSUB/FOR stack, ON x GOTO, FN, STOP;
* :mod:`.signals` - the exceptions that end or redirect a run, the BASIC error
  of a Python exception, ON ERROR GOTO / RESUME / ERROR;
* :mod:`.breaks` - Ctrl-C (a break CONT can resume) and CONT;
* :mod:`.io_statements` - PRINT, PRINT USING, WRITE, INPUT, the screen's settings, file I/O.

The mixins' contract.  Each mixin is a class without ``__init__`` whose methods run
on a :class:`Machine`: they may read and write the state :meth:`Machine.__init__`
sets (``scalars``, ``arrays``, ``stack``, ``screen``, ``printer``, ``files``,
``dialect``, ``arith``, ``compiled``, ``namespaces``, ``line``, ...) and call each
other's public methods, and they add no state of their own outside the names
``__init__`` creates.  A mixin imports only modules below the machine (errors, the
numbers, the runtime functions, the screen): never this module nor another mixin's
class (only the exceptions of :mod:`.signals` and :class:`.stack.ForFrame`).
Mixins, not separate objects the machine holds, because the generated code and the
hot paths reach them as ``_M.method(...)``: a part held as ``_M.part.method(...)``
and reading the state back through ``self.machine`` cost 1.2-1.6 times as much a call
in a micro-benchmark of the FOR-stack push (CPU time, CPython 3.11).
"""

from __future__ import annotations

import math
import sys
from functools import lru_cache

from yaseer.basic.arithmetic import arith_policy, binade_cache, casio_math, formatting, values
from yaseer.basic.compile.number_models import initial_value
from yaseer.basic.compile import program_cache
from yaseer.basic.compile.compiled import MAX_STACK, CompiledArea  # noqa: F401  MAX_STACK: GOSUB returns + open FOR loops together
from yaseer.basic.dialects import dialect as dialects
from yaseer.basic.machine import argument_reading, gwfunctions, memory_model, runtime, string_space, val_numbers
from yaseer.basic.machine.clock import Clock
from yaseer.basic.machine.device_files import reserved_names
from yaseer.basic.machine.files import FileTable, Sandbox, file_byte
from yaseer.basic.errors import (  # noqa: F401  (INPUT_PAST_END re-exported)
    BasicError, OutputError, BREAK, INPUT_PAST_END, NO_RESUME, OUT_OF_DATA, OUT_OF_MEMORY, STRING_TOO_LONG, SYNTAX_ERROR,
    TYPE_MISMATCH, UNDEFINED_LINE,
    UNDEFINED_PROGRAM_AREA, error_for, undefined_line_message,
)
from yaseer.basic.machine.console import Console
from yaseer.basic.machine.chaining import ChainTo, Chaining, RunAgain
from yaseer.basic.machine.breaks import Breaks, _interrupt_handler
from yaseer.basic.machine import casio_words
from yaseer.basic.machine.casio_words import CasioWords
from yaseer.basic.machine.address_space import AddressSpace
from yaseer.basic.machine.devices import Devices
from yaseer.basic.machine.signals import (  # noqa: F401  (the run-time exceptions are re-exported)
    END, INTERNAL_ERROR, BreakPoint, DirectJump, ErrorTrapping, ProgramEnd, ProgramStop, ResumeDirect,
    to_basic_error,
)
from yaseer.basic.machine.io_statements import (  # noqa: F401  (the PRINT items are re-exported)
    COMMA, NUMBER_THEN_COMMA, InputOutput, Spc, Tab, _as_number, _same,
)
from yaseer.basic.machine.stack import AREA_MARK, ControlStack, ForFrame  # noqa: F401  (re-exported)
from yaseer.basic.machine.variables import (  # noqa: F401  (the array limits are re-exported)
    MAX_ARRAY_ELEMENTS, MAX_TOTAL_ELEMENTS, MadeNames, Variables, _check_clear_arguments, clear_argument, clear_sizes,
)
from yaseer.basic.source.scanner import UndefinedLineInFile, entry_messages, program_lines
from yaseer.basic.machine.screen import OutputStream

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from typing import Callable, TextIO


# Resource limits (each exceeded limit is "Out of memory in N"; the arrays': machine_variables).
MAX_AREA_DEPTH = 100  # GOSUB PROG nesting


@lru_cache(maxsize=4096)
def _parse_cached(number: int, text: str, dialect):
    from yaseer.basic.source.parser import parse_line  # here: a program read from the cache needs no parser

    return parse_line(number, text, dialect)


class _AreaRuntime:
    """Per-area state the compiled code reaches: DATA pointer."""

    def __init__(self, machine: "Machine", number: int, compiled: CompiledArea):
        self.machine = machine
        self.number = number
        self.compiled = compiled
        self.data_index = 0
        self.data_start = 0  # where the READ running started (read_commits: GW's DATPTR)
        self.failed: int | None = None  # read_commits: the DATA line of an item that was no number
        self.read_texts: dict[int, str] = {}  # gw: the string READ gave of each item (string_space.text)

    def read_item(self) -> tuple[str, int]:
        if self.failed is not None:  # the READ stops at the variable given a bad item's number
            self.read_end()
        data = self.compiled.data
        if self.data_index >= len(data):
            raise BasicError("Out of DATA", OUT_OF_DATA)
        item = data[self.data_index]
        self.data_index += 1
        return item

    def read_number(self) -> float:
        """The next DATA item as a number; an item that is not one is a Syntax error in
        the DATA line, and the pointer stays on it (a READ of a string, in an error
        handler, reads it again, as GW-BASIC does)."""
        text, line = self.read_item()
        dialect = self.machine.dialect
        try:
            value = gwfunctions.number_field(text, dialect.number_reading)
        except BasicError as err:
            self.data_index -= 1
            raise err.at(line, self.number) from None
        if value is None:
            if dialect.read_commits:  # the number at its start is assigned, then the error
                if text.strip() in ("+", "-"):
                    return 0.0  # (FIN reads a sign and no digits as 0: nothing is left)
                self.failed = line
                return gwfunctions.read_number(text, dialect.number_reading)[0]
            self.data_index -= 1
            words = dialect.words
            if words is not None and words.read_mismatch:
                raise BasicError("Type mismatch", TYPE_MISMATCH)  # the READ's error (casio: READ.md item 2)
            raise BasicError("Syntax error", SYNTAX_ERROR).at(line, self.number)
        return value

    def read_end(self) -> None:
        """The end of a READ (read_commits): the DATA pointer is kept, or, after an item
        that was no number, Syntax error in its DATA line."""
        if self.failed is not None:
            line, self.failed = self.failed, None
            raise BasicError("Syntax error", SYNTAX_ERROR).at(line, self.number)
        self.data_start = self.data_index

    def abandon(self) -> None:
        """An error stopped the statement running (read_commits): a READ among it leaves
        the DATA pointer where it started."""
        if self.machine.dialect.read_commits:
            self.data_index = self.data_start
            self.failed = None

    def read_string(self) -> str:
        """The next DATA item as a string: a quoted item is the text between its quotes
        (an unclosed quote runs to the end); anything after the closing quote is a
        Syntax error in the DATA line (GW-BASIC); one over the dialect's string length is
        String too long, also in the DATA line (as PC-BASIC 2.0.8 reports it)."""
        text, line = self.read_item()
        if text.startswith('"'):
            end = text.find('"', 1)
            if end >= 0 and text[end + 1:].strip():
                raise BasicError("Syntax error", SYNTAX_ERROR).at(line, self.number)
            text = text[1:] if end < 0 else text[1:end]
        if len(text) > self.machine.dialect.string_length:
            raise BasicError("String too long", STRING_TOO_LONG).at(line, self.number)
        if len(text) > 1 and self.machine.dialect.free_memory is not None:
            # the string stays in the DATA text (LETCN6 copies none): one object an item
            text = self.read_texts.setdefault(self.data_index, text)
            self.machine.string_space.text[id(text)] = text
        return text

    def restore_at(self, value: float) -> None:
        """RESTORE (expression): the line the value names (truncated), which must exist
        (RESTORE.md: UL error)."""
        line = int(value)
        if line not in self.machine.programs.get(self.number, {}):
            raise BasicError(f"Undefined line number {line}", UNDEFINED_LINE)
        self.restore(line)

    def restore(self, line) -> None:
        if line is None:
            self.data_index = self.data_start = 0
            return
        later = [i for number, i in self.compiled.data_lines.items() if number >= line]
        self.data_index = self.data_start = min(later) if later else len(self.compiled.data)


_DEF_SUFFIX = {"INT": "%", "SNG": "!", "DBL": "#", "STR": "$"}


def _table_key(table: dict) -> tuple:
    """A DEF type table (letter -> type character) as a key of its compiled variant."""
    return tuple(sorted((letter, kind) for letter, kind in table.items() if kind != "!"))


FIRST_FILE_AREA = 1000  # the program areas of program files (GOSUB "file:label") are numbered from here

# Compiling one program area is held to about 550 MB (docs/interpreter.md, Resource limits), by
# two bounds, each an Out of memory before the costly step.  Measured (ru_maxrss growth):
# parsing costs up to about 530 bytes of memory per listing character (lines of 40 operators;
# the Al-Yaseer listings about 40), so MAX_LISTING_CHARACTERS (4 times the 64 KB a GW-BASIC or
# FX-880P program can fill) keeps it under about 140 MB; Python's compiler takes about 100
# bytes per character of the Python code yaseer writes, which can be 140 times the BASIC text
# (gw single-precision arithmetic, rounded inline: 400 lines of 8 results each, 91 kB, are 2.75 MB
# of Python and 274 MB), so MAX_PYTHON_CHARACTERS keeps that step under about 420 MB.
MAX_LISTING_CHARACTERS = 256 * 1024
MAX_PYTHON_CHARACTERS = 4 * 1024 * 1024


class Machine(Variables, ControlStack, ErrorTrapping, Breaks, InputOutput, Console, Chaining, CasioWords):
    """A pocket-computer BASIC machine (see the module docstring)."""

    def __init__(self, screen: TextIO | None = None, printer: TextIO | None = None,
                 output_format: str = "text", angle: str | None = None, input_stream: TextIO | None = None,
                 dialect: "str | dialects.Dialect" = "casio", files=None):
        # The dialect (scanner rules, number model, print rules, error policy, start-up
        # state: see dialect.py); ``angle`` overrides its start-up unit ("deg"/"rad").
        self.dialect = dialects.get_dialect(dialect)
        self.def_types: dict = {}  # gw: letter -> type character of the last DEF statements
        self.string_space = string_space.StringSpace(self.measure_memory, self.held_strings)  # gw: GW's 64 KB for strings
        self.arith = arith_policy.ArithmeticPolicy(self)  # division by zero, overflow: stop or go on
        # how PRINT shows a number: typed (GW: integers, 7-digit singles, 16-digit D doubles) or not
        self._printed_number, self._number_text = (
            (_same, values.number_to_text) if self.dialect.typed_numbers else (_as_number, formatting.number_to_text))
        self.screen = self._init_console(screen if screen is not None else sys.stdout)
        self.printer = OutputStream(self.shown(printer) if printer is not None else self.screen.stream,
                                    self.dialect.printer_width, moves_items=False)
        # without a printer LPRINT shares the screen, or (the dialect's screen rules: the
        # Casio, whose LCD holds only what the program shows) goes to the output beside it
        self.own_printer = printer is not None
        if printer is None and (output_format != "text" or not self.dialect.screen.printer_apart):
            self.printer = self.screen
        self.streams = (self.screen, self.printer)
        self.csv = output_format == "csv"
        self.default_angle = (angle or self.dialect.angle).upper()[:3]
        self.input_stream = input_stream
        self.programs: dict[int, dict[int, str]] = {}
        self.python_areas: dict[int, Callable] = {}
        self.file_areas: dict[str, int] = {}  # "file:label" -> the area its program was loaded in
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
        self.init_casio_words()
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
        self.tracing = False  # TRON: lines run are shown (the dialect's trace_mark)
        self.subscript_base = 0  # OPTION BASE
        self.option_seen = False  # an OPTION BASE has run since the run or a CLEAR
        # gw: program area 0 came from a file SAVEd with ,P (LIST, EDIT and a SAVE other than ,P
        # refuse it: GIODSK.ASM PROCHK); LOAD, RUN "file" and CHAIN set it, NEW clears it
        self.program_protected = False
        self.auto_request = None  # gw: AUTO run by a program: (start, step) for the session
        self.auto_step = 0  # gw: the step AUTO used last (GWMAIN.ASM AUTINC: 0 until an AUTO sets it)
        self.edit_request = None  # casio: the line a program's EDIT put up for editing, for the session
        # gw: GW's DOT, the line ``.`` stands for in LIST, LLIST, DELETE, EDIT, AUTO and RENUM
        # (GWMAIN.ASM LINSPC): the line last entered, listed or edited, or where an error
        # stopped or was trapped (``Dialect.current_line_listed``); the session hands it over
        self.current_line = 0
        self._direct_line = None  # (compiled, program, namespace) of a direct line whose DEFs switch it
        # gw: the simple variables a statement made (recorded only where a SWAP may ask: compiler.made)
        self.made = MadeNames()
        # gw: key -> (namespace, block -> names it makes, name -> blocks): Variables.register_makings
        self.making_flags: dict = {}
        self._types_as_statements = None  # the program of area 0 a RUN n entered past its DEFs (_run_types)
        # the program's sequential files, all in one directory (``files``; default the current one)
        words = self.dialect.words
        devices = self.dialect.device_files
        self.files = FileTable(Sandbox(files, reserved_names(devices), self.dialect.nameless_file_error),
                               self.dialect.file_devices,
                               words.absent_devices if words else None, devices)
        self.files.device_streams.update(screen=self.screen, printer=self.printer)
        self.devices = Devices(self.files)  # gw's INP, OUT, ENVIRON, LOCK ... (machine/devices.py)
        # gw's PEEK and POKE (machine/address_space.py): the screen's memory is the display's
        self.address_space = AddressSpace(self._screen_model, self.dialect.charset, self.dialect.screen.video_segment,
                                          self.files, self._fields_poked,
                                          self if self.dialect.data_segment is not None else None,
                                          (lambda: self.screen_words.canvas) if self.display is not None else None)
        self._events = None  # gw's event traps, made by the first statement that sets one (events)
        self._music = None  # gw's music queue, made by the first PLAY, SOUND or BEEP (music)
        self._graphics = None  # gw's graphics words, made by the first that runs (graphics)
        self.clock = Clock()  # TIMER, DATE$, TIME$; DATE$ = and TIME$ = move it
        self._output_eof = bool(words and words.output_eof)  # casio: EOF of an output file is 0 (EOF.md item 4)
        self.gosub_levels = words.gosub_levels if words else None  # casio: 96 (GOSUB.md item 2)
        self.for_levels = words.for_levels if words else None  # casio: 29 (FOR_NEXT_STEP.md item 4)
        # Ctrl-C stops a run where CONT can resume it exactly (the session wants this;
        # ``yaseer run`` stops at once): see _on_interrupt.
        self.resumable_breaks = False
        self._break_armed = None  # (compiled area, its real blocks) while a Ctrl-C waits to land
        self._reading_input = False
        self.while_loops: set = set()  # the WHILE loops running: (area, loop number), see the compiler
        # CLS: called to clear the screen (the session clears a terminal); None: nothing to clear
        self.on_clear_screen: Callable[[], object] | None = None

    # ------------------------------------------------------------ programs and their namespaces
    def load(self, text: str, area: int = 0, entered: bool = True) -> None:
        """Replace area ``area``'s program by the listing ``text`` (line -> text).

        ``entered``: the lines are entered now, so the messages GW-BASIC prints when
        it reads a line are shown (``Overflow`` of a literal: :func:`scanner.entry_messages`);
        False for lines entered before (the session hands its typed program over at RUN).
        A listing over :data:`MAX_LISTING_CHARACTERS` is Out of memory before it is parsed."""
        if len(text) > MAX_LISTING_CHARACTERS:
            raise BasicError("Out of memory", OUT_OF_MEMORY)
        text = self.dialect.charset.codes(text)  # symbols typed or read (a UTF-8 file's) as the machine's codes
        program, stopped = program_lines(text, self.dialect)  # a line without a number: the lines before it load
        program, full = memory_model.fitting_lines({}, program, self.dialect.free_memory)
        stopped = full or stopped  # (a line that does not fit comes before the line without a number)
        if entered:
            for statement_text in program.values():
                self.show_messages(entry_messages(statement_text, self.dialect))
            self._entered(program)
        self.programs[area] = program
        self.python_areas.pop(area, None)
        self._invalidate(area)
        if isinstance(stopped, UndefinedLineInFile):
            # GW's LOAD prints it and keeps the lines before it, which RUN then runs (a real
            # GW-BASIC 3.23 ran such a program so: PC-BASIC's undefined_line_number test)
            self.show_messages([str(stopped)])
        elif stopped is not None:
            raise stopped

    def _entered(self, program: dict[int, str]) -> None:
        """Lines read in as if typed (an ASCII file's LOAD goes through GWMAIN.ASM's line
        entry, which keeps each line's number in DOT): the current line is the last read."""
        if program and self.dialect.current_line_listed:
            self.current_line = next(reversed(program))

    def set_line(self, number: int, text: str, area: int = 0) -> None:
        """Enter (or, with empty text, delete) one program line, as typed."""
        program = self.programs.setdefault(area, {})
        text = self.dialect.charset.codes(text)
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

    def _compile_direct(self, text: str) -> CompiledArea:
        """A line typed (or read as typed) without a number, compiled to run once: its
        namespace is not kept, so the next direct line starts from the program's."""
        compiled = self._compile("direct", {0: text}, direct=True)
        self.namespaces.pop("direct", None)
        return compiled

    def _compile(self, area, program: dict, direct: bool = False, entry_lines=(), dynamic_loops=()) -> CompiledArea:
        """Parse, compile and exec one area's program (line -> text); returns the CompiledArea.

        A program area (not a direct statement) is looked up first in the on-disk
        cache of compiled programs (:mod:`yaseer.basic.compile.program_cache`) and stored
        there after a compile (not the TRON variant, see ``set_trace``, nor one with
        ``dynamic_loops``, see ``cont``)."""
        statement_types = area == 0 and not direct and program == self._types_as_statements
        plain = not (direct or self.tracing or dynamic_loops or statement_types)
        base_one = self.subscript_base == 1  # (a CHAIN's new program keeps the OPTION BASE)
        entry = program_cache.key(area, program, entry_lines, self.dialect, base_one) if plain else None
        cached = program_cache.load(entry) if entry else None
        if cached is not None:
            compiled, codes = cached
        else:
            from yaseer.basic.compile.compiler import compile_area

            if sum(map(len, program.values())) > MAX_LISTING_CHARACTERS:  # also CHAIN's, MERGE's, a file's
                raise BasicError("Out of memory", OUT_OF_MEMORY)
            lines = [_parse_cached(number, text, self.dialect) for number, text in sorted(program.items())]
            compiled = compile_area(lines, area if isinstance(area, int) else 0, direct=direct,
                                    entry_lines=entry_lines, trace=self.tracing, dynamic_loops=dynamic_loops,
                                    dialect=self.dialect, def_types=self.def_types if direct else None,
                                    statement_types=statement_types, base_one=base_one)
            if sum(len(text) for _, text in compiled.pieces) > MAX_PYTHON_CHARACTERS:
                raise BasicError("Out of memory", OUT_OF_MEMORY)
            codes = [None] * len(compiled.pieces)
        runtime_state = _AreaRuntime(self, area, compiled)
        namespace = self._namespace(area, runtime_state)
        codes = [self._exec_piece(text, first_line, area, namespace, code)
                 for (first_line, text), code in zip(compiled.pieces, codes)]
        if entry and cached is None:
            program_cache.store(entry, compiled, codes)
        compiled.blocks = [namespace[f"_b{b}"] for b in range(compiled.block_count)]
        if compiled.makings or not direct:
            self.register_makings("direct" if direct else area, namespace, compiled.makings)
        if direct or area == 0:  # DEF types hold for the direct statements that follow
            self.def_types = dict(compiled.def_types)
        if compiled.dynamic_types:
            compiled.variants[(_table_key(compiled.def_types), self.tracing)] = list(compiled.blocks)
            if direct:  # its DEF statements switch it to its variant for the new table (use_def_types)
                self._direct_line = (compiled, program, namespace)
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
            if self.dialect.free_memory is not None:
                self.string_space.keep_text(code)
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
            "__builtins__": {"abs": abs, "len": len, "float": float, "map": map, "range": range, "type": type, "int": int, "iter": iter,
                             "BaseException": BaseException, "KeyError": KeyError},
            "_M": self, "_S": self.scalars, "_A": self.arrays, "_arr": self.array_nd, "_ix": self.subscript_check(0),
            "_ovf": self.arith.overflowed, "_fail": runtime.fail, "_fail_after": runtime.fail_after, "_err": BasicError, "_rd": argument_reading.Reading, "_wh": self.while_loops, "_END": END, "_off_end": self._ran_off_end, "_DirectJump": DirectJump,
            "_pr": self.print_items, "_pru": self.print_using, "_puo": self.using_line, "_COMMA": COMMA, "_NUMCOMMA": NUMBER_THEN_COMMA, "_Tab": Tab, "_Spc": Spc,
            "_gosub": self.gosub, "_return": self.gosub_return, "_stk": self.stack,
            "_oom": self._out_of_memory, "_deep": self.gosubs_full, "_loops": self.open_loops, "_call": self.call_area, "_call_file": self.call_file,
            "_bank": self.data_bank,
            "_on": self.on_index, "_for": self.for_push, "_next": self.next_frame,
            "_pop": self.stack.pop, "_next_any": self.next_any, "_stop": self._stopper(area),
            "_dim": self.dim, "_clear": self.clear, "_made": self.made, "_mk": self.make_variable, "_dfn": self.define_function, "_swap2": self.swap_second, "_read_n": rt.read_number,
            "_read_s": rt.read_string, "_read_end": rt.read_end, "_restore": rt.restore, "_restore_at": rt.restore_at,
            "_input": self.input_values, "_input_cut": self.input_names_cut,
            "_fn": self.user_function, "_resume": self.resume, "_resume_at": self.resume_at,
            "_error_off": self.error_trapping_off, "_error": self.raise_error,
            "_randomize": self.randomize, "_rnd": self.rnd, "_rndf": self._first_draw,
            "_sqrt": math.sqrt, "_floor": runtime.floor, "_fix": runtime.fix, "_sgn": runtime.sign,
            "_exp": math.exp, "_log": math.log, "_len": lambda s: float(len(s)),
            "_strs": formatting.str_dollar, "_val": gwfunctions.val, "_chr": runtime.chr_dollar,
            "_asc": runtime.asc, "_left": runtime.left, "_right": runtime.right, "_mid": runtime.mid,
            "_cat": runtime.concatenation(self.dialect.string_length), "_pow": runtime.power, "_idiv": runtime.int_divide,
            "_mod": runtime.modulo, "_and": runtime.logical_and, "_or": runtime.logical_or,
            "_not": runtime.logical_not, "_frange": runtime.float_range,
            "_fcount": runtime.pass_counter, "_fidle": runtime.idle_passes, "_fvalue": runtime.counted_value,
            "_fafter": runtime.counted_final, "_tr": self._tracer(area), "_cint": lambda x: float(runtime.cint(x)),
            "_csng": float, "_cdbl": float,
        }
        ns.update(self._gw_functions())
        if self.dialect.typed_numbers:  # (GW: string functions' counts are 16-bit integers, then bytes)
            ns.update(gwfunctions.BYTE_ARGUMENTS)
            ns.update(values.RUNTIME)
            ns.update(runtime.single_loop_helpers())
            ns.update(arith_policy.helpers(self.arith, ns["_idiv"], ns["_mod"], ns["_pow"]))
            ns.update(binade_cache.writers(ns))
            ns.update(val_numbers.helpers(self.arith, ns, self.dialect.number_reading))
        if self.dialect.free_memory is not None:  # strings take room in GW's 64 KB (string_space.py)
            ns.update(self.string_space.helpers(ns, self.dialect.string_length))
        if self.dialect.words:  # the casio functions (dialects/casio.py)
            ns.update(casio_math.RUNTIME)
            ns.update(casio_words.OPERATORS)
            ns.update(casio_words.STRING_FUNCTIONS)
            ns.update({"_ran": self.ran, "_valf": self.valf, "_fre0": self.free_area, "_sroom": self.string_room})
        ns.update(self._trig_functions())
        if self.dialect.arithmetic == "decimal":
            from yaseer.basic.arithmetic import decimal_arith, decimal_calls, decimal_scales  # here: only --arith decimal loads the decimal module

            if self.dialect.words:
                ns.update(decimal_arith.rounding_all(casio_math.RUNTIME))
            ns.update(decimal_arith.RUNTIME)
            ns.update(self._trig_functions())
            ns.update(decimal_arith.rounding_all({name: ns[name] for name in decimal_arith.ENTERING if name in ns}))
            ns.update(decimal_scales.writers(ns))
            ns.update(decimal_calls.helpers(ns))
            ns["_rndr"] = self._first_raw_draw
        if self.dialect.words:  # the casio functions' argument ranges, in either arithmetic
            ns.update(casio_math.ranged(ns))
        if self.dialect.arithmetic == "decimal":  # bound to the namespace's routines, ranges checked
            from yaseer.basic.arithmetic import decimal_fast

            ns.update(decimal_fast.helpers(ns))
        self.namespaces[area] = ns
        return ns

    def _gw_functions(self) -> dict:
        """The namespace entries of GW-BASIC's statements and functions."""
        g = gwfunctions
        return {
            "_instr": g.instr, "_string": g.string_dollar, "_space": g.space_dollar,
            "_hex": g.hex_dollar, "_oct": g.oct_dollar, "_mki": g.mki, "_mks": g.mks, "_mkd": g.mkd,
            "_cvi": g.cvi, "_cvs": g.cvs, "_cvd": g.cvd, "_timer": self.clock.timer, "_date": self.clock.date,
            "_time": self.clock.time, "_xor": g.logical_xor, "_eqv": g.logical_eqv,
            "_imp": g.logical_imp, "_midset": g.mid_assign, "_byte": g.byte_argument, "_fre": self.free_memory,
            "_pos": self.cursor_column,
            "_lpos": self.printer_column,
            "_erase": self.erase, "_option_base": self.option_base, "_line_input": self.line_input,
            "_write": self.write_values, "_clear_args": _check_clear_arguments, "_clear_arg": clear_argument, "_clear_sizes": clear_sizes,
            # sequential files (files.py)
            "_open": self.files.open, "_close": self.files.close, "_field": self.field_variable,
            "_get": self.get_record, "_swapf": self.swap_fields, "_lset": self.set_field, "_kill": self.files.kill,
            "_rename": self.files.rename, "_rename_from": self.files.rename_from, "_chain": self.chain, "_command": self.program_command, "_files": self.list_files,
            "_fout": lambda n: self.files.get(n).output(), "_prf": self.print_to,
            "_pruf": self.print_using_to, "_puof": self.using_line_to, "_writef": self.write_to,
            "_fin_n": self.file_number, "_fin_s": lambda f: f.read_field(False, self.dialect.string_length),
            "_fline": lambda f: f.read_line(self.dialect.string_length),
            "_eof": self.end_of_file,
            "_lof": lambda n: float(self.files.get(n).length()),
            "_loc": lambda n: float(self.files.get(n).records()),
            "_input_chars": self.input_chars, "_inkey": self.inkey, "_input_keys": self.input_keys,
            "_peek": self.peek, "_usr": self.user_routine, "_locate": self.locate,
        }

    def _trig_functions(self) -> dict:
        """The compiled code's angle-dependent helpers in the current unit (DEG, RAD, GRA)."""
        if self.dialect.typed_numbers and self.angle == "RAD":  # MBF singles: GW-BASIC's own routines
            return arith_policy.transcendental_functions(self.arith)
        decimal = self.dialect.arithmetic == "decimal"
        if decimal:
            from yaseer.basic.arithmetic import decimal_arith

            functions = decimal_arith.trig_functions(self.angle)
        elif self.angle == "RAD":
            functions = {"_sin": math.sin, "_cos": math.cos, "_tan": math.tan, "_atn": math.atan}
        else:
            functions = {"_sin": runtime.sin_degrees, "_cos": runtime.cos_degrees,
                         "_tan": runtime.tan_degrees, "_atn": runtime.atn_degrees}
        if self.dialect.words:  # ASN ACS POL REC (and every function in grads)
            extra = casio_math.angle_functions(self.angle)
            if decimal:
                extra = {name: f for name, f in extra.items() if name not in functions}
                extra = decimal_arith.rounding_all(extra)
            functions.update(extra)
        return functions

    def _tracer(self, area):
        """TRON's ``_tr(line)`` for the code of ``area``: the mark names the area (``P0``..,
        a program file's area by the file's name)."""
        name = f"P{area}"
        if isinstance(area, int) and area >= FIRST_FILE_AREA:
            name = next((file.split(":", 1)[0] for file, n in self.file_areas.items() if n == area), name)
        return lambda number: self.trace_line(number, name)

    @property
    def events(self):
        """gw's event traps (machine/events.py), made when a program first sets one up."""
        if self._events is None:
            from yaseer.basic.machine.events import Events  # (only programs with event traps)

            self._events = Events(self.dialect.device_words.events, self)
        return self._events

    @property
    def canvas(self):
        """The graphics mode's pixels (machine/graphics.py Canvas: the one the graphics
        statements draw on), None in a text mode."""
        return self.screen_words.canvas

    @property
    def graphics(self):
        """gw's graphics statements and functions (machine/graphics_words.py), made when a
        program first draws or asks POINT or PMAP."""
        if self._graphics is None:
            from yaseer.basic.machine.graphics_words import GraphicsWords  # (only programs that draw)

            self._graphics = GraphicsWords(self)
        return self._graphics

    @property
    def music(self):
        """gw's music queue and PLAY's state (machine/music.py), made when a program first
        uses PLAY, SOUND, BEEP or PLAY(n)."""
        if self._music is None:
            from yaseer.basic.machine.music import Music  # (only programs with music)

            self._music = Music(self)
        return self._music

    def clear(self) -> None:
        """CLEAR, RUN: the variables (Variables.clear), and PLAY's settings and queue back to
        their start (BIMISC.ASM CLEARC calls GWSTS.ASM SNDINI)."""
        super().clear()
        if self._music is not None:
            self._music.reset()

    def set_trace(self, on: bool) -> None:
        """TRON / TROFF: swap every compiled area's blocks for its traced (or plain) variant.

        The variants have the same blocks, so a running program goes on in the
        new variant from its next block (TRON and TROFF end their block).
        """
        if on == self.tracing:
            return
        self.tracing = on
        from yaseer.basic.compile.compiler import compile_area

        for area, compiled in list(self.compiled.items()):
            extra = tuple(self._extra_entries) if area == 0 else ()
            lines = [_parse_cached(number, text, self.dialect)
                     for number, text in sorted(self.programs.get(area, {}).items())]
            variant = compile_area(lines, area, entry_lines=extra, trace=on, dynamic_loops=compiled.dynamic_loops,
                                   dialect=self.dialect, def_types=self.def_types if compiled.dynamic_types else None,
                                   statement_types=compiled.dynamic_types, base_one=self.subscript_base == 1)
            namespace = self.namespaces[area]
            for first_line, text in variant.pieces:
                self._exec_piece(text, first_line, area, namespace)
            self.register_makings(area, namespace, variant.makings, merge=True)
            armed = self._break_armed
            blocks = armed[1] if armed is not None and armed[0] is compiled else compiled.blocks
            blocks[:] = [namespace[f"_b{b}"] for b in range(variant.block_count)]

    def set_def_types(self, area: int, kind: str, ranges: list) -> None:
        """DEFINT/DEFSNG/DEFDBL/DEFSTR run as a statement (GWMAIN.ASM DEFCON): the letters of
        ``ranges`` ("AZ": first and last) take type ``kind`` ("INT" ...), and a program whose
        types depend on when these run (compiler.stmt_DefType) goes on in its variant compiled
        for the new table, from the next block (the statement ends its block)."""
        table = dict(self.def_types)
        for first, last in ranges:
            for code in range(ord(first), ord(last) + 1):
                table[chr(code)] = _DEF_SUFFIX[kind]
        self.use_def_types(area, {letter: kind for letter, kind in table.items() if kind != "!"})

    def use_def_types(self, area: int | None, table: dict) -> None:
        """Make ``table`` (letter -> type character, single left out) the DEF types, and run
        ``area`` (None: the direct line running) on, if its types switch as it runs, in its
        variant compiled for it (each compiled once, when first reached; they have the same
        blocks, as TRON's variant has)."""
        if table == self.def_types:
            return
        self.def_types = table
        if area is None:
            if self._direct_line is None:
                return
            compiled, program, namespace = self._direct_line
        else:
            compiled, program, namespace = self.compiled.get(area), self.programs.get(area, {}), self.namespaces.get(area)
        if compiled is None or not compiled.dynamic_types:
            return
        key = (_table_key(table), self.tracing)
        blocks = compiled.variants.get(key)
        if blocks is None:
            from yaseer.basic.compile.compiler import compile_area

            extra = tuple(self._extra_entries) if area == 0 else ()
            lines = [_parse_cached(number, text, self.dialect) for number, text in sorted(program.items())]
            variant = compile_area(lines, area or 0, direct=area is None, entry_lines=extra, trace=self.tracing,
                                   dynamic_loops=compiled.dynamic_loops, dialect=self.dialect, def_types=table,
                                   statement_types=True, base_one=self.subscript_base == 1)
            if variant.block_count != compiled.block_count:  # (a compile error cut a statement's blocks short)
                raise BasicError("Internal error (the DEF type variants differ)", INTERNAL_ERROR)
            for first_line, text in variant.pieces:
                self._exec_piece(text, first_line, area, namespace)
            self.register_makings("direct" if area is None else area, namespace, variant.makings, merge=True)
            blocks = compiled.variants[key] = [namespace[f"_b{b}"] for b in range(variant.block_count)]
            for name in variant.scalars:
                self.scalars.setdefault(name, initial_value(name))
        armed = self._break_armed
        target = armed[1] if armed is not None and armed[0] is compiled else compiled.blocks
        target[:] = blocks

    def reset_def_types(self) -> None:
        """CLEAR, RUN: every letter single again (BIMISC.ASM CLEARC), in a program whose
        DEF types switch as it runs (the table of one whose types are fixed stays: it is
        applied before the program runs, and holds for the direct statements after it)."""
        compiled = self.compiled.get(0)
        if compiled is not None and compiled.dynamic_types:
            self.use_def_types(0, {})

    def set_angle(self, mode: str) -> None:
        """DEG or RAD: the unit SIN, COS, TAN take and ATN returns."""
        self.angle = mode.upper()[:3]
        functions = self._trig_functions()
        for ns in list(self.namespaces.values()):
            ns.update(functions)

    # ------------------------------------------------------------ program areas (GOSUB PROG)
    def call_area(self, n: int, line=None) -> bool:
        """GOSUB PROG n (at BASIC ``line``): run program area n and come back.  Returns whether
        the arrays may have been replaced (DIM, ERASE, CLEAR), so that the caller looks up the
        arrays it holds again: not after a Python area marked ``keeps_arrays`` (one that only
        reads and writes elements, or makes an array not made yet) when no hook ran."""
        self.line = line
        python_area = self.python_areas.get(n)
        if python_area is not None:
            python_area(self)
            changed = not getattr(python_area, "keeps_arrays", False)
        else:
            self._call_basic_area(n)
            changed = True
        for hook in self.area_hooks:
            self.line = line
            hook(self, n)
            changed = True
        if (python_area is not None or self.area_hooks) and self.dialect.arithmetic == "decimal":
            self._decimal_values()
        return changed

    def _decimal_values(self) -> None:
        """Every number in the scalars and arrays as a 12-digit decimal (``--arith decimal``),
        after Python code stored its own (the compiled arithmetic relies on it, decimal_scales.py)."""
        from yaseer.basic.arithmetic.decimal_arith import held

        def each(values: list) -> None:
            for i, v in enumerate(values):
                if type(v) is list:
                    each(v)
                elif type(v) is not str:
                    values[i] = held(v)

        scalars = self.scalars
        for name, v in list(scalars.items()):
            if type(v) is not str:
                scalars[name] = held(v)
        for array in self.arrays.values():
            each(array)

    def call_file(self, name: str, line=None) -> None:
        """GOSUB "file:label" (and GOTO, which ends when it comes back): run the program
        file ``name`` names (program_files.py) as a program area of its own, sharing the
        variables, until its RETURN."""
        area = self.file_areas.get(name)
        if area is None:
            from yaseer.basic.machine import program_files  # here: only programs that call files load it

            text = program_files.read_program(name, self.files.sandbox, self.dialect.charset)
            area = FIRST_FILE_AREA + len(self.file_areas)
            self.load(text, area)
            self.file_areas[name] = area
        self.call_area(area, line)

    def end_of_file(self, n) -> float:
        """EOF(n): -1 at the end of an input file, else 0; an output file is Bad file mode, or 0
        where the dialect says so (casio: EOF.md item 4); EOF(0) 0 where the dialect says so."""
        if self.dialect.eof_of_file_zero and file_byte(n) == 0:
            return 0.0
        file = self.files.get(n)
        if self._output_eof and getattr(file, "is_output", False):
            return 0.0
        return -1.0 if file.at_end() else 0.0

    def data_bank(self):
        """The Casio's DATA BANK (machine/databank.py), made when a program first uses it."""
        bank = self.__dict__.get("_data_bank")
        if bank is None:
            from yaseer.basic.machine.databank import DataBank  # here: only programs that use it load it

            bank = self._data_bank = DataBank()
        return bank

    def _call_basic_area(self, n: int) -> None:
        """Run BASIC program area ``n`` until its RETURN (its own line numbers, shared variables)."""
        if n not in self.programs:
            raise BasicError(f"Undefined program area {n}", UNDEFINED_PROGRAM_AREA)
        levels = self.gosub_levels
        if self.area_depth >= MAX_AREA_DEPTH or (levels is not None and len(self.stack) >= levels and self.gosubs_full()):
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

    # ------------------------------------------------------------ the run loop
    def _run_area(self, area: int, compiled: CompiledArea, block: int, direct: bool = False,
                  handler: bool = False) -> None:
        """Run ``area`` from ``block`` until its RETURN (areas) or END (raises ProgramEnd).

        ``direct``: ``compiled`` is a direct statement run against ``area``; an error of it that
        the program's ON ERROR GOTO catches runs the handler in the program's code, and the
        handler's RESUME [NEXT] comes back into ``compiled`` (ResumeDirect).  ``handler``:
        its error is already trapped, ``block`` is the handler's in the program's code.
        """
        blocks = self._compiled(area).blocks if handler else compiled.blocks
        b = block
        while True:
            try:
                while b >= 0:
                    b = blocks[b]()
                return
            except (ProgramEnd, ProgramStop, DirectJump, BrokenPipeError, OutputError):
                raise
            except ResumeDirect as back:
                blocks, b = compiled.blocks, back.block
            except BaseException as exc:  # noqa: BLE001 - every error becomes a BASIC error
                err = to_basic_error(exc)
                err.at(self.line, area)
                in_direct = direct and blocks is compiled.blocks
                target = self._trap(err, area, b, compiled if in_direct else None)
                if target is None:
                    raise err from None
                if in_direct:
                    blocks = self._compiled(area).blocks
                b = target

    def reset(self) -> None:
        """The state RUN starts from: no variables, empty stack, the default angle unit."""
        self.clear()
        self.stack.clear()
        self.while_loops.clear()
        self.on_error = None
        self.in_handler = False
        self.err = self.erl = 0.0
        self.cont_point = None
        self.area_depth = 0
        self.set_angle(self.default_angle)
        self.set_subscript_base(0)
        self.files.close()
        self.random.reset()
        if self._events is not None:  # RUN forgets the traps
            self._events.disarm()
            self._events = None
        if self.display is not None:
            self.display.drawn = False  # the new run's text streams until it draws

    def run(self, line: int | None = None) -> str:
        """RUN (from ``line``): returns "end" or "stop"; raises BasicError on an error."""
        self.compile_areas(line)
        self.reset()
        block = 0
        if line is not None:
            block = self._line_block(line)
        return self._execute(0, block)

    def compile_areas(self, line: int | None = None) -> None:
        """Compile (or read from the cache) every area RUN [``line``] runs, as :meth:`run` does first;
        a second call finds them compiled.  A ``yaseer run`` process calls it before the program
        starts, while its collector is still paused (yaseer.collection_pause): parsing and
        compiling make many objects but no cyclic garbage worth a collection."""
        if self.compiled.get(0) is not None and self.compiled[0].dynamic_loops:
            self._invalidate(0)  # the variant CONT made after a Ctrl-C: back to native loops
        self._run_types(line)
        for area in self.programs:
            self._compiled(area)

    def _run_types(self, line: int | None) -> None:
        """Before RUN [line] resets the machine: RUN clears the DEF type table (BIMISC.ASM
        CLEARC), so a program whose DEFs are applied before it runs (blocks.types_fixed)
        but is entered at a later ``line`` is compiled with them switching the table where
        they run (from the top it keeps the compile that applies them first)."""
        compiled = self._compiled(0)
        if line is not None and compiled.def_types and not compiled.dynamic_types and line != compiled.first_line:
            self._types_as_statements = dict(self.programs[0])
            self._invalidate(0)
            self._compiled(0)

    def _line_block(self, line: int) -> int:
        """The block that starts at ``line`` of area 0 (recompiling so that one does)."""
        if line not in self.programs.get(0, {}):
            raise BasicError(undefined_line_message(line, self.dialect.names_missing_line), UNDEFINED_LINE)
        block = self._compiled(0).line_blocks.get(line)
        if block is None:
            self._extra_entries.add(line)
            self._compile(0, self.programs[0], entry_lines=tuple(self._extra_entries))
            block = self._compiled(0).line_blocks[line]
        return block

    def _ended(self) -> str:
        """END (or the last line run): an error handler left so is left (BIMISC.ASM ENDST
        clears ONEFLG), so the ON ERROR GOTO still set traps the next error."""
        self.in_handler = False
        return "end"

    def _ran_off_end(self, line: int) -> None:
        """The program ran past its last ``line``: inside an error handler that is No RESUME
        in that line, where the dialect says so (GWMAIN.ASM PRGEND); the handler's own
        error is not trapped (ONEFLG is still set)."""
        if self.in_handler and self.dialect.handler_must_resume:
            self.line = line
            raise error_for(NO_RESUME)

    def _execute(self, area: int, block: int, direct_code: CompiledArea | None = None) -> str:
        self.cont_point = None
        try:
            with _interrupt_handler(self._on_interrupt):
                return self._execute_loop(area, block, direct_code)
        finally:
            self._disarm_break()

    def _execute_loop(self, area: int, block: int, direct_code: CompiledArea | None = None) -> str:
        """Run from ``block`` of ``area`` (with ``direct_code``: of the program's handler, for
        an error of that direct line, which RESUME goes back into) to the end."""
        stopped = False
        try:
            while True:
                in_direct = direct_code is not None  # (a STOP there leaves nothing to CONTinue)
                try:
                    if direct_code is None:
                        self._run_area(area, self._compiled(area), block)
                    else:
                        code, direct_code = direct_code, None
                        self._run_area(0, code, block, direct=True, handler=True)
                    break
                except ChainTo as chain:  # CHAIN: on in the new program (MERGE: stop)
                    start = self.chained(chain)
                    if start is None:
                        return "end"
                    area, block, direct_code = 0, start.block, start.direct_code
                except RunAgain as again:  # RUN in the program
                    area, block = 0, self.run_again(again)
                except DirectJump as jump:  # GOTO in that direct line
                    area, block = 0, self._line_block(jump.line)
        except ProgramEnd:
            return self._ended()
        except BreakPoint as stop:
            self._disarm_break()
            if stop.area == 0 and stop.depth == 0:
                self.cont_point = (0, stop.block, stop.loops)
            self.area_depth = 0
            self.line = stop.line
            raise BasicError("Break", BREAK).at(stop.line) from None
        except ProgramStop as stop:
            if in_direct:
                self.line = None  # a direct line's STOP: a plain "Break"
            elif stop.area == 0 and self.area_depth == 0:
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
            self.show_screen(final=True)
            self.flush()
        return "end"

    def execute_direct(self, text: str) -> str:
        """Run statements typed without a line number against the same variables."""
        text = self.dialect.charset.codes(text)
        self.show_messages(entry_messages(text, self.dialect))
        compiled = self._compile_direct(text)
        self.string_space.temps.clear()  # those of a line that failed before
        try:
            self.line = None
            try:
                self._run_area(0, compiled, 0, direct=True)
            except BasicError as err:
                if err.line == 0:
                    err.line = None
                raise
            return "end"
        except ChainTo as chain:
            start = self.chained(chain)
            return "end" if start is None else self._execute(0, start.block, start.direct_code)
        except RunAgain as again:
            return self._execute(0, self.run_again(again))
        except ProgramEnd:
            return self._ended()
        except ProgramStop:
            return "stop"
        except DirectJump as jump:
            return self._execute(0, self._line_block(jump.line))
        finally:
            self._direct_line = None
            if self.csv:  # a last line left open (PRINT A;) is still a row
                self.end_line()
            self.end_drawing()
            self.flush()

    # ------------------------------------------------------------ RND
    def rnd(self, x: float = 1.0) -> float:
        """RND(x): x > 0 the next number, 0 the last again, x < 0 reseeds with x first."""
        return self.random.rnd(x)

    def _first_draw(self) -> float:
        """RND's next number, the first time an area draws one: from then on each area's
        ``_rndf`` (RND and RND(x) with a constant x > 0) is the generator's own drawer
        (in decimal arithmetic rounded to 12 digits, as the namespace's other entries)."""
        return self._set_drawers()[1]()

    def _first_raw_draw(self) -> float:
        """``_rndr``'s first number (decimal arithmetic, whose compiled code rounds it): from then
        on each area's ``_rndr`` is the generator's own drawer, ``_rndf`` as :meth:`_first_draw`."""
        return self._set_drawers()[0]()

    def _set_drawers(self) -> tuple:
        """Every area's ``_rndr`` and ``_rndf``: (the generator's drawer, the one RND calls)."""
        draw = rounded_draw = self.random.drawer()
        if self.dialect.arithmetic == "decimal":
            from yaseer.basic.arithmetic.decimal_arith import rounding

            rounded_draw = rounding(draw)
        for namespace in self.namespaces.values():
            namespace["_rndr"], namespace["_rndf"] = draw, rounded_draw
        return draw, rounded_draw

    def randomize(self, seed, kind: str = "!") -> None:
        """RANDOMIZE seed; ``kind`` is the seed's type ("%", "!", "#", see yaseer.basic.arithmetic.randomness).

        Without a seed a generator with a ``seed_prompt`` (GW-BASIC's) asks for one
        on the screen and reads it as INPUT does, rounded to an integer.
        """
        if seed is None and self.random.seed_prompt is not None:
            seed, kind = runtime.cint(self.input_values(self.random.seed_prompt, False, "n")[0]), "%"
            if not -32768 <= seed <= 32767:
                runtime.overflow()
        self.random.randomize(seed, kind)
