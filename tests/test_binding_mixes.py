"""GOSUB PROG 2 with forces through the interpreter under mixes of inputs (the listings of
tests/benchmarks/percall.py): whatever path each call's inputs take, and in whatever order
the paths are met, a recorded call gives the bits of the same call made alone, of the plain
scalar code (the recordings switched off), and the kinematics of an independent closed form
(percall.closed_form_fourbar, written out from the loop equations)."""

from __future__ import annotations

import io
import math
import sys
from pathlib import Path

import pytest

from yaseer import binding
from yaseer.basic.machine.machine import Machine

sys.path.insert(0, str(Path(__file__).resolve().parent / "benchmarks"))
from percall import INPUTS, closed_form_fourbar, machine_for, mix_listing  # noqa: E402
from test_binding_recorded import recorded_and_plain  # noqa: E402  (recordings fresh, then the plain code)

# Program 2's outputs (contract): angles and rates, the three points, the solved load, the reactions
OUTPUTS = ([("T", 13), ("W", 6), ("A", 6), ("T", 14), ("W", 7), ("A", 7)]
           + [(name, k) for name in "XY" for k in (3, 4, 5)] + [("V", k) for k in range(5, 11)]
           + [("A", k) for k in range(37, 43)] + [("U", 2)] + [("F", k) for k in range(21, 38)])
# Q(n)'s unknown loads: what a call solves for is a known load of the next call with another Q(2);
# set back every pass, each call's inputs are its crank angle and its Q(2) alone
UNKNOWN_LOADS = {("U", 2): 0.0, ("F", 31): 0.0, ("F", 34): 0.0, ("F", 37): INPUTS[2]["F"][37]}
CALLS = 24


@pytest.fixture(autouse=True)
def no_kept_paths(monkeypatch):
    """Each run records its paths afresh (no on-disk cache): the order the paths are met in is the test's."""
    monkeypatch.setenv("YASEER_CACHE_DIR", "")
    binding._recordings.clear()
    binding._calls.clear()
    yield
    binding._recordings.clear()
    binding._calls.clear()


def angle(k: int) -> float:
    return 7.3 * k + 0.25


def listing(q_of, branch: float) -> str:
    """CALLS passes of PROG 2 with forces, Q(2) = q_of(K), each pass's outputs taken by PROG 9 (:func:`run_rows`)."""
    settings = [f"{name}({index})={value!r}" for name, elements in INPUTS[2].items()
                for index, value in elements.items()] + ["Z(2)=2", "G=9.81", f"L(10)={branch!r}"]
    reset = ": ".join(f"{name}({index})={value!r}" for (name, index), value in UNKNOWN_LOADS.items())
    passes = []
    for k in range(CALLS):
        passes.append(f"{100 + 10 * k} K={k}: T(12)={angle(k)!r}: Q(2)={q_of(k)}: {reset}: GOSUB PROG 2: GOSUB PROG 9")
    return (f"20 {': '.join(settings)}\n" + "\n".join(passes)
            + "\n9000 END\n")


def run_rows(text: str, recorded: bool = True) -> list[list[str]]:
    """The outputs after each GOSUB PROG 2 of ``text`` run on a fresh machine with the library
    bound (taken by a Python area 9 the listing calls next), as float.hex (signed zeros apart);
    ``recorded``: False runs the plain code."""
    rows = []

    def take(machine) -> None:
        rows.append([float(machine.array(name)[index]).hex() for name, index in OUTPUTS])

    saved = binding.MAX_RECORDINGS
    binding.MAX_RECORDINGS = saved if recorded else 0
    try:
        machine = Machine(screen=io.StringIO())
        binding.install(machine)
        machine.set_area(9, take)
        machine.load(text)
        machine.run()
    finally:
        binding.MAX_RECORDINGS = saved
    assert bool(binding._recordings.get((2, None))) == recorded
    assert len(rows) == CALLS
    return rows


def cycling(k: int) -> int:
    return k % 4 + 1


@pytest.mark.parametrize("branch", [0.0, 1.0])
def test_q_cycling_gives_the_bits_of_each_call_made_alone(branch):
    mixed = run_rows(listing(cycling, branch))
    assert len(binding._recordings[(2, None)]) >= 4  # one path a Q(2) at least: the mix did take several
    for q in (1, 2, 3, 4):
        binding._recordings.clear()
        binding._calls.clear()
        alone = run_rows(listing(lambda k: q, branch))
        assert len(binding._recordings[(2, None)]) == 1  # one input pattern: one path
        for k in range(CALLS):
            if cycling(k) == q:
                assert mixed[k] == alone[k], (q, k)
    binding._recordings.clear()
    assert mixed == run_rows(listing(cycling, branch), recorded=False)


def test_q_cycling_kinematics_equal_the_closed_form():
    rows = run_rows(listing(cycling, 0.0))
    given = {name: {index: value for index, value in elements.items()} for name, elements in INPUTS[2].items()}
    for k, row in enumerate(rows):
        values = [float.fromhex(text) for text in row]
        coupler, w3, a3, follower, w4, a4 = closed_form_fourbar(
            given["L"][11], given["T"][11], given["L"][12], given["L"][13], given["L"][14], angle(k),
            given["W"][5], given["A"][5], given["D"][2], given["E"][2])
        assert math.remainder(values[0] - math.degrees(coupler), 360.0) == pytest.approx(0.0, abs=1e-9)
        assert math.remainder(values[3] - math.degrees(follower), 360.0) == pytest.approx(0.0, abs=1e-9)
        for got, want in zip((values[1], values[2], values[4], values[5]), (w3, a3, w4, a4)):
            assert got == pytest.approx(want, rel=1e-9, abs=1e-9)


def arrays_bits(machine: Machine) -> dict:
    return {name: [float(value).hex() if not isinstance(value, (list, str)) else value for value in values]
            for name, values in machine.arrays.items()}


@pytest.mark.parametrize("mix", ["one path", "Q(2) cycling 1..4", "32 input patterns"])
def test_the_benchmark_mixes_give_the_plain_codes_bits(mix):
    # the listings the benchmark times, every array and scalar after the run, against the plain code
    def scenario():
        machine = machine_for(2)
        machine.load(mix_listing(mix, 70, True))
        machine.run()
        return arrays_bits(machine), {name: float(value).hex() for name, value in machine.scalars.items()
                                      if not isinstance(value, str)}

    recorded, plain = recorded_and_plain(scenario)
    assert recorded == plain


@pytest.mark.parametrize("base", [float.fromhex("0x1.f450b0d1e5574p-2"), complex(float.fromhex("0x1.f450b0d1e5574p-2"), -0.0),
                                  complex(-0.0, 1.5), -3.25, 0.0, -0.0])
def test_a_square_is_recorded_as_the_power_the_plain_code_computes(base):
    # reference: Python's own x ** 2 (libm's pow for a float); the first float is one whose
    # square by pow is not the product x * x (...296c against ...296b), which a recording of
    # x ** 2 as x * x gave: PROG 2's forces at crank angle 117.05 differed in their last bit
    from yaseer.linkages.tracing import Recorder

    recorder = Recorder()
    squared = recorder.read(base, "_x") ** 2
    namespace = {"_x": base, **recorder.names}
    exec(compile("\n".join(str(line) for line in recorder.lines), "<record>", "exec"), namespace)
    got, want = namespace[squared.name], base ** 2
    parts = (lambda v: (v.real.hex(), v.imag.hex())) if isinstance(want, complex) else float.hex
    assert parts(got) == parts(want) == parts(squared.value)
