"""The paper's five example mechanisms as real links and joints (independent reference).

Each mechanism of section 4 of the paper (seed 000; its figures are lost) is
rebuilt from the dimensions of its calling listing and the contract
(docs/contract.md) as rigid bodies, pins, sliders and a crank drive,
and solved by :mod:`yaseer.reference.solver` -- not through virtual links, not
through yaseer.linkages.  docs/reference.md gives every body, joint and the
listing line each dimension comes from.

API::

    example_columns(n, crank_angles, number="float", dps=50) -> numpy array (rows x columns)
    example_snapshots(n, crank_angles, number="float", dps=50) -> list of solver Snapshots
    example_forces(n, crank_angles, ...) -> {contract name: array}  (Examples 2 and 5, signed)
    EXAMPLE_ANGLES[n]   the crank angles the (corrected) listing loops over
    COLUMNS[n]          the printed column names

Columns (units as the listing's: mm, cm or m; rad/s; N, N m):

1. QQ, Y(2), V(4), A(36): crank angle; y, v_y, a_y of piston D.
2. QQ, U(1), N(1), |F(3),F(4)|: crank torque (ccw +), wall on piston B along
   u(T(4)+90), magnitude of the bearing reaction at Ao.
3. T(2), T(9), W(4), A(4), X(7): crank angle; inclination of Co->C and its
   rates (the output member CCoD); x of D.
4. QQ, W(6), A(6), V(7), A(39): angular velocity and acceleration of link EDH;
   v_x and a_x of E.
5. QQ, U(2), |F(27),F(28)|, |F(21),F(22)|: crank torque (ccw +); magnitudes of
   the bearing reactions at Bo (toggle BoB) and Ao (crank).

``number="mpmath"`` computes every position by Newton polished at ``dps``
digits and rates and forces in that precision; the array is then of mpf
objects (dtype object).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Optional

from yaseer.reference.solver import (AngleDriver, Body, Mechanism, MechanismError, PointLoad,
                                     PointOnLine, Revolute, cross, dot, polar)

#: crank angles of each listing's FOR loop (degrees), in the order the listing prints them.
EXAMPLE_ANGLES = {
    1: [0.1 + 15 * k for k in range(25)],
    2: [360.1 - 20 * k for k in range(19)],
    3: [0.1 + 20 * k for k in range(19)],
    4: [0.1 + 20 * k for k in range(19)],
    5: [360.1 - 20 * k for k in range(19)],
}

COLUMNS = {
    1: ("QQ", "Y(2)", "V(4)", "A(36)"),
    2: ("QQ", "U(1)", "N(1)", "SQR(F(3)^2+F(4)^2)"),
    3: ("T(2)", "T(9)", "W(4)", "A(4)", "X(7)"),
    4: ("QQ", "W(6)", "A(6)", "V(7)", "A(39)"),
    5: ("QQ", "U(2)", "SQR(F(27)^2+F(28)^2)", "SQR(F(21)^2+F(22)^2)"),
}

#: crank speed (rad/s, ccw +) of each example
CRANK_RATE = {1: 25, 2: -8, 3: 30, 4: 35, 5: -22}

#: The listings turn their cylinder axes and Example 4's fixed link by 0.1 degree off 0, 90
#: and -90 (T(4) = .1, 90.1, -90.1; T(11) = 90.1) to dodge Program 5's divisions by cos T
#: and sin T.  The models use the listings' geometry by default; ``dodge=0`` gives the
#: mechanisms as drawn (axes exactly horizontal and vertical).  Example 5 has no dodge.
DODGE = 0.1


def _unit(ar, angle_deg):
    angle = ar.radians(ar.num(angle_deg))
    return (ar.cos(angle), ar.sin(angle))


def _ahead(snapshot, body_from, point_from, body_to, point_to, axis_deg, what):
    """Branch guard: ``point_to`` must lie ahead of ``point_from`` along u(axis_deg)."""
    ar = snapshot.ar
    a, b = snapshot.position(body_from, point_from), snapshot.position(body_to, point_to)
    if dot((b[0] - a[0], b[1] - a[1]), _unit(ar, axis_deg)) <= 0:
        raise MechanismError(f"{what}: the slider left its assembly branch")


def _side(snapshot, body_a, a, body_b, b, body_p, p, sign, what):
    """Branch guard: point p on the left (sign +1) or right (-1) of the directed line a->b."""
    pa, pb, pp = (snapshot.position(body_a, a), snapshot.position(body_b, b),
                  snapshot.position(body_p, p))
    side = cross((pb[0] - pa[0], pb[1] - pa[1]), (pp[0] - pa[0], pp[1] - pa[1]))
    if side * sign <= 0:
        raise MechanismError(f"{what}: the four-bar left its assembly branch")


def _magnitude(ar, vector):
    return ar.sqrt(vector[0] ** 2 + vector[1] ** 2)


def _named(*entries) -> dict:
    """{name: value} from (name, value) and (name_x, name_y, (x, y)) entries."""
    named = {}
    for entry in entries:
        if len(entry) == 2:
            named[entry[0]] = entry[1]
        else:
            named[entry[0]], named[entry[1]] = entry[2]
    return named


@dataclass
class ExampleModel:
    """One example as a mechanism: its solver model, a rough sketch of its coordinates at
    crank angle ``home``, its branch check, the reader of its printed row
    ``columns(snapshot, angle)``, how far it needs analysing (``level``) and, for the
    force examples, ``forces(snapshot) -> {contract name: value}``."""

    mechanism: Mechanism
    sketch: list
    home: float
    check: Callable
    columns: Callable
    level: str
    forces: Optional[Callable] = None


# --------------------------------------------------------------------------- Example 1

def example1(dodge=DODGE):
    """Double slider-crank (Fig. 6): crank AoA = 75, rod ABC = 300 (B its midpoint), BD = 150, mm.

    Listing line 20: piston C on the line e = 25 right of the axis u(0.1 deg)
    (L(1) = 25, T(4) = .1); line 50: piston D on the line e = 150 right of the
    axis u(90.1 deg), i.e. through 150 u(0.1 deg) (L(1) = 150, T(4) = 90.1).
    C is ahead of A along its axis, D ahead of B along its axis (Program 1's branch).
    """
    crank = Body("crank", points={"A": (75, 0)})
    rod = Body("rod ABC", points={"A": (0, 0), "B": (150, 0), "C": (300, 0)})
    link = Body("link BD", points={"B": (0, 0), "D": (150, 0)})
    mechanism = Mechanism(
        [crank, rod, link],
        [Revolute("Ao", crank, (0, 0), None, (0, 0)),
         Revolute("A", crank, "A", rod, "A"),
         PointOnLine("C", rod, "C", None, polar(25, dodge - 90), dodge),
         Revolute("B", rod, "B", link, "B"),
         PointOnLine("D", link, "D", None, polar(150, dodge), 90 + dodge),
         AngleDriver("crank", crank)])
    sketch = mechanism.coordinates({"crank": (0, 0, 0), "rod ABC": (75, 0, -4.8),
                                    "link BD": (224, -12, 120)})

    def check(s):
        _ahead(s, "rod ABC", "A", "rod ABC", "C", dodge, "Example 1, piston C")
        _ahead(s, "rod ABC", "B", "link BD", "D", 90 + dodge, "Example 1, piston D")

    def columns(s, angle):
        ar = s.ar
        return [ar.num(angle), s.position("link BD", "D")[1], s.velocity("link BD", "D")[1],
                s.acceleration("link BD", "D")[1]]

    return ExampleModel(mechanism, sketch, 0, check, columns, "accelerations")


# --------------------------------------------------------------------------- Example 2

def example2(dodge=DODGE):
    """Churning mechanism (Fig. 8): AoA = .021, AB = .032, BC = .029 (C beyond B), CD = .054, m.

    Line 100: piston B on the axis u(0.1 deg) through Ao (L(1) = 0, T(4) = .1),
    C on the rod beyond B (R(4) = .029, H(4) = 180).  Line 40: plunger D on the
    axis u(90.1 deg) e = .08 to its right (through .08 u(0.1 deg)).  Masses
    neglected.  Load on D: P = 650 v|v| pushing D toward the crank (along
    -u(90.1 deg)), v the plunger's velocity along its axis (line 50 of the
    corrected listing; it resists the motion).
    """
    crank = Body("crank", points={"A": (".021", 0)})
    rod = Body("rod ABC", points={"A": (0, 0), "B": (".032", 0), "C": (".061", 0)})
    link = Body("link CD", points={"C": (0, 0), "D": (".054", 0)})

    plunger_axis = 90 + dodge

    def plunger_force(s):
        ar = s.ar
        axis = _unit(ar, plunger_axis)
        v = dot(s.velocity("link CD", "D"), axis)
        p = 650 * v * abs(v)
        return (-p * axis[0], -p * axis[1])

    mechanism = Mechanism(
        [crank, rod, link],
        [Revolute("Ao", crank, (0, 0), None, (0, 0)),
         Revolute("A", crank, "A", rod, "A"),
         PointOnLine("B", rod, "B", None, (0, 0), dodge),
         Revolute("C", rod, "C", link, "C"),
         PointOnLine("D", link, "D", None, polar(".08", dodge), plunger_axis),
         AngleDriver("crank", crank)],
        loads=[PointLoad(link, "D", plunger_force)])
    sketch = mechanism.coordinates({"crank": (0, 0, 0), "rod ABC": (0.021, 0, 0),
                                    "link CD": (0.082, 0, 92)})

    def check(s):
        _ahead(s, "rod ABC", "A", "rod ABC", "B", dodge, "Example 2, piston B")
        _ahead(s, "rod ABC", "C", "link CD", "D", plunger_axis, "Example 2, plunger D")

    def columns(s, angle):
        ar = s.ar
        return [ar.num(angle), s.driver_torque("crank"), s.normal_force("B"),
                _magnitude(ar, s.reaction("Ao", "crank"))]

    def forces(s):
        """Program 1's force outputs for AoABC (the listing's last call), in the contract's signs."""
        normal, wall = s.normal_force("B"), _unit(s.ar, 90 + dodge)
        return _named(("U(1)", s.driver_torque("crank")), ("N(1)", normal),
                      ("F(3)", "F(4)", s.reaction("Ao", "crank")), ("F(5)", "F(6)", s.reaction("A", "rod ABC")),
                      ("F(10)", "F(11)", (-normal * wall[0], -normal * wall[1])),
                      ("F(7)", "F(8)", s.reaction("C", "rod ABC")))

    return ExampleModel(mechanism, sketch, 0, check, columns, "forces", forces)


# --------------------------------------------------------------------------- Example 3

def example3(dodge=DODGE):
    """Indexing mechanism (Fig. 1): AoA = 2.5, AB = 6, AC = 1.5 (C beyond A), CoD = 3.5, cm.

    Line 3010: piston B on the axis u(-90.1 deg) through Ao (L(1) = 0), C on the
    rod 7.5 from B along B->A (R(4) = 7.5, H(4) = 0).  Line 3020: Co = -L(6) u(T(6))
    = (-1.5, 5.5).  C carries a block sliding along the output member CCoD,
    pivoted at Co; D on it 3.5 beyond Co (R(7) = 3.5, H(6) = 180).
    The output member's drawing frame has its x axis along Co->C, so its angle
    is T(9).
    """
    crank = Body("crank", points={"A": (2.5, 0)})
    rod = Body("rod BAC", points={"B": (0, 0), "A": (6, 0), "C": (7.5, 0)})
    follower = Body("member CCoD", points={"Co": (0, 0), "D": (-3.5, 0)})
    mechanism = Mechanism(
        [crank, rod, follower],
        [Revolute("Ao", crank, (0, 0), None, (0, 0)),
         Revolute("A", crank, "A", rod, "A"),
         PointOnLine("B", rod, "B", None, (0, 0), -90 - dodge),
         Revolute("Co", follower, "Co", None, (-1.5, 5.5)),
         PointOnLine("C", rod, "C", follower, (0, 0), 0),
         AngleDriver("crank", crank)])
    sketch = mechanism.coordinates({"crank": (0, 0, 0), "rod BAC": (0, -5.45, 65.4),
                                    "member CCoD": (-1.5, 5.5, -41.8)})

    def check(s):
        _ahead(s, "rod BAC", "A", "rod BAC", "B", -90 - dodge, "Example 3, piston B")
        _ahead(s, "member CCoD", "Co", "rod BAC", "C", s.ar.to_float(s.angle("member CCoD")),
               "Example 3, block C")

    def columns(s, angle):
        ar = s.ar
        return [ar.num(angle), s.angle("member CCoD"), s.omega("member CCoD"),
                s.alpha("member CCoD"), s.position("member CCoD", "D")[0]]

    return ExampleModel(mechanism, sketch, 0, check, columns, "accelerations")


# --------------------------------------------------------------------------- Example 4

def example4(dodge=DODGE):
    """Film transport (Fig. 11): AoA = 6.5, AB = 28, BBo = 14, AC = 15, CD = 5.5, DE = 11.5,
    DH = 31.5, HHo = 17.5, mm.

    Line 4020: Bo = (26.5, -10).  Line 4030: D on the coupler at (15, -5.5) in
    the frame A->B (C on AB 15 from A, D 5.5 to its right: H(11) = -ATN(5.5/15)).
    Line 4070: Ho = 25 u(90.1 deg); link EDH pinned to the coupler at D, H at
    31.5, E 11.5 beyond D (R(11) = 11.5, H(11) = 180).  AoABBo uncrossed (B left
    of A->Bo), AoDHHo crossed (H right of D->Ho).
    """
    crank = Body("crank", points={"A": (6.5, 0)})
    coupler = Body("coupler ABD", points={"A": (0, 0), "B": (28, 0), "D": (15, -5.5)})
    follower = Body("follower BoB", points={"Bo": (0, 0), "B": (14, 0)})
    link = Body("link EDH", points={"D": (0, 0), "H": (31.5, 0), "E": (-11.5, 0)})
    rocker = Body("rocker HoH", points={"Ho": (0, 0), "H": (17.5, 0)})
    mechanism = Mechanism(
        [crank, coupler, follower, link, rocker],
        [Revolute("Ao", crank, (0, 0), None, (0, 0)),
         Revolute("A", crank, "A", coupler, "A"),
         Revolute("B", coupler, "B", follower, "B"),
         Revolute("Bo", follower, "Bo", None, (26.5, -10)),
         Revolute("D", coupler, "D", link, "D"),
         Revolute("H", link, "H", rocker, "H"),
         Revolute("Ho", rocker, "Ho", None, polar(25, 90 + dodge)),
         AngleDriver("crank", crank)])
    sketch = mechanism.coordinates({"crank": (0, 0, 0), "coupler ABD": (6.5, 0, 3.1),
                                    "follower BoB": (26.5, -10, 55.4),
                                    "link EDH": (21.8, -4.7, 98), "rocker HoH": (0, 25, 5)})

    def check(s):
        _side(s, "coupler ABD", "A", "follower BoB", "Bo", "coupler ABD", "B", +1,
              "Example 4, AoABBo (uncrossed)")
        _side(s, "link EDH", "D", "rocker HoH", "Ho", "link EDH", "H", -1,
              "Example 4, AoDHHo (crossed)")

    def columns(s, angle):
        ar = s.ar
        return [ar.num(angle), s.omega("link EDH"), s.alpha("link EDH"),
                s.velocity("link EDH", "E")[0], s.acceleration("link EDH", "E")[0]]

    return ExampleModel(mechanism, sketch, 0, check, columns, "accelerations")


# --------------------------------------------------------------------------- Example 5

def crushing_force(t14_deg, w7):
    """Example 5's crushing force (N): 500/(T(14)+100.5)^3 while the jaw closes (W(7) < 0), else 0."""
    if w7 < 0:
        return 500 / (t14_deg + 100.5) ** 3
    return 0 * t14_deg


def example5(dodge=DODGE):
    """Double-toggle jaw crusher (Fig. 13), m-kg-s, masses and inertias of the paper's table.

    Lines 5100-5120: Bo = (-.85, 1.25), crank AoA = .075 (200 kg, I = 156, G at Ao),
    pitman ABC: AB = 1.2 (30 kg, I = 18, G .5 from A on AB), toggle BoB = .85
    (15 kg, I = 3.7, G .35 from Bo on BoB); AoABBo crossed.  The listing takes C
    at R(11) = 1.2, H(11) = 0 from A, i.e. on B (the table's BC = 20 cm is not
    used by the listing; the contract's T(14) range -100.4..-99.5 confirms C = B).
    Lines 5200-5210: Do = (.75, -1), toggle CD = 1.2 (35 kg, I = 28, G .4 from C),
    jaw DoD = 2.45 (180 kg, I = 435, G 1.5 from Do at 9 deg from Do->D, crushing
    point P 2.5 from Do at 18 deg); AoCDDo uncrossed.  The crushing force
    F = 500/(T(14)+100.5)^3 N (T(14) the inclination of D->Do in (-180, 180] deg)
    acts at P normal to DoD whenever the jaw's angular velocity W(7) < 0, on
    the jaw along u(T(14) - 90 deg): the material's reaction, resisting the
    closing jaw (the printed line 5050's u(T(14) + 90 deg) would drive it; see
    listings/ERRATA.md).  Gravity 0 (the listing never sets G).
    """
    crank = Body("crank", mass=200, inertia=156, points={"A": (".075", 0)})
    pitman = Body("pitman ABC", mass=30, inertia=18, centre=(".5", 0),
                  points={"A": (0, 0), "B": ("1.2", 0), "C": polar("1.2", 0)})
    toggle = Body("toggle BoB", mass=15, inertia="3.7", centre=(".35", 0),
                  points={"Bo": (0, 0), "B": (".85", 0)})
    toggle2 = Body("toggle CD", mass=35, inertia=28, centre=(".4", 0),
                   points={"C": (0, 0), "D": ("1.2", 0)})
    jaw = Body("jaw DoD", mass=180, inertia=435, centre=polar("1.5", 9),
               points={"Do": (0, 0), "D": ("2.45", 0), "P": polar("2.5", 18)})

    def crushing(s):
        ar = s.ar
        t14 = s.direction("jaw DoD", "D", "Do")
        force = crushing_force(t14, s.omega("jaw DoD"))
        direction = _unit(ar, t14 - 90)
        return (force * direction[0], force * direction[1])

    mechanism = Mechanism(
        [crank, pitman, toggle, toggle2, jaw],
        [Revolute("Ao", crank, (0, 0), None, (0, 0)),
         Revolute("A", crank, "A", pitman, "A"),
         Revolute("B", pitman, "B", toggle, "B"),
         Revolute("Bo", toggle, "Bo", None, ("-.85", "1.25")),
         Revolute("C", pitman, "C", toggle2, "C"),
         Revolute("D", toggle2, "D", jaw, "D"),
         Revolute("Do", jaw, "Do", None, (".75", -1)),
         AngleDriver("crank", crank)],
        loads=[PointLoad(jaw, "P", crushing)])
    sketch = mechanism.coordinates({"crank": (0, 0, 0), "pitman ABC": (0.075, 0, 93.7),
                                    "toggle BoB": (-0.85, 1.25, -3.5),
                                    "toggle CD": (0, 1.2, 10.3), "jaw DoD": (0.75, -1, 79.9)})

    def check(s):
        _side(s, "pitman ABC", "A", "toggle BoB", "Bo", "pitman ABC", "B", -1,
              "Example 5, AoABBo (crossed)")
        _side(s, "toggle CD", "C", "jaw DoD", "Do", "toggle CD", "D", +1,
              "Example 5, AoCDDo (uncrossed)")

    def columns(s, angle):
        ar = s.ar
        return [ar.num(angle), s.driver_torque("crank"), _magnitude(ar, s.reaction("Bo", "toggle BoB")),
                _magnitude(ar, s.reaction("Ao", "crank"))]

    def forces(s):
        """Program 2's force outputs for AoABBo (the listing's last call), in the contract's signs."""
        return _named(("U(2)", s.driver_torque("crank")),
                      ("F(21)", "F(22)", s.reaction("Ao", "crank")),
                      ("F(23)", "F(24)", s.reaction("A", "pitman ABC")),
                      ("F(25)", "F(26)", s.reaction("B", "toggle BoB")),
                      ("F(27)", "F(28)", s.reaction("Bo", "toggle BoB")),
                      ("F(32)", "F(33)", s.reaction("C", "pitman ABC")))

    return ExampleModel(mechanism, sketch, 0, check, columns, "forces", forces)


BUILDERS = {1: example1, 2: example2, 3: example3, 4: example4, 5: example5}


def example_mechanism(n: int, dodge=DODGE) -> ExampleModel:
    """Example ``n``'s model (a fresh one each call); ``dodge``: see DODGE."""
    try:
        return BUILDERS[n](dodge)
    except KeyError:
        raise ValueError(f"the paper has examples 1 to 5, not {n!r}") from None


def example_snapshots(n: int, crank_angles=None, number="float", dps=50, gravity=0, level=None, dodge=DODGE):
    """Solved states of example ``n`` at ``crank_angles`` (degrees; default the listing's loop).

    ``gravity``: acceleration of gravity along -y (the listings leave G = 0).
    ``level``: as Mechanism.analyse; default "forces" for Examples 2 and 5,
    "accelerations" for the others.  ``dodge``: see DODGE.
    """
    model = example_mechanism(n, dodge)
    model.mechanism.gravity = gravity
    angles = EXAMPLE_ANGLES[n] if crank_angles is None else list(crank_angles)
    return model.mechanism.analyse(angles, CRANK_RATE[n], 0, model.sketch, number=number, dps=dps,
                                   level=level or model.level, branch_check=model.check,
                                   home_deg=model.home)


def _table(rows, number):
    import numpy as np

    return np.array(rows, dtype=float if number == "float" else object)


def example_columns(n: int, crank_angles=None, number="float", dps=50, gravity=0, dodge=DODGE):
    """The columns example ``n`` prints (see COLUMNS[n]), one row per crank angle, as a numpy array.

    Float by default; ``number="mpmath"`` gives an object array of mpf at ``dps`` digits.
    ``dodge=0``: the mechanism without the listings' 0.1 degree offsets (see DODGE).
    """
    columns = example_mechanism(n, dodge).columns
    angles = EXAMPLE_ANGLES[n] if crank_angles is None else list(crank_angles)
    snapshots = example_snapshots(n, angles, number, dps, gravity, dodge=dodge)
    return _table([columns(s, angle) for s, angle in zip(snapshots, angles)], number)


def example_forces(n: int, crank_angles=None, number="float", dps=50, gravity=0, dodge=DODGE) -> dict:
    """Signed force outputs of Examples 2 and 5 under the contract's names and conventions.

    Example 2: U(1), N(1), F(3)..F(6), F(10), F(11) of Program 1 on AoABC and F(7), F(8)
    (the force of CD on ABC at C).  Example 5: U(2), F(21)..F(28) of Program 2 on
    AoABBo and F(32), F(33) (the force of CD on the pitman at C).  Reactions are the
    force of the upstream body on the downstream one, of the ground on the link at
    fixed pivots; torques counter-clockwise positive.  Returns {name: array}.
    """
    reader = example_mechanism(n, dodge).forces
    if reader is None:
        raise ValueError(f"Example {n} has no force analysis (Examples 2 and 5 have)")
    snapshots = example_snapshots(n, crank_angles, number, dps, gravity, dodge=dodge)
    named = [reader(s) for s in snapshots]
    return {name: _table([row[name] for row in named], number) for name in named[0]}
