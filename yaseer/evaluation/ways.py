"""The three ways of running a method on a case, each timed and measured.

* ``listing``: a calling listing through the interpreter, in process, exactly
  as ``yaseer run FILE --format csv --method N=NAME`` runs it; its time per
  position is the time of ``machine.run()`` / printed rows.
* ``listing (decimal)``: the same with ``--arith decimal`` (the BASIC part in the
  FX-850P family's 12-digit decimal arithmetic; the library programs stay binary).
* ``per position``: the Python programs called once per crank angle (floats).
* ``array``: one vectorised call over the whole cycle (numpy arrays).

Each returns a :class:`Run`: seconds per position (best of ``repeat``) and the
:class:`~yaseer.evaluation.measure.Outcome` against the 50-digit reference.
"""

from __future__ import annotations

import io
import math
import time
from dataclasses import dataclass

import numpy as np

from .listings import parse_csv_rows
from .measure import Outcome, outcome_of

WAYS = ("listing", "listing (decimal)", "per position", "array")
LISTING_ARITHMETIC = {"listing": "binary", "listing (decimal)": "decimal"}  # yaseer run --arith
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


def run_listing(case, method: str, angles, repeat: int = 1, arithmetic: str = "binary") -> Run:
    """Run ``case``'s listing through the interpreter with program ``N`` using ``method``.

    In process, as ``yaseer run FILE --format csv --method N=NAME`` does it (the
    same Machine, binding and output format); the clock runs over
    ``machine.run()`` only, so parsing and compiling the listing are not counted.
    """
    if case.listing is None:
        return Run(math.nan, Outcome(math.nan, "n/a", "no listing for this case"), 0)
    from yaseer import binding
    from yaseer.basic.dialects.dialect import CASIO
    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.machine import Machine

    dialect = CASIO.with_arithmetic(arithmetic)
    text = case.listing(np.asarray(angles, float))
    best, output = math.inf, ""
    for _ in range(repeat):
        screen = io.StringIO()
        machine = Machine(screen=screen, printer=screen, output_format="csv", dialect=dialect)
        try:
            machine.load(text)
            binding.install(machine, {PROGRAM_OF[case.linkage]: method})
            start = time.perf_counter()
            machine.run()
            best = min(best, time.perf_counter() - start)
        except BasicError as error:
            return Run(math.nan, Outcome(math.nan, "exception", f"BasicError: {error}"), 0)
        machine.flush()
        output = screen.getvalue()
    rows = parse_csv_rows(output)
    width = len(case.columns)
    if not rows or any(len(row) < width for row in rows):
        return Run(math.nan, Outcome(math.nan, "exception", "the listing printed no or too few columns"), len(rows))
    printed_angles = np.array([row[0] for row in rows])
    results = {name: np.array([row[len(row) - width + k] for row in rows]) for k, name in enumerate(case.columns)}
    return Run(best / len(rows), _judge(case, printed_angles, results), len(rows))
