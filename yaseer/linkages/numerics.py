"""The functions the linkage formulas use beyond ``+ - * /``, ``**`` and ``abs``,
for one position in Python numbers and for many positions in numpy arrays.

Every formula of the linkages is written once, against a namespace ``xp``:
:data:`SCALAR` (``math``/``cmath`` on Python floats and complex numbers, no numpy
imported: a ``GOSUB PROG n`` call) or the numpy namespace (arrays: a whole
cycle in one call).  :func:`math_for` picks it from the arguments.  Points are
complex numbers in both (``x + 1j*y``).

Floating-point trouble differs only in how it shows: numpy returns inf or NaN
(the caller checks results with ``isfinite``), Python raises ZeroDivisionError,
OverflowError or ValueError (math domain error); the binding turns both into
the same BASIC error.
"""

from __future__ import annotations

import cmath
import functools
import math
from types import SimpleNamespace

_NUMBERS = (int, float, complex)


def _where(condition, yes, no):
    return yes if condition else no


def _isfinite(value) -> bool:
    return cmath.isfinite(value) if isinstance(value, complex) else math.isfinite(value)


def _zeros_like(value):
    return 0j if isinstance(value, complex) else 0.0


def _ones_like(value):
    return 1.0


def _real(value) -> float:
    return value.real


def _imag(value) -> float:
    return value.imag


def _angle(value: complex) -> float:
    """atan2(imag, real) in radians.  (Not cmath.phase: it raises OverflowError when the
    angle underflows to a subnormal, as for an eccentricity of 5e-324.)"""
    return math.atan2(value.imag, value.real)


_unit = functools.partial(cmath.rect, 1.0)  # u(angle) = cos(angle) + i sin(angle)


QUADRANTS = {0.0: complex(1.0, 0.0), 90.0: complex(0.0, 1.0), 180.0: complex(-1.0, 0.0), 270.0: complex(0.0, -1.0)}


def _unit_degrees(angle_deg) -> complex:
    """u(angle) for an angle in degrees, exact at multiples of 90 (see planar.unit_degrees)."""
    exact = QUADRANTS.get(angle_deg % 360.0)
    return exact if exact is not None else _unit(math.radians(angle_deg))


def _unit_of(length: float) -> float:
    """The power of two just above ``length``'s size (1.0 for 0, inf or nan): dividing by it is exact."""
    return math.ldexp(1.0, math.frexp(length)[1])


#: One position: Python numbers (``float``, ``complex``), ``math`` and ``cmath``.
SCALAR = SimpleNamespace(
    scalar=True, pi=math.pi,
    float=float, complex=complex, sqrt=math.sqrt, cos=math.cos, sin=math.sin, arctan=math.atan,
    radians=math.radians, degrees=math.degrees, angle=_angle, unit=_unit, unit_degrees=_unit_degrees, exp=cmath.exp,
    where=_where, any=bool, all=bool, isfinite=_isfinite, real=_real, imag=_imag,
    zeros_like=_zeros_like, ones_like=_ones_like, maximum=max, unit_of=_unit_of,
)

_numpy_math: SimpleNamespace | None = None


def array_math() -> SimpleNamespace:
    """Many positions: the same names over numpy arrays (numpy imported on first use)."""
    global _numpy_math
    if _numpy_math is None:
        import numpy as np

        _numpy_math = SimpleNamespace(
            scalar=False, pi=np.pi,
            float=lambda value: np.asarray(value, dtype=float),
            complex=lambda value: np.asarray(value, dtype=complex),
            sqrt=np.sqrt, cos=np.cos, sin=np.sin, arctan=np.arctan, radians=np.radians, degrees=np.degrees,
            angle=np.angle, unit=lambda angle: np.exp(1j * np.asarray(angle, dtype=float)), exp=np.exp,
            where=np.where, any=np.any, all=np.all, isfinite=np.isfinite, real=np.real, imag=np.imag,
            zeros_like=np.zeros_like, ones_like=np.ones_like, maximum=np.maximum,
            unit_of=lambda length: np.ldexp(1.0, np.frexp(length)[1]),
        )
    return _numpy_math


def math_for(*values) -> SimpleNamespace:
    """:data:`SCALAR` when every value is a Python number (numpy's float64 is
    one); the namespace a value's type names (``math_namespace``: a recording,
    :mod:`tracing`); else the numpy namespace (:func:`array_math`)."""
    for value in values:
        if not isinstance(value, _NUMBERS):
            return getattr(type(value), "math_namespace", None) or array_math()
    return SCALAR
