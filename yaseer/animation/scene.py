"""What stays fixed over an animation: bounds, traced paths, symbol size, steady followers."""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Sequence

from yaseer.animation.geometry import Frame, Point, Snapshot, distance
from yaseer.animation.labels import letter_joints


class AnimationError(Exception):
    """An animation that cannot be made (no frames, unknown format, no ffmpeg)."""


@dataclass
class Path2D:
    """The positions of one traced point over the frames (None where a frame lacks it)."""

    label: str
    positions: list[Point | None] = field(default_factory=list)

    def extent(self) -> float:
        """The largest distance between two recorded positions (0 for a fixed point)."""
        known = [p for p in self.positions if p is not None]
        if not known:
            return 0.0
        xs, ys = [p[0] for p in known], [p[1] for p in known]
        return math.hypot(max(xs) - min(xs), max(ys) - min(ys))


def traced_paths(frames: Sequence[Frame], scale: float) -> list[Path2D]:
    """The path of every traced point that is off its link's joint and moves.

    A point is identified by its snapshot's position in the frame and its
    label.  Points that sit on their reference joint in every frame (R = 0: the
    piston itself, the crank pin) add nothing to the joints and get no path;
    nor do points that never move (both within 1e-9 of the scene ``scale``).
    """
    paths: dict[tuple[int, str], Path2D] = {}
    offset: dict[tuple[int, str], float] = {}
    for number, frame in enumerate(frames):
        for index, snapshot in enumerate(frame.snapshots):
            for point in snapshot.points:
                key = (index, point.label)
                path = paths.setdefault(key, Path2D(point.label, [None] * len(frames)))
                path.positions[number] = point.position
                offset[key] = max(offset.get(key, 0.0), distance(point.position, point.joint))
    tiny = 1e-9 * scale
    return [path for key, path in paths.items() if offset[key] > tiny and path.extent() > tiny]


PATH_BREAK = 0.25  # a step longer than this share of the scene is a jump (another branch), not motion


def path_segments(path: Path2D, scale: float) -> list[list[Point]]:
    """The path as polylines: split where a frame lacks the point or it jumps (PATH_BREAK)."""
    segments: list[list[Point]] = []
    current: list[Point] = []
    for position in path.positions:
        if position is None or (current and distance(current[-1], position) > PATH_BREAK * scale):
            if current:
                segments.append(current)
            current = []
        if position is not None:
            current.append(position)
    if current:
        segments.append(current)
    return segments


def scene_bounds(frames: Sequence[Frame]) -> tuple[float, float, float, float]:
    """(xmin, xmax, ymin, ymax) over every joint, bar end and traced point of every frame."""
    xs: list[float] = []
    ys: list[float] = []
    for frame in frames:
        for snapshot in frame.snapshots:
            for point in _all_points(snapshot):
                if math.isfinite(point[0]) and math.isfinite(point[1]):
                    xs.append(point[0])
                    ys.append(point[1])
    if not xs:
        return (-1.0, 1.0, -1.0, 1.0)
    return (min(xs), max(xs), min(ys), max(ys))


def _all_points(snapshot: Snapshot) -> list[Point]:
    points = [p for bar in snapshot.bars for p in (bar.start, bar.end)]
    points += list(snapshot.joints) + list(snapshot.ground)
    points += [traced.position for traced in snapshot.points]
    return points


@dataclass
class Scene:
    """What stays fixed in every frame: the bounds, the paths and the symbol size."""

    frames: list[Frame]
    bounds: tuple[float, float, float, float]
    paths: list[Path2D]
    size: float  # a length in the mechanism's units used for blocks and ground symbols
    letters: dict | None = None  # (call index, role) -> the joint's letter (see .labels)
    zoom: tuple | None = None  # ((x, y), radius, corner): a small link's surroundings, magnified in a corner


def steady_followers(frames: Sequence[Frame]) -> list[Frame]:
    """Give each Program 3 follower (the slotted link) one length over the run: its longest.

    Per call the follower is drawn from Bo past the block; over a cycle the
    block slides, so a follower drawn to each call's own length would seem to
    telescope.  Followers are matched by their call's place in the frame.
    """
    longest: dict[int, float] = {}
    for frame in frames:
        for index, snapshot in enumerate(frame.snapshots):
            if snapshot.area == 3:
                follower = snapshot.bars[1]
                longest[index] = max(longest.get(index, 0.0), distance(follower.start, follower.end))
    if not longest:
        return list(frames)
    return [Frame(tuple(_with_follower_length(s, longest[i]) if s.area == 3 else s
                        for i, s in enumerate(frame.snapshots)), frame.printed) for frame in frames]


def _with_follower_length(snapshot: Snapshot, length: float) -> Snapshot:
    pivot, end = snapshot.bars[1].start, snapshot.bars[1].end
    current = distance(pivot, end)
    if current == 0.0:
        return snapshot
    scale = length / current
    new_end = (pivot[0] + (end[0] - pivot[0]) * scale, pivot[1] + (end[1] - pivot[1]) * scale)
    return replace(snapshot, bars=(snapshot.bars[0], replace(snapshot.bars[1], end=new_end)))


def build_scene(frames: Sequence[Frame]) -> Scene:
    """Bounds with a margin, the moving traced points' paths, the symbol size."""
    if not frames:
        raise AnimationError("Nothing to animate: the listing called no library program before printing")
    frames = steady_followers(frames)
    xmin, xmax, ymin, ymax = scene_bounds(frames)
    span = max(xmax - xmin, ymax - ymin, 1e-12)
    margin = 0.12 * span
    bounds = (xmin - margin, xmax + margin, ymin - margin, ymax + margin)
    return Scene(list(frames), bounds, traced_paths(frames, span), 0.035 * span,
                 letter_joints(frames[0].snapshots, span), small_link_zoom(frames, bounds, span))


SMALL_LINK = 0.03  # a crank shorter than this share of the scene is magnified in an inset (Example 1: 0.045, not)
CORNERS = ((1, 0), (0, 0), (1, 1), (0, 1))  # (x, y) of an inset corner, in axes fractions


def small_link_zoom(frames: Sequence[Frame], bounds, span: float) -> tuple | None:
    """Where to magnify a crank too short to see at the scene's scale (Example 5's 0.075 m crank in a
    2.5 m picture): its fixed pivot, a radius twice the crank, and the corner of the picture farthest
    from every joint of the run (the inset sits there); None when every crank is long enough."""
    short = [(bar.start, distance(bar.start, bar.end)) for snapshot in frames[0].snapshots
             if snapshot.crank is not None and not (bar := snapshot.bars[snapshot.crank]).virtual
             and 0.0 < distance(bar.start, bar.end) < SMALL_LINK * span]
    if not short:
        return None
    pivot, length = min(short, key=lambda item: item[1])
    xmin, xmax, ymin, ymax = bounds
    points = [p for frame in frames for snapshot in frame.snapshots for p in _all_points(snapshot)]

    def clearance(corner):
        cx = xmin + (xmax - xmin) * (0.15 + 0.7 * corner[0])
        cy = ymin + (ymax - ymin) * (0.15 + 0.7 * corner[1])
        return min((math.hypot(px - cx, py - cy) for px, py in points), default=span)

    return pivot, 2.0 * length, max(CORNERS, key=clearance)
