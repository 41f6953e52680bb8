"""Program 1: the general (offset, inclined, flexible-crank) slider-crank AoAB.

Geometry (contract, Program 1): crank pivot Ao at the origin, crank pin
A = a u(theta); the piston pin B runs on the line {e u(phi - 90 deg) + s u(phi)}
(``e`` to the right of the axis direction u(phi)) and is the solution ahead of A:
s = A.u(phi) + sqrt(b**2 - (e + A.u(phi + 90 deg))**2).  Every formula is a vector
form, exact at dead centres and with a vertical axis; rates are singular only
where the rod is perpendicular to the axis (the assembly limit).

Units: lengths in any unit, angles in degrees at the interface, rates in rad/s.
"""

from __future__ import annotations

from yaseer.linkages.chunks import chunked
from yaseer.linkages.errors import AssemblyError
from yaseer.linkages.kinetostatics import Body, ForceResult, Joint, Load, MassProps, analyse, loads_at_point, rigid_body
from yaseer.linkages.numerics import math_for
from yaseer.linkages.registry import lookup, register
from yaseer.linkages.planar import CrankedLinkage, Motion, Rotation, Stretch, driven_crank, dot
from yaseer.linkages.planar import Values, solve_two_directions, still, unit, unit_degrees

# Loads of Program 1, by name (contract element in brackets):
# crank_fx, crank_fy [F(0), F(1)] force components on the crank at its point;
# crank_perpendicular [F(2)] on the crank at its point; crank_torque [U(1)];
# rod_fx, rod_fy [F(7), F(8)] on the rod at its point; rod_perpendicular [F(9)];
# piston [P(1)] along -u(phi), pushing the piston toward the crank.
LOAD_NAMES = (
    "crank_fx", "crank_fy", "crank_perpendicular", "crank_torque",
    "rod_fx", "rod_fy", "rod_perpendicular", "piston",
)


class SliderCrank(CrankedLinkage):
    """Kinematics of a slider-crank at one or many positions (arrays broadcast).

    ``crank``: crank angle/rates; ``rod``: inclination of A->B and rates;
    ``pin_a``, ``pin_b``: crank pin and piston pin motions; ``travel``: s along
    the axis; ``axis``: the axis inclination phi (radians); ``moving``: whether
    rates were computed (otherwise every velocity and acceleration is exactly 0).
    """

    crank: Rotation
    crank_length: Stretch
    rod: Rotation
    pin_a: Motion
    pin_b: Motion
    travel: Stretch
    axis: Values
    moving: bool
    FIELDS = ("crank", "crank_length", "rod", "pin_a", "pin_b", "travel", "axis", "moving")

    FRAMES = {"crank": (None, "crank", False), "rod": ("pin_b", "rod", True)}

    def rod_point(self, distance, offset_deg) -> Motion:
        """A point of the rod: ``distance`` from the piston pin B, ``offset_deg`` from B->A."""
        return self.body_point("rod", distance, offset_deg)

    def forces(
        self,
        *,
        crank: MassProps = MassProps(),
        rod: MassProps = MassProps(),
        piston_mass=0.0,
        crank_point=(0.0, 0.0),
        rod_point=(0.0, 0.0),
        loads: dict | None = None,
        unknown: str = "crank_torque",
        gravity=0.0,
    ) -> ForceResult:
        """Joint reactions and the ``unknown`` load (one of :data:`LOAD_NAMES`).

        ``crank_point``/``rod_point`` are (distance, offset_deg) of the points of
        interest where the point loads act; ``loads`` gives the known loads.
        Reactions: ``ground_on_crank`` at Ao, ``crank_on_rod`` at A,
        ``rod_on_piston`` at B (complex), ``wall_on_piston`` along u(phi + 90 deg).
        """
        loads = loads or {}
        bodies = [rigid_body(self, "crank", crank), rigid_body(self, "rod", rod),
                  Body("piston", piston_mass, 0.0, self.pin_b, 0.0, particle=True)]
        axis = unit(self.axis)
        joints = [
            Joint("ground_on_crank", None, "crank", "pin", point=0j),
            Joint("crank_on_rod", "crank", "rod", "pin", point=self.pin_a.pos),
            Joint("rod_on_piston", "rod", "piston", "pin", point=self.pin_b.pos),
            Joint("wall_on_piston", None, "piston", "slide", point=self.pin_b.pos, direction=1j * axis),
        ]
        catalogue = {**loads_at_point(self, "crank", crank_point), "crank_torque": Load("crank"),
                     **loads_at_point(self, "rod", rod_point), "piston": Load("piston", -axis, self.pin_b.pos)}
        return analyse(bodies, joints, catalogue, loads, unknown, gravity)


@chunked
def slider_crank(*args, method: str | None = None, **kwargs) -> SliderCrank:
    """Slider-crank kinematics by ``method`` (default ``"closed"``); see
    :func:`slider_crank_closed` for the arguments."""
    return lookup("slider_crank", method)(*args, **kwargs)


@register("slider_crank", "closed", default=True)
def slider_crank_closed(
    eccentricity,
    crank_length,
    rod_length,
    crank_angle_deg,
    omega=0.0,
    alpha=0.0,
    *,
    crank_length_rate=0.0,
    crank_length_accel=0.0,
    axis_deg=0.0,
) -> SliderCrank:
    """Positions always; velocities and accelerations when any crank rate
    (omega, alpha, crank_length_rate, crank_length_accel) is non-zero.

    Lengths in any unit (e is positive to the right of the axis direction u(phi)),
    angles in degrees counter-clockwise from +x, omega and alpha in rad/s and
    rad/s**2 counter-clockwise positive, the crank length's rates in length/s and
    length/s**2.  Raises AssemblyError for a rod of length <= 0 or where b < |e + A.u(phi+90)|,
    LockedError where the rod is perpendicular to the axis and rates are asked.
    """
    xp = math_for(eccentricity, crank_length, rod_length, crank_angle_deg, omega, alpha, crank_length_rate,
                  crank_length_accel, axis_deg)
    e = xp.float(eccentricity)
    b = xp.float(rod_length)
    crank, length, pin_a, moving = driven_crank(crank_length, crank_angle_deg, omega, alpha, crank_length_rate,
                                                crank_length_accel)
    phi = xp.radians(xp.float(axis_deg))
    n = unit_degrees(axis_deg, xp)
    if xp.any(b <= 0):
        raise AssemblyError("connecting rod of zero length")
    across = -(e + dot(pin_a.pos, 1j * n))  # component of A->B along u(phi + 90)
    # in a unit of the rod's size (a power of two: exact, the same bits as before): the squares
    # of lengths measured in 1E-165 units would underflow to 0
    unit = xp.unit_of(b)
    discriminant = (b / unit) ** 2 - (across / unit) ** 2
    if xp.any(discriminant < 0):
        raise AssemblyError("the rod cannot reach the cylinder axis")
    along = xp.sqrt(discriminant) * unit
    s = dot(pin_a.pos, n) + along
    b_pos = -e * 1j * n + s * n
    rod_angle = xp.angle(n * (along + 1j * across))
    if not moving:
        zero = xp.zeros_like(s)
        return SliderCrank(crank, length, Rotation(rod_angle, zero, zero), pin_a, still(Motion(b_pos, b_pos, b_pos)),
                           Stretch(s, zero, zero), phi, False)
    rod_vec = b_pos - pin_a.pos
    rod, travel_rates = slider_rates(pin_a, rod_vec, n)
    s_dot, s_ddot = travel_rates
    pin_b = Motion(b_pos, s_dot * n, s_ddot * n)
    return SliderCrank(crank, length, Rotation(rod_angle, *rod), pin_a, pin_b, Stretch(s, s_dot, s_ddot), phi, True)


def slider_rates(pin_a: Motion, rod_vec, axis_direction) -> tuple[tuple, tuple]:
    """((rod omega, rod alpha), (s', s'')) of A + rod_vec = B = -e i n + s n, positions known.

    Differentiating: s' n - beta' (i rod) = A' and
    s'' n - beta'' (i rod) = A'' - beta'**2 rod, each solved as one 2x2 system
    (LockedError where the rod is perpendicular to the axis).  Shared by every
    slider-crank method.
    """
    s_dot, omega = solve_two_directions(pin_a.vel, axis_direction, -1j * rod_vec)
    s_ddot, alpha = solve_two_directions(pin_a.acc - omega**2 * rod_vec, axis_direction, -1j * rod_vec)
    return (omega, alpha), (s_dot, s_ddot)
