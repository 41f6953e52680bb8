"""The private on-disk cache's directory and its sealed entries, shared by every kind of entry.

Two kinds of entry live there: compiled program areas (:mod:`yaseer.basic.compile.program_cache`)
and recorded paths of the library programs (:mod:`yaseer.linkages.recording_cache`).  Both are
code objects and plain values written with :mod:`marshal`, which trusts its input (damaged code
objects can crash or mislead the interpreter), so this module holds what keeps that safe:

- **Where:** ``$YASEER_CACHE_DIR`` if set (empty: no cache), else
  ``$XDG_CACHE_HOME/yaseer/compiled`` (an absolute XDG_CACHE_HOME; default
  ``~/.cache/yaseer/compiled``; no cache without a home directory); never inside the checkout.
- **Private:** the directory is made mode 0700 and used only while it is owned by the user and
  writable by no one else (:func:`private_dir`): code is never read from a place another user
  could write.
- **Sealed:** an entry is a header (its kind's magic bytes and a BLAKE2 hash of the marshalled
  bytes keyed with the entry's own key) and the bytes (:func:`write_sealed`); :func:`read_sealed`
  checks the hash before anything reads a byte of it, so a damaged, truncated or renamed entry
  is never unmarshalled: its caller computes the value again and the entry is rewritten.
- **Atomic:** an entry is written to a temporary file in the same directory and renamed into
  place; concurrent runs are safe.  Any OSError (read-only home, full disk) just means no cache.
- **Bounded:** the directory is kept near :data:`LIMIT` bytes: now and then after an entry is
  written (on average once for every sixteenth of the limit written) the oldest files are removed
  until the rest fit; an entry alone over a quarter of the limit is not kept.
- **Keyed on the sources:** an entry's key includes a hash of the text of the source files that
  made its code (:func:`source_fingerprint`), remembered in the directory for the files' sizes
  and modification times so that a start need not read them all.

Paths are os.path strings here, not pathlib (whose import costs a few ms of every start).
"""

from __future__ import annotations

import marshal
import os

try:  # the built-in module: hashlib would load OpenSSL (~10 ms of start-up)
    from _blake2 import blake2b
except ImportError:  # pragma: no cover - other Pythons
    from hashlib import blake2b

LIMIT = 64 * 1024 * 1024  # bytes: the most the cache directory holds
DIGEST = 32  # bytes of an entry's hash


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


def seal(entry: str, data: bytes) -> bytes:
    """The hash an entry's bytes are stored under, keyed with the entry's key (hexadecimal)."""
    return blake2b(data, digest_size=DIGEST, key=bytes.fromhex(entry)[:64]).digest()


def read_sealed(name: str, entry: str, magic: bytes) -> bytes | None:
    """The bytes stored in the file ``name`` of the cache under the key ``entry`` behind ``magic``,
    or None: no such file, another kind of entry, or bytes that do not hash to the hash stored
    with them (then nothing of them must be read), or a directory others could write (checked
    here too, not only by the callers: marshal must never read what another user planted)."""
    directory = private_dir()
    if directory is None:
        return None
    try:
        with open(os.path.join(directory, name), "rb") as stored:
            data = stored.read()
    except (OSError, TypeError):
        return None
    header = len(magic) + DIGEST
    if not data.startswith(magic) or data[len(magic):header] != seal(entry, data[header:]):
        return None
    return data[header:]


def write_sealed(name: str, entry: str, magic: bytes, data: bytes, limit: int = LIMIT) -> None:
    """Keep ``data`` in the file ``name`` of the cache, sealed with the key ``entry``, then now and
    then prune the cache to ``limit`` bytes; data over a quarter of the limit is not kept."""
    if len(data) > limit // 4:
        return
    directory = cache_dir()
    if directory is None:
        return
    write_atomically(os.path.join(directory, name), magic + seal(entry, data) + data)
    # Pruning reads the size of every entry (thousands of files: tens of ms), so a store prunes
    # with the chance len(data) / (limit / 16), drawn from the entry's own hash: on average once
    # for every sixteenth of the limit written, by all processes together.
    if int(entry[:8], 16) < len(data) / (limit // 16) * 0x100000000:
        prune(directory, limit)


def read_marshalled(name: str, entry: str, magic: bytes) -> tuple | None:
    """The values :func:`write_marshalled` kept in ``name`` under ``entry``, or None: nothing
    there, a bad seal (then nothing is unmarshalled), another entry's key stored with them,
    or another layout."""
    data = read_sealed(name, entry, magic)
    if data is None:
        return None
    try:
        stored = marshal.loads(data)
    except (EOFError, ValueError, TypeError):
        return None
    if type(stored) is not tuple or not stored or stored[0] != entry:
        return None
    return stored[1:]


def write_marshalled(name: str, entry: str, magic: bytes, *values, limit: int = LIMIT) -> bool:
    """Keep ``values`` in ``name``, sealed under ``entry`` with the key itself stored first (as
    :func:`write_sealed` keeps data); False when :mod:`marshal` cannot write them (nothing kept)."""
    try:
        data = marshal.dumps((entry, *values))
    except ValueError:
        return False
    write_sealed(name, entry, magic, data, limit)
    return True


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


def write_atomically(path: str, data: bytes) -> None:
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


def source_files(directory: str, suffixes: tuple[str, ...] = (".py",)) -> list:
    """(path relative to ``directory``, os.stat_result) of every file ending in one of ``suffixes``
    in ``directory`` and its subdirectories one level down, sorted."""
    found = []
    with os.scandir(directory) as entries:
        subdirectories = []
        for entry in entries:
            if entry.name.endswith(suffixes):
                found.append((entry.name, entry.stat()))
            elif entry.is_dir() and entry.name != "__pycache__":
                subdirectories.append(entry.name)
    for subdirectory in subdirectories:
        with os.scandir(os.path.join(directory, subdirectory)) as entries:
            found.extend((f"{subdirectory}/{entry.name}", entry.stat()) for entry in entries
                         if entry.name.endswith(suffixes))
    return sorted(found)


def text_fingerprint(directory: str, names, digest) -> bytes:
    """``digest`` (a BLAKE2 hash begun with what else the key depends on) updated with the name
    and text of each named source file of ``directory``: its digest."""
    for name in names:
        with open(os.path.join(directory, name), "rb") as source:
            digest.update(name.encode() + b"\0" + source.read() + b"\0")
    return digest.digest()


def installed_fingerprint(record: str, prefix: str, sources: list, digest) -> bytes | None:
    """``digest`` (a BLAKE2 hash begun with what else the key depends on) updated with the name and
    the hash of each of ``sources`` ((name, os.stat_result) pairs) as ``pip`` listed them in the
    installed distribution's ``RECORD`` file ``record`` (each path there is ``prefix`` + name, with
    the file's SHA-256 and size): its digest, or None when the list cannot stand for their text:
    no such file, a source it does not list or lists with another size, or a source modified
    after the list was written (pip writes it last).  Reading it costs a first run after an
    install a fraction of hashing the sources' text (1.4 MB: about 25M instructions) and gives
    a hash as sure (a reinstall of other text lists other hashes)."""
    try:
        with open(record, "rb") as listing:
            written = os.fstat(listing.fileno()).st_mtime_ns
            text = listing.read().decode("utf-8", "surrogateescape")
    except OSError:
        return None
    listed = {}
    for line in text.splitlines():
        path, _, rest = line.partition(",")
        if path.startswith(prefix):
            listed[path[len(prefix):]] = rest
    for name, status in sources:
        hash_and_size = listed.get(name, "")
        hashed, _, size = hash_and_size.partition(",")
        if not hashed.startswith("sha256=") or size != str(status.st_size) or status.st_mtime_ns > written:
            return None
        digest.update(f"{name}\0{hashed}\0".encode("utf-8", "surrogateescape"))
    return digest.digest()


def source_fingerprint(sources: list, start, hash_text) -> bytes:
    """The hash of the text of ``sources`` ((name, os.stat_result) pairs, as :func:`source_files`
    gives), as ``hash_text(names)`` computes it, remembered in the cache for their names, sizes and
    modification times.

    ``start()`` is a BLAKE2 hash begun with what else the hash depends on (the cache's format,
    yaseer's version, the Python).  Reading and hashing the text costs every start about a
    millisecond, so ``toolchain-<S>.key`` keeps the hash for the sources whose names, sizes and
    modification times (in nanoseconds) hash to ``S`` (Python's own bytecode cache trusts size
    and modification time the same way): a start then only asks the sources' sizes and times and
    reads that one file.  Sources copied elsewhere or reinstalled are hashed again once (and give
    the same hash when their text is the same); a file rewritten with new text of the same size in
    the same nanosecond would go unnoticed.  Nothing is written beside the sources.
    """
    signature = start()
    for name, status in sources:
        signature.update(f"{name}\0{status.st_size}\0{status.st_mtime_ns}\0".encode("utf-8", "surrogateescape"))
    directory = private_dir()
    remembered = os.path.join(directory, f"toolchain-{signature.hexdigest()}.key") if directory else None
    fingerprint = None
    if remembered is not None:
        try:
            with open(remembered, "rb") as stored:
                fingerprint = stored.read()
        except OSError:
            pass
    if fingerprint is None or len(fingerprint) != signature.digest_size:
        fingerprint = hash_text([name for name, _ in sources])
        if remembered is not None:
            write_atomically(remembered, fingerprint)
    return fingerprint
