"""Progress bars for long runs and renders, on stderr only.

A bar appears only once its task has taken longer than :data:`DELAY_SECONDS`
(tqdm's ``delay``), so a short run prints nothing extra; it goes to stderr,
never into the program's output, and by default only when stderr is a
terminal (a redirected stderr gets no bar characters).  tqdm is imported
lazily: importing this module costs nothing at start-up.
"""

from __future__ import annotations

import sys
from contextlib import contextmanager

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from typing import IO, Iterable, Iterator, TypeVar

    T = TypeVar("T")

DELAY_SECONDS = 1.0  # a task quicker than this shows no bar at all


def bar(
    total: int | None = None,
    description: str = "",
    unit: str = "it",
    file: IO[str] | None = None,
    delay: float = DELAY_SECONDS,
    force: bool = False,
    refresh_seconds: float = 0.1,
):
    """A tqdm bar on ``file`` (default stderr), shown after ``delay`` seconds.

    ``total`` may be None for a task of unknown length (a counter is shown).
    With ``force`` the bar is drawn even when ``file`` is not a terminal
    (tests and logs); otherwise a non-terminal ``file`` disables it.  The bar
    is redrawn at most every ``refresh_seconds`` and erased when done.
    Use it as a context manager; call ``.update(n)`` as work is done.
    """
    from tqdm import tqdm

    stream = sys.stderr if file is None else file
    return tqdm(
        total=total,
        desc=description or None,
        unit=unit,
        file=stream,
        delay=delay,
        leave=False,
        dynamic_ncols=True,
        mininterval=refresh_seconds,
        miniters=1,
        disable=False if force else not _is_terminal(stream),
    )


def track(
    items: Iterable[T],
    total: int | None = None,
    description: str = "",
    unit: str = "it",
    file: IO[str] | None = None,
    delay: float = DELAY_SECONDS,
    force: bool = False,
    refresh_seconds: float = 0.1,
) -> Iterator[T]:
    """Iterate over ``items`` with a :func:`bar` that ticks once per item."""
    if total is None and hasattr(items, "__len__"):
        total = len(items)  # type: ignore[arg-type]
    with bar(total, description, unit, file=file, delay=delay, force=force,
             refresh_seconds=refresh_seconds) as progress:
        for item in items:
            yield item
            progress.update(1)


def _is_terminal(stream: IO[str]) -> bool:
    isatty = getattr(stream, "isatty", None)
    try:
        return bool(isatty and isatty())
    except ValueError:  # a closed stream
        return False


class CountingStream:
    """A text stream that forwards to ``stream`` and ticks ``progress`` once per line written."""

    def __init__(self, stream: IO[str], progress) -> None:
        self._stream = stream
        self._progress = progress

    def write(self, text: str) -> int:
        """Forward ``text``; each newline in it is one tick."""
        self._stream.write(text)
        lines = text.count("\n")
        if lines:
            self._progress.update(lines)
        return len(text)

    def flush(self) -> None:
        """Flush the stream underneath."""
        self._stream.flush()

    def isatty(self) -> bool:
        """Whatever the stream underneath is."""
        return _is_terminal(self._stream)


@contextmanager
def output_progress(stream: IO[str], description: str = "running", file: IO[str] | None = None,
                    delay: float = DELAY_SECONDS, refresh_seconds: float = 0.1) -> Iterator[IO[str]]:
    """A program's output stream that counts its lines on a bar, when that cannot mix with it.

    When ``stream`` is a terminal the program's output is the progress, so
    ``stream`` itself is given back and no bar is drawn; so it is when ``file``
    (stderr) is not a terminal.  Otherwise (output to a file or a pipe) a bar
    counting the lines written appears on ``file`` after ``delay`` seconds.  Usage::

        with output_progress(sys.stdout) as out:
            machine = Machine(screen=out)
            machine.run()
    """
    if _is_terminal(stream) or not _is_terminal(sys.stderr if file is None else file):
        yield stream  # no bar could be shown: do not even import tqdm
        return
    with bar(None, description, "line", file=file, delay=delay, refresh_seconds=refresh_seconds) as progress:
        yield CountingStream(stream, progress)
