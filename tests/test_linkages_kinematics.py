"""Velocities and accelerations of every program against finite differences of
positions along a prescribed motion, over full cycles, flexible cranks included.

Each crank is driven by known functions of time t (angle, and for a flexible
crank its length); the positions at t +- h (static calls: positions only) give
the reference rates by central differences, independent of the rate formulas.
"""

from __future__ import annotations

import numpy as np
import pytest

from yaseer.linkages import fourbar, inverted_slider_crank, slider_crank, virtual_link

STEP = 1e-3
TIMES = np.linspace(0.0, 2 * np.pi, 361)[:-1]  # one full crank turn for the drive below


def crank_drive(t, flexible):
    """Crank angle (deg), omega, alpha (rad/s, rad/s^2) and length a, a', a'' at time t.

    theta(t) = t + 0.3 sin 2t (one turn per 2 pi, never reversing);
    a(t) = a0 (1 + 0.08 sin 3t) when flexible, else a0 (factor returned separately).
    """
    theta = t + 0.3 * np.sin(2 * t)
    omega = 1 + 0.6 * np.cos(2 * t)
    alpha = -1.2 * np.sin(2 * t)
    k = 0.08 if flexible else 0.0
    scale = 1 + k * np.sin(3 * t)
    scale_rate = 3 * k * np.cos(3 * t)
    scale_accel = -9 * k * np.sin(3 * t)
    return np.degrees(theta), omega, alpha, scale, scale_rate, scale_accel


def central(values_minus, values, values_plus, step=STEP):
    """First and second central differences of complex or real samples."""
    return (values_plus - values_minus) / (2 * step), (values_plus - 2 * values + values_minus) / step**2


def angle_samples(angle_minus, angle, angle_plus):
    """Angles (rad) made continuous around the middle sample for differencing."""
    return (angle + np.angle(np.exp(1j * (angle_minus - angle))), angle,
            angle + np.angle(np.exp(1j * (angle_plus - angle))))


def assert_close(actual, expected, scale, rtol=2e-5):
    np.testing.assert_allclose(actual, expected, rtol=0, atol=rtol * scale)


def check_point(moving, positions, scale):
    """A point's code velocity/acceleration against differences of its positions."""
    velocity, acceleration = central(*positions)
    assert_close(moving.vel, velocity, scale)
    assert_close(moving.acc, acceleration, scale * 10)


def check_rotation(rotation, angles, scale=1.0):
    rate, accel = central(*angle_samples(*angles))
    assert_close(rotation.omega, rate, scale)
    assert_close(rotation.alpha, accel, scale * 10)


def drive_slider_crank(t, flexible, rates=True):
    theta, omega, alpha, s, s1, s2 = crank_drive(t, flexible)
    a0 = 3.0
    kwargs = dict(crank_length_rate=a0 * s1, crank_length_accel=a0 * s2, axis_deg=-35.0) if rates else dict(axis_deg=-35.0)
    if rates:
        return slider_crank(1.5, a0 * s, 8.0, theta, omega, alpha, **kwargs)
    return slider_crank(1.5, a0 * s, 8.0, theta, **kwargs)


@pytest.mark.parametrize("flexible", [False, True])
def test_slider_crank_rates_match_differences(flexible):
    moving = drive_slider_crank(TIMES, flexible)
    samples = [drive_slider_crank(TIMES + d, flexible, rates=False) for d in (-STEP, 0.0, STEP)]
    assert not samples[1].moving and np.all(samples[1].pin_b.vel == 0)
    check_point(moving.pin_b, [k.pin_b.pos for k in samples], 100.0)
    check_rotation(moving.rod, [k.rod.angle for k in samples])
    check_point(moving.pin_a, [k.pin_a.pos for k in samples], 10.0)
    for distance, offset in ((2.0, 30.0), (0.0, 0.0), (2.5, -120.0)):
        check_point(moving.crank_point(distance, offset), [k.crank_point(distance, offset).pos for k in samples], 10.0)
        check_point(moving.rod_point(distance, offset), [k.rod_point(distance, offset).pos for k in samples], 100.0)
    np.testing.assert_allclose(moving.travel.rate * np.exp(1j * moving.axis), moving.pin_b.vel, atol=1e-12)


def drive_fourbar(t, flexible, branch, rates=True):
    theta, omega, alpha, s, s1, s2 = crank_drive(t, flexible)
    a0 = 40.0
    args = (100.0, 10.0, a0 * s, 120.0, 80.0, theta)
    if rates:
        return fourbar(*args, omega, alpha, crank_length_rate=a0 * s1, crank_length_accel=a0 * s2, branch=branch)
    return fourbar(*args, branch=branch)


@pytest.mark.parametrize("flexible", [False, True])
@pytest.mark.parametrize("branch", [1, -1])
def test_fourbar_rates_match_differences(flexible, branch):
    moving = drive_fourbar(TIMES, flexible, branch)
    samples = [drive_fourbar(TIMES + d, flexible, branch, rates=False) for d in (-STEP, 0.0, STEP)]
    check_rotation(moving.coupler, [k.coupler.angle for k in samples])
    check_rotation(moving.follower, [k.follower.angle for k in samples])
    check_point(moving.pin_b, [k.pin_b.pos for k in samples], 100.0)
    for distance, offset in ((25.0, 40.0), (0.0, 0.0), (60.0, -150.0)):
        for name in ("crank_point", "coupler_point", "follower_point"):
            point = getattr(moving, name)(distance, offset)
            check_point(point, [getattr(k, name)(distance, offset).pos for k in samples], 100.0)


def drive_fisc(t, flexible, ground, crank, rates=True):
    theta, omega, alpha, s, s1, s2 = crank_drive(t, flexible)
    args = (ground, 30.0, crank * s, theta)
    if rates:
        return inverted_slider_crank(*args, omega, alpha, crank_length_rate=crank * s1, crank_length_accel=crank * s2)
    return inverted_slider_crank(*args)


@pytest.mark.parametrize("flexible", [False, True])
@pytest.mark.parametrize("ground, crank", [(5.0, 2.5), (2.0, 5.0)])  # oscillating and rotating follower
def test_inverted_slider_crank_rates_match_differences(flexible, ground, crank):
    moving = drive_fisc(TIMES, flexible, ground, crank)
    samples = [drive_fisc(TIMES + d, flexible, ground, crank, rates=False) for d in (-STEP, 0.0, STEP)]
    check_rotation(moving.follower, [k.follower.angle for k in samples])
    rate, accel = central(*[k.follower_length.value for k in samples])
    assert_close(moving.follower_length.rate, rate, 10.0)
    assert_close(moving.follower_length.accel, accel, 100.0)
    for distance, offset in ((3.5, 180.0), (0.0, 0.0), (1.0, 45.0)):
        check_point(moving.crank_point(distance, offset), [k.crank_point(distance, offset).pos for k in samples], 10.0)
        check_point(moving.follower_point(distance, offset),
                    [k.follower_point(distance, offset).pos for k in samples], 10.0)


def moving_point(t):
    """A point circling round the origin without reaching it: position, velocity, acceleration."""
    radius = 3 + np.sin(3 * t)
    p = radius * np.exp(1j * t)
    v = (3 * np.cos(3 * t) + 1j * radius) * np.exp(1j * t)
    acc = (-9 * np.sin(3 * t) - radius + 1j * 6 * np.cos(3 * t)) * np.exp(1j * t)
    return p, v, acc


@pytest.mark.parametrize("method", ["polar", "paper"])
def test_virtual_link_rates_match_differences(method):
    times = TIMES + 0.013  # keeps the paper's method off its 0/90/180/270 deg divisions
    p, v, a = moving_point(times)
    link = virtual_link(p.real, p.imag, v.real, v.imag, a.real, a.imag, method=method)
    samples = [virtual_link(*(lambda q: (q.real, q.imag))(moving_point(times + d)[0])) for d in (-STEP, 0.0, STEP)]
    np.testing.assert_allclose(link.length, np.abs(p), rtol=1e-12)
    np.testing.assert_allclose(np.exp(1j * np.radians(link.angle_deg)), p / np.abs(p), atol=1e-12)
    assert np.all((link.angle_deg >= 0) & (link.angle_deg < 360))
    rate, accel = central(*angle_samples(*[np.radians(k.angle_deg) for k in samples]))
    tolerance = 1e-4 if method == "paper" else 2e-5  # the paper's method loses digits near its divisions
    assert_close(link.angle_rate, rate, 1.0, tolerance)
    assert_close(link.angle_accel, accel, 10.0, tolerance)
    rate, accel = central(*[k.length for k in samples])
    assert_close(link.length_rate, rate, 1.0, tolerance)
    assert_close(link.length_accel, accel, 10.0, tolerance)


from hypothesis import assume, given, settings, strategies as st  # noqa: E402

FINE = 1e-4  # random rates up to 5 rad/s: a finer step keeps the truncation error small


@settings(max_examples=40, deadline=None)
@given(ground_fraction=st.floats(0.05, 0.95), ground_angle=st.floats(-180, 180), crank=st.floats(0.05, 0.3),
       coupler=st.floats(1.0, 2.0), follower=st.floats(1.0, 2.0), start=st.floats(0, 360),
       omega=st.floats(-5, 5), alpha=st.floats(-5, 5), rate=st.floats(-1, 1), accel=st.floats(-1, 1),
       branch=st.sampled_from([1, -1]))
def test_fourbar_rates_match_differences_for_random_linkages(ground_fraction, ground_angle, crank, coupler, follower,
                                                             start, omega, alpha, rate, accel, branch):
    # a short crank and a ground between |b - c| + a and b + c - a: it assembles at every crank
    # angle; positions near a toggle (coupler and follower within ~17 deg of parallel, where
    # the differences lose accuracy) are skipped
    shortest, longest = abs(coupler - follower) + crank + 0.05, coupler + follower - crank - 0.05
    ground = shortest + ground_fraction * (longest - shortest)
    t = np.array([-FINE, 0.0, FINE])
    theta = start + np.degrees(omega * t + alpha * t**2 / 2)
    length = crank + rate * t + accel * t**2 / 2
    positions = fourbar(ground, ground_angle, length, coupler, follower, theta, branch=branch)
    moving = fourbar(ground, ground_angle, crank, coupler, follower, start, omega, alpha, crank_length_rate=rate,
                     crank_length_accel=accel, branch=branch)
    assume(abs(np.sin(moving.coupler.angle - moving.follower.angle)) > 0.3)
    velocity, acceleration = central(*positions.pin_b.pos, step=FINE)
    assert abs(moving.pin_b.vel - velocity) < 1e-5 * (1 + abs(velocity))
    assert abs(moving.pin_b.acc - acceleration) < 1e-3 * (1 + abs(acceleration))


@settings(max_examples=40, deadline=None)
@given(eccentricity=st.floats(-1, 1), crank=st.floats(0.1, 1.0), rod=st.floats(2.5, 5.0), axis=st.floats(-180, 180),
       start=st.floats(0, 360), omega=st.floats(-5, 5), alpha=st.floats(-5, 5), rate=st.floats(-1, 1),
       accel=st.floats(-1, 1))
def test_slider_crank_rates_match_differences_for_random_linkages(eccentricity, crank, rod, axis, start, omega, alpha,
                                                                  rate, accel):
    t = np.array([-FINE, 0.0, FINE])
    theta = start + np.degrees(omega * t + alpha * t**2 / 2)
    length = crank + rate * t + accel * t**2 / 2
    positions = slider_crank(eccentricity, length, rod, theta, axis_deg=axis)
    moving = slider_crank(eccentricity, crank, rod, start, omega, alpha, crank_length_rate=rate,
                          crank_length_accel=accel, axis_deg=axis)
    velocity, acceleration = central(*positions.pin_b.pos, step=FINE)
    assert abs(moving.pin_b.vel - velocity) < 1e-5 * (1 + abs(velocity))
    assert abs(moving.pin_b.acc - acceleration) < 1e-3 * (1 + abs(acceleration))
    rod_rate, rod_accel = central(*angle_samples(*positions.rod.angle), step=FINE)
    assert abs(moving.rod.omega - rod_rate) < 1e-5 * (1 + abs(rod_rate))
    assert abs(moving.rod.alpha - rod_accel) < 1e-3 * (1 + abs(rod_accel))


def test_a_subnormal_eccentricity_is_a_tiny_offset_not_an_error():
    """Found by hypothesis: cmath.phase raised OverflowError for the subnormal angle."""
    offset = slider_crank(5e-324, 1.0, 3.0, 0.0, 0.0, 0.0, axis_deg=0.0)
    plain = slider_crank(0.0, 1.0, 3.0, 0.0, 0.0, 0.0, axis_deg=0.0)
    assert abs(offset.pin_b.pos - plain.pin_b.pos) < 1e-300
    assert abs(offset.rod.angle - plain.rod.angle) < 1e-300
