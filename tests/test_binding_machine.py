"""The library programs bound into the real BASIC machine: small listings run
through ``yaseer run`` (the command's main), checked against the seed papers'
numbers, finite differences taken in BASIC itself, and the error contract."""

from __future__ import annotations

import csv
import io

import pytest

from yaseer import cli


def run(tmp_path, capsys, listing: str, *options: str):
    path = tmp_path / "listing.bas"
    path.write_text(listing)
    status = cli.main(["run", str(path), "--format", "csv", *options])
    captured = capsys.readouterr()
    rows = [[float(cell) for cell in row] for row in csv.reader(io.StringIO(captured.out)) if row]
    return status, rows, captured.err.strip()


def test_seed_001_through_gosub_prog_1(tmp_path, capsys):
    listing = (
        "10 L(1) = -2: L(2) = 3: L(3) = 8: T(2) = -30: W(2) = -15: A(2) = -10: T(4) = 0\n"
        "20 GOSUB PROG 1\n"
        "30 PRINT X(2); V(3); W(3); A(35); A(3)\n"
    )
    status, rows, _ = run(tmp_path, capsys, listing)
    assert status == 0
    assert rows[0] == pytest.approx([9.79, -41.46, 5.42, -709.1, -29.03], abs=0.006)


def test_rates_agree_with_differences_taken_in_basic(tmp_path, capsys):
    # a four-bar with a flexible crank: BASIC steps time by +-H and differences X(4), Y(4)
    listing = (
        "10 H = .0001: L(11) = 100: T(11) = 10: L(13) = 120: L(14) = 80: L(10) = 1: R(11) = 60: H(11) = 30\n"
        "20 FOR K = -1 TO 1: TT = 1 + K * H\n"
        "30 T(12) = 57.29577951308232 * (TT + .3 * SIN(114.5915590261646 * TT))\n"
        "40 L(12) = 40 + 3 * SIN(171.8873385392969 * TT): W(5) = 0: A(5) = 0: D(2) = 0: E(2) = 0\n"
        "50 GOSUB PROG 2: P(K + 2) = X(4): C(K + 2) = Y(4): NEXT K\n"
        "60 TT = 1: T(12) = 57.29577951308232 * (TT + .3 * SIN(114.5915590261646 * TT))\n"
        "70 L(12) = 40 + 3 * SIN(171.8873385392969 * TT): W(5) = 1 + .6 * COS(114.5915590261646 * TT)\n"
        "80 A(5) = -1.2 * SIN(114.5915590261646 * TT): D(2) = 9 * COS(171.8873385392969 * TT)\n"
        "90 E(2) = -27 * SIN(171.8873385392969 * TT): GOSUB PROG 2\n"
        "100 PRINT (P(3) - P(1)) / 2 / H; V(7); (C(3) - C(1)) / 2 / H; V(8)\n"
        "110 PRINT (P(3) - 2 * X(4) + P(1)) / H / H; A(39); (C(3) - 2 * Y(4) + C(1)) / H / H; A(40)\n"
    )
    status, rows, err = run(tmp_path, capsys, listing)
    assert status == 0, err
    (dx, vx, dy, vy), (ddx, ax, ddy, ay) = rows
    assert vx == pytest.approx(dx, rel=1e-6) and vy == pytest.approx(dy, rel=1e-6)
    assert ax == pytest.approx(ddx, rel=1e-3, abs=1e-2) and ay == pytest.approx(ddy, rel=1e-3, abs=1e-2)


def test_cannot_be_assembled_names_program_and_calling_line(tmp_path, capsys):
    listing = "10 L(11) = 10: L(12) = 1: L(13) = 2: L(14) = 2\n40 GOSUB PROG 2\n50 PRINT 1\n"
    status, rows, err = run(tmp_path, capsys, listing)
    assert status == 1 and rows == []
    assert err == "Mechanism cannot be assembled (PROG 2) in 40"


def test_on_error_goto_traps_the_assembly_error(tmp_path, capsys):
    listing = (
        "10 ON ERROR GOTO 100\n"
        "20 L(11) = 60: L(12) = 30: L(13) = 36: L(14) = 36\n"
        "30 FOR Q = 0 TO 330 STEP 30: T(12) = Q: GOSUB PROG 2: PRINT Q; T(13)\n"
        "40 NEXT Q: END\n"
        "100 PRINT -Q; ERR; ERL: RESUME 40\n"
    )
    status, rows, err = run(tmp_path, capsys, listing)
    assert status == 0, err
    skipped = [row for row in rows if row[0] < 0]
    assert [-row[0] for row in skipped] == [120, 150, 180, 210, 240]  # seed 003's missing rows
    assert all(row[1:] == [14, 30] for row in skipped)  # the Casio's MA error (Illegal function call), line 30
    assert [row[0] for row in rows if row[0] >= 0] == [0, 30, 60, 90, 270, 300, 330]


def test_method_option_selects_the_papers_virtual_link(tmp_path, capsys):
    listing = "10 X(10) = 0: Y(10) = 2: V(17) = 1: GOSUB PROG 5: PRINT T; L; D(5)\n"
    status, rows, _ = run(tmp_path, capsys, listing)
    assert status == 0 and rows[0] == pytest.approx([90.0, 2.0, -0.5])
    status, rows, err = run(tmp_path, capsys, listing, "--method", "5=paper")
    assert status == 1 and err == "Division by zero (PROG 5) in 10"
    status, rows, err = run(tmp_path, capsys, listing, "--method", "5=nonesuch")
    assert status == 2 and "unknown method 'nonesuch' for PROG 5 (known: polar, paper)" in err


def test_forces_only_when_z_is_2(tmp_path, capsys):
    listing = (
        "10 L(2) = .1: L(3) = .3: T(2) = 60: W(2) = 10: M(3) = 2: I(3) = .01: R(3) = .15: P(1) = 100\n"
        "20 Q(1) = 1: F(3) = 777: GOSUB PROG 1: PRINT U(1); F(3)\n"
        "30 Z(1) = 2: GOSUB PROG 1: PRINT U(1); F(3); N(1)\n"
    )
    status, rows, err = run(tmp_path, capsys, listing)
    assert status == 0, err
    assert rows[0] == [0.0, 777.0]
    assert rows[1][0] != 0 and rows[1][1] != 777.0


def test_a_two_dimensional_input_array_is_a_basic_error_not_a_traceback(tmp_path, capsys):
    status, rows, err = run(tmp_path, capsys, "10 DIM W(3, 3)\n20 L(1) = 0: L(2) = 1: L(3) = 3\n30 GOSUB PROG 1\n")
    assert status == 1 and err == "Type mismatch (PROG 1) in 30"


def test_a_two_dimensional_output_array_is_a_basic_error(tmp_path, capsys):
    listing = "10 DIM V(4, 4)\n20 L(2) = 1: L(3) = 3: W(2) = 1\n30 GOSUB PROG 1\n"  # V is written, never read
    status, rows, err = run(tmp_path, capsys, listing)
    assert status == 1 and err == "Type mismatch (PROG 1) in 30"


@pytest.mark.parametrize("inputs", [
    "L(2) = 1E+200: L(3) = 1E+200: W(2) = 1E+200",  # kinematics overflow
    "L(2) = 1: L(3) = 3: W(2) = 1: Z(1) = 2: Q(1) = 1: M(2) = 1E+300: R(2) = 1E+300",  # inertia overflows
])
def test_overflowing_inputs_are_an_overflow_error(tmp_path, capsys, inputs):
    status, rows, err = run(tmp_path, capsys, f"10 {inputs}: GOSUB PROG 1\n")
    assert status == 1 and err == "Overflow (PROG 1) in 10"


def test_an_overflow_in_the_first_library_call_is_one_line_without_numpy_warnings(tmp_path):
    """A fresh process: numpy is imported by the first GOSUB PROG, whose warnings are silenced too."""
    import subprocess
    import sys

    path = tmp_path / "listing.bas"
    path.write_text("10 X(10) = 1E-300: V(18) = 1E300\n20 GOSUB PROG 5\n")
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(path)], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 1
    assert done.stderr.splitlines() == ["Overflow (PROG 5) in 20"]
