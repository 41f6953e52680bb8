"""Number types for the reference solver: IEEE double (``FLOAT``) or mpmath at a chosen precision.

The solver's algebra is written once against the small interface below
(``num``, ``sin``, ``cos``, ``atan2``, ``sqrt``, ``radians``, ``degrees``,
``solve``); an arithmetic object supplies it.  ``FLOAT`` works on Python
floats and solves linear systems with numpy; ``MpArithmetic(dps)`` works on
mpmath numbers of ``dps`` decimal digits in a private mpmath context (the
global ``mpmath.mp`` precision is never touched).

Angles passed to ``radians`` are degrees; everything else is plain numbers.
"""

from __future__ import annotations

import math


class SingularSystemError(ArithmeticError):
    """The linear system of a step (Newton, velocity, acceleration or force) is singular."""


class FloatArithmetic:
    """IEEE double arithmetic (Python floats, numpy for the linear solves)."""

    name = "float"
    #: Newton stops when its correction is below this (relative to the size of the coordinates).
    tolerance = 1e-13
    #: A system whose condition number exceeds this is reported as singular.
    max_condition = 1e15

    def num(self, value) -> float:
        """``value`` (int, float or decimal string) as a float."""
        return float(value)

    sin = staticmethod(math.sin)
    cos = staticmethod(math.cos)
    sqrt = staticmethod(math.sqrt)
    atan2 = staticmethod(math.atan2)
    radians = staticmethod(math.radians)
    degrees = staticmethod(math.degrees)
    pi = math.pi

    def to_float(self, value) -> float:
        return float(value)

    def solve(self, rows: list[list[float]], rhs: list[float]) -> list[float]:
        """Solve the square system ``rows @ x = rhs``; raise SingularSystemError if it is singular."""
        import numpy as np

        matrix = np.array(rows, dtype=float)
        try:
            condition = np.linalg.cond(matrix)
            if not condition < self.max_condition:
                raise SingularSystemError(f"singular system (condition number {condition:.3g})")
            return np.linalg.solve(matrix, np.array(rhs, dtype=float)).tolist()
        except np.linalg.LinAlgError as exc:
            raise SingularSystemError("singular system") from exc


class MpArithmetic:
    """mpmath arithmetic at ``dps`` significant decimal digits (its own mpmath context)."""

    name = "mpmath"

    def __init__(self, dps: int = 50):
        import mpmath

        self.ctx = mpmath.MPContext()
        self.ctx.dps = dps
        self.dps = dps
        self.tolerance = self.ctx.mpf(10) ** (-(dps - 3))
        self.pi = self.ctx.pi

    def num(self, value):
        """``value`` as an mpf: floats exactly as their binary value, strings as exact decimals."""
        return self.ctx.mpf(value)

    def sin(self, x):
        return self.ctx.sin(x)

    def cos(self, x):
        return self.ctx.cos(x)

    def sqrt(self, x):
        return self.ctx.sqrt(x)

    def atan2(self, y, x):
        return self.ctx.atan2(y, x)

    def radians(self, degrees):
        return self.ctx.mpf(degrees) * self.ctx.pi / 180

    def degrees(self, radians):
        return radians * 180 / self.ctx.pi

    def to_float(self, value) -> float:
        return float(value)

    def solve(self, rows, rhs):
        """Solve the square system ``rows @ x = rhs`` at the context's precision.

        Gaussian elimination with partial pivoting on plain lists (mpmath's
        matrix class costs ten times more for these 5-20 unknowns).
        """
        n = len(rhs)
        augmented = [list(row) + [value] for row, value in zip(rows, rhs)]
        for k in range(n):
            pivot = max(range(k, n), key=lambda i: abs(augmented[i][k]))
            if not augmented[pivot][k]:
                raise SingularSystemError("singular system")
            augmented[k], augmented[pivot] = augmented[pivot], augmented[k]
            head = augmented[k]
            for i in range(k + 1, n):
                row = augmented[i]
                factor = row[k] / head[k]
                if factor:
                    for j in range(k + 1, n + 1):
                        row[j] -= factor * head[j]
        solution = [self.ctx.mpf(0)] * n
        for k in range(n - 1, -1, -1):
            head = augmented[k]
            total = head[n] - sum((head[j] * solution[j] for j in range(k + 1, n)), self.ctx.mpf(0))
            solution[k] = total / head[k]
        return solution


FLOAT = FloatArithmetic()


def arithmetic_for(number: str | object = "float", dps: int = 50):
    """The arithmetic named ``number`` ("float" or "mpmath"), or ``number`` itself if it is one."""
    if number == "float":
        return FLOAT
    if number in ("mp", "mpmath"):
        return MpArithmetic(dps)
    if hasattr(number, "solve") and hasattr(number, "num"):
        return number
    raise ValueError(f"unknown arithmetic {number!r}: use 'float' or 'mpmath'")
