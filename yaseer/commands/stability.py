"""``yaseer stability``: every method swept towards the configurations where methods fail.

Prints the table (sweep x method: worst error, NaN, exceptions, wrong branches,
silent wrong numbers, what happened at the singular configuration) and writes
``stability.csv``, ``stability_points.csv``, ``stability_table.md`` and the chart ``stability.png`` /
``stability.svg`` to ``--out`` (default ``stability-out``).  See docs/stability.md.
"""

from __future__ import annotations


def add_arguments(parser) -> None:
    parser.epilog = "Exit status: 0 done, 1 an error (one line on standard error), 2 a wrong command line, 130 Ctrl-C."
    parser.add_argument("--out", default="stability-out", metavar="DIR",
                        help="directory for the CSV files, stability_table.md and the chart (created; "
                             "default: stability-out in the current directory)")
    parser.add_argument("--no-chart", action="store_true", help="write the CSV files only")


def main(args) -> int:
    from yaseer.commands.output import output_directory
    from yaseer.evaluation import stability
    from yaseer.whole_files import staged

    out = output_directory(args.out)
    points = stability.sweep_points()
    summary = stability.summarise(points)
    print(stability.format_table(summary))
    with staged() as place:  # the tables and the charts appear together, or none of them (Ctrl-C)
        written = stability.write_all(out, points, summary, place)
        if not args.no_chart:
            written += stability.draw_chart(points, out / "stability", place)
    for path in written:
        print(f"wrote {path}")
    return 0
