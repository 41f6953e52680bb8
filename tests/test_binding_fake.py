"""A minimal stand-in for yaseer.basic.machine.machine.Machine, for the binding tests.

It implements only what Python program areas use: array/scalar/set_scalar/set_area.
Arrays not DIMensioned get BASIC's implicit dimension 10 (subscripts 0..10).
"""

from __future__ import annotations

import copy


class FakeMachine:
    def __init__(self, dims: dict[str, int] | None = None):
        self.arrays: dict[str, list[float]] = {name: [0.0] * (size + 1) for name, size in (dims or {}).items()}
        self.scalars: dict[str, float] = {}
        self.areas: dict[int, object] = {}

    def array(self, name: str) -> list[float]:
        return self.arrays.setdefault(name, [0.0] * 11)

    def scalar(self, name: str) -> float:
        return self.scalars.get(name, 0.0)

    def set_scalar(self, name: str, value: float) -> None:
        self.scalars[name] = float(value)

    def set_area(self, number: int, area) -> None:
        self.areas[number] = area

    def call(self, number: int) -> None:
        self.areas[number](self)

    def set(self, **values) -> None:
        """set(L=[(1, 2.0), ...]) or scalar G=9.81."""
        for name, value in values.items():
            if isinstance(value, dict):
                for index, element in value.items():
                    self.array(name)[index] = float(element)
            else:
                self.set_scalar(name, value)

    def snapshot(self):
        return copy.deepcopy(self.arrays), dict(self.scalars)


# The paper's universal dimension statement (Example 1, line 2).
PAPER_DIMS = dict(F=46, M=11, R=19, H=24, A=53, L=20, T=25, W=10, Z=5, C=14, U=4, D=6, E=6, X=11, Y=11, V=21,
                  Q=4, N=3, I=11, P=4)
