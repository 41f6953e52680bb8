"""Program 5: the motion of a virtual link from the origin to a moving point.

Given the point's position (x, y), velocity (vx, vy) and acceleration (ax, ay),
the link has inclination T (degrees, in [0, 360) as the printed listing returns
it), length L and the rates T' = D(5), T'' = E(5) (rad/s, rad/s**2) and
L' = D(6), L'' = E(6).

Methods:
- ``"polar"`` (default): with the radial unit vector e_r = p/L and e_t = i e_r,
  L' = v.e_r, T' = v.e_t / L, L'' = a.e_r + L T'**2, T'' = (a.e_t - 2 L' T') / L.
  Exact everywhere except L = 0 (raises AssemblyError).
- ``"paper"``: the paper's equations (1)-(4) as printed, with the listing's
  T = ATN(Y/X) (+180 when X < 0) and L = X/COS T.  They divide by X, cos T and
  sin T, so they break at T = 0, 90, 180, 270 deg (MethodDivisionByZero there,
  as the pocket computer's degree-mode COS 90 = 0 would) and lose accuracy near
  them.  Equation (4) is used with its factor L on E(5) cos T (the printed line 60
  drops it; programs/prog5.bas keeps that listing as printed).
"""

from __future__ import annotations

from collections import namedtuple  # not typing.NamedTuple: importing typing costs start-up

from yaseer.linkages.chunks import chunked
from yaseer.linkages.errors import AssemblyError, MethodDivisionByZero
from yaseer.linkages.numerics import math_for
from yaseer.linkages.planar import dot
from yaseer.linkages.registry import lookup, register


class VirtualLink(namedtuple("VirtualLink", "angle_deg length angle_rate angle_accel length_rate length_accel")):
    """Inclination T (``angle_deg``, degrees, [0, 360)), ``length`` L, dT/dt, d2T/dt2
    (``angle_rate``, ``angle_accel``: rad/s, rad/s**2), dL/dt, d2L/dt2 (``length_rate``,
    ``length_accel``: length/s, length/s**2); floats or arrays."""

    __slots__ = ()


@chunked
def virtual_link(x, y, vx=0.0, vy=0.0, ax=0.0, ay=0.0, *, method: str | None = None) -> VirtualLink:
    """The virtual link Ao->(x, y) by ``method`` (default ``"polar"``)."""
    return lookup("virtual_link", method)(x, y, vx, vy, ax, ay)


def _wrap_360(angle_deg, xp):
    """An angle in degrees brought into [0, 360)."""
    wrapped = angle_deg % 360.0
    return xp.where(wrapped >= 360.0, wrapped - 360.0, wrapped)


@register("virtual_link", "polar", default=True)
def virtual_link_polar(x, y, vx=0.0, vy=0.0, ax=0.0, ay=0.0) -> VirtualLink:
    """Polar components of the velocity and acceleration vectors (no cos T, sin T divisions)."""
    xp = math_for(x, y, vx, vy, ax, ay)
    position = xp.float(x) + 1j * xp.float(y)
    velocity = xp.float(vx) + 1j * xp.float(vy)
    acceleration = xp.float(ax) + 1j * xp.float(ay)
    length = abs(position)
    if xp.any(length == 0):
        raise AssemblyError("virtual link of zero length")
    radial = position / length
    tangential = 1j * radial
    length_rate = dot(velocity, radial)
    angle_rate = dot(velocity, tangential) / length
    length_accel = dot(acceleration, radial) + length * angle_rate**2
    angle_accel = (dot(acceleration, tangential) - 2 * length_rate * angle_rate) / length
    angle = _wrap_360(xp.degrees(xp.angle(position)), xp)
    return VirtualLink(angle, length, angle_rate, angle_accel, length_rate, length_accel)


def cos_sin_degrees(angle_deg) -> tuple:
    """cos and sin of an angle in degrees, exactly 0 at odd/even multiples of 90
    (as a pocket computer in degree mode gives them)."""
    xp = math_for(angle_deg)
    angle = xp.float(angle_deg)
    turn = angle % 360.0
    cos = xp.where((turn == 90.0) | (turn == 270.0), 0.0, xp.cos(xp.radians(angle)))
    sin = xp.where((turn == 0.0) | (turn == 180.0), 0.0, xp.sin(xp.radians(angle)))
    return cos, sin


def divide_as_printed(numerator, denominator, what: str):
    """numerator / denominator, raising MethodDivisionByZero where the denominator is 0."""
    xp = math_for(denominator)
    denominator = xp.float(denominator)
    if xp.any(denominator == 0):
        raise MethodDivisionByZero(f"division by zero ({what} = 0)")
    return numerator / denominator


@register("virtual_link", "paper")
def virtual_link_paper(x, y, vx=0.0, vy=0.0, ax=0.0, ay=0.0) -> VirtualLink:
    """The paper's equations (1)-(4) with the listing's T and L (lines 10-30)."""
    xp = math_for(x, y, vx, vy, ax, ay)
    x, y, vx, vy, ax, ay = (xp.float(v) for v in (x, y, vx, vy, ax, ay))
    angle = xp.degrees(xp.arctan(divide_as_printed(y, x, "X")))
    angle = xp.where(x < 0, angle + 180.0, angle)
    cos, sin = cos_sin_degrees(angle)
    length = divide_as_printed(x, cos, "COS T")
    angle = xp.where(angle < 0, angle + 360.0, angle)
    angle = xp.where(angle - 360.0 > 0, angle - 360.0, angle)
    length_rate = vx * cos + vy * sin  # (1)
    angle_rate = divide_as_printed(divide_as_printed(vy - length_rate * sin, length, "L"), cos, "COS T")  # (2)
    angle_accel = (ay * cos - ax * sin - 2 * length_rate * angle_rate) / length  # (3)
    length_accel = divide_as_printed(  # (4)
        ay + length * angle_rate**2 * sin - length * angle_accel * cos - 2 * length_rate * angle_rate * cos,
        sin, "SIN T",
    )
    return VirtualLink(angle, length, angle_rate, angle_accel, length_rate, length_accel)
