"""``yaseer centrode [--out DIR]``: seed 004's space centrode (Jong, Reynolds, Adams 1996).

Prints the change-point velocities found from the acceleration equations
(omega_BD = (1 +/- 2 sqrt 2)/5 omega_AB, AC = 0.0918 m or -1.1204 m), which root the
motion takes at each pass, the crank angles where the centrode jumps and its
asymptotes there, and draws the paper's Fig. 5 (PNG and SVG in DIR).
"""

from __future__ import annotations

import math
from pathlib import Path

WINDOW = (-3.2, 3.6, -2.4, 2.4)  # x min, x max, y min, y max (m) of the figure


def add_arguments(parser) -> None:
    parser.epilog = "Exit status: 0 done, 1 an error (one line on standard error), 2 a wrong command line, 130 Ctrl-C."
    parser.add_argument("--out", default=".", metavar="DIR",
                        help="directory for centrode.png and centrode.svg (created; default: the current directory)")
    parser.add_argument("--step", type=_positive, default=0.05, help="crank angle step in degrees (default 0.05)")
    parser.add_argument("--no-plot", action="store_true", help="print the numbers only")


def report_lines(step_deg: float = 0.05) -> list[str]:
    """The printed numbers (see the module docstring)."""
    import numpy as np

    from yaseer.linkages.centrode import SEED004, change_point_angles, collinear_centres, jumps, space_centrode

    lines = ["Seed 004: AB = 0.3 m, BD = 0.5 m, DE = 1 m, AE = 1.2 m; crank angle beta from +x, "
             "first revolution on the crossed assembly"]
    for angle in change_point_angles(SEED004):
        try:
            centres = collinear_centres(SEED004, angle)
        except ArithmeticError:
            continue
        lines.append(f"collinear configuration at beta = {angle:g} deg (velocity from the acceleration equations):")
        for centre in centres:
            lines.append(f"  omega_BD = {centre.ratio:.6f} omega_AB   ->  AC = {centre.ac:.4f} m")
        paper = [(1 + sign * 2 * math.sqrt(2)) / 5 for sign in (1, -1)]
        lines.append(f"  (the paper's (1 +/- 2 sqrt 2)/5 = {paper[0]:.6f} / {paper[1]:.6f})")
    tracked, centre = space_centrode(crank_angles_deg=np.arange(0.0, 720.0 + 1e-9, step_deg))
    angles = np.arange(0.0, 720.0 + 1e-9, step_deg)
    for index in np.flatnonzero(tracked.singular):
        lines.append(f"the motion passes beta = {angles[index]:g} deg with omega_BD = "
                     f"{float(tracked.fourbar.coupler.omega[index]):.6f} omega_AB, AC = {centre[index].real:.4f} m")
    for switch in tracked.switches:
        lines.append(switch.describe())
    for asymptote in jumps():
        intercept = asymptote.offset / math.cos(math.radians(asymptote.crank_angle_deg))
        lines.append(f"C jumps at beta = {asymptote.crank_angle_deg:.2f} deg along the asymptote "
                     f"y = {asymptote.slope:.4f} x {'+' if intercept >= 0 else '-'} {abs(intercept):.4f} m")
    return lines


def draw(out: Path, step_deg: float = 0.05) -> list[Path]:
    """Fig. 5: the space centrode (thick: first revolution, thin: second), its asymptotes."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    from yaseer.linkages.centrode import SEED004, collinear_centres, jumps, space_centrode
    from yaseer.whole_files import staged

    angles = np.arange(0.0, 720.0 + 1e-9, step_deg)
    _, centre = space_centrode(crank_angles_deg=angles)
    x_min, x_max, y_min, y_max = WINDOW
    far = (np.abs(centre) > 50) | ~np.isfinite(centre)
    centre = np.where(far, np.nan, centre)
    figure, axes = plt.subplots(figsize=(8, 5.6))
    first = angles < 360.0
    for mask, width, label in ((first, 2.6, "first revolution (0 <= beta < 360 deg)"),
                               (~first, 0.9, "second revolution (360 <= beta < 720 deg)")):
        axes.plot(np.where(mask, centre.real, np.nan), np.where(mask, centre.imag, np.nan),
                  color="black", linewidth=width, label=label)
    span = np.array([-10.0, 10.0])
    for asymptote in jumps():
        ends = [asymptote.point(t) for t in span]
        axes.plot([e.real for e in ends], [e.imag for e in ends], "--", color="0.45", linewidth=0.9)
        label_at = asymptote.point(-2.4)
        axes.annotate(f"asymptote, beta = {asymptote.crank_angle_deg:.2f} deg", xy=(label_at.real, label_at.imag),
                      textcoords="offset points", xytext=(0, 14 if label_at.imag > 0 else -18), fontsize=8, color="0.3")
    pivot = SEED004.ground_length
    axes.plot([0, pivot], [0, 0], "o", color="black", markersize=4)
    axes.annotate("A", (0, 0), textcoords="offset points", xytext=(-12, -14))
    axes.annotate("E", (pivot, 0), textcoords="offset points", xytext=(4, -12))
    for centre, shift in zip(collinear_centres(SEED004, 180.0), ((6, 6), (-78, 6))):
        axes.plot([centre.ac], [0], "x", color="black")
        axes.annotate(f"AC = {centre.ac:.4f} m", (centre.ac, 0), textcoords="offset points", xytext=shift, fontsize=8)
    axes.set_xlim(x_min, x_max)
    axes.set_ylim(y_min, y_max)
    axes.set_aspect("equal")
    axes.axhline(0, color="0.8", linewidth=0.6)
    axes.axvline(0, color="0.8", linewidth=0.6)
    axes.set_xlabel("x (m)")
    axes.set_ylabel("y (m)")
    axes.set_title("Space centrode of the coupler BD and its asymptotes (seed 004, Fig. 5)")
    axes.legend(loc="lower right", fontsize=8)
    out.mkdir(parents=True, exist_ok=True)
    paths = [out / "centrode.png", out / "centrode.svg"]
    with staged() as place:  # both appear, or neither
        for path in paths:
            figure.savefig(place(path), dpi=120)
    plt.close(figure)
    return paths


def _positive(text: str) -> float:
    import argparse

    try:
        value = float(text)
    except ValueError:
        value = 0.0
    if not value > 0:
        raise argparse.ArgumentTypeError(f"a positive number of degrees, not {text!r}")
    return value


def main(args) -> int:
    from yaseer.commands.output import output_directory

    out = None if args.no_plot else output_directory(args.out)
    for line in report_lines(args.step):
        print(line)
    if out is not None:
        paths = draw(out, args.step)
        print("wrote " + ", ".join(str(p) for p in paths))
    return 0
