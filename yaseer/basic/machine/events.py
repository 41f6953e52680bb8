"""gw's event traps: ON KEY(n) GOSUB line, KEY(n) ON, TIMER ON ... (dialects/gw_words.py EVENTS).

Each trap is a line to GOSUB when its event happens and a state (OFF, ON, STOP: GWSTS.ASM
EVSET).  yaseer has no function keys to watch, no serial port, light pen or joystick: their
events never happen, so setting them up checks the arguments as GW-BASIC does and changes
nothing a program can see.  The timer's event and the music queue's happen: PLAY's when the
notes waiting (machine/music.py) go from n to n-1, ``ON PLAY(n)``'s n (as the recordings
show: a trap at 18 with at most 16 staccato notes queued never happens).

GW-BASIC looks for events before every statement (GWMAIN.ASM NEWSTT calls CHKINT).  A
program that sets up a trap is compiled with a block for every statement and no loop
inside a block (compile/blocks.py ``plan``), and while the timer or the music's trap is ON
(or STOPped) with a line to go to, each block of the program is wrapped: when its event has
happened (the period has passed since TIMER ON or the last event; the notes waiting went
below n), the wrapper GOSUBs the line instead of running the block, which the handler's
RETURN then runs.  As in GW-BASIC the event waits while its own handler runs (until that
RETURN) and while the trap is STOPped; OFF forgets it.
"""

from __future__ import annotations

import time

from yaseer.basic.errors import ILLEGAL_FUNCTION_CALL, error_for
from yaseer.basic.machine.runtime import byte_argument as _byte


_WATCHED = ("TIMER", "PLAY")  # the events that happen here: their switches wrap the blocks


def _signed_byte(k: int) -> int:
    return k - 256 if k >= 128 else k


def _turned(k: int) -> int:
    """A trigger number rotated right one bit (ROR AL,1): 0, 2, 4, 6 -> 0..3; an odd one gets bit 7."""
    return k >> 1 | (k & 1) << 7


class Events:
    """The traps of one run: ``targets`` (word, event) -> (area, block) or None; ``states``
    (word, event) -> "ON" / "OFF" / "STOP" (every event starts OFF)."""

    def __init__(self, events: dict, machine):
        self.events = events
        self.machine = machine
        self.targets: dict = {}
        self.states: dict = {}
        self.period = 0.0  # the timer's, in seconds
        self.due = 0.0  # time.monotonic() of the timer's next event
        self.wrapped = None  # (the blocks list wrapped, its real blocks) while a trap is armed
        self.handler_depth: dict = {}  # word -> the stack's length inside its running handler

    def check(self, word: str, n, switching: bool) -> tuple[int, ...]:
        """The events ``word(n)`` names, or Illegal function call.  ON word(n) GOSUB
        (``switching`` False: GWSTS.ASM ONFUN) names one: n-1, or n/2 for a trigger, below
        the word's count compared unsigned; word(n) ON|OFF|STOP (SEVSTT) names every event
        for n = 0, else compares signed, so n-1 or the rotated trigger number from 128 up
        passes, as in GW-BASIC (the recordings: STRIG(1) ON, STRIG(5) ON are taken)."""
        on_form, switch_form, count, _ = self.events[word]
        form = switch_form if switching else on_form
        if n is None:
            return (0,)
        if form == "seconds":
            if not n > 0:
                raise error_for(ILLEGAL_FUNCTION_CALL)
            return (0,)
        k = _byte(n)
        if switching and form == "byte" and k == 0:
            return tuple(range(count))
        event = _turned(k) if form == "trigger" else (k - 1) & 0xFF
        if (_signed_byte(event) if switching else event) >= count:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        return (event,)

    def trap(self, word: str, n, target) -> None:
        """ON word(n) GOSUB: the block to GOSUB (None: no trap).  A word switched without
        parentheses (TIMER, PLAY) has one trap, n its period or its count of notes."""
        (event,) = self.check(word, n, False)
        if self.events[word][1] is None:
            event = 0
        self.targets[word, event] = target
        if word == "TIMER":
            self.period = float(n)
        if word == "PLAY":
            queue = self.machine.music.queue
            queue.threshold = int(n)
            queue.observe()
        self._watch_changed()

    def switch(self, word: str, n, state: str) -> None:
        """word(n) ON | OFF | STOP."""
        for event in self.check(word, n, True):
            if state == "ON" and word == "TIMER" and self.states.get((word, event)) != "STOP":
                self.due = time.monotonic() + self.period  # the count starts at TIMER ON
            self.states[word, event] = state
        if word == "PLAY" and state == "OFF" and self.machine._music is not None:
            self.machine._music.queue.crossed = False  # OFF forgets an event that happened
        if word in _WATCHED:
            self._watch_changed()

    def _live(self, word: str):
        """The trap's target while ``word``'s event may fire (a line to go to, not OFF)."""
        target = self.targets.get((word, 0))
        return target if target is not None and self.states.get((word, 0), "OFF") != "OFF" else None

    def _watch_changed(self) -> None:
        """Wrap the program's blocks while the timer or the music may fire, else unwrap."""
        target = self._live("TIMER") or self._live("PLAY")
        if target is not None and self.wrapped is None:
            compiled = self.machine.compiled.get(target[0])
            if compiled is None:
                return
            blocks = compiled.blocks
            self.wrapped = (blocks, list(blocks))
            blocks[:] = [self._watching(b, real) for b, real in enumerate(blocks)]
        elif target is None:
            self.disarm()

    def disarm(self) -> None:
        """Put the real blocks back (the timer is OFF, has no line, or the run ended)."""
        if self.wrapped is not None:
            blocks, real = self.wrapped
            blocks[:] = real
            self.wrapped = None

    def _watching(self, b: int, real):
        """Block ``b`` run after a look at the timer and the music: when an event is due,
        its handler's block instead, with ``b`` pushed for its RETURN."""

        def watched():
            if time.monotonic() >= self.due and self._may_run("TIMER"):
                self.due = time.monotonic() + self.period
                return self._handle("TIMER", b)
            music = self.machine._music
            if music is not None and self._may_run("PLAY"):
                queue = music.queue
                queue.observe()
                if queue.crossed:
                    queue.crossed = False
                    return self._handle("PLAY", b)
            return real()
        return watched

    def _may_run(self, word: str) -> bool:
        """``word``'s trap is ON, has a line, and its handler is not running."""
        if self.states.get((word, 0)) != "ON" or self.targets.get((word, 0)) is None:
            return False
        depth = self.handler_depth.get(word)
        return depth is None or len(self.machine.stack) < depth

    def _handle(self, word: str, b: int):
        """GOSUB ``word``'s handler from block ``b``: the handler's block."""
        self.machine.gosub(b)
        self.handler_depth[word] = len(self.machine.stack)
        return self.targets[word, 0][1]
