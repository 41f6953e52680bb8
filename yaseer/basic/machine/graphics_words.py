"""GW-BASIC's graphics statements and functions on the machine's Canvas
(machine/graphics.py): PSET, PRESET, LINE, VIEW, WINDOW, GET, PUT, PALETTE, POINT, PMAP.

The compiled code calls :meth:`GraphicsWords.check` first (the statements that refuse the
text mode), then :meth:`GraphicsWords.run` with the pieces source/graphics_syntax.py read,
evaluated, and the error the text is past them (raised before the statement acts when the
reading stopped inside it; after it acted when only text after a whole statement is bad:
GWMAIN.ASM NEWSTT finds it).

Numbers: coordinates through the WINDOW to integers (CINT's rounding; beyond -32768..32767
Overflow: the recorded PSET test), attributes GETBYT's (beyond an integer Overflow, outside
0..255 Illegal function call), then the mode's (an attribute above the mode's highest is
its highest, as PC-BASIC 2.0.8 draws).
"""

from __future__ import annotations

import math

from yaseer.basic.arithmetic.values import to_int, to_single
from yaseer.basic.errors import BasicError, OVERFLOW, TYPE_MISMATCH
from yaseer.basic.machine.figures import FigureWords
from yaseer.basic.machine.runtime import illegal_function_call


def _byte(value) -> int:
    """GETBYT: an integer (Overflow beyond), 0..255 (else Illegal function call)."""
    n = to_int(value)
    if not 0 <= n <= 255:
        raise illegal_function_call()
    return n


def _number(value):
    """A number argument; a string Type mismatch (functions take either, then check)."""
    if isinstance(value, str):
        raise BasicError("Type mismatch", TYPE_MISMATCH)
    return value


class GraphicsWords(FigureWords):
    """The graphics statements of one machine (its screen mode's Canvas); CIRCLE, PAINT
    and DRAW from :class:`FigureWords` (machine/figures.py)."""

    def __init__(self, machine):
        self.machine = machine
        self.palette = {}  # PALETTE attribute -> colour set by the program

    @property
    def canvas(self):
        """The Canvas of the screen mode (None in a text mode)."""
        return self.machine.screen_words.canvas

    def _canvas(self):
        canvas = self.canvas
        if canvas is None:
            raise illegal_function_call()
        return canvas

    def check(self, word: str) -> None:
        """A statement that needs a graphics mode, before it reads anything."""
        self._canvas()

    def run(self, word: str, parts: tuple, fault) -> None:
        """Statement ``word`` with its evaluated pieces; ``fault`` (message, code, after)."""
        if fault is not None and not fault[2:3] == (True,):
            checks = getattr(self, "_check_" + word.lower(), None)
            if checks is not None:  # the pieces read are checked before the text's error
                checks(*parts)
            raise BasicError(fault[0], fault[1])
        if word != "PALETTE":
            self._canvas()  # (LINE's text is read before the mode is asked for: GLINE, ATRSCN)
        getattr(self, "_" + word.lower())(*parts)
        if fault is not None:
            raise BasicError(fault[0], fault[1])

    # ------------------------------------------------------------ helpers
    def _attr(self, value, default: int) -> int:
        """An attribute argument (None: ``default``) within the mode's attributes."""
        canvas = self.canvas
        if value is None:
            return default
        return min(_byte(value), canvas.colours - 1)

    def _point(self, point) -> tuple[int, int]:
        """A (step, x, y) piece in view coordinates; it becomes the last point referenced."""
        canvas = self.canvas
        step, x, y = point
        physical = canvas.step(x, y) if step else canvas.to_physical(x, y)
        canvas.last_physical = physical
        canvas.draw_point = None
        return physical

    # ------------------------------------------------------------ statements
    def _pset(self, point, attr=None) -> None:
        """PSET (x, y)[, attribute]: the foreground by default."""
        x, y = self._point(point)
        canvas = self.canvas
        canvas.set_pixel(x, y, self._attr(attr, canvas.foreground))

    def _preset(self, point, attr=None) -> None:
        """PRESET (x, y)[, attribute]: the background (0) by default."""
        x, y = self._point(point)
        self.canvas.set_pixel(x, y, self._attr(attr, 0))

    def _line(self, first, second, attr=None, shape="", style=None) -> None:
        """LINE [(x1, y1)]-(x2, y2)[, [attribute][, [B|BF][, style]]]: from the last point
        when the first is left out; the second point's STEP counts from the first."""
        canvas = self.canvas
        if first == "":
            x0, y0 = canvas.last_physical
        else:
            x0, y0 = self._point(first)
        x1, y1 = self._point(second)
        colour = self._attr(attr, canvas.foreground)
        pattern = 0xFFFF if style is None else to_int(style) & 0xFFFF
        if shape == "BF":
            canvas.fill_box(x0, y0, x1, y1, colour)
        elif shape == "B":
            canvas.box(x0, y0, x1, y1, colour, pattern)
        else:
            canvas.line(x0, y0, x1, y1, colour, pattern)

    def _view(self, screen=None, first=None, second=None, fill=None, border=None) -> None:
        """VIEW [[SCREEN] (x1, y1)-(x2, y2)[, [fill][, [border]]]]: the clip rectangle, in
        the screen's pixels (ADVGRP.ASM VIEW): corners off the screen or a rectangle without
        width or height Illegal function call; filled and framed (the frame one pixel
        outside it) before it clips."""
        canvas = self.canvas
        if screen is None:
            canvas.unset_view()
            return
        (_, x1, y1), (_, x2, y2) = first, second
        x1, y1, x2, y2 = (to_int(v) for v in (x1, y1, x2, y2))
        fill = None if fill is None else _byte(fill)
        border = None if border is None else _byte(border)
        if not (0 <= x1 < canvas.width and 0 <= x2 < canvas.width and 0 <= y1 < canvas.height
                and 0 <= y2 < canvas.height) or x1 == x2 or y1 == y2:
            raise illegal_function_call()
        canvas.unset_view()
        if fill is not None:
            canvas.fill_box(x1, y1, x2, y2, min(fill, canvas.colours - 1))
        if border is not None:
            canvas.box(min(x1, x2) - 1, min(y1, y2) - 1, max(x1, x2) + 1, max(y1, y2) + 1,
                       min(border, canvas.colours - 1))
        canvas.set_view(x1, y1, x2, y2, screen == "SCREEN")

    def _window(self, screen=None, first=None, second=None) -> None:
        """WINDOW [[SCREEN] (x1, y1)-(x2, y2)]: logical coordinates over the view; corners
        of the same x or the same y Illegal function call."""
        canvas = self.canvas
        if screen is None:
            canvas.unset_window()
            return
        (_, x1, y1), (_, x2, y2) = first, second
        if x1 == x2 or y1 == y2:
            raise illegal_function_call()
        canvas.set_window(x1, y1, x2, y2, screen == "SCREEN")

    def _get(self, first, second, array) -> None:
        """GET (x1, y1)-(x2, y2), array: the rectangle's pixels into the array."""
        from yaseer.basic.machine.sprites import get_sprite

        get_sprite(self.machine, self.canvas, self._point(first), self._point(second), array)

    def _put(self, point, array, action="XOR") -> None:
        """PUT (x, y), array[, action]: a GET's pixels back at (x, y)."""
        from yaseer.basic.machine.sprites import put_sprite

        put_sprite(self.machine, self.canvas, self._point(point), array, action)

    def _palette(self, first=None, second=None, array=None) -> None:
        """PALETTE [attribute, colour] | PALETTE USING array(start): nothing shows, so only
        the numbers are checked: the attribute within the mode's, the colour's low byte
        within the mode's colours or 255 (-1: leave the attribute as it is).  (The recorded
        PALETTE test: ``PALETTE 0, 254`` is Illegal function call, 255 and 256 are not.)"""
        mode = self.machine.screen_words.mode
        attrs = 16 if mode is None or not mode.bits else 1 << mode.bits
        colours = 64 if mode is None or mode.number in (0, 9) else 16
        if first is None:
            self.palette.clear()
            return
        if first == "USING":
            from yaseer.basic.machine.sprites import array_values

            pairs = list(enumerate(array_values(self.machine, second, attrs)))
        else:
            attr = to_int(first)
            if not 0 <= attr < attrs:
                raise illegal_function_call()
            pairs = [(attr, to_int(second))]
        for attr, colour in pairs:
            low = colour & 0xFF
            if low != 0xFF and low >= colours:
                raise illegal_function_call()
        for attr, colour in pairs:
            if colour & 0xFF != 0xFF:
                self.palette[attr] = colour & 0xFF

    # ------------------------------------------------------------ functions
    def point(self, a, b=None) -> float:
        """POINT(n): the last point referenced (0, 1: physical x, y; 2, 3: logical; 0 in a
        text mode); POINT(x, y): the attribute there, -1 off the screen."""
        canvas = self.canvas
        if b is None:
            n = to_int(_number(a))
            if not 0 <= n <= 3:
                raise illegal_function_call()
            if canvas is None:
                return 0.0
            px, py = canvas.draw_point or canvas.last_physical
            if n < 2:
                return float((px, py)[n])
            return float(canvas.to_logical(px, py)[n - 2])
        if canvas is None:
            raise illegal_function_call()
        x, y = canvas.to_physical(_number(a), _number(b))
        return float(canvas.point(x, y))

    def point_argument(self, value) -> tuple:
        """POINT's first argument as a bad call's reading takes it (argument_reading.py
        ``_point``): with whether the screen is in a graphics mode."""
        return value, self.canvas is not None

    def pmap(self, value, n) -> float:
        """PMAP(value, n): 0, 1 a logical x, y in view pixels; 2, 3 a view pixel's logical
        x, y (the value made an integer first); 0 in a text mode."""
        if math.isinf(to_single(value)):  # the value is made a single first
            raise BasicError("Overflow", OVERFLOW)
        n = to_int(n)
        if not 0 <= n <= 3:
            raise illegal_function_call()
        if n >= 2:
            value = to_int(value)
        canvas = self.canvas
        if canvas is None:
            return 0.0
        if n == 0:
            return float(canvas.to_physical(value, 0)[0])
        if n == 1:
            return float(canvas.to_physical(0, value)[1])
        if n == 2:
            return float(canvas.to_logical(value, 0)[0])
        return float(canvas.to_logical(0, value)[1])
