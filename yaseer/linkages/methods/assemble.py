"""Shared steps of the alternative methods: inputs in, the linkages' named results out.

Every method here has the same arguments and returns the same named result as
the default ("closed") function of its linkage (:class:`SliderCrank`,
:class:`FourBar`); a method only finds the positions its own way (and the
pseudographic one its rates too).  Laziness as the contract asks: the rates are
computed only when a crank rate is non-zero (``moving``), else they are exactly 0.
"""

from __future__ import annotations

import numpy as np

from yaseer.linkages.errors import LinkageError
from yaseer.linkages.fourbar import CROSSED, FourBar, loop_rates
from yaseer.linkages.planar import DrivenCrank, Motion, Rotation, Stretch, fixed_point, still, unit
from yaseer.linkages.slider_crank import SliderCrank, slider_rates


class NoConvergenceError(LinkageError):
    """An iterative method stopped at its iteration cap (or met a singular Jacobian).

    ``index`` is the flat index of the first such position of an array call.
    """

    def __init__(self, message: str, index: int | None = None):
        super().__init__(message)
        self.index = index


def slider_crank_result(crank: DrivenCrank, eccentricity, rod_length, axis, rod_angle, travel, rates=None) -> SliderCrank:
    """Build :class:`SliderCrank` from positions (radians, length) found by a method;
    ``crank`` from :func:`driven_crank` (``exact_degrees=False``: the methods take cos
    and sin of radians, as their sources do).

    ``rates(pin)`` may give (rod omega, rod alpha, s', s''); by default they come
    from the differentiated loop A + b u(beta) = -e i u(phi) + s u(phi)
    (:func:`slider_rates`, shared with the closed form).
    """
    e, b = np.asarray(eccentricity, float), np.asarray(rod_length, float)
    direction = unit(axis)
    shape = np.broadcast(rod_angle, travel, crank.pin.pos).shape
    rod_angle, travel = np.broadcast_to(rod_angle, shape), np.broadcast_to(travel, shape)
    b_pos = -e * 1j * direction + travel * direction
    if not crank.moving:
        zero = np.zeros(shape)
        return SliderCrank(crank.rotation, crank.length, Rotation(rod_angle, zero, zero), crank.pin,
                           still(fixed_point(b_pos)), Stretch(travel, zero, zero), axis, False)
    if rates is None:
        (omega, alpha), (s_dot, s_ddot) = slider_rates(crank.pin, b * unit(rod_angle), direction)
    else:
        omega, alpha, s_dot, s_ddot = rates(crank.pin)
    return SliderCrank(crank.rotation, crank.length, Rotation(rod_angle, omega, alpha), crank.pin,
                       Motion(b_pos, s_dot * direction, s_ddot * direction), Stretch(travel, s_dot, s_ddot), axis, True)


def fourbar_result(crank: DrivenCrank, pivot: Motion, coupler_angle, follower_pivot_angle, coupler_length) -> FourBar:
    """Build :class:`FourBar` from the coupler angle A->B and the angle Bo->B (radians).

    Rates from the differentiated loop A + b u(beta) = Bo - (B->Bo) (:func:`loop_rates`,
    shared with the closed form); LockedError where coupler and follower are in line
    (toggle or change point).
    """
    b = np.asarray(coupler_length, float)
    coupler_vec = b * unit(coupler_angle)
    b_pos = crank.pin.pos + coupler_vec
    follower_vec = pivot.pos - b_pos
    follower_angle = follower_pivot_angle + np.pi
    shape = np.shape(b_pos)
    coupler_angle, follower_angle = np.broadcast_to(coupler_angle, shape), np.broadcast_to(follower_angle, shape)
    if not crank.moving:
        zero = np.zeros(shape)
        return FourBar(crank.rotation, crank.length, Rotation(coupler_angle, zero, zero),
                       Rotation(follower_angle, zero, zero), crank.pin, still(fixed_point(b_pos)), pivot, False)
    (w3, a3), (w4, a4), b_motion = loop_rates(crank.pin, coupler_vec, follower_vec)
    return FourBar(crank.rotation, crank.length, Rotation(coupler_angle, w3, a3), Rotation(follower_angle, w4, a4),
                   crank.pin, b_motion, pivot, True)


def ground_pivot(ground_length, ground_angle_deg) -> Motion:
    """The follower pivot Bo = L11 u(T11)."""
    return fixed_point(np.asarray(ground_length, float) * unit(np.radians(np.asarray(ground_angle_deg, float))))


def side_of(branch) -> np.ndarray:
    """+1 uncrossed (B left of A->Bo), -1 crossed."""
    return np.where(np.asarray(branch) == CROSSED, -1.0, 1.0)


def first_index(mask) -> int | None:
    """The flat index of the first True of ``mask`` (None for a scalar)."""
    return int(np.flatnonzero(mask)[0]) if np.ndim(mask) else None
