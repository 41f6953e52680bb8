"""notebooks/casio.ipynb executed by a real kernel: a Casio program's LCD in a notebook.

The program (ours, in the style of the FX-850P's scientific library) solves
x^2 - 3x + 2 = 0; the roots it must show, 1 and 2, are the closed form's.  Its
subscripts are DEFCHR$ characters, which the notebook's LCD draws from their dots.
"""

import math
from pathlib import Path

import pytest

nbformat = pytest.importorskip("nbformat", reason="the notebook test needs yaseer[jupyter] (nbformat)")

NOTEBOOK = Path(__file__).resolve().parents[1] / "notebooks" / "casio.ipynb"


@pytest.fixture(scope="module")
def executed():
    from test_notebook import execute_notebook

    return execute_notebook(NOTEBOOK, timeout=120)


def cell(notebook, tag):
    return next(c for c in notebook.cells if c.cell_type == "code" and tag in c.metadata.get("tags", ()))


def html_of(c) -> str:
    return "".join(o.data["text/html"] for o in c.outputs
                   if o.output_type in ("display_data", "execute_result") and "text/html" in o.data)


def test_the_lcd_shows_the_roots_with_drawn_subscripts(executed):
    lcd = html_of(cell(executed, "quadratic"))
    a, b, c = 1, -3, 2
    roots = sorted(((-b - math.sqrt(b * b - 4 * a * c)) / (2 * a), (-b + math.sqrt(b * b - 4 * a * c)) / (2 * a)))
    assert lcd.count("background:#c8d4b0") >= 4  # a panel each time the program waited for a key
    assert f"= {roots[0]:g}" in lcd and f"= {roots[1]:g}" in lcd
    assert lcd.count("<svg") >= 2  # x1 and x2: their subscripts' dots, not the table's symbols
    assert not [o for c in executed.cells for o in c.get("outputs", ()) if o.output_type == "error"]


def test_the_result_is_there_for_the_next_cell(executed):
    screen = "".join(o.data["text/plain"] for o in cell(executed, "screen").outputs if o.output_type == "execute_result")
    assert "x" in screen and "EXE: again" in screen


def test_the_notebook_stays_small(executed):
    assert len(nbformat.writes(executed).encode()) < 60_000


def test_a_library_program_shows_its_lcd(executed):
    # Becker's LIB5615 (the area of a circle) for r = 2: the LCD panel shows pi*r^2 to the
    # display's 10 digits; the library is not part of the repository (YASEER_CASIO_LIBRARY)
    import os

    library = os.environ.get("YASEER_CASIO_LIBRARY")
    if not library or not (Path(library) / "LIB5615.bas").is_file():
        pytest.skip("Becker's library is absent: set YASEER_CASIO_LIBRARY to its sources folder")
    lcd = html_of(cell(executed, "library"))
    assert lcd.count("background:#c8d4b0") >= 2  # the prompt's panel and the result's
    assert f"Area = {math.pi * 2 * 2:.10g}" in lcd
