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
from dataclasses import dataclass
from pathlib import Path
from typing import Sequence


@dataclass(frozen=True)
class Quantity:
    """A printed quantity: what it means and its unit (empty when unknown)."""

    meaning: str
    unit: str = ""

    def axis_label(self) -> str:
        return f"{self.meaning} ({self.unit})" if self.unit else self.meaning


@dataclass(frozen=True)
class FigureSpec:
    """Title, the abscissa (first printed column) and the other printed columns."""

    title: str
    x: Quantity
    columns: tuple[Quantity, ...]


DEG, RAD_S, RAD_S2 = "deg", "rad/s", "rad/s²"

# What the paper's examples print (the contract's last table), with the units each
# listing works in (Example 1 and 4: mm; Example 3: cm; Examples 2 and 5: m, kg, s).
PAPER_EXAMPLES: dict[str, FigureSpec] = {
    "example1": FigureSpec(
        "Example 1: kinematics of piston D (paper Fig. 7)",
        Quantity("crank angle QQ", DEG),
        (
            Quantity("position of piston D, Y(2)", "mm"),
            Quantity("velocity of piston D, V(4)", "mm/s"),
            Quantity("acceleration of piston D, A(36)", "mm/s²"),
        ),
    ),
    "example2": FigureSpec(
        "Example 2: churning mechanism, torque and reactions (paper Fig. 9)",
        Quantity("crank angle QQ", DEG),
        (
            Quantity("input torque on AoA, U(1)", "N·m"),
            Quantity("normal reaction at B, N(1)", "N"),
            Quantity("bearing reaction at Ao, |F(3), F(4)|", "N"),
        ),
    ),
    "example3": FigureSpec(
        "Example 3: indexing mechanism, output member CCoD (paper Fig. 10)",
        Quantity("crank angle T(2)", DEG),
        (
            Quantity("inclination of CCoD (Co→C), T(9)", DEG),
            Quantity("angular velocity of CCoD, W(4)", RAD_S),
            Quantity("angular acceleration of CCoD, A(4)", RAD_S2),
            Quantity("x of point D, X(7)", "cm"),
        ),
    ),
    "example4": FigureSpec(
        "Example 4: film transport, member DE and point E (paper Fig. 12)",
        Quantity("crank angle QQ", DEG),
        (
            Quantity("angular velocity of DE, W(6)", RAD_S),
            Quantity("angular acceleration of DE, A(6)", RAD_S2),
            Quantity("horizontal velocity of E, V(7)", "mm/s"),
            Quantity("horizontal acceleration of E, A(39)", "mm/s²"),
        ),
    ),
    "example5": FigureSpec(
        "Example 5: jaw crusher, crank torque and main reactions (paper Fig. 14)",
        Quantity("crank angle QQ", DEG),
        (
            Quantity("crank torque, U(2)", "N·m"),
            Quantity("bearing reaction at Bo, |F(27), F(28)|", "N"),
            Quantity("bearing reaction at Ao, |F(21), F(22)|", "N"),
        ),
    ),
}


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


def printed_expressions(listing_text: str) -> list[str]:
    """The expressions of the last ``PRINT``/``LPRINT`` statement of a listing, as written.

    ``60 PRINT USING "###.##"; QQ; Y(2): NEXT QQ`` gives ``["QQ", "Y(2)"]``.  Only what
    is needed for labels: the statement ends at a ``:`` outside strings and parentheses,
    and the items are split at ``;`` and ``,`` outside them.
    """
    last: list[str] = []
    for line in listing_text.splitlines():
        for statement in _split_top_level(line, ":"):
            items = _print_items(statement)
            if items is not None:
                last = items
    return last


def _print_items(statement: str) -> list[str] | None:
    """The items of a PRINT/LPRINT statement (after any USING format), else None."""
    words = statement.strip().split(None, 1)
    if words and words[0].isdigit():  # the line number before the first statement
        words = words[1].split(None, 1) if len(words) > 1 else []
    if not words or words[0].upper() not in ("PRINT", "LPRINT"):
        return None
    rest = words[1] if len(words) > 1 else ""
    if rest.upper().startswith("USING"):
        parts = _split_top_level(rest, ";")
        rest = ";".join(parts[1:])
    items = [item.strip() for part in _split_top_level(rest, ";") for item in _split_top_level(part, ",")]
    return [item for item in items if item]


def _split_top_level(text: str, separator: str) -> list[str]:
    """Split ``text`` at ``separator`` where it is outside quotes and parentheses."""
    parts, depth, quoted, start = [], 0, False, 0
    for index, char in enumerate(text):
        if char == '"':
            quoted = not quoted
        elif not quoted and char == "(":
            depth += 1
        elif not quoted and char == ")":
            depth -= 1
        elif not quoted and depth == 0 and char == separator:
            parts.append(text[start:index])
            start = index + 1
    parts.append(text[start:])
    return parts


def figure_spec(listing: Path, n_columns: int) -> FigureSpec:
    """Labels for a listing's ``n_columns`` printed columns.

    The paper's examples (files named ``example1.bas`` … ``example5.bas``, corrected or as
    printed) get their known meanings and units; other listings get their printed
    expressions, or "column k" where those cannot be matched to the columns.
    """
    known = PAPER_EXAMPLES.get(listing.stem.lower())
    if known is not None and len(known.columns) == n_columns - 1:
        return known
    expressions = printed_expressions(listing.read_text(errors="replace"))
    if len(expressions) != n_columns:
        expressions = [f"column {k + 1}" for k in range(n_columns)]
    return FigureSpec(listing.name, Quantity(expressions[0]), tuple(Quantity(e) for e in expressions[1:]))


def build_figure(rows: Sequence[Sequence[float]], spec: FigureSpec):
    """A matplotlib Figure: one panel per printed quantity against the first column."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

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
