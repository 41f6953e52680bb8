"""The plotting helpers behind ``yaseer plot``: table parsing, labels, the figure."""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from listing_runs import screen_numbers

from yaseer import plotting

ROOT = Path(__file__).resolve().parents[1]


def test_numeric_rows_keeps_the_table_and_drops_text_and_stray_rows():
    text = "ANGLE,TORQUE\n0.1,1.5,-2e-3\n20.1,2.5,4.0\n7\n40.1,-0.5,1e300\n"
    assert plotting.numeric_rows(text) == [[0.1, 1.5, -0.002], [20.1, 2.5, 4.0], [40.1, -0.5, 1e300]]


def test_numeric_rows_of_no_table_is_empty():
    assert plotting.numeric_rows("HELLO\n\n") == []


@pytest.mark.parametrize(
    "source, expected",
    [
        ('60 PRINT USING "###.###.##"; QQ; Y(2); V(4); A(36): NEXT QQ', ["QQ", "Y(2)", "V(4)", "A(36)"]),
        ('80 LPRINT USING "#.#"; QQ; SQR(F(3) ^ 2 + F(4) ^ 2): NEXT QQ: END', ["QQ", "SQR(F(3) ^ 2 + F(4) ^ 2)"]),
        ('10 PRINT "A;B:C", X, Y: PRINT Z', ["Z"]),
        ('10 PRINT A, B(1, 2); C\n20 END', ["A", "B(1, 2)", "C"]),
        ("10 X = 1", []),
    ],
)
def test_printed_expressions_are_those_of_the_last_print(source, expected):
    assert plotting.printed_expressions(source) == expected


def test_every_paper_example_has_a_meaning_for_each_printed_column():
    """The table matches the PRINT statement of each corrected listing, column for column."""
    for stem, spec in plotting.PAPER_EXAMPLES.items():
        expressions = plotting.printed_expressions((ROOT / "listings" / f"{stem}.bas").read_text())
        assert len(expressions) == len(spec.columns) + 1, stem
        for expression, quantity in zip(expressions[1:], spec.columns):
            elements = re.findall(r"[A-Z]+\(\d+\)", expression.replace(" ", ""))
            assert elements, expression
            for element in elements:
                assert element in quantity.meaning, (stem, expression, quantity.meaning)


def test_figure_spec_falls_back_to_the_printed_expressions(tmp_path):
    listing = tmp_path / "mine.bas"
    listing.write_text("10 FOR I = 0 TO 3: PRINT I; I * I; SIN(I): NEXT I\n")
    spec = plotting.figure_spec(listing, 3)
    assert spec.x.meaning == "I"
    assert [q.meaning for q in spec.columns] == ["I * I", "SIN(I)"]
    assert [q.meaning for q in plotting.figure_spec(listing, 4).columns] == ["column 2", "column 3", "column 4"]


def test_figure_has_one_panel_per_quantity_with_the_printed_values(tmp_path):
    rows = [[angle, math.sin(math.radians(angle)), angle ** 2] for angle in range(0, 361, 20)]
    spec = plotting.PAPER_EXAMPLES["example5"]
    spec = plotting.FigureSpec(spec.title, spec.x, spec.columns[:2])
    figure = plotting.build_figure(rows, spec)
    axes = figure.get_axes()
    assert len(axes) == 2
    for index, ax in enumerate(axes, start=1):
        (line,) = ax.get_lines()
        assert list(line.get_xdata()) == [row[0] for row in rows]
        assert list(line.get_ydata()) == [row[index] for row in rows]
    assert "crank torque" in axes[0].get_ylabel() and "N·m" in axes[0].get_ylabel()
    assert axes[1].get_xlabel() == "crank angle QQ (deg)"
    paths = plotting.save_figure(figure, tmp_path / "out", "example5")
    assert [p.name for p in paths] == ["example5.png", "example5.svg"]
    assert paths[0].read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert "Bo" in paths[1].read_text()


def _yaseer_plot(*args):
    import subprocess
    import sys

    return subprocess.run([sys.executable, "-m", "yaseer", "plot", *args], cwd=ROOT,
                          capture_output=True, text=True, timeout=120, check=False)


def test_plot_command_draws_a_listing_run_through_the_machine(tmp_path):
    result = _yaseer_plot("listings/example1.bas", "--out", str(tmp_path))
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == [str(tmp_path / "example1.png"), str(tmp_path / "example1.svg")]
    assert (tmp_path / "example1.png").read_bytes()[:4] == b"\x89PNG"
    svg = (tmp_path / "example1.svg").read_text()
    assert "piston D" in svg and "crank angle QQ" in svg


def test_plot_command_reports_the_listings_error_line(tmp_path):
    result = _yaseer_plot("listings/paper/example4.bas", "--out", str(tmp_path))
    assert result.returncode == 1
    assert result.stderr.strip() == "Syntax error in 4080"
    assert list(tmp_path.iterdir()) == []


def test_plot_command_refuses_a_listing_without_a_table(tmp_path):
    listing = tmp_path / "one.bas"
    listing.write_text('10 PRINT "HELLO"\n')
    result = _yaseer_plot(str(listing), "--out", str(tmp_path / "out"))
    assert result.returncode == 1
    assert "no table" in result.stderr
    assert not (tmp_path / "out").exists()


def test_plot_command_reports_an_unwritable_output_directory(tmp_path):
    occupied = tmp_path / "occupied"
    occupied.write_text("a file, not a directory")
    result = _yaseer_plot("listings/example2.bas", "--out", str(occupied))
    assert result.returncode == 1
    assert result.stderr == (f"yaseer plot: --out {occupied}: is a file; --out names a directory here "
                             "(several files are written)\n")
    assert "Traceback" not in result.stderr


# ---------------------------------------------------------------- rows of several kinds


def test_the_lower_branch_of_seed_003_is_a_second_series_under_its_own_columns():
    from yaseer import run
    from yaseer.series import plot_tables

    tables = plot_tables(run(ROOT / "listings" / "fortran_fourbar.bas").lines)
    assert len(tables) == 1
    (main,) = tables
    assert main.names == ("THET", "PHI", "BETA", "VELC", "VELB", "ACCC", "ACCB")
    upper, lower = main.series
    printed = screen_numbers("listings/fortran_fourbar.bas")
    assert [r for r in printed if len(r) == 7] == [pytest.approx(r, abs=0.006) for r in upper.rows]
    assert [r for r in printed if len(r) == 6] == [pytest.approx(r[1:], abs=0.006) for r in lower.rows]
    assert [r[0] for r in lower.rows] == [r[0] for r in upper.rows]  # each under the angle printed above it


def test_a_labelled_row_is_a_table_of_its_own_named_by_its_label():
    from yaseer import run
    from yaseer.series import plot_tables

    main, backsolve = plot_tables(run(ROOT / "listings" / "tk_slider_crank.bas").lines)
    assert main.width == 6 and len(main.series) == 1 and len(main.series[0].rows) == 50
    assert backsolve.label == "BACKSOLVE THETA, OMEGA, ALPHA:"
    assert backsolve.names == ("BACKSOLVE THETA", "OMEGA", "ALPHA")
    assert backsolve.series[0].rows == [pytest.approx([-30.0, -15.0, -10.0], abs=0.6)]  # it recovers the crank's


def test_a_line_breaks_where_the_crank_angle_steps_back_or_jumps_a_gap():
    from yaseer.series import broken

    xs, ys = broken([0, 30, 60, 90, 270, 300, 0, 30], [1, 2, 3, 4, 5, 6, 7, 8])
    gaps = [i for i, x in enumerate(xs) if math.isnan(x)]
    assert gaps == [4, 7]
    assert [x for x in xs if not math.isnan(x)] == [0, 30, 60, 90, 270, 300, 0, 30]
    assert math.isnan(ys[4]) and math.isnan(ys[7])


def test_plot_of_seed_003_draws_both_branches_broken_at_the_unassembled_angles(tmp_path):
    import yaseer

    figure = yaseer.run(ROOT / "listings" / "fortran_fourbar.bas").plot(subtitle="--method 2=newton")
    assert [ax.get_ylabel() for ax in figure.axes] == ["PHI", "BETA", "VELC", "VELB", "ACCC", "ACCB"]
    upper, lower = figure.axes[0].get_lines()
    for line in (upper, lower):
        xs = list(line.get_xdata())
        assert [x for x in xs if x == x] == [0, 30, 60, 90, 270, 300, 330]
        assert math.isnan(xs[4])  # no line across 120-240, where the linkage cannot be assembled
    assert "--method 2=newton" in figure._suptitle.get_text()


def test_plot_names_the_methods_in_the_title(tmp_path):
    result = _yaseer_plot("listings/example4.bas", "--out", str(tmp_path), "--method", "2=newton")
    assert result.returncode == 0, result.stderr
    assert "-method 2=newton -->" in (tmp_path / "example4.svg").read_text()  # (SVG comments cannot hold "--")
