"""GW-BASIC's graphics statements read as GW reads them: piece by piece, each piece's error
where the reading gets to it.

PSET, PRESET, LINE, VIEW, WINDOW, PALETTE and the graphics GET and PUT read their text
from left to right (GENGRP.ASM SCAND: an optional STEP, ``(``, x, ``,``, y, ``)``; ADVGRP.ASM
VIEW, WINDOW, GPUTG; then each statement's options), evaluating each number as they reach
it.  So ``VIEW ("1","!")`` is Type mismatch (the first number), ``LINE (10,10) -`` Syntax
error (``(`` missing), ``VIEW (1,1)-(9,9),`` Missing operand (an expression wanted at the
statement's end) and ``LINE (0,0)-(9,9),1,`` Syntax error (a letter wanted there).

:func:`mark_graphics` replaces each such statement's tokens (from its word to the
statement's end) by one ``GRAPHICS`` token whose value is its
:class:`~yaseer.basic.source.syntax_tree.Graphics` node: the pieces read, in order, and the
error where the reading stopped (None when the text is whole).  The grammar takes that
token as the statement (grammar.lark ``graphics_stmt``).

A piece: ``("xy", step, x, y)`` a point (``step``: True after STEP), ``("n", expr)`` a
number (None: left out), ``("w", word)`` a word (LINE's B/BF, PUT's PSET/PRESET/AND/OR/XOR,
VIEW's and WINDOW's SCREEN), ``("a", expr)`` an array (its name, or an element for
PALETTE USING).
"""

from __future__ import annotations

from yaseer.basic.errors import BasicError, MISSING_OPERAND, SYNTAX_ERROR
from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.dialects.reserved import StoredName
from yaseer.basic.source.scanner import UNSCANNED, Token

_ENDS = frozenset(("_COLON", "ELSE"))
_STARTS = frozenset(("_COLON", "THEN", "ELSE"))
GRAPHICS_WORDS = frozenset(("PSET", "LINE", "VIEW", "WINDOW", "GET", "PUT", "PALETTE", "CIRCLE", "PAINT", "DRAW"))
_PUT_ACTIONS = {"PSET": "PSET", "AND": "AND", "OR": "OR", "XOR": "XOR"}


def _syntax() -> BasicError:
    return BasicError("Syntax error", SYNTAX_ERROR)


def _missing() -> BasicError:
    return BasicError("Missing operand", MISSING_OPERAND)


class _Stop(Exception):
    """The reading stopped: ``error`` is what the text is there."""

    def __init__(self, error, after: bool = False):
        super().__init__()
        self.error = error
        self.after = after


class _Reader:
    """One statement's tokens (after its word) and the pieces read from them."""

    def __init__(self, tokens: list, parse_expression):
        self.tokens = tokens
        self.at = 0
        self.parts: list = []
        self.parse_expression = parse_expression

    def peek(self) -> str | None:
        return self.tokens[self.at].type if self.at < len(self.tokens) else None

    def value(self):
        return self.tokens[self.at].value

    def ended(self) -> bool:
        return self.at >= len(self.tokens)

    def take(self, kind: str) -> bool:
        if self.peek() == kind:
            self.at += 1
            return True
        return False

    def expect(self, kind: str) -> None:
        """SYNCHR: ``kind`` must come next, else Syntax error."""
        if not self.take(kind):
            raise _Stop(self.fault())

    def fault(self) -> BasicError:
        """The error of the text at the reading point: the scanner's own, else Syntax error."""
        if not self.ended() and self.peek() == UNSCANNED:
            return self.value()
        return _syntax()

    def expression(self, stops: tuple = ("COMMA",)):
        """The expression from here to the next ``stops`` token outside parentheses (or the
        end): its node; none there Missing operand at the statement's end, else Syntax
        error; an expression followed by text that cannot go on with it: the expression,
        then Syntax error."""
        depth, k = 0, self.at
        while k < len(self.tokens):
            kind = self.tokens[k].type
            if depth == 0 and kind in stops:
                break
            depth += {"_LPAR": 1, "_RPAR": -1}.get(kind, 0)
            if depth < 0:
                break
            k += 1
        piece = self.tokens[self.at:k]
        if not piece:
            raise _Stop(_missing() if self.ended() else self.fault())
        whole = self.parse_expression(piece)
        if whole is not None:
            self.at = k
            return whole
        read = next((n for n in range(len(piece) - 1, 0, -1) if self.parse_expression(piece[:n]) is not None), 0)
        if read == 0:
            if piece[0].type == UNSCANNED:
                raise _Stop(piece[0].value)
            # an expression that goes wrong inside (``1+``): at the end Missing operand
            raise _Stop(_missing() if piece[-1].type in ("PLUS", "MINUS", "STAR", "SLASH") and k == len(self.tokens)
                        else _syntax())
        self.at += read
        return self.parse_expression(piece[:read])

    def number(self, stops: tuple = ("COMMA",)) -> None:
        """A number piece."""
        self.parts.append(("n", self.expression(stops)))

    def point(self, step_allowed: bool = True) -> None:
        """SCAND: [STEP] ( x , y )."""
        step = step_allowed and self.take("STEP")
        self.expect("_LPAR")
        x = self.expression(("COMMA", "_RPAR"))
        self.parts.append(("n", x))  # (x is evaluated before the comma is looked for)
        self.expect("COMMA")
        y = self.expression(("COMMA", "_RPAR"))
        self.parts.pop()
        self.parts.append(("xy", step, x, y))
        self.expect("_RPAR")

    def optional(self, stops: tuple = ("COMMA",)) -> None:
        """A number that may be left out (a comma or the end comes first)."""
        if self.ended() or self.peek() in stops:
            self.parts.append(("n", None))
        else:
            self.number(stops)

    def end(self) -> None:
        """The statement must end here (text after it: the statement runs, then NEWSTT
        finds the text bad)."""
        if not self.ended():
            raise _Stop(self.fault(), after=True)


def _read_pset(r: _Reader) -> None:
    r.point()
    if r.take("COMMA"):
        r.number()
    r.end()


def _word(name: str) -> str:
    """A name read as a word of the statement (LINE's B and BF): in capitals, but for a name
    a tokenised file holds in small letters (scanner.STORED_NAME), which keeps them: SYNCHR
    compares with capitals, so ``bf`` there is a Syntax error (recording unsorted/LOWRCASE)."""
    return name if name != name.upper() and type(name) is StoredName else name.upper()


def _read_line(r: _Reader) -> None:
    if r.peek() != "MINUS":
        r.point()
    else:
        r.parts.append(("w", ""))  # no first point: from the last point referenced
    r.expect("MINUS")
    r.point()
    if r.take("COMMA"):  # ATRSCN: a comma, then the attribute unless another comma follows
        if r.ended():
            raise _Stop(_missing())
        r.optional()
        if r.take("COMMA"):
            shape = ""
            if r.peek() == "NAME":
                shape = _word(r.value())
                r.at += 1
                if shape == "B" and r.peek() == "NAME" and _word(r.value()) == "F":
                    shape = "BF"  # (SYNCHR skips the blanks: ``B F`` is BF, the recorded LINE test)
                    r.at += 1
                if shape not in ("B", "BF"):
                    raise _Stop(_syntax())
            elif not (r.peek() == "COMMA" and shape == ""):
                raise _Stop(r.fault())
            r.parts.append(("w", shape))
            if r.take("COMMA"):
                r.number()
    r.end()


def _corners(r: _Reader) -> bool:
    """VIEW's and WINDOW's [SCREEN] (x1, y1)-(x2, y2); False when the statement is the word
    alone (the view or window reset)."""
    screen = r.take("SCREEN")
    if r.ended() and not screen:
        return False
    r.parts.append(("w", "SCREEN" if screen else ""))
    r.point(step_allowed=False)
    r.expect("MINUS")
    r.point(step_allowed=False)
    return True


def _read_view(r: _Reader) -> None:
    if not _corners(r):
        return
    for _ in range(2):
        if not r.take("COMMA"):
            break
        if r.ended():  # a comma at the end: an expression wanted there (EVAL's Missing operand)
            raise _Stop(_missing())
        r.optional()
    r.end()


def _read_window(r: _Reader) -> None:
    if _corners(r):
        r.end()


def _array(r: _Reader) -> None:
    """An array's name (GET, PUT), with subscripts or without."""
    if r.peek() not in ("NAME", "STRNAME"):
        raise _Stop(_missing() if r.ended() else r.fault())
    r.parts.append(("a", r.expression()))


def _read_get(r: _Reader) -> None:
    r.point()
    r.expect("MINUS")
    r.point()
    r.expect("COMMA")
    _array(r)
    r.end()


def _read_put(r: _Reader) -> None:
    r.point()
    r.expect("COMMA")
    _array(r)
    if r.take("COMMA"):
        kind = r.peek()
        word = r.value().upper() if kind in ("PSET", "AND", "OR", "XOR") else None
        if word is None:
            raise _Stop(_missing() if r.ended() else r.fault())
        r.at += 1
        r.parts.append(("w", word))
    r.end()


def _read_palette(r: _Reader) -> None:
    if r.take("USING"):
        r.parts.append(("w", "USING"))
        _array(r)
        if not isinstance(r.parts[-1][1], ast.Elem):  # an element must name where to start
            raise _Stop(_syntax())
        r.end()
        return
    if r.ended():
        return
    r.number()
    r.expect("COMMA")
    r.number()
    r.end()


def _after_comma(r: _Reader, kind: str = "n") -> None:
    """An argument after a comma that may be left out where another comma follows (ADVGRP.ASM
    ATRSCN, CGTCNT); at the statement's end an expression is wanted (Missing operand)."""
    if r.ended():
        raise _Stop(_missing())
    if r.peek() == "COMMA":
        r.parts.append((kind, None))
    else:
        r.parts.append((kind, r.expression()))


def _read_circle(r: _Reader) -> None:
    """CIRCLE [STEP] (x, y), radius [, [attribute] [, [start] [, [end] [, aspect]]]]."""
    r.point()
    r.expect("COMMA")
    r.number()
    for _ in range(3):  # attribute, start, end
        if not r.take("COMMA"):
            r.end()
            return
        _after_comma(r)
    if r.take("COMMA"):
        r.number()
    r.end()


def _read_paint(r: _Reader) -> None:
    """PAINT [STEP] (x, y) [, [paint] [, [border] [, background]]]: paint a number or a
    tile string, the background a string."""
    r.point()
    for kind in ("x", "n", "x"):
        if not r.take("COMMA"):
            break
        _after_comma(r, kind)
    r.end()


def _read_draw(r: _Reader) -> None:
    """DRAW string (MACLNG's FRMEVL: any expression, a number Type mismatch when run)."""
    r.parts.append(("x", r.expression()))
    r.end()


_READERS = {"CIRCLE": _read_circle, "PAINT": _read_paint, "DRAW": _read_draw, "PSET": _read_pset, "LINE": _read_line, "VIEW": _read_view, "WINDOW": _read_window,
            "GET": _read_get, "PUT": _read_put, "PALETTE": _read_palette}


def _graphics_form(tokens: list, k: int, end: int) -> bool:
    """Whether the statement at ``tokens[k]`` is the graphics one (not LINE INPUT, VIEW
    PRINT, a file's GET or PUT)."""
    kind = tokens[k].type
    after = tokens[k + 1].type if k + 1 < end else None
    if kind == "LINE":
        return after != "INPUT"
    if kind == "VIEW":
        return after != "PRINT"
    if kind in ("GET", "PUT"):
        return after in ("_LPAR", "STEP")
    return True


def mark_graphics(tokens: list, dialect, parse_expression) -> list:
    """``tokens`` with each graphics statement as one ``GRAPHICS`` token (see the module
    docstring), in a dialect that has them (gw: its screen has graphics modes)."""
    if not dialect.screen.modes or not any(t.type in GRAPHICS_WORDS for t in tokens):
        return tokens
    out: list = []
    k, n = 0, len(tokens)
    while k < n:
        token = tokens[k]
        starts = k == 0 or tokens[k - 1].type in _STARTS
        if not (starts and token.type in GRAPHICS_WORDS):
            out.append(token)
            k += 1
            continue
        end = next((j for j in range(k + 1, n) if tokens[j].type in _ENDS), n)
        if not _graphics_form(tokens, k, end):
            out.append(token)
            k += 1
            continue
        word = token.value.upper() if token.type == "PSET" else token.type
        reader = _Reader(tokens[k + 1:end], parse_expression)
        error, after = None, False
        try:
            _READERS[token.type](reader)
        except _Stop as stop:
            error, after = stop.error, stop.after
        out.append(Token("GRAPHICS", ast.Graphics(word, reader.parts, error, after)))
        k = end
    return out
