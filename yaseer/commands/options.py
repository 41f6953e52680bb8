"""The options shared by every command that runs a listing: ``run``, ``diff``, ``plot``, ``animate``, ``report``.

:func:`add_run_options` adds them to a sub-command's parser (one place, so the
commands cannot drift apart); :func:`run_settings` turns the parsed options into
the plain values a run needs (area texts read and checked, methods checked,
the INPUT file opened, :meth:`RunSettings.run_arguments` for :func:`yaseer.run`).
A new run option (``--files``) is added here once and every command takes it.

A wrong option value (``--prog 12=x.bas``, ``--method 5=fast``) is a usage error
(exit status 2, the sub-command's usage line); an area file that cannot be read,
is empty or has no ``RETURN`` is an error naming the file (exit status 1).
"""

from __future__ import annotations

import argparse
import re
TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up, issue 15)
    from typing import TextIO

AREAS = range(1, 10)  # --prog N: areas 1-9 (area 0 is the listing itself)


class CommandError(Exception):
    """An error the user can fix: one line on stderr, exit status 1 (see ``yaseer.cli``)."""


class UsageError(CommandError):
    """Options that do not go together (found after parsing): one line on stderr, exit status 2."""


def area_file(text: str) -> tuple[int, str]:
    """``"5=prog5.bas"`` -> ``(5, "prog5.bas")``; areas 1-9 only."""
    number, _, path = text.partition("=")
    if not number.strip().isdigit() or not path:
        raise argparse.ArgumentTypeError(f"expected N=FILE, got {text!r}")
    area = int(number)
    if area == 0:
        raise argparse.ArgumentTypeError(f"area 0 is the listing itself; --prog takes areas 1-9, got {text!r}")
    if area not in AREAS:
        raise argparse.ArgumentTypeError(f"program areas are 1-9, got {text!r}")
    return area, path


def method_pair(text: str) -> tuple[int, str]:
    """``"5=paper"`` -> ``(5, "paper")``, checked against the method registry."""
    number, _, name = text.partition("=")
    if not number.strip().isdigit() or not name.strip():
        raise argparse.ArgumentTypeError(f"expected N=NAME, got {text!r}")
    area, name = int(number), name.strip()
    known = method_choices()
    if area not in known:
        raise argparse.ArgumentTypeError(
            f"no library program {area} to choose a method for (programs: {', '.join(map(str, known))})")
    if name not in known[area]:
        raise argparse.ArgumentTypeError(f"unknown method {name!r} for PROG {area} (known: {', '.join(known[area])})")
    return area, name


def method_choices() -> dict[int, list[str]]:
    """Program number -> its method names, the default first (from ``yaseer.linkages.registry``)."""
    from yaseer.binding import LINKAGES
    from yaseer.linkages.registry import default_method, method_names

    choices = {}
    for number, linkage in LINKAGES.items():
        names = method_names(linkage)
        default = default_method(linkage)
        choices[number] = [default] + [n for n in names if n != default]
    return choices


class _MethodAction(argparse._AppendAction):
    """``--method N=NAME`` whose help lists every program's methods, computed only when help is shown.

    (Building the list imports the numerics; a plain ``yaseer run`` must not.)
    """

    @property
    def help(self) -> str:
        listed = "; ".join(f"{n}: {', '.join(names)}" for n, names in method_choices().items())
        return ("the method library program N uses, the first named being the default "
                f"({listed}); may be repeated")

    @help.setter
    def help(self, value) -> None:
        """The help is computed (see the class docstring)."""


def add_dialect_argument(parser) -> None:
    """``--dialect casio|gw`` (a run option, and the interactive session's)."""
    parser.add_argument("--dialect", choices=("casio", "gw"), default="casio",
                        help="casio: the paper's pocket computer (default); gw: GW-BASIC 3.23")


def add_run_options(parser: argparse.ArgumentParser) -> None:
    """--prog N=FILE, --method N=NAME, --dialect, --angle deg|rad, --input FILE (as ``yaseer run``)."""
    group = parser.add_argument_group("running the listing (the same in run, diff, plot, animate and report)")
    group.add_argument("--prog", metavar="N=FILE", type=area_file, action="append", default=[],
                       help="load a BASIC subroutine into program area N (1-9) instead of the library program; "
                            "it shares the listing's variables and must end in RETURN; may be repeated")
    group.add_argument("--method", metavar="N=NAME", type=method_pair, action=_MethodAction, default=[])
    add_dialect_argument(group)
    group.add_argument("--angle", choices=("deg", "rad"), default=None,
                       help="unit of SIN COS TAN ATN at the start (default: the dialect's: casio deg, gw rad)")
    group.add_argument("--arith", choices=("binary", "decimal"), default="binary",
                       help="casio's arithmetic: binary (IEEE doubles, default) or decimal (13 digits inside, "
                            "as the FX-850P family's BCD)")
    group.add_argument("--input", metavar="FILE",
                       help="answer INPUT statements with the lines of FILE (default: standard input)")
    group.add_argument("--files", metavar="DIR", default=None,
                       help="the one directory the program's OPEN, KILL, NAME and FILES use "
                            "(default: the current directory; nothing outside it is ever touched)")


class RunSettings:
    """The run options, read and checked: what a machine needs to run the listing.

    (A plain class, not a dataclass: importing dataclasses costs every start several ms.)
    """

    def __init__(self, areas: dict[int, str] | None = None, methods: dict[int, str] | None = None,
                 dialect: object = "casio", angle: str | None = None, input: TextIO | None = None,
                 files: str | None = None) -> None:
        self.areas = areas if areas is not None else {}  # area -> BASIC text (--prog)
        self.methods = methods if methods is not None else {}  # program -> method name (--method)
        self.dialect = dialect  # a dialect name, or a Dialect (--arith decimal)
        self.angle = angle  # None: the dialect's
        self.input = input  # the --input file, opened (None: standard input)
        self.files = files  # --files DIR: the directory of the program's files (None: the current one)

    def run_arguments(self) -> dict:
        """The keyword arguments of :func:`yaseer.run` these options give (INPUT from the keyboard without --input)."""
        import sys

        return {"method": self.methods, "prog": self.areas, "dialect": self.dialect, "angle": self.angle,
                "input": self.input if self.input is not None else sys.stdin, "files": self.files}

    def close(self) -> None:
        if self.input is not None:
            self.input.close()


def run_settings(args: argparse.Namespace) -> RunSettings:
    """The parsed run options of ``args`` (see :func:`add_run_options`): area files read and checked,
    the --input file opened (close it with :meth:`RunSettings.close`); OSError naming a file that cannot be read."""
    areas = {n: read_area(n, path) for n, path in args.prog}
    dialect = args.dialect
    if getattr(args, "arith", "binary") != "binary":
        from yaseer.basic.dialect import get_dialect

        try:
            dialect = get_dialect(dialect).with_arithmetic(args.arith)
        except ValueError as error:
            import sys

            print(f"yaseer: {error}", file=sys.stderr)
            raise SystemExit(2) from None
    return RunSettings(areas=areas, methods=dict(args.method), dialect=dialect, angle=args.angle,
                       input=open(args.input, encoding="utf-8", errors="replace") if args.input else None,
                       files=_files_directory(args.files))


_STRINGS = re.compile(r'"[^"]*("|$)')


def read_area(number: int, path: str) -> str:
    """The text of ``--prog N=path``; :class:`CommandError` if it holds no lines or no RETURN."""
    from yaseer.basic.errors import BasicError
    from yaseer.basic.scanner import split_lines

    text = read_text(path)
    try:
        lines = [statement for _, statement, _ in split_lines(text) if statement]
    except BasicError as error:
        raise CommandError(f"--prog {number}={path}: {error}") from None
    if not lines:
        raise CommandError(f"--prog {number}={path}: the file holds no numbered program lines")
    if not any("RETURN" in _STRINGS.sub("", line).upper() for line in lines):
        raise CommandError(f"--prog {number}={path}: no RETURN, so GOSUB PROG {number} could never come back")
    return text


def _files_directory(path: str | None) -> str | None:
    """``--files DIR``: DIR must be an existing directory (CommandError otherwise)."""
    import os

    if path is not None and not os.path.isdir(path):
        raise CommandError(f"--files {path}: no such directory")
    return path


def read_text(path: str) -> str:
    """A listing's text (``-`` is standard input); undecodable bytes become U+FFFD."""
    import sys

    if path == "-":
        return sys.stdin.buffer.read().decode("utf-8", errors="replace")
    with open(path, encoding="utf-8", errors="replace") as handle:
        return handle.read()
