"""The on-disk cache of compiled programs (yaseer.basic.compile.program_cache): a warm
run gives the same output without importing the parser; the key changes with
the program, the area and the compiler's sources; bad entries are ignored; it
can be switched off; it never lives in the checkout; concurrent runs are safe."""

from __future__ import annotations

import ast
import io
import os
import subprocess
import sys
from pathlib import Path

import pytest

from yaseer.basic.compile import program_cache
from yaseer.basic.dialects.dialect import CASIO, GW
from yaseer.basic.machine.machine import Machine

ROOT = Path(__file__).resolve().parents[1]
LISTING = "10 FOR I=1 TO 3: PRINT I*I;: NEXT\n20 GOSUB 100: PRINT \"END\"\n30 END\n100 PRINT \"SUB\";: RETURN\n"
EXPECTED = " 1  4  9 SUBEND\n"  # as GW-BASIC prints it


def run(text: str = LISTING) -> str:
    screen = io.StringIO()
    machine = Machine(screen=screen)
    machine.load(text)
    machine.run()
    return screen.getvalue()


@pytest.fixture
def cache(tmp_path, monkeypatch) -> Path:
    monkeypatch.setenv("YASEER_CACHE_DIR", str(tmp_path / "cache"))
    return tmp_path / "cache"


def entries(directory: Path) -> list[Path]:
    return sorted(directory.glob("*.bin")) if directory.exists() else []


def test_a_warm_run_reads_the_entry_and_prints_the_same(cache, monkeypatch):
    assert run() == EXPECTED
    assert len(entries(cache)) == 1
    calls = []
    monkeypatch.setattr("yaseer.basic.compile.compiler.compile_area", lambda *a, **k: calls.append(a))
    assert run() == EXPECTED
    assert calls == []  # compiled program taken from the cache


HEAVY = ("lark", "yaseer.basic.source.parser", "yaseer.basic.compile.compiler", "numpy", "yaseer.linkages", "yaseer.animation")


def imported_by_run(listing: Path, cache: Path) -> tuple[str, list[str]]:
    """The output of ``yaseer run LISTING`` in a fresh process, and which HEAVY modules it imported."""
    probe = ("import sys, runpy; sys.argv = ['yaseer', 'run', sys.argv[1]]\n"
             "try:\n    runpy.run_module('yaseer', run_name='__main__')\nexcept SystemExit:\n    pass\n"
             f"print(sorted(m for m in {HEAVY!r} if m in sys.modules))")
    env = dict(os.environ, YASEER_CACHE_DIR=str(cache))
    done = subprocess.run([sys.executable, "-c", probe, str(listing)], capture_output=True, text=True, env=env)
    *output, modules = done.stdout.splitlines()
    return "\n".join(output) + "\n", ast.literal_eval(modules)


def test_a_warm_process_imports_neither_parser_nor_lark(cache):
    listing = cache.parent / "prog.bas"
    listing.write_text(LISTING)
    cold_output, cold = imported_by_run(listing, cache)
    warm_output, warm = imported_by_run(listing, cache)
    assert cold_output == warm_output == EXPECTED
    assert "yaseer.basic.source.parser" in cold and "lark" not in cold  # the parser runs generated tables
    assert warm == []


def test_a_listing_calling_the_programs_runs_without_numpy(cache):
    listing = ROOT / "listings" / "example1.bas"
    imported_by_run(listing, cache)
    output, warm = imported_by_run(listing, cache)
    assert output == (ROOT / "tests" / "golden" / "example1.txt").read_text()
    assert warm == ["yaseer.linkages"]  # the programs' formulas, on Python floats


def copied_sources(tmp_path: Path, monkeypatch) -> Path:
    """A copy of yaseer/basic's sources and its wings' (new modification times) that the cache keys on from now."""
    sources = tmp_path / "basic"
    for path in Path(program_cache._SOURCES).rglob("*"):
        if path.suffix in (".py", ".lark") and "__pycache__" not in path.parts:
            copy = sources / path.relative_to(program_cache._SOURCES)
            copy.parent.mkdir(parents=True, exist_ok=True)
            copy.write_bytes(path.read_bytes())
    monkeypatch.setattr(program_cache, "_SOURCES", str(sources))
    monkeypatch.setattr(program_cache, "_fingerprint", None)
    return sources


def test_the_key_follows_program_area_entries_and_sources(cache, monkeypatch, tmp_path):
    program = {10: "PRINT 1"}
    base = program_cache.key(0, program)
    assert base == program_cache.key(0, dict(program))
    assert base != program_cache.key(0, {10: "PRINT 2"})
    assert base != program_cache.key(0, {11: "PRINT 1"})
    assert base != program_cache.key(1, program)
    assert base != program_cache.key(0, program, entry_lines=(10,))
    assert program_cache.key(0, program, dialect=CASIO) != program_cache.key(0, program, dialect=GW)
    sources = copied_sources(tmp_path, monkeypatch)
    assert program_cache.key(0, program) == base  # the same sources: the same key
    (sources / "source" / "grammar.lark").write_text((sources / "source" / "grammar.lark").read_text() + "\n// edited\n")
    monkeypatch.setattr(program_cache, "_fingerprint", None)
    assert program_cache.key(0, program) != base  # an edited grammar invalidates every entry


def test_the_sources_hash_is_remembered_for_their_sizes_and_times(cache, monkeypatch, tmp_path):
    """The text of the sources is hashed once; later starts read the hash kept beside their
    bytecode while no source's size or time changes (an edit, or a damaged hash, is hashed again)."""
    program = {10: "PRINT 1"}
    base = program_cache.key(0, program)
    monkeypatch.setattr(sys, "dont_write_bytecode", False)
    sources = copied_sources(tmp_path, monkeypatch)
    assert program_cache.key(0, program) == base  # the same text: the same key
    (remembered,) = (sources / "__pycache__").glob("toolchain-*.key")
    remembered.write_bytes(b"short")
    monkeypatch.setattr(program_cache, "_fingerprint", None)
    assert program_cache.key(0, program) == base  # damaged: hashed again and replaced
    assert len(remembered.read_bytes()) == 64
    text_fingerprint = program_cache._text_fingerprint

    def hashing_again(names):
        raise AssertionError("the sources were hashed again")

    monkeypatch.setattr(program_cache, "_text_fingerprint", hashing_again)
    monkeypatch.setattr(program_cache, "_fingerprint", None)
    assert program_cache.key(0, program) == base  # read back, not hashed
    grammar = sources / "source" / "grammar.lark"
    grammar.write_text(grammar.read_text() + "\n// edited\n")
    monkeypatch.setattr(program_cache, "_fingerprint", None)
    with pytest.raises(AssertionError, match="hashed again"):
        program_cache.key(0, program)
    monkeypatch.setattr(program_cache, "_text_fingerprint", text_fingerprint)
    assert program_cache.key(0, program) != base
    assert len(list((sources / "__pycache__").glob("toolchain-*.key"))) == 2


def test_the_sources_hash_is_not_written_where_python_writes_no_bytecode(cache, monkeypatch, tmp_path):
    base = program_cache.key(0, {10: "PRINT 1"})
    monkeypatch.setattr(sys, "dont_write_bytecode", True)
    sources = copied_sources(tmp_path, monkeypatch)
    assert program_cache.key(0, {10: "PRINT 1"}) == base
    assert not (sources / "__pycache__").exists()


@pytest.mark.parametrize("damage", [b"", b"not marshal data", b"\x00" * 40])
def test_a_damaged_entry_is_ignored_and_replaced(cache, damage):
    assert run() == EXPECTED
    (entry,) = entries(cache)
    entry.write_bytes(damage)
    assert program_cache.load(entry.stem) is None
    assert run() == EXPECTED
    assert program_cache.load(entry.stem) is not None  # rewritten


def test_an_entry_under_another_name_is_not_taken(cache):
    assert run() == EXPECTED
    (entry,) = entries(cache)
    other = "f" * len(entry.stem)
    (cache / f"{other}.bin").write_bytes(entry.read_bytes())
    assert program_cache.load(other) is None  # it carries its own key


def test_an_empty_cache_dir_switches_the_cache_off(tmp_path, monkeypatch):
    monkeypatch.setenv("YASEER_CACHE_DIR", "")
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert program_cache.key(0, {10: "PRINT 1"}) is None
    assert run() == EXPECTED
    assert list(tmp_path.iterdir()) == []


def test_the_default_place_is_the_user_cache_not_the_checkout(tmp_path, monkeypatch):
    monkeypatch.delenv("YASEER_CACHE_DIR", raising=False)
    monkeypatch.setenv("XDG_CACHE_HOME", str(tmp_path))
    assert Path(program_cache.cache_dir()) == tmp_path / "yaseer" / "compiled"
    monkeypatch.delenv("XDG_CACHE_HOME")
    assert ROOT not in Path(program_cache.cache_dir()).parents
    assert Path(program_cache.cache_dir()) == Path.home() / ".cache" / "yaseer" / "compiled"
    monkeypatch.setenv("XDG_CACHE_HOME", "relative/dir")  # not absolute: ignored, as XDG says
    assert Path(program_cache.cache_dir()) == Path.home() / ".cache" / "yaseer" / "compiled"
    monkeypatch.setenv("HOME", "")
    monkeypatch.setattr("os.path.expanduser", lambda path: path)  # no home directory at all
    assert program_cache.cache_dir() is None
    assert program_cache.key(0, {10: "PRINT 1"}) is None


def test_concurrent_first_runs_all_print_right_and_leave_one_entry(cache, tmp_path):
    listing = tmp_path / "prog.bas"
    listing.write_text(LISTING)
    env = dict(os.environ, YASEER_CACHE_DIR=str(cache))
    processes = [subprocess.Popen([sys.executable, "-m", "yaseer", "run", str(listing)], stdout=subprocess.PIPE,
                                  text=True, env=env, cwd=str(ROOT)) for _ in range(6)]
    outputs = [process.communicate(timeout=120)[0] for process in processes]
    assert outputs == [EXPECTED] * 6
    assert len(entries(cache)) == 1
    assert [path.name for path in cache.iterdir() if not path.name.endswith(".bin")] == []  # no temporary left
