"""The one module that maps ``GOSUB PROG n`` to the Python library programs.

(Stub until the programs land: it binds nothing, so ``GOSUB PROG n`` is the
error ``Undefined program area n``.)
"""

from __future__ import annotations


def install(machine, methods: dict[int, str] | None = None) -> None:
    """Bind the library programs into ``machine``'s program areas 1, 2, 3, 5."""
