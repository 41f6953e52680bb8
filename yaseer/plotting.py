"""Plots of a listing's printed columns against its first column (the crank angle).

The paper shows each example's results as curves over one crank revolution (Figs. 7, 9,
10, 12 and 14). :func:`build_figure` draws the same thing from the rows a listing printed:
one panel per printed quantity, all against the first printed column.  What each of the
paper's examples prints, with units, is in :data:`PAPER_EXAMPLES`; for any other listing
the panels are labelled with the expressions of its last ``PRINT``/``LPRINT`` statement.

matplotlib is imported only inside the functions that draw, so importing this module is
cheap.
"""

from __future__ import annotations

import csv
import io
from collections import Counter
from pathlib import Path
from typing import Sequence

from yaseer.describe import DEG, PAPER_EXAMPLES, FigureSpec, Quantity, printed_expressions  # noqa: F401


def numeric_rows(csv_text: str) -> list[list[float]]:
    """The table a listing printed in ``--format csv``: its all-numeric rows.

    Rows that hold a string, and rows whose length differs from the most common length of
    the numeric rows (a header or a stray PRINT), are left out.
    """
    rows = []
    for fields in csv.reader(io.StringIO(csv_text)):
        try:
            rows.append([float(field) for field in fields])
        except ValueError:
            continue
    rows = [row for row in rows if row]
    if not rows:
        return []
    width, _ = Counter(len(row) for row in rows).most_common(1)[0]
    return [row for row in rows if len(row) == width]


def figure_spec(listing: Path, n_columns: int) -> FigureSpec:
    """Labels for the ``n_columns`` printed columns of the listing file ``listing`` (see :func:`spec_for`)."""
    return spec_for(listing.stem, listing.read_text(errors="replace"), n_columns, listing.name)


def spec_for(name: str | None, listing_text: str, n_columns: int, title: str | None = None,
             header: Sequence[str] | None = None) -> FigureSpec:
    """Labels for a listing's ``n_columns`` printed columns.

    The paper's examples (``name`` ``example1`` … ``example5``) get their known
    meanings and units; other listings their header's names, else their printed
    expressions, or "column k" where those cannot be matched to the columns.
    """
    known = PAPER_EXAMPLES.get((name or "").lower())
    if known is not None and len(known.columns) == n_columns - 1:
        return known
    names = list(header) if header is not None and len(header) == n_columns else \
        printed_expressions(listing_text)
    if len(names) != n_columns:
        names = [f"column {k + 1}" for k in range(n_columns)]
    return FigureSpec(title or name or "listing", Quantity(names[0]), tuple(Quantity(e) for e in names[1:]))


def build_figure(rows: Sequence[Sequence[float]], spec: FigureSpec):
    """A matplotlib Figure: one panel per printed quantity against the first column."""
    from matplotlib.figure import Figure  # free-standing: no pyplot, the user's backend untouched

    x = [row[0] for row in rows]
    figure = Figure(figsize=(7.5, 1.0 + 2.1 * len(spec.columns)), layout="constrained")
    axes = figure.subplots(len(spec.columns), 1, sharex=True, squeeze=False)[:, 0]
    for index, (ax, quantity) in enumerate(zip(axes, spec.columns), start=1):
        ax.plot(x, [row[index] for row in rows], marker="o", markersize=3.5, linewidth=1.3)
        ax.set_ylabel(_wrap(quantity.axis_label()), fontsize=9)
        ax.grid(True, linewidth=0.4, alpha=0.6)
    axes[-1].set_xlabel(spec.x.axis_label())
    if spec.x.unit == DEG and min(x) >= -1 and max(x) <= 361:
        axes[-1].set_xticks(range(0, 361, 60))
    figure.suptitle(spec.title, fontsize=11)
    return figure


def _wrap(label: str, width: int = 24) -> str:
    """Break a long axis label into lines of about ``width`` characters."""
    lines, current = [], ""
    for word in label.split():
        if current and len(current) + 1 + len(word) > width:
            lines.append(current)
            current = word
        else:
            current = f"{current} {word}".strip()
    lines.append(current)
    return "\n".join(lines)


def save_figure(figure, out_dir: Path, stem: str) -> list[Path]:
    """Write ``stem.png`` and ``stem.svg`` into ``out_dir`` (created if needed)."""
    out_dir.mkdir(parents=True, exist_ok=True)
    paths = [out_dir / f"{stem}.png", out_dir / f"{stem}.svg"]
    figure.savefig(paths[0], dpi=110)
    figure.savefig(paths[1])
    return paths
