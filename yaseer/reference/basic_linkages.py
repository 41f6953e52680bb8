"""Al-Yaseer's basic linkages in the contract's conventions, as real bodies and joints.

Independent references for Programs 1, 2 and 3 (docs/contract.md): each
linkage is built from bodies, pins and sliders and solved by
:mod:`yaseer.reference.solver`; nothing here uses yaseer.linkages.  Each
function takes crank angles (degrees; solved one by one by Newton from a rough
sketch on the requested branch, so positions that do not assemble raise
MechanismError), the crank's rate and acceleration (rad/s, rad/s^2, ccw +;
numbers or one per angle), optionally a flexible crank's length rates (the
contract's D and E; the pin then slides along the crank at a driven distance),
and returns a dict of numpy arrays, or of lists of mpf with
``number="mpmath"`` (``dps`` digits).  Angles out are degrees in (-180, 180].

* :func:`slider_crank` -- Program 1: e, a, b, axis phi; B on the line
  e u(phi - 90) + s u(phi), ahead of A along u(phi) (``ahead=False``: behind).
* :func:`fourbar` -- Program 2: fixed link Ao->Bo = L11 u(T11), crank L12,
  coupler L13, follower L14; uncrossed: B left of the directed line A->Bo.

Program 3 (FISC), the inverted slider-crank, is solved in full in
:mod:`yaseer.reference.programs` (:func:`~yaseer.reference.programs.inverted_slider_crank`).
"""

from __future__ import annotations

import math

from yaseer.reference.arithmetic import arithmetic_for
from yaseer.reference.solver import (AngleDriver, Body, LengthDriver, Mechanism, MechanismError,
                                     PointOnLine, Revolute, cross, dot, normalise_degrees, polar)


def collect(rows: list[dict], number):
    """Rows of named values -> dict of numpy arrays (float) or of lists (mpmath)."""
    import numpy as np

    names = rows[0].keys() if rows else ()
    if number == "float":
        return {name: np.array([float(r[name]) for r in rows]) for name in names}
    return {name: [r[name] for r in rows] for name in names}


def solve_each(mechanism, thetas_deg, rate, acceleration, sketch_at, check, number, dps, crank=None,
               level="accelerations"):
    """One snapshot per crank angle, each by Newton from ``sketch_at(theta, k)`` (float, then ``number``).

    ``crank``: the FlexibleCrank of the mechanism, if any.  ``rate``, ``acceleration``:
    the crank's, numbers or one per angle.
    """
    thetas = list(thetas_deg)
    rates, accelerations = _each(rate, len(thetas)), _each(acceleration, len(thetas))
    snapshots = []
    for k, theta in enumerate(thetas):
        drives = None if crank is None or not crank.flexible else {CRANK_LENGTH: crank.at(k)}
        (snapshot,) = mechanism.analyse([theta], rates[k], accelerations[k], sketch_at(float(theta), k),
                                        number=number, dps=dps, branch_check=check, drives=drives,
                                        level=level)
        snapshots.append(snapshot)
    return snapshots


CRANK_LENGTH = "crank length"


class FlexibleCrank:
    """A crank's length per position and its rates (the contract's L, D, E): numbers or one per angle.

    ``flexible`` is False for a rigid crank (no rates, one length): then the pin is a
    plain revolute; otherwise the pin slides along the crank at the driven distance.
    """

    def __init__(self, length, rate=0, acceleration=0, count=1):
        self.lengths = _each(length, count)
        self.rates, self.accelerations = _each(rate, count), _each(acceleration, count)
        self.flexible = not (_is_number(length) and _is_zero(rate) and _is_zero(acceleration))

    def at(self, k):
        return self.lengths[k], self.rates[k], self.accelerations[k]

    def joint_names(self):
        """The constraints that make the crank pin (their forces are the pin's force)."""
        return ("pin",) if not self.flexible else ("pin", CRANK_LENGTH)

    def pin(self, crank_body, body, point):
        """The constraints at the crank pin joining ``body``'s ``point`` to the crank."""
        if not self.flexible:
            return [Revolute("pin", crank_body, (self.lengths[0], 0), body, point)]
        return [PointOnLine("pin", body, point, crank_body, (0, 0), 0),
                LengthDriver(CRANK_LENGTH, body, point, crank_body, (0, 0), 0)]


def _is_number(value):
    return isinstance(value, str) or not hasattr(value, "__len__")


def _is_zero(value):
    return _is_number(value) and float(value) == 0


def _each(value, count):
    if _is_number(value):
        return [value] * count
    if len(value) != count:
        raise ValueError(f"{len(value)} values for {count} crank angles")
    return list(value)


def _polar_xy(ar, length, angle_deg):
    """length u(angle_deg) in arithmetic ``ar`` (decimal strings exact in mpmath)."""
    angle = ar.radians(ar.num(angle_deg))
    return (ar.num(length) * ar.cos(angle), ar.num(length) * ar.sin(angle))


def _unit(theta_deg):
    return (math.cos(math.radians(theta_deg)), math.sin(math.radians(theta_deg)))


# --------------------------------------------------------------------------- slider-crank

def slider_crank_model(e, crank: FlexibleCrank, b, axis_deg=0):
    """Crank from Ao (pivot at the origin), rod A->B, B on the line e u(axis - 90) + s u(axis)."""
    crank_body = Body("crank")
    rod = Body("rod", points={"A": (0, 0), "B": (b, 0)})
    return Mechanism([crank_body, rod],
                     [Revolute("Ao", crank_body, (0, 0), None, (0, 0)),
                      *crank.pin(crank_body, rod, "A"),
                      PointOnLine("B", rod, "B", None, polar(e, _minus_90(axis_deg)), axis_deg),
                      AngleDriver("crank", crank_body)])


def _minus_90(angle):
    """angle - 90 (kept exact for decimal strings: they become exact in mpmath)."""
    if isinstance(angle, str):
        from decimal import Decimal

        return str(Decimal(angle) - 90)
    return angle - 90


def slider_crank(e, a, b, thetas_deg, omega=0, alpha=0, axis_deg=0, ahead=True, crank_rate=0,
                 crank_accel=0, number="float", dps=50):
    """Program 1: rod angle T(3) (deg), W(3), A(3); pin B's x, y, v, a.

    ``a``, ``crank_rate``, ``crank_accel``: the crank length L(2) and D(0), E(0)
    (numbers, or one per angle for a flexible crank).
    """
    thetas = list(thetas_deg)
    crank = FlexibleCrank(a, crank_rate, crank_accel, len(thetas))
    mechanism = slider_crank_model(e, crank, b, axis_deg)
    sign = 1 if ahead else -1
    axis = float(axis_deg)

    def sketch_at(theta, k):
        length = float(crank.lengths[k])
        return mechanism.coordinates({"crank": (0, 0, theta),
                                      "rod": (length * _unit(theta)[0], length * _unit(theta)[1],
                                              axis if ahead else axis + 180)})

    def check(s):
        run = [p - q for p, q in zip(s.position("rod", "B"), s.position("rod", "A"))]
        if sign * dot(run, _unit(axis)) <= 0:
            raise MechanismError("slider-crank: the piston left its assembly branch")

    rows = []
    for s in solve_each(mechanism, thetas, omega, alpha, sketch_at, check, number, dps, crank):
        position, velocity, acceleration = (s.position("rod", "B"), s.velocity("rod", "B"),
                                            s.acceleration("rod", "B"))
        rows.append({"T(3)": s.angle("rod"), "W(3)": s.omega("rod"), "A(3)": s.alpha("rod"),
                     "xB": position[0], "yB": position[1], "vxB": velocity[0], "vyB": velocity[1],
                     "axB": acceleration[0], "ayB": acceleration[1]})
    return collect(rows, number)


# --------------------------------------------------------------------------- four-bar

def fourbar_model(crank, coupler, follower, follower_pivot):
    """Crank pivot at the origin, crank pin B at ``crank`` on the crank; coupler B->C; follower D->C, D fixed.

    ``crank``: a length, or a FlexibleCrank.  (Named as seed 003 names them; in the
    contract's words the pin is A, the coupler's far end B, the follower pivot Bo.)
    """
    crank = crank if isinstance(crank, FlexibleCrank) else FlexibleCrank(crank)
    crank_body = Body("crank")
    coupler_body = Body("coupler", points={"B": (0, 0), "C": (coupler, 0)})
    follower_body = Body("follower", points={"D": (0, 0), "C": (follower, 0)})
    return Mechanism([crank_body, coupler_body, follower_body],
                     [Revolute("A", crank_body, (0, 0), None, (0, 0)),
                      *crank.pin(crank_body, coupler_body, "B"),
                      Revolute("C", coupler_body, "C", follower_body, "C"),
                      Revolute("D", follower_body, "D", None, follower_pivot),
                      AngleDriver("crank", crank_body)])


def fourbar_sketch(mechanism, theta_deg, crank, coupler, follower, pivot, side):
    """A rough placement on ``side`` (+1 left, -1 right of B->D): the coupler and follower
    drawn as the triangle B C D would be drawn by compass, with the spread clamped so that
    a position that does not assemble still gives a sketch (Newton then reports it)."""
    crank, coupler, follower = float(crank), float(coupler), float(follower)
    pivot = (float(pivot[0]), float(pivot[1]))
    pin = (crank * _unit(theta_deg)[0], crank * _unit(theta_deg)[1])
    run = (pivot[0] - pin[0], pivot[1] - pin[1])
    length = math.hypot(*run) or 1.0
    along = (coupler * coupler - follower * follower + length * length) / (2 * length)
    along = max(-coupler, min(coupler, along))
    h = math.sqrt(max(coupler * coupler - along * along, (0.05 * coupler) ** 2))
    tip = (pin[0] + (along * run[0] - side * h * run[1]) / length,
           pin[1] + (along * run[1] + side * h * run[0]) / length)
    return mechanism.coordinates({
        "crank": (0, 0, theta_deg),
        "coupler": (pin[0], pin[1], math.degrees(math.atan2(tip[1] - pin[1], tip[0] - pin[0]))),
        "follower": (pivot[0], pivot[1], math.degrees(math.atan2(tip[1] - pivot[1], tip[0] - pivot[0])))})


def fourbar_side_check(side, what):
    """Branch guard: C on ``side`` of the directed line from the crank pin to the follower pivot."""
    def check(s):
        b, c, d = s.position("coupler", "B"), s.position("coupler", "C"), s.position("follower", "D")
        if side * cross((d[0] - b[0], d[1] - b[1]), (c[0] - b[0], c[1] - b[1])) <= 0:
            raise MechanismError(f"{what}: the four-bar left its assembly branch")
    return check


def fourbar_snapshots(thetas_deg, omega, alpha, lengths, pivot, side, number, dps, what,
                      crank_rate=0, crank_accel=0):
    """Solved four-bar states at each crank angle (see :func:`fourbar_model`); the crank
    length may be one per angle with its rates (a flexible crank)."""
    thetas = list(thetas_deg)
    crank_length, coupler, follower = lengths
    crank = FlexibleCrank(crank_length, crank_rate, crank_accel, len(thetas))
    mechanism = fourbar_model(crank, coupler, follower, pivot)
    return solve_each(mechanism, thetas, omega, alpha,
                      lambda theta, k: fourbar_sketch(mechanism, theta, crank.lengths[k], coupler, follower,
                                                      pivot, side),
                      fourbar_side_check(side, what), number, dps, crank)


def fourbar(L11, T11, L12, L13, L14, thetas_deg, omega=0, alpha=0, crossed=False, crank_rate=0,
            crank_accel=0, number="float", dps=50):
    """Program 2: T(13), W(6), A(6) of A->B; T(14) of B->Bo, W(7), A(7).

    ``L12``, ``crank_rate``, ``crank_accel``: the crank length and D(2), E(2)
    (numbers, or one per angle for a flexible crank).
    """
    pivot = _polar_xy(arithmetic_for(number, dps), L11, T11)
    snapshots = fourbar_snapshots(thetas_deg, omega, alpha, (L12, L13, L14), pivot,
                                  -1 if crossed else 1, number, dps, "PROG 2 reference", crank_rate, crank_accel)
    rows = [{"T(13)": s.angle("coupler"), "W(6)": s.omega("coupler"), "A(6)": s.alpha("coupler"),
             "T(14)": normalise_degrees(s.angle("follower") + 180, s.ar),
             "W(7)": s.omega("follower"), "A(7)": s.alpha("follower")} for s in snapshots]
    return collect(rows, number)
