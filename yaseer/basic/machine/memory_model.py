"""The bytes GW-BASIC's FRE reports: its 64 KB segment as the program and the variables
use it, counted from what the machine holds (yaseer keeps its values in Python, so this
is a model of GW-BASIC's layout, not a measurement).

GW-BASIC keeps, from the bottom of its segment up, the tokenised program, the simple
variables, the arrays, and from the top down the strings; FRE is what lies between
(PC-BASIC 2.0.8 counts the same way, ``memory.py`` ``_get_free``).  With no program
60300 bytes are free (the figure GW-BASIC's banner shows; ``Dialect.free_memory``).

* a program line (a program that does not fit is Out of memory at the line that does
  not fit, typed or read from a file: GWMAIN.ASM's line insertion after NODEL moves the
  program up with BLTU, whose REASON refuses an end past FRETOP, the strings forgotten;
  the lines before it stay: :func:`fitting_lines`): a 2-byte link, a 2-byte line number, its tokens as CRUNCH stores them
  (machine/program_crunch.py: a number after GOTO, ERL, LIST ... a 3-byte line-number
  token, LINRES) and a 0 byte;
* a simple variable: its type, two name characters, the count of the others and those
  others, then its value (2 bytes an integer, 4 a single, 8 a double, 3 a string's
  descriptor); one holding 0 or "" only where a statement made it (GW's PTRGET makes it
  when LET, FOR, INPUT, READ ... first name it, before the value is worked out; a
  program that reads FRE records the makings: compiler.made);
* a DEF FN: a simple variable's entry of the function's type, its parameters' variables
  made by the DEF (GWEVAL.ASM DEF: GETFNM, then SCNLIS's PTRGET each);
* an array: that header with its size (2), dimension count (1) and 2 bytes a dimension,
  then its elements;
* the strings: every string value's characters but those that stay in the program text
  (a literal assigned, a string READ from DATA, a copy of either: GW's LETCN6 copies none;
  a literal of one character is counted, as Python shares it with made strings); FRE(0) also counts the garbage
  the strings made since the last collection left (machine/string_space.py), FRE("")
  collects it first.
"""

from __future__ import annotations

from yaseer.basic.errors import OUT_OF_MEMORY, BasicError
from yaseer.basic.machine.program_crunch import crunch_line

_VALUE_BYTES = {"%": 2, "!": 4, "#": 8, "$": 3}
FN_KEY = "\0FN"  # a DEF FN's place among the made names (``made``: FN_KEY + its name)
_LINE_BYTES: dict[str, int] = {}  # a line's text -> its bytes (FRE counts every line each time)


def line_bytes(text: str) -> int:
    """The bytes line ``text`` (without its number) takes in GW-BASIC's program text: its
    link, number, tokens and 0 (a line CRUNCH would not take, as its characters)."""
    size = _LINE_BYTES.get(text)
    if size is None:
        try:
            size = len(crunch_line(text)) + 5
        except BasicError:  # (an &H number past &HFFFF: GW refuses the line)
            size = len(text) + 5
        if len(_LINE_BYTES) > 50_000:
            _LINE_BYTES.clear()
        _LINE_BYTES[text] = size
    return size


_MOST_BYTES_A_CHARACTER = 5  # "1#" is 9 bytes (a double), "GOTO 1" stores its 1 as 3


def program_bytes(program: dict) -> int:
    """The bytes the lines of ``program`` (number -> text) take in GW-BASIC's program text."""
    return sum(line_bytes(text) for text in program.values())


def fitting_lines(program: dict, lines: dict, total: int | None) -> tuple[dict, BasicError | None]:
    """``program`` (number -> text) with ``lines`` entered one by one in their order, as
    GW-BASIC enters a typed line or one LOAD, MERGE or CHAIN reads: each replaces the line of
    its number (a number with None: deletes the line), and the first that would take the
    program past ``total`` bytes (None: no limit) is Out of memory, the lines before it entered (REASON: the program may end
    exactly at the top).  (The new program, that error or None.)"""
    merged = dict(program)
    deleted = [number for number, text in lines.items() if text is None]
    if deleted:  # (a MERGE file's bare number of a program line: scanner.program_lines)
        lines = {number: text for number, text in lines.items() if text is not None}
        for number in deleted:
            merged.pop(number, None)
    if total is None:
        merged.update(lines)
        return merged, None
    # a bound from the characters first: most programs are not tokenised to know they fit
    texts = list(merged.values()) + list(lines.values())
    if sum(_MOST_BYTES_A_CHARACTER * len(text) + 5 for text in texts) <= total:
        merged.update(lines)
        return merged, None
    used = program_bytes(merged)
    for number, text in lines.items():
        used += line_bytes(text) - (line_bytes(merged[number]) if number in merged else 0)
        if used > total:  # (the old line of the number was deleted first: ERAINS calls DEL)
            merged.pop(number, None)
            return merged, BasicError("Out of memory", OUT_OF_MEMORY)
        merged[number] = text
    return merged, None


def variable_bytes(name: str) -> int:
    """The bytes simple variable ``name`` (with its type character) takes: header and value."""
    return _name_bytes(name) + _VALUE_BYTES.get(name[-1], 4)


def function_bytes(name: str) -> int:
    """The bytes DEF FN ``name`` (with its type character) takes: a simple variable's entry
    of the function's type (GWEVAL.ASM DEF; PC-BASIC 2.0.8 counts the same)."""
    return variable_bytes(name)


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
                     fns: dict, text=(), made=()) -> tuple[int, int]:
    """(:func:`free_bytes`, the bytes of those strings); a string whose id is in ``text``
    stays in the program text (a literal's, DATA's) and takes no string space; a simple
    variable named in ``made`` is counted whatever it holds (a statement made it)."""
    used = program_bytes(program)
    strings = 0
    for name, value in scalars.items():
        if type(value) is str:
            if value:
                used += _name_bytes(name) + 3
                if id(value) not in text:
                    strings += len(value)
            elif name in made:
                used += _name_bytes(name) + 3
        elif value or name in made:
            used += _name_bytes(name) + _VALUE_BYTES.get(name[-1], 4)
    for name in fns:  # a DEF FN's entry (its parameters are variables: DEF made them)
        used += function_bytes(name)
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
