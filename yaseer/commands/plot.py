"""``yaseer plot FILE [--out DIR]``: run a listing and plot its printed columns.

The listing runs through :func:`yaseer.run` as ``yaseer run`` runs it (the same run
options: ``--prog``, ``--method``, ``--dialect``, ``--angle``, ``--input``), its rows
kept at full precision; each printed column is then drawn against the first (the
crank angle), one panel per quantity, as the paper's Figs. 7, 9, 10, 12 and 14 do.
Rows of other kinds are separate series (:mod:`yaseer.series`: a second branch
printed under the first, a labelled row in panels of its own); a line breaks where
the crank angle jumps a gap or starts again.  Panels are labelled by the paper's
meanings for its examples, else the listing's printed header, else its PRINT
expressions; the title names the ``--method``/``--prog`` variant drawn.
Writes ``<stem>.png`` and ``<stem>.svg`` into DIR.
"""

from __future__ import annotations

from pathlib import Path


def add_arguments(parser) -> None:
    from yaseer.commands.parsers import add_run_options

    parser.epilog = ("Exit status: 0 drawn, 1 an error (one line on standard error: the listing's BASIC error, "
                     "or what is wrong), 2 a wrong command line, 130 Ctrl-C.")
    parser.add_argument("file", help="BASIC listing to run")
    parser.add_argument("--out", default=".", metavar="DIR",
                        help="directory for <stem>.png and <stem>.svg (created; default: the current directory)")
    add_run_options(parser)


def main(args) -> int:
    """Run through :func:`yaseer.run`, draw :meth:`Result.plot`, save PNG and SVG."""
    from yaseer import plotting
    from yaseer.api import run
    from yaseer.commands.options import CommandError, run_settings
    from yaseer.commands.output import output_directory
    from yaseer.commands.run import raise_if_interrupted, report

    listing = Path(args.file)
    settings = run_settings(args)
    try:
        result = run(listing, **settings.run_arguments())
    finally:
        settings.close()
    raise_if_interrupted(result.exception)
    if result.error is not None:
        return report(result)
    try:
        figure = result.plot(subtitle=variant(args))
    except ValueError:
        raise CommandError(f"{listing}: printed no table of at least two rows and two columns to plot") from None
    paths = plotting.save_figure(figure, output_directory(args.out), listing.stem)
    for path in paths:
        print(path)
    return 0


def variant(args) -> str:
    """The run options that change what is drawn (``--method 2=newton, --prog 5=prog5.bas``), for the title."""
    chosen = [f"--method {n}={name}" for n, name in args.method]
    chosen += [f"--prog {n}={Path(path).name}" for n, path in args.prog]
    chosen += [f"--{option} {getattr(args, option)}" for option in ("dialect", "angle")
               if getattr(args, option) not in (None, "casio")]
    return ", ".join(chosen)
