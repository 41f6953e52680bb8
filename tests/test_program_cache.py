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
    """The text of the sources is hashed once; later starts read the hash kept in the cache
    while no source's size or time changes (an edit, or a damaged hash, is hashed again)."""
    program = {10: "PRINT 1"}
    base = program_cache.key(0, program)
    sources = copied_sources(tmp_path, monkeypatch)
    before = set(cache.glob("toolchain-*.key"))
    assert program_cache.key(0, program) == base  # the same text: the same key
    (remembered,) = set(cache.glob("toolchain-*.key")) - before
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
    assert len(set(cache.glob("toolchain-*.key")) - before) == 2


@pytest.mark.parametrize("bytecode", [True, False])
def test_nothing_is_written_inside_the_package(cache, monkeypatch, tmp_path, bytecode):
    base = program_cache.key(0, {10: "PRINT 1"})
    monkeypatch.setattr(sys, "dont_write_bytecode", not bytecode)
    sources = copied_sources(tmp_path, monkeypatch)
    listed = sorted(p.name for p in sources.iterdir())
    assert program_cache.key(0, {10: "PRINT 1"}) == base
    assert sorted(p.name for p in sources.iterdir()) == listed


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
    assert [path.name for path in cache.iterdir()
            if not path.name.endswith(".bin") and not path.name.startswith("toolchain-")] == []  # no temporary left


# ---------------------------------------------------------------- damaged, crowded and shared caches

FLIP_LISTINGS = {  # listing -> its output, worked out by hand
    "10 FOR I = 1 TO 3: PRINT I * 2: NEXT I\n": " 2 \n 4 \n 6 \n",
    "10 A$ = \"AB\": FOR K = 1 TO 2: A$ = A$ + \"C\": NEXT\n20 PRINT A$; LEN(A$)\n": "ABCC 4 \n",
    "10 DIM X(3): FOR I = 0 TO 3: X(I) = I * I: NEXT\n20 S = 0: FOR I = 0 TO 3: S = S + X(I): NEXT: PRINT S\n"
    "30 GOSUB 50: PRINT \"B\"\n40 END\n50 PRINT \"A\";: RETURN\n": " 14 \nAB\n",
}

FLIPPER = """
import os, random, sys
os.environ["YASEER_CACHE_DIR"] = sys.argv[1]
os.makedirs(sys.argv[1], mode=0o700)
import yaseer
from yaseer.basic.compile import program_cache
listings = {listings!r}
pristine = {{}}
for text, expected in listings.items():
    before = set(os.listdir(sys.argv[1]))
    assert yaseer.run(text).text == expected
    (name,) = [n for n in set(os.listdir(sys.argv[1])) - before if n.endswith(".bin")]
    path = os.path.join(sys.argv[1], name)
    with open(path, "rb") as f:
        pristine[text] = (path, f.read())
chance = random.Random(21)
for n in range({flips}):
    text = list(listings)[n % len(listings)]
    path, data = pristine[text]
    damaged = bytearray(data)
    if n % 25 == 24:
        damaged = damaged[:chance.randrange(len(damaged))]  # cut short
    else:
        for _ in range(chance.choice((1, 2))):
            damaged[chance.randrange(len(damaged))] ^= chance.randrange(1, 256)
    with open(path, "wb") as f:
        f.write(bytes(damaged))
    result = yaseer.run(text)
    if (result.text, result.error) != (listings[text], None):
        print("WRONG", n, repr(result.text), result.error)
        sys.exit(1)
    name = os.path.basename(path)[:-4]
    assert program_cache.load(name) is not None, "the damaged entry was not replaced by a good one"
print("ran", {flips})
"""


def test_flipped_bytes_in_entries_never_crash_hang_or_mislead(tmp_path):
    """Hundreds of entries damaged by 1-2 flipped bytes (or cut short), each then run: a fresh
    process (a crash or a hang would show as its status or its timeout) that always prints the
    listing's right output and leaves a good entry behind."""
    cache = tmp_path / "cache"
    flips = 300
    done = subprocess.run([sys.executable, "-c", FLIPPER.format(listings=FLIP_LISTINGS, flips=flips), str(cache)],
                          capture_output=True, text=True, timeout=600, cwd=ROOT)
    assert (done.returncode, done.stdout, done.stderr) == (0, f"ran {flips}\n", "")


def test_the_cache_is_pruned_to_its_limit_oldest_first(cache, monkeypatch):
    listings = [f"10 PRINT {n}\n" for n in range(12)]
    assert run(listings[0]) == " 0 \n"
    (first,) = entries(cache)
    size = first.stat().st_size
    monkeypatch.setattr(program_cache, "LIMIT", 4 * size + 500)  # every store prunes: its chance is over 1
    written = []
    for number, text in enumerate(listings):
        before = set(entries(cache))
        assert run(text) == f" {number} \n"
        (new,) = set(entries(cache)) - before if number else (first,)
        os.utime(new, ns=(number * 10**9, number * 10**9))  # distinct ages, whatever the clock's grain
        written.append(new)
    total = sum(path.stat().st_size for path in cache.iterdir())
    assert total <= program_cache.LIMIT
    kept = [path for path in written if path.exists()]
    assert kept == written[-len(kept):] and len(kept) >= 3  # the newest kept, the oldest gone


def test_an_entry_too_big_for_the_cache_is_not_kept(cache, monkeypatch):
    monkeypatch.setattr(program_cache, "LIMIT", 400)
    assert run() == EXPECTED
    assert entries(cache) == []


def test_a_directory_others_can_write_is_not_used(cache):
    assert run() == EXPECTED
    (entry,) = entries(cache)
    good = entry.read_bytes()
    cache.chmod(0o777)
    try:
        assert program_cache.key(0, {10: "PRINT 1"}) is None
        entry.unlink()
        assert run() == EXPECTED
        assert entries(cache) == []  # nothing stored, and so nothing read, in a shared directory
    finally:
        cache.chmod(0o700)
    assert good and run() == EXPECTED and len(entries(cache)) == 1


def test_the_directory_is_made_private(tmp_path, monkeypatch):
    monkeypatch.setenv("YASEER_CACHE_DIR", str(tmp_path / "new" / "cache"))
    assert run() == EXPECTED
    assert (tmp_path / "new" / "cache").stat().st_mode & 0o777 == 0o700


def test_an_entry_in_a_directory_others_can_write_is_never_read(cache):
    """The sealed reader itself refuses a shared directory (not only the callers that ask first):
    a valid entry there is not handed to marshal."""
    from yaseer import sealed_cache

    assert run() == EXPECTED
    (entry,) = entries(cache)
    key = entry.stem
    assert sealed_cache.read_sealed(entry.name, key, program_cache.MAGIC) is not None
    cache.chmod(0o777)
    try:
        assert sealed_cache.read_sealed(entry.name, key, program_cache.MAGIC) is None
    finally:
        cache.chmod(0o700)


@pytest.mark.parametrize("dialect", ["casio", "gw"])
def test_the_key_is_the_same_in_every_process(dialect):
    """The key holds the dialect's repr: a field whose repr names an address (a function's
    default repr) would make every process miss the cache."""
    probe = ("import sys; from yaseer.basic.compile import program_cache\n"
             "from yaseer.basic.dialects.dialect import get_dialect\n"
             "print(program_cache.key(0, {10: 'PRINT 1'}, (), get_dialect(sys.argv[1])))")
    keys = {subprocess.run([sys.executable, "-c", probe, dialect], capture_output=True, text=True, check=True).stdout
            for _ in range(2)}
    assert len(keys) == 1 and keys != {"None\n"}


def installed_sources(tmp_path: Path, monkeypatch) -> tuple[Path, Path]:
    """A copy of yaseer/basic laid out as pip installs it (site/yaseer/basic beside
    site/yaseer-VERSION.dist-info/RECORD, written after the files, listing each file's SHA-256 and
    size as pip does), which the cache keys on from now; (the sources, the RECORD file)."""
    import base64
    import hashlib

    from yaseer.version import __version__

    site = tmp_path / "site"
    sources = site / "yaseer" / "basic"
    rows = []
    for path in sorted(Path(program_cache._SOURCES).rglob("*")):
        if path.suffix in (".py", ".lark") and "__pycache__" not in path.parts:
            copy = sources / path.relative_to(program_cache._SOURCES)
            copy.parent.mkdir(parents=True, exist_ok=True)
            data = path.read_bytes()
            copy.write_bytes(data)
            digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            rows.append(f"{copy.relative_to(site).as_posix()},sha256={digest},{len(data)}")
    record = site / f"yaseer-{__version__}.dist-info" / "RECORD"
    record.parent.mkdir()
    record.write_text("\n".join(["yaseer/__init__.py,sha256=x,1", *rows, f"{record.relative_to(site).as_posix()},,"]) + "\n")
    newest = max(p.stat().st_mtime_ns for p in sources.rglob("*") if p.is_file())
    os.utime(record, ns=(newest + 10**9, newest + 10**9))  # written after the files, as pip writes it
    monkeypatch.setattr(program_cache, "_SOURCES", str(sources))
    monkeypatch.setattr(program_cache, "_fingerprint", None)
    return sources, record


def test_an_installed_copy_takes_the_hashes_pip_recorded_instead_of_reading_the_text(cache, monkeypatch, tmp_path):
    """The first start after a regular install keys the cache on the SHA-256 hashes pip listed for the
    sources in RECORD (no source text read); a reinstall listing other hashes gives another key."""
    program = {10: "PRINT 1"}
    sources, record = installed_sources(tmp_path, monkeypatch)

    def hashing(names):
        raise AssertionError("the sources' text was read")

    monkeypatch.setattr(program_cache, "_text_fingerprint", hashing)
    installed = program_cache.key(0, program)
    listed = record.read_text()
    compiler_row = next(row for row in listed.splitlines() if row.startswith("yaseer/basic/compile/compiler.py,"))
    name, hashed, size = compiler_row.split(",")
    written = record.stat().st_mtime_ns
    record.write_text(listed.replace(compiler_row, f"{name},sha256=other{hashed[len('sha256=') + 5:]},{size}"))
    os.utime(record, ns=(written, written))
    monkeypatch.setattr(program_cache, "_fingerprint", None)
    for remembered in cache.glob("toolchain-*.key"):  # the same sizes and times: make it look again
        remembered.unlink()
    assert program_cache.key(0, program) not in (installed, None)


@pytest.mark.parametrize("change", ["edited after", "size", "unlisted", "no record"])
def test_an_installed_copy_whose_record_cannot_stand_for_its_text_is_hashed(cache, monkeypatch, tmp_path, change):
    """A source modified after RECORD was written, listed with another size or not listed, or no
    RECORD at all (an editable install, a checkout): the text is read and hashed, as before."""
    program = {10: "PRINT 1"}
    sources, record = installed_sources(tmp_path, monkeypatch)
    grammar = sources / "source" / "grammar.lark"
    listed = record.read_text()
    row = next(row for row in listed.splitlines() if row.startswith("yaseer/basic/source/grammar.lark,"))
    written = record.stat().st_mtime_ns
    if change == "edited after":
        os.utime(grammar, ns=(written + 1, written + 1))
    elif change == "size":
        record.write_text(listed.replace(row, row.rsplit(",", 1)[0] + ",1"))
    elif change == "unlisted":
        record.write_text(listed.replace(row + "\n", ""))
    else:
        record.unlink()
    if record.exists():
        os.utime(record, ns=(written, written))
    hashed = []
    text_fingerprint = program_cache._text_fingerprint
    monkeypatch.setattr(program_cache, "_text_fingerprint", lambda names: hashed.append(names) or text_fingerprint(names))
    assert program_cache.key(0, program) is not None and len(hashed) == 1
    assert "source/grammar.lark" in hashed[0]
