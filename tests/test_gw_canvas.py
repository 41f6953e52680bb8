"""The graphics Canvas (yaseer/basic/machine/graphics.py) on its own: pixels, the view, the
window mapping and the line drawing.  References: the pixels PC-BASIC 2.0.8 sets for the
same statements (worked out by hand here from its published behaviour: Bresenham from the
upper end, the view's middle as the start point) and WINDOW's mapping of its corners onto
the view's edges (GW-BASIC 3.23's manual: the corners map onto the view's corners)."""

from __future__ import annotations

import pytest

from yaseer.basic.dialects.screens import GW_MODES
from yaseer.basic.errors import BasicError
from yaseer.basic.machine.graphics import Canvas, canvas_for


def _mode(number):
    return next(m for m in GW_MODES if m.number == number)


def _lit(canvas):
    return {(x, y) for y in range(canvas.height) for x in range(canvas.width)
            if canvas.screen_pixel(x, y)}


def test_modes_geometry():
    for number, size, colours in ((1, (320, 200), 4), (2, (640, 200), 2), (7, (320, 200), 16),
                                  (8, (640, 200), 16), (9, (640, 350), 16)):
        c = canvas_for(_mode(number), 1)
        assert (c.width, c.height, c.colours) == size + (colours,)
    assert canvas_for(_mode(1), 1).foreground == 3
    assert canvas_for(_mode(2), 1).foreground == 1
    assert canvas_for(_mode(7), 1).foreground == 15
    assert canvas_for(_mode(1), 1).aspect == pytest.approx(5 / 6)


def test_pixels_and_view_clipping():
    c = Canvas(320, 200, 4)
    c.set_pixel(10, 20, 3)
    assert c.get_pixel(10, 20) == 3 and c.get_pixel(11, 20) == 0
    assert c.get_pixel(-1, 0) == -1 and c.get_pixel(320, 0) == -1
    c.set_pixel(400, 5, 1)  # off the screen: nothing
    c.set_view(100, 50, 199, 149, absolute=False)
    c.set_pixel(0, 0, 2)  # the view's corner
    assert c.screen_pixel(100, 50) == 2
    c.set_pixel(100, 0, 2)  # beyond the view's right edge: clipped
    assert c.screen_pixel(200, 50) == 0
    assert c.get_pixel(100, 0) == -1
    assert c.point(-90, -30) == 3  # POINT reads outside the view: screen (10, 20)
    assert c.middle() == (50, 50)
    c.set_view(100, 50, 199, 149, absolute=True)
    c.set_pixel(100, 50, 1)
    assert c.screen_pixel(100, 50) == 1
    assert c.middle() == (150, 100)


def test_window_mapping():
    c = Canvas(320, 200, 4)
    c.set_window(0, 0, 100, 100)  # y upward
    assert c.to_physical(0, 0) == (0, 199)
    assert c.to_physical(100, 100) == (319, 0)
    assert c.to_physical(50, 50) == (160, 100)  # 159.5 and 99.5 round half up
    assert c.to_logical(0, 199) == pytest.approx((0, 0))
    c.set_window(0, 0, 100, 100, screen=True)  # y downward
    assert c.to_physical(0, 0) == (0, 0)
    assert c.to_physical(100, 100) == (319, 199)
    c.set_view(0, 0, 99, 99, absolute=False)  # the window follows the view
    assert c.to_physical(100, 100) == (99, 99)
    c.unset_window()
    assert c.to_physical(2.5, -2.5) == (3, -3)
    with pytest.raises(BasicError):
        c.to_physical(40000, 0)


def test_line_box_fill():
    c = Canvas(320, 200, 4)
    c.line(0, 0, 4, 2, 1)
    assert _lit(c) == {(0, 0), (1, 0), (2, 1), (3, 1), (4, 2)}
    c = Canvas(320, 200, 4)
    c.line(0, 0, 7, 0, 1, pattern=0xAAAA)  # style bits from the highest, a level line from its end
    assert _lit(c) == {(7, 0), (5, 0), (3, 0), (1, 0)}
    c = Canvas(320, 200, 4)
    c.box(1, 1, 3, 3, 2)
    assert _lit(c) == {(1, 1), (2, 1), (3, 1), (1, 2), (3, 2), (1, 3), (2, 3), (3, 3)}
    c = Canvas(320, 200, 4)
    c.fill_box(3, 3, 1, 1, 2)
    assert len(_lit(c)) == 9
    c.clear()
    assert not _lit(c)


def test_pages_copy():
    c = Canvas(320, 200, 16, pages=2)
    c.set_pixel(5, 5, 9)
    c.copy_page(0, 1)
    c.set_pages(1, 0)
    assert c.get_pixel(5, 5) == 9


def test_draw_pen_apart_from_last_point():
    # the recorded graphics_position test: POINT(n) reports DRAW's pen while only DRAW moved
    # it; a statement that references a point drops it (and STEP counts from its own point)
    from types import SimpleNamespace

    from yaseer.basic.machine.graphics_words import GraphicsWords

    canvas = canvas_for(_mode(9), 2)
    words = GraphicsWords(SimpleNamespace(screen_words=SimpleNamespace(canvas=canvas)))
    assert (words.point(0), words.point(1)) == (320.0, 175.0)
    canvas.draw_point = (300, 175)  # as DRAW "L10" under a WINDOW leaves it
    assert words.point(0) == 300.0
    words.run("PSET", ((True, 0, 0), None), None)
    assert (words.point(0), words.point(1)) == (320.0, 175.0)
    assert canvas.draw_point is None
