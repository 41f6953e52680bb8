"""The BASIC machine's GOSUB/FOR stack: GOSUB and RETURN, FOR and NEXT through the
stack (the loops the compiler could not make native Python loops), ON x GOTO's
branch, FN's function and STOP (the :class:`ControlStack` mixin of
:class:`yaseer.basic.machine.machine.Machine`).

The stack (``Machine.stack``) holds return blocks (int), open loops
(:class:`ForFrame`) and :data:`AREA_MARK` where a BASIC program area was entered;
GOSUB returns and FOR loops share its ``MAX_STACK`` entries."""

from __future__ import annotations

from yaseer.basic.arithmetic import values

from yaseer.basic.machine import runtime
from yaseer.basic.compile.compiled import MAX_STACK
from yaseer.basic.compile.number_models import variant_function
from yaseer.basic.errors import (
    BasicError, FOR_WITHOUT_NEXT, ILLEGAL_FUNCTION_CALL, NEXT_WITHOUT_FOR, OUT_OF_MEMORY, RETURN_WITHOUT_GOSUB,
    SYNTAX_ERROR, UNDEFINED_USER_FUNCTION,
)
from yaseer.basic.machine.signals import ProgramStop


class _AreaReturn:
    """Marks the GOSUB stack where a BASIC program area was entered."""


AREA_MARK = _AreaReturn()


class ForFrame:
    """An open FOR loop; ``next_id`` is the NEXT statement it is bound to (GW-BASIC),
    or None where any NEXT of its variable continues it."""

    __slots__ = ("key", "limit", "step", "body", "next_id")

    def __init__(self, key, limit, step, body, next_id=None):
        self.key, self.limit, self.step, self.body = key, limit, step, body
        self.next_id = next_id


class ControlStack:
    """The GOSUB/FOR stack's statements (see the module docstring).  A mixin of
    ``Machine``, on its state (``stack``, ``scalars``, ``fns``, ``frame_body``, ``line``)."""

    @staticmethod
    def _out_of_memory() -> None:
        raise BasicError("Out of memory", OUT_OF_MEMORY)

    def gosub(self, return_block: int) -> None:
        """GOSUB: remember the block to come back to (the generated code inlines this)."""
        levels = self.gosub_levels
        if len(self.stack) >= MAX_STACK or (levels is not None and len(self.stack) >= levels and self.gosubs_full()):
            raise BasicError("Out of memory", OUT_OF_MEMORY)
        self.stack.append(return_block)

    def gosubs_full(self) -> bool:
        """Does the stack hold the dialect's GOSUB levels already (casio: 96, GOSUB.md item 2)?
        A return block and a program area's mark are a level each; FOR loops are none."""
        return sum(1 for entry in self.stack if type(entry) is int or entry is AREA_MARK) >= self.gosub_levels

    def open_loops(self) -> int:
        """How many FOR loops the stack holds open (a dialect's FOR levels count them: casio's
        29, FOR_NEXT_STEP.md item 4; a native loop's enclosing native loops are added by its code)."""
        return sum(1 for entry in self.stack if type(entry) is ForFrame)

    def gosub_return(self) -> int:
        """RETURN: the block to go back to (-2 ends a BASIC area); FOR loops opened since the GOSUB close."""
        stack = self.stack
        while stack:
            top = stack[-1]
            if top is AREA_MARK:
                return -2
            stack.pop()
            if type(top) is int:
                return top
        raise BasicError("RETURN without GOSUB", RETURN_WITHOUT_GOSUB)

    def for_push(self, key: str, limit: float, step: float, body: int, bound=False) -> None:
        """FOR (through the stack): open a loop over ``key`` whose body starts at block ``body``.

        ``bound`` is what GW-BASIC's FOR finds scanning for its NEXT (see
        ``blocks.scan_for_next``): ``(statement index, its line, names this loop?, the
        NEXT's place)`` or None
        for no NEXT.  In a dialect with ``Dialect.for_binds_next`` the loop is bound
        to that NEXT, and no NEXT (``FOR without NEXT``) or one naming another
        variable (``NEXT without FOR`` in its line) is an error now.
        """
        next_id = self.bound_next(bound)
        stack = self.stack
        same_statement = self.dialect.for_binds_next
        for k in range(len(stack) - 1, -1, -1):
            frame = stack[k]
            if type(frame) is not ForFrame:
                break
            if frame.key == key and (frame.body == body or not same_statement):
                # re-entering a loop: drop it and the loops inside it (GW-BASIC: only a loop this
                # FOR statement opened, GWMAIN.ASM FOR's LPFORM compares the FOR's end in the
                # text; another FOR of the variable opens a loop of its own above it)
                del stack[k:]
                break
        levels = self.for_levels
        if len(stack) >= MAX_STACK or (levels is not None and len(stack) >= levels and self.open_loops() >= levels):
            raise BasicError("Out of memory", OUT_OF_MEMORY)
        stack.append(ForFrame(key, limit, step, body, next_id))

    def bound_next(self, bound):
        """The NEXT a FOR is bound to (None: not bound), raising GW-BASIC's errors for
        what its scan found (see :meth:`for_push`); also run by a FOR that loops zero times."""
        if not self.dialect.for_binds_next or bound is False:
            return None
        if bound is None:
            raise BasicError("FOR without NEXT", FOR_WITHOUT_NEXT)
        _, next_line, names_this, next_id = bound
        if type(names_this) is tuple:  # its name does not read: the first test's error (NEXTS's PTRGET)
            raise BasicError(*names_this).at(next_line)
        if not names_this:
            raise BasicError("NEXT without FOR", NEXT_WITHOUT_FOR).at(next_line)
        return next_id

    def next_frame(self, key: str, next_id=None) -> ForFrame:
        """NEXT ``key``: its loop's frame, closing the loops opened inside it; a loop
        bound to another NEXT (GW-BASIC) is ``NEXT without FOR``."""
        stack = self.stack
        while stack:
            top = stack[-1]
            if type(top) is not ForFrame:
                break
            if top.key == key:
                if top.next_id is not None and next_id is not None and top.next_id != next_id:
                    break
                return top
            stack.pop()
        raise BasicError("NEXT without FOR", NEXT_WITHOUT_FOR)

    def next_any(self, next_id=None) -> bool:
        """NEXT with no name whose FOR the compiler could not see: step the innermost loop,
        unless that loop is bound to another NEXT (GW-BASIC: NEXT86.ASM NEXTC finds the top
        FOR entry, then compares the text pointer of the NEXT it keeps with its own)."""
        if not self.stack or type(self.stack[-1]) is not ForFrame or self.stack[-1].key.endswith("()"):
            raise BasicError("NEXT without FOR", NEXT_WITHOUT_FOR)
        frame = self.stack[-1]
        if frame.next_id is not None and next_id is not None and frame.next_id != next_id:
            raise BasicError("NEXT without FOR", NEXT_WITHOUT_FOR)
        value = values.stepped(frame.key, self.scalars[frame.key], frame.step)
        self.scalars[frame.key] = value
        if (value <= frame.limit) if frame.step >= 0 else (value >= frame.limit):
            self.frame_body = frame.body
            return True
        self.stack.pop()
        return False

    def on_index(self, selector: float, count: int) -> int:
        """ON x GOTO: the 1-based branch, or 0 to fall through; below 0 is an error (GW-BASIC),
        or falls through too where the dialect truncates the selector (the Casio: ON_GOTO.md)."""
        words = self.dialect.words
        if words and words.truncates:
            k = int(selector) if selector >= 1 else 0
            return k if k <= count else 0
        k = runtime.cint(selector)
        if k < 0 or k > 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        return k if k <= count else 0

    def user_function(self, name: str, nargs: int):
        """FN ``name``: the compiled function DEF FN made, called with ``nargs`` arguments."""
        entry = self.fns.get(name)
        if entry is None:
            raise BasicError("Undefined user function", UNDEFINED_USER_FUNCTION)
        function, expected = entry
        if expected != nargs:
            raise BasicError("Syntax error", SYNTAX_ERROR)
        if type(function) is str:  # its body typed by the DEF types of now, its result as DEF made it
            return self.namespaces[0][variant_function(function, self.def_types, name[-1])]
        return function

    def _stopper(self, area):
        def stop(block: int) -> None:
            raise ProgramStop(area, block, self.line)
        return stop
