"""A recorded path's text translated into a program of double operations for the optional C
accelerator :mod:`yaseer.linkages._straight_fast`, which runs it without a Python object a value.

A path recorded by :mod:`yaseer.linkages.tracing` is Python text: element reads, a few hundred
assignments of float and complex arithmetic and calls of ``math``/``cmath``, guards (``if ...:
raise``), then the checks and writes of its outputs.  :func:`yaseer.linkages.path_translation.translate` reads that text with
:mod:`ast` and gives each value a register (a complex number two: real, imaginary) and each
operation an instruction; any construct it does not know (another function, a power other than a
float's square, a complex power, a conversion of a complex number to a float, ...) makes it give
up (None), and the path keeps its Python function alone.  The accelerator computes each operation
as CPython does for the values it accepts and refuses all others (a zero divisor, a non-finite
argument, an input that is not a float, a failing guard): the path's Python function then runs the
whole call, so the outputs written are always the Python function's (see the C source's header).

:func:`accelerated` wraps a path's function: its first :data:`WARM` calls run the Python function
(a path taken a few times is not worth translating), then it is translated once and, where that
succeeds, its calls run the program.

Mixed float and complex arithmetic is translated as CPython 3.11-3.13 compute it (the float made
the complex number (x, 0.0) first); on other versions nothing is translated.
"""

from __future__ import annotations

import sys

from yaseer.accelerators import pure_python

# Calls of a path run by its Python function before it is translated.  A translation costs about
# 10 ms, the time of 400-500 calls of a path of Program 2's: a run taking a path a few dozen times
# (each of the paper's examples) never pays it; one taking it more pays it once, and with the
# on-disk cache once for good (the program is kept: a later run runs it from the first call).
WARM = 64


def _module():
    """The C accelerator, or None (not built, another Python's arithmetic, or YASEER_PURE_PYTHON set)."""
    if pure_python():
        return None
    if sys.implementation.name != "cpython" or not (3, 11) <= sys.version_info[:2] <= (3, 13):
        return None
    try:
        from yaseer.linkages import _straight_fast
    except ImportError:
        return None
    return _straight_fast


def accelerated(run, text: str, programs=None):
    """``run`` (a path's Python function, of the Python text ``text``) as it runs from now on: the
    accelerator's Path, which calls ``run`` for :data:`WARM` calls, then translates ``text`` once
    and runs its program wherever the accelerator accepts the inputs (``run`` for all others, and
    for every call when the text cannot be translated); ``run`` itself where there is no accelerator.

    ``programs``: where translated programs are kept between runs (``kept_program(run,
    operations)`` gives the one kept with ``run`` or None, ``keep_program(run, operations,
    program)`` keeps one: :class:`yaseer.linkages.recording_cache.Shelf`); a path whose program is
    kept runs it from its first call, and a translation is kept there."""
    module = _module()
    if module is None or not text:
        return run
    names, operations = run.__globals__, module.OPERATIONS
    kept = programs.kept_program(run, operations) if programs is not None else None
    if kept is not None:
        return module.Path(run, lambda: kept, 0)

    def translation():
        from yaseer.linkages.path_translation import translate  # (a run that translates imports ast)

        program = translate(text, names, operations)
        if program is not None and programs is not None:
            programs.keep_program(run, operations, program)
        return program

    return module.Path(run, translation, WARM)
