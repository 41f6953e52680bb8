"""GW-BASIC's CIRCLE on a graphics canvas (machine/graphics.py's Canvas), following the
algorithm of ADVGRP.ASM CIRCLE (CIRCLP, CPLOT8, CPLOT4, CGTCNT, SCALE).

The circle is walked over one octant in half pixels (the radius doubled, a point plotted at
every even step, rounded up), and each point is reflected into the eight octants.  An
ellipse is the circle with one axis scaled by the aspect as a fraction of 256 (the y axis
when the aspect is at most 1, else the x axis by its inverse).  Arcs are counted in points:
an octant holds ``radius * SQR(2)/2`` of them (CNPNTS), an angle is the number of points
from angle 0 (``angle / 2pi * 8 * CNPNTS``), and a point is plotted when its count lies
between the start's and the end's (outside them when the end comes first); a negative
angle draws a line from the centre to the point whose count it is.

Lengths are in pixels of the view (the canvas's view coordinates); angles in radians.
"""

from __future__ import annotations

import math
import struct

from yaseer.basic.arithmetic.values import nearest_integer
from yaseer.basic.errors import ILLEGAL_FUNCTION_CALL, error_for
from yaseer.basic.machine.runtime import signed_word

TWO_PI_FRACTION = 1 / (2 * math.pi)  # CGTCNT multiplies the angle by 1/(2pi) (a single)
NO_END = 0xFFFF  # the end count left out: "infinity" (compared unsigned)


def _single(x: float) -> float:
    """``x`` rounded to a single-precision number (the source computes in singles)."""
    return struct.unpack("f", struct.pack("f", x))[0]


def aspect_fraction(aspect: float) -> tuple[int, bool]:
    """(the aspect as a fraction of 256, True when it scales x): CIRC1 inverts an aspect
    above 1 and scales x by it; FRCINT rounds."""
    aspect = _single(aspect)
    if aspect > 1:
        return nearest_integer(_single(_single(1 / aspect) * 256)), True
    return nearest_integer(_single(aspect * 256)), False


def scale(value: int, fraction: int) -> int:
    """SCALE: ``value`` times ``fraction``/256 rounded (16-bit; 256: unchanged, 0: 0)."""
    low = fraction & 0xFF
    if not low:
        return value if fraction & 0xFF00 else 0
    return signed_word(((value & 0xFFFF) * low + 128) >> 8)


def angle_count(angle: float, per_octant: int) -> tuple[int, bool]:
    """CGTCNT: (the point count of ``angle``, True when it was negative: a line to the
    centre).  Beyond 2pi (as a single) Illegal function call."""
    negative = angle < 0
    fraction = _single(_single(abs(angle)) * _single(TWO_PI_FRACTION))
    if fraction > 1:
        raise error_for(ILLEGAL_FUNCTION_CALL)
    return nearest_integer(_single(_single(per_octant * 8) * fraction)), negative


def circle(canvas, cx: int, cy: int, radius: int, attr: int, start: float | None = None,
           end: float | None = None, fraction: int = 256, scales_x: bool = False) -> None:
    """Draw CIRCLE's outline of ``radius`` pixels about view point (cx, cy) in ``attr``;
    ``start``/``end`` the arc's angles (None: left out), ``fraction``/``scales_x`` the
    aspect (:func:`aspect_fraction`)."""
    per_octant = nearest_integer(_single(_single(radius) * _single(math.sqrt(2) / 2)))
    first, line_first = angle_count(start, per_octant) if start is not None else (0, False)
    last, line_last = angle_count(end, per_octant) if end is not None else (NO_END, False)
    first &= 0xFFFF
    last &= 0xFFFF
    between = last >= first  # plot the points between; else those outside
    if not between:
        first, last = last, first
        line_first, line_last = line_last, line_first

    def plot(dx: int, dy: int, count: int) -> None:
        """CPLOT's test: the count at the start or the end plots the point (or the line
        to the centre its angle asks for), between them plots it when drawing between."""
        count &= 0xFFFF
        x, y = cx + dx, cy + dy
        if count == first:
            edge_line = line_first
        elif count < first:
            edge_line = None
        elif count == last:
            edge_line = line_last
        else:
            edge_line = None
        if edge_line:
            canvas.line(x, y, cx, cy, attr)
        elif edge_line is not None or (first < count < last) == between:
            canvas.set_pixel(x, y, attr)

    def both(value: int) -> tuple[int, int]:
        """(the offset as x uses it, as y uses it): one of them scaled by the aspect."""
        scaled = scale(value, fraction)
        return (scaled, value) if scales_x else (value, scaled)

    def octants(x: int, y: int) -> None:
        """CPLOT8: the point (x, y) of octant 0 (y up) reflected into all eight, each
        with its count."""
        xx, xy = both(x)
        yx, yy = both(y)
        n = per_octant
        plot(xx, -yy, y)
        plot(-yx, -xy, 2 * n + y)
        plot(-xx, yy, 4 * n + y)
        plot(yx, xy, 6 * n + y)
        plot(yx, -xy, 2 * n - y)
        plot(-xx, -yy, 4 * n - y)
        plot(-yx, xy, 6 * n - y)
        plot(xx, yy, 8 * n - y)

    x, y, total = radius * 2, 0, 0
    while True:
        if not y & 1:
            octants((x + 1) >> 1, (y + 1) >> 1)
            if y >= x:
                return
        total += 2 * y + 1
        if total >= 0:
            total -= 2 * x - 1
            x -= 1
        y += 1
