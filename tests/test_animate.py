"""Recording and drawing frames, with a stand-in machine (no interpreter needed).

The stand-in's "Program 1" is an offset slider-crank written here from the
triangle A-B-axis (not the library's formulation); the recorder must read the
joints back from the arrays in the contract's conventions.
"""

from __future__ import annotations

import io
import math
import os
import re
import sys

import pytest

from yaseer.api import _Output
from yaseer.animation import (
    AnimationError,
    Frame,
    Recorder,
    build_scene,
    distance,
    draw_frame,
    render,
)


class StandInMachine:
    """Arrays, scalars and areas, the part of the machine API the recorder uses."""

    def __init__(self):
        self.arrays = {}
        self.scalars = {}
        self.areas = {}
        self.area_hooks = []

    def array(self, name):
        return self.arrays.setdefault(name, [0.0] * 60)

    def scalar(self, name):
        return self.scalars.get(name, 0.0)

    def set_scalar(self, name, value):
        self.scalars[name] = value

    def set_area(self, number, area):
        self.areas[number] = area

    def gosub_prog(self, number):
        self.areas[number](self)
        for hook in self.area_hooks:
            hook(self, number)


def slider_crank_area(machine):
    """Offset slider-crank, cylinder along +x with its axis at y = -e (the contract's side)."""
    L, T, X, Y = (machine.array(n) for n in "LTXY")
    e, a, b, theta = L[1], L[2], L[3], math.radians(T[2])
    ax, ay = a * math.cos(theta), a * math.sin(theta)
    bx = ax + math.sqrt(b * b - (ay + e) ** 2)
    T[3] = math.degrees(math.atan2(-e - ay, bx - ax))
    R, H = machine.array("R"), machine.array("H")
    toward_a = math.atan2(ay + e, ax - bx) + math.radians(H[4])  # H(4) from the line B->A
    X[2], Y[2] = bx + R[4] * math.cos(toward_a), -e + R[4] * math.sin(toward_a)


def virtual_link_area(machine):
    X, Y = machine.array("X"), machine.array("Y")
    machine.set_scalar("T", math.degrees(math.atan2(Y[10], X[10])) % 360)
    machine.set_scalar("L", math.hypot(X[10], Y[10]))


def install_stand_ins(machine, methods=None):
    machine.set_area(1, slider_crank_area)
    machine.set_area(5, virtual_link_area)


def run_cycle(angles, e=2.0, a=3.0, b=8.0, print_heading=True, calls_per_line=1, rod_point=(0.0, 0.0)):
    """A 'listing': heading, then per angle PROG 1 (and PROG 5 on the rod point) and one printed line."""
    recorder = Recorder()
    machine = StandInMachine()
    install_stand_ins(machine)
    machine.area_hooks.append(recorder.hook)
    machine.array("R")[4], machine.array("H")[4] = rod_point
    tap = _Output(None, keep=True, on_line=recorder.line_printed)
    if print_heading:
        tap.write("  QQ      X(2)\n")
    L, T, X, Y = (machine.array(n) for n in "LTXY")
    for angle in angles:
        L[1], L[2], L[3], T[2], T[4] = e, a, b, angle, 0.0
        for _ in range(calls_per_line):
            machine.gosub_prog(1)
        X[10], Y[10] = X[2], Y[2]
        machine.gosub_prog(5)
        tap.write(f"{angle:6.1f} {X[2]:8.3f}")
        tap.write("\n")
    return recorder.finish(), tap


def test_each_printed_line_closes_a_frame_and_headings_are_not_frames():
    frames, tap = run_cycle([10.0, 40.0, 70.0])
    assert [f.crank_angle for f in frames] == [10.0, 40.0, 70.0]
    assert frames[1].printed == "  40.0 " + f"{3 * math.cos(math.radians(40)) + math.sqrt(64 - (3 * math.sin(math.radians(40)) + 2) ** 2):8.3f}"
    assert tap.text.splitlines()[0] == "  QQ      X(2)"


def test_recorded_joints_satisfy_the_linkage_constraints():
    frames, _ = run_cycle([float(a) for a in range(0, 360, 30)])
    for frame in frames:
        crank, rod = frame.snapshots[0].bars
        a_pin, b_pin = rod.start, rod.end
        assert distance(crank.start, (0.0, 0.0)) == 0.0
        assert distance(a_pin, (0.0, 0.0)) == pytest.approx(3.0)
        assert distance(a_pin, b_pin) == pytest.approx(8.0)
        assert b_pin[1] == pytest.approx(-2.0)  # on the cylinder axis y = -e
        (slider,) = frame.snapshots[0].sliders
        assert slider.centre == b_pin and slider.axis == pytest.approx((0.0, -2.0))


def test_repeated_calls_with_the_same_geometry_are_drawn_once():
    frames, _ = run_cycle([10.0, 20.0], calls_per_line=3)
    assert [s.area for s in frames[0].snapshots] == [1, 5]


def test_virtual_link_is_dashed_and_a_crank_on_it_is_too():
    recorder = Recorder()
    machine = StandInMachine()
    install_stand_ins(machine)
    machine.area_hooks.append(recorder.hook)
    L, T, X, Y = (machine.array(n) for n in "LTXY")
    X[10], Y[10] = 3.0, 4.0
    machine.gosub_prog(5)
    L[1], L[2], L[3], T[2], T[4] = 0.0, 5.0, 9.0, machine.scalar("T"), 0.0  # crank = the virtual link
    machine.gosub_prog(1)
    L[2], T[2] = 4.0, 30.0  # a crank elsewhere
    machine.gosub_prog(1)
    recorder.line_printed("row")
    (frame,) = recorder.finish()
    virtual, on_link, elsewhere = frame.snapshots
    assert virtual.bars[0].virtual
    assert on_link.bars[0].virtual and not on_link.bars[1].virtual
    assert not elsewhere.bars[0].virtual


def test_lines_without_new_calls_join_the_frame_and_trailing_calls_make_a_last_frame():
    recorder = Recorder()
    machine = StandInMachine()
    install_stand_ins(machine)
    machine.area_hooks.append(recorder.hook)
    machine.array("L")[2:4] = [3.0, 8.0]
    machine.gosub_prog(1)
    recorder.line_printed("first")
    recorder.line_printed("second")
    machine.gosub_prog(1)
    frames = recorder.finish()
    assert [f.printed for f in frames] == ["first\nsecond", ""]


def test_only_points_off_their_joint_that_move_have_paths():
    frames, _ = run_cycle([float(a) for a in range(0, 360, 45)])
    # X(1),Y(1) stays at the origin (R(1) = 0); X(2),Y(2) is the piston itself (R(4) = 0)
    assert build_scene(frames).paths == []
    frames, _ = run_cycle([float(a) for a in range(0, 360, 45)], rod_point=(1.5, 180.0))
    (path,) = build_scene(frames).paths
    assert path.label == "PROG 1 X(2),Y(2)"
    # at 0 degrees C is 1.5 beyond the piston along A->B = (sqrt(8^2 - 2^2), -2) / 8
    assert path.positions[0] == pytest.approx((3 + math.sqrt(60) * (1 + 1.5 / 8), -2 - 2 * 1.5 / 8))


def test_paths_break_where_the_point_jumps_or_is_missing():
    from yaseer.animation import Path2D, path_segments

    path = Path2D("p", [(0.0, 0.0), (0.1, 0.0), None, (0.2, 0.0), (5.0, 0.0), (5.1, 0.0)])
    assert path_segments(path, scale=10.0) == [[(0.0, 0.0), (0.1, 0.0)], [(0.2, 0.0)], [(5.0, 0.0), (5.1, 0.0)]]


def test_no_frames_is_an_error():
    with pytest.raises(AnimationError, match="Nothing to animate"):
        build_scene([])


def test_a_drawn_frame_has_bars_joints_blocks_and_caption():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle, Polygon

    frames, _ = run_cycle([30.0, 60.0])
    figure, ax = plt.subplots()
    draw_frame(ax, build_scene(frames), 1, "demo")
    circles = [p for p in ax.patches if isinstance(p, Circle)]
    polygons = [p for p in ax.patches if isinstance(p, Polygon)]
    dashed = [line for line in ax.lines if line.get_linestyle() == "--"]
    letters = {t.get_text() for t in ax.texts}
    texts = [t.get_text() for t in figure.texts]
    plt.close(figure)
    # joints A, B and the pivot Ao (twice: PROG 1's and PROG 5's ground)
    assert len(circles) == 4
    assert len(polygons) == 3  # a block and two ground triangles
    assert len(dashed) == 1  # the virtual link of PROG 5
    assert letters == {"Ao", "A", "B"}  # the contract's names of Program 1's joints
    assert "60.0\N{DEGREE SIGN}" in texts  # the crank angle
    assert any(text.startswith("60.0 ") for text in texts)  # the printed row (no column names known)


def test_render_gif_html_and_png(tmp_path):
    from PIL import Image

    frames, _ = run_cycle([float(a) for a in range(0, 360, 60)])
    gif = tmp_path / "cycle.gif"
    assert render(frames, gif, fps=4) == 6
    with Image.open(gif) as image:
        assert image.n_frames == 6
    html = tmp_path / "cycle.html"
    assert render(frames, html) == 6
    page = html.read_text()
    assert page.count("data:image/png;base64,") == 6 + 2  # every frame, the first shown at once, the background
    png = tmp_path / "frame.png"
    render(frames, png, frame_number=2)
    with Image.open(png) as image:
        assert image.size[0] > 100
    with pytest.raises(AnimationError, match=r"Frame 9 does not exist: the run has 6 frames, numbered from 0 to 5$"):
        render(frames, tmp_path / "x.png", frame_number=9)
    with pytest.raises(AnimationError, match="Unknown animation format"):
        render(frames, tmp_path / "x.avi")
    for fps in (0.0, -3.0, math.nan):
        with pytest.raises(AnimationError, match="Frames per second must be a positive number"):
            render(frames, tmp_path / "x.gif", fps=fps)


def test_mp4_without_ffmpeg_says_so(tmp_path, monkeypatch):
    import yaseer.animation as animation

    monkeypatch.setattr(animation.encode.shutil, "which", lambda name: None)
    monkeypatch.setitem(sys.modules, "imageio_ffmpeg", None)  # and no wheel-shipped binary
    frames, _ = run_cycle([0.0, 90.0])
    with pytest.raises(AnimationError, match="needs ffmpeg, which is not installed"):
        render(frames, tmp_path / "cycle.mp4")


def test_mp4_frames_are_piped_to_ffmpeg_as_raw_rgb(tmp_path, monkeypatch):
    """A stand-in ffmpeg records its arguments and how many bytes it was sent."""
    import stat
    import sys

    fake = tmp_path / "bin" / "ffmpeg"
    fake.parent.mkdir()
    fake.write_text(f"#!{sys.executable}\nimport sys\ndata = sys.stdin.buffer.read()\n"
                    "open(sys.argv[-1], 'w').write(' '.join(sys.argv[1:]) + ' BYTES=' + str(len(data)))\n")
    fake.chmod(fake.stat().st_mode | stat.S_IEXEC)
    monkeypatch.setenv("PATH", f"{fake.parent}:{os.environ['PATH']}")
    frames, _ = run_cycle([0.0, 90.0, 180.0])
    out = tmp_path / "cycle.mp4"
    assert render(frames, out, fps=5) == 3
    arguments = out.read_text()
    size = re.search(r"-s (\d+)x(\d+)", arguments)
    width, height = int(size.group(1)), int(size.group(2))
    assert width % 2 == 0 and height % 2 == 0
    assert arguments.endswith(f"BYTES={3 * width * height * 3}")
    assert "-r 5" in arguments and "-pix_fmt rgb24" in arguments


def test_mp4_is_a_real_h264_video_with_one_frame_per_printed_row(tmp_path):
    """Through the real ffmpeg (PATH or the imageio-ffmpeg wheel), read back by ffmpeg itself."""
    import subprocess

    import yaseer.animation as animation

    frames, _ = run_cycle([0.0, 90.0, 180.0, 270.0])
    out = tmp_path / "cycle.mp4"
    assert render(frames, out, fps=4) == 4
    probe = subprocess.run([animation.ffmpeg_program(), "-i", str(out), "-map", "0:v", "-f", "null", "-"],
                           capture_output=True, text=True)
    assert probe.returncode == 0, probe.stderr
    assert "h264" in probe.stderr
    assert re.search(r"frame=\s*4\b", probe.stderr), probe.stderr[-300:]


def test_a_long_render_shows_progress_on_the_given_stream(tmp_path, monkeypatch):
    import yaseer.progress as progress

    monkeypatch.setattr(progress, "DELAY_SECONDS", 0.0)
    original = progress.bar
    monkeypatch.setattr(progress, "bar", lambda *a, **k: original(*a, **{**k, "delay": 0.0, "force": True, "refresh_seconds": 0.0}))
    frames, _ = run_cycle([0.0, 120.0, 240.0])
    stream = io.StringIO()
    render(frames, tmp_path / "c.gif", progress_file=stream)
    assert "3/3" in stream.getvalue()


def test_the_output_stream_hands_on_lines_and_a_last_partial_line():
    seen = []
    tap = _Output(None, keep=False, on_line=seen.append)
    tap.write("a\nb")
    tap.write("c\n\n")
    tap.write("end")
    tap.close_line()
    assert seen == ["a", "bc", "", "end"]
    assert isinstance(Frame((), "x"), Frame)


def test_long_runs_are_thinned_evenly_keeping_first_and_last(tmp_path):
    from PIL import Image

    from yaseer.animation import frames_to_paint

    assert frames_to_paint(5, 10) == [0, 1, 2, 3, 4]
    assert frames_to_paint(1000, 5) == [0, 250, 500, 749, 999]
    with pytest.raises(AnimationError):
        frames_to_paint(10, 1)
    frames, _ = run_cycle([float(a) for a in range(0, 360, 10)])
    assert render(frames, tmp_path / "thin.gif", max_frames=4) == 4
    with Image.open(tmp_path / "thin.gif") as image:
        assert image.n_frames == 4
