"""A program's text -> GW-BASIC's tokenised bytes, as GW-BASIC's CRUNCH stores a typed line
(GWMAIN.ASM CRUNCH, IBMRES.ASM CRUNCX); the inverse of program_file.detokenise.

SAVE "f",P writes these bytes scrambled (program_file.protect); the reading side is
machine/program_file.py.  What CRUNCH does to a line, character by character:

* a string (``"`` to the next ``"`` or the end of the line) is stored as it is; so is
  everything after REM, after ``'`` (stored as ``:`` REM 0xD9) and after DATA up to the
  next ``:`` outside quotes;
* a reserved word (matched case-insensitively, the longest one the tables hold there)
  becomes its token (one byte, two for the 0xFD/0xFE/0xFF tables' words); ELSE is stored
  after a ``:`` (KRNSVC), WHILE with a ``+`` token after it.  A word followed by a letter
  or digit is no reserved word (``FORI`` is a name) unless it ends in ``(`` or is FN or
  USR (no blank needed: ``FNA``).  ``?`` is PRINT; ``GO TO``/``GO SUB`` are GOTO/GOSUB;
* a name is stored in capitals with its letters, digits and dots;
* a number is stored by its type (MATH1.ASM FIN reads it; blanks inside it are dropped):
  an integer 0-9 as one byte 0x11-0x1A, 10-255 as 0x0F and a byte, else 0x1C and two
  bytes; a single 0x1D and MKS$'s 4 bytes, a double 0x1F and MKD$'s 8; ``&H``/``&O`` as
  0x0C/0x0B and two bytes (the blanks after an octal number are gone with it);
* after GOTO, GOSUB, THEN, ELSE, RESTORE, RESUME, RUN, LIST, LLIST, DELETE, EDIT, RENUM,
  AUTO, RETURN and ERL (LINRES) a number is a line number: 0x0E and two bytes, until a
  ``:``, a name or another reserved word; digits right after a name stay text
  (``OPTION BASE 1``: BASE is a name, its ``1`` is the character);
* ``+ - * / ^ \\ > = <`` are operator tokens; a control character other than TAB and LF
  is stored as a blank; a character from 128 up outside strings, REM and DATA is dropped
  (NTDATA skips it).

A program in memory is its lines from ``TEXT_START`` up, each a 2-byte link (the address
of the next line), the 2-byte line number, the tokens and a 0 byte, then a 0 link; the
file holds exactly these bytes after its first byte.
"""

from __future__ import annotations

from yaseer.basic.errors import OVERFLOW, BasicError, error_for
from yaseer.basic.machine.gwfunctions import mkd, mks
from yaseer.basic.machine.program_file import (
    END_OF_FILE, TOKENISED, TOKENS, TWO_BYTE_TOKENS, line_text, protected_file,
)
from yaseer.basic.source.scanner import (
    EXACT_MARKERS, LINE_NUMBER_WORDS, STORED_ELSE, STORED_NAME, detokenize, exact_constant, gw_number, linget,
    radix_number,
)

# GW-BASIC 3.23's program start (TXTTAB) with its default /F:3 /S:128 file buffers: the
# address the links of a SAVEd program count from (PC-BASIC 2.0.8 uses the same).
TEXT_START = 0x126E

_WORDS: dict[str, bytes] = {word: bytes((code,)) for code, word in TOKENS.items() if word[0].isalpha()}
_WORDS.update({word: bytes((prefix, code)) for prefix, table in TWO_BYTE_TOKENS.items()
               for code, word in table.items()})
_LONGEST = max(map(len, _WORDS))
_OPERATORS = {word: bytes((code,)) for code, word in TOKENS.items() if word in "+-*/^\\>=<" and len(word) == 1}
_NO_BLANK_AFTER = frozenset(("FN", "USR"))
_CAPITALS = str.maketrans("abcdefghijklmnopqrstuvwxyz", "ABCDEFGHIJKLMNOPQRSTUVWXYZ")
_NAME = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.")
_LINE_NUMBER, _NUMBER, _IN_NAME = 1, 0, -1  # DONUM: what a digit starts
_COLON, _REM, _QUOTE_REM, _DATA, _ELSE, _WHILE, _PLUS = 0x3A, 0x8F, 0xD9, 0x84, 0xA1, 0xB1, 0xE9


def crunch_line(text: str) -> bytes:
    """The tokens of a program line's ``text`` (after its number; characters are the
    machine's codes 0-255), as CRUNCH stores them (see the module docstring)."""
    upper = text.translate(_CAPITALS)  # a-z only (MAKUPL): str.upper() makes code 223 two letters
    n = len(text)
    out = bytearray()
    donum = _NUMBER
    data = False  # after DATA: characters are stored as they are up to a ':'
    i = 0
    while i < n:
        c = text[i]
        if c == '"':
            close = text.find('"', i + 1)
            end = n if close < 0 else close + 1
            out += _codes(text[i:end])
            i = end
        elif c == " ":
            out.append(0x20)
            i += 1
        elif c == STORED_ELSE and not data and upper.startswith("ELSE", i + 1):
            out += _WORDS["ELSE"]  # the token alone: a file's ELSE without its ":"
            donum = _LINE_NUMBER
            i += 5
        elif c == STORED_NAME and not data:
            end = i + 1
            while end < n and upper[end] in _NAME:
                end += 1
            out += text[i + 1:end].encode("ascii")  # a file's name that spells a word, its letters as the file had them
            donum = _IN_NAME
            i = end
        elif c in EXACT_MARKERS and not data and exact_constant(upper, i) is not None:
            marker, constant, i = exact_constant(upper, i)  # a file's number constant: its own bytes back
            out += _codes(marker) + constant
        elif data:
            out += _codes(c)
            i += 1
            if c == ":":
                data, donum = False, _NUMBER
        elif ord(c) >= 0x80:
            i += 1
        elif c == "?":
            out.append(0x91)  # PRINT
            donum = _NUMBER
            i += 1
        elif c.isalpha() and c.isascii():
            word, end = _reserved_word(upper, i)
            if word is None:
                while end < n and upper[end] in _NAME:
                    end += 1
                out += upper[i:end].encode("ascii")
                donum = _IN_NAME
            else:
                if word == "ELSE":
                    out.append(_COLON)
                out += _WORDS[word]
                if word == "WHILE":
                    out.append(_PLUS)
                elif word == "REM":
                    return bytes(out + _codes(text[end:]))
                data = word == "DATA"
                donum = _LINE_NUMBER if word in LINE_NUMBER_WORDS else _NUMBER
            i = end
        elif c.isdigit() or c == ".":
            if donum == _IN_NAME or (donum == _LINE_NUMBER and c == "."):
                out += _codes(c)
                i += 1
            elif donum == _LINE_NUMBER:
                number, i = linget(text, i)
                out += bytes((0x0E,)) + number.to_bytes(2, "little")
            else:
                (value, kind), i = gw_number(upper, i)
                out += _number(value, kind)
        elif c == "&":
            hexadecimal = upper[i + 1:].lstrip(" \t\n")[:1] == "H"  # OCTCNS reads the letter with CHRGTR
            value, i = radix_number(upper, i)
            if value > 0xFFFF:
                raise error_for(OVERFLOW)
            out += bytes((0x0C if hexadecimal else 0x0B,)) + value.to_bytes(2, "little")
            while not hexadecimal and i < n and text[i] in " \t\n":
                i += 1  # OCTCNS reads its digits with CHRGTR, past the blanks after them (no BAKSP)
        elif c == "'":
            return bytes(out + bytes((_COLON, _REM, _QUOTE_REM)) + _codes(text[i + 1:]))
        else:
            if donum == _IN_NAME:
                donum = _NUMBER
            if c in _OPERATORS:
                out += _OPERATORS[c]
            else:
                out += _codes(c if ord(c) >= 32 or c in "\t\n" else " ")
                if c == ":":
                    donum = _NUMBER
            i += 1
    return bytes(out)


def _codes(text: str) -> bytes:
    return text.encode("latin-1", errors="replace")


def _reserved_word(upper: str, i: int) -> tuple[str | None, int]:
    """The reserved word at ``upper[i]`` and the position after it, or (None, i): the
    longest word of the tables there; not one if a letter or digit follows it (but for
    words ending in ``(``, FN and USR).  ``GO TO`` and ``GO SUB`` are GOTO and GOSUB."""
    if upper.startswith("GO ", i):
        after = upper[i + 2:i + 6]
        if after == " SUB":
            return "GOSUB", i + 6
        if after[:3] == " TO" and after[3:4] not in _NAME:
            return "GOTO", i + 5
        if after[:2] == "  ":
            j = i + 2
            while upper.startswith(" ", j):
                j += 1
            if upper.startswith("TO", j):
                return "GOTO", j + 2
    for length in range(min(_LONGEST, len(upper) - i), 0, -1):
        word = upper[i:i + length]
        if word in _WORDS:
            after = upper[i + length:i + length + 1]
            if word[-1] == "(" or word in _NO_BLANK_AFTER or not (after.isalnum() and after.isascii()):
                return word, i + length
            return None, i
    return None, i


def _number(value, kind: str) -> bytes:
    """A number constant's bytes: its type's token and value (see the module docstring)."""
    if kind == "%":
        value = int(value)
        if 0 <= value <= 9:
            return bytes((0x11 + value,))
        if 10 <= value <= 255:
            return bytes((0x0F, value))
        return bytes((0x1C,)) + value.to_bytes(2, "little", signed=True)
    if kind == "!":
        return bytes((0x1D,)) + _codes(mks(value))
    return bytes((0x1F,)) + _codes(mkd(value))


def tokenised_program(program: dict[int, str], start: int = TEXT_START) -> bytes:
    """Program ``program`` (line number -> text) as GW-BASIC holds it in memory from
    address ``start``: each line's link, number, tokens and 0, then the 0 link."""
    out = bytearray()
    for number in sorted(program):
        body = number.to_bytes(2, "little") + crunch_line(program[number]) + bytes(1)
        out += (start + len(out) + 2 + len(body)).to_bytes(2, "little") + body
    return bytes(out + bytes(2))


def saved_program(program: dict[int, str], option: str, dialect) -> bytes:
    """The bytes SAVE writes for ``program`` (line number -> text in the machine's codes,
    ``chr(0..255)``; a character beyond is written as ``?``): the one writer of program
    files, for the session's SAVE and a program's.  ``option`` "P": GW-BASIC's protected
    form (GIODSK.ASM PROSAV: 0xFE, the tokens scrambled by PENCOD, a Ctrl-Z); "A": the
    ``dialect``'s listing (:func:`listing_text`, :func:`ascii_file`); "" (a plain SAVE):
    where the dialect keeps tokens (``tokenised_programs``) its tokenised form (GIODSK.ASM
    BINSAV: 0xFF, the tokens, a Ctrl-Z), else the listing."""
    if option == "P":
        return protected_file(tokenised_program(program))
    if option == "" and dialect.tokenised_programs:
        return bytes((TOKENISED,)) + tokenised_program(program) + bytes((END_OF_FILE,))
    return ascii_file(listing_text(program, dialect))


def listing_text(program: dict[int, str], dialect) -> str:
    """``program``'s lines as LIST writes them to a file, each ending in CR LF (SAVE ,A)."""
    return "".join(listed_row(n, program[n], dialect, True) + "\r\n" for n in sorted(program))


def listed_row(number: int, text: str, dialect, to_file: bool = False) -> str:
    """Line ``number`` with its ``text`` as LIST shows it: the number, a blank, the line
    (:func:`listed_line`).  Where the ``dialect`` keeps programs as tokens, as GWLIST.ASM LIST
    writes it: no blank when the line starts with a TAB (NOSPAL), a blank that begins line 0
    (which LOAD keeps there, GWMAIN.ASM MAIN) not shown, as a real GW-BASIC 3.23 lists it
    (PC-BASIC's recorded line_number_0 test); ``to_file``: each LF of the line written LF CR
    (SCNEDT.ASM OUTCH1, so that LOAD reads the line back whole)."""
    body = listed_line(text, dialect)
    if not dialect.tokenised_programs:
        return f"{number} {body}"
    if number == 0 and body.startswith(" "):
        body = body[1:]
    if to_file:
        body = body.replace("\n", "\n\r")
    return f"{number}{'' if body.startswith(chr(9)) else ' '}{body}"


def listed_line(text: str, dialect) -> str:
    """A line's text (the machine's codes) as LIST shows it after its number: where the
    ``dialect`` keeps programs as tokens (``tokenised_programs``, GW-BASIC), the tokens
    CRUNCH makes of it listed back (GWLIST.ASM LIST: keywords and names in capitals, the
    blanks as typed); else the dialect's listing (scanner.detokenize).  A line CRUNCH
    refuses (a ``&H`` constant beyond 65535) is shown as it is."""
    if not dialect.tokenised_programs:
        return detokenize(text, dialect)
    try:
        return line_text(crunch_line(text))
    except BasicError:
        return text


def ascii_file(text: str) -> bytes:
    """An ASCII program file's bytes: ``text`` (the machine's codes) and the Ctrl-Z GW-BASIC
    ends a file with (GIODSK.ASM DSKEOF)."""
    return _codes(text) + bytes((END_OF_FILE,))
