"""The machine's display: a grid of character cells with a cursor, one model for every dialect.

A :class:`Display` is ``columns`` x ``rows`` cells (the *virtual screen*), of which
``shown`` rows are visible at a time: a window that follows the cursor.  The
geometry is the dialect's (``Dialect.display``):

* casio: 32 columns x 8 rows, 2 of them shown - the FX-850P/880P's 32-column,
  2-line LCD over its 32 x 8 virtual screen (owner's manual, part 6 "Virtual
  screen function"; LOCATE's page: 0 <= x <= 31, 0 <= y <= 7 in its picture);
* gw: 80 x 25 with all 25 rows shown (GW-BASIC's text screen), for the text-screen
  statements LOCATE, CLS, CSRLIN, POS and SCREEN(row, col).

Writing text puts each character at the cursor and moves it right; past the last
column the cursor goes to the start of the next row, and below the last row the
whole virtual screen scrolls up one row, the new bottom row blank (PRINT's page:
"A line feed results when the cursor reaches the last column on the last line of
the screen ..., scrolling the entire screen upwards").  Control codes (below 32)
do what the dialect's ``controls`` table says (casio: ``dialects.charset.CASIO_CONTROLS``,
the character code table's parenthesised codes); a code with no action there is not
shown.  The window moves only as far as needed to keep the cursor's row visible.

A display is *drawn* once a program placed text itself (LOCATE, CLS, a cursor
control code): from then on a transcript shows its screens (:meth:`shown_lines`)
instead of the streamed text.  Columns and rows are 0-based.
"""

from __future__ import annotations

import re

# Codes that place text where the program chooses: once one is written the display is "drawn".
_CONTROL = re.compile("[\x00-\x1f]")
DRAWING_ACTIONS = frozenset(("line_top", "line_cancel", "line_end", "backspace", "home", "clear",
                             "right", "left", "up", "down"))


class Display:
    """``columns`` x ``rows`` character cells, ``shown`` rows visible (see module docstring)."""

    __slots__ = ("columns", "rows", "shown", "controls", "cells", "x", "y", "top", "drawn", "changed",
                 "view_top", "view_bottom")

    def __init__(self, columns: int, rows: int, shown: int | None = None, controls: dict | None = None):
        self.columns = columns
        self.rows = rows
        self.shown = rows if shown is None else shown
        self.controls = controls if controls is not None else {}
        self.cells = [[" "] * columns for _ in range(rows)]
        self.x = 0
        self.y = 0
        self.top = 0  # the first row shown
        self.view_top, self.view_bottom = 0, rows - 1  # the rows that scroll (gw's VIEW PRINT)
        self.drawn = False
        self.changed = False  # anything written, located or cleared since the last screen shown

    # ------------------------------------------------------------ the cursor
    def locate(self, x: int, y: int) -> None:
        """Put the cursor at column ``x`` of row ``y`` (the caller checked the ranges)."""
        self.x, self.y = x, y
        self.drawn = self.changed = True
        self._follow()

    def clear(self) -> None:
        """Blank the rows that scroll (every row unless a view is set); the cursor goes to
        their first row and the window home (CLS, ``CHR$(12)``)."""
        for row in self.cells[self.view_top:self.view_bottom + 1]:
            row[:] = [" "] * self.columns
        self.x, self.y, self.top = 0, self.view_top, 0
        self._follow()
        self.drawn = self.changed = True

    def set_view(self, first: int, last: int) -> None:
        """Only rows ``first``..``last`` scroll (and CLS clears them); the cursor goes to
        ``first`` (the caller checked the rows).  ``set_view(0, rows - 1)`` is the whole screen."""
        self.view_top, self.view_bottom = first, last
        self.x, self.y = 0, first
        self._follow()

    def new_line(self) -> None:
        """The cursor to the start of the next row, scrolling at the bottom."""
        self.x = 0
        self._down()

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
                getattr(self, "_" + action)()
                if action in DRAWING_ACTIONS:
                    self.drawn = True
            start = match.end()
        if start < len(text):
            self._put(text[start:])
        self._follow()

    def _put(self, run: str) -> None:
        """Characters without control codes, row by row (a full row wraps at once)."""
        columns = self.columns
        while run:
            room = columns - self.x
            piece = run[:room]
            self.cells[self.y][self.x:self.x + len(piece)] = piece
            self.x += len(piece)
            run = run[room:]
            if self.x >= columns:
                self.new_line()

    def _carriage_return(self) -> None:
        self.new_line()

    def _line_feed(self) -> None:
        self._down()

    def _home(self) -> None:
        self.x = self.y = 0

    def _clear(self) -> None:
        self.clear()

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
        if self.y != self.view_bottom and self.y < self.rows - 1:
            self.y += 1
        else:
            self.scroll()

    def scroll(self) -> None:
        """Move the rows that scroll up one; the last of them becomes blank."""
        del self.cells[self.view_top]
        self.cells.insert(self.view_bottom, [" "] * self.columns)

    def _follow(self) -> None:
        """Move the window just far enough to show the cursor's row."""
        if self.y < self.top:
            self.top = self.y
        elif self.y >= self.top + self.shown:
            self.top = self.y - self.shown + 1

    # ------------------------------------------------------------ reading it
    def char_at(self, x: int, y: int) -> str:
        """The character in column ``x`` of row ``y``."""
        return self.cells[y][x]

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
