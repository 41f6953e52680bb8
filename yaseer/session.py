"""The editing session of the pocket computer, without any terminal I/O.

A :class:`Session` takes one typed line at a time (:meth:`Session.handle`) and
writes what the pocket computer would show through a ``write(text)`` callable.
The terminal front end (``yaseer.commands.interactive``) only reads lines and
passes them in; everything else — the program store, the commands, errors —
lives here, so it can be tested by calling functions.

What the user can type:

- ``10 PRINT X`` stores line 10 in the program area being edited; ``10`` alone
  deletes it.
- ``LIST [range]`` (lines as the pocket computer lists them: keywords in
  capitals and spaced, see ``scanner.detokenize``), ``LLIST [range]`` (the
  same to the printer), ``DELETE range``, ``RENUM [new[,old[,step]]]``,
  ``EDIT n``, ``AUTO [start][,step]``, ``NEW``, ``RUN [line]``, ``CONT``,
  ``LOAD "file"``, ``SAVE "file"``, ``PROG n`` (switch the area being edited,
  0-9; 0 is the main listing), ``SYSTEM`` / ``BYE`` (leave).  A range is
  ``n``, ``n-m``, ``n-`` or ``-m``.
- Anything else is a direct-mode statement run at once against the same
  variables: ``PRINT 2*3``, ``GOSUB PROG 5``, ``X(10)=3``, ``TRON``, ``CLS``.

AUTO offers line numbers as the prompt (``30 ``, or ``30*`` when line 30
exists, as GW-BASIC marks it); what is typed becomes that line.  Enter alone
after ``30*`` keeps line 30 and offers the next number (GW-BASIC); Enter alone
after a free number, or Ctrl-C (:meth:`Session.interrupt`), ends AUTO.  A
``Syntax error in 20`` from a run puts line 20 up for editing, as GW-BASIC does.

Areas 1, 2, 3 and 5 hold the library programs (Python) until lines are typed
or loaded into them; then the typed BASIC program replaces the library program
in that area for this session (``NEW`` in the area brings the library back).
Every error is shown as one BASIC error line and the session goes on.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, NamedTuple

from yaseer.basic.source.line_ranges import deleted_lines
from yaseer.basic.source.scanner import entry_messages
from yaseer.basic.errors import (
    BREAK,
    CANT_CONTINUE,
    ILLEGAL_FUNCTION_CALL,
    SYNTAX_ERROR,
    UNDEFINED_LINE,
    BasicError,
    password_protected,
)

MAX_LINE_NUMBER = 65529  # the largest line number MS-BASIC accepts
_PERIOD = re.compile(r"(?<![\d.])\.(?![\d.])")  # the current line's ``.`` in LIST ., DELETE 10-. ...
AREAS = range(10)  # PROG 0 (the listing) to PROG 9, as on the pocket computers
LIBRARY_AREAS = (1, 2, 3, 5)  # the areas yaseer.binding fills with Python programs
PROMPT_READY = "Ready"

Program = dict[int, str]  # line number -> statement text (without the number)

# --- the program text: storing, listing, ranges, renumbering -----------------

_NUMBERED = re.compile(r"\s*(\d+)(?=[\sA-Za-z'?]|$)\s?(.*)$", re.S)


def split_numbered(text: str, keeps_blanks: bool = False) -> tuple[int, str] | None:
    """``"10 PRINT X"`` -> ``(10, "PRINT X")``; None if the text has no line number.
    ``keeps_blanks`` (``Dialect.tokenised_programs``): the text keeps the blanks after it
    (scanner.split_lines); else they are dropped.

    Raises ``Syntax error`` for a number beyond :data:`MAX_LINE_NUMBER`.
    """
    match = _NUMBERED.match(text)
    if not match:
        return None
    number = int(match.group(1))
    if number > MAX_LINE_NUMBER:
        raise BasicError("Syntax error", SYNTAX_ERROR)
    body = match.group(2)
    return number, body if keeps_blanks else body.rstrip()


def parse_listing(text: str, keeps_blanks: bool = False) -> Program:
    """A listing file as line -> text, read as the machine reads a file.

    Blank lines are skipped; a line that does not start with a line number
    continues the line before it (the paper's listings wrap long lines; see
    ``yaseer.basic.source.scanner.split_lines``).  Text before the first numbered
    line is a ``Syntax error``; a repeated number keeps the later line.
    """
    from yaseer.basic.source.scanner import split_lines

    program: Program = {}
    for number, body, _ in split_lines(text, keeps_blanks=keeps_blanks):
        if number > MAX_LINE_NUMBER:
            raise BasicError("Syntax error", SYNTAX_ERROR)
        program[number] = body
    return program


def program_text(program: Program) -> str:
    """The program as a listing: one ``"<number> <text>"`` line each, in order."""
    return "".join(f"{number} {program[number]}\n" for number in sorted(program))


def parse_range(text: str) -> tuple[int, int]:
    """``"10-40"``, ``"10"``, ``"10-"``, ``"-40"`` or ``""`` -> inclusive (first, last)."""
    text = text.strip()
    if not text:
        return 0, MAX_LINE_NUMBER
    match = re.fullmatch(r"(\d*)\s*(-?)\s*(\d*)", text)
    if not match or not (match.group(1) or match.group(3)):
        raise BasicError("Syntax error", SYNTAX_ERROR)
    first_text, dash, last_text = match.groups()
    first = int(first_text) if first_text else 0
    if not dash:
        return first, first
    last = int(last_text) if last_text else MAX_LINE_NUMBER
    return first, last


def given_range(text: str) -> tuple[int | None, int | None]:
    """GW-BASIC's ``[first][-[last]]`` (GWMAIN.ASM SCNLIN): the numbers, None where left out
    (``"20"`` is 20 to 20; ``""`` and ``"-"`` none)."""
    match = re.fullmatch(r"(\d*)\s*(-?)\s*(\d*)", text.strip())
    if not match or (match.group(3) and not match.group(2)):
        raise BasicError("Syntax error", SYNTAX_ERROR)
    first = int(match.group(1)) if match.group(1) else None
    last = int(match.group(3)) if match.group(3) else None
    return (first, first) if not match.group(2) and first is not None else (first, last)


def lines_in_range(program: Program, first: int, last: int) -> list[int]:
    """The line numbers of ``program`` between ``first`` and ``last`` inclusive, in order."""
    return [number for number in sorted(program) if first <= number <= last]


def renumber_references(text: str, mapping: dict[int, int], dialect: str = "casio") -> tuple[str, list[int]]:
    """Rewrite the line numbers that ``text`` names through ``mapping`` (as the tokeniser
    reads them: yaseer.basic.source.renumbering); also the numbers absent from ``mapping``."""
    from yaseer.basic.dialects.dialect import get_dialect
    from yaseer.basic.source.renumbering import renumber_text

    return renumber_text(text, mapping, get_dialect(dialect))


def renumber(program: Program, new: int = 10, old: int = 0, step: int = 10,
             dialect: str = "casio") -> tuple[Program, list[str]]:
    """RENUM: lines from ``old`` on become ``new``, ``new+step``, ...; the line numbers
    statements name follow; warnings (``"Undefined line 90 in 30"``) for those that name no
    line; ``Illegal function call`` where GW-BASIC's RESEQ refuses
    (yaseer.basic.source.renumbering)."""
    from yaseer.basic.dialects.dialect import get_dialect
    from yaseer.basic.source.renumbering import renumber as renumber_program

    return renumber_program(program, new, old, step, get_dialect(dialect))


def file_name_argument(text: str) -> str:
    """``"\"EX1.BAS\""`` -> ``EX1.BAS`` (closing quote optional, as on the period machines)."""
    match = re.fullmatch(r'\s*"([^"]*)"?\s*', text)
    if not match or not match.group(1).strip():
        raise BasicError("Syntax error", SYNTAX_ERROR)
    return match.group(1).strip()


def read_listing_file(name: str, directory: Path, dialect=None) -> Program:
    """LOAD: the program in file ``name`` (``.bas`` is tried if ``name`` has no suffix),
    inside ``directory`` only (yaseer.basic.machine.files.Sandbox: a name that leads out of it is
    ``Path/File access error``), as the ``dialect``'s character set shows it
    (program_file.program_text), read as the dialect's LOAD reads it (scanner.program_lines).
    A line without a number raises the ``Direct statement in file`` that stopped the reading."""
    program, _, stopped, _ = read_program_file(name, directory, dialect)
    if stopped is not None:
        raise stopped
    return program


class ProgramFile(NamedTuple):
    """A program file as LOAD reads it (:func:`read_program_file`)."""

    program: Program  # the lines before a line without a number, where the dialect stops there
    protected: bool  # SAVEd with ,P
    stopped: BasicError | None  # the ``Direct statement in file`` that stopped the reading
    typed: bool  # an ASCII file, whose lines are entered as typed ones (GW's DOT: the last)


def read_program_file(name: str, directory: Path, dialect=None) -> ProgramFile:
    """:func:`read_listing_file`'s program, and what else LOAD learns from the file."""
    from yaseer.basic.dialects.dialect import CASIO
    from yaseer.basic.machine.program_file import is_protected, program_text
    from yaseer.basic.machine.memory_model import fitting_lines
    from yaseer.basic.machine.sandbox import Sandbox
    from yaseer.basic.source.scanner import program_lines

    sandbox = Sandbox(directory)
    if not sandbox.exists(sandbox.dos_name(name)) and "." not in name.replace("\\", "/").rsplit("/", 1)[-1]:
        name += ".bas"
    data = sandbox.read_bytes(sandbox.dos_name(name))  # DOS ignores case: a program's SAVE "f" wrote F.BAS
    dialect = dialect or CASIO
    program, stopped = program_lines(program_text(data, dialect.charset), dialect, from_file=True)
    program, full = fitting_lines({}, program, dialect.free_memory)  # gw: the lines that fit are loaded
    stopped = full or stopped
    if any(number > MAX_LINE_NUMBER for number in program):
        raise BasicError("Syntax error", SYNTAX_ERROR)
    return ProgramFile(program, is_protected(data), stopped, data[:1] not in (b"\xfe", b"\xff"))


def file_and_option(text: str) -> tuple[str, str]:
    """``"\"F\",P"`` -> (``F``, ``P``): SAVE's file name and the letter after a comma ("" without one)."""
    match = re.fullmatch(r'(\s*"[^"]*"?\s*)(?:,\s*([A-Za-z])\s*)?', text)
    if not match:
        raise BasicError("Syntax error", SYNTAX_ERROR)
    return file_name_argument(match.group(1)), (match.group(2) or "").upper()


# --- the session ----------------------------------------------------------------

HELP_TEXT = """\
10 PRINT X          store line 10 (10 alone deletes it)
LIST [a-b]          show lines            DELETE a-b   remove lines
EDIT n              edit line n           RENUM [new[,old[,step]]]
AUTO [n][,step]     number lines for you (Enter on a free number or Ctrl-C ends)
LLIST [a-b]         list to the printer   TRON, TROFF  trace lines run as [n]
CLS                 clear the screen
RUN [n] | RUN "f"   run PROG 0            CONT         go on after STOP or Ctrl-C
NEW                 erase this area       PROG n       edit area n (0-9)
LOAD "f" | SAVE "f" read / write a .bas   FILES        list the .bas files here
PRINT 2*3, GOSUB PROG 5, ...              run at once (direct mode)
SYSTEM, BYE, Ctrl-D leave                 Ctrl-C       break a running program
"""

_COMMAND = re.compile(
    r"\s*(LLIST|LIST|DELETE|RENUM|EDIT|AUTO|NEW|RUN|CONT|LOAD|SAVE|PROG|FILES|HELP|SYSTEM|BYE)(?![A-Z$(=])(.*)$",
    re.I | re.S,
)


@dataclass
class Session:
    """One user's pocket computer: programs per area, the machine, the commands.

    ``write`` receives everything shown (program output and messages, with
    newlines).  ``engine`` runs BASIC: :class:`MachineEngine`, or anything
    with ``run(programs, start)``, ``cont()``, ``direct(statement, programs)``
    and ``reset()`` that reports errors, STOP and breaks as BasicError.
    ``directory`` is where LOAD and SAVE look; ``printer`` receives LLIST
    (default: ``write``, the screen); ``dialect`` ("casio" or "gw", as the
    engine's) decides how LIST reads a line (GW-BASIC reads ``COST`` as a name).
    """

    write: Callable[[str], object]
    engine: object
    directory: Path = field(default_factory=Path.cwd)
    programs: dict[int, Program] = field(default_factory=lambda: {area: {} for area in AREAS})
    area: int = 0
    edit_text: str | None = None  # a line EDIT put up for the next input
    finished: bool = False
    printer: Callable[[str], object] | None = None
    dialect: str = "casio"
    auto: tuple[int, int] | None = None  # AUTO: (number offered next, step)
    current_line: int | None = None  # the line most recently written, edited or run (LIST ., EDIT .)
    protected_areas: set = field(default_factory=set)  # areas LOADed from a file SAVEd with ,P
    _auto_step: int = 10
    _can_continue: bool = False

    @property
    def prompt(self) -> str:
        """What the next line is typed after: ``P0> `` or, in AUTO, the line number offered."""
        if self.auto is not None:
            number = self.auto[0]
            return f"{number}{'*' if number in self.program else ' '}"
        return f"P{self.area}> "

    def interrupt(self) -> None:
        """Ctrl-C at the prompt: the typed line is dropped and AUTO ends."""
        self.auto = None
        self.edit_text = None

    # -- entry point --

    def handle(self, text: str) -> None:
        """Act on one typed line; errors are shown, never raised."""
        self.edit_text = None
        if hasattr(self.engine, "typed_line"):  # the machine's input buffer (PEEK) holds it
            self.engine.typed_line = text
        try:
            self._dispatch(text)
        except BasicError as error:
            self.write(f"{error}\n")
        except (KeyboardInterrupt, SystemExit):
            raise
        except Exception as error:  # noqa: BLE001 - a slip of ours must not end the user's session
            self.write(f"Internal error ({type(error).__name__}: {error})\n")

    def _dispatch(self, text: str) -> None:
        if self.auto is not None:
            self._auto_line(text)
            return
        if not text.strip():
            return
        numbered = split_numbered(text, self._dialect().tokenised_programs)
        if numbered is not None:
            self.store_line(*numbered)
            return
        command = _COMMAND.match(text)
        if command is None:
            self.direct(text.strip())
            return
        name, argument = command.group(1).upper(), command.group(2).strip()
        getattr(self, f"command_{name.lower()}")(self._current_line_read(name, argument))

    # -- the program store --

    @property
    def program(self) -> Program:
        """The program of the area being edited."""
        return self.programs[self.area]

    def _refuse_protected(self) -> None:
        """LIST, EDIT, a line typed and a SAVE other than ,P of a program LOADed from a
        protected file: Illegal function call (GIODSK.ASM PROCHK, called by LIST, BUFLIN,
        the line entry of GWMAIN.ASM and BINSAV)."""
        if self.area in self.protected_areas:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self._refuse_password()

    def _refuse_password(self) -> None:
        """A password registered (PASS, casio): a program written, LIST, LLIST, EDIT, NEW and
        SAVE, in any area, are the PR error (PASS.md item 5)."""
        if getattr(self.engine, "password", None) is not None:
            raise password_protected()

    def store_line(self, number: int, text: str) -> None:
        """Type ``number text``: store (or, with no text, delete) a line."""
        self._refuse_protected()
        if text.strip(" "):
            self._fit_line(number, text)
            self.program[number] = text
            self.current_line = number
            self._show_entry_messages({number: text})
        else:
            self.program.pop(number, None)
        self._can_continue = False
        self._program_edited()

    def _fit_line(self, number: int, text: str) -> None:
        """gw: a typed line that would take the program past the 64 KB is Out of memory and
        is not entered; the line of its number is gone (memory_model.fitting_lines)."""
        from yaseer.basic.machine.memory_model import fitting_lines

        _, full = fitting_lines(self.program, {number: text}, self._dialect().free_memory)
        if full is not None:
            self.program.pop(number, None)
            self._can_continue = False
            self._program_edited()
            raise full

    def _program_edited(self) -> None:
        """A typed line or DELETE changed the program: the engine applies the dialect's rule."""
        if hasattr(self.engine, "program_edited"):
            self.engine.program_edited()

    def _show_entry_messages(self, program: Program) -> None:
        """What GW-BASIC prints when it reads the lines ``program`` in (``Overflow`` for
        a literal beyond the range: scanner.entry_messages), one row each."""
        from yaseer.basic.dialects.dialect import get_dialect

        dialect = get_dialect(self.dialect)
        for number in sorted(program):
            for message in entry_messages(program[number], dialect):
                self.write(message + "\n")

    def _auto_line(self, text: str) -> None:
        """A line typed after an AUTO number (see the module docstring)."""
        number, step = self.auto
        if not text.strip() and number not in self.program:
            self.auto = None
            return
        if text.strip():
            self.store_line(number, text)
        following = number + step
        self.auto = (following, step) if following <= MAX_LINE_NUMBER else None

    def listed(self, number: int, area: int | None = None) -> str:
        """Line ``number`` of the current area (or of program area ``area``) as LIST shows
        it (``20 FOR J=1 TO 3``)."""
        from yaseer.basic.machine.program_crunch import listed_line

        lines = self.program if area is None else self.programs[area]
        charset = self._dialect().charset  # the session keeps lines as typed; LIST lists the machine's codes
        return f"{number} {charset.symbols(listed_line(charset.codes(lines[number]), self._dialect()))}"

    # -- commands --

    def command_list(self, argument: str, write: Callable[[str], object] | None = None) -> None:
        """LIST [range]: show the stored lines of the current area as the machine lists them."""
        write = write or self.write
        if self._every_area(argument):  # LIST ALL (casio, LIST.md item 13): areas P0-P9 in turn
            self._refuse_password()
            for area in sorted(a for a, lines in self.programs.items() if lines):
                write(f"P{area}\n")
                for number in sorted(self.programs[area]):
                    write(self.listed(number, area) + "\n")
            return
        first, last = parse_range(argument)
        self._refuse_protected()
        if not self.program and self.area in LIBRARY_AREAS:
            from yaseer.library_text import LIBRARY_TEXT

            write(LIBRARY_TEXT[self.area] + "(typed lines replace it for this session; NEW brings it back)\n")
            return
        for number in lines_in_range(self.program, first, last):
            write(self.listed(number) + "\n")
            if self._dialect().current_line_listed:
                self.current_line = number  # GWLIST.ASM LIST keeps each line shown in DOT

    def command_llist(self, argument: str) -> None:
        """LLIST [range]: LIST to the printer."""
        self.command_list(argument, self.printer or self.write)

    def command_auto(self, argument: str) -> None:
        """AUTO [start][,[step]]: offer line numbers from ``start`` (10) by ``step`` (10, or the last one)."""
        match = re.fullmatch(r"(\d*)\s*(?:,\s*(\d*))?", argument)
        if not match:
            raise BasicError("Syntax error", SYNTAX_ERROR)
        start = int(match.group(1)) if match.group(1) else 10
        step = int(match.group(2)) if match.group(2) else (self._auto_step if "," in argument else 10)
        if start > MAX_LINE_NUMBER or step <= 0:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self._auto_step = step
        if hasattr(self.engine, "auto_step"):  # a program's AUTO n, takes this step after it
            self.engine.auto_step = step
        self.auto = (start, step)

    def command_delete(self, argument: str) -> None:
        """DELETE range: remove lines; a single missing line is an error (where the dialect's
        range must end on a line, ``delete_needs_last_line``: source/line_ranges.py)."""
        exact = self._dialect().delete_needs_last_line
        if not argument and not exact:
            raise BasicError("Syntax error", SYNTAX_ERROR)
        self._refuse_password()  # a program write (PASS.md item 5)
        if exact:
            doomed = deleted_lines(self.program, *given_range(argument), open_end=True)
        else:
            first, last = parse_range(argument)
            doomed = lines_in_range(self.program, first, last)
            if not doomed and first == last:
                raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        for number in doomed:
            del self.program[number]
        self._can_continue = False
        self._program_edited()

    def command_renum(self, argument: str) -> None:
        """RENUM [new[,old[,step]]] (defaults 10, first line, 10)."""
        self._refuse_password()  # a program write (PASS.md item 5)
        values = [part.strip() for part in argument.split(",")] if argument else []
        if len(values) > 3 or not all(value.isdigit() or value == "" for value in values):
            raise BasicError("Syntax error", SYNTAX_ERROR)
        numbers = [int(value) if value else default for value, default in zip(values + ["", "", ""], (10, 0, 10))]
        renumbered, warnings = renumber(self.program, *numbers, dialect=self.dialect)
        self.programs[self.area] = renumbered
        for warning in warnings:
            self.write(warning + "\n")
        self._can_continue = False

    def command_edit(self, argument: str) -> None:
        """EDIT n (and EDIT ., see ``_current_line_read``): put line n up for editing as the next input."""
        current = None
        words = self._dialect().words
        if not argument and words is not None and words.edit_lists_from and self.program:
            current = (min(self.program),) * 2  # EDIT alone: the first line (EDIT.md, its parameter)
        if current is None and not argument.isdigit():
            raise BasicError("Syntax error", SYNTAX_ERROR)
        number = current[0] if current is not None else int(argument)
        self._refuse_protected()
        if number not in self.program:
            raise BasicError("Undefined line number", UNDEFINED_LINE)
        self.current_line = number
        self.edit_text = self.listed(number)

    def _current_line_read(self, name: str, argument: str) -> str:
        """``argument`` of command ``name`` with each ``.`` that stands for a line number (not
        beside a digit or another ``.``) made the current line's number, where the dialect's
        ``name`` reads it so (``Dialect.current_line_commands``): the line last typed, edited,
        stopped in by an error or Break, and in gw listed (GW's DOT), in casio run.  Before any
        such line: line 0 in gw (``current_line_listed``), a Syntax error in casio."""
        dialect = self._dialect()
        if "." not in argument or name not in dialect.current_line_commands:
            return argument
        current = self.current_line
        if current is None:
            if not dialect.current_line_listed:
                raise BasicError("Syntax error", SYNTAX_ERROR)
            current = 0
        return _PERIOD.sub(str(current), argument)

    def _dialect(self):
        from yaseer.basic.dialects.dialect import get_dialect

        return get_dialect(self.dialect)

    def _every_area(self, argument: str) -> bool:
        """Is ``argument`` the ALL of NEW ALL / LIST ALL (a word of the dialect: casio)?"""
        return argument.strip().upper() == "ALL" and "ALL" in self._dialect().own_words

    def command_new(self, argument: str) -> None:
        """NEW: erase the current area's program (and the variables if it is PROG 0); NEW ALL
        (casio, NEW.md item 6): every area's program and all variables."""
        self._refuse_password()  # NEW.md item 4
        if self._every_area(argument):
            for area in list(self.programs):
                self.programs[area] = {}
            self.protected_areas.clear()
            self._can_continue = False
            self.engine.reset()
            return
        if argument:
            raise BasicError("Syntax error", SYNTAX_ERROR)
        self.programs[self.area] = {}
        self.protected_areas.discard(self.area)
        self._can_continue = False
        if self.area == 0:
            self.engine.reset()

    def command_prog(self, argument: str) -> None:
        """PROG n: edit program area n from now on."""
        if not argument.isdigit() or int(argument) not in AREAS:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.area = int(argument)
        if not self.program and self.area in LIBRARY_AREAS:
            self.write(f"PROG {self.area}: library program (Python); typed lines replace it\n")

    def command_load(self, argument: str) -> None:
        """LOAD "file": replace the current area's program with the file's."""
        name = file_name_argument(argument)
        self._read_program(self.area, name)
        self._can_continue = False

    def _read_program(self, area: int, name: str) -> None:
        """LOAD's and RUN "file"'s reading: area ``area`` holds file ``name``'s program (the
        lines before a line without a number, whose error is raised after them)."""
        self.programs[area], protected, stopped, typed = read_program_file(name, self.directory, self._dialect())
        self._mark_protected(area, protected)
        self._show_entry_messages(self.programs[area])
        if typed and self.programs[area] and self._dialect().current_line_listed:
            self.current_line = next(reversed(self.programs[area]))  # entered as typed: GW's DOT
        if stopped is not None:
            raise stopped

    def _mark_protected(self, area: int, protected: bool) -> None:
        if protected:
            self.protected_areas.add(area)
        else:
            self.protected_areas.discard(area)

    def command_save(self, argument: str) -> None:
        """SAVE "file"[,A|,P]: write the current area's program, in the session's directory
        only; a name without an extension gets ``.bas`` (GW-BASIC adds ``.BAS``).  The file
        is the one a program's SAVE writes (program_crunch.saved_program): gw's tokens, ``,A``
        the listing, ``,P`` (a letter the dialect's SAVE takes) GW-BASIC's protected form;
        casio's listing."""
        from yaseer.basic.compile.compiler import NO_WORDS
        from yaseer.basic.machine.sandbox import Sandbox

        name, option = file_and_option(argument)
        words = self._dialect().words or NO_WORDS
        if option and option not in words.command_options.get("SAVE", ""):
            raise BasicError("Syntax error", SYNTAX_ERROR)
        if option != "P":
            self._refuse_protected()
        self._refuse_password()  # SAVE_SAVE_ALL.md item 6: yaseer's files are ASCII
        if not Path(name).suffix:
            name += ".bas"
        from yaseer.basic.machine.program_crunch import saved_program

        dialect = self._dialect()
        codes = dialect.charset.codes  # the session keeps lines as typed: the file holds the machine's codes
        data = saved_program({n: codes(t) for n, t in self.program.items()}, option, dialect)
        sandbox = Sandbox(self.directory)
        name = sandbox.dos_name(name)  # DOS ignores case: SAVE "x" writes over X.BAS, not beside it
        check_not_open = getattr(self.engine, "check_not_open", None)
        if check_not_open is not None:  # a program STOPped with the file open (GIODSK.ASM CHKFOP)
            check_not_open(name)
        sandbox.write_bytes(name, data)

    def command_run(self, argument: str) -> None:
        """RUN [line] or RUN "file": fresh variables, then run PROG 0 from its start (or ``line``).

        ``RUN "file"`` loads the file into PROG 0 first (whatever area is being edited).
        """
        if argument.startswith('"'):
            self._can_continue = False
            self._read_program(0, file_name_argument(argument))
            argument = ""
        if argument and not argument.isdigit():
            raise BasicError("Syntax error", SYNTAX_ERROR)
        start = int(argument) if argument else None
        if start is not None and start not in self.programs[0]:
            raise BasicError("Undefined line number", UNDEFINED_LINE)
        self._can_continue = False
        self._tell_protected()
        self._execute(lambda: self.engine.run(self.programs, start), in_program=True)

    def command_cont(self, argument: str) -> None:
        """CONT: go on after STOP, END-less break or Ctrl-C."""
        if argument or not self._can_continue:
            raise BasicError("Can't continue", CANT_CONTINUE)
        self._execute(self.engine.cont, in_program=True)

    def command_files(self, argument: str) -> None:
        """FILES ["pattern"]: the files of the directory LOAD and SAVE use (default ``*.bas``)."""
        from yaseer.basic.machine.sandbox import Sandbox

        pattern = file_name_argument(argument) if argument else "*.bas"
        for name in Sandbox(self.directory).listing(pattern):
            self.write(name + "\n")

    def command_help(self, argument: str) -> None:
        """HELP: the commands, one line each."""
        self.write(HELP_TEXT)

    def command_system(self, argument: str) -> None:
        """SYSTEM: leave the session."""
        self.finished = True

    command_bye = command_system

    def _tell_protected(self) -> None:
        """Let the engine's machine know whether PROG 0 is protected (its LIST, SAVE ... refuse it)."""
        if hasattr(self.engine, "protected"):
            self.engine.protected = 0 in self.protected_areas

    def direct(self, statement: str) -> None:
        """Run one direct-mode statement against the current variables."""
        self._tell_protected()
        self._execute(lambda: self.engine.direct(statement, self.programs), in_program=False)

    def _execute(self, action: Callable[[], object], in_program: bool) -> None:
        """Run ``action`` and show its error, if any.

        A program (RUN, CONT) that ends by STOP or Ctrl-C (a ``Break`` error
        placed at a line) may be continued; one that ends otherwise may not.
        A direct statement leaves that as it was.
        """
        keeps_dot = self._dialect().current_line_listed and hasattr(self.engine, "current_line")
        if keeps_dot:  # GW's DOT: the program's LIST ., EDIT . ... read it, its LIST and errors set it
            self.engine.current_line = self.current_line or 0
        try:
            action()
        except BasicError as error:
            self._take_back_programs()
            if keeps_dot:
                self.current_line = self.engine.current_line
            if in_program:
                self._can_continue = error.code == BREAK and error.line is not None
            if error.line is not None:
                self.current_line = error.line
            self.write(f"{error}\n")
            if error.code == SYNTAX_ERROR and error.area == self.area and error.line in self.program:
                self.edit_text = self.listed(error.line)  # GW-BASIC offers the line for editing
            return
        self._take_back_programs()
        if keeps_dot:
            self.current_line = self.engine.current_line
        last = getattr(self.engine, "last_line", None)
        if in_program and last is not None and not self._dialect().current_line_listed:
            self.current_line = last  # casio: the line last run (GW's DOT stays: no error)
        if in_program:
            self._can_continue = False
        self._take_auto()
        self._take_edit()

    def _taken(self, request: str):
        """The engine's ``request`` (the machine's ``auto_request`` or ``edit_request``), once;
        None if none (or an engine without a machine's requests)."""
        take = getattr(self.engine, "take_request", None)
        return take(request) if take is not None else None

    def _take_edit(self) -> None:
        """EDIT run by the program (casio, EDIT.md item 1): the edit mode showed the program from
        its line, and the session puts that line up for editing, as the typed EDIT does."""
        number = self._taken("edit_request")
        if number is not None and number in self.program:
            self.current_line = number
            self.edit_text = self.listed(number)

    def _take_auto(self) -> None:
        """AUTO run by the program or the direct line: the session numbers the lines typed
        next (the step left out after a comma: the one AUTO used last)."""
        request = self._taken("auto_request")
        if request is not None:
            start, step = request
            self._auto_step = self._auto_step if step is None else step
            if hasattr(self.engine, "auto_step"):
                self.engine.auto_step = self._auto_step
            self.auto = (start, self._auto_step)

    def _take_back_programs(self) -> None:
        """The areas a program changed (its LOAD, NEW, DELETE, RENUM, LOAD ALL) become the
        session's: LIST then shows what the machine holds."""
        changed = getattr(self.engine, "changed_programs", None)
        if changed is None:
            return
        for area, lines in changed().items():
            self.programs[area] = dict(lines)
            self._can_continue = False
            if area == 0:  # a program's LOAD of a protected file protects what it loaded
                self._mark_protected(0, bool(getattr(self.engine, "protected", False)))


# --- the BASIC machine, as the session and the animation use it ---------------------


def create_machine(screen, printer, methods: dict[int, str] | None = None, install=None,
                   angle: str | None = None, dialect: str = "casio", files=None):
    """A BASIC machine writing PRINT to ``screen`` and LPRINT to ``printer``, library bound.

    ``install(machine, methods)`` binds the library programs (default
    ``yaseer.binding.install``; the animation passes a recording one);
    ``angle`` ("deg" or "rad") is the unit of SIN, COS, TAN and ATN at start
    (default: the dialect's); ``dialect`` is "casio" or "gw" (see
    ``yaseer.basic.dialects.dialect``): the library is bound only in a dialect with program areas;
    ``files`` the directory of the program's files (default: the current one).
    """
    from yaseer import binding
    from yaseer.basic.machine.machine import Machine

    machine = Machine(screen=screen, printer=printer, angle=angle, dialect=dialect, files=files)
    if machine.dialect.program_areas:
        (install or binding.install)(machine, methods)
    return machine


class FoldedScreen:
    """A screen ``width`` columns wide in front of a ``write`` callable (``--width``).

    Text that reaches the right edge goes on at the start of the next row, one
    character at a time, as on a pocket computer's display (the FX-850P shows 32
    columns): a character written when the row is full first starts a new row.
    Everything shown goes through it: program output, listings, messages.
    ``column`` is the column (0-based) the next character goes to; the terminal
    front end calls :meth:`line_typed` when the user ends a line with Enter.
    """

    def __init__(self, write: Callable[[str], object], width: int) -> None:
        from yaseer.basic.machine.screen import OutputStream

        self._screen = OutputStream(_Screen(write), width)  # the machine's screen folding, at ``width``

    @property
    def column(self) -> int:
        return self._screen.column

    def __call__(self, text: str) -> None:
        self._screen.write(text)

    def line_typed(self) -> None:
        """The user typed a line and Enter: the cursor is at the start of a row."""
        self._screen.column = 0


class _Screen:
    """A text stream that forwards to a ``write`` callable."""

    def __init__(self, write: Callable[[str], object]) -> None:
        self._write = write

    def write(self, text: str) -> int:
        self._write(text)
        return len(text)

    def flush(self) -> None:
        """Output is forwarded at once."""

    def isatty(self) -> bool:
        """Not a terminal as far as the machine is concerned."""
        return False


class MachineEngine:
    """The session's view of the BASIC machine: run typed areas, continue, direct mode.

    PRINT shows on the session's screen, LPRINT on ``printer`` (default: the
    screen too).  STOP comes back as a ``Break`` BasicError placed at the STOP's
    line (as MS-BASIC shows it), so does Ctrl-C (the machine places it); CONT
    resumes after either.  ``clear_screen`` is called for CLS (None: CLS does
    nothing, e.g. on a pipe).  TRON stays on across RUN; NEW turns it off.
    """

    def __init__(self, write: Callable[[str], object], dialect: str = "casio",
                 printer: Callable[[str], object] | None = None,
                 clear_screen: Callable[[], object] | None = None, files=None) -> None:
        self._screen = _Screen(write)
        self._files = files  # the directory of the programs' files (None: the current one)
        self._dialect = dialect
        self._printer = _Screen(printer) if printer is not None else self._screen
        self._clear_screen = clear_screen
        self._machine = None  # made on first use: the prompt comes up without waiting for it
        self.protected = False  # PROG 0 came from a file SAVEd with ,P (the session says so)
        self.current_line = 0  # gw: GW's DOT, handed to the machine for each run and taken back
        # casio: the password PASS registered; it outlives RUN's fresh machine and NEW ALL,
        # as the machine keeps it until PASS cancels it (PASS.md)
        self.password: str | None = None
        self.typed_line = "RUN"  # the line last typed (the session sets it): the machine's input buffer
        self.auto_step = 0  # gw: the step AUTO used last, handed to each machine (GWMAIN.ASM AUTINC)

    @property
    def machine(self):
        """The machine holding the variables (created when first needed)."""
        if self._machine is None:
            self._machine = create_machine(self._screen, self._printer, dialect=self._dialect, files=self._files)
            self._machine.on_clear_screen = self._clear_screen
            self._machine.resumable_breaks = True  # Ctrl-C, then CONT goes on exactly
            self._machine.boxed_screens = True  # a program that draws shows the LCD in its frame
        return self._machine

    def reset(self) -> None:
        """Fresh variables and areas (NEW)."""
        self._machine = None

    def check_not_open(self, name: str) -> None:
        """``File already open`` when the machine's files (a program STOPped leaves them
        open; END and RUN close them) include one called ``name``, as the program's SAVE
        checks (machine/files.py FileTable.check_not_open)."""
        if self._machine is not None:
            self._machine.files.check_not_open(name)

    def program_edited(self) -> None:
        """A program line was typed, replaced or deleted: where the dialect says so
        (``edit_clears``: GW), the machine clears what RUN clears before it runs."""
        if self._machine is not None and self._machine.dialect.edit_clears:
            self._machine.reset()

    def run(self, areas: dict[int, Program], start: int | None) -> None:
        """RUN: a fresh machine with the typed areas' programs, from ``start`` or the top."""
        tracing = self._machine is not None and self._machine.tracing
        self.reset()
        self.machine.set_trace(tracing)
        self.sync(areas)
        self.machine.type_line(self.typed_line)
        self._finish(self._guard(lambda: self.machine.run(start)))

    def cont(self) -> None:
        """CONT: go on from the last STOP."""
        self.machine.type_line(self.typed_line)
        self._finish(self._guard(self.machine.cont))

    def direct(self, statement: str, areas: dict[int, Program]) -> None:
        """Execute one direct-mode statement (a GOTO in it runs the typed program)."""
        self.sync(areas)
        self.machine.type_line(self.typed_line)
        self._finish(self._guard(lambda: self.machine.execute_direct(statement)), direct=True)

    def sync(self, areas: dict[int, Program]) -> None:
        """Give the machine every typed area whose program it does not have yet, and
        whether PROG 0 is protected (``protected``).

        Unchanged areas are left alone, so a STOPped program stays resumable.
        An area emptied by NEW gets its library program back (if it has one).
        """
        machine = self.machine
        machine.program_protected = self.protected
        machine.password_set = self.password
        machine.auto_step = self.auto_step
        for area, program in areas.items():
            held = machine.programs.get(area)
            if program and held != {n: text.strip() for n, text in program.items()}:
                machine.load(program_text(program), area=area, entered=False)  # shown when typed
            elif not program and held is not None and area in LIBRARY_AREAS:
                from yaseer import binding

                binding.install(machine)
        self._given = {area: dict(lines) for area, lines in machine.programs.items()}

    def take_request(self, request: str):
        """The machine's ``request``, once (None if none): ``auto_request``, the AUTO a program
        or direct line ran (start, step or None); ``edit_request``, the line a program's EDIT
        put up for editing."""
        if self._machine is None:
            return None
        value = getattr(self._machine, request)
        setattr(self._machine, request, None)
        return value

    def changed_programs(self) -> dict[int, Program]:
        """The areas whose lines the machine changed since the session gave them (a
        program's LOAD, NEW, ...): area -> its lines now (empty when it has none)."""
        if self._machine is None:
            return {}
        held = self._machine.programs
        self.protected = self._machine.program_protected
        given = getattr(self, "_given", {})
        changed = {area: dict(held.get(area, {})) for area in set(held) | set(given)
                   if held.get(area, {}) != given.get(area, {})}
        self._given = {area: dict(lines) for area, lines in held.items()}
        return changed

    @property
    def last_line(self) -> int | None:
        """The line the machine ran last (None before any run)."""
        return None if self._machine is None else self._machine.line

    def _finish(self, outcome: str, direct: bool = False) -> None:
        if outcome == "stop":
            line = self.machine.line
            if direct and not line and 0 not in (self.machine.programs.get(0) or {}):
                line = None  # a STOP typed without a line number: a plain "Break", as GW-BASIC prints it
            raise BasicError("Break", BREAK, line=line)

    def _guard(self, action: Callable[[], str]) -> str:
        """Run ``action``; a line left open (``PRINT 1;``, TRON's ``[30]``) is ended
        before the prompt or the error message, as MS-BASIC does."""
        self.machine.current_line = self.current_line
        try:
            return action()
        except KeyboardInterrupt:  # between the machine's own checks
            raise BasicError("Break", BREAK) from None
        except BasicError as err:
            if self._machine is not None:
                self._machine.note_untrapped(err)
            raise
        finally:
            if self._machine is not None:
                self._machine.end_line()
                self.password = self._machine.password_set
                self.current_line = self._machine.current_line
