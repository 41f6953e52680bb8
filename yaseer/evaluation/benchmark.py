"""``yaseer bench``: time per position against worst error, per method and way of running.

Rows (one per case x method x way) are dicts with the keys of :data:`FIELDS`.
The chart aggregates them per (linkage, method, way): the median time per
position over the cases and the worst error over the cases; Newton adds a
curve over its tolerances (array way).
"""

from __future__ import annotations

import csv
import math
import statistics
from pathlib import Path

import numpy as np

from .cases import all_cases
from .ways import LISTING_ARITHMETIC, WAYS, run_listing, run_python

FIELDS = ("case", "linkage", "method", "way", "single", "positions", "seconds_per_position", "worst_error", "status",
          "where", "detail", "model_note")
NEWTON_TOLERANCES = (1e-1, 1e-2, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14)
ERROR_FLOOR = 1e-17  # a zero error is drawn here on the log axis


def methods_of(linkage: str) -> list[str]:
    """Every method registered for ``linkage`` (importing the alternative methods first)."""
    import yaseer.linkages.methods  # noqa: F401  (registers them)
    from yaseer.linkages.registry import method_names

    return method_names(linkage)


def interpreter_available() -> bool:
    try:
        import yaseer.commands.run  # noqa: F401
    except ImportError:
        return False
    return True


def _row(case, method, way, run) -> dict:
    outcome = run.outcome
    return {"case": case.name, "linkage": case.linkage, "method": method, "way": way, "single": case.single,
            "model_note": case.model_note,
            "positions": run.positions,
            "seconds_per_position": run.seconds_per_position, "worst_error": outcome.worst,
            "status": outcome.status, "where": outcome.where, "detail": outcome.detail}


def selected_cases(pattern: str | None = None):
    """The cases whose name contains ``pattern`` (case-insensitive), or all."""
    return [c for c in all_cases() if pattern is None or pattern.lower() in c.name.lower()]


def bench_rows(quick: bool = False, ways=WAYS, repeat: int = 3, progress=None, pattern=None) -> list[dict]:
    """Every case x method x way.  ``progress(text)`` is told what runs."""
    rows = []
    listing = any(way in LISTING_ARITHMETIC for way in ways) and interpreter_available()
    for case in selected_cases(pattern):
        angles = case.quick if quick else case.dense
        for method in methods_of(case.linkage):
            for way in ways:
                if progress:
                    progress(f"{case.name}: {method}, {way}")
                if way in LISTING_ARITHMETIC:
                    if not listing:
                        continue
                    run = run_listing(case, method, angles, arithmetic=LISTING_ARITHMETIC[way])
                elif case.compute is None:
                    continue
                else:
                    run = run_python(case, method, angles, way, repeat=repeat)
                rows.append(_row(case, method, way, run))
    return rows


def newton_rows(quick: bool = False, repeat: int = 3, pattern=None) -> list[dict]:
    """Newton over its tolerances, array way, on every case of a linkage it solves."""
    rows = []
    for case in selected_cases(pattern):
        if case.compute is None or "newton" not in methods_of(case.linkage):
            continue
        angles = case.quick if quick else case.dense
        for tol in NEWTON_TOLERANCES:
            run = run_python(case, "newton", angles, "array", {"tol": tol}, repeat=repeat)
            rows.append(_row(case, f"newton tol={tol:g}", "array", run))
    return rows


def aggregate(rows) -> list[dict]:
    """Per (linkage, method, way): the median seconds per position over the
    single-program cases (one program call a position: the seeds' linkages, the
    ellipse), the worst error over every case (but those whose listing and
    reference differ by a modelling choice, ``model_note``), and the failures."""
    groups: dict[tuple, list[dict]] = {}
    for row in rows:
        groups.setdefault((row["linkage"], row["method"], row["way"]), []).append(row)
    summary = []
    for (linkage, method, way), members in groups.items():
        timed = [m["seconds_per_position"] for m in members
                 if math.isfinite(m["seconds_per_position"]) and m.get("single", True)]
        errors = [m["worst_error"] for m in members if m["status"] != "exception" and not m.get("model_note")]
        failures = [m for m in members if m["status"] not in ("ok",)]
        summary.append({"linkage": linkage, "method": method, "way": way, "cases": len(members),
                        "seconds_per_position": statistics.median(timed) if timed else math.nan,
                        "worst_error": max(errors) if errors else math.nan,
                        "failures": "; ".join(f"{m['case']}: {m['status']}" for m in failures)})
    return sorted(summary, key=lambda s: (s["linkage"], s["method"], WAYS.index(s["way"]) if s["way"] in WAYS else 9))


def write_csv(path: Path, rows, fields, place=None) -> None:
    """``rows`` (dicts) as CSV with the columns ``fields``; floats as their repr.  ``place``: the
    :class:`yaseer.whole_files.Staging` of a set of outputs this file belongs to (default: its own)."""
    from yaseer.whole_files import staged

    with staged(place) as place, open(place(path), "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(fields))
        writer.writeheader()
        for row in rows:
            writer.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in row.items() if k in fields})


def format_table(summary) -> str:
    """The aggregated rows as a plain-text table."""
    lines = [f"{'linkage':<13} {'method':<22} {'way':<17} {'us/position':>12} {'worst error':>12}  failures"]
    for s in summary:
        micro = s["seconds_per_position"] * 1e6
        lines.append(f"{s['linkage']:<13} {s['method']:<22} {s['way']:<17} {micro:>12.2f} "
                     f"{s['worst_error']:>12.3g}  {s['failures']}")
    return "\n".join(lines)


def format_summary_markdown(summary) -> str:
    """Per method: time per position for each way and the worst error, as a markdown table."""
    lines = ["| linkage | method | listing | per position | array | worst error |", "|---|---|---|---|---|---|"]
    keys = list(dict.fromkeys((s["linkage"], s["method"]) for s in summary))
    for linkage, method in keys:
        members = {s["way"]: s for s in summary if (s["linkage"], s["method"]) == (linkage, method)}
        times = [f"{members[w]['seconds_per_position'] * 1e6:.3g} us" if w in members else "–" for w in WAYS]
        worst = max(m["worst_error"] for m in members.values())
        lines.append(f"| {linkage.replace('_', '-')} | {method} | " + " | ".join(times) + f" | {worst:.2g} |")
    return "\n".join(lines) + "\n"


def format_newton_markdown(curve) -> str:
    """Newton over its tolerance: time per position and worst error, per linkage."""
    lines = ["| linkage | tol | time per position (array) | worst error | failures |", "|---|---|---|---|---|"]
    for n in sorted(curve, key=lambda n: (n["linkage"], -n["tol"])):
        lines.append(f"| {n['linkage'].replace('_', '-')} | {n['tol']:g} | {n['seconds_per_position'] * 1e6:.3g} us "
                     f"| {n['worst_error']:.2g} | {n['failures']} |")
    return "\n".join(lines) + "\n"


def format_laziness_markdown(rows) -> str:
    """The laziness measurement: time per position per level and way, ratio to positions only."""
    lines = ["| linkage | level | array | per position |", "|---|---|---|---|"]
    for linkage in dict.fromkeys(r["linkage"] for r in rows):
        for level in LAZINESS_LEVELS:
            cells = {r["way"]: r for r in rows if r["linkage"] == linkage and r["level"] == level}
            array, single = cells["array"], cells["per position"]
            lines.append(f"| {linkage.replace('_', '-')} | {level} | {array['seconds_per_position'] * 1e6:.3g} us "
                         f"(x{array['ratio_to_positions_array']:.1f}) | {single['seconds_per_position'] * 1e6:.3g} us |")
    return "\n".join(lines) + "\n"


def format_markdown(rows) -> str:
    """Every case x method: worst error (time per position) per way, as a markdown table."""
    cases = list(dict.fromkeys(r["case"] for r in rows))
    lines = ["| case | method | listing | per position | array |", "|---|---|---|---|---|"]
    for case in cases:
        members = [r for r in rows if r["case"] == case and "tol=" not in r["method"]]
        for method in dict.fromkeys(r["method"] for r in members):
            cells = {}
            for r in (m for m in members if m["method"] == method):
                if r["status"] == "ok":
                    cells[r["way"]] = f"{r['worst_error']:.1e} ({r['seconds_per_position'] * 1e6:.1f} us)"
                else:
                    cells[r["way"]] = f"{r['status']}: {r['detail']}"
            lines.append(f"| {case} | {method} | " + " | ".join(cells.get(w, "–") for w in WAYS) + " |")
    return "\n".join(lines) + "\n"


def draw_chart(summary, newton_summary, path_stem: Path, place=None) -> list[Path]:
    """Time per position (log) against worst error (log), a panel per linkage: PNG and SVG.

    Colour: the method; marker: the way of running; grey line: Newton over its
    tolerance (array way), each point labelled with its tolerance and failures.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D

    markers = {"listing": "s", "listing (decimal)": "D", "per position": "o", "array": "^"}
    linkages = sorted({s["linkage"] for s in summary})
    figure, axes = plt.subplots(1, len(linkages), figsize=(5.5 * len(linkages), 6.2), squeeze=False)
    for axis, linkage in zip(axes[0], linkages):
        members = [s for s in summary if s["linkage"] == linkage]
        methods = sorted({s["method"] for s in members})
        colours = {m: plt.cm.tab10(k % 10) for k, m in enumerate(methods)}
        for s in members:
            if not math.isfinite(s["seconds_per_position"]):
                continue
            error = s["worst_error"] if math.isfinite(s["worst_error"]) else 1.0
            axis.scatter(s["seconds_per_position"] * 1e6, max(error, ERROR_FLOOR), marker=markers.get(s["way"], "x"),
                         color=colours[s["method"]], s=70, zorder=3, edgecolors="black", linewidths=0.4)
        handles = [Line2D([], [], color=colours[m], marker="o", ls="", label=m) for m in methods]
        handles += [Line2D([], [], color="black", marker=markers[w], ls="", mfc="none", label=w) for w in markers]
        curve = sorted((n for n in newton_summary if n["linkage"] == linkage), key=lambda n: n["tol"])
        if curve:
            xs = [n["seconds_per_position"] * 1e6 for n in curve]
            ys = [max(n["worst_error"], ERROR_FLOOR) for n in curve]
            axis.plot(xs, ys, "-", color="grey", lw=1, zorder=2)
            for n, x, y in zip(curve, xs, ys):
                label = f"{n['tol']:g}" + (f" ({n['failures']} failed)" if n["failures"] else "")
                axis.annotate(label, (x, y), textcoords="offset points", xytext=(4, -3), fontsize=6, color="dimgrey")
            handles.append(Line2D([], [], color="grey", label="Newton over tol (array)"))
        axis.legend(handles=handles, fontsize=7, loc="upper center", bbox_to_anchor=(0.5, -0.13), ncol=4,
                    frameon=False)
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_xlabel("time per position, single-program cases (us)")
        axis.set_ylabel("worst error over all cases (relative; angles in rad)")
        axis.set_title(linkage.replace("_", " "))
        axis.grid(True, which="major", alpha=0.3)
    figure.suptitle("yaseer bench: speed against accuracy per method and way of running", fontsize=10)
    return save_figure(figure, path_stem, dpi=110, place=place)


def save_figure(figure, path_stem: Path, dpi: int, place=None) -> list[Path]:
    """Write ``figure`` as PNG and SVG next to each other, close it, return the paths.

    Both appear or neither (``place``: the staging of a larger set of outputs, see
    :mod:`yaseer.whole_files`)."""
    import matplotlib.pyplot as plt

    from yaseer.whole_files import staged

    figure.tight_layout()
    paths = []
    with staged(place) as place:
        for suffix in (".png", ".svg"):
            path = path_stem.with_suffix(suffix)
            figure.savefig(place(path), dpi=dpi)
            paths.append(path)
    plt.close(figure)
    return paths


def newton_summary(rows) -> list[dict]:
    """Per (linkage, tolerance): median time per position and worst error over the cases."""
    groups: dict[tuple, list[dict]] = {}
    for row in rows:
        tol = float(row["method"].split("=")[1])
        groups.setdefault((row["linkage"], tol), []).append(row)
    out = []
    for (linkage, tol), members in groups.items():
        timed = [m["seconds_per_position"] for m in members
                 if math.isfinite(m["seconds_per_position"]) and m.get("single", True)]
        errors = [m["worst_error"] for m in members if m["status"] != "exception" and not m.get("model_note")]
        out.append({"linkage": linkage, "tol": tol,
                    "seconds_per_position": statistics.median(timed) if timed else math.nan,
                    "worst_error": max(errors) if errors else math.nan,
                    "failures": sum(m["status"] != "ok" for m in members)})
    return out


# --------------------------------------------------------------------------- laziness

LAZINESS_LEVELS = ("positions", "+ velocities and accelerations", "+ forces")


def laziness_rows(positions: int = 3601, repeat: int = 5) -> list[dict]:
    """What "model no more than a scene needs" buys: the default programs at each level.

    Array way over ``positions`` crank angles, per-position way over 361 of them.
    The contract computes velocities and accelerations together (any crank rate
    non-zero), so there is no separate velocities-only level to measure.
    """
    import time

    angles = np.linspace(0.0, 360.0, positions)
    rows = []
    for name, function in (("slider_crank", _slider_level), ("fourbar", _fourbar_level)):
        base = None
        for level, label in enumerate(LAZINESS_LEVELS):
            for way, cycle, tries in (("array", angles, repeat), ("per position", angles[::10], 3)):
                best = math.inf
                for _ in range(tries):
                    start = time.perf_counter()
                    if way == "array":
                        function(level, cycle)
                    else:
                        for angle in cycle:
                            function(level, float(angle))
                    best = min(best, time.perf_counter() - start)
                per_position = best / len(cycle)
                base = per_position if base is None else base
                rows.append({"linkage": name, "level": label, "way": way, "seconds_per_position": per_position,
                             "ratio_to_positions_array": per_position / base})
    return rows


def _masses():
    from yaseer.linkages import MassProps

    return MassProps(mass=2.0, inertia=0.01, distance=0.05, offset_deg=0.0)


def _slider_level(level, angles):
    """Example 2's first slider-crank at ``level`` 0 (positions), 1 (+ rates), 2 (+ forces)."""
    from yaseer.linkages import slider_crank

    result = slider_crank(0.0, 0.021, 0.032, angles, 0.0 if level == 0 else -8.0, 0.0, axis_deg=0.1)
    if level == 2:
        result.forces(crank=_masses(), rod=_masses(), piston_mass=1.0, loads={"piston": 10.0},
                      unknown="crank_torque")


def _fourbar_level(level, angles):
    """Example 5's first four-bar at ``level`` 0 (positions), 1 (+ rates), 2 (+ forces)."""
    from yaseer.linkages import fourbar

    result = fourbar(math.hypot(0.85, 1.25), math.degrees(math.atan2(1.25, -0.85)), 0.075, 1.2, 0.85, angles,
                     0.0 if level == 0 else -22.0, 0.0, branch=-1)
    if level == 2:
        result.forces(crank=_masses(), coupler=_masses(), follower=_masses(), unknown="crank_torque")
