"""Devices a program OPENs by name: the screen, the printer, the null device.

GW-BASIC reads a name with a colon after two or more characters as one of its own devices
(GIO86.ASM ``PARDEV`` looks it up in GIOTBL.ASM's table: ``SCRN:``, ``LPT1:``, ``KYBD:``,
``COM1:`` ...; a name not there is ``Bad file name``); any other name goes to DOS, which
takes ``CON``, ``NUL``, ``PRN``, ``AUX``, ``LPT1`` ... as its devices whatever extension
follows (``NUL.TXT`` is the null device).  Which names are which is the dialect's data
(``Dialect.device_files``); this module makes the open "file" of each kind:

* ``screen``: PRINT # and WRITE # print on the screen as PRINT does (SCRN:, CONS:, and
  DOS's CON, whose text reaches the same screen); ``WIDTH #n, w`` gives the file a width of
  its own (:class:`ScreenFile`);
* ``printer``: as LPRINT prints (LPT1:, PRN, LPT1);
* ``null``: output is dropped, input is at its end at once (EOF -1, the next read
  ``Input past end``);
* ``absent``: a device yaseer does not have (COM1:, CAS1:, AUX ...): ``Device
  unavailable``.

None of them is ever a file of the program's directory.  Reading the screen, the printer
or the keyboard (``keyboard``: KYBD:) as a file is ``Bad file mode`` here
(yaseer's choice: the keys are read by INPUT, LINE INPUT, INPUT$ and INKEY$).
"""

from __future__ import annotations

from yaseer.basic.errors import BAD_FILE_MODE, BAD_FILE_NAME, DEVICE_UNAVAILABLE, INPUT_PAST_END, error_for

OUTPUT_KINDS = ("screen", "printer", "null")


def device_kind(name: str, devices: tuple) -> str | None:
    """The kind of device ``name`` names among ``devices`` ((name, kind) pairs: ``NAME:``
    a device of the BASIC's own, read at the start of the name; ``NAME`` one of DOS's,
    the name's part before its extension), ``"unknown"`` for another name with a colon
    after two or more characters (PARDEV: ``Bad file name``), None for a file name."""
    upper = name.strip().upper()
    colon = upper.find(":")
    if colon >= 2:
        return next((kind for device, kind in devices if device.endswith(":") and upper.startswith(device)), "unknown")
    if colon >= 0:
        return None  # a drive letter: the directory's business
    base = upper.rsplit("/", 1)[-1].rsplit("\\", 1)[-1].split(".", 1)[0].rstrip()
    return next((kind for device, kind in devices if device == base), None)


def reserved_names(devices: tuple) -> frozenset:
    """The DOS device names among ``devices``: no file of the directory may be made with one."""
    return frozenset(device for device, _ in devices if not device.endswith(":"))


def open_device(kind: str, mode: str, streams: dict) -> "DeviceFile":
    """The open device of ``kind`` in ``mode`` ("I", "O", "A", "R"); ``streams``: the
    machine's ``screen`` and ``printer`` output streams."""
    if kind == "unknown":
        raise error_for(BAD_FILE_NAME)
    if kind == "keyboard":
        raise error_for(BAD_FILE_MODE)
    if kind not in OUTPUT_KINDS:
        raise error_for(DEVICE_UNAVAILABLE)
    if mode == "R" or (mode == "I" and kind != "null"):
        raise error_for(BAD_FILE_MODE)
    return DeviceFile(mode, None if kind == "null" else streams[kind], kind)


class _Dropped:
    """A text sink that keeps nothing (the null device's output)."""

    @staticmethod
    def write(text: str) -> None:
        pass


class DeviceFile:
    """An open device: ``stream`` the screen's or printer's output stream, None for the
    null device (whose output goes nowhere and whose input is empty)."""

    identity = None  # never the same file as one of the directory's

    def __init__(self, mode: str, stream, kind: str = ""):
        from yaseer.basic.machine.screen import FileStream

        self.mode = mode
        self.kind = kind
        self.stream = stream if stream is not None else FileStream(_Dropped())

    @property
    def is_output(self) -> bool:
        return self.mode != "I"

    def output(self):
        if self.mode == "I":
            raise error_for(BAD_FILE_MODE)
        return self.stream

    def set_width(self, width: int | None) -> None:
        """WIDTH #n, w: the screen's file takes width w (None: 255, no width) as its own
        (:class:`ScreenFile`); the screen and printer keep theirs (WIDTH, WIDTH LPRINT)."""
        screen = getattr(self.stream, "screen", self.stream)
        if self.kind == "screen":
            self.stream = ScreenFile(screen, width)

    def close(self) -> None:
        """Nothing to write out: a device keeps no Ctrl-Z."""

    # -- input: only the null device reads, and it is at its end
    def _input(self) -> None:
        if self.mode != "I":
            raise error_for(BAD_FILE_MODE)

    def at_end(self) -> bool:
        self._input()
        return True

    def first(self) -> str:
        self._input()
        raise error_for(INPUT_PAST_END)

    def next(self) -> None:
        return None

    def back(self, ch: str) -> None:
        pass

    def read_chars(self, n: int) -> str:
        return self.first()

    def read_line(self, longest: int) -> str:
        return self.first()

    def read_field(self, numeric: bool, longest: int) -> str:
        return self.first()

    # -- LOF, LOC: a device has no length and no records
    def length(self) -> int:
        return 0

    def records(self) -> int:
        return 0


BACK_ONTO_LAST_COLUMN = "\x1d"  # the screen's cursor-left code: from the waiting wrap to the last column


class ScreenFile:
    """The screen as a file with a width of its own (``WIDTH #n, w`` on SCRN:), as GIOSCN.ASM
    prints through a file: a PRINT item is fitted to the file's width (SCNGWD gives F_WID)
    and the column is the screen cursor's (SCNGPS); a character (not a carriage return)
    that would stand past column w starts a new row first, unless w is the screen's own
    width, where the screen's wrap does it (SCNOL2: CSRX against F_WID, then LINLEN); a
    file wider than the screen never wraps: a character past the row's end is written
    over its last column.  ``screen``: the screen's output stream; ``width``
    None: no width of its own (255)."""

    row_waits = True
    file = None

    def __init__(self, screen, width: int | None):
        self.screen = screen
        self.width = width
        self.moves_items = True

    @property
    def column(self) -> int:
        return self.screen.column

    @column.setter
    def column(self, value: int) -> None:
        self.screen.column = value

    @property
    def row(self) -> list:
        return self.screen.row

    def write(self, text: str) -> None:
        width, screen = self.width or 255, self.screen
        if width == screen.width:
            screen.write(text)
            return
        for ch in text:
            if ch not in "\r\n":
                if screen.column >= width:
                    screen.new_row()
                elif screen.column >= screen.width:  # wider than the screen: no wrap, the last
                    screen.write(BACK_ONTO_LAST_COLUMN)  # column is written over (SCNOL2 DEC CSRX)
            screen.write(ch)

    def new_row(self) -> None:
        self.screen.new_row()

    def end_line(self) -> None:
        """The end of a PRINT # line: CR and LF to the screen (SCNOL1), one new row even
        after a full row (the screen's PRINT leaves an empty row there)."""
        self.screen.new_row()

    def flush(self) -> None:
        self.screen.flush()

    def __getattr__(self, name):  # item, comma, tab, spc: OutputStream's, on the file's width
        from yaseer.basic.machine.screen import OutputStream

        return getattr(OutputStream, name).__get__(self)
