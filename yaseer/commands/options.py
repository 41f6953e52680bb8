"""Command-line options as data, and the options shared by every command that runs a listing.

An :class:`Option` is one argument (``--dialect``, or the positional ``file``)
with everything a parser needs: its flag, help, metavar, value conversion,
choices, default, and whether it may be repeated.  A command lists its options
in a table: (title, options) groups in the order of its help (title ``None``:
argparse's default groups).  From that one table

* :func:`yaseer.commands.parsers.add_groups` builds the command's argparse parser
  (its help, usage and every error message), and
* :func:`scan` reads a plain command line without importing argparse at all
  (argparse with gettext, locale and shutil costs every ``yaseer run`` several
  milliseconds of start-up).

:func:`scan` accepts only the forms whose meaning is plain: an option's exact
flag with its value as the next word (``--dialect gw``) or after ``=``
(``--dialect=gw``), and each positional once, in any order.  Anything else
(``--help``, an abbreviated flag, ``--``, a value that looks like an option, a
missing or extra positional, a value its conversion or choices refuse) makes it
answer ``None``: the caller then parses with argparse, which reads it, or prints
the usage and error exactly as it always has.  Where :func:`scan` answers, its
namespace is the one argparse makes (pinned in tests/test_startup_imports.py).
A value conversion raises :class:`OptionValueError` with the user's message
(argparse shows it as ``argument --prog: MESSAGE``).

The run options (``run``, ``diff``, ``plot``, ``animate``, ``report``):
:data:`RUN_OPTIONS` describes them once; :func:`yaseer.commands.parsers.add_run_options` adds them to a
sub-command's argparse parser, and ``yaseer run``'s own table includes them, so
the commands cannot drift apart.  :func:`run_settings` turns the parsed options into
the plain values a run needs (area texts read and checked, methods checked,
the INPUT file opened, :meth:`RunSettings.run_arguments` for :func:`yaseer.run`).
A new run option (``--files``) is added here once and every command takes it.
This module does not import argparse (start-up time).

A wrong option value (``--prog 12=x.bas``, ``--method 5=fast``) is a usage error
(exit status 2, the sub-command's usage line); an area file that cannot be read,
is empty or has no ``RETURN`` is an error naming the file (exit status 1).
"""

from __future__ import annotations

from types import SimpleNamespace

from yaseer.run_arguments import ANGLES, DIALECTS

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from argparse import Namespace
    from typing import Callable, Sequence, TextIO


class OptionValueError(ValueError):
    """A value an option's conversion refuses; its text is the whole message (``program areas are 1-9, got '12'``)."""


class Option:
    """One argument of a command: a ``--flag`` taking one value, or a positional (a flag without ``-``).

    ``convert`` turns the text into the value (raising :class:`OptionValueError`);
    ``choices`` the values allowed (after ``convert``); ``default`` the value when
    the option is not given; ``repeated``: every occurrence appended to a list
    (default: an empty list).  ``help`` is the text, or a function returning it
    when it is costly to compute (shown only by ``--help``).
    """

    __slots__ = ("flag", "help", "metavar", "convert", "choices", "default", "repeated")

    def __init__(self, flag: str, help: str | Callable[[], str] | None = None, *, metavar: str | None = None,
                 convert: Callable[[str], object] | None = None, choices: tuple | None = None,
                 default: object = None, repeated: bool = False) -> None:
        self.flag = flag
        self.help = help
        self.metavar = metavar
        self.convert = convert
        self.choices = choices
        self.default = default
        self.repeated = repeated

    @property
    def positional(self) -> bool:
        return not self.flag.startswith("-")

    @property
    def dest(self) -> str:
        """The attribute of the parsed namespace (argparse's rule: the flag without dashes, ``-`` as ``_``)."""
        return self.flag.lstrip("-").replace("-", "_")

    def value(self, text: str) -> object:
        """``text`` converted and checked against the choices (as argparse does); ValueError when refused."""
        value = self.convert(text) if self.convert is not None else text
        if self.choices is not None and value not in self.choices:
            raise ValueError(f"invalid choice: {value!r}")
        return value


def scan(argv: Sequence[str], groups: Sequence[tuple[str | None, Sequence[Option]]]) -> SimpleNamespace | None:
    """The namespace argparse makes of ``argv`` for the options of ``groups`` (a command's table:
    (title, options) pairs), or None when ``argv`` is not a plain command line (see the module
    docstring: argparse then parses it)."""
    options = [option for _, group in groups for option in group]
    flags = {option.flag: option for option in options if not option.positional}
    waiting = iter([option for option in options if option.positional])
    found = {option.dest: [] if option.repeated else option.default for option in options}
    words = iter(argv)
    for word in words:
        if _is_flag(word):
            flag, equals, text = word.partition("=")
            option = flags.get(flag)
            if option is None:
                return None
            if not equals:
                text = next(words, None)
                if text is None or _is_flag(text):
                    return None
        else:
            option, text = next(waiting, None), word
            if option is None:
                return None
        try:
            value = option.value(text)
        except (TypeError, ValueError):  # argparse reports it
            return None
        if option.repeated:
            found[option.dest].append(value)
        else:
            found[option.dest] = value
    if next(waiting, None) is not None:
        return None
    return SimpleNamespace(**found)


def _is_flag(word: str) -> bool:
    """Whether argparse might read ``word`` as an option (``-`` alone is standard input, a positional)."""
    return word.startswith("-") and word != "-"


class CommandError(Exception):
    """An error the user can fix: one line on stderr, exit status 1 (see ``yaseer.cli``)."""


class UsageError(CommandError):
    """Options that do not go together (found after parsing): one line on stderr, exit status 2."""


def area_file(text: str) -> tuple[int, str]:
    """``"5=prog5.bas"`` -> ``(5, "prog5.bas")``; areas 1-9 only (:func:`yaseer.run_arguments.area_number`)."""
    from yaseer.run_arguments import area_number

    number, _, path = text.partition("=")
    if not number.strip().isdigit() or not path:
        raise OptionValueError(f"expected N=FILE, got {text!r}")
    try:
        return area_number(int(number), text), path
    except ValueError as error:
        raise OptionValueError(str(error)) from None


def method_pair(text: str) -> tuple[int, str]:
    """``"5=paper"`` -> ``(5, "paper")``, checked against the method registry
    (:func:`yaseer.run_arguments.method_choice`)."""
    from yaseer.run_arguments import method_choice

    number, _, name = text.partition("=")
    if not number.strip().isdigit() or not name.strip():
        raise OptionValueError(f"expected N=NAME, got {text!r}")
    try:
        return method_choice(int(number), name)
    except ValueError as error:
        raise OptionValueError(str(error)) from None


def method_help() -> str:
    """``--method``'s help, listing every program's methods (computed only when help is shown:
    building the list imports the numerics, and a plain ``yaseer run`` must not)."""
    from yaseer.run_arguments import method_choices

    listed = "; ".join(f"{n}: {', '.join(names)}" for n, names in method_choices().items())
    return f"the method library program N uses, the first named being the default ({listed}); may be repeated"


DIALECT = Option("--dialect", "casio: the paper's pocket computer (default); gw: GW-BASIC 3.23",
                 choices=DIALECTS, default="casio")
"""``--dialect casio|gw`` (a run option, and the interactive session's)."""

RUN_OPTIONS = ("running the listing (the same in run, diff, plot, animate and report)", (
    Option("--prog", "load a BASIC subroutine into program area N (1-9) instead of the library program; "
                     "it shares the listing's variables and must end in RETURN; may be repeated",
           metavar="N=FILE", convert=area_file, repeated=True),
    Option("--method", method_help, metavar="N=NAME", convert=method_pair, repeated=True),
    DIALECT,
    Option("--angle", "unit of SIN COS TAN ATN at the start (default: the dialect's: casio deg, gw rad)",
           choices=ANGLES),
    Option("--arith", "casio's arithmetic: binary (IEEE doubles, default) or decimal (12 digits inside, "
                      "as the FX-850P family's BCD)", choices=("binary", "decimal"), default="binary"),
    Option("--input", "answer INPUT statements with the lines of FILE (default: standard input)", metavar="FILE"),
    Option("--files", "the one directory the program's OPEN, KILL, NAME and FILES use "
                      "(default: the current directory; nothing outside it is ever touched)", metavar="DIR"),
    Option("--typed", "casio: the line typed at the prompt that started the program (default RUN), which "
                      "PEEK reads from the input buffer at address 512 (the library's PBLOAD/PBGET program "
                      "reads its command there)", metavar="LINE", default="RUN"),
))
"""--prog N=FILE, --method N=NAME, --dialect, --angle deg|rad, --arith, --input FILE, --files DIR, --typed LINE:
one titled group of a command's table."""


class RunSettings:
    """The run options, read and checked: what a machine needs to run the listing.

    (A plain class, not a dataclass: importing dataclasses costs every start several ms.)
    """

    def __init__(self, areas: dict[int, str] | None = None, methods: dict[int, str] | None = None,
                 dialect: object = "casio", angle: str | None = None, input: TextIO | None = None,
                 files: str | None = None, typed: str = "RUN") -> None:
        self.areas = areas if areas is not None else {}  # area -> BASIC text (--prog)
        self.methods = methods if methods is not None else {}  # program -> method name (--method)
        self.dialect = dialect  # a dialect name, or a Dialect (--arith decimal)
        self.angle = angle  # None: the dialect's
        self.input = input  # the --input file, opened (None: standard input)
        self.files = files  # --files DIR: the directory of the program's files (None: the current one)
        self.typed = typed  # --typed LINE: the line typed that started the program (the input buffer)

    def run_arguments(self) -> dict:
        """The keyword arguments of :func:`yaseer.run` these options give (INPUT from the keyboard without --input)."""
        import sys

        return {"method": self.methods, "prog": self.areas, "dialect": self.dialect, "angle": self.angle,
                "input": self.input if self.input is not None else sys.stdin, "files": self.files,
                "typed": self.typed}

    def close(self) -> None:
        if self.input is not None:
            self.input.close()


def run_settings(args: Namespace) -> RunSettings:
    """The parsed run options of ``args`` (see :func:`yaseer.commands.parsers.add_run_options`): area files read and checked,
    the --input file opened (close it with :meth:`RunSettings.close`); OSError naming a file that cannot be read."""
    areas = {n: read_area(n, path) for n, path in args.prog}
    dialect = args.dialect
    if getattr(args, "arith", "binary") != "binary":
        from yaseer.basic.dialects.dialect import get_dialect

        try:
            dialect = get_dialect(dialect).with_arithmetic(args.arith)
        except ValueError as error:
            import sys

            print(f"yaseer: {error}", file=sys.stderr)
            raise SystemExit(2) from None
    return RunSettings(areas=areas, methods=dict(args.method), dialect=dialect, angle=args.angle,
                       input=open(args.input, encoding="utf-8", errors="replace") if args.input else None,
                       files=_files_directory(args.files), typed=getattr(args, "typed", "RUN"))


def read_area(number: int, path: str) -> str:
    """The text of ``--prog N=path``; :class:`CommandError` if it holds no lines or no RETURN
    (:func:`yaseer.run_arguments.area_text`, the check the API makes)."""
    from yaseer.run_arguments import area_text

    try:
        return area_text(number, read_text(path))
    except ValueError as error:
        raise CommandError(f"--prog {number}={path}: {error}") from None


def _files_directory(path: str | None) -> str | None:
    """``--files DIR``: DIR must be an existing directory (CommandError otherwise)."""
    from yaseer.run_arguments import files_directory

    try:
        return files_directory(path)
    except ValueError as error:
        raise CommandError(f"--files {error}") from None


def read_text(path: str) -> str:
    """A listing's text (``-`` is standard input), read as a program file
    (yaseer.basic.machine.program_file: ASCII up to a Ctrl-Z, tokenised or protected)."""
    import sys

    from yaseer.basic.machine.program_file import program_text

    if path == "-":
        return program_text(sys.stdin.buffer.read())
    with open(path, "rb") as handle:
        return program_text(handle.read())
