"""DRAW's Graphics Macro Language on a graphics canvas (machine/graphics.py's Canvas), read
by the macro reader PLAY uses (machine/mml.py :class:`Macro`: MACLNG, VALSC3, SCNVAR, X).

The commands (ADVGRP.ASM DRAW, its table DRWTAB; TA and P, which the published source
lacks, as GW-BASIC 3.23 reads them in the recorded DRAW2 test and as PC-BASIC 2.0.8 draws):

* ``U D L R E F G H`` n: a line n steps up, down, left, right or diagonally (n left out: 1),
  each step the scale S over 4 pixels (DSCLDE: truncated toward 0);
* ``M x,y``: a line to view point (x, y); ``M+x,y`` / ``M-x,y``: by (x, y) steps;
* ``B`` the next move draws nothing; ``N`` the next move comes back where it started;
* ``A n`` (0..3) turns the moves by n right angles counterclockwise (an odd one scales the
  turned lengths by the pixel aspect, as DOMOVR's GTASPC does); ``TA n`` (-360..360) by n
  degrees;
* ``C n`` the attribute of the lines; ``S n`` (0..255; 0 as 4) the scale;
* ``P paint, border`` fills from the current point (as PAINT does with attributes);
* ``X`` a string variable's commands.

Numbers are MACLNG's: digits, ``=variable;`` or a VARPTR$ string; 16 bits.
"""

from __future__ import annotations

import math

from yaseer.basic.arithmetic.values import nearest_integer
from yaseer.basic.machine.mml import Macro
from yaseer.basic.machine.runtime import illegal_function_call, signed_word

PAINT_LARGEST = 9999  # P's attributes: 10000 is Illegal function call (the recorded DRAW2 test)
TURN_LARGEST = 360  # TA's degrees either way (DRAW2: TA400 Illegal function call)
# the eight moves: letter -> (x, y) of one step
STEPS = {"U": (0, -1), "D": (0, 1), "L": (-1, 0), "R": (1, 0),
         "E": (1, -1), "F": (1, 1), "G": (-1, 1), "H": (-1, -1)}


class DrawState:
    """What DRAW keeps between statements: the scale, the angle (right angles, or degrees
    after TA) and the attribute of its lines (None: the canvas's foreground)."""

    def __init__(self):
        self.scale = 0  # DRWSCL: 0 draws each step one pixel, as S4
        self.angle = 0  # A's right angles 0..3
        self.degrees = None  # TA's degrees (None: A's angle)
        self.attr = None


class Drawer(Macro):
    """One DRAW statement's string drawn on ``canvas`` with ``state`` (:class:`DrawState`);
    ``paint(x, y, fill, border)`` fills for P."""

    def __init__(self, machine, canvas, state: DrawState, text: str, paint=None):
        super().__init__(machine, text)
        self.canvas = canvas
        self.state = state
        self.paint = paint
        self.plot = True  # B not given
        self.stay = False  # N not given
        # the pen: where the last DRAW left it while no other statement has referenced a
        # point since (Canvas.draw_point), else the last point referenced
        self.pen = getattr(canvas, "draw_point", None) or canvas.last_physical

    def run(self) -> None:
        """The commands, then the pen left on the canvas: the last point referenced too
        without a WINDOW (under one, STEP and PSET go on from their own point: the recorded
        graphics_position test)."""
        try:
            super().run()
        finally:
            canvas = self.canvas
            canvas.draw_point = self.pen
            if canvas.window is None:
                canvas.last_physical = self.pen

    def number(self, needed: bool = True) -> int | None:
        """A command's number as MISCMD reads it (None left out); left out where one is
        needed Illegal function call."""
        given, n = self.argument()
        if not given:
            if needed:
                raise illegal_function_call()
            return None
        return n

    def command(self, c: str) -> None:
        """One command (DRWTAB; another letter Illegal function call)."""
        state = self.state
        if c in STEPS:
            n = self.number(needed=False)
            n = 1 if n is None else signed_word(n)
            sx, sy = STEPS[c]
            self.move_by(sx * n, sy * n)
        elif c == "M":
            self.move()
        elif c == "B":
            self.plot = False
        elif c == "N":
            self.stay = True
        elif c == "X":
            self.execute()
        elif c == "A":
            n = self.number() & 0xFF
            if n >= 4:
                raise illegal_function_call()
            state.angle, state.degrees = n, None
        elif c == "T":
            if self.reader.fetch_needed() != "A":
                raise illegal_function_call()
            n = signed_word(self.number())
            if not -TURN_LARGEST <= n <= TURN_LARGEST:
                raise illegal_function_call()
            state.degrees = n
        elif c == "C":
            state.attr = min(self.number() & 0xFF, self.canvas.colours - 1)
        elif c == "S":
            n = self.number()
            if n > 0xFF:
                raise illegal_function_call()
            state.scale = n
        elif c == "P":
            self.fill()
        else:
            raise illegal_function_call()

    def move(self) -> None:
        """DMOVE: ``M`` then x ``,`` y; a sign before x makes the move relative."""
        reader = self.reader
        c = reader.fetch_needed()
        relative = c in "+-"
        x = signed_word(self.value(c))
        if reader.fetch_needed() != ",":
            raise illegal_function_call()
        y = signed_word(self.value(reader.fetch_needed()))
        if relative:
            self.move_by(x, y)
        else:
            self.go(x, y)

    def scaled(self, n: int) -> int:
        """DSCLDE: ``n`` steps in pixels, the scale over 4, truncated toward 0 (16 bits)."""
        scale = self.state.scale
        if not scale:
            return n
        return int(signed_word(n * scale) / 4)

    def move_by(self, dx: int, dy: int) -> None:
        """DOMOVR: a move of (dx, dy) steps, scaled and turned.  The pixel aspect is the
        mode's as a fraction of 256 (GTASPC; 213 in SCREEN 1) and its inverse as 8.8 bits;
        TA turns through the same fraction, rounding half away from 0 (the recorded
        DRAW_angle drawing matches this to its lines' own pixels)."""
        dx, dy = self.scaled(dx), self.scaled(dy)
        state = self.state
        fraction = max(1, nearest_integer(self.canvas.aspect * 256))
        if state.degrees is not None:
            phi = math.radians(state.degrees)
            c, s = math.cos(phi), math.sin(phi)
            dx, dy = nearest_integer(c * dx + s * dy * 256 / fraction), nearest_integer(c * dy - s * dx * fraction / 256)
        else:
            if state.angle & 1:  # a right angle: x and y swap, each through the aspect
                inverse = nearest_integer(65536 / fraction)
                dx, dy = dy * (inverse >> 8) + _scaled(dy, inverse & 0xFF), -_scaled(dx, fraction & 0xFF)
            if state.angle & 2:
                dx, dy = -dx, -dy
        x, y = self.pen
        self.go(x + dx, y + dy)

    def go(self, x: int, y: int) -> None:
        """DRWABS: a line from the current point to (x, y) unless B; the current point
        moves there unless N; B and N then cleared."""
        canvas = self.canvas
        x0, y0 = self.pen
        if self.plot:
            attr = canvas.foreground if self.state.attr is None else self.state.attr
            canvas.line(x, y, x0, y0, attr)
        if not self.stay:
            self.pen = (x, y)
        self.plot, self.stay = True, False

    def fill(self) -> None:
        """P paint, border: a solid fill from the current point."""
        paint = self.number()
        if self.reader.fetch_needed() != ",":
            raise illegal_function_call()
        border = self.number()
        if paint > PAINT_LARGEST or border > PAINT_LARGEST:
            raise illegal_function_call()
        top = self.canvas.colours - 1
        x, y = self.pen
        self.paint(x, y, min(paint, top), min(border, top))


def _scaled(value: int, fraction: int) -> int:
    """GOSCAL: ``value`` times ``fraction``/256, its magnitude rounded (SCALE), its sign kept."""
    if value < 0:
        return -_scaled(-value, fraction)
    return (value * fraction + 128) >> 8


def draw(machine, canvas, state: DrawState, text: str, paint=None) -> None:
    """DRAW text (MACLNG with DRWTAB)."""
    Drawer(machine, canvas, state, text, paint).run()
