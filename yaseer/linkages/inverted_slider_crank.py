"""Program 3: the first inversion of the slider-crank (FISC) with a flexible crank.

Geometry (contract, Program 3): Ao at the origin, Bo = -L6 u(T6) (L6, T6 give
the vector Bo->Ao), crank pin A = a u(theta) carries a slider block that slides
along the follower, a link pivoted at Bo whose line passes through A.  The
follower Bo->A has length L5 and inclination T9:  L5 u(T9) = A - Bo, found with
atan2 and |.| (the paper's equations (7), (8) divide by cos T9).  Rates from
A' = L5' u + L5 T9' i u (one 2x2 solve), singular only where A reaches Bo.
"""

from __future__ import annotations

from yaseer.linkages.chunks import chunked
from yaseer.linkages.errors import AssemblyError
from yaseer.linkages.kinetostatics import Body, ForceResult, Joint, Load, MassProps, analyse, loads_at_point, rigid_body
from yaseer.linkages.numerics import math_for
from yaseer.linkages.registry import lookup, register
from yaseer.linkages.virtual_link import cos_sin_degrees, divide_as_printed
from yaseer.linkages.planar import CrankedLinkage, DrivenCrank, Motion, Rotation, Stretch, driven_crank, fixed_point
from yaseer.linkages.planar import solve_two_directions, unit_degrees

# Loads of Program 3: crank_torque [U(3)], follower_perpendicular [F(18)].
LOAD_NAMES = ("crank_torque", "follower_perpendicular")


class InvertedSliderCrank(CrankedLinkage):
    """Kinematics of the FISC at one or many positions (arrays broadcast).

    ``follower``: inclination T9 of Bo->A and rates; ``follower_length``: L5 = |Bo->A|
    and rates; ``pin_a``: the crank pin (and slider block) motion; ``pivot``: Bo.
    """

    crank: Rotation
    crank_length: Stretch
    follower: Rotation
    follower_length: Stretch
    pin_a: Motion
    pivot: Motion
    moving: bool
    FIELDS = ("crank", "crank_length", "follower", "follower_length", "pin_a", "pivot", "moving")

    FRAMES = {"crank": (None, "crank", False), "follower": ("pivot", "follower", False)}

    def follower_point(self, distance, offset_deg) -> Motion:
        """A point of the follower: ``distance`` from Bo, ``offset_deg`` from Bo->A."""
        return self.body_point("follower", distance, offset_deg)

    def forces(
        self,
        *,
        crank: MassProps = MassProps(),
        block_mass=0.0,
        block_inertia=0.0,
        follower: MassProps = MassProps(),
        follower_point=(0.0, 0.0),
        loads: dict | None = None,
        unknown: str = "crank_torque",
        gravity=0.0,
    ) -> ForceResult:
        """Joint reactions and the ``unknown`` load (``crank_torque`` or
        ``follower_perpendicular``).

        The block sits at A and turns with the follower.  Reactions:
        ``ground_on_crank`` at Ao and ``crank_on_block`` at A (complex);
        ``follower_on_block`` (normal force at A along u(T9 + 90 deg)) and
        ``follower_on_block_couple`` (couple about A); ``ground_on_follower`` at Bo.
        """
        loads = loads or {}
        bodies = [rigid_body(self, "crank", crank), Body("block", block_mass, block_inertia, self.pin_a, self.follower.alpha),
                  rigid_body(self, "follower", follower)]
        joints = [
            Joint("ground_on_crank", None, "crank", "pin", point=0j),
            Joint("crank_on_block", "crank", "block", "pin", point=self.pin_a.pos),
            Joint("follower_on_block", "follower", "block", "slide", point=self.pin_a.pos,
                  direction=1j * self.unit_vector("follower")),
            Joint("follower_on_block_couple", "follower", "block", "couple"),
            Joint("ground_on_follower", None, "follower", "pin", point=self.pivot.pos),
        ]
        catalogue = {"crank_torque": Load("crank"),
                     "follower_perpendicular": loads_at_point(self, "follower", follower_point)["follower_perpendicular"]}
        return analyse(bodies, joints, catalogue, loads, unknown, gravity)


@chunked
def inverted_slider_crank(*args, method: str | None = None, **kwargs) -> InvertedSliderCrank:
    """FISC kinematics by ``method`` (default ``"closed"``); see
    :func:`inverted_slider_crank_closed` for the arguments."""
    return lookup("inverted_slider_crank", method)(*args, **kwargs)


def _fisc_method(name: str, *, default: bool = False):
    """Register ``solve`` as method ``name`` with the arguments every FISC method takes.

    ``solve(crank, crank_angle_deg, ground_length, ground_angle_deg)`` gets the
    :class:`DrivenCrank` and returns (pivot Bo, follower inclination T9 in radians,
    L5, ``rates``); ``rates()`` -> ((T9', T9''), (L5', L5'')) is called only when a
    crank rate is non-zero (otherwise every rate is exactly 0).
    """

    def decorate(solve):
        def method(ground_length, ground_angle_deg, crank_length, crank_angle_deg, omega=0.0, alpha=0.0, *,
                   crank_length_rate=0.0, crank_length_accel=0.0) -> InvertedSliderCrank:
            crank = driven_crank(crank_length, crank_angle_deg, omega, alpha, crank_length_rate, crank_length_accel)
            pivot, follower_angle, l5, rates = solve(crank, crank_angle_deg, ground_length, ground_angle_deg)
            if not crank.moving:
                zero = math_for(l5).zeros_like(l5)
                return InvertedSliderCrank(crank.rotation, crank.length, Rotation(follower_angle, zero, zero),
                                           Stretch(l5, zero, zero), crank.pin, pivot, False)
            (w4, a4), (l5_dot, l5_ddot) = rates()
            return InvertedSliderCrank(crank.rotation, crank.length, Rotation(follower_angle, w4, a4),
                                       Stretch(l5, l5_dot, l5_ddot), crank.pin, pivot, True)

        method.__name__ = method.__qualname__ = f"inverted_slider_crank_{name}"
        method.__doc__ = solve.__doc__
        return register("inverted_slider_crank", name, default=default)(method)

    return decorate


@_fisc_method("closed", default=True)
def inverted_slider_crank_closed(crank: DrivenCrank, crank_angle_deg, ground_length, ground_angle_deg):
    """FISC kinematics: ``inverted_slider_crank_closed(ground_length, ground_angle_deg,
    crank_length, crank_angle_deg, omega=0, alpha=0, *, crank_length_rate=0,
    crank_length_accel=0)``.  Positions always; velocities and accelerations when any
    crank rate is non-zero.

    ``ground_length``, ``ground_angle_deg``: the vector Bo->Ao.  Lengths in any
    unit, angles in degrees counter-clockwise from +x, rates in rad/s, rad/s**2
    (counter-clockwise positive) and length/s, length/s**2.  Raises AssemblyError
    where the crank pin A falls on Bo (L5 = 0).
    """
    pin_a = crank.pin
    xp = math_for(pin_a.pos, ground_length, ground_angle_deg)
    pivot = fixed_point(-xp.float(ground_length) * unit_degrees(ground_angle_deg, xp), xp)
    radius = pin_a.pos - pivot.pos
    l5 = abs(radius)
    if xp.any(l5 == 0):
        raise AssemblyError("the crank pin falls on the follower pivot (zero-length follower)")

    def rates():
        """A' = L5' u + L5 T9' i u and its derivative, each one 2x2 solve."""
        u = radius / l5
        l5_dot, w4 = solve_two_directions(pin_a.vel, u, 1j * radius)
        rhs = pin_a.acc - 2j * l5_dot * w4 * u + w4**2 * radius
        l5_ddot, a4 = solve_two_directions(rhs, u, 1j * radius)
        return (w4, a4), (l5_dot, l5_ddot)

    return pivot, xp.angle(radius), l5, rates


@_fisc_method("paper")
def inverted_slider_crank_paper(crank: DrivenCrank, crank_angle_deg, ground_length, ground_angle_deg):
    """The paper's equations (7)-(11) as printed (section 3.1); same arguments and
    result as ``inverted_slider_crank_closed``.

    T9 = ATN(num/den) (+180 deg when den < 0, as the listings do), L5 = den / cos T9
    (8), W4 (9), D4 = (...)/cos T9 (10), A4 (11); E4, which the paper does not
    print, from the x component of the second derivative, divided by cos T9 in the
    same style.  They divide by den and cos T9, so they break where the follower is
    vertical (T9 = 90, 270 deg): MethodDivisionByZero there, lost digits near it.
    """
    xp = math_for(crank.length.value, crank_angle_deg, ground_length, ground_angle_deg)
    l6, l7 = xp.float(ground_length), crank.length.value
    d3, e3 = crank.length.rate, crank.length.accel
    w0, a0 = crank.rotation.omega, crank.rotation.alpha
    c6, s6 = cos_sin_degrees(ground_angle_deg)
    c7, s7 = cos_sin_degrees(crank_angle_deg)
    numerator, denominator = l6 * s6 + l7 * s7, l6 * c6 + l7 * c7
    t9 = xp.degrees(xp.arctan(divide_as_printed(numerator, denominator, "L(6) cos T(6) + L(7) cos T(7)")))  # (7)
    t9 = xp.where(denominator < 0, t9 + 180.0, t9)
    c9, s9 = cos_sin_degrees(t9)
    l5 = divide_as_printed(denominator, c9, "COS T(9)")  # (8)

    def rates():
        c79, s79 = cos_sin_degrees(xp.float(crank_angle_deg) - t9)  # cos, sin (T7 - T9)
        w4 = (l7 * w0 * c79 + d3 * s79) / l5  # (9)
        d4 = divide_as_printed(d3 * c7 - l7 * w0 * s7 + l5 * w4 * s9, c9, "COS T(9)")  # (10)
        a4 = (l7 * w0**2 * -s79 + l7 * a0 * c79 + 2 * d3 * w0 * c79 - e3 * -s79 - 2 * d4 * w4) / l5  # (11)
        x_accel = (e3 - l7 * w0**2) * c7 - (l7 * a0 + 2 * d3 * w0) * s7
        e4 = divide_as_printed(x_accel + 2 * d4 * w4 * s9 + l5 * a4 * s9 + l5 * w4**2 * c9, c9, "COS T(9)")
        return (w4, a4), (d4, e4)

    return fixed_point(-l6 * (c6 + 1j * s6)), xp.radians(t9), l5, rates
