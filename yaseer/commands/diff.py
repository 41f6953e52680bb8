"""``yaseer diff FILE TABLE [--tol X]``: a listing's rows beside a table typed from a paper.

FILE is a BASIC listing, run through :func:`yaseer.run` with the run options of
``yaseer run``; its printed rows are read as :mod:`yaseer.series` reads them for a
plot: the rows of the most common length are the table, a text line naming its
columns just before is its header, a shorter row printed right after a row (the
lower branch of ``listings/fortran_fourbar.bas``) fills the *last* columns and
takes the crank angle of the row before, and other lines (a labelled row) are
not compared.  A FILE ending in ``.csv`` is taken as a listing's ``--format csv``
output already (so two tables can be compared).  TABLE is typed from a paper, either

* CSV (a line with a comma makes the file CSV): an empty field is a blank cell, or
* whitespace-separated columns as printed: a header line of names, then rows.
  A row with a cell for every name is read in order; in a shorter row each cell
  goes under the header name whose right edge is nearest to its own (printed
  numbers are right-aligned), so a blank cell is just missing text.
  ``********`` (a Fortran/BASIC field overflow) is a cell of its own, even when
  it touches the number before it.  Without a header, a short row lacks its
  leading cells (like the Fortran seed's ``8X`` continuation rows).

``#`` starts a comment line.  A row whose first cell is blank continues the
previous row's key.  Rows are matched on the first column: the n-th table row
with key k goes with the n-th program row with key k.  Every compared cell that
differs by more than the tolerance is marked; blank cells are not compared; an
overflow cell agrees when the program's value, printed with that column's
decimals, would not fit in as many characters as there are asterisks.  A program
value with no table cell to compare with (a blank cell, or a column the table
does not have) is shown in parentheses and counted as not compared.  The
default tolerance of a cell is half a unit of its last printed digit; ``--tol``
gives one absolute tolerance instead.  When ``yaseer/data/errata.csv`` knows why
a differing column of TABLE differs, a ``why COLUMN:`` line says so.  The last
line is the verdict; the exit status is 0 when every compared cell agrees, 1
when cells differ or rows are missing, and 1 with one error line when the
listing or the table cannot be read.
"""

from __future__ import annotations

import csv
import io
import re
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Sequence

ERRATA = Path(__file__).resolve().parent.parent / "data" / "errata.csv"  # why a paper's column differs
OVERFLOW_CHAR = "*"
_TOKEN = re.compile(r"\*+|[^\s*]+")
_NUMBER = re.compile(r"^[-+]?(\d+\.?\d*|\.\d+)([eEdD][-+]?\d+)?$")


class TableError(ValueError):
    """A table that cannot be read (the message names the file and line)."""


@dataclass
class Cell:
    """One table cell: ``value`` (None if blank or overflow), the ``text`` as
    typed, its ``decimals`` (digits after the point) and whether it is an
    overflow (``********``)."""

    text: str
    value: float | None = None
    decimals: int = 0
    overflow: bool = False

    @property
    def blank(self) -> bool:
        return not self.text


BLANK = Cell("")


def parse_cell(text: str) -> Cell:
    """Read one cell's text (``-10.00``, ``.00``, ``********`` or empty)."""
    text = text.strip()
    if not text:
        return BLANK
    if set(text) == {OVERFLOW_CHAR}:
        return Cell(text, overflow=True)
    if not _NUMBER.match(text):
        return Cell(text)
    mantissa = re.split(r"[eEdD]", text)[0]
    decimals = len(mantissa.split(".")[1]) if "." in mantissa else 0
    return Cell(text, float(re.sub(r"[dD]", "e", text)), decimals)


@dataclass
class Table:
    """A parsed table: optional column ``names`` and ``rows`` of cells (keys filled in)."""

    names: list[str] = field(default_factory=list)
    rows: list[list[Cell]] = field(default_factory=list)
    line_numbers: list[int] = field(default_factory=list)


def _is_header(cells: list[Cell]) -> bool:
    return any(c.text for c in cells) and all(c.value is None and not c.overflow for c in cells if c.text)


def _tokens(line: str) -> list[tuple[int, str]]:
    """(right edge, text) of each token of a printed line."""
    return [(m.end(), m.group()) for m in _TOKEN.finditer(line)]


def _place_by_edges(tokens: list[tuple[int, str]], edges: list[int]) -> list[Cell]:
    cells = [BLANK] * len(edges)
    for end, text in tokens:
        column = min(range(len(edges)), key=lambda j: abs(edges[j] - end))
        if cells[column].text:
            raise TableError(f"two cells under column {column + 1}")
        cells[column] = parse_cell(text)
    return cells


def _rows_of_printed(lines: list[tuple[int, str]]) -> Table:
    table = Table()
    edges: list[int] = []
    for number, line in lines:
        tokens = _tokens(line)
        cells = [parse_cell(text) for _, text in tokens]
        if not table.rows and not table.names and _is_header(cells):
            table.names = [c.text for c in cells]
            edges = [end for end, _ in tokens]
            continue
        if edges and len(tokens) > len(edges):
            raise TableError(f"line {number}: {len(tokens)} cells for {len(edges)} columns")
        if edges and len(tokens) < len(edges):  # a full row is read in order, a short one by position
            try:
                cells = _place_by_edges(tokens, edges)
            except TableError as exc:
                raise TableError(f"line {number}: {exc}") from None
        table.rows.append(cells)
        table.line_numbers.append(number)
    _left_pad(table)
    return table


def _rows_of_csv(lines: list[tuple[int, str]]) -> Table:
    table = Table()
    for number, line in lines:
        cells = [parse_cell(text) for text in next(csv.reader([line]))]
        if not table.rows and not table.names and _is_header(cells):
            table.names = [c.text for c in cells]
            continue
        if _is_header(cells):  # a later PRINT of titles: not a data row
            continue
        table.rows.append(cells)
        table.line_numbers.append(number)
    _left_pad(table)
    return table


def _left_pad(table: Table) -> None:
    """Give short rows their missing leading cells, then carry keys down."""
    width = max([len(table.names)] + [len(r) for r in table.rows])
    for index, row in enumerate(table.rows):
        table.rows[index] = [BLANK] * (width - len(row)) + row
    previous_key = BLANK
    for row in table.rows:
        if row[0].blank:
            row[0] = previous_key
        previous_key = row[0]


def parse_table(text: str) -> Table:
    """Parse a typed table (CSV or printed columns); see the module docstring."""
    lines = [(n, line.rstrip("\n")) for n, line in enumerate(text.splitlines(), 1)
             if line.strip() and not line.lstrip().startswith("#")]
    if any("," in line for _, line in lines):
        return _rows_of_csv(lines)
    return _rows_of_printed(lines)


# ---------------------------------------------------------------- comparison


@dataclass
class Verdict:
    names: list[str] = field(default_factory=list)  # the column names shown (table's, else the listing's)

    """The outcome of a comparison, with the rendered report ``lines``."""

    matched_rows: int = 0
    compared_cells: int = 0
    differing_cells: int = 0
    uncompared_cells: int = 0  # program values with no table cell (shown in parentheses)
    differing_columns: list[int] = field(default_factory=list)  # in order of first difference
    missing_rows: int = 0
    extra_rows: int = 0
    lines: list[str] = field(default_factory=list)

    @property
    def agrees(self) -> bool:
        return self.differing_cells == 0 and self.missing_rows == 0 and self.compared_cells > 0

    def summary(self, tol_text: str) -> str:
        word = "AGREE" if self.agrees else "DIFFER"
        return (f"{word}: {self.matched_rows} rows matched, {self.differing_cells} of "
                f"{self.compared_cells} compared cells differ beyond {tol_text}; "
                f"{self.uncompared_cells} program values not compared (in parentheses: no table cell); "
                f"{self.missing_rows} table rows missing from the program, "
                f"{self.extra_rows} program rows not in the table")


def cell_tolerance(cell: Cell, tol: float | None) -> float:
    """``tol`` if given, else half a unit of the cell's last printed digit."""
    if tol is not None:
        return tol
    return 0.5 * 10.0 ** (-cell.decimals) * (1 + 1e-9)


def column_decimals(table: Table, column: int) -> int:
    """The most decimals any numeric cell of ``column`` shows (2 if none)."""
    found = [row[column].decimals for row in table.rows if len(row) > column and row[column].value is not None]
    return max(found) if found else 2


def cell_agrees(printed: Cell, value: float, tol: float | None, decimals: int) -> bool:
    """Does the program's ``value`` agree with the ``printed`` cell?"""
    if printed.overflow:
        return len(f"{value:.{decimals}f}") > len(printed.text)
    return abs(value - printed.value) <= cell_tolerance(printed, tol)


def _keys_match(a: float, b: float, tol: float | None, key_cell: Cell) -> bool:
    return abs(a - b) <= max(cell_tolerance(key_cell, tol), 1e-9)


def _pair_rows(program: list[list[float]], table: Table, tol: float | None):
    """Yield (table row, program row or None); leftover program rows come last with None table row."""
    used = [False] * len(program)
    for row in table.rows:
        key = row[0]
        partner = None
        if key.value is not None:
            for index, candidate in enumerate(program):
                if not used[index] and candidate and _keys_match(candidate[0], key.value, tol, key):
                    used[index] = True
                    partner = candidate
                    break
        yield row, partner
    for index, candidate in enumerate(program):
        if not used[index]:
            yield None, candidate


def _fmt(value: float | None, decimals: int) -> str:
    return "" if value is None else f"{value:.{decimals}f}"


def compare(program: list[list[float]], table: Table, tol: float | None = None, show_extra: bool = False,
            program_names: Sequence[str] | None = None) -> Verdict:
    """Set the program's rows beside the table's; mark each cell beyond tolerance.

    A differing cell is shown as ``program|printed!``, a program value with no
    table cell as ``(value)``; program rows the table does not have are counted,
    and listed only with ``show_extra``.  The header is the table's names, else
    ``program_names`` (the listing's printed header).  A NaN program value is a
    cell the program did not print.
    """
    verdict = Verdict()
    width = max([len(table.names)] + [len(r) for r in table.rows] + [len(r) for r in program] + [1])
    decimals = [column_decimals(table, j) for j in range(width)]
    names = list(table.names or program_names or [])
    if names and len(names) < width and len(names) == len(table.names):
        names += [f"({program_names[j]})" if program_names and j < len(program_names) else "(no column)"
                  for j in range(len(names), width)]
    verdict.names = names
    rendered: list[list[str]] = [names + [""] * (width - len(names))] if names else []
    for printed, values in _pair_rows(program, table, tol):
        if printed is None:
            verdict.extra_rows += 1
            if show_extra:
                rendered.append([_fmt(v, decimals[j]) for j, v in enumerate(values)] + ["(extra)"])
            continue
        if values is None:
            verdict.missing_rows += 1
            rendered.append([c.text for c in printed] + ["(missing)"])
            continue
        verdict.matched_rows += 1
        rendered.append(_render_row(printed, values, tol, decimals, verdict))
    verdict.lines = _align(rendered)
    return verdict


def _render_row(printed: list[Cell], values: list[float], tol, decimals, verdict: Verdict) -> list[str]:
    texts = []
    for j in range(max(len(printed), len(values))):
        cell = printed[j] if j < len(printed) else BLANK
        value = values[j] if j < len(values) and values[j] == values[j] else None  # NaN: not printed
        shown = _fmt(value, decimals[j])
        if cell.blank or (cell.value is None and not cell.overflow):
            if j and value is not None:  # the key column is what the rows were matched on
                verdict.uncompared_cells += 1
                shown = f"({shown})"
            texts.append(shown)
            continue
        verdict.compared_cells += 1
        if value is not None and cell_agrees(cell, value, tol, decimals[j]):
            texts.append(shown)
        else:
            verdict.differing_cells += 1
            if j not in verdict.differing_columns:
                verdict.differing_columns.append(j)
            texts.append(f"{shown or '(none)'}|{cell.text}!")
    return texts


def _align(rows: list[list[str]]) -> list[str]:
    width = max((len(r) for r in rows), default=0)
    sizes = [max((len(r[j]) for r in rows if j < len(r)), default=0) for j in range(width)]
    return ["  ".join(text.rjust(sizes[j]) for j, text in enumerate(row)).rstrip() for row in rows]


# ---------------------------------------------------------------- running


def program_rows(path: Path, run_arguments: dict | None = None) -> tuple[tuple[str, ...] | None, list[list[float]]]:
    """(the listing's header names or None, its rows in print order) - see the module docstring.

    ``run_arguments`` are :func:`yaseer.run`'s (``method``, ``prog`` ...).
    Raises :class:`TableError` with the run's own error line if it fails.
    """
    if path.suffix.lower() == ".csv":
        return None, csv_number_rows(read_table_text(path))
    from yaseer.api import run
    from yaseer.series import classify

    from yaseer.basic.errors import FILE_NOT_FOUND

    result = run(path, **(run_arguments or {}))
    if result.error is not None:  # the listing's own error line, naming the listing unless it does already
        named = getattr(result.exception, "code", None) == FILE_NOT_FOUND
        raise TableError(result.error if named else f"{path}: {result.error}") from result.exception
    _, names, printed = classify(result.lines)
    return names, [row.values for row in printed if row.kind != "other"]


def read_table_text(path: Path) -> str:
    """The text of a typed table: UTF-8, or Latin-1 if it is not UTF-8; binary data is a TableError."""
    data = path.read_bytes()
    if b"\0" in data:
        raise TableError("not a text table (it holds binary data)")
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("latin-1")


def csv_number_rows(text: str) -> list[list[float]]:
    """Rows of numbers from CSV text, read like a table: rows holding any text
    (titles) are skipped, a short row lacks its leading cells and takes the key of
    the row before (a listing printing a lower branch without repeating the angle)."""
    table = Table()
    for fields in csv.reader(io.StringIO(text)):
        cells = [parse_cell(f) for f in fields]
        if cells and all(c.value is not None for c in cells):
            table.rows.append(cells)
    _left_pad(table)
    return [[c.value for c in row] for row in table.rows]


def add_arguments(parser) -> None:
    from yaseer.commands.parsers import add_run_options

    parser.epilog = ("Exit status: 0 every compared cell agrees, 1 cells differ or rows are missing (the last line "
                     "says which) or an error (one line on standard error, nothing on standard output), "
                     "2 a wrong command line, 130 Ctrl-C.  Nothing is written to files.")
    parser.add_argument("file", type=Path, help="BASIC listing to run (or a .csv of its rows)")
    parser.add_argument("table", type=Path, help="table typed from a paper (CSV or printed columns; UTF-8 or Latin-1)")
    parser.add_argument("--tol", type=_tolerance, default=None,
                        help="absolute tolerance (default: half a unit of each printed cell's last digit)")
    parser.add_argument("--extra", action="store_true", help="also list the program rows the table does not have")
    add_run_options(parser)


def _tolerance(text: str) -> float:
    import argparse

    try:
        value = float(text)
    except ValueError:
        value = -1.0
    if not value >= 0:
        raise argparse.ArgumentTypeError(f"a non-negative number, not {text!r}")
    return value


def main(args) -> int:
    from yaseer.commands.options import CommandError, run_settings
    from yaseer.commands.run import raise_if_interrupted

    try:
        table = parse_table(read_table_text(args.table))
    except TableError as exc:
        raise CommandError(f"bad table {args.table}: {exc}") from None
    settings = run_settings(args)
    try:
        names, rows = program_rows(args.file, settings.run_arguments())
    except TableError as exc:
        raise_if_interrupted(exc.__cause__)
        raise CommandError(str(exc)) from None
    finally:
        settings.close()
    verdict = compare(rows, table, args.tol, args.extra, names)
    for line in verdict.lines:
        print(line)
    for line in errata_lines(args.table, verdict):
        print(line)
    tol_text = f"tol {args.tol:g}" if args.tol is not None else "half a printed digit"
    print(verdict.summary(tol_text))
    return 0 if verdict.agrees else 1


def errata_lines(table_path: Path, verdict: Verdict) -> list[str]:
    """``why COLUMN: reason`` for each differing column that ``yaseer/data/errata.csv`` explains for this table."""
    known = {}
    with open(ERRATA, encoding="utf-8") as handle:
        for entry in csv.DictReader(line for line in handle if not line.startswith("#")):
            known[(entry["table"], entry["column"])] = entry["reason"]
    lines = []
    for column in verdict.differing_columns:
        name = verdict.names[column] if column < len(verdict.names) else f"column {column + 1}"
        reason = known.get((Path(table_path).name, name))
        if reason:
            lines.append(f"why {name}: {reason}")
    return lines
