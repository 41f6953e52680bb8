"""Continuous branch tracking for the four-bar (the contract's ``L(10) = -1``).

Program 2 holds a fixed assembly flag: B left (uncrossed, +1) or right (crossed,
-1) of the directed line A->Bo.  A real linkage does not keep to one side: at a
*change point* (all four joints in line, possible when s + l = p + q) the two
assemblies meet and a linkage moving through continues smoothly on the *other*
side; at a *toggle* (coupler and follower in line, the crank at a limit) a crank
that turns back continues on the other side too.  Tracking follows the motion:
for each position (in the order given) it takes, of the two assemblies from
:func:`yaseer.linkages.fourbar.fourbar_closed`, the one nearest the linear
extrapolation (in the crank angle) of the last two tracked positions of B, and
reports every change of side as a :class:`BranchSwitch`.  Extrapolation carries
the motion smoothly through a change point; at a toggle B's path has a cusp in
the crank angle instead, so a crank that turns back exactly at the toggle
position (a position where both assemblies coincide) takes the other assembly,
while a crank that turns back anywhere else retraces its own.

At a point where the two assemblies coincide (a change point or toggle hit
exactly) the velocity equations are singular.  There, as Jong does for seed 004,
the velocities come from the acceleration equations: along the common line the
acceleration loop gives b w3^2 + s c w4^2 = A''.n, which with the one velocity
equation left is a quadratic with two roots, one per assembly passing through
(:func:`collinear_rates`); the tracked motion takes the root that continues the
incoming motion.  The accelerations there are the two-sided limit along the
tracked motion (regular formula at theta -/+ 1e-4 rad, averaged; error of order 1e-8).  Where the crank
pin's velocity has a component along the line (a toggle driven by the crank) no
velocity satisfies the loop and the position is locked (``LockedError``).

Angles in degrees at the interface, rates in rad/s and rad/s**2, counter-clockwise
positive; the follower is reported as the vector B->Bo like Program 2's T(14).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from yaseer.linkages.errors import LockedError
from yaseer.linkages.fourbar import CROSSED, UNCROSSED, FourBar, fourbar_closed
from yaseer.linkages.planar import Motion, Rotation, Stretch, crank_pin, fixed_point

COINCIDENT = 1e-7     # assemblies closer than this (times b + c) are one point
RESTART_STEP_DEG = 90.0  # a larger crank step is a new motion, not a continuation
LIMIT_STEP = 1e-4     # radians either side of a singular point for the limits (error ~ step**2)


@dataclass(frozen=True)
class Geometry:
    """Program 2's lengths: ground Ao->Bo (length, degrees), crank a, coupler b, follower c."""

    ground_length: float
    ground_angle_deg: float
    crank_length: float
    coupler_length: float
    follower_length: float

    def positions(self, theta_deg, branch) -> np.ndarray:
        """Pin B (complex) for the crank angles ``theta_deg`` on side ``branch``."""
        return fourbar_closed(*self.astuple(), theta_deg, branch=branch).pin_b.pos

    def astuple(self) -> tuple:
        return (self.ground_length, self.ground_angle_deg, self.crank_length,
                self.coupler_length, self.follower_length)

    @property
    def scale(self) -> float:
        return abs(self.coupler_length) + abs(self.follower_length)


@dataclass(frozen=True)
class BranchSwitch:
    """A change of assembly between two tracked positions.

    ``crank_angle_deg``: where it was detected (the first position on the new side);
    ``kind``: ``"change point"`` (the crank kept its sense) or ``"toggle"`` (it turned back).
    """

    crank_angle_deg: float
    from_branch: int
    to_branch: int
    kind: str

    def describe(self) -> str:
        names = {UNCROSSED: "uncrossed", CROSSED: "crossed"}
        return (f"branch switch at crank angle {self.crank_angle_deg:g} deg ({self.kind}): "
                f"{names[self.from_branch]} -> {names[self.to_branch]}")


@dataclass
class _History:
    """The last tracked positions: (crank angle deg, B, side, singular)."""

    points: list = field(default_factory=list)
    last_direction: float = 0.0

    def add(self, theta: float, pos: complex, side: int, singular: bool) -> None:
        self.points = (self.points + [(theta, pos, side, singular)])[-2:]

    def predict(self, theta: float) -> complex | None:
        if not self.points:
            return None
        theta1, pos1 = self.points[-1][:2]
        if len(self.points) < 2 or self.points[-2][0] == theta1:
            return pos1
        theta0, pos0 = self.points[-2][:2]
        return pos1 + (pos1 - pos0) * (theta - theta1) / (theta1 - theta0)

    def direction(self, theta: float) -> float:
        """+1 if the crank angle is increasing into ``theta``, -1 if decreasing, 0 unknown."""
        if not self.points or self.points[-1][0] == theta:
            return 0.0
        return math.copysign(1.0, theta - self.points[-1][0])

    def turned_back(self, theta: float) -> bool:
        if len(self.points) < 2:
            return False
        before = self.points[-1][0] - self.points[-2][0]
        return before * (theta - self.points[-1][0]) < 0


def _choose(history: _History, theta: float, up: complex, down: complex, start_branch: int,
            scale: float) -> tuple[int, bool]:
    """(side, singular) for one position: nearest the extrapolation, or the start branch."""
    singular = abs(up - down) <= COINCIDENT * scale
    previous_side = history.points[-1][2] if history.points else start_branch
    if singular:
        return previous_side, True
    predicted = history.predict(theta)
    if predicted is None:
        return start_branch, False
    if history.points[-1][3] and len(history.points) == 1:
        return start_branch, False  # the motion starts at a singular point: leave on start_branch
    if history.points[-1][3] and history.turned_back(theta):
        return -previous_side, False  # back out of a toggle: the other assembly
    return (UNCROSSED if abs(up - predicted) <= abs(down - predicted) else CROSSED), False


def collinear_rates(pin_a: Motion, coupler_vec: complex, follower_vec: complex) -> list[tuple[float, float]]:
    """The (w3, w4) pairs possible where coupler and follower are in line.

    ``pin_a``: scalar motion of the crank pin; ``coupler_vec`` A->B, ``follower_vec``
    B->Bo.  Velocity along the normal t = i u3: A'.t + b w3 + s c w4 = 0 (s = +1 if
    the follower points the same way as the coupler, -1 if opposite); acceleration
    along u3: A''.u3 = b w3^2 + s c w4^2.  Raises LockedError where A'.u3 != 0.
    """
    b, c = abs(coupler_vec), abs(follower_vec)
    u3 = coupler_vec / b
    s = 1.0 if (follower_vec * np.conj(coupler_vec)).real > 0 else -1.0
    vel, acc = complex(pin_a.vel), complex(pin_a.acc)
    along = (vel * np.conj(u3)).real
    if abs(along) > 1e-9 * max(abs(vel), 1e-300):
        raise LockedError("toggle: the crank pin moves along the line of coupler and follower")
    p = (vel * np.conj(1j * u3)).real
    q = (acc * np.conj(u3)).real
    quadratic = (b * c + s * b * b, 2 * s * p * b, s * p * p - c * q)
    roots = _real_roots(*quadratic)
    return [(w3, -(p + b * w3) / (s * c)) for w3 in roots]


def _real_roots(a2: float, a1: float, a0: float) -> list[float]:
    if a2 == 0:
        if a1 == 0:
            raise LockedError("branch point: the acceleration equations leave the velocity free")
        return [-a0 / a1]
    disc = a1 * a1 - 4 * a2 * a0
    if disc < 0:
        raise LockedError("branch point: no real velocity satisfies the acceleration equations")
    root = math.sqrt(disc)
    return [(-a1 + root) / (2 * a2), (-a1 - root) / (2 * a2)]


@dataclass
class Tracked:
    """The tracked motion: Program 2 kinematics per position, the side used, where
    the rates came from the singular-point rule, and the switches."""

    fourbar: FourBar
    branch: np.ndarray
    singular: np.ndarray
    switches: list[BranchSwitch]


def _point(geometry: Geometry, theta_deg: float, omega: float, alpha: float, side: int, rates: dict) -> FourBar:
    return fourbar_closed(*geometry.astuple(), theta_deg, omega, alpha, branch=side, **rates)


def _singular_point(geometry: Geometry, theta: float, omega: float, alpha: float, incoming: int,
                    direction: float, rates: dict, starting: bool = False) -> FourBar:
    """Kinematics at a point where both assemblies coincide (see the module docstring).

    ``incoming``: the side the motion arrives on, or (``starting``) leaves on."""
    base = fourbar_closed(*geometry.astuple(), theta, branch=incoming)
    length = Stretch(float(geometry.crank_length), float(rates.get("crank_length_rate", 0.0)),
                     float(rates.get("crank_length_accel", 0.0)))
    crank = Rotation(math.radians(theta), float(omega), float(alpha))
    pin_a = crank_pin(length, crank)
    pos_b = complex(base.pin_b.pos)
    coupler_vec = pos_b - complex(pin_a.pos)
    follower_vec = complex(base.pivot.pos) - pos_b
    roots = collinear_rates(pin_a, coupler_vec, follower_vec)
    step = math.degrees(LIMIT_STEP) * (direction or 1.0)
    sides = (UNCROSSED, CROSSED)
    befores = {side: _point(geometry, theta - step, omega, alpha, side, rates) for side in sides}
    afters = {side: _point(geometry, theta + step, omega, alpha, side, rates) for side in sides}
    known = afters[incoming] if starting else befores[incoming]
    w3, w4 = min(roots, key=lambda r: abs(r[0] - float(known.coupler.omega)))

    def nearest(candidates: dict) -> FourBar:
        return min(candidates.values(), key=lambda fb: abs(float(fb.coupler.omega) - w3))

    before, after = nearest(befores), nearest(afters)
    a3 = 0.5 * float(before.coupler.alpha + after.coupler.alpha)
    a4 = 0.5 * float(before.follower.alpha + after.follower.alpha)
    vel_b = complex(pin_a.vel) + 1j * w3 * coupler_vec
    acc_b = complex(pin_a.acc) + (1j * a3 - w3 ** 2) * coupler_vec
    return FourBar(crank, length, Rotation(base.coupler.angle, w3, a3), Rotation(base.follower.angle, w4, a4),
                   pin_a, Motion(pos_b, vel_b, acc_b), fixed_point(base.pivot.pos), True)


def _advance(history: _History, geometry: Geometry, theta: float, up: complex, down: complex,
             start_branch: int) -> tuple[int, bool, BranchSwitch | None]:
    """Choose the side at the next position, record it, and return (side, singular, switch)."""
    side, singular = _choose(history, theta, up, down, start_branch, geometry.scale)
    switch = None
    if history.points and side != history.points[-1][2]:
        kind = "toggle" if history.turned_back(theta) else "change point"
        switch = BranchSwitch(theta, history.points[-1][2], side, kind)
    direction = history.direction(theta)
    history.add(theta, up if side == UNCROSSED else down, side, singular)
    history.last_direction = direction
    return side, singular, switch


def _is_moving(*values) -> bool:
    return any(np.any(np.asarray(v) != 0) for v in values)


class BranchTracker:
    """Tracks one four-bar call by call (what Program 2 needs for ``L(10) = -1``).

    A change of geometry, or a crank-angle step of more than ``RESTART_STEP_DEG``
    (not a continuous motion: e.g. a listing run again from its first angle),
    starts a new track on ``start_branch``.
    """

    def __init__(self, start_branch: int = UNCROSSED):
        self.start_branch = start_branch
        self.geometry: Geometry | None = None
        self.history = _History()
        self.switches: list[BranchSwitch] = []
        self._pending = None

    @property
    def branch(self) -> int:
        return self.history.points[-1][2] if self.history.points else self.start_branch

    def step(self, geometry: Geometry, theta_deg: float, omega: float = 0.0, alpha: float = 0.0, *,
             defer: bool = False, **rates) -> tuple[FourBar, BranchSwitch | None]:
        """Kinematics at the next position of the motion, and the switch made to reach it.

        With ``defer`` the track moves on only when :meth:`accept` is called (a
        caller that may still fail after the kinematics, e.g. in its forces)."""
        theta = float(theta_deg)
        continuing = geometry == self.geometry and self.history.points \
            and abs(theta - self.history.points[-1][0]) <= RESTART_STEP_DEG
        history = _History(list(self.history.points)) if continuing else _History()
        up, down = (complex(geometry.positions(theta, side)) for side in (UNCROSSED, CROSSED))
        side, singular, switch = _advance(history, geometry, theta, up, down, self.start_branch)
        if singular and _is_moving(omega, alpha, *rates.values()):
            direction = history.last_direction or math.copysign(1.0, omega or 1.0)
            result = _singular_point(geometry, theta, omega, alpha, side, direction, rates,
                                     starting=len(history.points) == 1)
        else:
            result = _point(geometry, theta, omega, alpha, side, rates)
        # only a successful call moves the track on (a failed one leaves it as it was)
        self._pending = (geometry, history, switch)
        if not defer:
            self.accept()
        return result, switch

    def accept(self) -> None:
        """Move the track on to the last step's position."""
        if self._pending is None:
            return
        self.geometry, self.history, switch = self._pending
        self._pending = None
        if switch:
            self.switches.append(switch)


def track(geometry: Geometry, crank_angles_deg, omega=0.0, alpha=0.0, *, start_branch: int = UNCROSSED,
          **rates) -> Tracked:
    """Follow the motion through ``crank_angles_deg`` (in that order).

    ``omega``, ``alpha`` (and ``crank_length_rate``/``crank_length_accel``) are
    scalars or arrays matching the angles.  Raises AssemblyError where a position
    does not close, LockedError at a toggle the crank drives into.
    """
    thetas = np.atleast_1d(np.asarray(crank_angles_deg, dtype=float))
    every = {"omega": omega, "alpha": alpha, **rates}
    every = {k: np.broadcast_to(np.asarray(v, float), thetas.shape) for k, v in every.items()}
    ups, downs = geometry.positions(thetas, UNCROSSED), geometry.positions(thetas, CROSSED)
    history, switches = _History(), []
    branch = np.zeros(thetas.shape, int)
    singular = np.zeros(thetas.shape, bool)
    directions = np.zeros(thetas.shape)
    for k, theta in enumerate(thetas):
        branch[k], singular[k], switch = _advance(history, geometry, float(theta), complex(ups[k]),
                                                  complex(downs[k]), start_branch)
        directions[k] = history.last_direction
        if switch:
            switches.append(switch)
    regular = np.flatnonzero(~singular)
    pieces = [(regular, fourbar_closed(*geometry.astuple(), thetas[regular], every["omega"][regular],
                                       every["alpha"][regular], branch=branch[regular],
                                       **{k: v[regular] for k, v in every.items() if k not in ("omega", "alpha")}))]
    moving = _is_moving(*every.values())
    for k in np.flatnonzero(singular):
        values = {name: float(v[k]) for name, v in every.items()}
        omega_k, alpha_k = values.pop("omega"), values.pop("alpha")
        if moving:
            direction = directions[k] or math.copysign(1.0, omega_k or 1.0)
            point = _singular_point(geometry, thetas[k], omega_k, alpha_k, int(branch[k]), direction, values,
                                    starting=k == 0)
        else:
            point = _point(geometry, thetas[k], omega_k, alpha_k, int(branch[k]), values)
        pieces.append((np.array([k]), point))
    return Tracked(_merge(len(thetas), pieces, moving), branch, singular, switches)


def _merge(n: int, pieces: list[tuple[np.ndarray, FourBar]], moving: bool) -> FourBar:
    """One FourBar of length-n arrays from results at the given indices."""
    def merged(kind, getter):
        parts = []
        for component in range(len(kind._fields)):
            values = [(index, getter(result)[component]) for index, result in pieces if len(index)]
            dtype = np.result_type(*(np.asarray(v) for _, v in values))
            out = np.zeros(n, dtype=dtype)
            for index, value in values:
                out[index] = np.broadcast_to(value, index.shape)
            parts.append(out)
        return kind(*parts)

    return FourBar(
        merged(Rotation, lambda r: r.crank), merged(Stretch, lambda r: r.crank_length),
        merged(Rotation, lambda r: r.coupler), merged(Rotation, lambda r: r.follower),
        merged(Motion, lambda r: r.pin_a), merged(Motion, lambda r: r.pin_b),
        merged(Motion, lambda r: r.pivot), moving,
    )


def instant_centre(fourbar: FourBar) -> np.ndarray:
    """The coupler's instant centre C = A + i v_A / w3 (complex; nan where w3 = 0).

    Needs rates (a moving crank); at a change point it uses the tracked w3."""
    w3 = np.asarray(fourbar.coupler.omega, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        centre = fourbar.pin_a.pos + 1j * fourbar.pin_a.vel / w3
    return np.where(w3 == 0, np.nan + 0j, centre)
