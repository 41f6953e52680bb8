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
from yaseer.reference.basic_linkages import collect, fourbar_snapshots, slider_crank
from yaseer.reference.solver import normalise_degrees


# --------------------------------------------------------------------------- seed 001

def seed001_slider_crank(thetas_deg, omega=-15, alpha=-10, branch="open", AO=3, AB=8, offset=2,
                         number="float", dps=50):
    """Seed 001's offset slider-crank at crank angles ``thetas_deg`` (thetaAO, degrees).

    Returns xB, vB, aB (slider, along +x), thetaAB (degrees, inclination of A->B),
    omegaAB, alphaAB (rad/s, rad/s^2, counter-clockwise positive).  In the
    contract's terms: axis 0 deg, e = -offset (the line y = +offset lies to the
    left of +x), open = B ahead of A.
    """
    if branch not in ("open", "crossed"):
        raise ValueError("branch is 'open' (xB > xA) or 'crossed' (xB < xA)")
    r = slider_crank(_negated(offset), AO, AB, thetas_deg,
                     omega, alpha, axis_deg=0, ahead=branch == "open", number=number, dps=dps)
    return {"xB": r["xB"], "vB": r["vxB"], "aB": r["axB"], "thetaAB": r["T(3)"],
            "omegaAB": r["W(3)"], "alphaAB": r["A(3)"]}


def _negated(value):
    """-value, exact for decimal strings."""
    if isinstance(value, str):
        from decimal import Decimal

        return str(-Decimal(value))
    return -value


# --------------------------------------------------------------------------- four-bars

SIDES = {"left": 1, "right": -1}


def seed003_fourbar(thetas_deg, omega=10, alpha=0, branch="right", a=30, b=36, c=36, d=60,
                    number="float", dps=50):
    """Seed 003's four-bar at THET = ``thetas_deg``; ``branch``: C left or right of B->D.

    The printed table's first row of each angle is the "right" branch.
    Returns PHI (D->C), BETA (B->C) in degrees and the rates
    omega_coupler = dBETA/dt, omega_follower = dPHI/dt (rad/s; the printed
    VELB and VELC), alpha_coupler, alpha_follower (rad/s^2).
    """
    snapshots = fourbar_snapshots(thetas_deg, omega, alpha, (a, b, c), (d, 0), SIDES[branch],
                                  number, dps, "seed 003")
    rows = [dict(PHI=s.angle("follower"), BETA=s.angle("coupler"),
                 omega_coupler=s.omega("coupler"), omega_follower=s.omega("follower"),
                 alpha_coupler=s.alpha("coupler"), alpha_follower=s.alpha("follower"))
            for s in snapshots]
    return collect(rows, number)


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
    snapshots = fourbar_snapshots(thetas, -theta1_rate, -theta1_acceleration, (AB, BD, DE), (AE, 0),
                                  SIDES[branch], number, dps, "seed 004")
    rows = []
    for s in snapshots:
        rows.append(dict(theta2=normalise_degrees(-s.angle("coupler"), ar),
                         theta3=normalise_degrees(s.angle("follower") + 180, ar),
                         theta2_rate=-s.omega("coupler"), theta3_rate=s.omega("follower"),
                         theta2_acceleration=-s.alpha("coupler"),
                         theta3_acceleration=s.alpha("follower")))
    return collect(rows, number)
