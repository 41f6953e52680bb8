"""A listing run once through :func:`yaseer.run` while the animation recorder watches its program calls.

This sits above both the API and :mod:`yaseer.animation` (the API records frames with the
animation's :class:`~yaseer.animation.record.Recorder`; this module runs the API), so neither of
them imports the other's caller.
"""

from __future__ import annotations

from yaseer.animation.geometry import Frame
from yaseer.api import run
from yaseer.progress import bar


class _LineCounter:
    """A text stream that only counts lines into a progress bar."""

    def __init__(self, progress) -> None:
        self._progress = progress

    def write(self, text: str) -> int:
        self._progress.update(text.count("\n"))
        return len(text)

    def flush(self) -> None:
        """Nothing is kept."""

    def isatty(self) -> bool:
        return False


def record_run(listing, methods: dict[int, str] | None = None, progress_file=None, angle: str | None = None,
               **run_options):
    """Run ``listing`` (a path or the program text) once through :func:`yaseer.run`: its Result.

    PRINT and LPRINT output both close frames.  A BASIC error (syntax, run
    time, a mechanism that cannot be assembled) ends the run: the frames
    recorded before it are kept with the error, so the animation can show the
    mechanism up to where the method broke.  A progress counter of printed
    lines appears on stderr if the run takes more than a second.  ``angle``
    is the unit of the trigonometric functions, as ``yaseer run --angle``;
    ``run_options`` are further :func:`yaseer.run` arguments (``prog``,
    ``input``, ``dialect``).
    """
    with bar(None, "running", "line", file=progress_file) as progress:
        return run(listing, method=methods, angle=angle, screen=_LineCounter(progress), **run_options)


def record_listing(text: str, methods: dict[int, str] | None = None, progress_file=None) -> list[Frame]:
    """The frames of a run that must complete: as :func:`record_run`, raising its BASIC error."""
    result = record_run(text, methods, progress_file)
    if result.exception is not None:
        raise result.exception
    return result.frames
