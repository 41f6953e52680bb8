"""The Jupyter magics: ``%load_ext yaseer``, then ``%%basic`` (a cell of BASIC) or ``%basic FILE``.

    %%basic [--dialect casio|gw] [--method N=NAME] [--prog N=FILE] [--angle deg|rad]
            [--input TEXT] [--files DIR] [--plot] [--animate] [--fps F] [--size WxH] [--max-frames N] [-o NAME]
    10 FOR QQ = 0 TO 90 STEP 30: X(10) = COS(QQ): Y(10) = SIN(QQ): GOSUB PROG 5
    20 PRINT QQ; T; L: NEXT QQ

The cell runs through :func:`yaseer.run`.  Its screen is the cell's output, shown
as the program prints it, and for a program that drew on the LCD (a program of
Becker's library: ``%basic LIB5615.bas --files DIR --input 2\\n``) its LCD panels,
each time it waited for a key and at its end; an error is one red line (no
traceback); ``--plot`` shows ``result.plot()`` inline, ``--animate`` the mechanism
as a self-contained HTML player.  The :class:`yaseer.api.Result` is stored in the notebook as ``_basic``
(or the name given with ``-o``) for the next cells: ``_basic.rows``,
``_basic.error``...  Needs IPython (``pip install -e '.[jupyter]'`` in the repository: the README's *Teaching with yaseer*).
"""

from __future__ import annotations

import html
import sys
from pathlib import Path

from IPython.core.magic import Magics, line_cell_magic, magics_class
from IPython.core.magic_arguments import argument, magic_arguments


def _words(line: str) -> list[str]:
    """The magic's line split as a shell splits it (quotes removed: ``--input "3, 4"`` gives ``3, 4``),
    except that a backslash stays itself, so ``--input 3\\n4`` keeps its ``\\n`` for the line break."""
    import shlex

    lexer = shlex.shlex(line, posix=True)
    lexer.whitespace_split = True
    lexer.escape = ""
    lexer.commenters = ""
    return list(lexer)


def _pair(text: str) -> tuple[int, str]:
    number, _, value = text.partition("=")
    if not number.strip().isdigit() or not value:
        raise ValueError(f"expected N=VALUE, got {text!r}")
    return int(number), value


@magics_class
class BasicMagics(Magics):
    """``%basic`` and ``%%basic``."""

    @magic_arguments()
    @argument("file", nargs="?", help="a listing to run (line magic); a cell runs its own text")
    @argument("--dialect", default=None, help="casio (default) or gw")
    @argument("--method", action="append", default=[], metavar="N=NAME", help="method of library program N")
    @argument("--prog", action="append", default=[], metavar="N=FILE", help="load program area N from FILE")
    @argument("--angle", choices=("deg", "rad"), default=None, help="unit of SIN COS TAN ATN at start")
    @argument("--input", default=None, help="what INPUT reads (lines separated by \\n)")
    @argument("--files", default=None, metavar="DIR", help="the directory of the program's files and program files")
    @argument("--plot", action="store_true", help="plot the printed columns")
    @argument("--animate", action="store_true", help="animate the mechanism")
    @argument("--fps", type=float, default=6.0, help="frames per second of the animation")
    @argument("--size", default="960x540", help="frame size of the animation, WxH pixels (default 960x540)")
    @argument("--finer", type=int, default=1, metavar="K",
              help="run every FOR ... STEP s loop with the step s/K: K times as many positions (smoother)")
    @argument("--max-frames", type=int, default=90, help="at most this many frames in the player (default 90)")
    @argument("-o", "--output", default="_basic", help="the name the result is stored under (default _basic)")
    @line_cell_magic
    def basic(self, line: str, cell: str | None = None):
        """Run BASIC: the cell's text, or the file named on the line."""
        from IPython.core.error import UsageError

        from yaseer.run_arguments import frame_size, frames_per_second, max_frames

        try:
            args = self.basic.parser.parse_args(_words(line))
            methods = dict(_pair(text) for text in args.method)
            areas = dict(_pair(text) for text in args.prog)
            size = frame_size(args.size)
            args.fps, args.max_frames = frames_per_second(args.fps), max_frames(args.max_frames)
        except ValueError as error:
            raise UsageError(str(error)) from None
        if cell is None and not args.file:
            raise UsageError("%basic FILE runs a listing; %%basic runs the cell's BASIC")
        if cell is not None and args.file:
            raise UsageError("%%basic runs the cell; name no file on its line")
        listing = cell if cell is not None else Path(args.file)
        result = run_magic(listing, args, methods, areas, self.shell)
        show(result, plot=args.plot, animate=args.animate, fps=args.fps, size=size, max_frames=args.max_frames)


def run_magic(listing, args, methods: dict, areas: dict, shell):
    """Run ``listing`` (the cell's text, or a Path), store the result in the user's namespace, return it."""
    from yaseer.api import run

    if isinstance(listing, str) and "\n" not in listing:
        listing += "\n"  # a one-line cell is program text, never a file name
    try:  # the screen streams into the cell as the program prints (the kernel sends it every moment)
        result = run(listing, dialect=args.dialect, method=methods, prog=areas, angle=args.angle,
                     input=args.input.replace("\\n", "\n") if args.input else None, screen=sys.stdout,
                     files=args.files, finer=args.finer)
    except ValueError as error:  # an argument yaseer.run refuses (yaseer.run_arguments): one line
        from IPython.core.error import UsageError

        raise UsageError(str(error)) from None
    if shell is not None:
        shell.user_ns[args.output] = result
    return result


def show(result, plot: bool = False, animate: bool = False, fps: float = 6.0, size=(960, 540),
         max_frames: int = 90) -> None:
    """After the screen (printed as the program ran): an error as one red line, then the plot and the player."""
    from IPython.display import HTML, Image, display

    if result.text and not result.text.endswith("\n"):
        print()  # end the line the program left open
    sys.stdout.flush()  # the screen before the red line, the plot and the player
    if result.screens:  # a program that drew: its LCD, each time it waited for a key and at its end
        from yaseer.lcd import lcd_html

        display({"text/plain": "", "text/html": lcd_html(result.screens, result.glyphs)}, raw=True)
    if result.error is not None:
        _red_line(result.error)
    if plot:
        try:
            display(Image(_png(result.plot())))
        except ValueError as error:
            _red_line(str(error))
    if animate:
        from yaseer.animation import AnimationError, html_player

        try:
            display(HTML(html_player(result.frames, result.look(size), fps=fps, max_frames=max_frames)))
        except AnimationError as error:
            _red_line(str(error))


def _red_line(text: str) -> None:
    """One line in red (HTML), plain text for other front ends."""
    from IPython.display import display

    display({"text/plain": text, "text/html": f'<pre style="color:#c00000;margin:0">{html.escape(text)}</pre>'},
            raw=True)


def _png(figure) -> bytes:
    import io

    buffer = io.BytesIO()
    figure.savefig(buffer, format="png", dpi=100)
    return buffer.getvalue()


def load_ipython_extension(ipython) -> None:
    """Register the magics (``%load_ext yaseer``)."""
    ipython.register_magics(BasicMagics)
