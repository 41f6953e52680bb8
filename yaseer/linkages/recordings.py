"""The recorded paths of one program, and how a call finds the one it takes.

A program recorded by :mod:`yaseer.linkages.tracing` has one compiled path per
way its inputs lead it (forces or not, each ``Q(n)``, loads that are zero or not,
a crank at rest or turning, ...).  Trying the paths in turn until one's guards
hold costs every failed path the work it did before its failing guard: a listing
cycling through four choices pays several calls a call.  Most guards test the
inputs alone (an input's value, whether it is zero, an array's length): their
tests (:meth:`tracing.Recorder.keys`) are gathered into one small compiled
function giving the call's *key*, and each key remembers the path that ran for
it.  A call computes its key, runs that path, and falls back to trying every path
only for a key not met before (or one whose path failed a guard on a computed
value).  The key only chooses: every path still checks all its guards, so a
wrong choice costs time, never a wrong number.
"""

from __future__ import annotations

import re

from yaseer.linkages.tracing import Retrace

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only
    from typing import Callable

KEY_BUILTINS = {"float": float, "bool": bool, "len": len}  # all a key function may call
MEMORY = 4096  # keys remembered (a listing whose every call has a new key starts over)
_ARRAY = re.compile(r"\b_a_(\w+)\b")


def _no_key(machine) -> tuple:
    return ()


class Recordings:
    """The compiled paths of one program (``len``: how many) and the key that picks one;
    ``compiler``: what compiles a key function (default :func:`compile_key`)."""

    def __init__(self, compiler: Callable | None = None) -> None:
        self._compile = compiler or compile_key
        self._paths: list = []
        self._tests: list[str] = []  # every input guard's test, of every path
        self._outcomes: list[tuple] = []  # per path: the tests' values for the call recorded
        self._key = _no_key
        self._chosen: dict = {}  # key -> the path that ran for it

    def __len__(self) -> int:
        return len(self._paths)

    def add(self, run, tests: tuple[str, ...], machine) -> None:
        """Add the compiled path ``run`` whose input guards test ``tests``; the
        call on ``machine`` that was recorded takes it.

        The key holds only the tests on which the paths differ (a test every path
        passes alike chooses nothing and would cost every call its reading)."""
        self._paths.append(run)
        self._tests += [test for test in tests if test not in self._tests]
        every = self._compile(self._tests)
        self._outcomes = [self._outcome(every, machine if path is run else None, k)
                          for k, path in enumerate(self._paths)]
        self._choose()

    def withdraw(self, run) -> None:
        """Take back the path ``run`` (one added for a call whose inputs it did not hold for)."""
        index = self._paths.index(run)
        del self._paths[index], self._outcomes[index]
        self._choose()

    def _choose(self) -> None:
        """The key of the paths' tests that tell them apart, and the path each key's calls take."""
        differing = [k for k in range(len(self._tests))
                     if len({outcome[k] if k < len(outcome) else None for outcome in self._outcomes}) > 1]
        self._key = self._compile([self._tests[k] for k in differing]) if differing else _no_key
        self._chosen.clear()
        for path, outcome in zip(self._paths, self._outcomes):
            self._chosen.setdefault(tuple(outcome[k] if k < len(outcome) else None for k in differing), path)

    def _outcome(self, every, machine, index: int) -> tuple:
        """The tests' values for path ``index``: computed on ``machine`` for the path
        just recorded, else those known (a test added since is unknown: None)."""
        if machine is None:
            return self._outcomes[index]
        try:
            return every(machine)
        except (LookupError, TypeError, ValueError):
            return ()

    def run(self, machine) -> bool:
        """Run the path ``machine``'s inputs take (it commits its outputs); False when
        none of the paths holds for them."""
        try:
            key = self._key(machine)
        except (LookupError, TypeError, ValueError):  # an input missing or not a number: no key, every path tried
            key = None
        chosen = self._chosen.get(key)
        if chosen is not None:
            try:
                chosen(machine)
                return True
            except Retrace:
                pass
        for path in self._paths:
            if path is chosen:
                continue
            try:
                path(machine)
            except Retrace:
                continue
            if key is not None:
                if len(self._chosen) >= MEMORY:
                    self._chosen.clear()
                self._chosen[key] = path
            return True
        return False


_READ_TEXT = re.compile(r"float\(_a_(\w+)\[(\d+)\]\)")
_COMPARED = re.compile(r"bool\((\((?:_e\w+|[-\d.e]+) (?:==|!=|<=?|>=?) (?:_e\w+|[-\d.e]+)\))\)")
_TRUTH = re.compile(r"bool\((_e\w+)\)")


def compile_key(tests) -> "Callable":
    """The function ``key(_M)``: the tuple of ``tests``' values (Python texts reading
    ``_M``'s arrays as ``_a_X`` and its scalars).

    Each element the tests read is read and made a float once (most tests read a choice,
    ``Q(n)`` several times), and a test of a float is written as the comparison it is:
    ``bool((x == 2.0))`` as ``(x == 2.0)``, ``bool(x)`` as ``(x != 0.0)`` (NaN too is true):
    the same values with fewer calls, on every call of a program."""
    reads: dict[str, str] = {}  # the text reading an element -> its local

    def local(found) -> str:
        return reads.setdefault(found.group(0), f"_e{found.group(1)}_{found.group(2)}")

    tests = [_TRUTH.sub(r"(\1 != 0.0)", _COMPARED.sub(r"\1", _READ_TEXT.sub(local, test))) for test in tests]
    arrays = dict.fromkeys(name for test in [*tests, *reads] for name in _ARRAY.findall(test))
    lines = ["_arrays = _M.arrays"] + [f"_a_{name} = _arrays[{name!r}]" for name in arrays]
    lines += [f"{name} = {text}" for text, name in reads.items()]
    lines.append(f"return ({''.join(test + ', ' for test in tests)})")
    text = "def key(_M):\n" + "".join(f"    {line}\n" for line in lines)
    namespace = {"__builtins__": dict(KEY_BUILTINS)}
    exec(compile(text, "<recorded paths' key>", "exec"), namespace)
    return namespace["key"]
