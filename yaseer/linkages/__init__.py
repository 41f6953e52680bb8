"""Pure planar-linkage numerics. They know nothing of BASIC.

Vectorised: every argument may be a float or a numpy array (a whole crank cycle in
one call); results are named and broadcast to the common shape.  Points are complex
numbers ``x + 1j*y``; angles at the interface are degrees, angular rates rad/s.

- :func:`slider_crank` (Program 1), :func:`fourbar` (Program 2),
  :func:`inverted_slider_crank` (Program 3): kinematics objects whose
  ``*_point(distance, offset_deg)`` give points of links and whose ``forces(...)``
  solve the kinetostatics (:mod:`yaseer.linkages.kinetostatics`).
- :func:`virtual_link` (Program 5), methods ``"polar"`` (default) and ``"paper"``.
- Methods are registered per linkage in :mod:`yaseer.linkages.registry`.
"""

from yaseer.linkages.errors import (
    AssemblyError,
    LinkageError,
    LockedError,
    MethodDivisionByZero,
    SingularForceError,
    UnknownLoadError,
    UnknownMethodError,
)
from yaseer.linkages.fourbar import CROSSED, UNCROSSED, FourBar, fourbar
from yaseer.linkages.inverted_slider_crank import InvertedSliderCrank, inverted_slider_crank
from yaseer.linkages.kinetostatics import ForceResult, MassProps
from yaseer.linkages.slider_crank import SliderCrank, slider_crank
from yaseer.linkages.virtual_link import VirtualLink, virtual_link

__all__ = [
    "AssemblyError", "LinkageError", "LockedError", "MethodDivisionByZero", "SingularForceError",
    "UnknownLoadError", "UnknownMethodError", "CROSSED", "UNCROSSED", "FourBar", "fourbar",
    "InvertedSliderCrank", "inverted_slider_crank", "ForceResult", "MassProps", "SliderCrank",
    "slider_crank", "VirtualLink", "virtual_link",
]
