"""COMMON's list, read only when a CHAIN runs (FIVEO.ASM CHAIN, its step 2).

GW-BASIC's COMMON statement skips its list as DATA skips its items (FIVEO.ASM COMMON
jumps to GWMAIN.ASM DATA), so a list that does not read is no error where COMMON runs
(the scanner keeps it as typed: scanner.py ``COMMON_TEXT``).  A CHAIN without ALL scans
the program for the COMMON statements that begin a statement and reads their lists; the
first one that does not read stops the CHAIN with its error, in the COMMON's line (CHAIN
keeps each line's number in CURLIN as it scans).
"""

from __future__ import annotations

from yaseer.basic.dialects.dialect import Dialect
from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL, MISSING_OPERAND, SYNTAX_ERROR, error_for
from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.source.parser import parse_expression
from yaseer.basic.source.scanner import tokenize_statements

_UNARY = frozenset(("PLUS", "MINUS", "NOT"))


def chained_lists(text: str, dialect: Dialect) -> list[str]:
    """The lists (as typed) of the COMMON statements a CHAIN finds in the line ``text``:
    those that begin a statement, at the line's start or after a colon, not after THEN or
    ELSE (CHAIN skips every other statement as DATA does, to its colon)."""
    tokens = tokenize_statements(text, dialect)
    return [tokens[k + 1].value for k, token in enumerate(tokens[:-1])
            if token.type == "COMMON" and tokens[k + 1].type == "COMMON_TEXT"
            and (k == 0 or tokens[k - 1].type == "_COLON")]


def common_items(text: str, dialect: Dialect) -> tuple[list[tuple[str, bool]], BasicError | None]:
    """The variables of the COMMON list ``text``, ``(name, is an array)`` each, up to the
    first that does not read, and its error (None: the whole list reads).

    As CHAIN reads a list: nothing, or a name (BIPTRG.ASM PTRGTN: Syntax error where none
    starts), an array with ``()`` or ``(`` one operand ``)`` after it (the operand, a number
    of dimensions other compilers want, read by GWEVAL.ASM EVAL: none at the statement's end
    Missing operand, a string Illegal function call, more than one operand Syntax error),
    then a comma and the next, or the statement's end.  The operand is not evaluated.  A
    name followed by ``[``, a number and ``]`` is passed over and not kept, any other
    bracket Syntax error, as a real GW-BASIC 3.23 recorded them (PC-BASIC's COMMONA,
    COMMONC, COMMONI) and PC-BASIC 2.0.8 reads them."""
    tokens = tokenize_statements(text, dialect)
    items: list[tuple[str, bool]] = []
    k = 0
    while tokens:
        if k == len(tokens) or tokens[k].type not in ("NAME", "STRNAME"):
            return items, error_for(SYNTAX_ERROR)
        name, k = tokens[k].value, k + 1
        if k < len(tokens) and tokens[k].value == "[":
            # a bracket after the name (the recordings: ``COMMON A[2]`` keeps neither A nor
            # A(), no error; ``COMMON B[]`` is Syntax error; FIVEO.ASM's scan knows only
            # "("): a number, then the closing bracket, as PC-BASIC 2.0.8 reads it
            if not (k + 2 < len(tokens) and tokens[k + 1].type == "NUMBER" and tokens[k + 2].type == "_RPAR"):
                return items, error_for(SYNTAX_ERROR)
            k += 3
            if k == len(tokens):
                break
            if tokens[k].type != "COMMA":
                return items, error_for(SYNTAX_ERROR)
            k += 1
            continue
        array = k < len(tokens) and tokens[k].type == "_LPAR"
        if array:
            k, error = _dimensions(tokens, k + 1)
            if error is not None:
                return items, error
        items.append((name, array))
        if k == len(tokens):
            break
        if tokens[k].type != "COMMA":
            return items, error_for(SYNTAX_ERROR)
        k += 1
    return items, None


def _dimensions(tokens: list, k: int) -> tuple[int, BasicError | None]:
    """After an array's ``(`` at ``k``: where its ``)`` ends, and the error of what is
    between (nothing, or one operand: see :func:`common_items`)."""
    if k < len(tokens) and tokens[k].type == "_RPAR":
        return k + 1, None
    end, depth = k, 0
    while end < len(tokens) and not (depth == 0 and tokens[end].type == "_RPAR"):
        depth += {"_LPAR": 1, "_RPAR": -1}.get(tokens[end].type, 0)
        end += 1
    for last in range(end, k, -1):
        operand = tokens[k:last]
        node = parse_expression(operand)
        if node is not None and (not isinstance(node, ast.Binary) or _enclosed(operand)):
            if ast.expr_type(node) == "s":
                return last, error_for(ILLEGAL_FUNCTION_CALL)
            if last < len(tokens) and tokens[last].type == "_RPAR":
                return last + 1, None
            return last, error_for(SYNTAX_ERROR)
    if end == len(tokens) and all(token.type in _UNARY for token in tokens[k:end]):
        return end, error_for(MISSING_OPERAND)  # EVAL met the statement's end
    return end, error_for(SYNTAX_ERROR)


def _enclosed(tokens: list) -> bool:
    """Whether ``tokens`` are one parenthesised expression, ``( ... )``."""
    depth = 0
    for k, token in enumerate(tokens):
        depth += {"_LPAR": 1, "_RPAR": -1}.get(token.type, 0)
        if depth == 0:
            return k == len(tokens) - 1 and token.type == "_RPAR"
    return False
