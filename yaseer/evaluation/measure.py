"""Errors against a 50-digit reference.

The reference is kept as two floats per value (``hi + lo``, the mpf rounded
twice), so that the error of a float result is measured to well below one
unit in the last place: ``(value - hi) - lo``.

Error measure (``yaseer bench``'s "worst relative error"):

* an angle (degrees) is compared modulo 360 deg and its error is the absolute
  difference in **radians** (an angle has no natural scale of its own);
* any other quantity's error is the absolute difference divided by the largest
  |reference| of that quantity over the case (normwise relative error: a rate
  that passes through zero does not blow the measure up).

The worst error of a case is the largest over its quantities and positions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class ReferenceColumn:
    """One quantity of a case at every position: 50-digit values as hi + lo floats."""

    name: str
    hi: np.ndarray
    lo: np.ndarray
    angle: bool

    @classmethod
    def from_mpf(cls, name: str, values, angle: bool = False) -> "ReferenceColumn":
        import mpmath

        his, los = [], []
        with mpmath.workdps(60):
            for value in values:
                value = mpmath.mpf(value)
                hi = float(value)
                his.append(hi)
                los.append(float(value - hi) if math.isfinite(hi) else 0.0)
        return cls(name, np.array(his), np.array(los), angle)

    @property
    def scale(self) -> float:
        """The normalising scale: max |reference| (1 rad for angles)."""
        if self.angle:
            return 1.0
        biggest = float(np.max(np.abs(self.hi))) if self.hi.size else 0.0
        return biggest if biggest > 0 else 1.0

    def errors(self, values) -> np.ndarray:
        """Error of ``values`` (float array, same positions) per position; NaN stays NaN."""
        values = np.asarray(values, dtype=float)
        difference = (values - self.hi) - self.lo
        if self.angle:
            difference = np.radians(np.mod(difference + 180.0, 360.0) - 180.0)
        return np.abs(difference) / self.scale


@dataclass(frozen=True)
class Outcome:
    """What one method did on one case: worst error or how it failed.

    ``status``: "ok", "nan" (NaN or infinity returned silently), "exception"
    (a clear error raised: ``detail`` has its text), "wrong branch" (a finite,
    loop-closing answer of the other assembly mode, returned silently).
    """

    worst: float
    status: str = "ok"
    detail: str = ""
    where: str = ""

    @property
    def silent_wrong(self) -> bool:
        return self.status in ("nan", "wrong branch") or (self.status == "ok" and not self.worst <= 1e-6)


def worst_error(reference: list[ReferenceColumn], results: dict) -> tuple[float, str]:
    """(worst error, "column at position index") of ``results`` (name -> values)."""
    worst, where = 0.0, ""
    for column in reference:
        errors = column.errors(results[column.name])
        if np.any(~np.isfinite(errors)):
            index = int(np.flatnonzero(~np.isfinite(errors))[0])
            return math.inf, f"{column.name}[{index}]"
        if errors.size and errors.max() > worst:
            worst, where = float(errors.max()), f"{column.name}[{int(errors.argmax())}]"
    return worst, where


def outcome_of(reference: list[ReferenceColumn], results: dict, closes_other_branch=None) -> Outcome:
    """Classify a finished run: NaN/inf, wrong branch (if ``closes_other_branch(results)``
    says the answer is a valid assembly of the other mode), or ok with its worst error."""
    worst, where = worst_error(reference, results)
    if not math.isfinite(worst):
        return Outcome(math.inf, "nan", "NaN or infinity returned", where)
    if worst > 1e-3 and closes_other_branch is not None and closes_other_branch(results):
        return Outcome(worst, "wrong branch", "the other assembly mode, returned silently", where)
    return Outcome(worst, "ok", "", where)
