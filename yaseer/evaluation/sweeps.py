"""``yaseer stability``: each method swept towards the configurations where methods fail.

A :class:`Sweep` is a family of positions at distances 10^-k (k = 1..12, in
degrees of the driving angle) from one singular configuration, plus the
configuration itself (distance 0).  At every position each method of the
sweep's linkage is called once (floats, the per-position way) and its result
is classified against the 50-digit reference of the same inputs:

* ``ok`` with its error (measure of :mod:`.measure`, normalised per sweep);
* ``nan``: NaN or infinity returned without an error;
* ``exception``: a clear error raised (the robust behaviour at a singularity);
* ``wrong branch``: a valid assembly of the other mode, returned silently.

At distance 0 there is no reference where the configuration is singular (the
rates do not exist); only what the method did is recorded there.

Families:

1. Program 5 at T = 0, 90, 180, 270 deg exactly and 10^-k deg away (point at
   L = 100, velocity (3, -4), acceleration (-50, 20)).
2. Slider-crank dead centres (e = 0, a = 1, b = 3, theta = 0 and 180 deg) with a
   horizontal axis, and with the axis at exactly 90 deg (theta = 90, 270 deg).
3. Slider-crank assembly limit: e = 0.5, a = 1, b = 1.5, the rod square to the axis
   at theta = 90 deg (it assembles on both sides; rates are unbounded there).
4. Four-bar toggle: seed 003's linkage (30, 36, 36, 60) at the end of its crank
   range, theta_lim = 100.95 deg, approached from inside, both modes.
5. The change-point four-bar of seed 004 through its collinear configuration
   (theta = 180 deg), both sides, crossed mode, in decimetres (3, 5, 10, 12): as
   binary floats 0.3 + 1.2 falls 5.6e-17 short of 0.5 + 1, so the metre version
   is not a change point at all (its branches pass 7e-9 rad apart near 180 deg).
6. The half-angle quadratic's own trouble: seed 003's linkage where AA = 0
   (theta = 82.82 deg, the follower at 180 deg on one root), both modes.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from .cases import FOURBAR_COLUMNS, SLIDER_COLUMNS
from .measure import ReferenceColumn

DISTANCES = tuple(10.0 ** -k for k in range(1, 13))
#: the kind of each quantity: position, velocity or acceleration
KINDS = {"T": "position", "L": "position", "D(5)": "velocity", "D(6)": "velocity", "E(5)": "acceleration",
         "E(6)": "acceleration", "T(3)": "position", "X(2)": "position", "W(3)": "velocity", "V(3)": "velocity",
         "A(3)": "acceleration", "A(35)": "acceleration", "T(13)": "position", "T(14)": "position",
         "W(6)": "velocity", "W(7)": "velocity", "A(6)": "acceleration", "A(7)": "acceleration"}
VIRTUAL_COLUMNS = ("T", "L", "D(5)", "E(5)", "D(6)", "E(6)")


@dataclass
class Sweep:
    """Positions approaching one singular configuration of one linkage."""

    family: str
    group: str
    linkage: str
    columns: tuple[str, ...]
    angle_columns: frozenset
    positions: list  # (signed distance in degrees, inputs)
    compute: Callable[[str, dict], dict]
    reference: Callable[[dict], dict | None]
    other_branch: Callable[[dict, dict], bool] | None = None
    _references: dict = field(default_factory=dict, repr=False)

    def reference_at(self, index: int):
        """The reference of position ``index`` (None where the configuration is singular)."""
        if index not in self._references:
            try:
                self._references[index] = self.reference(self.positions[index][1])
            except Exception:  # noqa: BLE001 - the reference refuses singular configurations
                self._references[index] = None
        return self._references[index]

    def scales(self) -> dict:
        """Per quantity, the largest |reference| over the sweep (1 rad for angles)."""
        scale = {}
        for index in range(len(self.positions)):
            values = self.reference_at(index)
            if values is None:
                continue
            for name in self.columns:
                scale[name] = max(scale.get(name, 0.0), abs(float(values[name])))
        return {name: (1.0 if name in self.angle_columns or not scale.get(name) else scale[name])
                for name in self.columns}


@dataclass(frozen=True)
class Point:
    """What one method did at one position of a sweep."""

    distance: float
    status: str
    error: float
    detail: str = ""
    by_kind: tuple = ()  # ((kind, worst error of that kind), ...)


def evaluate(sweep: Sweep, method: str) -> list[Point]:
    """Run ``method`` at every position of ``sweep``."""
    scales = sweep.scales()
    points = []
    for index, (distance, inputs) in enumerate(sweep.positions):
        try:
            result = {k: float(v) for k, v in sweep.compute(method, inputs).items()}
        except Exception as error:  # noqa: BLE001 - a clear error is a result to record
            points.append(Point(distance, "exception", math.nan, f"{type(error).__name__}: {error}"))
            continue
        if not all(math.isfinite(result[name]) for name in sweep.columns):
            points.append(Point(distance, "nan", math.inf, "NaN or infinity returned"))
            continue
        reference = sweep.reference_at(index)
        if reference is None:
            points.append(Point(distance, "unverified", math.nan, "finite values at the singular configuration"))
            continue
        kinds: dict[str, float] = {}
        for name in sweep.columns:
            column = ReferenceColumn.from_mpf(name, [reference[name]], name in sweep.angle_columns)
            value = float(column.errors([result[name]])[0]) * column.scale / scales[name]
            kinds[KINDS[name]] = max(kinds.get(KINDS[name], 0.0), value)
        error, by_kind = max(kinds.values()), tuple(sorted(kinds.items()))
        if error > 1e-3 and sweep.other_branch is not None and sweep.other_branch(inputs, result):
            points.append(Point(distance, "wrong branch", error, "the other assembly mode", by_kind))
        else:
            points.append(Point(distance, "ok", error, "", by_kind))
    return points


def _approach(centre: float, signs=(1.0,), exact: bool = True) -> list[float]:
    """Driving angles at 10^-k deg from ``centre`` (and ``centre`` itself)."""
    angles = [(0.0, centre)] if exact else []
    for sign in signs:
        angles += [(sign * d, centre + sign * d) for d in DISTANCES]
    return angles


# --------------------------------------------------------------------------- Program 5

def _virtual_sweep(centre_deg: int) -> Sweep:
    length, velocity, acceleration = 100.0, (3.0, -4.0), (-50.0, 20.0)
    exact = {0: (1.0, 0.0), 90: (0.0, 1.0), 180: (-1.0, 0.0), 270: (0.0, -1.0)}[centre_deg]
    positions = [(0.0, {"x": length * exact[0], "y": length * exact[1]})]
    for sign in (-1.0, 1.0):
        for d in DISTANCES:
            angle = math.radians(centre_deg + sign * d)
            positions.append((sign * d, {"x": length * math.cos(angle), "y": length * math.sin(angle)}))

    def compute(method, p):
        from yaseer.linkages import virtual_link

        r = virtual_link(p["x"], p["y"], *velocity, *acceleration, method=method)
        return {"T": r.angle_deg, "L": r.length, "D(5)": r.angle_rate, "E(5)": r.angle_accel,
                "D(6)": r.length_rate, "E(6)": r.length_accel}

    def reference(p):
        from .virtual_link_reference import virtual_link_reference

        return virtual_link_reference(p["x"], p["y"], *velocity, *acceleration)

    return Sweep(f"PROG 5 near T = {centre_deg}", "PROG 5 at T = 0, 90, 180, 270", "virtual_link", VIRTUAL_COLUMNS, frozenset({"T"}),
                 positions, compute, reference)


# --------------------------------------------------------------------------- slider-crank

def _slider_sweep(family, group, e, a, b, axis, centre, signs=(-1.0, 1.0), omega=10.0) -> Sweep:
    positions = [(d, {"theta": theta}) for d, theta in _approach(centre, signs)]

    def compute(method, p):
        from yaseer.linkages import slider_crank

        r = slider_crank(e, a, b, p["theta"], omega, 0.0, axis_deg=axis, method=method)
        return {"T(3)": r.rod.degrees, "W(3)": r.rod.omega, "A(3)": r.rod.alpha,
                "X(2)": r.travel.value, "V(3)": r.travel.rate, "A(35)": r.travel.accel}

    def reference(p):
        import mpmath
        from yaseer.reference.seeds import seed001_slider_crank

        r = seed001_slider_crank([p["theta"] - axis], omega, 0.0, "open", a, b, -e, number="mpmath", dps=50)
        return {"T(3)": mpmath.mpf(r["thetaAB"][0]) + axis, "W(3)": r["omegaAB"][0], "A(3)": r["alphaAB"][0],
                "X(2)": r["xB"][0], "V(3)": r["vB"][0], "A(35)": r["aB"][0]}

    def other(p, result):
        return math.cos(math.radians(result["T(3)"] - axis)) < 0

    return Sweep(family, group, "slider_crank", SLIDER_COLUMNS, frozenset({"T(3)"}), positions, compute, reference, other)


# --------------------------------------------------------------------------- four-bar

def _fourbar_sweep(family, group, lengths, crossed, centre, signs, omega=10.0) -> Sweep:
    a, b, c, d = lengths
    branch = -1 if crossed else 1
    positions = [(dd, {"theta": theta}) for dd, theta in _approach(centre, signs)]

    def compute(method, p):
        from yaseer.linkages import fourbar

        r = fourbar(d, 0.0, a, b, c, p["theta"], omega, 0.0, branch=branch, method=method)
        return {"T(13)": r.coupler.degrees, "W(6)": r.coupler.omega, "A(6)": r.coupler.alpha,
                "T(14)": r.follower.degrees, "W(7)": r.follower.omega, "A(7)": r.follower.alpha}

    def reference(p):
        import mpmath
        from yaseer.reference.seeds import seed003_fourbar

        r = seed003_fourbar([p["theta"]], omega, 0, "right" if crossed else "left", a, b, c, d,
                            number="mpmath", dps=50)
        phi = mpmath.mpf(r["PHI"][0])
        return {"T(13)": r["BETA"][0], "W(6)": r["omega_coupler"][0], "A(6)": r["alpha_coupler"][0],
                "T(14)": phi + 180 if phi <= 0 else phi - 180, "W(7)": r["omega_follower"][0],
                "A(7)": r["alpha_follower"][0]}

    def other(p, result):
        pin = a * complex(math.cos(math.radians(p["theta"])), math.sin(math.radians(p["theta"])))
        tip = pin + b * complex(math.cos(math.radians(result["T(13)"])), math.sin(math.radians(result["T(13)"])))
        run, reach = d - pin, tip - pin
        return branch * (run.real * reach.imag - run.imag * reach.real) < 0

    mode = "crossed" if crossed else "uncrossed"
    return Sweep(f"{family}, {mode}", group, "fourbar", FOURBAR_COLUMNS, frozenset({"T(13)", "T(14)"}), positions,
                 compute, reference, other)


def seed003_limit_deg() -> float:
    """Seed 003's crank limit: |A - Bo| = b + c, cos(theta) = (a^2 + d^2 - (b + c)^2) / (2 a d)."""
    a, b, c, d = 30.0, 36.0, 36.0, 60.0
    return math.degrees(math.acos((a * a + d * d - (b + c) ** 2) / (2 * a * d)))


def seed003_half_angle_pole_deg() -> float:
    """Where seed 003's AA = AK - a(d - c)cos(theta) - cd vanishes."""
    a, b, c, d = 30.0, 36.0, 36.0, 60.0
    ak = (a * a - b * b + c * c + d * d) / 2
    return math.degrees(math.acos((ak - c * d) / (a * (d - c))))


def all_sweeps() -> list[Sweep]:
    seed003 = (30.0, 36.0, 36.0, 60.0)
    seed004 = (3.0, 5.0, 10.0, 12.0)  # seed 004 in decimetres: 0.3 + 1.2 != 0.5 + 1 in binary floats
    sweeps = [_virtual_sweep(t) for t in (0, 90, 180, 270)]
    dead = "slider-crank dead centres, axis at 0 and exactly 90"
    sweeps += [
        _slider_sweep("slider-crank dead centre theta = 0", dead, 0.0, 1.0, 3.0, 0.0, 0.0),
        _slider_sweep("slider-crank dead centre theta = 180", dead, 0.0, 1.0, 3.0, 0.0, 180.0),
        _slider_sweep("slider-crank, axis at 90: dead centre theta = 90", dead, 0.0, 1.0, 3.0, 90.0, 90.0),
        _slider_sweep("slider-crank, axis at 90: dead centre theta = 270", dead, 0.0, 1.0, 3.0, 90.0, 270.0),
        _slider_sweep("slider-crank assembly limit theta = 90", "slider-crank assembly limit", 0.5, 1.0, 1.5,
                      0.0, 90.0),
    ]
    for crossed in (False, True):
        sweeps.append(_fourbar_sweep("four-bar toggle (seed 003 crank limit)", "four-bar toggle / assembly limit",
                                     seed003, crossed, seed003_limit_deg(), (-1.0,)))
    sweeps.append(_fourbar_sweep("change-point four-bar (seed 004) theta = 180", "change point (seed 004)",
                                 seed004, True, 180.0, (-1.0, 1.0), omega=1.0))
    for crossed in (False, True):
        sweeps.append(_fourbar_sweep("half-angle pole AA = 0 (seed 003)", "half-angle pole AA = 0", seed003,
                                     crossed, seed003_half_angle_pole_deg(), (-1.0, 1.0)))
    return sweeps
