"""``yaseer animate FILE [--out FILE.gif|.mp4|.html|.png]``: the mechanism moving through its cycle.

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
    """FILE, --out, --fps, --frame, --title, --max-frames, --angle, --method N=NAME."""
    parser.add_argument("file", help="the calling listing (.bas)")
    parser.add_argument("--out", help="FILE.gif (default), .html, .mp4 (H.264 via ffmpeg) or .png (one frame)")
    parser.add_argument("--fps", type=float, default=6.0, help="frames per second (default 6)")
    parser.add_argument("--frame", type=int, default=0, help="with --out FILE.png: which frame (from 0)")
    parser.add_argument("--title", default=None,
                        help="a title over every frame (default: the paper's title, or the listing's first REM)")
    parser.add_argument("--max-frames", type=int, default=360,
                        help="show at most this many evenly spaced frames of a long run (default 360)")
    parser.add_argument("--angle", choices=("deg", "rad"), default="deg",
                        help="unit of SIN COS TAN ATN, as for yaseer run (default deg)")
    parser.add_argument("--method", action="append", default=[], metavar="N=NAME",
                        help="the method for program area N, as for yaseer run")


def main(args) -> int:
    """Record the run, render it; 0 on success, 1 with a one-line error otherwise.

    A run stopped by a BASIC error after some frames is still drawn up to the
    error (the error line goes to stderr and the status is 1).
    """
    from yaseer.animation import AnimationError, record_run, render
    from yaseer.basic.errors import BasicError

    listing = Path(args.file)
    out = Path(args.out) if args.out else Path(listing.stem + ".gif")
    try:
        methods = parse_methods(args.method)
        recording = record_run(listing, methods, angle=args.angle)
        if recording.error is not None and not recording.frames:
            raise recording.error
        count = render(recording.frames, out, title=args.title if args.title is not None else recording.title,
                       fps=args.fps, frame_number=args.frame, max_frames=args.max_frames)
    except FileNotFoundError as error:
        print(f"File not found: {error.filename or listing}", file=sys.stderr)
        return 1
    except OSError as error:
        print(f"Cannot use {error.filename or listing}: {error.strerror or error}", file=sys.stderr)
        return 1
    except (BasicError, AnimationError) as error:
        print(error, file=sys.stderr)
        return 1
    print(f"{out}: {count} frame{'s' if count != 1 else ''}")
    if recording.error is not None:
        print(f"{recording.error} (the animation stops there)", file=sys.stderr)
        return 1
    return 0


def parse_methods(pairs: list[str]) -> dict[int, str] | None:
    """``["2=paper"]`` -> ``{2: "paper"}``; a malformed pair is an error naming it."""
    from yaseer.animation import AnimationError

    methods: dict[int, str] = {}
    for pair in pairs:
        area, _, name = pair.partition("=")
        if not area.strip().isdigit() or not name.strip():
            raise AnimationError(f"--method wants N=NAME, not {pair!r}")
        methods[int(area)] = name.strip()
    return methods or None
