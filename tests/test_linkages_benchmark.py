"""The benchmark script runs (a tiny cycle; no timing is asserted) and its array
calls give the same numbers as its scalar calls."""

from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np

SCRIPT = Path(__file__).parent / "benchmarks" / "linkage_speed.py"


def load_script():
    spec = importlib.util.spec_from_file_location("linkage_speed", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_benchmark_script_runs(capsys):
    assert load_script().main(["--positions", "7", "--repeat", "1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    table = 2 + len(load_script().CASES)
    assert len(lines) > table
    assert all("pylinkage" in line for line in lines[table:])  # the reference, or why it is skipped


def test_array_call_equals_the_scalar_loop():
    script = load_script()
    angles = np.linspace(0.0, 360.0, 13)
    for case in (script.program_1, script.program_2, script.program_3):
        array = case(angles)
        for i, angle in enumerate(angles):
            scalar = case(float(angle))
            assert np.isclose(array.value[i], scalar.value, rtol=1e-12, atol=1e-12)
            for name, values in array.reactions.items():
                assert np.isclose(values[i], scalar.reactions[name], rtol=1e-12, atol=1e-12)
