"""BASIC errors, in the style of the period.

A :class:`BasicError` carries the message (``"Division by zero"``), the MS-BASIC
error code (``ERR``) and, once the machine knows them, the line and program
area it happened in.  ``str()`` gives the one line the user sees, e.g.
``Division by zero in 20 (PROG 5)`` or ``Syntax error in 4080``.

Python program areas (the library programs bound to ``GOSUB PROG n``) raise
``BasicError`` with the area already in the message, e.g.
``BasicError("Mechanism cannot be assembled (PROG 2)", ILLEGAL_FUNCTION_CALL)``;
the machine then adds the calling line: ``... (PROG 2) in 4040``.
"""

from __future__ import annotations

# MS-BASIC (GW-BASIC) error codes, as ERR returns them.
NEXT_WITHOUT_FOR = 1
SYNTAX_ERROR = 2
RETURN_WITHOUT_GOSUB = 3
OUT_OF_DATA = 4
ILLEGAL_FUNCTION_CALL = 5
OVERFLOW = 6
OUT_OF_MEMORY = 7
UNDEFINED_LINE = 8
SUBSCRIPT_OUT_OF_RANGE = 9
DUPLICATE_DEFINITION = 10
DIVISION_BY_ZERO = 11
TYPE_MISMATCH = 13
STRING_TOO_LONG = 15
CANT_CONTINUE = 17
UNDEFINED_USER_FUNCTION = 18
NO_RESUME = 19
RESUME_WITHOUT_ERROR = 20
MISSING_OPERAND = 22
FOR_WITHOUT_NEXT = 26
FILE_NOT_FOUND = 53
DEVICE_IO_ERROR = 57
UNDEFINED_PROGRAM_AREA = 252  # yaseer's own: GOSUB PROG n with nothing in area n
BREAK = 253  # yaseer's own: Ctrl-C (not trappable)


class BasicError(Exception):
    """A BASIC syntax or run-time error.

    ``line`` is the BASIC line number (``None`` in direct mode or before the
    machine has placed it); ``area`` is the program area (0 is the listing).
    """

    def __init__(self, message: str, code: int, line: int | None = None, area: int = 0):
        super().__init__(message)
        self.message = message
        self.code = code
        self.line = line
        self.area = area

    def at(self, line: int | None, area: int = 0) -> "BasicError":
        """Place the error at ``line`` of ``area`` unless it is placed already."""
        if self.line is None:
            self.line = line
            self.area = area
        return self

    def __str__(self) -> str:
        text = self.message
        if self.line is not None:
            text += f" in {self.line}"
        if self.area:
            text += f" (PROG {self.area})"
        return text


class OutputError(OSError):
    """Writing a run's screen or printer stream failed (a full disk, a closed file).

    Not a BASIC error: the machine lets it through and the run stops; its
    ``filename`` names the stream (``standard output``, the ``--printer`` file).
    """
