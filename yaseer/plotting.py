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

from yaseer.describe import DEG, PAPER_EXAMPLES, FigureSpec, Quantity, column_names, printed_expressions  # noqa: F401


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
    names = column_names(None, n_columns, header if header is not None and len(header) == n_columns else None,
                         listing_text) or [f"column {k + 1}" for k in range(n_columns)]
    return FigureSpec(title or name or "listing", Quantity(names[0]), tuple(Quantity(e) for e in names[1:]))


def build_figure(rows: Sequence[Sequence[float]], spec: FigureSpec, subtitle: str = ""):
    """A matplotlib Figure: one panel per printed quantity against the first column (one series)."""
    from yaseer.series import PlotTable, Series

    return draw_tables([PlotTable(len(spec.columns) + 1, series=[Series("", [list(r) for r in rows])])], spec,
                       subtitle)


def draw_tables(tables: Sequence, spec: FigureSpec, subtitle: str = ""):
    """A matplotlib Figure of :func:`yaseer.series.plot_tables`' tables.

    The main table (the first) is labelled by ``spec``; each of its series is a
    line in every panel (a legend names them when there are several); every other
    table gets panels of its own below, labelled by its printed label and names.
    A line breaks only where the sweep restarts or jumps a gap (positions that
    cannot be assembled; :func:`yaseer.series.broken`).  ``subtitle`` (e.g. the methods chosen) goes
    under the title.
    """
    from matplotlib.figure import Figure  # free-standing: no pyplot, the user's backend untouched

    from yaseer.series import broken

    panels = [(tables[0], index, spec.x, quantity) for index, quantity in enumerate(spec.columns, start=1)]
    for table in tables[1:]:
        x, quantities = _other_quantities(table)
        panels += [(table, index, x, quantity) for index, quantity in enumerate(quantities, start=1)]
    figure = Figure(figsize=(7.5, 1.0 + 2.1 * len(panels)), layout="constrained")
    axes = figure.subplots(len(panels), 1, squeeze=False)[:, 0]
    main_axes = [ax for ax, panel in zip(axes, panels) if panel[0] is tables[0]]
    for ax in main_axes[1:]:
        ax.sharex(main_axes[0])
    for position, (ax, (table, index, x, quantity)) in enumerate(zip(axes, panels)):
        for series in table.series:
            xs, ys = broken([row[0] for row in series.rows], [row[index] for row in series.rows])
            ax.plot(xs, ys, marker="o", markersize=3.5, linewidth=1.3, label=series.name or f"rows of {table.width}")
        ax.set_ylabel(_wrap(quantity.axis_label()), fontsize=9)
        ax.grid(True, linewidth=0.4, alpha=0.6)
        last_of_table = position + 1 == len(panels) or panels[position + 1][0] is not table
        if last_of_table:
            ax.set_xlabel(x.axis_label())
        else:
            ax.tick_params(labelbottom=False)
        if table is tables[0] and position == 0 and len(table.series) > 1:
            ax.legend(fontsize=7, loc="best")
    xs = [row[0] for series in tables[0].series for row in series.rows]
    if xs and spec.x.unit == DEG and min(xs) >= -1 and max(xs) <= 361:
        main_axes[-1].set_xticks(range(0, 361, 60))
    figure.suptitle(spec.title + (f"\n{subtitle}" if subtitle else ""), fontsize=11)
    return figure


def _other_quantities(table) -> tuple[Quantity, list[Quantity]]:
    """The abscissa and panel quantities of a table other than the main one (its label and names)."""
    names = list(table.names) if table.names else [f"column {k + 1}" for k in range(table.width)]
    prefix = f"{table.label}: " if table.label and not table.names else ""
    return Quantity(prefix + names[0]), [Quantity(prefix + name) for name in names[1:]]


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
    from yaseer.whole_files import staged

    out_dir.mkdir(parents=True, exist_ok=True)
    paths = [out_dir / f"{stem}.png", out_dir / f"{stem}.svg"]
    with staged() as place:  # both appear, or neither (Ctrl-C while drawing the SVG)
        figure.savefig(place(paths[0]), dpi=110)
        figure.savefig(place(paths[1]))
    return paths
