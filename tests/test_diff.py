"""``yaseer diff``: table parsing and comparison on small synthetic tables."""

from __future__ import annotations

from pathlib import Path

import pytest
from listing_runs import screen_numbers

from yaseer.cli import main as cli_main
from yaseer.commands import diff


def _run_cli(tmp_path: Path, program_csv: str, table_text: str, *extra: str) -> tuple[int, str]:
    program = tmp_path / "out.csv"
    table = tmp_path / "table.txt"
    program.write_text(program_csv)
    table.write_text(table_text)
    return cli_main(["diff", str(program), str(table), *extra]), ""


def test_printed_columns_with_header_place_blank_cells_by_alignment():
    text = ("   THET     PHI    BETA\n"
            "   0.00 -114.62  -65.38\n"
            "         114.62        \n"
            "  30.00          -82.70\n")
    table = diff.parse_table(text)
    assert table.names == ["THET", "PHI", "BETA"]
    assert [c.value for c in table.rows[0]] == [0.0, -114.62, -65.38]
    # continuation row: key carried down, the missing BETA stays blank
    assert table.rows[1][0].value == 0.0 and table.rows[1][1].value == 114.62 and table.rows[1][2].blank
    assert table.rows[2][1].blank and table.rows[2][2].value == -82.70


def test_overflow_touching_a_number_is_its_own_cell():
    table = diff.parse_table("       A       B       C\n    1.00  -23.63********\n")
    row = table.rows[0]
    assert row[1].value == -23.63
    assert row[2].overflow and row[2].value is None


def test_headerless_short_rows_lack_leading_cells():
    table = diff.parse_table("0 1.5 2.5\n3.5 4.5\n30 5 6\n")
    assert [c.value for c in table.rows[1]] == [0.0, 3.5, 4.5]
    assert [c.value for c in table.rows[2]] == [30.0, 5.0, 6.0]


def test_csv_blank_fields_are_not_compared():
    table = diff.parse_table("x,y,z\n1,,3.0\n")
    verdict = diff.compare([[1.0, 999.0, 3.0]], table)
    assert verdict.agrees
    assert verdict.compared_cells == 2  # key and z; the blank y is not compared


def test_default_tolerance_is_half_the_last_printed_digit():
    table = diff.parse_table("t,v\n0,9.79\n1,-41.46\n")
    assert diff.compare([[0, 9.794], [1, -41.455]], table).agrees
    verdict = diff.compare([[0, 9.796], [1, -41.46]], table)
    assert not verdict.agrees and verdict.differing_cells == 1
    assert any("9.80|9.79!" in line for line in verdict.lines)


def test_explicit_tolerance_overrides():
    table = diff.parse_table("t,v\n0,9.79\n")
    assert diff.compare([[0, 9.85]], table, tol=0.1).agrees
    assert not diff.compare([[0, 9.95]], table, tol=0.1).agrees


def test_rows_match_on_first_column_by_occurrence_not_position():
    table = diff.parse_table("t,v\n30,2\n0,1\n0,-1\n")
    program = [[0, 1.0], [0, -1.0], [30, 2.0]]
    verdict = diff.compare(program, table)
    assert verdict.agrees and verdict.matched_rows == 3


def test_missing_and_extra_rows_are_reported():
    table = diff.parse_table("t,v\n0,1\n60,3\n")
    verdict = diff.compare([[0, 1.0], [30, 2.0]], table)
    assert not verdict.agrees
    assert verdict.missing_rows == 1 and verdict.extra_rows == 1
    assert "1 table rows missing" in verdict.summary("tol")


def test_overflow_cell_agrees_only_with_a_value_too_wide_for_the_field():
    table = diff.parse_table("       A       B\n    1.00********\n    2.00   -5.25\n")
    wide = diff.compare([[1.0, -12345.678], [2.0, -5.25]], table)
    assert wide.agrees
    narrow = diff.compare([[1.0, -1234.5], [2.0, -5.25]], table)  # "-1234.50" fits 8 characters
    assert not narrow.agrees and narrow.differing_cells == 1


def test_cli_exit_status_and_verdict_line(tmp_path, capsys):
    status, _ = _run_cli(tmp_path, "0,1.0\n30,2.0\n", "t,v\n0,1.00\n30,2.00\n")
    assert status == 0
    assert capsys.readouterr().out.strip().splitlines()[-1].startswith("AGREE: 2 rows matched")
    status, _ = _run_cli(tmp_path, "0,1.0\n30,2.5\n", "t,v\n0,1.00\n30,2.00\n")
    last = capsys.readouterr().out.strip().splitlines()[-1]
    assert status == 1 and last.startswith("DIFFER: 2 rows matched, 1 of 4 compared cells differ")


def test_cli_unreadable_table_is_a_clear_error(tmp_path, capsys):
    program = tmp_path / "out.csv"
    program.write_text("0,1\n")
    status = cli_main(["diff", str(program), str(tmp_path / "nope.txt")])
    assert status == 1
    assert capsys.readouterr().err == f"yaseer diff: {tmp_path / 'nope.txt'}: No such file or directory\n"


@pytest.mark.parametrize("text", ["1.5", "-.25", "+3", "1e3", "1.0D2"])
def test_numbers_in_period_notations(text):
    assert diff.parse_cell(text).value == pytest.approx(float(text.replace("D", "e")))


def test_cli_listing_error_is_reported_as_the_basic_error(tmp_path, capsys):
    listing = tmp_path / "bad.bas"
    listing.write_text("10 PRINT 1\n20 PRINT 1/0\n")
    table = tmp_path / "t.csv"
    table.write_text("x\n1\n")
    assert cli_main(["diff", str(listing), str(table)]) == 1
    assert capsys.readouterr().err == f"yaseer diff: {listing}: Division by zero in 20\n"


def test_cli_ambiguous_printed_row_names_the_line(tmp_path, capsys):
    table = tmp_path / "t.txt"
    table.write_text("# comment\n       A       B       C\n    1.00    2.00    3.00\n 1.00 2.00\n 4.0 5.0 6.0 7.0\n")
    program = tmp_path / "out.csv"
    program.write_text("1,2\n")
    assert cli_main(["diff", str(program), str(table)]) == 1
    assert capsys.readouterr().err == f"yaseer diff: bad table {table}: line 4: two cells under column 1\n"
    table.write_text("       A       B\n    1.00    2.00\n    1.00 2.00 3.00\n")
    assert cli_main(["diff", str(program), str(table)]) == 1
    assert capsys.readouterr().err == f"yaseer diff: bad table {table}: line 3: 3 cells for 2 columns\n"


def test_full_rows_are_read_in_order_even_under_a_loosely_aligned_header():
    table = diff.parse_table("THET PHI BETA\n0.00 -114.62 -65.38\n30.00 -144.88 -82.70\n")
    assert [[c.value for c in row] for row in table.rows] == [[0.0, -114.62, -65.38], [30.0, -144.88, -82.70]]


# ---------------------------------------------------------------- what was compared, ragged rows, errata

ROOT = Path(__file__).resolve().parents[1]


def test_program_columns_the_table_lacks_are_shown_and_counted_as_not_compared(tmp_path, capsys):
    status, _ = _run_cli(tmp_path, "0,1.0,5.0\n30,2.0,6.0\n", "t,v\n0,1.00\n30,2.00\n")
    out = capsys.readouterr().out.splitlines()
    assert status == 0
    assert out[0].split() == ["t", "v", "(no", "column)"]
    assert out[1].split() == ["0", "1.00", "(5.00)"] and out[2].split() == ["30", "2.00", "(6.00)"]
    assert out[-1].startswith("AGREE: 2 rows matched, 0 of 4 compared cells differ beyond half a printed digit; "
                              "2 program values not compared")


def test_a_blank_table_cell_is_not_compared_and_marked(tmp_path, capsys):
    status, _ = _run_cli(tmp_path, "0,1.0,5.0\n", "t,v,w\n0,1.00,\n")
    out = capsys.readouterr().out.splitlines()
    assert out[1].split() == ["0", "1.00", "(5.00)"]
    assert "0 of 2 compared cells differ" in out[-1] and "1 program values not compared" in out[-1]


def test_ragged_rows_fill_the_last_columns_under_the_row_before_and_the_header_names_them():
    listing = ROOT / "listings" / "fortran_fourbar.bas"
    names, rows = diff.program_rows(listing)
    assert names == ("THET", "PHI", "BETA", "VELC", "VELB", "ACCC", "ACCB")
    screen = screen_numbers(listing)
    assert len(rows) == len(screen) == 14
    for row, printed in zip(rows, screen):
        assert len(row) == 7
        assert row[-len(printed):] == pytest.approx(printed, abs=0.006)  # a 6-value row: the last 6 columns
    assert [row[0] for row in rows[1::2]] == [row[0] for row in rows[0::2]]  # branch 2 under branch 1's angle


def test_the_listings_header_names_the_columns_of_an_unnamed_table(tmp_path):
    import subprocess
    import sys

    table = tmp_path / "t.csv"
    table.write_text("0,-114.62\n,114.62\n")
    done = subprocess.run([sys.executable, "-m", "yaseer", "diff", str(ROOT / "listings" / "fortran_fourbar.bas"),
                           str(table)], capture_output=True, text=True)
    lines = done.stdout.splitlines()
    assert lines[0].split() == ["THET", "PHI", "BETA", "VELC", "VELB", "ACCC", "ACCB"]
    assert lines[2].split()[:2] == ["0", "114.62"]  # the lower branch's PHI, not shifted
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_errata_file_explains_the_differing_printed_columns_of_seed_003():
    import subprocess
    import sys

    done = subprocess.run([sys.executable, "-m", "yaseer", "diff", str(ROOT / "listings" / "fortran_fourbar.bas"),
                           str(ROOT / "yaseer" / "data" / "seed003_printed.txt"), "--tol", "0.1"],
                          capture_output=True, text=True)
    why = [line for line in done.stdout.splitlines() if line.startswith("why ")]
    assert len(why) == 1 and why[0].startswith("why ACCC: the printed program computes C2 with VEL")
    flagged = {line.split()[5] for line in done.stdout.splitlines() if "!" in line}  # the ACCC cells only
    assert all("|" in cell for cell in flagged)
