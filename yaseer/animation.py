"""Animating a listing's mechanism from the positions its programs computed.

Recording: :class:`Recorder` is a machine area hook.  After each ``GOSUB PROG n`` it reads
back, from the machine's arrays, the joints that program's inputs and outputs
imply — lengths and angles it was given or computed, never a second solve —
as a :class:`Snapshot`.  A :class:`Frame` is everything recorded between two
printed lines, with the line printed, so each frame shows the mechanism at the
position the listing reported.

Drawing: :func:`render` draws links as bars, joints as circles, fixed pivots as
ground triangles, sliders as blocks on their axes, the path of each traced
point (a point of interest whose path is not a single point), and on each frame
the crank angle and the printed values.  Virtual links (Program 5) are dashed;
a crank that *is* a virtual link (a flexible crank fed by Program 5 in the same
frame) is dashed too.

Geometry conventions are those of the programs' contract
(``shared/spec/programs.md``): crank pivot Ao at the origin, x right, y up,
angles in degrees counter-clockwise from +x, any consistent length unit.
"""

from __future__ import annotations

import math
import shutil
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable, Sequence

Point = tuple[float, float]

ORIGIN: Point = (0.0, 0.0)


def polar(length: float, angle_deg: float) -> Point:
    """The vector of ``length`` at ``angle_deg`` (degrees, counter-clockwise from +x)."""
    angle = math.radians(angle_deg)
    return (length * math.cos(angle), length * math.sin(angle))


def plus(p: Point, q: Point) -> Point:
    """p + q."""
    return (p[0] + q[0], p[1] + q[1])


def distance(p: Point, q: Point) -> float:
    """|p - q|."""
    return math.hypot(p[0] - q[0], p[1] - q[1])


@dataclass(frozen=True)
class Bar:
    """A link drawn as a bar from ``start`` to ``end``; ``virtual`` bars are dashed."""

    start: Point
    end: Point
    virtual: bool = False


@dataclass(frozen=True)
class Slider:
    """A block at ``centre`` turned to ``angle_deg``; ``axis`` is a point on its fixed axis (None: no fixed axis)."""

    centre: Point
    angle_deg: float
    axis: Point | None = None


@dataclass(frozen=True)
class TracedPoint:
    """A point of interest ``label`` at ``position``, carried by the link through ``joint``."""

    label: str
    position: Point
    joint: Point


@dataclass(frozen=True)
class Snapshot:
    """What one call of program ``area`` computed, as geometry.

    ``crank`` is the index in ``bars`` of the driving crank (None for
    Program 5), ``crank_angle`` its angle in degrees.
    """

    area: int
    crank_angle: float
    bars: tuple[Bar, ...]
    joints: tuple[Point, ...]
    ground: tuple[Point, ...]
    sliders: tuple[Slider, ...] = ()
    points: tuple[TracedPoint, ...] = ()
    crank: int | None = 0

    def key(self) -> tuple:
        """Identity of the drawn geometry (two calls with equal keys draw the same)."""
        rounded = tuple(tuple(round(c, 9) for c in (*bar.start, *bar.end)) for bar in self.bars)
        return (self.area, rounded)


@dataclass
class Frame:
    """The calls recorded between two printed lines, and the text printed."""

    snapshots: tuple[Snapshot, ...]
    printed: str = ""

    @property
    def crank_angle(self) -> float:
        """The input crank angle of the first basic linkage called (degrees)."""
        for snapshot in self.snapshots:
            if snapshot.crank is not None:
                return snapshot.crank_angle
        return self.snapshots[0].crank_angle


# --- reading a call's geometry back from the machine ------------------------------


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
        return [prepare_frame(frame) for frame in self.frames]


@dataclass
class Recording:
    """The frames of one run and the BASIC error that stopped it (None: it ran to its end)."""

    frames: list[Frame]
    error: Exception | None = None
    title: str = ""


class _LineCounter:
    """A text stream that only counts lines into a progress bar."""

    def __init__(self, progress) -> None:
        self._progress = progress

    def write(self, text: str) -> int:
        self._progress.update(text.count("\n"))
        return len(text)

    def flush(self) -> None:
        """Nothing is kept."""

    def isatty(self) -> bool:
        return False


def record_run(listing, methods: dict[int, str] | None = None, progress_file=None,
               angle: str | None = None, **run_options) -> Recording:
    """Run ``listing`` (a path or the program text) once through :func:`yaseer.run`, keeping its frames.

    PRINT and LPRINT output both close frames.  A BASIC error (syntax, run
    time, a mechanism that cannot be assembled) ends the run: the frames
    recorded before it are kept with the error, so the animation can show the
    mechanism up to where the method broke.  A progress counter of printed
    lines appears on stderr if the run takes more than a second.  ``angle``
    is the unit of the trigonometric functions, as ``yaseer run --angle``;
    ``run_options`` are further :func:`yaseer.run` arguments (``prog``,
    ``input``, ``dialect``).
    """
    from yaseer.api import run
    from yaseer.progress import bar

    with bar(None, "running", "line", file=progress_file) as progress:
        result = run(listing, method=methods, angle=angle, screen=_LineCounter(progress), **run_options)
    return Recording(result.frames, result.exception, result.title)


def record_listing(text: str, methods: dict[int, str] | None = None, progress_file=None) -> list[Frame]:
    """The frames of a run that must complete: as :func:`record_run`, raising its BASIC error."""
    recording = record_run(text, methods, progress_file)
    if recording.error is not None:
        raise recording.error
    return recording.frames


# --- assembling frames ------------------------------------------------------------

VIRTUAL_MATCH = 1e-9  # relative distance within which a crank tip is a virtual link's end


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


def _mark_virtual_crank(snapshot: Snapshot, virtual_ends: Sequence[Point]) -> Snapshot:
    if snapshot.crank is None:
        return snapshot
    crank = snapshot.bars[snapshot.crank]
    scale = max(1.0, math.hypot(*crank.end))
    if not any(distance(crank.end, end) <= VIRTUAL_MATCH * scale for end in virtual_ends):
        return snapshot
    bars = list(snapshot.bars)
    bars[snapshot.crank] = replace(crank, virtual=True)
    return replace(snapshot, bars=tuple(bars))


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


# --- drawing --------------------------------------------------------------------

SUFFIXES = (".gif", ".mp4", ".html", ".png")
TRACE_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink")


class AnimationError(Exception):
    """An animation that cannot be made (no frames, unknown format, no ffmpeg)."""


@dataclass
class Scene:
    """What stays fixed in every frame: the bounds, the paths and the symbol size."""

    frames: list[Frame]
    bounds: tuple[float, float, float, float]
    paths: list[Path2D]
    size: float  # a length in the mechanism's units used for blocks and ground symbols


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
    return Scene(list(frames), bounds, traced_paths(frames, span), 0.035 * span)


def draw_background(ax, scene: Scene) -> None:
    """What every frame shares: the limits, equal scales, the grid and the traced paths."""
    ax.set_xlim(scene.bounds[0], scene.bounds[1])
    ax.set_ylim(scene.bounds[2], scene.bounds[3])
    ax.set_aspect("equal", adjustable="box")
    ax.grid(True, color="0.92", linewidth=0.6)
    span = max(scene.bounds[1] - scene.bounds[0], scene.bounds[3] - scene.bounds[2])
    for colour, path in zip(_colours(), scene.paths):
        for segment in path_segments(path, span):
            ax.plot(*zip(*segment), color=colour, linewidth=1.0, alpha=0.6, marker=".", markersize=2.5)


def draw_moving(ax, scene: Scene, number: int, title: str = "", animated: bool = False) -> list:
    """Add frame ``number``'s mechanism, angle and printed text to ``ax``; returns the artists."""
    from matplotlib.patches import Circle, Polygon

    frame = scene.frames[number]
    artists: list = []
    for snapshot in frame.snapshots:
        for pivot in snapshot.ground:
            artists.append(ax.add_patch(Polygon(_ground_triangle(pivot, scene.size), closed=True,
                                                color="0.6", zorder=2)))
        for slider in snapshot.sliders:
            if slider.axis is not None:
                artists.append(ax.axline(slider.axis, plus(slider.axis, polar(1.0, slider.angle_deg)),
                                         color="0.5", linewidth=0.8, linestyle="-.", zorder=1))
            artists.append(ax.add_patch(Polygon(_block(slider, scene.size), closed=True, facecolor="#c9d6e8",
                                                edgecolor="black", linewidth=1.0, zorder=4)))
        for traced in snapshot.points:  # the rigid link carried on to its point of interest
            artists += ax.plot(*zip(traced.joint, traced.position), color="0.3", linewidth=2.0,
                               solid_capstyle="round", zorder=3)
        for bar in snapshot.bars:
            style = dict(color="0.45", linewidth=1.4, linestyle="--") if bar.virtual else \
                dict(color="black", linewidth=3.2, solid_capstyle="round")
            artists += ax.plot(*zip(bar.start, bar.end), zorder=3, **style)
        for joint in (*snapshot.joints, *snapshot.ground):
            artists.append(ax.add_patch(Circle(joint, 0.35 * scene.size, facecolor="white", edgecolor="black",
                                               linewidth=1.2, zorder=5)))
    for colour, path in zip(_colours(), scene.paths):
        position = path.positions[number]
        if position is not None:
            artists += ax.plot(*position, marker="o", markersize=5, color=colour, zorder=6)
    heading = f"{title}   crank angle {frame.crank_angle:.1f}\N{DEGREE SIGN}".strip()
    artists.append(ax.text(0.5, 1.015, heading, transform=ax.transAxes, ha="center", va="bottom", fontsize=10))
    artists.append(ax.annotate(frame.printed, xy=(0.0, 0.0), xycoords="axes fraction", xytext=(0, -24),
                               textcoords="offset points", va="top", ha="left", family="monospace",
                               fontsize=9, annotation_clip=False))
    for artist in artists:
        artist.set_animated(animated)
    return artists


def draw_frame(ax, scene: Scene, number: int, title: str = "") -> None:
    """Draw frame ``number`` of ``scene`` on an empty ``ax`` (background and mechanism)."""
    draw_background(ax, scene)
    draw_moving(ax, scene, number, title)


def _colours():
    while True:
        yield from TRACE_COLOURS


def _ground_triangle(pivot: Point, size: float) -> list[Point]:
    x, y = pivot
    return [(x, y), (x - 0.6 * size, y - 1.0 * size), (x + 0.6 * size, y - 1.0 * size)]


def _block(slider: Slider, size: float) -> list[Point]:
    """The four corners of the slider block, 2.4 x 1.4 ``size``, turned to its axis."""
    along = polar(1.2 * size, slider.angle_deg)
    across = polar(0.7 * size, slider.angle_deg + 90.0)
    cx, cy = slider.centre
    return [(cx + sa * along[0] + sc * across[0], cy + sa * along[1] + sc * across[1])
            for sa, sc in ((1, 1), (-1, 1), (-1, -1), (1, -1))]


class _Painter:
    """Paints frames fast: the background is drawn once, each frame only adds its moving parts."""

    def __init__(self, scene: Scene, title: str) -> None:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt

        width, height, bottom, top = _figure_layout(scene)
        self.figure, self.ax = plt.subplots(figsize=(width, height), dpi=90)
        self.figure.subplots_adjust(left=0.1, right=0.97, top=1.0 - top / height, bottom=bottom / height)
        self.scene, self.title = scene, title
        draw_background(self.ax, scene)
        self.figure.canvas.draw()
        self.background = self.figure.canvas.copy_from_bbox(self.figure.bbox)

    def image(self, number: int):
        """Frame ``number`` as a PIL RGB image."""
        import numpy as np
        from PIL import Image

        canvas = self.figure.canvas
        canvas.restore_region(self.background)
        artists = draw_moving(self.ax, self.scene, number, self.title, animated=True)
        for artist in sorted(artists, key=lambda a: a.get_zorder()):
            self.ax.draw_artist(artist)
        pixels = np.asarray(canvas.buffer_rgba())
        image = Image.fromarray(pixels[..., :3].copy(), "RGB")
        for artist in artists:
            artist.remove()
        return image

    def close(self) -> None:
        import matplotlib.pyplot as plt

        plt.close(self.figure)


MAX_FRAMES = 360  # a longer run is shown by evenly spaced frames (its paths stay complete)


def frames_to_paint(count: int, max_frames: int = MAX_FRAMES) -> list[int]:
    """The frame numbers an animation shows: all, or ``max_frames`` evenly spaced ones (first and last kept)."""
    if max_frames < 2:
        raise AnimationError("An animation needs at least 2 frames")
    if count <= max_frames:
        return list(range(count))
    return sorted({round(k * (count - 1) / (max_frames - 1)) for k in range(max_frames)})


def render(frames: Sequence[Frame], out: Path, title: str = "", fps: float = 6.0,
           frame_number: int = 0, progress_file=None, max_frames: int = MAX_FRAMES) -> int:
    """Write the animation to ``out`` (.gif, .mp4, .html; .png: only frame ``frame_number``).

    Returns the number of frames written (at most ``max_frames``: a longer run
    is thinned evenly, see :func:`frames_to_paint`).  Raises
    :class:`AnimationError` for an unknown suffix, no frames, a missing frame,
    or .mp4 without ffmpeg.  A progress bar (stderr) appears when painting
    takes over a second.
    """
    suffix = out.suffix.lower()
    if suffix not in SUFFIXES:
        raise AnimationError(f"Unknown animation format {out.suffix!r}: use {', '.join(SUFFIXES)}")
    if not (math.isfinite(fps) and fps > 0):
        raise AnimationError(f"Frames per second must be a positive number, not {fps:g}")
    scene = build_scene(frames)
    if suffix == ".png" and not 0 <= frame_number < len(scene.frames):
        raise AnimationError(f"Frame {frame_number} does not exist: the run has {len(scene.frames)}")
    if suffix == ".mp4" and ffmpeg_program() is None:
        raise AnimationError("Writing .mp4 needs ffmpeg, which is not installed here; use .gif or .html")
    painter = _Painter(scene, title)
    try:
        if suffix == ".png":
            painter.image(frame_number).save(out)
            return 1
        images = _paint_all(painter, frames_to_paint(len(scene.frames), max_frames), progress_file)
    finally:
        painter.close()
    WRITERS[suffix](images, out, fps)
    return len(images)


def player(frames: Sequence[Frame], title: str = "", fps: float = 6.0, max_frames: int = MAX_FRAMES):
    """A matplotlib ``FuncAnimation`` of the frames (``.to_jshtml()`` for a notebook, ``.save()`` for a file).

    Its figure is a free-standing ``matplotlib.figure.Figure`` (not pyplot's), so
    a notebook does not also show it as a still.
    """
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure

    scene = build_scene(frames)
    width, height, bottom, top = _figure_layout(scene)
    figure = Figure(figsize=(width, height), dpi=90)
    figure.subplots_adjust(left=0.1, right=0.97, top=1.0 - top / height, bottom=bottom / height)
    ax = figure.add_subplot()
    draw_background(ax, scene)
    shown: list = []

    def update(number: int) -> list:
        for artist in shown:
            artist.remove()
        shown[:] = draw_moving(ax, scene, number, title)
        return shown

    return FuncAnimation(figure, update, frames=frames_to_paint(len(scene.frames), max_frames),
                         interval=1000.0 / fps, blit=False)


def _paint_all(painter: _Painter, numbers: list[int], progress_file) -> list:
    from yaseer.progress import track

    return [painter.image(n) for n in track(numbers, description="rendering", unit="frame", file=progress_file)]


GIF_COLOURS = 64  # line art in a few colours: plenty, and a quarter of the time of an adaptive 256


def write_gif(images: list, out: Path, fps: float) -> None:
    """An endlessly looping GIF, ``fps`` frames a second (Pillow; 64 colours, fast octree palette)."""
    fast_octree = 2  # Image.Quantize.FASTOCTREE (a plain number for Pillow before 9.1)
    frames = [image.quantize(colors=GIF_COLOURS, method=fast_octree) for image in images]
    frames[0].save(out, save_all=True, append_images=frames[1:], duration=round(1000.0 / fps), loop=0)


HTML_PAGE = """<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>{title}</title></head>
<body style="font-family: sans-serif">
<img id="frame" src="{first}" alt="{title}"><br>
<button id="play">pause</button>
<input id="slider" type="range" min="0" max="{last}" value="0" style="width: 60%">
<span id="number">0</span>
<script>
const frames = {frames};
const img = document.getElementById("frame"), slider = document.getElementById("slider");
const number = document.getElementById("number"), play = document.getElementById("play");
let current = 0, timer = null;
function show(n) {{ current = n; img.src = frames[n]; slider.value = n; number.textContent = n; }}
function start() {{ timer = setInterval(() => show((current + 1) % frames.length), {interval}); play.textContent = "pause"; }}
function stop() {{ clearInterval(timer); timer = null; play.textContent = "play"; }}
play.onclick = () => (timer ? stop() : start());
slider.oninput = () => {{ stop(); show(Number(slider.value)); }};
start();
</script>
</body></html>
"""


def write_html(images: list, out: Path, fps: float) -> None:
    """A self-contained page: the frames as PNG data, play/pause and a frame slider."""
    import base64
    import io
    import json

    urls = []
    for image in images:
        buffer = io.BytesIO()
        image.save(buffer, format="PNG")
        urls.append("data:image/png;base64," + base64.b64encode(buffer.getvalue()).decode("ascii"))
    out.write_text(HTML_PAGE.format(title=out.stem, first=urls[0], last=len(urls) - 1, frames=json.dumps(urls),
                                    interval=round(1000.0 / fps)), encoding="utf-8")


def ffmpeg_program() -> str | None:
    """The ffmpeg to run: one on PATH, else the binary the imageio-ffmpeg wheel ships, else None."""
    found = shutil.which("ffmpeg")
    if found is not None:
        return found
    try:
        import imageio_ffmpeg
    except ImportError:
        return None
    try:
        return imageio_ffmpeg.get_ffmpeg_exe()
    except RuntimeError:  # the wheel has no binary for this platform
        return None


def write_mp4(images: list, out: Path, fps: float) -> None:
    """H.264 through the ffmpeg program: raw RGB frames piped to it."""
    import subprocess

    width, height = images[0].size
    width, height = width - width % 2, height - height % 2  # yuv420p wants even sizes
    command = [ffmpeg_program() or "ffmpeg", "-y", "-loglevel", "error", "-f", "rawvideo", "-pix_fmt", "rgb24",
               "-s", f"{width}x{height}", "-r", f"{fps}", "-i", "-", "-pix_fmt", "yuv420p", str(out)]
    data = b"".join(image.crop((0, 0, width, height)).tobytes() for image in images)
    result = subprocess.run(command, input=data, capture_output=True)
    if result.returncode != 0:
        raise AnimationError(f"ffmpeg failed: {result.stderr.decode(errors='replace').strip()[:200]}")


WRITERS = {".gif": write_gif, ".html": write_html, ".mp4": write_mp4}


FIGURE_WIDTH = 6.4  # inches


def _figure_layout(scene: Scene) -> tuple[float, float, float, float]:
    """(width, height, bottom margin, top margin) in inches: the axes keep the scene's shape.

    The axes are at most 6 inches tall; the bottom margin holds the tick
    labels and the longest caption.
    """
    xmin, xmax, ymin, ymax = scene.bounds
    axes_width = FIGURE_WIDTH * 0.87
    axes_height = min(6.0, max(2.5, axes_width * (ymax - ymin) / (xmax - xmin)))
    caption_lines = max(frame.printed.count("\n") + 1 for frame in scene.frames)
    bottom = 0.55 + 0.18 * caption_lines
    top = 0.4
    return FIGURE_WIDTH, axes_height + bottom + top, bottom, top
