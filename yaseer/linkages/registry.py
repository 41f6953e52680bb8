"""Registry of solution methods per linkage.

Each linkage (``"slider_crank"``, ``"fourbar"``, ``"inverted_slider_crank"``,
``"virtual_link"``) has one or more methods, each a function with the same
signature and result type as the linkage's default. A new method (Newton,
half-angle, pseudographic, ...) is added with::

    @register("fourbar", "newton")
    def fourbar_newton(...): ...

and chosen with the public function's ``method=`` argument (or, from the command
line, ``--method 2=newton``).
"""

from __future__ import annotations

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from typing import Callable

from yaseer.linkages.errors import UnknownMethodError

# Packages whose import registers further methods (the alternative methods of
# ``yaseer.linkages.methods``); imported on the first look-up, if present.
EXTENSION_PACKAGES = ("yaseer.linkages.methods",)
_extensions_loaded = False

_REGISTRY: dict[str, dict[str, Callable]] = {}
_DEFAULTS: dict[str, str] = {}


def register(linkage: str, name: str, *, default: bool = False) -> Callable[[Callable], Callable]:
    """Decorator registering ``function`` as method ``name`` of ``linkage``."""

    def decorate(function: Callable) -> Callable:
        _REGISTRY.setdefault(linkage, {})[name] = function
        if default or linkage not in _DEFAULTS:
            _DEFAULTS[linkage] = name
        return function

    return decorate


def _load_extensions() -> None:
    """Import the extension packages once, so their methods are registered (importlib only then:
    a run with the default methods never needs it, and importing it costs start-up)."""
    global _extensions_loaded
    if _extensions_loaded:
        return
    _extensions_loaded = True
    import importlib

    for package in EXTENSION_PACKAGES:
        try:
            importlib.import_module(package)
        except ModuleNotFoundError as error:
            if error.name is None or not package.startswith(error.name):
                raise


def _load_linkage(linkage: str) -> None:
    """Import the module of ``linkage`` (named as it is), which registers its own methods."""
    module = f"yaseer.linkages.{linkage}"
    try:
        __import__(module)
    except ModuleNotFoundError as error:  # no such linkage: it has no methods
        if error.name != module:
            raise


def method_names(linkage: str) -> list[str]:
    """The registered method names of ``linkage``, sorted."""
    _load_linkage(linkage)
    _load_extensions()
    return sorted(_REGISTRY.get(linkage, {}))


def default_method(linkage: str) -> str:
    """The name of the method used when none is asked for."""
    _load_linkage(linkage)
    return _DEFAULTS[linkage]


def lookup(linkage: str, name: str | None = None) -> Callable:
    """The function of method ``name`` (the default when ``None``) of ``linkage``."""
    if name is not None:
        _load_extensions()
    methods = _REGISTRY.get(linkage, {})
    chosen = default_method(linkage) if name is None else name
    if chosen not in methods:
        raise UnknownMethodError(
            f"Unknown method {chosen!r} for {linkage} (known: {', '.join(method_names(linkage))})"
        )
    return methods[chosen]
