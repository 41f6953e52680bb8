"""The alternative methods (pseudographic, Newton, half-angle) against independent values.

References: the seeds' printed numbers (001's TK table, 003's Fortran output,
004's FindRoot answer) and closed forms evaluated here in mpmath at 50 digits
(written out in this file, not taken from yaseer).
"""

import math

import mpmath
import numpy as np
import pytest

import yaseer.linkages.methods  # noqa: F401  (registers the methods)
from yaseer.linkages import AssemblyError, fourbar, slider_crank
from yaseer.linkages.methods import NoConvergenceError
from yaseer.linkages.registry import method_names

SLIDER_METHODS = ["pseudographic", "newton"]
FOURBAR_METHODS = ["half-angle", "half-angle-printed", "newton"]


def test_registered_by_name():
    assert {"pseudographic", "newton"} <= set(method_names("slider_crank"))
    assert {"half-angle", "half-angle-printed", "newton"} <= set(method_names("fourbar"))


# --------------------------------------------------------------------------- mpmath closed forms (test-local)

def mp_slider(e, a, b, theta_deg, omega, alpha, axis_deg):
    """Rod angle (deg), omega, alpha, travel s and its rates, by differentiating the
    closed-form position along theta(t) = theta + omega t + alpha t^2/2 (mpmath.diff)."""
    with mpmath.workdps(50):
        return _mp_slider(e, a, b, theta_deg, omega, alpha, axis_deg)


def _mp_slider(e, a, b, theta_deg, omega, alpha, axis_deg):
    e, a, b = (mpmath.mpf(v) for v in (e, a, b))
    phi = mpmath.radians(mpmath.mpf(axis_deg))
    th0 = mpmath.radians(mpmath.mpf(theta_deg))

    def position(t):
        th = th0 + omega * t + alpha * t * t / 2
        along = a * mpmath.cos(th - phi)
        across = -(e + a * mpmath.sin(th - phi))
        h = mpmath.sqrt(b * b - across * across)
        return mpmath.atan2(across, h) + phi, along + h

    beta = [mpmath.diff(lambda t: position(t)[0], 0, n) for n in range(3)]
    travel = [mpmath.diff(lambda t: position(t)[1], 0, n) for n in range(3)]
    return [mpmath.degrees(beta[0])] + beta[1:] + travel


def mp_fourbar(d, a, b, c, theta_deg, omega, alpha, crossed):
    """Coupler A->B (deg) and rates, follower B->Bo (deg) and rates, fixed link on +x."""
    with mpmath.workdps(50):
        return _mp_fourbar(d, a, b, c, theta_deg, omega, alpha, crossed)


def _mp_fourbar(d, a, b, c, theta_deg, omega, alpha, crossed):
    a, b, c, d = (mpmath.mpf(v) for v in (a, b, c, d))
    th0 = mpmath.radians(mpmath.mpf(theta_deg))
    side = -1 if crossed else 1

    def position(t):
        th = th0 + omega * t + alpha * t * t / 2
        ax, ay = a * mpmath.cos(th), a * mpmath.sin(th)
        dx, dy = d - ax, -ay
        span = mpmath.sqrt(dx * dx + dy * dy)
        along = (b * b - c * c + span * span) / (2 * span)
        height = side * mpmath.sqrt(b * b - along * along)
        bx = ax + (along * dx - height * dy) / span
        by = ay + (along * dy + height * dx) / span
        return mpmath.atan2(by - ay, bx - ax), mpmath.atan2(-by, d - bx)

    coupler = [mpmath.diff(lambda t: position(t)[0], 0, n) for n in range(3)]
    follower = [mpmath.diff(lambda t: position(t)[1], 0, n) for n in range(3)]
    return [mpmath.degrees(coupler[0])] + coupler[1:] + [mpmath.degrees(follower[0])] + follower[1:]


def slider_values(r):
    return [r.rod.degrees, r.rod.omega, r.rod.alpha, r.travel.value, r.travel.rate, r.travel.accel]


def fourbar_values(r):
    return [r.coupler.degrees, r.coupler.omega, r.coupler.alpha, r.follower.degrees, r.follower.omega,
            r.follower.alpha]


def assert_close(values, reference, rtol, scale):
    for value, ref in zip(values, reference):
        assert abs(float(value) - float(ref)) <= rtol * scale, (values, reference)


# --------------------------------------------------------------------------- against the mpmath closed forms

@pytest.mark.parametrize("method", SLIDER_METHODS)
@pytest.mark.parametrize("theta", [-170.0, -33.3, 12.5, 77.7, 140.0, 263.0])
@pytest.mark.parametrize("axis", [0.0, 90.1, -37.0])
def test_slider_methods_generic_positions(method, theta, axis):
    """Offset and inclined axis (the flexible crank is the next test)."""
    r = slider_crank(0.7, 2.0, 5.5, theta, 3.0, -2.0, axis_deg=axis, method=method)
    reference = mp_slider(0.7, 2.0, 5.5, theta, 3.0, -2.0, axis)
    assert_close(slider_values(r), reference, 1e-12, 100.0)


def test_slider_flexible_crank_by_finite_differences():
    """With a flexible crank the rates are checked against finite differences of positions
    along the motion a(t) = a + a' t + a'' t^2 / 2, theta(t) = theta + omega t."""
    kwargs = dict(crank_length_rate=0.4, crank_length_accel=-1.5, axis_deg=20.0)
    for method in SLIDER_METHODS:
        r = slider_crank(0.3, 2.0, 5.0, 50.0, 2.0, 0.5, method=method, **kwargs)
        h = 1e-4

        def travel(t):
            return slider_crank(0.3, 2.0 + 0.4 * t - 0.75 * t * t, 5.0, 50.0 + math.degrees(2.0 * t + 0.25 * t * t),
                                axis_deg=20.0, method="closed").travel.value

        rate = (travel(h) - travel(-h)) / (2 * h)
        accel = (travel(h) - 2 * travel(0) + travel(-h)) / h**2
        assert float(r.travel.rate) == pytest.approx(float(rate), rel=1e-7)
        assert float(r.travel.accel) == pytest.approx(float(accel), rel=1e-5)


@pytest.mark.parametrize("method", FOURBAR_METHODS)
@pytest.mark.parametrize("crossed", [False, True])
@pytest.mark.parametrize("theta", [-150.0, -60.0, 10.0, 40.0, 95.0, 200.0, 300.0])
def test_fourbar_methods_generic_positions(method, crossed, theta):
    """The textbook crank-rocker a=40, b=120, c=80, d=100 (Grashof: a full turn)."""
    r = fourbar(100.0, 0.0, 40.0, 120.0, 80.0, theta, 10.0, 3.0, branch=-1 if crossed else 1, method=method)
    reference = mp_fourbar(100.0, 40.0, 120.0, 80.0, theta, 10.0, 3.0, crossed)
    assert_close(fourbar_values(r), reference, 1e-12, 100.0)


@pytest.mark.parametrize("method", FOURBAR_METHODS)
def test_fourbar_inclined_ground_matches_turned_frame(method):
    """A fixed link at 30 deg is the same linkage turned: angles shift by 30, rates equal."""
    turned = fourbar(100.0, 30.0, 40.0, 120.0, 80.0, 70.0, 10.0, 0.0, method=method)
    reference = mp_fourbar(100.0, 40.0, 120.0, 80.0, 40.0, 10.0, 0.0, False)
    expected = [reference[0] + 30, reference[1], reference[2], reference[3] + 30, reference[4], reference[5]]
    assert_close(fourbar_values(turned), expected, 1e-12, 100.0)


# --------------------------------------------------------------------------- the seeds' printed numbers

@pytest.mark.parametrize("method", SLIDER_METHODS)
def test_seed001_row_c(method):
    """Seed 001: AO=3, AB=8, offset 2 (slider line y = +2 along +x, so e = -2):
    xB = 9.79, vB = -41.46, omegaAB = 5.42, aB = -709.1, alphaAB = -29.03."""
    r = slider_crank(-2.0, 3.0, 8.0, -30.0, -15.0, -10.0, method=method)
    assert round(float(r.travel.value), 2) == 9.79
    assert round(float(r.travel.rate), 2) == -41.46
    assert round(float(r.rod.omega), 2) == 5.42
    assert round(float(r.travel.accel), 1) == -709.1
    assert round(float(r.rod.alpha), 2) == -29.03


def test_pseudographic_crossed_branch_is_the_mirror():
    """Seed 001's crossed branch: B behind A; compare with the closed-form mpmath value
    of the same loop (travel = xA - sqrt(...))."""
    r = yaseer.linkages.methods.pseudographic.slider_crank_pseudographic(-2.0, 3.0, 8.0, -30.0, -15.0, -10.0,
                                                                         branch="crossed")
    xa, ya = 3 * math.cos(math.radians(-30)), 3 * math.sin(math.radians(-30))
    assert float(r.travel.value) == pytest.approx(xa - math.sqrt(64 - (2 - ya) ** 2), rel=1e-14)
    # omega_AB from the y velocity equation: omega*(xB - xA) = -vA_y
    va_y = -15 * 3 * math.cos(math.radians(-30))
    assert float(r.rod.omega) == pytest.approx(-va_y / (float(r.travel.value) - xa), rel=1e-12)


# Seed 003's printed table (THET, PHI of both rows) for a=30, b=36, c=36, d=60.
SEED003_PRINTED = {0: (-114.62, 114.62), 30: (-144.88, 97.30), 60: (-166.19, 106.19), 90: (174.73, 132.14),
                   270: (-132.14, -174.73), 300: (-106.19, 166.19), 330: (-97.30, 144.88)}


@pytest.mark.parametrize("method", ["half-angle-printed", "half-angle"])
def test_seed003_printed_follower_angles(method):
    """Seed 003's PHI (direction D->C = Bo->B) of both roots, to the printed 0.01 deg."""
    for theta, printed in SEED003_PRINTED.items():
        got = set()
        for branch in (1, -1):
            r = fourbar(60.0, 0.0, 30.0, 36.0, 36.0, float(theta), 10.0, method=method, branch=branch)
            phi = float(r.follower.degrees) + 180.0
            got.add(round((phi + 180.0) % 360.0 - 180.0, 2))
        assert got == {round(p, 2) for p in printed}, theta


def test_seed004_findroot_answer_by_newton():
    """Seed 004 at theta1 = 90 deg: th2 = 64.94, th3 = 8.80 deg.  In the contract's
    frame (A at the origin, E = Bo at (1.2, 0)) the crank is at 90 deg, the coupler
    A->B at -th2 and the follower B->Bo at th3 (crossed mode)."""
    r = fourbar(1.2, 0.0, 0.3, 0.5, 1.0, 90.0, 1.0, method="newton", branch=-1, guess=(-60.0, 10.0))
    assert round(float(r.coupler.degrees), 2) == -64.94
    assert round(float(r.follower.degrees), 2) == 8.80


# --------------------------------------------------------------------------- vectorised, laziness, errors

@pytest.mark.parametrize("method", SLIDER_METHODS)
def test_slider_array_call_equals_scalar_calls(method):
    angles = np.linspace(0.0, 360.0, 37)
    array = slider_crank(0.5, 1.0, 3.0, angles, 5.0, 1.0, axis_deg=10.0, method=method)
    for k in (0, 9, 18, 27):
        one = slider_crank(0.5, 1.0, 3.0, float(angles[k]), 5.0, 1.0, axis_deg=10.0, method=method)
        assert float(array.rod.alpha[k]) == pytest.approx(float(one.rod.alpha), rel=1e-13, abs=1e-13)


@pytest.mark.parametrize("method", FOURBAR_METHODS)
def test_fourbar_array_call_equals_scalar_calls(method):
    angles = np.linspace(0.0, 360.0, 37)
    array = fourbar(100.0, 0.0, 40.0, 120.0, 80.0, angles, 10.0, method=method)
    for k in (0, 9, 18, 27):
        one = fourbar(100.0, 0.0, 40.0, 120.0, 80.0, float(angles[k]), 10.0, method=method)
        assert float(array.follower.alpha[k]) == pytest.approx(float(one.follower.alpha), rel=1e-12)


@pytest.mark.parametrize("linkage,args,method", [
    ("slider", (0.5, 1.0, 3.0, 40.0), "pseudographic"), ("slider", (0.5, 1.0, 3.0, 40.0), "newton"),
    ("fourbar", (100.0, 0.0, 40.0, 120.0, 80.0, 40.0), "half-angle"),
    ("fourbar", (100.0, 0.0, 40.0, 120.0, 80.0, 40.0), "newton")])
def test_static_call_writes_zero_rates(linkage, args, method):
    """Laziness: no crank rate, no rates computed (exactly zero) but the positions."""
    function = slider_crank if linkage == "slider" else fourbar
    r = function(*args, method=method)
    assert r.moving is False
    rates = [r.rod.omega, r.rod.alpha] if linkage == "slider" else [r.coupler.omega, r.follower.alpha]
    assert all(float(v) == 0.0 for v in rates)


def test_cannot_assemble_is_an_assembly_error():
    with pytest.raises(AssemblyError):
        slider_crank(0.0, 2.0, 1.0, 90.0, 1.0, method="pseudographic")
    with pytest.raises(AssemblyError):
        fourbar(60.0, 0.0, 30.0, 36.0, 36.0, 150.0, 1.0, method="half-angle")


def test_newton_recognises_a_position_that_cannot_be_assembled():
    """Seed 003's linkage at 150 deg cannot be assembled (|A - Bo| > b + c)."""
    with pytest.raises(AssemblyError):
        fourbar(60.0, 0.0, 30.0, 36.0, 36.0, 150.0, 1.0, method="newton")
    with pytest.raises(AssemblyError):
        slider_crank(0.0, 2.0, 1.0, 90.0, 1.0, method="newton")


def test_newton_tolerance_and_iteration_cap_are_parameters():
    reference = mp_fourbar(100.0, 40.0, 120.0, 80.0, 40.0, 10.0, 0.0, False)
    errors = []
    for tol in (1e-1, 1e-3, 1e-6, 1e-12):
        r = fourbar(100.0, 0.0, 40.0, 120.0, 80.0, 40.0, 10.0, method="newton", tol=tol)
        errors.append(abs(float(r.follower.degrees) - float(reference[3])))
    assert errors[-1] < 1e-11
    assert errors[0] > errors[-1]
    with pytest.raises(NoConvergenceError):
        fourbar(100.0, 0.0, 40.0, 120.0, 80.0, 40.0, 10.0, method="newton", tol=1e-14, max_iter=1)


def test_newton_from_the_other_branch_guess_converges_there():
    """Newton promises a root, not the branch: a guess near the crossed assembly
    converges to it although the uncrossed mode was asked for."""
    crossed = fourbar(100.0, 0.0, 40.0, 120.0, 80.0, 40.0, 10.0, branch=-1)
    r = fourbar(100.0, 0.0, 40.0, 120.0, 80.0, 40.0, 10.0, branch=1, method="newton",
                guess=(float(crossed.coupler.degrees) + 1.0, float(crossed.follower.degrees) - 1.0))
    assert float(r.coupler.degrees) == pytest.approx(float(crossed.coupler.degrees), abs=1e-10)


def test_half_angle_printed_returns_nan_silently_at_its_pole():
    """Where AA = 0 the printed quadratic formula divides 0 by 0 on one root:
    NaN comes back with no error (a finding of yaseer stability), while the
    cancellation-free form stays exact."""
    from yaseer.evaluation.sweeps import seed003_half_angle_pole_deg

    theta = seed003_half_angle_pole_deg()
    frame = yaseer.linkages.methods.half_angle._Frame(60.0, 0.0, 30.0, 36.0, 36.0, theta)
    aa, bb, cc = frame.coefficients()
    assert abs(float(aa)) < 1e-12
    printed = fourbar(60.0, 0.0, 30.0, 36.0, 36.0, theta, 10.0, method="half-angle-printed", branch=1)
    assert math.isnan(float(printed.coupler.degrees))
    stable = fourbar(60.0, 0.0, 30.0, 36.0, 36.0, theta, 10.0, method="half-angle", branch=1)
    reference = mp_fourbar(60.0, 30.0, 36.0, 36.0, theta, 10.0, 0.0, False)
    assert_close(fourbar_values(stable), reference, 1e-12, 100.0)


def test_half_angle_printed_asin_loses_a_coupler_past_90_degrees():
    """Seed 003's BET = ASIN(...) only returns |beta| <= 90 deg: with the coupler at
    about 104 deg (a = 1, b = 3, c = 3, d = 2, theta = 315) it answers 180 - beta,
    silently, while its follower angle (the quadratic) is right."""
    reference = mp_fourbar(2.0, 1.0, 3.0, 3.0, 315.0, 1.0, 0.0, False)
    assert float(reference[0]) > 90.0
    printed = fourbar(2.0, 0.0, 1.0, 3.0, 3.0, 315.0, 1.0, method="half-angle-printed")
    assert float(printed.coupler.degrees) == pytest.approx(180.0 - float(reference[0]), abs=1e-9)
    assert float(printed.follower.degrees) == pytest.approx(float(reference[3]), abs=1e-9)
    stable = fourbar(2.0, 0.0, 1.0, 3.0, 3.0, 315.0, 1.0, method="half-angle")
    assert_close(fourbar_values(stable), reference, 1e-12, 100.0)
