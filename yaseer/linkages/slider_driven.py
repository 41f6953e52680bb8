"""The slider-crank driven from its slider: seed 001's TK "backsolve".

Given the slider's travel ``s`` along the cylinder axis and its rates ``s_dot``,
``s_ddot``, find the crank angle theta (degrees) and its rates omega (rad/s) and
alpha (rad/s**2).  Geometry and conventions are Program 1's (the contract): crank
pivot Ao at the origin, crank pin A = a u(theta), piston pin B = s u(phi) + e u(phi - 90)
on the axis of inclination ``axis_deg``, B ahead of A along u(phi) (for seed 001's
crossed branch, turn the axis by 180 degrees and negate e and s).

Position: A lies on the circle of radius a about Ao and on the circle of radius b
about B; of the two intersections ``crank_side = +1`` is A to the left of the
directed line Ao->B, ``-1`` to the right.  Rates: the forward slider-crank
(:func:`yaseer.linkages.slider_crank.slider_crank`) gives s_dot = k omega with
k = ds/dtheta (its s_dot at omega = 1), and s_ddot = k alpha + s_ddot(omega, alpha=0),
so omega = s_dot / k and alpha = (s_ddot - s_ddot(omega, 0)) / k.  At the dead
centres k = 0 and the slider cannot drive the crank (``LockedError``).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from yaseer.linkages.errors import AssemblyError, LockedError
from yaseer.linkages.slider_crank import slider_crank

LEFT = 1
RIGHT = -1


class CrankMotion(NamedTuple):
    """Crank angle (degrees, (-180, 180]), omega (rad/s), alpha (rad/s**2), counter-clockwise positive."""

    theta_deg: float
    omega: float
    alpha: float


def crank_angle_for_travel(eccentricity, crank_length, rod_length, travel, *, axis_deg=0.0,
                           crank_side=LEFT) -> float:
    """The crank angle (degrees) that puts the piston pin at ``travel`` on the axis.

    Raises AssemblyError when no crank angle reaches it (or it needs B behind A).
    """
    phi = np.radians(axis_deg)
    axis = np.exp(1j * phi)
    pin_b = travel * axis - eccentricity * 1j * axis
    reach = abs(pin_b)
    a, b = float(crank_length), float(rod_length)
    if a <= 0 or b <= 0 or reach == 0:
        raise AssemblyError("slider-driven crank: zero length")
    cos_spread = (a * a + reach * reach - b * b) / (2 * a * reach)
    if abs(cos_spread) > 1 + 1e-12:
        raise AssemblyError("slider-driven crank: the crank cannot reach that slider position")
    spread = np.arccos(min(1.0, max(-1.0, cos_spread)))
    theta = np.angle(pin_b) + (1 if crank_side == LEFT else -1) * spread
    pin_a = a * np.exp(1j * theta)
    if ((pin_b - pin_a) * np.conj(axis)).real < 0:
        raise AssemblyError("slider-driven crank: that position has the piston behind the crank pin "
                            "(the other branch: turn the axis by 180 degrees)")
    return float(np.degrees(np.angle(np.exp(1j * theta))))


def crank_from_slider(eccentricity, crank_length, rod_length, travel, travel_rate=0.0, travel_accel=0.0, *,
                      axis_deg=0.0, crank_side=LEFT) -> CrankMotion:
    """Crank angle, angular velocity and acceleration for a given slider motion.

    ``travel``, ``travel_rate``, ``travel_accel``: s, ds/dt, d2s/dt2 along u(axis_deg)
    (length, length/s, length/s**2).  Raises AssemblyError or LockedError (dead centre
    with a moving slider).
    """
    theta = crank_angle_for_travel(eccentricity, crank_length, rod_length, travel,
                                   axis_deg=axis_deg, crank_side=crank_side)
    if travel_rate == 0 and travel_accel == 0:
        return CrankMotion(theta, 0.0, 0.0)
    unit_rate = slider_crank(eccentricity, crank_length, rod_length, theta, 1.0, 0.0, axis_deg=axis_deg)
    gain = float(unit_rate.travel.rate)  # ds/dtheta, length per radian
    if abs(gain) <= 1e-9 * float(crank_length):  # within ~1e-9 rad of a dead centre
        raise LockedError("slider-driven crank: dead centre, the slider cannot turn the crank")
    omega = travel_rate / gain
    if omega == 0:
        return CrankMotion(theta, 0.0, travel_accel / gain)
    centripetal = slider_crank(eccentricity, crank_length, rod_length, theta, omega, 0.0, axis_deg=axis_deg)
    alpha = (travel_accel - float(centripetal.travel.accel)) / gain
    return CrankMotion(theta, omega, alpha)
