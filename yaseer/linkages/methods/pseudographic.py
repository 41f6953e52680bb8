"""Slider-crank by the pseudographic construction of seed 001 (Boyle & Liu, TK Solver).

The position, velocity and acceleration polygons are built as that paper's TK
rule sheets build them (its Fig. 6): vertices located by intersecting lines of
slope ``m2 = -1/m1`` with the slider line, magnitudes found with square roots and
the signs of omega_AB and alpha_AB decided by its four ``if and`` rules (Fig. 3).

Two generalisations, both needed by Al-Yaseer's Program 1 and neither changing
the construction: the slider axis may point along any angle phi (the polygons are
built in the axis frame, x' along u(phi), and turned back), and the crank may be
flexible (the vertices ``a`` and ``a1`` are A's full velocity and acceleration
instead of omega*AO and the normal/tangential pair).  In the axis frame the
slider line is y' = offset = -e (the contract's line lies e to the right of the
axis direction); the ``open`` branch (B ahead of A) is the contract's.

Like the TK model it does not check its arithmetic: at the assembly limit the
rod is square to the axis, m1 is infinite, and the result is whatever IEEE
arithmetic makes of it (``yaseer stability`` shows what).
"""

from __future__ import annotations

import numpy as np

from yaseer.linkages.errors import AssemblyError
from yaseer.linkages.registry import register
from yaseer.linkages.slider_crank import SliderCrank

from yaseer.linkages.numerics import array_math
from yaseer.linkages.planar import driven_crank

from .assemble import slider_crank_result


@register("slider_crank", "pseudographic")
def slider_crank_pseudographic(eccentricity, crank_length, rod_length, crank_angle_deg, omega=0.0, alpha=0.0, *,
                               crank_length_rate=0.0, crank_length_accel=0.0, axis_deg=0.0,
                               branch: str = "open") -> SliderCrank:
    """Same arguments and result as ``slider_crank_closed`` (degrees, rad/s); ``branch``
    "open" (the contract's B ahead of A) or "crossed" (seed 001's other branch).

    Raises AssemblyError where TK has no square root (b^2 < (yB - yA)^2).
    """
    crank = driven_crank(crank_length, crank_angle_deg, omega, alpha, crank_length_rate, crank_length_accel,
                         exact_degrees=False)
    phi = np.radians(np.asarray(axis_deg, dtype=float))
    to_axis = np.exp(-1j * phi)  # global -> axis frame
    b = np.asarray(rod_length, float)
    pin = crank.pin.pos * to_axis
    x_a, y_a, y_b = pin.real, pin.imag, -np.asarray(eccentricity, float)
    with np.errstate(all="ignore"):
        # TK's sqrt(b^2 - (yB - yA)^2) in a unit of the rod's size (a power of two: exact, the
        # same bits): the squares of lengths measured in 1E-165 units would underflow to 0
        unit = array_math().unit_of(b)
        span = (b / unit) ** 2 - ((y_b - y_a) / unit) ** 2
        if np.any(span < 0):
            raise AssemblyError("pseudographic: the rod cannot reach the slider line")
        x_b = x_a + (1.0 if branch == "open" else -1.0) * np.sqrt(span) * unit
        theta_ab = np.degrees(np.arctan2(y_a - y_b, x_a - x_b))  # direction B->A, TK's atan2d
        m2 = -1.0 / np.tan(np.radians(theta_ab))
        horizontal = (theta_ab == 180.0) | (theta_ab == 360.0)

        def polygons(pin_motion):
            return _velocity_and_acceleration(pin_motion.vel * to_axis, pin_motion.acc * to_axis,
                                              b, x_a, x_b, theta_ab, m2, horizontal)

        return slider_crank_result(crank, eccentricity, b, phi, np.radians(theta_ab + 180.0) + phi, x_b, polygons)


def _velocity_and_acceleration(pin_vel, pin_acc, ab, x_a, x_b, theta_ab, m2, horizontal):
    """TK's velocity and acceleration function sheets; returns (omega_AB, alpha_AB, vB, aB)."""
    xa, ya = pin_vel.real, pin_vel.imag  # vertex a; vertex o at the origin
    xb = np.where(horizontal, xa, xa - ya / m2)  # b on yb = 0 and on the line through a of slope m2
    omega_ab = _signed(np.hypot(xa - xb, ya) / ab, x_b, x_a, ya)
    xa1, ya1 = pin_acc.real, pin_acc.imag  # vertex a1 (a11 then the tangential step, in one)
    a_ban = omega_ab**2 * ab
    xb11 = xa1 + a_ban * np.cos(np.radians(theta_ab))
    yb11 = ya1 + a_ban * np.sin(np.radians(theta_ab))
    xb1 = np.where(horizontal, xb11, xb11 - yb11 / m2)  # b1 on yb1 = 0, line through b11 of slope m2
    alpha_ab = _signed(np.hypot(xb1 - xb11, yb11) / ab, x_b, x_a, yb11)
    return omega_ab, alpha_ab, xb, xb1


def _signed(magnitude, x_b, x_a, y_vertex):
    """TK's four ``if and`` rules (seed 001, Fig. 3) in one line: the rate is positive
    when ``xB >= xA`` and ``0 >= y_vertex`` are both true or both false (y_vertex is
    ya for omega_AB, yb11 for alpha_AB; yb = yb1 = 0).  At equality the magnitude is 0."""
    return np.where((x_b >= x_a) == (0.0 >= y_vertex), magnitude, -magnitude)
