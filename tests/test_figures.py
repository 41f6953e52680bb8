"""The committed figures (README, docs/) are what the commands draw now: ``tools/figures.py --check``.

Pictures are compared by their ink (see tools/figures.py), so the check holds across
matplotlib and Pillow versions; a line drawn as dots instead of a line fails it, as the
last test shows by drawing Example 5 with its line cut at every row.
"""

from __future__ import annotations

import importlib.util
import math
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _figures():
    spec = importlib.util.spec_from_file_location("figures", ROOT / "tools" / "figures.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules["figures"] = module  # dataclasses look their module up there
    spec.loader.exec_module(module)
    return module


figures = _figures()


def test_every_picture_the_readme_shows_is_regenerated_by_the_script():
    import re

    shown = set()
    for page in [ROOT / "README.md", *(ROOT / "docs").glob("*.md")]:
        for target in re.findall(r"!\[[^\]]*\]\(([^)]+)\)", page.read_text()):
            shown.add((page.parent / target).resolve().relative_to(ROOT).as_posix())
    assert shown <= {figure.path for figure in figures.FIGURES}


@pytest.mark.parametrize("figure", [f for f in figures.FIGURES if f.compared], ids=lambda f: f.path)
def test_the_committed_figure_is_what_its_command_draws_now(figure, tmp_path):
    fresh = tmp_path / Path(figure.path).name
    figure.draw(fresh)
    assert figures.differences(ROOT / figure.path, fresh) == [], f"redraw it: python tools/figures.py {figure.path}"


def test_the_comparison_fails_for_a_figure_drawn_as_dots(tmp_path, monkeypatch):
    from yaseer import series

    def cut_everywhere(xs, ys):
        out_x, out_y = [], []
        for x, y in zip(xs, ys):
            out_x += [x, math.nan]
            out_y += [y, math.nan]
        return out_x, out_y

    monkeypatch.setattr(series, "broken", cut_everywhere)
    (example5,) = [f for f in figures.FIGURES if f.path == "docs/example5.png"]
    example5.draw(tmp_path / "dots.png")
    found = figures.differences(ROOT / example5.path, tmp_path / "dots.png")
    assert any(line.startswith("coloured ink") and "committed picture" in line for line in found), found
