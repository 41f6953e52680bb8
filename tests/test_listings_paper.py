"""The paper's listings as printed (listings/paper/, programs/prog5.bas) under `yaseer run`.

Pinned here: which printed listing runs and which stops, with the error line the user
sees; for those that run, how far their numbers are from the corrected listing's (whose
every number tests/test_listings_golden.py checks against the real mechanisms).  The
reasons are in listings/ERRATA.md.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from listing_runs import ROOT, column_scale, csv_table, golden_csv, run_csv, run_yaseer

PRINTED_PROGRAM_5 = "5=programs/prog5.bas"


def test_example1_as_printed_runs_and_only_its_format_is_wrong():
    assert np.array_equal(run_csv("listings/paper/example1.bas"), run_csv("listings/example1.bas"))
    result = run_yaseer("listings/paper/example1.bas")
    assert result.returncode == 0, result.stderr
    # "###.###.##" is two fields, "###.###" and ".##", taken in turn (Microsoft BASIC):
    # QQ = 0.1 -> "  0.100"; Y(2) = 117.965 has no integer places -> "%117.97";
    # V(4) = 982.343 -> "982.343"; A(36) = 30137.30 -> "%30137.30".
    assert result.stdout.splitlines()[0] == "  0.100%117.97982.343%30137.30"
    assert len(result.stdout.splitlines()) == 25


def _pc_basic_first_line(tmp_path, program: str) -> str:
    """The first line PC-BASIC 2.0.8 (a GW-BASIC reimplementation) prints for ``program``."""
    import subprocess
    import sys

    source, output = tmp_path / "peer.bas", tmp_path / "peer.txt"
    source.write_text(program + "\n")
    subprocess.run([sys.executable, "-m", "pcbasic", "-n", "-q", str(source), f"-o={output}"],
                   check=True, timeout=60, capture_output=True)
    return output.read_text(errors="replace").splitlines()[0].rstrip("\r")


def test_example1s_printed_format_garbles_the_row_in_gw_basic_too(tmp_path):
    """PC-BASIC prints the first row the same way."""
    program = '10 PRINT USING "###.###.##"; .1; 117.9653; 982.3431; 30137.3'
    assert _pc_basic_first_line(tmp_path, program) == "  0.100%117.97982.343%30137.30"


def test_example2_as_printed_applies_the_previous_joint_force_at_the_plunger():
    printed, corrected = run_csv("listings/paper/example2.bas"), golden_csv(2)
    assert printed.shape == corrected.shape
    assert np.array_equal(printed[:, 0], corrected[:, 0])
    difference = np.abs(printed - corrected) / column_scale(corrected)
    # The first position has no previous joint force: the rows agree.
    assert difference[0].max() < 1e-12
    # From the second on, the stale F(7), F(8) move every force column (ERRATA: up to
    # 2.6, 3.7, 4.0 times each column's largest value).
    assert (difference[1:, 1:].max(axis=1) > 0.01).all()
    assert np.round(difference[:, 1:].max(axis=0), 1).tolist() == [2.6, 3.7, 4.0]


def test_example3_as_printed_runs_in_yaseer_with_overflowing_fields():
    """`FOR T(2) = ...` is accepted (GW-BASIC would not); numbers as corrected, format overflows."""
    assert np.array_equal(run_csv("listings/paper/example3.bas"), run_csv("listings/example3.bas"))
    lines = run_yaseer("listings/paper/example3.bas").stdout.splitlines()
    assert lines[4] == "  80.1 -37.1 -17.3%-1991.8  -4.3"
    assert lines[6] == " 120.1 -92.0 -42.52788.1  -1.4"


@pytest.mark.parametrize("n, line", [(4, 4080), (5, 5070)])
def test_examples_4_and_5_as_printed_are_syntax_errors(n, line):
    """`USING "...":QQ` (4080) and `USING"...";QQ: U(2): ...` (5070): nothing is printed."""
    result = run_yaseer(f"listings/paper/example{n}.bas")
    assert result.returncode == 1
    assert result.stdout == ""
    assert result.stderr.strip() == f"Syntax error in {line}"


def _polar_motion():
    """A point moving in polar form: L = 2, L' = .3, L'' = -.5, T = 30 deg, T' = 1.2, T'' = .7.

    Returns (X, Y, X', Y', X'', Y'') from the polar kinematics, written independently of
    Program 5: r = L u(T), r' = L' u + L T' u_perp, r'' = (L'' - L T'^2) u + (L T'' + 2 L' T') u_perp.
    """
    length, rate, accel = 2.0, 0.3, -0.5
    theta, omega, alpha = math.radians(30), 1.2, 0.7
    u = (math.cos(theta), math.sin(theta))
    perp = (-u[1], u[0])
    radial, transverse = accel - length * omega ** 2, length * alpha + 2 * rate * omega
    return (length * u[0], length * u[1],
            rate * u[0] + length * omega * perp[0], rate * u[1] + length * omega * perp[1],
            radial * u[0] + transverse * perp[0], radial * u[1] + transverse * perp[1])


def _virtual_link_listing(tmp_path):
    x, y, vx, vy, ax, ay = _polar_motion()
    listing = tmp_path / "virtual_link.bas"
    listing.write_text(
        f"10 X(10) = {x!r}: Y(10) = {y!r}: V(17) = {vx!r}: V(18) = {vy!r}\n"
        f"20 A(49) = {ax!r}: A(50) = {ay!r}: GOSUB PROG 5\n"
        "30 PRINT T; L; D(5); E(5); D(6); E(6)\n")
    return str(listing)


def test_printed_program5_keeps_the_slip_of_line_60(tmp_path):
    """Line 60 drops L from the E(5) term of eq. (4): E(6) is off by (L - 1) E(5) cos T / sin T."""
    listing = _virtual_link_listing(tmp_path)
    printed = csv_table(run_yaseer(listing, "--format", "csv", "--prog", PRINTED_PROGRAM_5).stdout)[0]
    exact = [30.0, 2.0, 1.2, 0.7, 0.3, -0.5]
    assert np.allclose(printed[:5], exact[:5], rtol=1e-12, atol=1e-12)
    slip = (2.0 - 1) * 0.7 * math.cos(math.radians(30)) / math.sin(math.radians(30))
    assert printed[5] == pytest.approx(-0.5 + slip, rel=1e-12)
    default = csv_table(run_yaseer(listing, "--format", "csv").stdout)[0]
    assert np.allclose(default, exact, rtol=1e-12, atol=1e-12)


def test_printed_program5_divides_by_zero_on_the_y_axis(tmp_path):
    listing = tmp_path / "on_axis.bas"
    listing.write_text("10 X(10) = 0: Y(10) = 1: GOSUB PROG 5\n20 PRINT T; L\n")
    result = run_yaseer(str(listing), "--prog", PRINTED_PROGRAM_5)
    assert result.returncode == 1
    assert result.stderr.strip() == "Division by zero in 10 (PROG 5)"
    assert run_yaseer(str(listing)).stdout.split() == ["90", "1"]


@pytest.mark.parametrize(
    "n, columns, worst",
    [(1, ["A(36)"], [4.7]), (3, ["A(4)"], [0.6]), (4, ["A(6)", "A(39)"], [23.5, 24.1])],
)
def test_printed_program5_moves_only_the_accelerations(n, columns, worst):
    """Corrected listings with the printed Program 5: positions and velocities as before,
    accelerations off by `worst` times each column's largest value (the line-60 slip,
    amplified where sin T is small)."""
    corrected = golden_csv(n)
    printed = run_csv(f"listings/example{n}.bas", "--prog", PRINTED_PROGRAM_5)
    difference = np.abs(printed - corrected) / column_scale(corrected)
    names = {1: ["QQ", "Y(2)", "V(4)", "A(36)"], 3: ["T(2)", "T(9)", "W(4)", "A(4)", "X(7)"],
             4: ["QQ", "W(6)", "A(6)", "V(7)", "A(39)"]}[n]
    for index, name in enumerate(names):
        if name in columns:
            assert round(difference[:, index].max(), 1) == worst[columns.index(name)], name
        else:
            assert difference[:, index].max() < 1e-12, name


def test_printed_program5_leaves_the_massless_example2_unchanged():
    """Example 2 neglects all masses: its forces need no acceleration, so E(6) cannot matter."""
    printed = run_csv("listings/example2.bas", "--prog", PRINTED_PROGRAM_5)
    corrected = golden_csv(2)
    assert np.all(np.abs(printed - corrected) <= 1e-12 * column_scale(corrected))


def test_every_paper_file_is_a_transcription_with_numbered_lines():
    for path in sorted((ROOT / "listings" / "paper").glob("*.bas")) + [ROOT / "programs" / "prog5.bas"]:
        for line in path.read_text().splitlines():
            assert line.split()[0].isdigit(), (path.name, line)
            assert "$" not in line and "\\text" not in line, (path.name, line)


def _paper_with_lines_from_corrected(tmp_path, n, line_numbers):
    """The printed listing n with only the given lines replaced by the corrected listing's."""
    corrected = {line.split()[0]: line for line in (ROOT / "listings" / f"example{n}.bas").read_text().splitlines()}
    printed = (ROOT / "listings" / "paper" / f"example{n}.bas").read_text().splitlines()
    lines = [corrected[line.split()[0]] if int(line.split()[0]) in line_numbers else line for line in printed]
    path = tmp_path / f"paper{n}_repaired.bas"
    path.write_text("\n".join(lines) + "\n")
    return str(path)


def test_example4_with_its_syntax_repaired_prints_the_corrected_numbers(tmp_path):
    listing = _paper_with_lines_from_corrected(tmp_path, 4, {4080})
    assert np.array_equal(run_csv(listing), run_csv("listings/example4.bas"))


def test_example5_with_only_its_syntax_repaired_misses_the_crushing_load(tmp_path):
    """Without GOSUB 5200 the call at 5030 solves AoABBo again: T(14), W(7) are the rear
    toggle's, the crushing force hardly acts, and torque and reactions are off by about
    their whole size (the real reaction at Bo peaks near 398 kN; here it stays under 400 N)."""
    printed = run_csv(_paper_with_lines_from_corrected(tmp_path, 5, {5070}))
    corrected = golden_csv(5)
    assert corrected[:, 2].max() > 390_000
    assert printed[:, 2].max() < 400
    difference = np.abs(printed - corrected) / column_scale(corrected)
    assert (difference[:, 1:].max(axis=0) > 0.9).all()  # measured 1.02, 1.00, 0.955


@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_the_papers_equations_without_the_slip_give_the_corrected_numbers(n):
    """`--method 5=paper` evaluates equations (1)-(4) as printed in the text (with the L that
    line 60 drops). At the listings' angles, kept off 0/90/180/270 deg by the .1 offsets,
    their divisions by cos T and sin T cost under 1e-8 of each column's size: the slip of
    line 60, not the singularities, is what moves the printed Program 5's numbers."""
    corrected = golden_csv(n)
    paper = run_csv(f"listings/example{n}.bas", "--method", "5=paper")
    assert np.all(np.abs(paper - corrected) <= 1e-8 * column_scale(corrected))


def test_the_printed_crushing_direction_would_drive_the_jaw(tmp_path):
    """Line 5050's `T(14) + 90` against the corrected `T(14) - 90`, at QQ = 120.1.

    Only the load's direction differs, so by the power balance the crank torques differ by
    (U_printed - U_corrected) * omega = -2 * (power of the load in the printed direction).
    That power comes from the reference model (velocity of P on the real jaw): it is positive,
    about 21 kW, i.e. the printed load drives the closing jaw and the crank has to brake."""
    from yaseer.reference.paper_mechanisms import crushing_force, example_snapshots

    text = (ROOT / "listings" / "example5.bas").read_text()
    assert "T = T(14) - 90" in text
    listing = tmp_path / "printed_direction.bas"
    listing.write_text(text.replace("T = T(14) - 90", "T = T(14) + 90"))
    printed, corrected = run_csv(str(listing)), golden_csv(5)
    row = int(np.argmin(np.abs(corrected[:, 0] - 120.1)))

    (state,) = example_snapshots(5, [120.1])
    t14 = float(state.direction("jaw DoD", "D", "Do"))
    force = float(crushing_force(t14, float(state.omega("jaw DoD"))))
    velocity = [float(v) for v in state.velocity("jaw DoD", "P")]
    direction = (math.cos(math.radians(t14 + 90)), math.sin(math.radians(t14 + 90)))
    power = force * (direction[0] * velocity[0] + direction[1] * velocity[1])
    assert power > 20_000
    omega = -22.0
    assert (printed[row, 1] - corrected[row, 1]) * omega == pytest.approx(-2 * power, rel=1e-9)
    assert printed[row, 1] > 0 > corrected[row, 1]


@pytest.mark.parametrize(
    "program, first_line",
    [
        ("10 FOR A(1) = 1 TO 2: NEXT A(1)", "Syntax error in 10"),  # Example 3, line 3030
        ('10 PRINT USING "#####.#":1; 2', "Syntax error in 10"),  # Example 4, line 4080
        ("10 A = 3: B = 4: PRINT SQR(A^2 = B^2)", " 0 "),  # Example 5, line 5070: a silent 0
    ],
)
def test_the_errata_claims_about_microsoft_basic_hold_in_pc_basic(tmp_path, program, first_line):
    assert _pc_basic_first_line(tmp_path, program).startswith(first_line)
