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

A string an operation is still working on is a temporary (BISTRS.ASM PUTNEW puts its
descriptor in TEMPST): a collection keeps it (GARBAG walks TEMPST before the variables),
and an operation that uses it up without making a string of it frees it, giving its bytes
back when it is the last string made (FRETMP moves FRETOP up over it), so it leaves no
garbage.  The compiler marks both (compile/expressions.py ``held``).
"""

from __future__ import annotations

import sys

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from typing import Callable

from yaseer.basic.errors import OUT_OF_STRING_SPACE, BasicError, STRING_TOO_LONG

# the helpers of the generated code that make a new string (their result is taken from the space)
MAKERS = ("_string", "_space", "_left", "_right", "_mid", "_chr", "_strs", "_hex", "_oct",
          "_mki", "_mks", "_mkd", "_fin_s", "_fline", "_input_chars", "_date", "_time", "_line_input")


def block_locals() -> dict:
    """The Python locals of the innermost block running (its scalars, not stored back yet)."""
    frame = sys._getframe(1)
    while frame is not None:
        name = frame.f_code.co_name
        if name.startswith("_b") and name[2:].isdecimal():  # a block function of the generated code (_b12)
            return frame.f_locals
        frame = frame.f_back
    return {}


class StringSpace:
    """The string space's count (see the module docstring).  ``measure(block_locals)`` is
    (bytes free with no garbage, bytes the strings hold) as memory_model counts them;
    ``held(block_locals)`` the ids of the string objects the variables hold.

    ``temps`` are the temporaries an operation still works on (GW's TEMPST): the left
    side of a ``+`` or a relation, or an earlier argument of a function, while the rest is
    evaluated (the compiler holds them with ``_hold`` only where that rest can make a
    string, and lets them go with ``_free``); a collection keeps them, as it keeps the
    strings a making function works on (GARBAG walks TEMPST before the variables).

    ``count`` is [bytes of the strings made so far, the count at which the free bytes run
    out]: a new string adds its length and compares, nothing more (the generated code's
    string operations call it often)."""

    def __init__(self, measure: Callable[[dict], tuple[int, int]], held: Callable[[dict], set]):
        self.measure = measure
        self.held = held
        self.temps: list = []
        self.text: dict = {}  # id -> string that stays in the program text (see keep_text)
        self.last: list = [None]  # the last string made (those used up at once are not)
        self.count = [0, -1]  # -1: count the free bytes at the next string
        self.base = None  # (strings held, count) at the last collection; None: none since a reset
        # once a program reads the data segment (machine/data_segment.py): id -> (string, its
        # address) of each string in the space, kept from then on (:meth:`track`); None before
        self.places: list = [None]
        self.top = 0  # the string space's end (an offset in the data segment) while tracked

    def keep_text(self, code) -> None:
        """Note the string literals of generated ``code`` (and of the code inside it): a
        variable given one points into the program text and takes no string space (GW's
        LETCN6 copies no literal), nor does a copy of such a variable.  (The dictionary
        keeps each object, so its id is not used again.  A literal of one character is
        left out: Python shares those with every made string of that character.)"""
        for constant in code.co_consts:
            if type(constant) is str:
                if len(constant) > 1:
                    self.text[id(constant)] = constant
            elif hasattr(constant, "co_consts"):
                self.keep_text(constant)

    def reset(self) -> None:
        """CLEAR, RUN, FRE(""): no garbage (the next string counts afresh)."""
        self.count[1] = -1
        self.base = None
        self.last[0] = None
        if self.places[0] is not None:
            self.places[0] = {}

    def take_room(self, text: str) -> None:
        """String ``text`` made outside the compiled code's helpers (LSET's copy): counted
        as theirs are, a collection first where it does not fit."""
        count = self.count
        count[0] += len(text)
        if count[0] > count[1]:
            self.collect(len(text))
        if self.places[0] is not None:
            self.place(text)

    def track(self, top: int, placed: dict) -> None:
        """Keep, from now on, where each new string lies: the space ends at ``top``, the
        strings the variables hold lie at ``placed`` (id -> (string, address)).  Each new
        string goes at FRETOP, below the others and the garbage (BISTRS.ASM GETSPA); a
        collection moves the strings kept up to the top in the order they lay (GARBAG)."""
        self.top = top
        self.places[0] = dict(placed)

    def place(self, text: str) -> None:
        """String ``text``, just made, lies at FRETOP: the top less the strings the last
        collection kept and the bytes made since."""
        held, made = self.base if self.base is not None else (0, 0)
        self.places[0][id(text)] = (text, self.top - held - (self.count[0] - made))

    def _compact(self, names: dict, operands: tuple = ()) -> None:
        """GARBAG's moves, where the strings are tracked: those a variable holds, the
        temporaries and ``operands`` go up to the top, the highest first."""
        places = self.places[0]
        if places is None:
            return
        keep = self.held(names) | {id(text) for text in self.temps} | {id(text) for text in operands}
        at = self.top
        moved = {}
        for key, (text, address) in sorted(places.items(), key=lambda item: -item[1][1]):
            if key in keep:
                at -= len(text)
                moved[key] = (text, at)
        self.places[0] = moved

    def collect(self, needed: int, operands: tuple = ()) -> None:
        """GARBAG, after a string of ``needed`` bytes did not fit: room for it, or Out of
        string space (the count then stands as if it had not been made).  The
        temporaries and the strings ``operands`` the new one is made from are kept."""
        count = self.count
        count[0] -= needed
        names = block_locals()
        free, strings = self.measure(names)
        kept = self.kept(names, operands)
        free -= kept
        count[1] = count[0] + free
        self.base = (strings + kept, count[0])
        self._compact(names, operands)
        if free < needed:
            raise BasicError("Out of string space", OUT_OF_STRING_SPACE)
        count[0] += needed

    def collected(self, free: int, strings: int, names: dict) -> int:
        """A collection now (FRE(""), GWMAIN.ASM REASON) with ``free`` bytes free without
        garbage and ``strings`` bytes held (``names``: the running block's locals): the
        count starts again from here (the garbage later strings leave is counted from
        it); the bytes free after it, less the temporaries it keeps."""
        kept = self.kept(names)
        self.count[1] = self.count[0] + free - kept
        self.base = (strings + kept, self.count[0])
        self.last[0] = None
        self._compact(names)
        return free - kept

    def kept(self, names: dict, operands: tuple = ()) -> int:
        """The bytes of the temporaries (and of ``operands``) a collection keeps: those in
        the string space, not a variable's own string (an operation works on that one in
        place) nor a literal's (it stays in the program text).  An operand of one character
        is taken for a literal (Python shares such strings: see keep_text)."""
        temps = [text for text in self.temps if text]
        temps += [text for text in operands if type(text) is str and len(text) > 1]
        if not temps:
            return 0
        held = self.held(names)
        seen = set()
        kept = 0
        for text in temps:
            key = id(text)
            if key not in held and key not in seen:
                seen.add(key)
                kept += len(text)
        return kept

    def garbage(self, strings: int) -> int:
        """The bytes of garbage when the variables hold ``strings`` bytes of strings."""
        if self.base is None:
            return 0
        held, made = self.base
        return max(held + self.count[0] - made - strings, 0)

    def helpers(self, namespace: dict, longest: int) -> dict:
        """Namespace entries that take each new string from the space: ``_cat`` (``+``, at
        most ``longest`` characters), ``_scopy`` (another variable's string copied) and the
        :data:`MAKERS` of ``namespace`` wrapped; ``_hold``/``_free`` (see the class) and
        ``_drop``/``_release``: a temporary used up by a function that makes no string from
        it (LEN, ASC, VAL, INSTR, STRING$'s character, a relation, PRINT) gives its bytes
        back when it is the last string made (BISTRS.ASM FRETMP moves FRETOP up over it),
        so it leaves no garbage; ``last`` holds the last string made for that.  Each
        maker's ``_u`` form is for a string used up as soon as it is made: it needs the
        room (a collection where there is none) and leaves the count as it was."""
        count, collect, temps = self.count, self.collect, self.temps
        last, in_text = self.last, self.text
        places, place = self.places, self.place  # (where the strings lie: only once tracked)

        def take(text: str) -> str:
            if id(text) in in_text:  # a literal's or DATA's: it stays where it is
                return text
            made = count[0] + len(text)
            count[0] = made
            if made > count[1]:  # (what it copies is a variable's or outside the space)
                collect(len(text))
            last[0] = text
            if places[0] is not None:
                place(text)
            return text

        def hold(text: str) -> str:
            temps.append(text)
            return text

        def free(value, held: int = 1):
            del temps[-held:]
            return value

        def drop(text: str) -> str:
            if text is last[0]:
                count[0] -= len(text)
                last[0] = None  # (the string made before it is not known: it stays)
            return text

        def release(value, held: int = 1):
            for text in reversed(temps[-held:]):
                drop(text)
            del temps[-held:]
            return value

        def summing(lets_go: bool):
            """``+`` (``lets_go``: its left side was held, and is let go)."""
            def concat(a: str, b: str) -> str:
                text = a + b
                n = len(text)
                if n > longest:
                    raise BasicError("String too long", STRING_TOO_LONG)
                if (text is b or text is a) and n > 1:  # an empty side: Python gave the other back,
                    text = text[:1] + text[1:]  # but CAT copies both into a new string (a literal's too)
                made = count[0] + n
                count[0] = made
                if made > count[1]:
                    collect(n, (a, b))
                last[0] = text
                if places[0] is not None:
                    place(text)
                if lets_go:
                    temps.pop()
                return text
            return concat

        def taking(function):
            def made_by(*args):
                text = function(*args)
                if id(text) in in_text:  # a literal given back whole (LEFT$ of all of it): GW's
                    text = text[:1] + text[1:]  # LEFT$, RIGHT$, MID$ copy it all the same (STRINI, MOVINS)
                made = count[0] + len(text)
                count[0] = made
                if made > count[1]:
                    collect(len(text), args)
                last[0] = text
                if places[0] is not None:
                    place(text)
                return text
            return made_by

        def passing(function):
            def made_and_used(*args):
                text = function(*args)
                n = len(text)
                if count[0] + n > count[1]:  # the room is needed while it is used
                    count[0] += n
                    collect(n, args)
                    count[0] -= n
                return text
            return made_and_used

        entries = {name: taking(namespace[name]) for name in MAKERS if name in namespace}
        entries.update({f"{name}_u": passing(namespace[name]) for name in MAKERS if name in namespace})
        entries.update(_cat=summing(False), _cath=summing(True), _cat_u=passing(namespace["_cat"]), _scopy=take, _hold=hold, _free=free,
                       _drop=drop, _release=release)
        return entries
