"""A listing's printed lines as the series a plot draws.

The *main table* is the rows of the most common length W (all numbers; the first
column is the crank angle).  Its header, when the listing printed one (a text
line naming W columns just before), names the columns.  Other lines become
series of their own rather than being folded into the main rows:

* a *continuation*: a shorter row printed right after a row (the lower branch of
  ``listings/fortran_fourbar.bas``, printed under the columns it shares without
  repeating the crank angle).  Its values are the last columns of the table and
  its crank angle is the row before's; it is a second series in the same panels.
* any other row - a row of another length not following a row, or a line that
  starts with a text label (``BACKSOLVE THETA, OMEGA, ALPHA: -30 -15 -10`` of
  ``listings/tk_slider_crank.bas``) - goes into a table of its own (its own
  panels), one per label and length; a label naming as many quantities as the
  row has (split at commas) names its columns.

Within a series the line breaks only where the mechanism's motion did: a step
against the sweep's own direction (a second pass, or another assembly branch
started over; a sweep ``STEP -20`` steps back at every row and is one line), a
repeated crank angle, or a gap wider than 1.5 times the usual step (positions
that cannot be assembled): :func:`broken` puts a NaN there.  Only the standard
library is imported.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field
from typing import Sequence

from yaseer.table import header_names

GAP = 1.5  # a step wider than this many usual steps is a gap


@dataclass
class Series:
    """Rows of one kind, each a full row of its table (NaN where the row printed nothing)."""

    name: str
    rows: list[list[float]] = field(default_factory=list)


@dataclass
class PlotTable:
    """A set of panels: ``width`` columns (the first is the abscissa), their names, the series drawn."""

    width: int
    label: str = ""  # "" for the main table, else the text printed before the values
    names: tuple[str, ...] | None = None
    series: list[Series] = field(default_factory=list)

    def series_named(self, name: str) -> Series:
        for series in self.series:
            if series.name == name:
                return series
        self.series.append(Series(name))
        return self.series[-1]


@dataclass
class PrintedRow:
    """One printed line classified: ``kind`` is ``"row"`` (the main table), ``"continuation"``
    or ``"other"``; ``values`` is a full main-table row for the first two (NaN where the
    line printed nothing), the printed numbers otherwise; ``label`` any text before them."""

    kind: str
    values: list[float]
    label: str = ""


def classify(lines: Sequence[Sequence[object]]) -> tuple[int, tuple[str, ...] | None, list[PrintedRow]]:
    """(main width, the main table's header names or None, the printed rows in order) - see the module docstring."""
    rows = [line for line in lines if line and all(type(v) is float for v in line)]
    if not rows:
        return 0, None, []
    width = Counter(len(row) for row in rows).most_common(1)[0][0]
    names: tuple[str, ...] | None = None
    header: tuple[str, ...] | None = None
    previous: list[float] | None = None  # the last row, if the line before was a row
    printed: list[PrintedRow] = []
    for line in lines:
        found = header_names(line)
        if found is not None:
            header, previous = found, None
            continue
        numbers = [v for v in line if type(v) is float]
        label = " ".join(str(v).strip() for v in line if type(v) is str).strip()
        if not numbers or (label and type(line[0]) is not str):
            previous = None  # text after numbers, or no numbers: not a row
            continue
        if not label and len(numbers) == width:
            if names is None and header is not None and len(header) == width:
                names = header
            printed.append(PrintedRow("row", numbers))
            previous = numbers
        elif not label and len(numbers) < width and previous is not None:
            previous = [previous[0]] + [math.nan] * (width - 1 - len(numbers)) + numbers
            printed.append(PrintedRow("continuation", previous))
        else:
            printed.append(PrintedRow("other", numbers, label))
            previous = None
    return width, names, printed


def plot_tables(lines: Sequence[Sequence[object]]) -> list[PlotTable]:
    """The main table first, then one table per other kind of row (see the module docstring)."""
    width, names, printed = classify(lines)
    if not printed:
        return []
    main = PlotTable(width, names=names)
    others: dict[tuple[str, int], PlotTable] = {}
    for row in printed:
        if row.kind == "row":
            main.series_named("").rows.append(row.values)
        elif row.kind == "continuation":
            count = sum(1 for v in row.values[1:] if not math.isnan(v))
            main.series_named(f"rows of {count} after a row (the last {count} columns)").rows.append(row.values)
        else:
            key = (row.label, len(row.values))
            if key not in others:
                others[key] = PlotTable(len(row.values), row.label, _label_names(row.label, len(row.values)))
            others[key].series_named(row.label).rows.append(row.values)
    return [main, *others.values()]


def _label_names(label: str, width: int) -> tuple[str, ...] | None:
    """``"BACKSOLVE THETA, OMEGA, ALPHA:"`` with 3 values -> ``("BACKSOLVE THETA", "OMEGA", "ALPHA")``."""
    names = tuple(part.strip() for part in label.rstrip(":;= ").split(","))
    return names if len(names) == width and all(names) else None


def broken(xs: Sequence[float], ys: Sequence[float]) -> tuple[list[float], list[float]]:
    """``xs``, ``ys`` with a NaN point wherever the sweep restarts, repeats or jumps a gap, so a line breaks there.

    The sweep's direction and usual step are those of the median step (a listing may
    sweep its crank angle down as well as up); a step the other way, a zero step, or
    one longer than :data:`GAP` usual steps breaks the line.
    """
    steps = [b - a for a, b in zip(xs, xs[1:]) if b != a]
    usual = sorted(steps)[len(steps) // 2] if steps else 0.0
    out_x, out_y = [], []
    for index, (x, y) in enumerate(zip(xs, ys)):
        if index:
            along = (x - xs[index - 1]) * (1.0 if usual >= 0 else -1.0)  # the step in the sweep's direction
            if along <= 0 or (usual != 0 and along > GAP * abs(usual)):
                out_x.append(math.nan)
                out_y.append(math.nan)
        out_x.append(x)
        out_y.append(y)
    return out_x, out_y
