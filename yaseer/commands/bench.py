"""``yaseer bench``: time per position against worst error for every method and way of running.

Writes to ``--out`` (default ``bench-out``): ``bench.csv`` (every case x method x
way), ``bench_summary.csv`` (per method and way), ``bench_newton.csv`` (Newton
over its tolerances), ``bench_laziness.csv``, ``bench_results.md`` (the tables
as markdown) and the chart ``bench.png`` /
``bench.svg``; prints the summary and the laziness table.  See docs/bench.md.
"""

from __future__ import annotations

import sys



def add_arguments(parser) -> None:
    parser.epilog = "Exit status: 0 done, 1 an error (one line on standard error), 2 a wrong command line, 130 Ctrl-C."
    parser.add_argument("--out", default="bench-out", metavar="DIR",
                        help="directory for the CSV files, bench_results.md and the chart (created; "
                             "default: bench-out in the current directory)")
    parser.add_argument("--quick", action="store_true", help="the listings' own coarse grids, one repeat")
    parser.add_argument("--no-listing", action="store_true", help="skip the interpreter way")
    parser.add_argument("--no-chart", action="store_true", help="write the CSV files only")
    parser.add_argument("--case", metavar="TEXT", help="only the cases whose name contains TEXT (e.g. 'seed 001')")


def main(args) -> int:
    from yaseer.commands.options import CommandError
    from yaseer.commands.output import output_directory
    from yaseer.evaluation import benchmark as bench
    from yaseer.whole_files import staged

    out = output_directory(args.out)
    ways = tuple(w for w in bench.WAYS if not (args.no_listing and w.startswith("listing")))
    repeat = 1 if args.quick else 3
    if "listing" in ways and not bench.interpreter_available():
        print("note: the interpreter (yaseer run) is not available; the listing way is skipped", file=sys.stderr)
    rows = bench.bench_rows(quick=args.quick, ways=ways, repeat=repeat, pattern=args.case)
    newton = bench.newton_rows(quick=args.quick, repeat=repeat, pattern=args.case)
    if not rows:
        raise CommandError(f"--case {args.case}: no case matches")
    summary = bench.aggregate(rows)
    newton_curve = bench.newton_summary(newton)
    laziness = bench.laziness_rows(positions=361 if args.quick else 3601, repeat=repeat)
    with staged() as place:  # every table and the chart appear together, or none of them (Ctrl-C)
        bench.write_csv(out / "bench.csv", rows + newton, bench.FIELDS, place)
        bench.write_csv(out / "bench_summary.csv", summary, list(summary[0]), place)
        bench.write_csv(out / "bench_newton.csv", newton_curve, list(newton_curve[0]), place)
        bench.write_csv(out / "bench_laziness.csv", laziness, list(laziness[0]), place)
        with open(place(out / "bench_results.md"), "w") as results:
            results.write(
                "### Per method and way (the chart's points)\n\n" + bench.format_summary_markdown(summary)
                + "\n### Newton over its tolerance\n\n" + bench.format_newton_markdown(newton_curve)
                + "\n### Laziness\n\n" + bench.format_laziness_markdown(laziness)
                + "\n### Every case: worst error (time per position)\n\n" + bench.format_markdown(rows))
        charts = bench.draw_chart(summary, newton_curve, out / "bench", place) if not args.no_chart else []
    print(bench.format_table(summary))
    print()
    print("Newton over its tolerance (array way; median time, worst error over the cases):")
    for n in sorted(newton_curve, key=lambda n: (n["linkage"], -n["tol"])):
        print(f"  {n['linkage']:<13} tol={n['tol']:<7g} {n['seconds_per_position'] * 1e6:9.3f} us  "
              f"worst error {n['worst_error']:.3g}  failures {n['failures']}")
    print()
    print("Laziness (default programs; ratio to positions only, array way):")
    for r in laziness:
        print(f"  {r['linkage']:<13} {r['level']:<32} {r['way']:<13} {r['seconds_per_position'] * 1e6:10.3f} us"
              f"  x{r['ratio_to_positions_array']:.1f}")
    for path in charts:
        print(f"wrote {path}")
    print(f"wrote {out / 'bench.csv'}")
    return 0
