"""The ``yaseer`` program's first code (the console script and ``python -m yaseer``).

Ctrl-C while Python is still importing the command line (the first tens of
milliseconds of every start) ends the program as Ctrl-C does anywhere else: one
line on standard error and status 130, never a KeyboardInterrupt traceback from
the middle of an import.  Once the command line is imported, Ctrl-C is Python's
KeyboardInterrupt again, which :func:`yaseer.cli.guarded` (and a running BASIC
machine, as ``Break``) turns into the same line and status.
"""

import os

import _signal  # the built-in module: ``signal`` would first be searched for along sys.path and build its enums

INTERRUPTED = 130  # the shell's status of a program ended by SIGINT (128 + 2)


def _interrupted_while_starting(signum, frame) -> None:
    try:
        os.write(2, b"yaseer: interrupted (Ctrl-C)\n")
    except OSError:  # standard error closed: the status says it
        pass
    os._exit(INTERRUPTED)


_signal.signal(_signal.SIGINT, _interrupted_while_starting)  # at import: the script imports this module first

from yaseer import collection_pause  # noqa: E402

collection_pause.pause()  # until the program runs: the start's objects are no garbage


def main() -> int:
    """Import the command line quietly interruptible, then run it (``sys.argv``); the exit status."""
    from yaseer import cli

    _signal.signal(_signal.SIGINT, _signal.default_int_handler)
    return cli.main()
