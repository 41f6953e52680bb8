"""``yaseer run FILE``: run a BASIC listing the way the pocket computer did.

Errors are one line on standard error (``Division by zero in 20 (PROG 5)``)
and exit status 1; never a Python traceback.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path


def _area_file(text: str) -> tuple[int, str]:
    number, _, path = text.partition("=")
    if not number.strip().isdigit() or not path:
        raise argparse.ArgumentTypeError(f"expected N=FILE, got {text!r}")
    return int(number), path


def _method(text: str) -> tuple[int, str]:
    number, _, name = text.partition("=")
    if not number.strip().isdigit() or not name:
        raise argparse.ArgumentTypeError(f"expected N=NAME, got {text!r}")
    return int(number), name


def add_dialect_argument(parser: argparse.ArgumentParser) -> None:
    """``--dialect casio|gw`` (shared by ``run`` and the interactive session)."""
    parser.add_argument("--dialect", choices=("casio", "gw"), default="casio",
                        help="casio: the paper's pocket computer (default); gw: GW-BASIC 3.23")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", help="the BASIC listing (area 0)")
    parser.add_argument("--format", choices=("text", "csv"), default="text",
                        help="text: the faithful output; csv: one row of full-precision values per PRINT")
    parser.add_argument("--printer", metavar="FILE", help="write LPRINT output to FILE (default: standard output)")
    parser.add_argument("--prog", metavar="N=FILE", type=_area_file, action="append", default=[],
                        help="load a BASIC file into program area N (shares the variables)")
    add_dialect_argument(parser)
    parser.add_argument("--angle", choices=("deg", "rad"), default=None,
                        help="unit of SIN COS TAN ATN at start (default: the dialect's: casio deg, gw rad)")
    parser.add_argument("--input", metavar="FILE", help="read INPUT lines from FILE instead of standard input")
    parser.add_argument("--method", metavar="N=NAME", type=_method, action="append", default=[],
                        help="the method library program N uses (passed to yaseer.binding.install)")


def main(args: argparse.Namespace) -> int:
    """Run through :func:`yaseer.run`, streaming the output; the one error line and the exit status."""
    from yaseer.api import run
    from yaseer.progress import output_progress

    try:
        printer = open(args.printer, "w", encoding="utf-8") if args.printer else None
    except OSError as exc:
        print(f"yaseer run: {exc.filename}: {exc.strerror}", file=sys.stderr)
        return 1
    try:
        # A line counter on stderr for a long run whose output goes to a file or pipe.
        with output_progress(sys.stdout) as screen:
            result = run(args.file, method=dict(args.method), prog=dict(args.prog),
                         input=Path(args.input) if args.input else sys.stdin, angle=args.angle,
                         dialect=args.dialect, screen=screen, printer=printer, output_format=args.format, keep=False)
    except BrokenPipeError:  # the reader went away (e.g. `| head`): stop quietly
        import os
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    finally:
        if printer is not None:
            printer.close()
    if result.error is not None:
        print(result.error, file=sys.stderr)
        return 1
    if result.status == "stop":
        print(f"Break in {result.line}", file=sys.stderr)
    return 0
