"""Where PRINT puts its text: a stream that knows its column and, optionally, its width.

An :class:`OutputStream` with ``width = None`` (the Casio dialect) never wraps:
lines are as long as the program makes them.  With a width (GW-BASIC's 80
columns, ``WIDTH n``) it lays text out as GW-BASIC's screen does, one output line
per screen row, following Microsoft's source (GIO86.ASM, the PRINT code from
``PRINT1`` to ``NOTABR``) as PC-BASIC 2.0.8
reproduces it:

* a character written when the row is full (column = width) first starts a new
  row, so a line of exactly ``width`` characters followed by the end of the PRINT
  leaves an empty row, as on the real screen; a new row that PRINT itself starts
  (an item that does not fit, ``,``, ``TAB``) does not add another, nor does a
  carriage return or line feed the program prints (``CHR$(13)``: the full row's
  wrap is its new row, as PC-BASIC 2.0.8's screen shows it);
* a PRINT item (a number with its blanks, or a string) that would run past the
  width starts on a new row unless the row is empty (``STRDON``/``LINCHK``);
  longer ones then wrap character by character (on the printer, ``moves_items``
  False, every item wraps so: PC-BASIC's LPRINT);
* ``,`` moves to the next 14-column zone, or to a new row from the last zone on
  (``COMPRT``); ``TAB(n)`` and ``SPC(n)`` count modulo the width (``TABER``).

Columns are 0-based here (BASIC's ``POS`` and ``TAB`` are 1-based).
"""

from __future__ import annotations

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from typing import TextIO

SCREEN_WIDTHS = (40, 80)  # the widths WIDTH n accepts (GW-BASIC's text screen; PC-BASIC checked)
# WIDTH "dev", n: what each of GW-BASIC's device names does (any other name: Bad file name).
# "other": a device yaseer does not have; n is checked (0..255) and changes nothing shown.
DEVICE_WIDTHS = {
    "LPT1:": "printer", "SCRN:": "screen", "KYBD:": "refused",
    "LPT2:": "other", "LPT3:": "other", "COM1:": "other", "COM2:": "other", "CAS1:": "other",
}


class OutputStream:
    """A text stream with its current column; ``width`` None never wraps (see module docstring)."""

    row_waits = True  # a full row waits for its next character to wrap (a file's line never does)
    file = None  # a random file whose record buffer this writes into (PRINT # to a device: none)

    def __init__(self, stream: TextIO, width: int | None = None, moves_items: bool = True):
        self.stream = stream
        self.column = 0
        self.width = width
        self.moves_items = moves_items  # False: a printer, whose items wrap where they are
        self.row: list = []  # csv output: the values of the line being printed

    def write(self, text: str) -> None:
        """Write ``text``; a carriage return (``CHR$(13)``) ends the line as on the screen."""
        if not text:
            return
        if "\r" in text:
            text = text.replace("\r", "\n")
        if self.width is not None:
            text = self._folded(text)
        self.stream.write(text)
        newline = text.rfind("\n")
        self.column = len(text) - newline - 1 if newline >= 0 else self.column + len(text)

    def _folded(self, text: str) -> str:
        """``text`` with a row break before every character that meets a full row."""
        width, column = self.width, self.column
        if "\n" not in text and column + len(text) < width:
            return text  # the common case: it fits and leaves room
        out = []
        for ch in text:
            if ch == "\n":
                column = 0
            elif column >= width:
                out.append("\n")
                column = 1
            else:
                column += 1
            out.append(ch)
        return "".join(out)

    def end_line(self) -> None:
        """The end of a PRINT line: after a full row, its wrap and then the new row."""
        width = self.width
        self.write("\n\n" if width is not None and self.column >= width else "\n")

    def before_write_end(self) -> None:
        """What WRITE # writes before its line end: nothing (a random file pads its record)."""

    def new_row(self) -> None:
        """Start a new row (a row that is full has one already waiting: no empty row)."""
        self.stream.write("\n")
        self.column = 0

    def item(self, text: str) -> None:
        """One PRINT item: on a new row first if it would run past the width (GW-BASIC's
        screen; a printer's items wrap character by character, as PC-BASIC 2.0.8 prints)."""
        width = self.width
        # (a full row's cursor counts as in its last column: one character more still "fits",
        # and wraps by itself; a CHR$(13) then makes no empty row, as PC-BASIC 2.0.8 shows)
        column = self.column
        if width is not None and column and column + len(text) > width and self.moves_items \
                and (column < width or len(text) > 1 or not self.row_waits):
            self.new_row()
        self.write(text)

    def comma(self, zone: int) -> None:
        """``,`` in PRINT: blanks to the next zone; from the last zone on, a new row."""
        width = self.width
        if width is not None and width >= zone and self.column >= zone * (width // zone - 1):
            self.new_row()
            return
        self.write(" " * (zone - self.column % zone))

    def tab(self, n: int) -> None:
        """``TAB(n)``: to 1-based column n (n below 1 is column 1), on a new row if already
        past it; with a width, n counts modulo the width."""
        target = max(n, 1) - 1
        column = self.column
        if self.width is not None:
            target %= self.width
            if self.row_waits and self.moves_items:  # the screen's column of a full row is its last
                column = min(column, self.width - 1)  # (GIOSCN.ASM SCNGPS): TAB(80) there adds nothing
        if target < column:
            self.new_row()
            column = 0
        self.write(" " * (target - column))

    def spc(self, n: int) -> None:
        """``SPC(n)``: n blanks (none for n below 1; modulo the width when there is one)."""
        count = max(n, 0)
        if self.width is not None:
            count %= self.width
        self.write(" " * count)

    def flush(self) -> None:
        self.stream.flush()


class FileStream(OutputStream):
    """A sequential file's stream (PRINT #, WRITE #): bytes as the program prints them, a
    PRINT line ending in CR LF, and the file's column as GW-BASIC counts it (GIODSK.ASM
    ``SOUTPS``): a carriage return puts it back to 0, a character from blank up moves it
    one, other control codes (a lone LF, ``CHR$(8)``, ``CHR$(28)`` ...) not at all, and
    the count is a byte: a line of 260 characters leaves it at 4.  ``width`` None is the
    disk's infinite width (255); ``WIDTH #n, w`` sets another (``F_WID``), where a PRINT
    item that does not fit starts a new line, ``TAB`` and ``SPC`` count modulo it; the
    disk driver itself never breaks a line (GIODSK.ASM; as PC-BASIC 2.0.8 writes it)."""

    row_waits = False

    def write(self, text: str) -> None:
        if not text:
            return
        self.stream.write(text)
        self.advance(text)

    def advance(self, text: str) -> None:
        """Move the column over ``text``, written (SOUTPS)."""
        cr = text.rfind("\r")
        counted = text[cr + 1:] if cr >= 0 else text
        moved = len(counted) if counted.isprintable() else sum(ch >= " " for ch in counted)
        self.column = ((0 if cr >= 0 else self.column) + moved) % 256

    def new_row(self) -> None:
        self.stream.write("\r\n")
        self.column = 0

    def end_line(self) -> None:
        self.write("\r\n")
