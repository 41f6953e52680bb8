"""The ``yaseer`` command line: a thin dispatcher over ``yaseer.commands.*``.

Each sub-command lives in its own module (``yaseer/commands/<name>.py``) with
``add_arguments(parser)`` and ``main(args) -> int``.  Only the module of the
command being run is imported (the others' sub-parsers are left empty, their
one-line help is kept here), so start-up stays small.  A command whose module
describes its arguments as a table (``ARGUMENTS``, see
:mod:`yaseer.commands.options`: ``run``) has its plain command lines read from
that table without importing argparse; argparse, built from the same table,
reads everything else and prints the help, usage and errors.

Exit statuses, the same in every command: 0 success, 1 an error (one line on
standard error, never a traceback), 2 a usage error (the sub-command's usage
line first), 130 after Ctrl-C.  A reader that goes away (``yaseer run x | head``)
stops the command quietly with status 0.
"""

from __future__ import annotations

import os
import sys

from yaseer import collection_pause
from yaseer.version import __version__

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: argparse is imported only when a command line needs it
    from argparse import ArgumentParser

COMMANDS = {
    "run": "run a BASIC listing and print what it prints",
    "diff": "run a listing and set its rows beside a table typed from a paper",
    "plot": "run a listing and draw each printed column against the first",
    "animate": "run a listing and animate its mechanism (GIF, MP4, HTML or one PNG frame)",
    "bench": "time against accuracy for every method and way of running",
    "stability": "sweep each method towards the places where methods fail",
    "centrode": "the change-point four-bar's space centrode (seed 004)",
    "report": "run a listing and write a one-page HTML handout (listing, output, plots, animation, errata)",
}

DESCRIPTION = """\
yaseer emulates the 1980s pocket computer on which the Al-Yaseer mechanism-analysis
package ran: BASIC listings calling the library programs with GOSUB PROG 1, 2, 3 and 5
(slider-crank, four-bar, inverted slider-crank, virtual link).

Type `yaseer` alone to open the interactive pocket-computer session (numbered lines,
LIST, RUN, CONT, EDIT, SAVE, LOAD, PROG n; HELP lists its commands); `yaseer --dialect gw`
opens it as GW-BASIC."""

EPILOG = """\
`yaseer COMMAND --help` describes a command and its options.
Exit status: 0 success, 1 an error (one line on standard error), 2 a wrong command
line, 130 interrupted by Ctrl-C."""


def _load(name: str):
    module = f"yaseer.commands.{name}"
    __import__(module)  # not importlib.import_module: importing importlib costs start-up
    return sys.modules[module]


def build_parser(command: str | None = None) -> tuple[ArgumentParser, ArgumentParser | None]:
    """The whole ``yaseer`` parser and ``command``'s sub-parser, the only one given its arguments
    (its module imported).  A command line that names a command needs only :func:`command_parser`."""
    import argparse

    parser = argparse.ArgumentParser(prog="yaseer", description=DESCRIPTION, epilog=EPILOG,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--version", action="version", version=f"yaseer {__version__}")
    _load("interactive").add_arguments(parser)  # options before any command are the session's (--dialect)
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", title="commands")
    chosen = None
    for name, help_text in COMMANDS.items():
        command_parser = sub.add_parser(name, help=help_text, description=help_text,
                                        formatter_class=argparse.RawDescriptionHelpFormatter)
        if name == command:
            _load(name).add_arguments(command_parser)
            chosen = command_parser
    return parser, chosen


def command_parser(command: str) -> ArgumentParser:
    """``command``'s parser alone: the sub-parser :func:`build_parser` makes for it (the same
    prog, description and arguments), without the main parser and the other commands' empty
    sub-parsers (every ``yaseer run`` would build them for nothing: start-up time)."""
    import argparse

    parser = argparse.ArgumentParser(prog=f"yaseer {command}", description=COMMANDS[command],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    _load(command).add_arguments(parser)
    return parser


def main(argv: list[str] | None = None) -> int:
    """Parse ``argv`` (default ``sys.argv[1:]``), run the command; the exit status.

    Called without ``argv`` (the ``yaseer`` program itself), a run stopped by
    Ctrl-C ends the process at once with status 130: an interrupt that landed in
    the middle of an import can leave a half-made module that makes the
    interpreter's own shutdown end the process by SIGINT instead.
    """
    if argv is None:
        try:
            status = main(sys.argv[1:])
        finally:  # on again whatever ended the command (a run stopped before its program started)
            collection_pause.resume()
        if status == 130:
            for stream in (sys.stdout, sys.stderr):
                try:
                    stream.flush()
                except (AttributeError, OSError, ValueError):
                    pass
            os._exit(130)
        return status
    argv = _command_first(list(argv))
    command = argv[0] if argv and argv[0] in COMMANDS else None
    if command != "run":  # the collector paused at start (yaseer.entry) is on again, except while
        collection_pause.resume()  # `run` starts: it is switched on just before the program runs (api.execute)
    if sys.stdout is None:  # started with standard output closed (`yaseer run x >&-`)
        if sys.stderr is not None:
            print("yaseer: standard output is closed", file=sys.stderr)
        return 1
    if not argv:
        return guarded("session", lambda: _load("interactive").main(None))
    return guarded(command or "session", lambda: _dispatch(argv, command))


SESSION_VALUE_OPTIONS = ("--dialect", "--printer", "--width")  # the options before a command, each with a value


def _command_first(argv: list[str]) -> list[str]:
    """``argv`` with a command written after the session's options (``--dialect gw run x.bas``,
    the order the usage line shows) moved first, those options handed to the command: the
    command's own parser then takes them or names the one it has not got."""
    index, options = 0, []
    while index < len(argv) and argv[index].split("=", 1)[0] in SESSION_VALUE_OPTIONS:
        if "=" in argv[index]:
            options.append(argv[index])
            index += 1
        else:  # joined, so a command without this option names it and its value as one unknown
            options.append("=".join(argv[index:index + 2]))
            index += 2
    if options and index < len(argv) and argv[index] in COMMANDS:
        return [argv[index], *options, *argv[index + 1:]]
    return argv


def _dispatch(argv: list[str], command: str | None) -> int:
    """Parse ``argv`` (only ``command``'s module imported) and run it; a usage error is status 2."""
    try:
        if command is None:  # the session's options (--dialect gw), --help, --version, or not a command
            args = build_parser()[0].parse_args(argv)
            return _load("interactive").main(args)
        args = scan_command_line(command, argv[1:])
        if args is None:  # the command's parser alone, so a wrong option prints that command's usage
            args = command_parser(command).parse_args(argv[1:])
    except SystemExit as exit_:  # --help, --version (0) or a usage error (2, usage already printed)
        return exit_.code if isinstance(exit_.code, int) else 2
    args.command = command
    return _load(command).main(args)


def scan_command_line(command: str, argv: list[str]):
    """``argv`` read from the table of ``command``'s arguments without argparse (the namespace
    argparse would make), or None: the command has no table, or ``argv`` is not a plain command
    line (see :func:`yaseer.commands.options.scan`)."""
    table = getattr(_load(command), "ARGUMENTS", None)
    if table is None:
        return None
    from yaseer.commands.options import scan

    return scan(argv, table)


def guarded(command: str, call) -> int:
    """``call()``'s status, with every escaping error made one line on stderr and its status.

    The one place that turns :class:`~yaseer.commands.options.CommandError` and
    ``OSError`` into status 1 (a ``UsageError`` into 2), Ctrl-C into 130 and a
    closed pipe into a quiet 0.
    """
    try:
        return _guarded(command, call)
    except KeyboardInterrupt:  # also while the command's first modules are being imported
        _report(f"yaseer {command}: interrupted (Ctrl-C)")
        return 130


def _guarded(command: str, call) -> int:
    from yaseer.commands.options import CommandError, UsageError
    from yaseer.commands.output import NamedStream

    stdout = sys.stdout
    sys.stdout = NamedStream(stdout, "standard output")
    try:
        status = call()
        sys.stdout.flush()
        return status
    except BrokenPipeError:  # the reader went away (`| head`): stop quietly
        _silence(stdout)
        return 0
    except CommandError as error:
        _report(f"yaseer {command}: {error}")
        return 2 if isinstance(error, UsageError) else 1
    except OSError as error:
        _report(f"yaseer {command}: {describe(error)}")
        if getattr(error, "filename", None) == "standard output":
            _silence(stdout)
        return 1
    finally:
        sys.stdout = stdout


def describe(error: OSError) -> str:
    """``OSError`` as ``FILE: reason`` (the file it names, then the system's words)."""
    reason = error.strerror or str(error)
    if error.filename is not None and error.filename2 is not None:
        return f"{error.filename} -> {error.filename2}: {reason}"
    return f"{error.filename}: {reason}" if error.filename is not None else reason


def _report(line: str) -> None:
    if sys.stderr is not None:
        try:
            print(line, file=sys.stderr, flush=True)
        except OSError:
            pass


def _silence(stream) -> None:
    """Point ``stream``'s descriptor at /dev/null so the interpreter's last flush cannot fail."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), stream.fileno())
    except (OSError, ValueError, AttributeError):
        pass
