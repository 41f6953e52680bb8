"""``yaseer plot FILE [--out DIR]``: run a listing and plot its printed columns.

The listing runs through :func:`yaseer.run` as ``yaseer run`` runs it (same ``--prog``
and ``--method`` options), its rows kept at full precision; each printed column is then drawn
against the first (the crank angle), one panel per quantity, as the paper's Figs. 7, 9,
10, 12 and 14 do.  Writes ``<stem>.png`` and ``<stem>.svg`` into DIR.
"""

from __future__ import annotations

import sys
from pathlib import Path

from yaseer.commands.run import _area_file, _method


def add_arguments(parser) -> None:
    parser.add_argument("file", help="BASIC listing to run")
    parser.add_argument("--out", default=".", help="directory for the PNG and SVG (default: current)")
    parser.add_argument("--prog", action="append", default=[], metavar="N=FILE", type=_area_file,
                        help="load a BASIC program area from FILE (as for `yaseer run`)")
    parser.add_argument("--method", action="append", default=[], metavar="N=NAME", type=_method,
                        help="method for library program N (as for `yaseer run`)")


def main(args) -> int:
    """Run through :func:`yaseer.run`, draw :meth:`Result.plot`, save PNG and SVG."""
    from yaseer import plotting
    from yaseer.api import run

    listing = Path(args.file)
    result = run(listing, method=dict(args.method), prog=dict(args.prog))
    if result.error is not None:
        print(result.error, file=sys.stderr)
        return 1
    try:
        figure = result.plot()
    except ValueError:
        print(f"{listing}: printed no table of at least two rows and two columns to plot", file=sys.stderr)
        return 1
    try:
        paths = plotting.save_figure(figure, Path(args.out), listing.stem)
    except OSError as exc:
        print(f"Cannot write the plot into {args.out}: {exc.strerror or exc}", file=sys.stderr)
        return 1
    for path in paths:
        print(path)
    return 0
