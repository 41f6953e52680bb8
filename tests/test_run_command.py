"""``yaseer run``: options, output streams, exit status, no tracebacks."""

import subprocess
import sys
from pathlib import Path

import pytest

from yaseer import binding
from yaseer.cli import main


def write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


def test_text_output_and_exit_zero(tmp_path, capsys):
    path = write(tmp_path, "a.bas", '10 FOR I=1 TO 3: PRINT I;: NEXT: PRINT\n20 PRINT "done"\n')
    assert main(["run", path]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[-1] == "done"
    assert [float(x) for x in out.splitlines()[0].split()] == [1.0, 2.0, 3.0]


def test_csv_format(tmp_path, capsys):
    path = write(tmp_path, "a.bas", '10 PRINT 1/3, "x"; 2\n20 LPRINT USING "##.#"; 2/3\n')
    assert main(["run", path, "--format", "csv"]) == 0
    assert capsys.readouterr().out == f"{1/3!r},x,2.0\n{2/3!r}\n"


def test_error_goes_to_stderr_with_status_one(tmp_path, capsys):
    path = write(tmp_path, "a.bas", "10 PRINT 1;\n20 X=1/0\n")
    assert main(["run", path]) == 1
    captured = capsys.readouterr()
    assert captured.err == "Division by zero in 20\n"
    assert "Traceback" not in captured.err


def test_printer_file(tmp_path, capsys):
    path = write(tmp_path, "a.bas", '10 PRINT "screen": LPRINT "paper"\n')
    printer = tmp_path / "printer.txt"
    assert main(["run", path, "--printer", str(printer)]) == 0
    assert capsys.readouterr().out == "screen\n"
    assert printer.read_text() == "paper\n"


def test_prog_option_loads_a_basic_area(tmp_path, capsys):
    path = write(tmp_path, "a.bas", "10 X(10)=2: GOSUB PROG 5: PRINT T\n")
    area = write(tmp_path, "p5.bas", "10 T=X(10)^3: RETURN\n")
    assert main(["run", path, "--prog", f"5={area}", "--format", "csv"]) == 0
    assert capsys.readouterr().out == "8.0\n"


def test_angle_and_input_options(tmp_path, capsys):
    path = write(tmp_path, "a.bas", "10 INPUT A: PRINT ATN(A)\n")
    data = write(tmp_path, "in.txt", "1\n")
    assert main(["run", path, "--angle", "rad", "--input", data, "--format", "csv"]) == 0
    assert capsys.readouterr().out.splitlines()[-1] == repr(0.7853981633974483)


def test_method_pairs_reach_binding_install(tmp_path, capsys, monkeypatch):
    seen = []
    monkeypatch.setattr(binding, "install", lambda machine, methods=None: seen.append(methods))
    path = write(tmp_path, "a.bas", "10 END\n")
    assert main(["run", path, "--method", "5=paper", "--method", "2=newton"]) == 0
    assert seen == [{5: "paper", 2: "newton"}]
    assert main(["run", path]) == 0
    assert seen[-1] is None


def test_missing_file(tmp_path, capsys):
    assert main(["run", str(tmp_path / "nope.bas")]) == 1
    assert "nope.bas" in capsys.readouterr().err


def test_stop_reports_break(tmp_path, capsys):
    path = write(tmp_path, "a.bas", "10 PRINT 1\n20 STOP\n30 PRINT 2\n")
    assert main(["run", path]) == 0
    captured = capsys.readouterr()
    assert captured.err == "Break in 20\n" and "2" not in captured.out.split()


def test_python_dash_m_runs_and_never_shows_a_traceback(tmp_path):
    path = write(tmp_path, "a.bas", "10 PRINT 7\n20 GOSUB 20\n")
    result = subprocess.run([sys.executable, "-m", "yaseer", "run", path], capture_output=True, text=True,
                            timeout=60)
    assert result.returncode == 1
    assert result.stdout.split() == ["7"]
    assert result.stderr == "Out of memory in 20\n"


@pytest.mark.parametrize("junk", ["10 PRINT (((\n", "10 \x00\x01\n", "10 FOR\n", "10 DIM A(-1)\n"])
def test_garbage_gives_a_basic_error(tmp_path, capsys, junk):
    path = write(tmp_path, "a.bas", junk)
    assert main(["run", path]) == 1
    err = capsys.readouterr().err
    assert err.endswith("in 10\n") and "Traceback" not in err


PAPER_PROGRAM_5 = Path(__file__).resolve().parents[1] / "programs" / "prog5.bas"  # as printed

# Shaped like the paper's Example 1: the universal line and line 20 wrapped, a FOR
# over QQ from .1 in steps of 15, a virtual link through GOSUB PROG 5.
LISTING = """2 CLEAR: DIM F(46), M(11), R(19), H(24), A(53), L(20), T(25), W(10),
Z(5), C(14), U(4), D(6), E(6), X(11), Y(11), V(21), Q(4), N(3), I(11), P(4)
20 FOR QQ = .1 TO 360.1 STEP 15: X(10) = 3 * COS QQ: Y(10) = 3 *
SIN QQ: V(17) = 1: V(18) = 2: A(49) = 0: A(50) = 0: GOSUB
   PROG 5
60 PRINT QQ; T; L; D(5); D(6): NEXT QQ
70 END
"""


def test_listing_shaped_program_with_the_papers_program_5(tmp_path, capsys):
    import math

    listing = write(tmp_path, "example.bas", LISTING)
    area = str(PAPER_PROGRAM_5)
    assert main(["run", listing, "--prog", f"5={area}", "--format", "csv"]) == 0
    rows = [[float(x) for x in line.split(",")] for line in capsys.readouterr().out.splitlines()]
    qq, expected = 0.1, []
    while qq <= 360.1:
        x, y = 3 * math.cos(math.radians(qq)), 3 * math.sin(math.radians(qq))
        vx, vy = 1.0, 2.0
        length = math.hypot(x, y)
        angle = math.degrees(math.atan2(y, x)) % 360
        # independent: d|r|/dt = r.v/|r|, dtheta/dt = (r x v)/|r|^2
        expected.append([qq, angle, length, (x * vy - y * vx) / length ** 2, (x * vx + y * vy) / length])
        qq += 15
    assert len(rows) == len(expected) == 25
    for row, want in zip(rows, expected):
        assert row == pytest.approx(want, rel=1e-9, abs=1e-9)


def test_a_csv_row_is_a_printed_line(tmp_path):
    """Values printed by several PRINT statements on one screen line are one CSV row (one length per kind)."""
    import csv
    import subprocess
    import sys

    listing = tmp_path / "parts.bas"
    listing.write_text("10 FOR I = 1 TO 3\n20 PRINT I;\n30 IF I > 1 THEN PRINT I * 2;\n40 PRINT I * 3\n50 NEXT\n"
                       "60 PRINT 7, 8,\n70 PRINT 9;\n")
    text = subprocess.run([sys.executable, "-m", "yaseer", "run", str(listing)], capture_output=True, text=True,
                          check=True).stdout
    rows = subprocess.run([sys.executable, "-m", "yaseer", "run", str(listing), "--format", "csv"],
                          capture_output=True, text=True, check=True).stdout
    screen = [[float(word) for word in line.split()] for line in text.splitlines()]
    assert [[float(v) for v in row] for row in csv.reader(rows.splitlines())] == screen
    assert [len(row) for row in screen] == [2, 3, 3, 3]
