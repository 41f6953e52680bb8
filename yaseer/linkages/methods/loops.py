"""Loop-closure helpers shared by the alternative methods.

Everything works on floats or numpy arrays (element-wise) and in **radians**;
the public method functions convert degrees at their boundary.  Vectors are
pairs ``(x, y)``.  The velocity and acceleration helpers are the time
derivatives of the loop equations, solved for the two unknown rates once the
positions are known, whatever method found the positions.
"""

from __future__ import annotations

import numpy as np


class LinkageError(ValueError):
    """A position that cannot be assembled or a method that cannot proceed.

    ``index`` is the flat index of the first failing position of an array call
    (``None`` for a scalar call).
    """

    def __init__(self, message: str, index: int | None = None):
        super().__init__(message)
        self.index = index


def unit(angle):
    """The unit vector u(angle) = (cos, sin), angle in radians."""
    return np.cos(angle), np.sin(angle)


def dot(u, v):
    return u[0] * v[0] + u[1] * v[1]


def crank_pin(length, angle, length_rate, angle_rate, length_accel, angle_accel):
    """Position, velocity and acceleration of the pin A = a*u(theta) of a flexible crank.

    Rates: ``length_rate`` = da/dt, ``angle_rate`` = dtheta/dt (rad/s) and likewise the
    second derivatives.  Returns three vectors.
    """
    radial = unit(angle)
    normal = unit(angle + np.pi / 2)
    position = (length * radial[0], length * radial[1])
    along = length_rate
    across = length * angle_rate
    velocity = (along * radial[0] + across * normal[0], along * radial[1] + across * normal[1])
    along_acc = length_accel - length * angle_rate**2
    across_acc = length * angle_accel + 2 * length_rate * angle_rate
    acceleration = (
        along_acc * radial[0] + across_acc * normal[0],
        along_acc * radial[1] + across_acc * normal[1],
    )
    return position, velocity, acceleration


def slider_rates(pin_velocity, pin_acceleration, rod_length, rod_angle, axis_angle):
    """Rod and slider rates of A + b*u(beta) = -e*u(phi+90) + s*u(phi), positions known.

    Returns (beta', beta'', s', s'') in rad/s, rad/s^2, length/s, length/s^2.  The
    divisor b*cos(beta - phi) vanishes only with the rod square to the axis, the
    assembly limit.
    """
    axis = unit(axis_angle)
    normal = unit(axis_angle + np.pi / 2)
    skew = rod_angle - axis_angle
    divisor = rod_length * np.cos(skew)
    omega = -dot(pin_velocity, normal) / divisor
    velocity = dot(pin_velocity, axis) - rod_length * omega * np.sin(skew)
    alpha = (-dot(pin_acceleration, normal) + rod_length * omega**2 * np.sin(skew)) / divisor
    acceleration = (
        dot(pin_acceleration, axis) - rod_length * alpha * np.sin(skew) - rod_length * omega**2 * np.cos(skew)
    )
    return omega, alpha, velocity, acceleration


def fourbar_rates(pin_velocity, pin_acceleration, coupler, coupler_angle, follower, follower_angle):
    """Coupler and follower rates of A + b*u(beta) = g + c*u(gamma), positions known.

    ``follower_angle`` gamma is the direction Bo->B.  Returns (beta', beta'',
    gamma', gamma'').  The divisor sin(beta - gamma) vanishes at the toggle and
    change points (coupler and follower collinear), where the velocity equations
    alone cannot give the rates.
    """
    along_coupler = unit(coupler_angle)
    along_follower = unit(follower_angle)
    sine = np.sin(coupler_angle - follower_angle)
    coupler_omega = dot(pin_velocity, along_follower) / (coupler * sine)
    follower_omega = dot(pin_velocity, along_coupler) / (follower * sine)
    rest = (
        pin_acceleration[0] - coupler * coupler_omega**2 * along_coupler[0] + follower * follower_omega**2 * along_follower[0],
        pin_acceleration[1] - coupler * coupler_omega**2 * along_coupler[1] + follower * follower_omega**2 * along_follower[1],
    )
    coupler_alpha = dot(rest, along_follower) / (coupler * sine)
    follower_alpha = dot(rest, along_coupler) / (follower * sine)
    return coupler_omega, coupler_alpha, follower_omega, follower_alpha


def normalise_degrees(angle):
    """Angle in degrees brought into (-180, 180]."""
    wrapped = np.mod(angle, 360.0)
    return np.where(wrapped > 180.0, wrapped - 360.0, wrapped) if np.ndim(wrapped) else (
        wrapped - 360.0 if wrapped > 180.0 else float(wrapped)
    )


def as_float_or_array(value):
    """A 0-d result becomes a Python float; arrays stay arrays."""
    return float(value) if np.ndim(value) == 0 else value


def check_finite(method: str, *values) -> None:
    """Raise LinkageError naming the first position where a robust method produced NaN/inf."""
    for value in values:
        bad = ~np.isfinite(np.asarray(value, dtype=float))
        if bad.any():
            index = int(np.flatnonzero(bad)[0]) if np.ndim(value) else None
            raise LinkageError(f"{method}: the position is singular (no finite solution)", index)
