"""The three ways of running a method on a case, each timed and measured.

* ``listing``: a calling listing through the interpreter (``yaseer run FILE
  --format csv --method N=NAME`` in a subprocess).  Its time per position is
  (run time - the run time of an empty listing) / positions, both measured in
  the same bench run, so the interpreter's start-up is not counted.
* ``per position``: the Python programs called once per crank angle (floats).
* ``array``: one vectorised call over the whole cycle (numpy arrays).

Each returns a :class:`Run`: seconds per position (best of ``repeat``) and the
:class:`~yaseer.evaluation.measure.Outcome` against the 50-digit reference.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass

import numpy as np

from .listings import parse_csv_rows
from .measure import Outcome, outcome_of

WAYS = ("listing", "per position", "array")
PROGRAM_OF = {"slider_crank": 1, "fourbar": 2, "inverted_slider_crank": 3, "virtual_link": 5}


@dataclass(frozen=True)
class Run:
    """One timed run: seconds per position (NaN when it did not run) and its outcome."""

    seconds_per_position: float
    outcome: Outcome
    positions: int


def run_python(case, method: str, angles, way: str, options=None, repeat: int = 3) -> Run:
    """Run ``method`` (of ``case.linkage``) per position or as one array call."""
    options = options or {}
    methods = {case.linkage: method}
    angles = np.asarray(angles, float)
    best, results = math.inf, None
    try:
        for _ in range(repeat):
            start = time.perf_counter()
            if way == "array":
                results = case.compute(methods, angles, options)
            else:
                rows = [case.compute(methods, float(a), options) for a in angles]
                results = {name: np.array([float(row[name]) for row in rows]) for name in rows[0]}
            best = min(best, time.perf_counter() - start)
    except Exception as error:  # noqa: BLE001 - every failure is a finding to report
        return Run(math.nan, Outcome(math.nan, "exception", f"{type(error).__name__}: {error}"), len(angles))
    return Run(best / len(angles), _judge(case, angles, results), len(angles))


def _judge(case, angles, results) -> Outcome:
    other = None if case.other_branch is None else (lambda r: case.other_branch(angles, r))
    return outcome_of(case.reference(angles), {k: np.asarray(v, float) for k, v in results.items()}, other)


def yaseer_command() -> list[str]:
    return [sys.executable, "-m", "yaseer"]


def _run_listing_text(text: str, method: str | None, program: int, timeout: float = 300.0):
    """Run a listing in a subprocess; (seconds, completed process)."""
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "bench.bas")
        with open(path, "w") as handle:
            handle.write(text)
        command = yaseer_command() + ["run", path, "--format", "csv"]
        if method is not None:
            command += ["--method", f"{program}={method}"]
        start = time.perf_counter()
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        return time.perf_counter() - start, done


def startup_seconds(repeat: int = 3) -> float:
    """The run time of an empty listing (interpreter start-up), best of ``repeat``."""
    return min(_run_listing_text("10 END\n", None, 1)[0] for _ in range(repeat))


def run_listing(case, method: str, angles, startup: float, repeat: int = 1) -> Run:
    """Run ``case``'s listing through the interpreter with ``--method N=method``."""
    if case.listing is None:
        return Run(math.nan, Outcome(math.nan, "n/a", "no listing for this case"), 0)
    text = case.listing(np.asarray(angles, float))
    best, done = math.inf, None
    for _ in range(repeat):
        seconds, done = _run_listing_text(text, method, PROGRAM_OF[case.linkage])
        best = min(best, seconds)
    rows = parse_csv_rows(done.stdout)
    if done.returncode != 0 or not rows:
        message = (done.stderr.strip() or done.stdout.strip() or f"exit status {done.returncode}").splitlines()
        return Run(math.nan, Outcome(math.nan, "exception", message[-1] if message else "no output"), 0)
    printed_angles = np.array([row[0] for row in rows])
    width = len(case.columns)
    values = [row[-width:] for row in rows]
    if any(len(row) < width for row in values):
        return Run(math.nan, Outcome(math.nan, "exception", "the listing printed fewer columns"), len(rows))
    results = {name: np.array([row[k] for row in values]) for k, name in enumerate(case.columns)}
    per_position = (best - startup) / len(rows) if best > startup else math.nan  # too short to time
    return Run(per_position, _judge(case, printed_angles, results), len(rows))
