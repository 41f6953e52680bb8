"""The ``yaseer`` command line: a thin dispatcher over ``yaseer.commands.*``.

Each sub-command lives in its own module (``yaseer/commands/<name>.py``) with
``add_arguments(parser)`` and ``main(args) -> int``; modules are imported only
when their command runs, so start-up stays small.
"""

from __future__ import annotations

import argparse
import importlib
import sys

COMMANDS = {
    "run": "run a BASIC listing",
    "plot": "run a listing and plot its printed columns",
    "bench": "time against accuracy, for every method and way of running",
    "stability": "sweep each method across the places where methods fail",
    "diff": "run a listing and diff its rows against a paper's table",
    "centrode": "the change-point four-bar's space centrode (seed 004)",
    "animate": "animate the mechanism of a listing",
}


def _load(name: str):
    return importlib.import_module(f"yaseer.commands.{name}")


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else argv
    parser = argparse.ArgumentParser(prog="yaseer", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    available = {}
    for name, help_text in COMMANDS.items():
        try:
            module = _load(name)
        except ModuleNotFoundError as exc:
            if exc.name != f"yaseer.commands.{name}":
                raise
            continue
        available[name] = module
        module.add_arguments(sub.add_parser(name, help=help_text, description=help_text))
    interactive = "interactive" in _interactive_available()
    if interactive:  # options before any command are the interactive session's (--dialect)
        _load("interactive").add_arguments(parser)
    if not argv and interactive:
        return _load("interactive").main(None)
    args = parser.parse_args(argv)
    if args.command is None and interactive:
        return _load("interactive").main(args)
    if args.command is None:
        parser.print_help()
        return 2
    return available[args.command].main(args)


def _interactive_available() -> set[str]:
    try:
        _load("interactive")
    except ModuleNotFoundError:
        return set()
    return {"interactive"}
