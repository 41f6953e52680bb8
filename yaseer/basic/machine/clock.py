"""GW-BASIC's clock: TIMER, DATE$ and TIME$, and the statements ``DATE$ = s`` and
``TIME$ = s`` that set it.

An emulator does not set the computer's clock: a machine keeps an offset in seconds from
the host's clock instead, so after ``TIME$ = "12:00:00"`` TIME$ reads 12:00:00 and goes on
from there (and DATE$ and TIMER with it), as the set clock of the PC would; a new machine
starts at the host's time again.

The texts are read as GWSTS.ASM reads them: PRSTIM ``h[:m[:s[:t]]]`` (``.`` also separates;
hours below 24, minutes and seconds below 60, hundredths below 100; a missing part is 0),
PRSDAT ``m/d/y`` or ``m-d-y`` (a year 0..77 is 20yy, 78..99 19yy, else 1978..2099).  Each
number is digits up to the next non-digit; what follows the last one is not read.  Then DOS
sets the date (GW's SETDAT, INT 21h function 2Bh), which the machine the PC-BASIC suite was
recorded on (its faulty_DATE test) refuses for a year before 1980, a month beyond 1..12 or a
day beyond 1..31, whatever the month: ``02-30-2000`` is taken and DATE$ shows it so.
Anything else, an empty text among it, is ``Illegal function call``.
"""

from __future__ import annotations

import time

from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL


def _illegal() -> BasicError:
    return BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)


class _Text:
    """A clock text read number by number (GWSTS.ASM GNUM16, DIGIT)."""

    def __init__(self, text: str):
        if not text:
            raise _illegal()  # the string must not be null
        self.text, self.at = text, 0

    def number(self, most: int = 255) -> int:
        """The digits from here (none: 0); beyond ``most`` (GNUM8: a byte) Illegal function call."""
        start = self.at
        while self.at < len(self.text) and self.text[self.at] in "0123456789":
            self.at += 1
        value = int(self.text[start:self.at] or "0")
        if value > most:
            raise _illegal()
        return value

    def separator(self, marks: str, needed: bool) -> None:
        """Step over one of ``marks``; at the end of the text an error only if ``needed``
        (DATSEP), else nothing (TIMSEP); any other character Illegal function call."""
        if self.at >= len(self.text):
            if needed:
                raise _illegal()
            return
        if self.text[self.at] not in marks:
            raise _illegal()
        self.at += 1


def time_of_day(text: str) -> tuple[int, int, int, int]:
    """(hours, minutes, seconds, hundredths) of a ``TIME$ =`` text (GWSTS.ASM PRSTIM)."""
    reader = _Text(text)
    parts = []
    for k, limit in enumerate((24, 60, 60, 100)):
        if k:
            reader.separator(":.", False)
        value = reader.number()
        if value >= limit:
            raise _illegal()
        parts.append(value)
    return parts[0], parts[1], parts[2], parts[3]


# the dates DOS's set-date call took on the machine the recordings were made on
FIRST_YEAR, LAST_DAY = 1980, 31


def calendar_date(text: str) -> tuple[int, int, int]:
    """(year, month, day) of a ``DATE$ =`` text (GWSTS.ASM PRSDAT, DYOFYR)."""
    reader = _Text(text)
    month = reader.number()
    reader.separator("/-", True)
    day = reader.number()
    reader.separator("/-", True)
    year = reader.number(65535)
    if year < 100:
        year += 2000 if year < 78 else 1900
    elif year < 1978:
        raise _illegal()
    if not FIRST_YEAR <= year < 2100 or not 1 <= month <= 12 or not 1 <= day <= LAST_DAY:
        raise _illegal()  # (the year from 1978 is PRSDAT's; DOS's call refuses the rest)
    return year, month, day


class Clock:
    """The machine's clock: the host's, moved by what ``DATE$ =`` and ``TIME$ =`` set."""

    def __init__(self) -> None:
        self.offset = 0.0  # seconds added to the host's clock
        # a date set beyond its month's days (``02-30-2000``): (DATE$ as the calendar shows
        # the day it falls on, DATE$ as set), the text shown while the clock is on that day
        self.shown_date: tuple[str, str] | None = None

    def now(self) -> float:
        """The machine's time, seconds since the epoch."""
        return time.time() + self.offset

    def skip(self, seconds: float) -> None:
        """Move the clock on by ``seconds`` at once (a wait the machine does not sleep: the
        music queue's, machine/music.py)."""
        self.offset += seconds

    def timer(self) -> float:
        """TIMER: seconds since midnight (local time), to the hundredth."""
        now = self.now()
        local = time.localtime(now)
        return round(local.tm_hour * 3600 + local.tm_min * 60 + local.tm_sec + now % 1.0, 2)

    def date(self) -> str:
        """DATE$: ``MM-DD-YYYY``."""
        shown = time.strftime("%m-%d-%Y", time.localtime(self.now()))
        if self.shown_date is not None and shown == self.shown_date[0]:
            return self.shown_date[1]
        return shown

    def time(self) -> str:
        """TIME$: ``HH:MM:SS`` (24-hour)."""
        return time.strftime("%H:%M:%S", time.localtime(self.now()))

    def set(self, name: str, text: str) -> None:
        """``DATE$ = text`` (the date, the time of day kept) or ``TIME$ = text`` (the time of
        day, the date kept)."""
        now = self.now()
        local = time.localtime(now)
        if name == "TIME$":
            hours, minutes, seconds, hundredths = time_of_day(text)
            fields = (local.tm_year, local.tm_mon, local.tm_mday, hours, minutes, seconds)
            fraction = hundredths / 100
        else:
            fields = calendar_date(text) + (local.tm_hour, local.tm_min, local.tm_sec)
            fraction = now % 1.0
        target = time.mktime(fields + (0, 0, -1)) + fraction
        self.offset += target - now
        if name != "TIME$":
            year, month, day = fields[:3]
            self.shown_date = (time.strftime("%m-%d-%Y", time.localtime(target)), f"{month:02d}-{day:02d}-{year}")
