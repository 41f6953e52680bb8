"""The reference solver (yaseer/reference/solver.py) against independent computations.

* closed forms derived by hand here (a plain offset slider-crank, a four-bar by
  circle intersection and Cramer's rule on the differentiated loop equation);
* finite differences of the solver's own positions along the crank angle;
* Newton's laws for the whole machine (sum of external forces and moments equals
  the rate of change of momentum and angular momentum) and the power balance
  (drive power = dT/dt - power of the loads, dT/dt by finite differences);
* the mpmath path against the float path, and against itself at two precisions.
"""

from __future__ import annotations

import math

import pytest

from yaseer.reference.arithmetic import MpArithmetic
from yaseer.reference.solver import (AngleDriver, AngleLock, Body, Couple, Drive, Mechanism,
                                     MechanismError, PointLoad, PointOnLine, Revolute, polar)
from yaseer.reference.paper_mechanisms import example_mechanism, example_snapshots
from yaseer.reference import basic_linkages, programs
from yaseer.reference.basic_linkages import fourbar_model as four_bar


def rel(a, b, floor=1.0):
    return abs(float(a) - float(b)) / max(floor, abs(float(b)))


# --------------------------------------------------------------------------- closed forms

def slider_crank_closed_form(r, l, e, theta_deg, w, alpha, rd=0.0, rdd=0.0):
    """Offset slider-crank, pin B on y = e, B to the right of A: derived by hand.

    r sin(t) + l sin(b) = e fixes the rod angle b; x_B = r cos(t) + l cos(b);
    differentiate twice (the crank length r may change: rd, rdd).
    """
    t = math.radians(theta_deg)
    b = math.asin((e - r * math.sin(t)) / l)
    bd = -(rd * math.sin(t) + r * w * math.cos(t)) / (l * math.cos(b))
    bdd = (-rdd * math.sin(t) - 2 * rd * w * math.cos(t) - r * alpha * math.cos(t) + r * w * w * math.sin(t)
           + l * bd * bd * math.sin(b)) / (l * math.cos(b))
    x = r * math.cos(t) + l * math.cos(b)
    xd = rd * math.cos(t) - r * w * math.sin(t) - l * bd * math.sin(b)
    xdd = (rdd * math.cos(t) - 2 * rd * w * math.sin(t) - r * alpha * math.sin(t) - r * w * w * math.cos(t)
           - l * bdd * math.sin(b) - l * bd * bd * math.cos(b))
    return dict(x=x, v=xd, a=xdd, rod=math.degrees(b), w_rod=bd, a_rod=bdd)


def slider_crank_model(r, l, e, with_slider_body=False, masses=False):
    crank = Body("crank", mass=2 if masses else 0, inertia=0.3 if masses else 0, centre=(r / 3, 0.1),
                 points={"A": (r, 0)})
    rod = Body("rod", mass=3 if masses else 0, inertia=0.7 if masses else 0, centre=(l / 2, -0.2),
               points={"A": (0, 0), "B": (l, 0)})
    bodies, constraints = [crank, rod], [
        Revolute("O", crank, (0, 0), None, (0, 0)),
        Revolute("A", crank, "A", rod, "A"),
        AngleDriver("drive", crank)]
    if with_slider_body:
        piston = Body("piston", mass=1.5 if masses else 0, inertia=0.05 if masses else 0, points={"B": (0, 0)})
        bodies.append(piston)
        constraints += [Revolute("B", rod, "B", piston, "B"),
                        PointOnLine("guide", piston, "B", None, (0, e), 0),
                        AngleLock("lock", piston, None, 0)]
    else:
        constraints.append(PointOnLine("guide", rod, "B", None, (0, e), 0))
    return Mechanism(bodies, constraints)


@pytest.mark.parametrize("theta", [-170.0, -30.0, 12.5, 77.0, 133.0])
@pytest.mark.parametrize("with_slider_body", [False, True])
def test_slider_crank_against_closed_form(theta, with_slider_body):
    r, l, e, w, alpha = 3.0, 8.0, 2.0, -15.0, -10.0
    model = slider_crank_model(r, l, e, with_slider_body)
    placement = {"crank": (0, 0, theta), "rod": (r * math.cos(math.radians(theta)),
                                                  r * math.sin(math.radians(theta)), 5)}
    if with_slider_body:
        placement["piston"] = (9, e, 0)
    (s,) = model.analyse([theta], w, alpha, model.coordinates(placement))
    exact = slider_crank_closed_form(r, l, e, theta, w, alpha)
    assert rel(s.position("rod", "B")[0], exact["x"]) < 1e-12
    assert rel(s.velocity("rod", "B")[0], exact["v"]) < 1e-11
    assert rel(s.acceleration("rod", "B")[0], exact["a"]) < 1e-10
    assert rel(s.angle("rod"), exact["rod"]) < 1e-11
    assert rel(s.omega("rod"), exact["w_rod"]) < 1e-11
    assert rel(s.alpha("rod"), exact["a_rod"]) < 1e-10
    assert abs(s.velocity("rod", "B")[1]) < 1e-11 and abs(s.acceleration("rod", "B")[1]) < 1e-9


def four_bar_closed_form(a, b, c, d, theta_deg, w, alpha, side, m=math):
    """Crank A(0,0)-B, coupler B-C, follower D(d,0)-C; C on ``side`` (+1 left) of B->D.

    Position: intersection of the circles (B, b) and (D, c).  Rates: the loop
    a u(t) + b u(beta) - c u(phi) - d x = 0 differentiated; the 2x2 system in
    (beta', phi') [and (beta'', phi'')] solved by Cramer's rule.  ``m``: math, or an
    mpmath context for the same formulas in high precision.
    """
    t = m.radians(theta_deg)
    bx, by = a * m.cos(t), a * m.sin(t)
    ex, ey = d - bx, -by
    dist = m.hypot(ex, ey)
    along = (b * b - c * c + dist * dist) / (2 * dist)
    h = m.sqrt(b * b - along * along)
    cx = bx + along * ex / dist - side * h * ey / dist
    cy = by + along * ey / dist + side * h * ex / dist
    beta, phi = m.atan2(cy - by, cx - bx), m.atan2(cy, cx - d)
    # columns: beta' multiplies b J u(beta), phi' multiplies -c J u(phi)
    m11, m21 = -b * m.sin(beta), b * m.cos(beta)
    m12, m22 = c * m.sin(phi), -c * m.cos(phi)
    det = m11 * m22 - m12 * m21

    def cramer(r1, r2):
        return (r1 * m22 - m12 * r2) / det, (m11 * r2 - r1 * m21) / det

    r1, r2 = a * w * m.sin(t), -a * w * m.cos(t)
    bd, pd = cramer(r1, r2)
    r1 = a * alpha * m.sin(t) + a * w * w * m.cos(t) + b * bd * bd * m.cos(beta) - c * pd * pd * m.cos(phi)
    r2 = -a * alpha * m.cos(t) + a * w * w * m.sin(t) + b * bd * bd * m.sin(beta) - c * pd * pd * m.sin(phi)
    bdd, pdd = cramer(r1, r2)
    return dict(beta=m.degrees(beta), phi=m.degrees(phi), bd=bd, pd=pd, bdd=bdd, pdd=pdd, C=(cx, cy))


@pytest.mark.parametrize("theta", [0.0, 37.0, 95.0, 181.0, 260.0, 333.0])
@pytest.mark.parametrize("side", [1, -1])
def test_four_bar_against_closed_form(theta, side):
    a, b, c, d, w, alpha = 40.0, 120.0, 80.0, 100.0, 7.0, -3.0
    model = four_bar(a, b, c, (d, 0))
    exact = four_bar_closed_form(a, b, c, d, theta, w, alpha, side)
    bx, by = a * math.cos(math.radians(theta)), a * math.sin(math.radians(theta))
    sketch = model.coordinates({"crank": (0, 0, theta), "coupler": (bx, by, exact["beta"] + 8),
                                "follower": (d, 0, exact["phi"] - 8)})
    (s,) = model.analyse([theta], w, alpha, sketch)
    assert rel(s.angle("coupler"), exact["beta"]) < 1e-11
    assert rel(s.angle("follower"), exact["phi"]) < 1e-11
    assert rel(s.omega("coupler"), exact["bd"]) < 1e-11
    assert rel(s.omega("follower"), exact["pd"]) < 1e-11
    assert rel(s.alpha("coupler"), exact["bdd"]) < 1e-10
    assert rel(s.alpha("follower"), exact["pdd"]) < 1e-10
    assert rel(s.position("coupler", "C")[0], exact["C"][0]) < 1e-12


def test_textbook_open_four_bar_angles():
    """The contract's example: a=40, b=120, c=80, d=100, theta=40: coupler 20.30, follower Bo->B 57.32."""
    model = four_bar(40, 120, 80, (100, 0))
    (s,) = model.analyse([40], 1, 0, model.coordinates(
        {"crank": (0, 0, 40), "coupler": (30.6, 25.7, 25), "follower": (100, 0, 60)}))
    assert round(float(s.angle("coupler")), 2) == 20.30
    assert round(float(s.angle("follower")), 2) == 57.32


# --------------------------------------------------------------------------- finite differences

@pytest.mark.parametrize("n, body, point", [(1, "link BD", "D"), (3, "member CCoD", "D"),
                                            (4, "link EDH", "E"), (5, "jaw DoD", "P"),
                                            (2, "rod ABC", "C")])
@pytest.mark.parametrize("theta", [17.3, 141.0, 263.9])
def test_rates_against_finite_differences_of_positions(n, body, point, theta):
    """Constant crank speed w: v = w dp/dtheta, a = w^2 d2p/dtheta2 (central differences, h = 1e-4 rad)."""
    from yaseer.reference.paper_mechanisms import CRANK_RATE

    w = CRANK_RATE[n]
    h = 1e-4
    hd = math.degrees(h)
    snapshots = example_snapshots(n, [theta - hd, theta, theta + hd], level="accelerations")
    before, here, after = (snap.position(body, point) for snap in snapshots)
    s = snapshots[1]
    v, acc = s.velocity(body, point), s.acceleration(body, point)
    scale_v = max(abs(v[0]), abs(v[1]))
    scale_a = max(abs(acc[0]), abs(acc[1]))
    for k in range(2):
        fd_v = w * (after[k] - before[k]) / (2 * h)
        fd_a = w * w * (after[k] - 2 * here[k] + before[k]) / (h * h)
        assert abs(v[k] - fd_v) < 1e-7 * scale_v
        assert abs(acc[k] - fd_a) < 1e-5 * scale_a


def test_angular_rates_against_finite_differences():
    """Example 3's output member: W(4), A(4) against differences of its angle T(9)."""
    h = 1e-4
    hd = math.degrees(h)
    snapshots = example_snapshots(3, [200.0 - hd, 200.0, 200.0 + hd])
    before, here, after = [float(snap.angle("member CCoD")) for snap in snapshots]
    s = snapshots[1]
    w = 30
    assert abs(s.omega("member CCoD") - w * math.radians(after - before) / (2 * h)) < 1e-7 * abs(s.omega("member CCoD"))
    assert abs(s.alpha("member CCoD") - w * w * math.radians(after - 2 * here + before) / h ** 2) \
        < 1e-4 * abs(s.alpha("member CCoD"))


# --------------------------------------------------------------------------- forces

def momentum_balance(s, fixed_joints):
    """Residual of Newton's laws for the whole machine (force x, force y, moment about the origin).

    External actions: ground reactions at ``fixed_joints``, the drive torque,
    the point loads and gravity; the inertia side m a_G and I alpha + r_G x m a_G.
    """
    mech = s.mechanism
    fx = fy = moment = 0.0
    for joint, body in fixed_joints:
        force = s.reaction(joint, body)
        at = s.position(body, mech.constraints[joint].local_i)
        fx, fy = fx + force[0], fy + force[1]
        moment += at[0] * force[1] - at[1] * force[0]
    moment += s.driver_torque("crank")
    for load in mech.loads:
        if isinstance(load, PointLoad):
            force = load.force(s)
            at = s.position(load.body.name, load.local)
            fx, fy = fx + force[0], fy + force[1]
            moment += at[0] * force[1] - at[1] * force[0]
        else:
            moment += load.torque(s)
    for body in mech.bodies.values():
        m = float(body.mass)
        g = s.position(body.name, body.centre)
        acc = s.acceleration(body.name, body.centre)
        weight = -m * float(mech.gravity)
        fy += weight
        moment += g[0] * weight
        fx -= m * acc[0]
        fy -= m * acc[1]
        moment -= float(body.inertia) * s.alpha(body.name) + m * (g[0] * acc[1] - g[1] * acc[0])
    return fx, fy, moment


@pytest.mark.parametrize("theta", [0.1, 100.1, 151.0, 300.1])
@pytest.mark.parametrize("gravity", [0, 9.81])
def test_example5_whole_machine_momentum(theta, gravity):
    (s,) = example_snapshots(5, [theta], gravity=gravity)
    residual = momentum_balance(s, [("Ao", "crank"), ("Bo", "toggle BoB"), ("Do", "jaw DoD")])
    scale = max(abs(c) for c in s.reaction("Bo", "toggle BoB")) + 1
    assert all(abs(r) < 1e-8 * scale for r in residual)


@pytest.mark.parametrize("theta", [40.1, 130.0])
def test_example5_every_body_obeys_newton_euler(theta):
    """Each body: sum of the joint forces on it + loads + weight = m a_G, and moments about G
    = I alpha.  Checks every reaction's sign convention (the force on the body named)."""
    (s,) = example_snapshots(5, [theta], gravity=9.81)
    mech = s.mechanism
    for body in mech.bodies.values():
        g = s.position(body.name, body.centre)
        fx = fy = moment = 0.0

        def add(force, at):
            nonlocal fx, fy, moment
            fx, fy = fx + force[0], fy + force[1]
            moment += (at[0] - g[0]) * force[1] - (at[1] - g[1]) * force[0]

        for joint in mech.constraints.values():
            if isinstance(joint, Revolute) and body in (joint.body_i, joint.body_j):
                local = joint.local_i if body is joint.body_i else joint.local_j
                add(s.reaction(joint.name, body.name), s.position(body.name, local))
        for load in mech.loads:
            if load.body is body:
                add(load.force(s), s.position(body.name, load.local))
        add((0.0, -float(body.mass) * 9.81), g)
        if body.name == "crank":
            moment += s.driver_torque("crank")
        acc = s.acceleration(body.name, body.centre)
        scale = 1 + max(abs(fx), abs(fy), float(body.mass) * math.hypot(*acc))
        assert abs(fx - float(body.mass) * acc[0]) < 1e-9 * scale, body.name
        assert abs(fy - float(body.mass) * acc[1]) < 1e-9 * scale, body.name
        assert abs(moment - float(body.inertia) * s.alpha(body.name)) < 1e-9 * (scale + abs(moment)), body.name


def test_action_equals_reaction_at_pins():
    (s,) = example_snapshots(5, [77.0])
    on_pitman, on_toggle = s.reaction("B", "pitman ABC"), s.reaction("B", "toggle BoB")
    assert on_pitman == (-on_toggle[0], -on_toggle[1])
    with pytest.raises(ValueError, match="not in joint"):
        s.reaction("B", "jaw DoD")


def test_levels_compute_no_more_than_asked():
    (p,) = example_snapshots(4, [50.0], level="positions")
    with pytest.raises(ValueError, match="velocities were not computed"):
        p.velocity("link EDH", "E")
    (v,) = example_snapshots(4, [50.0], level="velocities")
    (a,) = example_snapshots(4, [50.0])
    assert v.velocity("link EDH", "E") == a.velocity("link EDH", "E")
    with pytest.raises(ValueError, match="accelerations were not computed"):
        v.alpha("link EDH")
    assert p.position("link EDH", "E") == a.position("link EDH", "E")
    with pytest.raises(ValueError, match="level is one of"):
        example_snapshots(4, [50.0], level="jerks")


def kinetic_energy_rate_by_differences(n, theta, h=1e-4):
    from yaseer.reference.paper_mechanisms import CRANK_RATE

    hd = math.degrees(h)
    before, after = example_snapshots(n, [theta - hd, theta + hd], level="velocities")
    return CRANK_RATE[n] * (after.kinetic_energy() - before.kinetic_energy()) / (2 * h)


@pytest.mark.parametrize("n, gravity", [(2, 0), (5, 0), (5, 9.81)])
@pytest.mark.parametrize("theta", [20.1, 120.1, 250.0])
def test_drive_power_balances_energy(n, gravity, theta):
    """U w = dT/dt - power of the loads and gravity; dT/dt by central differences of the kinetic energy."""
    from yaseer.reference.paper_mechanisms import CRANK_RATE

    (s,) = example_snapshots(n, [theta], gravity=gravity)
    drive_power = s.driver_torque("crank") * CRANK_RATE[n]
    expected = kinetic_energy_rate_by_differences(n, theta) - s.power_of_loads()
    assert abs(drive_power - expected) < 1e-6 * (abs(expected) + abs(s.power_of_loads()) + 1e-3)


@pytest.mark.parametrize("theta", [10.0, 200.0])
def test_slider_crank_with_gravity_power_and_piston_forces(theta):
    """Masses, gravity, a piston body with a prismatic pair and a couple on the rod."""
    model = slider_crank_model(3.0, 8.0, 2.0, with_slider_body=True, masses=True)
    model.gravity = 9.81
    rod = model.body("rod")
    model.loads = [Couple(rod, lambda s: 4.0),
                   PointLoad(model.body("piston"), "B", lambda s: (-50.0, 0.0))]
    w = 12.0
    h = 1e-4

    def solve(angle):
        placement = {"crank": (0, 0, angle), "rod": (3 * math.cos(math.radians(angle)),
                                                      3 * math.sin(math.radians(angle)), 5),
                     "piston": (9, 2, 0)}
        (s,) = model.analyse([angle], w, 0, model.coordinates(placement), level="forces")
        return s

    s, before, after = solve(theta), solve(theta - math.degrees(h)), solve(theta + math.degrees(h))
    energy_rate = w * (after.kinetic_energy() - before.kinetic_energy()) / (2 * h)
    assert abs(s.driver_torque("drive") * w - (energy_rate - s.power_of_loads())) < 1e-6 * abs(energy_rate) + 1e-6
    # the piston: guide normal force balances weight, rod force and the wall couple keeps it from turning
    piston_force = s.reaction("B", "piston")
    normal = s.normal_force("guide")
    assert abs(piston_force[1] + normal - 1.5 * 9.81 - 1.5 * s.acceleration("piston", (0, 0))[1]) < 1e-9
    assert abs(piston_force[0] - 50.0 - 1.5 * s.acceleration("piston", (0, 0))[0]) < 1e-9


# --------------------------------------------------------------------------- arithmetic

@pytest.mark.parametrize("n", [1, 2, 3, 4, 5])
def test_mpmath_path_agrees_with_float_path(n):
    from yaseer.reference.paper_mechanisms import example_columns

    angles = [40.1, 220.1]
    exact = example_columns(n, angles, number="mpmath", dps=40)
    rough = example_columns(n, angles)
    for row_exact, row_float in zip(exact, rough):
        for e, f in zip(row_exact, row_float):
            assert rel(f, e) < 1e-11


def test_mpmath_positions_are_polished_to_the_precision():
    """At 50 digits the constraints hold to ~1e-48 and 50 vs 70 digits agree to ~1e-45."""
    mechanism = example_mechanism(4).mechanism
    (s50,) = example_snapshots(4, [123.4], number="mpmath", dps=50)
    (s70,) = example_snapshots(4, [123.4], number="mpmath", dps=70)
    from yaseer.reference.solver import _Kinematics

    residuals = mechanism._residuals(_Kinematics(s50.ar, s50.q), s50.drive)
    assert max(abs(r) for r in residuals) < 1e-46
    for a, b in zip(s50.qdd, s70.qdd):
        assert abs(a - b) < 1e-42 * (1 + abs(b))
    assert s50.error_bound < 1e-44


def test_mp_arithmetic_takes_decimal_strings_exactly():
    ar = MpArithmetic(40)
    assert ar.num("0.1") * 10 == 1
    assert ar.num(0.1) * 10 != 1  # a float is its binary value


# --------------------------------------------------------------------------- failures are errors

def test_not_assembled_is_an_error():
    model = four_bar(30, 36, 36, (60, 0))
    with pytest.raises(MechanismError, match="cannot be assembled"):
        model.analyse([180.0], 10, 0, model.coordinates({"crank": (0, 0, 180), "coupler": (-30, 0, 0),
                                                          "follower": (60, 0, 180)}))


def test_toggle_position_is_an_error_not_a_number():
    """A four-bar driven through its toggle (coupler and follower in line) stops with a clear error."""
    a, b, c, d = 30.0, 36.0, 36.0, 60.0
    toggle = math.degrees(math.acos((a * a + d * d - (b + c) ** 2) / (2 * a * d)))
    model = four_bar(a, b, c, (d, 0))
    sketch = model.coordinates({"crank": (0, 0, 0), "coupler": (30, 0, 65), "follower": (60, 0, 115)})
    with pytest.raises(MechanismError, match="singular|converge"):
        model.analyse([toggle], 10, 0, sketch, home_deg=0)


def test_conditioning_is_reported():
    (s,) = example_snapshots(1, [30.0])
    assert 1 <= s.condition < 1e4 and s.error_bound < 1e-8


def test_mechanism_needs_as_many_equations_as_coordinates():
    crank = Body("crank", points={"A": (1, 0)})
    with pytest.raises(ValueError, match="constraint equations"):
        Mechanism([crank], [Revolute("O", crank, (0, 0), None, (0, 0))])


def test_forces_require_a_force_analysis():
    (s,) = example_snapshots(1, [30.0])
    with pytest.raises(ValueError, match="forces were not computed"):
        s.reaction("Ao", "crank")


def test_drive_values_enter_velocity_and_acceleration():
    model = slider_crank_model(3.0, 8.0, 2.0)
    q = model.newton(model.coordinates({"crank": (0, 0, 50), "rod": (1.9, 2.3, 0)}),
                     Drive(math.radians(50), 0, 0))
    still = model.snapshot(q, Drive(math.radians(50), 0.0, 0.0))
    assert all(v == 0 for v in still.qd) and all(a == 0 for a in still.qdd)
    moving = model.snapshot(q, Drive(math.radians(50), 2.0, 0.0))
    assert moving.omega("crank") == pytest.approx(2.0)
    assert polar(2, 90).xy(still.ar)[1] == pytest.approx(2.0)


# --------------------------------------------------------------------------- the examples' loads

def test_example5_crushing_force_resists_the_closing_jaw():
    """F acts only while W(7) < 0, never does positive work, and T(14) stays in the contract's range."""
    angles = [0.1 + 10 * k for k in range(36)]
    loaded = 0
    for s in example_snapshots(5, angles):
        t14 = float(s.direction("jaw DoD", "D", "Do"))
        assert -100.4 < t14 < -99.5
        (load,) = s.mechanism.loads
        force = load.force(s)
        power = force[0] * s.velocity("jaw DoD", "P")[0] + force[1] * s.velocity("jaw DoD", "P")[1]
        if s.omega("jaw DoD") < 0:
            loaded += 1
            assert math.hypot(*force) == pytest.approx(500 / (t14 + 100.5) ** 3, rel=1e-12)
            assert power < 0
        else:
            assert force == (0.0, 0.0)
    assert 5 < loaded < 31


def test_example2_plunger_load_resists_the_plunger():
    for s in example_snapshots(2, [5.0 + 20 * k for k in range(18)]):
        (load,) = s.mechanism.loads
        force, v = load.force(s), s.velocity("link CD", "D")
        speed = math.hypot(*v)
        assert math.hypot(*force) == pytest.approx(650 * speed ** 2, rel=1e-12)
        assert force[0] * v[0] + force[1] * v[1] <= 0


# --------------------------------------------------------------------------- basic linkages in the contract's terms

@pytest.mark.parametrize("axis", [0.0, 90.0, 90.1, -37.0])
@pytest.mark.parametrize("theta", [0.0, 66.0, 180.0, 250.0])
def test_program1_reference_against_the_rotated_closed_form(axis, theta):
    """Program 1's line e u(axis - 90) + s u(axis): in a frame turned by ``axis`` it is the
    plain slider-crank with the pin on y' = -e and crank angle theta - axis."""
    e, a, b, w, alpha = 20.0, 40.0, 120.0, 6.0, -2.0
    r = basic_linkages.slider_crank(e, a, b, [theta], w, alpha, axis_deg=axis)
    exact = slider_crank_closed_form(a, b, -e, theta - axis, w, alpha)
    c, s = math.cos(math.radians(axis)), math.sin(math.radians(axis))
    turn = lambda x, y: (c * x - s * y, s * x + c * y)  # noqa: E731
    expected = {"xB": turn(exact["x"], -e)[0], "yB": turn(exact["x"], -e)[1],
                "vxB": turn(exact["v"], 0)[0], "vyB": turn(exact["v"], 0)[1],
                "axB": turn(exact["a"], 0)[0], "ayB": turn(exact["a"], 0)[1]}
    for name, value in expected.items():
        assert abs(r[name][0] - value) < 1e-10 * (1 + abs(value)), name
    assert abs(r["W(3)"][0] - exact["w_rod"]) < 1e-12 and abs(r["A(3)"][0] - exact["a_rod"]) < 1e-10
    rod = exact["rod"] + axis
    assert abs(math.remainder(r["T(3)"][0] - rod, 360)) < 1e-10


def test_program1_reference_at_the_dead_centre():
    """In line (e = 0) at theta = 0: the piston stops, a = -a w^2 (1 + a/b) (textbook)."""
    a, b, w = 40.0, 120.0, 6.0
    r = basic_linkages.slider_crank(0, a, b, [0.0], w, 0)
    assert r["xB"][0] == pytest.approx(a + b, rel=1e-15)
    assert abs(r["vxB"][0]) < 1e-12
    assert r["axB"][0] == pytest.approx(-a * w * w * (1 + a / b), rel=1e-12)


@pytest.mark.parametrize("ground", [0.0, 30.0, -123.0])
def test_program2_reference_contract_example_any_ground_direction(ground):
    """a=40, b=120, c=80, d=100, theta=40 (relative to the ground): uncrossed coupler 20.30,
    follower Bo->B 57.32, so T(14) (B->Bo) = -122.68; all turn with the fixed link."""
    r = basic_linkages.fourbar(100, ground, 40, 120, 80, [40 + ground], 7.0, 0)
    assert math.remainder(r["T(13)"][0] - ground - 20.30, 360) == pytest.approx(0, abs=0.005)
    assert math.remainder(r["T(14)"][0] - ground + 122.68, 360) == pytest.approx(0, abs=0.005)
    exact = four_bar_closed_form(40, 120, 80, 100, 40, 7.0, 0, 1)
    assert r["W(6)"][0] == pytest.approx(exact["bd"], rel=1e-11)
    assert r["A(7)"][0] == pytest.approx(exact["pdd"], rel=1e-10)


def test_program2_reference_crossed_is_the_mirror_branch():
    r = basic_linkages.fourbar(100, 0, 40, 120, 80, [40], 7.0, 0, crossed=True)
    exact = four_bar_closed_form(40, 120, 80, 100, 40, 7.0, 0, -1)
    assert r["T(13)"][0] == pytest.approx(exact["beta"], abs=1e-10)
    assert r["W(7)"][0] == pytest.approx(exact["pd"], rel=1e-11)


@pytest.mark.parametrize("theta", [10.0, 135.0, 290.0])
def test_program3_reference_against_geometry_and_differences(theta):
    """FISC: L(5), T(9) from the vector Bo->A directly; rates against central differences."""
    L6, T6, L7, w = 5.7, -74.74, 2.5, 30.0
    h = 1e-4
    hd = math.degrees(h)
    r = programs.inverted_slider_crank(L6, T6, L7, [theta - hd, theta, theta + hd], w, 0)
    bo = (-L6 * math.cos(math.radians(T6)), -L6 * math.sin(math.radians(T6)))
    pin = (L7 * math.cos(math.radians(theta)), L7 * math.sin(math.radians(theta)))
    assert r["L(5)"][1] == pytest.approx(math.hypot(pin[0] - bo[0], pin[1] - bo[1]), rel=1e-13)
    assert r["T(9)"][1] == pytest.approx(math.degrees(math.atan2(pin[1] - bo[1], pin[0] - bo[0])), abs=1e-11)
    for value, rate, accel, unit in (("L(5)", "D(4)", "E(4)", 1.0), ("T(9)", "W(4)", "A(4)", math.pi / 180)):
        before, here, after = (float(v) * unit for v in r[value])
        assert r[rate][1] == pytest.approx(w * (after - before) / (2 * h), rel=1e-7)
        assert r[accel][1] == pytest.approx(w * w * (after - 2 * here + before) / h ** 2, rel=1e-5, abs=1e-6)


def test_basic_linkage_references_refuse_what_does_not_assemble():
    with pytest.raises(MechanismError, match="cannot be assembled"):
        basic_linkages.slider_crank(0, 40, 30, [90.0], 1, 0)
    with pytest.raises(MechanismError, match="cannot be assembled"):
        basic_linkages.fourbar(60, 0, 30, 36, 36, [180.0], 1, 0)


def test_basic_linkage_references_in_mpmath():
    r = basic_linkages.fourbar("100", "30", "40", "120", "80", [70.0], 7, 0, number="mpmath", dps=40)
    f = basic_linkages.fourbar(100, 30, 40, 120, 80, [70.0], 7, 0)
    assert abs(float(r["A(6)"][0]) - f["A(6)"][0]) < 1e-11 * abs(f["A(6)"][0])
    s = basic_linkages.slider_crank("25", "75", "300", [33.0], 25, 0, axis_deg="0.1", number="mpmath", dps=40)
    g = basic_linkages.slider_crank(25, 75, 300, [33.0], 25, 0, axis_deg=0.1)
    assert abs(float(s["ayB"][0]) - g["ayB"][0]) < 1e-10 * abs(g["axB"][0])


def test_mp_solve_against_a_system_with_a_known_solution():
    """A 3x3 system built from x = (1/3, -2, 7/11) needs pivoting (zero first pivot)."""
    from yaseer.reference.arithmetic import SingularSystemError

    ar = MpArithmetic(60)
    x = [ar.num(1) / 3, ar.num(-2), ar.num(7) / 11]
    rows = [[ar.num(0), ar.num(2), ar.num(1)], [ar.num(4), ar.num(-1), ar.num(3)], [ar.num(1), ar.num(5), ar.num(-2)]]
    rhs = [sum(a * b for a, b in zip(row, x)) for row in rows]
    solved = ar.solve(rows, rhs)
    assert all(abs(a - b) < ar.num(10) ** -57 for a, b in zip(solved, x))
    with pytest.raises(SingularSystemError):
        ar.solve([[ar.num(1), ar.num(2)], [ar.num(2), ar.num(4)]], [ar.num(1), ar.num(2)])


def test_drive_rates_may_change_from_position_to_position():
    """theta(t) with a varying rate: each position uses its own (rate, acceleration)."""
    model = slider_crank_model(3.0, 8.0, 2.0)
    sketch = model.coordinates({"crank": (0, 0, 10), "rod": (2.95, 0.52, 10)})
    varying = model.analyse([10.0, 50.0], [4.0, -7.0], [1.0, 2.5], sketch)
    for s, (theta, w, alpha) in zip(varying, [(10.0, 4.0, 1.0), (50.0, -7.0, 2.5)]):
        exact = slider_crank_closed_form(3.0, 8.0, 2.0, theta, w, alpha)
        assert rel(s.velocity("rod", "B")[0], exact["v"]) < 1e-11
        assert rel(s.acceleration("rod", "B")[0], exact["a"]) < 1e-10
    with pytest.raises(ValueError, match="rates for"):
        model.analyse([10.0, 50.0], [4.0], 0, sketch)


def test_mpmath_reference_near_a_toggle_against_the_closed_form_in_mpmath():
    """1e-9 deg before the toggle of seed 003's four-bar (rates ~1e4 x normal): the 50-digit
    solver and the closed form evaluated at 50 digits agree to 1e-30."""
    import mpmath

    ctx = mpmath.MPContext()
    ctx.dps = 50
    a, b, c, d = 30, 36, 36, 60
    toggle = ctx.degrees(ctx.acos(ctx.mpf(a * a + d * d - (b + c) ** 2) / (2 * a * d)))
    theta = toggle - ctx.mpf("1e-9")
    exact = four_bar_closed_form(a, b, c, d, theta, 10, 0, -1, m=ctx)
    r = basic_linkages.fourbar(d, 0, a, b, c, [theta], 10, 0, crossed=True, number="mpmath", dps=50)
    assert abs(r["W(6)"][0] - exact["bd"]) < ctx.mpf("1e-30") * abs(exact["bd"])
    assert abs(r["A(7)"][0] - exact["pdd"]) < ctx.mpf("1e-30") * abs(exact["pdd"])
    assert abs(exact["bd"]) > 1e4
    with pytest.raises(MechanismError, match="singular"):
        basic_linkages.fourbar(d, 0, a, b, c, [float(theta)], 10, 0, crossed=True)


# --------------------------------------------------------------------------- flexible cranks

@pytest.mark.parametrize("theta", [20.0, 160.0, 300.0])
def test_flexible_slider_crank_against_the_closed_form(theta):
    """A crank whose length changes (D(0) = 4, E(0) = -30): the pin slides along the crank."""
    r, rd, rdd, l, e, w, alpha = 3.0, 4.0, -30.0, 8.0, 2.0, -15.0, -10.0
    got = basic_linkages.slider_crank(-e, r, l, [theta], w, alpha, crank_rate=rd, crank_accel=rdd)
    exact = slider_crank_closed_form(r, l, e, theta, w, alpha, rd, rdd)
    assert got["xB"][0] == pytest.approx(exact["x"], rel=1e-12)
    assert got["vxB"][0] == pytest.approx(exact["v"], rel=1e-11)
    assert got["axB"][0] == pytest.approx(exact["a"], rel=1e-10)
    assert got["W(3)"][0] == pytest.approx(exact["w_rod"], rel=1e-11)
    assert got["A(3)"][0] == pytest.approx(exact["a_rod"], rel=1e-10)


def time_law(t, start, rate, accel):
    return start + rate * t + accel * t * t / 2, rate + accel * t, accel


@pytest.mark.parametrize("program", ["fourbar", "fisc"])
def test_flexible_crank_rates_against_differences_in_time(program):
    """theta(t) and the crank length L(t) both vary; the outputs at t = -h, 0, h by the
    reference's positions, differenced in time, against its rates at t = 0."""
    h = 1e-4
    times = [-h, 0.0, h]
    theta = [time_law(t, 35.0, math.degrees(6.0), math.degrees(-4.0)) for t in times]
    length = [time_law(t, 40.0, 25.0, -300.0) for t in times]
    angles = [th[0] for th in theta]
    omegas = [math.radians(th[1]) for th in theta]
    alphas = [math.radians(th[2]) for th in theta]
    lengths, rates, accels = ([x[k] for x in length] for k in range(3))
    if program == "fourbar":
        r = basic_linkages.fourbar(100, 20, lengths, 120, 80, angles, omegas, alphas,
                                   crank_rate=rates, crank_accel=accels)
        pairs = [("T(13)", "W(6)", "A(6)", math.pi / 180), ("T(14)", "W(7)", "A(7)", math.pi / 180)]
    else:
        r = programs.inverted_slider_crank(90, 200, lengths, angles, omegas, alphas,
                                                 crank_rate=rates, crank_accel=accels)
        pairs = [("T(9)", "W(4)", "A(4)", math.pi / 180), ("L(5)", "D(4)", "E(4)", 1.0)]
    for value, rate, accel, unit in pairs:
        before, here, after = (float(v) * unit for v in r[value])
        assert r[rate][1] == pytest.approx((after - before) / (2 * h), rel=1e-6), rate
        assert r[accel][1] == pytest.approx((after - 2 * here + before) / h ** 2, rel=1e-4), accel


def test_length_driver_needs_its_values():
    from yaseer.reference.basic_linkages import FlexibleCrank, slider_crank_model

    model = slider_crank_model(0, FlexibleCrank(3.0, 1.0, 0.0), 8.0)
    with pytest.raises(ValueError, match="no values given"):
        model.analyse([10.0], 1, 0, model.coordinates({"crank": (0, 0, 10), "rod": (3, 0.5, 0)}))


PROGRAM1_MASSES_AND_LOADS = {
    "L(1)": 0.01, "T(4)": 20, "L(2)": 0.021, "L(3)": 0.06, "R(1)": 0.02, "H(1)": 45, "R(2)": 0.01, "H(2)": 30,
    "R(3)": 0.015, "H(3)": -20, "R(4)": 0.01, "H(4)": 150, "M(2)": 2, "M(3)": 3, "M(4)": 1.5, "I(2)": 0.1,
    "I(3)": 0.2, "F(0)": 5, "F(1)": -3, "F(7)": 2, "F(8)": 1, "F(2)": 4, "F(9)": -6, "U(1)": 0.7, "P(1)": 12,
    "G": 9.81, "Z(1)": 2}
PROGRAM2_MASSES_AND_LOADS = {
    "L(11)": 100, "T(11)": 15, "L(12)": 40, "L(13)": 120, "L(14)": 80, "R(9)": 20, "H(9)": 30, "R(8)": 10,
    "H(10)": -40, "R(11)": 60, "H(11)": 25, "R(10)": 50, "H(12)": 10, "R(13)": 30, "H(13)": -15, "R(12)": 35,
    "H(14)": 20, "M(6)": 2, "M(7)": 3, "M(8)": 2.5, "I(6)": 0.1, "I(7)": 0.4, "I(8)": 0.3, "F(29)": 5,
    "F(30)": -3, "F(32)": 2, "F(33)": 7, "F(35)": -4, "F(36)": 1, "F(31)": 4, "F(34)": -6, "F(37)": 3,
    "U(2)": 0.7, "G": 9.81, "Z(2)": 2}


PROGRAM3_MASSES_AND_LOADS = {
    "L(6)": 90, "T(6)": 20, "L(7)": 40, "R(0)": 25, "H(23)": 35, "R(5)": 15, "T(5)": -20, "R(7)": 70,
    "H(6)": -10, "R(6)": 45, "H(7)": 5, "M(0)": 2, "M(1)": 0.8, "M(5)": 3, "I(0)": 0.2, "I(1)": 0.05,
    "I(5)": 0.6, "U(3)": 0.9, "F(18)": -4, "G": 9.81, "Z(3)": 2}


def _program_snapshots(program, q, angles, w):
    from yaseer.reference.basic_linkages import FlexibleCrank, fourbar_sketch
    from yaseer.reference.programs import program1_model, program2_model, program3_model

    if program == 3:
        model = program3_model(dict(PROGRAM3_MASSES_AND_LOADS, **{"Q(3)": q}), FlexibleCrank(40))
        pin = (40 * math.cos(math.radians(angles[0])), 40 * math.sin(math.radians(angles[0])))
        bo = (-90 * math.cos(math.radians(20)), -90 * math.sin(math.radians(20)))
        direction = math.degrees(math.atan2(pin[1] - bo[1], pin[0] - bo[0]))
        sketch = model.coordinates({"crank": (0, 0, angles[0]), "block": (pin[0], pin[1], direction),
                                    "follower": (bo[0], bo[1], direction)})
    elif program == 1:
        model = program1_model(dict(PROGRAM1_MASSES_AND_LOADS, **{"Q(1)": q}), FlexibleCrank(0.021))
        sketch = model.coordinates({"crank": (0, 0, angles[0]), "rod": (0.05, 0.03, 200),
                                    "piston": (0.05, 0.03, 0)})
    else:
        model = program2_model(dict(PROGRAM2_MASSES_AND_LOADS, **{"Q(2)": q}), FlexibleCrank(40))
        pivot = (100 * math.cos(math.radians(15)), 100 * math.sin(math.radians(15)))
        sketch = fourbar_sketch(model, angles[0], 40, 120, 80, pivot, 1)
    return model.analyse(angles, w, 0, sketch, level="forces")


@pytest.mark.parametrize("program, q", [(1, 1), (1, 2), (1, 3), (1, 4), (2, 1), (2, 2), (2, 3), (2, 4),
                                        (3, 1), (3, 3)])
def test_program_reference_unknown_load_balances_the_energy(program, q):
    """With the unknown load found, the drive does no work: dT/dt (central differences of the
    kinetic energy) = power of all loads, the unknown one and gravity included."""
    w, h, theta = -8.0, 1e-4, 130.0
    before, here, after = _program_snapshots(program, q, [theta - math.degrees(h), theta,
                                                          theta + math.degrees(h)], w)
    assert abs(here.driver_torque("crank")) < 1e-9
    assert here.unknown_value != 0
    energy_rate = w * (after.kinetic_energy() - before.kinetic_energy()) / (2 * h)
    assert here.power_of_loads() == pytest.approx(energy_rate, rel=1e-6)


def test_program1_reference_refuses_an_unknown_that_cannot_balance():
    """An unknown perpendicular force at R = 0 on the crank has no moment: a clear error."""
    with pytest.raises(MechanismError, match="cannot balance"):
        programs.program1({"L(2)": 2, "L(3)": 6, "T(4)": 0, "W(2)": 1, "Z(1)": 2, "Q(1)": 2,
                                 "U(1)": 1.0}, [40.0])
    with pytest.raises(ValueError, match="Q\\(1\\)"):
        programs.program1({"L(2)": 2, "L(3)": 6, "Z(1)": 2, "Q(1)": 7}, [40.0])


@pytest.mark.parametrize("program, inputs, q_name", [(1, PROGRAM1_MASSES_AND_LOADS, "Q(1)"),
                                                    (2, PROGRAM2_MASSES_AND_LOADS, "Q(2)"),
                                                    (3, PROGRAM3_MASSES_AND_LOADS, "Q(3)")])
def test_program_references_in_mpmath(program, inputs, q_name):
    run = getattr(programs, f"program{program}")
    values = dict(inputs, **{q_name: 3, "W(2)": -8, "W(5)": 7, "W(0)": 6, "L(12)": 40, "L(7)": 40})
    rough = run(values, [40.0])
    exact = run(values, [40.0], number="mpmath", dps=40)
    for name, value in rough.items():
        assert abs(float(exact[name][0]) - value[0]) <= 1e-12 * (1 + abs(value[0])), name


def test_examples_as_drawn_have_exact_axes():
    """dodge=0: Example 1's piston D runs on x = 150 exactly, Example 3's B on x = 0."""
    for s in example_snapshots(1, [12.0, 200.0], dodge=0):
        assert s.position("link BD", "D")[0] == pytest.approx(150, abs=1e-12)
        assert abs(s.velocity("link BD", "D")[0]) < 1e-9
    for s in example_snapshots(3, [12.0, 200.0], dodge=0):
        assert abs(s.position("rod BAC", "B")[0]) < 1e-12


# --------------------------------------------------------------------------- random geometries

from hypothesis import HealthCheck, assume, example, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(a=st.floats(5, 60), b=st.floats(20, 150), c=st.floats(20, 150), d=st.floats(20, 150),
       theta=st.floats(-180, 180), side=st.sampled_from([1, -1]), w=st.floats(-20, 20), alpha=st.floats(-50, 50))
# A parallelogram 1.5 degrees from its folded position: the diagonal B-D is 1.2 long against
# links of 139, so every double-precision solution loses about two digits there.
@example(a=47.0, b=139.0, c=139.0, d=47.0, theta=1.5, side=1, w=1.0, alpha=0.0)
def test_four_bar_reference_on_random_geometries(a, b, c, d, theta, side, w, alpha):
    """Any assemblable position away from toggles: the solver equals the hand closed form.

    The tolerance of the rates grows with the condition of the position, (b + c) / reach:
    the loop closes on the short diagonal from B to the follower's pivot, and an error of
    one unit in the last place of the links is magnified by that ratio in any solution.
    """
    t = math.radians(theta)
    reach = math.hypot(d - a * math.cos(t), a * math.sin(t))
    assume(abs(b - c) + 1 < reach < b + c - 1)
    exact = four_bar_closed_form(a, b, c, d, theta, w, alpha, side)
    r = basic_linkages.fourbar(d, 0, a, b, c, [theta], w, alpha, crossed=side < 0)
    condition = (b + c) / reach
    scale_w = abs(a * w) / min(b, c) + 1e-9
    assert math.remainder(r["T(13)"][0] - exact["beta"], 360) == pytest.approx(0, abs=1e-9)
    assert r["W(6)"][0] == pytest.approx(exact["bd"], rel=1e-8, abs=1e-10 * scale_w * condition)
    assert r["A(7)"][0] == pytest.approx(exact["pdd"], rel=1e-8,
                                         abs=1e-10 * (scale_w ** 2 + abs(alpha)) * condition)


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(r=st.floats(5, 60), l=st.floats(20, 150), e=st.floats(-100, 100), theta=st.floats(-180, 180),
       axis=st.floats(-180, 180), w=st.floats(-20, 20), alpha=st.floats(-50, 50))
def test_slider_crank_reference_on_random_geometries(r, l, e, theta, axis, w, alpha):
    """Program 1's reference on random geometries against the closed form turned by the axis."""
    height = -e - r * math.sin(math.radians(theta - axis))
    assume(abs(height) < 0.98 * l)
    got = basic_linkages.slider_crank(e, r, l, [theta], w, alpha, axis_deg=axis)
    exact = slider_crank_closed_form(r, l, -e, theta - axis, w, alpha)
    scale = r * (abs(w) + 1) ** 2 + r * abs(alpha)
    c, s = math.cos(math.radians(axis)), math.sin(math.radians(axis))
    assert got["xB"][0] == pytest.approx(c * exact["x"] + s * e, abs=1e-10 * (l + r))
    assert got["vxB"][0] == pytest.approx(c * exact["v"], abs=1e-9 * scale)
    assert got["axB"][0] == pytest.approx(c * exact["a"], abs=1e-8 * scale * (1 + r / l) ** 2 / (1 - (height / l) ** 2))


# --------------------------------------------------------------------------- the virtual link is exact

def polar_motion(r, v, a):
    """Length, angle (deg) and their rates of the vector r with velocity v and acceleration a.

    r = L u, v = L' u + L T' n, a = (L'' - L T'^2) u + (L T'' + 2 L' T') n, u = r/L, n = u turned 90 deg.
    """
    length = math.hypot(*r)
    u = (r[0] / length, r[1] / length)
    n = (-u[1], u[0])
    rate = v[0] * u[0] + v[1] * u[1]
    angle_rate = (v[0] * n[0] + v[1] * n[1]) / length
    accel = a[0] * u[0] + a[1] * u[1] + length * angle_rate ** 2
    angle_accel = (a[0] * n[0] + a[1] * n[1] - 2 * rate * angle_rate) / length
    return length, math.degrees(math.atan2(r[1], r[0])), rate, accel, angle_rate, angle_accel


@pytest.mark.parametrize("theta", [20.0, 150.0, 275.0])
def test_example1_virtual_link_as_a_flexible_crank_is_exact(theta):
    """The paper's idea, checked without Program 5: Ao->B of the real Example 1 mechanism,
    turned into a flexible crank (length, angle and their rates), drives the slider-crank
    AoBD of programs.program1 to exactly the real piston D."""
    (s,) = example_snapshots(1, [theta])
    length, angle, rate, accel, w, alpha = polar_motion(
        s.position("rod ABC", "B"), s.velocity("rod ABC", "B"), s.acceleration("rod ABC", "B"))
    crank = programs.program1({"L(1)": 150, "T(4)": 90.1, "L(2)": length, "L(3)": 150, "T(2)": angle,
                               "W(2)": w, "A(2)": alpha, "D(0)": rate, "E(0)": accel})
    d = "link BD", "D"
    assert crank["Y(2)"][0] == pytest.approx(s.position(*d)[1], rel=1e-12)
    assert crank["V(4)"][0] == pytest.approx(s.velocity(*d)[1], rel=1e-10, abs=1e-9)
    assert crank["A(36)"][0] == pytest.approx(s.acceleration(*d)[1], rel=1e-9, abs=1e-6)
