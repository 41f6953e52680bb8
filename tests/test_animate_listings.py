"""Every paper example and the seed linkages animate, end to end on the real machine.

Each printed row must be one frame, and the frame's crank angle (read from
the first library call's input) must be the angle the listing printed in its
first column: the recording and the printout describe the same positions.
"""

from __future__ import annotations

import math
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from yaseer.animation import build_scene, distance
from yaseer.animation.draw import make_figure
from yaseer.recorded_run import record_listing

REPO = Path(__file__).resolve().parents[1]
LISTINGS = REPO / "listings"

# Seed 004 (Jong, Reynolds and Adams): the change-point four-bar, ground AE = 1.2 m,
# crank AB = 0.3, coupler BD = 0.5, follower DE = 1 (0.3 + 1.2 = 0.5 + 1); two crank turns.
SEED_004 = """\
10 REM SEED 004: THE CHANGE-POINT FOUR-BAR OF JONG, REYNOLDS AND ADAMS
20 L(11) = 1.2: T(11) = 0: L(12) = .3: L(13) = .5: L(14) = 1: W(5) = 1: L(10) = 0
30 R(11) = .25: H(11) = 0
40 FOR QQ = 2.5 TO 720 STEP 15: T(12) = QQ: GOSUB PROG 2
50 PRINT QQ; T(13); T(14): NEXT QQ
"""

PAPER = {1: 25, 2: 19, 3: 19, 4: 19, 5: 19}  # printed rows per example (the FOR loops' counts)


def first_number(text: str) -> float:
    return float(re.match(r"\s*(-?\d*\.?\d+)", text).group(1))


@pytest.mark.parametrize("example, rows", sorted(PAPER.items()))
def test_paper_examples_give_one_frame_per_printed_row(example, rows):
    frames = record_listing((LISTINGS / f"example{example}.bas").read_text())
    assert len(frames) == rows
    for frame in frames:
        assert frame.crank_angle == pytest.approx(first_number(frame.printed), abs=0.006)
    assert build_scene(frames).paths  # each example traces at least one point


def test_example_4_second_four_bar_is_driven_by_the_virtual_link():
    frames = record_listing((LISTINGS / "example4.bas").read_text())
    for frame in frames:
        first, virtual, second = frame.snapshots
        assert [s.area for s in frame.snapshots] == [2, 5, 2]
        point_d = next(p for p in first.points if p.label.endswith("X(4),Y(4)")).position
        assert virtual.bars[0].end == pytest.approx(point_d)
        assert second.bars[0].virtual and second.bars[0].end == pytest.approx(point_d, abs=1e-9)
        # the loop D-H-Ho closes: |H - Ho| = 17.5, Ho = 25 u(90.1)
        assert distance(second.bars[2].start, second.bars[2].end) == pytest.approx(17.5)


def test_the_slider_crank_seed_animates_a_frame_per_position():
    frames = record_listing((LISTINGS / "tk_slider_crank.bas").read_text())
    # row C at -30 degrees, then one cycle in which each angle shows both assemblies (the listing prints
    # a whole cycle of the open one, then a whole cycle of the crossed one), then the backsolve's crank
    assert [f.crank_angle for f in frames[:-1]] == pytest.approx([-30.0] + [15.0 * k for k in range(24)])
    assert frames[-1].crank_angle == pytest.approx(-30.0, abs=0.1) and frames[-1].printed.startswith("BACKSOLVE")
    for frame in frames[:-1]:
        assert [s.alternative for s in frame.snapshots] == [False, True]
        assert len(frame.printed.splitlines()) == 2


# Seed 001 by an independent closed form: crank AO = 3, rod AB = 8, piston B on the line y = 2;
# x_B = AO cos(theta) +/- sqrt(AB^2 - (2 - AO sin(theta))^2), + for the open assembly, - for the crossed.
SEED_001 = (3.0, 8.0, 2.0)
BLOCK_INK = (0xC9, 0xD6, 0xE8)  # the slider block's fill (draw.py's facecolor), as the picture shows it


def slider_x(theta_deg: float, branch: int) -> float:
    crank, rod, line = SEED_001
    theta = math.radians(theta_deg)
    return crank * math.cos(theta) + branch * math.sqrt(rod ** 2 - (line - crank * math.sin(theta)) ** 2)


def block_runs(row) -> list[tuple[int, int]]:
    """(first, last) pixel columns of each stretch of the slider block's fill along one pixel row
    (gaps of up to 3 pixels, a grid line or a letter's edge, do not split a stretch)."""
    runs: list[list[int]] = []
    for x, pixel in enumerate(row):
        if sum(abs(int(c) - b) for c, b in zip(pixel[:3], BLOCK_INK)) <= 24:
            if runs and x - runs[-1][1] <= 4:
                runs[-1][1] = x
            else:
                runs.append([x, x])
    return [(first, last) for first, last in runs if last - first >= 4]


def test_seed_001_gif_draws_both_pistons_of_each_crank_angle_in_one_frame(tmp_path):
    """As a person sees the GIF: 26 frames (row c, 24 angles, the backsolve), and in every frame of a
    position two slider blocks on the line y = 2, centred where the closed form puts the open and the
    crossed piston at that frame's crank angle (the listing prints the two cycles as separate runs)."""
    import numpy as np
    from PIL import Image

    import yaseer
    from yaseer.animation import Painter

    result = run_cli(str(LISTINGS / "tk_slider_crank.bas"), "--out", "seed.gif", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "seed.gif: 26 frames\n"
    run = yaseer.run(LISTINGS / "tk_slider_crank.bas")
    scene = build_scene(run.frames)
    painter = Painter(scene, run.look())  # where the axes put a point of the mechanism, in pixels
    height = painter.figure.bbox.height
    angles = [-30.0] + [15.0 * k for k in range(24)]
    with Image.open(tmp_path / "seed.gif") as gif:
        assert gif.n_frames == 26
        for number, theta in enumerate(angles):
            gif.seek(number)
            pixels = np.asarray(gif.convert("RGB"))
            # a row through the lower half of the blocks, below the joint circles and the axis line
            _, y = painter.ax.transData.transform((0.0, SEED_001[2] - 0.5 * scene.size))
            runs = block_runs(pixels[round(height - y)])
            expected = sorted(painter.ax.transData.transform((slider_x(theta, branch), 0.0))[0] for branch in (1, -1))
            assert len(runs) == 2, (theta, runs)
            per_unit = painter.ax.transData.transform((1.0, 0.0))[0] - painter.ax.transData.transform((0.0, 0.0))[0]
            for (first, last), centre in zip(runs, expected):
                assert abs((first + last) / 2 - centre) <= 2.5, (theta, first, last, centre)
                # a whole block: 2.4 symbol sizes long, less its 1.6-point outline at each end
                assert (last - first) == pytest.approx(2.4 * scene.size * per_unit - 2 * 1.6 * 100 / 72, abs=2)


def test_every_frame_of_seed_001_names_both_branches_values():
    """Every position's frame shows each column's name with the open and the crossed value (x_B agreeing with
    the closed form), the crank angle once, the legend naming the grey assembly, and nothing runs off the frame."""
    import yaseer
    from yaseer.animation import draw_moving

    result = yaseer.run(LISTINGS / "tk_slider_crank.bas")
    scene = build_scene(result.frames)
    look = result.look()
    figure, ax = make_figure(scene, look)
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    renderer = FigureCanvasAgg(figure).get_renderer()
    for number, frame in enumerate(scene.frames[:-1]):
        artists = draw_moving(ax, scene, number, look)
        texts = [t.get_text() for t in figure.texts if t in artists]
        assert texts[1] == f"{frame.crank_angle:.1f}\N{DEGREE SIGN}"
        for name in ("X(2)", "V(3)", "W(3)", "A(35)", "A(3)"):
            assert " / " in texts[texts.index(name) + 1]
        open_x, crossed_x = (float(v) for v in texts[texts.index("X(2)") + 1].split(" / "))
        assert open_x == pytest.approx(slider_x(frame.crank_angle, 1), abs=1e-8)
        assert crossed_x == pytest.approx(slider_x(frame.crank_angle, -1), abs=1e-8)
        for artist in artists:
            if artist in figure.texts:
                assert artist.get_window_extent(renderer).x1 <= figure.bbox.x1, artist.get_text()
            artist.remove()
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == ["link", "fixed pivot", "other assembly, same angle"]


def test_each_position_of_seed_003_shows_both_assemblies_in_one_frame():
    """The Fortran prints each angle's crossed row, then the uncrossed one under it: one frame each angle,
    the crossed branch (the first call) in black, the other drawn with it (not in a frame of its own)."""
    import math

    frames = record_listing((LISTINGS / "fortran_fourbar.bas").read_text())
    assert [f.crank_angle for f in frames] == [0.0, 30.0, 60.0, 90.0, 270.0, 300.0, 330.0]
    for frame in frames:
        first, other = frame.snapshots
        assert (first.alternative, other.alternative) == (False, True)
        # the same crank, the two solutions of the dyad: B mirrored in the line A->Bo
        assert first.bars[0] == other.bars[0]
        a, bo, b1, b2 = first.bars[0].end, first.bars[2].end, first.bars[1].end, other.bars[1].end
        ux, uy = bo[0] - a[0], bo[1] - a[1]
        side = [ux * (b[1] - a[1]) - uy * (b[0] - a[0]) for b in (b1, b2)]
        assert side[0] * side[1] < 0 and math.isclose(abs(side[0]), abs(side[1]), rel_tol=1e-9)
        assert len(frame.printed.splitlines()) == 2


def test_every_frame_of_seed_003_names_both_rows_values():
    import yaseer
    from yaseer.animation import draw_moving

    result = yaseer.run(LISTINGS / "fortran_fourbar.bas")
    scene = build_scene(result.frames)
    figure, ax = make_figure(scene, result.look())
    for number in range(len(scene.frames)):
        artists = draw_moving(ax, scene, number, result.look())
        texts = [t.get_text() for t in figure.texts if t in artists]
        upper, lower = scene.frames[number].printed.splitlines()
        for k, name in enumerate(("PHI", "BETA", "VELC", "VELB", "ACCC", "ACCB")):
            assert texts[texts.index(name) + 1] == f"{upper.split()[k + 1]} / {lower.split()[k]}"
        if number == 0:  # the joints lettered as the Fortran names them, whose letters VELB, VELC use
            assert sorted(t.get_text() for t in ax.texts) == ["A", "B", "C", "D"]
        for artist in artists:
            artist.remove()
    legend = [t.get_text() for t in ax.get_legend().get_texts()]
    assert legend == ["link", "fixed pivot", "other assembly, same angle"]


def test_seed_004_change_point_four_bar_animates_over_two_turns():
    frames = record_listing(SEED_004)
    assert len(frames) == 48
    assert [f.crank_angle for f in frames] == pytest.approx([2.5 + 15 * k for k in range(48)])
    for frame in frames:
        crank, coupler, follower = frame.snapshots[0].bars
        assert distance(follower.start, follower.end) == pytest.approx(1.0)
    (path,) = build_scene(frames).paths  # the coupler point
    assert path.label.endswith("X(4),Y(4)")


def run_cli(*args, cwd):
    env = dict(os.environ, PYTHONPATH=str(REPO))
    return subprocess.run([sys.executable, "-m", "yaseer", "animate", *args], capture_output=True,
                          text=True, cwd=cwd, env=env, timeout=120)


def test_the_command_writes_a_gif_with_a_frame_per_row(tmp_path):
    from PIL import Image

    result = run_cli(str(LISTINGS / "example3.bas"), "--out", "ex3.gif", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "ex3.gif: 19 frames\n"
    with Image.open(tmp_path / "ex3.gif") as image:
        assert image.n_frames == 19


def test_command_errors_are_one_line(tmp_path, monkeypatch, capsys):
    from yaseer.cli import main

    monkeypatch.chdir(tmp_path)
    (tmp_path / "bad.bas").write_text("10 PRINT 1\n20 PRINT (\n")
    (tmp_path / "none.bas").write_text("10 PRINT 1\n")
    (tmp_path / "apart.bas").write_text("10 L(2) = 1: L(3) = 9: L(1) = 20: GOSUB PROG 1\n")
    cases = {
        ("missing.bas",): "File not found: missing.bas\n",
        ("bad.bas",): "Syntax error in 20\n",
        ("none.bas",): "Nothing to animate: the listing called no library program before printing\n",
        ("apart.bas",): "cannot be assembled (PROG 1) in 10\n",
        ("none.bas", "--out", "x.avi"): "Unknown animation format '.avi': use .gif, .mp4, .html, .png\n",
    }
    for args, message in cases.items():
        assert main(["animate", *args]) == 1
        shown = capsys.readouterr()
        assert shown.err.endswith(message), (args, shown.err)
        assert shown.out == ""
    assert main(["animate", "none.bas", "--frame", "2"]) == 2  # a usage error
    assert capsys.readouterr().err == "yaseer animate: --frame chooses the frame of a .png; none.gif is a whole animation\n"
    assert main(["animate", "none.bas", "--method", "2"]) == 2
    assert capsys.readouterr().err.endswith("argument --method: expected N=NAME, got '2'\n")


def test_example_3_slotted_follower_keeps_one_length_through_the_cycle():
    frames = build_scene(record_listing((LISTINGS / "example3.bas").read_text())).frames
    lengths = set()
    for frame in frames:
        slider_crank, virtual, inversion = frame.snapshots
        follower = inversion.bars[1]
        (block,) = inversion.sliders
        lengths.add(round(distance(follower.start, follower.end), 9))
        assert distance(follower.start, block.centre) < distance(follower.start, follower.end)
    assert len(lengths) == 1


def test_a_run_that_breaks_part_way_is_drawn_up_to_the_break(tmp_path, monkeypatch, capsys):
    """A slider-crank whose offset grows until the rod cannot reach its axis (at 60 degrees)."""
    from PIL import Image

    from yaseer.cli import main

    monkeypatch.chdir(tmp_path)
    (tmp_path / "short.bas").write_text(
        "10 L(1) = 0: L(2) = 2: L(3) = 5: T(4) = 0: R(4) = 1: H(4) = 180\n"
        "20 FOR QQ = 0 TO 90 STEP 10: L(1) = QQ / 15: T(2) = QQ: GOSUB PROG 1: PRINT QQ; X(2): NEXT QQ\n")
    # B exists while the rod reaches the axis: e + (pin height) = QQ/15 + 2 sin(QQ) <= 5 (up to QQ = 50)
    frames_before = [qq for qq in range(0, 91, 10) if (qq / 15 + 2 * math.sin(math.radians(qq))) <= 5]
    assert main(["animate", "short.bas"]) == 1
    shown = capsys.readouterr()
    assert shown.out == f"short.gif: {len(frames_before)} frames\n"
    assert shown.err.endswith("cannot be assembled (PROG 1) in 20 (the animation stops there)\n")
    with Image.open(tmp_path / "short.gif") as image:
        assert image.n_frames == len(frames_before)


def test_a_listing_that_dims_an_input_array_small_still_animates():
    """With DIM T(3), T(4) (the cylinder axis) reads as 0 for Program 1 and for the recorder alike."""
    frames = record_listing(
        "5 DIM T(3)\n"
        "10 L(1) = 1: L(2) = 2: L(3) = 6: R(4) = 1: H(4) = 180\n"
        "20 FOR QQ = 0 TO 90 STEP 30: T(2) = QQ: GOSUB PROG 1: PRINT QQ; X(2): NEXT QQ\n")
    assert len(frames) == 4
    for frame in frames:
        (slider,) = frame.snapshots[0].sliders
        assert slider.angle_deg == 0.0 and slider.centre[1] == pytest.approx(-1.0)  # axis y = -e


def test_angle_option_sets_the_unit_of_the_trigonometric_functions():
    """In radians, T(2) = ATN(1) * 4 is 3.14159: the recorded crank angle is what the listing computed."""
    from yaseer.recorded_run import record_run

    text = "10 L(2) = 1: L(3) = 3: T(2) = ATN(1) * 4: GOSUB PROG 1: PRINT T(2)\n"
    (radians,) = record_run(text, angle="rad").frames
    (degrees,) = record_run(text).frames
    assert radians.crank_angle == pytest.approx(math.pi)
    assert degrees.crank_angle == pytest.approx(180.0)


@pytest.mark.parametrize("name", ["example1", "example2", "example3", "example4", "example5", "tk_slider_crank",
                                  "fortran_fourbar"])
def test_every_frame_of_a_numeric_row_shows_its_values_under_column_names(name):
    """No frame falls back to unnamed numbers: the paper's names, the listing's header, or the expressions
    of the PRINT that printed the table (seed 001: T(2), X(2), ... though a labelled line is printed last)."""
    import yaseer
    from yaseer.animation.draw import _column_values

    result = yaseer.run(LISTINGS / f"{name}.bas")
    names = result.look().names
    assert names is not None and names == result.columns
    numeric = [frame for frame in result.frames if not frame.printed[:1].isalpha()]
    assert len(numeric) >= len(result.frames) - 1  # seed 001's backsolve line is labelled: its own text
    for frame in numeric:
        assert _column_values(frame.printed, names) is not None, frame.printed
