"""Timers of the tests that interrupt a run (SIGALRM), stopped without a race."""

from __future__ import annotations

import signal


def stop_alarm(previous) -> None:
    """Stop the ITIMER_REAL timer and give SIGALRM back its ``previous`` handler.

    The handler is set to ignore first: a timer that has already fired may still have
    its Python handler pending (CPython runs it at the next bytecode), and a handler that
    arms the timer again would otherwise leave it armed behind the restored handler.
    With the default handler restored, that late SIGALRM kills the whole test process
    (exit status 142)."""
    signal.signal(signal.SIGALRM, signal.SIG_IGN)
    signal.setitimer(signal.ITIMER_REAL, 0)
    signal.signal(signal.SIGALRM, previous)
