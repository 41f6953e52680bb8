"""Seed 004's space centrode: the paper's printed numbers, its equations (10)-(11)
on the independent reference solver, and ``yaseer centrode``."""

from __future__ import annotations

import argparse
import math

import numpy as np
import pytest

from yaseer.commands import centrode as command
from yaseer.linkages.centrode import SEED004, change_point_angles, collinear_centres, jumps, space_centrode
from yaseer.reference.seeds import seed004_fourbar


def test_change_point_is_the_crank_along_the_ground_away_from_e():
    assert change_point_angles(SEED004) == [0.0, 180.0]
    with pytest.raises(ArithmeticError):  # at 0 deg the joints are not in line: no quadratic
        collinear_centres(SEED004, 0.0)


def test_collinear_velocity_and_centre_are_the_papers():
    centres = collinear_centres(SEED004, 180.0)
    ratios = sorted(c.ratio for c in centres)
    assert ratios == pytest.approx(sorted((1 + s * 2 * math.sqrt(2)) / 5 for s in (1, -1)), abs=1e-13)
    acs = sorted(round(c.ac, 4) for c in centres)
    assert acs == [-1.1204, 0.0918]
    for centre in centres:  # eq. (9): AC = 3 / (2 +/- 4 sqrt 2) - 0.3 with BC = 0.3 / ratio
        assert centre.ac == pytest.approx(0.3 / centre.ratio - 0.3, abs=1e-13)


def test_first_collinear_pass_is_0918_and_the_second_minus_1_1204():
    tracked, centre = space_centrode(crank_angles_deg=np.arange(0.0, 720.0 + 1e-9, 2.0))
    passes = np.flatnonzero(tracked.singular)
    assert [round(centre[k].real, 4) for k in passes] == [0.0918, -1.1204]
    assert np.all(np.abs(centre[passes].imag) < 1e-12)


def test_centre_jumps_where_the_paper_says():
    """Printed: 22.62 and 337.38 deg; there the reference solver's follower DE is
    parallel to the crank (so the lines meeting in C are parallel)."""
    found = jumps()
    assert [round(j.crank_angle_deg, 2) for j in found] == [22.62, 337.38]
    for jump in found:
        assert jump.slope == pytest.approx(math.tan(math.radians(jump.crank_angle_deg)), abs=1e-12)
        misalignment = []
        for side in ("left", "right"):
            theta3 = seed004_fourbar([180.0 - jump.crank_angle_deg], branch=side)["theta3"][0]
            misalignment.append(abs(math.sin(math.radians(theta3 - jump.crank_angle_deg))))
        assert min(misalignment) < 1e-9 < max(misalignment)


def _paper_centre(theta1_deg: float, theta3_deg: float) -> complex:
    """Equations (10) and (11) of seed 004."""
    t1, t3 = math.tan(math.radians(theta1_deg)), math.tan(math.radians(theta3_deg))
    return complex(1.2 * t3 / (t1 + t3), -1.2 * t1 * t3 / (t1 + t3))


@pytest.mark.parametrize("beta", [40.0, 90.0, 135.0, 250.0, 300.0])
def test_centre_matches_equations_10_and_11_on_the_reference_solution(beta):
    """Each revolution's C equals eq. (10)-(11) with the reference solver's th1, th3
    for the assembly that revolution is on."""
    tracked, centre = space_centrode(crank_angles_deg=np.arange(0.0, 720.0, 5.0))
    angles = np.arange(0.0, 720.0, 5.0)
    for turn in (0.0, 360.0):
        k = int(np.flatnonzero(np.isclose(angles, beta + turn))[0])
        coupler_deg = math.degrees(float(tracked.fourbar.coupler.angle[k]))
        matched = []
        for side in ("left", "right"):
            row = seed004_fourbar([180.0 - beta], branch=side)
            if abs(math.remainder(-row["theta2"][0] - coupler_deg, 360.0)) < 1e-7:
                matched.append(_paper_centre(180.0 - beta, row["theta3"][0]))
        assert len(matched) == 1
        assert abs(centre[k] - matched[0]) < 1e-9


def test_findroot_solution_at_theta1_90_is_on_the_track():
    """The paper's Mathematica output: th2 = 64.94 deg, th3 = 8.80 deg at th1 = 90 (beta = 90)."""
    tracked, _ = space_centrode(crank_angles_deg=np.arange(0.0, 720.0, 90.0))
    couplers = [round(-math.degrees(float(tracked.fourbar.coupler.angle[k])), 2) for k in (1, 5)]
    followers = [round(math.degrees(float(tracked.fourbar.follower.angle[k])), 2) for k in (1, 5)]
    assert 64.94 in couplers and 8.80 in followers


def test_the_paper_s_tour_of_figure_5():
    angles = np.arange(0.0, 720.0, 0.5)
    _, centre = space_centrode(crank_angles_deg=angles)
    early = centre[(angles > 0.5) & (angles < 22.0)]
    assert np.all(early.real > 1.2) and np.all(early.imag > 0)          # from E to the upper right
    middle = centre[(angles > 23.0) & (angles < 337.0)]
    assert middle[0].real < 0 and middle[0].imag < 0                     # from the third quadrant ...
    assert middle[-1].real < 0 and middle[-1].imag > 0                   # ... to the second
    late = centre[(angles > 338.0) & (angles < 359.5)]
    assert np.all(late.real > 1.2) and np.all(late.imag < 0)            # fourth quadrant back to E
    second = centre[angles >= 360.0]
    assert np.all(np.abs(second) < 1.3)                                  # the closed thin curve
    assert abs(centre[0] - 1.2) < 1e-12 and abs(centre[np.flatnonzero(angles == 360.0)[0]] - 1.2) < 1e-12


def test_command_prints_the_numbers_and_draws_png_and_svg(tmp_path, capsys):
    parser = argparse.ArgumentParser()
    command.add_arguments(parser)
    assert command.main(parser.parse_args(["--out", str(tmp_path), "--step", "0.5"])) == 0
    out = capsys.readouterr().out
    for text in ("0.765685 omega_AB", "-0.365685 omega_AB", "AC = 0.0918 m", "AC = -1.1204 m",
                 "beta = 22.62 deg", "beta = 337.38 deg"):
        assert text in out
    assert (tmp_path / "centrode.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "<svg" in (tmp_path / "centrode.svg").read_text()[:1000]
