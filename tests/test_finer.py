"""Smoother animations from positions the listing itself computes: ``--finer K`` divides each FOR loop's STEP."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

import yaseer
from yaseer.finer import finer_steps

ROOT = Path(__file__).resolve().parents[1]


def test_only_numeric_steps_outside_strings_and_remarks_are_divided():
    text = '10 FOR I = 1 TO 9 STEP - 2: PRINT "STEP 5": NEXT: FOR J = 0 TO 3\n20 REM STEP 30\n'
    assert finer_steps(text, 4) == '10 FOR I = 1 TO 9 STEP (-2)/4: PRINT "STEP 5": NEXT: FOR J = 0 TO 3\n20 REM STEP 30\n'
    assert finer_steps(text, 1) == text
    with pytest.raises(ValueError, match="whole number of 1 or more"):
        finer_steps(text, 0)


def test_the_finer_run_is_the_listing_with_a_finer_step_typed_by_hand():
    """Example 5 every 5 degrees: the rows equal those of the listing edited to STEP -5 (every one computed)."""
    source = (ROOT / "listings" / "example5.bas").read_text()
    assert "STEP -20" in source
    by_hand = yaseer.run(source.replace("STEP -20", "STEP -5"))
    finer = yaseer.run(ROOT / "listings" / "example5.bas", finer=4)
    assert finer.rows.shape == (73, 4) and finer.rows.names == yaseer.run(ROOT / "listings" / "example5.bas").rows.names
    assert finer.rows.shape == by_hand.rows.shape
    assert finer.rows.ravel().tolist() == pytest.approx(by_hand.rows.ravel().tolist(), rel=1e-12, abs=1e-9)
    assert [f.crank_angle for f in finer.frames] == pytest.approx([360.1 - 5 * k for k in range(73)])


def test_the_animate_command_draws_a_frame_per_finer_position(tmp_path):
    from PIL import Image

    out = tmp_path / "crusher.gif"
    done = subprocess.run([sys.executable, "-m", "yaseer", "animate", "listings/example2.bas", "--finer", "2",
                           "--size", "320x180", "--out", str(out)], cwd=ROOT, capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    with Image.open(out) as image:
        assert image.n_frames == 37  # 360.1 down to .1 every 10 degrees (the listing: every 20)
    bad = subprocess.run([sys.executable, "-m", "yaseer", "animate", "listings/example2.bas", "--finer", "0"],
                         cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert bad.returncode == 2 and "whole number of 1 or more" in bad.stderr and "Traceback" not in bad.stderr
