"""The binding: GOSUB PROG n reads the contract's inputs, writes exactly its outputs.

Run with a stand-in machine (tests/test_binding_fake.py) implementing the machine
API the binding uses.  Output values are compared with the numerics (tested
against independent references elsewhere) through the contract's element
numbers written out here, and through a virtual-work check on elements alone.
"""

from __future__ import annotations

import numpy as np
import pytest

from test_binding_fake import PAPER_DIMS, FakeMachine
from yaseer.basic.errors import DIVISION_BY_ZERO, ILLEGAL_FUNCTION_CALL, SUBSCRIPT_OUT_OF_RANGE, BasicError
from yaseer.binding import install
from yaseer.linkages import MassProps, fourbar, inverted_slider_crank, slider_crank, virtual_link

SENTINEL = 12345.0


def machine(methods=None, dims=PAPER_DIMS):
    m = FakeMachine(dims)
    install(m, methods)
    return m


def fill_outputs(m, elements):
    """Pre-set every output element to a sentinel so each write is visible."""
    for name, index in elements:
        m.array(name)[index] = SENTINEL


def changed(before, after):
    arrays_before, scalars_before = before
    arrays_after, scalars_after = after
    diff = set()
    for name, values in arrays_after.items():
        old = arrays_before.get(name, [0.0] * len(values))
        diff |= {(name, i) for i, (a, b) in enumerate(zip(old, values)) if a != b}
    diff |= {name for name, value in scalars_after.items() if scalars_before.get(name, 0.0) != value}
    return diff


def run_and_check(m, area, expected: dict):
    """Call ``area``; every expected element is written with its value, nothing else changes."""
    fill_outputs(m, [key for key in expected if isinstance(key, tuple)])
    before = m.snapshot()
    m.call(area)
    after = m.snapshot()
    for key, value in expected.items():
        actual = m.array(key[0])[key[1]] if isinstance(key, tuple) else m.scalar(key)
        assert actual == pytest.approx(float(value), rel=1e-12, abs=1e-12), key
    assert changed(before, after) <= set(expected)
    return m


def point_elements(motion, xs, ys, vs, accs):
    p, v, a = (complex(value) for value in motion)
    return {xs: p.real, ys: p.imag, vs[0]: v.real, vs[1]: v.imag, accs[0]: a.real, accs[1]: a.imag}


def test_install_binds_areas_1_2_3_5():
    m = machine()
    assert sorted(m.areas) == [1, 2, 3, 5] and all(callable(area) for area in m.areas.values())


def test_program_1_matches_seed_001_through_the_elements():
    m = machine()
    m.set(L={1: -2, 2: 3, 3: 8}, T={2: -30, 4: 0}, W={2: -15}, A={2: -10})
    m.call(1)
    assert m.array("X")[2] == pytest.approx(9.79, abs=0.005)
    assert m.array("V")[3] == pytest.approx(-41.46, abs=0.005)
    assert m.array("W")[3] == pytest.approx(5.42, abs=0.005)
    assert m.array("A")[35] == pytest.approx(-709.1, abs=0.05)
    assert m.array("A")[3] == pytest.approx(-29.03, abs=0.005)


P1_INPUTS = dict(L={1: 0.02, 2: 0.1, 3: 0.35}, T={2: 37.0, 4: 15.0}, W={2: -8.0}, A={2: 2.0}, D={0: 0.3}, E={0: -1.0},
                 R={1: 0.07, 2: 0.04, 3: 0.12, 4: 0.2}, H={1: 25.0, 2: -10.0, 3: 8.0, 4: 170.0},
                 M={2: 2.0, 3: 1.5, 4: 0.7}, I={2: 0.01, 3: 0.03}, F={0: 1.0, 1: -2.0, 2: 3.0, 7: 4.0, 8: -5.0, 9: 6.0},
                 U={1: 0.5}, P={1: 20.0})
P1_LOADS = dict(crank_fx=1.0, crank_fy=-2.0, crank_perpendicular=3.0, crank_torque=0.5, rod_fx=4.0, rod_fy=-5.0,
                rod_perpendicular=6.0, piston=20.0)
P1_UNKNOWN = {1: ("crank_torque", ("U", 1)), 2: ("crank_perpendicular", ("F", 2)),
              3: ("rod_perpendicular", ("F", 9)), 4: ("piston", ("P", 1))}


def p1_expected(forces_q=None, gravity=0.0):
    kin = slider_crank(0.02, 0.1, 0.35, 37.0, -8.0, 2.0, crank_length_rate=0.3, crank_length_accel=-1.0, axis_deg=15.0)
    expected = {("T", 3): kin.rod.degrees, ("W", 3): kin.rod.omega, ("A", 3): kin.rod.alpha,
                ("A", 10): kin.crank_point(0.04, -10.0).acc.real, ("A", 11): kin.crank_point(0.04, -10.0).acc.imag}
    expected |= point_elements(kin.crank_point(0.07, 25.0), ("X", 1), ("Y", 1), (("V", 1), ("V", 2)), (("A", 33), ("A", 34)))
    expected |= point_elements(kin.rod_point(0.2, 170.0), ("X", 2), ("Y", 2), (("V", 3), ("V", 4)), (("A", 35), ("A", 36)))
    if forces_q is not None:
        name, element = P1_UNKNOWN[forces_q]
        loads = {k: v for k, v in P1_LOADS.items() if k != name}
        r = kin.forces(crank=MassProps(2.0, 0.01, 0.04, -10.0), rod=MassProps(1.5, 0.03, 0.12, 8.0), piston_mass=0.7,
                       crank_point=(0.07, 25.0), rod_point=(0.2, 170.0), loads=loads, unknown=name, gravity=gravity)
        expected[element] = r.value
        for reaction, (x, y) in (("ground_on_crank", (("F", 3), ("F", 4))), ("crank_on_rod", (("F", 5), ("F", 6))),
                                 ("rod_on_piston", (("F", 10), ("F", 11)))):
            expected[x], expected[y] = complex(r.reactions[reaction]).real, complex(r.reactions[reaction]).imag
        expected[("N", 1)] = r.reactions["wall_on_piston"]
    return expected


def test_program_1_writes_its_kinematic_outputs_and_nothing_else():
    m = machine()
    m.set(**P1_INPUTS, Z={1: 0}, Q={1: 1})
    run_and_check(m, 1, p1_expected())


@pytest.mark.parametrize("q", [1, 2, 3, 4])
@pytest.mark.parametrize("gravity", [0.0, 9.81])
def test_program_1_forces_for_every_q(q, gravity):
    m = machine()
    m.set(**P1_INPUTS, Z={1: 2}, Q={1: q}, G=gravity)
    run_and_check(m, 1, p1_expected(q, gravity))


P2_INPUTS = dict(L={10: 1, 11: 1.2, 12: 0.3, 13: 1.0, 14: 0.8}, T={11: 20.0, 12: 75.0}, W={5: 4.0}, A={5: -1.0},
                 D={2: 0.1}, E={2: 0.2}, R={8: 0.1, 9: 0.2, 10: 0.4, 11: 0.7, 12: 0.3, 13: 0.5},
                 H={9: 30.0, 10: 5.0, 11: -20.0, 12: 10.0, 13: 40.0, 14: -15.0}, M={6: 3.0, 7: 2.0, 8: 1.0},
                 I={6: 0.05, 7: 0.2, 8: 0.1},
                 F={29: 1.0, 30: 2.0, 31: 3.0, 32: -1.0, 33: 4.0, 34: 2.5, 35: 0.5, 36: -0.7, 37: 1.5}, U={2: 0.8})
P2_LOADS = dict(crank_fx=1.0, crank_fy=2.0, crank_perpendicular=3.0, crank_torque=0.8, coupler_fx=-1.0, coupler_fy=4.0,
                coupler_perpendicular=2.5, follower_fx=0.5, follower_fy=-0.7, follower_perpendicular=1.5)
P2_UNKNOWN = {1: ("crank_torque", ("U", 2)), 2: ("crank_perpendicular", ("F", 31)),
              3: ("coupler_perpendicular", ("F", 34)), 4: ("follower_perpendicular", ("F", 37))}


def p2_expected(forces_q=None, gravity=0.0, branch=-1):
    kin = fourbar(1.2, 20.0, 0.3, 1.0, 0.8, 75.0, 4.0, -1.0, crank_length_rate=0.1, crank_length_accel=0.2,
                  branch=branch)
    expected = {("T", 13): kin.coupler.degrees, ("W", 6): kin.coupler.omega, ("A", 6): kin.coupler.alpha,
                ("T", 14): kin.follower.degrees, ("W", 7): kin.follower.omega, ("A", 7): kin.follower.alpha}
    expected |= point_elements(kin.crank_point(0.2, 30.0), ("X", 3), ("Y", 3), (("V", 5), ("V", 6)), (("A", 37), ("A", 38)))
    expected |= point_elements(kin.coupler_point(0.7, -20.0), ("X", 4), ("Y", 4), (("V", 7), ("V", 8)),
                               (("A", 39), ("A", 40)))
    expected |= point_elements(kin.follower_point(0.5, 40.0), ("X", 5), ("Y", 5), (("V", 9), ("V", 10)),
                               (("A", 41), ("A", 42)))
    if forces_q is not None:
        name, element = P2_UNKNOWN[forces_q]
        loads = {k: v for k, v in P2_LOADS.items() if k != name}
        r = kin.forces(crank=MassProps(3.0, 0.05, 0.1, 5.0), coupler=MassProps(2.0, 0.2, 0.4, 10.0),
                       follower=MassProps(1.0, 0.1, 0.3, -15.0), crank_point=(0.2, 30.0), coupler_point=(0.7, -20.0),
                       follower_point=(0.5, 40.0), loads=loads, unknown=name, gravity=gravity)
        expected[element] = r.value
        for reaction, first in (("ground_on_crank", 21), ("crank_on_coupler", 23), ("coupler_on_follower", 25),
                                ("ground_on_follower", 27)):
            expected[("F", first)] = complex(r.reactions[reaction]).real
            expected[("F", first + 1)] = complex(r.reactions[reaction]).imag
    return expected


@pytest.mark.parametrize("l10, branch", [(1, -1), (0, 1), (-1, 1), (2, 1)])
def test_program_2_branch_from_l10(l10, branch):
    m = machine()
    m.set(**P2_INPUTS)
    m.set(L={10: l10})
    run_and_check(m, 2, p2_expected(branch=branch))


@pytest.mark.parametrize("q", [1, 2, 3, 4])
@pytest.mark.parametrize("gravity", [0.0, 9.81])
def test_program_2_forces_for_every_q(q, gravity):
    m = machine()
    m.set(**P2_INPUTS, Z={2: 2}, Q={2: q}, G=gravity)
    run_and_check(m, 2, p2_expected(q, gravity))


P3_INPUTS = dict(L={6: 0.5, 7: 0.25}, T={6: 30.0, 7: 100.0}, W={0: 6.0}, A={0: 1.0}, D={3: 0.2}, E={3: -0.5},
                 R={0: 0.2, 5: 0.1, 6: 0.3, 7: 0.6}, H={23: 15.0, 7: 5.0, 6: -10.0}, M={0: 2.0, 1: 0.7, 5: 3.0},
                 I={0: 0.02, 1: 0.004, 5: 0.4}, U={3: 1.5}, F={18: 4.0})
P3_UNKNOWN = {1: ("crank_torque", ("U", 3)), 3: ("follower_perpendicular", ("F", 18))}


def p3_expected(forces_q=None, gravity=0.0):
    kin = inverted_slider_crank(0.5, 30.0, 0.25, 100.0, 6.0, 1.0, crank_length_rate=0.2, crank_length_accel=-0.5)
    expected = {("L", 5): kin.follower_length.value, ("D", 4): kin.follower_length.rate,
                ("E", 4): kin.follower_length.accel, ("T", 9): kin.follower.degrees, ("W", 4): kin.follower.omega,
                ("A", 4): kin.follower.alpha}
    expected |= point_elements(kin.crank_point(0.2, 15.0), ("X", 6), ("Y", 6), (("V", 11), ("V", 12)), (("A", 43), ("A", 44)))
    expected |= point_elements(kin.follower_point(0.6, -10.0), ("X", 7), ("Y", 7), (("V", 13), ("V", 14)),
                               (("A", 45), ("A", 46)))
    if forces_q is not None:
        name, element = P3_UNKNOWN[forces_q]
        loads = {k: v for k, v in dict(crank_torque=1.5, follower_perpendicular=4.0).items() if k != name}
        r = kin.forces(crank=MassProps(2.0, 0.02, 0.1, 0.0), block_mass=0.7, block_inertia=0.004,
                       follower=MassProps(3.0, 0.4, 0.3, 5.0), follower_point=(0.6, -10.0), loads=loads, unknown=name,
                       gravity=gravity)
        expected[element] = r.value
        for reaction, first in (("ground_on_crank", 12), ("crank_on_block", 14), ("ground_on_follower", 16)):
            expected[("F", first)] = complex(r.reactions[reaction]).real
            expected[("F", first + 1)] = complex(r.reactions[reaction]).imag
        expected[("N", 3)] = r.reactions["follower_on_block"]
        expected[("U", 4)] = r.reactions["follower_on_block_couple"]
    return expected


@pytest.mark.parametrize("q", [None, 1, 3])
@pytest.mark.parametrize("gravity", [0.0, 9.81])
def test_program_3_outputs_and_forces(q, gravity):
    m = machine()
    # T(5) is the crank mass centre's angle (R(5), T(5)); 0 here, as in the paper's examples
    m.set(**P3_INPUTS, Z={3: 0 if q is None else 2}, Q={3: q or 0}, G=gravity)
    run_and_check(m, 3, p3_expected(q, gravity))


@pytest.mark.parametrize("method", [None, "paper"])
def test_program_5_outputs(method):
    m = machine({5: method} if method else None)
    m.set(X={10: 3.0}, Y={10: 4.0}, V={17: 1.0, 18: -2.0}, A={49: 0.5, 50: 0.25})
    link = virtual_link(3.0, 4.0, 1.0, -2.0, 0.5, 0.25)
    expected = {"T": link.angle_deg, "L": link.length, "X": 3.0, "Y": 4.0, ("D", 5): link.angle_rate,
                ("E", 5): link.angle_accel, ("D", 6): link.length_rate, ("E", 6): link.length_accel}
    run_and_check(m, 5, expected)
    assert m.scalar("L") == pytest.approx(5.0) and m.scalar("T") == pytest.approx(np.degrees(np.arctan2(4, 3)))


def test_static_call_writes_zero_rates_and_no_forces_unless_z_is_2():
    m = machine()
    m.set(**P2_INPUTS, Z={2: 1}, Q={2: 1})
    m.set(W={5: 0.0}, A={5: 0.0}, D={2: 0.0}, E={2: 0.0})
    fill_outputs(m, [("W", 6), ("A", 6), ("W", 7), ("A", 7), ("V", 7), ("A", 40), ("F", 21), ("F", 27)])
    m.call(2)
    assert [m.array(n)[i] for n, i in [("W", 6), ("A", 6), ("W", 7), ("A", 7), ("V", 7), ("A", 40)]] == [0.0] * 6
    assert m.array("F")[21] == SENTINEL and m.array("F")[27] == SENTINEL
    assert m.array("U")[2] == 0.8  # the known crank torque is left as the listing gave it


def test_virtual_work_through_the_elements_alone():
    # massless four-bar, crank torque U(2) unknown against a follower load F(37): the virtual
    # work U(2) dtheta + F(37) (perpendicular at the follower point) . dP = 0, with dP from the
    # positions X(5), Y(5) of two calls a small crank step apart (no rates involved)
    m = machine()
    m.set(L={10: 0, 11: 1.0, 12: 0.35, 13: 1.1, 14: 0.7}, T={11: 0.0, 12: 50.0}, R={13: 0.5}, H={13: 0.0},
          F={37: 2.0}, Z={2: 2}, Q={2: 1})
    m.call(2)
    torque, follower_angle = m.array("U")[2], m.array("T")[14]
    step = 1e-4

    def follower_point(theta):
        probe = machine()
        probe.set(L={10: 0, 11: 1.0, 12: 0.35, 13: 1.1, 14: 0.7}, T={11: 0.0, 12: theta}, R={13: 0.5})
        probe.call(2)
        return complex(probe.array("X")[5], probe.array("Y")[5])

    displacement = (follower_point(50.0 + step) - follower_point(50.0 - step)) / (2 * np.radians(step))
    load = 2.0 * np.exp(1j * np.radians(follower_angle + 180.0 + 90.0))  # perpendicular to Bo->P, ccw about Bo
    assert torque + np.real(np.conj(load) * displacement) == pytest.approx(0.0, abs=1e-7)
    assert abs(torque) > 0.1


def assert_fails_cleanly(m, area, message, code=ILLEGAL_FUNCTION_CALL):
    """The call raises ``message`` and leaves every array element and scalar as it was."""
    before = m.snapshot()
    with pytest.raises(BasicError) as caught:
        m.call(area)
    assert str(caught.value) == message and caught.value.code == code
    assert str(caught.value.at(4040)) == f"{message} in 4040"
    arrays_after, scalars_after = m.snapshot()
    for name, values in before[0].items():
        assert arrays_after[name] == values, name
    assert scalars_after == before[1]


def test_cannot_be_assembled_names_the_program():
    m = machine()
    m.set(L={11: 10.0, 12: 1.0, 13: 2.0, 14: 2.0})
    assert_fails_cleanly(m, 2, "Mechanism cannot be assembled (PROG 2)")
    m.set(L={1: 5.0, 2: 3.0, 3: 1.0}, T={2: 90.0})
    assert_fails_cleanly(m, 1, "Mechanism cannot be assembled (PROG 1)")
    assert_fails_cleanly(machine(), 3, "Mechanism cannot be assembled (PROG 3)")  # all zero: A on Bo
    assert_fails_cleanly(machine(), 5, "Mechanism cannot be assembled (PROG 5)")  # zero-length virtual link


def test_bad_q_and_singular_forces_are_errors():
    m = machine()
    m.set(**P1_INPUTS, Z={1: 2}, Q={1: 7})
    assert_fails_cleanly(m, 1, "Q(1) = 7 is not 1 or 2 or 3 or 4 (PROG 1)")
    m = machine()
    m.set(**P3_INPUTS, Z={3: 2}, Q={3: 2})
    assert_fails_cleanly(m, 3, "Q(3) = 2 is not 1 or 3 (PROG 3)")
    m = machine()  # unknown perpendicular force at R(1) = 0 on the crank
    m.set(L={2: 0.1, 3: 0.3}, T={2: 30.0}, W={2: 5.0}, U={1: 1.0}, Z={1: 2}, Q={1: 2})
    assert_fails_cleanly(m, 1, "Force system is singular (PROG 1)")
    m = machine()  # the piston force cannot turn a crank at dead centre
    m.set(L={2: 0.1, 3: 0.3}, T={2: 0.0}, U={1: 1.0}, Z={1: 2}, Q={1: 4})
    assert_fails_cleanly(m, 1, "Force system is singular (PROG 1)")


def test_paper_method_division_by_zero_and_toggle():
    m = machine({5: "paper"})
    m.set(X={10: 0.0}, Y={10: 2.0}, V={17: 1.0})
    assert_fails_cleanly(m, 5, "Division by zero (PROG 5)", DIVISION_BY_ZERO)
    m = machine()
    m.set(X={10: 0.0}, Y={10: 2.0}, V={17: 1.0})
    m.call(5)
    assert m.scalar("T") == 90.0 and m.array("D")[5] == pytest.approx(-0.5)
    m = machine()  # coupler and follower in line: positions exist, rates do not
    m.set(L={11: 1.0, 12: 0.5, 13: 0.5, 14: 1.0}, T={12: 0.0}, W={5: 1.0})
    assert_fails_cleanly(m, 2, "Mechanism locks: rates undefined at a toggle position (PROG 2)")


def test_outputs_beyond_the_dimensions_are_subscript_errors_and_write_nothing():
    m = machine(dims={})  # no DIM: every array has the implicit 0..10
    m.set(L={1: -2, 2: 3, 3: 8}, T={2: -30}, W={2: -15})
    assert_fails_cleanly(m, 1, "Subscript out of range (PROG 1)", SUBSCRIPT_OUT_OF_RANGE)
    # Program 5 writes only low subscripts and scalars: it runs without a DIM
    m.set(X={10: 1.0}, Y={10: 1.0})
    m.call(5)
    assert m.scalar("T") == pytest.approx(45.0)


def test_unknown_method_or_program_is_rejected_at_install():
    with pytest.raises(BasicError, match="Unknown method 'fast' for PROG 5 .*polar"):
        install(FakeMachine(), {5: "fast"})
    with pytest.raises(BasicError, match="No library program 4"):
        install(FakeMachine(), {4: "closed"})
    m = machine({"5": "paper"})  # a string key from the command line is accepted
    m.set(X={10: 1.0}, Y={10: 0.0})
    with pytest.raises(BasicError, match="Division by zero"):
        m.call(5)


def test_program_3_paper_method_is_selectable_and_breaks_at_a_vertical_follower():
    inputs = dict(L={6: 1.0, 7: 2.0}, T={6: 90.0, 7: 90.0}, W={0: 1.0})
    m = machine({3: "paper"})
    m.set(**inputs)
    assert_fails_cleanly(m, 3, "Division by zero (PROG 3)", DIVISION_BY_ZERO)
    m = machine()
    m.set(**inputs)
    m.call(3)
    assert (m.array("T")[9], m.array("L")[5]) == (90.0, 3.0)
