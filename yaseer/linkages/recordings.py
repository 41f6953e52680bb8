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

Computing a whole key costs a call every test (a listing cycling Q(2) through 1..4
read four elements and made seven tests, about 3% of the call): the keys met so far
are compiled into a decision tree (:func:`compile_choice`) that makes only the tests
which tell their paths apart on the way to a leaf, and names a key met there.  An
input whose key was never met may be sent down the tree to a path it does not take:
its guards refuse it, and the whole key is computed, as before, to find and remember
the one it takes.
"""

from __future__ import annotations

import re

from yaseer.linkages.straight_line import accelerated
from yaseer.linkages.tracing import Retrace

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only
    from typing import Callable

KEY_BUILTINS = {"float": float, "bool": bool, "len": len}  # all a key function may call
MEMORY = 4096  # keys remembered (a listing whose every call has a new key starts over)
TREE = 256  # keys a decision tree is compiled for (beyond: the whole key every call)
SETTLE = 32  # calls the keys met must stay the same before their decision tree is compiled
_ARRAY = re.compile(r"\b_a_(\w+)\b")


def _no_key(machine) -> tuple:
    return ()


class Recordings:
    """The compiled paths of one program (``len``: how many) and the key that picks one;
    ``compiler``: what compiles a key function (default :func:`compile_key`); ``programs``: where
    the paths' translated programs are kept (:func:`straight_line.accelerated`; None: nowhere)."""

    def __init__(self, compiler: Callable | None = None, programs=None) -> None:
        self._compile = compiler or compile_key
        self._programs = programs
        self._paths: list = []
        self._tests: list[str] = []  # every input guard's test, of every path
        self._outcomes: list[tuple] = []  # per path: the tests' values for the call recorded
        self._key = _no_key
        self._chosen: dict = {}  # key -> the path that ran for it
        self._differing: list[str] = []  # the tests of the key
        self._pick = _no_key  # a key met whose path the call likely takes (compile_choice)

    def __len__(self) -> int:
        return len(self._paths)

    def add(self, run, tests: tuple[str, ...], machine) -> None:
        """Add the compiled path ``run`` whose input guards test ``tests``; the
        call on ``machine`` that was recorded takes it.  Its calls run its program of double
        operations once it has been taken a few times (:func:`straight_line.accelerated`).

        The key holds only the tests on which the paths differ (a test every path
        passes alike chooses nothing and would cost every call its reading)."""
        added = accelerated(run, getattr(run, "text", ""), self._programs)
        self._paths.append(added)
        self._tests += [test for test in tests if test not in self._tests]
        every = self._compile(self._tests)
        self._outcomes = [self._outcome(every, machine if path is added else None, k)
                          for k, path in enumerate(self._paths)]
        self._choose()

    def withdraw(self, run) -> None:
        """Take back the path ``run`` (one added for a call whose inputs it did not hold for)."""
        index = next(k for k, path in enumerate(self._paths) if path is run or getattr(path, "fallback", None) is run)
        del self._paths[index], self._outcomes[index]
        self._choose()

    def _choose(self) -> None:
        """The key of the paths' tests that tell them apart, and the path each key's calls take."""
        differing = [k for k in range(len(self._tests))
                     if len({outcome[k] if k < len(outcome) else None for outcome in self._outcomes}) > 1]
        self._differing = [self._tests[k] for k in differing]
        self._key = self._compile(self._differing) if differing else _no_key
        self._chosen.clear()
        for path, outcome in zip(self._paths, self._outcomes):
            self._chosen.setdefault(tuple(outcome[k] if k < len(outcome) else None for k in differing), path)
        self._grow()

    def _grow(self) -> None:
        """The decision tree of the keys met (a key with an unknown test, None, is never
        met: every call's key is known), once they have stayed the same for :data:`SETTLE`
        calls (until then, and beyond :data:`TREE` keys, the whole key).

        Compiling a tree costs about as much as a hundred calls; a run that takes its kept
        paths one call after another (each one a new key), or makes only a few calls, would
        compile a tree a key and use each for a call or two (a warm Example 5: eight trees, a
        fifth of its run)."""
        if not self._differing:
            self._pick = _no_key
        elif len(self._chosen) > TREE:
            self._pick = self._key
        else:
            self._pick = self._settling()

    def _settling(self) -> "Callable":
        """A ``pick`` giving the whole key for :data:`SETTLE` calls, then putting the decision
        tree of the keys met in its place (a new key before then starts another count)."""
        key, left = self._key, SETTLE

        def pick(machine) -> tuple:
            nonlocal left
            left -= 1
            if not left:
                self._pick = compile_choice(self._differing, [(met, path) for met, path in self._chosen.items()
                                                              if None not in met])
            return key(machine)

        return pick

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
            chosen = self._chosen.get(self._pick(machine))
        except (LookupError, TypeError, ValueError):  # an input missing or not a number: every path tried
            chosen = None
        if chosen is not None:
            try:
                chosen(machine)
                return True
            except Retrace:
                pass
        try:
            key = self._key(machine)
        except (LookupError, TypeError, ValueError):
            key = None
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
                new = key not in self._chosen
                self._chosen[key] = path
                if new:
                    self._grow()
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
    tests, reads = _plain_tests(tests)
    arrays = dict.fromkeys(name for test in [*tests, *reads] for name in _ARRAY.findall(test))
    lines = ["_arrays = _M.arrays"] + [f"_a_{name} = _arrays[{name!r}]" for name in arrays]
    lines += [f"{name} = {text}" for text, name in reads.items()]
    lines.append(f"return ({''.join(test + ', ' for test in tests)})")
    return _function("key", lines, "<recorded paths' key>")


def _plain_tests(tests) -> tuple[list[str], dict[str, str]]:
    """``tests`` with each element read made a local (``float(_a_Q[2])`` -> ``_eQ_2``) and a
    test of a float written as the comparison it is, and the reads (text -> local)."""
    reads: dict[str, str] = {}  # the text reading an element -> its local

    def local(found) -> str:
        return reads.setdefault(found.group(0), f"_e{found.group(1)}_{found.group(2)}")

    return [_TRUTH.sub(r"(\1 != 0.0)", _COMPARED.sub(r"\1", _READ_TEXT.sub(local, test))) for test in tests], reads


def _function(name: str, lines: list[str], label: str):
    """The function ``name(_M)`` of body ``lines``, calling nothing but :data:`KEY_BUILTINS`."""
    text = f"def {name}(_M):\n" + "".join(f"    {line}\n" for line in lines)
    namespace = {"__builtins__": dict(KEY_BUILTINS)}
    exec(compile(text, label, "exec"), namespace)
    return namespace[name]


_BOOLEAN = re.compile(r"\(.* (?:==|!=|<=?|>=?) .*\)$")


def compile_choice(tests, entries) -> "Callable":
    """The function ``pick(_M)``: the key of one of ``entries`` ((key, path) pairs, each key the
    tuple of ``tests``' values, as :func:`compile_key` computes it) whose path the inputs of
    ``_M`` likely take, or None.

    A decision tree: each node makes the test that best tells apart the paths of the entries
    that reach it, and reads an element only where a test needs it; a leaf is reached once the
    entries there share a path (its key is returned: a key reaching a leaf need not be the
    key returned, or any key met).  Made on the entries a caller has met, it returns for
    each of their keys a key of the same path."""
    tests, reads = _plain_tests(tests)
    needs = [[(text, name) for text, name in reads.items() if re.search(rf"\b{name}\b", test)] for test in tests]
    lines = ["_arrays = _M.arrays"]

    def node(entries: list, done: frozenset, made: frozenset, indent: str) -> None:
        if len({id(path) for _, path in entries}) <= 1:
            lines.append(f"{indent}return {entries[0][0]!r}" if entries else f"{indent}return None")
            return
        best = min((k for k in range(len(tests)) if k not in done and len({key[k] for key, _ in entries}) > 1),
                   key=lambda k: (sum(len({id(path) for key, path in entries if key[k] == value})
                                      for value in {key[k] for key, _ in entries}), k))
        for text, name in needs[best]:
            if name not in made:
                array = _ARRAY.search(text).group(1)
                if f"_a_{array}" not in made:
                    lines.append(f"{indent}_a_{array} = _arrays[{array!r}]")
                    made |= {f"_a_{array}"}
                lines.append(f"{indent}{name} = {text}")
                made |= {name}
        for array in _ARRAY.findall(tests[best]):
            if f"_a_{array}" not in made:
                lines.append(f"{indent}_a_{array} = _arrays[{array!r}]")
                made |= {f"_a_{array}"}
        values = list(dict.fromkeys(key[best] for key, _ in entries))
        if set(values) <= {True, False} and _BOOLEAN.match(tests[best]):
            branches = [(f"if {tests[best]}:", True), ("else:", False)]
        else:
            lines.append(f"{indent}_v{best} = {tests[best]}")
            branches = [(f"{'if' if k == 0 else 'elif'} _v{best} == {value!r}:", value) for k, value in enumerate(values)]
            branches.append(("else:", None))
        for head, value in branches:
            lines.append(indent + head)
            chosen = [(key, path) for key, path in entries if value is not None and key[best] == value]
            if value is None:
                lines.append(f"{indent}    return None")
            else:
                node(chosen, done | {best}, made, indent + "    ")

    node(list(entries), frozenset(), frozenset(), "")
    return _function("pick", lines, "<recorded paths' choice>")
