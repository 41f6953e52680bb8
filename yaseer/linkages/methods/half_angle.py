"""Four-bar by Freudenstein's tan-half-angle quadratic (seed 003, Oke et al.).

With the fixed link turned onto +x (Ao at 0, Bo at d), the loop
a*u(theta) + b*u(beta) = d + c*u(phi) (phi the direction Bo->B) gives, for
t = tan(phi/2), the quadratic AA*t^2 + BB*t + CC = 0 with (Fortran listing of 003)

    AK = (a^2 - b^2 + c^2 + d^2)/2
    AA = AK - a*(d - c)*cos(theta) - c*d
    BB = -2*a*c*sin(theta)
    CC = AK - a*(d + c)*cos(theta) + c*d

Two forms:

* ``half-angle-printed`` (:func:`fourbar_half_angle_printed`) is the listing as printed: t = (-BB +/- sqrt(BB^2 - 4*AA*CC))/(2*AA),
  phi = 2*ATAN(t), and the coupler from BET = ASIN((c*sin(phi) - a*sin(theta))/b).
  The quadratic formula cancels catastrophically for the root that stays finite
  as AA -> 0 (phi near 180 deg on the other root) and divides by zero at AA = 0;
  ASIN returns only |beta| <= 90 deg, the wrong coupler when it points back
  towards Ao; near |beta| = 90 deg it loses half the digits.  Nothing is checked:
  those are findings for ``yaseer stability``, reported as they fall.
* ``half-angle`` (:func:`fourbar_half_angle`) is the cancellation-free form: q = -(BB + sign(BB)*sqrt(D))/2,
  the roots q/AA and CC/q taken as half-angles with atan2 (no division at all),
  and the coupler from the angle of B - A.  It raises AssemblyError where the
  discriminant is negative (cannot be assembled).

Both compute the two roots and keep the one on the side of A->Bo the
contract's assembly mode asks for (uncrossed: B left of A->Bo), and take the
rates from the differentiated loop equations (the rate formulas printed in 003
carry sign errors that are not a matter of numerics; the errata document them).
"""

from __future__ import annotations

import numpy as np

from yaseer.linkages.errors import AssemblyError
from yaseer.linkages.fourbar import UNCROSSED, FourBar
from yaseer.linkages.registry import register

from yaseer.linkages.numerics import array_math
from yaseer.linkages.planar import driven_crank

from .assemble import fourbar_result, ground_pivot, side_of


def _printed_angles(frame: "_Frame", branch):
    """Seed 003's listing as printed: the quadratic formula, 2*ATAN, BET = ASIN(...)."""
    with np.errstate(all="ignore"):
        aa, bb, cc = frame.coefficients()
        root = np.sqrt(bb**2 - 4 * aa * cc)  # a negative discriminant gives NaN: Fortran's SQRT would fail
        phi_plus = 2 * np.arctan((-bb + root) / (2 * aa))
        phi_minus = 2 * np.arctan((-bb - root) / (2 * aa))
        phi = frame.pick(phi_plus, phi_minus, branch)
        beta = np.arcsin((frame.c * np.sin(phi) - frame.a * np.sin(frame.theta)) / frame.b)
    return beta, phi


def _stable_angles(frame: "_Frame", branch):
    """The same quadratic without cancellation; AssemblyError where it has no real root."""
    aa, bb, cc = frame.coefficients()
    discriminant = bb**2 - 4 * aa * cc
    if np.any(discriminant < 0) or np.any(frame.b <= 0) or np.any(frame.c <= 0):
        raise AssemblyError("half-angle: the coupler and follower cannot meet")
    q = -(bb + np.where(bb < 0, -1.0, 1.0) * np.sqrt(discriminant)) / 2
    phi = frame.pick(2 * np.arctan2(q, aa), 2 * np.arctan2(cc, q), branch)
    b_point = frame.d + frame.c * np.exp(1j * phi) - frame.a * np.exp(1j * frame.theta)
    return np.angle(b_point), phi


def _half_angle_method(name: str, angles, summary: str):
    """Register a four-bar method with ``fourbar_closed``'s arguments whose positions
    come from ``angles(frame, branch)`` -> (coupler, Bo->B) in the fixed link's frame."""

    def method(ground_length, ground_angle_deg, crank_length, coupler_length, follower_length, crank_angle_deg,
               omega=0.0, alpha=0.0, *, crank_length_rate=0.0, crank_length_accel=0.0, branch=UNCROSSED) -> FourBar:
        crank = driven_crank(crank_length, crank_angle_deg, omega, alpha, crank_length_rate, crank_length_accel,
                         exact_degrees=False)
        frame = _Frame(ground_length, ground_angle_deg, crank_length, coupler_length, follower_length,
                       crank_angle_deg)
        beta, phi = angles(frame, branch)
        with np.errstate(all="ignore"):
            return fourbar_result(crank, ground_pivot(ground_length, ground_angle_deg),
                                  beta + frame.turn, phi + frame.turn, coupler_length)

    method.__name__ = method.__qualname__ = "fourbar_" + name.replace("-", "_")
    method.__doc__ = f"{summary}; same arguments and result as ``fourbar_closed``."
    return register("fourbar", name)(method)


fourbar_half_angle_printed = _half_angle_method(
    "half-angle-printed", _printed_angles, "Seed 003's position formulas as printed")
fourbar_half_angle = _half_angle_method(
    "half-angle", _stable_angles, "The same quadratic solved without cancellation")


class _Frame:
    """The linkage turned so that the fixed link lies along +x (angles in radians), its lengths
    in a unit of the mechanism's size: a power of two near its largest length, so that the
    quadratic's coefficients (products of two lengths) neither underflow nor overflow for a
    mechanism measured in 1E-165 or 1E+165 units; a power of two divides exactly, so every
    other mechanism gives the same bits as in its own unit."""

    def __init__(self, ground_length, ground_angle_deg, crank_length, coupler_length, follower_length, crank_angle_deg):
        lengths = [np.asarray(length, float) for length in (ground_length, crank_length, coupler_length,
                                                              follower_length)]
        largest = np.abs(lengths[0])
        for length in lengths[1:]:  # each may be one number or an array over the positions
            largest = np.maximum(largest, np.abs(length))
        unit = array_math().unit_of(largest)
        self.d, self.a, self.b, self.c = (length / unit for length in lengths)
        self.turn = np.radians(np.asarray(ground_angle_deg, float))
        self.theta = np.radians(np.asarray(crank_angle_deg, float)) - self.turn

    def pick(self, phi_one, phi_other, branch):
        """The root on the side of A->Bo the assembly mode asks for (left: uncrossed).

        The side is the sign of cross(Bo - A, B - A) = c*((d - a*cos(theta))*sin(phi) + a*sin(theta)*cos(phi)).
        """
        side = (self.d - self.a * np.cos(self.theta)) * np.sin(phi_one) + self.a * np.sin(self.theta) * np.cos(phi_one)
        return np.where(side_of(branch) * side >= 0, phi_one, phi_other)

    def coefficients(self):
        """AA, BB, CC of seed 003's quadratic in tan(phi/2)."""
        a, b, c, d, theta = self.a, self.b, self.c, self.d, self.theta
        ak = (a**2 - b**2 + c**2 + d**2) / 2
        return ak - a * (d - c) * np.cos(theta) - c * d, -2 * a * c * np.sin(theta), ak - a * (d + c) * np.cos(theta) + c * d
