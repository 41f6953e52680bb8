"""The paper's figures are drawn as lines, broken only where the mechanism's motion broke.

Where the motion breaks is worked out here without the plotting code: the crank
positions a listing's ``FOR`` statement sweeps (exact fractions), the four-bar's
assembly condition (the diagonal from crank pin to follower pivot must be no longer
than coupler + follower), and the branches a listing runs one after the other.  Each
drawn line must be exactly those pieces: a line cut at a ``STEP -20`` sweep's every
row (dots without lines, the regression this file guards) fails, and so does a line
joined across positions that cannot be assembled.
"""

from __future__ import annotations

import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from fractions import Fraction
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def swept(listing: str, variable: str = "QQ") -> list[float]:
    """The values ``FOR variable = a TO b STEP s`` takes in ``listing``, computed exactly."""
    found = re.search(rf"FOR {variable} = ([-\d.]+) TO ([-\d.]+)(?: STEP ([-\d. ]+))?", listing)
    assert found, f"no FOR {variable} in the listing"
    start, stop = Fraction(found[1]), Fraction(found[2])
    step = Fraction(found[3].replace(" ", "")) if found[3] else Fraction(1)
    values, value = [], start
    while (value - stop) * step <= 0:
        values.append(float(value))
        value += step
    return values


def fourbar_assembles(crank_deg: float, ground: float, crank: float, coupler: float, follower: float) -> bool:
    """Whether a four-bar assembles: the crank pin to follower pivot distance lies within the dyad's reach."""
    diagonal = math.sqrt(ground ** 2 + crank ** 2 - 2 * ground * crank * math.cos(math.radians(crank_deg)))
    return abs(coupler - follower) <= diagonal <= coupler + follower


def runs_of(values: list[float], keep) -> list[list[float]]:
    """The maximal runs of consecutive ``values`` for which ``keep`` holds."""
    pieces, current = [], []
    for value in values:
        if keep(value):
            current.append(value)
        elif current:
            pieces.append(current)
            current = []
    return pieces + ([current] if current else [])


def seed004_listing() -> str:
    """The README's ``%%basic`` cell: seed 004's change-point four-bar, tracked through its change point."""
    readme = (ROOT / "README.md").read_text()
    cell = re.search(r"```\n%%basic[^\n]*\n(.*?)```", readme, re.S)
    return cell[1]


def expected_pieces() -> dict[str, list[list[float]]]:
    """For each figure: the crank angles of each unbroken piece of its (first) line."""
    pieces = {}
    for n in (1, 2, 3, 4, 5):
        # One crank revolution that assembles at every position (the paper's Figs. 7-14 are unbroken curves).
        pieces[f"example{n}"] = [swept((ROOT / "listings" / f"example{n}.bas").read_text())]
    # Seed 003: ground 60, crank 30, coupler 36, follower 36, every 30 degrees; skipped where it cannot assemble.
    angles = [30.0 * j for j in range(12)]
    pieces["fortran_fourbar"] = runs_of(angles, lambda a: fourbar_assembles(a, 60, 30, 36, 36))
    # Seed 001: row C open, row C crossed (two assemblies, one position each), then a cycle of each assembly.
    cycle = swept((ROOT / "listings" / "tk_slider_crank.bas").read_text())
    pieces["tk_slider_crank"] = [[-30.0], [-30.0], cycle, cycle]
    # Seed 004 with continuous branch tracking passes its change point: two crank turns, one line.
    pieces["seed004"] = [swept(seed004_listing())]
    return pieces


FIGURES = expected_pieces()


def _source(name: str):
    return seed004_listing() if name == "seed004" else ROOT / "listings" / f"{name}.bas"


def _pieces(xs) -> list[list[float]]:
    return [piece for piece in runs_of(list(xs) + [math.nan], lambda x: not math.isnan(x))]


@pytest.mark.parametrize("name", sorted(FIGURES))
def test_every_line_of_a_paper_figure_is_broken_only_where_the_mechanism_broke(name):
    import yaseer

    figure = yaseer.run(_source(name)).plot()
    expected = FIGURES[name]
    main_panels = [ax for ax in figure.axes if ax.get_lines() and ax.get_lines()[0].get_xdata().size]
    assert main_panels
    for ax in main_panels[:1] if name == "tk_slider_crank" else main_panels:
        line = ax.get_lines()[0]
        drawn = _pieces(line.get_xdata())
        assert [len(piece) for piece in drawn] == [len(piece) for piece in expected], (name, ax.get_ylabel())
        for piece, want in zip(drawn, expected):
            assert piece == pytest.approx(want, abs=1e-9), (name, ax.get_ylabel())
    if name == "fortran_fourbar":  # the lower branch, printed under the upper, breaks in the same places
        drawn = _pieces(figure.axes[0].get_lines()[1].get_xdata())
        assert drawn == [pytest.approx(piece) for piece in expected]


def _svg_line_pieces(svg: Path) -> list[int]:
    """For each data line of a ``yaseer plot`` SVG (a clipped, unfilled path in a ``line2d`` group drawn in
    one of the plot's series colours), how many pieces it is drawn in (its move-to commands)."""
    colours = ("#1f77b4", "#ff7f0e", "#2ca02c", "#d62728")
    counts = []
    for group in ET.parse(svg).getroot().iter("{http://www.w3.org/2000/svg}g"):
        if not group.get("id", "").startswith("line2d_"):
            continue
        for path in group.findall("{http://www.w3.org/2000/svg}path"):
            style = path.get("style", "")
            if path.get("clip-path") and "fill: none" in style and any(f"stroke: {c}" in style for c in colours):
                counts.append(path.get("d").count("M"))
    return counts


@pytest.mark.parametrize("name", ["example2", "example5", "fortran_fourbar"])
def test_the_plot_command_draws_each_figure_in_the_pieces_of_the_mechanisms_motion(name, tmp_path):
    result = subprocess.run([sys.executable, "-m", "yaseer", "plot", f"listings/{name}.bas", "--out", str(tmp_path)],
                            cwd=ROOT, capture_output=True, text=True, timeout=180, check=False)
    assert result.returncode == 0, result.stderr
    counts = _svg_line_pieces(tmp_path / f"{name}.svg")
    panels = 6 if name == "fortran_fourbar" else 3
    series = 2 if name == "fortran_fourbar" else 1
    assert counts == [len(FIGURES[name])] * (panels * series)


def test_a_sweep_downwards_is_one_line_and_a_restart_or_gap_still_breaks_it():
    from yaseer.series import broken

    down = [360.1 - 20 * k for k in range(19)]
    xs, _ = broken(down, list(range(19)))
    assert xs == down  # no NaN: STEP -20 is the sweep's direction, not a step back
    xs, _ = broken(down + down, list(range(38)))  # a second downward pass starts over: one break
    assert [i for i, x in enumerate(xs) if math.isnan(x)] == [19]
    xs, _ = broken([300, 280, 260, 120, 100], [0] * 5)  # a gap of 140 where the usual step is 20
    assert [i for i, x in enumerate(xs) if math.isnan(x)] == [3]
    xs, _ = broken([0, 10, 10, 20], [0] * 4)  # the same angle again (another branch) breaks too
    assert [i for i, x in enumerate(xs) if math.isnan(x)] == [2]
