"""Running listings through ``yaseer run`` for the listing tests (a helper, not a test module)."""

from __future__ import annotations

import contextlib
import functools
import io
import os
from pathlib import Path
from typing import NamedTuple

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
GOLDEN = ROOT / "tests" / "golden"
EXAMPLES = (1, 2, 3, 4, 5)


class Run(NamedTuple):
    """What ``yaseer run`` returned and wrote."""

    returncode: int
    stdout: str
    stderr: str


@functools.lru_cache(maxsize=None)
def run_yaseer(*args: str) -> Run:
    """``yaseer run ARGS`` from the repository root, in this process (cached: each run once).

    The command line itself (``python -m yaseer ...`` in a child process) is exercised by
    the plot tests and tests/test_reference_examples.py; in-process keeps these tests fast.
    """
    from yaseer.cli import main

    stdout, stderr = io.StringIO(), io.StringIO()
    previous = os.getcwd()
    os.chdir(ROOT)
    try:
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
            returncode = main(["run", *args])
    finally:
        os.chdir(previous)
    return Run(returncode, stdout.getvalue(), stderr.getvalue())


def csv_table(text: str) -> np.ndarray:
    """The rows of ``--format csv`` output as a float array."""
    return np.array([[float(field) for field in line.split(",")] for line in text.strip().splitlines()])


def run_csv(listing: str, *options: str) -> np.ndarray:
    """Run ``listing`` in csv form; fail the test with its error line if it does not finish."""
    result = run_yaseer(listing, "--format", "csv", *options)
    assert result.returncode == 0, result.stderr
    return csv_table(result.stdout)


def golden_csv(n: int) -> np.ndarray:
    return csv_table((GOLDEN / f"example{n}.csv").read_text())


def column_scale(table: np.ndarray) -> np.ndarray:
    """Each column's largest magnitude: the yardstick for differences within that column."""
    return np.abs(table).max(axis=0)


def screen_numbers(listing: str) -> list[list[float]]:
    """The numbers on each all-numeric line of ``yaseer run LISTING``'s faithful text output."""
    rows = []
    for line in run_yaseer(str(listing)).stdout.splitlines():
        try:
            rows.append([float(word) for word in line.split()])
        except ValueError:
            continue
    return rows
