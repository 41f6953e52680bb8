"""GW-BASIC's screen statements as its SCNINT reads them: CLS, LOCATE, WIDTH (the
screen's), COLOR, SCREEN and PCOPY, and the screen mode SCREEN chose.

The compiled code hands each statement its arguments in order (None where one was left
out) and, where its text went wrong or went on past its last argument, the error that
stands for the rest (compile/statements_io.py ``byte_statement``, source/byte_lists.py).
:class:`ByteReader` reads them as GWSTS.ASM SCNINT does: each with GETBYT (beyond
-32768..32767 Overflow, outside 0..255 Illegal function call), in order, the error for
the rest once they are read; the statement checks what it read as it goes (LOCATE's row
before its column is read: GWSTS.ASM LOCATE), then what the OEM's routines check (CLRSCN,
CSRATR, SWIDTH, SETCLR, SCRSTT, not in the published source: as a real GW-BASIC 3.23 did
in the recordings of PC-BASIC's test suite, and PC-BASIC 2.0.8 where they agree).

The modes are the dialect's (``Dialect.screen.modes``); a graphics mode's text is the text
screen's (no drawing is emulated).  Pages other than the one shown are checked, not kept.
"""

from __future__ import annotations

from yaseer.basic.arithmetic.values import to_int
from yaseer.basic.errors import BasicError, MISSING_OPERAND
from yaseer.basic.machine.runtime import byte_argument, illegal_function_call


class ByteReader:
    """A statement's arguments as SCNINT reads them (see the module docstring); ``fault``:
    (message, code) of the error the text after them is, or None."""

    __slots__ = ("values", "fault", "at")

    def __init__(self, values: tuple, fault):
        self.values = values
        self.fault = fault
        self.at = 0

    def next(self):
        """The next argument, GETBYT's byte (None when left out or past the last)."""
        at = self.at
        if at >= len(self.values):
            self.end()
            return None
        self.at = at + 1
        value = self.values[at]
        return None if value is None else byte_argument(to_int(value))

    def rest(self) -> list:
        """Every argument left, in order (GTPRMS), then the text's error if any."""
        read = [self.next() for _ in range(len(self.values) - self.at)]
        self.end()
        return read

    def end(self) -> None:
        """The statement's end (EOSCHK): the error of the text after the arguments."""
        if self.fault is not None:
            raise BasicError(*self.fault)


class ScreenWords:
    """The screen statements of a machine whose dialect reads them so, and its screen mode."""

    def __init__(self, machine):
        self.machine = machine
        modes = machine.dialect.screen.modes
        self.modes = {mode.number: mode for mode in modes}
        self.mode = modes[0] if modes else None
        self.canvas = None  # a graphics mode's pixels (machine/graphics.py); None in a text mode

    def run(self, word: str, values: tuple, fault) -> None:
        """Statement ``word`` with its arguments ``values`` and the error for its rest."""
        getattr(self, word.lower())(ByteReader(values, fault))

    # ------------------------------------------------------------ the statements
    def cls(self, reader: ByteReader) -> None:
        """CLS [n]: n 0..2 (CLRSCN; PC-BASIC 2.0.8), checked after the statement's end."""
        n = reader.next()
        reader.end()
        if n is not None and n > 2:
            raise illegal_function_call()
        self.machine.clear_screen(n)

    def locate(self, reader: ByteReader) -> None:
        """LOCATE [row][, [column][, [cursor][, [start][, [stop]]]]] (GWSTS.ASM LOCATE):
        the row checked before the column is read, the column before the rest; then the
        statement's end, then the cursor's visibility (0, 1) and shape (0..31; a stop
        without a start Illegal function call: CSRATR as PC-BASIC 2.0.8 checks it)."""
        machine = self.machine
        display = machine._screen_model()
        row = reader.next()
        row = display.row() if row is None else row - 1
        top, bottom = (display.view_top, display.view_bottom) if display.view_set else (0, display.rows - 1)
        if display.keys_on and display.keys:
            bottom = min(bottom, display.rows - 2)
        if not top <= row <= bottom:
            raise illegal_function_call()
        column = reader.next()
        # left out: the cursor's column, a full row's waiting wrap as the last (SCNDRV.ASM SCNPOS)
        column = min(display.x, display.columns - 1) if column is None else column - 1
        if not 0 <= column < display.columns:
            raise illegal_function_call()
        cursor, start, stop = reader.next(), reader.next(), reader.next()
        reader.end()
        if (cursor is not None and cursor > 1) or (start is None and stop is not None) \
                or any(v is not None and v > 31 for v in (start, stop)):
            raise illegal_function_call()
        display.locate(column, row)
        machine.screen.column = column

    def width(self, reader: ByteReader) -> None:
        """WIDTH [columns][, rows] (GWSTS.ASM GWWID): left out, the screen's own; the same
        size changes nothing, another must be 40 or 80 columns of 25 rows (SWIDTH)."""
        columns, rows = reader.next(), reader.next()
        reader.end()
        display = self.machine._screen_model()
        columns = display.columns if columns is None else columns
        rows = display.rows if rows is None else rows
        if (columns, rows) == (display.columns, display.rows):
            return
        if rows != display.rows or columns not in (40, 80):
            raise illegal_function_call()
        self.machine.set_width(columns)

    def color(self, reader: ByteReader) -> None:
        """COLOR [foreground][, background][, border]: every number read first (GTPRMS),
        then SETCLR: none at all Illegal function call, a last one left out Missing operand,
        more than three Illegal function call, then the mode's ranges (ScreenMode.color)."""
        values = reader.rest()
        if not values:
            raise illegal_function_call()
        _no_missing_last(values)
        if len(values) > 3:
            raise illegal_function_call()
        mode = self.mode
        rule = "text" if mode is None else mode.color
        if rule == "none":
            raise illegal_function_call()
        if rule == "ega":
            fore, back = (values + [None, None])[:2]
            display = self.machine._screen_model()
            fore = display.attr & 0x0F if fore is None else fore
            if not 1 <= fore <= 15 or (back is not None and back >= mode.colours):
                raise illegal_function_call()
            display.attr = fore
            if self.canvas is not None:  # the colour PSET, LINE ... draw in when given none
                self.canvas.foreground = fore
            return
        if rule == "text":
            self.machine.screen_statement("COLOR", tuple(values))

    def screen(self, reader: ByteReader) -> None:
        """SCREEN [mode][, [colour]][, [active page]][, [shown page]]: every number read
        first (GTPRMS), then SCRSTT: none or a last one left out Missing operand, more than
        four Illegal function call, a mode the machine lacks or a page beyond the mode's
        Illegal function call (the colour switch takes any byte).  A new mode clears the
        screen, takes its width (a text mode keeps the width) and its first colours."""
        values = reader.rest()
        if not values:
            raise BasicError("Missing operand", MISSING_OPERAND)
        _no_missing_last(values)
        if len(values) > 4:
            raise illegal_function_call()
        number, _colour, active, shown = (values + [None] * 4)[:4]
        current = self.mode
        if not self.modes:  # no modes: the text screen alone
            if number not in (None, 0) or any(v not in (None, 0) for v in (active, shown)):
                raise illegal_function_call()
            return
        mode = current if number is None else self.modes.get(number)
        if mode is None:
            raise illegal_function_call()
        display = self.machine._screen_model()
        columns = mode.columns or display.columns
        pages = mode.pages[columns == 80]
        if any(page is not None and page >= pages for page in (active, shown)):
            raise illegal_function_call()
        if mode is not current:
            self.mode = mode
            self.canvas = None
            if mode.width:  # a graphics mode: its pixels, blank (machine/graphics.py)
                from yaseer.basic.machine.graphics import canvas_for  # (only programs that draw)

                self.canvas = canvas_for(mode, pages)
            self.machine.set_width(columns)
            self.machine.clear_screen(0)
            display.attr = mode.attribute
        canvas = self.canvas
        if canvas is not None and (active is not None or shown is not None):
            active = canvas.active if active is None else active
            canvas.set_pages(active, canvas.shown if shown is None else shown)

    def copy_page(self, source: int, target: int) -> None:
        """PCOPY source, target: both pages of the mode (0..pages-1), else Illegal function
        call (as the recorded PCOPY test); the pages not shown are not kept, so nothing
        changes on the text screen; a graphics mode's pixels are copied."""
        mode = self.mode
        display = self.machine._screen_model()
        pages = 1 if mode is None else mode.pages[display.columns == 80]
        if not (0 <= source < pages and 0 <= target < pages):
            raise illegal_function_call()
        if self.canvas is not None:
            self.canvas.copy_page(source, target)


def _no_missing_last(values: list) -> None:
    """A list whose last number is left out (``COLOR 1,``): Missing operand."""
    if len(values) > 1 and values[-1] is None:
        raise BasicError("Missing operand", MISSING_OPERAND)
