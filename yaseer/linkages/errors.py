"""Exceptions of the linkage numerics (they know nothing of BASIC).

The binding (``yaseer.binding``) turns each into a BASIC run-time error naming
the program; nothing here ever returns NaN or infinity silently instead.
"""

from __future__ import annotations


class LinkageError(ArithmeticError):
    """Base class: the numerics cannot give a finite, unique answer."""


class AssemblyError(LinkageError):
    """The position cannot be assembled: a square root of a negative number or a
    zero-length link (rod, coupler, follower, virtual link)."""


class LockedError(LinkageError):
    """The position assembles but its rates are not unique (toggle or branch point)."""


class SingularForceError(LinkageError):
    """The force system cannot be solved: the selected unknown load cannot balance it."""


class UnknownLoadError(LinkageError, ValueError):
    """The selected unknown is not one of the linkage's loads."""


class MethodDivisionByZero(LinkageError, ZeroDivisionError):
    """A method as printed divides by zero (the paper's equations at 0, 90, 180, 270 deg)."""


class UnknownMethodError(LinkageError, KeyError):
    """No method of that name is registered for the linkage."""

    def __str__(self) -> str:  # KeyError would quote the message
        return str(self.args[0]) if self.args else ""
