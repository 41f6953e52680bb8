"""An on-disk cache of compiled program areas, so a listing run again starts
without parsing or compiling it (and without importing lark).

Key: a BLAKE2 hash of the area's lines and every other input of the compile
(area number, extra entry lines, the machine's dialect), of yaseer's version, of the Python that
runs it (bytecode is version-specific), and of the text of every source file
that turns text into compiled code (every ``.py`` and ``.lark`` of ``yaseer/basic`` and its wings),
so editing the grammar or the compiler invalidates every entry.  Reading and
hashing that text cost every start about 0.8 ms, so its hash is remembered in
the cache directory itself: ``toolchain-<S>.key`` holds it for the sources whose
names, sizes and modification times (in nanoseconds) hash to ``S`` (Python's own
bytecode cache trusts size and modification time the same way).  A start then
only asks the sources' sizes and times (about 0.05 ms) and reads that one file.
Sources copied elsewhere or reinstalled are hashed again once (and give the same
key when their text is the same); a file rewritten with new text of the same size
in the same nanosecond would go unnoticed.  Nothing is written inside the
installed package.

Value: the :class:`~yaseer.basic.compile.compiled.CompiledArea` fields and the code object
of each generated function, stored with :mod:`marshal` behind a header of
:data:`MAGIC` and a BLAKE2 hash of the marshalled bytes keyed with the entry's own
key.  :mod:`marshal` trusts its input (damaged code objects can crash or mislead
the interpreter), so the hash is checked before ``marshal.loads`` sees a byte: a
damaged, truncated or renamed entry is never loaded, the area is compiled again and
the entry rewritten.

Where: ``$YASEER_CACHE_DIR`` if set (empty: no cache), else
``$XDG_CACHE_HOME/yaseer/compiled`` (an absolute XDG_CACHE_HOME; default
``~/.cache/yaseer/compiled``; no cache without a home directory); never inside
the checkout.  The directory is made private (mode 0700) and used only while it
is owned by the user and writable by no one else: compiled code is never read
from a place another user could write.  It is kept near :data:`LIMIT` bytes:
now and then after an entry is written (on average once for every sixteenth of
the limit written) the oldest entries are removed until the rest fit; an area
whose entry alone would take over a quarter of it is not kept.
Safe under concurrent runs: an entry is written to a temporary file in the same
directory and renamed into place (atomic).  Any OSError (read-only home, full
disk) just means no cache.
"""

from __future__ import annotations

import marshal
import os
import sys

try:  # the built-in module: hashlib would load OpenSSL (~10 ms of start-up)
    from _blake2 import blake2b
except ImportError:  # pragma: no cover - other Pythons
    from hashlib import blake2b

from yaseer.version import __version__
from yaseer.basic.compile.compiled import CompiledArea

FORMAT = 1  # bump when the stored layout changes
# Paths are os.path strings here, not pathlib (whose import costs a few ms of every start).
# yaseer/basic: every wing (the dialects, the scanner and grammar, the compiler, the number models) shapes the code
_SOURCES = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))


def _source_files():
    """(path relative to yaseer/basic, os.stat_result) of every .py and .lark file of yaseer/basic and its wings."""
    found = []
    with os.scandir(_SOURCES) as entries:
        wings = []
        for entry in entries:
            if entry.name.endswith((".py", ".lark")):
                found.append((entry.name, entry.stat()))
            elif entry.is_dir() and entry.name != "__pycache__":
                wings.append(entry.name)
    for wing in wings:
        with os.scandir(os.path.join(_SOURCES, wing)) as entries:
            found.extend((f"{wing}/{entry.name}", entry.stat()) for entry in entries
                         if entry.name.endswith((".py", ".lark")))
    return sorted(found)


def cache_dir() -> str | None:
    """The directory of the cache, or None when it is switched off."""
    configured = os.environ.get("YASEER_CACHE_DIR")
    if configured is not None:
        return configured or None
    base = os.environ.get("XDG_CACHE_HOME", "")
    if not os.path.isabs(base):  # unset or relative (the XDG rule: ignore it)
        home = os.path.expanduser("~")
        if not os.path.isabs(home):  # no home directory: no cache (never one in the current directory)
            return None
        base = os.path.join(home, ".cache")
    return os.path.join(base, "yaseer", "compiled")


LIMIT = 64 * 1024 * 1024  # bytes: the most the cache directory holds
MAGIC = b"yaseer-compiled\n"
_DIGEST = 32  # bytes of the entry's hash


def private_dir() -> str | None:
    """The cache directory, created private (0700) if missing; None when the cache is off or the
    directory belongs to someone else or is writable by others (its contents cannot be trusted)."""
    directory = cache_dir()
    if directory is None:
        return None
    try:
        os.makedirs(directory, mode=0o700, exist_ok=True)
        status = os.stat(directory)
    except OSError:
        return None
    if status.st_uid != os.getuid() or status.st_mode & 0o022:
        return None
    return directory


_fingerprint: bytes | None = None


def toolchain_fingerprint() -> bytes:
    """The hash of yaseer's version, the Python, and the text of the compiler's source files
    (remembered in the cache for the files' sizes and modification times: see the module docstring)."""
    global _fingerprint
    if _fingerprint is None:
        sources = _source_files()
        signature = _toolchain_digest()
        for name, status in sources:
            signature.update(f"{name}\0{status.st_size}\0{status.st_mtime_ns}\0".encode("utf-8", "surrogateescape"))
        directory = private_dir()
        remembered = os.path.join(directory, f"toolchain-{signature.hexdigest()}.key") if directory else None
        if remembered is not None:
            try:
                with open(remembered, "rb") as stored:
                    _fingerprint = stored.read()
            except OSError:
                pass
        if _fingerprint is None or len(_fingerprint) != signature.digest_size:
            _fingerprint = _text_fingerprint(name for name, _ in sources)
            if remembered is not None:
                _write_atomically(remembered, _fingerprint)
    return _fingerprint


def _toolchain_digest():
    """A BLAKE2 hash begun with the cache's format, yaseer's version and the Python."""
    return blake2b(f"{FORMAT} {__version__} {sys.version} {sys.implementation.cache_tag}".encode())


def _text_fingerprint(names) -> bytes:
    """The hash of the named source files' text (with :func:`_toolchain_digest`'s start)."""
    digest = _toolchain_digest()
    for name in names:
        with open(os.path.join(_SOURCES, name), "rb") as source:
            digest.update(name.encode() + b"\0" + source.read() + b"\0")
    return digest.digest()


def key(area, program: dict[int, str], entry_lines=(), dialect=None) -> str | None:
    """The cache key of compiling ``program`` (line -> text) as ``area`` in
    ``dialect`` (its repr: every field); None when the cache is switched off, cannot be
    trusted (see :func:`private_dir`) or its sources cannot be read."""
    if private_dir() is None:
        return None
    try:
        digest = blake2b(toolchain_fingerprint())
    except OSError:
        return None
    digest.update(repr((area, sorted(entry_lines), dialect)).encode())
    for number, text in sorted(program.items()):
        digest.update(f"{number}\0{text}\0".encode("utf-8", "surrogatepass"))
    return digest.hexdigest()


def _seal(entry: str, data: bytes) -> bytes:
    """The hash an entry's marshalled bytes are stored under, keyed with the entry's key."""
    return blake2b(data, digest_size=_DIGEST, key=bytes.fromhex(entry)[:64]).digest()


def load(entry: str) -> tuple[CompiledArea, list] | None:
    """The compiled area and its code objects stored under ``entry``, or None (no entry, or one
    whose bytes do not hash to the hash stored with them: nothing of it is unmarshalled)."""
    try:
        with open(os.path.join(cache_dir(), f"{entry}.bin"), "rb") as stored:
            data = stored.read()
    except OSError:
        return None
    header = len(MAGIC) + _DIGEST
    if not data.startswith(MAGIC) or data[len(MAGIC):header] != _seal(entry, data[header:]):
        return None
    try:
        stored_key, fields, codes = marshal.loads(data[header:])
        if stored_key != entry or len(codes) != len(fields[1]):
            return None
        return CompiledArea.from_plain(fields), codes
    except (EOFError, ValueError, TypeError, IndexError, KeyError):  # another yaseer's layout
        return None


def store(entry: str, compiled: CompiledArea, codes: list) -> None:
    """Keep ``compiled`` and its code objects (None for a piece that could not be
    compiled) under ``entry``, then prune the cache to :data:`LIMIT`; failures are ignored."""
    try:
        data = marshal.dumps((entry, compiled.as_plain(), codes))
    except ValueError:
        return
    if len(data) > LIMIT // 4:
        return
    directory = cache_dir()
    _write_atomically(os.path.join(directory, f"{entry}.bin"), MAGIC + _seal(entry, data) + data)
    # Pruning reads the size of every entry (thousands of files: tens of ms), so a store prunes
    # with the chance len(data) / (LIMIT / 16), drawn from the entry's own hash: on average once
    # for every sixteenth of the limit written, by all processes together.
    if int(entry[:8], 16) < len(data) / (LIMIT // 16) * 0x100000000:
        prune(directory, LIMIT)


def prune(directory: str, limit: int) -> None:
    """Remove the oldest files of ``directory`` (by modification time) until the rest
    take at most ``limit`` bytes."""
    try:
        with os.scandir(directory) as found:
            files = [(entry.stat().st_mtime_ns, entry.stat().st_size, entry.path) for entry in found
                     if entry.is_file(follow_symlinks=False)]
    except OSError:
        return
    total = sum(size for _, size, _ in files)
    for _, size, path in sorted(files):
        if total <= limit:
            break
        try:
            os.unlink(path)
        except OSError:
            continue
        total -= size


def _write_atomically(path: str, data: bytes) -> None:
    """Write ``data`` to a temporary file beside ``path`` and rename it into place; failures are ignored."""
    directory = os.path.dirname(path)
    temporary = os.path.join(directory, f".{os.path.basename(path)}.{os.getpid()}.tmp")
    try:
        os.makedirs(directory, exist_ok=True)
        with open(temporary, "wb") as written:
            written.write(data)
        os.replace(temporary, path)
    except OSError:
        try:
            os.unlink(temporary)
        except OSError:
            pass
