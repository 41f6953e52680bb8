"""Animation frames for a projector: size, the paper's joint letters, units, named values, title, stills.

References: the paper's names (Example 1's "piston D", Example 3's "output member CCoD" and
"point D"), whose printed coordinates (the golden rows: Y(2) of piston D, X(7) of point D)
must be where the letters sit; the golden screens for the values shown.
"""

import base64
import io
import os
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import yaseer
from yaseer.animation import Look, build_scene, render
from yaseer.animation.draw import Painter, lettered_joints, make_figure

ROOT = Path(__file__).resolve().parents[1]
LISTINGS = ROOT / "listings"


def letters(result):
    scene = build_scene(result.frames)
    return scene, [dict((name, position) for position, name in lettered_joints(scene, frame))
                   for frame in scene.frames]


def test_example_1_letters_its_second_piston_d_where_the_listing_says_piston_d_is():
    result = yaseer.run(LISTINGS / "example1.bas")
    _, per_frame = letters(result)
    assert set(per_frame[0]) == {"Ao", "A", "B", "C", "D"}
    assert [frame["D"][1] for frame in per_frame] == pytest.approx(list(result.rows[:, 1]), rel=1e-9)
    assert all(frame["Ao"] == (0.0, 0.0) for frame in per_frame)


def test_example_3_letters_the_output_member_ccod_as_the_paper_does():
    result = yaseer.run(LISTINGS / "example3.bas")
    _, per_frame = letters(result)
    assert {"C", "Co", "D"} <= set(per_frame[0])
    assert [frame["D"][0] for frame in per_frame] == pytest.approx(list(result.rows[:, 4]), rel=1e-9)  # X(7)
    assert len({frame["Co"] for frame in per_frame}) == 1  # a fixed pivot


def test_a_frame_shows_title_unit_and_each_printed_value_under_its_name():
    result = yaseer.run(LISTINGS / "example1.bas")
    scene = build_scene(result.frames)
    figure, ax = make_figure(scene, result.look())
    from yaseer.animation import draw_moving

    draw_moving(ax, scene, 0, result.look())
    texts = [t.get_text() for t in figure.texts]
    assert texts[0] == "Example 1: kinematics of piston D (paper Fig. 7)"
    assert ax.get_xlabel() == "x (mm)" and ax.get_ylabel() == "y (mm)"
    first = (ROOT / "tests" / "golden" / "example1.txt").read_text().split()[:4]  # 0.10 117.97 982.34 30137.30
    assert "0.1\N{DEGREE SIGN}" in texts
    for name, value in zip(result.rows.names[1:], first[1:]):
        label = next(i for i, text in enumerate(texts) if text.replace("\n", " ") == name)
        assert texts[label + 1] == value  # the value right under its name


def test_a_listing_without_a_known_unit_or_paper_title_uses_its_first_rem():
    result = yaseer.run(LISTINGS / "fortran_fourbar.bas")
    look = result.look()
    assert look.title.startswith("SEED 003: OKE, SHOGBAMOWO AND OKUNLOLA") and look.unit == ""
    assert look.names == ("THET", "PHI", "BETA", "VELC", "VELB", "ACCC", "ACCB")


def test_default_size_is_1280x720_and_a_still_is_the_players_frame(tmp_path):
    from PIL import Image, ImageChops

    result = yaseer.run(LISTINGS / "example4.bas")
    still, page = tmp_path / "still.png", tmp_path / "film.html"
    render(result.frames, still, frame_number=3, look=result.look())
    render(result.frames, page, fps=12.5, look=result.look())
    with Image.open(still) as image:
        assert image.size == (1280, 720)
        # [0]: the background, [1]: the layer shown first, then the frames' layers
        background, _, *layers = re.findall(r'"data:image/png;base64,([^"]+)"', page.read_text())
        with Image.open(io.BytesIO(base64.b64decode(background))) as under, \
                Image.open(io.BytesIO(base64.b64decode(layers[3]))) as layer:
            played = Image.alpha_composite(under.convert("RGBA"), layer.convert("RGBA")).convert("RGB")
        difference = np.asarray(ImageChops.difference(image.convert("RGB"), played)).max(axis=2)
        moving = np.asarray(layer.convert("RGBA"))[..., 3] > 0
        assert difference[~moving].max() == 0  # where the layer is transparent the background is the still
        assert (difference > 48).mean() < 0.002  # the moving parts, up to the player's 32-colour palette
        assert len(image.convert("RGB").getcolors(1 << 16)) > 20  # drawn, not blank
    assert "setInterval(() => show((current + 1) % frames.length), 80)" in page.read_text()  # --fps 12.5


def test_size_scales_the_frame(tmp_path):
    from PIL import Image

    result = yaseer.run(LISTINGS / "example2.bas")
    image = Painter(build_scene(result.frames), result.look((1920, 1080))).image(0)
    assert image.size == (1920, 1080)
    with pytest.raises(Exception, match="frame size must be from 160x120"):
        render(result.frames, tmp_path / "x.png", look=Look(size=(100, 50)))


def run_cli(*args, cwd):
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    return subprocess.run([sys.executable, "-m", "yaseer", "animate", *args], capture_output=True, text=True,
                          cwd=cwd, env=env, timeout=120)


def test_the_command_takes_size_and_refuses_a_bad_one(tmp_path):
    from PIL import Image

    done = run_cli(str(LISTINGS / "example5.bas"), "--out", "s.png", "--frame", "2", "--size", "800x450",
                   cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    with Image.open(tmp_path / "s.png") as image:
        assert image.size == (800, 450)
    bad = run_cli(str(LISTINGS / "example5.bas"), "--out", "s.png", "--size", "wide", cwd=tmp_path)
    assert bad.returncode == 2 and "WIDTHxHEIGHT" in bad.stderr and "Traceback" not in bad.stderr
    small = run_cli(str(LISTINGS / "example5.bas"), "--out", "s.png", "--size", "20x20", cwd=tmp_path)
    assert small.returncode == 2 and small.stderr.strip().endswith("not 20x20")  # refused before the run


def test_unnamed_columns_are_shown_under_the_expressions_of_the_last_print():
    result = yaseer.run("10 FOR Q = 0 TO 90 STEP 45: X(10) = COS(Q): Y(10) = SIN(Q): GOSUB PROG 5\n"
                        "20 PRINT Q; T; L * 2: NEXT Q\n")
    # No header printed: the rows, the plot and the frames all name the columns by the PRINT's expressions.
    assert result.columns == result.rows.names == result.look().names == ("Q", "T", "L * 2")
    assert [ax.get_ylabel() for ax in result.plot().axes] == ["T", "L * 2"]
    scene = build_scene(result.frames)
    figure, ax = make_figure(scene, result.look())
    from yaseer.animation import draw_moving

    draw_moving(ax, scene, 1, result.look())
    texts = [t.get_text() for t in figure.texts]
    assert texts[texts.index("T") + 1] == "45" and texts[texts.index("L * 2") + 1] == "2"


def _letter_boxes(figure, axes) -> list:
    renderer = figure.canvas.get_renderer()
    return [(t.get_text(), t.get_window_extent(renderer)) for t in axes.texts]


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_the_joints_letters_never_overlap(n):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from yaseer.animation import draw_moving

    result = yaseer.run(LISTINGS / f"example{n}.bas")
    scene = build_scene(result.frames)
    figure, ax = make_figure(scene, result.look())
    FigureCanvasAgg(figure)
    for number in range(0, len(scene.frames), 3):
        artists = draw_moving(ax, scene, number, result.look())
        for axes in [ax, *ax.child_axes]:
            boxes = _letter_boxes(figure, axes)
            for k, (name, box) in enumerate(boxes):
                for other, second in boxes[k + 1:]:
                    assert not box.overlaps(second), (n, number, name, other)
        for artist in artists:
            artist.remove()


def test_example_5s_short_crank_is_magnified_and_lettered_in_an_inset():
    """The crank is 0.075 m (listings/example5.bas) in a picture about 3 m across: an inset shows it."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from yaseer.animation import draw_moving

    result = yaseer.run(LISTINGS / "example5.bas")
    scene = build_scene(result.frames)
    figure, ax = make_figure(scene, result.look())
    FigureCanvasAgg(figure)
    (inset,) = ax.child_axes
    low, high = inset.get_xlim()
    assert high - low == pytest.approx(4 * 0.075)  # twice the crank each way around Ao
    draw_moving(ax, scene, 3, result.look())
    assert sorted(t.get_text() for t in inset.texts) == ["A", "Ao"]
    assert "A" not in [t.get_text() for t in ax.texts]  # too close to Ao at the picture's scale
    renderer = figure.canvas.get_renderer()
    crank = [line for line in inset.get_lines() if line.get_linewidth() > 3]
    extent = max(line.get_window_extent(renderer).width + line.get_window_extent(renderer).height for line in crank)
    assert extent > 40  # pixels: visible, where the main picture draws the crank in about 10


EXAMPLE_5_CRANK = 0.075  # m, the jaw crusher's crank AoA (the paper's Example 5 data; listings/example5.bas L(12))
VISIBLE = 20  # pixels of unbroken ink along a link's centre line for a person to see it as a bar


def _ink_along(image, axes, start, end) -> int:
    """The longest unbroken run of dark pixels (each channel below 80) on the segment start-end,
    points of the mechanism drawn on ``axes``, in the frame's ``image`` (rows counted from the top)."""
    import math

    pixels = np.asarray(image)
    (x0, y0), (x1, y1) = axes.transData.transform([start, end])
    steps = max(1, round(2 * math.hypot(x1 - x0, y1 - y0)))
    visited, longest, run = set(), 0, 0
    for k in range(steps + 1):
        place = (round(pixels.shape[0] - (y0 + (y1 - y0) * k / steps)), round(x0 + (x1 - x0) * k / steps))
        if place in visited:
            continue
        visited.add(place)
        run = run + 1 if pixels[place].max() < 80 else 0
        longest = max(longest, run)
    return longest


def test_example_5s_crank_is_seen_only_in_its_inset():
    """As a person sees the frames: at the picture's scale the 0.075 m crank is a few dark pixels between
    its pivot's and its pin's circles (no bar to see); somewhere in the frame, the inset, it is drawn as a
    bar at least VISIBLE pixels long.  Without the inset no part of the frame shows the crank."""
    import math

    from yaseer.animation.draw import _inset

    result = yaseer.run(LISTINGS / "example5.bas")
    scene = build_scene(result.frames)
    painter = Painter(scene, result.look())
    for number in range(0, len(scene.frames), 3):
        theta = math.radians(float(scene.frames[number].printed.split()[0]))  # the angle the listing printed
        pin = (EXAMPLE_5_CRANK * math.cos(theta), EXAMPLE_5_CRANK * math.sin(theta))
        image = painter.image(number)
        assert _ink_along(image, painter.ax, (0.0, 0.0), pin) < VISIBLE, number
        seen = [_ink_along(image, axes, (0.0, 0.0), pin) for axes in (painter.ax, _inset(painter.ax)) if axes]
        assert max(seen) >= VISIBLE, (number, seen)
