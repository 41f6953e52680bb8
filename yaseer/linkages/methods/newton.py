"""Newton iteration on the loop-closure equations (seed 004's FindRoot, by hand).

Positions are found by Newton's method from a crude geometric first guess (or a
guess the caller passes, e.g. the previous position of a cycle); velocities and
accelerations then come from the differentiated loop equations
(:mod:`.loops`).  ``tol`` is the size of the last Newton step at which the
iteration stops (radians for angles; lengths are scaled by the rod or coupler
length), ``max_iter`` the iteration cap.  Not converging within the cap, or a
singular Jacobian, raises :class:`LinkageError`; nothing is returned silently.

Works on floats or numpy arrays: every position iterates until its own step is
below ``tol`` (converged positions are frozen).
"""

from __future__ import annotations

import numpy as np

from .loops import LinkageError, as_float_or_array, check_finite, crank_pin, fourbar_rates, normalise_degrees, slider_rates, unit
from .types import FourBarMotion, SliderCrankMotion

DEFAULT_TOL = 1e-12
DEFAULT_MAX_ITER = 50


def slider_crank(
    eccentricity,
    crank_length,
    rod_length,
    crank_angle,
    axis_angle=0.0,
    crank_speed=0.0,
    crank_accel=0.0,
    crank_length_rate=0.0,
    crank_length_accel=0.0,
    *,
    tol: float = DEFAULT_TOL,
    max_iter: int = DEFAULT_MAX_ITER,
    guess=None,
) -> SliderCrankMotion:
    """Slider-crank AoAB: unknowns rod angle beta and slider travel s.

    Residual A + b*u(beta) + e*u(phi+90) - s*u(phi) = 0.  Default first guess: the
    rod along the axis (beta = phi), s = A.u(phi) + b.  ``guess`` = (beta deg, s).
    """
    e, a, b = (np.asarray(v, float) for v in (eccentricity, crank_length, rod_length))
    theta, phi = np.radians(np.asarray(crank_angle, float)), np.radians(np.asarray(axis_angle, float))
    pin, pin_v, pin_a = crank_pin(a, theta, np.asarray(crank_length_rate, float), np.asarray(crank_speed, float),
                                  np.asarray(crank_length_accel, float), np.asarray(crank_accel, float))
    axis, normal = unit(phi), unit(phi + np.pi / 2)
    if guess is None:
        beta = phi + 0.0 * theta
        s = pin[0] * axis[0] + pin[1] * axis[1] + b
    else:
        beta, s = np.radians(np.asarray(guess[0], float)) + 0.0 * theta, np.asarray(guess[1], float) + 0.0 * theta

    def residual(beta, s):
        rod = unit(beta)
        return (pin[0] + b * rod[0] + e * normal[0] - s * axis[0], pin[1] + b * rod[1] + e * normal[1] - s * axis[1])

    def jacobian(beta, s):
        rod = unit(beta)
        return (-b * rod[1], -axis[0] + 0.0 * s, b * rod[0], -axis[1] + 0.0 * s)

    beta, s = _iterate(residual, jacobian, beta, s, b, tol, max_iter, "Newton (slider-crank)")
    omega, alpha, velocity, acceleration = slider_rates(pin_v, pin_a, b, beta, phi)
    with np.errstate(all="ignore"):
        check_finite("Newton (slider-crank)", omega, alpha)
    return SliderCrankMotion(*(as_float_or_array(v) for v in (
        normalise_degrees(np.degrees(beta)), omega, alpha, s, velocity, acceleration)))


def fourbar(
    ground_length,
    ground_angle,
    crank_length,
    coupler_length,
    follower_length,
    crank_angle,
    crank_speed=0.0,
    crank_accel=0.0,
    crank_length_rate=0.0,
    crank_length_accel=0.0,
    *,
    crossed: bool = False,
    tol: float = DEFAULT_TOL,
    max_iter: int = DEFAULT_MAX_ITER,
    guess=None,
) -> FourBarMotion:
    """Four-bar AoABBo: unknowns coupler angle beta (A->B) and gamma (Bo->B).

    Residual a*u(theta) + b*u(beta) - g - c*u(gamma) = 0, g = Ao->Bo.  Default first
    guess: B half the shorter of b, c off the midpoint of A and Bo, on the side the
    assembly mode asks for (left of A->Bo uncrossed, right crossed).
    ``guess`` = (coupler deg, follower B->Bo deg), the contract's T(13), T(14).
    """
    g_len, g_ang = np.asarray(ground_length, float), np.radians(np.asarray(ground_angle, float))
    a, b, c = (np.asarray(v, float) for v in (crank_length, coupler_length, follower_length))
    theta = np.radians(np.asarray(crank_angle, float))
    pin, pin_v, pin_a = crank_pin(a, theta, np.asarray(crank_length_rate, float), np.asarray(crank_speed, float),
                                  np.asarray(crank_length_accel, float), np.asarray(crank_accel, float))
    ground = (g_len * np.cos(g_ang), g_len * np.sin(g_ang))
    if guess is None:
        beta, gamma = _fourbar_guess(pin, ground, b, c, -1.0 if crossed else 1.0)
    else:
        beta = np.radians(np.asarray(guess[0], float)) + 0.0 * theta
        gamma = np.radians(np.asarray(guess[1], float) - 180.0) + 0.0 * theta

    def residual(beta, gamma):
        cu, fu = unit(beta), unit(gamma)
        return (pin[0] + b * cu[0] - ground[0] - c * fu[0], pin[1] + b * cu[1] - ground[1] - c * fu[1])

    def jacobian(beta, gamma):
        cu, fu = unit(beta), unit(gamma)
        return (-b * cu[1], c * fu[1], b * cu[0], -c * fu[0])

    beta, gamma = _iterate(residual, jacobian, beta, gamma, 1.0, tol, max_iter, "Newton (four-bar)")
    rates = fourbar_rates(pin_v, pin_a, b, beta, c, gamma)
    with np.errstate(all="ignore"):
        check_finite("Newton (four-bar)", *rates)
    coupler_omega, coupler_alpha, follower_omega, follower_alpha = rates
    return FourBarMotion(*(as_float_or_array(v) for v in (
        normalise_degrees(np.degrees(beta)), coupler_omega, coupler_alpha,
        normalise_degrees(np.degrees(gamma) + 180.0), follower_omega, follower_alpha)))


def _fourbar_guess(pin, ground, b, c, side):
    """A first guess for B on the requested side of the line A->Bo."""
    mid = ((pin[0] + ground[0]) / 2, (pin[1] + ground[1]) / 2)
    dx, dy = ground[0] - pin[0], ground[1] - pin[1]
    span = np.hypot(dx, dy)
    with np.errstate(all="ignore"):
        left = (-dy / span, dx / span)
    height = 0.5 * np.minimum(b, c)
    guess_b = (mid[0] + side * height * left[0], mid[1] + side * height * left[1])
    beta = np.arctan2(guess_b[1] - pin[1], guess_b[0] - pin[0])
    gamma = np.arctan2(guess_b[1] - ground[1], guess_b[0] - ground[0])
    return beta, gamma


def _iterate(residual, jacobian, x, y, y_scale, tol, max_iter, name):
    """Newton on two unknowns (x, y), element-wise; stops each element when its
    scaled step max(|dx|, |dy|/y_scale) <= tol (x is an angle in radians; y an
    angle with y_scale = 1 or a length with y_scale a link length)."""
    x = np.array(x, float, copy=True)
    y = np.array(y, float, copy=True)
    active = np.ones(np.shape(x), bool)
    with np.errstate(all="ignore"):
        for _ in range(max_iter):
            r1, r2 = residual(x, y)
            j11, j12, j21, j22 = (np.broadcast_to(j, np.shape(x)) for j in jacobian(x, y))
            det = j11 * j22 - j12 * j21
            dx = (r1 * j22 - r2 * j12) / det
            dy = (j11 * r2 - j21 * r1) / det
            if not np.all(np.isfinite(np.where(active, dx, 0.0)) & np.isfinite(np.where(active, dy, 0.0))):
                bad = active & ~(np.isfinite(dx) & np.isfinite(dy))
                raise LinkageError(f"{name}: singular Jacobian", _first(bad))
            x = np.where(active, x - dx, x)
            y = np.where(active, y - dy, y)
            step = np.maximum(np.abs(dx), np.abs(dy) / y_scale)
            active = active & (step > tol)
            if not active.any():
                return x, y
    raise LinkageError(f"{name}: no convergence in {max_iter} iterations", _first(active))


def _first(mask):
    return int(np.flatnonzero(mask)[0]) if np.ndim(mask) else None
