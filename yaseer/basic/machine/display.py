"""The machine's display: a grid of character cells with a cursor, one model for every dialect.

A :class:`Display` is ``columns`` x ``rows`` cells (the *virtual screen*), of which
``shown`` rows are visible at a time: a window that follows the cursor.  The
geometry is the dialect's (``Dialect.display``):

* casio: 32 columns x 8 rows, 2 of them shown - the FX-850P/880P's 32-column,
  2-line LCD over its 32 x 8 virtual screen (owner's manual, part 6 "Virtual
  screen function"; LOCATE's page: 0 <= x <= 31, 0 <= y <= 7 in its picture);
* gw: 80 x 25 with all 25 rows shown (GW-BASIC's text screen), the last row the
  function-key line (KEY ON/OFF), for LOCATE, CLS, COLOR, CSRLIN, POS, SCREEN(row, col)
  and VIEW PRINT.

How the cursor wraps, where rows and columns are counted from, the key line and
whether cells carry colours are the dialect's screen rules
(yaseer/basic/dialects/screens.py).

Writing text puts each character at the cursor and moves it right; past the last
column the cursor goes to the start of the next row (at once, or with ``late_wrap``
when the next character comes: the cursor then waits at ``x == columns``), and below
the last row that scrolls the rows that scroll move up one row, the new bottom row blank (PRINT's page:
"A line feed results when the cursor reaches the last column on the last line of
the screen ..., scrolling the entire screen upwards").  Control codes (below 32)
do what the dialect's ``controls`` table says (casio: ``dialects.charset.CASIO_CONTROLS``,
the character code table's parenthesised codes); a code with no action there is not
shown.  The window moves only as far as needed to keep the cursor's row visible.

A display is *drawn* once a program placed text itself (LOCATE, a cursor control
code, VIEW PRINT, and CLS where the rules say so): from then on a transcript shows its screens (:meth:`shown_lines`)
instead of the streamed text.  Columns and rows are 0-based.
"""

from __future__ import annotations

from yaseer.basic.dialects.screens import CASIO_SCREEN
from yaseer.patterns import Pattern

# Codes that place text where the program chooses: once one is written the display is "drawn".
_CONTROL = Pattern("[\x00-\x1f]")
DRAWING_ACTIONS = frozenset(("line_top", "line_cancel", "line_end", "backspace", "home", "clear",
                             "right", "left", "up", "down",
                             "window_home", "advance", "regress", "window_up", "window_down"))
NORMAL = 7  # the attribute of a cell: white on black (COLOR 7, 0)
REVERSE = 0x70  # the key line's key texts (GWSTS.ASM KEYDSP swaps the colours)
KEY_LINE_SHOWS = {"\r": "\u2190", "\n": "<"}  # KEYDCH: CR as the OEM's arrow (PC-BASIC: ←), LF as <


class Display:
    """``columns`` x ``rows`` character cells, ``shown`` rows visible (see module docstring)."""

    __slots__ = ("columns", "rows", "shown", "controls", "rules", "cells", "attrs", "attr", "x", "y", "top",
                 "joined", "drawn", "changed", "view_top", "view_bottom", "view_set", "keys", "keys_on")

    def __init__(self, columns: int, rows: int, shown: int | None = None, controls: dict | None = None,
                 rules=CASIO_SCREEN):
        self.columns = columns
        self.rows = rows
        self.shown = rows if shown is None else shown
        self.controls = controls if controls is not None else {}
        self.rules = rules
        self.attr = NORMAL
        self.keys = list(rules.function_keys)
        self.keys_on = False  # GWINIT.ASM: a program named on the command line starts with KEY OFF
        self.x = self.y = self.top = 0
        self.drawn = False
        self.changed = False  # anything written, located or cleared since the last screen shown
        self._new_cells()

    def _new_cells(self) -> None:
        """A blank screen of the current size, the cursor home, the whole screen's window."""
        self.cells = [[" "] * self.columns for _ in range(self.rows)]
        self.joined = [False] * self.rows  # row k goes on from row k - 1 (text wrapped into it)
        self.attrs = [[NORMAL] * self.columns for _ in range(self.rows)] if self.rules.attributes else None
        self.reset_view()
        self.x, self.y, self.top = 0, 0, 0
        self.draw_keys()

    # ------------------------------------------------------------ the cursor
    def locate(self, x: int, y: int) -> None:
        """Put the cursor at column ``x`` of row ``y`` (the caller checked the ranges)."""
        self.x, self.y = x, y
        self.drawn = self.changed = True
        self._follow()

    def clear(self, whole: bool | None = None) -> None:
        """Blank the rows that scroll, or (``whole``; by default when no view is set) every
        row, the key line drawn again; the cursor to the first row that scrolls and the
        window home (CLS, ``CHR$(12)``)."""
        if whole is None:
            whole = not self.view_set
        first, last = (0, self.rows - 1) if whole else (self.view_top, self.view_bottom)
        for k in range(first, last + 1):
            self.cells[k] = [" "] * self.columns
            self.joined[k] = False
            if self.attrs is not None:
                self.attrs[k] = [self.attr & 0x70 | NORMAL] * self.columns  # CLS keeps the background
        if whole:
            self.draw_keys()
        self.x, self.y, self.top = 0, self.view_top, 0
        self._follow()
        self.changed = True
        if self.rules.clear_draws:
            self.drawn = True

    def reset_view(self) -> None:
        """The rows that scroll: every row but the key line (if the screen has one)."""
        self.view_top, self.view_bottom = 0, self.rows - 1 - (1 if self.rules.function_keys else 0)
        self.view_set = False

    def set_view(self, first: int, last: int) -> None:
        """Only rows ``first``..``last`` scroll (and CLS clears them); the cursor goes to
        ``first`` (the caller checked the rows)."""
        self.view_top, self.view_bottom = first, last
        self.view_set = True
        self.x, self.y = 0, first
        self.drawn = self.changed = True
        self._follow()

    def new_line(self) -> None:
        """The cursor to the start of the next row, scrolling at the bottom."""
        self.x = 0
        self._down()

    def to_end_of_logical_line(self) -> None:
        """The cursor to the last row of its logical line (the rows its text wrapped into),
        where EXE leaves it before the line ends (INPUT.md item 8: the whole logical line is
        input)."""
        y = self.row()
        while y + 1 < self.rows and self.joined[y + 1]:
            y += 1
        if y != self.y:
            self.x, self.y = self.columns - 1, y
            self._follow()

    def resize(self, columns: int) -> None:
        """A screen ``columns`` wide (WIDTH 40 / 80): blank, the cursor home."""
        self.columns = columns
        self._new_cells()
        self.changed = True

    # ------------------------------------------------------------ the function-key line
    def set_keys_shown(self, on: bool) -> None:
        """KEY ON / KEY OFF: show the function keys' texts on the last row, or blank it."""
        if on != self.keys_on:
            self.keys_on = on
            self.draw_keys()
            self.changed = True

    def define_key(self, number: int, text: str) -> None:
        """KEY n, text: function key ``number`` (1-based) types ``text`` (at most 15 characters)."""
        self.keys[number - 1] = text[:15]
        if self.keys_on:
            self.draw_keys()
            self.changed = True

    def draw_keys(self) -> None:
        """The last row: each key's number and its first characters (KEYDSP), or blanks."""
        if not self.keys:
            return
        last = self.rows - 1
        self.cells[last] = [" "] * self.columns
        if self.attrs is not None:
            self.attrs[last] = [self.attr] * self.columns
        if not self.keys_on:
            return
        width = self.rules.key_label
        for k, text in enumerate(self.keys):
            start = k * (width + 2)
            if start + width + 2 > self.columns:
                break  # only whole keys (40 columns: five)
            label = "".join(KEY_LINE_SHOWS.get(ch, ch) for ch in text[:width]).ljust(width)
            self.cells[last][start:start + width + 1] = str((k + 1) % 10) + label
            if self.attrs is not None:
                self.attrs[last][start + 1:start + width + 1] = [REVERSE] * width

    # ------------------------------------------------------------ text
    def write(self, text: str) -> None:
        """Show ``text`` from the cursor on: characters, line ends and control codes."""
        self.changed = True
        start = 0
        for match in _CONTROL.finditer(text):
            if match.start() > start:
                self._put(text[start:match.start()])
            ch = match.group()
            action = "carriage_return" if ch == "\n" else self.controls.get(ord(ch))
            if action is not None:
                if action == "glyph":
                    self._put(ch)
                else:
                    getattr(self, "_" + action)()
                    if action in DRAWING_ACTIONS:
                        self.drawn = True
            start = match.end()
        if start < len(text):
            self._put(text[start:])
        self._follow()

    def _put(self, run: str) -> None:
        """Characters without control codes, row by row (a full row wraps at once, or
        before the next character with ``late_wrap``)."""
        columns = self.columns
        late = self.rules.late_wrap
        attrs = self.attrs
        while run:
            if self.x >= columns:
                self.new_line()  # the wrap that waited for this character
                self.joined[self.y] = True
            room = columns - self.x
            piece = run[:room]
            self.cells[self.y][self.x:self.x + len(piece)] = piece
            if attrs is not None:
                attrs[self.y][self.x:self.x + len(piece)] = [self.attr] * len(piece)
            self.x += len(piece)
            run = run[room:]
            if self.x >= columns and not late:
                self.new_line()
                self.joined[self.y] = True

    def _carriage_return(self) -> None:
        self.new_line()  # (after a full row: its waiting wrap, one new row)
        self.joined[self.y] = False

    def _line_feed(self) -> None:
        self._down()

    def _home(self) -> None:
        self.x = self.y = 0

    def _clear(self) -> None:
        self.clear(whole=False)

    def _line_cancel(self) -> None:
        """Blank the cursor's row; the cursor to its start (the library prints CHR$(5) before
        each value it shows in the same place: the value before must go)."""
        self.cells[self.y][:] = [" "] * self.columns
        self.x = 0

    def _line_top(self) -> None:
        self.x = 0

    def _line_end(self) -> None:
        row = self.cells[self.y]
        end = len("".join(row).rstrip(" "))
        self.x = min(end, self.columns - 1)

    def _backspace(self) -> None:
        if self.x > 0:
            self.x -= 1
            self.cells[self.y][self.x] = " "

    def _right(self) -> None:
        if self.x < self.columns - 1:
            self.x += 1

    def _left(self) -> None:
        if self.x > 0:
            self.x -= 1

    def _up(self) -> None:
        if self.y > 0:
            self.y -= 1

    def _down(self) -> None:
        if self.y > self.view_bottom:  # below the rows that scroll (the key line): back into them
            self.scroll()
            self.y = self.view_bottom
        elif self.y != self.view_bottom and self.y < self.rows - 1:
            self.y += 1
        else:
            self.scroll()

    def _bell(self) -> None:
        """BEL: a sound, nothing on the screen, the cursor stays."""

    # GW-BASIC's cursor codes move within the window and never scroll (SCNDRV.ASM WCS*)
    def _tab(self) -> None:
        self._put(" " * (8 - (min(self.x, self.columns - 1) % 8)))

    def _window_home(self) -> None:
        self.x, self.y = 0, self.view_top

    def _advance(self) -> None:
        if self.x + 1 < self.columns:
            self.x += 1
        elif self.y < self.view_bottom:
            self.x, self.y = 0, self.y + 1
        else:
            self.x = self.columns - 1

    def _regress(self) -> None:
        if self.x > 0:
            self.x -= 1
        elif self.y > self.view_top:
            self.x, self.y = self.columns - 1, self.y - 1

    def _window_up(self) -> None:
        self.y = max(self.y - 1, self.view_top)

    def _window_down(self) -> None:
        self.y = min(self.y + 1, self.view_bottom)

    def scroll(self) -> None:
        """Move the rows that scroll up one; the last of them becomes blank."""
        del self.cells[self.view_top]
        self.cells.insert(self.view_bottom, [" "] * self.columns)
        del self.joined[self.view_top]
        self.joined.insert(self.view_bottom, False)
        if self.attrs is not None:
            del self.attrs[self.view_top]
            self.attrs.insert(self.view_bottom, [self.attr] * self.columns)

    def _follow(self) -> None:
        """Move the window just far enough to show the cursor's row."""
        if self.y < self.top:
            self.top = self.y
        elif self.y >= self.top + self.shown:
            self.top = self.y - self.shown + 1

    # ------------------------------------------------------------ where the cursor is
    def column(self) -> int:
        """The 0-based column the next character goes to (POS: a full row's waiting wrap
        puts it in the first column; GIOSCN.ASM POS)."""
        return 0 if self.x >= self.columns else self.x

    def row(self) -> int:
        """The 0-based row the next character goes to (CSRLIN: after a full row the next
        one, unless the wrap will scroll; GWSTS.ASM GTLINE)."""
        if self.x >= self.columns and self.y < self.view_bottom:
            return self.y + 1
        return self.y

    # ------------------------------------------------------------ reading it
    def char_at(self, x: int, y: int) -> str:
        """The character in column ``x`` of row ``y``."""
        return self.cells[y][x]

    def logical_line_from(self, x: int, y: int) -> str:
        """The characters from column ``x`` of row ``y`` to the end of its logical line: on
        through the rows its text wrapped into (INPUT.md, item 8)."""
        text = "".join(self.cells[y][x:])
        k = y + 1
        while k < self.rows and self.joined[k]:
            text += "".join(self.cells[k])
            k += 1
        return text

    def poke_cell(self, x: int, y: int, byte: int, attribute: bool) -> None:
        """Put code ``byte`` (0..255) in the cell of column ``x``, row ``y``, or with
        ``attribute`` make it the cell's colour attribute (a screen without colours keeps
        none): a POKE into the screen's memory, which places text as LOCATE does."""
        if attribute:
            if self.attrs is not None:
                self.attrs[y][x] = byte
        else:
            self.cells[y][x] = chr(byte)
        self.drawn = self.changed = True

    def attr_at(self, x: int, y: int) -> int:
        """The colour attribute of column ``x`` of row ``y`` (0..255; 7 without colours)."""
        return NORMAL if self.attrs is None else self.attrs[y][x]

    def lines(self) -> list[str]:
        """Every row of the virtual screen, trailing blanks dropped."""
        return ["".join(row).rstrip(" ") for row in self.cells]

    def shown_lines(self) -> list[str]:
        """The rows in the window (what the LCD shows), trailing blanks dropped."""
        return self.lines()[self.top:self.top + self.shown]

    def screen_text(self) -> str:
        """The shown rows as text, one line each (a transcript's picture of the display)."""
        return "".join(line + "\n" for line in self.shown_lines())


def boxed(lines: list[str], columns: int) -> str:
    """``lines`` drawn as an LCD in a frame ``columns`` wide (the interactive session's screen)."""
    edge = "\u2500" * columns
    rows = "".join(f"\u2502{line[:columns].ljust(columns)}\u2502\n" for line in lines)
    return f"\u250c{edge}\u2510\n{rows}\u2514{edge}\u2518\n"
