"""Planar vector helpers shared by every linkage.

Points and vectors of the plane are complex numbers ``x + 1j*y`` (Python complex
numbers for one position, numpy complex arrays for a whole cycle at once: every
formula is written once against :mod:`yaseer.linkages.numerics`): a rotation by 90 degrees counter-clockwise is a
multiplication by ``1j`` and ``u(t) = exp(1j*t)`` is the unit vector at angle ``t``.
Angles inside this package are radians unless a name says ``_deg``; angular rates
are rad/s and rad/s**2, counter-clockwise positive.
"""

from __future__ import annotations

from collections import namedtuple  # records (not typing.NamedTuple: importing typing costs start-up)

from yaseer.linkages.errors import LockedError
from yaseer.linkages.numerics import QUADRANTS, SCALAR, math_for

# A value of this module: a Python number for one position, a numpy array for many.
Values = "float | complex | numpy.ndarray"


def unit(angle, xp=None):
    """The unit vector u(angle), angle in radians, as a complex number."""
    return (xp or math_for(angle)).unit(angle)


def unit_degrees(angle_deg, xp=None):
    """The unit vector u(angle) for an angle in degrees, exact at multiples of 90
    (cos 90 = 0, as a pocket computer in degree mode gives it), so dead centres and
    vertical axes given as 90, 180, 270 are exact."""
    xp = xp or math_for(angle_deg)
    if xp.scalar:
        return xp.unit_degrees(xp.float(angle_deg))
    import numpy as np

    angle = np.asarray(angle_deg, dtype=float)
    turn = np.mod(angle, 360.0)
    vector = np.exp(1j * np.radians(angle))
    on_axis = (np.mod(turn, 90.0) == 0.0) & (turn < 360.0)  # mod gives 360.0 for -1e-17
    if np.any(on_axis):
        axes = np.array(list(QUADRANTS.values()))  # u(0, 90, 180, 270)
        if vector.ndim == 0:
            return axes[int(turn // 90.0)]
        vector[on_axis] = axes[(turn[on_axis] // 90.0).astype(int)]
    return vector


def cross(p, q):
    """The z component of p x q (positive when q is counter-clockwise of p)."""
    return p.real * q.imag - p.imag * q.real


def dot(p, q):
    """The scalar product p . q."""
    return p.real * q.real + p.imag * q.imag


def normalize_degrees(angle_deg):
    """An angle in degrees brought into the half-open range (-180, 180]."""
    return 180.0 - (180.0 - math_for(angle_deg).float(angle_deg)) % 360.0


def any_nonzero(*values) -> bool:
    """True when any element of any of ``values`` is non-zero (a motion is asked for)."""
    xp = math_for(*values)
    return any(xp.any(xp.float(value) != 0) for value in values)


# |sin| of the angle between two directions below which they count as parallel.
PARALLEL_TOLERANCE = 1e-12


def solve_two_directions(rhs, first, second, xp=None):
    """Real x1, x2 with ``x1*first + x2*second == rhs`` (all complex vectors).

    Raises :class:`LockedError` where ``first`` and ``second`` are parallel: the
    loop has no unique rate there (a toggle or branch point).
    """
    xp = xp or math_for(first, second)
    # Each direction in a unit of its own size (a power of two: exact, the same bits as before):
    # |first| * |second| of a mechanism measured in 1E-165 units would underflow to 0.
    unit_1, unit_2 = xp.unit_of(abs(first)), xp.unit_of(abs(second))
    first, second = first / unit_1, second / unit_2
    determinant = cross(first, second)
    if xp.any(abs(determinant) <= PARALLEL_TOLERANCE * abs(first) * abs(second)):
        raise LockedError("the velocity directions are parallel (toggle or branch point)")
    return cross(rhs, second) / determinant / unit_1, cross(first, rhs) / determinant / unit_2


class Motion(namedtuple("Motion", "pos vel acc")):
    """Position ``pos`` (length units), velocity ``vel`` (per s) and acceleration ``acc``
    (per s**2) of a point, each :data:`Values`, ``x + 1j*y`` in the frame of the crank pivot Ao."""

    __slots__ = ()


class Rotation(namedtuple("Rotation", "angle omega alpha")):
    """Inclination ``angle`` (radians, not normalised), angular velocity ``omega`` (rad/s)
    and angular acceleration ``alpha`` (rad/s**2) of a link, counter-clockwise positive
    (each :data:`Values`)."""

    __slots__ = ()

    @property
    def degrees(self):
        """The inclination in degrees, in (-180, 180]."""
        return normalize_degrees(math_for(self.angle).degrees(self.angle))


class Stretch(namedtuple("Stretch", "value rate accel")):
    """A length ``value`` (length units) and its first and second time derivatives
    ``rate`` and ``accel`` (each :data:`Values`)."""

    __slots__ = ()


def fixed_point(position, xp=None) -> Motion:
    """A point of the ground: it neither moves nor accelerates."""
    xp = xp or math_for(position)
    pos = xp.complex(position)
    zero = xp.zeros_like(pos)
    return Motion(pos, zero, zero)


def arm(distance, offset_deg, direction, xp=None):
    """The vector ``distance`` long at ``offset_deg`` degrees counter-clockwise from
    the unit vector ``direction``."""
    xp = xp or math_for(distance, offset_deg, direction)
    return xp.float(distance) * direction * xp.unit(xp.radians(offset_deg))


def rigid_point(origin: Motion, link: Rotation, distance, offset_deg, direction=None) -> Motion:
    """A point of a rigid link, ``distance`` from ``origin`` (a point of the link) at
    ``offset_deg`` degrees counter-clockwise from the link's reference line, whose
    inclination and rates are ``link``; ``direction`` is u(link.angle) when the
    caller has it already (it saves a complex exponential over the positions).

    v = v_origin + omega k x r and a = a_origin + alpha k x r - omega**2 r, r = origin->point.
    """
    r = arm(distance, offset_deg, unit(link.angle) if direction is None else direction)
    pos = origin.pos + r
    vel = origin.vel + 1j * link.omega * r
    acc = origin.acc + (1j * link.alpha - link.omega**2) * r
    return Motion(pos, vel, acc)


def crank_pin(length: Stretch, crank: Rotation, direction=None) -> Motion:
    """The pin at the end of a flexible crank pivoted at the origin.

    pos = a u, vel = (a' + i a w) u, acc = (a'' - a w**2 + i (a alpha + 2 a' w)) u,
    u = u(crank angle) (or ``direction``, the same vector computed exactly in
    degrees): the pin slides along the turning crank.
    """
    a, a_dot, a_ddot = length
    u = unit(crank.angle) if direction is None else direction
    pos = a * u
    vel = (a_dot + 1j * a * crank.omega) * u
    acc = (a_ddot - a * crank.omega**2 + 1j * (a * crank.alpha + 2 * a_dot * crank.omega)) * u
    return Motion(pos, vel, acc)


def still(motion: Motion) -> Motion:
    """``motion`` with its velocity and acceleration set exactly to zero."""
    zero = math_for(motion.pos).zeros_like(motion.pos)
    return Motion(motion.pos, zero, zero)


def perpendicular_direction(reference_direction, offset_deg, distance):
    """The direction of a perpendicular point load (Shared rules of the contract).

    The load acts at the point ``distance`` from the link's reference joint at
    ``offset_deg`` from the reference line (the unit vector ``reference_direction``),
    perpendicular to joint->point and counter-clockwise about the joint:
    u(reference + H + 90 deg), reversed when ``distance`` is negative (the point
    then lies the other way); at distance 0 it is u(reference + H + 90 deg).
    """
    xp = math_for(reference_direction, offset_deg, distance)
    sign = xp.where(xp.float(distance) < 0, -1.0, 1.0)
    return sign * reference_direction * xp.unit(xp.radians(offset_deg) + xp.pi / 2)


class DrivenCrank(namedtuple("DrivenCrank", "rotation length pin moving")):
    """The driving crank of a call: its ``rotation`` (a :class:`Rotation`), its (flexible)
    ``length`` (a :class:`Stretch`), the :class:`Motion` of its ``pin`` A, and whether any
    crank rate is non-zero (``moving``; when not, A's velocity and acceleration are exactly
    0 and no rates are computed)."""

    __slots__ = ()


def driven_crank(crank_length, crank_angle_deg, omega, alpha, crank_length_rate, crank_length_accel, *,
                 exact_degrees: bool = True) -> DrivenCrank:
    """The crank inputs every linkage shares, as arrays: angle in degrees, omega,
    alpha in rad/s, rad/s**2, the length and its rates.

    ``exact_degrees``: the pin's direction is exact at multiples of 90 degrees (as
    a pocket computer in degree mode gives it); the alternative methods pass False
    and take cos and sin of the angle in radians, as their sources do.
    """
    xp = math_for(crank_length, crank_angle_deg, omega, alpha, crank_length_rate, crank_length_accel)
    length = Stretch(xp.float(crank_length), xp.float(crank_length_rate), xp.float(crank_length_accel))
    rotation = Rotation(xp.radians(xp.float(crank_angle_deg)), xp.float(omega), xp.float(alpha))
    moving = any_nonzero(omega, alpha, crank_length_rate, crank_length_accel)
    pin = crank_pin(length, rotation, unit_degrees(crank_angle_deg, xp) if exact_degrees else None)
    return DrivenCrank(rotation, length, pin if moving else still(pin), moving)


class CrankedLinkage:
    """Base of the linkages' kinematics results, whose ``crank`` (a :class:`Rotation`)
    turns about the origin Ao.

    A result is immutable and made from its ``FIELDS`` in order, compared, hashed and
    shown by them as a frozen dataclass would be, but a plain class: importing
    dataclasses costs every start several milliseconds.

    ``FRAMES`` names, for each moving body, how its points are given: (the attribute
    holding the Motion of the joint they are measured from, None for Ao; the
    attribute holding the body's Rotation; True where the reference line runs from
    that joint the other way, inclination + 180 deg, as for the rod B->A).
    """

    crank: Rotation
    FIELDS: tuple[str, ...] = ("crank",)  # class constants (typing's ClassVar is not imported: start-up)
    FRAMES: dict[str, tuple[str | None, str, bool]] = {"crank": (None, "crank", False)}

    def __init__(self, *values) -> None:
        if len(values) != len(self.FIELDS):
            raise TypeError(f"{type(self).__name__} takes {len(self.FIELDS)} values ({', '.join(self.FIELDS)}), "
                            f"not {len(values)}")
        self.__dict__.update(zip(self.FIELDS, values))

    def __setattr__(self, name: str, value) -> None:
        raise AttributeError(f"cannot assign to field {name!r} of an immutable {type(self).__name__}")

    __delattr__ = __setattr__

    def _values(self) -> tuple:
        return tuple(getattr(self, name) for name in self.FIELDS)

    def __eq__(self, other) -> bool:
        if other.__class__ is not self.__class__:
            return NotImplemented
        return self._values() == other._values()

    def __hash__(self) -> int:
        return hash(self._values())

    def __repr__(self) -> str:
        return f"{type(self).__name__}({', '.join(f'{name}={getattr(self, name)!r}' for name in self.FIELDS)})"

    def unit_vector(self, link: str, reverse: bool = False):
        """u(inclination) of the link named ``link`` (``-u`` with ``reverse``: its line
        measured from the other end), computed once per result and kept."""
        kept = self.__dict__.setdefault("_unit_vectors", {})  # the result is immutable; its __dict__ is not
        if link not in kept:
            kept[link] = unit(getattr(self, link).angle)
        return -kept[link] if reverse else kept[link]

    def body_point(self, body: str, distance, offset_deg) -> Motion:
        """The motion of a point of ``body`` (a key of ``FRAMES``): ``distance`` from its
        reference joint, ``offset_deg`` counter-clockwise from its reference line."""
        origin, link, reverse = self.FRAMES[body]
        start = fixed_point(0j, SCALAR) if origin is None else getattr(self, origin)
        return rigid_point(start, getattr(self, link), distance, offset_deg, self.unit_vector(link, reverse))

    def body_position(self, body: str, distance, offset_deg):
        """The position alone of :meth:`body_point` (no rates computed)."""
        origin, link, reverse = self.FRAMES[body]
        start = 0j if origin is None else getattr(self, origin).pos
        return start + arm(distance, offset_deg, self.unit_vector(link, reverse))

    def load_direction(self, body: str, distance, offset_deg):
        """The direction of the perpendicular point load at (``distance``, ``offset_deg``)
        of ``body`` (:func:`perpendicular_direction`)."""
        _, link, reverse = self.FRAMES[body]
        return perpendicular_direction(self.unit_vector(link, reverse), offset_deg, distance)

    def crank_point(self, distance, offset_deg) -> Motion:
        """A point of the crank: ``distance`` from Ao, ``offset_deg`` from Ao->A."""
        return self.body_point("crank", distance, offset_deg)
