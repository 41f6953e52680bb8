"""GW-BASIC's graphics screen: the pixels of a graphics mode (SCREEN 1, 2, 7, 8, 9) kept
in memory, with the view (VIEW), the logical window (WINDOW) and the last point referenced.

Nothing is displayed: a program sees its pixels through POINT, PMAP, GET arrays, BSAVE
files and PEEK.  Coordinates come in three kinds:

* *logical*: what a program writes, ``(x, y)`` in its WINDOW's units (without a WINDOW the
  same numbers as the view coordinates);
* *view* coordinates (what :meth:`Canvas.to_physical` returns, what GW keeps in its
  graphics cursor GRPACX/GRPACY, GENGRP.ASM SCANN): integer pixels counted from the view's
  top left corner (from the screen's after VIEW SCREEN, or with no VIEW);
* *screen* pixels: from the screen's top left corner, ``0 <= x < width``.

:meth:`Canvas.set_pixel` and :meth:`Canvas.get_pixel` take view coordinates and stay inside
the view (the clip rectangle :attr:`Canvas.view`, in screen pixels).  Attributes are small
integers 0 .. ``colours - 1`` (4, 2 or 16).
"""

from __future__ import annotations

from yaseer.basic.arithmetic.values import nearest_integer

INT_MIN, INT_MAX = -32768, 32767


class Canvas:
    """The pixels of a graphics mode: ``pages`` pages of ``width`` x ``height`` attributes,
    one of them active (drawn on), with the view, the window and the graphics cursor.

    ``aspect`` is the pixel aspect CIRCLE uses by default: the height a pixel shows over its
    width, on a screen of 4:3 (4/3 * height / width: 5/6 in 320x200, 5/12 in 640x200,
    35/48 in 640x350; PC-BASIC 2.0.8 computes it so)."""

    def __init__(self, width: int, height: int, colours: int, pages: int = 1, bits: int = 1,
                 foreground: int | None = None):
        self.width = width
        self.height = height
        self.colours = colours
        self.bits = bits  # bits a pixel takes in the mode's memory (GET arrays, BSAVE)
        self.pages = [bytearray(width * height) for _ in range(max(1, pages))]
        self.active = 0
        self.shown = 0
        self.pixels = self.pages[0]
        self.aspect = 4.0 * height / (3.0 * width)
        self.foreground = colours - 1 if foreground is None else foreground
        self.view = (0, 0, width - 1, height - 1)
        self.view_set = False  # a VIEW is in force
        self.view_absolute = False  # VIEW SCREEN: view coordinates are screen pixels
        self.window = None  # (scale x, scale y, offset x, offset y) of a WINDOW
        self.window_bounds = None  # the WINDOW's corners as given, ordered, and its kind
        self.last_physical = self.middle()
        # DRAW's pen (view coordinates) while only DRAW has moved it since another statement
        # referenced a point: DRAW starts from it (else from last_physical) and leaves it where
        # it ends, moving last_physical too only without a WINDOW; every other statement that
        # references a point sets it to None; POINT(n) reports it while it is set (the
        # recorded graphics_position test)
        self.draw_point = None

    # ------------------------------------------------------------------ pages
    def set_pages(self, active: int, shown: int) -> None:
        """SCREEN's active and shown pages (numbers the mode has)."""
        self.active, self.shown = active, shown
        self.pixels = self.pages[active]

    def copy_page(self, source: int, target: int) -> None:
        """PCOPY source, target: the target page becomes the source's copy."""
        self.pages[target][:] = self.pages[source]

    def clear(self) -> None:
        """CLS in a graphics mode: the view (the whole screen without VIEW) set to 0, the
        graphics cursor back to the view's middle."""
        x1, y1, x2, y2 = self.view
        width, pixels = self.width, self.pixels
        blank = bytes(x2 - x1 + 1)
        for y in range(y1, y2 + 1):
            pixels[y * width + x1:y * width + x2 + 1] = blank
        self.last_physical = self.middle()
        self.draw_point = None

    def clear_all(self) -> None:
        """CLS 0 (or CLS without a view of either kind): the whole page blank, the graphics
        cursor back to the view's middle."""
        self.pixels[:] = bytes(len(self.pixels))
        self.last_physical = self.middle()
        self.draw_point = None

    # ----------------------------------------------------------------- pixels
    def _screen_xy(self, x: int, y: int) -> tuple[int, int]:
        """View coordinates to screen pixels."""
        if self.view_absolute:
            return x, y
        return x + self.view[0], y + self.view[1]

    def inside_view(self, x: int, y: int) -> bool:
        """True when view point (x, y) is inside the view (its edges included)."""
        sx, sy = self._screen_xy(x, y)
        x1, y1, x2, y2 = self.view
        return x1 <= sx <= x2 and y1 <= sy <= y2

    def set_pixel(self, x: int, y: int, attr: int) -> None:
        """Pixel (x, y) in view coordinates set to ``attr`` (already within the mode's
        attributes); nothing outside the view."""
        sx, sy = self._screen_xy(x, y)
        x1, y1, x2, y2 = self.view
        if x1 <= sx <= x2 and y1 <= sy <= y2:
            self.pixels[sy * self.width + sx] = attr

    def get_pixel(self, x: int, y: int) -> int:
        """The attribute of view point (x, y); -1 outside the view."""
        sx, sy = self._screen_xy(x, y)
        x1, y1, x2, y2 = self.view
        if x1 <= sx <= x2 and y1 <= sy <= y2:
            return self.pixels[sy * self.width + sx]
        return -1

    def point(self, x: int, y: int) -> int:
        """POINT(x, y) of view point (x, y): its attribute, read outside the view as well,
        -1 off the screen (as PC-BASIC 2.0.8)."""
        sx, sy = self._screen_xy(x, y)
        if 0 <= sx < self.width and 0 <= sy < self.height:
            return self.pixels[sy * self.width + sx]
        return -1

    def screen_pixel(self, sx: int, sy: int) -> int:
        """The attribute at screen pixel (sx, sy) of the active page."""
        return self.pixels[sy * self.width + sx]

    # ------------------------------------------------------------ coordinates
    @property
    def last(self) -> tuple[float, float]:
        """The last point referenced, in logical coordinates."""
        return self.to_logical(*self.last_physical)

    @last.setter
    def last(self, point: tuple[float, float]) -> None:
        self.last_physical = self.to_physical(*point)
        self.draw_point = None

    def view_size(self) -> tuple[int, int]:
        """The view's width and height in pixels."""
        x1, y1, x2, y2 = self.view
        return x2 - x1 + 1, y2 - y1 + 1

    def middle(self) -> tuple[int, int]:
        """Where the graphics cursor starts after SCREEN, VIEW, CLS: the view's middle in
        view coordinates (half its width and height, rounded up as PC-BASIC 2.0.8 has it)."""
        x1, y1, x2, y2 = self.view
        x, y = (x2 - x1) // 2 + 1, (y2 - y1) // 2 + 1
        if self.view_absolute:
            return x1 + x, y1 + y
        return x, y

    def to_physical(self, x: float, y: float) -> tuple[int, int]:
        """Logical (x, y) to view coordinates (PMAP 0 and 1); Overflow beyond an integer."""
        if self.window is not None:
            sx, sy, ox, oy = self.window
            x, y = ox + x * sx, oy + y * sy
        return _to_integer(x), _to_integer(y)

    def to_logical(self, px: float, py: float) -> tuple[float, float]:
        """View coordinates to logical (PMAP 2 and 3)."""
        if self.window is None:
            return float(px), float(py)
        sx, sy, ox, oy = self.window
        return (px - ox) / sx, (py - oy) / sy

    def scale(self, dx: float, dy: float) -> tuple[int, int]:
        """Logical lengths dx, dy in pixels (a WINDOW's scale; CIRCLE's radius)."""
        if self.window is not None:
            dx, dy = dx * self.window[0], dy * self.window[1]
        return _to_integer(dx), _to_integer(dy)

    def step(self, x: float, y: float) -> tuple[int, int]:
        """STEP (x, y): the point x, y logical units from the last point referenced."""
        if self.window is None:
            lx, ly = self.last_physical
            return _to_integer(lx + x), _to_integer(ly + y)
        lx, ly = self.to_logical(*self.last_physical)
        return self.to_physical(lx + x, ly + y)

    def set_view(self, x1: int, y1: int, x2: int, y2: int, absolute: bool) -> None:
        """VIEW [SCREEN] (x1, y1)-(x2, y2): the clip rectangle (ordered), in screen pixels."""
        self.view = (min(x1, x2), min(y1, y2), max(x1, x2), max(y1, y2))
        self.view_set, self.view_absolute = True, absolute
        self._view_changed()

    def unset_view(self) -> None:
        """VIEW alone: the whole screen."""
        self.view = (0, 0, self.width - 1, self.height - 1)
        self.view_set = self.view_absolute = False
        self._view_changed()

    def _view_changed(self) -> None:
        self.last_physical = self.middle()
        self.draw_point = None
        if self.window_bounds is not None:
            self.set_window(*self.window_bounds)

    def set_window(self, x1: float, y1: float, x2: float, y2: float, screen: bool = False) -> None:
        """WINDOW [SCREEN] (x1, y1)-(x2, y2) over the view: the smaller x at the left; the
        smaller y at the bottom (at the top with SCREEN)."""
        x1, x2 = min(x1, x2), max(x1, x2)
        y1, y2 = min(y1, y2), max(y1, y2)
        self.window_bounds = (x1, y1, x2, y2, screen)
        if not screen:
            y1, y2 = y2, y1
        width, height = self.view_size()
        scale_x = (width - 1) / (x2 - x1)
        scale_y = (height - 1) / (y2 - y1)
        self.window = (scale_x, scale_y, -x1 * scale_x, -y1 * scale_y)

    def unset_window(self) -> None:
        """WINDOW alone: logical coordinates are view coordinates again."""
        self.window = self.window_bounds = None

    # ---------------------------------------------------------------- drawing
    def clip_end(self, x: int, y: int) -> tuple[int, int]:
        """A line's end pulled to at most one pixel off the screen (so a far point costs
        no time; PC-BASIC 2.0.8 cuts them so)."""
        sx, sy = self._screen_xy(x, y)
        cx = min(self.width, max(-1, sx))
        cy = min(self.height, max(-1, sy))
        return x + cx - sx, y + cy - sy

    def line(self, x0: int, y0: int, x1: int, y1: int, attr: int, pattern: int = 0xFFFF) -> None:
        """A straight line between view points, Bresenham's, drawn from the upper end
        (the lower x first on a level line's right end, as the style's bits run), the
        style's bits from the highest, one a pixel."""
        x0, y0 = self.clip_end(x0, y0)
        x1, y1 = self.clip_end(x1, y1)
        if y1 <= y0:
            x0, y0, x1, y1 = x1, y1, x0, y0
        dx, dy = abs(x1 - x0), abs(y1 - y0)
        steep = dy > dx
        if steep:
            x0, y0, x1, y1 = y0, x0, y1, x1
            dx, dy = dy, dx
        sx = 1 if x1 > x0 else -1
        sy = 1 if y1 > y0 else -1
        mask = 0x8000
        error = dx // 2
        y = y0
        plot = self.set_pixel
        for x in range(x0, x1 + sx, sx):
            if pattern & mask:
                if steep:
                    plot(y, x, attr)
                else:
                    plot(x, y, attr)
            mask = (mask >> 1) or 0x8000
            error -= dy
            if error < 0:
                y += sy
                error += dx

    def box(self, x0: int, y0: int, x1: int, y1: int, attr: int, pattern: int = 0xFFFF) -> None:
        """LINE ... ,B: the rectangle's edges, the style running on across them (bottom,
        top right to left, then the sides downward)."""
        x0, y0 = self.clip_end(x0, y0)
        x1, y1 = self.clip_end(x1, y1)
        mask = self._straight(x1, y1, x0, y1, attr, pattern, 0x8000)
        mask = self._straight(x1, y0, x0, y0, attr, pattern, mask)
        top, bottom = min(y0, y1), max(y0, y1)  # the sides drawn downward
        mask = self._straight(x1, top, x1, bottom, attr, pattern, mask)
        self._straight(x0, top, x0, bottom, attr, pattern, mask)

    def _straight(self, x0, y0, x1, y1, attr, pattern, mask) -> int:
        plot = self.set_pixel
        if x0 == x1:
            step = 1 if y1 > y0 else -1
            for y in range(y0, y1 + step, step):
                if pattern & mask:
                    plot(x0, y, attr)
                mask = (mask >> 1) or 0x8000
        else:
            step = 1 if x1 > x0 else -1
            for x in range(x0, x1 + step, step):
                if pattern & mask:
                    plot(x, y0, attr)
                mask = (mask >> 1) or 0x8000
        return mask

    def fill_box(self, x0: int, y0: int, x1: int, y1: int, attr: int) -> None:
        """LINE ... ,BF: the rectangle filled, clipped to the view."""
        ax, ay = self._screen_xy(x0, y0)
        bx, by = self._screen_xy(x1, y1)
        vx1, vy1, vx2, vy2 = self.view
        left, right = max(min(ax, bx), vx1), min(max(ax, bx), vx2)
        top, bottom = max(min(ay, by), vy1), min(max(ay, by), vy2)
        if left > right:
            return
        run = bytes([attr]) * (right - left + 1)
        width, pixels = self.width, self.pixels
        for y in range(top, bottom + 1):
            pixels[y * width + left:y * width + right + 1] = run


def _to_integer(value: float) -> int:
    """A coordinate as GW's integer (rounded half away from zero); Overflow beyond
    -32768..32767."""
    result = value if type(value) is int else nearest_integer(value)
    if not INT_MIN <= result <= INT_MAX:
        from yaseer.basic.errors import BasicError, OVERFLOW
        raise BasicError("Overflow", OVERFLOW)
    return result


def canvas_for(mode, pages: int) -> Canvas:
    """A blank Canvas for screen mode ``mode`` (dialects/screens.py ScreenMode: its pixels
    and bits a pixel) with ``pages`` pages; its foreground the mode's text attribute."""
    colours = 1 << mode.bits
    return Canvas(mode.width, mode.height, colours, pages, mode.bits, mode.attribute % colours)
