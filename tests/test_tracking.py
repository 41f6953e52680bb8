"""Continuous branch tracking of the four-bar (yaseer.linkages.tracking).

Independent references: the constraint solver's seed-004 model
(yaseer.reference.seeds) and plain geometry in the tests.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from yaseer.linkages.errors import LockedError
from yaseer.linkages.fourbar import CROSSED, UNCROSSED, fourbar_closed
from yaseer.linkages.tracking import BranchTracker, Geometry, collinear_rates, track
from yaseer.linkages.planar import Motion
from yaseer.reference.seeds import seed004_fourbar

SEED004 = Geometry(1.2, 0.0, 0.3, 0.5, 1.0)
CRANK_ROCKER = Geometry(100.0, 0.0, 40.0, 120.0, 80.0)
SEED003 = Geometry(60.0, 0.0, 30.0, 36.0, 36.0)
SEED003_LIMIT = math.degrees(math.acos((30 ** 2 + 60 ** 2 - 72 ** 2) / (2 * 30 * 60)))  # |A - Bo| = b + c


def _reference_at(beta_deg: float, side: str) -> dict:
    """Seed 004 reference at crank inclination beta, crank turning +1 rad/s (ccw)."""
    row = seed004_fourbar([180.0 - beta_deg], theta1_rate=-1.0, branch=side)
    return {"coupler_deg": -row["theta2"][0], "w3": -row["theta2_rate"][0], "a3": -row["theta2_acceleration"][0]}


def test_change_point_linkage_switches_twice_per_two_turn_cycle():
    angles = np.arange(0.0, 720.0 + 1e-9, 5.0)
    tracked = track(SEED004, angles, 1.0, start_branch=CROSSED)
    assert [(s.crank_angle_deg, s.kind) for s in tracked.switches] == [(185.0, "change point"), (545.0, "change point")]
    assert list(np.flatnonzero(tracked.singular)) == [36, 108]  # 180 and 540 deg
    pin_b = tracked.fourbar.pin_b.pos
    assert abs(pin_b[-1] - pin_b[0]) < 1e-12                  # back where it started after 720 deg
    assert abs(pin_b[72] - pin_b[0].conjugate()) < 1e-12      # at 360 deg: the mirror assembly
    assert abs(pin_b[72] - pin_b[0]) > 0.5


def test_tracked_rates_are_smooth_through_the_change_point_and_match_the_reference():
    before, at, after = 179.5, 180.0, 180.5
    tracked = track(SEED004, [170.0, before, at, after, 190.0], 1.0, start_branch=CROSSED)
    w3 = tracked.fourbar.coupler.omega
    references = {beta: [_reference_at(beta, side)["w3"] for side in ("left", "right")] for beta in (before, after)}
    assert min(abs(w3[1] - r) for r in references[before]) < 1e-9
    assert min(abs(w3[3] - r) for r in references[after]) < 1e-9
    assert abs(w3[3] - w3[1]) < 0.01                        # smooth on the tracked motion
    kept_side = fourbar_closed(*SEED004.astuple(), after, 1.0, branch=int(tracked.branch[1])).coupler.omega
    assert abs(kept_side - w3[1]) > 0.3                     # a fixed flag would jump
    assert w3[2] == pytest.approx((1 + 2 * math.sqrt(2)) / 5, abs=1e-12)  # seed 004, eq. (7)


def test_acceleration_at_the_change_point_is_the_limit_along_the_motion():
    """Compared with the reference solver just either side of the singular position."""
    tracked = track(SEED004, [178.0, 179.0, 180.0, 181.0], 1.0, 0.0, start_branch=CROSSED)
    a3 = float(tracked.fourbar.coupler.alpha[2])
    w3 = float(tracked.fourbar.coupler.omega[2])
    near = []
    for beta in (179.99, 180.01):
        candidates = [_reference_at(beta, side) for side in ("left", "right")]
        near.append(min(candidates, key=lambda r: abs(r["w3"] - w3))["a3"])
    assert a3 == pytest.approx(0.5 * sum(near), abs=1e-4)


@pytest.mark.parametrize("start", [UNCROSSED, CROSSED])
def test_grashof_crank_rocker_keeps_its_assembly(start):
    angles = np.arange(0.0, 720.0, 7.5)
    tracked = track(CRANK_ROCKER, angles, 3.0, -1.0, start_branch=start)
    fixed = fourbar_closed(*CRANK_ROCKER.astuple(), angles, 3.0, -1.0, branch=start)
    assert tracked.switches == [] and not tracked.singular.any()
    assert np.allclose(tracked.fourbar.coupler.angle, fixed.coupler.angle)
    assert np.allclose(tracked.fourbar.follower.alpha, fixed.follower.alpha)


def test_toggle_reached_exactly_and_left_backwards_takes_the_other_assembly():
    out = np.linspace(0.0, SEED003_LIMIT, 11)
    back = out[::-1][1:]
    tracked = track(SEED003, np.concatenate([out, back]))
    assert [(s.kind, s.from_branch, s.to_branch) for s in tracked.switches] == [("toggle", UNCROSSED, CROSSED)]
    assert tracked.singular[10]
    # the return path is the other assembly: B mirrored in the line A->Bo
    assert abs(tracked.fourbar.pin_b.pos[9] - tracked.fourbar.pin_b.pos[11]) > 1.0


def test_crank_turning_back_short_of_the_toggle_retraces_its_assembly():
    out = np.linspace(0.0, SEED003_LIMIT - 0.5, 11)
    tracked = track(SEED003, np.concatenate([out, out[::-1][1:]]))
    assert tracked.switches == []
    assert np.allclose(tracked.fourbar.pin_b.pos[:11], tracked.fourbar.pin_b.pos[10:][::-1])


def test_a_crank_driven_into_the_toggle_is_locked():
    with pytest.raises(LockedError, match="toggle"):
        track(SEED003, [SEED003_LIMIT - 1.0, SEED003_LIMIT], 10.0)


def test_collinear_rates_reproduce_seed_004_equation_7_and_8():
    """Crank at 180 deg turning at 1 rad/s: the coupler's w3 are the roots of the
    paper's 25 w^2 - 10 w - 7 = 0, eq. (7); each pair satisfies the velocity loop, and
    the follower's rates are eq. (8)'s (the sign of that paper's theta3 rate is ours)."""
    pin_a = Motion(complex(-0.3, 0.0), complex(0.0, -0.3), complex(0.3, 0.0))  # crank at 180 deg, w = 1
    roots = collinear_rates(pin_a, complex(0.5, 0.0), complex(1.0, 0.0))
    coupler = sorted(r[0] for r in roots)
    assert coupler == pytest.approx(sorted([(1 + 2 * math.sqrt(2)) / 5, (1 - 2 * math.sqrt(2)) / 5]), abs=1e-14)
    for w3, w4 in roots:
        # velocity loop: A' + i w3 (B - A) + i w4 (Bo - B) = 0 along y
        assert -0.3 + 0.5 * w3 + 1.0 * w4 == pytest.approx(0.0, abs=1e-14)
        # seed 004 eq. (8): theta3_rate = (-1 +/- sqrt 2)/5 theta1_rate; theta1_rate = -1, theta3_rate = w4
        assert w4 in (pytest.approx((1 - math.sqrt(2)) / 5), pytest.approx((1 + math.sqrt(2)) / 5))


def test_tracker_call_by_call_matches_track_and_restarts_on_new_geometry():
    angles = np.arange(0.0, 400.0, 10.0)
    tracker = BranchTracker(CROSSED)
    omegas = [float(tracker.step(SEED004, a, 1.0)[0].coupler.omega) for a in angles]
    tracked = track(SEED004, angles, 1.0, start_branch=CROSSED)
    assert np.allclose(omegas, tracked.fourbar.coupler.omega)
    assert [s.crank_angle_deg for s in tracker.switches] == [190.0]
    result, switch = tracker.step(CRANK_ROCKER, 0.0)
    assert switch is None and tracker.branch == CROSSED  # a new linkage starts on the start branch


def test_static_tracking_gives_zero_rates():
    tracked = track(SEED004, np.arange(0.0, 361.0, 30.0), start_branch=CROSSED)
    assert not tracked.fourbar.moving
    assert np.all(tracked.fourbar.coupler.omega == 0) and np.all(tracked.fourbar.follower.alpha == 0)
    assert len(tracked.switches) == 1


def test_a_failed_step_leaves_the_track_as_it_was():
    tracker = BranchTracker(UNCROSSED)
    for angle in (80.0, 90.0):
        tracker.step(SEED003, angle, 10.0)
    with pytest.raises(LockedError):
        tracker.step(SEED003, SEED003_LIMIT, 10.0)
    result, switch = tracker.step(SEED003, 95.0, 10.0)
    expected = fourbar_closed(*SEED003.astuple(), 95.0, 10.0, branch=UNCROSSED)
    assert switch is None and complex(result.pin_b.pos) == pytest.approx(complex(expected.pin_b.pos))


def test_a_deferred_step_moves_the_track_only_when_accepted():
    tracker = BranchTracker(CROSSED)
    for angle in (170.0, 175.0, 180.0):
        tracker.step(SEED004, angle, 1.0)
    _, switch = tracker.step(SEED004, 185.0, 1.0, defer=True)
    assert switch is not None and tracker.switches == [] and tracker.branch == CROSSED
    tracker.accept()
    assert tracker.switches == [switch] and tracker.branch == UNCROSSED


def test_a_large_crank_step_starts_a_new_track():
    tracker = BranchTracker(UNCROSSED)
    for angle in np.arange(0.0, 366.0, 15.0):  # through the change point at 180: now crossed
        tracker.step(SEED004, angle, 1.0)
    assert tracker.branch == CROSSED
    _, switch = tracker.step(SEED004, 0.0, 1.0)  # the listing runs again from 0
    assert switch is None and tracker.branch == UNCROSSED


@pytest.mark.parametrize("start", [UNCROSSED, CROSSED])
def test_a_motion_starting_at_the_change_point_leaves_on_the_start_branch(start):
    tracked = track(SEED004, [180.0, 180.5, 181.0], 1.0, start_branch=start)
    assert list(tracked.branch[1:]) == [start, start] and tracked.switches == []
    w3 = tracked.fourbar.coupler.omega
    assert abs(w3[1] - w3[0]) < 0.01 and abs(w3[2] - w3[1]) < 0.01  # the root continuing the motion
