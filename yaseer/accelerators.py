"""The switch of the optional C accelerators (setup.py builds them where a compiler is found):
gw's transcendental routines, ``--arith decimal``'s operations and the library programs'
recorded paths each have one, and each is left unused when :data:`PURE_PYTHON` is set."""

from __future__ import annotations

import os

PURE_PYTHON = "YASEER_PURE_PYTHON"
"""The environment variable that, set to anything but ``""`` or ``0``, keeps the Python functions."""


def pure_python() -> bool:
    """Is :data:`PURE_PYTHON` set (to anything but ``""`` or ``0``), so that the optional C
    accelerators are left unused?"""
    return os.environ.get(PURE_PYTHON, "") not in ("", "0")
