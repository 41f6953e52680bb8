"""Python's automatic garbage collection paused while a ``yaseer`` process starts.

A start imports some eighty modules and reads the compiled program: tens of thousands of
objects (classes, functions, code, tables), none of them garbage.  Every 700 new objects
Python's collector looks through the young ones, and every hundredth time through all of
them: in a ``yaseer run`` of ``10 END`` those passes cost about a tenth of the whole
process's instructions (valgrind: 14.7M of 157M) and find nothing to free.

So the program's first code (:mod:`yaseer.entry`) calls :func:`pause`, and :func:`resume`
switches the collector back on just before the BASIC program runs (:func:`yaseer.api.execute`,
after the listing is parsed and compiled or read from the cache: a cold start's parse and
compile make tens of thousands of objects too, and no cyclic garbage worth a collection)
or, for every other command, once the command line is read (:mod:`yaseer.cli`).  It first
freezes what the start made (``gc.freeze``: objects kept for the whole run, moved where no
later collection looks at them), so the collections during the run, and the one at exit,
look only at what the run itself makes.  A program run in another Python process (the API,
Jupyter, the tests) never pauses, and :func:`resume` then does nothing.
"""

from __future__ import annotations

import gc

_paused = False


def pause() -> None:
    """Switch automatic collection off until :func:`resume` (if it was on)."""
    global _paused
    if gc.isenabled():
        gc.disable()
        _paused = True


def paused() -> bool:
    """True between :func:`pause` and :func:`resume`."""
    return _paused


def resume() -> None:
    """After :func:`pause`: freeze the objects made so far and switch automatic collection on again."""
    global _paused
    if _paused:
        _paused = False
        gc.freeze()
        gc.enable()
