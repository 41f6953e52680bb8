"""Screen statements whose text goes wrong, read as GW-BASIC reads their small numbers.

GW-BASIC reads the arguments of CLS, LOCATE, WIDTH (the screen's), COLOR and SCREEN one at
a time (GWSTS.ASM SCNINT, called by CLS, LOCATE, GWWID and GTPRMS): a comma or the end of
the statement where an argument may stand leaves it out; otherwise GETBYT evaluates a
number, and what stops it must be ``,``, ``)`` (read like a comma) or the statement's end,
else Illegal function call.  So a bad statement of that kind is not a Syntax error as a
whole: the numbers before the bad text are read (and checked) first, then

* a number followed by something that cannot go on with it (``CLS 0 LAH``, ``WIDTH 40 X``)
  is Illegal function call;
* text no expression starts with where an argument starts (``CLS , PRINT``) is the
  evaluation's Syntax error.

:func:`read_byte_list` makes the :class:`~yaseer.basic.source.syntax_tree.ByteList` that
runs so (the compiler then applies the statement's own count: EOSCHK after it).  A text
that goes wrong inside an expression (``CLS 1+``) is left to the expression's own error.

:func:`mark_literal_widths` reads ``WIDTH n`` where n starts with a number as that number
alone (``Dialect.screen.literal_width``).
"""

from __future__ import annotations

from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL, SYNTAX_ERROR, error_for
from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.source.scanner import UNSCANNED, Token

_ENDS = frozenset(("_COLON", "ELSE"))
# what may follow a whole expression and go on with it: the text is then bad inside it
_GOES_ON = frozenset(("PLUS", "MINUS", "STAR", "SLASH", "BSLASH", "CARET", "EQ", "LT", "GT", "LE", "GE", "NE",
                      "AND", "OR", "XOR", "EQV", "IMP", "MOD", "_LPAR"))


def _pieces(tokens: list) -> list:
    """``tokens`` cut at each ``,`` and each ``)`` that closes no ``(`` (SCNINT reads both
    as the end of an argument)."""
    pieces, depth, piece = [], 0, []
    for token in tokens:
        kind = token.type
        if depth == 0 and kind in ("COMMA", "_RPAR"):
            pieces.append(piece)
            piece = []
            continue
        depth += {"_LPAR": 1, "_RPAR": -1}.get(kind, 0)
        piece.append(token)
    pieces.append(piece)
    return pieces


def read_byte_list(tokens: list, start: int, dialect, parse_expression):
    """The bad statement at ``tokens[start]`` as a ByteList, where the dialect reads its
    word's arguments so (see the module docstring); else None.  ``parse_expression`` reads
    a list of tokens as one expression (None where they are none)."""
    word = tokens[start].type
    if word not in dict(dialect.screen.byte_statements):
        return None
    end = next((k for k in range(start + 1, len(tokens)) if tokens[k].type in _ENDS), len(tokens))
    if word == "WIDTH" and (start + 1 == end or tokens[start + 1].type in ("HASH", "LPRINT")):
        return None  # a file's or the printer's width, or no width: GIO86.ASM WIDTHS reads those otherwise
    args: list = []
    for k, piece in enumerate(_pieces(tokens[start + 1:end])):
        if not piece:
            args.append(None)
            continue
        whole = parse_expression(piece)
        if whole is not None:
            if word == "WIDTH" and k == 0 and ast.expr_type(whole) == "s":
                return None  # WIDTH "device", n
            args.append(whole)
            continue
        read = next((n for n in range(len(piece) - 1, 0, -1) if parse_expression(piece[:n]) is not None), 0)
        if read == 0:  # no expression starts here: GETBYT's evaluation finds none
            first = piece[0]
            error = first.value if first.type == UNSCANNED else BasicError("Syntax error", SYNTAX_ERROR)
            return ast.ByteList(word, args, error)
        first = parse_expression(piece[:read])
        if piece[read].type in _GOES_ON or (word == "WIDTH" and k == 0 and ast.expr_type(first) == "s"):
            return None  # bad inside the expression (its own error), or WIDTH "device" without its comma
        return ast.ByteList(word, args + [first], error_for(ILLEGAL_FUNCTION_CALL))
    return ast.ByteList(word, args, None)


def mark_literal_widths(tokens: list, dialect) -> list:
    """``tokens`` with each ``WIDTH n ...`` whose n is a number followed by more than a
    comma or the statement's end cut after the number, an unscanned token holding Illegal
    function call standing for the rest (so ``WIDTH 39+1`` reads 39 and then fails: the
    recorded WIDTH test), in a dialect whose screen reads so (``literal_width``)."""
    if not dialect.screen.literal_width or not any(token.type == "WIDTH" for token in tokens):
        return tokens
    out: list = []
    k = 0
    while k < len(tokens):
        token = tokens[k]
        out.append(token)
        k += 1
        if token.type != "WIDTH" or k + 1 >= len(tokens) or tokens[k].type != "NUMBER" \
                or tokens[k + 1].type in _ENDS or tokens[k + 1].type in ("COMMA", "_RPAR"):
            continue
        out.append(tokens[k])
        out.append(Token(UNSCANNED, error_for(ILLEGAL_FUNCTION_CALL)))
        k += 1
        while k < len(tokens) and tokens[k].type not in _ENDS:
            k += 1
    return out
