"""``yaseer run FILE``: run a BASIC listing the way the pocket computer did.

Errors are one line on standard error (``Division by zero in 20 (PROG 5)``)
and exit status 1; never a Python traceback.
"""

from __future__ import annotations

import argparse
import sys


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


def _read(path: str) -> str:
    with open(path, encoding="utf-8", errors="replace") as handle:
        return handle.read()


def main(args: argparse.Namespace) -> int:
    from yaseer.basic.machine import Machine
    from yaseer.progress import output_progress

    printer = input_stream = None
    try:
        source = _read(args.file)
        areas = {n: _read(path) for n, path in args.prog}
        if args.printer:
            printer = open(args.printer, "w", encoding="utf-8")
        if args.input:
            input_stream = open(args.input, encoding="utf-8")
    except OSError as exc:
        print(f"yaseer run: {exc.filename}: {exc.strerror}", file=sys.stderr)
        return 1
    # A line counter on stderr for a long run whose output goes to a file or pipe.
    with output_progress(sys.stdout) as screen:
        return _run(Machine(screen=screen, printer=printer, output_format=args.format,
                            angle=args.angle, input_stream=input_stream, dialect=args.dialect),
                    source, areas, args, printer, input_stream)


def _run(machine, source: str, areas: dict[int, str], args: argparse.Namespace, printer, input_stream) -> int:
    """Load, bind and run; the one error line and exit status."""
    from yaseer import binding
    from yaseer.basic.errors import BasicError

    try:
        machine.load(source)
        binding.install(machine, dict(args.method) or None)
        for n, text in areas.items():
            machine.set_area(n, text)
        outcome = machine.run()
    except BasicError as err:
        machine.end_line()
        machine.flush()
        print(str(err), file=sys.stderr)
        return 1
    except BrokenPipeError:  # the reader went away (e.g. `| head`): stop quietly
        import os
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except KeyboardInterrupt:
        machine.flush()
        print(f"Break in {machine.line}" if machine.line is not None else "Break", file=sys.stderr)
        return 1
    finally:
        for handle in (printer, input_stream):
            if handle is not None:
                handle.close()
    if outcome == "stop":
        print(f"Break in {machine.line}", file=sys.stderr)
    return 0
