"""notebooks/classroom.ipynb executed by a real kernel (nbclient + ipykernel), its outputs asserted.

References: the golden screens of the corrected examples (tests/golden, each number
checked against independent mechanism models in test_reference_examples), the errata
(listings/ERRATA.md: Example 4 as printed is a syntax error in 4080), the paper's
change-point centres of seed 004 (AC = 0.3/w - 0.3 with w = (1 +/- 2 sqrt 2)/5), and the
space centrode of yaseer.linkages.centrode (a Python formulation, no BASIC).
"""

import math
import re
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat", reason="the notebook test needs yaseer[jupyter] (nbformat)")
nbclient = pytest.importorskip("nbclient", reason="the notebook test needs yaseer[jupyter] (nbclient)")
pytest.importorskip("ipykernel", reason="the notebook test needs yaseer[jupyter] (ipykernel)")

ROOT = Path(__file__).resolve().parents[1]
NOTEBOOK = ROOT / "notebooks" / "classroom.ipynb"
GOLDEN = ROOT / "tests" / "golden"


def execute_notebook(path: Path, timeout: int = 600):
    """The notebook at ``path`` executed by a real kernel (in its own folder)."""
    notebook = nbformat.read(path, as_version=4)
    client = nbclient.NotebookClient(notebook, timeout=timeout, kernel_name="python3",
                                     resources={"metadata": {"path": str(path.parent)}})
    client.execute()
    return notebook


@pytest.fixture(scope="module")
def executed():
    """The notebook executed by a real kernel."""
    return execute_notebook(NOTEBOOK)


@pytest.fixture(scope="module")
def cells(executed):
    """The executed notebook's cells by tag."""
    return {cell.metadata["tags"][0]: cell for cell in executed.cells if cell.cell_type == "code"}


def test_with_six_animations_the_executed_notebook_stays_under_3_mb(executed, cells):
    players = [tag for tag, cell in cells.items() if any('class="yaseer-player"' in html for html in
                                                          data(cell, "text/html"))]
    assert players == ["example1", "example2", "example3", "example4", "example5", "seed004"]
    assert len(nbformat.writes(executed).encode()) < 3_000_000


def stdout(cell) -> str:
    return "".join(o.text for o in cell.outputs if o.output_type == "stream" and o.name == "stdout")


def data(cell, mime: str) -> list[str]:
    return [o.data[mime] for o in cell.outputs if o.output_type in ("display_data", "execute_result")
            and mime in o.data]


def test_no_cell_shows_a_traceback(cells):
    for tag, cell in cells.items():
        assert not [o for o in cell.outputs if o.output_type == "error"], tag


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_each_example_prints_its_golden_screen_and_plots_it(cells, n):
    cell = cells[f"example{n}"]
    assert stdout(cell) == (GOLDEN / f"example{n}.txt").read_text()
    assert len(data(cell, "image/png")) == 1


def test_example_1_is_animated_in_a_self_contained_player(cells):
    (player,) = data(cells["example1"], "text/html")
    rows = len((GOLDEN / "example1.txt").read_text().splitlines())
    assert 'class="yaseer-player"' in player and "<script" in player
    assert player.count("data:image/png;base64,") == rows + 2  # every frame, the first shown at once, the background
    assert "http" not in player  # nothing fetched from a network


def test_the_result_is_there_for_the_next_cell(cells):
    (names,) = data(cells["example1-names"], "text/plain")
    assert "position of piston D, Y(2) (mm)" in names
    (extremes,) = data(cells["example2-range"], "text/plain")
    low, high = (float(v) for v in re.findall(r"-?\d+\.\d+(?:e-?\d+)?", extremes))
    golden = [float(line.split()[1]) for line in (GOLDEN / "example2.txt").read_text().splitlines()]
    assert low == pytest.approx(min(golden), abs=5e-4) and high == pytest.approx(max(golden), abs=5e-4)


def test_the_printed_program_5_changes_the_acceleration(cells):
    (difference,) = data(cells["example1-printed-prog5"], "text/plain")
    assert float(difference) > 1000.0  # mm/s², on accelerations up to 46 516 (ERRATA, Program 5 line 60)


def test_an_error_is_one_red_line(cells):
    for tag, expected, before in (("example4-printed", "Syntax error in 4080", ""),
                                  ("error", "Division by zero in 20", "ONE\n")):
        cell = cells[tag]
        assert stdout(cell) == before
        assert data(cell, "text/plain") == [expected]
        (red,) = data(cell, "text/html")
        assert "color:#c00000" in red and expected in red


def seed004_rows(cells) -> list[tuple[float, float, float]]:
    return [tuple(float(v) for v in line.split()) for line in stdout(cells["seed004"]).splitlines()]


def test_the_seed_004_centrode_matches_the_python_formulation(cells):
    import numpy as np

    from yaseer.linkages.centrode import space_centrode

    rows = np.array(seed004_rows(cells))
    assert rows.shape == (144, 3) and list(rows[:, 0]) == [2.5 + 5 * k for k in range(144)]
    # The listing starts on the other assembly than space_centrode does: the motion takes two
    # crank turns to come back, so the listing's first turn is space_centrode's second.
    _, centre = space_centrode(crank_angles_deg=np.arange(2.5, 1080.0, 5.0))
    centre = centre[72:]
    printed = rows[:, 1] + 1j * rows[:, 2]
    # 10 significant digits printed (at 170 m near an asymptote: 1e-7 m)
    assert (np.abs(printed - centre) / np.maximum(1.0, np.abs(centre))).max() < 1e-8
    assert data(cells["seed004-plot"], "image/png")
    assert data(cells["seed004"], "text/html")  # the animation


def test_the_centre_reaches_the_papers_change_point_positions(cells):
    paper = sorted(0.3 / ((1 + sign * 2 * math.sqrt(2)) / 5) - 0.3 for sign in (1, -1))  # -1.1204, 0.0918
    by_angle = {row[0]: row[1:] for row in seed004_rows(cells)}
    for angles, ac in (((177.5, 182.5), paper[0]), ((537.5, 542.5), paper[1])):
        for angle in angles:
            x, y = by_angle[angle]
            assert x == pytest.approx(ac, abs=2e-3) and abs(y) < 0.05


def golden_columns(n):
    return [[float(v) for v in line.split()] for line in (GOLDEN / f"example{n}.txt").read_text().splitlines()]


@pytest.mark.parametrize("tag, n, column", [("example3-fastest", 3, 2), ("example5-peak", 5, 1)])
def test_the_extreme_values_the_notebook_reports(cells, tag, n, column):
    (shown,) = data(cells[tag], "text/plain")
    angle, value = (float(v) for v in shown.strip("()").split(","))
    rows = golden_columns(n)
    peak = max(rows, key=lambda row: abs(row[column]))
    assert angle == pytest.approx(peak[0], abs=0.005) and value == pytest.approx(peak[column], abs=0.005)
