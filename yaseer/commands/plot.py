"""``yaseer plot FILE [--out DIR]``: run a listing and plot its printed columns.

The listing runs through the BASIC machine exactly as ``yaseer run FILE --format csv``
runs it (same ``--prog`` and ``--method`` options); each printed column is then drawn
against the first (the crank angle), one panel per quantity, as the paper's Figs. 7, 9,
10, 12 and 14 do.  Writes ``<stem>.png`` and ``<stem>.svg`` into DIR.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path


def add_arguments(parser) -> None:
    parser.add_argument("file", help="BASIC listing to run")
    parser.add_argument("--out", default=".", help="directory for the PNG and SVG (default: current)")
    parser.add_argument("--prog", action="append", default=[], metavar="N=FILE",
                        help="load a BASIC program area from FILE (as for `yaseer run`)")
    parser.add_argument("--method", action="append", default=[], metavar="N=NAME",
                        help="method for library program N (as for `yaseer run`)")


def run_listing_csv(listing: str, prog: list[str], method: list[str]) -> subprocess.CompletedProcess:
    """Run ``yaseer run LISTING --format csv`` in a child process; return its result."""
    command = [sys.executable, "-m", "yaseer", "run", listing, "--format", "csv"]
    for pair in prog:
        command += ["--prog", pair]
    for pair in method:
        command += ["--method", pair]
    return subprocess.run(command, capture_output=True, text=True, check=False)


def main(args) -> int:
    from yaseer import plotting

    listing = Path(args.file)
    if not listing.is_file():
        print(f"File not found: {listing}", file=sys.stderr)
        return 1
    result = run_listing_csv(str(listing), args.prog, args.method)
    if result.returncode != 0:
        sys.stderr.write(result.stderr)
        return result.returncode
    rows = plotting.numeric_rows(result.stdout)
    if len(rows) < 2 or len(rows[0]) < 2:
        print(f"{listing}: printed no table of at least two rows and two columns to plot", file=sys.stderr)
        return 1
    spec = plotting.figure_spec(listing, len(rows[0]))
    figure = plotting.build_figure(rows, spec)
    try:
        paths = plotting.save_figure(figure, Path(args.out), listing.stem)
    except OSError as exc:
        print(f"Cannot write the plot into {args.out}: {exc.strerror or exc}", file=sys.stderr)
        return 1
    for path in paths:
        print(path)
    return 0
