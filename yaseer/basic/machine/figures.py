"""GW-BASIC's CIRCLE, PAINT and DRAW statements: their arguments checked as GW-BASIC 3.23
checks them (the recorded CIRCLE, PAINT and DRAW2 tests), then drawn by machine/circle.py,
machine/paint.py and machine/draw_macro.py on the screen mode's Canvas.

:class:`FigureWords` is a part of machine/graphics_words.py's GraphicsWords (which gives it
``canvas``, ``_point`` and ``_attr``); source/graphics_syntax.py reads the statements and
compile/graphics_statements.py calls ``_circle``, ``_paint`` and ``_draw`` with their pieces.
"""

from __future__ import annotations

from yaseer.basic.arithmetic.values import to_int
from yaseer.basic.errors import BasicError, TYPE_MISMATCH
from yaseer.basic.machine.runtime import byte_argument, illegal_function_call


def _byte(value) -> int:
    """GETBYT: an integer (Overflow beyond), 0..255 (else Illegal function call)."""
    return byte_argument(to_int(value))


def _radius(canvas, radius) -> int:
    """CIRCLE's radius in pixels: an integer (GETIN2: Overflow beyond), not negative (else
    Illegal function call: the recorded CIRCLE test); under a WINDOW in its x units, as
    PC-BASIC 2.0.8 scales it (the published source reads pixels)."""
    if canvas.window is None:
        r = to_int(radius)
    elif radius < 0:
        r = -1
    else:
        r = abs(canvas.scale(radius, 0)[0])
    if r < 0:
        raise illegal_function_call()
    return r


class FigureWords:
    """CIRCLE, PAINT and DRAW of one machine's graphics."""

    def _circle(self, point, radius, attr=None, start=None, end=None, aspect=None) -> None:
        """CIRCLE [STEP] (x, y), radius[, attribute[, start, end[, aspect]]]: the centre
        becomes the last point; a negative radius or attribute outside 0..255 Illegal
        function call (the recorded CIRCLE test); without an aspect the mode's pixels'."""
        from yaseer.basic.machine import circle

        cx, cy = self._point(point)
        canvas = self.canvas
        r = _radius(canvas, radius)
        colour = canvas.foreground if attr is None else min(_byte(attr), canvas.colours - 1)
        fraction, scales_x = circle.aspect_fraction(canvas.aspect if aspect is None else aspect)
        circle.circle(canvas, cx, cy, r, colour, start, end, fraction, scales_x)
        canvas.last_physical = (cx, cy)

    def _check_paint(self, point=None, paint=None, border=None, background=None) -> None:
        """PAINT's pieces checked as they are read, before the error of the text after them
        (``PAINT (1,1), 32768,`` is Overflow: the recorded PAINT test)."""
        if point is None:
            return
        self.canvas.to_physical(*point[1:])
        if paint is not None and not isinstance(paint, str):
            _byte(paint)
        if border is not None:
            _byte(border)

    def _check_circle(self, point=None, radius=None, attr=None, *angles) -> None:
        """CIRCLE's pieces checked as they are read (GETIN2, ATRSCN), before the text's error."""
        if point is None:
            return
        self.canvas.to_physical(*point[1:])
        if radius is not None:
            _radius(self.canvas, radius)
        if attr is not None:
            _byte(attr)

    def _paint(self, point, paint=None, border=None, background=None) -> None:
        """PAINT [STEP] (x, y)[, paint[, border[, background]]]: paint an attribute or a
        tile string ("" Illegal function call); the border by default the paint's
        attribute, or the foreground under a tile; the background a string."""
        from yaseer.basic.machine.paint import paint as flood

        x, y = self._point(point)
        canvas = self.canvas
        top = canvas.colours - 1
        pattern = None
        if isinstance(paint, str):
            if not paint:
                raise illegal_function_call()
            pattern = paint.encode("latin-1")
            colour = canvas.foreground
        else:
            colour = canvas.foreground if paint is None else min(_byte(paint), top)
        edge = (colour if pattern is None else canvas.foreground) if border is None else min(_byte(border), top)
        back = None
        if background is not None:
            if not isinstance(background, str):
                raise illegal_function_call()
            back = background.encode("latin-1")
        flood(canvas, x, y, colour, edge, pattern, back)
        canvas.last_physical = (x, y)

    def _draw(self, text) -> None:
        """DRAW string: a number Type mismatch."""
        from yaseer.basic.machine.draw_macro import draw
        from yaseer.basic.machine.paint import paint as flood

        if not isinstance(text, str):
            raise BasicError("Type mismatch", TYPE_MISMATCH)
        canvas = self.canvas
        state = getattr(canvas, "draw_state", None)
        if state is None:  # DRAW's scale, angle and colour start anew with each screen mode
            from yaseer.basic.machine.draw_macro import DrawState

            state = canvas.draw_state = DrawState()
        draw(self.machine, canvas, state, text,
             lambda x, y, fill, border: flood(canvas, x, y, fill, border))
