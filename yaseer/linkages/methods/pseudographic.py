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

Works on floats or numpy arrays.  Like the TK model it does not check its
arithmetic: at the assembly limit the rod is square to the axis, m1 is infinite
and the result is whatever IEEE arithmetic makes of it.
"""

from __future__ import annotations

import numpy as np

from .loops import LinkageError, as_float_or_array, crank_pin, normalise_degrees
from .types import SliderCrankMotion


def slider_crank(
    eccentricity,
    crank_length,
    rod_length,
    crank_angle,
    axis_angle=0.0,
    crank_speed=0.0,
    crank_accel=0.0,
    crank_length_rate=0.0,
    crank_length_accel=0.0,
    *,
    branch: str = "open",
) -> SliderCrankMotion:
    """Slider-crank AoAB by polygons.  Angles in degrees, rates in rad/s, rad/s^2.

    Raises LinkageError only where the TK model has no square root
    (b^2 < (yB - yA)^2): the mechanism cannot be assembled.
    """
    with np.errstate(all="ignore"):
        return _solve(
            np.asarray(eccentricity, float), np.asarray(crank_length, float), np.asarray(rod_length, float),
            np.radians(np.asarray(crank_angle, float) - np.asarray(axis_angle, float)),
            np.asarray(axis_angle, float), np.asarray(crank_speed, float), np.asarray(crank_accel, float),
            np.asarray(crank_length_rate, float), np.asarray(crank_length_accel, float), branch,
        )


def _solve(e, ao, ab, theta, phi_deg, omega_ao, alpha_ao, ao_rate, ao_accel, branch):
    (x_a, y_a), (xa, ya), (xa1, ya1) = crank_pin(ao, theta, ao_rate, omega_ao, ao_accel, alpha_ao)
    y_b = -e
    span = ab**2 - (y_b - y_a) ** 2
    if np.any(span < 0):
        raise LinkageError("pseudographic: the mechanism cannot be assembled", _first(span < 0))
    side = 1.0 if branch == "open" else -1.0
    x_b = x_a + side * np.sqrt(span)
    theta_ab = np.degrees(np.arctan2(y_a - y_b, x_a - x_b))  # direction B->A, as TK's atan2d
    m1 = np.tan(np.radians(theta_ab))
    m2 = -1.0 / m1
    horizontal = (theta_ab == 180.0) | (theta_ab == 360.0)
    # velocity polygon: b on yb = 0, on the line through a of slope m2
    xb = np.where(horizontal, xa, xa - ya / m2)
    v_ab = np.hypot(xa - xb, ya)
    omega_ab = _signed(v_ab / ab, x_b, x_a, 0.0, ya)
    # acceleration polygon: b11 = a1 + omega_AB^2*AB along B->A, b1 on yb1 = 0
    a_ban = omega_ab**2 * ab
    xb11 = xa1 + a_ban * np.cos(np.radians(theta_ab))
    yb11 = ya1 + a_ban * np.sin(np.radians(theta_ab))
    xb1 = np.where(horizontal, xb11, xb11 - yb11 / m2)
    a_bat = np.hypot(xb1 - xb11, yb11)
    alpha_ab = _signed(a_bat / ab, x_b, x_a, 0.0, yb11)
    rod_angle = normalise_degrees(theta_ab + 180.0 + phi_deg)
    return SliderCrankMotion(*(as_float_or_array(v) for v in (rod_angle, omega_ab, alpha_ab, x_b, xb, xb1)))


def _signed(magnitude, x_b, x_a, y_low, y_high):
    """TK's four ``if and`` rules (seed 001, Fig. 3) in one line: the rate is
    positive when xB >= xA and y_low >= y_high are both true or both false.

    Velocity: y_low = yb = 0, y_high = ya.  Acceleration: y_low = yb1 = 0,
    y_high = yb11.  (At equality both rules of a pair apply; the magnitude is 0.)
    """
    ahead = x_b >= x_a
    above = y_low >= y_high
    return np.where(ahead == above, magnitude, -magnitude)


def _first(mask) -> int | None:
    return int(np.flatnonzero(mask)[0]) if np.ndim(mask) else None
