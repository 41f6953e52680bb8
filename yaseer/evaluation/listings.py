"""Calling listings for the interpreter way of running, and how their output is read.

The paper's examples run from the corrected listings (``listings/exampleN.bas``)
with only the STEP of their ``FOR QQ`` loop changed; the seeds' linkages from a
small generated listing (:func:`yaseer.evaluation.cases._loop_listing`).  Every
listing prints the crank angle first, so that the reference is taken exactly at
the angles the interpreter reached (a FOR loop accumulates its steps).
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

LISTINGS = Path(__file__).resolve().parents[2] / "listings"
_FOR = re.compile(r"(FOR\s+QQ\s*=\s*)([-+]?[\d.]+)(\s*TO\s*)([-+]?[\d.]+)(\s*STEP\s*)(-\s*)?([\d.]+)", re.I)


def for_loop_angles(start: float, stop: float, step: float) -> np.ndarray:
    """The values a BASIC ``FOR QQ = start TO stop STEP step`` loop takes (binary floats, accumulated)."""
    values, value = [], float(start)
    while (value <= stop) if step > 0 else (value >= stop):
        values.append(value)
        value += step
    return np.array(values)


def example_loop(number: int) -> tuple[float, float, float]:
    """(start, stop, step) of the FOR QQ loop of ``listings/exampleN.bas``."""
    match = _FOR.search(example_text(number))
    step = float(match.group(7)) * (-1 if match.group(6) else 1)
    return float(match.group(2)), float(match.group(4)), step


def example_text(number: int) -> str:
    return (LISTINGS / f"example{number}.bas").read_text()


def paper_listing_over(number: int, step: float) -> str:
    """``listings/exampleN.bas`` with the magnitude of its FOR QQ step replaced by |step|."""
    def replace(match):
        return f"{match.group(1)}{match.group(2)}{match.group(3)}{match.group(4)}{match.group(5)}{match.group(6) or ''}{abs(step):g}"
    return _FOR.sub(replace, example_text(number), count=1)


def parse_csv_rows(text: str) -> list[list[float]]:
    """The rows ``yaseer run --format csv`` printed, as floats (non-numeric rows skipped)."""
    rows = []
    for line in text.splitlines():
        cells = [cell.strip() for cell in line.split(",")]
        try:
            rows.append([float(cell) for cell in cells if cell])
        except ValueError:
            continue
    return [row for row in rows if row]
