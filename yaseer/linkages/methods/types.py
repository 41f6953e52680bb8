"""Named results shared by every alternative method (and the reference).

Units and signs follow ``shared/spec/programs.md``: lengths in the caller's unit,
angles in **degrees** counter-clockwise from +x, angular rates in rad/s and
rad/s^2, linear rates in length/s and length/s^2.  Every field is a float or a
numpy array of the same shape as the crank angle passed in.
"""

from __future__ import annotations

from typing import NamedTuple


class SliderCrankMotion(NamedTuple):
    """Slider-crank AoAB: the rod A->B and the piston pin B along the axis u(phi).

    ``slider_position`` is s in B = e*u(phi - 90deg) + s*u(phi); its rates are along u(phi).
    """

    rod_angle: object
    rod_omega: object
    rod_alpha: object
    slider_position: object
    slider_velocity: object
    slider_acceleration: object


class FourBarMotion(NamedTuple):
    """Four-bar AoABBo: coupler A->B and follower as the vector B->Bo (contract's T(14))."""

    coupler_angle: object
    coupler_omega: object
    coupler_alpha: object
    follower_angle: object
    follower_omega: object
    follower_alpha: object


class VirtualLinkMotion(NamedTuple):
    """Virtual link Ao->P: polar angle T in [0, 360) degrees, length L and their rates."""

    angle: object
    length: object
    angle_rate: object
    angle_accel: object
    length_rate: object
    length_accel: object


MOTION_TYPES = {"slider_crank": SliderCrankMotion, "fourbar": FourBarMotion, "virtual_link": VirtualLinkMotion}
