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

The names below are imported at their first use: a run whose library calls are all
recorded paths kept on disk (:mod:`yaseer.linkages.recording_cache`) imports this
package for those modules only, and the formulas' modules cost a start about 9 ms.
"""

import sys
from types import ModuleType

#: Each public name -> the module that defines it.
_HOMES = {
    **dict.fromkeys(("AssemblyError", "LinkageError", "LockedError", "MethodDivisionByZero", "SingularForceError",
                     "UnknownLoadError", "UnknownMethodError"), "errors"),
    **dict.fromkeys(("CROSSED", "UNCROSSED", "FourBar", "fourbar"), "fourbar"),
    **dict.fromkeys(("InvertedSliderCrank", "inverted_slider_crank"), "inverted_slider_crank"),
    **dict.fromkeys(("ForceResult", "MassProps"), "kinetostatics"),
    **dict.fromkeys(("SliderCrank", "slider_crank"), "slider_crank"),
    **dict.fromkeys(("VirtualLink", "virtual_link"), "virtual_link"),
}
# The functions named as their modules are: importing such a module binds the module under
# that name in this package, and the name must keep meaning the function.
_SHADOWED = frozenset(name for name, home in _HOMES.items() if name == home)

__all__ = list(_HOMES)


class _Package(ModuleType):
    """This package: its public names are looked up in their modules at first use."""

    def __getattr__(self, name: str):
        home = _HOMES.get(name)
        if home is None:
            raise AttributeError(f"module {self.__name__!r} has no attribute {name!r}")
        __import__(f"{self.__name__}.{home}")
        value = getattr(sys.modules[f"{self.__name__}.{home}"], name)
        setattr(self, name, value)
        return value

    def __setattr__(self, name: str, value) -> None:
        if name in _SHADOWED and isinstance(value, ModuleType):
            value = getattr(value, name)
        super().__setattr__(name, value)

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(_HOMES))


sys.modules[__name__].__class__ = _Package
