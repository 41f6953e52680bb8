"""The statements of gw's device words (dialects/gw_words.py: OUT, WAIT, LOCK, CALL ...) as
GW-BASIC reads them: argument by argument, each error where its routine finds it.

GW-BASIC has no grammar: a statement's routine reads an argument, checks its type, reads a
comma (SYNCHR), reads the next, and returns to NEWSTT, which refuses anything but the end of
the statement (GWMAIN.ASM GONZER).  So ``OUT "!"`` is Type mismatch before the missing
comma is seen, ``OUT 0,`` is Missing operand (FRMEVL finds no operand), and ``OUT 0,0,0``
does its OUT and is then Syntax error.  :func:`device_statement` writes the code that does
the same: the arguments evaluated in order up to the first that fails, or the helper called
with them and then the error of what follows.
"""

from __future__ import annotations

from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.errors import MISSING_OPERAND, SYNTAX_ERROR, TYPE_MISMATCH, error_message


def _fail(code: int) -> str:
    return f"_fail({error_message(code)!r}, {code})"


def _routine_error(arg) -> int | None:
    """CALL's routine: a numeric variable, with variables in parentheses (CALL86.ASM reads each
    as PTRGET does); None when it is one, else its error (a string variable: Type mismatch)."""
    if not isinstance(arg, (ast.Var, ast.Elem)):
        return SYNTAX_ERROR
    if arg.name.endswith("$"):
        return TYPE_MISMATCH
    if isinstance(arg, ast.Elem) and not all(isinstance(a, (ast.Var, ast.Elem)) for a in arg.indices):
        return SYNTAX_ERROR
    return None


def _argument(compiler, arg, kind: str, scope) -> tuple[str | None, int | None]:
    """(code, None) for an argument of ``kind`` (gw_words.STATEMENTS), or (None, its error)."""
    if kind == "v":
        error = _routine_error(arg)
        return ("None", None) if error is None else (None, error)
    is_string = compiler.type_of(arg) == "s"
    if is_string != (kind == "s"):
        return None, TYPE_MISMATCH
    if kind == "s":
        return compiler.string(arg, scope), None
    if kind == "i":
        return compiler.integer(arg, scope), None
    return compiler.numeric(arg, scope), None


def device_statement(compiler, stmt, words, scope) -> None:
    """Emit ``stmt``, a statement of the device words ``words`` (gw_words.Words): its entry's
    kinds, least arguments, helper and the marks that may come first; the word before its last
    argument (LOCK's TO: ``range_words``), else a comma; whether it checks the end of the
    statement before it acts (``ends_first``)."""
    kinds, least, helper, first = words.statements[stmt.word]
    range_word = words.range_words.get(stmt.word)
    checks_end = stmt.word in words.ends_first
    marks = stmt.marks
    lead = marks[:1] if marks[:1] in ("#", "=") else ""
    separators = marks[len(lead):]
    codes: list[str] = []
    before = after = None  # the error before the helper runs, and after it
    if lead and lead not in first:
        before = SYNTAX_ERROR
    for k, arg in enumerate(stmt.args):
        if before is not None:
            break
        if k >= len(kinds):  # the routine has read all it reads: NEWSTT finds the rest (EOSCHK first)
            if checks_end:
                before = SYNTAX_ERROR
            else:
                after = SYNTAX_ERROR
            break
        wanted = "T" if range_word and k == len(kinds) - 1 else ","
        if k and separators[k - 1] != wanted:
            before = SYNTAX_ERROR
            break
        code, before = _argument(compiler, arg, kinds[k], scope)
        if code is not None:
            codes.append(code)
    if before is None and after is None:
        trailing = len(separators) >= max(len(stmt.args), 1) and separators.endswith(",")
        if trailing and len(stmt.args) < len(kinds):
            before = MISSING_OPERAND  # a comma read, then FRMEVL finds no operand
        elif trailing and checks_end:
            before = SYNTAX_ERROR
        elif trailing:
            after = SYNTAX_ERROR
        elif not stmt.args and least:  # FRMEVL finds no operand; CALL's PTRGET finds no name
            before = SYNTAX_ERROR if kinds[0] == "v" else MISSING_OPERAND
        elif len(stmt.args) < least:
            before = SYNTAX_ERROR  # SYNCHR wants the comma
    if before is not None:
        compiler.emit(f"({', '.join(codes + [_fail(before)])},)")
        return
    compiler.emit(f"{helper}({', '.join(codes)})")
    if after is not None:
        compiler.emit(_fail(after))


def _event_index(compiler, stmt, form: str | None, scope) -> tuple[str | None, int | None]:
    """(code of the number in parentheses, None), or (None, the error): Syntax error where the
    word wants parentheses and has none or has them and wants none; a string is Type mismatch
    (GETBYT's FRMEVL, before anything else is checked)."""
    if (form is None) != (stmt.index is None):
        return None, SYNTAX_ERROR
    if stmt.index is None:
        return "None", None
    if compiler.type_of(stmt.index) == "s":
        return None, TYPE_MISMATCH
    if form == "seconds":
        return compiler.numeric(stmt.index, scope), None
    return compiler.integer(stmt.index, scope), None


def event_trap(compiler, stmt, events, scope) -> None:
    """Emit ``ON word(n) GOSUB line`` (gw_words.EVENTS): n checked (GWSTS.ASM ONGOTP), then the
    line found (FNDLN1: Undefined line number), then the trap set; line 0 ends the trap."""
    form = events[stmt.word][0]
    index, error = _event_index(compiler, stmt, form, scope)
    if error is not None:
        compiler.emit(_fail(error))
        return
    block = compiler.block_of_line(stmt.line) if stmt.line else None
    if stmt.line and block is None:  # n checked, then the line's error, as a GOTO to it
        compiler.emit(f"_M.events.check({stmt.word!r}, {index}, False)")
        compiler.emit(compiler.jump(stmt.line))
        return
    target = "None" if block is None else f"({compiler.area}, {block})"
    compiler.emit(f"_M.events.trap({stmt.word!r}, {index}, {target})")  # (trap checks n)


def event_switch(compiler, stmt, events, scope) -> None:
    """Emit ``word(n) ON|OFF|STOP`` or ``word ON|OFF|STOP`` (GWSTS.ASM SEVSTT, PENS, STRIGS)."""
    _, form, _, alone = events[stmt.word]
    if stmt.index is None and stmt.state not in alone:
        compiler.emit(_fail(SYNTAX_ERROR))
        return
    index, error = _event_index(compiler, stmt, form if stmt.index is not None else None, scope)
    if error is not None:
        compiler.emit(_fail(error))
        return
    compiler.emit(f"_M.events.switch({stmt.word!r}, {index}, {stmt.state!r})")
