"""The abstract syntax tree of a BASIC line: plain data, no behaviour.

Expression nodes carry their static type through :func:`expr_type`: a name
ending in ``$``, a string literal and the string functions are strings (``"s"``),
everything else is a number (``"n"``).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Union

# ---------------------------------------------------------------- expressions


@dataclass(frozen=True)
class Num:
    value: float


@dataclass(frozen=True)
class Str:
    value: str


@dataclass(frozen=True)
class Var:
    """A scalar variable; ``name`` is upper case and keeps its ``$``."""
    name: str


@dataclass(frozen=True)
class Elem:
    """An array element ``name(indices...)``."""
    name: str
    indices: tuple


@dataclass(frozen=True)
class Unary:
    op: str  # "-", "+", "NOT"
    operand: object


@dataclass(frozen=True)
class Binary:
    op: str  # "+", "-", "*", "/", "\\", "^", "MOD", "=", "<>", "<", ">", "<=", ">=", "AND", "OR"
    left: object
    right: object


@dataclass(frozen=True)
class Call:
    """A built-in function; ``args`` may be empty (``RND``)."""
    name: str
    args: tuple


@dataclass(frozen=True)
class FnCall:
    """A user function ``FN name(args)``."""
    name: str
    args: tuple


@dataclass(frozen=True)
class SysVar:
    name: str  # "ERR", "ERL"


Expr = Union[Num, Str, Var, Elem, Unary, Binary, Call, FnCall, SysVar]
LValue = Union[Var, Elem]

STRING_FUNCTIONS = frozenset({"STR$", "CHR$", "LEFT$", "RIGHT$", "MID$"})


def expr_type(node) -> str:
    """``"s"`` for a string-valued expression, ``"n"`` for a number."""
    if isinstance(node, Str):
        return "s"
    if isinstance(node, (Var, Elem, FnCall)):
        return "s" if node.name.endswith("$") else "n"
    if isinstance(node, Call):
        return "s" if node.name in STRING_FUNCTIONS else "n"
    if isinstance(node, Binary) and node.op == "+":
        return expr_type(node.left)
    return "n"


# ---------------------------------------------------------------- statements


@dataclass
class Let:
    target: object
    value: object


@dataclass
class Print:
    printer: bool  # LPRINT
    items: list  # expressions, "," ";" separators, Tab, Spc
    using: object = None  # format expression for PRINT USING


@dataclass(frozen=True)
class Tab:
    column: object


@dataclass(frozen=True)
class Spc:
    count: object


@dataclass
class For:
    var: object
    start: object
    stop: object
    step: object = None


@dataclass
class Next:
    var: object = None  # None: the innermost loop


@dataclass
class Goto:
    target: int


@dataclass
class Gosub:
    target: int


@dataclass
class GosubProg:
    area: int


@dataclass
class Return:
    pass


@dataclass
class OnJump:
    selector: object
    targets: list
    gosub: bool


@dataclass
class OnError:
    target: int  # 0 switches trapping off


@dataclass
class End:
    pass


@dataclass
class Stop:
    pass


@dataclass
class Rem:
    text: str = ""


@dataclass
class Dim:
    arrays: list  # [(name, (size exprs...))]


@dataclass
class Clear:
    pass


@dataclass
class Data:
    text: str


@dataclass
class Read:
    targets: list


@dataclass
class Restore:
    target: int | None = None


@dataclass
class Input:
    prompt: str | None
    question_mark: bool
    targets: list


@dataclass
class DefFn:
    name: str
    params: list
    body: object


@dataclass
class Resume:
    mode: str  # "retry", "next", "line"
    target: int | None = None


@dataclass
class Randomize:
    seed: object = None


@dataclass
class Angle:
    mode: str  # "DEG" or "RAD"


@dataclass
class If:
    condition: object
    then: object  # int line number or list of statements
    otherwise: object = None  # int, list or None


@dataclass
class Line:
    """One program line: its number, its statements, and its source text."""
    number: int
    statements: list = field(default_factory=list)
    text: str = ""
    error: object = None  # a BasicError when the line does not parse
