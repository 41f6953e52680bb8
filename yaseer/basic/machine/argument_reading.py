"""A function call whose arguments do not fit it, read as GW-BASIC reads them: argument by
argument, each checked as soon as it is read, before what follows it is looked at.

GW-BASIC has no list of arguments to count: each function's routine reads its ``(``, an
argument (FRMEVL), checks it, then asks for a ``,`` or the ``)`` (SYNCHR: Syntax error when
another character is there) and so on.  So ``INSTR(-1)`` is Illegal function call (the
start is checked before the missing comma is found), ``LEFT$(1)`` Syntax error (the comma
is asked for before the string is checked), ``INSTR(1, 1, 1, 1)`` Type mismatch (the second
argument must be a string), and an argument after a cut is never evaluated.

A reading is a generator that yields what it asks for next: ``"e"`` an argument (sent back
its value), ``","`` or ``")"``; it raises the errors of its checks.  :class:`Reading` drives
it with what the call's text holds, in order (the compiler chains ``.a(value)`` for each
argument, then ``.close()`` for a ``)`` or ``.cut(...)`` where the text went wrong), so each
argument is evaluated only when the routine would have read it.
"""

from __future__ import annotations

from yaseer.basic.arithmetic.values import to_int
from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL, MISSING_OPERAND, SYNTAX_ERROR, TYPE_MISMATCH


def _syntax_error() -> BasicError:
    return BasicError("Syntax error", SYNTAX_ERROR)


def _string(value) -> None:
    """CHKSTR, FRESTR: a number where a string must be is Type mismatch."""
    if not isinstance(value, str):
        raise BasicError("Type mismatch", TYPE_MISMATCH)


def _byte(value, nonzero: bool = False) -> int:
    """GETBYT, CONINT (GWEVAL.ASM): a number (else Type mismatch), made an integer (FRCINT:
    beyond -32768..32767 Overflow), then 0..255 (else Illegal function call); ``nonzero``:
    0 too is Illegal function call (INSTR's start, MID$'s position)."""
    if isinstance(value, str):
        raise BasicError("Type mismatch", TYPE_MISMATCH)
    n = to_int(value)
    if not 0 <= n <= 255 or (nonzero and n == 0):
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    return n


def _instr():
    """BISTRS.ASM INSTR: FRMPRN; a string first is the text (then ``, t)``), a number the
    start (CONINT, not 0), then ``, text, t)``; the strings found to be strings at the end."""
    first = yield "e"
    if not isinstance(first, str):
        _byte(first, nonzero=True)
        yield ","
        _string((yield "e"))
    yield ","
    last = yield "e"
    yield ")"
    _string(last)


def _string_dollar():
    """BISTRS.ASM STRNG$: GETBYT the count, ``,``, FRMEVL the character, ``)``, then the
    character: a string's first (ASC2: empty Illegal function call) or CONINT's byte."""
    count = yield "e"
    _byte(count)
    yield ","
    character = yield "e"
    yield ")"
    if isinstance(character, str):
        if not character:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    else:
        _byte(character)


def _left_right():
    """GWEVAL.ASM ISFUN's two-argument functions (LEFT$, RIGHT$): FRMPRN, ``,``, CHKSTR of
    the first, GETBYT of the second, then ``)``."""
    text = yield "e"
    yield ","
    _string(text)
    _byte((yield "e"))
    yield ")"


def _mid():
    """MID$: as LEFT$ up to its position (not 0: BISTRS.ASM MID$ via PREAM2), then an optional
    ``, length`` (GETBYT) before the ``)``."""
    text = yield "e"
    yield ","
    _string(text)
    _byte((yield "e"), nonzero=True)
    if (yield ",?") == ",":
        _byte((yield "e"))
    yield ")"


def _one():
    """A function of one argument (GWEVAL.ASM OKNORM: PARCHK reads ``(``, the argument and
    ``)`` before the function looks at it)."""
    yield "e"
    yield ")"


def _byte_first():
    """A function that reads its argument as a byte before its ``)`` (PLAY(n): the recording
    PLAYFN shows ``PLAY("ABC"`` Type mismatch, ``PLAY(1`` Syntax error)."""
    _byte((yield "e"))
    yield ")"


def _screen():
    """GWSTS.ASM SCRENF: SCNINT the row and the column (``"b"``: a number GETBYT reads, one
    left out Illegal function call), each ended by ``,`` or ``)`` (``"s"``: any other text, the
    statement's end too, leaves SCNINT's next argument missing: Illegal function call); after
    the column a ``)`` ends the call, else the attribute, which ``)`` must end.  (The rows and
    columns of the screen are checked when the whole call reads: Console.screen_char.)"""
    _byte((yield "b"))
    yield "s"
    _byte((yield "b"))
    if (yield "s") == ")":
        return
    _byte((yield "b"))
    if (yield "s") != ")":
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)


def _number(value) -> None:
    """A string where a number must be is Type mismatch."""
    if isinstance(value, str):
        raise BasicError("Type mismatch", TYPE_MISMATCH)


def _point():
    """POINT (the recorded POINT and POINT2 tests): the first argument, then a look at what
    follows (``"p"``: the separator or the cut is sent back); a ``)`` makes it POINT(n);
    anything else is POINT(x, y): Illegal function call in a text mode, the first argument a
    number, then ``,``, the second argument a number, ``)``.  The first argument comes as
    (value, whether the screen draws) from GraphicsWords.point_argument."""
    value, draws = yield "e"
    follows = yield "p"
    if follows == ")":
        _number(value)
        return
    if not draws:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    _number(value)
    if follows != ",":
        raise _syntax_error()
    _number((yield "e"))
    yield ")"


def _pmap():
    """PMAP (the recorded PMAP test): each argument a number as it is read, ``,`` between
    them, then ``)``."""
    _number((yield "e"))
    yield ","
    _number((yield "e"))
    yield ")"


# (the names are Dialect.argument_readings of gw)
READINGS = {"INSTR": _instr, "STRING$": _string_dollar, "LEFT$": _left_right, "RIGHT$": _left_right,
            "MID$": _mid, "PLAY": _byte_first, "SCREEN": _screen, "POINT": _point, "PMAP": _pmap}


def reading_of(name: str, one_argument: bool):
    """The reading of function ``name`` (a one-argument function's where none of its own is
    listed and ``one_argument``), or None."""
    found = READINGS.get(name)
    return found if found is not None or not one_argument else _one


class Reading:
    """One call's reading: ``Reading(name, error).a(x).a(y).close()`` (or ``.cut(...)``).
    Every path ends in an error: the reading's own, a misplaced ``,`` or ``)``, the cut's;
    a reading that accepts the whole text raises ``error``, what the compiler found."""

    __slots__ = ("steps", "wants", "given", "error")

    def __init__(self, name: str, message: str, code: int):
        self.steps = reading_of(name, True)()
        self.error = BasicError(message, code)
        self.given = 0
        self.wants = self._next(None)

    def _next(self, sent):
        try:
            wants = self.steps.send(sent)
        except StopIteration:
            return None
        return self._next(None) if wants is None else wants

    def _separator(self, found: str) -> None:
        """The routine's next request met ``found`` (``,`` or ``)``) in the text."""
        wants = self.wants
        if wants == "p":  # the routine looks at what follows and goes on by itself
            self.wants = self._next(found)
            return
        if wants == "b":  # SCNINT met a separator where a number may stand: it is missing
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if wants == "s":
            self.wants = self._next(found)
            return
        if wants == ",?":
            self.wants = self._next(found)
            if found == ",":
                return
            wants = self.wants
        if wants != found:
            raise _syntax_error()
        self.wants = self._next(None)

    def a(self, value) -> "Reading":
        """The next argument, evaluated (the comma before it first, unless it is the first)."""
        if self.given:
            self._separator(",")
        if self.wants not in ("e", "b"):
            raise _syntax_error()
        self.given += 1
        self.wants = self._next(value)
        return self

    def close(self):
        """The ``)`` after the last argument: the checks after it, else the compiler's error."""
        if self.wants in ("e", "b"):  # FN(): no argument where one must be
            raise _syntax_error()
        self._separator(")")
        if self.wants == "b":  # SCNINT after the ")": the statement goes on without the number
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        raise self.error

    def cut(self, after_comma: bool, message: str, code: int):
        """The text went wrong here (``message``, ``code``): after a comma (or the ``(``),
        where an argument must start, or after a whole argument, where the routine wants a
        separator (Syntax error)."""
        if after_comma and self.given:
            self._separator(",")
        if self.wants == "p":  # the routine looks at the text that is not a separator
            self.wants = self._next("cut")
        wants = self.wants
        if wants == "s" or (wants == "b" and code == MISSING_OPERAND):
            # SCNINT: any text ends a number, and the statement's end leaves the next one missing
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if wants in ("e", "b") and (after_comma or not self.given):
            raise BasicError(message, code)
        raise _syntax_error()
