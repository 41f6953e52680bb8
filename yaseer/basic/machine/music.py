"""gw's music: the speaker's queue of notes that PLAY, SOUND and BEEP fill, and PLAY(n).

yaseer makes no sound; it keeps the queue GW-BASIC keeps and its timing, so that a program
sees what it would see on a PC: how long a statement waits, what TIMER reads after it, what
PLAY(n) counts and when ON PLAY(n) traps.  The model follows GWSTS.ASM (PLAYS, SOUNDS, BEEPS,
SNDINI, SNDRST) and the outputs of a real GW-BASIC 3.23 recorded in PC-BASIC's test suite:

* an entry is a tone or a silence with a duration in GW's units (DONOTE: 400 a second);
  entries play one after another from when they are queued (an empty queue starts at once);
  a note played normal (MN) or staccato (MS) is two entries, the tone and the silence after
  it (PLAYS' PLYNO6), so 32 legato notes fit but only 16 others;
* the entry playing is out of the queue; 32 more may wait.  Music in the background (MB)
  waits only for room; music in the foreground (MF, SOUND in MF, BEEP always) waits until
  its last entry has started (PC-BASIC 2.0.8's reading of the recordings: two SOUNDs of a
  second in the foreground take one second);
* PLAY(n) counts the tones and the pauses waiting, not the silences after the notes and
  not the entry playing.

Time: a wait does not sleep.  The machine's clock (machine/clock.py, which TIMER reads) is
moved on by the time waited, so ``A=TIMER: PLAY "L1C": PRINT TIMER-A`` shows the note's
length at once.  Between statements the queue plays on with the host's clock; a read of
PLAY(n) that finds the count the last read found (nothing queued between) moves the clock
on to the count's next change, so a program that loops until the queue is empty ends after
the music's time, not the host's, and at once.  Imported only by a program that uses PLAY, SOUND, BEEP or PLAY(n).
"""

from __future__ import annotations

import sys
from collections import deque

from yaseer.basic.errors import ILLEGAL_FUNCTION_CALL, error_for
from yaseer.basic.machine.runtime import byte_argument

UNITS_PER_SECOND = 400.0  # DONOTE's duration unit: 2.5 ms (GWSTS.ASM PPAUS2)
WAITING_ROOM = 32  # entries that may wait behind the one playing
SOUND_UNITS_PER_TICK = 22  # SOUNDS: the duration in ticks times 22 is DONOTE's units
BEEP_FREQUENCY, BEEP_UNITS = 800, 100  # BEEPS: 800 Hz for a quarter of a second


class Entry:
    """One tone (frequency in Hz) or silence (frequency 0) of the queue: ``start`` and ``end``
    on the machine's clock (seconds); ``counts``: PLAY(n) counts it (not a note's silence)."""

    __slots__ = ("frequency", "start", "end", "counts")

    def __init__(self, frequency: int, start: float, end: float, counts: bool):
        self.frequency, self.start, self.end, self.counts = frequency, start, end, counts


class MusicQueue:
    """The speaker's queue on ``clock`` (machine/clock.py: ``now()`` and ``skip(seconds)``)."""

    def __init__(self, clock):
        self.clock = clock
        self.entries: deque[Entry] = deque()
        self.threshold = None  # ON PLAY(n)'s n: the event is the count going from n to n-1
        self.seen = 0  # the count when last looked at
        self.crossed = False  # the event has happened and waits for its trap
        self.reads: dict = {}  # where -> the count PLAY(n) read there last, while nothing has been queued since

    def _played(self, now: float) -> None:
        """Drop the entries that have ended by ``now``."""
        entries = self.entries
        while entries and entries[0].end <= now:
            entries.popleft()

    def waiting(self, now: float | None = None) -> list[Entry]:
        """The entries not yet started (the one playing is not among them)."""
        now = self.clock.now() if now is None else now
        self._played(now)
        return [e for e in self.entries if e.start > now]

    def count(self, now: float | None = None) -> int:
        """PLAY(n)'s number: the tones and pauses waiting."""
        return sum(1 for e in self.waiting(now) if e.counts)

    def observe(self) -> None:
        """Look at the count now: the event has happened if it went from n or more to below
        n since the last look (entries only start between looks; every queuing looks)."""
        found = self.count()
        if self.threshold is not None and self.seen >= self.threshold > found:
            self.crossed = True
        self.seen = found

    def read(self, where) -> int:
        """PLAY(n)'s read at ``where`` (the place in the compiled program).  A read that finds
        what the same read found last time, nothing queued in between, is a program looping
        until the music moves on: the clock moves on to the count's next change (the next
        counted entry's start), as the loop would spin until then."""
        found = self.count()
        if found and self.reads.get(where) == found:
            now = self.clock.now()
            following = min(e.start for e in self.entries if e.counts and e.start > now)
            self._wait_until(following)
            found = self.count()
        self.reads[where] = found
        return found

    def put(self, frequency: int, units: int, counts: bool, foreground: bool) -> None:
        """Queue a tone or silence of ``units`` (DONOTE): first wait for room; in the
        foreground, then wait until it has started."""
        self.observe()
        waiting = self.waiting()
        if len(waiting) >= WAITING_ROOM:  # room comes when the first waiting entry starts
            self._wait_until(waiting[len(waiting) - WAITING_ROOM].start)
        now = self.clock.now()
        start = max(now, self.entries[-1].end) if self.entries else now
        self.entries.append(Entry(frequency, start, start + units / UNITS_PER_SECOND, counts))
        self.reads.clear()
        if foreground:
            self._wait_until(start)
        self.observe()

    def _wait_until(self, moment: float) -> None:
        """Move the clock on to ``moment`` (no sleep: the wait is the music's time)."""
        ahead = moment - self.clock.now()
        if ahead > 0:
            self.clock.skip(ahead)
        self.observe()

    def stop(self) -> None:
        """SNDRST: the queue emptied, the note playing cut off."""
        self.entries.clear()
        self.seen = 0
        self.reads.clear()


class Music:
    """PLAY's state (GWSTS.ASM SNDINI: octave 4, tempo 120, length 4, normal, foreground)
    and the queue; the machine's ``music``, made by the first statement that uses it."""

    def __init__(self, machine):
        self.machine = machine
        self.queue = MusicQueue(machine.clock)
        self.reset()

    def reset(self) -> None:
        """SNDINI (RUN, CLEAR): PLAY's settings back to their start, the queue stopped."""
        self.octave, self.beats, self.length, self.scale, self.background = 4, 120, 4, 3, False
        self.queue.stop()

    # -- statements
    def play(self, text: str) -> None:
        """PLAY string: its Music Macro Language (machine/mml.py)."""
        from yaseer.basic.machine.mml import play  # (only PLAY reads the language)

        play(self, text)

    def note(self, frequency: int, units: int, counts: bool = True) -> None:
        """DONOTE in PLAY's mode (MMODE): foreground or background."""
        self.queue.put(frequency, units, counts, not self.background)

    def sound(self, frequency: int, duration: float) -> None:
        """SOUND frequency, duration in ticks (18.2 a second): checked as PC-BASIC 2.0.8
        checks it and as the recordings show (SOUND 0,0 is taken: a duration of 0 stops the
        music, SNDRST); otherwise the tone is queued in PLAY's mode (SOUNDS: DOSND), its
        units the ticks times 22, at most 65535 (SOUL4, SOUNL5)."""
        if not -65535 <= duration <= 65535:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        if duration and frequency and not 37 <= frequency <= 32767:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        if duration == 0:
            self.queue.stop()
            return
        units = min(int(round(abs(duration) * SOUND_UNITS_PER_TICK)), 65535)
        if units:
            self.note(frequency, units)

    def beep(self) -> None:
        """BEEP: 800 Hz for a quarter of a second, in the foreground whatever PLAY's mode
        (BEEPS); the terminal's bell rings where standard output is one."""
        self.machine.ring_bell()
        self.queue.put(BEEP_FREQUENCY, BEEP_UNITS, True, True)

    # -- PLAY(n)
    def count(self, n: int) -> float:
        """PLAY(n): the notes waiting in the background queue; n, which names the voice on
        other machines, must be 0..255 (the recordings: -1 and 256 are Illegal function call)."""
        byte_argument(n)
        caller = sys._getframe(1)  # the compiled code's call: which read of the program this is
        return float(self.queue.read((caller.f_code, caller.f_lasti)))
