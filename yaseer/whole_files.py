"""Output files that appear whole or not at all.

A command that writes files (an animation, a plot's PNG and SVG, the stability
CSVs and charts) writes each under a temporary name in the same directory
(``.NAME.PID.N.tmp.SUFFIX``: hidden, and keeping the suffix a writer reads the
format from) and renames them into place only when every file of the set is
complete.  Ctrl-C or an error before that removes the temporary files and
leaves what was there before; the renames themselves run with Ctrl-C held back,
so a set is never left half renamed.

    with staged() as place:
        figure.savefig(place(out / "x.png"))
        figure.savefig(place(out / "x.svg"))
"""

from __future__ import annotations

import itertools
import os
from contextlib import contextmanager

_numbers = itertools.count()


class Staging:
    """The temporary names of one set of output files; ``place(path)`` gives the name to write ``path`` under."""

    def __init__(self) -> None:
        self._moves: list[tuple[object, object]] = []

    def __call__(self, path):
        """The temporary name (same type as ``path``: str or ``pathlib.Path``) to write ``path`` under."""
        text = os.fspath(path)
        directory, name = os.path.split(text)
        suffix = os.path.splitext(name)[1]
        temporary = os.path.join(directory, f".{name}.{os.getpid()}.{next(_numbers)}.tmp{suffix}")
        placed = temporary if isinstance(path, str) else type(path)(temporary)
        self._moves.append((placed, path))
        return placed

    def commit(self) -> None:
        """Rename every written file into place (Ctrl-C waits until all are renamed)."""
        import signal

        blocked = {signal.SIGINT} if hasattr(signal, "pthread_sigmask") else None
        if blocked:
            signal.pthread_sigmask(signal.SIG_BLOCK, blocked)
        try:
            for temporary, path in self._moves:
                os.replace(temporary, path)
            self._moves.clear()
        finally:
            if blocked:
                signal.pthread_sigmask(signal.SIG_UNBLOCK, blocked)

    def discard(self) -> None:
        """Remove every temporary file that exists."""
        for temporary, _ in self._moves:
            try:
                os.unlink(temporary)
            except OSError:
                pass
        self._moves.clear()


@contextmanager
def staged(outer: Staging | None = None):
    """A :class:`Staging` committed when the block ends normally and discarded otherwise;
    within an ``outer`` staging the block's files join its set (``outer`` commits them)."""
    if outer is not None:
        yield outer
        return
    staging = Staging()
    try:
        yield staging
    except BaseException:
        staging.discard()
        raise
    try:
        staging.commit()
    except BaseException:
        staging.discard()
        raise
