"""``yaseer stability``: the table (method x sweep) and the chart (error against distance).

Summary per (sweep, method): the worst verified error at distances 1e-12..1e-1 deg,
and counts of NaN, exceptions, wrong branches, "silent" results (finite, no
error raised, error > 1e-6: NaN and wrong branches included) and what the method
did at the singular configuration itself.
"""

from __future__ import annotations

import math
from pathlib import Path

from .benchmark import methods_of, save_figure, write_csv
from .sweeps import all_sweeps, evaluate

SILENT = 1e-6
POINT_FIELDS = ("family", "group", "method", "distance_deg", "status", "error", "position_error", "velocity_error",
                "acceleration_error", "detail")
KIND_NAMES = ("position", "velocity", "acceleration")


def sweep_points(sweeps=None) -> list[dict]:
    """Every sweep x method x position, as rows."""
    rows = []
    for sweep in sweeps if sweeps is not None else all_sweeps():
        for method in methods_of(sweep.linkage):
            for point in evaluate(sweep, method):
                kinds = dict(point.by_kind)
                rows.append({"family": sweep.family, "group": sweep.group, "method": method,
                             "distance_deg": point.distance, "status": point.status, "error": point.error,
                             **{f"{k}_error": kinds.get(k, math.nan) for k in KIND_NAMES},
                             "detail": point.detail})
    return rows


def summarise(points) -> list[dict]:
    groups: dict[tuple, list[dict]] = {}
    for p in points:
        groups.setdefault((p["family"], p["method"]), []).append(p)
    summary = []
    for (family, method), members in groups.items():
        verified = [m["error"] for m in members if m["status"] in ("ok", "wrong branch") and m["distance_deg"] != 0.0]
        at_zero = [m for m in members if m["distance_deg"] == 0.0]
        silent = [m for m in members if m["status"] in ("nan", "wrong branch")
                  or (m["status"] == "ok" and m["error"] > SILENT)]
        away = [m for m in members if m["status"] in ("ok", "wrong branch") and m["distance_deg"] != 0.0]
        summary.append({
            "family": family, "group": members[0]["group"], "method": method,
            "worst_error": max(verified) if verified else math.nan,
            **{f"worst_{k}": max((m[f"{k}_error"] for m in away), default=math.nan) for k in KIND_NAMES},
            "nan": sum(m["status"] == "nan" for m in members),
            "exception": sum(m["status"] == "exception" for m in members),
            "wrong_branch": sum(m["status"] == "wrong branch" for m in members),
            "silent_wrong": len(silent),
            "closest_silent_free_deg": _closest_clean(members),
            "at_singularity": _describe(at_zero[0]) if at_zero else "",
            "positions": len(members),
        })
    return summary


def _describe(point) -> str:
    """What a method did at the singular configuration itself."""
    if point["status"] in ("ok", "wrong branch"):
        return f"{point['status']} (error {point['error']:.2g})"
    return point["status"]


def _closest_clean(members) -> float:
    """The smallest distance down to which every position is accurate (<= 1e-6) or a clear error."""
    closest = math.inf
    for m in sorted(members, key=lambda m: -abs(m["distance_deg"])):
        if m["distance_deg"] == 0.0:
            continue
        clean = m["status"] == "exception" or (m["status"] == "ok" and m["error"] <= SILENT)
        if not clean:
            break
        closest = min(closest, abs(m["distance_deg"]))
    return closest


def format_table(summary) -> str:
    """Method x sweep: worst error / NaN / exceptions / wrong branch / silent, and the value at 0."""
    lines = [f"{'sweep':<52} {'method':<19} {'pos err':>8} {'vel err':>8} {'acc err':>8} {'NaN':>4} {'exc':>4} "
             f"{'wrong':>5} {'silent':>6}  at the singularity"]
    for s in summary:
        lines.append(f"{s['family']:<52} {s['method']:<19} {s['worst_position']:>8.1e} {s['worst_velocity']:>8.1e} "
                     f"{s['worst_acceleration']:>8.1e} {s['nan']:>4} {s['exception']:>4} {s['wrong_branch']:>5} "
                     f"{s['silent_wrong']:>6}  {s['at_singularity']}")
    return "\n".join(lines)


def format_markdown(summary) -> str:
    """The summary as a markdown table (docs/stability.md pastes it)."""
    def number(value):
        return f"{value:.1e}" if math.isfinite(value) else "–"

    def clean(value):
        if value <= min(d for d in (10.0 ** -k for k in range(1, 13))):
            return "all"
        return "none" if math.isinf(value) else f"{value:g}"

    lines = ["| sweep | method | positions | velocities | accelerations | NaN | error raised | wrong branch "
             "| silent > 1e-6 | clean down to (deg) | at the singular configuration |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for s in summary:
        lines.append(f"| {s['family']} | {s['method']} | {number(s['worst_position'])} | {number(s['worst_velocity'])} "
                     f"| {number(s['worst_acceleration'])} | {s['nan']} | {s['exception']} | {s['wrong_branch']} "
                     f"| {s['silent_wrong']} | {clean(s['closest_silent_free_deg'])} | {s['at_singularity']} |")
    return "\n".join(lines) + "\n"


def draw_chart(points, path_stem: Path, place=None) -> list[Path]:
    """Error against distance from the singularity, one panel per group, a line per method."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    groups = list(dict.fromkeys(p["group"] for p in points))
    columns = 3
    rows = math.ceil(len(groups) / columns)
    figure, axes = plt.subplots(rows, columns, figsize=(6 * columns, 4.6 * rows), squeeze=False)
    for axis, group in zip(axes.flat, groups):
        members = [p for p in points if p["group"] == group and p["distance_deg"] != 0.0]
        methods = list(dict.fromkeys(p["method"] for p in members))
        for k, method in enumerate(methods):
            colour = plt.cm.tab10(k % 10)
            worst: dict[float, list[float]] = {}
            failures: dict[str, list[float]] = {}
            for p in (m for m in members if m["method"] == method):
                d = abs(p["distance_deg"])
                if p["status"] == "ok":
                    rates = max(p["position_error"], p["velocity_error"])
                    old_rates, old_acc = worst.get(d, [0.0, 0.0])
                    worst[d] = [max(old_rates, rates), max(old_acc, p["acceleration_error"])]
                else:
                    failures.setdefault(p["status"], []).append(d)
            xs = sorted(worst)
            axis.plot(xs, [min(max(worst[x][0], 1e-17), 1e3) for x in xs], "-o", ms=3, color=colour, label=method)
            axis.plot(xs, [min(max(worst[x][1], 1e-17), 1e3) for x in xs], "--", lw=0.8, color=colour)
            for status, marker, level in (("exception", "x", 1e5), ("nan", "v", 1e6), ("wrong branch", "D", 1e7),
                                          ("unverified", "+", 1e4)):
                if status in failures:
                    axis.scatter(failures[status], [level * (1 + 0.25 * k)] * len(failures[status]),
                                 marker=marker, color=colour, s=30)
        axis.axhline(SILENT, color="grey", lw=0.6, ls=":")
        axis.set_xscale("log")
        axis.set_yscale("log")
        axis.set_ylim(1e-17, 3e8)
        axis.set_xlabel("distance from the singular configuration (deg)")
        axis.set_ylabel("worst error (relative; angles in rad)")
        axis.set_title(group, fontsize=10)
        axis.grid(True, which="major", alpha=0.3)
        axis.legend(fontsize=7, loc="lower left")
    for axis in list(axes.flat)[len(groups):]:
        axis.set_visible(False)
    figure.suptitle("yaseer stability: solid = positions and velocities, dashed = accelerations (drawn at most 1e3); "
                    "above: + unverifiable, x exception, v NaN/inf, diamond wrong branch; dotted line 1e-6", fontsize=10)
    return save_figure(figure, path_stem, dpi=100, place=place)


def write_all(out: Path, points, summary, place=None) -> list[Path]:
    """The two CSV files and the Markdown table in ``out`` (all or none: ``place``, see :mod:`yaseer.whole_files`)."""
    from yaseer.whole_files import staged

    with staged(place) as place:
        write_csv(out / "stability_points.csv", points, POINT_FIELDS, place)
        write_csv(out / "stability.csv", summary, list(summary[0]), place)
        with open(place(out / "stability_table.md"), "w") as table:
            table.write(format_markdown(summary))
    return [out / "stability_points.csv", out / "stability.csv", out / "stability_table.md"]
