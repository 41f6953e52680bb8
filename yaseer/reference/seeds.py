"""The seed papers' linkages as real links and joints (independent reference).

* seed 001 (TK Solver, Norton's Table P7-2 row c): offset slider-crank, AO = 3,
  AB = 8, slider pin B on the line y = +offset running along +x; "open" branch
  xB > xA, "crossed" xB < xA.  :func:`seed001_slider_crank`.
* seed 003 (Fortran): four-bar A(0, 0) crank AB = a = 30, coupler BC = b = 36,
  follower DC = c = 36, D = (d, 0) = (60, 0); angles THET (A->B), BETA (B->C),
  PHI (D->C).  Non-Grashof: it assembles only for |THET| <= 100.95 deg.
  :func:`seed003_fourbar`.
* seed 004 (Mathematica FindRoot): change-point four-bar A(0, 0) crank AB = 0.3,
  coupler BD = 0.5, output DE = 1, E = (1.2, 0).  That paper's angles:
  B = 0.3 (-cos th1, sin th1), D - B = 0.5 (cos th2, -sin th2),
  E - D = (cos th3, sin th3), so th1 = 180 - (inclination of A->B),
  th2 = -(inclination of B->D), th3 = inclination of D->E.  Its collinear
  configuration (th1 = 0: B, D, E on the x axis) is a change point, where the
  position Jacobian is singular: the solver stops there with MechanismError.
  :func:`seed004_fourbar`.

Each function takes a sequence of crank angles (degrees, the paper's own
convention), solves each position independently by Newton from a rough sketch
on the requested branch (so gaps where the linkage cannot be assembled are
allowed: those raise MechanismError), and returns a dict of numpy arrays
(float) or of lists of mpf (``number="mpmath"``, ``dps`` digits).
Angles out in degrees in (-180, 180], rates rad/s and rad/s^2.
"""

from __future__ import annotations

from yaseer.reference.arithmetic import arithmetic_for
from yaseer.reference.solver import (AngleDriver, Body, Mechanism, MechanismError, PointOnLine,
                                     Revolute, cross, normalise_degrees)

import math


def _collect(rows: list[dict], number):
    """Rows of named values -> dict of arrays (float) or lists (mpmath)."""
    import numpy as np

    names = rows[0].keys() if rows else ()
    if number == "float":
        return {name: np.array([float(r[name]) for r in rows]) for name in names}
    return {name: [r[name] for r in rows] for name in names}


def _solve_one(mechanism, sketch, angle_deg, rate, acceleration, number, dps, check):
    """One position by Newton from ``sketch`` (float first, then polished in ``number``)."""
    (snapshot,) = mechanism.analyse([angle_deg], rate, acceleration, sketch, number=number,
                                    dps=dps, branch_check=check)
    return snapshot


# --------------------------------------------------------------------------- seed 001

def slider_crank(crank, rod, offset):
    """Crank AO (pivot O at the origin), rod AB, pin B on the line y = offset along +x."""
    crank_body = Body("crank", points={"A": (crank, 0)})
    rod_body = Body("rod", points={"A": (0, 0), "B": (rod, 0)})
    return Mechanism([crank_body, rod_body],
                     [Revolute("O", crank_body, (0, 0), None, (0, 0)),
                      Revolute("A", crank_body, "A", rod_body, "A"),
                      PointOnLine("B", rod_body, "B", None, (0, offset), 0),
                      AngleDriver("crank", crank_body)])


def seed001_slider_crank(thetas_deg, omega=-15, alpha=-10, branch="open", AO=3, AB=8, offset=2,
                         number="float", dps=50):
    """Seed 001's offset slider-crank at crank angles ``thetas_deg`` (thetaAO, degrees).

    Returns xB, vB, aB (slider, along +x), thetaAB (degrees, inclination of A->B),
    omegaAB, alphaAB (rad/s, rad/s^2, counter-clockwise positive).
    """
    if branch not in ("open", "crossed"):
        raise ValueError("branch is 'open' (xB > xA) or 'crossed' (xB < xA)")
    mechanism = slider_crank(AO, AB, offset)
    sign = 1 if branch == "open" else -1

    def check(s):
        if sign * (s.position("rod", "B")[0] - s.position("rod", "A")[0]) <= 0:
            raise MechanismError(f"seed 001: the slider-crank left its {branch} branch")

    rows = []
    for theta in thetas_deg:
        a = (AO * math.cos(math.radians(theta)), AO * math.sin(math.radians(theta)))
        sketch = mechanism.coordinates({"crank": (0, 0, theta),
                                        "rod": (a[0], a[1], 0 if sign > 0 else 180)})
        s = _solve_one(mechanism, sketch, theta, omega, alpha, number, dps, check)
        rows.append(dict(xB=s.position("rod", "B")[0], vB=s.velocity("rod", "B")[0],
                         aB=s.acceleration("rod", "B")[0], thetaAB=s.angle("rod"),
                         omegaAB=s.omega("rod"), alphaAB=s.alpha("rod")))
    return _collect(rows, number)


# --------------------------------------------------------------------------- four-bars

def four_bar(crank, coupler, follower, follower_pivot):
    """Crank pivot at the origin; crank pin B = crank u(theta); coupler B->C; follower pivot->C."""
    crank_body = Body("crank", points={"B": (crank, 0)})
    coupler_body = Body("coupler", points={"B": (0, 0), "C": (coupler, 0)})
    follower_body = Body("follower", points={"D": (0, 0), "C": (follower, 0)})
    return Mechanism([crank_body, coupler_body, follower_body],
                     [Revolute("A", crank_body, (0, 0), None, (0, 0)),
                      Revolute("B", crank_body, "B", coupler_body, "B"),
                      Revolute("C", coupler_body, "C", follower_body, "C"),
                      Revolute("D", follower_body, "D", None, follower_pivot),
                      AngleDriver("crank", crank_body)])


def _four_bar_sketch(mechanism, theta_deg, crank, coupler, follower, pivot, side):
    """A rough placement: C half a link off the midpoint of B and D, on ``side`` (+1 left, -1 right)."""
    crank, coupler, follower = float(crank), float(coupler), float(follower)
    pivot = (float(pivot[0]), float(pivot[1]))
    theta_deg = float(theta_deg)
    b = (crank * math.cos(math.radians(theta_deg)), crank * math.sin(math.radians(theta_deg)))
    mid = ((b[0] + pivot[0]) / 2, (b[1] + pivot[1]) / 2)
    run = (pivot[0] - b[0], pivot[1] - b[1])
    length = math.hypot(*run) or 1.0
    h = 0.5 * min(coupler, follower)
    c = (mid[0] - side * h * run[1] / length, mid[1] + side * h * run[0] / length)
    return mechanism.coordinates({
        "crank": (0, 0, theta_deg),
        "coupler": (b[0], b[1], math.degrees(math.atan2(c[1] - b[1], c[0] - b[0]))),
        "follower": (pivot[0], pivot[1], math.degrees(math.atan2(c[1] - pivot[1], c[0] - pivot[0])))})


def _side_check(side, what):
    def check(s):
        b, c, d = s.position("coupler", "B"), s.position("coupler", "C"), s.position("follower", "D")
        if side * cross((d[0] - b[0], d[1] - b[1]), (c[0] - b[0], c[1] - b[1])) <= 0:
            raise MechanismError(f"{what}: the four-bar left its assembly branch")
    return check


def _four_bar_rows(thetas_deg, omega, alpha, lengths, pivot, side, number, dps, what):
    crank, coupler, follower = lengths
    mechanism = four_bar(crank, coupler, follower, pivot)
    check = _side_check(side, what)
    snapshots = []
    for theta in thetas_deg:
        sketch = _four_bar_sketch(mechanism, theta, crank, coupler, follower, pivot, side)
        snapshots.append(_solve_one(mechanism, sketch, theta, omega, alpha, number, dps, check))
    return snapshots


SIDES = {"left": 1, "right": -1}


def seed003_fourbar(thetas_deg, omega=10, alpha=0, branch="right", a=30, b=36, c=36, d=60,
                    number="float", dps=50):
    """Seed 003's four-bar at THET = ``thetas_deg``; ``branch``: C left or right of B->D.

    The printed table's first row of each angle is the "right" branch.
    Returns PHI (D->C), BETA (B->C) in degrees and the rates
    omega_coupler = dBETA/dt, omega_follower = dPHI/dt (rad/s; the printed
    VELB and VELC), alpha_coupler, alpha_follower (rad/s^2).
    """
    snapshots = _four_bar_rows(thetas_deg, omega, alpha, (a, b, c), (d, 0), SIDES[branch],
                               number, dps, "seed 003")
    rows = [dict(PHI=s.angle("follower"), BETA=s.angle("coupler"),
                 omega_coupler=s.omega("coupler"), omega_follower=s.omega("follower"),
                 alpha_coupler=s.alpha("coupler"), alpha_follower=s.alpha("follower"))
            for s in snapshots]
    return _collect(rows, number)


def seed004_fourbar(theta1s_deg, theta1_rate=1, theta1_acceleration=0, branch="right",
                    AB="0.3", BD="0.5", DE="1", AE="1.2", number="float", dps=50):
    """Seed 004's change-point four-bar at that paper's th1 = ``theta1s_deg``.

    ``theta1_rate`` is d(th1)/dt (that paper's crank turns clockwise for
    positive th1 rate).  ``branch``: D right (the paper's FindRoot solution at
    th1 = 90) or left of the directed line B->E.  Returns th2, th3 (degrees,
    that paper's conventions), their rates (rad/s) and accelerations
    (rad/s^2).  At the collinear configuration th1 = 0 (mod 360) the position
    Jacobian is singular: MechanismError.  The lengths default to exact
    decimal strings (exact in mpmath: AB + AE = BD + DE holds exactly, so th1 = 0
    is a true change point); pass floats to analyse the binary-rounded linkage a
    float program sees (0.3 + 1.2 falls short of 1.5 by 5.6e-17 there, which
    moves the position at th1 = 0 by about 1e-8 rad).
    """
    ar = arithmetic_for(number, dps)
    thetas = [ar.num(180) - ar.num(t) for t in theta1s_deg]  # exact in mpmath near th1 = 0
    snapshots = _four_bar_rows(thetas, -theta1_rate, -theta1_acceleration, (AB, BD, DE), (AE, 0),
                               SIDES[branch], number, dps, "seed 004")
    rows = []
    for s in snapshots:
        rows.append(dict(theta2=normalise_degrees(-s.angle("coupler"), ar),
                         theta3=normalise_degrees(s.angle("follower") + 180, ar),
                         theta2_rate=-s.omega("coupler"), theta3_rate=s.omega("follower"),
                         theta2_acceleration=-s.alpha("coupler"),
                         theta3_acceleration=s.alpha("follower")))
    return _collect(rows, number)
