"""Regular expressions compiled when first used, not when their module is imported.

A module-level ``re.compile`` runs at every start of the program, whether or not the run
ever matches that pattern: the twenty patterns of the modules a ``yaseer run`` of a cached
listing imports took about 2.6 ms to compile (CPython 3.11), a tenth of what the whole
start-up may add to ``python -c pass`` (most of them serve the scanner, PRINT USING's
number reader, the display's control codes: paths a given run seldom takes).

:class:`Pattern` stands where the compiled pattern stood (``_NAME = Pattern(r"...")``) and
offers its methods; the first use compiles it and keeps the compiled pattern's bound
methods in its slots, so every later call costs what a compiled pattern's call costs.
"""

from __future__ import annotations

_METHODS = ("match", "fullmatch", "search", "sub", "subn", "split", "findall", "finditer")


class Pattern:
    """``re.compile(pattern, flags)``, made on the first use of one of its methods
    (``match``, ``fullmatch``, ``search``, ``sub``, ``subn``, ``split``, ``findall``,
    ``finditer``) or of ``compiled``."""

    __slots__ = ("_source", "_flags") + _METHODS

    def __init__(self, pattern: str, flags: int = 0) -> None:
        self._source = pattern
        self._flags = flags

    @property
    def compiled(self):
        """The compiled pattern (:class:`re.Pattern`)."""
        import re  # the re module caches it: compiled once however often asked

        return re.compile(self._source, self._flags)

    def __getattr__(self, name: str):
        # Reached only while a method's slot is empty: compile once, fill every slot.
        if name not in _METHODS:
            raise AttributeError(name)
        compiled = self.compiled
        for method in _METHODS:
            setattr(self, method, getattr(compiled, method))
        return getattr(compiled, name)

    def __repr__(self) -> str:
        return f"Pattern({self._source!r})"
