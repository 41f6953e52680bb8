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
ILLEGAL_DIRECT = 12
TYPE_MISMATCH = 13
OUT_OF_STRING_SPACE = 14
STRING_TOO_LONG = 15
CANT_CONTINUE = 17
UNDEFINED_USER_FUNCTION = 18
NO_RESUME = 19
RESUME_WITHOUT_ERROR = 20
MISSING_OPERAND = 22
FOR_WITHOUT_NEXT = 26
WHILE_WITHOUT_WEND = 29
WEND_WITHOUT_WHILE = 30
FIELD_OVERFLOW = 50
INTERNAL_ERROR = 51  # a Python exception no BASIC error stands for (a slip of yaseer's)
BAD_FILE_NUMBER = 52
FILE_NOT_FOUND = 53
BAD_FILE_MODE = 54
FILE_ALREADY_OPEN = 55
DEVICE_IO_ERROR = 57
FILE_ALREADY_EXISTS = 58
INPUT_PAST_END = 62
BAD_RECORD_NUMBER = 63
BAD_FILE_NAME = 64
DEVICE_UNAVAILABLE = 68
DIRECT_STATEMENT_IN_FILE = 66
LINE_BUFFER_OVERFLOW = 23
PERMISSION_DENIED = 70
RENAME_ACROSS_DISKS = 74
PATH_FILE_ACCESS_ERROR = 75
PATH_NOT_FOUND = 76
PASSWORD_PROTECTED = 251  # yaseer's own: the Casio PR error (a password registered, or PASS with another one)
UNDEFINED_PROGRAM_AREA = 252  # yaseer's own: GOSUB PROG n with nothing in area n
BREAK = 253  # yaseer's own: Ctrl-C (not trappable)


# GW-BASIC's message for each error code (checked against PC-BASIC 2.0.8's ERROR n);
# a code in 1..255 that is not listed is "Unprintable error".
MESSAGES = {
    1: "NEXT without FOR", 2: "Syntax error", 3: "RETURN without GOSUB", 4: "Out of DATA",
    5: "Illegal function call", 6: "Overflow", 7: "Out of memory", 8: "Undefined line number",
    9: "Subscript out of range", 10: "Duplicate Definition", 11: "Division by zero",
    12: "Illegal direct", 13: "Type mismatch", 14: "Out of string space", 15: "String too long",
    16: "String formula too complex", 17: "Can't continue", 18: "Undefined user function",
    19: "No RESUME", 20: "RESUME without error", 22: "Missing operand", 23: "Line buffer overflow",
    24: "Device Timeout", 25: "Device Fault", 26: "FOR without NEXT", 27: "Out of paper",
    29: "WHILE without WEND", 30: "WEND without WHILE", 50: "FIELD overflow", 51: "Internal error",
    52: "Bad file number", 53: "File not found", 54: "Bad file mode", 55: "File already open",
    57: "Device I/O error", 58: "File already exists", 61: "Disk full", 62: "Input past end",
    63: "Bad record number", 64: "Bad file name", 66: "Direct statement in file",
    67: "Too many files", 68: "Device Unavailable", 69: "Communication buffer overflow",
    70: "Permission Denied", 71: "Disk not Ready", 72: "Disk media error", 73: "Advanced Feature",
    74: "Rename across disks", 75: "Path/File access error", 76: "Path not found", 77: "Deadlock",
}


def error_message(code: int) -> str:
    """The message GW-BASIC prints for error ``code`` (1..255)."""
    return MESSAGES.get(code, "Unprintable error")


def error_for(code: int) -> "BasicError":
    """The BasicError for error ``code`` with the message GW-BASIC prints for it."""
    return BasicError(error_message(code), code)


def not_emulated(what: str, code: int = ILLEGAL_FUNCTION_CALL) -> "BasicError":
    """The run ends at a part of the machine yaseer does not have: one line naming it (not
    trappable: no ON ERROR handler can make the missing part work)."""
    err = BasicError(f"{what} is not emulated", code)
    err.trappable = False
    return err


def undefined_line_message(line: int, names_line: bool) -> str:
    """``Undefined line number``, naming the missing ``line`` when ``names_line``
    (``Dialect.names_missing_line``)."""
    return f"{MESSAGES[UNDEFINED_LINE]} {line}" if names_line else MESSAGES[UNDEFINED_LINE]


class BasicError(Exception):
    """A BASIC syntax or run-time error.

    ``line`` is the BASIC line number (``None`` in direct mode or before the
    machine has placed it); ``area`` is the program area (0 is the listing).
    """

    trappable = True  # ON ERROR GOTO may catch it (not RESUME without error, not Break)

    def __init__(self, message: str, code: int, line: int | None = None, area: int = 0):
        super().__init__(message)
        self.message = message
        self.code = code
        self.line = line
        self.area = area

    @classmethod
    def of_code(cls, code: int) -> "BasicError":
        """The error GW-BASIC raises for code ``code`` (``ERROR n``)."""
        return cls(error_message(code), code)

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


def password_protected() -> BasicError:
    """The Casio's PR error for a command refused while a password is registered (PASS.md
    item 5; part-12-2: code 21).  Not in MESSAGES: GW-BASIC's ERROR 251 stays unprintable."""
    return BasicError("Password protected", PASSWORD_PROTECTED)
