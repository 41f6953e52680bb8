"""Program 2 with L(10) = -1 (continuous branch tracking) through the BASIC machine."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from yaseer.linkages.fourbar import UNCROSSED
from yaseer.linkages.tracking import Geometry, track

SEED004_LISTING = """\
10 DIM A(53), L(20), T(25), W(10), R(19), H(24), X(11), Y(11), V(21)
20 L(11) = 1.2: T(11) = 0: L(12) = .3: L(13) = .5: L(14) = 1: L(10) = -1
30 FOR QQ = 0 TO 720 STEP 15: T(12) = QQ: W(5) = 1: A(5) = 0: GOSUB PROG 2
40 PRINT QQ; T(13); W(6); A(6); W(7)
50 NEXT QQ
"""


def _run(tmp_path, text: str) -> subprocess.CompletedProcess:
    path = tmp_path / "listing.bas"
    path.write_text(text)
    return subprocess.run([sys.executable, "-m", "yaseer", "run", str(path), "--format", "csv"],
                          capture_output=True, text=True)


def test_l10_minus_1_follows_the_motion_through_both_change_points(tmp_path):
    done = _run(tmp_path, SEED004_LISTING)
    assert done.returncode == 0, done.stderr
    rows = np.array([[float(v) for v in line.split(",")] for line in done.stdout.split()])
    angles = np.arange(0.0, 721.0, 15.0)
    expected = track(Geometry(1.2, 0.0, 0.3, 0.5, 1.0), angles, 1.0, 0.0, start_branch=UNCROSSED)
    assert np.allclose(rows[:, 0], angles)
    assert np.allclose(rows[:, 2], expected.fourbar.coupler.omega, atol=1e-12)
    assert np.allclose(rows[:, 4], expected.fourbar.follower.omega, atol=1e-12)
    # the change point itself: the velocity from the acceleration equations, not a division by ~0
    assert rows[12, 2] == pytest.approx((1 - 2 * np.sqrt(2)) / 5, abs=1e-12)
    assert rows[36, 2] == pytest.approx((1 + 2 * np.sqrt(2)) / 5, abs=1e-12)
    switches = [line for line in done.stderr.splitlines() if line.startswith("PROG 2: branch switch")]
    assert switches == ["PROG 2: branch switch at crank angle 195 deg (change point): uncrossed -> crossed",
                        "PROG 2: branch switch at crank angle 555 deg (change point): crossed -> uncrossed"]


def test_a_fixed_assembly_stops_at_the_change_point(tmp_path):
    """Without tracking the rates at the change point are undefined: a run-time error."""
    done = _run(tmp_path, SEED004_LISTING.replace("L(10) = -1", "L(10) = 0"))
    assert done.returncode == 1
    assert "branch switch" not in done.stderr
    assert done.stderr.strip().splitlines()[-1] == "Mechanism locks: rates undefined at a toggle position (PROG 2) in 30"
    assert len(done.stdout.split()) == 12  # 0 .. 165 deg printed


def test_a_failing_call_does_not_move_the_track_on(tmp_path):
    """A call that fails after its kinematics (a bad Q(2), trapped by ON ERROR) writes nothing and
    leaves the track as it was: the motion goes on on the branch it was on (crossed after 195 deg)."""
    trapped = SEED004_LISTING.replace(
        "10 DIM", "5 ON ERROR GOTO 100\n10 DIM").replace(
        "50 NEXT QQ\n",
        "45 IF QQ = 300 THEN T(12) = 0: Z(2) = 2: Q(2) = 7: GOSUB PROG 2\n"
        "47 Z(2) = 0\n50 NEXT QQ\n60 END\n100 RESUME 47\n")
    plain, failed = _run(tmp_path, SEED004_LISTING), _run(tmp_path, trapped)
    assert plain.returncode == failed.returncode == 0, failed.stderr
    assert failed.stdout == plain.stdout
    assert failed.stderr == plain.stderr
