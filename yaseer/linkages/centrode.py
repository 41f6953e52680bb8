"""The space centrode of a four-bar's coupler (seed 004, Jong, Reynolds and Adams 1996).

Seed 004's linkage in Program 2's terms: crank pivot Ao = the paper's A at the
origin, follower pivot Bo = E at (1.2, 0) m; crank AB = 0.3 m (the paper's angle
beta, counter-clockwise from +x, is Program 2's crank angle T(12)); coupler BD =
0.5 m; follower DE = 1 m.  s + l = p + q (0.3 + 1.2 = 0.5 + 1): a change-point
linkage.  All four joints fall in line at beta = 180 deg, where the two assemblies
meet; moving through, the linkage changes assembly, so the follower's cycle takes
two crank turns.  The paper's first revolution starts on the crossed assembly
(D below the line A->E at beta = 0+).

The coupler's instant centre C is where the crank line AoA meets the follower line
BoB; from the velocities, C = A + i v_A / w3 (:func:`yaseer.linkages.tracking.instant_centre`),
which also holds at the change point, where the lines coincide and w3 comes from
the acceleration equations.  C runs to infinity where the crank and the follower
are parallel (w3 = 0): there it jumps along an asymptote of the centrode, the line
of direction u(beta*) at signed distance ``offset`` (to the left) from Ao.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from yaseer.linkages.fourbar import CROSSED, fourbar_closed
from yaseer.linkages.tracking import Geometry, Tracked, collinear_rates, instant_centre, track
from yaseer.linkages.planar import Motion, crank_pin, Rotation, Stretch

SEED004 = Geometry(ground_length=1.2, ground_angle_deg=0.0, crank_length=0.3, coupler_length=0.5,
                   follower_length=1.0)
SEED004_START = CROSSED


@dataclass(frozen=True)
class CollinearCentre:
    """At a change point: the coupler's angular velocity per unit crank angular
    velocity (w_BD / w_AB) and the instant centre's x on the common line (AC, m)."""

    ratio: float
    ac: float


@dataclass(frozen=True)
class Asymptote:
    """Where C leaves to infinity: the crank angle (deg) and the asymptote, the line
    through ``offset * u(angle + 90 deg)`` with direction u(angle)."""

    crank_angle_deg: float
    offset: float

    def point(self, along: float) -> complex:
        direction = complex(math.cos(math.radians(self.crank_angle_deg)), math.sin(math.radians(self.crank_angle_deg)))
        return (1j * self.offset + along) * direction

    @property
    def slope(self) -> float:
        return math.tan(math.radians(self.crank_angle_deg))


def change_point_angles(geometry: Geometry) -> list[float]:
    """Crank angles (deg, [0, 360)) with all four joints in line: the crank along the ground."""
    return sorted({geometry.ground_angle_deg % 360.0, (geometry.ground_angle_deg + 180.0) % 360.0})


def collinear_centres(geometry: Geometry, crank_angle_deg: float) -> list[CollinearCentre]:
    """Both solutions at a change point (seed 004: (1 +/- 2 sqrt 2)/5 and AC = 0.0918 / -1.1204 m).

    Uses unit crank angular velocity; AC is measured along the common line's +x.
    """
    crank = Rotation(math.radians(crank_angle_deg), 1.0, 0.0)
    pin_a = crank_pin(Stretch(geometry.crank_length, 0.0, 0.0), crank)
    pin_a = Motion(complex(pin_a.pos), complex(pin_a.vel), complex(pin_a.acc))
    position = fourbar_closed(*geometry.astuple(), crank_angle_deg)
    pin_b, pivot = complex(position.pin_b.pos), complex(position.pivot.pos)
    roots = collinear_rates(pin_a, pin_b - pin_a.pos, pivot - pin_b)
    return [CollinearCentre(w3, (pin_a.pos + 1j * pin_a.vel / w3).real) for w3, _ in roots]


def space_centrode(geometry: Geometry = SEED004, crank_angles_deg=None, start_branch: int = SEED004_START) -> tuple[Tracked, np.ndarray]:
    """Track the motion (unit crank speed) and return it with C at each position."""
    if crank_angles_deg is None:
        crank_angles_deg = np.arange(0.0, 720.0 + 1e-9, 0.25)
    tracked = track(geometry, crank_angles_deg, 1.0, 0.0, start_branch=start_branch)
    return tracked, instant_centre(tracked.fourbar)


def _follower_omega(geometry: Geometry, angle: float, side: int) -> float:
    return float(fourbar_closed(*geometry.astuple(), angle, 1.0, 0.0, branch=side).coupler.omega)


def jumps(geometry: Geometry = SEED004, start_branch: int = SEED004_START, step_deg: float = 0.5) -> list[Asymptote]:
    """The crank angles (deg, over the two-turn cycle) where C goes to infinity, with
    their asymptotes; found where the tracked w3 changes sign, refined by bisection
    on that assembly."""
    angles = np.arange(0.0, 720.0 + 1e-9, step_deg)
    tracked = track(geometry, angles, 1.0, 0.0, start_branch=start_branch)
    w3 = np.asarray(tracked.fourbar.coupler.omega)
    found = []
    for k in range(len(angles) - 1):
        same_side = tracked.branch[k] == tracked.branch[k + 1] and not tracked.singular[k:k + 2].any()
        if same_side and w3[k] * w3[k + 1] < 0:
            angle = _bisect(geometry, angles[k], angles[k + 1], int(tracked.branch[k]))
            found.append(Asymptote(angle, _asymptote_offset(geometry, angle, int(tracked.branch[k]))))
    return found


def _bisect(geometry: Geometry, low: float, high: float, side: int) -> float:
    f_low = _follower_omega(geometry, low, side)
    for _ in range(60):
        mid = 0.5 * (low + high)
        f_mid = _follower_omega(geometry, mid, side)
        if f_low * f_mid <= 0:
            high = mid
        else:
            low, f_low = mid, f_mid
    return 0.5 * (low + high)


def _asymptote_offset(geometry: Geometry, angle: float, side: int, h_deg: float = 1e-4) -> float:
    """Limit of C's distance from the crank line at ``angle`` (average of both sides)."""
    direction = complex(math.cos(math.radians(angle)), math.sin(math.radians(angle)))
    offsets = []
    for near in (angle - h_deg, angle + h_deg):
        result = fourbar_closed(*geometry.astuple(), near, 1.0, 0.0, branch=side)
        centre = complex(instant_centre(result))
        offsets.append((centre * direction.conjugate()).imag)
    return 0.5 * sum(offsets)
