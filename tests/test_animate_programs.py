"""The recorder reads the real library programs' outputs back into consistent joints.

The library programs (yaseer.binding) run on a stand-in machine through the
recorder.  Each snapshot builds joints from the angles and lengths the program
was given and returned; the checks here are the constraints the program did
not get to see in that form: a slider-crank's piston on its axis and the
four-bar loop closing on Bo (|B - Bo| = follower length).  A wrong sign
convention in either the program or the reading breaks them.
"""

from __future__ import annotations

import math

import pytest

from test_animate import StandInMachine
from yaseer import binding
from yaseer.animation import Recorder, distance, polar

ANGLES = [0.1 + 15.0 * k for k in range(24)]


def recorded(setup, area, angles=ANGLES):
    """Call ``area`` once per crank angle after ``setup(machine, angle)``; one frame each."""
    recorder = Recorder()
    machine = StandInMachine()
    binding.install(machine)
    machine.area_hooks.append(recorder.hook)
    for angle in angles:
        setup(machine, angle)
        machine.gosub_prog(area)
        recorder.line_printed(f"{angle}")
    return [frame.snapshots[0] for frame in recorder.finish()], machine


def _distance_to_line(point, through, angle_deg):
    ux, uy = polar(1.0, angle_deg)
    return abs((point[0] - through[0]) * uy - (point[1] - through[1]) * ux)


@pytest.mark.parametrize("e, phi", [(25.0, 0.1), (-40.0, 30.0), (150.0, 90.1)])
def test_slider_crank_piston_stays_on_its_axis(e, phi):
    def setup(machine, angle):
        L, T = machine.array("L"), machine.array("T")
        L[1], L[2], L[3], T[2], T[4] = e, 75.0, 300.0, angle, phi

    snapshots, _ = recorded(setup, 1)
    for snapshot in snapshots:
        crank, rod = snapshot.bars
        assert distance(crank.end, (0, 0)) == pytest.approx(75.0)
        assert distance(rod.start, rod.end) == pytest.approx(300.0)
        (slider,) = snapshot.sliders
        assert _distance_to_line(slider.centre, slider.axis, phi) == pytest.approx(0.0, abs=1e-9)
        # the piston is ahead of the crank pin along the axis direction
        ux, uy = polar(1.0, phi)
        assert (rod.end[0] - rod.start[0]) * ux + (rod.end[1] - rod.start[1]) * uy > 0


@pytest.mark.parametrize("crossed", [0.0, 1.0])
def test_four_bar_loop_closes_on_the_fixed_pivot(crossed):
    def setup(machine, angle):
        L, T, R, H = (machine.array(n) for n in "LTRH")
        L[10], L[11], T[11], L[12], L[13], L[14], T[12] = crossed, 100.0, 0.0, 40.0, 120.0, 80.0, angle
        R[11], H[11] = 60.0, 30.0

    snapshots, _ = recorded(setup, 2)
    for snapshot in snapshots:
        crank, coupler, follower = snapshot.bars
        assert distance(follower.start, follower.end) == pytest.approx(80.0)
        assert follower.end == pytest.approx((100.0, 0.0))
        # the coupler point is R(11) from A, H(11) from the direction A->B
        point = next(p for p in snapshot.points if p.label.endswith("X(4),Y(4)"))
        assert distance(point.position, coupler.start) == pytest.approx(60.0)
        heading = math.degrees(math.atan2(coupler.end[1] - coupler.start[1], coupler.end[0] - coupler.start[0]))
        expected = polar(60.0, heading + 30.0)
        assert point.position == pytest.approx((coupler.start[0] + expected[0], coupler.start[1] + expected[1]))


def test_inverted_slider_crank_block_sits_on_the_follower():
    def setup(machine, angle):
        L, T = machine.array("L"), machine.array("T")
        L[6], T[6], L[7], T[7] = 5.7, -74.7, 2.5, angle

    snapshots, machine = recorded(setup, 3)
    for snapshot in snapshots:
        (block,) = snapshot.sliders
        pivot = snapshot.ground[1]
        assert _distance_to_line(block.centre, pivot, block.angle_deg) == pytest.approx(0.0, abs=1e-9)
        assert distance(snapshot.bars[0].end, (0, 0)) == pytest.approx(2.5)


def test_virtual_link_snapshot_ends_at_the_moving_point():
    def setup(machine, angle):
        X, Y = machine.array("X"), machine.array("Y")
        X[10], Y[10] = polar(3.0, angle)

    snapshots, machine = recorded(setup, 5)
    for angle, snapshot in zip(ANGLES, snapshots):
        assert snapshot.bars[0].end == pytest.approx(polar(3.0, angle))
        assert snapshot.bars[0].virtual
        assert snapshot.crank_angle == pytest.approx(angle % 360.0)
