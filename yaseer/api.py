"""``yaseer.run``: run a BASIC listing from Python and get its screen, rows, error and frames.

    >>> import yaseer
    >>> result = yaseer.run("listings/example1.bas", method={5: "paper"})
    >>> result.text          # the screen, as printed
    >>> result.rows          # the printed rows: a 2-D array (names: result.rows.names)
    >>> result.error         # None, or the one error line ("Division by zero in 20")
    >>> result.frames        # the mechanism's positions, one frame per printed line
    >>> result.plot()        # a matplotlib Figure of the printed columns
    >>> result.animate()     # a matplotlib animation of the mechanism

This is the one way a listing runs: ``yaseer run``, ``plot``, ``animate``, ``report``
and the Jupyter magic all call :func:`run`.  Importing this module imports neither
numpy nor matplotlib; ``rows``, ``plot()`` and ``animate()`` import them when used.
"""

from __future__ import annotations

import os
import sys
from yaseer.patterns import Pattern

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from typing import IO, Mapping, Union

    Listing = Union[str, bytes, "os.PathLike[str]"]

_LINE_NUMBER = Pattern(r"\s*\d")


class _Output:
    """The machine's output stream: forwards to ``stream`` (if any), keeps the text, reports lines.

    ``on_line(text)`` is called with every completed line (the animation's frames
    close on printed lines).
    """

    def __init__(self, stream: IO[str] | None, keep: bool, on_line=None) -> None:
        self._stream = stream
        self._parts: list[str] | None = [] if keep else None
        self._on_line = on_line
        self._partial = ""

    def write(self, text: str) -> int:
        if self._stream is not None:
            self._stream.write(text)
        if self._parts is not None:
            self._parts.append(text)
        if self._on_line is not None:
            self._partial += text
            while "\n" in self._partial:
                line, self._partial = self._partial.split("\n", 1)
                self._on_line(line)
        return len(text)

    def close_line(self) -> None:
        """Report a last line that has no newline."""
        if self._on_line is not None and self._partial:
            self._on_line(self._partial)
            self._partial = ""

    def flush(self) -> None:
        if self._stream is not None:
            self._stream.flush()

    def isatty(self) -> bool:
        return bool(self._stream is not None and self._stream.isatty())

    @property
    def text(self) -> str:
        return "".join(self._parts or ())


class Result:
    """What one run of a listing gave.

    ``text``: the screen as printed (PRINT, and LPRINT unless a printer stream
    was given).  ``error``: the one BASIC error line that stopped the run, or
    None.  ``status``: ``"end"``, ``"stop"`` (STOP), or ``"error"`` (``Break``
    after Ctrl-C is an error line too).  ``frames``: the recorded positions of
    the mechanism, one :class:`yaseer.animation.Frame` per printed line after a
    library call.  ``screens``: for a program that drew on the display (LOCATE, CLS),
    the display's shown rows (one text of a line each) every time it waited for a key
    and when it ended, as the output shows them.  ``name``: the listing's file stem (None for program text).
    ``protected``: the listing came from a file SAVEd with ,P; the program may not LIST, LLIST
    or SAVE itself but with ,P (GIODSK.ASM PROCHK), as in GW-BASIC.  ``listing``: the program
    as LIST shows it (a tokenised file's lines listed back); "" for a protected program, which
    GW-BASIC never lists.

    Compared and shown by its fields as a dataclass would be, but a plain class:
    importing dataclasses costs every start several milliseconds.
    """

    _SHOWN = ("listing", "name", "text", "error", "status", "line", "exception", "frames")

    def __init__(self, listing: str, name: str | None = None, text: str = "", error: str | None = None,
                 status: str = "end", line: int | None = None, exception: Exception | None = None,
                 frames: list | None = None, lines: list | None = None, _rows: object = None,
                 screens: list | None = None, glyphs: list | None = None, protected: bool = False) -> None:
        self.listing = listing
        self.name = name
        self.protected = protected
        self.text = text
        self.error = error
        self.status = status
        self.line = line  # the BASIC line the run stopped in (STOP, an error), else None
        self.exception = exception
        self.frames = frames if frames is not None else []
        self.lines = lines if lines is not None else []  # values printed per line (yaseer.table)
        self._rows = _rows
        self.screens = screens if screens is not None else []  # the LCD's screens shown (console.py)
        # for each screen, the DEFCHR$ characters then defined: code -> its dots (10 hex digits)
        self.glyphs = glyphs if glyphs is not None else []

    def __repr__(self) -> str:
        return f"Result({', '.join(f'{name}={getattr(self, name)!r}' for name in self._SHOWN)})"

    def __eq__(self, other) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        return vars(self) == vars(other)

    __hash__ = None  # mutable

    @property
    def rows(self):
        """The printed rows: a 2-D float array (``.names``: the header's column names or None),
        or a list of such arrays when the rows have several shapes."""
        if self._rows is None:
            from yaseer.table import as_arrays

            self._rows = as_arrays(self.row_groups())
        return self._rows

    @property
    def columns(self) -> tuple[str, ...] | None:
        """The column names of the main table (the shape with most rows), or None."""
        group = self._main_group()
        return group.names if group is not None else None

    @property
    def title(self) -> str:
        """The paper's title for its examples, else the listing's first REM, else its name."""
        from yaseer.describe import listing_title

        return listing_title(self.listing, self.name)

    def row_groups(self):
        """The printed rows by shape (:class:`yaseer.table.RowGroup`), each with its column names.

        The last PRINT's expressions can name only the main table (the shape with most
        rows), as the plot's panels are named."""
        from yaseer.describe import column_names
        from yaseer.table import group_rows

        groups = group_rows(self.lines)
        main = max(groups, key=lambda g: len(g.rows)) if groups else None
        for group in groups:
            group.names = column_names(self.name, group.width, group.names, self.listing if group is main else "")
        return groups

    def _main_group(self):
        groups = self.row_groups()
        return max(groups, key=lambda g: len(g.rows)) if groups else None

    def plot(self, subtitle: str = ""):
        """A matplotlib Figure: each printed column against the first (see :mod:`yaseer.series`).

        The main table's rows, rows continuing them (a second branch) as a second
        series, and any other kind of row in panels of its own; ``subtitle`` goes
        under the title (the command names the methods chosen there).
        """
        from yaseer import plotting
        from yaseer.series import plot_tables

        tables = plot_tables(self.lines)
        main = tables[0] if tables else None
        if main is None or main.width < 2 or sum(len(s.rows) for s in main.series) < 2:
            raise ValueError("the listing printed no table of at least two rows and two columns to plot")
        spec = plotting.spec_for(self.name, self.listing, main.width, self.title, main.names)
        return plotting.draw_tables(tables, spec, subtitle)

    def look(self, size: tuple[int, int] | None = None, title: str | None = None):
        """How this run's frames look (:class:`yaseer.animation.Look`): title, column names, unit, size.

        The columns are named as in :attr:`columns` (as ``rows.names`` and the plot name them).
        """
        from yaseer.animation.draw import DEFAULT_SIZE, Look
        from yaseer.describe import joint_letters, length_unit

        names = self.columns
        return Look(title=self.title if title is None else title, names=names,
                    unit=length_unit(self.name), size=size or DEFAULT_SIZE, letters=joint_letters(self.name))

    def animate(self, size: tuple[int, int] | None = None, fps: float = 6.0, max_frames: int | None = None):
        """A matplotlib ``FuncAnimation`` of the mechanism, ``size`` pixels (default 1280 x 720)."""
        from yaseer.animation import MAX_FRAMES, player

        return player(self.frames, self.look(size), fps=fps, max_frames=max_frames or MAX_FRAMES)

    def _repr_pretty_(self, printer, cycle) -> None:  # IPython shows the screen, then the error
        printer.text(self.text + (self.error + "\n" if self.error else ""))


def run(listing: Listing, *, dialect: str | None = None, method: Mapping[int, str] | None = None,
        prog: Mapping[int, Listing] | None = None, input=None, angle: str | None = None,
        raise_errors: bool = False, screen: IO[str] | None = None, printer: IO[str] | None = None,
        output_format: str = "text", keep: bool = True, files=None, finer: int = 1, typed: str = "RUN") -> Result:
    """Run ``listing`` (a path, the program text, or a program file's bytes) once on a fresh machine.

    ``method``: the method of library program n (``{2: "newton"}``); ``prog``:
    program area n loaded from a path or text (``{5: "programs/prog5.bas"}``);
    ``input``: what INPUT reads (text, a path-like, or an open file, each
    echoed on the screen; ``sys.stdin``: typed at the keyboard; default nothing:
    ``Input past end``); ``angle``: ``"deg"`` or ``"rad"``, the unit of
    SIN COS TAN ATN at start (default: the dialect's); ``dialect``: ``"casio"``
    (the default, the paper's pocket computer) or ``"gw"`` (GW-BASIC 3.23);
    ``files``: the one directory OPEN, KILL, NAME and FILES use (default: the current one).
    ``typed``: the line typed at the prompt that started the program (casio: PEEK reads it
    from the input buffer, ``Dialect.words.input_buffer``; default ``"RUN"``).
    ``finer``: run every ``FOR ... STEP s`` loop with the step s/finer, so the listing itself
    computes that many times as many positions (:mod:`yaseer.finer`; for smoother animations).
    A BASIC error (and a missing file) is ``result.error``,
    one line; with ``raise_errors`` it is raised.  An argument the command line
    would refuse (area 0 or 10, an area without RETURN, an unknown dialect,
    angle, method or output format, ``files`` that is no directory) raises
    :class:`yaseer.run_arguments.ArgumentError` (a ValueError), one line.

    For the command line: ``screen`` / ``printer`` also receive PRINT / LPRINT
    output as it is printed (a printer takes LPRINT off the screen and out of
    ``text``), ``output_format="csv"`` prints full-precision rows, and
    ``keep=False`` keeps neither text, rows nor frames (a long streamed run).
    """
    from yaseer import run_arguments as check
    from yaseer.basic.errors import BasicError

    dialect, angle = check.dialect_choice(dialect), check.angle_choice(angle)
    output_format, files = check.output_format_choice(output_format), check.files_directory(files)
    typed = check.typed_line(typed)
    methods = dict(check.method_choice(n, name) for n, name in (method or {}).items())
    numbers = {check.area_number(n): text for n, text in (prog or {}).items()}
    result = Result(listing="")
    opened: list[IO[str]] = []
    try:
        from yaseer.basic.dialects.dialect import get_dialect

        program, result.listing, result.name, result.protected, entered = _source(listing, get_dialect(dialect).charset)
        if finer != 1:
            from yaseer.finer import finer_steps

            program = finer_steps(program, finer)
            result.listing = "" if result.protected else program
        areas = {n: _area_text(n, _source(text, get_dialect(dialect).charset)[0]) for n, text in numbers.items()}
        input_stream = _input_stream(input, opened)
    except BasicError as error:
        return _failed(result, error, raise_errors)
    execute(result, areas, methods, input_stream, angle, dialect, screen, printer, output_format, keep, files,
            program, entered, typed)
    for handle in opened:
        handle.close()
    if result.exception is not None and raise_errors:
        raise result.exception
    return result


def execute(result: Result, areas: dict, methods: dict, input_stream, angle: str | None, dialect: str,
            screen, printer, output_format: str, keep: bool, files=None, program: str | None = None,
            entered: bool = True, typed: str = "RUN") -> None:
    """Load, bind and run ``program`` (default ``result.listing``; ``entered``: its lines are
    read as typed ones, not a tokenised file's: Machine.load) as ``typed`` starts it (the line
    typed, in the machine's input buffer); fill in ``result`` (text, rows, frames, error, status)."""
    from yaseer import collection_pause
    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.machine import Machine

    recorder = None
    if keep:  # the animation package (and its drawing code) only when frames are kept: start-up
        from yaseer.animation import Recorder

        recorder = Recorder()
    on_line = recorder.line_printed if recorder is not None else None
    out = _Output(screen, keep, on_line)
    paper = _Output(printer, False, on_line) if printer is not None else None
    from yaseer.basic.dialects.dialect import get_dialect

    library = get_dialect(dialect).program_areas  # the library programs are bound in casio only
    # gw has no program areas (PROG is no word) unless areas are given (--prog)
    chosen = get_dialect(dialect).with_program_areas() if areas else dialect
    machine = Machine(screen=out, printer=paper, output_format=output_format, angle=angle,
                      input_stream=input_stream, dialect=chosen, files=files)
    if keep:
        machine.area_hooks.append(recorder.hook)
        machine.line_hooks.append(lambda device, values: result.lines.append(values))
    try:
        machine.load(result.listing if program is None else program, entered=entered)
        machine.program_protected = result.protected
        if library:
            from yaseer import binding  # the library's methods (casio): a gw start imports none of them

            binding.install(machine, methods or None)
        for number, text in areas.items():
            machine.set_area(number, text)
        machine.type_line(typed)
        try:
            if collection_pause.paused():  # a `yaseer run` process: compiled with the collector still off
                machine.compile_areas()
        finally:  # (on a compile's error too)
            collection_pause.resume()  # a `yaseer run` process: the start is over (a no-op in any other caller)
        result.status = machine.run()
        if result.status == "stop":
            result.line = machine.line
            machine.end_line()  # Break in N starts on a new row, as after an error
    except BasicError as error:
        machine.end_line()
        result.status, result.error, result.exception = "error", str(error), _detached(error)
        result.line = error.line
    finally:
        machine.flush()
        for stream in (out, paper):
            if stream is not None:
                stream.close_line()
    result.text = out.text
    result.screens = machine.screens
    result.glyphs = machine.screen_glyphs
    if recorder is not None:
        result.frames = recorder.finish()


def _area_text(number: int, text: str) -> str:
    """Program area ``number``'s text, refused (ArgumentError naming the area) as ``--prog`` refuses it."""
    from yaseer.run_arguments import ArgumentError, area_text

    try:
        return area_text(number, text)
    except ArgumentError as error:
        raise ArgumentError(f"prog {number}: {error}") from None


def _detached(error: BaseException) -> BaseException:
    """``error`` without its traceback and the exception it replaced: their frames hold the
    machine, which a result kept for its error line must not keep alive."""
    error.__traceback__ = error.__context__ = error.__cause__ = None
    return error


def _failed(result: Result, error, raise_errors: bool) -> Result:
    if raise_errors:
        raise error
    result.status, result.error, result.exception = "error", str(error), error
    return result


def _source(listing: Listing, charset=None) -> tuple[str, str, str | None, bool, bool]:
    """(program text, its listing, file stem or None, protected, entered): a path-like, or a one-line
    str that is no BASIC line, is a file; bytes are a file's contents.  A file is read as LOAD
    reads it (program_file.program_text: ASCII, tokenised or protected; as the ``charset``
    shows it, yaseer/basic/dialects/charset.py); ``protected``: it was SAVEd with ,P.  The
    listing is the program as LIST shows it (see :class:`Result`); ``entered``: the lines are
    read as typed ones (program text, an ASCII file), not a tokenised file's (GW-BASIC's line
    entry prints their messages and keeps each number in DOT)."""
    from yaseer.basic.errors import DEVICE_IO_ERROR, FILE_NOT_FOUND, BasicError

    if isinstance(listing, str) and not os.path.isfile(listing) \
            and ("\n" in listing or not listing.strip() or _LINE_NUMBER.match(listing)):
        return listing, listing, None, False, True
    if isinstance(listing, bytes):
        return _file_text(listing, charset, None)
    if not isinstance(listing, (str, os.PathLike)):
        raise TypeError(f"a listing is a path, the program text or a file's bytes, not {type(listing).__name__}")
    try:
        with open(listing, "rb") as binary:
            data = binary.read()
    except FileNotFoundError:
        raise BasicError(f"File not found: {_shown(listing)}", FILE_NOT_FOUND) from None
    except OSError as error:
        raise BasicError(f"Cannot read {_shown(listing)}: {error.strerror or error}", DEVICE_IO_ERROR) from None
    return _file_text(data, charset, _stem(listing))


def _file_text(data: bytes, charset, name: str | None) -> tuple[str, str, str | None, bool, bool]:
    """:func:`_source`'s answer for a program file's bytes (the listing's lines end in LF, as
    text mode reads them; the program keeps the file's line ends for the dialect's LOAD to
    read, scanner.program_lines): the program keeps a tokenised file's double constants whole, the listing shows
    their digits; a protected program has no listing (GIODSK.ASM PROCHK: GW-BASIC's LIST of it
    is Illegal function call)."""
    from yaseer.basic.machine.program_file import is_protected, program_text

    def lines(text: str) -> str:
        return text.replace("\r\n", "\n").replace("\r", "\n")

    protected = is_protected(data)
    program = program_text(data, charset)  # its line ends as the dialect's LOAD reads them (a LF inside a gw line)
    listing = "" if protected else lines(program_text(data, charset, exact=False))
    return program, listing, name, protected, data[:1] not in (b"\xfe", b"\xff")


def _stem(path) -> str:
    """The file name of ``path`` without its last suffix, as ``pathlib.PurePath.stem`` gives it
    (``x.bas`` -> ``x``, ``.bas`` and ``x.`` stay whole), without importing pathlib at start-up."""
    name = os.path.basename(os.fspath(path))
    dot = name.rfind(".")
    return name[:dot] if 0 < dot < len(name) - 1 else name


def _shown(path) -> str:
    """``path`` as an error names it (normalised as ``pathlib.Path`` shows it: ``./x.bas`` is ``x.bas``)."""
    from pathlib import Path

    return str(Path(path))


def _input_stream(source, opened: list):
    """What INPUT reads: an open stream as given; text or a path-like opened here (and noted)."""
    import io

    from yaseer.basic.errors import FILE_NOT_FOUND, BasicError

    if source is None:
        return io.StringIO("")
    if source is sys.stdin:
        return None  # the machine reads the keyboard itself (and does not echo what was typed)
    if hasattr(source, "readline"):
        return source
    if isinstance(source, os.PathLike):
        try:
            handle = open(source, encoding="utf-8")
        except OSError as error:
            raise BasicError(f"Cannot read {source}: {error.strerror or error}", FILE_NOT_FOUND) from None
        opened.append(handle)
        return handle
    if isinstance(source, str):
        return io.StringIO(source if source.endswith("\n") or not source else source + "\n")
    raise TypeError(f"input is text, a path or an open file, not {type(source).__name__}")
