"""Ctrl-C and CONT on the BASIC machine: a SIGINT while running becomes a break
(with ``resumable_breaks`` one that lands where CONT can resume exactly), and CONT
goes on after STOP or such a break, reopening the native FOR loops it broke (the
:class:`Breaks` mixin of :class:`yaseer.basic.machine.machine.Machine`)."""

from __future__ import annotations

import contextlib
import _signal as signal  # the built-in module: signal's own builds its enums at import (start-up)
import sys

from yaseer.basic.machine import runtime
from yaseer.basic.errors import BasicError, CANT_CONTINUE
from yaseer.basic.machine.signals import BreakPoint
from yaseer.basic.machine.stack import ForFrame

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from yaseer.basic.compile.compiled import CompiledArea


class Breaks:
    """Ctrl-C and CONT (see the module docstring).  A mixin of ``Machine``, on its state
    (``cont_point``, ``_break_armed``, ``_reading_input``, the compiled area 0)."""

    def _on_interrupt(self, signum, frame) -> None:
        """SIGINT while running: arm a resumable break, or note the line and variables and break.

        With ``resumable_breaks`` the first Ctrl-C lets the run go on to the next
        point where CONT can resume it exactly (:meth:`_arm_break`); a second
        Ctrl-C before it lands, or one while INPUT waits for a line, breaks at once.

        (A ``continue`` back-edge in Python 3.11 lets KeyboardInterrupt bypass the
        block's ``finally``, so the line and the locals are read from the frame here.)
        """
        if self.resumable_breaks and self._break_armed is None and not self._reading_input:
            if self._arm_break(frame):
                return
        while frame is not None:
            if frame.f_globals.get("_M") is self and "_ln" in frame.f_locals:
                self.line = frame.f_locals["_ln"]
                for local, value in frame.f_locals.items():
                    for name in _scalar_names(local):
                        if name in self.scalars:
                            self.scalars[name] = value
                break
            frame = frame.f_back
        raise KeyboardInterrupt

    def _arm_break(self, frame) -> bool:
        """Make the run stop at the next point CONT can resume from exactly; False if none.

        Those points are: the start of any block of area 0 (every block function is
        swapped for a stub that raises :class:`BreakPoint`, until the break lands),
        and, inside the block running now, its compiled break points (the top of a
        native loop's pass, the back-jump of a block looping to itself), reached
        through a line trace on that frame alone.  Their lines hold nothing that
        can be interrupted half-way, so no statement is ever run twice or skipped.
        """
        compiled = self.compiled.get(0)
        if compiled is None or not compiled.blocks:
            return False
        self._break_armed = (compiled, list(compiled.blocks))
        prelude = len(compiled.pieces) - compiled.block_count
        compiled.blocks[:] = [self._break_stub(b, compiled.pieces[prelude + b][0])
                              for b in range(compiled.block_count)]
        namespace = self.namespaces.get(0)
        while frame is not None:
            if frame.f_globals is namespace and frame.f_code.co_name.startswith("_b"):
                block = int(frame.f_code.co_name[2:])
                points = compiled.break_points.get(block)
                if points and sys.gettrace() is None:
                    frame.f_trace = self._break_tracer(block, points)
                    frame.f_trace_lines = True
                    sys.settrace(_no_call_trace)  # line events reach f_trace only while tracing is on
                break
            frame = frame.f_back
        return True

    def _break_stub(self, block: int, line):
        def stub():
            raise BreakPoint(0, block, self.line if line is None else line, (), self.area_depth)
        return stub

    def _break_tracer(self, block: int, points: dict):
        def trace(frame, event, arg):
            if event == "line":
                point = points.get(frame.f_lineno)
                if point is not None:
                    line, loops = point
                    raise BreakPoint(0, block, line, _loop_states(frame.f_locals, loops), self.area_depth)
            return trace
        return trace

    def _disarm_break(self) -> None:
        """Put the real blocks back and stop the line trace (the break landed, or the run ended)."""
        if self._break_armed is not None:
            compiled, blocks = self._break_armed
            compiled.blocks[:] = blocks
            self._break_armed = None
            if sys.gettrace() is _no_call_trace:
                sys.settrace(None)

    def cont(self) -> str:
        """CONT after STOP, or after a Ctrl-C that landed at a resumable point."""
        if self.cont_point is None:
            raise BasicError("Can't continue", CANT_CONTINUE)
        area, block, *loops = self.cont_point
        if loops and loops[0]:
            block = self._resume_loops(loops[0])
        return self._execute(area, block)

    def _resume_loops(self, loops: tuple) -> int:
        """Reopen native loops broken at the top of a pass; the block to go on at.

        Area 0 is compiled again with those loops run through the FOR stack (every
        block of the old compile keeps an equivalent: the stack's return blocks are
        renumbered), their frames are pushed with the values they had, and the run
        goes on at the innermost loop's body, exactly where the pass would have begun.
        """
        old, old_runtime = self._compiled(0), self.runtimes.get(0)
        forced = tuple(sorted(set(old.dynamic_loops) | {loop[0] for loop in loops}))
        new = self._compile(0, self.programs.get(0, {}), entry_lines=tuple(self._extra_entries),
                            dynamic_loops=forced)
        if old_runtime is not None:
            self.runtimes[0].data_index = old_runtime.data_index
            self.runtimes[0].data_start = old_runtime.data_start
        self._renumber_blocks(_block_mapping(old, new))
        body = 0
        for index, key, value, limit, step in loops:
            body = new.index_blocks[index + 1]
            if value is not None:
                self.scalars[key] = value
            self.stack.append(ForFrame(key, limit, step, body))
        return body

    def _renumber_blocks(self, mapping: dict) -> None:
        """Area 0's block numbers held by the machine (GOSUB returns, FOR bodies, the error handler)."""
        for k, item in enumerate(self.stack):
            if type(item) is int:
                self.stack[k] = mapping.get(item, item)
            elif type(item) is ForFrame:
                item.body = mapping.get(item.body, item.body)
        for name in ("on_error", "error_point"):
            point = getattr(self, name)
            if point is not None and point[0] == 0 and point[2:] in ((), (None,)):
                setattr(self, name, (0, mapping.get(point[1], point[1]), *point[2:]))


def _no_call_trace(frame, event, arg):
    """The thread's trace function while a break is armed: no other frame is traced."""
    return None


def _loop_states(local: dict, loops: tuple) -> tuple:
    """``(FOR index, key, value, limit, step)`` of each native loop open in a block's frame.

    ``loops`` are the compiler's descriptions (see ``CompiledArea.break_points``);
    ``local`` the frame's locals at the top of a pass.
    """
    states = []
    for index, key, n, mode, name in loops:
        limit, step = local[f"_l{n}"], local[f"_s{n}"]
        if mode == "count":
            value = runtime.counted_value(local[f"_it{n}"], local[f"_v{n}"], step, local[f"_i{n}"])
        else:
            value = local[name] if name else None
        states.append((index, key, value, limit, step))
    return tuple(states)


def _block_mapping(old: CompiledArea, new: CompiledArea) -> dict:
    """Old block number -> new, for two compiles of one program that differ only in loops
    made dynamic (which adds block entries and no other blocks)."""
    old_entries, new_entries = len(old.index_blocks), len(new.index_blocks)
    if old.block_count - old_entries != new.block_count - new_entries:
        raise BasicError("Can't continue", CANT_CONTINUE)
    mapping = {block: new.index_blocks[index] for index, block in old.index_blocks.items()}
    for block in range(old_entries, old.block_count):
        mapping[block] = block - old_entries + new_entries
    return mapping


@contextlib.contextmanager
def _interrupt_handler(handler):
    """Use ``handler`` for SIGINT while running, if Python's default one is in place."""
    try:
        installed = signal.getsignal(signal.SIGINT) is signal.default_int_handler
        if installed:
            signal.signal(signal.SIGINT, handler)
    except ValueError:  # not the main thread
        installed = False
    try:
        yield
    finally:
        if installed:
            signal.signal(signal.SIGINT, signal.default_int_handler)


_LOCAL_SUFFIXES = {"n_": ("", "!"), "s_": ("$",), "i_": ("%",), "d_": ("#",)}


def _scalar_names(local: str) -> tuple:
    """The scalar names a compiled block's Python local may hold (number_models.local_name):
    ``n_A`` is A (casio) or A! (gw), ``i_A`` A%, ``d_A`` A#, ``s_A`` A$."""
    suffixes = _LOCAL_SUFFIXES.get(local[:2])
    if suffixes is None or not local[2:3].isalpha():
        return ()
    return tuple(local[2:] + suffix for suffix in suffixes)

