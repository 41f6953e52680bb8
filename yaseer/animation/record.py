"""Recording a run: the geometry of every ``GOSUB PROG n``, one frame per printed line.

:class:`Recorder` is a machine area hook.  After each ``GOSUB PROG n`` it reads
back, from the machine's arrays, the joints that program's inputs and outputs
imply — lengths and angles it was given or computed, never a second solve — as
a :class:`~yaseer.animation.geometry.Snapshot`.  A frame is everything recorded
between two printed lines, with the line printed, so each frame shows the
mechanism at the position the listing reported.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Callable, Sequence

from yaseer.animation.geometry import (
    ORIGIN, Bar, Frame, Point, Slider, Snapshot, TracedPoint, distance, plus, polar,
)


class _Elements:
    """Read-only view of a machine array: an element the listing's DIM left out reads as 0.

    (The recorder must never turn a listing's own ``DIM X(3)`` into an error.)
    """

    def __init__(self, values) -> None:
        self._values = values

    def __getitem__(self, index: int) -> float:
        try:
            return float(self._values[index])
        except (IndexError, TypeError, ValueError):
            return 0.0


def _arrays(machine, *names: str) -> list[_Elements]:
    return [_Elements(machine.array(name)) for name in names]


def snapshot_slider_crank(machine) -> Snapshot:
    """Program 1: crank Ao->A = L(2) at T(2), rod A->B = L(3) at T(3), piston B on the axis at T(4)."""
    L, T, X, Y = _arrays(machine, "L", "T", "X", "Y")
    a_pin = polar(L[2], T[2])
    b_pin = plus(a_pin, polar(L[3], T[3]))
    axis_point = polar(L[1], T[4] - 90.0)
    return Snapshot(
        area=1,
        crank_angle=T[2],
        bars=(Bar(ORIGIN, a_pin), Bar(a_pin, b_pin)),
        joints=(a_pin, b_pin),
        ground=(ORIGIN,),
        sliders=(Slider(b_pin, T[4], axis_point),),
        points=(
            TracedPoint("PROG 1 X(1),Y(1)", (X[1], Y[1]), ORIGIN),
            TracedPoint("PROG 1 X(2),Y(2)", (X[2], Y[2]), b_pin),
        ),
    )


def snapshot_four_bar(machine) -> Snapshot:
    """Program 2: crank L(12) at T(12), coupler L(13) at T(13), Bo = L(11) at T(11)."""
    L, T, X, Y = _arrays(machine, "L", "T", "X", "Y")
    a_pin = polar(L[12], T[12])
    b_pin = plus(a_pin, polar(L[13], T[13]))
    b_pivot = polar(L[11], T[11])
    return Snapshot(
        area=2,
        crank_angle=T[12],
        bars=(Bar(ORIGIN, a_pin), Bar(a_pin, b_pin), Bar(b_pin, b_pivot)),
        joints=(a_pin, b_pin),
        ground=(ORIGIN, b_pivot),
        points=(
            TracedPoint("PROG 2 X(3),Y(3)", (X[3], Y[3]), ORIGIN),
            TracedPoint("PROG 2 X(4),Y(4)", (X[4], Y[4]), a_pin),
            TracedPoint("PROG 2 X(5),Y(5)", (X[5], Y[5]), b_pivot),
        ),
    )


FOLLOWER_OVERHANG = 0.15  # the slotted follower of Program 3 is drawn this much longer than Bo->A


def snapshot_inverted_slider_crank(machine) -> Snapshot:
    """Program 3: crank L(7) at T(7), Bo = -L(6) u(T(6)), follower Bo->A = L(5) at T(9), block at A."""
    L, T, X, Y = _arrays(machine, "L", "T", "X", "Y")
    a_pin = polar(L[7], T[7])
    b_pivot = polar(-L[6], T[6])
    follower_end = plus(b_pivot, polar(L[5] * (1.0 + FOLLOWER_OVERHANG), T[9]))
    return Snapshot(
        area=3,
        crank_angle=T[7],
        bars=(Bar(ORIGIN, a_pin), Bar(b_pivot, follower_end)),
        joints=(a_pin,),
        ground=(ORIGIN, b_pivot),
        sliders=(Slider(a_pin, T[9]),),
        points=(
            TracedPoint("PROG 3 X(6),Y(6)", (X[6], Y[6]), ORIGIN),
            TracedPoint("PROG 3 X(7),Y(7)", (X[7], Y[7]), b_pivot),
        ),
    )


def snapshot_virtual_link(machine) -> Snapshot:
    """Program 5: the virtual link from the origin to (X(10), Y(10)), dashed."""
    X, Y = _arrays(machine, "X", "Y")
    tip = (X[10], Y[10])
    return Snapshot(
        area=5,
        crank_angle=machine.scalar("T"),
        bars=(Bar(ORIGIN, tip, virtual=True),),
        joints=(),
        ground=(ORIGIN,),
        crank=None,
    )


SNAPSHOTS: dict[int, Callable[[object], Snapshot]] = {
    1: snapshot_slider_crank,
    2: snapshot_four_bar,
    3: snapshot_inverted_slider_crank,
    5: snapshot_virtual_link,
}


# --- recording ------------------------------------------------------------------


class Recorder:
    """Collects frames during a run: register :meth:`hook` in ``machine.area_hooks``, feed it printed lines."""

    def __init__(self) -> None:
        self.frames: list[Frame] = []
        self._pending: list[Snapshot] = []

    def hook(self, machine, area_number: int) -> None:
        """After ``GOSUB PROG n`` returned: record the geometry of program n (other areas: nothing).

        A call that fails raises before the hooks run, so it records nothing.
        """
        reader = SNAPSHOTS.get(area_number)
        if reader is not None:
            self._pending.append(reader(machine))

    def line_printed(self, text: str) -> None:
        """A line was printed: it closes the frame of the calls since the last one.

        A line printed with no call since the previous line joins that frame's
        text; one printed before any call (a heading) is not a frame.
        """
        if self._pending:
            self.frames.append(Frame(tuple(self._pending), text))
            self._pending = []
        elif self.frames:
            self.frames[-1].printed += "\n" + text

    def finish(self) -> list[Frame]:
        """Close the run: calls after the last printed line make a last frame."""
        if self._pending:
            self.frames.append(Frame(tuple(self._pending), ""))
            self._pending = []
        return merge_positions([prepare_frame(frame) for frame in self.frames])


# --- assembling frames ------------------------------------------------------------

SAME_POINT = 1e-9  # relative distance within which two points are one (a crank tip and a virtual link end)


def prepare_frame(frame: Frame) -> Frame:
    """Drop repeated calls with the same geometry and dash cranks that are virtual links."""
    seen: set = set()
    unique: list[Snapshot] = []
    for snapshot in frame.snapshots:
        if snapshot.key() not in seen:
            seen.add(snapshot.key())
            unique.append(snapshot)
    virtual_ends = [s.bars[0].end for s in unique if s.area == 5]
    marked = tuple(_mark_virtual_crank(s, virtual_ends) for s in unique)
    return Frame(marked, frame.printed)


def merge_positions(frames: Sequence[Frame]) -> list[Frame]:
    """One frame per position: a frame showing another assembly of a position already shown joins
    that position's frame, its calls marked ``alternative`` and its printed line under the first.

    The other assembly is the same mechanism (same calls, same driving crank, fixed pivots and
    slider lines: :func:`_same_position`) with its moving joints elsewhere.  It may be printed on
    the next line (seed 003 prints each angle's two rows together) or in a later run of its own
    (seed 001 prints a whole cycle of each branch): either way every branch of one position is
    drawn together, instead of the branches taking turns.  A position takes one other assembly.
    """
    merged: list[Frame] = []
    for frame in frames:
        target = next((k for k in range(len(merged) - 1, -1, -1)
                       if frame.printed and _same_position(merged[k], frame)), None)
        if target is None:
            merged.append(frame)
            continue
        before = merged[target]
        others = tuple(replace(s, alternative=True) for s in frame.snapshots)
        merged[target] = prepare_frame(Frame(before.snapshots + others, before.printed + "\n" + frame.printed))
    return merged


def _same_position(shown: Frame, other: Frame) -> bool:
    """Whether ``other`` is another assembly of ``shown``'s position (which has none yet)."""
    if any(s.alternative for s in shown.snapshots) or not _same_angle(shown.crank_angle, other.crank_angle):
        return False
    pairs = list(zip(shown.snapshots, other.snapshots))
    if len(shown.snapshots) != len(other.snapshots) or any(a.area != b.area for a, b in pairs):
        return False
    driving = next((k for k, s in enumerate(shown.snapshots) if s.crank is not None), None)
    if driving is not None and not _same_bar(shown.snapshots[driving].bars[0], other.snapshots[driving].bars[0]):
        return False
    return all(_same_frame_of_reference(a, b) for a, b in pairs) and \
        any(a.key() != b.key() for a, b in pairs)


def _same_frame_of_reference(a: Snapshot, b: Snapshot) -> bool:
    """The same fixed pivots and the same slider lines (an axis and its reverse are one line)."""
    if len(a.ground) != len(b.ground) or len(a.sliders) != len(b.sliders):
        return False
    scale = max([1.0] + [abs(c) for bar in a.bars for c in (*bar.start, *bar.end)])
    if any(distance(p, q) > SAME_POINT * scale for p, q in zip(a.ground, b.ground)):
        return False
    for one, two in zip(a.sliders, b.sliders):
        if (one.axis is None) != (two.axis is None):
            return False
        if one.axis is not None and not _on_one_line(one, two, scale):
            return False
    return True


def _on_one_line(one, two, scale: float) -> bool:
    turn = math.remainder(one.angle_deg - two.angle_deg, 180.0)
    direction = polar(1.0, one.angle_deg)
    dx, dy = two.axis[0] - one.axis[0], two.axis[1] - one.axis[1]
    return abs(turn) <= 1e-9 and abs(direction[0] * dy - direction[1] * dx) <= SAME_POINT * scale


def _same_bar(p: Bar, q: Bar) -> bool:
    scale = max(1.0, abs(p.start[0]), abs(p.start[1]), abs(p.end[0]), abs(p.end[1]))
    return distance(p.start, q.start) <= SAME_POINT * scale and distance(p.end, q.end) <= SAME_POINT * scale


def _same_angle(a: float, b: float) -> bool:
    return abs(a - b) <= 1e-9 * max(1.0, abs(a))


def _mark_virtual_crank(snapshot: Snapshot, virtual_ends: Sequence[Point]) -> Snapshot:
    if snapshot.crank is None:
        return snapshot
    crank = snapshot.bars[snapshot.crank]
    scale = max(1.0, math.hypot(*crank.end))
    if not any(distance(crank.end, end) <= SAME_POINT * scale for end in virtual_ends):
        return snapshot
    bars = list(snapshot.bars)
    bars[snapshot.crank] = replace(crank, virtual=True)
    return replace(snapshot, bars=tuple(bars))
