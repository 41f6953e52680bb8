"""Recorded paths run as programs of double operations (yaseer/linkages/_straight_fast.c,
path_translation.py, straight_line.py).

The reference is CPython itself: each path's Python function (and, for single operations, the
Python expression) run on the same inputs.  Wherever the program completes a call, the Python
function must complete it too and write the same bits (a zero's sign, a NaN's absence included);
wherever the Python function raises (a Retrace, an error), the program must refuse the call.
The program must also complete most calls (a program refusing everything would pass the first
rule alone), and a damaged program must be refused whole, never run."""

from __future__ import annotations

import io
import math
import random
import struct
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from yaseer import binding
from yaseer.basic.machine.machine import Machine
from yaseer.linkages import straight_line, tracing
from yaseer.linkages.tracing import Retrace

fast = pytest.importorskip("yaseer.linkages._straight_fast", reason="the C accelerator is not built")
from yaseer.linkages.path_translation import translate  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent / "benchmarks"))
from percall import CRANK, INPUTS, machine_for, mix_listing  # noqa: E402
from test_binding_mixes import no_kept_paths  # noqa: E402,F401  (each test records its paths afresh)

if straight_line._module() is None:
    pytest.skip("the accelerator is not used on this Python", allow_module_level=True)


class Refused(Exception):
    """Raised by the stand-in fallback: the program refused the call."""


def refuse(machine):
    raise Refused


def program_of(run, text=None):
    """The accelerator's Path of the Python function ``run``, translated at its first call, whose
    refusals raise :class:`Refused` (the Python function is not run)."""
    text = text if text is not None else run.text
    parts = translate(text, run.__globals__, fast.OPERATIONS)
    assert parts is not None, "the path's text was not translated"
    return fast.Path(refuse, lambda: parts, 0)


class Stand:
    """What a recorded path reads of a machine: arrays, scalars, a dialect, set_scalar."""

    class dialect:
        typed_numbers = False

    def __init__(self, arrays: dict, scalars: dict):
        self.arrays = {name: list(values) for name, values in arrays.items()}
        self.scalars = dict(scalars)

    def array(self, name):
        return self.arrays.setdefault(name, [0.0] * 11)

    def set_scalar(self, name, value):
        self.scalars[name] = float(value)

    def bits(self):
        return ({name: [struct.pack("<d", v).hex() if type(v) is float else repr(v) for v in values]
                 for name, values in self.arrays.items()},
                {name: struct.pack("<d", v).hex() for name, v in self.scalars.items()})


def outcome(run, stand: Stand):
    """What ``run`` does to ``stand``: its bits, or the name of what it raised."""
    try:
        run(stand)
    except Refused:
        return "refused"
    except Retrace:
        return "Retrace"
    except Exception as error:  # an error of the path (Overflow, Subscript out of range, ...)
        return type(error).__name__
    return stand.bits()


def same_or_refused(run, program, arrays, scalars) -> bool:
    """Check one input: the program writes the Python function's bits or refuses; True when it ran."""
    by_python = outcome(run, Stand(arrays, scalars))
    by_program = outcome(program, Stand(arrays, scalars))
    if by_program == "refused":
        return False
    assert by_program == by_python
    return True


# -- the library programs' paths ------------------------------------------------------------------

def machine(number: int, z: float, q: float) -> Machine:
    m = machine_for(number)
    if number != 5:
        m.array("Z")[number] = float(z)
        m.array("Q")[number] = float(q)
    return m


def recorded_path(number: int, z: float, q: float):
    """Program ``number``'s path for these inputs: its Python function (with its text) and the
    machine it was recorded on."""
    from yaseer.linkages.tracing import Recorder

    m = machine(number, z, q)
    frame = binding._RecordingFrame(m, number, Recorder())
    binding.PROGRAMS[number](frame, None)
    run, _ = frame.recorded()
    run(m)  # the arrays it writes made, as the first call of a run makes them
    return run, m


SPECIAL = [0.0, -0.0, 1e-310, -1e-310, 1e300, -1e300, math.inf, -math.inf, math.nan, 90.0, 180.0, 270.0,
           360.0, -90.0, 1.0, -1.0, 5e-324, 2.0 ** 1023]


@pytest.mark.parametrize("number,z,q", [(1, 2.0, 1), (1, 0.0, 3), (2, 2.0, 1), (2, 2.0, 2), (2, 2.0, 3), (2, 2.0, 4),
                                        (2, 0.0, 1), (3, 2.0, 1), (3, 2.0, 3), (5, 0.0, 0)])
def test_a_programs_path_writes_the_bits_of_its_python_function(number, z, q):
    run, m = recorded_path(number, z, q)
    program = program_of(run)
    arrays = {name: list(values) for name, values in m.arrays.items()}
    ran = 0
    for trial in range(400):
        state = random.Random(trial)
        changed = {name: list(values) for name, values in arrays.items()}
        for name, elements in INPUTS[number].items():
            for index, value in elements.items():
                roll = state.random()
                if (name, index) == ("L", 10):  # Program 2's branch: a choice its path is pinned to
                    continue
                if roll < 0.03:
                    changed[name][index] = state.choice(SPECIAL)
                elif roll < 0.8:
                    changed[name][index] = value * state.uniform(0.7, 1.4)
        crank, index = CRANK[number]
        changed[crank][index] = (state.choice(SPECIAL) if state.random() < 0.1
                                 else state.choice([state.uniform(-720.0, 720.0), float(state.randrange(-8, 9) * 45)]))
        ran += same_or_refused(run, program, changed, dict(m.scalars, G=state.choice([9.81, 0.0, -0.0, 1.5])))
    assert ran > 100, ran  # most inputs near the recorded call's take its path, and the program runs them


def test_an_input_that_is_not_a_float_leaves_the_call_to_the_python_function():
    run, m = recorded_path(2, 2.0, 1)
    program = program_of(run)
    arrays = {name: list(values) for name, values in m.arrays.items()}
    assert same_or_refused(run, program, arrays, m.scalars)  # as recorded: it runs
    for value in (1, True, "1", [1.0], 2 ** 80):
        changed = {name: list(values) for name, values in arrays.items()}
        changed["L"][11] = value
        assert outcome(program, Stand(changed, m.scalars)) == "refused"
    del arrays["R"]  # an array the path reads missing: the Python function makes it
    assert outcome(program, Stand(arrays, m.scalars)) == "refused"


def test_an_output_array_too_short_or_of_rows_is_refused_before_anything_is_written():
    run, m = recorded_path(2, 2.0, 1)
    program = program_of(run)
    for change in ("short", "rows"):
        stand = Stand(m.arrays, m.scalars)
        if change == "short":
            stand.arrays["X"] = stand.arrays["X"][:4]  # X(5) is written, never read
        else:
            stand.arrays["X"] = [[0.0] * 3 for _ in stand.arrays["X"]]
        before = stand.bits()
        assert outcome(program, stand) == "refused"
        assert stand.bits() == before  # nothing written
        assert outcome(run, Stand(stand.arrays, stand.scalars)) == "BasicError"


def test_a_machine_with_typed_numbers_is_refused():
    run, m = recorded_path(2, 2.0, 1)
    program = program_of(run)
    stand = Stand(m.arrays, m.scalars)
    stand.dialect = type("Typed", (), {"typed_numbers": True})()
    assert outcome(program, stand) == "refused"


# -- single operations against the Python expression ----------------------------------------------

EXPRESSIONS = {
    # float arithmetic and the calls of math a path makes
    "v0 + v1": "f", "v0 - v1": "f", "v0 * v1": "f", "v0 / v1": "f", "v0 % v1": "f", "v0 % 360.0": "f",
    "v0 ** 2": "f", "-v0": "f", "abs(v0)": "f", "_sqrt(v0)": "f", "_cos(v0)": "f", "_sin(v0)": "f",
    "_arctan(v0)": "f", "_atan2(v0, v1)": "f", "_ulp(v0)": "f", "_ldexp(1.0, _frexp(v0)[1])": "f",
    "v0 * 0.017453292519943295": "f", "(v0 if (v0 < v1) else v1)": "f", "(v1 if v1 > v0 else v0)": "f",
    "(-1.0 if (v0 < 0) else 1.0)": "f", "(1.0 if (v0 == 0) else v0)": "f", "2 * v0": "f",
    # complex arithmetic, mixed with floats as a path mixes them
    "_rect(v0, v1)": "c", "_rect(1.0, v1)": "c", "(_quadrant(v0 % 360.0) or _rect(1.0, v1))": "c",
    "(v0 + 1j * v1) * (v1 - 2j)": "c", "v0 * (1j * v1)": "c", "0j + v0": "c", "0j - v0": "c",
    "(v0 + 1j * v1) / (v1 + 1j * v0)": "c", "(v0 + 1j * v1) / v1": "c", "v0 / (v1 + 0.5j)": "c",
    "-(v0 + 1j * v1)": "c", "(v0 * 1j) - v1": "c", "(1+0j) * v0": "c", "v0 * (v1 * 0j)": "c",
    "abs(v0 + 1j * v1)": "f", "_atan2((v0 + 1j * v1).imag, (v0 - 1j * v1).real)": "f",
    # guards
    "(v0 <= v1 < 2.0)": "b", "(v0 != 0)": "b", "not v0": "b", "(v0 == v1) or (v0 > 1.0)": "b",
    "_isfinite(v0)": "b", "((v0 + 1j) == (v1 + 1j))": "b",
}


def _text(expression: str, kind: str) -> str:
    """A path's text computing ``expression`` of two inputs X(0), X(1) and writing it to Y."""
    lines = ["_arrays = _M.arrays",
             "try: _a_X = _arrays['X']; _a_Y = _arrays['Y']",
             "except KeyError: _ready = False",
             "else: _ready = True",
             "v0 = _a_X[0] - 0.0",
             "v1 = _a_X[1] - 0.0",
             f"v2 = {expression}"]
    if kind == "c":
        lines += ["v3 = v2.real", "v4 = v2.imag"]
    elif kind == "b":
        lines += ["v3 = (1.0 if v2 else 0.0)", "v4 = (0.0 if v2 else 1.0)"]
    else:
        lines += ["v3 = v2", "v4 = -v2"]
    lines += ["try: _a_Y[1]", "except IndexError: raise _error('Subscript out of range', 9) from None",
              "_a_Y[0] = v3", "_a_Y[1] = v4"]
    return ("def run(_M):\n  try:\n" + "".join(f"    {line}\n" for line in lines)
            + "  except (IndexError, TypeError):\n    raise _Retrace from None\n")


def _function(text: str):
    names = tracing.namespace({**tracing.BOUND, "_isfinite": math.isfinite,
                               "_error": lambda message, code: ValueError(message)})
    exec(compile(text, "<test path>", "exec"), names)
    run = names["run"]
    run.text = text
    return run


FUNCTIONS = {expression: _function(_text(expression, kind)) for expression, kind in EXPRESSIONS.items()}
PROGRAMS = {expression: program_of(run) for expression, run in FUNCTIONS.items()}

NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.floats(-1e6, 1e6),
    st.sampled_from([0.0, -0.0, 1.0, -1.0, 90.0, 180.0, 270.0, 360.0, -360.0, 450.0, 5e-324, -5e-324, 2.0 ** -1022,
                     2.0 ** 1023, 1.7976931348623157e308, 1e-160, 1e160, math.pi, -math.pi, 0.5, 2.0]),
)


@settings(max_examples=3000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(expression=st.sampled_from(sorted(EXPRESSIONS)), x=NUMBERS, y=NUMBERS)
def test_each_operation_gives_the_bits_python_gives_or_is_refused(expression, x, y):
    same_or_refused(FUNCTIONS[expression], PROGRAMS[expression], {"X": [x, y], "Y": [0.0, 0.0]}, {})


@pytest.mark.parametrize("expression", sorted(EXPRESSIONS))
def test_each_operation_runs_on_ordinary_numbers(expression):
    ran = sum(same_or_refused(FUNCTIONS[expression], PROGRAMS[expression],
                              {"X": [x, y], "Y": [0.0, 0.0]}, {})
              for x in (0.3, -1.7, 45.0, 1e-3, 250.0, 0.0) for y in (0.6, -2.5, 7.0, 1.2))
    assert ran >= 12, ran  # zeros, negatives and the like may be left to Python; ordinary numbers are not


def test_signed_zeros_of_mixed_complex_arithmetic_are_pythons():
    # (x, 0.0) times (0, 1): the real part 0*x - 1*0.0 is -0.0 for x = -0.0 ... each as CPython 3.11 computes it
    for expression in ("v0 * (1j * v1)", "0j - v0", "(v0 * 1j) - v1", "v0 * (v1 * 0j)", "(1+0j) * v0"):
        for x in (0.0, -0.0, 1.0, -1.0):
            for y in (0.0, -0.0, 2.0, -2.0):
                assert same_or_refused(FUNCTIONS[expression], PROGRAMS[expression], {"X": [x, y], "Y": [0.0, 0.0]}, {})


# -- the programs are checked before use ----------------------------------------------------------

def test_a_damaged_program_is_refused_whole_and_the_python_function_runs():
    run = FUNCTIONS["(v0 + 1j * v1) * (v1 - 2j)"]
    parts = translate(run.text, run.__globals__, fast.OPERATIONS)
    good = fast.Path(run, lambda: parts, 0)
    stand = Stand({"X": [0.5, 0.25], "Y": [0.0, 0.0]}, {})
    good(stand)
    assert good.state == "running" and good.counts == (1, 0)
    state = random.Random(7)
    refused = 0
    for trial in range(3000):
        damaged = dict(parts, code=list(parts["code"]), extra=list(parts["extra"]))
        for _ in range(state.randint(1, 3)):
            where = state.randrange(len(damaged["code"]))
            damaged["code"][where] = state.choice([-1, 1 << 20, state.randrange(64), damaged["code"][where] + 1,
                                                   len(parts["registers"]), 2 ** 31 - 1])
        path = fast.Path(run, lambda: damaged, 0)
        stand = Stand({"X": [0.5, 0.25], "Y": [0.0, 0.0]}, {})
        path(stand)  # never a crash: either the checked program runs or the Python function does
        refused += path.state == "plain"
    assert refused > 1000
    for broken in (dict(parts, code=parts["code"][:-1]), dict(parts, registers=parts["registers"][:2]),
                   dict(parts, arrays=("X",)), dict(parts, registers=[1] * len(parts["registers"])), None, 42,
                   dict(parts, code=[*parts["code"][:-4], fast.OPERATIONS["JUMP"], 0, 0, 0])):
        path = fast.Path(run, lambda: broken, 0)
        stand = Stand({"X": [0.5, 0.25], "Y": [0.0, 0.0]}, {})
        path(stand)
        assert path.state == "plain"
        assert stand.bits() == outcome(run, Stand({"X": [0.5, 0.25], "Y": [0.0, 0.0]}, {}))


# -- in a run ----------------------------------------------------------------------------------------

def test_a_listing_taking_a_path_often_runs_its_program_and_prints_what_python_prints(monkeypatch):
    text = mix_listing("Q(2) cycling 1..4", 2 * straight_line.WARM * 4 + 40, True).replace(
        "GOSUB PROG 2:", "GOSUB PROG 2: S=S+T(13)+W(6)+A(7)+X(5)+F(22)+U(2):") + "25 PRINT S\n"
    printed = {}
    for accelerated in (True, False):
        binding._recordings.clear()
        binding._calls.clear()
        if not accelerated:
            monkeypatch.setattr(straight_line, "_module", lambda: None)
        screen = io.StringIO()
        m = Machine(screen=screen)
        binding.install(m)
        m.load(text.replace("30 END", "25 PRINT S: END"))
        m.run()
        printed[accelerated] = screen.getvalue()
        paths = binding._recordings[(2, None)]._paths
        if accelerated:
            # (a path taken once, by the first pass's inputs, stays with its Python function)
            assert sum(path.state == "running" for path in paths) >= 4, [path.state for path in paths]
            assert sum(path.counts[0] for path in paths) > 4 * straight_line.WARM
        else:
            assert not any(hasattr(path, "state") for path in paths)
    assert printed[True] == printed[False] and printed[True].strip()


def test_ctrl_c_during_the_translation_is_raised_and_the_path_is_translated_later():
    run = FUNCTIONS["v0 + v1"]
    parts = translate(run.text, run.__globals__, fast.OPERATIONS)
    attempts = []

    def translation():
        attempts.append(1)
        if len(attempts) == 1:
            raise KeyboardInterrupt
        return parts

    path = fast.Path(run, translation, 0)
    with pytest.raises(KeyboardInterrupt):
        path(Stand({"X": [0.5, 0.25], "Y": [0.0, 0.0]}, {}))
    assert path.state == "warming" and path.error is None
    stand = Stand({"X": [0.5, 0.25], "Y": [0.0, 0.0]}, {})
    path(stand)
    assert path.state == "running" and path.counts == (1, 0) and stand.arrays["Y"] == [0.75, -0.75]
