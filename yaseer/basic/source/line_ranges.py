"""GW-BASIC's DELETE range, as the statement, the session's command and CHAIN's DELETE
option read it (GWLIST.ASM ``DELETE``, FIVEO.ASM ``CHAIN``).

``SCNLIN`` (GWMAIN.ASM) reads ``[first][-[last]]``: a first number left out is 0, a last
one left out (``DELETE``, ``DELETE 20-``, ``DELETE -``) is 65530, above every line number.
``FNDLIN`` then finds the first line from ``first`` on, and is called again for ``last``:
only an exact match sets the carry, and without it the statement jumps to ``FCERR``
("MUST HAVE A MATCH ON THE UPPER BOUND"), so a range whose last line is not in the program
is ``Illegal function call`` however many lines it holds; so is one whose first line found
does not come before the line after the last (``DELETE 30-20``).

DELETE's last line left out is the exception, decided by a real GW-BASIC 3.23 over the
published source: PC-BASIC's DELETE test recorded there shows ``DELETE 60-`` deleting lines
60 to the program's end (as PC-BASIC 2.0.8 does), so that range needs no line at its end
(``open_end``).  CHAIN's DELETE option keeps the exact match (PC-BASIC 2.0.8 agrees).
"""

from __future__ import annotations

from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL

NO_LAST_LINE = 65530  # SCNLIN's upper bound when none is given (line numbers end at 65529)


def deleted_lines(numbers, first: int | None, last: int | None, open_end: bool = False) -> list[int]:
    """The program lines (``numbers``) DELETE first-last removes, in order (None: left
    out); ``Illegal function call`` where GW-BASIC refuses the range.  ``open_end``: a last
    line left out means the program's end (the DELETE statement and command)."""
    open_end = open_end and last is None
    last = NO_LAST_LINE if open_end else last
    first = 0 if first is None else first
    if not open_end and last not in numbers:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    doomed = sorted(n for n in numbers if first <= n <= last)
    if not doomed:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    return doomed
