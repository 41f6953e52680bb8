"""Four-bar by Freudenstein's tan-half-angle quadratic (seed 003, Oke et al.).

With the fixed link turned onto +x (Ao at 0, Bo at d), the loop
a*u(theta) + b*u(beta) = d + c*u(phi) (phi the direction Bo->B) gives, for
t = tan(phi/2), the quadratic AA*t^2 + BB*t + CC = 0 with (Fortran listing of 003)

    AK = (a^2 - b^2 + c^2 + d^2)/2
    AA = AK - a*(d - c)*cos(theta) - c*d
    BB = -2*a*c*sin(theta)
    CC = AK - a*(d + c)*cos(theta) + c*d

Two forms:

* :func:`fourbar_printed` is the listing as printed: t = (-BB +/- sqrt(BB^2 - 4*AA*CC))/(2*AA),
  phi = 2*ATAN(t), and the coupler from BET = ASIN((c*sin(phi) - a*sin(theta))/b).
  The quadratic formula cancels catastrophically for the root that stays finite
  as AA -> 0 (phi near 180 deg on the other root) and divides by zero at AA = 0;
  ASIN returns only |beta| <= 90 deg, the wrong coupler when it points back
  towards Ao; near |beta| = 90 deg it loses half the digits.  Nothing is checked:
  those are findings for ``yaseer stability``, reported as they fall.
* :func:`fourbar_stable` is the cancellation-free form: q = -(BB + sign(BB)*sqrt(D))/2,
  the roots q/AA and CC/q taken as half-angles with atan2 (no division at all),
  and the coupler from atan2 of B - A.  It raises LinkageError where the
  discriminant is negative (cannot be assembled).

Both compute the two roots and keep the one on the side of A->Bo the
contract's assembly mode asks for (uncrossed: B left of A->Bo) and take the rates from the differentiated loop equations (the rate
formulas printed in 003 carry sign errors that are not a matter of numerics).
"""

from __future__ import annotations

import numpy as np

from .loops import LinkageError, as_float_or_array, check_finite, crank_pin, fourbar_rates, normalise_degrees
from .types import FourBarMotion


def fourbar_printed(ground_length, ground_angle, crank_length, coupler_length, follower_length, crank_angle,
                    crank_speed=0.0, crank_accel=0.0, crank_length_rate=0.0, crank_length_accel=0.0,
                    *, crossed: bool = False) -> FourBarMotion:
    """Seed 003's position formulas as printed; degrees in and out, rates rad/s."""
    with np.errstate(all="ignore"):
        frame = _Frame(ground_length, ground_angle, crank_length, coupler_length, follower_length, crank_angle)
        aa, bb, cc = frame.coefficients()
        root = np.sqrt(bb**2 - 4 * aa * cc)  # a negative discriminant gives NaN, as Fortran's SQRT would fail
        phi_plus = 2 * np.arctan((-bb + root) / (2 * aa))
        phi_minus = 2 * np.arctan((-bb - root) / (2 * aa))
        phi = frame.pick(phi_plus, phi_minus, crossed)
        beta = np.arcsin((frame.c * np.sin(phi) - frame.a * np.sin(frame.theta)) / frame.b)
        return frame.motion(beta, phi, crank_speed, crank_accel, crank_length_rate, crank_length_accel)


def fourbar_stable(ground_length, ground_angle, crank_length, coupler_length, follower_length, crank_angle,
                   crank_speed=0.0, crank_accel=0.0, crank_length_rate=0.0, crank_length_accel=0.0,
                   *, crossed: bool = False) -> FourBarMotion:
    """The same quadratic solved without cancellation; degrees in and out, rates rad/s."""
    with np.errstate(all="ignore"):
        frame = _Frame(ground_length, ground_angle, crank_length, coupler_length, follower_length, crank_angle)
        aa, bb, cc = frame.coefficients()
        discriminant = bb**2 - 4 * aa * cc
        if np.any(discriminant < 0):
            bad = discriminant < 0
            raise LinkageError("half-angle: the mechanism cannot be assembled",
                               int(np.flatnonzero(bad)[0]) if np.ndim(bad) else None)
        bb_sign = np.where(bb < 0, -1.0, 1.0)
        q = -(bb + bb_sign * np.sqrt(discriminant)) / 2
        phi = frame.pick(2 * np.arctan2(q, aa), 2 * np.arctan2(cc, q), crossed)
        b_x = frame.d + frame.c * np.cos(phi) - frame.a * np.cos(frame.theta)
        b_y = frame.c * np.sin(phi) - frame.a * np.sin(frame.theta)
        beta = np.arctan2(b_y, b_x)
        motion = frame.motion(beta, phi, crank_speed, crank_accel, crank_length_rate, crank_length_accel)
        check_finite("half-angle", *motion)
        return motion


class _Frame:
    """The linkage turned so that the fixed link lies along +x (angles in radians)."""

    def __init__(self, ground_length, ground_angle, crank_length, coupler_length, follower_length, crank_angle):
        self.d = np.asarray(ground_length, float)
        self.turn = np.radians(np.asarray(ground_angle, float))
        self.a = np.asarray(crank_length, float)
        self.b = np.asarray(coupler_length, float)
        self.c = np.asarray(follower_length, float)
        self.theta = np.radians(np.asarray(crank_angle, float)) - self.turn

    def pick(self, phi_one, phi_other, crossed):
        """The root on the side of A->Bo the assembly mode asks for (left: uncrossed).

        The side is the sign of cross(Bo - A, B - A) = c*((d - a*cos(theta))*sin(phi) + a*sin(theta)*cos(phi)).
        """
        mode = -1.0 if crossed else 1.0
        side = (self.d - self.a * np.cos(self.theta)) * np.sin(phi_one) + self.a * np.sin(self.theta) * np.cos(phi_one)
        return np.where(mode * side >= 0, phi_one, phi_other)

    def coefficients(self):
        a, b, c, d, theta = self.a, self.b, self.c, self.d, self.theta
        ak = (a**2 - b**2 + c**2 + d**2) / 2
        return ak - a * (d - c) * np.cos(theta) - c * d, -2 * a * c * np.sin(theta), ak - a * (d + c) * np.cos(theta) + c * d

    def motion(self, beta, phi, crank_speed, crank_accel, crank_length_rate, crank_length_accel) -> FourBarMotion:
        """Turn back to the global frame and add the rates of the loop equations."""
        beta_g, phi_g = beta + self.turn, phi + self.turn
        _, pin_v, pin_a = crank_pin(self.a, self.theta + self.turn, np.asarray(crank_length_rate, float),
                                    np.asarray(crank_speed, float), np.asarray(crank_length_accel, float),
                                    np.asarray(crank_accel, float))
        w_c, a_c, w_f, a_f = fourbar_rates(pin_v, pin_a, self.b, beta_g, self.c, phi_g)
        return FourBarMotion(*(as_float_or_array(v) for v in (
            normalise_degrees(np.degrees(beta_g)), w_c, a_c, normalise_degrees(np.degrees(phi_g) + 180.0), w_f, a_f)))
