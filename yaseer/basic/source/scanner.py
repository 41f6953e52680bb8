"""Source text -> tokens, the way the dialect's tokeniser reads a line.

Casio (``Dialect.keyword_first``): keywords are recognised first, wherever they start inside a run of letters:
``COST`` is ``COS T``, ``GOSUBPROG1`` is ``GOSUB PROG 1``, ``IFX<0THEN`` is
``IF X < 0 THEN``.  A variable name is a letter followed by letters and digits
up to the next place where a keyword starts; a trailing ``$`` makes it a
string variable.  Case does not matter outside string literals.

GW-BASIC reads a run of name characters as one word (``COST`` is a variable,
``FORI=1TO3`` a syntax error) and, with ``Dialect.typed_numbers``, number
literals carry their type (``(value, "%" | "!" | "#")``; see
:func:`_scan_typed_number`); names keep their type character (``A%``, ``B#``).

The scanner also splits a listing into lines: a physical line that does not
begin with a line number continues the previous line (the paper wraps long
lines); see :func:`split_lines`.

Token types are the terminal names declared in ``grammar.lark``.
"""

from __future__ import annotations

import functools

from yaseer.basic.dialects.dialect import CASIO, Dialect
from yaseer.basic.errors import (
    DIRECT_STATEMENT_IN_FILE, LINE_BUFFER_OVERFLOW, BasicError, OVERFLOW, SYNTAX_ERROR, UNDEFINED_LINE, error_message,
)
from yaseer.basic.dialects.reserved import GW_RESERVED_WORDS, UNSUPPORTED, StoredName
from yaseer.patterns import Pattern

# Statement and operator keywords every dialect reserves: each is its own terminal type.
STATEMENT_KEYWORDS = (
    "LET", "PRINT", "LPRINT", "USING", "FOR", "TO", "STEP", "NEXT", "GOTO", "GOSUB",
    "RETURN", "IF", "THEN", "ELSE", "ON", "END", "STOP", "DIM", "CLEAR",
    "READ", "RESTORE", "INPUT", "DEF", "FN", "ERROR", "RESUME", "RANDOMIZE",
    "AND", "OR", "NOT", "MOD", "TAB", "SPC", "TRON", "TROFF", "CLS", "WIDTH",
)
# GW-BASIC's statements, in both dialects.
GW_STATEMENT_KEYWORDS = (
    "WHILE", "WEND", "SWAP", "ERASE", "OPTION", "LINE", "WRITE", "OPEN", "CLOSE", "KILL",
    "FILES", "APPEND",
)
RENAME_KEYWORD = "NAME"  # NAME old AS new (token RENAME: NAME is the variables' terminal)
# Functions of one argument (parentheses optional: ``COS T``).
UNARY_FUNCTIONS = (
    "SIN", "COS", "TAN", "ATN", "SQR", "ABS", "INT", "FIX", "SGN", "EXP", "LOG", "RND",
    "LEN", "STR$", "VAL", "CHR$", "ASC", "CINT", "CSNG", "CDBL",
    "SPACE$", "HEX$", "OCT$", "MKI$", "MKS$", "MKD$", "CVI", "CVS", "CVD", "FRE", "POS",
    "LPOS", "EOF", "LOF", "LOC",
)
# Functions that need a parenthesised argument list.
LIST_FUNCTIONS = ("LEFT$", "RIGHT$", "MID$", "INSTR", "STRING$", "INPUT$")
# Values without arguments.
SYSTEM_VARIABLES = ("ERR", "ERL", "TIMER", "DATE$", "TIME$")
COMMENT_KEYWORD = "REM"
DATA_KEYWORD = "DATA"
# Words some dialects reserve (Dialect.own_words, pi_keyword, program_areas) -> token type.
DIALECT_WORDS = {
    "PROG": "PROG", "DEG": "DEG", "RAD": "RAD", "PI": "SYSVAR", "XOR": "XOR", "EQV": "EQV",
    "IMP": "IMP", "DEFINT": "DEFTYPE", "DEFSNG": "DEFTYPE", "DEFDBL": "DEFTYPE", "DEFSTR": "DEFTYPE",
    "LOCATE": "LOCATE", "INKEY$": "SYSVAR", "PEEK": "FUNC",
    "WRITE#": "BANK", "READ#": "BANK", "RESTORE#": "BANK", "LIST#": "BANK", "LLIST#": "BANK", "NEW#": "BANK",
    "SAVE#": "BANK", "LOAD#": "BANK",
    "FIELD": "FIELD", "GET": "GET", "PUT": "PUT", "LSET": "LSET", "RSET": "LSET", "RESET": "RESET",
    "CHAIN": "CHAIN", "COMMON": "COMMON", "MERGE": "MERGE", "DELETE": "DELETE",
    "RUN": "RUN", "LIST": "LIST", "LLIST": "LIST", "LOAD": "LOAD", "SAVE": "SAVE", "NEW": "NEW",
    "EDIT": "EDIT", "RENUM": "RENUM", "AUTO": "AUTO", "KEY": "KEY", "OFF": "OFF", "SYSTEM": "SYSTEM", "ALL": "ALL",
    "CSRLIN": "SYSVAR", "COLOR": "COLOR", "SCREEN": "SCREEN", "VIEW": "VIEW", "USR": "USR",
    "PSET": "PSET", "PRESET": "PSET", "WINDOW": "WINDOW", "PALETTE": "PALETTE",
    "CIRCLE": "CIRCLE", "PAINT": "PAINT", "DRAW": "DRAW",
}
# GW-BASIC reads these keywords even when name characters follow (``FNA``, ``USR0(``, ``TAB(``).
_GW_PREFIX_KEYWORDS = ("FN", "USR")

_COMMON_TYPES: dict[str, str] = {}
for _word in STATEMENT_KEYWORDS + GW_STATEMENT_KEYWORDS:
    _COMMON_TYPES[_word] = _word
_COMMON_TYPES[RENAME_KEYWORD] = "RENAME"
for _word in UNARY_FUNCTIONS:
    _COMMON_TYPES[_word] = "FUNC"
for _word in LIST_FUNCTIONS:
    _COMMON_TYPES[_word] = "FUNCN"
for _word in SYSTEM_VARIABLES:
    _COMMON_TYPES[_word] = "SYSVAR"
_COMMON_TYPES[COMMENT_KEYWORD] = "REMARK"
_COMMON_TYPES[DATA_KEYWORD] = "DATA_TEXT"
_KEYWORD_TYPES = {**_COMMON_TYPES, **DIALECT_WORDS}  # every word some dialect reserves


class _Keywords:
    """One dialect's keyword table: word -> token type, and the words by first letter
    (longest first, so that INPUT wins over INT and ERROR over ERR)."""

    def __init__(self, dialect: Dialect):
        words = dict(_COMMON_TYPES)
        own = list(dialect.own_words)
        own += ["PI"] if dialect.pi_keyword else []
        own += ["PROG"] if dialect.program_areas else []
        for word in own:
            words[word] = DIALECT_WORDS[word]
        # the machine's own words (dialects/casio.py): functions, statements, two-word spellings
        table = dialect.words
        self.spelled = table.spellings if table else {}  # "HYP SIN" -> "HYPSIN"
        self.operators = table.operators if table else {}  # the Casio's ¥
        self.paren_function = {"DEG": table.deg_function[0]} if table else {}  # DEG( is a function
        if table:
            for word, entry in table.functions.items():
                words[word] = entry[0]
            for word in table.statements:
                words[word] = "WORDSTMT"
            for spelling, word in table.spellings.items():
                words[spelling] = words[word]
            for word in table.reserved_only:
                words.setdefault(word, UNSUPPORTED)
            for word in table.reserved_variables:
                words[word] = "STRNAME"
        # GW-BASIC's words for the PC's devices (dialects/gw_words.py)
        devices = dialect.device_words
        if devices:
            for word, entry in devices.functions.items():
                words[word] = entry[0]
            for word in devices.system_values:
                words[word] = "SYSVAR"
            for word in devices.statements:  # (PLAY: a function; a statement where one starts)
                if word not in devices.functions:
                    words[word] = "WORDSTMT"
        self.dollar_apart = devices.dollar_apart if devices else frozenset()
        # a longer GW-BASIC word that is no keyword here stays whole (VARPTR, CSRLIN in casio;
        # LOCK, not LOC K, where LOCK is no keyword)
        self.longer = {word: tuple(r for r in longer if r not in words) for word, longer in _longer_reserved().items()}
        for word in (table.reserved_only if table else ()):
            self.longer[word] = tuple(r for r in GW_RESERVED_WORDS if r.startswith(word) and r not in words)
        self.types = words
        self.by_letter: dict[str, tuple[str, ...]] = {}
        for word in sorted(words, key=len, reverse=True):
            self.by_letter[word[0]] = self.by_letter.get(word[0], ()) + (word,)

    def at(self, upper: str, i: int) -> str | None:
        """The longest keyword that starts at position ``i`` of the upper-cased text
        (none where a longer reserved word begins with it: see :func:`_longer_reserved`)."""
        for word in self.by_letter.get(upper[i], ()):
            if upper.startswith(word, i):
                if any(upper.startswith(longer, i) for longer in self.longer.get(word, ())):
                    return None
                return word
        return None


# Keyword-first reading must not split a longer GW-BASIC reserved word that begins with
# one of GW-BASIC's statement keywords (LOCATE is not LOC ATE, LOCK not LOC K): it stays one name,
# which the parser reports as an unsupported word.
_ADDED_KEYWORDS = set(GW_STATEMENT_KEYWORDS) | {RENAME_KEYWORD} | {
    "SPACE$", "HEX$", "OCT$", "MKI$", "MKS$", "MKD$", "CVI", "CVS", "CVD", "FRE", "POS", "LPOS",
    "EOF", "LOF", "LOC", "INSTR", "STRING$", "INPUT$", "TIMER", "DATE$", "TIME$"}


@functools.lru_cache(maxsize=None)
def _longer_reserved() -> dict[str, tuple[str, ...]]:
    """Each added keyword's longer reserved words (made when a line is first scanned: a run of
    a cached program reads no tokens)."""
    return {word: tuple(r for r in GW_RESERVED_WORDS if r.startswith(word) and r != word and r not in _COMMON_TYPES)
            for word in _ADDED_KEYWORDS}


@functools.lru_cache(maxsize=None)
def _keywords(dialect: Dialect) -> _Keywords:
    return _Keywords(dialect)


_OPERATORS = {
    "+": "PLUS", "-": "MINUS", "*": "STAR", "/": "SLASH", "\\": "BSLASH", "^": "CARET",
    "(": "_LPAR", ")": "_RPAR", ",": "COMMA", ";": "SEMI", ":": "_COLON", "#": "HASH",
    "@": "AT",
}
_RELATIONS = {
    "=": "EQ", "<": "LT", ">": "GT", "<=": "LE", "=<": "LE", ">=": "GE", "=>": "GE",
    "<>": "NE", "><": "NE",
}
_NUMBER = Pattern(r"(\d+\.?\d*|\.\d+)(E[+-]?\d+)?")
_AFTER_LINE_NUMBER = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz'?")


def _line_number(physical: str) -> tuple[int, int] | None:
    """The number a physical line starts with and where its text begins, or None: blanks, the
    digits, then the line's end, a blank (one is skipped), a letter, ``'`` or ``?`` (the match
    of ``\\s*(\\d+)(?=[\\sA-Za-z'?]|$)\\s?``: blanks and digits as :mod:`re` reads them in a
    str, str.isspace and str.isdecimal).  Written out: reading a cached program's lines then
    needs no :mod:`re` (which, with the enum module, costs ``python -m yaseer`` a fifth of a
    gw start-up)."""
    end = len(physical)
    start = 0
    while start < end and physical[start].isspace():
        start += 1
    digits = start
    while digits < end and physical[digits].isdecimal():
        digits += 1
    if digits == start:
        return None
    if digits == end:
        return int(physical[start:digits]), end
    after = physical[digits]
    if after.isspace():
        return int(physical[start:digits]), digits + 1
    return (int(physical[start:digits]), digits) if after in _AFTER_LINE_NUMBER else None


def _syntax_error() -> BasicError:
    return BasicError("Syntax error", SYNTAX_ERROR)


def _scan_string(text: str, i: int) -> tuple[str, int]:
    """A string literal starting at the quote at ``i``; an unclosed one ends the line."""
    end = text.find('"', i + 1)
    if end < 0:
        return text[i + 1:], len(text)
    return text[i + 1:end], end + 1


def _scan_data(text: str, i: int) -> tuple[str, int]:
    """The raw text of a DATA statement: up to the first ``:`` outside quotes."""
    j = i
    quoted = False
    while j < len(text):
        ch = text[j]
        if ch == '"':
            quoted = not quoted
        elif ch == ":" and not quoted:
            break
        j += 1
    return text[i:j], j


def _scan_word(upper: str, i: int, keywords: _Keywords) -> tuple[str, str, int]:
    """Keyword-first (the pocket computers): a keyword wherever one starts; otherwise a
    name of letters and digits up to the next place a keyword starts; ``$`` ends it.

    Returns ``(token type, value, end)``.
    """
    word = keywords.at(upper, i)
    if word is not None:
        end = i + len(word)
        if word in keywords.paren_function and upper[end:].lstrip(" ").startswith("("):
            return keywords.paren_function[word], word, end  # DEG(d, m, s), not the statement DEG
        return keywords.types[word], keywords.spelled.get(word, word), end
    j = i + 1
    while j < len(upper) and upper[j].isalnum() and upper[j].isascii() and keywords.at(upper, j) is None:
        j += 1
    if j < len(upper) and upper[j] == "$":
        return "STRNAME", upper[i:j + 1], j + 1
    return "NAME", upper[i:j], j


_NAME_CHARS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789.")


def _scan_word_whole(upper: str, i: int, keywords: _Keywords) -> tuple[str, str, int]:
    """GW-BASIC: letters, digits and ``.`` are read as one word; the word is a keyword
    when the characters read so far spell one and no name character follows (``FN``
    excepted: ``FNA`` is ``FN A``), so ``COST`` and ``FORI`` are names; a name may end
    in a type character ``% ! # $``.  (PC-BASIC 2.0.8's tokeniser, checked on it.)
    """
    n = len(upper)
    j = i
    while j < n:
        ch = upper[j]
        j += 1
        word = upper[i:j]
        if word == "GO" and (upper.startswith(" SUB", j) or (upper.startswith(" TO", j) and (
                j + 3 >= n or upper[j + 3] not in _NAME_CHARS))):
            word = "GOSUB" if upper[j + 1] == "S" else "GOTO"
            return word, word, j + len(word) - 1
        kind = keywords.types.get(word)
        if kind is not None and j < n and upper[j] == "$" and word + "$" in keywords.types:
            return keywords.types[word + "$"], word + "$", j + 1  # INPUT$, not INPUT
        if kind is not None and word in keywords.dollar_apart and upper[j:].lstrip(" ").startswith("$"):
            return keywords.types[word + "$"], word + "$", upper.index("$", j) + 1  # ENVIRON $(1)
        if kind is not None and (word in _GW_PREFIX_KEYWORDS or j >= n or upper[j] not in _NAME_CHARS):
            return kind, word, j
        if ch not in _NAME_CHARS:
            j -= 1
            break
    name = upper[i:j]
    if j < n and upper[j] in "%!#$":
        return ("STRNAME" if upper[j] == "$" else "NAME"), name + upper[j], j + 1
    return "NAME", name, j


_NAME_TYPES = ("NAME", "STRNAME")


def _name(text: str, start: int, end: int, kind: str, dialect: Dialect) -> str:
    """A variable's name as ``dialect`` keeps it: in the case it was typed when
    ``names_keep_case`` (``a`` and ``A`` are two Casio variables), at most
    ``name_length`` characters before the ``$`` (else a Syntax error)."""
    name = text[start:end] if dialect.names_keep_case else text[start:end].upper()
    length = dialect.name_length
    if length is not None and len(name) - (kind == "STRNAME") > length:
        raise _syntax_error()
    return name


_HEX_START = Pattern(r"&H[0-9A-F]")
_HEX_LITERAL = Pattern(r"&H([0-9A-F]{1,4})(?![0-9A-F])")


def _scan_hex(upper: str, i: int) -> tuple[float, int]:
    """The Casio's ``&H`` number (AMP_H.md): one to four hexadecimal digits, 0..65535;
    more digits are Overflow, none a Syntax error."""
    match = _HEX_LITERAL.match(upper, i)
    if match is None:
        if _HEX_START.match(upper, i):
            raise BasicError("Overflow", OVERFLOW)
        raise _syntax_error()
    return float(int(match.group(1), 16)), match.end()


def _scan_number(upper: str, i: int) -> tuple[float, int]:
    end, n = i, len(upper)
    while end < n and upper[end].isdecimal():  # what the pattern's \d takes
        end += 1
    if end > i and (end == n or upper[end] not in ".E"):  # digits alone, as the pattern reads them:
        value = float(upper[i:end])  # a cold start's scan then needs no regular expression (re, enum)
        if value == float("inf"):
            raise BasicError("Overflow", OVERFLOW)
        return value, end
    match = _NUMBER.match(upper, i)
    if match is None:
        raise _syntax_error()
    value = float(match.group(0))
    if value == float("inf"):
        raise BasicError("Overflow", OVERFLOW)
    return value, match.end()


# a type character may follow a number without exponent only (``1E2!`` is 1E2, then a bad ``!``)


def _typed_number_parts(text: str) -> tuple | None:
    """The parts of a number's whole text (:func:`_number_text`): (mantissa, exponent letter,
    exponent, type suffix), the groups of a full match of
    ``(\\d+\\.?\\d*|\\.\\d+)(?:([ED])([+-]?\\d*)|([%!#]?))`` (letter and exponent None beside a
    suffix, the suffix None beside an exponent, "" when there is neither), or None.  Written
    with str methods (digits as re reads them, str.isdecimal): gw's memory model reads every
    number of a program this way when it counts the program's bytes, and re is not imported."""
    end = len(text)
    digits = 0
    while digits < end and text[digits].isdecimal():
        digits += 1
    at = digits
    if at < end and text[at] == ".":
        at += 1
        while at < end and text[at].isdecimal():
            at += 1
    if digits == 0 and at - digits < 2:  # no digit before the point, and none after it
        return None
    mantissa, rest = text[:at], text[at:]
    if rest[:1] in ("E", "D"):
        exponent = rest[1:]
        if exponent[:1] in ("+", "-"):
            if exponent[1:].isdecimal() or len(exponent) == 1:
                return mantissa, rest[0], exponent, None
            return None
        return (mantissa, rest[0], exponent, None) if exponent.isdecimal() or not exponent else None
    return (mantissa, None, None, rest) if rest in ("", "%", "!", "#") else None


_LONE_POINT = Pattern(r"\.(?:[ED][+-]?\d*)?([!#]?)")
SINGLE_DIGITS = 7  # a literal with more significant digits is double precision (GW-BASIC)
_BLANKS = " \t\n"  # what GW-BASIC's CHRGTR steps over (GWMAIN.ASM CHRCON, NOTCON)


def _after_blanks(upper: str, j: int) -> int:
    """The position of the first character from ``j`` that is not a blank."""
    while j < len(upper) and upper[j] in _BLANKS:
        j += 1
    return j


def _take(upper: str, at: int, out: list) -> tuple[int, int]:
    """``upper[at]`` appended to ``out``; the position after it and the next non-blank one."""
    out.append(upper[at])
    return at + 1, _after_blanks(upper, at + 1)


def _number_text(upper: str, i: int) -> tuple[str, int]:
    """A decimal number's characters from ``i`` as GW-BASIC's number reader takes them, blanks
    left out, and the position after the last one: MATH1.ASM FIN reads each next character
    with CHRGTR, which steps over blanks (``1 2`` is 12, ``1 . 5 E - 2`` is .015), and
    CRUNCH (GWMAIN.ASM BAKSP) leaves the blanks after the number.  An ``E`` is an exponent
    unless ``L`` or ``Q`` follows it ($CHKEL: ELSE, EQV); a second point ends the number."""
    n, out, point = len(upper), [], False
    end = k = i
    while k < n and (upper[k].isdigit() or (upper[k] == "." and not point)):
        point = point or upper[k] == "."
        end, k = _take(upper, k, out)
    if k < n and upper[k] in "ED" and not (upper[k] == "E" and upper[_after_blanks(upper, k + 1):][:1] in ("L", "Q")):
        end, k = _take(upper, k, out)
        if k < n and upper[k] in "+-":
            end, k = _take(upper, k, out)
        while k < n and upper[k].isdigit():
            end, k = _take(upper, k, out)
    elif k < n and upper[k] in "%!#":
        end, k = _take(upper, k, out)
    return "".join(out), end


def _radix_number(upper: str, i: int) -> tuple[int, int]:
    """``&H``/``&O``/``&`` at ``i``: (value, end), as GWEVAL.ASM OCTCNS reads it.  The letter
    is read with CHRGTR (blanks before it skipped); octal digits too (``&O 7 7`` is 63), hex
    digits not (``&H 1F`` is 0, then 1F: LOPHEX reads the next byte itself).  A digit 8 or 9
    in an octal number is a Syntax error (CONERR)."""
    k = _after_blanks(upper, i + 1)
    if upper[k:k + 1] == "H":
        end = k + 1
        while end < len(upper) and upper[end] in "0123456789ABCDEF":
            end += 1
        return (int(upper[k + 1:end], 16) if end > k + 1 else 0), end
    end = i + 1
    if upper[k:k + 1] == "O":
        end = k + 1
        k = _after_blanks(upper, end)
    digits = []
    while k < len(upper) and upper[k].isdigit():
        if upper[k] in "89":
            raise _syntax_error()
        digits.append(upper[k])
        end = k + 1
        k = _after_blanks(upper, end)
    return (int("".join(digits), 8) if digits else 0), end


def significant_digits(whole: str, fraction: str) -> int:
    """How many digits of a decimal number's ``whole`` and ``fraction`` parts count
    towards double precision: from the first that is not 0, zeros ending the whole
    part included (``58183640.0``: 8), zeros ending the fraction not (``1.5000000``: 2)."""
    return len((whole + fraction.rstrip("0")).lstrip("0"))


def _scan_typed_number(upper: str, i: int, notes: list | None = None) -> tuple[tuple, int]:
    """A GW-BASIC number literal: ``((value, type), end)`` with type ``%``, ``!`` or ``#``.

    Without a suffix a whole number below 32768 is an integer, a ``D`` exponent or
    more than 7 digits makes a double, anything else is single precision.
    ``&H1F`` / ``&O17`` / ``&17`` are 16-bit integers (``&HFFFF`` is -1).
    A decimal literal beyond MBF's range (``1E+39``, ``1D+39``) is the largest number of
    its type, and ``"Overflow"`` is added to ``notes``: GW-BASIC's tokeniser prints it
    when the line is entered (PC-BASIC 2.0.8: when a program is loaded), not when the
    line runs; see :func:`entry_messages`.
    """
    from yaseer.basic.arithmetic.values import (DOUBLE_LARGEST, MBF_SMALLEST, SINGLE_LARGEST, double_from_decimal,
                                                single_literal, to_single)

    if upper[i] == "&":
        value, end = _radix_number(upper, i)
        if value > 0xFFFF:
            raise BasicError("Overflow", OVERFLOW)
        return (value - 0x10000 if value >= 0x8000 else value, "%"), end
    text, end = _number_text(upper, i)
    parts = _typed_number_parts(text)
    if parts is None:
        point = _LONE_POINT.fullmatch(text)  # no digit: the number reader's 0 ($FIN)
        if point is None:
            raise _syntax_error()
        return (0.0, "#" if point.group(1) == "#" else "!"), end
    mantissa, letter, exponent, suffix = parts
    value = float(mantissa + ("E" + (exponent if exponent.strip("+-") else "0") if letter else ""))
    plain = letter is None and "." not in mantissa
    if suffix == "%" or (not suffix and plain and value < 32768):
        if not value.is_integer() and suffix == "%":
            return (to_single(value), "!"), end
        if value == 32768:  # only as -32768%: a single until the minus makes it an integer
            return (32768.0, "!"), end
        if value > 32768:
            raise _syntax_error()
        return (int(value), "%"), end
    whole, _, fraction = mantissa.partition(".")
    if suffix == "#" or (not suffix and (letter == "D" or significant_digits(whole, fraction) > SINGLE_DIGITS)):
        if value > DOUBLE_LARGEST:  # MBF's double range ends where the single's does
            value = _overflowed(DOUBLE_LARGEST, notes)
        elif value < MBF_SMALLEST:  # ... and begins there too: below it a literal is 0
            value = 0.0
        elif value:  # GW's nearest 56 bits (values.Wide where no float holds them)
            value = double_from_decimal(whole, fraction, int(exponent) if letter and exponent.strip("+-") else 0)
            if value - value:
                value = _overflowed(DOUBLE_LARGEST, notes)
        return (value, "#"), end
    single = to_single(value)
    if not single - single:  # in range: the value GW-BASIC's conversion gives (values.mbf_single)
        single = single_literal(text.rstrip("!#%"), forced=suffix == "!")
    if single - single:  # beyond the single range
        single = _overflowed(SINGLE_LARGEST, notes)
    return (single, "!"), end


# A number constant as a tokenised program file holds it (the 0x1F token and MKD$'s 8 bytes,
# the 0x1D token and MKS$'s 4) where the digits LIST shows (16, 7) would not read back to the
# same bits: the token's own control character and the bytes in hexadecimal
# (program_file.detokenise writes it, program_crunch.crunch_line stores it back as its
# bytes).  GW-BASIC's CRUNCH makes any typed control character a blank, so no line typed
# into GW-BASIC holds one.
EXACT_DOUBLE, EXACT_SINGLE = "\x1f", "\x1d"
EXACT_MARKERS = EXACT_DOUBLE + EXACT_SINGLE
# a tokenised file's bytes that a typed line would not give (program_file.detokenise): a name
# whose letters spell a reserved word (STORED_NAME, then the name: ``PRINT=1``), and an
# ELSE token stored without the ``:`` CRUNCH puts before it (STORED_ELSE, then ELSE)
STORED_NAME, STORED_ELSE = "\x1e", "\x1b"
_EXACT = Pattern("\x1f([0-9A-F]{16})|\x1d([0-9A-F]{8})")


def exact_constant(text: str, i: int) -> tuple[str, bytes, int] | None:
    """The marker (:data:`EXACT_DOUBLE` or :data:`EXACT_SINGLE`) and bytes of an exact
    constant at ``text[i]``, and the position after it; None if there is none."""
    match = _EXACT.match(text, i)
    if match is None:
        return None
    return text[i], bytes.fromhex(match.group(1) or match.group(2)), match.end()


def gw_number(upper: str, i: int) -> tuple[tuple, int]:
    """The GW-BASIC number literal at ``upper[i]`` (a digit or ``.``; capitals) as
    :func:`_scan_typed_number` reads it: ``((value, type), end)``; the tokeniser of
    program files (machine/program_crunch.py) reads numbers with it."""
    return _scan_typed_number(upper, i)


def radix_number(upper: str, i: int) -> tuple[int, int]:
    """``&H``/``&O``/``&`` at ``upper[i]``: (value, end), see :func:`_radix_number`."""
    return _radix_number(upper, i)


def _overflowed(largest: float, notes: list | None) -> float:
    """The value of a literal beyond the range: ``largest``, noting GW's message."""
    if notes is not None:
        notes.append("Overflow")
    return largest


def _may_overflow(text: str) -> bool:
    """Whether ``text`` holds an exponent of two digits or more or 30 digits in a row (a
    search of ``[EDed][+]?\\d\\d|\\d{30}``): only such a literal can pass 1.7E+38, and a
    line without one is not scanned for entry messages.  Written with str methods: every
    line of a gw program is asked when it is loaded, and re is not imported for it."""
    for marker in "EDed":
        at = text.find(marker)
        while at >= 0:
            digits = at + 2 if text.startswith("+", at + 1) else at + 1
            if len(text) >= digits + 2 and text[digits:digits + 2].isdecimal():
                return True
            at = text.find(marker, at + 1)
    if len(text) < 30 or sum(map(str.isdecimal, text)) < 30:
        return False
    run = 0
    for character in text:
        run = run + 1 if character.isdecimal() else 0
        if run == 30:
            return True
    return False


def entry_messages(text: str, dialect: Dialect = CASIO) -> list[str]:
    """The messages GW-BASIC prints when the line ``text`` is entered or loaded: one
    ``Overflow`` for each number literal beyond the range (GWMAIN.ASM's tokeniser reads
    numbers as it stores the line; PC-BASIC 2.0.8 prints them when it loads a program,
    before RUN).  Literals in strings, remarks and DATA are text and print nothing."""
    if not dialect.typed_numbers or not _may_overflow(text):
        return []
    notes: list[str] = []
    try:
        for _ in _lexemes(text, dialect, notes):
            pass
    except BasicError:
        pass  # a character no token starts with: the line's error is reported when it runs
    return notes


def _lexemes(text: str, dialect: Dialect = CASIO, notes: list | None = None, begin: int = 0):
    """``(token type, value, start, end)`` for each token of one line, in order, as
    ``dialect`` reads it (see ``Dialect.keyword_first`` and ``Dialect.typed_numbers``);
    ``notes`` collects the messages of literals beyond the range (see :func:`entry_messages`);
    ``begin``: where in ``text`` to start (outside a string).

    ``start:end`` is the token's span in ``text``.  A remark (``REM`` or ``'``)
    is the last lexeme: type ``REMARK``, value the text after it.  Raises
    ``BasicError("Syntax error")`` at a character no token can start with.
    """
    keywords = _keywords(dialect)
    scan_word = _scan_word if dialect.keyword_first else _scan_word_whole
    typed = dialect.typed_numbers
    upper = _upper_outside_strings(text)
    i = begin
    n = len(text)
    line_numbers = False  # (Dialect.line_number_digits) a digit here starts a line number
    name_text = False  # after a name CRUNCH keeps as letters, and blanks (point_after_name_is_text)
    while i < n:
        ch = upper[i]
        start = i
        if ch in " \t\r\n":
            i += 1
            name_text = name_text and ch == " "
            continue
        if line_numbers and (ch.isdigit() or ch == "."):
            if ch == ".":  # stored as it is (GWMAIN.ASM NUMTRY: "EDIT ."), read as a number 0
                i += 1
                yield "NUMBER", (0.0, "!"), start, i
            else:  # LINCON: its value a single when an expression reads it (CONFC1: INEG2)
                number, i = linget(upper, i)
                yield "NUMBER", (float(number), "!"), start, i
            continue
        if name_text and ch == "." and dialect.point_after_name_is_text:
            raise _syntax_error()
        name_text = False
        if ch == '"':
            value, i = _scan_string(text, i)
            yield "STRING", value, start, i
        elif ch == "'":
            yield "REMARK", text[i + 1:], start, n
            return
        elif ch in EXACT_MARKERS and typed:
            found = exact_constant(upper, i)
            if found is None:
                raise _syntax_error()
            from yaseer.basic.arithmetic.values import wide_literal  # here: only such files need it

            marker, data, i = found
            if marker == EXACT_DOUBLE:
                yield "NUMBER", (wide_literal(data.hex()), "#"), start, i
            else:  # a single's 4 bytes are a double's with 4 low bytes of 0: exact in a float
                yield "NUMBER", (wide_literal("00000000" + data.hex()), "!"), start, i
        elif ch == STORED_ELSE and typed and upper.startswith("ELSE", i + 1):
            i += 1  # the ELSE after it is read as any ELSE
        elif ch == STORED_NAME and typed:
            j = i + 1
            while j < n and upper[j] in _NAME_CHARS:
                j += 1
            if j == i + 1:
                raise _syntax_error()
            kind = "STRNAME" if j < n and upper[j] == "$" else "NAME"
            j += j < n and upper[j] in "%!#$"
            written = text[i + 1:j]  # small letters kept: no word a statement reads matches them (SYNCHR)
            name = written if written != written.upper() else _name(text, i + 1, j, kind, dialect)
            yield kind, StoredName(name), start, j
            i = j
        elif ch.isdigit() or (ch == "." and i + 1 < n and upper[i + 1].isdigit()) or (ch in "&." and typed):
            value, i = _scan_typed_number(upper, i, notes) if typed else _scan_number(upper, i)
            yield "NUMBER", value, start, i
        elif ch == "&" and dialect.hex_literals:
            value, i = _scan_hex(upper, i)
            yield "NUMBER", value, start, i
        elif ch.isascii() and ch.isalpha():
            kind, word, end = scan_word(upper, i, keywords)
            if kind in _NAME_TYPES and word not in keywords.types:
                word = _name(text, start, end, kind, dialect)
            if kind == "REMARK":
                yield "REMARK", text[end:], start, n
                return
            if kind == "DATA_TEXT":
                words = dialect.words
                raw, i = (text[end:], n) if words and words.data_to_line_end else _scan_data(text, end)
                yield "DATA_TEXT", raw, start, i
            else:
                i = end
                if dialect.line_number_digits:  # GWMAIN.ASM CRUNCH's DONUM: set by a word of LINRES
                    line_numbers = kind not in _NAME_TYPES and word in LINE_NUMBER_WORDS
                name_text = kind in _NAME_TYPES and upper[i - 1] not in "$%!#"
                yield kind, word, start, i
        elif ch == ":":
            line_numbers = False
            i += 1
            yield "_COLON", ch, start, i
        elif ch in "<>=":
            pair, after = upper[i:i + 2], i + 2
            if dialect.spaced_relations and pair not in _RELATIONS:
                j = i + 1
                while j < n and upper[j] == " ":
                    j += 1
                pair, after = ch + upper[j:j + 1], j + 1
            symbol = pair if pair in _RELATIONS else ch
            i = after if symbol == pair else i + 1
            yield _RELATIONS[symbol], symbol, start, i
        elif ch in _OPERATORS:
            i += 1
            yield _OPERATORS[ch], ch, start, i
        elif ch in "[]" and dialect.bracket_subscripts:  # checked by _subscript_brackets
            i += 1
            yield ("_LPAR" if ch == "[" else "_RPAR"), ch, start, i
        elif ch in keywords.operators:
            i += 1
            yield keywords.operators[ch], ch, start, i
        elif ch == "?":
            i += 1
            line_numbers = False
            yield "PRINT", "PRINT", start, i
        elif ch == "." and dialect.words and dialect.words.current_line_period:
            i += 1
            yield "PERIOD", ".", start, i  # LIST . / EDIT .: the current line (the grammar places it)
        else:
            raise _syntax_error()


# After these words GW-BASIC's tokeniser reads a number as a line number (GWMAIN.ASM LINRES),
# and goes on so past commas, operators and blanks until a name, another word or a colon.
LINE_NUMBER_WORDS = frozenset(("RESTORE", "AUTO", "RENUM", "DELETE", "EDIT", "RESUME", "ERL", "ELSE", "RUN",
                         "LIST", "LLIST", "GOTO", "RETURN", "THEN", "GOSUB"))


def line_number_spans(text: str, dialect: Dialect = CASIO) -> list[tuple[int, int, int]]:
    """``(start, end, number)`` of each line number the statements ``text`` name (see
    ``LINE_NUMBER_WORDS``), as RENUM changes them; the 0 of ``ON ERROR GOTO 0`` is not one
    (GWMAIN.ASM SCCLIN leaves it).  Numbers up to a character no token starts with."""
    spans: list[tuple[int, int, int]] = []
    after, words = False, ["", ""]
    try:
        for kind, value, start, end in _lexemes(text, dialect):
            if kind == "REMARK":
                break
            if kind == "NUMBER":
                digits = "".join(ch for ch in text[start:end] if ch not in _BLANKS)
                if after and digits.isdigit():  # (LINGET reads digits; 1.5, &H10, 1E3 are no line numbers)
                    number = int(digits)
                    if number or words != ["ERROR", "GOTO"]:
                        spans.append((start, end, number))
                words = ["", ""]
            elif kind == "_COLON":
                after = False
            elif kind not in ("STRING", "DATA_TEXT") and isinstance(value, str) and value[:1].isalpha():
                after = value.upper() in LINE_NUMBER_WORDS
                words = [words[1], value.upper()]
    except BasicError:
        pass
    return spans


# After LIST, LLIST, DELETE, EDIT, AUTO and RENUM (``Dialect.current_line_commands``) GW-BASIC's
# CRUNCH keeps a "." as it is (DONUM set: "EDIT .") and LINSPC reads it as the current line;
# where a lone "." is otherwise the number 0 (gw) the scanner gives such a NUMBER the value
# CURRENT_LINE, up to a token that is no part of a line range or list.
_LINE_SPEC_TOKENS = frozenset(("NUMBER", "MINUS", "COMMA"))


class Token:
    """One lexeme as the parser takes it: ``type``, its terminal's name in grammar.lark, and
    ``value``, its text (a number: its value, or ``(value, type)`` where the dialect types it)."""

    __slots__ = ("type", "value")

    def __init__(self, type: str, value) -> None:  # noqa: A002 - the grammar's word for it
        self.type, self.value = type, value

    def update(self, type: str | None = None, value=None) -> "Token":  # noqa: A002
        """A copy with another type or value."""
        return Token(self.type if type is None else type, self.value if value is None else value)

    def __repr__(self) -> str:
        return f"Token({self.type!r}, {self.value!r})"


def _line_lexemes(text: str, dialect: Dialect):
    """The lexemes of a line as :func:`tokenize` takes them: a COMMON's list is one lexeme
    ``COMMON_TEXT``, its text as typed to the statement's end.  GW-BASIC's COMMON skips
    its list as DATA does (FIVEO.ASM COMMON jumps to DATA): only a CHAIN reads it
    (source/common_lists.py), so a list that does not read is no error where COMMON runs."""
    begin = 0
    while True:
        for kind, value, start, end in _lexemes(text, dialect, begin=begin):
            yield kind, value, start, end
            if kind == "COMMON":
                begin = _statement_end(text, end, dialect)
                yield "COMMON_TEXT", text[end:begin], end, begin
                break
        else:
            return


def _statement_end(text: str, i: int, dialect: Dialect) -> int:
    """Where the statement whose text goes on at ``i`` ends, as DATA's skip finds it in
    GW-BASIC's crunched line (GWMAIN.ASM DATA): at a colon outside quotes, which CRUNCH also
    puts before an ELSE and a ``'`` remark; a REM's text, stored as typed, runs on to a
    colon, and so does a character no token starts with (CRUNCH stores it)."""
    stop = i
    try:
        for kind, _value, start, end in _lexemes(text, dialect, begin=i):
            if kind in ("_COLON", "ELSE") or (kind == "REMARK" and text[start] == "'"):
                return start
            if kind == "REMARK":
                return _scan_data(text, start)[1]
            stop = end
    except BasicError:
        return _scan_data(text, stop)[1]
    return len(text)


def tokenize(text: str, dialect: Dialect = CASIO) -> list:
    """The tokens of one line's statements (the text after its line number), as ``dialect`` reads them.

    A ``'`` remark after a statement is dropped (no colon is needed before it).
    Raises ``BasicError("Syntax error")`` for a character no token can start with.
    """
    tokens: list = []
    line_spec = False  # after a word whose line numbers may be "." (see below), up to another kind of token
    for kind, value, start, end in _line_lexemes(text, dialect):
        if kind == "REMARK" and tokens and text[start] == "'":
            break
        if _joins_go(tokens, kind, value, dialect.keyword_first):
            tokens[-1] = Token(_GO_JOINED[value], "GO" + value)
            continue
        if line_spec and kind == "NUMBER" and text[start:end].strip() == ".":
            # a lone "." where GWMAIN.ASM LINSPC reads a line number: DOT (the syntax tree is
            # imported here: a run of a cached program reads its lines with this module, no tree)
            from yaseer.basic.source.syntax_tree import CURRENT_LINE

            value = CURRENT_LINE
        line_spec = (kind in dialect.current_line_commands or kind in dialect.line_dot_words
                     or (line_spec and kind in _LINE_SPEC_TOKENS))
        tokens.append(Token(kind, value))
    if dialect.bracket_subscripts:
        _subscript_brackets(tokens)
    words = dialect.words
    if words and words.closes_parentheses:
        tokens = _closed_parentheses(tokens)
    if words and words.open_words and "OPEN" in text.upper():
        _open_words(tokens, words.open_words)
    if dialect.open_clauses and "OPEN" in text.upper():
        _open_clauses(tokens)
    if "CHAIN" in text.upper():
        _chain_delete_tail(tokens)
    return tokens


def _chain_delete_tail(tokens: list) -> None:
    """A comma after the line range of a CHAIN's DELETE option and what follows it, to the
    statement's end, are never read (FIVEO.ASM CHAIN: GWMAIN.ASM SCNLIN reads the range up
    to the statement's end or a comma, then the chaining goes on: a real GW-BASIC 3.23
    ignores ``CHAIN "f",,ALL,DELETE 10,PRINT``'s last item, PC-BASIC's
    CHAIN_with_dummy_fifth_argument test): those tokens are dropped."""
    k = 0
    while k < len(tokens):
        if tokens[k].type == "CHAIN":
            j = k + 1
            while j < len(tokens) and tokens[j].type not in ("DELETE", "_COLON"):
                j += 1
            if j < len(tokens) and tokens[j].type == "DELETE":
                j += 1
                if j < len(tokens) and tokens[j].type == "NUMBER":
                    j += 1
                if j < len(tokens) and tokens[j].type == "MINUS":
                    j += 1
                    if j < len(tokens) and tokens[j].type == "NUMBER":
                        j += 1
                end = j
                while end < len(tokens) and tokens[end].type != "_COLON" and tokens[j].type == "COMMA":
                    end += 1
                del tokens[j:end]
            k = j
        k += 1


OPEN_CLAUSE = "OPENCLAUSE"  # OPEN's ACCESS ..., SHARED, LOCK ...: (word, "R" | "W" | "RW" | "SHARED")


def _open_clauses(tokens: list) -> None:
    """In an OPEN statement's FOR form, its ACCESS and LOCK clauses as one
    :data:`OPEN_CLAUSE` token each (after the mode: ``ACCESS`` then READ, WRITE or READ
    WRITE; ``SHARED`` before AS; ``LOCK`` then READ, WRITE or READ WRITE); any other
    word stays as it is, for the grammar to refuse."""
    k = 0
    after_mode = False
    while k < len(tokens):
        kind, value = tokens[k].type, tokens[k].value
        if kind in ("_COLON", "ELSE", "THEN", "OPEN"):
            after_mode = False
        if kind == "FOR" and k and any(t.type == "OPEN" for t in tokens[:k]):
            after_mode = True
            k += 2  # FOR and its mode
            continue
        if after_mode and ((kind == "NAME" and value == "ACCESS") or (kind == "WORDSTMT" and value == "LOCK")):
            rights = _read_write(tokens, k + 1)
            if rights:
                word = "ACCESS" if kind == "NAME" else "LOCK"
                tokens[k:k + 1 + len(rights)] = [Token(OPEN_CLAUSE, (word, "".join(r[0] for r in rights)))]
        elif after_mode and kind == "NAME" and value == "SHARED" and k + 1 < len(tokens) \
                and tokens[k + 1].type == "NAME" and tokens[k + 1].value.startswith("AS"):
            tokens[k] = Token(OPEN_CLAUSE, ("LOCK", "SHARED"))
        k += 1


def _read_write(tokens: list, k: int) -> list[str]:
    """READ, WRITE or READ WRITE at ``tokens[k]``: the words (none: [])."""
    if k < len(tokens) and tokens[k].type == "WRITE":
        return ["WRITE"]
    if k < len(tokens) and tokens[k].type == "READ":
        return ["READ", "WRITE"] if k + 1 < len(tokens) and tokens[k + 1].type == "WRITE" else ["READ"]
    return []


UNSCANNED = "UNSCANNED"  # a statement the scanner cannot read; its value the scanner's error


def _outside_quotes_colons(text: str, start: int = 0) -> list[int]:
    """The places of the colons after ``start`` that are not inside a string literal."""
    places, quoted = [], False
    for k in range(start, len(text)):
        if text[k] == '"':
            quoted = not quoted
        elif text[k] == ":" and not quoted:
            places.append(k)
    return places


def tokenize_statements(text: str, dialect: Dialect = CASIO) -> list:
    """The tokens of one line as :func:`tokenize` gives them, except that each statement
    the scanner cannot read (``NAME$=1``: NAME is a reserved word, then a ``$``) is one
    ``UNSCANNED`` token holding its ``BasicError``: GW-BASIC's tokeniser (GWMAIN.ASM
    CRUNCH) stores any text, and the statement is found bad only when NEWSTT reaches it,
    after the statements before it ran.  A statement ends at a colon outside quotes."""
    try:
        return tokenize(text, dialect)
    except BasicError as whole:
        error = whole
    colons = _outside_quotes_colons(text)
    good, bad_from = [], 0
    for colon in colons:
        try:
            tokens = tokenize(text[:colon], dialect)
        except BasicError as exc:
            error = exc  # the first statement that does not scan ends at this colon
            break
        good, bad_from = tokens + [Token("_COLON", ":")], colon + 1
    after = next((colon for colon in colons if colon >= bad_from), None)
    bad = good + _scanned_start(text[bad_from:after], error, dialect)
    if after is None:
        return bad
    return bad + [Token("_COLON", ":")] + tokenize_statements(text[after + 1:], dialect)


def _scanned_start(statement: str, error: BasicError, dialect: Dialect) -> list:
    """A statement that does not scan: the tokens before the first lexeme that fails, then
    one ``UNSCANNED`` token (so ``IF 0 THEN NAME$=1`` keeps its IF and skips its branch)."""
    read = 0
    try:
        for _kind, _value, _start, read in _lexemes(statement, dialect):
            pass
    except BasicError as exc:
        error = exc
    try:
        head = tokenize(statement[:read], dialect)
    except BasicError:
        head = []
    otherwise = _upper_outside_strings(statement).find("ELSE", read)
    if otherwise < 0 or not any(token.type == "THEN" for token in head):
        return head + [Token(UNSCANNED, error)]
    # the bad THEN branch ends at ELSE: a false condition runs the ELSE branch (GWMAIN.ASM IF)
    return head + [Token(UNSCANNED, error), Token("ELSE", "ELSE")] + tokenize_statements(
        statement[otherwise + 4:], dialect)


def _open_words(tokens: list, words: dict) -> None:
    """In an OPEN statement, the reserved words OPEN reads as the names its grammar expects
    (``words``: the dialect's ``open_words``, word sequence -> name: the Casio's ``OUT PUT``,
    its keyword-first reading of OUTPUT, is ``OUTPUT``; ``AS`` is ``AS``: OPEN.md)."""
    k = 0
    opened = False
    while k < len(tokens):
        kind = tokens[k].type
        if kind == "OPEN":
            opened = True
        elif kind in ("_COLON", "ELSE", "THEN"):
            opened = False
        elif opened and kind == UNSUPPORTED:
            for sequence, name in words.items():
                found = tokens[k:k + len(sequence)]
                if all(t.type == UNSUPPORTED for t in found) and tuple(t.value for t in found) == sequence:
                    tokens[k:k + len(sequence)] = [Token("NAME", name)]
                    break
        k += 1


def _closed_parentheses(tokens: list) -> list:
    """The parentheses a statement leaves open closed where it ends (at a ``:`` or the
    line's end), as the Casio reads ``A=SQR(ABS(B/C):GOTO 200``."""
    closed: list = []
    depth = 0
    for token in tokens:
        if token.type == "_LPAR":
            depth += 1
        elif token.type == "_RPAR":
            depth = max(depth - 1, 0)
        elif token.type == "_COLON" and depth:
            closed.extend(Token("_RPAR", ")") for _ in range(depth))
            depth = 0
        closed.append(token)
    closed.extend(Token("_RPAR", ")") for _ in range(depth))
    return closed


def _subscript_brackets(tokens: list) -> None:
    """GW-BASIC's ``[ ]``: either may stand for a parenthesis of a subscript (the one after
    a name), nowhere else (a Syntax error)."""
    subscripts: list[bool] = []
    previous = None
    for token in tokens:
        if token.type == "_LPAR":
            subscripts.append(previous in ("NAME", "STRNAME"))
            if token.value == "[" and not subscripts[-1]:
                raise _syntax_error()
        elif token.type == "_RPAR":
            if token.value == "]" and not (subscripts and subscripts[-1]):
                raise _syntax_error()
            if subscripts:
                subscripts.pop()
        previous = token.type


_GO_JOINED = {"TO": "GOTO", "SUB": "GOSUB"}
_STATEMENT_STARTS = (None, "_COLON", "THEN", "ELSE")


def _joins_go(tokens: list, kind: str, value, keyword_first: bool) -> bool:
    """Is this ``TO`` or ``SUB`` the second word of ``GO TO`` / ``GO SUB`` at a statement
    start?  GW-BASIC's whole-word reading joins ``GO SUB`` with one blank itself and ``GO``
    and ``TO`` with any blanks between (``GO  SUB`` is a Syntax error: PC-BASIC 2.0.8)."""
    if value not in _GO_JOINED or kind not in ("TO", "NAME") or not tokens:
        return False
    if value == "SUB" and not keyword_first:
        return False
    last = tokens[-1]
    before = tokens[-2].type if len(tokens) > 1 else None
    return last.type == "NAME" and last.value.upper() == "GO" and before in _STATEMENT_STARTS


# Lexemes listed as words: a space separates two of them (``FOR J``, ``1 TO``, ``COS T``).
_WORDS = {"NAME", "STRNAME", "NUMBER", "STRING", "SYSVAR", "_RPAR"}
# Keywords followed by ``(`` without a space: functions and TAB/SPC.
_FUNCTION_TYPES = {"FUNC", "FUNCN", "TAB", "SPC"}
_TIGHT_AFTER = {"_COLON", "SEMI", "COMMA", "_RPAR"}


def detokenize(text: str, dialect: Dialect = CASIO) -> str:
    """A line's statements as the pocket computer lists them (LIST).

    Keywords are found as the scanner finds them and shown in capitals, with a
    space between a keyword and a neighbouring word (name, number, string, or
    another keyword), none around operators and separators; names in
    capitals; numbers, strings, remarks and DATA as typed.  Typed
    ``L=X/COST`` lists as ``L=X/COS T``, ``forj=1to3:printj;:nextj`` as
    ``FOR J=1 TO 3:PRINT J;:NEXT J``.  A line the scanner cannot read is
    returned as typed.
    """
    try:
        lexemes = list(_lexemes(text, dialect))
    except BasicError:
        return text.strip()
    out: list[str] = []
    previous = None  # type of the lexeme before
    # words OPEN reads as one (the Casio's OUT PUT): listed whole, as typed
    joined = {sequence for sequence in (dialect.words.open_words if dialect.words else ()) if len(sequence) == 2}
    for kind, value, start, end in lexemes:
        if kind == "REMARK":
            piece = text[start:end] if text[start] == "'" else "REM" + value
        elif kind == "DATA_TEXT":
            piece = "DATA " + value.lstrip()
        elif kind in ("NAME", "STRNAME"):
            piece = value
        elif kind in ("NUMBER", "STRING") or kind in _OPERATORS.values() or kind in _RELATIONS.values():
            piece = text[start:end].upper() if kind == "NUMBER" else text[start:end]
        else:
            piece = value  # a keyword
        if previous is not None and _spaced(previous, kind) and (out[-1], piece) not in joined:
            out.append(" ")
        out.append(piece)
        previous = kind
    return "".join(out)


def _is_keyword(kind: str) -> bool:
    return (kind in _KEYWORD_TYPES.values() and kind not in ("REMARK", "DATA_TEXT", "SYSVAR")) or kind == UNSUPPORTED


def _spaced(left: str, right: str) -> bool:
    """Is there a space between lexemes of types ``left`` and ``right`` in a listing?"""
    if right in _TIGHT_AFTER or left == "FN":
        return False
    if _is_keyword(left):
        return not (left in _FUNCTION_TYPES and right == "_LPAR")
    if _is_keyword(right) or right in ("REMARK", "DATA_TEXT"):
        return left in _WORDS or _is_keyword(left)
    return left in _WORDS and right in _WORDS and left != "_RPAR"


def _upper_outside_strings(text: str) -> str:
    """Upper-case everything but string literals (same length as ``text``)."""
    parts = text.split('"')
    for k in range(0, len(parts), 2):
        parts[k] = parts[k].upper()
    return '"'.join(parts)


class DirectStatementInFile(BasicError):
    """A program file's line without a line number, where the dialect does not join it onto
    the line before: loading stops there; ``lines`` holds the lines read before it and
    ``statement`` the line's own text (a direct statement, as GW-BASIC's MAIN read it)."""

    def __init__(self, lines: list, statement: str = "", code: int = DIRECT_STATEMENT_IN_FILE):
        super().__init__(error_message(code), code)
        self.lines = lines
        self.statement = statement

    def at(self, line, area: int = 0) -> "DirectStatementInFile":
        """Never placed at a line: GW-BASIC names none (the line is the file's, not the program's)."""
        return self


class LineBufferOverflowInFile(DirectStatementInFile):
    """A program file's line of more than 255 characters (SCNEDT.ASM DSKCHI: ``LBOERR``,
    ``Line buffer overflow``): loading stops there as at a direct statement, the lines
    before it loaded."""

    def __init__(self, lines: list, statement: str = ""):
        super().__init__(lines, statement, LINE_BUFFER_OVERFLOW)


class UndefinedLineInFile(BasicError):
    """A program file's line number with nothing after it, where no line of that number
    was read before it (``Dialect.bare_line_must_exist``): loading stops there with
    ``Undefined line number`` (GWMAIN.ASM EDENT: deleting a line that is not there is
    USERR), the lines before it loaded; ``lines`` as :class:`DirectStatementInFile`'s."""

    def __init__(self, lines: list):
        super().__init__(error_message(UNDEFINED_LINE), UNDEFINED_LINE)
        self.lines = lines

    def at(self, line, area: int = 0) -> "UndefinedLineInFile":
        """Never placed at a line: the line is the file's, not the program's."""
        return self


DOS_LINE_LENGTH = 255  # SCNEDT.ASM DSKCHI: BUFLEN, the characters a loaded line may hold
_DOS_BLANKS = " \t\n"  # GWMAIN.ASM CHRGTR steps over them (also between a line number's digits)
_LINE_NUMBER_ROOM = 6552  # GWMAIN.ASM LINGET takes another digit only up to this value


def dos_lines(source: str) -> list[str]:
    """A program file's physical lines as GW-BASIC's ASCII LOAD reads them (SCNEDT.ASM
    DSKCHI): a line ends at a CR, but a CR right after a LF is dropped and the LF stays in
    the line (``10 A=1:\\n\\rB=2`` is one line: LIST writes a line's LF as LF CR, GWLIST.ASM
    LISPRT / SCNEDT.ASM OUTCH1); LFs at a line's start are dropped (the LF of CR LF).  Text
    with no CR at all (written on Unix, never by DOS) has its lines end at LF (yaseer's
    choice: DSKCHI would read it as one line)."""
    if "\r" not in source:
        return source.split("\n")
    lines: list[str] = []
    current = ""
    for piece in source.split("\r"):
        current += piece.lstrip("\n") if not current else piece
        if not current.endswith("\n"):
            lines.append(current)
            current = ""
    if current:
        lines.append(current)
    return lines


def linget(text: str, i: int) -> tuple[int, int]:
    """The line number whose first digit is ``text[i]`` and the position after its last
    digit, as GWMAIN.ASM LINGET reads it: blanks between the digits skipped (CHRGTR), those
    after the last given back (BAKSP), another digit taken only while the number is at most
    6552 (so at most 65529; ``65536`` is 6553, then the text ``6``)."""
    number, end, j = 0, i, i
    while j < len(text) and number <= _LINE_NUMBER_ROOM and (text[j].isdigit() or text[j] in _DOS_BLANKS):
        if text[j].isdigit():
            number = number * 10 + ord(text[j]) - 48
            end = j + 1
        j += 1
    return number, end


def _dos_line_number(physical: str) -> tuple[int, int] | None:
    """The number a loaded line starts with and where its text begins, as GWMAIN.ASM MAIN
    reads it (None: no digit first, a direct statement): blanks, then LINGET's digits
    (blanks between them skipped; another digit taken only while the number is at most
    6552, so a longer run of digits leaves the rest to the text: ``111111`` is line 11111
    and the text ``1``); BAKSP gives back the blanks after the last digit, then one blank
    is skipped unless the number is 0."""
    end = len(physical)
    i = 0
    while i < end and physical[i] in _DOS_BLANKS:
        i += 1
    if i == end or not "0" <= physical[i] <= "9":
        return None
    number = 0
    after = i
    while i < end and number <= _LINE_NUMBER_ROOM:
        ch = physical[i]
        if "0" <= ch <= "9":
            number = number * 10 + ord(ch) - 48
            i += 1
            after = i
        elif ch in _DOS_BLANKS:
            i += 1
        else:
            break
    if number and after < end and physical[after] == " ":
        after += 1
    return number, after


def split_lines(source: str, joins_unnumbered: bool = True, keeps_blanks: bool = False,
                dos: bool = False, longest: int | None = None) -> list[tuple[int, str, int]]:
    """Split a listing into ``(line number, statement text, physical line index)``.

    Lines end at CR LF, LF or CR only (a machine's codes 28-31 and 133, which
    ``str.splitlines`` would also break at, are characters of a line).  A physical line
    that begins with a number followed by a space, a letter or the end of the line starts
    a new program line; any other non-blank line continues the previous one (joined with
    one space), or, when not ``joins_unnumbered`` (``Dialect.joins_unnumbered_lines``),
    ends the reading with :class:`DirectStatementInFile` (GW-BASIC's LOAD).  Text before
    the first numbered line is a syntax error (``BasicError`` with no line).
    ``keeps_blanks`` (``Dialect.tokenised_programs``): a line's text keeps its blanks but
    the one after the number (GWMAIN.ASM MAIN eats one: LIST prints one); else it is
    stripped.  A text of blanks only is empty (the line is deleted).
    """
    if dos:
        return _dos_split(source, keeps_blanks, longest)
    lines: list[tuple[int, str, int]] = []
    # (lines end at CR LF, then a lone CR or LF: as re.split(r"\r\n|\n|\r") cuts them)
    for index, physical in enumerate(source.replace("\r\n", "\n").replace("\r", "\n").split("\n")):
        if not physical.strip():
            continue
        found = _line_number(physical)
        if found:
            number, begins = found
            text = physical[begins:]
            if keeps_blanks:
                text = text if text.strip(" ") else ""
            else:
                text = text.strip()
            lines.append((number, text, index))
        elif not joins_unnumbered:
            raise DirectStatementInFile(lines, physical.strip())
        elif lines:
            number, text, first = lines[-1]
            lines[-1] = (number, (text + " " + physical.strip()).strip(), first)
        else:
            raise BasicError(f"Syntax error (no line number: {physical.strip()[:30]!r})", SYNTAX_ERROR)
    return lines


def _dos_split(source: str, keeps_blanks: bool, longest: int | None) -> list[tuple[int, str, int]]:
    """:func:`split_lines` for ``dos``: :func:`dos_lines`, each read by :func:`_dos_line_number`
    up to its first zero byte (the end of the line as MAIN and CRUNCH read it); a line of
    more than ``longest`` characters (None: any length) stops the reading
    (:class:`LineBufferOverflowInFile`), so does one without a number
    (:class:`DirectStatementInFile`)."""
    lines: list[tuple[int, str, int]] = []
    for index, physical in enumerate(dos_lines(source)):
        if longest is not None and len(physical) > longest:
            raise LineBufferOverflowInFile(lines, physical[:30])
        physical = physical.split("\0", 1)[0]  # DSKCHI ends the buffer with a 0: MAIN reads up to the first
        if not physical.strip(_DOS_BLANKS):
            continue
        found = _dos_line_number(physical)
        if found is None:
            raise DirectStatementInFile(lines, physical.strip())
        number, begins = found
        text = physical[begins:]
        if not text.strip(_DOS_BLANKS):
            text = ""
        elif not keeps_blanks:
            text = text.strip()
        lines.append((number, text, index))
    return lines


def program_lines(text: str, dialect: Dialect = CASIO, from_file: bool = False,
                  existing=None) -> tuple[dict[int, str | None], BasicError | None]:
    """A program file's text as the ``dialect``'s LOAD reads it (the one reader of program
    text: LOAD, RUN "f", CHAIN and MERGE in a program, the session's LOAD, the API and
    ``yaseer run``): line number -> text in the order the lines were read, a later line of a
    number replacing an earlier one and a line of blanks deleting it (:func:`split_lines`, with the dialect's
    ``joins_unnumbered_lines`` and ``tokenised_programs``); and the
    :class:`DirectStatementInFile` that stopped the reading at a line without a number
    (GIO86.ASM DIRDO: the lines before it are loaded), or the :class:`UndefinedLineInFile`
    of a bare line number that deletes no line (``bare_line_must_exist``), None if none.  ``from_file``: a file
    a program or the session loads (LOAD, RUN "f", CHAIN, MERGE): where the dialect reads
    lines as DSKCHI does (``dos_program_lines``) one of more than 255 characters stops the
    reading with ``Line buffer overflow``; the program handed to ``yaseer run`` or the API
    may hold longer lines (yaseer's choice: a listing written in an editor runs whole).
    ``existing``: the line numbers of the program the file is merged into (MERGE): a bare
    number of one of them deletes it, noted as the number with None."""
    stopped = None
    try:
        lines = split_lines(text, dialect.joins_unnumbered_lines, dialect.tokenised_programs,
                            dialect.dos_program_lines, DOS_LINE_LENGTH if from_file else None)
    except DirectStatementInFile as error:
        lines, stopped = error.lines, error
    program: dict[int, str] = {}
    present = set(existing or ())
    for k, (number, statement_text, _) in enumerate(lines):
        if not statement_text and dialect.bare_line_must_exist:
            if number not in present:
                return program, UndefinedLineInFile(lines[:k])  # (the lines after it are never read)
            present.discard(number)
        elif statement_text:
            present.add(number)
        program.pop(number, None)  # the dict's order is the order the lines were read in
        if statement_text:
            program[number] = statement_text
        elif existing is not None and number in existing:
            program[number] = None
    return program, stopped
