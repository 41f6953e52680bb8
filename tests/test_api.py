"""``yaseer.run`` from Python: text, rows, names, errors as data, frames, plot, animate.

References: the golden output of the corrected examples (tests/golden, whose every
number is checked against independent mechanism models in test_reference_examples),
Python's own arithmetic for small programs, and the paper's column meanings.
"""

import csv
import math
import subprocess
import sys
from pathlib import Path

import pytest

import yaseer
from yaseer.basic.errors import BasicError

ROOT = Path(__file__).resolve().parents[1]
GOLDEN = ROOT / "tests" / "golden"


def golden_rows(n):
    with open(GOLDEN / f"example{n}.csv") as handle:
        return [[float(v) for v in row] for row in csv.reader(handle)]


@pytest.mark.parametrize("n", [1, 3])
def test_a_paper_example_gives_the_golden_screen_and_rows(n):
    result = yaseer.run(ROOT / "listings" / f"example{n}.bas")
    assert result.error is None and result.status == "end"
    assert result.text == (GOLDEN / f"example{n}.txt").read_text()
    # full precision (the golden csv to rounding), not the 2 printed decimals
    assert result.rows.tolist() == [pytest.approx(row, rel=1e-12, abs=1e-9) for row in golden_rows(n)]


def test_the_examples_columns_are_named_as_the_paper_means_them():
    result = yaseer.run(str(ROOT / "listings" / "example1.bas"))
    assert result.rows.names[0] == "crank angle QQ (deg)"
    assert result.rows.names[1] == "position of piston D, Y(2) (mm)"
    assert result.title.startswith("Example 1")
    assert list(result.rows.column("crank angle QQ (deg)")) == [row[0] for row in golden_rows(1)]


def test_program_text_with_a_header_and_two_row_shapes():
    text = '5 REM SQUARES AND CUBES\n10 PRINT "N", "SQUARE"\n20 FOR N = 1 TO 3: PRINT N, N*N: NEXT\n30 PRINT 1, 2, 3\n'
    result = yaseer.run(text)
    assert result.name is None and result.title == "SQUARES AND CUBES"
    squares, triple = result.rows
    assert squares.tolist() == [[1, 1], [2, 4], [3, 9]] and squares.names == ("N", "SQUARE")
    assert triple.tolist() == [[1, 2, 3]] and triple.names is None
    assert result.text.splitlines()[0].split() == ["N", "SQUARE"]


def test_a_header_split_at_blanks_names_the_fortran_four_bar():
    result = yaseer.run(ROOT / "listings" / "fortran_fourbar.bas")
    crossed, uncrossed = result.rows
    assert crossed.names == ("THET", "PHI", "BETA", "VELC", "VELB", "ACCC", "ACCB")
    assert crossed.shape[1] == 7 and uncrossed.shape[1] == 6
    assert list(crossed[:, 0]) == [0, 30, 60, 90, 270, 300, 330]  # 120..240 cannot be assembled


def test_an_error_is_one_line_of_data_and_the_screen_before_it_is_kept():
    result = yaseer.run("10 PRINT 7\n20 X = 1/0\n30 PRINT 8\n")
    assert result.error == "Division by zero in 20" and result.status == "error" and result.line == 20
    assert result.text == " 7 \n"
    with pytest.raises(BasicError, match="Division by zero in 20"):
        yaseer.run("10 PRINT 7\n20 X = 1/0\n", raise_errors=True)


def test_a_missing_file_and_an_unknown_method_are_errors_too():
    assert yaseer.run("missing.bas").error == "File not found: missing.bas"
    with pytest.raises(ValueError, match="unknown method 'magic' for PROG 2"):  # as the command line refuses it
        yaseer.run("10 PRINT 1", method={2: "magic"})
    with pytest.raises(TypeError):
        yaseer.run(42)


def test_input_angle_and_a_program_area_from_text():
    result = yaseer.run("10 INPUT A, B: PRINT A * B; SIN(A)", input="3\n4\n", angle="rad")
    assert result.rows.tolist() == [[12.0, pytest.approx(math.sin(3.0), rel=1e-15)]]
    assert result.text.startswith("? 3\n? 4\n")  # what INPUT read is echoed as if typed, a "?" a variable
    area = "10 X = X * 2: RETURN\n"
    assert yaseer.run("10 X = 21: GOSUB PROG 7: PRINT X", prog={7: area}).rows.tolist() == [[42.0]]


def test_the_printed_program_5_and_a_method_change_the_numbers_as_the_paper_says():
    corrected = yaseer.run(ROOT / "listings" / "example1.bas")
    printed = yaseer.run(ROOT / "listings" / "example1.bas", prog={5: ROOT / "programs" / "prog5.bas"})
    paper = yaseer.run(ROOT / "listings" / "example1.bas", method={5: "paper"})
    assert printed.error is None and paper.error is None
    # Positions and velocities do not use Program 5's line 60; accelerations do (ERRATA:
    # the printed line drops the factor L); the "paper" method (eqs. (1)-(4)) agrees with the default.
    for column in (1, 2):
        assert printed.rows[:, column].tolist() == pytest.approx(corrected.rows[:, column].tolist(), rel=1e-9)
    assert printed.rows[:, 3].tolist() != pytest.approx(corrected.rows[:, 3].tolist(), rel=1e-3)
    for column in range(4):
        assert paper.rows[:, column].tolist() == pytest.approx(corrected.rows[:, column].tolist(), rel=1e-9)
    # a BASIC program area is recorded like the library's: the printed Program 5's virtual link
    assert [s.area for s in printed.frames[0].snapshots] == [1, 5, 1]
    tip = printed.frames[0].snapshots[1].bars[0].end
    assert tip == pytest.approx(corrected.frames[0].snapshots[1].bars[0].end, rel=1e-12)


def test_frames_are_the_printed_positions():
    result = yaseer.run(ROOT / "listings" / "example1.bas")
    assert len(result.frames) == len(golden_rows(1))
    assert [f.printed for f in result.frames] == result.text.splitlines()
    assert [f.crank_angle for f in result.frames] == pytest.approx([row[0] for row in golden_rows(1)])


def test_plot_and_animate():
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure

    result = yaseer.run(ROOT / "listings" / "example4.bas")
    figure = result.plot()
    assert isinstance(figure, Figure)
    labels = [ax.get_ylabel().replace("\n", " ") for ax in figure.axes]
    assert labels[0].startswith("angular velocity of DE")
    assert list(figure.axes[0].lines[0].get_xdata()) == [row[0] for row in golden_rows(4)]
    animation = result.animate(max_frames=5)
    assert isinstance(animation, FuncAnimation)
    with pytest.raises(ValueError, match="no table"):
        yaseer.run("10 PRINT 1").plot()


def test_the_command_line_prints_what_the_api_keeps(tmp_path):
    listing = ROOT / "listings" / "example2.bas"
    command = subprocess.run([sys.executable, "-m", "yaseer", "run", str(listing)], capture_output=True, text=True)
    assert command.returncode == 0 and command.stdout == yaseer.run(listing).text


def test_importing_yaseer_and_reaching_run_imports_no_numpy_or_matplotlib():
    code = "import sys, yaseer; yaseer.run; print(sorted(m for m in ('numpy', 'matplotlib') if m in sys.modules))"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"


def test_running_a_basic_only_program_imports_no_numpy_until_rows_are_asked_for():
    code = ("import sys, yaseer\nr = yaseer.run('10 PRINT 2+2')\nbefore = 'numpy' in sys.modules\n"
            "r.rows\nprint(r.text.strip(), before, 'numpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.split() == ["4", "False", "True"]


def test_yaseer_run_of_a_basic_only_program_imports_no_numpy(tmp_path):
    listing = tmp_path / "a.bas"
    listing.write_text("10 PRINT 2+2\n")
    code = ("import sys\nfrom yaseer.cli import main\nstatus = main(['run', sys.argv[1]])\n"
            "print(status, 'numpy' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code, str(listing)], capture_output=True, text=True,
                         check=True).stdout
    assert out.split() == ["4", "0", "False"]


def test_the_gw_dialect_has_no_library_and_starts_in_radians():
    assert yaseer.run("10 PRINT ATN(1)*4", dialect="gw").rows[0][0] == pytest.approx(math.pi, rel=1e-6)
    assert yaseer.run("10 GOSUB PROG 1", dialect="gw").error is not None
