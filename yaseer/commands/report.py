"""``yaseer report LISTING --out page.html``: a one-page handout of a run (see ``yaseer.report``).

The listing runs once through :func:`yaseer.run` with the run options of
``yaseer run``; the page holds the listing, its output and rows, the plots as
inline SVG, the animation player and, for the paper's examples, the errata that
apply.  A run stopped by an error still gets its page (the error in red), and
the error line goes to stderr with its exit status.
"""

from __future__ import annotations

from pathlib import Path


def add_arguments(parser) -> None:
    """FILE, --out, --fps, --size, --max-frames and the run options of ``yaseer run``."""
    from yaseer.commands.parsers import add_run_options, checked
    from yaseer.run_arguments import frame_size, frames_per_second, max_frames

    parser.add_argument("file", help="the BASIC listing")
    parser.add_argument("--out", metavar="FILE", help="the page to write (default: <stem>.html here)")
    parser.add_argument("--fps", type=checked(frames_per_second), default=6.0, help="frames per second of the player (default 6)")
    parser.add_argument("--size", type=checked(frame_size), default=(1280, 720), metavar="WxH",
                        help="frame size of the player in pixels (default 1280x720)")
    parser.add_argument("--max-frames", type=checked(max_frames), default=120,
                        help="at most this many evenly spaced frames in the player (default 120)")
    add_run_options(parser)


def main(args) -> int:
    """Run, build the page, write it; the run's exit status (0, or 1 with its error line)."""
    from yaseer.api import run
    from yaseer.basic.errors import FILE_NOT_FOUND
    from yaseer.commands.options import run_settings
    from yaseer.commands.output import output_file
    from yaseer.commands.run import raise_if_interrupted, report
    from yaseer.whole_files import staged
    from yaseer.report import build_page

    listing = Path(args.file)
    out = Path(args.out) if args.out else Path(listing.stem + ".html")
    settings = run_settings(args)
    try:
        result = run(listing, **settings.run_arguments())
    finally:
        settings.close()
    raise_if_interrupted(result.exception)  # Ctrl-C: no page
    if getattr(result.exception, "code", None) == FILE_NOT_FOUND:  # no listing, no page
        return report(result)
    printed_program_5 = any(Path(path).name == "prog5.bas" for n, path in args.prog if n == 5)
    page = build_page(result, listing, printed_program_5, fps=args.fps, size=args.size,
                      max_frames=args.max_frames)
    with staged() as place, open(place(output_file(out)), "w", encoding="utf-8") as written:
        written.write(page)  # the page appears whole, or not at all
    print(out)
    return report(result)
