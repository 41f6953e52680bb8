"""gw's CIRCLE, PAINT and DRAW (machine/circle.py, paint.py, draw_macro.py, figures.py).

References: the pixels of CIRCLE worked out by hand from ADVGRP.ASM's CIRCLE algorithm
(CIRCLP walks the octant in half pixels, CPLOT8 reflects, SCALE applies the aspect as a
fraction of 256, CGTCNT counts an angle in points: no recording shows a circle's pixels,
and PC-BASIC 2.0.8 draws its ellipses by another algorithm, so the source decides there);
the rest against PC-BASIC 2.0.8, which draws what the recordings of a real GW-BASIC 3.23
show for PAINT and DRAW (PC-BASIC's PAINT_* and DRAW_* tests) and errs as they do (its
CIRCLE, PAINT and DRAW2 tests), on programs of our own.
"""

from __future__ import annotations

import pytest

from test_gw_files import both_runs
from yaseer.basic.machine.circle import aspect_fraction, circle, scale
from yaseer.basic.machine.graphics import Canvas
from yaseer.basic.machine.paint import tile_rows


def _drawn(canvas: Canvas, cx: int, cy: int) -> set[tuple[int, int]]:
    return {(x - cx, y - cy) for y in range(canvas.height) for x in range(canvas.width) if canvas.get_pixel(x, y)}


def _mirrored(points) -> set[tuple[int, int]]:
    return {(sx * x, sy * y) for x, y in points for sx in (1, -1) for sy in (1, -1)}


def test_a_circle_of_radius_3_is_the_octant_walk_reflected():
    # X=6, Y=0: points (3,0), (3,1), (2,2) of octant 0 (worked out from CIRCLP), reflected
    canvas = Canvas(20, 20, 4, bits=2)
    circle(canvas, 10, 10, 3, 1)
    octant = [(3, 0), (3, 1), (2, 2)]
    assert _drawn(canvas, 10, 10) == _mirrored(octant + [(y, x) for x, y in octant])


def test_an_ellipse_scales_one_axis_of_the_circle_by_the_aspect():
    # aspect .5: 128/256; SCALE rounds (v*128+128)/256: 0, 1, 1, 2 for 0..3
    assert aspect_fraction(0.5) == (128, False)
    assert aspect_fraction(2) == (128, True)
    assert [scale(v, 128) for v in range(4)] == [0, 1, 1, 2]
    assert scale(7, 256) == 7 and scale(7, 0) == 0
    canvas = Canvas(20, 20, 4, bits=2)
    circle(canvas, 10, 10, 3, 1, fraction=128)
    assert _drawn(canvas, 10, 10) == _mirrored([(3, 0), (0, 2), (3, 1), (1, 2), (2, 1)])
    tall = Canvas(20, 20, 4, bits=2)
    circle(tall, 10, 10, 3, 1, fraction=128, scales_x=True)
    assert _drawn(tall, 10, 10) == {(y, x) for x, y in _drawn(canvas, 10, 10)}


def test_an_arc_plots_the_points_whose_count_lies_between_its_angles():
    # radius 3: 2 points an octant; pi/2 is point 4 of 16: octant 0's counts 0..2, octant 1's 4-y
    canvas = Canvas(20, 20, 4, bits=2)
    circle(canvas, 10, 10, 3, 1, 0, 3.14159 / 2)
    assert _drawn(canvas, 10, 10) == {(3, 0), (3, -1), (2, -2), (1, -3), (0, -3)}
    # the other way round: the points outside, the ends with them (counts 1..3 left out)
    rest = Canvas(20, 20, 4, bits=2)
    circle(rest, 10, 10, 3, 1, 3.14159 / 2, 0)
    full = Canvas(20, 20, 4, bits=2)
    circle(full, 10, 10, 3, 1)
    assert _drawn(rest, 10, 10) == _drawn(full, 10, 10) - {(3, -1), (2, -2), (1, -3)}


def test_a_negative_angle_draws_a_line_to_the_centre():
    canvas = Canvas(20, 20, 4, bits=2)
    circle(canvas, 10, 10, 3, 1, -0.0001, 3.14159 / 2)
    assert {(1, 0), (2, 0), (0, 0)} <= _drawn(canvas, 10, 10)
    assert (0, -1) not in _drawn(canvas, 10, 10)


def test_tiles_of_packed_and_planed_modes():
    assert tile_rows(b"\x1b", 2) == [(0, 1, 2, 3)]
    assert tile_rows(b"\x80", 1) == [(1, 0, 0, 0, 0, 0, 0, 0)]
    # planes: one byte a plane, the first plane 0; a short row filled with zero bytes
    assert tile_rows(b"\x80\x80\x00\x80\x01", 4) == [(11, 0, 0, 0, 0, 0, 0, 0), (0, 0, 0, 0, 0, 0, 0, 1)]


def _same_as_pcbasic(source: str, tmp_path) -> None:
    ours, theirs, our_files, their_files = both_runs(source, tmp_path)
    assert ours == theirs
    assert our_files == their_files


def _pixels(x0: int, y0: int, x1: int, y1: int) -> str:
    """Lines that write the attributes of a rectangle to P.TXT."""
    return (f'9000 OPEN "P.TXT" FOR OUTPUT AS 3: FOR Y = {y0} TO {y1}: FOR X = {x0} TO {x1}\n'
            "9010 PRINT #3, CHR$(48 + POINT(X, Y));: NEXT: PRINT #3,: NEXT: CLOSE 3\n")


PAINTINGS = [
    # a solid fill inside a box with a hole, then a tile over it
    "10 SCREEN 1\n20 LINE (5,5)-(40,30),3,B: LINE (15,12)-(22,20),3,B\n30 PAINT (8,8),1,3\n"
    '40 PAINT (30,25),CHR$(&H1B)+CHR$(&HE4),3\n',
    # a tile with an empty row, a background string, a fill from outside the view's reach
    "10 SCREEN 1\n20 LINE (2,2)-(50,40),2,B\n30 PAINT (10,10),CHR$(&H55)+CHR$(0)+CHR$(&HAA),2\n"
    '40 PAINT (10,10),CHR$(&HFF)+CHR$(&H55),2,CHR$(&H55)\n',
    # SCREEN 2: one bit a pixel (the planes of SCREEN 7, 8, 9: the recorded PAINT_SCREEN_9 test)
    "10 SCREEN 2\n20 LINE (3,3)-(60,30),1,B\n30 PAINT (10,10),CHR$(&HA5)+CHR$(&H3C),1\n",
    # DRAW's P fills from the current point
    '10 SCREEN 1\n20 DRAW "BM10,10C2R30D20L30U20BM15,15P1,2"\n',
]


@pytest.mark.parametrize("program", PAINTINGS)
def test_paint_fills_as_pcbasic(program, tmp_path):
    _same_as_pcbasic(program + _pixels(0, 0, 64, 42), tmp_path)


DRAWINGS = [
    '20 DRAW "BM20,20R10D10L10U10E5F5G5H5"',
    '20 DRAW "BM30,30S8U3R3S2D9S4L4NU6BD3C2M+7,-2M50,40"',
    # (A1, A3 turn through the aspect: DOMOVR rounds the scaled length where PC-BASIC
    # truncates it; lengths both give the same are compared)
    '20 DRAW "BM32,20A1U10A2R6A3U5A0L3"',
    '20 X=7: Y%=-3: A$="R=X;D=Y%;": DRAW "BM10,10XA$;U=-Y%;L" + VARPTR$(X)',
    '20 DRAW "BM40,25TA30U10TA-90R8TA0D3"',
]


@pytest.mark.parametrize("drawing", DRAWINGS)
def test_draw_draws_as_pcbasic(drawing, tmp_path):
    # (the position printed after the pixels are read: text on a graphics screen is drawn)
    source = f"10 SCREEN 1\n{drawing}\n" + _pixels(0, 0, 64, 48) + "9020 PRINT POINT(0); POINT(1)\n"
    _same_as_pcbasic(source, tmp_path)


def test_a_circle_under_a_window_takes_its_radius_in_the_window_s_units(tmp_path):
    # (aspect 1: PC-BASIC 2.0.8's circle and the source's agree at this size)
    source = "10 SCREEN 1\n20 WINDOW SCREEN (0,0)-(159,99)\n30 CIRCLE (20,15),5,1,,,1\n40 WINDOW\n"
    _same_as_pcbasic(source + _pixels(15, 15, 55, 45), tmp_path)


def test_errors_of_circle_paint_and_draw_as_pcbasic(tmp_path):
    lines = [
        "CIRCLE", "CIRCLE (5,5)", "CIRCLE (5,5),3,", "CIRCLE (5,5),-2", "CIRCLE (5,5),3,300",
        "CIRCLE (5,5),3,1,7", "CIRCLE (5,5),3,1,1,2,", "CIRCLE (5,5),3,1,1,2,1,1", 'CIRCLE (5,5),"3"',
        "PAINT", "PAINT (5,5),", 'PAINT (5,5),""', "PAINT (5,5),1,256", 'PAINT (5,5),"A",1,2',
        "PAINT (5,5),40000,", 'PAINT (5,5),"AB",1,"A"',
        'DRAW', 'DRAW 5', 'DRAW "Q"', 'DRAW "A5"', 'DRAW "S300"', 'DRAW "TA361"', 'DRAW "M1"',
        'DRAW "XZ$;"', 'DRAW "XN;"', 'DRAW "U1", 2', 'DRAW "P1"',
    ]
    body = "".join(f"{100 + 10 * k} {line}\n" for k, line in enumerate(lines))
    source = ('10 ON ERROR GOTO 900\n20 GOSUB 100\n30 SCREEN 1: GOSUB 100\n40 END\n' + body
              + "890 RETURN\n900 PRINT ERR; ERL: RESUME NEXT\n")
    _same_as_pcbasic(source, tmp_path)


@pytest.mark.parametrize("commands, end", [
    # TA: the pixel aspect as GTASPC's fraction (213/256 in SCREEN 1), rounded half away
    # from 0: (sin 30 x -10 x 256/213, cos 30 x -10) = (-6.01, -8.66); the recorded
    # DRAW_angle drawing's ends are these
    ("TA30U10", (94, 91)),
    ("TA-90R9", (100, 107)),  # clockwise: (0, 9 x 213/256) = (0, 7.49)
    # A1, A3 as DOMOVR: dy times the inverse 308/256 (1 and SCALE by 52, rounded), dx by 213
    ("A1U10", (88, 100)),  # -10 - (10 x 52 + 128) / 256
    ("A3D4", (95, 100)),  # -(4 + (4 x 52 + 128) / 256)
    ("A1R6", (100, 95)),  # -(6 x 213 + 128) / 256
    ("S6U3", (100, 96)),  # 3 x 6 / 4 truncated
    ("S3L-5", (103, 100)),  # -5 x 3 / 4 truncated toward 0, then negated
])
def test_draw_turns_and_scales_as_the_source(commands, end):
    from yaseer.basic.machine.draw_macro import DrawState, draw

    canvas = Canvas(320, 200, 4, bits=2)
    draw(None, canvas, DrawState(), "BM100,100" + commands)
    assert canvas.last_physical == end
