"""GW-BASIC's string space: where a new string must find room, or ``Out of string space``.

GW-BASIC puts every string it makes (a ``+``, STRING$, SPACE$, LEFT$ ..., a string read
from a file or typed at INPUT or LINE INPUT, a copy of another variable's string) below the last one, in the free bytes
between the variables and the strings (BISTRS.ASM ``GETSPA``).  When they run out it
collects the garbage once (``GARBAG``: only the strings variables still hold are kept)
and tries again; if the string still does not fit: ``Out of string space`` (error 14).
A string space that fills with garbage is therefore collected, never an error.  FRE(0)
counts the garbage as used, FRE("") collects it first (BISTRS.ASM ``FRE``).

yaseer keeps its strings in Python and has no garbage, so it counts: the bytes of the
strings made since the last collection, against the free bytes counted then; a collection
counts the strings the variables hold now (machine/memory_model.py, with the running
block's own values, which it has not stored back yet), and the garbage is what was made
since less what the variables hold of it.  A literal assigned is not a new string, nor is
a string READ takes from DATA (GW points into the program text: GWMAIN.ASM LETCN6 copies
a string only from the keyboard buffer, a file buffer or the string space).
"""

from __future__ import annotations

import re
import sys

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from typing import Callable

from yaseer.basic.errors import OUT_OF_STRING_SPACE, BasicError, STRING_TOO_LONG

# the helpers of the generated code that make a new string (their result is taken from the space)
MAKERS = ("_string", "_space", "_left", "_right", "_mid", "_chr", "_strs", "_hex", "_oct",
          "_mki", "_mks", "_mkd", "_fin_s", "_fline", "_input_chars", "_date", "_time", "_line_input")
_BLOCK = re.compile(r"_b\d+$")  # a block function of the generated code


def block_locals() -> dict:
    """The Python locals of the innermost block running (its scalars, not stored back yet)."""
    frame = sys._getframe(1)
    while frame is not None:
        if _BLOCK.match(frame.f_code.co_name):
            return frame.f_locals
        frame = frame.f_back
    return {}


class StringSpace:
    """The string space's count (see the module docstring).  ``measure(block_locals)`` is
    (bytes free with no garbage, bytes the strings hold) as memory_model counts them.

    ``count`` is [bytes of the strings made so far, the count at which the free bytes run
    out]: a new string adds its length and compares, nothing more (the generated code's
    string operations call it often)."""

    def __init__(self, measure: Callable[[dict], tuple[int, int]]):
        self.measure = measure
        self.count = [0, -1]  # -1: count the free bytes at the next string
        self.base = None  # (strings held, count) at the last collection; None: none since a reset

    def reset(self) -> None:
        """CLEAR, RUN, FRE(""): no garbage (the next string counts afresh)."""
        self.count[1] = -1
        self.base = None

    def collect(self, needed: int) -> None:
        """GARBAG, after a string of ``needed`` bytes did not fit: room for it, or Out of
        string space (the count then stands as if it had not been made)."""
        count = self.count
        count[0] -= needed
        free, strings = self.measure(block_locals())
        count[1] = count[0] + free
        self.base = (strings, count[0])
        if free < needed:
            raise BasicError("Out of string space", OUT_OF_STRING_SPACE)
        count[0] += needed

    def garbage(self, strings: int) -> int:
        """The bytes of garbage when the variables hold ``strings`` bytes of strings."""
        if self.base is None:
            return 0
        held, made = self.base
        return max(held + self.count[0] - made - strings, 0)

    def helpers(self, namespace: dict, longest: int) -> dict:
        """Namespace entries that take each new string from the space: ``_cat`` (``+``, at
        most ``longest`` characters), ``_scopy`` (another variable's string copied) and the
        :data:`MAKERS` of ``namespace`` wrapped."""
        count, collect = self.count, self.collect

        def take(text: str) -> str:
            made = count[0] + len(text)
            count[0] = made
            if made > count[1]:
                collect(len(text))
            return text

        def concat(a: str, b: str) -> str:
            text = a + b
            n = len(text)
            if n > longest:
                raise BasicError("String too long", STRING_TOO_LONG)
            made = count[0] + n
            count[0] = made
            if made > count[1]:
                collect(n)
            return text

        def taking(function):
            def made_by(*args):
                text = function(*args)
                made = count[0] + len(text)
                count[0] = made
                if made > count[1]:
                    collect(len(text))
                return text
            return made_by

        entries = {name: taking(namespace[name]) for name in MAKERS if name in namespace}
        entries.update(_cat=concat, _scopy=take)
        return entries
