"""Benchmark: a 3,601-position cycle of each library program, scalar loop vs one array call.

Run:  PYTHONPATH=. python tests/benchmarks/linkage_speed.py [--positions N] [--repeat R] [--warmup W]

For Programs 1, 2, 3 each position gets positions, velocities, accelerations
(flexible crank) and the force analysis (masses, inertias, gravity, known loads,
crank torque unknown); Program 5 gets its full output.  Prints CPU microseconds
per position (CPU time: the machine is shared) for a Python loop of scalar calls
and for one vectorised call (the first call of each case, made in turn before
the allocator settles, and the best of R after W untimed ones once the allocator
has settled: see settle_allocator), and their ratio, all measured in this run.

Reference measured in the same run when installed: pylinkage 1.3 (with numba when
installed), the same four-bar's positions, velocities and accelerations
(``Linkage.step_fast_with_kinematics``), no forces.  Goals (issue 15): four-bar
positions, velocities, accelerations at most 0.3 us per position, with forces at
most 0.5 us, over 3,601 positions.  Numbers for more positions, in chunks, and
the peak memory: array_scaling.py.  Where OPENBLAS_CORETYPE is set, unset it for
this command alone (README, speed section).
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from yaseer.linkages import MassProps, fourbar, inverted_slider_crank, slider_crank, virtual_link


def program_1(theta):
    kin = slider_crank(0.02, 0.1, 0.35, theta, 8.0, 1.0, crank_length_rate=0.01, crank_length_accel=0.0, axis_deg=15.0)
    kin.crank_point(0.07, 25.0), kin.rod_point(0.2, 170.0)
    return kin.forces(crank=MassProps(2.0, 0.01, 0.04, -10.0), rod=MassProps(1.5, 0.03, 0.12, 8.0), piston_mass=0.7,
                      crank_point=(0.07, 25.0), rod_point=(0.2, 170.0), loads=dict(piston=20.0, rod_fx=3.0),
                      unknown="crank_torque", gravity=9.81)


def program_2(theta):
    kin = fourbar(1.2, 20.0, 0.3, 1.0, 0.8, theta, 4.0, -1.0, crank_length_rate=0.01, branch=-1)
    kin.crank_point(0.2, 30.0), kin.coupler_point(0.7, -20.0), kin.follower_point(0.5, 40.0)
    return kin.forces(crank=MassProps(3.0, 0.05, 0.1, 5.0), coupler=MassProps(2.0, 0.2, 0.4, 10.0),
                      follower=MassProps(1.0, 0.1, 0.3, -15.0), crank_point=(0.2, 30.0), coupler_point=(0.7, -20.0),
                      follower_point=(0.5, 40.0), loads=dict(follower_perpendicular=1.5), unknown="crank_torque",
                      gravity=9.81)


def program_2_kinematics_only(theta):
    kin = fourbar(1.2, 20.0, 0.3, 1.0, 0.8, theta, 4.0, -1.0, branch=-1)
    return kin.coupler_point(0.7, -20.0)


def program_3(theta):
    kin = inverted_slider_crank(0.5, 30.0, 0.25, theta, 6.0, 1.0, crank_length_rate=0.01)
    kin.crank_point(0.2, 15.0), kin.follower_point(0.6, -10.0)
    return kin.forces(crank=MassProps(2.0, 0.02, 0.1, 0.0), block_mass=0.7, block_inertia=0.004,
                      follower=MassProps(3.0, 0.4, 0.3, 5.0), follower_point=(0.6, -10.0),
                      loads=dict(follower_perpendicular=4.0), unknown="crank_torque", gravity=9.81)


def program_5(theta):
    p = (3 + np.sin(np.radians(3 * theta))) * np.exp(1j * np.radians(theta))
    return virtual_link(p.real, p.imag, -p.imag, p.real, -p.real, -p.imag)


def solve_floor(theta):
    """The floor under the force cases: one batched numpy.linalg.solve of 9x9 systems."""
    size = np.size(theta)
    matrices = np.eye(9) + 0.1 * np.sin(np.arange(81.0)).reshape(9, 9) + np.zeros((size, 1, 1))
    return np.linalg.solve(matrices, np.ones((size, 9, 1)))


CASES = {
    "PROG 1 slider-crank, pos+vel+acc+forces": program_1,
    "PROG 2 four-bar, pos+vel+acc+forces": program_2,
    "PROG 2 four-bar, pos+vel+acc only": program_2_kinematics_only,
    "PROG 3 inverted slider-crank, pos+vel+acc+forces": program_3,
    "PROG 5 virtual link": program_5,
    "floor: numpy.linalg.solve of one 9x9 system": solve_floor,
}


def best_time(function, repeat):
    best = float("inf")
    for _ in range(repeat):
        start = time.process_time()
        function()
        best = min(best, time.process_time() - start)
    return best


GOALS = {"PROG 2 four-bar, pos+vel+acc+forces": 0.5, "PROG 2 four-bar, pos+vel+acc only": 0.3}


def pylinkage_fourbar(positions: int):
    """The same four-bar in pylinkage (positions, velocities, accelerations over
    ``positions`` crank steps), or the reason it cannot be measured."""
    try:
        import pylinkage
        from pylinkage import Crank, Ground, Linkage, RRRDyad
    except ImportError:
        return "pylinkage not installed: reference skipped"
    try:
        import numba  # noqa: F401
        accelerated = "with numba"
    except ImportError:
        accelerated = "without numba"
    ground = Ground(0.0, 0.0, name="Ao")
    pivot = Ground(1.2 * math.cos(math.radians(20.0)), 1.2 * math.sin(math.radians(20.0)), name="Bo")
    crank = Crank(ground, 0.3, angular_velocity=2 * math.pi / positions, name="A")
    joint = RRRDyad(crank.output, pivot, 1.0, 0.8, name="B")
    linkage = Linkage([ground, pivot, crank, joint], name="four-bar")
    linkage.set_input_velocity(crank, 4.0, -1.0)
    label = f"pylinkage {getattr(pylinkage, '__version__', '?')} ({accelerated}), pos+vel+acc"
    return label, lambda: linkage.step_fast_with_kinematics(iterations=positions)


def settle_allocator() -> None:
    """Allocate and free one 16 MB array.  glibc's malloc then keeps arrays of a few
    hundred kB on its heap instead of mapping and unmapping pages for each (its
    dynamic mmap and trim thresholds rise with the largest block freed), as it does
    in any process that has done sizeable numpy work: without it, a cycle of
    3,601 positions spends up to half its time in page faults."""
    np.ones(2**21).sum()


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--positions", type=int, default=3601)
    parser.add_argument("--repeat", type=int, default=30)
    parser.add_argument("--warmup", type=int, default=20, help="untimed array calls before the best-of timing")
    args = parser.parse_args(argv)
    angles = np.linspace(0.0, 360.0, args.positions)
    scalar_angles = [float(angle) for angle in angles]
    first_calls = {name: best_time(lambda: case(angles), 1) for name, case in CASES.items()}
    settle_allocator()
    print(f"{args.positions} positions; loop: best of 2; array: the first call of each case before the allocator settles, then the best "
          f"of {args.repeat} after {args.warmup} untimed calls; ratio = loop / best array; CPU time")
    print(f"{'case':52s} {'loop us/pos':>12s} {'first us/pos':>13s} {'array us/pos':>13s} {'ratio':>8s}  goal")
    arrays = {}
    for name, case in CASES.items():
        loop = best_time(lambda: [case(angle) for angle in scalar_angles], 2)
        first = first_calls[name]
        for _ in range(args.warmup):
            case(angles)
        array = best_time(lambda: case(angles), args.repeat)
        per_loop, per_first, per_array = (1e6 * t / args.positions for t in (loop, first, array))
        arrays[name] = per_array
        goal = GOALS.get(name)
        verdict = "" if goal is None else f"<= {goal:g} us: {'met' if per_array <= goal else 'NOT met'}"
        print(f"{name:52s} {per_loop:12.1f} {per_first:13.3f} {per_array:13.3f} {loop / array:8.0f}  {verdict}")
    reference = pylinkage_fourbar(args.positions)
    if isinstance(reference, str):
        print(reference)
        return 0
    label, run = reference
    for _ in range(3):
        run()  # numba compiles on the first call
    per_reference = 1e6 * best_time(run, args.repeat) / args.positions
    print(f"{label:52s} {'':12s} {'':13s} {per_reference:13.3f}")
    for name in GOALS:
        print(f"  {name}: {per_reference / arrays[name]:.2f}x pylinkage's speed (pylinkage computes no forces)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
