"""A constraint-based planar multibody solver: the independent reference of yaseer.

Formulation (absolute coordinates, as in Haug's or Nikravesh's textbooks):
every rigid body ``i`` has coordinates ``q_i = (x_i, y_i, phi_i)``, the global
position of the origin of its drawing frame and the angle (radians,
counter-clockwise positive) of that frame.  Body-fixed points are given in the
drawing frame.  Constraints ``Phi(q, t) = 0``:

* :class:`Revolute` -- a pin: a point of body i coincides with a point of body j
  (or a fixed point of the ground): 2 equations.
* :class:`PointOnLine` -- a slider with free relative rotation (pin in a slot,
  slider block with a pin): a point of body i stays on a line fixed in body j
  (or the ground): 1 equation.  Add :class:`AngleLock` for a slider *without*
  relative rotation (a prismatic pair): 1 more equation.
* :class:`AngleDriver` -- the crank: ``phi_i - theta(t) = 0`` with theta, its
  rate and acceleration given per position: 1 equation.

Positions: Newton's method on ``Phi = 0`` (float continuation along the crank
angle, predictor from the tangent ``dq/dtheta``; an mpmath analysis polishes
each float position by Newton at its own precision).
Velocities: ``Phi_q qd = nu`` (``nu = -Phi_t``).  Accelerations:
``Phi_q qdd = gamma`` with gamma written out analytically per constraint.
Forces (d'Alembert): ``Phi_q^T lambda = Q_applied - Q_inertia``; the force a
constraint exerts on body i is ``-Phi_{q_i}^T lambda``.

Units are whatever the model uses (consistent set); angles given to the API are
degrees, rates rad/s and rad/s^2.  The number type is chosen per analysis
(:mod:`yaseer.reference.arithmetic`): the algebra below is written once.

This module knows nothing of BASIC or of yaseer.linkages.
"""

from __future__ import annotations

import math
from typing import Sequence

from yaseer.reference.arithmetic import FLOAT, SingularSystemError, arithmetic_for
from yaseer.reference.elements import (  # noqa: F401  (the solver's public vocabulary)
    AngleDriver, AngleLock, Body, Couple, Drive, LengthDriver, LocalPoint, MechanismError, PointLoad,
    PointOnLine, Revolute, UnknownLoad, _arms, _Kinematics, _resolve, cross, dot, normalise_degrees,
    perp, polar, rotate, xy)


# --------------------------------------------------------------------------- the mechanism

#: how far an analysis goes; each level includes the ones before it
LEVELS = ("positions", "velocities", "accelerations", "forces")


class Mechanism:
    """Bodies, constraints, loads, gravity and optionally the unknown load.

    The constraints must fix every coordinate once the drivers are given: the
    first AngleDriver is the crank (its angle is what analyses step along);
    further drivers (LengthDriver) get their values per analysis.  ``gravity`` is
    the acceleration of gravity, acting along -y on every mass; ``unknown`` the
    UnknownLoad that balances the motion in a force analysis (else the crank's
    drive torque does).
    """

    def __init__(self, bodies: Sequence[Body], constraints: Sequence, loads: Sequence = (), gravity=0,
                 unknown: UnknownLoad | None = None):
        self.bodies = {}
        for index, body in enumerate(bodies):
            body.index = index
            self.bodies[body.name] = body
        self.constraints = {}
        for constraint in constraints:
            if constraint.name in self.constraints:
                raise ValueError(f"two constraints named {constraint.name!r}")
            self.constraints[constraint.name] = constraint
        self.loads = list(loads)
        self.gravity = gravity
        self.unknown = unknown
        self.size = 3 * len(self.bodies)
        equations = sum(c.size for c in self.constraints.values())
        if equations != self.size:
            raise ValueError(f"{equations} constraint equations for {self.size} coordinates: "
                             "the reference solver needs a fully driven mechanism")
        self.rows = {}
        row = 0
        for constraint in self.constraints.values():
            self.rows[constraint.name] = range(row, row + constraint.size)
            row += constraint.size

    def body(self, name: str) -> Body:
        return self.bodies[name]

    # -- the constraint system in one arithmetic

    def _residuals(self, kin, drive):
        return [r for c in self.constraints.values() for r in c.residuals(kin, drive)]

    def _jacobian(self, kin):
        zero = kin.ar.num(0)
        dense = []
        for constraint in self.constraints.values():
            for sparse in constraint.jacobian(kin):
                row = [zero] * self.size
                for column, value in sparse.items():
                    row[column] = value
                dense.append(row)
        return dense

    def _stack(self, kin, drive, term):
        return [value for c in self.constraints.values() for value in getattr(c, term)(kin, drive)]

    def newton(self, q_guess, drive, ar=FLOAT, max_iterations=50, tolerance=None):
        """Positions: solve Phi(q) = 0 by Newton from ``q_guess``; returns q (list in ``ar``).

        Stops when the correction is below ``tolerance`` (default: the
        arithmetic's) relative to 1 + the largest coordinate.
        """
        tolerance = ar.tolerance if tolerance is None else tolerance
        q = [ar.num(v) for v in q_guess]
        previous_size = None
        for _ in range(max_iterations):
            kin = _Kinematics(ar, q)
            residual = self._residuals(kin, drive)
            try:
                step = ar.solve(self._jacobian(kin), [-r for r in residual])
            except SingularSystemError as exc:
                raise MechanismError(f"the mechanism cannot be assembled at crank angle "
                                     f"{ar.to_float(ar.degrees(drive.angle)):.12g} deg (Newton met a "
                                     "singular Jacobian)") from exc
            q = [a + b for a, b in zip(q, step)]
            scale = 1 + max(abs(v) for v in q)
            size = max(abs(s) for s in step)
            if size <= tolerance * scale:
                return q
            # At an ill-conditioned root the corrections stall at the roundoff floor
            # (about condition number x unit roundoff): accept, check_conditioning judges.
            if previous_size is not None and size >= previous_size / 2 and size <= tolerance ** 0.5 * scale:
                return q
            previous_size = size
        raise MechanismError(f"the mechanism cannot be assembled at crank angle "
                             f"{ar.to_float(ar.degrees(drive.angle)):.12g} deg (Newton did not "
                             "converge), or the position is singular (toggle, change point)")

    def velocities(self, q, drive, ar=FLOAT):
        """Solve Phi_q qd = nu."""
        kin = _Kinematics(ar, q)
        return self._solve(ar, self._jacobian(kin), self._stack(kin, drive, "nu"), "velocity")

    def accelerations(self, q, qd, drive, ar=FLOAT):
        """Solve Phi_q qdd = gamma."""
        kin = _Kinematics(ar, q, qd)
        return self._solve(ar, self._jacobian(kin), self._stack(kin, drive, "gamma"), "acceleration")

    def _solve(self, ar, rows, rhs, what):
        try:
            return ar.solve(rows, rhs)
        except SingularSystemError as exc:
            raise MechanismError(f"{what} equations are singular (a dead centre, toggle or "
                                 "change point: the constraints alone do not fix the motion)") from exc

    def multipliers(self, snapshot):
        """Forces: solve Phi_q^T lambda = Q_applied - Q_inertia (d'Alembert).

        With an UnknownLoad X: Phi_q^T lambda - X g = Q_applied - Q_inertia and the
        crank drive's multiplier = 0 (g: the generalised force of the unit load);
        X is stored as ``snapshot.unknown_value``.
        """
        ar = snapshot.ar
        kin = snapshot.kin
        transposed = [list(col) for col in zip(*self._jacobian(kin))]
        rhs = self._applied(snapshot)
        for body in self.bodies.values():
            inertial = self._inertia_force(kin, body)
            for offset in range(3):
                rhs[3 * body.index + offset] -= inertial[offset]
        if self.unknown is None:
            return self._solve(ar, transposed, rhs, "force")
        unit = self._unit_unknown(snapshot)
        rows = [row + [-g] for row, g in zip(transposed, unit)]
        drive_row = [ar.num(0)] * (self.size + 1)
        drive_row[self.rows[self._crank_driver().name][0]] = ar.num(1)
        try:
            solution = ar.solve(rows + [drive_row], rhs + [ar.num(0)])
        except SingularSystemError as exc:
            raise MechanismError("the unknown load cannot balance the mechanism in this position "
                                 "(it does no work on the motion)") from exc
        snapshot.unknown_value = solution[-1]
        return solution[:-1]

    def _crank_driver(self):
        for constraint in self.constraints.values():
            if isinstance(constraint, AngleDriver):
                return constraint
        raise ValueError("the mechanism has no crank drive (AngleDriver)")

    def _unit_unknown(self, snapshot):
        """Generalised force of the unknown load at unit magnitude."""
        ar, kin, load = snapshot.ar, snapshot.kin, self.unknown
        generalised = [ar.num(0)] * self.size
        k = 3 * load.body.index
        if load.local is None:
            generalised[k + 2] = ar.num(1)
            return generalised
        direction = load.direction(snapshot)
        arm = kin.arm(load.body, load.local)
        generalised[k], generalised[k + 1] = direction[0], direction[1]
        generalised[k + 2] = cross(arm, direction)
        return generalised

    def _inertia_force(self, kin, body):
        """Generalised inertia force (m a_G, m a_G; I alpha + arm x m a_G) of a body."""
        ar = kin.ar
        mass, inertia = ar.num(body.mass), ar.num(body.inertia)
        acc = kin.acceleration(body, body.centre)
        arm = kin.arm(body, body.centre)
        alpha = kin.qdd[3 * body.index + 2]
        force = (mass * acc[0], mass * acc[1])
        return (force[0], force[1], inertia * alpha + cross(arm, force))

    def _applied(self, snapshot):
        """Generalised applied forces: gravity, point loads, couples."""
        ar, kin = snapshot.ar, snapshot.kin
        generalised = [ar.num(0)] * self.size
        gravity = ar.num(self.gravity)

        def add_force(body, local, force):
            arm = kin.arm(body, local)
            k = 3 * body.index
            generalised[k] += force[0]
            generalised[k + 1] += force[1]
            generalised[k + 2] += cross(arm, force)

        for body in self.bodies.values():
            if gravity:
                add_force(body, body.centre, (ar.num(0), -ar.num(body.mass) * gravity))
        for load in self.loads:
            if isinstance(load, PointLoad):
                force = load.force(snapshot)
                add_force(load.body, load.local, (ar.num(force[0]), ar.num(force[1])))
            else:
                generalised[3 * load.body.index + 2] += ar.num(load.torque(snapshot))
        return generalised

    # -- whole analyses

    def condition(self, q, ar=FLOAT) -> float:
        """Condition number of the position Jacobian made dimensionless.

        With a characteristic length (the extent of the mechanism at ``q``),
        angle columns are divided by it (the unknown becomes length x angle) and
        the rows of angle constraints multiplied by it, so the number does not
        depend on the unit of length.  Infinite when singular.
        Estimated in float; above 1e13 an mpmath analysis recomputes it in its
        own precision.
        """
        import numpy as np

        kin = _Kinematics(ar, q)
        rows = self._scaled_jacobian(kin, ar.num(self._size_of(kin)))
        singular = np.linalg.svd(np.array([[ar.to_float(v) for v in row] for row in rows]), compute_uv=False)
        if ar is not FLOAT and (singular[-1] == 0 or singular[0] > 1e13 * singular[-1]):
            exact = ar.ctx.svd_r(ar.ctx.matrix(rows), compute_uv=False)
            singular = sorted((exact[i] for i in range(len(rows))), reverse=True)
        if singular[-1] == 0:
            return math.inf
        return float(singular[0] / singular[-1])

    def _size_of(self, kin):
        """The mechanism's extent at this position: the larger side of the box around its
        body origins and constraint points (float; 1 if it is a single point)."""
        xs, ys = [], []
        for constraint in self.constraints.values():
            for body, local in _arms(constraint):
                point = kin.position(body, local)
                xs.append(kin.ar.to_float(point[0]))
                ys.append(kin.ar.to_float(point[1]))
        for body in self.bodies.values():
            xs.append(kin.ar.to_float(kin.q[3 * body.index]))
            ys.append(kin.ar.to_float(kin.q[3 * body.index + 1]))
        extent = max(max(xs) - min(xs), max(ys) - min(ys))
        return extent if extent > 0 else 1.0

    def _scaled_jacobian(self, kin, length):
        """Jacobian rows with angle columns times 1/length and angle rows times length."""
        rows = []
        for constraint in self.constraints.values():
            angular = isinstance(constraint, (AngleLock, AngleDriver))
            for sparse in constraint.jacobian(kin):
                row = [kin.ar.num(0)] * self.size
                for column, value in sparse.items():
                    value = value * length if angular else value
                    row[column] = value / length if column % 3 == 2 else value
                rows.append(row)
        return rows

    def check_conditioning(self, q, drive, ar, accuracy, level="accelerations"):
        """(kappa, error bound); MechanismError if the bound exceeds ``accuracy``.

        Near a singular configuration (toggle, change point, dead point of a
        driven link) Newton's positions carry a relative error of about kappa*u
        (u the unit roundoff) and the rates, solved with that Jacobian, about
        kappa^2*u: the bound is kappa*u for ``level="positions"``, else kappa^2*u.
        """
        roundoff = 2.0 ** -53 if ar is FLOAT else 10.0 ** -ar.dps
        kappa = self.condition(q, ar)
        power = 1 if level == "positions" else 2
        bound = kappa ** power * roundoff if kappa < math.inf else math.inf
        if not bound <= accuracy:
            angle = ar.to_float(ar.degrees(drive.angle))
            raise MechanismError(
                f"singular configuration near crank angle {angle:.12g} deg (condition number "
                f"{kappa:.3g}: a toggle, change point or dead point where the constraints do not "
                f"fix the motion; {ar.name} arithmetic cannot give the "
                f"{'positions' if power == 1 else 'rates'} to {accuracy:g})")
        return kappa, bound

    def snapshot(self, q, drive, ar=FLOAT, *, level="accelerations") -> "Snapshot":
        """The state at position ``q`` computed up to ``level``.

        ``level``: "positions", "velocities", "accelerations" or "forces" (each
        includes the ones before it).
        """
        if level not in LEVELS:
            raise ValueError(f"level is one of {', '.join(LEVELS)}, not {level!r}")
        depth = LEVELS.index(level)
        qd = self.velocities(q, drive, ar) if depth >= 1 else None
        qdd = self.accelerations(q, qd, drive, ar) if depth >= 2 else None
        snap = Snapshot(self, ar, q, qd, qdd, drive)
        if depth >= 3:
            snap.lam = self.multipliers(snap)
        return snap

    def tangent(self, q, direction: Drive, ar=FLOAT):
        """dq/ds along a path of the drivers whose rates per unit s are ``direction``'s rates."""
        return self.velocities(q, direction, ar)

    def coordinates(self, placements: dict) -> list:
        """A coordinate vector from ``{body name: (x, y, angle_deg)}`` (e.g. a rough sketch)."""
        q = [0.0] * self.size
        for name, (x, y, angle_deg) in placements.items():
            k = 3 * self.body(name).index
            q[k:k + 3] = [float(x), float(y), FLOAT.radians(float(angle_deg))]
        return q

    def analyse(self, angles_deg, rate, acceleration, q_guess, *, number="float", dps=50,
                level="accelerations", max_step_deg=2.0, branch_check=None, home_deg=None,
                accuracy=1e-6, drives=None):
        """Analyse the mechanism at each driver angle of ``angles_deg`` (degrees, in order).

        ``rate``, ``acceleration``: the driver's rad/s and rad/s^2, numbers (the
        same at every position) or sequences (one per angle: theta(t) with any
        rate history).  ``drives``: the further drivers (LengthDriver) as
        ``{name: (values, rates, accelerations)}``, each a number or one per
        angle.  ``level``: how far to go ("positions", "velocities",
        "accelerations", "forces").  ``q_guess``: coordinates near the first
        position; the first position is found by Newton from it, each next one
        by continuation from the previous (float steps of at most
        ``max_step_deg`` of the crank, the other drivers interpolated,
        predictor from the tangent).  With ``home_deg``, ``q_guess`` is near
        the position at driver angle ``home_deg`` (others at their first
        values) and the continuation starts there.  ``number="mpmath"``
        polishes every position by Newton at ``dps`` digits and computes rates
        and forces there.  ``branch_check(snapshot)`` may raise MechanismError
        when the assembly branch is lost.  Each position is checked for
        conditioning (:meth:`check_conditioning`): where the estimated relative
        error exceeds ``accuracy`` the analysis stops with MechanismError
        instead of returning a wrong number.  Returns a list of :class:`Snapshot`.
        """
        ar = arithmetic_for(number, dps)
        angles = list(angles_deg)
        count = len(angles)
        rates, accelerations = _per_position(rate, count), _per_position(acceleration, count)
        others = {name: [_per_position(v, count) for v in values] for name, values in (drives or {}).items()}
        states = [(angle, {name: values[0][k] for name, values in others.items()}) for k, angle in enumerate(angles)]
        results = []
        q_float, previous = q_guess, None
        if home_deg is not None and states:
            previous = (home_deg, states[0][1])
            q_float = self._continue(q_guess, None, previous, max_step_deg=max_step_deg)
        for k, state in enumerate(states):
            q_float, q = self._position(q_float, previous, state, ar, max_step_deg)
            previous = state
            drive = self._drive(ar, state, rates[k], accelerations[k],
                                {name: (values[1][k], values[2][k]) for name, values in others.items()})
            condition, bound = self.check_conditioning(q, drive, ar, accuracy, level)
            snap = self.snapshot(q, drive, ar, level=level)
            snap.condition, snap.error_bound = condition, bound
            if branch_check is not None:
                branch_check(snap)
            results.append(snap)
        return results

    def _position(self, q_float, previous, state, ar, max_step_deg):
        """(float position, position in ``ar``) at driver ``state``, continuing from ``previous``.

        A state is (crank angle in degrees, {other driver: value}); its numbers
        may be mpf: the mpmath polish takes them exactly.  A float stage that
        only guesses for mpmath stops at 1e-9: near a singular position float
        Newton cannot reach 1e-13, the mpmath polish can.
        """
        loose = None if ar is FLOAT else 1e-9
        q_float = self._continue(q_float, previous, state, max_step_deg=max_step_deg, tolerance=loose)
        if ar is FLOAT:
            return q_float, q_float
        return q_float, self.newton(q_float, self._drive(ar, state, 0, 0), ar, max_iterations=200)

    @staticmethod
    def _drive(ar, state, rate, acceleration, other_rates=None):
        """The Drive at ``state`` with the crank's rate and acceleration and the others' (rate, accel)."""
        angle_deg, values = state
        other_rates = other_rates or {}
        others = {name: Drive(ar.num(value), ar.num(other_rates.get(name, (0, 0))[0]),
                              ar.num(other_rates.get(name, (0, 0))[1]))
                  for name, value in values.items()}
        return Drive(ar.radians(ar.num(angle_deg)), ar.num(rate), ar.num(acceleration), others)

    def _continue(self, q, previous, state, *, max_step_deg, tolerance=None):
        """Float positions: Newton at ``state`` from ``q`` (at ``previous``; None: ``q`` is a
        guess for ``state`` itself), in steps along the tangent, the drivers interpolated."""
        target = (float(state[0]), {name: float(v) for name, v in state[1].items()})
        if previous is None:
            return self.newton(q, self._drive(FLOAT, target, 0, 0), tolerance=tolerance, max_iterations=100)
        start = (float(previous[0]), {name: float(v) for name, v in previous[1].items()})
        span = target[0] - start[0]
        steps = max(1, int(abs(span) // max_step_deg) + (abs(span) % max_step_deg > 0))
        per_step = self._drive(FLOAT, (0.0, {name: 0.0 for name in target[1]}), FLOAT.radians(span / steps), 0,
                               {name: ((target[1][name] - start[1][name]) / steps, 0) for name in target[1]})
        for k in range(1, steps + 1):
            predicted = [v + s for v, s in zip(q, self.tangent(q, per_step))]
            there = (start[0] + span * k / steps,
                     {name: start[1][name] + (target[1][name] - start[1][name]) * k / steps for name in target[1]})
            q = self.newton(predicted, self._drive(FLOAT, there, 0, 0), tolerance=tolerance)
        return q


def _per_position(value, count):
    """``value`` repeated ``count`` times, or the sequence itself if it has ``count`` entries."""
    if isinstance(value, (str, bytes)) or not hasattr(value, "__len__"):
        return [value] * count
    if len(value) != count:
        raise ValueError(f"{len(value)} rates for {count} crank angles")
    return list(value)


class Snapshot:
    """The solved state at one position, with readers in the analysis's arithmetic.

    Angles come out in degrees (body angles normalised into (-180, 180]), rates
    in rad/s and rad/s^2, points in the model's length unit.  Forces follow the
    contract's rule "force of X on Y": :meth:`reaction` names the body the force
    acts on.
    """

    def __init__(self, mechanism, ar, q, qd, qdd, drive):
        self.mechanism, self.ar, self.q, self.qd, self.qdd, self.drive = mechanism, ar, q, qd, qdd, drive
        self.lam = None
        #: the size of the mechanism's UnknownLoad (forces level), else None
        self.unknown_value = None
        self.kin = _Kinematics(ar, q, qd, qdd)
        #: dimensionless condition number of the position Jacobian, and kappa^2 * unit roundoff
        #: (the estimated relative error of the rates); set by Mechanism.analyse.
        self.condition = None
        self.error_bound = None

    def _body(self, name):
        return None if name is None else self.mechanism.body(name)

    def _local(self, body_name, point):
        body = self._body(body_name)
        return body, _resolve(body, point)

    def angle(self, body: str):
        """Body angle in degrees, in (-180, 180]."""
        return normalise_degrees(self.ar.degrees(self.q[3 * self.mechanism.body(body).index + 2]), self.ar)

    def _need(self, values, what):
        if values is None:
            raise ValueError(f"{what} were not computed (analyse with a higher level)")
        return values

    def omega(self, body: str):
        """Angular velocity of a body (rad/s, ccw +)."""
        return self._need(self.qd, "velocities")[3 * self.mechanism.body(body).index + 2]

    def alpha(self, body: str):
        """Angular acceleration of a body (rad/s^2, ccw +)."""
        return self._need(self.qdd, "accelerations")[3 * self.mechanism.body(body).index + 2]

    def position(self, body: str, point):
        """Global (x, y) of a body point (a name, or drawing-frame coordinates)."""
        return self.kin.position(*self._local(body, point))

    def velocity(self, body: str, point):
        self._need(self.qd, "velocities")
        return self.kin.velocity(*self._local(body, point))

    def acceleration(self, body: str, point):
        self._need(self.qdd, "accelerations")
        return self.kin.acceleration(*self._local(body, point))

    def direction(self, body: str, point_from, point_to):
        """Inclination (degrees, (-180, 180]) of the vector between two points of a body."""
        a, b = self.position(body, point_from), self.position(body, point_to)
        return normalise_degrees(self.ar.degrees(self.ar.atan2(b[1] - a[1], b[0] - a[0])), self.ar)

    def _multipliers(self, name):
        if self.lam is None:
            raise ValueError("forces were not computed (analyse with level='forces')")
        return [self.lam[r] for r in self.mechanism.rows[name]]

    def reaction(self, joint: str, on: str | None):
        """Force (Fx, Fy) that joint ``joint`` transmits to body ``on`` (a Revolute).

        Pass the downstream body for "upstream on downstream", the link for
        "ground on link" at a fixed pivot.
        """
        constraint = self.mechanism.constraints[joint]
        lam = self._multipliers(joint)
        if on == constraint.body_i.name:
            return (-lam[0], -lam[1])
        if constraint.body_j is not None and on == constraint.body_j.name:
            return (lam[0], lam[1])
        raise ValueError(f"body {on!r} is not in joint {joint!r}")

    def force_on(self, body: str, *joints: str):
        """Total force (Fx, Fy) the named constraints exert on ``body``: -sum lambda dPhi/d(x, y)."""
        index = 3 * self.mechanism.body(body).index
        fx = fy = self.ar.num(0)
        for joint in joints:
            rows = self.mechanism.constraints[joint].jacobian(self.kin)
            for lam, row in zip(self._multipliers(joint), rows):
                fx -= lam * row.get(index, 0)
                fy -= lam * row.get(index + 1, 0)
        return (fx, fy)

    def moment_on(self, body: str, *joints: str):
        """Total moment (ccw +) the named constraints exert on ``body`` about its frame origin."""
        index = 3 * self.mechanism.body(body).index + 2
        total = self.ar.num(0)
        for joint in joints:
            rows = self.mechanism.constraints[joint].jacobian(self.kin)
            for lam, row in zip(self._multipliers(joint), rows):
                total -= lam * row.get(index, 0)
        return total

    def normal_force(self, joint: str):
        """Force of the line's body on the sliding point's body, along the line normal (PointOnLine)."""
        return -self._multipliers(joint)[0]

    def driver_torque(self, driver: str):
        """Torque (counter-clockwise positive) the drive applies to its body."""
        return -self._multipliers(driver)[0]

    def kinetic_energy(self):
        """Total kinetic energy (sum of m v_G^2 / 2 + I w^2 / 2)."""
        total = self.ar.num(0)
        for body in self.mechanism.bodies.values():
            v = self.kin.velocity(body, body.centre)
            w = self.qd[3 * body.index + 2]
            total += (self.ar.num(body.mass) * dot(v, v) + self.ar.num(body.inertia) * w * w) / 2
        return total

    def power_of_loads(self):
        """Power of the loads (the unknown one included, once solved) and gravity (not the drive's)."""
        ar, kin = self.ar, self.kin
        total = ar.num(0)
        gravity = ar.num(self.mechanism.gravity)
        for body in self.mechanism.bodies.values():
            total -= ar.num(body.mass) * gravity * kin.velocity(body, body.centre)[1]
        for load in self.mechanism.loads:
            if isinstance(load, PointLoad):
                force = load.force(self)
                total += dot((ar.num(force[0]), ar.num(force[1])), kin.velocity(load.body, load.local))
            else:
                total += ar.num(load.torque(self)) * self.qd[3 * load.body.index + 2]
        unknown = self.mechanism.unknown
        if unknown is not None and self.unknown_value is not None:
            if unknown.local is None:
                total += self.unknown_value * self.qd[3 * unknown.body.index + 2]
            else:
                direction = unknown.direction(self)
                total += self.unknown_value * dot(direction, kin.velocity(unknown.body, unknown.local))
        return total

    def kinetic_energy_rate(self):
        """dT/dt = sum of m v_G . a_G + I w alpha."""
        total = self.ar.num(0)
        for body in self.mechanism.bodies.values():
            v = self.kin.velocity(body, body.centre)
            a = self.kin.acceleration(body, body.centre)
            k = 3 * body.index + 2
            total += self.ar.num(body.mass) * dot(v, a) + self.ar.num(body.inertia) * self.qd[k] * self.qdd[k]
        return total
