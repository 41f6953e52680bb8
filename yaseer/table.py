"""The rows a listing printed, as tables of numbers with their column names.

A *printed line* is what one screen (or printer) line showed, as the values the
machine printed on it: floats and strings, in order (``Machine.line_hooks``).
A line that prints only numbers is a *row*; rows are grouped by their length
(their *shape*), in the order each shape first appears.  A line that prints only
text is a *header* when it names as many columns as the next row has: one string
split at blanks (``PRINT "  THET   PHI"``) or one string per column
(``PRINT "THET", "PHI"``).  Lines that mix text and numbers are neither.

numpy is imported only by :func:`as_arrays`, so collecting rows stays cheap.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Sequence

Line = Sequence[object]  # floats and strings printed on one line


@dataclass
class RowGroup:
    """The rows of one shape (``width`` numbers each) and their names (None: no header)."""

    width: int
    rows: list[list[float]] = field(default_factory=list)
    names: tuple[str, ...] | None = None


def header_names(line: Line) -> tuple[str, ...] | None:
    """The column names a text-only line gives (None for a line with a number or no text)."""
    if not line or any(type(value) is not str for value in line):
        return None
    if len(line) == 1:
        names = tuple(str(line[0]).split())
    else:
        names = tuple(str(value).strip() for value in line)
    return names if names and all(names) else None


def group_rows(lines: Sequence[Line]) -> list[RowGroup]:
    """The printed rows grouped by shape, each group named by the last header before its first row."""
    groups: dict[int, RowGroup] = {}
    pending: tuple[str, ...] | None = None
    for line in lines:
        names = header_names(line)
        if names is not None:
            pending = names
            continue
        if not line or any(type(value) is not float for value in line):
            continue
        group = groups.get(len(line))
        if group is None:
            group = groups[len(line)] = RowGroup(len(line))
            if pending is not None and len(pending) == len(line):
                group.names = pending
        group.rows.append(list(line))
    return list(groups.values())


def as_arrays(groups: Sequence[RowGroup]):
    """One :class:`Rows` array for one shape, a list of them for several, an empty array for none."""
    import numpy as np

    rows_type = _rows_class()
    arrays = [rows_type.of(group.rows, group.names) for group in groups]
    if not arrays:
        return rows_type.of(np.zeros((0, 0)), None)
    return arrays[0] if len(arrays) == 1 else arrays


@functools.cache
def _rows_class():
    import numpy as np

    class _Rows(np.ndarray):
        """A 2-D float array of printed rows; ``names`` are the column names (None: unnamed)."""

        names: tuple[str, ...] | None = None

        @classmethod
        def of(cls, rows, names):
            array = np.asarray(rows, dtype=float).view(cls)
            array.names = names
            return array

        def __array_finalize__(self, parent) -> None:
            self.names = getattr(parent, "names", None)

        def column(self, name: str):
            """The column named ``name`` (a plain 1-D array)."""
            if not self.names or name not in self.names:
                raise KeyError(f"no column named {name!r}; the columns are {self.names}")
            return np.asarray(self)[:, self.names.index(name)]

    _Rows.__name__ = _Rows.__qualname__ = "Rows"
    return _Rows


def __getattr__(name: str):
    """``Rows`` (the array class) is made on first use: importing this module does not import numpy."""
    if name == "Rows":
        return _rows_class()
    raise AttributeError(name)
