"""Many positions in bounded memory: a vectorised call per chunk of positions.

One array call over N positions holds a few dozen temporary arrays of N numbers
(the four-bar's forces: about 1 kB a position), so 10^7 positions at once would
need about 10 GB.  Calling the same function on the consecutive chunks of
at most ``chunk`` positions that :func:`angle_chunks` generates one at a time
keeps the working memory that of one chunk whatever N is, and the time linear
in N::

    for angles in angle_chunks(0.0, 360.0, 10**7):
        torque = fourbar(..., angles, ...).forces(...).value   # reduce, store or write out
"""

from __future__ import annotations

from typing import Iterator

CHUNK = 1 << 14  # positions per call: large enough that numpy's per-call cost is small, small enough for cache


def angle_chunks(start_deg: float, stop_deg: float, count: int, chunk: int = CHUNK) -> Iterator["numpy.ndarray"]:
    """The angles of ``numpy.linspace(start_deg, stop_deg, count)``, chunk by chunk
    (the same values, never all held at once)."""
    import numpy as np

    step = (stop_deg - start_deg) / (count - 1) if count > 1 else 0.0
    for first in range(0, count, chunk):
        index = np.arange(first, min(first + chunk, count), dtype=float)
        angles = start_deg + index * step
        if first + chunk >= count and count > 1:
            angles[-1] = stop_deg  # as linspace: the end point exactly
        yield angles
