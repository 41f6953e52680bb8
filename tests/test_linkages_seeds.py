"""Programs 1 and 2 against numbers printed in the seed papers and a textbook case,
and the exact special positions the paper dodged with its .1 offsets."""

from __future__ import annotations

import numpy as np
import pytest

from yaseer.linkages import AssemblyError, LockedError, fourbar, inverted_slider_crank, slider_crank


def test_slider_crank_matches_seed_001_worked_table():
    # Seed 001 (Boyle & Liu, TK Solver; Norton table P7-2 row c): AO = 3, AB = 8, offset 2, open
    # branch, thetaAO = -30 deg, omegaAO = -15, alphaAO = -10.  Its slider runs along +x on the
    # line y = +offset, B ahead of A: in the contract's terms phi = 0 and the line
    # e u(phi - 90) + s u(phi) = (s, -e), so e = -2.
    kin = slider_crank(-2.0, 3.0, 8.0, -30.0, -15.0, -10.0, axis_deg=0.0)
    assert kin.pin_b.pos.imag == pytest.approx(2.0, abs=1e-12)
    assert kin.pin_b.pos.real == pytest.approx(9.79, abs=0.005)
    assert kin.pin_b.vel.real == pytest.approx(-41.46, abs=0.005)
    assert kin.rod.omega == pytest.approx(5.42, abs=0.005)
    assert kin.pin_b.acc.real == pytest.approx(-709.1, abs=0.05)
    assert kin.rod.alpha == pytest.approx(-29.03, abs=0.005)
    assert kin.pin_b.vel.imag == 0 and abs(kin.pin_b.acc.imag) < 1e-12


# Seed 003 (Oke et al., Fortran four-bar, Plate 1): a = 30, b = 36, c = 36, d = 60, omega = 10,
# ground A->D along +x.  Its PHI is the follower angle D->C (our Bo->B, T(14) + 180) and BETA the
# coupler angle B->C (our T(13)).  Per crank angle, the two printed rows: (PHI, BETA) of the
# upper row (our crossed branch, L(10) = 1) and of the lower row (uncrossed).  Read from the
# scan (the OCR misreads -106.19 as "-06.19"); 120..240 deg cannot be assembled and are not printed.
SEED_003_ANGLES = {
    0: ((-114.62, -65.38), (114.62, 65.38)),
    30: ((-144.88, -82.70), (97.30, 35.12)),
    60: ((-166.19, -73.81), (106.19, 13.81)),
    90: ((174.73, -47.86), (132.14, -5.27)),
    270: ((-132.14, 5.27), (-174.73, 47.86)),
    300: ((-106.19, -13.81), (166.19, 73.81)),
    330: ((-97.30, -35.12), (144.88, 82.70)),
}


def seed_003(theta, branch):
    return fourbar(60.0, 0.0, 30.0, 36.0, 36.0, theta, 10.0, branch=branch)


@pytest.mark.parametrize("theta", sorted(SEED_003_ANGLES))
def test_fourbar_matches_seed_003_angles_on_both_branches(theta):
    for branch, (phi, beta) in zip((-1, 1), SEED_003_ANGLES[theta]):
        kin = seed_003(theta, branch)
        follower_from_pivot = np.degrees(np.angle(-np.exp(1j * kin.follower.angle)))
        assert follower_from_pivot == pytest.approx(phi, abs=0.006)
        assert kin.coupler.degrees == pytest.approx(beta, abs=0.006)


@pytest.mark.parametrize("theta", [120, 150, 180, 210, 240])
def test_fourbar_seed_003_positions_the_program_skipped_do_not_assemble(theta):
    with pytest.raises(AssemblyError):
        seed_003(theta, 1)


def test_fourbar_velocity_magnitudes_match_seed_003():
    # Only magnitudes of the follower's angular velocity (VELC) are compared, and VELB and the
    # acceleration columns not at all: the paper's equation (xxi) carries a spurious minus sign
    # (eliminating w2 from the differentiated loop gives w3 = a w1 sin(theta - beta) /
    # (c sin(phi - beta)); the listing's VELC statement has the right sign), the listing's VELB
    # divides by SIN(BET(I) - (I)) -- the loop index in radians where PHI(I) belongs -- its C2
    # uses VEL, never set (0 in Fortran), not VELA, and ACCB = B1 - B2 - B3/B4 divides only B3
    # (see docs/seed-003.md).  The scan keeps VELC legible in the first row (theta = 0, upper:
    # -10.00) and the last (theta = 330, lower: -8.69); the legible VELC values are
    # {10.00, 8.69, 8.26, 12.26} in magnitude.
    assert abs(seed_003(0, -1).follower.omega) == pytest.approx(10.00, abs=0.005)
    assert abs(seed_003(330, 1).follower.omega) == pytest.approx(8.69, abs=0.005)
    computed = {round(float(abs(seed_003(theta, branch).follower.omega)), 2)
                for theta in SEED_003_ANGLES for branch in (1, -1)}
    assert {10.00, 8.69, 8.26, 12.26} <= computed


def test_fourbar_matches_seed_004_findroot():
    # Seed 004 (Jong et al.): A = (0, 0), E = (1.2, 0); its constraints
    # -0.3 cos t1 + 0.5 cos t2 + cos t3 = 1.2 and 0.3 sin t1 - 0.5 sin t2 + sin t3 = 0 put the
    # crank pin B at 0.3 u(180 - t1), D = B + 0.5 u(-t2) and E = D + u(t3).  So: crank angle
    # T(12) = 180 - t1, coupler T(13) = -t2 and follower B->Bo, T(14) = t3.  At t1 = 90 deg
    # FindRoot gives t2 = 64.94, t3 = 8.80: D lies to the right of the line B->E, our crossed branch.
    kin = fourbar(1.2, 0.0, 0.3, 0.5, 1.0, 180.0 - 90.0, branch=-1)
    assert -kin.coupler.degrees == pytest.approx(64.94, abs=0.005)
    assert kin.follower.degrees == pytest.approx(8.80, abs=0.005)
    # the uncrossed branch is the other root
    other = fourbar(1.2, 0.0, 0.3, 0.5, 1.0, 90.0, branch=1)
    assert abs(other.coupler.degrees + 64.94) > 1


def test_fourbar_textbook_open_configuration():
    # a = 40, b = 120, c = 80, d = 100 along +x, theta = 40 deg, uncrossed: coupler 20.30 deg and
    # the follower Bo->B at 57.32 deg (the contract's T(14) is B->Bo, 180 deg away)
    kin = fourbar(100.0, 0.0, 40.0, 120.0, 80.0, 40.0, branch=1)
    assert kin.coupler.degrees == pytest.approx(20.30, abs=0.005)
    assert kin.follower.degrees == pytest.approx(57.32 - 180.0, abs=0.005)
    b = kin.pin_b.pos
    cross = np.imag(np.conj(kin.pivot.pos - kin.pin_a.pos) * (b - kin.pin_a.pos))
    assert cross > 0  # uncrossed: B left of A->Bo


def test_slider_crank_contract_example_axes():
    # Example 1's second slider: T(4) = 90.1, L(1) = 150 is the vertical line x = +150 (nearly);
    # with T(4) = 90 exactly it is x = 150 exactly.
    kin = slider_crank(150.0, 100.0, 150.0, 60.0, 25.0, axis_deg=90.0)
    assert kin.pin_b.pos.real == pytest.approx(150.0, abs=1e-12)
    assert kin.pin_b.pos.imag > kin.pin_a.pos.imag  # ahead of A along u(90)
    assert abs(kin.pin_b.vel.real) < 1e-12 and abs(kin.pin_b.acc.real) < 1e-12
    # Example 2: T(4) = 90.1, L(1) = .08 is x = +0.08
    kin = slider_crank(0.08, 0.05, 0.054, 10.0, -8.0, axis_deg=90.1)
    assert kin.pin_b.pos.real == pytest.approx(0.08, abs=1e-3)


@pytest.mark.parametrize("axis", [0.0, 90.0, -90.0, 180.0])
@pytest.mark.parametrize("dead_centre", [0.0, 180.0])
def test_slider_crank_is_exact_at_dead_centres_on_any_axis(axis, dead_centre):
    # in-line slider-crank (e = 0), crank along the axis: the piston stops, and its acceleration
    # along the axis is the classical -a w^2 (1 +- a/b) (top / bottom dead centre), rod at rest
    a, b, w = 2.0, 7.0, 3.0
    kin = slider_crank(0.0, a, b, axis + dead_centre, w, axis_deg=axis)
    axis_dir = np.exp(1j * np.radians(axis))
    sign = 1.0 if dead_centre == 0.0 else -1.0
    expected_position = sign * a + b
    assert np.real(np.conj(axis_dir) * kin.pin_b.pos) == pytest.approx(expected_position, abs=1e-12)
    assert abs(kin.pin_b.vel) < 1e-12
    assert np.real(np.conj(axis_dir) * kin.pin_b.acc) == pytest.approx(-sign * a * w**2 * (1 + sign * a / b), rel=1e-12)
    assert kin.rod.omega == pytest.approx(-sign * a * w / b, rel=1e-12)


def test_assembly_failures_raise_instead_of_nan():
    with pytest.raises(AssemblyError):
        slider_crank(5.0, 3.0, 1.0, 90.0)  # rod too short to reach the axis
    with pytest.raises(AssemblyError):
        slider_crank(0.0, 3.0, 0.0, 10.0)  # zero-length rod
    with pytest.raises(AssemblyError):
        fourbar(1.0, 0.0, 1.0, 0.5, 0.5, 0.0, branch=1)  # crank pin on Bo
    with pytest.raises(AssemblyError):
        fourbar(10.0, 0.0, 1.0, 2.0, 2.0, 30.0)  # coupler and follower cannot meet
    with pytest.raises(AssemblyError):
        fourbar(1.0, 0.0, 0.3, 0.0, 1.0, 30.0)  # zero-length coupler
    with pytest.raises(AssemblyError):
        inverted_slider_crank(2.0, 0.0, 2.0, 180.0)  # crank pin on Bo (Bo = -L6 u(T6))
    # one bad position in a cycle fails the whole array call (no NaN rows)
    with pytest.raises(AssemblyError):
        fourbar(60.0, 0.0, 30.0, 36.0, 36.0, np.arange(0.0, 360.0, 30.0), branch=1)


def test_rates_at_a_branch_point_raise_instead_of_infinity():
    # the rod exactly perpendicular to the axis: it assembles, but the piston speed is unbounded
    kin = slider_crank(0.0, 3.0, 3.0, 90.0)
    assert kin.pin_b.pos == 0  # A = (0, 3) exactly above the axis, the rod vertical
    with pytest.raises(LockedError):
        slider_crank(0.0, 3.0, 3.0, 90.0, 1.0)
    with pytest.raises(LockedError):
        fourbar(1.0, 0.0, 0.5, 0.5, 1.0, 0.0, 1.0)  # coupler and follower in line (toggle)


def test_static_calls_give_exact_zero_rates():
    kin = fourbar(100.0, 10.0, 40.0, 120.0, 80.0, np.arange(0.0, 360.0, 15.0))
    assert not kin.moving
    for value in (kin.coupler.omega, kin.coupler.alpha, kin.follower.omega, kin.follower.alpha, kin.pin_b.vel,
                  kin.pin_b.acc, kin.coupler_point(30.0, 20.0).vel, kin.coupler_point(30.0, 20.0).acc):
        assert np.all(value == 0)


def test_positions_satisfy_the_loop_constraints_over_a_cycle():
    theta = np.linspace(0.0, 360.0, 3601)
    sc = slider_crank(1.5, 3.0, 8.0, theta, axis_deg=-35.0)
    axis = np.exp(1j * np.radians(-35.0))
    np.testing.assert_allclose(np.abs(sc.pin_b.pos - sc.pin_a.pos), 8.0, rtol=1e-13)
    np.testing.assert_allclose(np.imag(np.conj(axis) * sc.pin_b.pos), -1.5, atol=1e-12)  # e to the right
    assert np.all(np.real(np.conj(axis) * (sc.pin_b.pos - sc.pin_a.pos)) >= 0)  # B ahead of A
    fb = fourbar(100.0, 10.0, 40.0, 120.0, 80.0, theta, branch=-1)
    np.testing.assert_allclose(np.abs(fb.pin_b.pos - fb.pin_a.pos), 120.0, rtol=1e-13)
    np.testing.assert_allclose(np.abs(fb.pin_b.pos - fb.pivot.pos), 80.0, rtol=1e-13)
    assert np.all(np.imag(np.conj(fb.pivot.pos - fb.pin_a.pos) * (fb.pin_b.pos - fb.pin_a.pos)) < 0)  # crossed
    assert np.all((fb.coupler.degrees > -180) & (fb.coupler.degrees <= 180))
    fisc = inverted_slider_crank(5.0, 30.0, 2.5, theta)
    bo = -5.0 * np.exp(1j * np.radians(30.0))
    np.testing.assert_allclose(fisc.follower_length.value * np.exp(1j * fisc.follower.angle),
                               fisc.pin_a.pos - bo, atol=1e-12)


def test_inverted_slider_crank_paper_equations_agree_away_from_a_vertical_follower():
    theta = np.arange(0.5, 360.0, 7.0)
    kwargs = dict(crank_length_rate=0.2, crank_length_accel=-0.3)
    closed = inverted_slider_crank(5.0, 30.0, 2.5, theta, 3.0, 1.0, **kwargs)
    paper = inverted_slider_crank(5.0, 30.0, 2.5, theta, 3.0, 1.0, method="paper", **kwargs)
    for ours, printed in ((closed.follower, paper.follower), (closed.follower_length, paper.follower_length)):
        for a, b in zip(ours, printed):
            np.testing.assert_allclose(np.exp(1j * a) if a is ours[0] else a,
                                       np.exp(1j * b) if a is ours[0] else b, atol=1e-10)


def test_inverted_slider_crank_paper_equations_break_at_a_vertical_follower():
    from yaseer.linkages import MethodDivisionByZero

    # Bo = -1 u(90) = (0, -1), crank 2 at 90 deg: A - Bo = (0, 3), the follower is vertical
    with pytest.raises(MethodDivisionByZero):
        inverted_slider_crank(1.0, 90.0, 2.0, 90.0, 1.0, method="paper")
    closed = inverted_slider_crank(1.0, 90.0, 2.0, 90.0, 1.0)
    assert closed.follower.degrees == 90.0 and closed.follower_length.value == 3.0
    assert closed.follower.omega == pytest.approx(2.0 / 3.0, rel=1e-15)  # A moves at 2 x 1 across a link of 3
    # next to it the printed (8) L5 = den / cos T9 loses digits; the vector form does not
    near = inverted_slider_crank(1.0, 90.0, 2.0, 90.0 + 1e-9, 1.0, method="paper")
    exact = inverted_slider_crank(1.0, 90.0, 2.0, 90.0 + 1e-9, 1.0)
    assert abs(exact.follower_length.value - 3.0) < 1e-15
    assert abs(near.follower_length.value - exact.follower_length.value) > 1e-9
