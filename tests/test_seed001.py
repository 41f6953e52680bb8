"""Seed 001 (Boyle and Liu's TK Solver slider-crank): Norton's row c, both branches,
and the slider-driven "backsolve".

Independent model here: x_B(theta) = a cos(theta) +/- sqrt(b^2 - (y_B - a sin(theta))^2)
on the slider line y_B = 2, differentiated by finite differences in time.
"""

from __future__ import annotations

import csv
import math
import subprocess
import sys
from pathlib import Path

import pytest

from yaseer.commands.diff import parse_table
from yaseer.linkages.errors import AssemblyError, LockedError
from yaseer.linkages.slider_crank import slider_crank
from yaseer.linkages.slider_driven import LEFT, RIGHT, crank_angle_for_travel, crank_from_slider

DATA = Path(__file__).resolve().parent.parent / "yaseer" / "data"
AO, AB, OFFSET = 3.0, 8.0, 2.0
OMEGA, ALPHA, THETA = -15.0, -10.0, -30.0
OPEN, CROSSED = 1.0, -1.0
# Program 1 frames for the two branches: (axis_deg, eccentricity); see the listing.
FRAMES = {OPEN: (0.0, -OFFSET), CROSSED: (180.0, OFFSET)}


def slider_x(theta_rad: float, branch: float) -> float:
    """x of the piston pin B on the line y = OFFSET (open: B right of A)."""
    return AO * math.cos(theta_rad) + branch * math.sqrt(AB ** 2 - (OFFSET - AO * math.sin(theta_rad)) ** 2)


def rod_angle(theta_rad: float, branch: float) -> float:
    """Direction of A->B, radians."""
    return math.atan2(OFFSET - AO * math.sin(theta_rad), slider_x(theta_rad, branch) - AO * math.cos(theta_rad))


def time_derivatives(f, theta_deg, omega, alpha, h=2e-5):
    """f(theta(t)) and its first two time derivatives at t=0, theta = theta0 + omega t + alpha t^2/2."""
    def at(t):
        return f(math.radians(theta_deg) + omega * t + 0.5 * alpha * t * t)
    value = at(0.0)
    first = (at(h) - at(-h)) / (2 * h)
    second = (at(h) - 2 * value + at(-h)) / h ** 2
    return value, first, second


def _unwrapped(f):
    reference = []

    def g(theta):
        angle = f(theta)
        if reference:
            angle = reference[0] + math.remainder(angle - reference[0], 2 * math.pi)
        else:
            reference.append(angle)
        return angle
    return g


def printed_row() -> dict:
    table = parse_table((DATA / "seed001_norton_c.csv").read_text())
    return {name: cell.value for name, cell in zip(table.names, table.rows[0])}


def test_independent_model_reproduces_the_papers_printed_open_row():
    row = printed_row()
    x, v, a = time_derivatives(lambda t: slider_x(t, OPEN), THETA, OMEGA, ALPHA)
    _, w, al = time_derivatives(_unwrapped(lambda t: rod_angle(t, OPEN)), THETA, OMEGA, ALPHA)
    assert (x, v, w, a, al) == pytest.approx(
        (row["xB"], row["vB"], row["omegaAB"], row["aB"], row["alphaAB"]), abs=0.06)


@pytest.mark.parametrize("branch", [OPEN, CROSSED])
def test_program_1_frames_give_both_branches(branch):
    axis, e = FRAMES[branch]
    result = slider_crank(e, AO, AB, THETA, OMEGA, ALPHA, axis_deg=axis)
    x, v, a = time_derivatives(lambda t: slider_x(t, branch), THETA, OMEGA, ALPHA)
    _, w, al = time_derivatives(_unwrapped(lambda t: rod_angle(t, branch)), THETA, OMEGA, ALPHA)
    assert result.pin_b.pos.real == pytest.approx(x, abs=1e-9)
    assert result.pin_b.pos.imag == pytest.approx(OFFSET, abs=1e-12)
    assert result.pin_b.vel.real == pytest.approx(v, abs=1e-5)
    assert result.rod.omega == pytest.approx(w, abs=1e-5)
    assert result.pin_b.acc.real == pytest.approx(a, rel=1e-5, abs=1e-3)
    assert result.rod.alpha == pytest.approx(al, rel=1e-5, abs=1e-3)


def test_crossed_branch_row_c_values():
    """The crossed row the paper does not print (independent model, 2 decimals)."""
    x, v, a = time_derivatives(lambda t: slider_x(t, CROSSED), THETA, OMEGA, ALPHA)
    _, w, al = time_derivatives(_unwrapped(lambda t: rod_angle(t, CROSSED)), THETA, OMEGA, ALPHA)
    assert (round(x, 2), round(v, 2), round(w, 2), round(a, 1), round(al, 2)) == (-4.6, -3.54, -5.42, -490.0, 29.03)


def test_backsolve_from_the_printed_slider_motion_recovers_the_crank():
    """Slider at the printed xB, vB, aB -> the crank's -30 deg, -15 rad/s, -10 rad/s^2
    (to the precision the printed 3-4 digits allow)."""
    row = printed_row()
    crank = crank_from_slider(-OFFSET, AO, AB, row["xB"], row["vB"], row["aB"], crank_side=RIGHT)
    assert crank.theta_deg == pytest.approx(THETA, abs=0.2)
    assert crank.omega == pytest.approx(OMEGA, abs=0.1)
    assert crank.alpha == pytest.approx(ALPHA, abs=2.0)


@pytest.mark.parametrize("branch", [OPEN, CROSSED])
@pytest.mark.parametrize("theta_deg, omega, alpha", [(-30, -15, -10), (70, 4, 25), (200, -2, 3), (300, 9, -40)])
def test_backsolve_inverts_the_independent_slider_motion(branch, theta_deg, omega, alpha):
    x, v, a = time_derivatives(lambda t: slider_x(t, branch), theta_deg, omega, alpha, h=1e-5)
    axis, e = FRAMES[branch]
    along = x if branch == OPEN else -x  # travel s along u(axis)
    pin_a = complex(AO * math.cos(math.radians(theta_deg)), AO * math.sin(math.radians(theta_deg)))
    pin_b = complex(x, OFFSET)
    side = LEFT if (pin_b.conjugate() * pin_a).imag > 0 else RIGHT
    crank = crank_from_slider(e, AO, AB, along, branch * v, branch * a, axis_deg=axis, crank_side=side)
    assert math.remainder(crank.theta_deg - theta_deg, 360) == pytest.approx(0, abs=1e-7)
    assert crank.omega == pytest.approx(omega, rel=1e-6)
    assert crank.alpha == pytest.approx(alpha, rel=1e-4, abs=1e-3)


def test_the_other_crank_side_is_the_mirror_solution():
    theta_right = crank_angle_for_travel(-OFFSET, AO, AB, 9.0, crank_side=RIGHT)
    theta_left = crank_angle_for_travel(-OFFSET, AO, AB, 9.0, crank_side=LEFT)
    direction_of_b = math.degrees(math.atan2(OFFSET, 9.0))
    assert theta_left - direction_of_b == pytest.approx(direction_of_b - theta_right)
    for theta in (theta_left, theta_right):
        assert slider_x(math.radians(theta), OPEN) == pytest.approx(9.0)


def test_unreachable_slider_position_is_an_assembly_error():
    with pytest.raises(AssemblyError, match="cannot reach"):
        crank_from_slider(-OFFSET, AO, AB, 12.0, 1.0)


def test_dead_centre_cannot_be_driven_from_the_slider():
    """At the outer dead centre (A, B in line, rod along AoB) ds/dtheta = 0."""
    far = math.sqrt((AO + AB) ** 2 - OFFSET ** 2)
    with pytest.raises(LockedError, match="dead centre"):
        crank_from_slider(-OFFSET, AO, AB, far, 1.0)


# ------------------------------------------------------------ the listing


LISTING = Path(__file__).resolve().parent.parent / "listings" / "tk_slider_crank.bas"


@pytest.fixture(scope="module")
def listing_csv() -> list[list[str]]:
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(LISTING), "--format", "csv"],
                          capture_output=True, text=True, check=True)
    return list(csv.reader(done.stdout.splitlines()))


def test_listing_prints_row_c_as_the_paper_then_the_crossed_row(listing_csv):
    from yaseer.commands.diff import compare, csv_number_rows
    rows = csv_number_rows("\n".join(",".join(r) for r in listing_csv))
    table = parse_table((DATA / "seed001_norton_c.csv").read_text())
    verdict = compare(rows[:1], table)
    assert verdict.agrees and verdict.compared_cells == 6
    theta, x, v, w, a, al = rows[1]
    assert (theta, round(x, 2), round(v, 2), round(w, 2), round(a, 1), round(al, 2)) == \
        (-30, -4.6, -3.54, -5.42, -490.0, 29.03)


def test_listing_full_cycles_follow_the_independent_model(listing_csv):
    rows = [list(map(float, r)) for r in listing_csv[2:50]]
    for k, (theta, x, v, w, a, al) in enumerate(rows):
        branch = OPEN if k < 24 else CROSSED
        assert theta == 15 * (k % 24)
        ref_x, ref_v, ref_a = time_derivatives(lambda t: slider_x(t, branch), theta, OMEGA, ALPHA)
        _, ref_w, ref_al = time_derivatives(_unwrapped(lambda t: rod_angle(t, branch)), theta, OMEGA, ALPHA)
        assert (x, v, w) == pytest.approx((ref_x, ref_v, ref_w), abs=1e-4)
        assert (a, al) == pytest.approx((ref_a, ref_al), abs=5e-3)


def test_listing_backsolve_recovers_the_crank(listing_csv):
    label, theta, omega, alpha = listing_csv[-1]
    assert label.startswith("BACKSOLVE")
    expected = crank_from_slider(-OFFSET, AO, AB, 9.79, -41.46, -709.1, crank_side=RIGHT)
    assert (float(theta), float(omega), float(alpha)) == pytest.approx(tuple(expected), rel=1e-9)
    assert float(theta) == pytest.approx(THETA, abs=0.2) and float(omega) == pytest.approx(OMEGA, abs=0.1)


def test_listing_with_the_pseudographic_method_gives_the_same_rows(listing_csv):
    """The TK model's construction (PROG 1 method "pseudographic") against the default."""
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(LISTING), "--format", "csv",
                           "--method", "1=pseudographic"], capture_output=True, text=True, check=True)
    rows = list(csv.reader(done.stdout.splitlines()))
    assert len(rows) == len(listing_csv) == 51
    for mine, default in zip(rows[:-1], listing_csv[:-1]):
        assert [float(x) for x in mine] == pytest.approx([float(x) for x in default], rel=1e-9, abs=1e-9)
