"""yaseer bench: the reference, the error measure, the ways of running and the command.

The reference values are checked against closed forms written out here in
mpmath (tests/test_methods.py), and every reported error against an error
computed here from scratch (mpmath, the same definition).
"""

import csv
import math

import mpmath
import numpy as np
import pytest

import yaseer.linkages.methods  # noqa: F401
from yaseer.evaluation import cases, ways
from yaseer.evaluation.measure import ReferenceColumn, worst_error
from yaseer.evaluation.virtual_link_reference import virtual_link_reference
from test_methods import mp_fourbar, mp_slider

SEED001_ANGLES = np.array([-170.0, -30.0, 0.5, 95.0, 181.0, 300.0])
SEED003_ANGLES = np.array([-95.0, -40.0, 0.0, 55.0, 100.0])


# --------------------------------------------------------------------------- the reference

@mpmath.workdps(50)
def test_seed001_reference_matches_closed_form():
    reference = cases.SEED001.reference(SEED001_ANGLES)
    for k, theta in enumerate(SEED001_ANGLES):
        closed = mp_slider(-2.0, 3.0, 8.0, theta, -15.0, -10.0, 0.0)
        for column, value in zip(reference, closed):
            got = mpmath.mpf(column.hi[k]) + mpmath.mpf(column.lo[k])
            assert abs(got - value) <= mpmath.mpf(10) ** -28 * max(1, abs(value)), column.name


@pytest.mark.parametrize("case,crossed", [(cases.SEED003_UNCROSSED, False), (cases.SEED003_CROSSED, True)])
@mpmath.workdps(50)
def test_seed003_reference_matches_closed_form(case, crossed):
    reference = case.reference(SEED003_ANGLES)
    for k, theta in enumerate(SEED003_ANGLES):
        closed = mp_fourbar(60.0, 30.0, 36.0, 36.0, theta, 10.0, 0.0, crossed)
        for column, value in zip(reference, closed):
            got = mpmath.mpf(column.hi[k]) + mpmath.mpf(column.lo[k])
            assert abs(got - value) <= mpmath.mpf(10) ** -28 * max(1, abs(value)), column.name


def polar_closed_form(x, y, vx, vy, ax, ay):
    """T (deg), L and rates of the point's polar coordinates, by the textbook formulas (50 digits)."""
    x, y, vx, vy, ax, ay = (mpmath.mpf(v) for v in (x, y, vx, vy, ax, ay))
    length = mpmath.sqrt(x * x + y * y)
    length_rate = (x * vx + y * vy) / length
    angle_rate = (x * vy - y * vx) / length**2
    length_accel = (x * ax + y * ay) / length + length * angle_rate**2
    angle_accel = ((x * ay - y * ax) / length - 2 * length_rate * angle_rate) / length
    angle = mpmath.degrees(mpmath.atan2(y, x)) % 360
    return {"T": angle, "L": length, "D(5)": angle_rate, "E(5)": angle_accel, "D(6)": length_rate,
            "E(6)": length_accel}


@pytest.mark.parametrize("point", [(3.0, 4.0, 1.0, 2.0, 5.0, -1.0), (-100.0, 0.0, 3.0, -4.0, -50.0, 20.0),
                                   (-7.0, -1e-9, 0.5, 0.25, 2.0, 3.0), (0.0, 2.0, -1.0, 0.0, 0.0, 4.0)])
@mpmath.workdps(50)
def test_virtual_link_reference_matches_polar_closed_form(point):
    reference = virtual_link_reference(*point)
    expected = polar_closed_form(*point)
    for name, value in expected.items():
        assert abs(reference[name] - value) <= mpmath.mpf(10) ** -40 * max(1, abs(value)), name


# --------------------------------------------------------------------------- the error measure

def test_angle_errors_wrap_and_are_in_radians():
    column = ReferenceColumn.from_mpf("T", [mpmath.mpf("179.9999"), mpmath.mpf(0)], angle=True)
    errors = column.errors([-179.9999, 359.999])
    assert errors[0] == pytest.approx(math.radians(0.0002), rel=1e-9)
    assert errors[1] == pytest.approx(math.radians(0.001), rel=1e-9)


def test_value_errors_are_relative_to_the_largest_reference():
    column = ReferenceColumn.from_mpf("V", [mpmath.mpf(-4), mpmath.mpf("0.5")])
    assert list(column.errors([-4.0, 0.5 + 1e-3])) == pytest.approx([0.0, 1e-3 / 4], rel=1e-12)


@mpmath.workdps(50)
def test_reference_keeps_digits_below_float():
    """hi + lo carries the reference beyond float: the error of float(1/3) is seen."""
    third = mpmath.mpf(1) / 3
    column = ReferenceColumn.from_mpf("x", [third])
    assert column.lo[0] != 0.0
    assert column.errors([float(third)])[0] == pytest.approx(abs(float(mpmath.mpf(float(third)) - third)), rel=1e-6)


# --------------------------------------------------------------------------- reported errors = independent errors

@mpmath.workdps(50)
def independent_worst(values: dict, names, angle_names, closed_rows) -> float:
    """The worst error by the bench's definition, computed in mpmath from scratch."""
    worst = mpmath.mpf(0)
    for j, name in enumerate(names):
        reference = [row[j] for row in closed_rows]
        scale = 1 if name in angle_names else max(abs(r) for r in reference)
        for value, ref in zip(values[name], reference):
            difference = mpmath.mpf(float(value)) - ref
            if name in angle_names:
                difference = mpmath.radians((difference + 180) % 360 - 180)
            worst = max(worst, abs(difference) / scale)
    return float(worst)


@pytest.mark.parametrize("method,options", [("closed", {}), ("pseudographic", {}), ("newton", {}),
                                            ("newton", {"tol": 1e-2})])
def test_reported_slider_error_is_the_independent_error(method, options):
    case = cases.SEED001
    run = ways.run_python(case, method, SEED001_ANGLES, "array", options, repeat=1)
    values = case.compute({"slider_crank": method}, SEED001_ANGLES, options)
    closed = [mp_slider(-2.0, 3.0, 8.0, theta, -15.0, -10.0, 0.0) for theta in SEED001_ANGLES]
    expected = independent_worst(values, case.columns, case.angle_columns, closed)
    assert run.outcome.status == "ok"
    assert run.outcome.worst == pytest.approx(expected, rel=1e-6)


@pytest.mark.parametrize("method", ["closed", "half-angle", "half-angle-printed", "newton"])
def test_reported_fourbar_error_is_the_independent_error(method):
    case = cases.SEED003_CROSSED
    run = ways.run_python(case, method, SEED003_ANGLES, "per position", repeat=1)
    values = case.compute({"fourbar": method}, SEED003_ANGLES, {})
    closed = [mp_fourbar(60.0, 30.0, 36.0, 36.0, theta, 10.0, 0.0, True) for theta in SEED003_ANGLES]
    expected = independent_worst(values, case.columns, case.angle_columns, closed)
    assert run.outcome.worst == pytest.approx(expected, rel=1e-6)


def test_newton_error_follows_its_tolerance():
    loose = ways.run_python(cases.SEED001, "newton", SEED001_ANGLES, "array", {"tol": 1e-1}, repeat=1)
    tight = ways.run_python(cases.SEED001, "newton", SEED001_ANGLES, "array", {"tol": 1e-12}, repeat=1)
    assert loose.outcome.worst > 1e-6 > 1e-13 > tight.outcome.worst


def test_a_failing_method_is_reported_not_raised():
    """Seed 003 beyond its crank limit: every way reports the exception."""
    run = ways.run_python(cases.SEED003_UNCROSSED, "half-angle", np.array([0.0, 150.0]), "array", repeat=1)
    assert run.outcome.status == "exception" and "assembled" in run.outcome.detail or "meet" in run.outcome.detail


def test_wrong_branch_is_recognised():
    """Values of the other assembly mode, finite and loop-closing, are "wrong branch"."""
    case = cases.SEED003_UNCROSSED
    other = cases.SEED003_CROSSED.compute({"fourbar": "closed"}, SEED003_ANGLES[:3], {})
    from yaseer.evaluation.measure import outcome_of

    outcome = outcome_of(case.reference(SEED003_ANGLES[:3]), other,
                         lambda r: case.other_branch(SEED003_ANGLES[:3], r))
    assert outcome.status == "wrong branch"


def test_paper_example_chain_agrees_with_the_reference():
    """Example 4's chain (PROG 2, 5, 2) in Python against the multibody reference."""
    case = [c for c in cases.paper_cases() if c.name.startswith("paper Example 4") and c.linkage == "fourbar"][0]
    run = ways.run_python(case, "newton", case.quick[:6], "array", repeat=1)
    assert run.outcome.status == "ok" and run.outcome.worst < 1e-12


# --------------------------------------------------------------------------- the listing way and the command

def test_listing_way_through_the_interpreter():
    run = ways.run_listing(cases.SEED001, "pseudographic", cases.SEED001.quick)
    assert run.positions == len(cases.SEED001.quick)
    assert run.outcome.status == "ok" and run.outcome.worst < 1e-13


def test_bench_command_quick(tmp_path, capsys):
    from yaseer.cli import main

    assert main(["bench", "--quick", "--case", "seed 00", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "pseudographic" in out and "half-angle-printed" in out and "Laziness" in out
    with open(tmp_path / "bench.csv") as handle:
        rows = list(csv.DictReader(handle))
    methods = {(r["linkage"], r["method"]) for r in rows}
    assert {("slider_crank", "pseudographic"), ("fourbar", "half-angle"), ("fourbar", "half-angle-printed"),
            ("slider_crank", "newton"), ("fourbar", "newton tol=0.001")} <= methods
    assert {r["case"] for r in rows} == {"seed 001 slider-crank", "seed 003 four-bar, uncrossed",
                                         "seed 003 four-bar, crossed", "seed 004 change-point four-bar"}
    assert all(r["status"] == "ok" for r in rows if not r["method"].startswith("newton tol=0.1"))
    assert {r["way"] for r in rows} == {"listing", "listing (decimal)", "per position", "array"}
    with open(tmp_path / "bench_laziness.csv") as handle:
        levels = {r["level"] for r in csv.DictReader(handle)}
    assert levels == {"positions", "+ velocities and accelerations", "+ forces"}
    for name in ("bench.png", "bench.svg", "bench_summary.csv", "bench_newton.csv", "bench_results.md"):
        assert (tmp_path / name).stat().st_size > 0


def test_yaseer_run_selects_the_methods_by_name(tmp_path, capsys):
    """``--method 2=NAME`` reaches the alternative methods; a position that cannot be
    assembled is a BASIC error naming the program and the line, whatever the method."""
    from yaseer.cli import main

    listing = tmp_path / "fourbar.bas"
    listing.write_text(cases.SEED003_CROSSED.listing(np.array([0.0, 30.0])))
    results = {}
    for method in ("closed", "half-angle", "half-angle-printed", "newton"):
        assert main(["run", str(listing), "--format", "csv", "--method", f"2={method}"]) == 0
        results[method] = capsys.readouterr().out
    rows = {m: [[float(v) for v in line.split(",")] for line in out.split()] for m, out in results.items()}
    for method in ("half-angle", "half-angle-printed", "newton"):
        assert np.allclose(rows[method], rows["closed"], rtol=1e-12, atol=1e-12)
    bad = tmp_path / "bad.bas"
    bad.write_text(cases.SEED003_CROSSED.listing(np.array([150.0])))
    for method in ("half-angle", "newton"):
        assert main(["run", str(bad), "--method", f"2={method}"]) == 1
        error = capsys.readouterr().err
        assert "cannot" in error and "(PROG 2) in 20" in error


@pytest.mark.parametrize("method", ["polar", "paper"])
def test_reported_virtual_link_error_is_the_independent_error(method):
    case = cases.ELLIPSE_CASE
    angles = case.quick
    run = ways.run_python(case, method, angles, "array", repeat=1)
    values = case.compute({"virtual_link": method}, angles, {})
    points = np.array(cases.ellipse_point(angles)).T
    with mpmath.workdps(50):
        closed = [[polar_closed_form(*p)[name] for name in case.columns] for p in points]
    expected = independent_worst(values, case.columns, case.angle_columns, closed)
    assert run.outcome.worst == pytest.approx(expected, rel=1e-6)


def test_example5_forces_chain_agrees_with_the_reference():
    """Example 5's chain with forces (PROG 2, 5, 2 with the crushing load, 2 with the joint force)."""
    case = [c for c in cases.paper_cases() if c.name.startswith("paper Example 5") and c.linkage == "fourbar"][0]
    run = ways.run_python(case, "half-angle", case.quick[:5], "array", repeat=1)
    assert run.outcome.status == "ok" and run.outcome.worst < 1e-11


def test_example2_differs_by_the_listings_vertical_velocity_only():
    """Example 2's listing takes P = 650 V(4)|V(4)| with V(4) the vertical velocity; the
    reference uses the velocity along the 90.1 deg axis: loads differ by tan^2(0.1 deg)."""
    case = [c for c in cases.paper_cases() if c.name.startswith("paper Example 2") and c.linkage == "slider_crank"][0]
    assert case.model_note
    run = ways.run_python(case, "pseudographic", case.quick[:6], "array", repeat=1)
    assert run.outcome.worst == pytest.approx(math.tan(math.radians(0.1)) ** 2, rel=1e-3)
