"""The bench cases: the seeds' linkages and the paper's mechanisms over full cycles.

A :class:`Case` sweeps the methods of one linkage (``slider_crank``, ``fourbar``
or ``virtual_link``) over the positions of a cycle.  ``compute(methods,
angles, options)`` runs the case in Python with a method per linkage (the others
at their defaults); ``angles`` is a float (one position) or an array (one
vectorised call): the same code serves both ways of running.  ``listing(angles)``
gives a BASIC calling listing printing the same quantities in the same order
(the interpreter way).  ``reference(angles)`` gives the 50-digit values from
:mod:`yaseer.reference` (independent multibody models, Newton-polished).

Cases (angles in degrees; ``dense`` is the bench default, ``quick`` for tests;
the paper's mechanisms use their listing's own grid for both):

* seed 001's offset slider-crank (AO = 3, AB = 8, offset 2, omega = -15, alpha = -10);
* seed 003's four-bar (30, 36, 36, 60; omega = 10), both assembly modes, over the
  crank range where it assembles (|theta| <= 100 deg of its 100.95);
* seed 004's change-point four-bar (0.3, 0.5, 1, 1.2), the mode of its FindRoot
  answer (crossed), a full turn at odd degrees (1 deg short of the change point);
* a crank-rocker whose coupler swings past 90 deg from the fixed link (a = 1, b = 3,
  c = 3, d = 2): where seed 003's printed ASIN returns the wrong coupler angle;
* Program 5 alone: a point on an ellipse around Ao (all four quadrants);
* the paper's Examples 1-5 as chains of programs (slider-crank or four-bar
  methods, and the virtual link's), giving the listing's printed columns
  (Examples 2 and 5: forces, through the linkages' ``forces``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

from .measure import ReferenceColumn

#: the paper's universal DIM statement (Example 1, line 2)
DIM_LINE = ("2 CLEAR: DIM F(46), M(11), R(19), H(24), A(53), L(20), T(25), W(10), Z(5), C(14), "
            "U(4), D(6), E(6), X(11), Y(11), V(21), Q(4), N(3), I(11), P(4)")


@dataclass
class Case:
    """One mechanism over a cycle, whose ``linkage`` methods are compared."""

    name: str
    linkage: str
    columns: tuple[str, ...]
    angle_columns: frozenset
    dense: np.ndarray
    quick: np.ndarray
    reference_values: Callable[[np.ndarray], dict]
    compute: Callable | None
    listing: Callable[[np.ndarray], str] | None
    other_branch: Callable[[np.ndarray, dict], bool] | None = None
    reference_key: str = ""
    single: bool = True  # one program call per position (the chart's times come from these)
    model_note: str = ""  # why the listing and the reference differ whatever the method (then not charted)

    def reference(self, angles) -> list[ReferenceColumn]:
        """The 50-digit reference at ``angles`` (computed once per mechanism and set of angles)."""
        key = (self.reference_key or self.name, tuple(np.asarray(angles, float).tolist()))
        if key not in _REFERENCES:
            values = self.reference_values(np.asarray(angles, float))
            _REFERENCES[key] = [ReferenceColumn.from_mpf(name, values[name], name in self.angle_columns)
                                for name in self.columns]
        return _REFERENCES[key]


_REFERENCES: dict = {}


def _data_lines(angles, first_line: int = 1000) -> list[str]:
    """DATA statements holding ``angles`` (full precision), ten per line."""
    items = [repr(float(a)) for a in angles]
    return [f"{first_line + k} DATA " + ", ".join(items[i:i + 10]) for k, i in enumerate(range(0, len(items), 10))]


def _loop_listing(angles, body: str, printed: str) -> str:
    """A calling listing: READ each crank angle Q from DATA, run ``body``, PRINT ``printed``."""
    lines = [DIM_LINE, f"10 FOR K = 1 TO {len(angles)}: READ Q", f"20 {body}", f"30 PRINT Q; {printed}: NEXT K: END"]
    return "\n".join(lines + _data_lines(angles)) + "\n"


# --------------------------------------------------------------------------- seed 001

SLIDER_COLUMNS = ("T(3)", "W(3)", "A(3)", "X(2)", "V(3)", "A(35)")


def _seed001_compute(methods, angles, options):
    from yaseer.linkages import slider_crank

    r = slider_crank(-2.0, 3.0, 8.0, angles, -15.0, -10.0, method=methods.get("slider_crank"), **options)
    return {"T(3)": r.rod.degrees, "W(3)": r.rod.omega, "A(3)": r.rod.alpha,
            "X(2)": r.travel.value, "V(3)": r.travel.rate, "A(35)": r.travel.accel}


def _seed001_reference(angles):
    from yaseer.reference.seeds import seed001_slider_crank

    r = seed001_slider_crank(list(angles), number="mpmath", dps=50)
    return {"T(3)": r["thetaAB"], "W(3)": r["omegaAB"], "A(3)": r["alphaAB"],
            "X(2)": r["xB"], "V(3)": r["vB"], "A(35)": r["aB"]}


def _slider_behind(axis_deg):
    def other(angles, results):
        return bool(np.any(np.cos(np.radians(np.asarray(results["T(3)"]) - axis_deg)) < 0))
    return other


SEED001 = Case(
    "seed 001 slider-crank", "slider_crank", SLIDER_COLUMNS, frozenset({"T(3)"}),
    np.arange(0.5, 360.0, 2.0), np.arange(0.5, 360.0, 30.0),
    _seed001_reference, _seed001_compute,
    lambda angles: _loop_listing(
        angles, "T(2) = Q: L(1) = -2: L(2) = 3: L(3) = 8: T(4) = 0: W(2) = -15: A(2) = -10: R(4) = 0: GOSUB PROG 1",
        "T(3); W(3); A(3); X(2); V(3); A(35)"),
    _slider_behind(0.0),
)


# --------------------------------------------------------------------------- four-bars (seeds 003, 004)

FOURBAR_COLUMNS = ("T(13)", "W(6)", "A(6)", "T(14)", "W(7)", "A(7)")


def _fourbar_case(name, lengths, omega, crossed, dense, quick):
    """A four-bar with its fixed link along +x: lengths = (a, b, c, d)."""
    a, b, c, d = lengths
    branch = -1 if crossed else 1

    def compute(methods, angles, options):
        from yaseer.linkages import fourbar

        r = fourbar(d, 0.0, a, b, c, angles, omega, 0.0, branch=branch, method=methods.get("fourbar"), **options)
        return {"T(13)": r.coupler.degrees, "W(6)": r.coupler.omega, "A(6)": r.coupler.alpha,
                "T(14)": r.follower.degrees, "W(7)": r.follower.omega, "A(7)": r.follower.alpha}

    def reference(angles):
        import mpmath
        from yaseer.reference.seeds import seed003_fourbar

        r = seed003_fourbar(list(angles), omega=omega, alpha=0, branch="right" if crossed else "left",
                            a=a, b=b, c=c, d=d, number="mpmath", dps=50)
        follower = [mpmath.mpf(p) + 180 if p <= 0 else mpmath.mpf(p) - 180 for p in r["PHI"]]
        return {"T(13)": r["BETA"], "W(6)": r["omega_coupler"], "A(6)": r["alpha_coupler"],
                "T(14)": follower, "W(7)": r["omega_follower"], "A(7)": r["alpha_follower"]}

    def other(angles, results):
        theta = np.radians(np.asarray(angles, float))
        pin = a * np.exp(1j * theta)
        tip = pin + b * np.exp(1j * np.radians(np.asarray(results["T(13)"], float)))
        run, reach = d - pin, tip - pin
        side = run.real * reach.imag - run.imag * reach.real
        return bool(np.any(branch * side < 0))

    listing = lambda angles: _loop_listing(  # noqa: E731
        angles, f"T(12) = Q: L(11) = {d}: T(11) = 0: L(12) = {a}: L(13) = {b}: L(14) = {c}: W(5) = {omega}: "
                f"A(5) = 0: L(10) = {1 if crossed else 0}: GOSUB PROG 2",
        "T(13); W(6); A(6); T(14); W(7); A(7)")
    return Case(name, "fourbar", FOURBAR_COLUMNS, frozenset({"T(13)", "T(14)"}), dense, quick,
                reference, compute, listing, other)


SEED003_UNCROSSED = _fourbar_case("seed 003 four-bar, uncrossed", (30.0, 36.0, 36.0, 60.0), 10.0, False,
                                  np.arange(-100.0, 100.5, 2.0), np.arange(-90.0, 91.0, 30.0))
SEED003_CROSSED = _fourbar_case("seed 003 four-bar, crossed", (30.0, 36.0, 36.0, 60.0), 10.0, True,
                                np.arange(-100.0, 100.5, 2.0), np.arange(-90.0, 91.0, 30.0))
STEEP_COUPLER = _fourbar_case("four-bar with the coupler past 90 deg", (1.0, 3.0, 3.0, 2.0), 1.0, False,
                              np.arange(0.5, 360.0, 2.0), np.arange(0.5, 360.0, 30.0))
SEED004 = _fourbar_case("seed 004 change-point four-bar", (0.3, 0.5, 1.0, 1.2), 1.0, True,
                        np.arange(1.0, 360.0, 2.0), np.arange(15.0, 360.0, 30.0))


# --------------------------------------------------------------------------- Program 5 alone

ELLIPSE = (60.0, 40.0, 25.0, 3.0)  # semi-axes, centre offset along x, angular speed (rad/s)


def ellipse_point(angles):
    """A point on an ellipse around Ao: p = (a cos t + c, b sin t), t at ``angles`` deg, dt/dt = w.

    Returns x, y, vx, vy, ax, ay (floats or arrays); its polar angle runs through
    every quadrant (near but not on the axes: the sweeps of ``yaseer stability``
    go onto them).
    """
    a, b, c, w = ELLIPSE
    t = np.radians(np.asarray(angles, float))
    return (a * np.cos(t) + c, b * np.sin(t), -a * w * np.sin(t), b * w * np.cos(t),
            -a * w * w * np.cos(t), -b * w * w * np.sin(t))


VIRTUAL_COLUMNS = ("T", "L", "D(5)", "E(5)", "D(6)", "E(6)")


def _ellipse_compute(methods, angles, options):
    from yaseer.linkages import virtual_link

    r = virtual_link(*ellipse_point(angles), method=methods.get("virtual_link"), **options)
    return {"T": r.angle_deg, "L": r.length, "D(5)": r.angle_rate, "E(5)": r.angle_accel,
            "D(6)": r.length_rate, "E(6)": r.length_accel}


def _ellipse_reference(angles):
    from .virtual_link_reference import virtual_link_reference

    rows = [virtual_link_reference(*(float(v) for v in ellipse_point(angle))) for angle in angles]
    return {name: [row[name] for row in rows] for name in VIRTUAL_COLUMNS}


def _ellipse_listing(angles):
    """READ the point's position, velocity and acceleration from DATA, GOSUB PROG 5."""
    values = np.array(ellipse_point(np.asarray(angles, float))).T
    lines = [DIM_LINE, f"10 FOR K = 1 TO {len(angles)}: READ Q, X(10), Y(10), V(17), V(18), A(49), A(50)",
             "20 GOSUB PROG 5", "30 PRINT Q; T; L; D(5); E(5); D(6); E(6): NEXT K: END"]
    items = [repr(float(v)) for angle, row in zip(angles, values) for v in (angle, *row)]
    lines += [f"{1000 + k} DATA " + ", ".join(items[i:i + 7]) for k, i in enumerate(range(0, len(items), 7))]
    return "\n".join(lines) + "\n"


ELLIPSE_CASE = Case("virtual link on an ellipse", "virtual_link", VIRTUAL_COLUMNS, frozenset({"T"}),
                    np.arange(0.5, 360.0, 2.0), np.arange(0.5, 360.0, 30.0), _ellipse_reference,
                    _ellipse_compute, _ellipse_listing)


# --------------------------------------------------------------------------- the paper's mechanisms

def _example1(methods, angles, options):
    """Example 1: PROG 1 (A o A B C), PROG 5 (virtual link Ao->B), PROG 1 (Ao B D)."""
    from yaseer.linkages import slider_crank, virtual_link

    sc = methods.get("slider_crank")
    first = slider_crank(25.0, 75.0, 300.0, angles, 25.0, 0.0, axis_deg=0.1, method=sc,
                         **options.get("slider_crank", {}))
    link = _virtual(virtual_link, first.rod_point(150.0, 0.0), methods, options)
    second = slider_crank(150.0, link.length, 150.0, link.angle_deg, link.angle_rate, link.angle_accel,
                          crank_length_rate=link.length_rate, crank_length_accel=link.length_accel,
                          axis_deg=90.1, method=sc, **options.get("slider_crank", {}))
    piston = second.rod_point(0.0, 0.0)
    return {"QQ": np.asarray(angles, float) + 0 * piston.pos.real, "Y(2)": piston.pos.imag,
            "V(4)": piston.vel.imag, "A(36)": piston.acc.imag}


def _example3(methods, angles, options):
    """Example 3: PROG 1 (AoAB, C on the rod), PROG 5 (Ao->C), PROG 3 (AoCCoD)."""
    from yaseer.linkages import inverted_slider_crank, slider_crank, virtual_link

    first = slider_crank(0.0, 2.5, 6.0, angles, 30.0, 0.0, axis_deg=-90.1, method=methods.get("slider_crank"),
                         **options.get("slider_crank", {}))
    link = _virtual(virtual_link, first.rod_point(7.5, 0.0), methods, options)
    fisc = inverted_slider_crank(math.hypot(1.5, 5.5), math.degrees(math.atan(-5.5 / 1.5)), link.length,
                                 link.angle_deg, link.angle_rate, link.angle_accel,
                                 crank_length_rate=link.length_rate, crank_length_accel=link.length_accel)
    return {"T(2)": np.asarray(angles, float) + 0 * fisc.follower.omega, "T(9)": fisc.follower.degrees,
            "W(4)": fisc.follower.omega, "A(4)": fisc.follower.alpha, "X(7)": fisc.follower_point(3.5, 180.0).pos.real}


def _example4(methods, angles, options):
    """Example 4: PROG 2 (AoABBo, D on the coupler), PROG 5 (Ao->D), PROG 2 (AoDHHo, crossed)."""
    from yaseer.linkages import fourbar, virtual_link

    fb = methods.get("fourbar")
    first = fourbar(math.hypot(26.5, 10.0), math.degrees(math.atan(-10 / 26.5)), 6.5, 28.0, 14.0, angles,
                    35.0, 0.0, branch=1, method=fb, **options.get("fourbar", {}))
    link = _virtual(virtual_link, first.coupler_point(math.hypot(15.0, 5.5), -math.degrees(math.atan(5.5 / 15))),
                    methods, options)
    second = fourbar(25.0, 90.1, link.length, 31.5, 17.5, link.angle_deg, link.angle_rate, link.angle_accel,
                     crank_length_rate=link.length_rate, crank_length_accel=link.length_accel, branch=-1,
                     method=fb, **options.get("fourbar", {}))
    point = second.coupler_point(11.5, 180.0)
    return {"QQ": np.asarray(angles, float) + 0 * point.pos.real, "W(6)": second.coupler.omega,
            "A(6)": second.coupler.alpha, "V(7)": point.vel.real, "A(39)": point.acc.real}


def _example2(methods, angles, options):
    """Example 2 (corrected listing): PROG 1 on AoABC, PROG 5 (Ao->C), PROG 1 on AoCD with
    forces (P = 650 v|v| on the plunger), PROG 1 on AoABC with the joint force at C."""
    from yaseer.linkages import slider_crank, virtual_link

    sc, extra = methods.get("slider_crank"), options.get("slider_crank", {})

    def first():  # GOSUB 100: GOSUB PROG 1
        return slider_crank(0.0, 0.021, 0.032, angles, -8.0, 0.0, axis_deg=0.1, method=sc, **extra)

    link = _virtual(virtual_link, first().rod_point(0.029, 180.0), methods, options)
    second = slider_crank(0.08, link.length, 0.054, link.angle_deg, link.angle_rate, link.angle_accel,
                          crank_length_rate=link.length_rate, crank_length_accel=link.length_accel,
                          axis_deg=90.1, method=sc, **extra)
    v4 = second.rod_point(0.0, 180.0).vel.imag
    plunger = second.forces(rod_point=(0.0, 180.0), loads={"piston": 650.0 * v4 * np.abs(v4)},
                            unknown="crank_torque")
    at_c = plunger.reactions["crank_on_rod"]  # F(5) + i F(6): crank AoC on rod CD at C
    result = first().forces(rod_point=(0.029, 180.0), loads={"rod_fx": -at_c.real, "rod_fy": -at_c.imag},
                            unknown="crank_torque")
    return {"QQ": np.asarray(angles, float) + 0 * v4, "U(1)": result.value,
            "N(1)": result.reactions["wall_on_piston"], "SQR(F(3)^2+F(4)^2)": np.abs(result.reactions["ground_on_crank"])}


def _example5(methods, angles, options):
    """Example 5 (corrected listing): PROG 2 on AoABBo, PROG 5 (Ao->C = B), PROG 2 on AoCDDo
    with forces (the crushing force on the jaw), PROG 2 on AoABBo with the joint force at C."""
    from yaseer.linkages import MassProps, fourbar, virtual_link

    fb, extra = methods.get("fourbar"), options.get("fourbar", {})

    def first():  # GOSUB 5100: GOSUB PROG 2
        return fourbar(math.hypot(0.85, 1.25), math.degrees(math.atan(1.25 / -0.85)) + 180, 0.075, 1.2, 0.85,
                       angles, -22.0, 0.0, branch=-1, method=fb, **extra)

    link = _virtual(virtual_link, first().coupler_point(1.2, 0.0), methods, options)
    second = fourbar(math.hypot(1.0, 0.75), math.degrees(math.atan(-1 / 0.75)), link.length, 1.2, 2.45,
                     link.angle_deg, link.angle_rate, link.angle_accel, crank_length_rate=link.length_rate,
                     crank_length_accel=link.length_accel, branch=1, method=fb, **extra)
    t14 = second.follower.degrees
    crushing = np.where(second.follower.omega < 0, 500.0 / (t14 + 100.5) ** 3, 0.0)
    push = crushing * np.exp(1j * np.radians(t14 - 90.0))  # F(35) + i F(36), line 5050
    jaw = second.forces(coupler=MassProps(35.0, 28.0, 0.4, 0.0), follower=MassProps(180.0, 435.0, 1.5, 9.0),
                        coupler_point=(0.0, 0.0), follower_point=(2.5, 18.0),
                        loads={"follower_fx": push.real, "follower_fy": push.imag}, unknown="crank_torque")
    at_c = jaw.reactions["crank_on_coupler"]  # F(23) + i F(24)
    crank = first().forces(crank=MassProps(200.0, 156.0, 0.0, 0.0), coupler=MassProps(30.0, 18.0, 0.5, 0.0),
                           follower=MassProps(15.0, 3.7, 0.35, 0.0), coupler_point=(1.2, 0.0),
                           follower_point=(2.5, 18.0), loads={"coupler_fx": -at_c.real, "coupler_fy": -at_c.imag},
                           unknown="crank_torque")
    return {"QQ": np.asarray(angles, float) + 0 * t14, "U(2)": crank.value,
            "SQR(F(27)^2+F(28)^2)": np.abs(crank.reactions["ground_on_follower"]),
            "SQR(F(21)^2+F(22)^2)": np.abs(crank.reactions["ground_on_crank"])}


def _virtual(virtual_link, point, methods, options):
    return virtual_link(point.pos.real, point.pos.imag, point.vel.real, point.vel.imag, point.acc.real,
                        point.acc.imag, method=methods.get("virtual_link"), **options.get("virtual_link", {}))


def _paper_reference(number):
    def reference(angles):
        from yaseer.reference.paper_mechanisms import COLUMNS, example_columns

        table = example_columns(number, list(angles), number="mpmath", dps=50)
        return {name: list(table[:, k]) for k, name in enumerate(COLUMNS[number])}
    return reference


def _paper_listing(number):
    """The example's corrected listing with its FOR loop stepping as ``angles`` do."""
    def listing(angles):
        from .listings import paper_listing_over

        return paper_listing_over(number, round(abs(float(angles[1] - angles[0])), 6))
    return listing


def _options_for(linkage, compute):
    """Wrap a chain so that ``options`` (keyword arguments) reach only the linkage under test."""
    def wrapped(methods, angles, options):
        return compute(methods, angles, {linkage: options} if options else {})
    return wrapped


EXAMPLE2_NOTE = ("the listing's P(1) = 650*V(4)^2 uses the vertical velocity, the reference the velocity along "
                 "the 90.1 deg axis: a factor sin^2(90.1 deg) = 1 - 3.05e-6 (listings/ERRATA.md)")


def _paper_case(number, linkage, compute, angle_columns, dense, quick):
    from yaseer.reference.paper_mechanisms import COLUMNS

    return Case(f"paper Example {number} ({linkage.replace('_', ' ')})", linkage, COLUMNS[number],
                frozenset(angle_columns), dense, quick, _paper_reference(number),
                None if compute is None else _options_for(linkage, compute), _paper_listing(number),
                reference_key=f"paper Example {number}", single=False,
                model_note=EXAMPLE2_NOTE if number == 2 else "")


def _grids(number):
    """(default, quick) crank angles of Example ``number``: both its FOR loop as printed.

    The reference of a paper mechanism costs about 0.1 s a position (a multibody
    model polished at 50 digits), so the bench keeps the listing's own grid (19
    or 25 positions: the rows of the paper's table).
    """
    from .listings import example_loop, for_loop_angles

    start, stop, step = example_loop(number)
    angles = for_loop_angles(start, stop, step)
    return angles, angles


def paper_cases() -> list[Case]:
    """The paper's five mechanisms, each once per linkage whose methods it can compare."""
    return [
        _paper_case(1, "slider_crank", _example1, (), *_grids(1)),
        _paper_case(1, "virtual_link", _example1, (), *_grids(1)),
        _paper_case(2, "slider_crank", _example2, (), *_grids(2)),
        _paper_case(2, "virtual_link", _example2, (), *_grids(2)),
        _paper_case(3, "slider_crank", _example3, ("T(9)",), *_grids(3)),
        _paper_case(3, "virtual_link", _example3, ("T(9)",), *_grids(3)),
        _paper_case(4, "fourbar", _example4, (), *_grids(4)),
        _paper_case(4, "virtual_link", _example4, (), *_grids(4)),
        _paper_case(5, "fourbar", _example5, (), *_grids(5)),
        _paper_case(5, "virtual_link", _example5, (), *_grids(5)),
    ]


def all_cases() -> list[Case]:
    """Every bench case: the seeds' linkages, then the paper's mechanisms."""
    return [SEED001, SEED003_UNCROSSED, SEED003_CROSSED, SEED004, STEEP_COUPLER, ELLIPSE_CASE, *paper_cases()]
