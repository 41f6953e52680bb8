"""RENUM: a program's lines renumbered, and the line numbers its statements name with them.

As GW-BASIC does it (GWMAIN.ASM ``RESEQ``): lines from ``old`` on become ``new``, ``new +
step``, ...; the line numbers in the text are the ones its tokeniser stored as line numbers
(CRUNCH: a number after one of the words of ``LINRES`` - GOTO, GOSUB, THEN, ELSE, RESTORE,
RESUME, RUN, RETURN, LIST, LLIST, DELETE, EDIT, AUTO, RENUM, ERL - and after the commas,
operators and blanks that follow, until a name, another word or a colon: so ``ON X GOTO
10, 20`` and ``IF ERL = 100`` are renumbered, ``PRINT 100`` is not).  A number that names
no line is left as it is, with the message ``Undefined line n in m`` (m the line's old
number: ``SCCLIN`` prints it before the lines change); ``ON ERROR GOTO 0`` is left without
one.  ``Illegal function call``: an increment of 0, new numbers past 65529, or new numbers
that would reach down to a line below ``old`` (the program would be out of order).
"""

from __future__ import annotations

from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL
from yaseer.basic.source.scanner import line_number_spans

LAST_LINE = 65529  # the highest line number GW-BASIC takes


def renumber_text(text: str, mapping: dict[int, int], dialect) -> tuple[str, list[int]]:
    """``text`` (one line's statements) with the line numbers it names replaced through
    ``mapping``; and those that ``mapping`` does not hold (left as they are)."""
    missing: list[int] = []
    pieces, position = [], 0
    for start, end, number in line_number_spans(text, dialect):
        if number not in mapping:
            missing.append(number)
            continue
        pieces += [text[position:start], str(mapping[number])]
        position = end
    pieces.append(text[position:])
    return "".join(pieces), missing


def renumber(program: dict[int, str], new: int = 10, old: int = 0, step: int = 10,
             dialect=None) -> tuple[dict[int, str], list[str]]:
    """RENUM new, old, step of ``program`` (line -> text): the new program and the messages
    (``"Undefined line 90 in 30"``) for numbers that name no line (see the module docstring)."""
    if step <= 0:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    numbers = sorted(program)
    moved = [number for number in numbers if number >= old]
    if any(new <= number < old for number in numbers):  # RESEQ: NN's line before MM's
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    if moved and new + (len(moved) - 1) * step > LAST_LINE:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    mapping = {number: number for number in numbers}
    mapping.update((number, new + k * step) for k, number in enumerate(moved))
    result: dict[int, str] = {}
    messages: list[str] = []
    for number in numbers:
        text, missing = renumber_text(program[number], mapping, dialect)
        result[mapping[number]] = text
        messages += [f"Undefined line {target} in {number}" for target in missing]
    return result, messages
