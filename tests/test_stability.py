"""yaseer stability: the sweeps, their classification and the command."""

import math

import mpmath
import pytest

import yaseer.linkages.methods  # noqa: F401
from yaseer.evaluation import stability, sweeps
from yaseer.evaluation.sweeps import DISTANCES, all_sweeps, evaluate
from test_bench import polar_closed_form

SWEEPS = {s.family: s for s in all_sweeps()}


def test_every_family_of_the_issue_is_swept():
    groups = {s.group for s in SWEEPS.values()}
    assert groups == {"PROG 5 at T = 0, 90, 180, 270", "slider-crank dead centres, axis at 0 and exactly 90",
                      "slider-crank assembly limit", "four-bar toggle / assembly limit", "change point (seed 004)",
                      "half-angle pole AA = 0"}
    prog5 = [s for s in SWEEPS.values() if s.linkage == "virtual_link"]
    assert len(prog5) == 4
    for sweep in prog5:
        distances = sorted(abs(d) for d, _ in sweep.positions)
        assert distances[0] == 0.0 and set(distances[1:]) == set(DISTANCES)  # both sides, k = 1..12


@mpmath.workdps(50)
@pytest.mark.parametrize("family", ["PROG 5 near T = 90", "PROG 5 near T = 180"])
def test_prog5_sweep_reference_is_the_polar_closed_form(family):
    sweep = SWEEPS[family]
    for index in (0, 5, 12, 24):
        p = sweep.positions[index][1]
        reference = sweep.reference_at(index)
        expected = polar_closed_form(p["x"], p["y"], 3.0, -4.0, -50.0, 20.0)
        for name, value in expected.items():
            assert abs(reference[name] - value) <= mpmath.mpf(10) ** -40 * max(1, abs(value))


@pytest.mark.parametrize("centre", [0, 90, 180, 270])
def test_prog5_paper_stops_at_the_axes_and_degrades_near_them(centre):
    """The paper's equations divide by cos T or sin T: a clear error exactly on an
    axis, and an error growing as the angle approaches it (not a silent NaN)."""
    points = evaluate(SWEEPS[f"PROG 5 near T = {centre}"], "paper")
    at_zero = [p for p in points if p.distance == 0.0]
    assert at_zero[0].status == "exception" and "Division by zero" in at_zero[0].detail or \
        "division by zero" in at_zero[0].detail
    near = max(p.error for p in points if abs(p.distance) == 1e-12)
    far = max(p.error for p in points if abs(p.distance) == 1e-1)
    assert near > 1e-6 > far


@pytest.mark.parametrize("centre", [0, 90, 180, 270])
def test_prog5_polar_stays_exact_through_the_axes(centre):
    points = evaluate(SWEEPS[f"PROG 5 near T = {centre}"], "polar")
    assert all(p.status == "ok" and p.error < 1e-14 for p in points)


@pytest.mark.parametrize("family", [
    "slider-crank dead centre theta = 0", "slider-crank dead centre theta = 180",
    "slider-crank, axis at 90: dead centre theta = 90", "slider-crank, axis at 90: dead centre theta = 270"])
@pytest.mark.parametrize("method", ["closed", "pseudographic", "newton"])
def test_slider_dead_centres_and_vertical_axis_are_harmless(family, method):
    points = evaluate(SWEEPS[family], method)
    assert all(p.status == "ok" and p.error < 1e-11 for p in points)


def test_half_angle_pole_silent_nan_for_the_printed_form_only():
    uncrossed = SWEEPS["half-angle pole AA = 0 (seed 003), uncrossed"]
    printed = evaluate(uncrossed, "half-angle-printed")
    assert printed[0].status == "nan"
    assert max(p.error for p in printed if p.status == "ok") > 1e-6
    for method in ("half-angle", "closed", "newton"):
        assert all(p.status == "ok" and p.error < 1e-13 for p in evaluate(uncrossed, method))


def test_change_point_closed_form_reports_the_lock():
    """At the collinear configuration the robust closed form raises a clear error."""
    from yaseer.linkages import LockedError

    sweep = SWEEPS["change-point four-bar (seed 004) theta = 180, crossed"]
    distance, inputs = sweep.positions[0]
    assert distance == 0.0
    with pytest.raises(LockedError):
        sweep.compute("closed", inputs)


def test_summary_counts_what_the_points_say():
    points = stability.sweep_points([SWEEPS["PROG 5 near T = 90"], SWEEPS["half-angle pole AA = 0 (seed 003), uncrossed"]])
    summary = {(s["family"], s["method"]): s for s in stability.summarise(points)}
    paper = summary[("PROG 5 near T = 90", "paper")]
    assert paper["exception"] == 1 and paper["nan"] == 0 and paper["at_singularity"] == "exception"
    assert paper["silent_wrong"] == sum(1 for p in points if p["family"] == "PROG 5 near T = 90"
                                        and p["method"] == "paper" and p["status"] == "ok" and p["error"] > 1e-6)
    polar = summary[("PROG 5 near T = 90", "polar")]
    assert polar["silent_wrong"] == 0 and polar["worst_error"] < 1e-14
    assert summary[("half-angle pole AA = 0 (seed 003), uncrossed", "half-angle-printed")]["nan"] == 1


def test_stability_command(tmp_path, capsys, monkeypatch):
    chosen = [SWEEPS["PROG 5 near T = 270"], SWEEPS["slider-crank dead centre theta = 0"]]
    monkeypatch.setattr(stability, "all_sweeps", lambda: chosen)
    from yaseer.cli import main

    assert main(["stability", "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    assert "PROG 5 near T = 270" in out and "pseudographic" in out
    for name in ("stability.csv", "stability_points.csv", "stability.png", "stability.svg"):
        assert (tmp_path / name).stat().st_size > 0


def test_limits_are_where_the_formulas_say():
    """Seed 003's crank limit and half-angle pole, from their defining equations."""
    limit = math.radians(sweeps.seed003_limit_deg())
    assert abs(math.hypot(30 * math.cos(limit) - 60, 30 * math.sin(limit)) - 72) < 1e-12
    pole = math.radians(sweeps.seed003_half_angle_pole_deg())
    assert abs(2250 - 30 * 24 * math.cos(pole) - 2160) < 1e-10


@mpmath.workdps(50)
def test_reported_sweep_errors_are_the_independent_errors():
    """PROG 5 "paper" next to T = 90: each position's error, recomputed from the polar
    closed form in mpmath with the sweep's normalisation (largest |value| per quantity)."""
    from yaseer.linkages import virtual_link

    sweep = SWEEPS["PROG 5 near T = 90"]
    references = [polar_closed_form(p["x"], p["y"], 3.0, -4.0, -50.0, 20.0) for _, p in sweep.positions]
    scale = {name: max(abs(r[name]) for r in references) for name in references[0]}
    scale["T"] = 1
    for point, (_, p), reference in zip(evaluate(sweep, "paper"), sweep.positions, references):
        if point.status == "exception":
            assert p["x"] == 0.0
            continue
        r = virtual_link(p["x"], p["y"], 3.0, -4.0, -50.0, 20.0, method="paper")
        got = {"T": r.angle_deg, "L": r.length, "D(5)": r.angle_rate, "E(5)": r.angle_accel,
               "D(6)": r.length_rate, "E(6)": r.length_accel}
        worst = 0
        for name, value in got.items():
            difference = mpmath.mpf(float(value)) - reference[name]
            if name == "T":
                difference = mpmath.radians((difference + 180) % 360 - 180)
            worst = max(worst, abs(difference) / scale[name])
        assert point.error == pytest.approx(float(worst), rel=1e-6, abs=1e-30)
