"""Recorded paths kept in the on-disk cache, so a listing run again neither records nor compiles
its library programs' paths (:mod:`yaseer.linkages.tracing`) anew.

A recorded path is a compiled function that holds for the inputs its guards accept and raises
:class:`~yaseer.linkages.tracing.Retrace` for any other: whichever path a call tries, it gets
the numbers the plain code computes or a Retrace, never other numbers.  A kept path is the code
object of that function (its guards included), its names, each one a function of
:data:`tracing.BOUND`, a function the caller provides, or a number, and its Python text (which
:mod:`yaseer.linkages.straight_line` translates): plain values :mod:`marshal` writes (nothing is
pickled).

Keys.  Every entry's key hashes the *toolchain*: the cache's format, yaseer's version, the Python,
and the text of every source of ``yaseer/linkages`` and of the caller's further sources (the
binding that reads and writes the machine), remembered for their sizes and times
(:func:`yaseer.sealed_cache.source_fingerprint`).  A path's entry is keyed on the toolchain, the
program, the method, the *recording's inputs* (the tests of its guards that read inputs alone and
their values at the call recorded, :meth:`tracing.Recorder.keys`) and its code.  A program's
*index* (keyed on the toolchain, the program and the method) lists its kept paths with those tests
and values, newest last, at most :data:`KEPT`.  A call that no path of this process holds for
evaluates each kept path's tests on its inputs; a path whose values match is loaded and tried.

A path's translated program (:mod:`yaseer.linkages.straight_line`), once it was taken often
enough to be translated, is kept in the path's entry too, with the accelerator's instruction
numbers it was made with: a later run loading the path runs it from the path's first call (and
reads no other file for it).

Every kind of file is a sealed entry of the private cache directory
(:mod:`yaseer.sealed_cache`): the hash is checked before :mod:`marshal` reads a byte, so a
damaged or foreign file is never loaded and the path is recorded again (and kept anew).
"""

from __future__ import annotations

import os
import sys
from types import CodeType, FunctionType

from yaseer import sealed_cache
from yaseer.linkages import tracing
from yaseer.linkages.recordings import KEY_BUILTINS, compile_key
from yaseer.version import __version__

FORMAT = 3  # bump when the stored layout changes
MAGIC = b"yaseer-recorded\n"
KEPT = 256  # paths an index lists per program and method (the oldest are dropped)
_LINKAGES = os.path.dirname(os.path.realpath(__file__))
_NUMBERS = (bool, int, float, complex)
_HELPERS = {name: value for name, value in tracing.namespace({}).items() if name != "__builtins__"}  # its own


def _start():
    """A BLAKE2 hash begun with the cache's format, yaseer's version and the Python."""
    return sealed_cache.blake2b(f"recorded {FORMAT} {__version__} {sys.version} {sys.implementation.cache_tag}".encode())


_toolchains: dict[tuple, bytes] = {}


def toolchain(also: tuple[str, ...] = ()) -> bytes:
    """The hash of the format, version, Python and the text of the linkages' sources and of the
    source files ``also`` (absolute paths), remembered in the cache (OSError: unreadable sources)."""
    found = _toolchains.get(also)
    if found is None:
        sources = sealed_cache.source_files(_LINKAGES)
        sources += [(os.path.relpath(path, _LINKAGES), os.stat(path)) for path in also]
        found = _toolchains[also] = sealed_cache.source_fingerprint(
            sources, _start, lambda names: sealed_cache.text_fingerprint(_LINKAGES, names, _start()))
    return found


def _key(*parts) -> str:
    """The hexadecimal hash of ``parts`` (numbers, strings, bytes and tuples of them, by their repr)."""
    return sealed_cache.blake2b(repr(parts).encode()).hexdigest()


def _numbering(operations: dict) -> tuple:
    """The accelerator's instruction numbers as a kept program records them (and is matched on)."""
    return tuple(sorted(operations.items()))


def portable(names: dict, provided: dict) -> tuple | None:
    """``names`` (a record's globals) as plain values: (name, kind, value) triples, kind
    ``bound`` (a function of :data:`tracing.BOUND` or ``provided``, by its name) or ``number``;
    None when one is none of these."""
    known = {**tracing.BOUND, **_HELPERS, **provided}
    plain = []
    for name, value in sorted(names.items()):
        if name == "__builtins__":
            continue
        if known.get(name) is value:
            plain.append((name, "bound", None))
        elif type(value) in _NUMBERS:
            plain.append((name, "number", value))
        else:
            return None
    return tuple(plain)


def restored(plain, provided: dict) -> dict | None:
    """The globals of a kept record from :func:`portable`'s triples; None when a name is unknown."""
    known = {**tracing.BOUND, **provided}
    names = {}
    for name, kind, value in plain:
        if kind == "bound" and name in known:
            names[name] = known[name]
        elif kind == "bound" and name in _HELPERS:
            continue  # tracing.namespace adds them
        elif kind == "number" and type(value) in _NUMBERS:
            names[name] = value
        else:
            return None
    return tracing.namespace(names)


class Shelf:
    """The kept paths of one program and method: :meth:`take` one for a call, :meth:`keep` a new one.

    ``provided``: the names the caller binds in every record (by identity: the same objects
    each time); ``also``: the caller's source files that shape the records.
    """

    def __init__(self, program: int, method, provided: dict, also: tuple[str, ...] = ()) -> None:
        self.program, self.method, self.provided = program, method, provided
        self._toolchain = toolchain(also)
        self._index_key = _key(self._toolchain, "index", program, method)
        self._index: list | None = None  # (tests, values, entry key), newest last
        self._keys: dict[tuple, object] = {}  # tests -> the compiled function computing their values
        self.unread = False  # the last take could not read a kept path's tests (an array not made yet)

    def _read_index(self) -> list:
        stored = sealed_cache.read_marshalled(f"{self._index_key}.rec", self._index_key, MAGIC)
        records = stored[0] if stored is not None and len(stored) == 1 else None
        if not isinstance(records, list):
            return []
        return [record for record in records if isinstance(record, tuple) and len(record) == 3
                and isinstance(record[0], tuple) and isinstance(record[1], tuple) and isinstance(record[2], str)]

    def compile_key(self, tests):
        """:func:`recordings.compile_key` of ``tests``, whose code is kept in the cache too (a
        program's key functions cost a warm run as much as its paths would: compiling each)."""
        tests = tuple(tests)
        function = self._keys.get(tests)
        if function is None:
            function = self._keys[tests] = self._kept_key(tests)
        return function

    def _kept_key(self, tests: tuple):
        entry = _key(self._toolchain, "key", tests)
        stored = sealed_cache.read_marshalled(f"{entry}.rec", entry, MAGIC)
        if stored is not None and len(stored) == 1 and type(stored[0]) is CodeType:
            return FunctionType(stored[0], {"__builtins__": dict(KEY_BUILTINS)})
        function = compile_key(tests)
        if sealed_cache.private_dir() is not None:
            sealed_cache.write_marshalled(f"{entry}.rec", entry, MAGIC, function.__code__)
        return function

    def _values(self, tests: tuple, machine):
        """The values of ``tests`` on ``machine``'s inputs (None where they cannot be read)."""
        try:
            return self.compile_key(tests)(machine)
        except (LookupError, TypeError, ValueError):
            return None

    def take(self, recordings, machine) -> bool:
        """Run a kept path that holds for ``machine``'s inputs (it commits the outputs) and add it to
        ``recordings``; False when none does (nothing changed; :attr:`unread`: a kept path's tests
        read an array the machine does not have yet, which the plain code's call may make)."""
        if sealed_cache.private_dir() is None:
            return False
        if self._index is None:
            self._index = self._read_index()
        self.unread = False
        for tests, values, entry in reversed(self._index):
            now = self._values(tests, machine)
            self.unread = self.unread or now is None
            if now != values:
                continue
            run = self._load(entry)
            if run is None:
                continue
            recordings.add(run, tests, machine)
            if recordings.run(machine):
                return True
            recordings.withdraw(run)
        return False

    def _load(self, entry: str):
        stored = sealed_cache.read_marshalled(f"{entry}.rec", entry, MAGIC)
        if (stored is None or len(stored) not in (3, 4) or type(stored[0]) is not CodeType
                or type(stored[2]) is not str):
            return None
        code, plain, text = stored[:3]
        try:
            names = restored(plain, self.provided)
        except (ValueError, TypeError):
            return None
        if names is None:
            return None
        run = FunctionType(code, names)
        run.text = text  # (straight_line translates it)
        run.kept = (entry, plain)  # where keep_program adds its program
        if len(stored) == 4 and type(stored[3]) is dict:
            run.program = stored[3]
        return run

    @staticmethod
    def kept_program(run, operations: dict) -> dict | None:
        """The program (:mod:`yaseer.linkages.path_translation`) kept with the path ``run``, made
        with the accelerator's instruction numbers ``operations``, or None (the accelerator
        checks a program whole before it runs one)."""
        program = getattr(run, "program", None)
        if program is None or program.get("operations") != _numbering(operations):
            return None
        return program

    @staticmethod
    def keep_program(run, operations: dict, program: dict) -> None:
        """Keep the translated ``program`` with the path ``run`` (its entry written again with it;
        a path not kept, or a failure: it is only not kept)."""
        kept = getattr(run, "kept", None)
        if kept is None or sealed_cache.private_dir() is None:
            return
        entry, plain = kept
        program = dict(program, operations=_numbering(operations))
        sealed_cache.write_marshalled(f"{entry}.rec", entry, MAGIC, run.__code__, plain, run.text, program)

    def keep(self, run, tests: tuple, machine) -> None:
        """Keep the path ``run`` just recorded for the call on ``machine`` (its outputs not yet
        written), whose input guards test ``tests``; failures are ignored (it is only not kept)."""
        values = self._values(tests, machine)
        plain = portable({name: value for name, value in run.__globals__.items() if value is not run}, self.provided)
        if values is None or plain is None or sealed_cache.private_dir() is None:
            return
        code = run.__code__
        entry = _key(self._toolchain, self.program, self.method, tests, values,
                     code.co_code, repr(code.co_consts), code.co_names)
        if not sealed_cache.write_marshalled(f"{entry}.rec", entry, MAGIC, code, plain, getattr(run, "text", "")):
            return
        run.kept = (entry, plain)
        records = [record for record in self._read_index() if record[2] != entry] + [(tests, values, entry)]
        self._index = records[-KEPT:]
        sealed_cache.write_marshalled(f"{self._index_key}.rec", self._index_key, MAGIC, self._index)

