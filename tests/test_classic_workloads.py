"""The in-repo classic workloads (tests/benchmarks/classic/) run in yaseer and print what PC-BASIC prints.

At a tenth of their loop counts, each workload runs once in yaseer and once in
PC-BASIC 2.0.8 (one session for all of them).  PC-BASIC works in single
precision and yaseer in double, so numbers are compared to a relative 1e-5
(Ahl's ten square roots and ten squares amplify single precision's 6e-8 about
a thousandfold); words exactly.  PC-BASIC uses radians, so yaseer runs with
``angle="rad"``.  Ahl's second line sums random numbers, and the two machines
have different generators: there both values are checked against the
expectation of the sum instead; in ``--dialect gw`` (GW's generator) it is PC-BASIC's
text exactly.
"""

from __future__ import annotations

import importlib.util
import io
import math
import os
import subprocess
import sys
from pathlib import Path

import pytest

from test_differential_support import PcBasic, core
from yaseer.basic.machine.machine import Machine

ROOT = Path(__file__).resolve().parents[1]
BENCHMARKS = ROOT / "tests" / "benchmarks"
SCALE = 0.1


def load(name: str):
    spec = importlib.util.spec_from_file_location(name, BENCHMARKS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module  # a dataclass looks its module up there
    spec.loader.exec_module(module)
    return module


classic = load("classic_workloads")
WORKLOADS = classic.in_repo()


def yaseer_output(text: str, dialect: str = "casio") -> str:
    screen = io.StringIO()
    machine = Machine(screen=screen, angle="rad", dialect=core(dialect))  # (casio: its MS-BASIC core)
    machine.load(text)
    machine.run()
    return screen.getvalue()


@pytest.fixture(scope="module")
def pcbasic_outputs():
    session = PcBasic()
    try:
        return {w.name: session.program(classic.scaled(w.text, SCALE)) for w in WORKLOADS}
    finally:
        session.close()


def words(line: str) -> list:
    """The words of a printed line, numbers as floats."""
    result = []
    for word in line.split():
        try:
            result.append(float(word))
        except ValueError:
            result.append(word)
    return result


def same_line(ours: str, theirs: str) -> bool:
    a, b = words(ours), words(theirs)
    if len(a) != len(b):
        return False
    for x, y in zip(a, b):
        if isinstance(x, float) and isinstance(y, float):
            if not math.isclose(x, y, rel_tol=1e-5, abs_tol=1e-30):
                return False
        elif x != y:
            return False
    return True


def test_the_workloads_are_all_there():
    assert [w.name for w in WORKLOADS] == ["bm1", "bm2", "bm3", "bm4", "bm5", "bm6", "bm7", "bm8",
                                           "ahl", "ahl_split"]


@pytest.mark.parametrize("workload", [w for w in WORKLOADS if w.name.startswith("bm")], ids=lambda w: w.name)
def test_rugg_feldman_prints_what_pcbasic_prints(workload, pcbasic_outputs):
    ours = yaseer_output(classic.scaled(workload.text, SCALE)).splitlines()
    theirs = [line for line in pcbasic_outputs[workload.name].splitlines() if line.strip() != "Ok"]
    theirs = [line for line in theirs if line.strip()]
    assert len(ours) == len(theirs) == 2, (ours, theirs)
    assert all(same_line(a, b) for a, b in zip(ours, theirs)), (ours, theirs)
    # the loop ran the scaled count: K is 100 at the end (101 after BM1's FOR loop)
    assert words(ours[1])[1] == (101 if workload.name == "bm1" else 100)


@pytest.mark.parametrize("name", ["ahl", "ahl_split"])
def test_ahl_prints_what_pcbasic_prints(name, pcbasic_outputs):
    workload = next(w for w in WORKLOADS if w.name == name)
    ours = yaseer_output(classic.scaled(workload.text, SCALE)).splitlines()
    theirs = [line for line in pcbasic_outputs[name].splitlines() if line.strip() and line.strip() != "Ok"]
    assert len(ours) == len(theirs) == 2, (ours, theirs)
    # line 1: ABS(1010 - S/5) with S = 1 + 2 + ... + 10 = 55 when SQR and ^2 cancel
    assert same_line(ours[0], theirs[0]), (ours, theirs)
    assert math.isclose(words(ours[0])[0], 1010 - 55 / 5, rel_tol=1e-9)
    # line 2: ABS(1000 - R), R a sum of 200 uniform numbers: mean 100, sd sqrt(200/12)
    sd = math.sqrt(200 / 12)
    for line in (ours[1], theirs[1]):
        assert abs(words(line)[0] - 900) < 6 * sd, line


@pytest.mark.parametrize("workload", WORKLOADS, ids=lambda w: w.name)
def test_in_the_gw_dialect_the_text_is_pcbasics(workload, pcbasic_outputs):
    """``--dialect gw``: single precision, GW's printing and GW's random numbers, so the
    text is PC-BASIC's, character for character, except the digits of SIN, LOG and SQR
    (GW's own series, and PC-BASIC cuts SQR's result where GW's ``$SQR`` rounds it;
    docs/compatibility.md): BM8's last digits and Ahl's accuracy line, which sums the
    rounding errors of 2,000 of them."""
    ours = yaseer_output(classic.scaled(workload.text, SCALE), dialect="gw").splitlines()
    theirs = pcbasic_outputs[workload.name].splitlines()
    if workload.name == "bm8":
        ours, theirs = [line.split()[:3] for line in ours], [line.split()[:3] for line in theirs]
    elif workload.name.startswith("ahl"):
        assert same_line(ours[0], theirs[0]), (ours, theirs)
        ours, theirs = ours[1:], theirs[1:]
    assert ours == theirs


def test_bwbasic_forms_end_with_system_and_keep_for_next_on_their_own_lines():
    for workload in WORKLOADS:
        lines = workload.bwbasic.splitlines()
        assert not any(line.split()[1:] == ["END"] for line in lines), workload.name
        assert sum(line.split()[1:] == ["SYSTEM"] for line in lines) == 1, workload.name
        for line in lines:
            statements = line.split(maxsplit=1)[1].split(":")
            assert not any(s.strip().startswith(("FOR", "NEXT")) for s in statements[1:]), (workload.name, line)
            assert not (len(statements) > 1 and statements[0].startswith("FOR")), (workload.name, line)


def test_for_bwbasic_adds_system_where_there_is_no_end():
    assert classic.for_bwbasic("10 PRINT 1\n20 GOTO 40\n40 PRINT 2\n") == \
        "10 PRINT 1\n20 GOTO 40\n40 PRINT 2\n50 SYSTEM\n"


def test_interpreter_speed_without_bwbasic_or_extra_copies_says_so_in_one_line(tmp_path):
    """From a clone alone (no bwbasic on PATH, no other copies) the script runs to the end."""
    env = dict(os.environ, PATH=str(Path(sys.executable).parent), YASEER_CLASSIC=str(tmp_path / "absent"))
    done = subprocess.run([sys.executable, str(BENCHMARKS / "interpreter_speed.py"), "--repeat", "1"],
                          capture_output=True, text=True, env=env, timeout=300, cwd=str(tmp_path))
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr
    skipped = [line for line in done.stdout.splitlines() if "bwbasic not found" in line]
    assert len(skipped) == 1
