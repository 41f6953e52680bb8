"""The library programs' recorded paths kept on disk (yaseer.linkages.recording_cache): a listing
run again prints what it printed with no cache and with a cold one (and what the real-mechanism
models of yaseer.reference compute), records and compiles nothing, reads no byte that its seal
did not vouch for, unpickles nothing, and records again whatever a flipped byte damaged."""

from __future__ import annotations

import marshal
import math
import os
import random
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import yaseer
from yaseer import binding, sealed_cache
from yaseer.linkages import recording_cache, tracing
from yaseer.reference.paper_mechanisms import example_columns

ROOT = Path(__file__).resolve().parents[1]
LISTINGS = ROOT / "listings"

PROBE = """\
import sys
from yaseer.linkages import recording_cache, tracing
compiled = []
path, key = tracing.Recorder.compile, recording_cache.compile_key
def counting_path(self, *args, **kwargs):
    compiled.append(1)
    return path(self, *args, **kwargs)
def counting_key(*args, **kwargs):
    compiled.append(1)
    return key(*args, **kwargs)
tracing.Recorder.compile = counting_path
recording_cache.compile_key = counting_key
from yaseer.cli import main
status = main(["run", "--format", "csv", sys.argv[1]])
print("PROBE", status, len(compiled), "pickle" in sys.modules)
"""


def run_process(n: int, cache: str) -> tuple[str, int]:
    """Example ``n`` printed as CSV by a fresh process with the cache ``cache`` ("": none), and how
    many paths and key functions the cache had that process compile."""
    env = dict(os.environ, YASEER_CACHE_DIR=cache)
    done = subprocess.run([sys.executable, "-c", PROBE, str(LISTINGS / f"example{n}.bas")], capture_output=True,
                          text=True, env=env, timeout=300, cwd=ROOT)
    *printed, probe = done.stdout.splitlines()
    word, status, compiled, pickle_loaded = probe.split()
    assert (word, status, pickle_loaded, done.stderr) == ("PROBE", "0", "False", "")
    return "\n".join(printed) + "\n", int(compiled)


@pytest.mark.parametrize("n", [2, 5])
def test_a_warm_process_prints_the_same_and_records_nothing(n, tmp_path):
    cache = str(tmp_path / "cache")
    none, compiled_without = run_process(n, "")
    cold, compiled_cold = run_process(n, cache)
    warm, compiled_warm = run_process(n, cache)
    assert none == cold == warm
    assert compiled_cold > 0 and compiled_warm == 0
    assert any(name.endswith(".rec") for name in os.listdir(cache))
    # and what it prints is the real mechanism (as tests/test_reference_examples.py checks it)
    printed = np.array([[float(v) for v in line.split(",")] for line in warm.splitlines()])
    model = example_columns(n, list(printed[:, 0]))
    if n == 2:  # the listing's churning load uses V(4), the model the velocity along the 90.1-degree axis
        model[:, 1:] *= math.sin(math.radians(90.1)) ** 2
    assert (np.abs(printed - model) / np.abs(model).max(axis=0)).max() < 1e-11


@pytest.fixture
def cache(tmp_path, monkeypatch) -> Path:
    monkeypatch.setenv("YASEER_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache"


@pytest.fixture
def compiled(monkeypatch) -> list:
    """The paths and the key functions compiled in this process from now on (one item each)."""
    counted: list = []
    path, key = tracing.Recorder.compile, recording_cache.compile_key

    def counting_path(self, *args, **kwargs):
        counted.append("path")
        return path(self, *args, **kwargs)

    def counting_key(*args, **kwargs):
        counted.append("key")
        return key(*args, **kwargs)

    monkeypatch.setattr(tracing.Recorder, "compile", counting_path)
    monkeypatch.setattr(recording_cache, "compile_key", counting_key)
    return counted


def new_process() -> None:
    """Forget this process's recordings and kept paths, as a new process starts."""
    binding._recordings.clear()
    binding._calls.clear()
    binding._shelves.clear()


def run_example(n: int) -> str:
    new_process()
    result = yaseer.run(LISTINGS / f"example{n}.bas")
    assert result.error is None
    return result.text


def test_flipped_bytes_in_kept_paths_are_recorded_again(cache, compiled, monkeypatch):
    """Each kept file (an index, a path, a key function) damaged in turn by flipped bytes, or cut
    short: the run prints the same, compiles again what it cannot trust, and leaves sound files behind."""
    monkeypatch.setenv("YASEER_CACHE_DIR", "")
    expected = run_example(5)
    monkeypatch.setenv("YASEER_CACHE_DIR", str(cache))
    assert run_example(5) == expected
    kept = sorted(cache.glob("*.rec"))
    assert len(kept) >= 3
    chance = random.Random(22)
    for path in kept:
        good = path.read_bytes()
        for damage in range(4):
            damaged = bytearray(good)
            if damage == 3:
                damaged = damaged[:chance.randrange(len(damaged))]
            else:
                for _ in range(damage + 1):
                    damaged[chance.randrange(len(damaged))] ^= chance.randrange(1, 256)
            path.write_bytes(bytes(damaged))
            compiled.clear()
            assert run_example(5) == expected
            assert compiled  # what was damaged was made again
            assert sealed_cache.read_sealed(path.name, path.stem, recording_cache.MAGIC) is not None  # and kept
        compiled.clear()
        assert run_example(5) == expected and not compiled


def test_marshal_reads_only_sealed_bytes_and_nothing_is_unpickled(cache, compiled, monkeypatch):
    run_example(5)
    vouched: list = []
    read = sealed_cache.read_sealed

    def reading(*args):
        data = read(*args)
        vouched.append(data)
        return data

    class Marshal:
        dumps = staticmethod(marshal.dumps)

        @staticmethod
        def loads(data):
            assert any(data is sealed for sealed in vouched), "unsealed bytes given to marshal"
            return marshal.loads(data)

    import pickle

    def refuse(*args, **kwargs):
        raise AssertionError("something was unpickled")

    monkeypatch.setattr(sealed_cache, "read_sealed", reading)
    monkeypatch.setattr(sealed_cache, "marshal", Marshal)  # the one place entries are unmarshalled
    for name in ("load", "loads", "Unpickler"):
        monkeypatch.setattr(pickle, name, refuse)
    compiled.clear()
    assert run_example(5) == (ROOT / "tests" / "golden" / "example5.txt").read_text()
    assert not compiled and len(vouched) >= 2


def test_a_forged_entry_is_never_loaded(cache, compiled, tmp_path):
    """A file in a kept path's place whose seal is not the entry's own (another key, or none): the
    code in it is never run, and the path is recorded again."""
    expected = run_example(2)
    witness = tmp_path / "ran"
    forged = compile(f"open({str(witness)!r}, 'w').close()", "<forged>", "exec")
    for path in cache.glob("*.rec"):
        body = marshal.dumps((path.stem, forged, ()))
        path.write_bytes(recording_cache.MAGIC + sealed_cache.seal("ab" * 64, body) + body)
    compiled.clear()
    assert run_example(2) == expected
    assert compiled and not witness.exists()


def test_a_cache_others_can_write_is_neither_read_nor_written(cache, compiled):
    run_example(5)
    cache.chmod(0o777)
    try:
        for path in cache.glob("*.rec"):
            path.unlink()
        compiled.clear()
        run_example(5)
        assert compiled and list(cache.glob("*.rec")) == []
    finally:
        cache.chmod(0o700)


def test_the_key_follows_the_sources(cache, tmp_path):
    source = tmp_path / "binding_like.py"
    source.write_text("A = 1\n")
    first = recording_cache.toolchain((str(source),))
    recording_cache._toolchains.clear()
    assert recording_cache.toolchain((str(source),)) == first
    source.write_text("A = 2\n")
    recording_cache._toolchains.clear()
    assert recording_cache.toolchain((str(source),)) != first
    assert recording_cache.toolchain() != first


def test_paths_kept_for_other_inputs_give_the_plain_codes_numbers(cache, compiled):
    """Random four-bar calls (each Q(2), forces or not, crank turning or at rest, either assembly)
    fill the cache; a second process's other random calls take kept paths where their inputs match,
    and every call gives what the plain code gives."""
    from test_binding_recorded import machine, outcome

    def calls(seed: int, plain: bool) -> list:
        new_process()
        saved = binding.MAX_RECORDINGS
        binding.MAX_RECORDINGS = 0 if plain else saved
        rng = random.Random(seed)
        m = machine(2, 0.0, 1)
        row = []
        try:
            for _ in range(40):
                moving = rng.random() < 0.7
                m.array("Z")[2], m.array("Q")[2] = rng.choice([0.0, 2.0]), rng.choice([1, 2, 3, 4])
                m.array("L")[10] = rng.choice([0.0, 1.0])
                m.array("T")[12] = rng.uniform(0, 360)
                m.array("W")[5], m.array("A")[5] = (4.0, -1.0) if moving else (0.0, 0.0)
                row.append(outcome(m, 2))
        finally:
            binding.MAX_RECORDINGS = saved
        return row

    calls(7, plain=False)
    assert len(binding._recordings[(2, None)]) > 4
    compiled.clear()
    kept = calls(8, plain=False)
    assert compiled.count("path") < len(binding._recordings[(2, None)])  # some paths came from the cache
    assert kept == calls(8, plain=True)


def test_a_run_without_a_cache_keeps_nothing(tmp_path, monkeypatch):
    monkeypatch.setenv("YASEER_CACHE_DIR", "")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert run_example(2) == (ROOT / "tests" / "golden" / "example2.txt").read_text()
    assert list(tmp_path.iterdir()) == []


def test_a_translated_program_is_kept_and_a_later_run_runs_it_from_the_first_call(cache, compiled, monkeypatch):
    """A path taken more than straight_line.WARM times is translated once (the program of double
    operations of linkages/_straight_fast.c) and the program kept: a new process's first call of the
    path runs it, translating nothing, and prints what the run without any cache printed; a damaged
    entry is not used (its seal): the path is recorded and translated again."""
    from yaseer.linkages import path_translation, straight_line

    if straight_line._module() is None:
        pytest.skip("the C accelerator is not built here: no program to keep")
    calls = 2 * straight_line.WARM
    listing = (
        "10 L(10)=1: L(11)=1.2: L(12)=.3: L(13)=1: L(14)=.8: T(11)=20: W(5)=4: A(5)=-1: D(2)=.1: E(2)=.2\n"
        f"20 FOR K=1 TO {calls}: T(12)=K*7.3: GOSUB PROG 2: S=S+T(13)+W(7)+A(6): NEXT K\n30 PRINT S\n")
    monkeypatch.setenv("YASEER_CACHE_DIR", "")
    new_process()
    expected = yaseer.run(listing).text
    translated: list = []
    translate = path_translation.translate

    def counting(*args):
        translated.append(1)
        return translate(*args)

    monkeypatch.setattr(path_translation, "translate", counting)
    monkeypatch.setenv("YASEER_CACHE_DIR", str(cache))
    new_process()
    assert yaseer.run(listing).text == expected
    assert translated == [1]  # the one path, translated once
    new_process()
    translated.clear()
    assert yaseer.run(listing).text == expected and not translated
    path = binding._recordings[(2, None)]._paths[0]
    assert path.state == "running" and path.counts[0] == calls - 1  # every call but the recorded one
    def stored(kept):
        return sealed_cache.read_marshalled(kept.name, kept.stem, recording_cache.MAGIC) or ()

    programs = [kept for kept in cache.glob("*.rec") if len(stored(kept)) == 4 and type(stored(kept)[3]) is dict]
    assert len(programs) == 1  # kept in the path's own entry
    damaged = bytearray(programs[0].read_bytes())
    damaged[-5] ^= 0x40
    programs[0].write_bytes(bytes(damaged))
    new_process()
    assert yaseer.run(listing).text == expected and translated == [1]


def test_a_kept_path_whose_arrays_the_first_call_makes_is_taken_from_the_second_call(cache, compiled):
    """The listing sets no Z(2): its first call's plain code makes the array Z, which the kept
    path's tests read; a warm run runs that first call plainly, takes the kept path at the second,
    and records nothing (before, it recorded the path again at its first call, every run)."""
    listing = ("10 L(10)=1: L(11)=1.2: L(12)=.3: L(13)=1: L(14)=.8: T(11)=20: W(5)=4: A(5)=-1\n"
               "20 FOR K=1 TO 5: T(12)=K*7.3: GOSUB PROG 2: PRINT T(13); W(7): NEXT K\n")
    new_process()
    cold = yaseer.run(listing).text
    assert compiled  # recorded (and its key compiled)
    compiled.clear()
    new_process()
    assert yaseer.run(listing).text == cold and not compiled
