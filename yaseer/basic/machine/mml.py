"""PLAY's Music Macro Language, read as GW-BASIC reads it (MACLNG.ASM MACLNG, FETCHR,
VALSCN, SCNVAR, MCLXEQ; GWSTS.ASM PLAYS and its command table PLYTAB).

The string is read a character at a time, blanks skipped and letters made capitals.  Each
character must be a command: a note ``A``..``G`` (then ``#`` or ``+`` sharp, ``-`` flat, a
length 1..64, dots), ``N`` note number 0..84 (0 a pause), ``O`` octave 0..6, ``>``/``<`` an
octave up/down (kept within 0..6: the recordings), ``P`` pause 1..64, ``T`` tempo 32..255,
``L`` length 1..64, ``M`` with ``F``/``B`` (foreground, background) or ``L``/``N``/``S``
(legato, normal, staccato), ``X`` a string variable's text played where it stands; anything
else is Illegal function call, raised where it is read (what came before has been played).
A command's number is digits (a 16-bit value; more is Illegal function call), ``=name;`` a
numeric variable's value (FRCINT), or a VARPTR$ string's variable; a ``;`` after a number is
read with it.  As the source does, the commands look at the number's low byte only.

A variable's name is read up to ``;`` (at most 40 characters); its subscripts may be
numbers or simple variables (GW-BASIC evaluates any expression there: others are refused
naming what is not emulated).
"""

from __future__ import annotations

import re

from yaseer.basic.arithmetic.values import nearest_integer
from yaseer.basic.errors import (
    ILLEGAL_FUNCTION_CALL, OUT_OF_MEMORY, OVERFLOW, SUBSCRIPT_OUT_OF_RANGE, TYPE_MISMATCH, error_for, not_emulated,
)

# the top octave's frequencies in Hz, C to B (GWSTS.ASM NOTTAB); lower octaves halve them
TOP_OCTAVE = (4186, 4435, 4699, 4978, 5274, 5588, 5920, 6272, 6645, 7040, 7459, 7902)
# a note letter and its mark -> the semitone 1..12 of C..B (GWSTS.ASM NOTXLT: A- is G#, no
# C-, B#, E# or F-); the index is 2 x (letter's place in A..G) + 1 for a sharp, - 1 for a flat
NOTE_INDEX = (9, 10, 11, 12, None, 1, 2, 3, 4, 5, None, 6, 7, 8, 9)
DIVIDEND = 96000  # 4 x 60 x 400: a quarter note at T beats a minute lasts 96000/(T x 4) units
VARPTR_TYPES = 9  # a VARPTR$ string starts with its variable's type, below 9 (SCNVAR)
NAME_LONGEST = 40  # SCNVR2 copies at most 40 characters of a name
# strings Xed inside each other: MCLXEQ asks GETSTK for room on BASIC's stack for each, and
# a full stack is Out of memory; yaseer's bound (the room depends on what else is stacked)
X_DEPTH = 100
# what ISVAR reads of a name: letters, digits and dots, a type mark, subscripts (the rest is not read)
_VARIABLE = re.compile(r"([A-Z][A-Z0-9.]*)([%!#$]?)(?:\((.*)\))?")


def _illegal():
    return error_for(ILLEGAL_FUNCTION_CALL)


class _Reader:
    """The strings being read: a stack of [text, position] (MCLXEQ pushes the one it plays)."""

    def __init__(self, text: str):
        self.stack = [[text, 0]]

    def fetch(self) -> str | None:
        """FETCHR: the next character of the string on top, blanks skipped, codes from 96 up
        less 32 (so letters are capitals); None at its end."""
        top = self.stack[-1]
        text = top[0]
        while top[1] < len(text):
            c = text[top[1]]
            top[1] += 1
            if c != " ":
                return chr(ord(c) - 32) if ord(c) >= 96 else c
        return None

    def fetch_needed(self) -> str:
        """FETCHZ: the next character; at the end Illegal function call."""
        c = self.fetch()
        if c is None:
            raise _illegal()
        return c

    def back(self) -> None:
        """DECFET: the last character read put back."""
        self.stack[-1][1] -= 1

    def raw(self) -> tuple[str, int]:
        """The string on top and the position reached (SCNVAR looks at the byte there as it is)."""
        text, at = self.stack[-1]
        return text, at


class Macro:
    """One macro string's reading (MACLNG): the commands' numbers and variables, X; a
    language's class adds :meth:`command` (PLAY's :class:`Player`, DRAW's
    machine/draw_macro.py)."""

    def __init__(self, machine, text: str):
        self.machine = machine
        self.reader = _Reader(text)

    def command(self, c: str) -> None:  # pragma: no cover - each language has its own
        raise NotImplementedError

    def run(self) -> None:
        """MACLNG's loop: each command in turn; at a string's end, the string that Xed it."""
        reader = self.reader
        while True:
            c = reader.fetch()
            if c is None:
                reader.stack.pop()
                if not reader.stack:
                    return
                continue
            self.command(c)

    # -- numbers
    def argument(self) -> tuple[bool, int]:
        """(given, value) of a command that takes a number (MISCMD): none at the string's end
        or before a letter (then 1, not given), else VALSC3."""
        reader = self.reader
        c = reader.fetch()
        if c is None:
            return False, 1
        if "A" <= c <= "Z":
            reader.back()
            return False, 1
        return True, self.value(c)

    def value(self, c: str) -> int:
        """VALSC3 from character ``c``: ``=`` a variable, ``+`` skipped, ``-`` negated (16
        bits), else digits (VALSC2)."""
        if c == "=":
            return self.variable_number()
        if c == "+":
            return self.value(self.reader.fetch_needed())
        if c == "-":
            return -self.value(self.reader.fetch_needed()) & 0xFFFF
        return self.digits(c)

    def digits(self, c: str | None) -> int:
        """VALSC2: the number whose digits start at ``c`` (0 if none); a comma or any other
        character ends it and is put back, a ``;`` ends it and is read; beyond 65535
        Illegal function call."""
        reader = self.reader
        total = 0
        while c is not None:
            if c == ";":
                return total
            if not "0" <= c <= "9":
                reader.back()
                return total
            total = total * 10 + ord(c) - 48
            if total > 0xFFFF:
                raise _illegal()
            c = reader.fetch()
        return total

    # -- variables
    def variable(self):
        """SCNVAR: a VARPTR$ string's variable or a name up to ``;``; its value."""
        reader = self.reader
        text, at = reader.raw()
        if at < len(text) and ord(text[at]) < VARPTR_TYPES and len(text) - at >= 3:
            reader.stack[-1][1] = at + 3
            return self.pointed(text[at:at + 3])
        c = reader.fetch_needed()
        if not "A" <= c <= "Z":
            raise _illegal()
        name = c
        while c != ";":
            c = reader.fetch_needed()
            name += c
            if len(name) > NAME_LONGEST:
                raise _illegal()
        return self._value_of(name[:-1])

    def pointed(self, pointer: str):
        """The value at a VARPTR$ string's address (RETVAR): the type byte's 2, 4 or 8 bytes
        of a number, or a string's descriptor (length, address) and its characters, read
        from the data segment as PEEK reads it (machine/address_space.py); another type
        byte is Illegal function call."""
        from yaseer.basic.machine import gwfunctions
        from yaseer.basic.machine.address_space import DATA_SEGMENT

        kind, address = ord(pointer[0]), ord(pointer[1]) | ord(pointer[2]) << 8
        memory = self.machine.address_space

        def chars(at: int, count: int) -> str:
            return "".join(chr(memory.read(DATA_SEGMENT * 16 + (at + k & 0xFFFF))) for k in range(count))

        if kind == 3:
            descriptor = chars(address, 3)
            return chars(ord(descriptor[1]) | ord(descriptor[2]) << 8, ord(descriptor[0]))
        reading = {2: gwfunctions.cvi, 4: gwfunctions.cvs, 8: gwfunctions.cvd}.get(kind)
        if reading is None:
            raise _illegal()
        return reading(chars(address, kind))

    def variable_number(self) -> int:
        """VARGET: the variable's value as an integer (FRCINT), 16 bits."""
        value = self.variable()
        if isinstance(value, str):
            raise error_for(TYPE_MISMATCH)
        k = nearest_integer(value)
        if not -32768 <= k <= 32767:
            raise error_for(OVERFLOW)
        return k & 0xFFFF

    def _value_of(self, name: str):
        """The value of the variable ``name`` (capitals, perhaps with subscripts) as ISVAR
        finds it: a simple variable or an array element (made as a reference would make it)."""
        found = _VARIABLE.match(name)
        base, mark, subscripts = found.groups()
        machine = self.machine
        full = machine.variable_name(base + (mark or machine.def_types.get(base[0], "!")))
        if subscripts is None:
            return machine.scalars.get(full, "" if full.endswith("$") else 0.0)
        indices = [self._subscript(s) for s in subscripts.split(",")]
        element = machine.array_nd(full, len(indices))
        try:
            for k in indices[:-1]:
                element = element[k]
            return element[indices[-1]]
        except IndexError:
            raise error_for(SUBSCRIPT_OUT_OF_RANGE) from None

    def _subscript(self, text: str) -> int:
        """A subscript: a number or a simple numeric variable (INTIDX: rounded; negative
        Illegal function call, below OPTION BASE Subscript out of range)."""
        if text.replace(".", "", 1).isdigit():
            value = float(text)
        elif _VARIABLE.fullmatch(text) and not text.endswith("$"):
            value = self._value_of(text)
        else:
            raise not_emulated(f"PLAY's subscript {text}")
        k = nearest_integer(value)
        if k < 0:
            raise _illegal()
        if k < self.machine.subscript_base:
            raise error_for(SUBSCRIPT_OUT_OF_RANGE)
        return k

    def execute(self) -> None:
        """MCLXEQ: X and a string variable: its text is read now, then the rest of this one."""
        value = self.variable()
        if not isinstance(value, str):
            raise error_for(TYPE_MISMATCH)
        if value:
            if len(self.reader.stack) > X_DEPTH:
                raise error_for(OUT_OF_MEMORY)
            self.reader.stack.append([value, 0])


class Player(Macro):
    """One PLAY statement's reading of its string, playing into ``music`` (machine/music.py)."""

    def __init__(self, music, text: str):
        super().__init__(music.machine, text)
        self.music = music

    # -- the commands (PLYTAB)
    def command(self, c: str) -> None:
        """One command, its letter read (MCLSCN: not in the table, Illegal function call)."""
        music = self.music
        if "A" <= c <= "G":
            self.note_letter(c)
        elif c == "M":
            self.meta(self.reader.fetch_needed())
        elif c in "NOPTL":
            given, n = self.argument()
            low = n & 0xFF  # the commands compare DL, the value's low byte
            if c == "N":
                self.note_number(given, low)
            elif c == "O":
                if not given or low >= 7:
                    raise _illegal()
                music.octave = low
            elif c == "P":
                if not given or low >= 65:
                    raise _illegal()
                if low:
                    self.sound(0, low)
            elif c == "T":
                if low < 32:
                    raise _illegal()
                music.beats = low
            else:
                if not given or low >= 65 or low == 0:
                    raise _illegal()
                music.length = low
        elif c == "X":
            self.execute()
        elif c == ">":
            music.octave = min(music.octave + 1, 6)
        elif c == "<":
            music.octave = max(music.octave - 1, 0)
        else:
            raise _illegal()

    def meta(self, c: str) -> None:
        """PLYMET: ML legato, MS staccato, MN normal (MSCALE 1, 2, 3), MF, MB."""
        music = self.music
        if c in "LSN":
            music.scale = "LSN".index(c) + 1
        elif c in "FB":
            music.background = c == "B"
        else:
            raise _illegal()

    def note_letter(self, c: str) -> None:
        """PLYNOT: a letter, perhaps a sharp or a flat; a note the table lacks is Illegal
        function call."""
        index = 2 * (ord(c) - 64)  # as if sharp
        mark = self.reader.fetch()
        if mark is None or mark not in "#+-":
            if mark is not None:
                self.reader.back()
            index -= 1
        elif mark == "-":
            index -= 2
        semitone = NOTE_INDEX[index]
        if semitone is None:
            raise _illegal()
        self.tone(semitone, self.music.octave)

    def note_number(self, given: bool, n: int) -> None:
        """PLYNUM: N0 a pause of the length, N1..N84 the notes from octave 0's C."""
        if not given or n >= 85:
            raise _illegal()
        if n == 0:
            self.tone(0, self.music.octave)
        else:
            octave, semitone = divmod(n - 1, 12)
            self.tone(semitone + 1, octave)

    def tone(self, semitone: int, octave: int) -> None:
        """PLYNU3: a note (semitone 0: a pause) with the length that may follow (1..64; 0 or
        none: L's), then played."""
        length = self.music.length
        c = self.reader.fetch()
        if c is not None:
            n = self.digits(c) & 0xFF
            if n >= 65:
                raise _illegal()
            length = n or length
        frequency = 0
        if semitone:
            top = TOP_OCTAVE[semitone - 1]
            shift = 6 - octave
            frequency = (top >> shift) + ((top >> (shift - 1)) & 1 if shift else 0)  # rounded up
        self.sound(frequency, length)

    def sound(self, frequency: int, length: int) -> None:
        """PPAUS2: the duration of a 1/length note at the tempo, times 1.5 for each dot
        (16 bits; more is Illegal function call), then the tone with the silence after it
        that ML/MN/MS ask for (PLYNO6: 7/8 normal, 3/4 staccato); a pause is whole."""
        music = self.music
        units = DIVIDEND // (music.beats * length)
        if not units:
            return
        while True:
            c = self.reader.fetch()
            if c != ".":
                if c is not None:
                    self.reader.back()
                break
            product = units * 3
            if product >> 17:
                raise _illegal()
            units = (product & 0xFFFF) >> 1  # as the source: the low word halved
        if frequency == 0 or music.scale == 1:
            music.note(frequency, units)
            return
        factor = 3 if music.scale == 2 else 7
        sounding = ((units * factor) & 0xFFFF) >> music.scale
        music.note(frequency, sounding or 1)
        silence = units >> music.scale
        if silence:
            music.note(0, silence, counts=False)


def play(music, text: str) -> None:
    """PLAY text (MACLNG with PLYTAB)."""
    Player(music, text).run()
