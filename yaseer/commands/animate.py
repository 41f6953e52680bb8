"""``yaseer animate FILE [--out FILE.gif|.mp4|.html|.png] [run options]``: the mechanism moving through its cycle.

The listing runs once on the BASIC machine with the library programs bound as
for ``yaseer run``; every ``GOSUB PROG n`` is recorded (see
``yaseer.animation``) and each printed line closes a frame.  The listing's own
output is not shown (it is the caption of each frame); errors are BASIC error
lines on stderr with exit status 1 — a run that fails part-way is still drawn
up to the failure.
"""

from __future__ import annotations

import sys
from pathlib import Path


def add_arguments(parser) -> None:
    """FILE, --out, --fps, --size, --frame, --title, --max-frames and the run options of ``yaseer run``."""
    from yaseer.commands.parsers import add_run_options, checked
    from yaseer.run_arguments import frame_size, frames_per_second, max_frames

    parser.epilog = ("Exit status: 0 written, 1 an error (one line on standard error; a run that fails part-way "
                     "is still drawn up to the failure), 2 a wrong command line (also --frame without a .png), "
                     "130 Ctrl-C.")
    parser.add_argument("file", help="the calling listing (.bas)")
    parser.add_argument("--out", metavar="FILE",
                        help="the file to write (its directory is created): .gif, .html, .mp4 (H.264 via ffmpeg) "
                             "or .png (one frame); default: <stem>.gif in the current directory")
    parser.add_argument("--fps", type=checked(frames_per_second), default=6.0, help="frames per second (default 6)")
    parser.add_argument("--size", type=checked(frame_size), default=(1280, 720), metavar="WxH",
                        help="frame size in pixels (default 1280x720, for a projector)")
    parser.add_argument("--frame", type=int, default=None,
                        help="with --out FILE.png: which frame to draw (from 0; default 0); refused otherwise")
    parser.add_argument("--title", default=None,
                        help="a title over every frame (default: the paper's title, or the listing's first REM)")
    parser.add_argument("--finer", type=_whole, default=1, metavar="K",
                        help="smoother motion: run every FOR ... STEP s loop with the step s/K, so the listing "
                             "computes K times as many positions (default 1: the listing as written)")
    parser.add_argument("--max-frames", type=checked(max_frames), default=360,
                        help="show at most this many evenly spaced frames of a long run (default 360)")
    add_run_options(parser)


def _whole(text: str) -> int:
    """``--finer 4`` -> 4; a usage error for anything but a whole number of 1 or more."""
    import argparse

    if not text.strip().isdigit() or int(text) < 1:
        raise argparse.ArgumentTypeError(f"expected a whole number of 1 or more, got {text!r}")
    return int(text)


def main(args) -> int:
    """Record the run, render it; 0 on success, 1 with a one-line error otherwise.

    A run stopped by a BASIC error after some frames is still drawn up to the
    error (the error line goes to stderr and the status is 1).
    """
    from yaseer.animation import AnimationError, render
    from yaseer.recorded_run import record_run
    from yaseer.commands.options import UsageError, run_settings
    from yaseer.commands.output import output_file
    from yaseer.commands.run import raise_if_interrupted

    listing = Path(args.file)
    out = Path(args.out) if args.out else Path(listing.stem + ".gif")
    if args.frame is not None and out.suffix.lower() != ".png":
        raise UsageError(f"--frame chooses the frame of a .png; {out} is a whole animation")
    settings = run_settings(args)
    options = settings.run_arguments()
    try:
        result = record_run(listing, options.pop("method"), angle=options.pop("angle"), finer=args.finer, **options)
    finally:
        settings.close()
    raise_if_interrupted(result.exception)  # Ctrl-C: nothing is drawn
    if result.error is not None and not result.frames:
        print(result.error, file=sys.stderr)
        return 1
    try:
        count = render(result.frames, output_file(out), look=result.look(args.size, args.title),
                       fps=args.fps, frame_number=args.frame or 0, max_frames=args.max_frames)
    except AnimationError as error:
        print(error, file=sys.stderr)
        return 1
    print(f"{out}: {count} frame{'s' if count != 1 else ''}")
    if result.error is not None:
        print(f"{result.error} (the animation stops there)", file=sys.stderr)
        return 1
    return 0
