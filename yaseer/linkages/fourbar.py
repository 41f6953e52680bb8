"""Program 2: the four-bar linkage AoABBo with a flexible crank, both assembly modes.

Geometry (contract, Program 2): Ao at the origin, Bo = L11 u(T11), crank pin
A = a u(theta), coupler A->B of length b, follower Bo->B of length c.  B is the
intersection of the two circles, found in the frame of the line A->Bo (law of
cosines, no half-angle tangent), so every crank angle including 90/180/270 deg
is exact.  ``branch = +1`` (uncrossed) puts B to the left of the directed line
A->Bo (cross(Bo - A, B - A) > 0), ``branch = -1`` (crossed) to the right.  The
follower is reported as the vector B->Bo (the contract's T(14)).

Continuous branch tracking (the contract's L(10) = -1) is built on top of this
function elsewhere; here the branch is given per position.
"""

from __future__ import annotations

from yaseer.linkages.chunks import chunked
from yaseer.linkages.errors import AssemblyError
from yaseer.linkages.kinetostatics import ForceResult, Joint, Load, MassProps, analyse, loads_at_point, rigid_body
from yaseer.linkages.numerics import math_for
from yaseer.linkages.registry import lookup, register
from yaseer.linkages.planar import CrankedLinkage, Motion, Rotation, Stretch, driven_crank, fixed_point
from yaseer.linkages.planar import solve_two_directions, still, unit_degrees

UNCROSSED = 1
CROSSED = -1

# Loads of Program 2, by name (contract element in brackets):
# crank_fx, crank_fy [F(29), F(30)], crank_perpendicular [F(31)], crank_torque [U(2)];
# coupler_fx, coupler_fy [F(32), F(33)], coupler_perpendicular [F(34)];
# follower_fx, follower_fy [F(35), F(36)], follower_perpendicular [F(37)].
LOAD_NAMES = (
    "crank_fx", "crank_fy", "crank_perpendicular", "crank_torque",
    "coupler_fx", "coupler_fy", "coupler_perpendicular",
    "follower_fx", "follower_fy", "follower_perpendicular",
)


class FourBar(CrankedLinkage):
    """Kinematics of a four-bar at one or many positions (arrays broadcast).

    ``coupler``: inclination of A->B and rates; ``follower``: inclination of the
    vector B->Bo and rates; ``pin_a``, ``pin_b``: motions of A and B; ``pivot``:
    Bo; ``moving``: whether rates were computed (otherwise exactly 0).
    """

    crank: Rotation
    crank_length: Stretch
    coupler: Rotation
    follower: Rotation
    pin_a: Motion
    pin_b: Motion
    pivot: Motion
    moving: bool
    FIELDS = ("crank", "crank_length", "coupler", "follower", "pin_a", "pin_b", "pivot", "moving")

    FRAMES = {"crank": (None, "crank", False), "coupler": ("pin_a", "coupler", False),
              "follower": ("pivot", "follower", True)}

    def coupler_point(self, distance, offset_deg) -> Motion:
        """A point of the coupler: ``distance`` from A, ``offset_deg`` from A->B."""
        return self.body_point("coupler", distance, offset_deg)

    def follower_point(self, distance, offset_deg) -> Motion:
        """A point of the follower: ``distance`` from Bo, ``offset_deg`` from Bo->B."""
        return self.body_point("follower", distance, offset_deg)

    def forces(
        self,
        *,
        crank: MassProps = MassProps(),
        coupler: MassProps = MassProps(),
        follower: MassProps = MassProps(),
        crank_point=(0.0, 0.0),
        coupler_point=(0.0, 0.0),
        follower_point=(0.0, 0.0),
        loads: dict | None = None,
        unknown: str = "crank_torque",
        gravity=0.0,
    ) -> ForceResult:
        """Joint reactions and the ``unknown`` load (one of :data:`LOAD_NAMES`).

        Reactions (complex): ``ground_on_crank`` at Ao, ``crank_on_coupler`` at A,
        ``coupler_on_follower`` at B, ``ground_on_follower`` at Bo.
        """
        loads = loads or {}
        bodies = [rigid_body(self, "crank", crank), rigid_body(self, "coupler", coupler),
                  rigid_body(self, "follower", follower)]
        joints = [
            Joint("ground_on_crank", None, "crank", "pin", point=0j),
            Joint("crank_on_coupler", "crank", "coupler", "pin", point=self.pin_a.pos),
            Joint("coupler_on_follower", "coupler", "follower", "pin", point=self.pin_b.pos),
            Joint("ground_on_follower", None, "follower", "pin", point=self.pivot.pos),
        ]
        catalogue = {"crank_torque": Load("crank"), **loads_at_point(self, "crank", crank_point),
                     **loads_at_point(self, "coupler", coupler_point), **loads_at_point(self, "follower", follower_point)}
        return analyse(bodies, joints, catalogue, loads, unknown, gravity)


@chunked
def fourbar(*args, method: str | None = None, **kwargs) -> FourBar:
    """Four-bar kinematics by ``method`` (default ``"closed"``); see
    :func:`fourbar_closed` for the arguments.

    A whole cycle in one call: ``fourbar(100, 0, 40, 120, 80, np.linspace(0, 360, 3601), 10)``.
    """
    return lookup("fourbar", method)(*args, **kwargs)


@register("fourbar", "closed", default=True)
def fourbar_closed(
    ground_length,
    ground_angle_deg,
    crank_length,
    coupler_length,
    follower_length,
    crank_angle_deg,
    omega=0.0,
    alpha=0.0,
    *,
    crank_length_rate=0.0,
    crank_length_accel=0.0,
    branch=UNCROSSED,
) -> FourBar:
    """Positions always; velocities and accelerations when any crank rate is non-zero.

    Lengths in any unit, angles in degrees, rates in rad/s, rad/s**2, length/s.
    Raises AssemblyError where the loop does not close (or a coupler/follower
    length is <= 0, or A falls on Bo), LockedError at a toggle (coupler and
    follower in line) when rates are asked.
    """
    xp = math_for(ground_length, ground_angle_deg, crank_length, coupler_length, follower_length, crank_angle_deg,
                  omega, alpha, crank_length_rate, crank_length_accel, branch)
    b = xp.float(coupler_length)
    c = xp.float(follower_length)
    crank, length, pin_a, moving = driven_crank(crank_length, crank_angle_deg, omega, alpha, crank_length_rate,
                                                crank_length_accel)
    pivot = fixed_point(xp.float(ground_length) * unit_degrees(ground_angle_deg, xp), xp)
    if xp.any(b <= 0) or xp.any(c <= 0):
        raise AssemblyError("coupler or follower of zero length")
    diagonal = pivot.pos - pin_a.pos
    span = abs(diagonal)
    if xp.any(span == 0):
        raise AssemblyError("the crank pin falls on the follower pivot")
    # lengths in a unit of the diagonal's size (a power of two: exact, the same bits as before):
    # squares of lengths measured in 1E-165 units would underflow to 0
    unit = xp.unit_of(span)
    b, c, span = b / unit, c / unit, span / unit
    along = (b**2 - c**2 + span**2) / (2 * span)
    height_squared = b**2 - along**2
    if xp.any(height_squared < 0):
        raise AssemblyError("the coupler and follower cannot meet")
    side = xp.where(xp.float(branch) == CROSSED, -1.0, 1.0)
    b_pos = pin_a.pos + (along + 1j * side * xp.sqrt(height_squared)) * diagonal / span
    coupler_vec = b_pos - pin_a.pos
    follower_vec = pivot.pos - b_pos  # B -> Bo
    coupler_angle, follower_angle = xp.angle(coupler_vec), xp.angle(follower_vec)
    if not moving:
        zero = xp.zeros_like(span)
        return FourBar(crank, length, Rotation(coupler_angle, zero, zero), Rotation(follower_angle, zero, zero),
                       pin_a, still(Motion(b_pos, b_pos, b_pos)), pivot, False)
    (w3, a3), (w4, a4), b_motion = loop_rates(pin_a, coupler_vec, follower_vec)
    return FourBar(crank, length, Rotation(coupler_angle, w3, a3), Rotation(follower_angle, w4, a4),
                   pin_a, b_motion, pivot, True)


def loop_rates(pin_a: Motion, coupler_vec, follower_vec) -> tuple[tuple, tuple, Motion]:
    """((coupler omega, alpha), (follower omega, alpha), motion of B) of the loop
    B = A + coupler_vec = Bo - follower_vec (follower_vec is B->Bo), positions known.

    Differentiating: w3 i coupler + w4 i follower = -A' and
    a3 i coupler + a4 i follower = -A'' + w3**2 coupler + w4**2 follower
    (LockedError where coupler and follower are in line).  Shared by every four-bar method.
    """
    w3, w4 = solve_two_directions(-pin_a.vel, 1j * coupler_vec, 1j * follower_vec)
    rhs = -pin_a.acc + w3**2 * coupler_vec + w4**2 * follower_vec
    a3, a4 = solve_two_directions(rhs, 1j * coupler_vec, 1j * follower_vec)
    b_motion = Motion(pin_a.pos + coupler_vec, pin_a.vel + 1j * w3 * coupler_vec,
                      pin_a.acc + (1j * a3 - w3**2) * coupler_vec)
    return (w3, a3), (w4, a4), b_motion
