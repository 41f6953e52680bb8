"""Source text -> tokens, the way the pocket computers' tokenisers read a line.

Keywords are recognised first, wherever they start inside a run of letters:
``COST`` is ``COS T``, ``GOSUBPROG1`` is ``GOSUB PROG 1``, ``IFX<0THEN`` is
``IF X < 0 THEN``.  A variable name is a letter followed by letters and digits
up to the next place where a keyword starts; a trailing ``$`` makes it a
string variable.  Case does not matter outside string literals.

The scanner also splits a listing into lines: a physical line that does not
begin with a line number continues the previous line (the paper wraps long
lines); see :func:`split_lines`.

Token types are the terminal names declared in ``grammar.lark``.
"""

from __future__ import annotations

import re

from yaseer.basic.errors import BasicError, OVERFLOW, SYNTAX_ERROR

# Statement and operator keywords: each is its own terminal type.
STATEMENT_KEYWORDS = (
    "LET", "PRINT", "LPRINT", "USING", "FOR", "TO", "STEP", "NEXT", "GOTO", "GOSUB",
    "PROG", "RETURN", "IF", "THEN", "ELSE", "ON", "END", "STOP", "DIM", "CLEAR",
    "READ", "RESTORE", "INPUT", "DEF", "FN", "ERROR", "RESUME", "RANDOMIZE", "DEG",
    "RAD", "AND", "OR", "NOT", "MOD", "TAB", "SPC", "TRON", "TROFF", "CLS", "WIDTH",
)
# Functions of one argument (parentheses optional: ``COS T``).
UNARY_FUNCTIONS = (
    "SIN", "COS", "TAN", "ATN", "SQR", "ABS", "INT", "FIX", "SGN", "EXP", "LOG", "RND",
    "LEN", "STR$", "VAL", "CHR$", "ASC",
)
# Functions that need a parenthesised argument list.
LIST_FUNCTIONS = ("LEFT$", "RIGHT$", "MID$")
# Values without arguments.
SYSTEM_VARIABLES = ("ERR", "ERL")
COMMENT_KEYWORD = "REM"
DATA_KEYWORD = "DATA"

_KEYWORD_TYPES: dict[str, str] = {}
for _word in STATEMENT_KEYWORDS:
    _KEYWORD_TYPES[_word] = _word
for _word in UNARY_FUNCTIONS:
    _KEYWORD_TYPES[_word] = "FUNC"
for _word in LIST_FUNCTIONS:
    _KEYWORD_TYPES[_word] = "FUNCN"
for _word in SYSTEM_VARIABLES:
    _KEYWORD_TYPES[_word] = "SYSVAR"
_KEYWORD_TYPES[COMMENT_KEYWORD] = "REMARK"
_KEYWORD_TYPES[DATA_KEYWORD] = "DATA_TEXT"

# Longest keywords first, so that INPUT wins over INT and ERROR over ERR.
_KEYWORDS_BY_LENGTH = sorted(_KEYWORD_TYPES, key=len, reverse=True)
_KEYWORDS_BY_LETTER: dict[str, tuple[str, ...]] = {}
for _word in _KEYWORDS_BY_LENGTH:
    _KEYWORDS_BY_LETTER.setdefault(_word[0], ())
    _KEYWORDS_BY_LETTER[_word[0]] += (_word,)

_OPERATORS = {
    "+": "PLUS", "-": "MINUS", "*": "STAR", "/": "SLASH", "\\": "BSLASH", "^": "CARET",
    "(": "_LPAR", ")": "_RPAR", ",": "COMMA", ";": "SEMI", ":": "_COLON",
}
_RELATIONS = {
    "=": "EQ", "<": "LT", ">": "GT", "<=": "LE", "=<": "LE", ">=": "GE", "=>": "GE",
    "<>": "NE", "><": "NE",
}
_NUMBER = re.compile(r"(\d+\.?\d*|\.\d+)(E[+-]?\d+)?")
_LINE_NUMBER = re.compile(r"\s*(\d+)(?=[\sA-Za-z'?]|$)\s?")

def keyword_at(upper: str, i: int) -> str | None:
    """The longest keyword that starts at position ``i`` of the upper-cased text."""
    for word in _KEYWORDS_BY_LETTER.get(upper[i], ()):
        if upper.startswith(word, i):
            return word
    return None


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


def _scan_name(upper: str, i: int) -> tuple[str, str, int]:
    """A variable name from ``i``: letters/digits until a keyword starts; ``$`` ends it."""
    j = i + 1
    while j < len(upper) and upper[j].isalnum() and upper[j].isascii() and keyword_at(upper, j) is None:
        j += 1
    if j < len(upper) and upper[j] == "$":
        return "STRNAME", upper[i:j + 1], j + 1
    return "NAME", upper[i:j], j


def _scan_number(upper: str, i: int) -> tuple[float, int]:
    match = _NUMBER.match(upper, i)
    if match is None:
        raise _syntax_error()
    value = float(match.group(0))
    if value == float("inf"):
        raise BasicError("Overflow", OVERFLOW)
    return value, match.end()


def _lexemes(text: str):
    """``(token type, value, start, end)`` for each token of one line, in order.

    ``start:end`` is the token's span in ``text``.  A remark (``REM`` or ``'``)
    is the last lexeme: type ``REMARK``, value the text after it.  Raises
    ``BasicError("Syntax error")`` at a character no token can start with.
    """
    upper = _upper_outside_strings(text)
    i = 0
    n = len(text)
    while i < n:
        ch = upper[i]
        start = i
        if ch in " \t\r\n":
            i += 1
            continue
        if ch == '"':
            value, i = _scan_string(text, i)
            yield "STRING", value, start, i
        elif ch == "'":
            yield "REMARK", text[i + 1:], start, n
            return
        elif ch.isdigit() or (ch == "." and i + 1 < n and upper[i + 1].isdigit()):
            value, i = _scan_number(upper, i)
            yield "NUMBER", value, start, i
        elif ch.isascii() and ch.isalpha():
            word = keyword_at(upper, i)
            if word == COMMENT_KEYWORD:
                yield "REMARK", text[i + len(word):], start, n
                return
            if word == DATA_KEYWORD:
                raw, i = _scan_data(text, i + len(word))
                yield "DATA_TEXT", raw, start, i
            elif word is not None:
                i += len(word)
                yield _KEYWORD_TYPES[word], word, start, i
            else:
                kind, name, i = _scan_name(upper, i)
                yield kind, name, start, i
        elif ch in "<>=":
            pair = upper[i:i + 2]
            symbol = pair if pair in _RELATIONS else ch
            i += len(symbol)
            yield _RELATIONS[symbol], symbol, start, i
        elif ch in _OPERATORS:
            i += 1
            yield _OPERATORS[ch], ch, start, i
        elif ch == "?":
            i += 1
            yield "PRINT", "PRINT", start, i
        else:
            raise _syntax_error()


def tokenize(text: str) -> list:
    """The tokens of one line's statements (the text after its line number).

    A ``'`` remark after a statement is dropped (no colon is needed before it).
    Raises ``BasicError("Syntax error")`` for a character no token can start with.
    """
    from lark import Token  # here, not at the top: loading a listing (split_lines) needs no lark

    tokens: list = []  # lark Tokens
    for kind, value, start, _ in _lexemes(text):
        if kind == "REMARK" and tokens and text[start] == "'":
            break
        tokens.append(Token(kind, value))
    return tokens


# Lexemes listed as words: a space separates two of them (``FOR J``, ``1 TO``, ``COS T``).
_WORDS = {"NAME", "STRNAME", "NUMBER", "STRING", "SYSVAR", "_RPAR"}
# Keywords followed by ``(`` without a space: functions and TAB/SPC.
_FUNCTION_TYPES = {"FUNC", "FUNCN", "TAB", "SPC"}
_TIGHT_AFTER = {"_COLON", "SEMI", "COMMA", "_RPAR"}


def detokenize(text: str) -> str:
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
        lexemes = list(_lexemes(text))
    except BasicError:
        return text.strip()
    out: list[str] = []
    previous = None  # type of the lexeme before
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
        if previous is not None and _spaced(previous, kind):
            out.append(" ")
        out.append(piece)
        previous = kind
    return "".join(out)


def _is_keyword(kind: str) -> bool:
    return kind in _KEYWORD_TYPES.values() and kind not in ("REMARK", "DATA_TEXT", "SYSVAR")


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


def split_lines(source: str) -> list[tuple[int, str, int]]:
    """Split a listing into ``(line number, statement text, physical line index)``.

    A physical line that begins with a number followed by a space, a letter or
    the end of the line starts a new program line; any other non-blank line
    continues the previous one (joined with one space).  Text before the first
    numbered line is a syntax error (``BasicError`` with no line).
    """
    lines: list[tuple[int, str, int]] = []
    for index, physical in enumerate(source.splitlines()):
        if not physical.strip():
            continue
        match = _LINE_NUMBER.match(physical)
        if match:
            lines.append((int(match.group(1)), physical[match.end():].strip(), index))
        elif lines:
            number, text, first = lines[-1]
            lines[-1] = (number, (text + " " + physical.strip()).strip(), first)
        else:
            raise BasicError(f"Syntax error (no line number: {physical.strip()[:30]!r})", SYNTAX_ERROR)
    return lines
