"""Program 5's reference at 50 digits: the polar angle and length of a moving point.

A different formulation from both Python methods: the point's path over a short
time is the Taylor polynomial p(t) = p + v t + a t^2/2, and the angle
T(t) = T(0) + atan2(p(0) x p(t), p(0) . p(t)) (continuous through t = 0, even on
atan2's cut at 180 deg) and L(t) = |p(t)| are differentiated numerically by
mpmath (``mpmath.taylor``, which raises its working precision to keep ``dps``
correct digits).  Inputs are taken as the exact binary floats the methods receive.
"""

from __future__ import annotations

import mpmath


def virtual_link_reference(x, y, vx, vy, ax, ay, dps: int = 50) -> dict:
    """T (degrees, [0, 360)), L, D(5) = T', E(5) = T'', D(6) = L', E(6) = L'' as mpf."""
    with mpmath.workdps(dps):
        px, py, qx, qy, rx, ry = (mpmath.mpf(float(v)) for v in (x, y, vx, vy, ax, ay))

        def path_x(t):
            return px + qx * t + rx * t * t / 2

        def path_y(t):
            return py + qy * t + ry * t * t / 2

        def turn(t):
            x, y = path_x(t), path_y(t)
            return mpmath.atan2(px * y - py * x, px * x + py * y)

        angle = mpmath.taylor(turn, 0, 2)
        angle[0] = mpmath.atan2(py, px)
        length = mpmath.taylor(lambda t: mpmath.hypot(path_x(t), path_y(t)), 0, 2)
        degrees = mpmath.degrees(angle[0])
        if degrees < 0:
            degrees += 360
        return {"T": degrees, "L": length[0], "D(5)": angle[1], "E(5)": 2 * angle[2],
                "D(6)": length[1], "E(6)": 2 * length[2]}
