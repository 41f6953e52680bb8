"""``yaseer run FILE``: run a BASIC listing the way the pocket computer did.

Errors are one line on standard error (``Division by zero in 20 (PROG 5)``)
and exit status 1; never a Python traceback.  ``STOP`` ends with ``Break in N``
(status 0), Ctrl-C with ``Break in N`` (status 130).
"""

from __future__ import annotations

import sys

from yaseer.commands.options import RUN_OPTIONS, Option, run_settings

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only
    from argparse import ArgumentParser, Namespace

EPILOG = """\
FILE - reads the listing from standard input (INPUT then needs --input).
Output: PRINT goes to standard output, LPRINT too unless --printer FILE is given.
A run writes nothing else but the files the program opens for output (inside
--files DIR only) and the cache of compiled programs and of the library programs'
recorded paths: ~/.cache/yaseer/compiled
($XDG_CACHE_HOME/yaseer/compiled; YASEER_CACHE_DIR=DIR to move it, YASEER_CACHE_DIR=
to switch it off), private, kept near 64 MiB, each entry checked by a hash.
Exit status: 0 (also after STOP, which prints Break in N on standard error), 1 a
BASIC error or an unreadable file (one line on standard error), 2 a wrong command
line, 130 Ctrl-C (Break in N)."""


ARGUMENTS = (
    (None, (
        Option("file", "the BASIC listing (program area 0); - for standard input"),
        Option("--format", "text (default): the faithful output; csv: one row of full-precision values per printed line",
               choices=("text", "csv"), default="text"),
        Option("--printer", "write LPRINT output to FILE (replaced; default: standard output)", metavar="FILE"),
    )),
    RUN_OPTIONS,
)
"""The command's arguments (see :mod:`yaseer.commands.options`): a plain ``yaseer run FILE [options]``
is read from this table without argparse, which builds the parser for help and errors from the same table."""


def add_arguments(parser: ArgumentParser) -> None:
    from yaseer.commands.parsers import add_groups

    parser.epilog = EPILOG
    add_groups(parser, ARGUMENTS)


def main(args: Namespace) -> int:
    """Run through :func:`yaseer.run`, streaming the output; the one error line and the exit status."""
    from yaseer.api import run
    from yaseer.commands.output import open_for_writing
    from yaseer.progress import output_progress

    # standard input's bytes are a program file's: the API reads them as LOAD does (and keeps ,P)
    listing = sys.stdin.buffer.read() if args.file == "-" else args.file
    settings = run_settings(args)
    printer = None
    try:
        printer = open_for_writing(args.printer) if args.printer else None
        # A line counter on stderr for a long run whose output goes to a file or pipe.
        with output_progress(sys.stdout) as screen:
            result = run(listing, **settings.run_arguments(), screen=screen, printer=printer,
                         output_format=args.format, keep=False)
    finally:
        settings.close()
        if printer is not None:
            printer.close()
    return report(result)


def report(result) -> int:
    """Print a finished run's one error line (or STOP's ``Break in N``); its exit status.

    0 after END or STOP, 130 after Ctrl-C (``Break in N``), 1 after any other error.
    """
    from yaseer.basic.errors import BREAK

    if result.error is not None:
        print(result.error, file=sys.stderr)
        return 130 if getattr(result.exception, "code", None) == BREAK else 1
    if result.status == "stop":
        print(f"Break in {result.line}", file=sys.stderr)
    return 0


def raise_if_interrupted(error) -> None:
    """Ctrl-C during the run (the BASIC error ``Break``) stops a command that is not ``run``
    as Ctrl-C anywhere else does: nothing written, one line, status 130 (see ``yaseer.cli``)."""
    from yaseer.basic.errors import BREAK

    if getattr(error, "code", None) == BREAK:
        raise KeyboardInterrupt
