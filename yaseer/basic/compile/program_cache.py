"""An on-disk cache of compiled program areas, so a listing run again starts
without parsing or compiling it (and without importing lark).

Key: a BLAKE2 hash of the area's lines and every other input of the compile
(area number, extra entry lines, the machine's dialect), of yaseer's version, of the Python that
runs it (bytecode is version-specific), and of the text of every source file
that turns text into compiled code (every ``.py`` and ``.lark`` of ``yaseer/basic`` and its wings),
so editing the grammar or the compiler invalidates every entry.  That text's hash is
remembered in the cache for the files' sizes and modification times
(:func:`yaseer.sealed_cache.source_fingerprint`): a start only asks the sources' sizes and
times (about 0.05 ms) and reads one file.  In a regular install the first start after it takes
the files' SHA-256 hashes from pip's ``RECORD`` instead of reading their text, while no file
is newer than that list (:func:`yaseer.sealed_cache.installed_fingerprint`).  Nothing is
written inside the installed package.

Value: the :class:`~yaseer.basic.compile.compiled.CompiledArea` fields and the code object
of each generated function, stored with :mod:`marshal` in a sealed entry
(:mod:`yaseer.sealed_cache`: behind a header of :data:`MAGIC` and a BLAKE2 hash of the
marshalled bytes keyed with the entry's own key, checked before ``marshal.loads`` sees a
byte): a damaged, truncated or renamed entry is never loaded, the area is compiled again and
the entry rewritten.

Where, and how it stays safe and small: :mod:`yaseer.sealed_cache` (``~/.cache/yaseer/compiled``
by default, a private 0700 directory that is not used when others can write it, atomic writes,
pruned oldest first to :data:`LIMIT`).
"""

from __future__ import annotations

import os
import sys

from yaseer import sealed_cache
from yaseer.sealed_cache import blake2b, cache_dir, private_dir  # noqa: F401  (cache_dir: where entries are)
from yaseer.version import __version__
from yaseer.basic.compile.compiled import CompiledArea

FORMAT = 1  # bump when the stored layout changes
# Paths are os.path strings here, not pathlib (whose import costs a few ms of every start).
# yaseer/basic: every wing (the dialects, the scanner and grammar, the compiler, the number models) shapes the code
_SOURCES = os.path.dirname(os.path.dirname(os.path.realpath(__file__)))


def _source_files():
    """(path relative to yaseer/basic, os.stat_result) of every .py and .lark file of yaseer/basic and its wings."""
    return sealed_cache.source_files(_SOURCES, (".py", ".lark"))


LIMIT = sealed_cache.LIMIT  # bytes: the most the cache directory holds
MAGIC = b"yaseer-compiled\n"

_fingerprint: bytes | None = None


def toolchain_fingerprint() -> bytes:
    """The hash of yaseer's version, the Python, and the text of the compiler's source files
    (remembered in the cache for the files' sizes and modification times)."""
    global _fingerprint
    if _fingerprint is None:
        sources = _source_files()
        _fingerprint = sealed_cache.source_fingerprint(
            sources, _toolchain_digest, lambda names: _installed_fingerprint(sources) or _text_fingerprint(names))
    return _fingerprint


def _installed_fingerprint(sources) -> bytes | None:
    """The hash of the sources' hashes as pip's RECORD lists them, where yaseer is installed
    (not an editable install or a checkout: then None, and the text is hashed)."""
    site = os.path.dirname(os.path.dirname(_SOURCES))
    record = os.path.join(site, f"yaseer-{__version__}.dist-info", "RECORD")
    return sealed_cache.installed_fingerprint(record, "yaseer/basic/", sources, _toolchain_digest())


def _toolchain_digest():
    """A BLAKE2 hash begun with the cache's format, yaseer's version and the Python."""
    return blake2b(f"{FORMAT} {__version__} {sys.version} {sys.implementation.cache_tag}".encode())


def _text_fingerprint(names) -> bytes:
    """The hash of the named source files' text (with :func:`_toolchain_digest`'s start)."""
    return sealed_cache.text_fingerprint(_SOURCES, names, _toolchain_digest())


def key(area, program: dict[int, str], entry_lines=(), dialect=None, base_one: bool = False) -> str | None:
    """The cache key of compiling ``program`` (line -> text) as ``area`` in
    ``dialect`` (its repr: every field), under OPTION BASE 1 when ``base_one``
    (compiler.compile_area); None when the cache is switched off, cannot be
    trusted (see :func:`private_dir`) or its sources cannot be read."""
    if private_dir() is None:
        return None
    try:
        digest = blake2b(toolchain_fingerprint())
    except OSError:
        return None
    digest.update(repr((area, sorted(entry_lines), dialect) + ((True,) if base_one else ())).encode())
    if getattr(dialect, "arithmetic", None) == "decimal":  # its code calls the C routines where built
        from yaseer.basic.arithmetic.decimal_fast import accelerated

        digest.update(b"decimal in C" if accelerated() else b"decimal inline")
    for number, text in sorted(program.items()):
        digest.update(f"{number}\0{text}\0".encode("utf-8", "surrogatepass"))
    return digest.hexdigest()


def load(entry: str) -> tuple[CompiledArea, list] | None:
    """The compiled area and its code objects stored under ``entry``, or None (no entry, or one
    whose bytes do not hash to the hash stored with them: nothing of it is unmarshalled)."""
    stored = sealed_cache.read_marshalled(f"{entry}.bin", entry, MAGIC)
    if stored is None:
        return None
    try:
        fields, codes = stored
        if len(codes) != len(fields[1]):
            return None
        return CompiledArea.from_plain(fields), codes
    except (ValueError, TypeError, IndexError, KeyError):  # another yaseer's layout
        return None


def store(entry: str, compiled: CompiledArea, codes: list) -> None:
    """Keep ``compiled`` and its code objects (None for a piece that could not be
    compiled) under ``entry``, then prune the cache to :data:`LIMIT`; failures are ignored."""
    sealed_cache.write_marshalled(f"{entry}.bin", entry, MAGIC, compiled.as_plain(), codes, limit=LIMIT)
