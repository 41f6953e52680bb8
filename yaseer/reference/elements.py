"""The pieces a reference mechanism is built from: points, bodies, constraints, loads.

Each constraint supplies, in any arithmetic (see :mod:`yaseer.reference.arithmetic`),
its residuals ``Phi``, its Jacobian rows ``Phi_q`` (sparse: {column: value}), ``nu =
-Phi_t`` and ``gamma`` (the right-hand side of ``Phi_q qdd = gamma``, written out
analytically).  Coordinates are ``(x, y, phi)`` per body: the global position and angle
(radians, counter-clockwise) of its drawing frame; body points are in that frame.
The ground is ``None``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable

from yaseer.reference.arithmetic import FLOAT


class MechanismError(ValueError):
    """A reference analysis that cannot proceed (not assembled, singular, branch lost)."""


# --------------------------------------------------------------------------- geometry helpers

def rotate(ar, phi, vector):
    """``vector`` (drawing-frame components) rotated by ``phi`` radians into global components."""
    c, s = ar.cos(phi), ar.sin(phi)
    return (c * vector[0] - s * vector[1], s * vector[0] + c * vector[1])


def perp(vector):
    """``vector`` turned +90 degrees (counter-clockwise)."""
    return (-vector[1], vector[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def cross(a, b):
    """z component of ``a x b``."""
    return a[0] * b[1] - a[1] * b[0]


def normalise_degrees(angle_deg, ar=FLOAT):
    """``angle_deg`` mapped into (-180, 180]."""
    turned = angle_deg - 360 * ar.num(int(ar.to_float(angle_deg) // 360))
    while turned > 180:
        turned -= 360
    while turned <= -180:
        turned += 360
    return turned


@dataclass(frozen=True)
class LocalPoint:
    """A body-fixed point, in Cartesian (x, y) or polar (r, angle in degrees) drawing-frame form.

    Numbers may be ints, floats or decimal strings (strings are exact in mpmath).
    """

    a: object
    b: object
    polar: bool = False

    def xy(self, ar):
        """The point's drawing-frame (x, y) in arithmetic ``ar``."""
        if not self.polar:
            return (ar.num(self.a), ar.num(self.b))
        r, angle = ar.num(self.a), ar.radians(ar.num(self.b))
        return (r * ar.cos(angle), r * ar.sin(angle))


def xy(x, y) -> LocalPoint:
    """A body-fixed point at drawing-frame coordinates (x, y)."""
    return LocalPoint(x, y)


def polar(r, angle_deg) -> LocalPoint:
    """A body-fixed point at distance ``r`` and angle ``angle_deg`` (from the frame's x axis)."""
    return LocalPoint(r, angle_deg, polar=True)


# --------------------------------------------------------------------------- bodies

@dataclass
class Body:
    """A rigid body: name, mass, centroidal moment of inertia, mass centre and named points.

    ``centre`` and ``points`` are in the body's drawing frame (a :class:`LocalPoint`
    or an (x, y) pair).  The ground is not a Body: pass ``None`` where a body is expected.
    """

    name: str
    mass: object = 0
    inertia: object = 0
    centre: LocalPoint = field(default_factory=lambda: xy(0, 0))
    points: dict = field(default_factory=dict)
    index: int = -1  # set by Mechanism

    def __post_init__(self):
        self.centre = _as_point(self.centre)
        self.points = {name: _as_point(p) for name, p in self.points.items()}

    def point(self, name: str) -> LocalPoint:
        try:
            return self.points[name]
        except KeyError:
            raise KeyError(f"body {self.name!r} has no point {name!r}") from None


def _as_point(p) -> LocalPoint:
    return p if isinstance(p, LocalPoint) else xy(*p)


def _resolve(body: Body | None, point) -> LocalPoint:
    """A body's point given by name, or a LocalPoint/pair (global for the ground)."""
    if isinstance(point, str):
        if body is None:
            raise ValueError("ground points are given as coordinates, not names")
        return body.point(point)
    return _as_point(point)


class _Kinematics:
    """Global position, velocity and acceleration of body-fixed points from (q, qd, qdd)."""

    def __init__(self, ar, q, qd=None, qdd=None):
        self.ar, self.q, self.qd, self.qdd = ar, q, qd, qdd

    def angle(self, body):
        return self.ar.num(0) if body is None else self.q[3 * body.index + 2]

    def rate(self, body, vector):
        return self.ar.num(0) if body is None else vector[3 * body.index + 2]

    def arm(self, body, local: LocalPoint):
        """Global vector from the body's frame origin to the point (the point itself for ground)."""
        return local.xy(self.ar) if body is None else rotate(self.ar, self.angle(body), local.xy(self.ar))

    def position(self, body, local: LocalPoint):
        arm = self.arm(body, local)
        if body is None:
            return arm
        k = 3 * body.index
        return (self.q[k] + arm[0], self.q[k + 1] + arm[1])

    def velocity(self, body, local: LocalPoint):
        zero = self.ar.num(0)
        if body is None:
            return (zero, zero)
        k, arm = 3 * body.index, self.arm(body, local)
        w = self.qd[k + 2]
        return (self.qd[k] - w * arm[1], self.qd[k + 1] + w * arm[0])

    def acceleration(self, body, local: LocalPoint):
        zero = self.ar.num(0)
        if body is None:
            return (zero, zero)
        k, arm = 3 * body.index, self.arm(body, local)
        w, alpha = self.qd[k + 2], self.qdd[k + 2]
        return (self.qdd[k] - alpha * arm[1] - w * w * arm[0],
                self.qdd[k + 1] + alpha * arm[0] - w * w * arm[1])


# --------------------------------------------------------------------------- constraints
# Each constraint gives, for arithmetic ar and kinematics kin:
#   residuals(kin, drive)      Phi
#   jacobian(kin)              rows as {column: value}
#   nu(kin, drive)             -Phi_t
#   gamma(kin, drive)          Phi_q qdd = gamma (the terms free of qdd, moved right)

def _add(row: dict, body, entries):
    """Add the three entries (d/dx, d/dy, d/dphi) for ``body`` to a sparse Jacobian row."""
    if body is None:
        return
    k = 3 * body.index
    for offset, value in enumerate(entries):
        row[k + offset] = row.get(k + offset, 0) + value


@dataclass
class Revolute:
    """A pin joint: point ``point_i`` of ``body_i`` coincides with ``point_j`` of ``body_j``.

    ``body_j = None`` is the ground (then ``point_j`` is global coordinates).
    Reaction convention: :meth:`Snapshot.reaction` gives the force on the body asked for.
    """

    name: str
    body_i: Body
    point_i: object
    body_j: Body | None
    point_j: object = (0, 0)
    size = 2

    def __post_init__(self):
        self.local_i = _resolve(self.body_i, self.point_i)
        self.local_j = _resolve(self.body_j, self.point_j)

    def residuals(self, kin, drive):
        pi, pj = kin.position(self.body_i, self.local_i), kin.position(self.body_j, self.local_j)
        return [pi[0] - pj[0], pi[1] - pj[1]]

    def jacobian(self, kin):
        ai, aj = kin.arm(self.body_i, self.local_i), kin.arm(self.body_j, self.local_j)
        one, zero = kin.ar.num(1), kin.ar.num(0)
        row_x, row_y = {}, {}
        _add(row_x, self.body_i, (one, zero, -ai[1]))
        _add(row_y, self.body_i, (zero, one, ai[0]))
        _add(row_x, self.body_j, (-one, zero, aj[1]))
        _add(row_y, self.body_j, (zero, -one, -aj[0]))
        return [row_x, row_y]

    def nu(self, kin, drive):
        zero = kin.ar.num(0)
        return [zero, zero]

    def gamma(self, kin, drive):
        ai, aj = kin.arm(self.body_i, self.local_i), kin.arm(self.body_j, self.local_j)
        wi, wj = kin.rate(self.body_i, kin.qd), kin.rate(self.body_j, kin.qd)
        return [ai[0] * wi * wi - aj[0] * wj * wj, ai[1] * wi * wi - aj[1] * wj * wj]


class _LineProjection:
    """Shared algebra of constraints on ``axis . (p_i - p_j)``, with ``axis`` a unit vector
    fixed in body j (or the ground) at ``line_angle_deg`` (+ 90 for a normal), ``p_j`` on
    the line through ``line_point``: residual ``axis.d - target``."""

    axis_offset_deg = 0

    def __post_init__(self):
        self.local_i = _resolve(self.body_i, self.point_i)
        self.local_j = _resolve(self.body_j, self.line_point)

    def axis(self, kin):
        """The global unit vector the separation is projected on."""
        ar = kin.ar
        angle = ar.radians(ar.num(self.line_angle_deg) + self.axis_offset_deg) + kin.angle(self.body_j)
        return (ar.cos(angle), ar.sin(angle))

    def _separation(self, kin):
        pi, pj = kin.position(self.body_i, self.local_i), kin.position(self.body_j, self.local_j)
        return (pi[0] - pj[0], pi[1] - pj[1])

    def _target(self, kin, drive):
        """(value, rate, acceleration) the projection must follow (zero for a slider)."""
        zero = kin.ar.num(0)
        return zero, zero, zero

    def residuals(self, kin, drive):
        return [dot(self.axis(kin), self._separation(kin)) - self._target(kin, drive)[0]]

    def jacobian(self, kin):
        n, d = self.axis(kin), self._separation(kin)
        ai, aj = kin.arm(self.body_i, self.local_i), kin.arm(self.body_j, self.local_j)
        row = {}
        _add(row, self.body_i, (n[0], n[1], dot(n, perp(ai))))
        _add(row, self.body_j, (-n[0], -n[1], dot(perp(n), d) - dot(n, perp(aj))))
        return [row]

    def nu(self, kin, drive):
        return [self._target(kin, drive)[1]]

    def gamma(self, kin, drive):
        n, d = self.axis(kin), self._separation(kin)
        ai, aj = kin.arm(self.body_i, self.local_i), kin.arm(self.body_j, self.local_j)
        wi, wj = kin.rate(self.body_i, kin.qd), kin.rate(self.body_j, kin.qd)
        vi, vj = kin.velocity(self.body_i, self.local_i), kin.velocity(self.body_j, self.local_j)
        d_rate = (vi[0] - vj[0], vi[1] - vj[1])
        # Phi'' = n''.d + 2 n'.d' + n.d'' - target''; n' = wj perp(n), n'' = alpha_j perp(n) - wj^2 n,
        # d'' = (accelerations of the two points); keep the terms free of qdd.
        rest = (-wj * wj * dot(n, d) + 2 * wj * dot(perp(n), d_rate)
                - wi * wi * dot(n, ai) + wj * wj * dot(n, aj))
        return [self._target(kin, drive)[2] - rest]


@dataclass
class PointOnLine(_LineProjection):
    """A slider: point ``point_i`` of ``body_i`` stays on a line fixed in ``body_j`` (or the ground).

    The line passes through ``line_point`` with direction angle ``line_angle_deg``
    (both in body j's drawing frame; global for the ground).  Its normal is the
    direction turned +90 degrees; :meth:`Snapshot.normal_force` reports the force
    of body j on body i along that normal.  Relative rotation is free; add an
    :class:`AngleLock` for a prismatic pair.
    """

    name: str
    body_i: Body
    point_i: object
    body_j: Body | None
    line_point: object
    line_angle_deg: object
    size = 1
    axis_offset_deg = 90

    def normal(self, kin):
        """Global unit normal of the line (its direction turned +90 degrees)."""
        return self.axis(kin)


@dataclass
class LengthDriver(_LineProjection):
    """A driven slide (a flexible crank's length): the distance of ``point_i`` of ``body_i``
    along a line fixed in ``body_j``, measured from ``line_point`` in the direction
    ``line_angle_deg``, follows s(t); per position s, its rate and acceleration (lengths).

    Use it with a PointOnLine on the same line.  :meth:`Snapshot.driver_torque` gives the
    force the drive applies to body i along the line direction.
    """

    name: str
    body_i: Body
    point_i: object
    body_j: Body | None
    line_point: object
    line_angle_deg: object = 0
    size = 1

    def _target(self, kin, drive):
        if self.name not in drive.others:
            raise ValueError(f"no values given for the driver {self.name!r} (analyse(..., drives=...))")
        values = drive.others[self.name]
        return values.angle, values.rate, values.acceleration


@dataclass
class AngleLock:
    """No relative rotation: ``phi_i - phi_j = offset_deg`` (with PointOnLine, a prismatic pair)."""

    name: str
    body_i: Body
    body_j: Body | None
    offset_deg: object = 0
    size = 1

    def residuals(self, kin, drive):
        ar = kin.ar
        return [kin.angle(self.body_i) - kin.angle(self.body_j) - ar.radians(ar.num(self.offset_deg))]

    def jacobian(self, kin):
        one, zero = kin.ar.num(1), kin.ar.num(0)
        row = {}
        _add(row, self.body_i, (zero, zero, one))
        _add(row, self.body_j, (zero, zero, -one))
        return [row]

    def nu(self, kin, drive):
        return [kin.ar.num(0)]

    def gamma(self, kin, drive):
        return [kin.ar.num(0)]


@dataclass
class AngleDriver:
    """The crank drive: ``phi_i = theta(t)``; per position theta (degrees), its rate and acceleration.

    :meth:`Snapshot.driver_torque` is the torque the drive applies to the body
    (counter-clockwise positive): the input torque the motion needs.
    """

    name: str
    body_i: Body
    size = 1

    def residuals(self, kin, drive):
        return [kin.angle(self.body_i) - drive.of(self.name).angle]

    def jacobian(self, kin):
        one, zero = kin.ar.num(1), kin.ar.num(0)
        row = {}
        _add(row, self.body_i, (zero, zero, one))
        return [row]

    def nu(self, kin, drive):
        return [drive.of(self.name).rate]

    def gamma(self, kin, drive):
        return [drive.of(self.name).acceleration]


@dataclass
class Drive:
    """The driver's value at one position: angle (radians), rate (rad/s), acceleration (rad/s^2).

    ``others`` holds the values of further drivers by name (a LengthDriver's length,
    rate and acceleration in the model's units); every driver reads its own with
    :meth:`of`, the crank's AngleDriver the main values.
    """

    angle: object
    rate: object
    acceleration: object
    others: dict = field(default_factory=dict)

    def of(self, name: str) -> "Drive":
        """The values of driver ``name`` (the main ones unless ``others`` has it)."""
        return self.others.get(name, self)


def _arms(constraint):
    """The (body, local point) pairs whose arms enter a constraint's Jacobian."""
    pairs = []
    for body_attr, point_attr in (("body_i", "local_i"), ("body_j", "local_j")):
        body, local = getattr(constraint, body_attr, None), getattr(constraint, point_attr, None)
        if body is not None and local is not None:
            pairs.append((body, local))
    return pairs


# --------------------------------------------------------------------------- loads

@dataclass
class PointLoad:
    """A force on ``body`` at ``point``; ``force(snapshot) -> (Fx, Fy)`` global components.

    The callable sees the solved kinematics (positions, velocities,
    accelerations), so loads may depend on the motion (e.g. P = 650 v|v|).
    """

    body: Body
    point: object
    force: Callable

    def __post_init__(self):
        self.local = _resolve(self.body, self.point)


@dataclass
class Couple:
    """A couple on ``body``; ``torque(snapshot)`` counter-clockwise positive."""

    body: Body
    torque: Callable


@dataclass
class UnknownLoad:
    """The one load of unknown size that balances the motion (the contract's Q(n) choice).

    A force of magnitude X on ``body`` at ``point`` along the unit vector
    ``direction(snapshot)``, or, with ``point=None``, a couple X on ``body``
    (counter-clockwise positive).  With an UnknownLoad the crank's drive only
    prescribes the motion: its torque is held at zero and X takes its place.
    """

    body: Body
    point: object = None
    direction: Callable | None = None

    def __post_init__(self):
        self.local = None if self.point is None else _resolve(self.body, self.point)
