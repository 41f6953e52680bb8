"""The abstract syntax tree of a BASIC line: plain data, no behaviour.

Expression nodes carry their static type through :func:`expr_type`: a name
ending in ``$``, a string literal and the string functions are strings (``"s"``),
everything else is a number (``"n"``).
"""

from __future__ import annotations

TYPE_CHECKING = False  # type checkers read the aliases below; a run does not import typing for them


class Node:
    """A syntax-tree node: fields named in ``_fields`` (class-level defaults allowed).

    Plain classes rather than dataclasses: creating dataclasses costs start-up time.
    """

    __slots__ = ()
    _fields: tuple = ()

    def __init__(self, *args, **kwargs):
        for name, value in zip(self._fields, args):
            object.__setattr__(self, name, value)
        for name in self._fields[len(args):]:
            if name in kwargs:
                value = kwargs.pop(name)
            elif name in _DEFAULTS.get(type(self).__name__, {}):
                value = _DEFAULTS[type(self).__name__][name]
                value = list(value) if isinstance(value, list) else value
            else:
                raise TypeError(f"{type(self).__name__} needs {name}")
            object.__setattr__(self, name, value)
        if kwargs:
            raise TypeError(f"{type(self).__name__} has no field {next(iter(kwargs))}")

    def _values(self) -> tuple:
        return tuple(getattr(self, name) for name in self._fields)

    def __eq__(self, other):
        return type(other) is type(self) and other._values() == self._values()

    def __hash__(self):
        return hash((type(self).__name__,) + tuple(
            tuple(v) if isinstance(v, list) else v for v in self._values()))

    def __repr__(self):
        inner = ", ".join(f"{name}={getattr(self, name)!r}" for name in self._fields)
        return f"{type(self).__name__}({inner})"


_DEFAULTS: dict[str, dict] = {}


def _node(name, bases: tuple = (), namespace: dict | None = None) -> type:
    """The metaclass of every node class (``class Num(metaclass=_node)``): the annotated names
    become the node's fields, in order, and the class is made once, a :class:`Node` with those
    slots.  (Still taken as a class decorator, ``@_node``, which makes each class twice: ~85
    classes, a cold start's time; tests/test_startup_imports.py refuses it.)"""
    if namespace is None:  # @_node class X: ... (the class made once already)
        made = name
        name = made.__name__
        namespace = {k: v for k, v in made.__dict__.items() if k not in ("__dict__", "__weakref__")}
    fields = tuple(namespace.get("__annotations__", {}))
    defaults = {field: namespace.pop(field) for field in fields if field in namespace}
    _DEFAULTS[name] = {k: ([] if v is _LIST else v) for k, v in defaults.items()}
    namespace["__slots__"] = fields
    namespace["_fields"] = fields
    return type(name, (Node,), namespace)


_LIST = object()  # default: a fresh empty list

# ---------------------------------------------------------------- expressions


class Num(metaclass=_node):
    value: float
    kind: str = ""  # GW-BASIC literal type "%", "!" or "#"; "" in the untyped (casio) model


class Str(metaclass=_node):
    value: str


class Var(metaclass=_node):
    """A scalar variable; ``name`` is upper case and keeps its ``$``."""
    name: str


class Elem(metaclass=_node):
    """An array element ``name(indices...)``."""
    name: str
    indices: tuple


class Unary(metaclass=_node):
    op: str  # "-", "+", "NOT"
    operand: object


class Binary(metaclass=_node):
    op: str  # "+", "-", "*", "/", "\\", "^", "MOD", "=", "<>", "<", ">", "<=", ">=", "AND", "OR"
    left: object
    right: object
    bare_not: bool = False  # the right side a NOT without parentheses (13*NOT 7: Dialect.not_after_operator)


class Call(metaclass=_node):
    """A built-in function; ``args`` may be empty (``RND``)."""
    name: str
    args: tuple


class FnCall(metaclass=_node):
    """A user function ``FN name(args)``."""
    name: str
    args: tuple


class SetClock(metaclass=_node):
    """``DATE$ = value`` or ``TIME$ = value``: the machine's clock set (machine/clock.py)."""
    name: str  # "DATE$" or "TIME$"
    value: object


class FilePointer(metaclass=_node):
    """``VARPTR(#n)``, ``IOCTL$(#n)``: a function of a file number."""
    name: str
    number: object


class CutFileCall(metaclass=_node):
    """``VARPTR(#n`` with no ``)``: the file number read and its file checked as the function
    checks it, then ``error`` where the ``)`` should be."""
    name: str
    number: object
    error: object


class SysVar(metaclass=_node):
    name: str  # "ERR", "ERL"


if TYPE_CHECKING:
    from typing import Union

    Expr = Union[Num, Str, Var, Elem, Unary, Binary, Call, FnCall, SysVar]
    LValue = Union[Var, Elem]

STRING_FUNCTIONS = frozenset({"STR$", "CHR$", "LEFT$", "RIGHT$", "MID$"})


# Functions of a string that give the string back in GW-BASIC: MATH1.ASM $VABS and $VINT look
# at the type only to pick the integer routine, not for a string (VSIGN, for SGN, raises Type
# mismatch); what $VINT's single-precision INT then does to a string's descriptor the real
# machine's recorded output shows: nothing (PC-BASIC 2.0.8 agrees).  Casio: Type mismatch.
KEEPS_STRINGS = frozenset(("ABS", "INT"))


def expr_type(node, named=None) -> str:
    """``"s"`` for a string-valued expression, ``"n"`` for a number.  ``named``: the type
    (``"s"`` or another) of a variable's or FN's name, where it is not the name's own
    character alone (gw's DEFSTR: compile.number_models); default: a name ending in ``$``."""
    if isinstance(node, Str):
        return "s"
    if isinstance(node, (Var, Elem, FnCall)):
        if named is not None:
            return "s" if named(node.name) == "s" else "n"
        return "s" if node.name.endswith("$") else "n"
    if isinstance(node, Call) and node.name in KEEPS_STRINGS and len(node.args) == 1:
        return expr_type(node.args[0], named)
    if isinstance(node, (Call, SysVar, CutCall)):
        return "s" if node.name.endswith("$") else "n"
    if isinstance(node, CutExpression):
        return expr_type(node.read, named)
    if isinstance(node, Unary) and node.op in "+-":  # (-A$ is A$ in GW)
        return expr_type(node.operand, named)
    if isinstance(node, Binary) and node.op == "+":
        return expr_type(node.left, named)
    return "n"


# ---------------------------------------------------------------- statements


class Let(metaclass=_node):
    target: object
    value: object


class Print(metaclass=_node):
    printer: bool  # LPRINT
    items: list  # expressions, "," ";" separators, Tab, Spc
    using: object = None  # format expression for PRINT USING
    channel: object = None  # PRINT #n: the file number expression
    lead: list = _LIST  # PRINT items USING ...: the items printed before the USING


class Tab(metaclass=_node):
    column: object


class Spc(metaclass=_node):
    count: object


class For(metaclass=_node):
    var: object
    start: object
    stop: object
    step: object = None


class Next(metaclass=_node):
    var: object = None  # None: the innermost loop


class Goto(metaclass=_node):
    target: int


class Gosub(metaclass=_node):
    target: int


class GosubProg(metaclass=_node):
    area: int


class GotoArea(metaclass=_node):
    """GOTO #n: run program area n; the program ends when it does."""
    area: int


class GosubArea(metaclass=_node):
    """GOSUB #n: run program area n and come back (as GOSUB PROG n)."""
    area: int


class GotoFile(metaclass=_node):
    """GOTO "file:label" (a string expression): run that program; the program ends when it does."""
    name: object


class GosubFile(metaclass=_node):
    """GOSUB "file:label": run that program until its RETURN and come back."""
    name: object


class Return(metaclass=_node):
    pass


class OnJump(metaclass=_node):
    """ON x GOTO/GOSUB: ``targets`` the line numbers (None where a place is empty);
    ``rest_error`` what the statement's text after them is when the selector picks none of
    them (GW reads them all then: GWMAIN.ASM NTONGS), None where the statement ends there."""
    selector: object
    targets: list
    gosub: bool
    rest_error: object = None


class OnError(metaclass=_node):
    target: int  # 0 switches trapping off


class End(metaclass=_node):
    pass


class Stop(metaclass=_node):
    pass


class Rem(metaclass=_node):
    text: str = ""
    skipped: list = _LIST  # an ELSE no IF owns: the statements after it, never run (blocks.scanned_statements)


class Dim(metaclass=_node):
    arrays: list  # [(name, (size exprs...))]


class Clear(metaclass=_node):
    args: list = _LIST  # CLEAR [n][,[m][,k]]: memory sizes by place (None: a place left empty), evaluated and checked only


class While(metaclass=_node):
    condition: object  # an expression, or the BasicError a condition that does not read is
    rest_error: object = None  # a BasicError: what follows the condition does not read


class Wend(metaclass=_node):
    error: object = None  # a BasicError: what follows WEND (raised when it is reached)


class Swap(metaclass=_node):
    first: object
    second: object


class MidAssign(metaclass=_node):
    """MID$(target, start[, count]) = value; ``error``: a statement that reads only up to
    its start or count (``value`` None), checked as far as it reads, then this error."""
    target: object
    start: object
    count: object
    value: object
    error: object = None


class Erase(metaclass=_node):
    names: list


class OptionBase(metaclass=_node):
    base: int


class LineInput(metaclass=_node):
    prompt: str | None
    target: object
    channel: object = None  # LINE INPUT #n
    keeps_row: bool = False  # LINE INPUT; : the cursor stays after the answer


class Write(metaclass=_node):
    items: list
    channel: object = None  # WRITE #n
    cut: str | None = None  # a WRITE that fails part way: what follows its items (their comma or nothing), no line end


class Open(metaclass=_node):
    """OPEN: mode ("I"/"O"/"A"/"R", or INPUT/OUTPUT/APPEND/RANDOM) expression, file number,
    name, and the record length (None: not given); GW-BASIC 3.23's ``access`` ("R", "W",
    "RW") and ``lock`` ("SHARED", "R", "W", "RW"), None where the clause is left out."""
    mode: object
    number: object
    name: object
    length: object = None
    access: str | None = None
    lock: str | None = None


class Field(metaclass=_node):
    """FIELD #n, width AS variable, ...: ``fields`` of (width expression, variable)."""
    number: object
    fields: list


class FileFirst(metaclass=_node):
    """A file statement (PRINT #, WRITE #, INPUT #, LINE INPUT #, FIELD, GET, PUT, WIDTH #)
    whose text after the file number does not read: GW-BASIC finds the file first (open,
    in one of ``modes``; ``opened``: found as GET and PUT find it), then meets ``error``."""
    number: object
    modes: str
    opened: bool
    error: object
    count: object = None  # INPUT$(count, #f: its count, read first as a byte


class GetPut(metaclass=_node):
    """GET #n[, record] (``put`` False) or PUT #n[, record]."""
    put: bool
    number: object
    record: object = None


class Chain(metaclass=_node):
    """CHAIN [MERGE] file [, line] [, ALL] [, DELETE first-last]; MERGE file (``run`` False:
    merge, then stop)."""
    merge: bool
    file: object
    line: object  # expression or None
    everything: bool  # ALL: every variable kept (else only COMMON ones)
    delete: object  # (first or None, last or None) or None
    run: bool = True
    error: object = None  # options that do not read: the file found first, then this error


# The period of LIST . and EDIT . (the Casio: LIST.md item 4, EDIT.md item 2): the line most
# recently handled (written, edited or executed; after an error, the error's line).
CURRENT_LINE = (".",)


class Command(metaclass=_node):
    """A command run by a program: ``name`` RUN LIST LLIST LOAD SAVE NEW SYSTEM DELETE EDIT
    KEY; ``argument`` its file name expression, line, line range or :data:`CURRENT_LINE`
    (the Casio's ``LIST .``, ``EDIT .``); ``option`` the
    letter after the comma (``,R`` ``,A`` ``,P``) or KEY's ON/OFF; ``everything`` the
    Casio's ALL (NEW ALL, LIST ALL, SAVE ALL, LOAD ALL: every program area); ``file`` the
    file name expression of ``LIST [range], "f"`` (None: the screen or the printer)."""
    name: str
    argument: object = None
    option: object = None
    everything: bool = False
    file: object = None


class Common(metaclass=_node):
    """COMMON: its list as typed, which a CHAIN reads (common_lists.py); nothing when it runs."""
    text: str


class LSet(metaclass=_node):
    """LSET variable = value (``right`` False) or RSET."""
    right: bool
    target: object
    value: object


class Close(metaclass=_node):
    numbers: list  # empty: every open file


class Kill(metaclass=_node):
    name: object


class Rename(metaclass=_node):
    """NAME old AS new; ``new`` None: ``old`` checked (a string, an existing file), then ``error``."""
    old: object
    new: object
    error: object = None


class Files(metaclass=_node):
    pattern: object = None


class ReturnTo(metaclass=_node):
    """RETURN n: leave the subroutine and go on at line n."""
    target: int


class Data(metaclass=_node):
    text: str


class Read(metaclass=_node):
    targets: list


class Restore(metaclass=_node):
    target: object = None  # a line number, None (the first DATA), or an expression: RESTORE (10*10)


class Input(metaclass=_node):
    prompt: str | None
    question_mark: bool
    targets: list
    channel: object = None  # INPUT #n
    at: int | None = None  # INPUT @n; (the FX-850P library's form)
    asks: list | None = None  # (message, "?" shown) or None for each target, when a later one has a message
    keeps_row: bool = False  # INPUT; : the cursor stays after the answer
    names_cut: bool = False  # no names, or a list ending in a comma: asked and read, then refused


class Touch(metaclass=_node):
    """A statement that fails after it has read its target: ``DIMA$(20)`` (no ``=``) reads
    the element, which can be Subscript out of range, before its Syntax error ``error``."""
    target: object
    error: object


class CutShort(metaclass=_node):
    """A statement whose good start runs before the rest of its text fails: ``statement``
    (the items a PRINT or WRITE printed, an assignment made), then ``error``, all one
    statement (a RESUME NEXT goes on after the whole of it)."""
    statement: object
    error: object


class CutCall(metaclass=_node):
    """A function call the text cuts short (``INSTR(-1``): the arguments read whole, then
    ``error`` where the next argument should start (``after_comma``) or where a ``,`` or
    ``)`` should follow the last one (Syntax error)."""
    name: str
    args: tuple
    after_comma: bool
    error: object


class CutExpression(metaclass=_node):
    """An expression the text cuts short after an operator (``FNA(X) + PRINT``): ``read``,
    the part before the operator, is evaluated, then ``error``."""
    read: object
    error: object


class DefFn(metaclass=_node):
    name: str
    params: list
    body: object


class Resume(metaclass=_node):
    mode: str  # "retry", "next", "line", "bad" (the text after RESUME does not read: ``error``)
    target: int | None = None
    error: object = None  # "bad": the error it is inside a handler (GWMAIN.ASM RESUME tests ONEFLG first)


class Error(metaclass=_node):
    """ERROR n: raise error code n."""
    code: object


class Randomize(metaclass=_node):
    seed: object = None


class DefMachine(metaclass=_node):
    """DEF SEG [= value] (``word`` "SEG") or DEF USR[n] = value (``word`` "USR")."""
    word: str
    value: object = None


class Angle(metaclass=_node):
    mode: str  # "DEG" or "RAD"


class WordStatement(metaclass=_node):
    """A statement of the dialect's own words (dialects/casio.py): ANGLE 1, POKE a, d; or of
    gw's device words (dialects/gw_words.py)."""
    word: str
    args: list
    marks: str = ""  # its punctuation in order: "=" "#" "," and "T" for TO (``LOCK #1, 2 TO 6``: "#,T")


class Trace(metaclass=_node):
    on: bool  # TRON (True) or TROFF


class Cls(metaclass=_node):
    """CLS [n]: clear the screen (n: 0 all of it, 2 the text window, 1 the graphics one)."""
    mode: object = None


class Graphics(metaclass=_node):
    """A graphics statement (gw) as GW reads it (source/graphics_syntax.py): ``word`` PSET,
    PRESET, LINE, VIEW, WINDOW, GET, PUT or PALETTE; ``parts`` its pieces in the order read;
    ``error`` what its text is where the reading stopped (None: the whole text read);
    ``after``: the error is text after the whole statement (raised once it has run)."""
    word: str
    parts: list
    error: object = None
    after: bool = False


class ScreenStatement(metaclass=_node):
    """A text-screen statement whose arguments may each be left out (None):
    ``word`` LOCATE (row/column, cursor), COLOR (foreground, background, border),
    SCREEN (mode, colour switch, pages) or VIEW alone (the graphics viewport reset)."""
    word: str
    args: list


class ByteList(metaclass=_node):
    """A screen statement read one small number at a time (``Dialect.screen.byte_statements``:
    GW's CLS, LOCATE, WIDTH, COLOR, SCREEN) whose text went wrong: ``args`` the numbers
    read before it (None where one was left out), ``error`` what the rest of the text is,
    raised once they are read (source/byte_lists.py)."""
    word: str
    args: list
    error: object = None


class ViewPrint(metaclass=_node):
    """VIEW PRINT [first TO last]: the rows that scroll (none given: the whole screen)."""
    first: object = None
    last: object = None


class Key(metaclass=_node):
    """KEY ON / OFF / LIST (``action``), KEY n, text (``"DEFINE"``: ``number``, ``text``), KEY (n)
    ON / OFF / STOP (``"TRAP"``), or ``"NUMBER"``: the key's number checked, then ``text``, an error."""
    action: str
    number: object = None
    text: object = None


class EventTrap(metaclass=_node):
    """ON word(index) GOSUB line (gw's event traps: dialects/gw_words.py EVENTS); ``index``
    None where no parentheses follow the word, ``line`` 0 to stop trapping."""
    word: str
    index: object
    line: int


class EventSwitch(metaclass=_node):
    """word(index) ON | OFF | STOP (``state``): an event's trapping switched."""
    word: str
    index: object
    state: str


class Bank(metaclass=_node):
    """A DATA BANK statement (``WRITE#`` ... ``LOAD#``) and its expressions."""
    word: str
    args: list


class DefChr(metaclass=_node):
    """``DEFCHR$(code) = pattern``: the dots of a user-defined character (casio)."""
    code: object
    pattern: object


class EndMark(metaclass=_node):
    """``THEN *`` / ``ELSE *``: Becker's library writes it where a program stops (casio only)."""


class Locate(metaclass=_node):
    """LOCATE: the cursor to a place of the display; ``args`` as written, None where
    one is left out (the Casio's ``x, y``; GW's ``row, column, cursor, start, stop``)."""
    args: list


class Width(metaclass=_node):
    """``WIDTH n``: the screen's width in columns (PRINT wraps there); ``WIDTH LPRINT n``
    (``printer``): the printer's (LPRINT wraps there); ``WIDTH "LPT1:", n``: the width
    of the device ``device`` names (a string expression); ``WIDTH #n, w``: the width of
    open file ``file``."""
    columns: object
    printer: bool = False
    device: object = None
    file: object = None


class DefType(metaclass=_node):
    kind: str  # "INT", "SNG", "DBL" or "STR" (DEFINT ...)
    ranges: list  # "AZ": first and last letter of each range


class If(metaclass=_node):
    condition: object
    then: object  # int line number or list of statements
    otherwise: object = None  # int, list or None
    unreachable: list = _LIST  # statements after "THEN n:" (never run; scanned for NEXT/DATA)


class Line(metaclass=_node):
    """One program line: its number, its statements, and its source text."""
    number: int
    statements: list = _LIST
    text: str = ""
    error: object = None  # a BasicError when the line does not parse; ``statements``
    # then holds the statements that do, and the BasicError of each one that does not
