"""Many positions in bounded memory: a vectorised call per chunk of positions.

One array call over N positions holds a few dozen temporary arrays of N numbers
(the four-bar's forces: about 1 kB a position), so 10^7 positions at once would
need about 10 GB.  The public linkage functions (:func:`yaseer.linkages.fourbar`
and the others, decorated with :func:`chunked`) therefore answer a call over
more than :data:`CHUNK` positions with a :class:`Lazy` result: nothing is
computed until a number is read, and reading one (``kin.coupler.angle``,
``kin.forces(...).value``, ``result.reactions["ground_on_crank"]``) runs the
whole computation chunk by chunk, keeping of each chunk only the numbers read.
The working memory is that of one chunk whatever N is, the time linear in N,
and every number is the one a single call gives (elementwise arithmetic on the
same values).  Each array read runs the computation again: read what you need
once.  An error (an assembly failure, a singular force system) is raised when a
number is read, by the chunk holding the position it concerns.

:func:`angle_chunks` gives the angles of ``numpy.linspace`` chunk by chunk, for a
caller who wants to reduce or write out each chunk itself::

    for angles in angle_chunks(0.0, 360.0, 10**7):
        torque = fourbar(..., angles, ...).forces(...).value   # reduce, store or write out
"""

from __future__ import annotations

import functools
import sys

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up)
    from typing import Iterator

CHUNK = 1 << 14  # positions per call: large enough that numpy's per-call cost is small, small enough for cache
_PROBE = 2  # positions of the trial run that tells an array per position from anything else


def angle_chunks(start_deg: float, stop_deg: float, count: int, chunk: int = CHUNK) -> Iterator["numpy.ndarray"]:
    """The angles of ``numpy.linspace(start_deg, stop_deg, count)``, chunk by chunk
    (the same values, never all held at once)."""
    import numpy as np

    step = (stop_deg - start_deg) / (count - 1) if count > 1 else 0.0
    for first in range(0, count, chunk):
        index = np.arange(first, min(first + chunk, count), dtype=float)
        angles = start_deg + index * step
        if first + chunk >= count and count > 1:
            angles[-1] = stop_deg  # as linspace: the end point exactly
        yield angles


def _positions(values) -> int | None:
    """N when some of ``values`` (arguments, also inside tuples, lists and dicts) are
    1-D numpy arrays of one length N > CHUNK and every other array holds one
    number; None otherwise (the call is made as it is)."""
    np = sys.modules.get("numpy")
    if np is None:  # no array can have been made
        return None
    lengths = set()
    for value in _leaves(values):
        if isinstance(value, np.ndarray) and value.size > 1:
            if value.ndim != 1:
                return None
            lengths.add(len(value))
    if len(lengths) != 1:
        return None
    count = lengths.pop()
    return count if count > CHUNK else None


def _leaves(value):
    if isinstance(value, dict):
        for item in value.values():
            yield from _leaves(item)
    elif isinstance(value, (tuple, list)):
        for item in value:
            yield from _leaves(item)
    else:
        yield value


def _sliced(value, count: int, part: slice):
    """``value`` with every array of ``count`` numbers cut to ``part`` (inside tuples,
    named tuples, lists and dicts too)."""
    np = sys.modules["numpy"]
    if isinstance(value, np.ndarray):
        return value[part] if value.ndim == 1 and len(value) == count else value
    if isinstance(value, dict):
        return {key: _sliced(item, count, part) for key, item in value.items()}
    if isinstance(value, list):
        return [_sliced(item, count, part) for item in value]
    if isinstance(value, tuple):
        items = [_sliced(item, count, part) for item in value]
        return type(value)(*items) if hasattr(value, "_fields") else tuple(items)
    return value


class _Plan:
    """A call over ``count`` positions and what is read of its result: ``steps``,
    each ("attr", name), ("item", key) or ("call", args, kwargs)."""

    def __init__(self, function, args: tuple, kwargs: dict, count: int):
        self.function, self.args, self.kwargs, self.count = function, args, kwargs, count

    def evaluate(self, steps: tuple, part: slice):
        """The value ``steps`` read, for the positions ``part`` alone."""
        count = self.count
        value = self.function(*_sliced(self.args, count, part), **_sliced(self.kwargs, count, part))
        for step in steps:
            if step[0] == "attr":
                value = getattr(value, step[1])
            elif step[0] == "item":
                value = value[step[1]]
            else:
                value = value(*_sliced(step[1], count, part), **_sliced(step[2], count, part))
        return value

    def read(self, steps: tuple):
        """What ``steps`` read over every position: an array of ``count`` numbers made
        chunk by chunk, a value that is the same at every position, or (an object,
        a tuple, a mapping, a method) a :class:`Lazy` of its own."""
        np = sys.modules["numpy"]
        probe = self.evaluate(steps, slice(0, _PROBE))
        if isinstance(probe, np.ndarray) and probe.ndim >= 1 and len(probe) == _PROBE:
            return self._gathered(steps, probe.dtype)
        if isinstance(probe, bool):  # a decision over the positions (e.g. whether anything moves)
            truths = {bool(self.evaluate(steps, part)) for part in self._parts()}
            if len(truths) != 1:
                raise ValueError(f"{_text(steps)} differs between the chunks of {self.count} positions; "
                                 f"ask for at most {CHUNK} positions at a time")
            return truths.pop()
        if isinstance(probe, (np.ndarray, np.generic, int, float, complex, str, bytes, type(None))):
            return probe  # the same at every position: it depends on no array of positions
        return Lazy(self, steps)

    def _parts(self):
        return (slice(first, min(first + CHUNK, self.count)) for first in range(0, self.count, CHUNK))

    def _gathered(self, steps: tuple, dtype):
        np = sys.modules["numpy"]
        out = None
        for part in self._parts():
            values = np.asarray(self.evaluate(steps, part))
            if out is None:
                out = np.empty((self.count,) + values.shape[1:], dtype=np.result_type(dtype, values.dtype))
            elif not np.can_cast(values.dtype, out.dtype):
                out = out.astype(np.result_type(out.dtype, values.dtype))
            out[part] = values
        return out


def _text(steps: tuple) -> str:
    parts = ["result"]
    for step in steps:
        parts.append(f".{step[1]}" if step[0] == "attr" else f"[{step[1]!r}]" if step[0] == "item" else "(...)")
    return "".join(parts)


class Lazy:
    """A linkage result over more than :data:`CHUNK` positions, computed chunk by
    chunk when a number is read (see the module's description).  Attributes,
    items, method calls and iteration work as on the result itself; each gives an
    array (of every position), a number, or another Lazy."""

    __slots__ = ("_plan", "_steps")

    def __init__(self, plan: _Plan, steps: tuple = ()):
        object.__setattr__(self, "_plan", plan)
        object.__setattr__(self, "_steps", steps)

    def __getattr__(self, name: str):
        if name.startswith("__"):
            raise AttributeError(name)
        return self._plan.read(self._steps + (("attr", name),))

    def __getitem__(self, key):
        return self._plan.read(self._steps + (("item", key),))

    def __call__(self, *args, **kwargs):
        return self._plan.read(self._steps + (("call", args, kwargs),))

    def _probe(self):
        return self._plan.evaluate(self._steps, slice(0, _PROBE))

    def __len__(self) -> int:
        return len(self._probe())

    def __iter__(self):
        probe = self._probe()
        if isinstance(probe, dict):
            return iter(list(probe))
        return (self[index] for index in range(len(probe)))

    def keys(self):
        return self._probe().keys()

    def items(self):
        return [(key, self[key]) for key in self.keys()]

    def values(self):
        return [self[key] for key in self.keys()]

    def __setattr__(self, name, value):
        raise AttributeError(f"cannot assign to {name!r} of a result")

    def __repr__(self) -> str:
        return (f"<{type(self._probe()).__name__} over {self._plan.count} positions, computed in chunks "
                f"when read: {_text(self._steps)}>")


def chunked(function):
    """``function`` (a public linkage function) answering a call over more than
    :data:`CHUNK` positions with a :class:`Lazy` result."""

    @functools.wraps(function)
    def call(*args, **kwargs):
        count = _positions((args, kwargs))
        if count is None:
            return function(*args, **kwargs)
        return Lazy(_Plan(function, args, kwargs, count))

    return call
