"""Program 5, the virtual link: exact at the paper's singular angles by default,
the paper's equations selectable and shown to break there."""

from __future__ import annotations

import numpy as np
import pytest

from yaseer.linkages import AssemblyError, MethodDivisionByZero, UnknownMethodError, virtual_link

RADIUS, SPEED = 2.0, 3.0


def circling(angle_deg):
    """A point on a circle of radius 2 turning at 3 rad/s: T' = 3, T'' = 0, L' = L'' = 0."""
    p = RADIUS * np.exp(1j * np.radians(angle_deg))
    v, a = 1j * SPEED * p, -(SPEED**2) * p
    return p.real, p.imag, v.real, v.imag, a.real, a.imag


@pytest.mark.parametrize("angle", [0.0, 90.0, 180.0, 270.0, 45.0, 359.999])
def test_polar_method_is_exact_on_the_axes(angle):
    link = virtual_link(*circling(angle))
    assert link.length == pytest.approx(RADIUS, rel=1e-15)
    assert link.angle_deg == pytest.approx(angle, abs=1e-9)
    assert link.angle_rate == pytest.approx(SPEED, rel=1e-14)
    assert link.angle_accel == pytest.approx(0.0, abs=1e-13)
    assert link.length_rate == pytest.approx(0.0, abs=1e-13)
    assert link.length_accel == pytest.approx(0.0, abs=1e-13)


def test_radial_motion_gives_length_rates():
    # a point sliding out along u(120 deg) with speed 4 and acceleration -1: L' = 4, L'' = -1, T' = 0
    direction = np.exp(1j * np.radians(120.0))
    p, v, a = 5 * direction, 4 * direction, -1 * direction
    for method in ("polar", "paper"):
        link = virtual_link(p.real, p.imag, v.real, v.imag, a.real, a.imag, method=method)
        assert link.angle_deg == pytest.approx(120.0, abs=1e-12)
        assert (link.length, link.length_rate, link.length_accel) == pytest.approx((5.0, 4.0, -1.0), abs=1e-12)
        assert (link.angle_rate, link.angle_accel) == pytest.approx((0.0, 0.0), abs=1e-12)


@pytest.mark.parametrize("x, y", [(0.0, 2.0), (0.0, -2.0), (3.0, 0.0), (-3.0, 0.0)])
def test_paper_method_divides_by_zero_on_the_axes(x, y):
    with pytest.raises(MethodDivisionByZero):
        virtual_link(x, y, 1.0, 1.0, method="paper")


def test_paper_method_loses_accuracy_next_to_90_degrees_where_polar_does_not():
    # 1e-12 deg from T = 90: the printed method's L = X / cos T and E(6) = (...) / sin T
    # amplify rounding; the polar method stays exact
    paper = virtual_link(*circling(90.0 + 1e-12), method="paper")
    polar = virtual_link(*circling(90.0 + 1e-12))
    assert abs(paper.length - RADIUS) / RADIUS > 1e-3
    assert abs(polar.length - RADIUS) / RADIUS < 1e-15
    assert abs(polar.length_accel) < 1e-12 < abs(paper.length_accel)


def test_angle_range_is_zero_to_360():
    angles = virtual_link(np.array([1.0, 1.0, -1.0, -1.0, 1.0]), np.array([-1e-20, 1.0, 1.0, -1.0, -1.0])).angle_deg
    np.testing.assert_allclose(angles, [0.0, 45.0, 135.0, 225.0, 315.0], atol=1e-12)
    assert np.all((angles >= 0) & (angles < 360))


def test_zero_length_and_unknown_method_raise():
    with pytest.raises(AssemblyError):
        virtual_link(0.0, 0.0, 1.0, 0.0)
    with pytest.raises(UnknownMethodError, match="polar"):
        virtual_link(1.0, 1.0, method="nonesuch")
