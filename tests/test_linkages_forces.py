"""Force analysis of Programs 1, 2, 3 against each body's equilibrium and a power balance.

Independent of the solver: each test rebuilds every body's free-body diagram
from the contract's text (reaction signs, load directions worked out here from
the points' positions), takes mass-centre and angular accelerations from finite
differences of positions along a prescribed crank motion, and checks
sum F = m a_G and sum M_G = I alpha.  The power balance checks the solved
unknown: power of all external loads (known, unknown, gravity) = dKE/dt, with
the kinetic energy from finite-difference velocities.  Every Q(n) choice, gravity
off and on; flexible cranks in the equilibrium check (their length actuator does
work, so the power balance uses rigid cranks).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import pytest

from yaseer.linkages import MassProps, SingularForceError, fourbar, inverted_slider_crank, slider_crank

H = 1e-4  # inner finite-difference step (s)
TIMES = np.linspace(0.0, 2 * np.pi, 181)[:-1]


def drive(t, flexible):
    """Crank angle (deg), rates, and length factor with its rates, as functions of time."""
    k = 0.08 if flexible else 0.0
    theta = t + 0.3 * np.sin(2 * t)
    return (np.degrees(theta), 1 + 0.6 * np.cos(2 * t), -1.2 * np.sin(2 * t),
            1 + k * np.sin(3 * t), 3 * k * np.cos(3 * t), -9 * k * np.sin(3 * t))


def ccw_perpendicular(joint, point):
    """Unit vector at ``point`` perpendicular to joint->point, counter-clockwise about the joint."""
    radius = point - joint
    return 1j * radius / np.abs(radius)


def velocity(positions_of, t, name):
    return (positions_of(t + H)[name] - positions_of(t - H)[name]) / (2 * H)


def acceleration(positions_of, t, name):
    return (positions_of(t + H)[name] - 2 * positions_of(t)[name] + positions_of(t - H)[name]) / H**2


def angular_velocity(positions_of, t, name):
    return np.angle(positions_of(t + H)[name] / positions_of(t - H)[name]) / (2 * H)


def angular_acceleration(positions_of, t, name):
    before, now, after = (positions_of(t + d)[name] for d in (-H, 0.0, H))
    return (np.angle(after / now) - np.angle(now / before)) / H**2


@dataclass
class Body:
    """A free body as the test sees it: mass centre point, orientation point name
    (a unit vector turning with the body), and the forces/couples acting on it."""

    mass: float
    inertia: float
    centre: str
    orientation: str | None
    forces: list = field(default_factory=list)  # (force complex array, point name)
    couples: list = field(default_factory=list)


def check_equilibrium(bodies, positions_of, t, gravity, scale):
    """sum F + m g = m a_G and sum M_G = I alpha, residuals relative to ``scale``."""
    where = positions_of(t)
    for name, body in bodies.items():
        total = sum(force for force, _ in body.forces) - 1j * body.mass * gravity
        a_g = acceleration(positions_of, t, body.centre)
        np.testing.assert_allclose(total, body.mass * a_g, rtol=0, atol=2e-5 * scale, err_msg=name)
        if body.orientation is None:
            continue
        moment = sum(np.imag(np.conj(where[point] - where[body.centre]) * force) for force, point in body.forces)
        moment = moment + sum(body.couples)
        alpha = angular_acceleration(positions_of, t, body.orientation)
        np.testing.assert_allclose(moment, body.inertia * alpha, rtol=0, atol=2e-5 * scale, err_msg=name)


def kinetic_energy(bodies, positions_of, t):
    energy = 0.0
    for body in bodies.values():
        energy = energy + 0.5 * body.mass * np.abs(velocity(positions_of, t, body.centre)) ** 2
        if body.orientation is not None:
            energy = energy + 0.5 * body.inertia * angular_velocity(positions_of, t, body.orientation) ** 2
    return energy


def check_power(bodies, external, positions_of, t, gravity, scale):
    """Power of the external loads (and gravity) = dKE/dt, dKE/dt by differences."""
    step = 1e-3
    ke_rate = (kinetic_energy(bodies, positions_of, t + step) - kinetic_energy(bodies, positions_of, t - step)) / (2 * step)
    power = 0.0
    for body_name, force, point, couple in external:
        if force is not None:
            power = power + np.real(np.conj(force) * velocity(positions_of, t, point))
        if couple is not None:
            power = power + couple * angular_velocity(positions_of, t, bodies[body_name].orientation)
    for body in bodies.values():
        power = power - body.mass * gravity * np.imag(velocity(positions_of, t, body.centre))
    np.testing.assert_allclose(power, ke_rate, rtol=0, atol=2e-5 * scale)


def well_conditioned(virtual_speed):
    """Positions where the unknown's point moves enough for it to do work (away from singular ones)."""
    return np.abs(virtual_speed) > 0.2 * np.max(np.abs(virtual_speed))


# ---------------------------------------------------------------- Program 1

P1 = dict(e=0.05, a=0.1, b=0.35, phi=20.0, crank=MassProps(2.0, 0.01, 0.03, 10.0), rod=MassProps(1.5, 0.02, 0.15, 5.0),
          piston=0.8, crank_point=(0.08, 40.0), rod_point=(0.1, -20.0))
P1_KNOWN = dict(crank_fx=3.0, crank_fy=-2.0, crank_perpendicular=5.0, crank_torque=1.5, rod_fx=-4.0, rod_fy=6.0,
                rod_perpendicular=2.0, piston=20.0)


def p1_kinematics(t, flexible, rates=True):
    theta, omega, alpha, s, s1, s2 = drive(t, flexible)
    if not rates:
        omega = alpha = s1 = s2 = 0.0
    return slider_crank(P1["e"], P1["a"] * s, P1["b"], theta, omega, alpha, crank_length_rate=P1["a"] * s1,
                        crank_length_accel=P1["a"] * s2, axis_deg=P1["phi"])


def p1_positions(flexible):
    def positions_of(t):
        k = p1_kinematics(t, flexible, rates=False)
        c, r = P1["crank"], P1["rod"]
        return dict(A=k.pin_a.pos, B=k.pin_b.pos, O=0j * k.pin_a.pos,
                    G2=c.distance * np.exp(1j * (np.radians(drive(t, flexible)[0]) + np.radians(c.offset_deg))),
                    G3=k.pin_b.pos + r.distance * np.exp(1j * np.radians(r.offset_deg)) * (k.pin_a.pos - k.pin_b.pos)
                    / np.abs(k.pin_a.pos - k.pin_b.pos),
                    P1=k.crank_point(*P1["crank_point"]).pos, P4=k.rod_point(*P1["rod_point"]).pos,
                    crank=np.exp(1j * np.radians(drive(t, flexible)[0])), rod=k.pin_b.pos - k.pin_a.pos)
    return positions_of


def p1_free_bodies(result, where, loads):
    """The three bodies of Program 1 from the contract's conventions."""
    reactions = result.reactions
    axis = np.exp(1j * np.radians(P1["phi"]))
    crank_perp = ccw_perpendicular(where["O"], where["P1"])
    rod_perp = ccw_perpendicular(where["B"], where["P4"])
    external = [
        ("crank", loads["crank_fx"] + 1j * loads["crank_fy"], "P1", None),
        ("crank", loads["crank_perpendicular"] * crank_perp, "P1", None),
        ("crank", None, None, loads["crank_torque"]),
        ("rod", loads["rod_fx"] + 1j * loads["rod_fy"], "P4", None),
        ("rod", loads["rod_perpendicular"] * rod_perp, "P4", None),
        ("piston", -axis * loads["piston"], "B", None),
    ]
    bodies = {
        "crank": Body(P1["crank"].mass, P1["crank"].inertia, "G2", "crank",
                      [(reactions["ground_on_crank"], "O"), (-reactions["crank_on_rod"], "A")]),
        "rod": Body(P1["rod"].mass, P1["rod"].inertia, "G3", "rod",
                    [(reactions["crank_on_rod"], "A"), (-reactions["rod_on_piston"], "B")]),
        "piston": Body(P1["piston"], 0.0, "B", None,
                       [(reactions["rod_on_piston"], "B"), (reactions["wall_on_piston"] * 1j * axis, "B")]),
    }
    return bodies, external


def add_external(bodies, external):
    for body_name, force, point, couple in external:
        if force is not None:
            bodies[body_name].forces.append((force, point))
        if couple is not None:
            bodies[body_name].couples.append(couple)


def solve_and_check(kinematics, free_bodies, positions_of, force_kwargs, known, unknown, unknown_point, gravity,
                    flexible, scale):
    """Solve, keep well-conditioned positions, check equilibrium (and power for rigid cranks)."""
    t = TIMES
    if unknown_point is not None:
        speeds = unknown_point(positions_of, t)
        t = t[well_conditioned(speeds)]
    loads = dict(known)
    loads.pop(unknown)
    result = kinematics(t, flexible).forces(loads=loads, unknown=unknown, gravity=gravity, **force_kwargs)
    assert result.unknown == unknown and np.all(np.isfinite(result.value))
    solved = dict(loads, **{unknown: result.value})
    bodies, external = free_bodies(result, positions_of(t), solved)
    add_external(bodies, external)
    check_equilibrium(bodies, positions_of, t, gravity, scale)
    if not flexible:
        check_power(bodies, external, positions_of, t, gravity, scale)
    return result


P1_UNKNOWN_SPEED = {
    "crank_torque": None,
    "crank_perpendicular": None,  # R(1) > 0 and the crank always turns
    "rod_perpendicular": lambda pos, t: np.real(np.conj(ccw_perpendicular(pos(t)["B"], pos(t)["P4"])) * velocity(pos, t, "P4")),
    "piston": lambda pos, t: np.real(np.conj(np.exp(1j * np.radians(P1["phi"]))) * velocity(pos, t, "B")),
}


@pytest.mark.parametrize("flexible", [False, True])
@pytest.mark.parametrize("gravity", [0.0, 9.81])
@pytest.mark.parametrize("unknown", list(P1_UNKNOWN_SPEED))
def test_slider_crank_forces_balance(unknown, gravity, flexible):
    kwargs = dict(crank=P1["crank"], rod=P1["rod"], piston_mass=P1["piston"], crank_point=P1["crank_point"],
                  rod_point=P1["rod_point"])
    solve_and_check(p1_kinematics, p1_free_bodies, p1_positions(flexible), kwargs, P1_KNOWN, unknown,
                    P1_UNKNOWN_SPEED[unknown], gravity, flexible, 100.0)


# ---------------------------------------------------------------- Program 2

P2 = dict(ground=(1.0, 10.0), a=0.4, b=1.2, c=0.8, crank=MassProps(3.0, 0.05, 0.1, 20.0),
          coupler=MassProps(2.0, 0.3, 0.5, 15.0), follower=MassProps(1.5, 0.1, 0.35, -10.0),
          crank_point=(0.3, 60.0), coupler_point=(0.9, 25.0), follower_point=(0.6, 30.0))
P2_KNOWN = dict(crank_fx=3.0, crank_fy=-2.0, crank_perpendicular=5.0, crank_torque=1.5, coupler_fx=-4.0,
                coupler_fy=6.0, coupler_perpendicular=2.0, follower_fx=1.0, follower_fy=-3.0,
                follower_perpendicular=4.0)


def p2_kinematics(branch):
    def kinematics(t, flexible, rates=True):
        theta, omega, alpha, s, s1, s2 = drive(t, flexible)
        if not rates:
            omega = alpha = s1 = s2 = 0.0
        return fourbar(*P2["ground"], P2["a"] * s, P2["b"], P2["c"], theta, omega, alpha,
                       crank_length_rate=P2["a"] * s1, crank_length_accel=P2["a"] * s2, branch=branch)
    return kinematics


def on_link(origin, towards, distance, offset_deg):
    """The point ``distance`` from ``origin`` at ``offset_deg`` from origin->towards."""
    direction = (towards - origin) / np.abs(towards - origin)
    return origin + distance * np.exp(1j * np.radians(offset_deg)) * direction


def p2_positions(branch, flexible):
    def positions_of(t):
        k = p2_kinematics(branch)(t, flexible, rates=False)
        o, a, b, bo = 0j * k.pin_a.pos, k.pin_a.pos, k.pin_b.pos, k.pivot.pos + 0 * k.pin_a.pos
        crank_dir = np.exp(1j * np.radians(drive(t, flexible)[0]))
        return dict(O=o, A=a, B=b, Bo=bo, crank=crank_dir, coupler=b - a, follower=b - bo,
                    G1=on_link(o, crank_dir, P2["crank"].distance, P2["crank"].offset_deg),
                    G2=on_link(a, b, P2["coupler"].distance, P2["coupler"].offset_deg),
                    G3=on_link(bo, b, P2["follower"].distance, P2["follower"].offset_deg),
                    P1=on_link(o, crank_dir, *P2["crank_point"]), P2=on_link(a, b, *P2["coupler_point"]),
                    P3=on_link(bo, b, *P2["follower_point"]))
    return positions_of


def p2_free_bodies(result, where, loads):
    r = result.reactions
    external = [("crank", None, None, loads["crank_torque"])]
    for body, point, joint in (("crank", "P1", "O"), ("coupler", "P2", "A"), ("follower", "P3", "Bo")):
        external.append((body, loads[f"{body}_fx"] + 1j * loads[f"{body}_fy"], point, None))
        external.append((body, loads[f"{body}_perpendicular"] * ccw_perpendicular(where[joint], where[point]), point, None))
    bodies = {
        "crank": Body(P2["crank"].mass, P2["crank"].inertia, "G1", "crank",
                      [(r["ground_on_crank"], "O"), (-r["crank_on_coupler"], "A")]),
        "coupler": Body(P2["coupler"].mass, P2["coupler"].inertia, "G2", "coupler",
                        [(r["crank_on_coupler"], "A"), (-r["coupler_on_follower"], "B")]),
        "follower": Body(P2["follower"].mass, P2["follower"].inertia, "G3", "follower",
                         [(r["coupler_on_follower"], "B"), (r["ground_on_follower"], "Bo")]),
    }
    return bodies, external


def perpendicular_speed(joint, point):
    return lambda pos, t: np.real(np.conj(ccw_perpendicular(pos(t)[joint], pos(t)[point])) * velocity(pos, t, point))


P2_UNKNOWN_SPEED = {
    "crank_torque": None,
    "crank_perpendicular": None,
    "coupler_perpendicular": perpendicular_speed("A", "P2"),
    "follower_perpendicular": perpendicular_speed("Bo", "P3"),
}


@pytest.mark.parametrize("flexible", [False, True])
@pytest.mark.parametrize("gravity", [0.0, 9.81])
@pytest.mark.parametrize("branch", [1, -1])
@pytest.mark.parametrize("unknown", list(P2_UNKNOWN_SPEED))
def test_fourbar_forces_balance(unknown, branch, gravity, flexible):
    kwargs = {key: P2[key] for key in ("crank", "coupler", "follower", "crank_point", "coupler_point", "follower_point")}
    solve_and_check(p2_kinematics(branch), p2_free_bodies, p2_positions(branch, flexible), kwargs, P2_KNOWN, unknown,
                    P2_UNKNOWN_SPEED[unknown], gravity, flexible, 100.0)


# ---------------------------------------------------------------- Program 3

P3 = dict(ground=(0.5, 30.0), a=0.25, crank=MassProps(2.0, 0.02, 0.1, 15.0), block=(0.7, 0.004),
          follower=MassProps(3.0, 0.4, 0.3, 5.0), follower_point=(0.6, -10.0))
P3_KNOWN = dict(crank_torque=1.5, follower_perpendicular=4.0)


def p3_kinematics(t, flexible, rates=True):
    theta, omega, alpha, s, s1, s2 = drive(t, flexible)
    if not rates:
        omega = alpha = s1 = s2 = 0.0
    return inverted_slider_crank(*P3["ground"], P3["a"] * s, theta, omega, alpha, crank_length_rate=P3["a"] * s1,
                                 crank_length_accel=P3["a"] * s2)


def p3_positions(flexible):
    def positions_of(t):
        k = p3_kinematics(t, flexible, rates=False)
        o, a, bo = 0j * k.pin_a.pos, k.pin_a.pos, k.pivot.pos + 0 * k.pin_a.pos
        crank_dir = np.exp(1j * np.radians(drive(t, flexible)[0]))
        return dict(O=o, A=a, Bo=bo, crank=crank_dir, follower=a - bo,
                    G1=on_link(o, crank_dir, P3["crank"].distance, P3["crank"].offset_deg),
                    G3=on_link(bo, a, P3["follower"].distance, P3["follower"].offset_deg),
                    P3=on_link(bo, a, *P3["follower_point"]))
    return positions_of


def p3_free_bodies(result, where, loads):
    r = result.reactions
    normal = r["follower_on_block"] * 1j * (where["A"] - where["Bo"]) / np.abs(where["A"] - where["Bo"])
    external = [("crank", None, None, loads["crank_torque"]),
                ("follower", loads["follower_perpendicular"] * ccw_perpendicular(where["Bo"], where["P3"]), "P3", None)]
    bodies = {
        "crank": Body(P3["crank"].mass, P3["crank"].inertia, "G1", "crank",
                      [(r["ground_on_crank"], "O"), (-r["crank_on_block"], "A")]),
        "block": Body(*P3["block"], "A", "follower", [(r["crank_on_block"], "A"), (normal, "A")],
                      [r["follower_on_block_couple"]]),
        "follower": Body(P3["follower"].mass, P3["follower"].inertia, "G3", "follower",
                         [(-normal, "A"), (r["ground_on_follower"], "Bo")], [-r["follower_on_block_couple"]]),
    }
    return bodies, external


@pytest.mark.parametrize("flexible", [False, True])
@pytest.mark.parametrize("gravity", [0.0, 9.81])
@pytest.mark.parametrize("unknown", ["crank_torque", "follower_perpendicular"])
def test_inverted_slider_crank_forces_balance(unknown, gravity, flexible):
    kwargs = dict(crank=P3["crank"], block_mass=P3["block"][0], block_inertia=P3["block"][1], follower=P3["follower"],
                  follower_point=P3["follower_point"])
    speed = None if unknown == "crank_torque" else perpendicular_speed("Bo", "P3")
    result = solve_and_check(p3_kinematics, p3_free_bodies, p3_positions(flexible), kwargs, P3_KNOWN, unknown, speed,
                             gravity, flexible, 100.0)
    # the couple of the follower on the block only turns the block: U(4) = I(1) A(4)
    kin = p3_kinematics(TIMES, flexible) if speed is None else None
    if kin is not None:
        np.testing.assert_allclose(result.reactions["follower_on_block_couple"], P3["block"][1] * kin.follower.alpha,
                                   atol=1e-12)


# ---------------------------------------------------------------- singular systems

def test_unknown_perpendicular_force_at_the_crank_pivot_is_singular():
    kin = slider_crank(0.0, 0.1, 0.3, 30.0, 5.0)
    with pytest.raises(SingularForceError):
        kin.forces(crank_point=(0.0, 0.0), loads=dict(crank_torque=1.0), unknown="crank_perpendicular")


@pytest.mark.parametrize("crank_angle", [0.0, 180.0])
def test_piston_force_cannot_balance_a_crank_torque_at_dead_centre(crank_angle):
    kin = slider_crank(0.0, 0.1, 0.3, crank_angle, 5.0)
    with pytest.raises(SingularForceError):
        kin.forces(loads=dict(crank_torque=1.0), unknown="piston")
    # the crank torque at the same dead centre is fine and zero for a piston force alone
    result = kin.forces(loads=dict(piston=10.0), unknown="crank_torque")
    assert result.value == pytest.approx(0.0, abs=1e-12)


def test_follower_load_cannot_drive_a_fourbar_whose_crank_and_coupler_are_in_line():
    # Ao = 0, Bo = (1, 0), a = 0.3, b = 0.9, c = 0.5: crank and coupler extend each other when
    # |1.2 u(theta) - Bo| = 0.5, i.e. cos(theta) = (1.44 + 1 - 0.25) / 2.4 (a dead centre of the crank)
    theta = np.degrees(np.arccos((1.44 + 1 - 0.25) / 2.4))
    collinear = [k for k in (fourbar(1.0, 0.0, 0.3, 0.9, 0.5, theta, 1.0, branch=b) for b in (1, -1))
                 if abs(k.pin_b.pos - 1.2 * np.exp(1j * np.radians(theta))) < 1e-6]
    assert len(collinear) >= 1
    with pytest.raises(SingularForceError):
        collinear[0].forces(loads=dict(crank_torque=1.0), unknown="follower_perpendicular", follower_point=(0.4, 0.0))
    # a generic position of the same linkage solves
    assert np.isfinite(fourbar(1.0, 0.0, 0.3, 0.9, 0.5, theta + 30, 1.0).forces(
        loads=dict(crank_torque=1.0), unknown="follower_perpendicular", follower_point=(0.4, 0.0)).value)


# A singular system is singular whatever the loads: with nothing to balance, the
# zero solution is one of infinitely many (the contract: a run-time error).

@pytest.mark.parametrize("off_dead_centre", [0.0, 1e-12, -1e-10])
def test_piston_force_at_dead_centre_is_singular_even_with_nothing_to_balance(off_dead_centre):
    kin = slider_crank(0.0, 0.1, 0.3, 180.0 + off_dead_centre, 5.0)
    with pytest.raises(SingularForceError):
        kin.forces(unknown="piston")  # no masses, no loads, no gravity


def test_fourbar_follower_load_is_singular_at_a_crank_coupler_line_up_with_nothing_to_balance():
    theta = np.degrees(np.arccos((1.44 + 1 - 0.25) / 2.4))  # crank and coupler in line (see above)
    kin = next(k for k in (fourbar(1.0, 0.0, 0.3, 0.9, 0.5, theta, branch=b) for b in (1, -1))
               if abs(k.pin_b.pos - 1.2 * np.exp(1j * np.radians(theta))) < 1e-6)
    with pytest.raises(SingularForceError):
        kin.forces(unknown="follower_perpendicular", follower_point=(0.4, 0.0))


def test_unknown_perpendicular_force_at_the_pivot_is_singular_with_nothing_to_balance():
    with pytest.raises(SingularForceError):
        inverted_slider_crank(0.5, 30.0, 0.25, 40.0).forces(unknown="follower_perpendicular", follower_point=(0.0, 0.0))


@pytest.mark.parametrize("unknown", ["crank_torque", "piston", "rod_perpendicular"])
def test_a_regular_position_with_nothing_to_balance_gives_exact_zeros(unknown):
    result = slider_crank(0.02, 0.1, 0.3, 50.0).forces(unknown=unknown, rod_point=(0.1, 10.0))
    assert result.value == 0.0
    assert all(np.all(reaction == 0.0) for reaction in result.reactions.values())


@pytest.mark.parametrize("scale", [1e-4, 1.0, 1e3])
def test_near_dead_centre_the_piston_force_follows_virtual_work_in_any_unit_of_length(scale):
    # 1e-6 deg from dead centre the system is nearly singular but solvable: the piston
    # force P that balances a crank torque U obeys U dtheta = P ds (power balance; the
    # piston load acts along -u(phi)), with ds/dtheta of s = a cos + sqrt(b^2 - a^2 sin^2)
    # differentiated by hand (e = 0, phi = 0).
    a, b, theta, torque = 0.1 * scale, 0.3 * scale, 180.0 + 1e-6, 2.0 * scale
    result = slider_crank(0.0, a, b, theta).forces(unknown="piston", loads=dict(crank_torque=torque))
    sin, cos = np.sin(np.radians(theta)), np.cos(np.radians(theta))
    ds_dtheta = -a * sin - a**2 * sin * cos / np.sqrt(b**2 - a**2 * sin**2)
    assert result.value == pytest.approx(torque / ds_dtheta, rel=1e-6)
    assert abs(result.value) > 1e8


def test_the_listing_gets_the_contracts_singular_force_error_when_nothing_needs_balancing(tmp_path, capsys):
    from yaseer import cli

    listing = tmp_path / "dead_centre.bas"  # crank at dead centre, piston force asked, no loads or masses
    listing.write_text("10 L(2) = 0.1: L(3) = 0.3: T(2) = 180: Z(1) = 2: Q(1) = 4\n20 GOSUB PROG 1\n30 PRINT P(1)\n")
    status = cli.main(["run", str(listing)])
    captured = capsys.readouterr()
    assert status == 1 and captured.out == ""
    assert captured.err.strip() == "Force system is singular (PROG 1) in 20"


@pytest.mark.parametrize("scale", [1e-6, 1.0, 1e6])
def test_crank_torque_unknown_is_regular_in_any_unit_of_length(scale):
    # A couple unknown next to force unknowns: the singularity test must not depend
    # on the unit of length.  Static balance by virtual work: U = P ds/dtheta.
    a, b, theta, piston = 0.1 * scale, 0.3 * scale, 30.0, 5.0
    result = slider_crank(0.0, a, b, theta).forces(unknown="crank_torque", loads=dict(piston=piston))
    sin, cos = np.sin(np.radians(theta)), np.cos(np.radians(theta))
    ds_dtheta = -a * sin - a**2 * sin * cos / np.sqrt(b**2 - a**2 * sin**2)
    assert result.value == pytest.approx(piston * ds_dtheta, rel=1e-12)
