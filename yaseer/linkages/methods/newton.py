"""Newton iteration on the loop-closure equations (seed 004's FindRoot, by hand).

Positions are found by Newton's method from a crude geometric first guess (or a
guess the caller passes, e.g. the previous position of a cycle); velocities and
accelerations then come from the differentiated loop equations.  ``tol`` is the
size of the last Newton step at which the iteration stops (radians; the slider
travel is scaled by the rod length), ``max_iter`` the iteration cap.  Not
converging within the cap, or a singular Jacobian, raises
:class:`NoConvergenceError` (a position that cannot be assembled at all is
recognised first, from the link lengths, and raises AssemblyError); nothing is
returned silently.  What Newton cannot
promise is the branch: from a poor guess near a toggle it may converge to the
other assembly, silently (``yaseer stability`` counts those).

Works on floats or numpy arrays: every position iterates until its own step is
below ``tol`` (converged positions are frozen).
"""

from __future__ import annotations

import numpy as np

from yaseer.linkages.errors import AssemblyError
from yaseer.linkages.fourbar import UNCROSSED, FourBar
from yaseer.linkages.registry import register
from yaseer.linkages.slider_crank import SliderCrank

from yaseer.linkages.numerics import array_math
from yaseer.linkages.planar import driven_crank

from .assemble import NoConvergenceError, first_index, fourbar_result, ground_pivot, side_of, slider_crank_result

DEFAULT_TOL = 1e-12
DEFAULT_MAX_ITER = 50


@register("slider_crank", "newton")
def slider_crank_newton(eccentricity, crank_length, rod_length, crank_angle_deg, omega=0.0, alpha=0.0, *,
                        crank_length_rate=0.0, crank_length_accel=0.0, axis_deg=0.0,
                        tol: float = DEFAULT_TOL, max_iter: int = DEFAULT_MAX_ITER, guess=None) -> SliderCrank:
    """Same arguments and result as ``slider_crank_closed``; unknowns rod angle beta, travel s.

    Residual A + b u(beta) + e i u(phi) - s u(phi) = 0 (complex form).  First guess:
    the rod along the axis (beta = phi), s = A.u(phi) + b; or ``guess`` = (beta deg, s).
    """
    crank = driven_crank(crank_length, crank_angle_deg, omega, alpha, crank_length_rate, crank_length_accel,
                         exact_degrees=False)
    e, b = np.asarray(eccentricity, float), np.asarray(rod_length, float)
    if np.any(b <= 0):
        raise AssemblyError("connecting rod of zero length")
    phi = np.radians(np.asarray(axis_deg, float))
    axis = np.exp(1j * phi)
    pin = crank.pin.pos
    if np.any(np.abs(e + (pin * axis.conjugate()).imag) > b):
        raise AssemblyError("Newton (slider-crank): the rod cannot reach the cylinder axis")
    if guess is None:
        beta, s = phi + 0.0 * pin.real, (pin * axis.conjugate()).real + b
    else:
        beta, s = np.radians(np.asarray(guess[0], float)) + 0.0 * pin.real, np.asarray(guess[1], float) + 0.0 * pin.real

    def residual(beta, s):
        return pin + b * np.exp(1j * beta) + e * 1j * axis - s * axis

    def columns(beta, s):
        return 1j * b * np.exp(1j * beta), -axis + 0.0 * s

    beta, s = _iterate(residual, columns, beta, s, b, tol, max_iter, "Newton (slider-crank)", length=array_math().unit_of(b))
    return slider_crank_result(crank, e, b, phi, beta, s)


@register("fourbar", "newton")
def fourbar_newton(ground_length, ground_angle_deg, crank_length, coupler_length, follower_length, crank_angle_deg,
                   omega=0.0, alpha=0.0, *, crank_length_rate=0.0, crank_length_accel=0.0, branch=UNCROSSED,
                   tol: float = DEFAULT_TOL, max_iter: int = DEFAULT_MAX_ITER, guess=None) -> FourBar:
    """Same arguments and result as ``fourbar_closed``; unknowns beta (A->B), gamma (Bo->B).

    Residual A + b u(beta) - Bo - c u(gamma) = 0.  First guess: B half the shorter of
    b, c off the midpoint of A and Bo, on the side ``branch`` asks for; or ``guess`` =
    (coupler deg, follower B->Bo deg), the contract's T(13), T(14).
    """
    crank = driven_crank(crank_length, crank_angle_deg, omega, alpha, crank_length_rate, crank_length_accel,
                         exact_degrees=False)
    pivot = ground_pivot(ground_length, ground_angle_deg)
    b, c = np.asarray(coupler_length, float), np.asarray(follower_length, float)
    if np.any(b <= 0) or np.any(c <= 0):
        raise AssemblyError("coupler or follower of zero length")
    pin = crank.pin.pos
    span = np.abs(pivot.pos - pin)
    if np.any(span > b + c) or np.any(span < np.abs(b - c)):
        raise AssemblyError("Newton (four-bar): the coupler and follower cannot meet")
    if guess is None:
        middle = (pin + pivot.pos) / 2
        with np.errstate(all="ignore"):
            left = 1j * (pivot.pos - pin) / np.abs(pivot.pos - pin)
        guess_b = middle + side_of(branch) * 0.5 * np.minimum(b, c) * left
        beta, gamma = np.angle(guess_b - pin), np.angle(guess_b - pivot.pos)
    else:
        beta = np.radians(np.asarray(guess[0], float)) + 0.0 * pin.real
        gamma = np.radians(np.asarray(guess[1], float)) + np.pi + 0.0 * pin.real

    def residual(beta, gamma):
        return pin + b * np.exp(1j * beta) - pivot.pos - c * np.exp(1j * gamma)

    def columns(beta, gamma):
        return 1j * b * np.exp(1j * beta), -1j * c * np.exp(1j * gamma)

    beta, gamma = _iterate(residual, columns, beta, gamma, 1.0, tol, max_iter, "Newton (four-bar)", length=array_math().unit_of(b))
    return fourbar_result(crank, pivot, beta, gamma, b)


def _iterate(residual, columns, x, y, y_scale, tol, max_iter, name, length=1.0):
    """Newton on two real unknowns of one complex residual, element-wise.

    ``columns(x, y)`` gives the residual's derivatives in x and y (complex).  Each
    element stops when its step max(|dx|, |dy|/y_scale) <= tol.  The residual and its
    derivatives are taken in units of ``length`` (a power of two near the mechanism's
    size: exact, the same bits as in its own unit): the determinant, a product of two
    lengths, would underflow to 0 for a mechanism measured in 1E-165 units, or overflow
    for one in 1E+165 units.
    """
    x = np.array(x, float, copy=True)
    y = np.array(y, float, copy=True)
    active = np.ones(np.shape(x), bool)
    with np.errstate(all="ignore"):
        for _ in range(max_iter):
            r = residual(x, y) / length
            jx, jy = (column / length for column in columns(x, y))
            det = jx.real * jy.imag - jx.imag * jy.real
            dx = (r.real * jy.imag - r.imag * jy.real) / det
            dy = (jx.real * r.imag - jx.imag * r.real) / det
            finite = np.isfinite(dx) & np.isfinite(dy)
            if np.any(active & ~finite):
                raise NoConvergenceError(f"{name}: singular Jacobian", first_index(active & ~finite))
            x = np.where(active, x - dx, x)
            y = np.where(active, y - dy, y)
            active = active & (np.maximum(np.abs(dx), np.abs(dy) / y_scale) > tol)
            if not active.any():
                return x, y
    raise NoConvergenceError(f"{name}: no convergence in {max_iter} iterations", first_index(active))
