"""The reference models of the seed papers' linkages against the numbers those papers print."""

from __future__ import annotations

import math

import pytest

from yaseer.reference.seeds import seed001_slider_crank, seed003_fourbar, seed004_fourbar
from yaseer.reference.solver import MechanismError


# --------------------------------------------------------------------------- seed 001

def test_seed001_worked_row_c():
    """Norton Table P7-2 row c as TK Solver prints it: xB 9.79, vB -41.46, omegaAB 5.42, aB -709.1, alphaAB -29.03."""
    r = seed001_slider_crank([-30], omega=-15, alpha=-10)
    assert round(float(r["xB"][0]), 2) == 9.79
    assert round(float(r["vB"][0]), 2) == -41.46
    assert round(float(r["omegaAB"][0]), 2) == 5.42
    assert round(float(r["aB"][0]), 1) == -709.1
    assert round(float(r["alphaAB"][0]), 2) == -29.03


def test_seed001_crossed_branch_follows_the_tk_rule():
    """TK's position rule for the crossed branch: xB - xA = -sqrt(AB^2 - (yB - yA)^2)."""
    theta = -30.0
    xa, ya = 3 * math.cos(math.radians(theta)), 3 * math.sin(math.radians(theta))
    r = seed001_slider_crank([theta], branch="crossed")
    assert r["xB"][0] == pytest.approx(xa - math.sqrt(64 - (2 - ya) ** 2), rel=1e-13)
    # the crossed rod is the open rod mirrored in the vertical through A: opposite rate
    open_ = seed001_slider_crank([theta])
    assert r["omegaAB"][0] == pytest.approx(-open_["omegaAB"][0], rel=1e-12)


def test_seed001_rejects_an_unknown_branch():
    with pytest.raises(ValueError):
        seed001_slider_crank([0], branch="sideways")


def test_seed001_full_cycle_in_mpmath_matches_float():
    angles = list(range(0, 360, 15))
    exact = seed001_slider_crank(angles, number="mpmath", dps=30)
    rough = seed001_slider_crank(angles)
    for name in ("xB", "vB", "aB", "omegaAB", "alphaAB"):
        for e, f in zip(exact[name], rough[name]):
            assert abs(float(e) - f) <= 1e-11 * (1 + abs(f))


# --------------------------------------------------------------------------- seed 003

# (THET, PHI, BETA) as printed in Plate 1 (the first row of each angle is the branch with
# C right of B->D, the second C left); None where the scan lost the cell.
PRINTED_003 = {
    "right": [(0, -114.62, -65.38), (30, -144.88, -82.70), (60, -166.19, -73.81), (90, 174.73, -47.86),
              (270, -132.14, None), (300, -106.19, -13.81), (330, -97.30, -35.12)],
    "left": [(0, 114.62, None), (30, 97.30, 35.12), (60, 106.19, 13.81), (90, None, -5.27),
             (270, -174.73, 47.86), (300, None, 73.81), (330, 144.88, 82.70)],
}


@pytest.mark.parametrize("branch", ["right", "left"])
def test_seed003_printed_angles(branch):
    rows = PRINTED_003[branch]
    r = seed003_fourbar([t for t, _, _ in rows], branch=branch)
    for k, (theta, phi, beta) in enumerate(rows):
        if phi is not None:
            assert round(float(r["PHI"][k]), 2) == phi, theta
        if beta is not None:
            assert round(float(r["BETA"][k]), 2) == beta, theta


def test_seed003_printed_follower_rates():
    """VELC (dPHI/dt, rad/s): -10.00 in the first row, -8.69 in the last; the other
    legible magnitudes (8.69, 8.26, 12.26) all occur among the correct rates."""
    thetas = [0, 30, 60, 90, 270, 300, 330]
    right = seed003_fourbar(thetas, branch="right")["omega_follower"]
    left = seed003_fourbar(thetas, branch="left")["omega_follower"]
    assert round(float(right[0]), 2) == -10.00
    assert round(float(left[-1]), 2) == -8.69
    magnitudes = {round(abs(float(w)), 2) for w in list(right) + list(left)}
    assert {10.00, 8.69, 8.26, 12.26} <= magnitudes


def test_seed003_cannot_be_assembled_where_the_program_skipped():
    """120..240 deg were skipped by the Fortran (negative discriminant): not assembled here either."""
    for theta in (120, 180, 240):
        with pytest.raises(MechanismError, match="cannot be assembled"):
            seed003_fourbar([theta])
    # the assembly limit: |B - D| = b + c at cos(THET) = (a^2 + d^2 - 72^2) / (2 a d)
    limit = math.degrees(math.acos((30 ** 2 + 60 ** 2 - 72 ** 2) / (2 * 30 * 60)))
    seed003_fourbar([limit - 0.5])
    with pytest.raises(MechanismError):
        seed003_fourbar([limit + 0.5])


# --------------------------------------------------------------------------- seed 004

def test_seed004_findroot_at_90_degrees():
    """FindRoot at th1 = 90 deg gives th2 = 64.94 deg, th3 = 8.80 deg."""
    r = seed004_fourbar([90])
    assert round(float(r["theta2"][0]), 2) == 64.94
    assert round(float(r["theta3"][0]), 2) == 8.80
    # and they satisfy that paper's own equations (12), (13)
    t1, t2, t3 = (math.radians(v) for v in (90, r["theta2"][0], r["theta3"][0]))
    assert -0.3 * math.cos(t1) + 0.5 * math.cos(t2) + math.cos(t3) == pytest.approx(1.2, abs=1e-13)
    assert 0.3 * math.sin(t1) - 0.5 * math.sin(t2) + math.sin(t3) == pytest.approx(0, abs=1e-13)


@pytest.mark.parametrize("branch, side, sign", [("right", 1, 1), ("right", -1, -1),
                                                ("left", -1, 1), ("left", 1, -1)])
def test_seed004_rates_tend_to_the_change_point_values(branch, side, sign):
    """Near the collinear configuration the rates tend to that paper's eqs. (7), (8):
    th2' = (1 +- 2 sqrt 2)/5 th1', th3' = (-1 +- sqrt 2)/5 th1' (and eq. (6) holds)."""
    r = seed004_fourbar([side * 1e-12], branch=branch, number="mpmath", dps=50)
    w2, w3 = float(r["theta2_rate"][0]), float(r["theta3_rate"][0])
    assert w2 == pytest.approx((1 + sign * 2 * math.sqrt(2)) / 5, abs=1e-10)
    assert w3 == pytest.approx((-1 + sign * math.sqrt(2)) / 5, abs=1e-10)
    assert 0.3 == pytest.approx(0.5 * w2 - w3, abs=1e-10)


@pytest.mark.parametrize("number", ["float", "mpmath"])
def test_seed004_change_point_is_an_error(number):
    """At the change point itself the constraints do not fix the velocities: an error, not a number."""
    with pytest.raises(MechanismError, match="singular"):
        seed004_fourbar([0], number=number)


def test_seed004_float_refuses_what_it_cannot_resolve_and_mpmath_resolves_it():
    with pytest.raises(MechanismError, match="singular"):
        seed004_fourbar([1e-6])
    r = seed004_fourbar([1e-6], number="mpmath", dps=50)
    assert float(r["theta2_rate"][0]) == pytest.approx((1 + 2 * math.sqrt(2)) / 5, rel=1e-6)


def test_seed004_mpmath_takes_angles_near_the_change_point_exactly():
    """th1 = 1e-12 deg is passed to mpmath without rounding 180 - th1 in binary: th2 ~ 0.7657 th1."""
    r = seed004_fourbar([1e-12], number="mpmath", dps=50)
    assert float(r["theta2"][0]) == pytest.approx((1 + 2 * math.sqrt(2)) / 5 * 1e-12, rel=1e-9)
    assert float(r["theta3"][0]) == pytest.approx((-1 + math.sqrt(2)) / 5 * 1e-12, rel=1e-9)
