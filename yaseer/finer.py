"""More positions from a listing itself: every ``FOR ... STEP s`` loop run with the step ``s / k``.

An animation of a 19-position cycle is jumpy; in-between frames invented by
interpolation would show positions the listing never computed.  ``finer_steps``
instead divides the numeric ``STEP`` of each ``FOR`` loop, so the listing computes
and prints ``k`` times as many positions through the library programs, each one as
honest as the originals (``FOR QQ = 360.1 TO .1 STEP -20`` runs as ``STEP (-20)/4``).
Loops without a ``STEP`` (counting 1, 2, 3, often an index) are left alone, as are
strings and remarks.
"""

from __future__ import annotations

import re

_STEP = re.compile(r"(\bSTEP\s*)(-?\s*(?:\d+\.?\d*|\.\d+)(?:E[-+]?\d+)?)", re.IGNORECASE)


def finer_steps(listing: str, k: int) -> str:
    """``listing`` with every numeric FOR step divided by ``k`` (a whole number, 1 or more)."""
    if k < 1:
        raise ValueError(f"--finer takes a whole number of 1 or more, not {k}")
    if k == 1:
        return listing
    return "\n".join(_finer_line(line, k) for line in listing.split("\n"))


def _finer_line(line: str, k: int) -> str:
    """One line: the steps outside strings and before a remark divided by ``k``."""
    out, code, quoted = [], [], False
    index = 0
    while index < len(line):
        char = line[index]
        if not quoted and (line[index:index + 3].upper() == "REM" or char == "'"):
            break
        if char == '"':
            if not quoted:
                out.append(_divided("".join(code), k))
                code = []
            quoted = not quoted
            out.append(char)
        elif quoted:
            out.append(char)
        else:
            code.append(char)
        index += 1
    out.append(_divided("".join(code), k))
    return "".join(out) + line[index:]


def _divided(code: str, k: int) -> str:
    return _STEP.sub(lambda m: f"{m[1]}({m[2].replace(' ', '')})/{k}", code)
