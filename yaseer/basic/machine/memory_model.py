"""The bytes GW-BASIC's FRE reports: its 64 KB segment as the program and the variables
use it, counted from what the machine holds (yaseer keeps its values in Python, so this
is a model of GW-BASIC's layout, not a measurement).

GW-BASIC keeps, from the bottom of its segment up, the tokenised program, the simple
variables, the arrays, and from the top down the strings; FRE is what lies between
(PC-BASIC 2.0.8 counts the same way, ``memory.py`` ``_get_free``).  With no program
60300 bytes are free (the figure GW-BASIC's banner shows; ``Dialect.free_memory``).

* a program line: a 2-byte link, a 2-byte line number, its tokens and a 0 byte; a
  keyword one byte (two for the 0xFD/0xFE/0xFF tables' words: FRE, CHR$, FIELD ...,
  and for ELSE, which a colon precedes),
  an integer literal 1 (0-9), 2 (10-255) or 3 bytes, a line number after a jump 3, a
  single 5, a double 9, and every other character (blanks included) one byte;
* a simple variable: its type, two name characters, the count of the others and those
  others, then its value (2 bytes an integer, 4 a single, 8 a double, 3 a string's
  descriptor); one that was never given a value other than 0 or "" is not counted (GW
  makes one when it is first assigned);
* a DEF FN: that header and 4 bytes, and 8 bytes a parameter (PC-BASIC 2.0.8's count);
* an array: that header with its size (2), dimension count (1) and 2 bytes a dimension,
  then its elements;
* the strings: every string value's characters but those that stay in the program text
  (a literal assigned, a string READ from DATA, a copy of either: GW's LETCN6 copies none;
  a literal of one character is counted, as Python shares it with made strings); FRE(0) also counts the garbage
  the strings made since the last collection left (machine/string_space.py), FRE("")
  collects it first.
"""

from __future__ import annotations

import re

from yaseer.basic.machine.program_file import TOKENS, TWO_BYTE_TOKENS
from yaseer.basic.source.scanner import EXACT_DOUBLE

_VALUE_BYTES = {"%": 2, "!": 4, "#": 8, "$": 3}
_ONE_BYTE = frozenset(word for word in TOKENS.values() if word.isalpha() or word.endswith(("$", "(")))
_TWO_BYTES = frozenset(word for table in TWO_BYTE_TOKENS.values() for word in table.values())
_JUMPS = frozenset(("GOTO", "GOSUB", "THEN", "ELSE", "RESTORE", "RUN", "RESUME", "LIST", "DELETE", "RETURN"))
_PIECE = re.compile(r'\x1f[0-9A-F]{16}|"[^"]*"?|[A-Za-z][A-Za-z0-9.]*[$%!#]?|&[HhOo]?[0-9A-Fa-f]+|[0-9.]+(?:[EeDd][-+]?[0-9]+)?[%!#]?|.')


def line_bytes(text: str) -> int:
    """The bytes line ``text`` (without its number) takes tokenised (see the module docstring)."""
    size = 5
    after_jump = False
    for piece in _PIECE.findall(text):
        first = piece[0]
        if first.isalpha():
            word = piece.upper()
            if word in ("REM", "DATA"):
                return size + len(text) - text.upper().find(word) - len(word) + 1
            if word in _TWO_BYTES:
                size += 2
            elif word in _ONE_BYTE or word.rstrip("(") in _ONE_BYTE:
                size += 1 + (word == "ELSE")  # CRUNCH stores a colon before ELSE (KRNSVC)
            elif word.startswith("FN") and len(word) > 2:
                size += 1 + len(word) - 2
            else:
                size += len(piece)
            after_jump = word in _JUMPS
            continue
        if first == "'":
            return size + len(text) - text.find("'") + 2
        if first == EXACT_DOUBLE and len(piece) > 1:  # a file's double constant kept as its 8 bytes
            size += 9
            continue
        if first.isdigit() or (first == "." and len(piece) > 1) or first == "&":
            size += _number_bytes(piece, after_jump)
            continue
        if first not in " ,":
            after_jump = False
        size += len(piece)
    return size


def _number_bytes(piece: str, line_number: bool) -> int:
    if piece[0] == "&":
        return 3
    if line_number and piece.isdigit():
        return 3
    if piece.isdigit() and int(piece) <= 32767:
        value = int(piece)
        return 1 if value <= 9 else 2 if value <= 255 else 3
    digits = len(piece.rstrip("%!#").replace(".", "").lstrip("0"))
    return 9 if piece.endswith("#") or "D" in piece.upper() or digits > 7 else 5


def _name_bytes(name: str) -> int:
    """A variable's header: its type, two name characters, the count of the others and those."""
    letters = len(name.rstrip("%!#$"))
    return 4 + max(letters - 2, 0)


def free_bytes(total: int, program: dict, scalars: dict, arrays: dict, array_dims: dict, fns: dict) -> int:
    """FRE: of ``total`` bytes (none used by a program), those left between the program and
    variables and the strings."""
    free, _ = free_and_strings(total, program, scalars, arrays, array_dims, fns)
    return free


def free_and_strings(total: int, program: dict, scalars: dict, arrays: dict, array_dims: dict,
                     fns: dict, text=()) -> tuple[int, int]:
    """(:func:`free_bytes`, the bytes of those strings); a string whose id is in ``text``
    stays in the program text (a literal's, DATA's) and takes no string space."""
    used = sum(line_bytes(text) for text in program.values())
    strings = 0
    for name, value in scalars.items():
        if type(value) is str:
            if value:
                used += _name_bytes(name) + 3
                if id(value) not in text:
                    strings += len(value)
        elif value:
            used += _name_bytes(name) + _VALUE_BYTES.get(name[-1], 4)
    for name, (_, parameters) in fns.items():  # a DEF FN: its entry, and a variable a parameter
        used += _name_bytes(name) + 4 + 8 * parameters
    for name, dims in array_dims.items():
        elements = 1
        for size in dims:
            elements *= size + 1
        used += _name_bytes(name) + 3 + 2 * len(dims) + elements * _VALUE_BYTES.get(name[-1], 4)
        if name.endswith("$"):
            strings += sum(len(v) for v in flat_strings(arrays.get(name, ())) if id(v) not in text)
    return total - used - strings, strings


def flat_strings(values):
    """The strings of array ``values`` (nested lists), every dimension walked."""
    for value in values:
        if isinstance(value, list):
            yield from flat_strings(value)
        elif type(value) is str:
            yield value
