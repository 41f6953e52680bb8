"""Run-time errors of the BASIC machine: the exceptions that end, stop or redirect a
run (END, STOP, a Ctrl-C break, a direct-mode GOTO), the BASIC error a Python
exception inside compiled code becomes, and ON ERROR GOTO / RESUME / ERROR (the
:class:`ErrorTrapping` mixin of :class:`yaseer.basic.machine.machine.Machine`)."""

from __future__ import annotations

from yaseer.basic.machine import runtime
from yaseer.basic.errors import (
    BasicError, BREAK, DIVISION_BY_ZERO, ILLEGAL_FUNCTION_CALL, INTERNAL_ERROR, OUT_OF_MEMORY, OVERFLOW,
    RESUME_WITHOUT_ERROR, SUBSCRIPT_OUT_OF_RANGE,
)


class ProgramEnd(BaseException):
    """END, or the program ran off its last line."""


class ProgramStop(BaseException):
    """STOP: ``area`` and ``block`` are where CONT resumes."""

    def __init__(self, area: int, block: int, line):
        super().__init__("Break")
        self.area, self.block, self.line = area, block, line


class BreakPoint(ProgramStop):
    """Ctrl-C landed where CONT can resume (see ``Machine.resumable_breaks``).

    ``block`` of ``area`` is where to go on; ``loops`` the native FOR loops that
    were open there, outermost first, as ``(FOR index, FOR-stack key, value,
    limit, step)`` (value None for an array element, which holds its own);
    ``depth`` the GOSUB PROG nesting it happened at (only 0 is resumable).
    """

    def __init__(self, area: int, block: int, line, loops: tuple = (), depth: int = 0):
        super().__init__(area, block, line)
        self.loops, self.depth = loops, depth


class DirectJump(BaseException):
    """GOTO/THEN n typed in direct mode: continue the program at line n."""

    def __init__(self, line: int):
        super().__init__(line)
        self.line = line


class ResumeDirect(BaseException):
    """RESUME [NEXT] of an error a direct statement made: go back into the direct line at
    ``block`` of its own code (the handler ran in the program's)."""

    def __init__(self, block: int):
        super().__init__(block)
        self.block = block


END = ProgramEnd  # raised as a class: a new instance each time (one shared instance would gather every
# run's frames in its growing __traceback__ and keep every machine alive)


def to_basic_error(exc: BaseException) -> BasicError:
    """The BASIC error for an exception raised inside compiled code or a Python area."""
    if isinstance(exc, BasicError):
        return exc
    if isinstance(exc, KeyboardInterrupt):
        return BasicError("Break", BREAK)
    if isinstance(exc, ZeroDivisionError):
        return BasicError("Division by zero", DIVISION_BY_ZERO)
    if isinstance(exc, OverflowError):
        return BasicError("Overflow", OVERFLOW)
    if isinstance(exc, (RecursionError, MemoryError)):
        return BasicError("Out of memory", OUT_OF_MEMORY)
    if isinstance(exc, ValueError):
        return BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    if isinstance(exc, IndexError):
        return BasicError("Subscript out of range", SUBSCRIPT_OUT_OF_RANGE)
    # (an element of more subscripts than its array has: read, "not subscriptable"; assigned,
    # "does not support item assignment")
    if isinstance(exc, TypeError) and ("subscript" in str(exc) or "item assignment" in str(exc)):
        return BasicError("Subscript out of range", SUBSCRIPT_OUT_OF_RANGE)
    return BasicError(f"Internal error ({type(exc).__name__}: {exc})", INTERNAL_ERROR)


class ErrorTrapping:
    """ON ERROR GOTO, RESUME, ERROR n: the error handler of area ``on_error`` and the
    point (``error_point``) RESUME goes back to.  A mixin of ``Machine``, on its state."""

    def resume(self, next_statement: bool) -> int:
        """RESUME / RESUME NEXT: the block of the failed statement, or of the one after it."""
        if not self.in_handler:
            raise _resume_without_error()
        area, block, direct_code = self.error_point
        self.in_handler = False
        self.err = 0.0
        code = direct_code or self._compiled(area)
        if next_statement:
            block = code.block_next.get(block, block + 1)
        if direct_code is not None:
            raise ResumeDirect(block)
        return block

    def resume_at(self, block: int) -> int:
        """RESUME n: leave the error handler and go to ``block``."""
        if not self.in_handler:
            raise _resume_without_error()
        self.in_handler = False
        self.err = 0.0
        return block

    def error_trapping_off(self) -> None:
        """ON ERROR GOTO 0: no more trapping; inside a handler the pending error stops the run."""
        self.on_error = None
        if self.in_handler:
            raise self.pending_error

    @staticmethod
    def raise_error(code: float) -> None:
        """ERROR n: raise error n (1..255; anything else is Illegal function call)."""
        n = runtime.cint(code)
        if not 1 <= n <= 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        raise BasicError.of_code(n)

    def note_untrapped(self, err: BasicError) -> None:
        """``err`` stopped the run or the direct line (no handler took it): where the dialect
        says so it is ERR and ERL all the same and a handler running is left (see
        ``Dialect.untrapped_errors_noted``).  A Break is no error (BIMISC.ASM STPEND)."""
        if not self.dialect.untrapped_errors_noted or err.code == BREAK or err.code > 255:
            return
        self.err = float(self.err_codes.get(err.code, err.code))
        self.erl = float(err.line if err.line is not None else self.dialect.direct_line_number)
        self.in_handler = False

    def _trap(self, err: BasicError, area: int, block: int, direct_code=None) -> int | None:
        """The handler block for ``err`` if ON ERROR GOTO of this area catches it.

        ``direct_code``: the compiled direct statement that failed at ``block`` (None: the
        program's own code); the dialect's ``direct_line_number`` says whether it is trapped.
        """
        if self.on_error is None or self.in_handler or err.code == BREAK or not err.trappable:
            return None
        handler_area, handler_block = self.on_error
        if handler_area != area:
            return None
        line = err.line or 0
        if direct_code is not None:
            line = self.dialect.direct_line_number
            if line is None:
                return None
        self.err = float(self.err_codes.get(err.code, err.code))  # the dialect's codes (casio: the manual's)
        self.erl = float(line)
        if err.line and direct_code is None and self.dialect.current_line_listed:  # a direct error: no DOT
            self.current_line = err.line  # GWMAIN.ASM ERROR sets DOT before it looks for a trap
        for stream in self.streams:
            stream.row = []
        self.string_space.temps.clear()  # the failed statement's temporaries are let go
        for runtime in self.runtimes.values():
            runtime.abandon()
        self.in_handler = True
        self.pending_error = err
        self.error_point = (area, block, direct_code)
        return handler_block


def _resume_without_error() -> BasicError:
    """RESUME outside an error handler: it stops the run even under ON ERROR GOTO (GW-BASIC)."""
    err = BasicError("RESUME without error", RESUME_WITHOUT_ERROR)
    err.trappable = False
    return err

