"""Programs 1, 2 and 3 in full -- kinematics and forces -- as real mechanisms.

Each ``programN(values, thetas)`` takes the contract's inputs by name (``"L(1)"``,
``"M(3)"``, ``"Q(1)"``, ``"G"``, ...; missing ones are 0, as BASIC variables are), builds
the basic linkage from bodies and joints with its masses, inertias, mass centres and
known loads (docs/contract.md), solves it with :mod:`yaseer.reference.solver`
and returns the contract's outputs by name, one value per crank angle.  The unknown
load that Q(n) selects is found with the Lagrange multipliers: the crank's drive only
prescribes the motion, its torque is held at zero and the unknown takes its place
(:class:`yaseer.reference.elements.UnknownLoad`).  A flexible crank (D, E non-zero)
is a pin sliding along the crank at a driven distance.  Nothing here uses
yaseer.linkages.
"""

from __future__ import annotations

import math

from yaseer.reference.arithmetic import FLOAT
from yaseer.reference.basic_linkages import (FlexibleCrank, _minus_90, _polar_xy, _unit, collect, fourbar_sketch,
                                             solve_each)
from yaseer.reference.solver import (AngleDriver, AngleLock, Body, Couple, Mechanism, MechanismError, PointLoad,
                                     PointOnLine, Revolute, UnknownLoad, cross, dot, normalise_degrees, polar)


# --------------------------------------------------------------------------- Program 1 in full

def _inputs(values: dict):
    """A reader of the contract's inputs by name; missing ones are 0, as BASIC variables are."""
    return lambda name: values.get(name, 0)


def _perpendicular(body_name, h_deg):
    """Direction u(body angle + H + 90): perpendicular to the line joint -> point of a body
    whose frame's x axis is the line H is measured from (the contract's rule, R = 0 included)."""
    def direction(s):
        ar = s.ar
        angle = s.q[3 * s.mechanism.body(body_name).index + 2] + ar.radians(ar.num(h_deg) + 90)
        return (ar.cos(angle), ar.sin(angle))
    return direction


def _constant(fx, fy):
    return lambda s: (fx, fy)


def program1_model(values: dict, crank: FlexibleCrank) -> Mechanism:
    """Program 1's slider-crank with masses and loads from the contract's inputs ``values``.

    Crank frame: origin Ao, x along Ao->A.  Rod frame: origin B, x along B->A (points and
    the mass centre are located from B).  Piston: a particle at B on the cylinder line,
    its orientation locked.  Known loads: F(0),F(1) and the perpendicular F(2) at the
    crank point, F(7),F(8) and F(9) at the rod point, U(1), P(1) (toward the crank);
    Q(1) picks the unknown among U(1), F(2), F(9), P(1).
    """
    v = _inputs(values)
    axis = v("T(4)")
    crank_body = Body("crank", mass=v("M(2)"), inertia=v("I(2)"), centre=polar(v("R(2)"), v("H(2)")),
                      points={"P": polar(v("R(1)"), v("H(1)"))})
    rod = Body("rod", mass=v("M(3)"), inertia=v("I(3)"), centre=polar(v("R(3)"), v("H(3)")),
               points={"B": (0, 0), "A": (v("L(3)"), 0), "P": polar(v("R(4)"), v("H(4)"))})
    piston = Body("piston", mass=v("M(4)"), points={"B": (0, 0)})
    toward_crank = lambda s: _scaled(_line_unit(s.ar, axis), -1)  # noqa: E731
    known = {
        1: Couple(crank_body, lambda s: v("U(1)")),
        2: PointLoad(crank_body, "P", lambda s: _scaled(_perpendicular("crank", v("H(1)"))(s), v("F(2)"))),
        3: PointLoad(rod, "P", lambda s: _scaled(_perpendicular("rod", v("H(4)"))(s), v("F(9)"))),
        4: PointLoad(piston, "B", lambda s: _scaled(toward_crank(s), v("P(1)"))),
    }
    unknowns = {1: UnknownLoad(crank_body), 2: UnknownLoad(crank_body, "P", _perpendicular("crank", v("H(1)"))),
                3: UnknownLoad(rod, "P", _perpendicular("rod", v("H(4)"))),
                4: UnknownLoad(piston, "B", toward_crank)}
    q = _selected(v, "Z(1)", "Q(1)", unknowns)
    loads = [PointLoad(crank_body, "P", _constant(v("F(0)"), v("F(1)"))),
             PointLoad(rod, "P", _constant(v("F(7)"), v("F(8)")))]
    loads += [load for k, load in known.items() if k != q]
    return Mechanism([crank_body, rod, piston],
                     [Revolute("Ao", crank_body, (0, 0), None, (0, 0)),
                      *crank.pin(crank_body, rod, "A"),
                      Revolute("B", rod, "B", piston, "B"),
                      PointOnLine("wall", piston, "B", None, polar(v("L(1)"), _minus_90(axis)), axis),
                      AngleLock("piston", piston, None, 0),
                      AngleDriver("crank", crank_body)],
                     loads, gravity=v("G"), unknown=unknowns.get(q))


def _line_unit(ar, angle_deg):
    angle = ar.radians(ar.num(angle_deg))
    return (ar.cos(angle), ar.sin(angle))


def _scaled(vector, factor):
    return (vector[0] * factor, vector[1] * factor)


UNKNOWN_NAMES_1 = {1: "U(1)", 2: "F(2)", 3: "F(9)", 4: "P(1)"}


def program1(values: dict, thetas_deg=None, number="float", dps=50) -> dict:
    """Program 1 in full (kinematics, and forces when Z(1) = 2) as a real mechanism.

    ``values``: the contract's inputs by name ("L(1)", "T(2)", "W(2)", "M(3)", "Q(1)", "G",
    ...; missing ones 0).  ``thetas_deg``: crank angles (default [T(2)]); W(2), A(2),
    D(0), E(0) apply at every one.  B is ahead of A along u(T(4)).  Returns the
    contract's outputs by name, each an array over the angles: T(3), W(3), A(3), the
    crank point X(1), Y(1), V(1), V(2), A(33), A(34), the crank's mass-centre
    acceleration A(10), A(11), the rod point X(2), Y(2), V(3), V(4), A(35), A(36); with
    Z(1) = 2 the selected unknown, F(3), F(4), F(5), F(6), F(10), F(11), N(1).
    """
    v = _inputs(values)
    thetas = [v("T(2)")] if thetas_deg is None else list(thetas_deg)
    crank = FlexibleCrank(v("L(2)"), v("D(0)"), v("E(0)"), len(thetas))
    mechanism = program1_model(values, crank)
    axis = float(v("T(4)"))

    def sketch_at(theta, k):
        length = float(crank.lengths[k])
        pin = (length * _unit(theta)[0], length * _unit(theta)[1])
        reach = float(v("L(3)"))
        tip = (pin[0] + reach * _unit(axis)[0], pin[1] + reach * _unit(axis)[1])
        return mechanism.coordinates({"crank": (0, 0, theta), "rod": (tip[0], tip[1], axis + 180),
                                      "piston": (tip[0], tip[1], 0)})

    def check(s):
        run = [p - q for p, q in zip(s.position("rod", "B"), s.position("rod", "A"))]
        if dot(run, _unit(axis)) <= 0:
            raise MechanismError("PROG 1 reference: the piston left its assembly branch")

    return _solve_program(v, mechanism, crank, thetas, ("W(2)", "A(2)", "Z(1)", "Q(1)"), UNKNOWN_NAMES_1,
                          sketch_at, check, _program1_row, number, dps)


def _program1_row(s, crank, forces, q):
    row = {"T(3)": normalise_degrees(s.angle("rod") + 180, s.ar), "W(3)": s.omega("rod"), "A(3)": s.alpha("rod")}
    row.update(_point_outputs(s, "crank", "P", ("X(1)", "Y(1)", "V(1)", "V(2)", "A(33)", "A(34)")))
    centre = s.acceleration("crank", s.mechanism.body("crank").centre)
    row["A(10)"], row["A(11)"] = centre
    row.update(_point_outputs(s, "rod", "P", ("X(2)", "Y(2)", "V(3)", "V(4)", "A(35)", "A(36)")))
    if forces:
        row[UNKNOWN_NAMES_1[q]] = s.unknown_value
        row["F(3)"], row["F(4)"] = s.reaction("Ao", "crank")
        row["F(5)"], row["F(6)"] = s.force_on("rod", *crank.joint_names())
        row["F(10)"], row["F(11)"] = s.reaction("B", "piston")
        row["N(1)"] = s.normal_force("wall")
    return row


def _point_outputs(s, body, point, names):
    x, y = s.position(body, point)
    vx, vy = s.velocity(body, point)
    ax, ay = s.acceleration(body, point)
    return dict(zip(names, (x, y, vx, vy, ax, ay)))


# --------------------------------------------------------------------------- Program 2 in full

UNKNOWN_NAMES_2 = {1: "U(2)", 2: "F(31)", 3: "F(34)", 4: "F(37)"}


def _perpendicular_load(body, body_name, h_deg, size):
    return PointLoad(body, "P", lambda s: _scaled(_perpendicular(body_name, h_deg)(s), size))


def program2_model(values: dict, crank: FlexibleCrank) -> Mechanism:
    """Program 2's four-bar with masses and loads from the contract's inputs ``values``.

    Frames: crank from Ao along Ao->A, coupler from A along A->B, follower from Bo along
    Bo->B (the contract's H references).  Known loads: F(29),F(30) and F(31) at the crank
    point, F(32),F(33) and F(34) at the coupler point, F(35),F(36) and F(37) at the
    follower point, U(2); Q(2) picks the unknown among U(2), F(31), F(34), F(37).
    """
    v = _inputs(values)
    crank_body = Body("crank", mass=v("M(6)"), inertia=v("I(6)"), centre=polar(v("R(8)"), v("H(10)")),
                      points={"P": polar(v("R(9)"), v("H(9)"))})
    coupler = Body("coupler", mass=v("M(7)"), inertia=v("I(7)"), centre=polar(v("R(10)"), v("H(12)")),
                   points={"A": (0, 0), "B": (v("L(13)"), 0), "P": polar(v("R(11)"), v("H(11)"))})
    follower = Body("follower", mass=v("M(8)"), inertia=v("I(8)"), centre=polar(v("R(12)"), v("H(14)")),
                    points={"Bo": (0, 0), "B": (v("L(14)"), 0), "P": polar(v("R(13)"), v("H(13)"))})
    known = {1: Couple(crank_body, lambda s: v("U(2)")),
             2: _perpendicular_load(crank_body, "crank", v("H(9)"), v("F(31)")),
             3: _perpendicular_load(coupler, "coupler", v("H(11)"), v("F(34)")),
             4: _perpendicular_load(follower, "follower", v("H(13)"), v("F(37)"))}
    unknowns = {1: UnknownLoad(crank_body),
                2: UnknownLoad(crank_body, "P", _perpendicular("crank", v("H(9)"))),
                3: UnknownLoad(coupler, "P", _perpendicular("coupler", v("H(11)"))),
                4: UnknownLoad(follower, "P", _perpendicular("follower", v("H(13)")))}
    q = _selected(v, "Z(2)", "Q(2)", unknowns)
    loads = [PointLoad(crank_body, "P", _constant(v("F(29)"), v("F(30)"))),
             PointLoad(coupler, "P", _constant(v("F(32)"), v("F(33)"))),
             PointLoad(follower, "P", _constant(v("F(35)"), v("F(36)")))]
    loads += [load for k, load in known.items() if k != q]
    return Mechanism([crank_body, coupler, follower],
                     [Revolute("Ao", crank_body, (0, 0), None, (0, 0)),
                      *crank.pin(crank_body, coupler, "A"),
                      Revolute("B", coupler, "B", follower, "B"),
                      Revolute("Bo", follower, "Bo", None, polar(v("L(11)"), v("T(11)"))),
                      AngleDriver("crank", crank_body)],
                     loads, gravity=v("G"), unknown=unknowns.get(q))


def _solve_program(v, mechanism, crank, thetas, names, unknown_names, sketch_at, check, row, number, dps):
    """Solve each angle and read its outputs; ``names``: the program's (rate, acceleration, Z, Q) inputs."""
    rate, acceleration, z_name, q_name = names
    forces = v(z_name) == 2
    snapshots = solve_each(mechanism, thetas, v(rate), v(acceleration), sketch_at, check, number, dps, crank,
                           "forces" if forces else "accelerations")
    selected = _selected(v, z_name, q_name, unknown_names)
    return collect([row(s, crank, forces, selected) for s in snapshots], number)


def _selected(v, z_name, q_name, unknowns):
    """The Q choice when forces are asked for (Z = 2), else None; a bad Q is an error."""
    if v(z_name) != 2:
        return None
    q = v(q_name)
    if q not in unknowns:
        raise ValueError(f"{q_name} must be one of {sorted(unknowns)}, not {q!r}")
    return int(q)


def program2(values: dict, thetas_deg=None, number="float", dps=50) -> dict:
    """Program 2 in full (kinematics, and forces when Z(2) = 2) as a real four-bar.

    ``values``: the contract's inputs by name (missing ones 0); ``thetas_deg``: crank
    angles (default [T(12)]).  L(10) = 1: crossed (B right of A->Bo), else uncrossed.
    Returns T(13), W(6), A(6), T(14) (B->Bo), W(7), A(7), the points X(3)...A(42); with
    Z(2) = 2 the selected unknown, F(21)...F(28).
    """
    v = _inputs(values)
    thetas = [v("T(12)")] if thetas_deg is None else list(thetas_deg)
    crank = FlexibleCrank(v("L(12)"), v("D(2)"), v("E(2)"), len(thetas))
    mechanism = program2_model(values, crank)
    side = -1 if v("L(10)") == 1 else 1
    pivot = _polar_xy(FLOAT, v("L(11)"), v("T(11)"))
    sketch_at = lambda theta, k: fourbar_sketch(mechanism, theta, crank.lengths[k], v("L(13)"),  # noqa: E731
                                                v("L(14)"), pivot, side)

    def check(s):
        a, b, bo = s.position("coupler", "A"), s.position("coupler", "B"), s.position("follower", "Bo")
        if side * cross((bo[0] - a[0], bo[1] - a[1]), (b[0] - a[0], b[1] - a[1])) <= 0:
            raise MechanismError("PROG 2 reference: the four-bar left its assembly branch")

    return _solve_program(v, mechanism, crank, thetas, ("W(5)", "A(5)", "Z(2)", "Q(2)"), UNKNOWN_NAMES_2,
                          sketch_at, check, _program2_row, number, dps)


def _program2_row(s, crank, forces, q):
    row = {"T(13)": s.angle("coupler"), "W(6)": s.omega("coupler"), "A(6)": s.alpha("coupler"),
           "T(14)": normalise_degrees(s.angle("follower") + 180, s.ar), "W(7)": s.omega("follower"),
           "A(7)": s.alpha("follower")}
    row.update(_point_outputs(s, "crank", "P", ("X(3)", "Y(3)", "V(5)", "V(6)", "A(37)", "A(38)")))
    row.update(_point_outputs(s, "coupler", "P", ("X(4)", "Y(4)", "V(7)", "V(8)", "A(39)", "A(40)")))
    row.update(_point_outputs(s, "follower", "P", ("X(5)", "Y(5)", "V(9)", "V(10)", "A(41)", "A(42)")))
    if forces:
        row[UNKNOWN_NAMES_2[q]] = s.unknown_value
        row["F(21)"], row["F(22)"] = s.reaction("Ao", "crank")
        row["F(23)"], row["F(24)"] = s.force_on("coupler", *crank.joint_names())
        row["F(25)"], row["F(26)"] = s.reaction("B", "follower")
        row["F(27)"], row["F(28)"] = s.reaction("Bo", "follower")
    return row


# --------------------------------------------------------------------------- Program 3 in full

UNKNOWN_NAMES_3 = {1: "U(3)", 3: "F(18)"}


def program3_model(values: dict, crank: FlexibleCrank) -> Mechanism:
    """Program 3's FISC with masses and loads from the contract's inputs ``values``.

    Crank from Ao along Ao->A; a block pinned to the crank at A (its mass centre there)
    slides along the follower and turns with it; the follower from Bo along Bo->A.
    Known loads: U(3) on the crank, the perpendicular F(18) at the follower point;
    Q(3) picks the unknown (1: U(3), 3: F(18)).
    """
    v = _inputs(values)
    crank_body = Body("crank", mass=v("M(0)"), inertia=v("I(0)"), centre=polar(v("R(5)"), v("T(5)")),
                      points={"P": polar(v("R(0)"), v("H(23)"))})
    block = Body("block", mass=v("M(1)"), inertia=v("I(1)"), points={"A": (0, 0)})
    follower = Body("follower", mass=v("M(5)"), inertia=v("I(5)"), centre=polar(v("R(6)"), v("H(7)")),
                    points={"Bo": (0, 0), "P": polar(v("R(7)"), v("H(6)"))})
    known = {1: Couple(crank_body, lambda s: v("U(3)")),
             3: _perpendicular_load(follower, "follower", v("H(6)"), v("F(18)"))}
    unknowns = {1: UnknownLoad(crank_body), 3: UnknownLoad(follower, "P", _perpendicular("follower", v("H(6)")))}
    q = _selected(v, "Z(3)", "Q(3)", unknowns)
    bo_from_ao = polar(v("L(6)"), _plus_180(v("T(6)")))
    return Mechanism([crank_body, block, follower],
                     [Revolute("Ao", crank_body, (0, 0), None, (0, 0)),
                      *crank.pin(crank_body, block, "A"),
                      Revolute("Bo", follower, "Bo", None, bo_from_ao),
                      PointOnLine("slide", block, "A", follower, (0, 0), 0),
                      AngleLock("lock", block, follower, 0),
                      AngleDriver("crank", crank_body)],
                     [load for k, load in known.items() if k != q], gravity=v("G"), unknown=unknowns.get(q))


def _plus_180(angle):
    """angle + 180 (exact for decimal strings)."""
    if isinstance(angle, str):
        from decimal import Decimal

        return str(Decimal(angle) + 180)
    return angle + 180


def program3(values: dict, thetas_deg=None, number="float", dps=50) -> dict:
    """Program 3 in full (kinematics, and forces when Z(3) = 2) as a real FISC.

    ``values``: the contract's inputs by name (missing ones 0); ``thetas_deg``: crank
    angles (default [T(7)]).  Returns L(5), D(4), E(4), T(9), W(4), A(4), the points
    X(6)...A(44) and X(7)...A(46); with Z(3) = 2 the unknown, F(12)...F(17), N(3), U(4).
    """
    v = _inputs(values)
    thetas = [v("T(7)")] if thetas_deg is None else list(thetas_deg)
    crank = FlexibleCrank(v("L(7)"), v("D(3)"), v("E(3)"), len(thetas))
    mechanism = program3_model(values, crank)
    bo = (-float(v("L(6)")) * _unit(float(v("T(6)")))[0], -float(v("L(6)")) * _unit(float(v("T(6)")))[1])

    def sketch_at(theta, k):
        length = float(crank.lengths[k])
        pin = (length * _unit(theta)[0], length * _unit(theta)[1])
        direction = math.degrees(math.atan2(pin[1] - bo[1], pin[0] - bo[0]))
        return mechanism.coordinates({"crank": (0, 0, theta), "block": (pin[0], pin[1], direction),
                                      "follower": (bo[0], bo[1], direction)})

    def check(s):
        pin, pivot = s.position("block", "A"), s.position("follower", "Bo")
        if dot((pin[0] - pivot[0], pin[1] - pivot[1]), _unit(float(s.angle("follower")))) <= 0:
            raise MechanismError("PROG 3 reference: the block passed through the follower's pivot")

    return _solve_program(v, mechanism, crank, thetas, ("W(0)", "A(0)", "Z(3)", "Q(3)"), UNKNOWN_NAMES_3,
                          sketch_at, check, _program3_row, number, dps)


def _program3_row(s, crank, forces, q):
    r = [p - q_ for p, q_ in zip(s.position("block", "A"), s.position("follower", "Bo"))]
    v, a = s.velocity("block", "A"), s.acceleration("block", "A")
    length = s.ar.sqrt(dot(r, r))
    rate = dot(r, v) / length
    row = {"L(5)": length, "D(4)": rate, "E(4)": (dot(v, v) + dot(r, a) - rate * rate) / length,
           "T(9)": s.angle("follower"), "W(4)": s.omega("follower"), "A(4)": s.alpha("follower")}
    row.update(_point_outputs(s, "crank", "P", ("X(6)", "Y(6)", "V(11)", "V(12)", "A(43)", "A(44)")))
    row.update(_point_outputs(s, "follower", "P", ("X(7)", "Y(7)", "V(13)", "V(14)", "A(45)", "A(46)")))
    if forces:
        row[UNKNOWN_NAMES_3[q]] = s.unknown_value
        row["F(12)"], row["F(13)"] = s.reaction("Ao", "crank")
        row["F(14)"], row["F(15)"] = s.force_on("block", *crank.joint_names())
        row["N(3)"] = s.normal_force("slide")
        row["U(4)"] = s.moment_on("block", "slide", "lock")
        row["F(16)"], row["F(17)"] = s.reaction("Bo", "follower")
    return row


# --------------------------------------------------------------------------- inverted slider-crank

def inverted_slider_crank(L6, T6, L7, thetas_deg, omega=0, alpha=0, crank_rate=0, crank_accel=0,
                          number="float", dps=50):
    """Program 3 (FISC): L(5) = |Bo->A|, D(4), E(4); T(9) of Bo->A, W(4), A(4).

    ``L7``, ``crank_rate``, ``crank_accel``: the crank length and D(3), E(3)
    (numbers, or one per angle for a flexible crank).  The block at A carries
    the pin; it slides along the follower, whose line passes through Bo
    (the kinematics of :func:`program3`).
    """
    r = program3({"L(6)": L6, "T(6)": T6, "L(7)": L7, "W(0)": omega, "A(0)": alpha, "D(3)": crank_rate,
                  "E(3)": crank_accel}, thetas_deg, number, dps)
    return {name: r[name] for name in ("L(5)", "D(4)", "E(4)", "T(9)", "W(4)", "A(4)")}
