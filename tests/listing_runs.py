"""Running listings through ``yaseer run`` for the listing tests (a helper, not a test module)."""

from __future__ import annotations

import functools
import subprocess
import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
GOLDEN = ROOT / "tests" / "golden"
EXAMPLES = (1, 2, 3, 4, 5)


@functools.lru_cache(maxsize=None)
def run_yaseer(*args: str) -> subprocess.CompletedProcess:
    """``python -m yaseer run ARGS`` from the repository root (cached: each run happens once)."""
    return subprocess.run([sys.executable, "-m", "yaseer", "run", *args], cwd=ROOT,
                          capture_output=True, text=True, timeout=120, check=False)


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
