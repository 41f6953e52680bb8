"""Seed 003 (the Fortran four-bar of Oke et al.): which formulas made the printed table.

The printed program is re-evaluated here exactly as printed (``fortran_row``), and an
independent solution (circle intersection for the position, finite differences in the
crank angle for the rates) gives the correct values.  The tests show that the printed
formulas reproduce the printed columns (the wrong ones included) and where and why
those columns differ from the correct ones.  Angles: Fortran's PHI is the angle of
D->C, BETA of B->C, THET of A->B, all from +x, counter-clockwise; rates in rad/s.
"""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import pytest

from yaseer.commands.diff import parse_table

DATA = Path(__file__).resolve().parent.parent / "yaseer" / "data"
A, B, C, D = 30.0, 36.0, 36.0, 60.0
VELA = 10.0          # crank angular velocity, rad/s
ACCA = 30.0          # crank angular acceleration, rad/s^2 (deduced below)
THETAS_DEG = [0, 30, 60, 90, 270, 300, 330]  # 120..240 cannot be assembled


def fortran_row(thet: float, branch: int, *, vel_undefined=0.0, acca=ACCA, as_printed=True) -> dict:
    """One row of the printed Fortran program, statement by statement.

    ``as_printed`` keeps the printed statements: ``SIN(BET(I)-(I))`` (I is the
    integer loop index, so the angle loses 1 or 2 *radians*), ``VEL`` (an undefined
    variable, zero) for ``VELA`` in C2, and ``B1 - B2 - B3/B4``.  ``branch`` is I (1, 2).
    """
    ak = (A * A - B * B + C * C + D * D) * 0.5
    aa = ak - A * (D - C) * math.cos(thet) - C * D
    bb = -2.0 * A * C * math.sin(thet)
    cc = ak - A * (D + C) * math.cos(thet) + C * D
    disc = bb ** 2 - 4 * aa * cc
    if disc < 0:
        return None
    ph = -bb + math.sqrt(disc) if branch == 1 else -bb - math.sqrt(disc)
    phi = math.atan(ph * 0.5 / aa) * 2
    bet = math.asin((C * math.sin(phi) - A * math.sin(thet)) / B)
    velc = A * VELA * math.sin(bet - thet) / (C * math.sin(bet - phi))
    velb_angle = bet - branch if as_printed else bet - phi
    velb = A * VELA * math.sin(phi - thet) / (B * math.sin(velb_angle))
    vel = vel_undefined if as_printed else VELA
    c1 = A * acca * math.sin(bet - thet)
    c2 = A * vel ** 2 * math.cos(bet - thet) + B * velb ** 2
    c3 = C * velc ** 2 * math.cos(phi - bet)
    c4 = C * math.sin(bet - phi)
    accc = (c1 - c2 + c3) / c4
    b1 = A * acca * math.sin(phi - thet)
    b2 = A * VELA ** 2 * math.cos(phi - thet)
    b3 = B * velb ** 2 * math.cos(phi - bet) - C * velc ** 2
    b4 = B * math.sin(bet - phi)
    accb = b1 - b2 - b3 / b4 if as_printed else (b1 - b2 - b3) / b4
    return dict(thet=math.degrees(thet), phi=math.degrees(phi), beta=math.degrees(bet),
                velc=velc, velb=velb, accc=accc, accb=accb)


def fortran_table(**options) -> list[dict]:
    rows = []
    for deg in range(0, 360, 30):
        for branch in (1, 2):
            row = fortran_row(math.radians(deg), branch, **options)
            if row is not None:
                rows.append(row)
    return rows


# ------------------------------------------------------------ independent model

def coupler_point(theta: float, right_of_bd: bool) -> tuple[float, float]:
    """C = intersection of the circles (B, b) and (D, c); B = a u(theta), D = (d, 0).

    ``right_of_bd``: C on the right of the directed line B->D."""
    bx, by = A * math.cos(theta), A * math.sin(theta)
    dx, dy = D - bx, -by
    dist = math.hypot(dx, dy)
    along = (B * B - C * C + dist * dist) / (2 * dist)
    across = math.sqrt(B * B - along * along)
    ux, uy = dx / dist, dy / dist
    sign = -1.0 if right_of_bd else 1.0
    return bx + along * ux - sign * across * uy, by + along * uy + sign * across * ux


def angles(theta: float, right: bool) -> tuple[float, float]:
    """(beta, phi) in radians: directions of B->C and D->C."""
    cx, cy = coupler_point(theta, right)
    return (math.atan2(cy - A * math.sin(theta), cx - A * math.cos(theta)), math.atan2(cy, cx - D))


def _unwrap(x: float) -> float:
    return (x + math.pi) % (2 * math.pi) - math.pi


def correct_rates(theta: float, right: bool, h=1e-4) -> dict:
    """omega and alpha of BC (beta) and DC (phi) by central differences in theta."""
    minus, mid, plus = angles(theta - h, right), angles(theta, right), angles(theta + h, right)
    out = {}
    for k, name in ((0, "b"), (1, "c")):
        first = _unwrap(plus[k] - minus[k]) / (2 * h)
        second = (_unwrap(plus[k] - mid[k]) - _unwrap(mid[k] - minus[k])) / h ** 2
        out["vel" + name] = first * VELA
        out["acc" + name] = second * VELA ** 2 + first * ACCA
    out["beta"], out["phi"] = (math.degrees(x) for x in mid)
    return out


def _printed() -> list:
    return parse_table((DATA / "seed003_printed.txt").read_text()).rows


def _scan() -> str:
    return (DATA / "seed003_scan.txt").read_text()


COLUMNS = ["thet", "phi", "beta", "velc", "velb", "accc", "accb"]


# ------------------------------------------------------------------ tests

def test_the_program_prints_fourteen_rows_and_skips_120_to_240():
    rows = fortran_table()
    assert [round(r["thet"]) for r in rows[::2]] == THETAS_DEG
    assert len(rows) == len(_printed()) == 14


def test_upper_row_of_each_angle_is_the_crossed_branch():
    """Fortran's I=1 puts C right of B->D (crossed); I=2 left (uncrossed)."""
    for row_1, row_2 in zip(fortran_table()[::2], fortran_table()[1::2]):
        theta = math.radians(row_1["thet"])
        assert math.degrees(angles(theta, True)[1]) == pytest.approx(row_1["phi"], abs=1e-9)
        assert math.degrees(angles(theta, False)[1]) == pytest.approx(row_2["phi"], abs=1e-9)


@pytest.mark.parametrize("column", ["phi", "beta", "velc"])
def test_positions_and_velc_reproduce_the_printed_cells(column):
    j = COLUMNS.index(column)
    compared = 0
    for printed, computed in zip(_printed(), fortran_table()):
        if printed[j].value is not None:
            assert computed[column] == pytest.approx(printed[j].value, abs=0.005)
            compared += 1
    assert compared >= 2


def test_acca_is_30_from_the_first_two_printed_accc():
    """ACCC is linear in ACCA: solve the two theta=0 rows for it (and for VEL**2)."""
    printed = [_printed()[k][5].value for k in (0, 1)]
    base = [fortran_row(0.0, i, acca=0.0)["accc"] for i in (1, 2)]
    slope = [fortran_row(0.0, i, acca=1.0)["accc"] - b for i, b in zip((1, 2), base)]
    assert slope[0] == pytest.approx(slope[1])  # both rows: d ACCC / d ACCA = -1 at theta 0
    acca = ((printed[0] - base[0]) + (printed[1] - base[1])) / (2 * slope[0])
    assert acca == pytest.approx(30.0, abs=0.1)


def test_printed_accc_needs_vel_zero_and_the_radian_slip():
    """All legible ACCC cells come from the printed statements (VEL=0, SIN(BET-(I)));
    the OCR keeps one decimal (truncated), and reads two 9s as 6s."""
    ocr_nines = {9: "169.6", 10: "-23.6"}
    printed_rows, computed = _printed(), fortran_table()
    for k, (printed, row) in enumerate(zip(printed_rows, computed)):
        cell = printed[5]
        if cell.value is None:
            continue
        text = f"{row['accc']:.2f}"
        if k in ocr_nines:
            assert text[-2] == "9" and text[:-2] + "6" == ocr_nines[k]
        else:
            assert text[:-1] == cell.text
    for wrong in (dict(vel_undefined=VELA), dict(as_printed=False)):
        rows = fortran_table(**wrong)
        assert abs(rows[0]["accc"] - printed_rows[0][5].value) > 1.0


def _ocr_fractions(label: str, column: int) -> list[str]:
    """The fractional parts of one OCR'd column of the plate, in scan order."""
    block = _scan().split(label, 1)[1].split(r"\end{array}", 1)[0]
    cells = [part.split("&")[column].strip() for part in block.split(r"\\") if "&" in part]
    fractions = ["." + c.split(".")[-1][-2:] if "." in c else "." + c[-2:] for c in cells if c]
    return fractions


def _is_subsequence(short: list, long: list) -> bool:
    remaining = iter(long)
    return all(item in remaining for item in short)


def test_printed_velb_comes_from_sin_bet_minus_i_radians():
    """The VELB fractions in the scan follow the printed SIN(BET(I)-(I)), not BET-PHI.

    The OCR column has 15 fragments for 14 rows (it repeats some, and loses the two
    30-degree rows); the other 12 printed-formula values appear in it in order."""
    ocr = _ocr_fractions("LB & ACCC", 0)
    assert len(ocr) == 15

    def fractions(rows):
        return ["." + f"{abs(r['velb']):.2f}".split(".")[-1] for r in rows]

    lost = {2, 3}
    printed_formula = fractions(fortran_table())
    assert _is_subsequence([f for k, f in enumerate(printed_formula) if k not in lost], ocr)
    correct = fractions(fortran_table(as_printed=False))
    assert not _is_subsequence([f for k, f in enumerate(correct) if k not in lost], ocr)


def test_printed_velc_is_the_correct_omega_of_dc_but_equation_xxi_has_the_wrong_sign():
    for row in fortran_table():
        theta = math.radians(row["thet"])
        right = row is not None and abs(math.degrees(angles(theta, True)[1]) - row["phi"]) < 1e-6
        ref = correct_rates(theta, right)
        assert row["velc"] == pytest.approx(ref["velc"], abs=1e-5)
        beta, phi = math.radians(row["beta"]), math.radians(row["phi"])
        paper_xxi = -A * VELA * math.sin(theta - beta) / (C * math.sin(phi - beta))
        assert paper_xxi == pytest.approx(-ref["velc"], abs=1e-5)


def _rows_with_reference():
    for row in fortran_table():
        theta = math.radians(row["thet"])
        right = abs(math.degrees(angles(theta, True)[1]) - row["phi"]) < 1e-6
        yield row, correct_rates(theta, right), fortran_row(theta, 1 if right else 2, as_printed=False)


def test_printed_velb_accc_accb_differ_from_the_correct_values():
    """Everywhere, except VELB of the lower 0-degree row: there sin(BET - 2 rad)
    happens to equal sin(BET - PHI) (65.38 deg - 114.59 deg vs 65.38 - 114.62)."""
    for k, (printed, ref, _) in enumerate(_rows_with_reference()):
        if k == 1:
            assert printed["velb"] == pytest.approx(ref["velb"], abs=0.01)
        else:
            assert abs(printed["velb"] - ref["velb"]) > 0.05  # visible at two decimals
        assert abs(printed["accc"] - ref["accc"]) > 1.0
        assert abs(printed["accb"] - ref["accb"]) > 1.0


def test_the_corrected_statements_give_the_correct_values():
    """VELA for VEL, BET-PHI for BET-(I), (B1-B2-B3)/B4 for B1-B2-B3/B4."""
    for _, ref, fixed in _rows_with_reference():
        for name in ("velc", "velb", "accc", "accb"):
            assert fixed[name] == pytest.approx(ref[name], rel=1e-5, abs=1e-4)


def test_precedence_alone_spoils_accb():
    """With VELB and VEL corrected, B1 - B2 - B3/B4 is still wrong by (B1-B2)(1-1/B4) - ..."""
    for _, ref, fixed in _rows_with_reference():
        theta, beta, phi = (math.radians(fixed[k]) for k in ("thet", "beta", "phi"))
        b1 = A * ACCA * math.sin(phi - theta)
        b2 = A * VELA ** 2 * math.cos(phi - theta)
        b3 = B * fixed["velb"] ** 2 * math.cos(phi - beta) - C * fixed["velc"] ** 2
        b4 = B * math.sin(beta - phi)
        assert (b1 - b2 - b3) / b4 == pytest.approx(ref["accb"], rel=1e-5, abs=1e-4)
        assert abs((b1 - b2 - b3 / b4) - ref["accb"]) > 10.0


# ------------------------------------------------------------ the listing


LISTING = Path(__file__).resolve().parent.parent / "listings" / "fortran_fourbar.bas"


@pytest.fixture(scope="module")
def listing_rows() -> list[list[float]]:
    from yaseer.commands.diff import csv_number_rows
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(LISTING), "--format", "csv"],
                          capture_output=True, text=True, check=True)
    return csv_number_rows(done.stdout)


def test_listing_prints_the_correct_values_for_both_branches(listing_rows):
    """THET, PHI, BETA, VELC, VELB, ACCC, ACCB against the independent model."""
    assert [row[0] for row in listing_rows] == [t for t in THETAS_DEG for _ in (1, 2)]
    for row, (_, ref, _) in zip(listing_rows, _rows_with_reference()):
        theta, phi, beta, velc, velb, accc, accb = row
        assert (phi, beta) == pytest.approx((ref["phi"], ref["beta"]), abs=1e-9)
        assert (velc, velb) == pytest.approx((ref["velc"], ref["velb"]), abs=1e-5)
        assert (accc, accb) == pytest.approx((ref["accc"], ref["accb"]), abs=1e-3)


def test_diff_against_the_printed_table_flags_exactly_the_accc_cells(listing_rows):
    from yaseer.commands.diff import compare
    verdict = compare(listing_rows, parse_table((DATA / "seed003_printed.txt").read_text()), tol=0.1)
    assert verdict.matched_rows == 14 and verdict.missing_rows == 0 and verdict.extra_rows == 0
    flagged = [line for line in verdict.lines if "!" in line]
    assert len(flagged) == verdict.differing_cells == 13
    assert all(line.count("!") == 1 for line in flagged)  # one cell per row: ACCC


def test_cli_diff_exit_status_is_one(tmp_path):
    done = subprocess.run([sys.executable, "-m", "yaseer", "diff", str(LISTING), str(DATA / "seed003_printed.txt"),
                           "--tol", "0.1"], capture_output=True, text=True)
    assert done.returncode == 1
    assert done.stdout.strip().splitlines()[-1].startswith("DIFFER: 14 rows matched, 13 of 53 compared cells differ beyond tol 0.1; 45 program values not compared")


def test_printed_velb_sign_is_wrong_in_every_upper_row_and_right_in_every_lower_row():
    for k, (printed, ref, _) in enumerate(_rows_with_reference()):
        same_sign = printed["velb"] * ref["velb"] > 0
        assert same_sign == (k % 2 == 1)


def test_printed_formulas_stop_with_the_untrapped_error_instead_of_losing_rows():
    """With the formulas as printed, a position that cannot be assembled gives NaN (Overflow),
    which the listing's handler (ERR = 5 only) does not trap: its ON ERROR GOTO 0 stops the run
    with that error and status 1, after the rows up to 90 degrees (GW-BASIC's rule, issue 12)."""
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(LISTING), "--method", "2=half-angle-printed"],
                          capture_output=True, text=True)
    assert done.returncode == 1
    assert done.stderr.strip().splitlines()[-1] == "Overflow (PROG 2) in 170"
    thetas = [line.split()[0] for line in done.stdout.splitlines()[1:] if len(line.split()) == 7]
    assert thetas == ["0.00", "30.00", "60.00", "90.00"]
