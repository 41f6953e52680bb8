"""The one module that maps ``GOSUB PROG n`` to the Python library programs.

:func:`install` registers program areas 1 (slider-crank), 2 (four-bar),
3 (first inversion of the slider-crank) and 5 (virtual link).  Each area reads
its inputs from the machine's arrays and scalars (elements never set, or beyond
an array's dimension, read as 0 like unset BASIC variables), calls
:mod:`yaseer.linkages`, and writes exactly the outputs of
the contract (docs/contract.md): positions always, velocities and accelerations
(0 for a static call), forces only when ``Z(n) = 2``.  All outputs are computed
and checked (finite, inside the arrays' dimensions) before the first is
written, so a failing call leaves the machine untouched.

Errors become BASIC run-time errors naming the program; the machine adds the
calling line (``Mechanism cannot be assembled (PROG 2) in 4040``).

:func:`install` imports nothing of :mod:`yaseer.linkages`: a listing that never
calls ``GOSUB PROG n`` starts without it, and the first call imports it.
"""

from __future__ import annotations

import contextlib
import functools
import math
import os
import sys

from yaseer.basic.errors import (
    DIVISION_BY_ZERO,
    ILLEGAL_FUNCTION_CALL,
    OVERFLOW,
    SUBSCRIPT_OUT_OF_RANGE,
    TYPE_MISMATCH,
    BasicError,
)

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (start-up time)
    from typing import Callable

    from yaseer.linkages.recordings import Recordings

LINKAGES = {1: "slider_crank", 2: "fourbar", 3: "inverted_slider_crank", 5: "virtual_link"}

Element = tuple[str, int]  # an array element, e.g. ("F", 27)

# Per program: the load catalogue (linkage load name -> element holding its value),
# the Q(n) choices (-> load name) and the reactions (-> element(s) written).
LOADS = {
    1: {"crank_fx": ("F", 0), "crank_fy": ("F", 1), "crank_perpendicular": ("F", 2), "crank_torque": ("U", 1),
        "rod_fx": ("F", 7), "rod_fy": ("F", 8), "rod_perpendicular": ("F", 9), "piston": ("P", 1)},
    2: {"crank_fx": ("F", 29), "crank_fy": ("F", 30), "crank_perpendicular": ("F", 31), "crank_torque": ("U", 2),
        "coupler_fx": ("F", 32), "coupler_fy": ("F", 33), "coupler_perpendicular": ("F", 34),
        "follower_fx": ("F", 35), "follower_fy": ("F", 36), "follower_perpendicular": ("F", 37)},
    3: {"crank_torque": ("U", 3), "follower_perpendicular": ("F", 18)},
}
UNKNOWNS = {
    1: {1: "crank_torque", 2: "crank_perpendicular", 3: "rod_perpendicular", 4: "piston"},
    2: {1: "crank_torque", 2: "crank_perpendicular", 3: "coupler_perpendicular", 4: "follower_perpendicular"},
    3: {1: "crank_torque", 3: "follower_perpendicular"},
}
REACTIONS = {
    1: {"ground_on_crank": (("F", 3), ("F", 4)), "crank_on_rod": (("F", 5), ("F", 6)),
        "rod_on_piston": (("F", 10), ("F", 11)), "wall_on_piston": (("N", 1),)},
    2: {"ground_on_crank": (("F", 21), ("F", 22)), "crank_on_coupler": (("F", 23), ("F", 24)),
        "coupler_on_follower": (("F", 25), ("F", 26)), "ground_on_follower": (("F", 27), ("F", 28))},
    3: {"ground_on_crank": (("F", 12), ("F", 13)), "crank_on_block": (("F", 14), ("F", 15)),
        "follower_on_block": (("N", 3),), "follower_on_block_couple": (("U", 4),),
        "ground_on_follower": (("F", 16), ("F", 17))},
}


@functools.cache
def _linkages():
    """The :mod:`yaseer.linkages` package, imported at the first ``GOSUB PROG n``."""
    import yaseer.linkages

    return yaseer.linkages


class _Frame:
    """One call of a program area: reads inputs, collects outputs, writes them at the end."""

    def __init__(self, machine, area: int):
        self.machine = machine
        self.area = area
        self._elements: dict[Element, float] = {}
        self._scalars: dict[str, float] = {}
        self._after_commit: list[Callable[[], None]] = []

    def get(self, name: str, index: int) -> float:
        """Array element ``name(index)`` (0 when beyond the array's dimension)."""
        values = self.machine.array(name)
        return float(values[index]) if index < len(values) else 0.0

    def scalar(self, name: str) -> float:
        return float(self.machine.scalar(name))

    def choice(self, name: str, index: int) -> float:
        """An input that selects what the program does (``Z(n)``, ``Q(n)``, ``L(10)``):
        a plain number, also while a call is recorded."""
        return self.get(name, index)

    def put(self, element: Element, value) -> None:
        self._elements[element] = float(value)

    def put_scalar(self, name: str, value) -> None:
        self._scalars[name] = float(value)

    def put_point(self, motion, position: tuple[Element, Element], velocity: tuple[Element, Element],
                  acceleration: tuple[Element, Element]) -> None:
        """Write a point's x, y components of position, velocity and acceleration."""
        for (x_element, y_element), vector in zip((position, velocity, acceleration), motion):
            self.put(x_element, vector.real)
            self.put(y_element, vector.imag)

    def after_commit(self, action: Callable[[], None]) -> None:
        """Run ``action`` once the outputs are written (not at all when the call fails)."""
        self._after_commit.append(action)

    def commit(self) -> None:
        """Check every output, then write them all (and run the :meth:`after_commit` actions)."""
        isfinite = math.isfinite
        if not (all(map(isfinite, self._elements.values())) and all(map(isfinite, self._scalars.values()))):
            raise self.error("Overflow", OVERFLOW)
        array = self.machine.array
        arrays = {name: array(name) for name in {name for name, _ in self._elements}}
        targets = [(arrays[name], index) for name, index in self._elements]
        if any(index >= len(values) or index < 0 for values, index in targets):
            raise self.error("Subscript out of range", SUBSCRIPT_OUT_OF_RANGE)
        if any(isinstance(values[index], (list, str)) for values, index in targets):
            raise self.error("Type mismatch", TYPE_MISMATCH)  # a 2-D (or string) array where a number goes
        for (values, index), value in zip(targets, self._elements.values()):
            values[index] = value
        for name, value in self._scalars.items():
            self.machine.set_scalar(name, value)
        for action in self._after_commit:
            action()

    def error(self, message: str, code: int = ILLEGAL_FUNCTION_CALL) -> BasicError:
        return BasicError(f"{message} (PROG {self.area})", code)


class _RecordingFrame(_Frame):
    """A call that is also recorded (:mod:`yaseer.linkages.tracing`): inputs are
    traced numbers read by recorded lines, outputs are kept as they come."""

    def __init__(self, machine, area: int, recorder):
        super().__init__(machine, area)
        self.recorder = recorder
        self._arrays: dict[str, int] = {}  # array read -> its length
        self._numbers: set[str] = set()  # arrays an element was read of: numbers, one dimension
        recorder.lines.append("_arrays = _M.arrays")

    def get(self, name: str, index: int):
        value = super().get(name, index)
        array = f"_a_{name}"
        if name not in self._arrays:
            self._arrays[name] = len(self.machine.array(name))
            self.recorder.lines.append(f"{array} = {_fetch(name)}")
        if index >= self._arrays[name]:  # beyond the dimension: 0, as long as the array is no longer
            self.recorder.at_most(f"len({array})", index)
            return value
        self._numbers.add(name)  # a shorter array raises IndexError at this read: another path (Recorder.compile)
        return self.recorder.read(value, f"float({array}[{index}])")

    def scalar(self, name: str):
        # a name that is the same in every dialect (upper case) and a number's: the dictionary of
        # scalars read as machine.scalar reads it, without the method's calls
        if name.isupper() and name.isalnum():
            return self.recorder.read(super().scalar(name), f"float(_M.scalars.get({name!r}, 0.0))")
        return self.recorder.read(super().scalar(name), f"float(_M.scalar({name!r}))")

    def choice(self, name: str, index: int) -> float:
        from yaseer.linkages.tracing import NotTraceable, Traced

        traced = self.get(name, index)
        if not isinstance(traced, Traced):  # beyond the dimension: 0 under the recording's length guard
            return traced
        if traced.value != traced.value:  # NaN equals nothing: no guard could pin it
            raise NotTraceable(f"{name}({index}) is NaN")
        bool(traced == traced.value)  # a guard: the recording holds for this value only
        return traced.value

    def put(self, element: Element, value) -> None:
        self._elements[element] = value

    def put_scalar(self, name: str, value) -> None:
        self._scalars[name] = value

    def recorded(self):
        """The compiled recording of this call, ``run(machine)``, which computes the outputs
        from the machine's inputs and commits them as :meth:`_Frame.commit` does
        (Retrace where the inputs take another path), and the tests of its input
        guards (:meth:`tracing.Recorder.keys`)."""
        from yaseer.linkages.tracing import not_finite

        recorder, area = self.recorder, self.area
        outputs = list(self._elements.values()) + list(self._scalars.values())
        lines = [f"if {not_finite([recorder.operand(value) for value in outputs])}: raise _error('Overflow', {OVERFLOW})"]
        largest: dict[str, int] = {}
        for name, index in self._elements:
            largest[name] = max(index, largest.get(name, -1))
            if name not in self._arrays:
                self._arrays[name] = -1  # written only
                lines.append(f"_a_{name} = {_fetch(name)}")
        if largest:
            # each array's last element written read (a list too short raises IndexError):
            # a subscript costs a tenth of a call of len
            lines.append(f"try: {'; '.join(f'_a_{n}[{i}]' for n, i in largest.items())}\nexcept IndexError: "
                         f"raise _error('Subscript out of range', {SUBSCRIPT_OUT_OF_RANGE}) from None")
        # an array's elements are all numbers, all strings or all rows: one look at each array
        # written, unless a number was read of it
        unread = {name: index for name, index in largest.items() if name not in self._numbers}
        typed = getattr(getattr(self.machine, "dialect", None), "typed_numbers", False)  # a stand-in has none
        if unread and typed:
            lines.append(f"if {' or '.join(f'isinstance(_a_{n}[{i}], (list, str))' for n, i in unread.items())}: "
                         f"raise _error('Type mismatch', {TYPE_MISMATCH})")
        elif unread:  # plain numbers (Recorder.compile): a row or a string is what cannot lose 0.0
            lines.append(f"try: {'; '.join(f'_a_{n}[{i}] - 0.0' for n, i in unread.items())}\nexcept TypeError: "
                         f"raise _error('Type mismatch', {TYPE_MISMATCH}) from None")
        for (name, index), value in self._elements.items():
            lines.append(f"_a_{name}[{index}] = {_as_float(recorder, value)}")
        for name, value in self._scalars.items():
            lines.append(f"_M.set_scalar({name!r}, {_as_float(recorder, value)})")
        recorder.names.update(_provided(area))
        return recorder.compile(lines, f"PROG {area}", not typed), recorder.keys()

    def plain(self) -> _Frame:
        """This call's outputs as a plain frame (concrete numbers)."""
        frame = _Frame(self.machine, self.area)
        for element, value in self._elements.items():
            frame.put(element, getattr(value, "value", value))
        for name, value in self._scalars.items():
            frame.put_scalar(name, getattr(value, "value", value))
        return frame


@functools.cache
def _provided(area: int) -> dict:
    """The names this module binds in program ``area``'s records (the same objects every time, so a
    kept record is given them again: :mod:`yaseer.linkages.recording_cache`)."""
    return {"_isfinite": math.isfinite,
            "_error": lambda message, code: BasicError(f"{message} (PROG {area})", code)}


def _fetch(name: str) -> str:
    """The recorded text reading array ``name`` as ``machine.array(name)`` does (the
    dictionary first: a method call for each array would cost a recorded call a
    tenth of its time)."""
    return f"_arrays.get({name!r}) or _M.array({name!r})"


def _as_float(recorder, value) -> str:
    """The recorded text of output ``value`` as a float (as :meth:`_Frame.put` stores it)."""
    text = recorder.operand(value)
    return text if isinstance(getattr(value, "value", value), float) else f"float({text})"


MAX_RECORDINGS = 64  # paths kept per program and method (forces or not, Q(n), zero loads, ...)
_recordings: dict[tuple, Recordings] = {}  # (program, method) -> its recorded paths
_calls: dict[tuple, int] = {}
_shelves: dict[tuple, object] = {}  # (program, method) -> its paths kept on disk (None: sources unreadable)


def _shelf(number: int, method: str | None):
    """The :class:`~yaseer.linkages.recording_cache.Shelf` of program ``number``'s kept paths, or None
    when the cache is off or cannot be trusted now (see :func:`yaseer.sealed_cache.private_dir`)."""
    from yaseer.sealed_cache import private_dir

    if private_dir() is None:
        return None
    key = (number, method)
    if key not in _shelves:
        from yaseer.linkages.recording_cache import Shelf

        try:
            _shelves[key] = Shelf(number, method, _provided(number), (os.path.realpath(__file__),))
        except OSError:  # the sources cannot be read: no cache
            _shelves[key] = None
    return _shelves[key]


def _call_program(machine, number: int, method: str | None) -> _Frame | None:
    """Run program ``number`` on ``machine``'s inputs, which none of its recorded paths in this
    process holds for (:func:`make_area` tries them first); returns the frame to commit
    (None: a recording ran and committed its outputs).

    From the second call of a program on, each call is recorded once per path
    it takes (:mod:`yaseer.linkages.tracing`) and later calls on the same path run
    the recording: the same operations on the same values, without the objects
    around them (:mod:`yaseer.linkages.recordings` finds the path of a call).  A
    path that cannot be recorded (branch tracking, another method) runs the plain
    code.  With the on-disk cache (:mod:`yaseer.linkages.recording_cache`) the
    paths are kept there, and from the first call on a kept path that holds is
    run, and one that none holds for is recorded and kept: a listing run again
    records and compiles nothing."""
    key = (number, method)
    recordings = _recordings.get(key)
    _calls[key] = calls = _calls.get(key, 0) + 1
    if method is None and (0 if recordings is None else len(recordings)) < MAX_RECORDINGS:
        from yaseer.linkages.recordings import Recordings

        shelf = _shelf(number, method)
        if shelf is not None:
            recordings = _recordings.setdefault(key, Recordings(shelf.compile_key, shelf))
            if shelf.take(recordings, machine):
                return None
        # a kept path whose tests read an array not made yet may hold from the next call on (the
        # plain code's first call makes it): that call is not recorded, the next tries again
        if calls > 1 or (shelf is not None and not shelf.unread):
            from yaseer.linkages.tracing import NotTraceable, Recorder

            frame = _RecordingFrame(machine, number, Recorder())
            try:
                with _quiet_numpy():
                    PROGRAMS[number](frame, method)
            except NotTraceable:
                pass
            else:
                plain = frame.plain()
                run, tests = frame.recorded()
                _recordings.setdefault(key, Recordings(programs=shelf)).add(run, tests, machine)
                if shelf is not None:
                    shelf.keep(run, tests, machine)
                return plain
    frame = _Frame(machine, number)
    with _quiet_numpy():
        PROGRAMS[number](frame, method)
    return frame


def _translate(error: Exception, frame: _Frame) -> BasicError:
    """The BASIC run-time error for a linkage exception."""
    from yaseer.linkages.errors import AssemblyError, LockedError, MethodDivisionByZero, SingularForceError

    if isinstance(error, AssemblyError):
        return frame.error("Mechanism cannot be assembled")
    if isinstance(error, LockedError):
        return frame.error("Mechanism locks: rates undefined at a toggle position")
    if isinstance(error, SingularForceError):
        return frame.error("Force system is singular")
    if isinstance(error, MethodDivisionByZero):
        return frame.error("Division by zero", DIVISION_BY_ZERO)
    if isinstance(error, (OverflowError, ZeroDivisionError)) or str(error) == "math domain error":
        # Python's float errors of a one-position call: the same error as the inf or
        # NaN numpy gives for many positions (Frame.commit)
        return frame.error("Overflow", OVERFLOW)
    if isinstance(error, TypeError):  # e.g. an input array the listing made two-dimensional
        return frame.error("Type mismatch", TYPE_MISMATCH)
    return frame.error(str(error))


def _selected_unknown(frame: _Frame) -> str:
    """The load named by Q(n), or the BASIC error for a Q(n) outside the allowed set."""
    choices = UNKNOWNS[frame.area]
    q = frame.choice("Q", frame.area)
    if q not in choices:
        allowed = " or ".join(str(choice) for choice in choices)
        raise frame.error(f"Q({frame.area}) = {q:g} is not {allowed}")
    return choices[int(q)]


def _known_loads(frame: _Frame) -> dict[str, float]:
    return {name: frame.get(*element) for name, element in LOADS[frame.area].items()}


def _put_forces(frame: _Frame, result) -> None:
    """Write the solved unknown and every reaction of the program."""
    frame.put(LOADS[frame.area][result.unknown], result.value)
    for name, elements in REACTIONS[frame.area].items():
        value = result.reactions[name]  # complex for a pin
        if len(elements) == 2:
            frame.put(elements[0], value.real)
            frame.put(elements[1], value.imag)
        else:
            frame.put(elements[0], value.real)


def _forces_wanted(frame: _Frame) -> bool:
    return frame.choice("Z", frame.area) == 2


def _mass(frame: _Frame, mass: int, inertia: Element, distance: Element, offset: Element):
    return _linkages().MassProps(frame.get("M", mass), frame.get(*inertia), frame.get(*distance), frame.get(*offset))


def program_1(frame: _Frame, method: str | None) -> None:
    """Slider-crank AoAB (contract, Program 1)."""
    g = frame.get
    kin = _linkages().slider_crank(g("L", 1), g("L", 2), g("L", 3), g("T", 2), g("W", 2), g("A", 2),
                       crank_length_rate=g("D", 0), crank_length_accel=g("E", 0), axis_deg=g("T", 4), method=method)
    frame.put(("T", 3), kin.rod.degrees)
    frame.put(("W", 3), kin.rod.omega)
    frame.put(("A", 3), kin.rod.alpha)
    frame.put_point(kin.crank_point(g("R", 1), g("H", 1)), (("X", 1), ("Y", 1)), (("V", 1), ("V", 2)),
                    (("A", 33), ("A", 34)))
    centre = kin.crank_point(g("R", 2), g("H", 2))
    frame.put(("A", 10), centre.acc.real)
    frame.put(("A", 11), centre.acc.imag)
    frame.put_point(kin.rod_point(g("R", 4), g("H", 4)), (("X", 2), ("Y", 2)), (("V", 3), ("V", 4)),
                    (("A", 35), ("A", 36)))
    if _forces_wanted(frame):
        result = kin.forces(
            crank=_mass(frame, 2, ("I", 2), ("R", 2), ("H", 2)),
            rod=_mass(frame, 3, ("I", 3), ("R", 3), ("H", 3)),
            piston_mass=g("M", 4),
            crank_point=(g("R", 1), g("H", 1)),
            rod_point=(g("R", 4), g("H", 4)),
            loads=_known_loads(frame),
            unknown=_selected_unknown(frame),
            gravity=frame.scalar("G"),
        )
        _put_forces(frame, result)


def _branch(l10: float) -> int:
    """L(10) = 1: crossed; anything else but TRACKING uncrossed."""
    return _linkages().CROSSED if l10 == 1 else _linkages().UNCROSSED


TRACKING = -1  # L(10) = -1: continuous branch tracking (yaseer.linkages.tracking)
_trackers = None  # a weakref.WeakKeyDictionary machine -> tracking.BranchTracker, made by the first tracked call


def _tracked_fourbar(frame: _Frame):
    """Program 2 kinematics following the motion across change points and toggles
    (one tracker per machine, starting uncrossed); each branch switch is reported
    on standard error as ``PROG 2: branch switch at crank angle ...``.  The track
    moves on only when the call succeeds: a failing call (an error after the
    kinematics, trapped by ON ERROR) leaves it, like every element, as it was."""
    from yaseer.linkages.tracking import BranchTracker, Geometry

    if isinstance(frame, _RecordingFrame):  # the tracker keeps state between calls: never recorded
        from yaseer.linkages.tracing import NotTraceable

        raise NotTraceable("branch tracking")
    g = frame.get
    global _trackers
    if _trackers is None:  # (weakref's import is start-up time a run without tracking would pay)
        from weakref import WeakKeyDictionary

        _trackers = WeakKeyDictionary()
    tracker = _trackers.get(frame.machine) or _trackers.setdefault(frame.machine, BranchTracker(_linkages().UNCROSSED))
    geometry = Geometry(g("L", 11), g("T", 11), g("L", 12), g("L", 13), g("L", 14))
    kin, switch = tracker.step(geometry, g("T", 12), g("W", 5), g("A", 5), defer=True,
                               crank_length_rate=g("D", 2), crank_length_accel=g("E", 2))
    frame.after_commit(tracker.accept)
    if switch is not None:
        frame.after_commit(lambda: print(f"PROG 2: {switch.describe()}", file=sys.stderr))
    return kin


def program_2(frame: _Frame, method: str | None) -> None:
    """Four-bar AoABBo (contract, Program 2)."""
    g = frame.get
    branch = frame.choice("L", 10)
    if branch == TRACKING:
        kin = _tracked_fourbar(frame)
    else:
        kin = _linkages().fourbar(g("L", 11), g("T", 11), g("L", 12), g("L", 13), g("L", 14), g("T", 12), g("W", 5),
                      g("A", 5), crank_length_rate=g("D", 2), crank_length_accel=g("E", 2),
                      branch=_branch(branch), method=method)
    for (angle, rate, accel), link in (((("T", 13), ("W", 6), ("A", 6)), kin.coupler),
                                       ((("T", 14), ("W", 7), ("A", 7)), kin.follower)):
        frame.put(angle, link.degrees)
        frame.put(rate, link.omega)
        frame.put(accel, link.alpha)
    frame.put_point(kin.crank_point(g("R", 9), g("H", 9)), (("X", 3), ("Y", 3)), (("V", 5), ("V", 6)),
                    (("A", 37), ("A", 38)))
    frame.put_point(kin.coupler_point(g("R", 11), g("H", 11)), (("X", 4), ("Y", 4)), (("V", 7), ("V", 8)),
                    (("A", 39), ("A", 40)))
    frame.put_point(kin.follower_point(g("R", 13), g("H", 13)), (("X", 5), ("Y", 5)), (("V", 9), ("V", 10)),
                    (("A", 41), ("A", 42)))
    if _forces_wanted(frame):
        result = kin.forces(
            crank=_mass(frame, 6, ("I", 6), ("R", 8), ("H", 10)),
            coupler=_mass(frame, 7, ("I", 7), ("R", 10), ("H", 12)),
            follower=_mass(frame, 8, ("I", 8), ("R", 12), ("H", 14)),
            crank_point=(g("R", 9), g("H", 9)),
            coupler_point=(g("R", 11), g("H", 11)),
            follower_point=(g("R", 13), g("H", 13)),
            loads=_known_loads(frame),
            unknown=_selected_unknown(frame),
            gravity=frame.scalar("G"),
        )
        _put_forces(frame, result)


def program_3(frame: _Frame, method: str | None) -> None:
    """First inversion of the slider-crank, FISC (contract, Program 3)."""
    g = frame.get
    kin = _linkages().inverted_slider_crank(g("L", 6), g("T", 6), g("L", 7), g("T", 7), g("W", 0), g("A", 0),
                                crank_length_rate=g("D", 3), crank_length_accel=g("E", 3), method=method)
    for element, value in ((("L", 5), kin.follower_length.value), (("D", 4), kin.follower_length.rate),
                           (("E", 4), kin.follower_length.accel), (("T", 9), kin.follower.degrees),
                           (("W", 4), kin.follower.omega), (("A", 4), kin.follower.alpha)):
        frame.put(element, value)
    frame.put_point(kin.crank_point(g("R", 0), g("H", 23)), (("X", 6), ("Y", 6)), (("V", 11), ("V", 12)),
                    (("A", 43), ("A", 44)))
    frame.put_point(kin.follower_point(g("R", 7), g("H", 6)), (("X", 7), ("Y", 7)), (("V", 13), ("V", 14)),
                    (("A", 45), ("A", 46)))
    if _forces_wanted(frame):
        result = kin.forces(
            crank=_mass(frame, 0, ("I", 0), ("R", 5), ("T", 5)),
            block_mass=g("M", 1),
            block_inertia=g("I", 1),
            follower=_mass(frame, 5, ("I", 5), ("R", 6), ("H", 7)),
            follower_point=(g("R", 7), g("H", 6)),
            loads=_known_loads(frame),
            unknown=_selected_unknown(frame),
            gravity=frame.scalar("G"),
        )
        _put_forces(frame, result)


def program_5(frame: _Frame, method: str | None) -> None:
    """Motion of a virtual link (contract, Program 5)."""
    g = frame.get
    x, y = g("X", 10), g("Y", 10)
    link = _linkages().virtual_link(x, y, g("V", 17), g("V", 18), g("A", 49), g("A", 50), method=method)
    frame.put_scalar("T", link.angle_deg)
    frame.put_scalar("L", link.length)
    frame.put_scalar("X", x)
    frame.put_scalar("Y", y)
    frame.put(("D", 5), link.angle_rate)
    frame.put(("E", 5), link.angle_accel)
    frame.put(("D", 6), link.length_rate)
    frame.put(("E", 6), link.length_accel)


PROGRAMS: dict[int, Callable[[_Frame, str | None], None]] = {1: program_1, 2: program_2, 3: program_3, 5: program_5}


def _quiet_numpy():
    """numpy's floating-point warnings silenced while numpy is in use (non-finite
    results are caught by :meth:`_Frame.commit`); nothing to silence otherwise.
    Only the plain code needs it (methods and branch tracking may use numpy): a
    recorded path uses none, and entering numpy.errstate would cost it a tenth of its time."""
    numpy = sys.modules.get("numpy")
    return numpy.errstate(all="ignore") if numpy is not None else contextlib.nullcontext()


def make_area(number: int, method: str | None = None) -> Callable[[object], None]:
    """The program area ``number`` as a callable ``area(machine) -> None``."""
    program = PROGRAMS[number]
    key = (number, method)

    def area(machine) -> None:
        try:
            # a recorded path first, here: a call level less on every call that takes one
            recordings = _recordings.get(key)
            if recordings is not None and recordings.run(machine):
                return
            frame = _call_program(machine, number, method)
        except BasicError:
            raise
        except (ArithmeticError, ValueError, TypeError) as error:
            raise _translate(error, _Frame(machine, number)) from error
        if frame is not None:
            frame.commit()

    area.keeps_arrays = True  # it reads and writes elements only (Machine.call_area)
    area.__name__ = f"prog_{number}"
    area.__doc__ = program.__doc__
    return area


def check_methods(methods: dict[int, str] | None) -> dict[int, str]:
    """``methods`` with integer keys, or a BasicError naming what is unknown."""
    checked = {}
    for number, name in (methods or {}).items():
        try:
            number = int(number)
        except (TypeError, ValueError):
            number = None
        if number not in LINKAGES:
            raise BasicError(f"No library program {number} to choose a method for (programs: 1, 2, 3, 5)",
                             ILLEGAL_FUNCTION_CALL)
        from yaseer.linkages.registry import method_names

        known = method_names(LINKAGES[number])
        if name not in known:
            raise BasicError(f"Unknown method {name!r} for PROG {number} (known: {', '.join(known)})",
                             ILLEGAL_FUNCTION_CALL)
        checked[number] = name
    return checked


def install(machine, methods: dict[int, str] | None = None) -> None:
    """Bind the library programs into ``machine``'s program areas 1, 2, 3, 5.

    ``methods`` maps a program number to a method name (e.g. ``{5: "paper"}``);
    unknown programs or names raise a BasicError before anything is bound.
    """
    chosen = check_methods(methods)
    for number in PROGRAMS:
        machine.set_area(number, make_area(number, chosen.get(number)))
