"""Alternative solution methods for the basic linkages.

Importing this package registers, in :mod:`yaseer.linkages.registry`:

- slider-crank: ``pseudographic`` (seed 001's polygons), ``newton``;
- four-bar: ``half-angle-printed`` (seed 003 as printed), ``half-angle``
  (cancellation-free), ``newton``.

Each has exactly the arguments and result type of the linkage's default
(``closed``) function; Newton adds ``tol``, ``max_iter`` and ``guess``.
"""

from yaseer.linkages.methods import half_angle, newton, pseudographic  # noqa: F401  (registration)
from yaseer.linkages.methods.assemble import NoConvergenceError

__all__ = ["NoConvergenceError", "half_angle", "newton", "pseudographic"]
