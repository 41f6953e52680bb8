"""Recorded GOSUB PROG calls (yaseer.linkages.tracing, yaseer.binding): from the
second call on, a program runs as a compiled recording of its scalar code.  The
recording must give the outputs and errors of the plain scalar code (the
recording switched off) on every path: forces or not, each Q(n), each branch,
assembly failures, overflow, and inputs that move from one path to another."""

from __future__ import annotations

import io
import math
import random
import sys
from pathlib import Path

import pytest

from yaseer import binding
from yaseer.basic.errors import BasicError
from yaseer.basic.machine.machine import Machine
from yaseer.linkages.tracing import NotTraceable, Recorder

sys.path.insert(0, str(Path(__file__).resolve().parent / "benchmarks"))
from percall import CRANK, INPUTS, machine_for  # noqa: E402  (the benchmark's inputs of each program)

WRITTEN = ("T", "W", "A", "X", "Y", "V", "F", "U", "N", "L", "D", "E", "P")


@pytest.fixture(autouse=True)
def no_kept_paths(monkeypatch):
    """The recordings of one process, as they are without the on-disk cache (the first call runs the
    plain code, each path is recorded when first met); tests/test_recording_cache.py keeps them."""
    monkeypatch.setenv("YASEER_CACHE_DIR", "")


def machine(number: int, z: float, q: float, branch: float = 0.0) -> Machine:
    m = Machine(screen=io.StringIO())
    binding.install(m)
    for name, elements in INPUTS[number].items():
        for index, value in elements.items():
            m.array(name)[index] = float(value)
    m.array("Z")[number] = z
    m.array("Q")[number] = q
    m.array("L")[10] = branch if number == 2 else m.array("L")[10]
    m.set_scalar("G", 9.81)
    return m


def outcome(m: Machine, number: int):
    """Every array the programs write and the scalars, or the error line."""
    try:
        m.python_areas[number](m)
    except BasicError as err:
        return str(err)
    return {name: list(m.array(name)) for name in WRITTEN}, dict(m.scalars)


def recorded_and_plain(scenario) -> list:
    """``scenario()`` run twice: with fresh recordings, and with the plain code."""
    results = []
    for recording in (True, False):
        binding._recordings.clear()
        binding._calls.clear()
        saved = binding.MAX_RECORDINGS
        binding.MAX_RECORDINGS = saved if recording else 0
        try:
            results.append(scenario())
        finally:
            binding.MAX_RECORDINGS = saved
        assert any(binding._recordings.values()) == recording  # recorded calls ran (or none)
    return results


def both_ways(number, z, q, angles, branch=0.0, scale=1.0):
    """The outcomes with recordings (fresh) and with the plain code, call by call."""

    def scenario():
        m = machine(number, z, q, branch)
        name, index = CRANK[number]
        row = []
        for angle in angles:
            m.array(name)[index] = angle
            m.array("L")[12 if number == 2 else 2] *= scale
            row.append(outcome(m, number))
        return row

    return recorded_and_plain(scenario)


ANGLES = [0.0, 37.5, 90.0, 123.4, 180.0, 270.0, 301.0, 359.9, 45.0, 0.0]


@pytest.mark.parametrize("number,q", [(1, 1), (1, 2), (1, 3), (1, 4), (2, 1), (2, 2), (2, 3), (2, 4), (3, 1), (3, 3)])
@pytest.mark.parametrize("z", [0.0, 2.0])
def test_recorded_calls_equal_the_plain_code(number, q, z):
    recorded, plain = both_ways(number, z, q, ANGLES)
    assert recorded == plain


@pytest.mark.parametrize("branch", [0.0, 1.0])
def test_branches_and_a_mechanism_that_stops_assembling(branch):
    # the crank grows every call until the four-bar cannot close: the same error both ways
    recorded, plain = both_ways(2, 2.0, 1, [10.0 * k for k in range(12)], branch=branch, scale=1.6)
    assert recorded == plain
    assert any(isinstance(item, str) and "cannot be assembled (PROG 2)" in item for item in recorded)


def test_inputs_that_change_path_between_calls_are_recorded_again():
    binding._recordings.clear()
    binding._calls.clear()
    m = machine(2, 0.0, 1)
    plain = machine(2, 0.0, 1)
    saved = binding.MAX_RECORDINGS
    rng = random.Random(7)
    for call in range(40):
        z = rng.choice([0.0, 2.0])
        q = rng.choice([1, 2, 3, 4])
        still = rng.random() < 0.3  # no crank rate: a static call
        for target in (m, plain):
            target.array("Z")[2], target.array("Q")[2] = z, q
            target.array("T")[12] = rng.uniform(0, 360) if target is m else m.array("T")[12]
            target.array("W")[5] = 0.0 if still else 4.0
            target.array("A")[5] = 0.0 if still else -1.0
            target.array("D")[2] = 0.0 if still else 0.1
            target.array("E")[2] = 0.0 if still else 0.2
        first = outcome(m, 2)
        binding.MAX_RECORDINGS = 0
        try:
            second = outcome(plain, 2)
        finally:
            binding.MAX_RECORDINGS = saved
        assert first == second
    assert len(binding._recordings[(2, None)]) > 2  # several paths were recorded


def test_overflow_in_a_recorded_call_is_the_basic_error():
    binding._recordings.clear()
    binding._calls.clear()
    m = machine(2, 2.0, 1)
    for _ in range(3):
        outcome(m, 2)
    m.array("M")[7] = 1e308  # coupler mass: forces overflow
    m.array("W")[5] = 1e200
    assert outcome(m, 2) == "Overflow (PROG 2)"


def test_a_traced_value_never_becomes_a_plain_number():
    recorder = Recorder()
    traced = recorder.emit(2.5, "2.5")
    with pytest.raises(NotTraceable):
        float(traced)
    with pytest.raises(TypeError):
        {traced: 1}
    assert (traced * 2).value == 5.0


def test_an_array_of_another_length_is_read_as_the_plain_code_reads_it():
    # I(7), I(8) fall beyond a shorter I (read as 0): the recording made for the longer
    # array must not be used for it, nor the one made for the shorter for the longer
    def scenario():
        m = machine(2, 2.0, 1)
        full = list(m.array("I"))
        row = []
        for call in range(8):
            m.arrays["I"] = full[:7] if call % 3 == 2 else list(full)
            m.array("T")[12] = 15.0 * call
            row.append(outcome(m, 2))
        return row

    runs = recorded_and_plain(scenario)
    recorded, plain = runs
    assert recorded == plain
    assert recorded[2] != recorded[1]  # the shorter array does change the forces


def pattern_inputs(m: Machine, j: int) -> None:
    """Pattern ``j`` of 32 (as the benchmark's mix): Q(2) 1..4, Z(2) 0 or 2, L(10) 0 or 1, crank turning or at rest."""
    moving = j // 16 % 2
    m.array("Q")[2], m.array("Z")[2], m.array("L")[10] = j % 4 + 1, 2.0 * (j // 4 % 2), float(j // 8 % 2)
    m.array("W")[5], m.array("A")[5], m.array("D")[2], m.array("E")[2] = 4.0 * moving, -moving, moving / 10, moving / 5


def test_a_call_runs_the_one_path_its_inputs_take_whatever_the_mix():
    # 32 input patterns cycled: equal to the plain code call by call, and once every
    # pattern was met, each call runs exactly one recorded path (chosen by its key),
    # never a path whose guards fail first
    def scenario():
        m = machine(2, 2.0, 1)
        row = []
        for call in range(96):
            pattern_inputs(m, call % 32)
            m.array("T")[12] = 7.5 * call
            row.append(outcome(m, 2))
        return row

    recorded, plain = recorded_and_plain(scenario)
    assert recorded == plain
    binding._recordings.clear()
    binding._calls.clear()
    scenario()
    recordings = binding._recordings[(2, None)]
    assert 8 <= len(recordings) <= 32  # Q(2) only matters with forces
    runs = []
    for k, path in enumerate(recordings._paths):
        def counted(machine, path=path, k=k):
            runs.append(k)
            return path(machine)
        recordings._chosen = {key: counted if chosen is path else chosen for key, chosen in recordings._chosen.items()}
        recordings._paths[k] = counted
    m = machine(2, 2.0, 1)
    for call in range(96):  # the first pass over the patterns on a fresh machine finds the paths of its keys
        pattern_inputs(m, call % 32)
        m.array("T")[12] = 3.0 * call
        outcome(m, 2)
        if call == 31:
            runs.clear()
    assert len(runs) == 64


def test_inputs_that_are_no_plain_floats_give_the_plain_codes_bits():
    # a recorded path reads an element as x - 0.0 (not float(x)): an int, a bool, a negative
    # zero, a string float() parses, a row of a two-dimensional array and gw's doubles (a float
    # subclass with arithmetic of its own) must give the plain code's bits or error, call by call
    def scenario(change):
        m = machine(2, 2.0, 1)
        row = []
        for call in range(6):
            m.array("T")[12] = 12.5 * call
            if call >= 3:  # the paths recorded on plain floats first
                change(m, call)
            try:
                m.python_areas[2](m)
            except BasicError as err:
                row.append(str(err))
            else:
                row.append(_bits(m))
        return row

    def rows(m, call):
        m.arrays["H"] = [[1.0, 2.0]] * 15

    changes = [lambda m, call: m.array("L").__setitem__(11, 1 + call % 2),  # an int: 1.0 or 2.0
               lambda m, call: m.array("M").__setitem__(7, call % 2 == 0),  # a bool
               lambda m, call: m.array("D").__setitem__(2, -0.0),
               lambda m, call: m.array("E").__setitem__(2, -0.0 if call % 2 else 0.0),
               lambda m, call: m.array("L").__setitem__(11, "1.25"),
               rows]
    for change in changes:
        recorded, plain = recorded_and_plain(lambda: scenario(change))
        assert recorded == plain
    assert isinstance(plain[-1], str) and "Type mismatch" in plain[-1]  # the rows

    def gw_scenario():
        m = Machine(screen=io.StringIO(), dialect="gw")
        m.load("10 DEFDBL A-Z: A = 1#/3: B = 2#/7: C = 4#/3\n")
        m.run()
        third, sevenths, coupler = m.scalar("A#"), m.scalar("B#"), m.scalar("C#")
        assert type(third) is not float and isinstance(third, float)  # doubles beyond a float's 53 bits
        for name in "LTWADERHMIFZQUXYVNP":  # the arrays the library programs read and write (API names)
            m.arrays[name] = [0.0] * 51
        binding.install(m)
        for name, elements in INPUTS[2].items():
            for index, value in elements.items():
                m.array(name)[index] = float(value)
        m.array("Z")[2], m.array("Q")[2], m.array("R")[11], m.array("L")[13] = 2.0, 1.0, sevenths, coupler
        m.set_scalar("G", 9.81)
        row = []
        for call in range(6):
            m.array("T")[12] = third * (call + 1)
            m.python_areas[2](m)
            row.append(_bits(m))
        return row

    recorded, plain = recorded_and_plain(gw_scenario)
    assert recorded == plain


def test_a_recorded_call_never_enters_numpy_errstate(monkeypatch):
    # numpy imported by something else (a notebook): the plain code is run under
    # numpy.errstate (methods may use numpy), a recorded path, which uses none, is not
    np = pytest.importorskip("numpy")
    entered = []
    real = np.errstate

    def errstate(**kwargs):
        entered.append(kwargs)
        return real(**kwargs)

    monkeypatch.setattr(np, "errstate", errstate)
    binding._recordings.clear()
    binding._calls.clear()
    m = machine(2, 2.0, 1)
    for call in range(10):
        m.array("T")[12] = 10.0 * call
        outcome(m, 2)
    assert len(entered) == 2  # the first call (plain) and the second (recorded while it ran)


def test_the_compiled_recording_drops_only_unused_values_that_cannot_raise():
    # a division, an abs and a call can raise (ZeroDivisionError, OverflowError, a domain
    # error): kept even when unused, as the plain code would raise there; an unused
    # product or part of a complex number is not computed
    from yaseer.linkages.tracing import _registers, _without_dead_lines

    lines = ["t0 = float(_a_L[1])", "t1 = t0 * 2.0", "t2 = t0 / t1", "t3 = abs(t0)", "t4 = _sqrt(t0)",
             "t5 = t0 - 1.0", "t6 = t5.real", "t7 = (t0 if t0 > t5 else t5)", "_a_X[1] = t7"]
    kept = _without_dead_lines(lines)
    assert kept == ["t0 = float(_a_L[1])", "t1 = t0 * 2.0", "t2 = t0 / t1", "t3 = abs(t0)", "t4 = _sqrt(t0)",
                    "t5 = t0 - 1.0", "t7 = (t0 if t0 > t5 else t5)", "_a_X[1] = t7"]
    renamed = _registers(kept)
    assert renamed[-1] == "_a_X[1] = " + renamed[-2].split(" = ")[0]  # the value written is the one computed
    names = {line.split(" = ")[0] for line in renamed if not line.startswith("_a_")}
    assert len(names) < 7  # variables taken again once their values are used no more
    namespace = {"_a_L": [0.0, 4.0], "_a_X": [0.0, 0.0], "_sqrt": math.sqrt}
    exec("\n".join(renamed), namespace)
    assert namespace["_a_X"][1] == 4.0


def test_a_recorded_path_makes_missing_arrays_where_the_plain_code_makes_them():
    # a path recorded on one machine, run on a fresh one whose output arrays do not exist yet
    # (the arrays are looked up together only where all exist): the same numbers, the same arrays
    def fresh():
        m = machine(2, 2.0, 1)
        return m, sorted(m.arrays)

    binding._recordings.clear()
    binding._calls.clear()
    for _ in range(3):
        outcome(machine(2, 2.0, 1), 2)  # recorded
    paths = len(binding._recordings[(2, None)])
    ran, before = fresh()
    ran.python_areas[2](ran)
    saved = binding.MAX_RECORDINGS
    binding.MAX_RECORDINGS = 0
    try:
        plain, plain_before = fresh()
        plain.python_areas[2](plain)
    finally:
        binding.MAX_RECORDINGS = saved
    assert before == plain_before and "X" not in before
    assert sorted(ran.arrays) == sorted(plain.arrays) and "X" in ran.arrays
    assert outcome(ran, 2) == outcome(plain, 2)
    assert len(binding._recordings[(2, None)]) == paths  # the kept path ran: nothing recorded again


def test_a_longer_array_takes_the_same_path_and_a_shorter_another():
    # an element read beyond a shorter array is 0 for the plain code: its IndexError in a
    # recorded path means another path; a longer array reads the same elements
    def scenario():
        m = machine(2, 2.0, 1)
        full = list(m.array("I"))
        row = []
        for call in range(9):
            m.arrays["I"] = full + [0.0] * 5 if call % 3 == 1 else full[:7] if call % 3 == 2 else list(full)
            m.array("T")[12] = 20.0 * call
            row.append(outcome(m, 2))
        return row

    recorded, plain = recorded_and_plain(scenario)
    assert recorded == plain
    binding._recordings.clear()
    binding._calls.clear()
    scenario()
    assert len(binding._recordings[(2, None)]) == 2  # the long and the full array share one path


def test_the_finiteness_test_is_each_value_finite():
    from yaseer.linkages.tracing import not_finite

    def fails(*values) -> bool:
        names = [f"x{k}" for k in range(len(values))]
        return eval(not_finite(names), {"_isfinite": math.isfinite, "_all": all, "_map": map,
                                        **dict(zip(names, values))})

    big = 1e308
    assert not fails(1.0) and fails(math.inf) and fails(math.nan)
    assert not fails(big, big, big) and not fails(-big, -big, 1.0)  # the sum overflows, each is finite
    assert fails(big, big, math.inf) and fails(math.inf, -math.inf) and fails(1.0, math.nan, 2.0)
    assert fails(big, -math.inf, big) and not fails(0.0, -0.0, 5e-324)


def _compiled_both_ways(number: int, z: float, q: float):
    """Program ``number``'s path for these inputs compiled as :meth:`Recorder.compile` does
    and as its recorded lines read, one statement a value (no rewriting)."""
    from yaseer.linkages import tracing

    made = {}
    real_compile = tracing.Recorder.compile

    def capture(recorder, epilogue, label, *how):
        made["lines"] = [str(line) for line in recorder.lines + epilogue]
        made["names"] = recorder.names
        return real_compile(recorder, epilogue, label, *how)

    m = machine(number, z, q) if number != 5 else machine_for(5)
    frame = binding._RecordingFrame(m, number, Recorder())
    binding.PROGRAMS[number](frame, None)
    tracing.Recorder.compile = capture
    try:
        optimised, _ = frame.recorded()
    finally:
        tracing.Recorder.compile = real_compile
    text = "def run(_M):\n" + "".join("    " + line.replace("\n", "\n    ") + "\n" for line in made["lines"])
    namespace = tracing.namespace(made["names"])
    exec(compile(text, "<as recorded>", "exec"), namespace)
    return optimised, namespace["run"]


def _bits(m: Machine):
    """Every number the programs write, as its bits (a signed zero told apart)."""
    return {name: [value.hex() if isinstance(value, float) else value for value in m.array(name)]
            for name in WRITTEN}, {name: float(value).hex() for name, value in m.scalars.items()}


@pytest.mark.parametrize("number,q", [(1, 2), (2, 1), (2, 3), (3, 3), (5, 1)])
def test_the_compiled_path_gives_the_bits_of_its_lines_as_recorded(number, q):
    # random inputs around the recorded call's: the rewritten path (reads and fetches batched,
    # guards merged, values fused, parts of floats not read) and the recorded lines one by one
    # write the same bits or both find another path
    from yaseer.linkages.tracing import Retrace

    optimised, as_recorded = _compiled_both_ways(number, 2.0, q)
    same_path = 0
    for trial in range(300):
        results = []
        for run in (optimised, as_recorded):
            m = machine(number, 2.0, q) if number != 5 else machine_for(5)
            state = random.Random(trial)
            for name, elements in INPUTS[number].items():
                for index, value in elements.items():
                    if (name, index) != ("L", 10):  # the branch: a choice, as Z(n) and Q(n)
                        m.array(name)[index] = value * state.uniform(0.8, 1.25)
            crank, index = CRANK[number]
            m.array(crank)[index] = state.uniform(-400.0, 400.0)
            try:
                run(m)
                results.append(_bits(m))
            except Retrace:
                results.append("another path")
            except (ArithmeticError, ValueError) as error:
                results.append(type(error).__name__)
        assert results[0] == results[1], trial
        same_path += results[0] != "another path"
    assert same_path > 100  # most random inputs take the recorded path


def test_a_part_of_a_float_is_not_read_and_of_anything_else_it_is():
    # a float's real part is itself and its imaginary part 0.0; a power's type depends on its
    # values (a negative base gives a complex number) and a complex value's parts are read
    from yaseer.linkages.tracing import _float_parts

    lines = ["t0 = float(_a_L[1])", "t1 = t0 * 2", "t2 = t1.imag", "t3 = -t1", "t4 = t3.real", "t5 = t0 ** 0.5",
             "t6 = t5.real", "t7 = _rect(1.0, t0)", "t8 = t7.imag", "t9 = (t4 if t4 > t6 else t1)",
             "t10 = t9.real", "t11 = _k1 * t0", "t12 = t11.real", "t13 = _k2 * t0", "t14 = t13.real",
             "_a_X[1] = t2 + t4 + t6 + t8 + t10 + t12 + t14"]
    assert _float_parts(lines, {"_k1": -1j, "_k2": 0.5}) == [
        "t0 = float(_a_L[1])", "t1 = t0 * 2", "t3 = -t1", "t5 = t0 ** 0.5", "t6 = t5.real", "t7 = _rect(1.0, t0)",
        "t8 = t7.imag", "t9 = (t3 if t3 > t6 else t1)", "t11 = _k1 * t0", "t12 = t11.real", "t13 = _k2 * t0",
        "_a_X[1] = 0.0 + t3 + t6 + t8 + t9 + t12 + t13"]


def test_a_complex_constant_keeps_the_signs_of_its_zeros():
    # -1j is complex(-0.0, -1.0), but its text compiles to (0.0, -1.0) when written "(-0-1j)",
    # and complex(0.0, -1.0)'s text "-1j" to (-0.0, -1.0): such constants are bound by name
    recorder = Recorder()
    height = recorder.read(0.0, "float(_M[0])")
    for constant in (-1j, complex(0.0, -1.0), complex(-0.0, 1.0), complex(2.0, -0.0), 1j, complex(1.5, 2.0)):
        product = height * constant
        run = recorder.compile([f"_done({product.name})"], "test")
        done = []
        run.__globals__["_done"] = done.append
        run([0.0])
        assert [math.copysign(1.0, part) for part in (done[0].real, done[0].imag)] == \
            [math.copysign(1.0, part) for part in (product.value.real, product.value.imag)], constant


@pytest.mark.parametrize("operation", ["x + 0.0", "0.0 + x", "x + 0", "x - -0.0", "x * 1.0", "1.0 * x", "x / 1.0",
                                       "x - 0.0", "z * 1.0", "1.0 * z", "z + 0.0", "z - 0.0", "z / 1.0"])
def test_an_operation_left_out_as_an_identity_is_one_for_every_later_value(operation):
    # recorded on x = 1.5 (z = x + 2j), the record is run on -0.0 and on infinities: it must give
    # what Python gives for each (x + 0.0 is +0.0 for x = -0.0; z * 1.0 is NaN for an infinite part)
    recorder = Recorder()
    x = recorder.read(1.5, "float(_M[0])")
    z = x + 2j
    result = eval(operation, {"x": x, "z": z})
    run = recorder.compile([f"_done({recorder.operand(result)})"], "test")
    for value in (-0.0, 0.0, math.inf, -math.inf, 2.5):
        done = []
        run.__globals__["_done"] = done.append
        run([value])
        expected = eval(operation, {"x": value, "z": value + 2j})
        assert repr(done[0]) == repr(expected), (operation, value)
        parts = (expected.real, expected.imag) if isinstance(expected, complex) else (expected,)
        got = (done[0].real, done[0].imag) if isinstance(done[0], complex) else (done[0],)
        assert [math.copysign(1.0, part) for part in got] == [math.copysign(1.0, part) for part in parts]


def test_the_key_function_gives_the_values_of_its_tests_as_written():
    # compile_key reads each element once and writes a test of a float as the comparison it
    # is; the values must be those of the tests' own texts, element by element, on any input
    from types import SimpleNamespace

    from yaseer.linkages.recordings import KEY_BUILTINS, compile_key

    tests = ["bool((float(_a_L[10]) == 0.0))", "bool((float(_a_W[5]) != 0))", "bool(float(_a_F[29]))",
             "bool((float(_a_Q[2]) == 2.0))", "bool((float(_a_Q[2]) == 3.0))", "bool(float(_a_F[34]))",
             "len(_a_T) > 3", "bool((float(_a_R[8]) < float(_a_R[9])))", "bool((float(_a_R[8]) <= 0))",
             "bool((float(_M.scalars.get('G', 0.0)) > 1e-05))", "bool((float(_a_L[10]) == 1.0))"]
    key = compile_key(tests)
    rng = random.Random(22)
    choices = [0.0, -0.0, 1.0, 2.0, 3.0, 2, 0, math.nan, math.inf, -math.inf, 1e-300, -5e-324]
    for _ in range(2000):
        pick = lambda: rng.choice(choices) if rng.random() < 0.8 else rng.uniform(-3.0, 3.0)  # noqa: E731
        arrays = {name: [pick() for _ in range(rng.choice((3, 40)) if name == "T" else 40)]
                  for name in ("L", "W", "F", "Q", "T", "R")}
        m = SimpleNamespace(arrays=arrays, scalars={"G": pick()})
        names = {"__builtins__": dict(KEY_BUILTINS), "_M": m, **{f"_a_{name}": a for name, a in arrays.items()}}
        expected = tuple(eval(test, names) for test in tests)
        got = key(m)
        assert got == expected and all(type(a) is type(b) for a, b in zip(got, expected))


def test_the_decision_tree_is_compiled_once_the_keys_met_stay_the_same(monkeypatch):
    # paths added one call after another (a warm run taking its kept paths) each bring a new
    # key: no tree is compiled for them; once no new key has come for SETTLE calls, one tree
    # is compiled and every later call goes through it, each call running the path of its key
    from types import SimpleNamespace

    from yaseer.linkages import recordings as module
    from yaseer.linkages.recordings import SETTLE, Recordings

    compiled = []
    real = module.compile_choice
    monkeypatch.setattr(module, "compile_choice", lambda tests, entries: compiled.append(len(entries))
                        or real(tests, entries))
    ran = []

    def path_for(q: float):
        def run(machine):
            if machine.arrays["Q"][2] != q:
                raise module.Retrace
            ran.append(q)
        return run

    tests = ("bool((float(_a_Q[2]) == 1.0))", "bool((float(_a_Q[2]) == 2.0))", "bool((float(_a_Q[2]) == 3.0))")
    m = SimpleNamespace(arrays={"Q": [0.0, 0.0, 0.0]}, scalars={})
    recordings = Recordings()
    for q in (1.0, 2.0, 3.0):
        m.arrays["Q"][2] = q
        recordings.add(path_for(q), tests, m)
        assert recordings.run(m) and ran[-1] == q
    assert compiled == []
    for call in range(3 * SETTLE):
        q = float(call % 3 + 1)
        m.arrays["Q"][2] = q
        assert recordings.run(m) and ran[-1] == q
    assert compiled == [3]


def _error_after_recording(name: str, array: list):
    """Program 2's outcome where array ``name`` is replaced by ``array`` after three calls on the
    universal dimensions (the paths recorded), and whether every array kept its elements."""
    m = machine(2, 2.0, 1)
    for angle in (10.0, 20.0, 30.0):
        m.array("T")[12] = angle
        outcome(m, 2)
    m.arrays[name] = array
    m.array("T")[12] = 40.0
    before = {name: list(m.array(name)) for name in WRITTEN}
    error = outcome(m, 2)
    return error, before == {name: list(m.array(name)) for name in WRITTEN}


def test_an_output_array_too_short_for_a_recorded_path_is_the_subscript_error_and_writes_nothing():
    # a path recorded with the universal dimensions run where X() holds 3 elements (it writes X(5)):
    # the error the plain code raises, every array as it was
    recorded, plain = recorded_and_plain(lambda: _error_after_recording("X", [0.0] * 4))
    assert recorded == plain == ("Subscript out of range (PROG 2)", True)


def _edge_floats() -> list[float]:
    """Signed zeros, subnormals, both ends of the normal range, infinities, NaN and random
    floats of every binade."""
    rng = random.Random(22)
    edges = [0.0, -0.0, 5e-324, -5e-324, 2.0 ** -1022, 2.0 ** -1022 * (1 - 2.0 ** -52),
             2.0 ** -1022 * (1 + 2.0 ** -52), 1.0, 1.0 - 2.0 ** -53, 1.0 + 2.0 ** -52, 2.0 ** 1023,
             2.0 ** 1023 * (1 - 2.0 ** -53), 1.7976931348623157e308,
             math.inf, -math.inf, math.nan, 90.0, 180.0, 360.0, -270.0, 1e-300, 3.0, 0.5]
    edges += [math.ldexp(rng.random() + 0.5, rng.randrange(-1074, 1024)) * rng.choice((1.0, -1.0))
              for _ in range(4000)]
    return edges + [-x for x in edges]


def _recorded_expression(function, value: float):
    """The recorded text of ``function`` (a name of tracing.TRACE) of a traced input of ``value``,
    compiled as a function of that input with the names a record has."""
    from yaseer.linkages import tracing

    recorder = Recorder()
    traced = recorder.read(value, "x")
    result = getattr(tracing.TRACE, function)(traced)
    expression = next(line for line in recorder.lines if str(line).startswith(f"{result.name} = ")).split(" = ", 1)[1]
    namespace = tracing.namespace(recorder.names)
    exec(compile(f"def f(t0):\n    return {expression}\n", "<expression>", "exec"), namespace)
    return expression, namespace["f"]


def _same_outcome(first, second, x) -> bool:
    """Whether first(x) and second(x) give the same bits, or raise the same exception type."""
    def run(function):
        try:
            return function(x).hex()
        except ArithmeticError as error:
            return type(error)
    return run(first) == run(second)


@pytest.mark.parametrize("name", ["radians", "degrees"])
def test_radians_and_degrees_are_recorded_as_the_product_they_compute(name):
    # reference: the math module's own function, on floats of every binade and the special values
    expression, recorded = _recorded_expression(name, 1.5)
    assert "_radians" not in expression and "_degrees" not in expression and " * " in expression
    function = getattr(math, name)
    assert all(_same_outcome(recorded, function, x) for x in _edge_floats())


def test_the_unit_of_a_length_is_recorded_without_frexp_where_the_float_is_normal():
    # reference: the plain code's ldexp(1.0, frexp(x)[1]), also where it raises (2**1023 and beyond)
    expression, recorded = _recorded_expression("unit_of", 1.5)
    assert expression.startswith("(_ulp(t0)")
    reference = lambda x: math.ldexp(1.0, math.frexp(x)[1])  # noqa: E731
    assert all(_same_outcome(recorded, reference, x) for x in _edge_floats())
    with pytest.raises(OverflowError):
        recorded(2.0 ** 1023)


def test_unit_degrees_is_recorded_with_the_product_for_radians():
    # reference: numerics.SCALAR.unit_degrees (quadrants exact, else cmath.rect of math.radians)
    from yaseer.linkages.numerics import SCALAR

    expression, recorded = _recorded_expression("unit_degrees", 30.0)
    assert "_radians" not in expression
    for x in _edge_floats()[:2000]:
        if math.isfinite(x):
            got, want = recorded(x), SCALAR.unit_degrees(x)
            assert (got.real.hex(), got.imag.hex()) == (want.real.hex(), want.imag.hex()), x


@pytest.mark.parametrize("made", [[[0.0, 0.0]] * 11, ["A"] * 11], ids=["rows", "strings"])
def test_an_output_array_of_rows_or_strings_is_the_type_mismatch_in_a_recorded_path(made):
    # V() is written, never read: a path recorded on numbers run where it holds rows or strings
    # raises the plain code's error and writes nothing
    recorded, plain = recorded_and_plain(lambda: _error_after_recording("V", list(made)))
    assert recorded == plain == ("Type mismatch (PROG 2)", True)


def test_gravity_read_by_a_recorded_path_gives_the_plain_codes_bits():
    # G is read as an element is (x - 0.0): an int, a bool and a negative zero as float(x) reads them
    def scenario():
        m = machine(2, 2.0, 1)
        row = []
        for call, gravity in enumerate((9.81, 9.81, 10, True, -0.0, 9.81, 3)):
            m.array("T")[12] = 15.0 * call
            m.scalars["G"] = gravity
            row.append(_bits(m) if outcome(m, 2) else None)
        return row

    recorded, plain = recorded_and_plain(scenario)
    assert recorded == plain
