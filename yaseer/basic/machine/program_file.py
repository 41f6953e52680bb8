"""A program file's bytes -> the program's text, as GW-BASIC's LOAD reads a file.

Three kinds of file, told apart by the first byte (DSKCOM.ASM, the LOAD code after
``NOTINI``):

* ``0xFF``: a tokenised program (GW-BASIC's plain ``SAVE``): lines of a 2-byte
  link, a 2-byte line number, the tokens and a 0 byte; a zero link ends it.
  :func:`detokenise` turns it back into the text LIST would show.
* ``0xFE``: a protected program (``SAVE "f",P``): a tokenised one whose bytes are
  scrambled with two tables of 11 and 13 bytes (GIODSK.ASM ``PENCOD``/``PDECOD``);
  :func:`unprotect` undoes it.
* anything else: ASCII text (``SAVE "f",A`` or an editor); reading stops at the
  first Ctrl-Z (``chr(26)``, GIODSK.ASM ``DSKEOF``/``CHKCTZ``: the end-of-file mark
  DOS editors leave); a UTF-8 byte-order mark before the first line is dropped
  (GW-BASIC would call that line a direct statement; an editor's mark is no part
  of the program).  Text that is not UTF-8 is read byte for byte (latin-1, the
  byte values CHR$ gives).
"""

from __future__ import annotations

from yaseer.basic.arithmetic import mbf_double
from yaseer.basic.arithmetic.values import DOUBLE_DIGITS, SINGLE_DIGITS, double_of, unsigned_text
from yaseer.basic.machine.gwfunctions import _from_mbf, mks
from yaseer.basic.source.scanner import STORED_ELSE, STORED_NAME, gw_number

END_OF_FILE = 0x1A  # Ctrl-Z
TOKENISED = 0xFF
PROTECTED = 0xFE
BYTE_ORDER_MARK = b"\xef\xbb\xbf"

# The token values, in the order of IBMRES.ASM's tables (``R``/``T`` macros count up
# from the table's start); "" marks a padding entry.  PCOPY LOCK UNLOCK EXTERR are
# GW-BASIC 3.2's additions (their values as PC-BASIC 2.0.8 saves them).
_STATEMENTS = (  # 0x81 ...
    "END FOR NEXT DATA INPUT DIM READ LET GOTO RUN IF RESTORE GOSUB RETURN REM STOP PRINT "
    "CLEAR LIST NEW ON WAIT DEF POKE CONT _ _ OUT LPRINT LLIST _ WIDTH ELSE TRON TROFF SWAP "
    "ERASE EDIT ERROR RESUME DELETE AUTO RENUM DEFSTR DEFINT DEFSNG DEFDBL LINE WHILE WEND "
    "CALL _ _ _ WRITE OPTION RANDOMIZE OPEN CLOSE LOAD MERGE SAVE COLOR CLS MOTOR BSAVE "
    "BLOAD SOUND BEEP PSET PRESET SCREEN KEY LOCATE _ TO THEN TAB( STEP USR FN SPC( NOT ERL "
    "ERR STRING$ USING INSTR ' VARPTR CSRLIN POINT OFF INKEY$ _ _ _ _ _ _ _ > = < + - * / ^ "
    "AND OR XOR EQV IMP MOD \\"
)
_FUNCTIONS = (  # 0xFF 0x81 ...
    "LEFT$ RIGHT$ MID$ SGN INT ABS SQR RND SIN LOG EXP COS TAN ATN FRE INP POS LEN STR$ VAL "
    "ASC CHR$ PEEK SPACE$ OCT$ HEX$ LPOS CINT CSNG CDBL FIX PEN STICK STRIG EOF LOC LOF"
)
_EXTENDED = (  # 0xFE 0x81 ...
    "FILES FIELD SYSTEM NAME LSET RSET KILL PUT GET RESET COMMON CHAIN DATE$ TIME$ PAINT COM "
    "CIRCLE DRAW PLAY TIMER ERDEV IOCTL CHDIR MKDIR RMDIR SHELL ENVIRON VIEW WINDOW PMAP "
    "PALETTE LCOPY CALLS _ _ _ PCOPY _ LOCK UNLOCK"
)
_EXTENDED_FUNCTIONS = "CVI CVS CVD MKI$ MKS$ MKD$ _ _ _ _ EXTERR"  # 0xFD 0x81 ...


def _table(words: str, first: int) -> dict[int, str]:
    return {first + k: word for k, word in enumerate(words.split(" ")) if word != "_"}


TOKENS: dict[int, str] = _table(_STATEMENTS, 0x81)
TWO_BYTE_TOKENS: dict[int, dict[int, str]] = {
    0xFF: _table(_FUNCTIONS, 0x81), 0xFE: _table(_EXTENDED, 0x81), 0xFD: _table(_EXTENDED_FUNCTIONS, 0x81),
}
_REM, _ELSE, _QUOTE_REM, _DATA, _WHILE, _PLUS = 0x8F, 0xA1, 0xD9, 0x84, 0xB1, 0xE9

# GIODSK.ASM PDECOD: the key bytes are those of two coefficient tables of MATH1.ASM,
# $EXPCN (bytes 1..11) and $LOGP (bytes 1..13), indexed by counters running down.
_EXPCN = bytes((0o174, 0o210, 0o131, 0o164, 0o340, 0o227, 0o046, 0o167, 0o304, 0o035, 0o036))
_LOGP = bytes((0o232, 0o367, 0o031, 0o203, 0o044, 0o143, 0o103, 0o203, 0o165, 0o315, 0o215, 0o204, 0o251))


def program_text(data: bytes, charset=None, exact: bool = True) -> str:
    """The text of a program file's ``data`` (any of the three kinds, see the module docstring),
    as it is shown: with a ``charset`` (yaseer/basic/dialects/charset.py) the machine's codes
    128..255 of a tokenised file are its symbols, and an ASCII file is read as the character
    set reads one (UTF-8 when it is, else the machine's codes); without one, codes stay
    ``chr(code)`` and an ASCII file is UTF-8, else read byte for byte.  ``exact``: a tokenised
    file's double constants keep all their bits (:func:`detokenise`); False: as LIST shows them."""
    if data[:1] in (bytes((PROTECTED,)), bytes((TOKENISED,))):
        body = unprotect(data[1:]) if data[0] == PROTECTED else data[1:]
        text = detokenise(body, exact)
        return text if charset is None else charset.symbols(text)
    if data.startswith(BYTE_ORDER_MARK):
        data = data[len(BYTE_ORDER_MARK):]
    cut = data.find(END_OF_FILE)
    if cut >= 0:
        data = data[:cut]
    if charset is not None:
        return charset.program_text(data)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def is_protected(data: bytes) -> bool:
    """Was the program file ``data`` SAVEd with ,P (GIODSK.ASM PROLOD sets PROFLG on its 0xFE)?"""
    return data[:1] == bytes((PROTECTED,))


def _counters():
    """PENCOD's and PDECOD's two counters, byte after byte: counter 1 runs 11..1, counter 2
    13..1, each starting again after 1."""
    one, two = 11, 13
    while True:
        yield one, two
        one = one - 1 or 11
        two = two - 1 or 13


def unprotect(data: bytes) -> bytes:
    """A protected program's bytes (after the 0xFE) as the tokenised bytes they scramble
    (GIODSK.ASM PDECOD): each byte less counter 1, XORed with the two tables' entries,
    plus counter 2."""
    return bytes((((byte - one) & 0xFF) ^ _LOGP[two - 1] ^ _EXPCN[one - 1]) + two & 0xFF
                 for byte, (one, two) in zip(data, _counters()))


def detokenise(data: bytes, exact: bool = False) -> str:
    """A tokenised program (after the 0xFF) as numbered text lines, as LIST shows them (CR LF
    after each, a LF inside a line written LF CR as LIST writes it to a file: the lines read
    back as GW-BASIC's ASCII LOAD reads them, scanner.dos_lines, keep their LFs; line 0's
    text follows its number with no blank, as LOAD keeps a blank after line number 0); a file
    cut short ends with its last whole line.  ``exact``: a double or single constant is its
    16 or 7 digits only where they read back to its 8 or 4 bytes, else scanner.EXACT_DOUBLE
    or EXACT_SINGLE and the bytes (the program then keeps all their bits, and SAVE writes
    them back)."""
    lines = []
    i = 0
    while i + 4 <= len(data):
        if data[i] == 0 and data[i + 1] == 0:  # the zero link: the end
            break
        number = data[i + 2] | data[i + 3] << 8
        text, i = _line_text(data, i + 4, exact)
        blank = "" if number == 0 and text[:1] not in "0123456789" else " "
        lines.append(f"{number}{blank}{text}".replace("\n", "\n\r"))
    return "".join(line + "\r\n" for line in lines)


def line_text(tokens: bytes) -> str:
    """One line's tokens (without link, number and the 0 that ends it) as LIST shows them."""
    return _line_text(tokens, 0)[0]


def _line_text(body: bytes, i: int, exact: bool = False) -> tuple[str, int]:
    """The tokens of the line that starts at ``body[i]``, as LIST shows them, and the index
    after the 0 byte that ends it (a number's bytes may hold zeros: tokens are read one by one);
    ``exact``: a double constant that its 16 digits do not hold is written as its bytes
    (:func:`detokenise`)."""
    out: list[str] = []
    n = len(body)
    quoted = False  # inside a string
    text = None  # after REM: "rem" (the rest of the line); after DATA: "data" (up to a ':' outside quotes)
    while i < n:
        byte = body[i]
        if byte == 0:
            i += 1
            break
        if byte == ord('"') and text != "rem":
            quoted = not quoted
        if quoted or text == "rem" or (text == "data" and byte != 0x3A) or byte == ord('"'):
            out.append(chr(byte))
            i += 1
            continue
        text = None
        if byte == _ELSE or (byte == 0x3A and i + 1 < n and body[i + 1] == _ELSE and exact and not _after_name(out)):
            if byte == _ELSE:
                out = _else_written(out, exact)
            else:  # ELSE is stored as ":ELSE": the ELSE typed alone gives both bytes back
                out.append("ELSE")
                i += 1
            i += 1
            if i < n and (_alnum(chr(body[i])) or body[i] == ord(".")):
                out.append(" ")  # (as after any keyword: the name after it kept apart)
            continue
        if exact and _starts_name(byte, out) and (_reads_as_word(body, i) or _lower_case(body, i)):
            out.append(STORED_NAME)  # a name the file holds where LIST shows a keyword (PRINT=1)
        if byte == 0x3A and body[i + 1:i + 3] == bytes((_REM, _QUOTE_REM)):  # ' is ":REM'"
            out.append("'")
            text, i = "rem", i + 3
            continue
        word, i = _token(body, i, exact)
        if word is None:
            out.append(chr(byte))
            i += 1
            continue
        if word[:1].isalpha() and out and (_alnum(out[-1][-1:]) or out[-1][-1:] == "."):
            out.append(" ")  # keep a keyword apart from the name before it
        out.append(word)
        if word in ("REM", "DATA"):
            text = word.lower()
        elif word == "WHILE" and i < n and body[i] == _PLUS:
            i += 1  # GW-BASIC stores WHILE with a + token LIST does not show
        if word[-1:].isalpha() and word != "FN" and i < n and (_alnum(chr(body[i])) or body[i] == ord(".")):
            out.append(" ")  # ... and from the name after it
    return "".join(out), i


def _else_written(out: list, exact: bool) -> list:
    """The text so far with an ELSE token added.  ``exact`` (the program's text): the
    marker scanner.STORED_ELSE and ELSE, which CRUNCH stores back as the token alone (the
    ``:`` CRUNCH puts before a typed ELSE is a byte of its own).  Else as GWLIST.ASM LIST
    shows it (NTQTTK: for ELSE it steps back over the character before, the ``:`` CRUNCH
    stores there, then adds a blank only after a letter or digit, as for any keyword): a
    ``:ELSE`` shows as ELSE with nothing between it and what came before (``10ELSE``), an
    ELSE with no ``:`` loses the character before it (``TEXT ELSE`` stored without the
    colon lists as ``TEXTELSE``), or, first in its line, its own E (``LSE``), as a real
    GW-BASIC 3.23 listed them (PC-BASIC's detokenise_ELSE test)."""
    if exact:  # (after a name's letters, ":" then the marker: ``AELSE`` would be one name)
        return out + [STORED_ELSE + "ELSE"]
    shown = "".join(out)
    if not shown:
        return ["LSE"]
    spaced = _alnum(shown[-1]) or shown[-1] == "."
    return [shown[:-1] + (" " if spaced else "") + "ELSE"]


_WORD_TEXTS = frozenset(word for table in (TOKENS, *TWO_BYTE_TOKENS.values())
                        for word in table.values() if word[:1].isalpha())
_LONGEST_WORD = max(map(len, _WORD_TEXTS))
_NAME_BYTES = frozenset(b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789.")


def _after_name(out: list) -> bool:
    """Does the text so far end in a letter, digit or point (a name or number goes on)?"""
    return bool(out) and (_alnum(out[-1][-1:]) or out[-1][-1:] == ".")


def _starts_name(byte: int, out: list) -> bool:
    """Does the letter ``byte`` start a name (no letter, digit or point before it)?"""
    return chr(byte).isascii() and chr(byte).isalpha() and not _after_name(out)


def _lower_case(body: bytes, i: int) -> bool:
    """Does the name whose letters start at ``body[i]`` hold a small letter?  CRUNCH makes
    every letter outside strings a capital, so only a file written elsewhere holds one; the
    words a statement reads as letters (LINE's ``BF``, OPEN's ``OUTPUT`` and ``AS``, OPTION's
    ``BASE``, DEF's ``SEG``) are compared with capitals (SYNCHR), so such a name is never one
    of them: a Syntax error in the recording unsorted/LOWRCASE."""
    end = i
    while end < len(body) and body[end] in _NAME_BYTES:
        end += 1
    return any(0x61 <= byte <= 0x7A for byte in body[i:end])


def _reads_as_word(body: bytes, i: int) -> bool:
    """Would the name whose letters start at ``body[i]`` be read back as a reserved word,
    as CRUNCH reads a typed line (program_crunch._reserved_word: the longest word there, not
    one when a letter or digit follows it but for FN, USR and words ending in ``(``)?  A
    tokenised file may hold such a name (``PRINT=1`` stored as letters: PC-BASIC's
    keyword_as_varname_in_tokenised_file test)."""
    end = i
    while end < len(body) and body[end] in _NAME_BYTES:
        end += 1
    text = body[i:end + 1].decode("latin-1").upper()
    for length in range(min(_LONGEST_WORD, len(text)), 0, -1):
        word = text[:length]
        if word in _WORD_TEXTS:
            after = text[length:length + 1]
            return word[-1] == "(" or word in ("FN", "USR") or not (after.isascii() and after.isalnum())
    return False


def _alnum(character: str) -> bool:
    """An ASCII letter or digit (a byte from 128 up is a token or a character, never one)."""
    return character.isascii() and character.isalnum()


def _token(body: bytes, i: int, exact: bool = False) -> tuple[str | None, int]:
    """The text of the token or number at ``body[i]`` and the index after it (None: a plain
    byte); ``exact``: see :func:`_line_text`."""
    byte = body[i]
    rest = body[i + 1:]
    if byte in TWO_BYTE_TOKENS and rest:
        word = TWO_BYTE_TOKENS[byte].get(rest[0])
        return (word, i + 2) if word is not None else (None, i)
    if byte in TOKENS:
        return TOKENS[byte], i + 1
    if 0x11 <= byte <= 0x1A:
        return str(byte - 0x11), i + 1
    sizes = {0x0B: 2, 0x0C: 2, 0x0D: 2, 0x0E: 2, 0x0F: 1, 0x1C: 2, 0x1D: 4, 0x1F: 8}
    size = sizes.get(byte)
    if size is None or len(rest) < size:
        return None, i
    value = rest[:size]
    if byte == 0x0B:
        return f"&O{int.from_bytes(value, 'little'):o}", i + 3
    if byte == 0x0C:
        return f"&H{int.from_bytes(value, 'little'):X}", i + 3
    if byte in (0x0D, 0x0E, 0x0F):
        return str(int.from_bytes(value, "little")), i + 1 + size
    if byte == 0x1C:
        return str(int.from_bytes(value, "little", signed=True)), i + 3
    if byte == 0x1D:
        text = unsigned_text(_from_mbf(value), SINGLE_DIGITS, "E")
        text = text if "." in text or "E" in text else text + "!"
    else:
        text = unsigned_text(double_of(mbf_double.from_bytes(value)), DOUBLE_DIGITS, "D")  # all 56 bits, as CVD
        text = text if "D" in text else text + "#"
    if exact and _read_back(text, size) != value:
        text = chr(byte) + value.hex().upper()  # scanner.EXACT_SINGLE / EXACT_DOUBLE
    return text, i + 1 + size


def _read_back(text: str, size: int) -> bytes:
    """The ``size`` bytes (4: a single, 8: a double) a constant's listed ``text`` gives when
    the line is read again."""
    number = gw_number(text, 0)[0][0]
    if size == 4:
        return mks(number).encode("latin-1")
    return mbf_double.to_bytes(getattr(number, "parts", None) or mbf_double.parts(number))


def protect(data: bytes) -> bytes:
    """Tokenised bytes scrambled as GIODSK.ASM PENCOD scrambles a program for SAVE "f",P
    (the inverse of :func:`unprotect`): each byte less counter 2, XORed with the two
    tables' entries, plus counter 1."""
    return bytes((((byte - two) & 0xFF) ^ _EXPCN[one - 1] ^ _LOGP[two - 1]) + one & 0xFF
                 for byte, (one, two) in zip(data, _counters()))


def protected_file(tokenised: bytes) -> bytes:
    """The bytes of a file SAVE "f",P writes: the 0xFE mark, the program's tokenised bytes
    scrambled (GIODSK.ASM PROSAV), and the Ctrl-Z that ends a file."""
    return bytes((PROTECTED,)) + protect(tokenised) + bytes((END_OF_FILE,))
