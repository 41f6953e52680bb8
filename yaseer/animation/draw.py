"""Drawing frames for a projector: the mechanism, its joints' letters, the printed values.

A frame is ``look.size`` pixels (default 1280 x 720) at 100 dots per inch: the
title across the top; on the left the mechanism in its own units with equal
scales (axes labelled with the unit where it is known), links as black bars,
joints as white circles lettered as the paper names them (:mod:`.labels`),
fixed pivots on grey ground triangles, sliders as blocks on their axes, virtual
links dashed, each traced point's path in colour; on the right the crank angle
and the values the listing printed at this position, each under its column's
name.  Type is sized for the back of a room (and scales with the height).

matplotlib is imported inside the functions that draw.
"""

from __future__ import annotations

import textwrap
from dataclasses import dataclass

from yaseer.animation.geometry import Frame, Point, Slider, plus, polar
from yaseer.animation.labels import joints, letter_joints
from yaseer.animation.scene import Scene, path_segments

TRACE_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown", "tab:pink")
DPI = 100
DEFAULT_SIZE = (1280, 720)
PANEL_LEFT = 0.655  # the values' panel starts here (figure fraction)
ALTERNATIVE_INK = "#9a9a9a"  # the other assembly branch at the same position


@dataclass(frozen=True)
class Look:
    """What a frame shows besides the mechanism: title, column names, length unit, size in pixels."""

    title: str = ""
    names: tuple[str, ...] | None = None
    unit: str = ""
    size: tuple[int, int] = DEFAULT_SIZE
    letters: tuple[tuple[str, str], ...] = ()  # (contract letter, the listing's own) where they differ

    @property
    def scale(self) -> float:
        """Type size relative to a 720-pixel-high frame."""
        return self.size[1] / 720.0


def make_figure(scene: Scene, look: Look):
    """A free-standing Figure of ``look.size`` with the background drawn; returns (figure, axes)."""
    from matplotlib.figure import Figure

    width, height = look.size
    figure = Figure(figsize=(width / DPI, height / DPI), dpi=DPI, facecolor="white")
    s = look.scale
    top = 0.80 if look.title else 0.88  # room above the mechanism for its legend
    axes = figure.add_axes((0.08, 0.1, PANEL_LEFT - 0.1, top - 0.1))
    if look.title:  # 22 pt at 720 pixels high, smaller if a long title would not fit the width
        figure.text(0.5, 1.0 - 0.025, look.title, ha="center", va="top", weight="bold",
                    fontsize=min(22 * s, 0.95 * width / max(len(look.title), 1)))
    draw_background(axes, scene, look)
    return figure, axes


def draw_background(ax, scene: Scene, look: Look | None = None) -> None:
    """What every frame shares: the limits, equal scales, the unit, the grid and the traced paths."""
    look = look or Look(size=(640, 480))
    s = look.scale
    ax.set_xlim(scene.bounds[0], scene.bounds[1])
    ax.set_ylim(scene.bounds[2], scene.bounds[3])
    ax.set_aspect("equal", adjustable="box")
    ax.grid(True, color="0.9", linewidth=0.8)
    ax.tick_params(labelsize=13 * s)
    unit = f" ({look.unit})" if look.unit else ""
    ax.set_xlabel(f"x{unit}", fontsize=15 * s)
    ax.set_ylabel(f"y{unit}", fontsize=15 * s)
    span = max(scene.bounds[1] - scene.bounds[0], scene.bounds[3] - scene.bounds[2])
    for colour, path in zip(_colours(), scene.paths):
        for segment in path_segments(path, span):
            ax.plot(*zip(*segment), color=colour, linewidth=2.0 * s, alpha=0.55)
    _legend(ax, scene, look)
    if scene.zoom is not None:
        _make_inset(ax, scene, look)


INSET = 0.34  # the magnifying inset's side, a share of the mechanism's axes


def _make_inset(ax, scene: Scene, look: Look) -> None:
    """An inset in ``scene.zoom``'s corner showing the small link's surroundings magnified, and its frame
    marked on the picture."""
    (cx, cy), radius, (right, top) = scene.zoom
    span = max(scene.bounds[1] - scene.bounds[0], scene.bounds[3] - scene.bounds[2])
    inset = ax.inset_axes((0.02 + right * (0.96 - INSET), 0.02 + top * (0.96 - INSET), INSET, INSET), label="zoom")
    inset.set_xlim(cx - radius, cx + radius)
    inset.set_ylim(cy - radius, cy + radius)
    inset.set_aspect("equal", adjustable="box")
    inset.set_xticks([])
    inset.set_yticks([])
    inset.grid(False)
    inset.set_title(f"x{span / (2 * radius):.0f}", fontsize=11 * look.scale, pad=2, loc="left")
    ax.indicate_inset((cx - radius, cy - radius, 2 * radius, 2 * radius), inset, edgecolor="0.45")


def _legend(ax, scene: Scene, look: Look) -> None:
    """One row over the mechanism naming what its marks mean: links, virtual links, fixed pivots,
    the other assembly branch and each traced path (only those the run draws)."""
    from matplotlib.lines import Line2D

    s = look.scale
    snapshots = [snapshot for frame in scene.frames for snapshot in frame.snapshots]
    handles = [Line2D([], [], color="black", linewidth=4 * s, label="link")]
    if any(bar.virtual for snapshot in snapshots for bar in snapshot.bars):
        handles.append(Line2D([], [], color="0.4", linewidth=2 * s, linestyle="--", label="virtual link"))
    if any(snapshot.ground for snapshot in snapshots):
        handles.append(Line2D([], [], color="0.65", marker="^", markersize=10 * s, linestyle="", label="fixed pivot"))
    if any(snapshot.alternative for snapshot in snapshots):
        handles.append(Line2D([], [], color=ALTERNATIVE_INK, linewidth=3 * s, label="other assembly, same angle"))
    seen: dict[str, int] = {}
    for colour, path in zip(_colours(), scene.paths):
        name = path.label.split(" ", 2)[-1]  # "PROG 2 X(4),Y(4)" -> "X(4),Y(4)"
        seen[name] = seen.get(name, 0) + 1
        call = f" (call {seen[name]})" if seen[name] > 1 else ""
        handles.append(Line2D([], [], color=colour, linewidth=2 * s, alpha=0.55, label=f"path of {name}{call}"))
    ax.legend(handles=handles, loc="lower left", bbox_to_anchor=(0.0, 1.0), ncol=min(len(handles), 3),
              fontsize=10 * s, frameon=False, borderaxespad=0.2, handlelength=1.8, columnspacing=1.0)


def draw_moving(ax, scene: Scene, number: int, look: Look | str | None = None, animated: bool = False) -> list:
    """Add frame ``number``'s mechanism, letters, angle and printed values; returns the artists.

    With a magnified small link (``scene.zoom``) its surroundings are drawn again in the
    inset, lettered there; the main picture then letters only the joint at its centre.
    """
    look = Look(title=look) if isinstance(look, str) or look is None else look
    s = look.scale
    frame = scene.frames[number]
    artists = _mechanism(ax, frame, s, scene.size)
    for colour, path in zip(_colours(), scene.paths):
        position = path.positions[number]
        if position is not None:
            artists += ax.plot(*position, marker="o", markersize=9 * s, color=colour, zorder=6)
    renamed = dict(look.letters)
    lettered = [(position, renamed.get(name, name)) for position, name in lettered_joints(scene, frame)]
    span = max(scene.bounds[1] - scene.bounds[0], scene.bounds[3] - scene.bounds[2])
    inset = _inset(ax)
    if inset is not None:
        centre, radius, _ = scene.zoom
        near = [(p, name) for p, name in lettered if _apart(p, centre) <= radius]
        keep = min(near, key=lambda item: _apart(item[0], centre)) if near else None
        size = scene.size * 2 * radius / (span * INSET)  # symbols as large as outside
        artists += _mechanism(inset, frame, s, size)
        # the inset shows 2 radius across INSET of the picture: letters keep clear by as many pixels there
        artists += _letters(inset, near, 2 * radius / INSET, s, _links(frame, size))
        lettered = [item for item in lettered if item not in near or item == keep]
    artists += _letters(ax, lettered, span, s, _links(frame, scene.size))
    artists += _panel(ax.figure, frame, look)
    for artist in artists:
        artist.set_animated(animated)
    return artists


def _apart(p: Point, q: Point) -> float:
    return ((p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2) ** 0.5


def _inset(ax):
    """The magnifying inset of ``ax`` (made by :func:`draw_background`), or None."""
    return next((child for child in getattr(ax, "child_axes", ()) if child.get_label() == "zoom"), None)


def _mechanism(ax, frame: Frame, s: float, size: float) -> list:
    """The links, joints, pivots and sliders of ``frame`` on ``ax``, symbols ``size`` long (the scene's units)."""
    from matplotlib.patches import Circle, Polygon

    artists: list = []
    for snapshot in frame.snapshots:
        for pivot in snapshot.ground:
            artists.append(ax.add_patch(Polygon(_ground_triangle(pivot, size), closed=True,
                                                color="0.65", zorder=2)))
        for slider in snapshot.sliders:
            if slider.axis is not None:
                artists.append(ax.axline(slider.axis, plus(slider.axis, polar(1.0, slider.angle_deg)),
                                         color="0.5", linewidth=1.2 * s, linestyle="-.", zorder=1))
            artists.append(ax.add_patch(Polygon(_block(slider, size), closed=True, facecolor="#c9d6e8",
                                                edgecolor="black", linewidth=1.6 * s, zorder=4)))
        for traced in snapshot.points:  # the rigid link carried on to its point of interest
            artists += ax.plot(*zip(traced.joint, traced.position), color="0.3", linewidth=3.5 * s,
                               solid_capstyle="round", zorder=3)
        ink, weight = (ALTERNATIVE_INK, 0.55) if snapshot.alternative else ("black", 1.0)
        for bar in snapshot.bars:
            style = dict(color="0.4", linewidth=2.2 * s, linestyle="--") if bar.virtual else \
                dict(color=ink, linewidth=5.5 * s * weight, solid_capstyle="round")
            artists += ax.plot(*zip(bar.start, bar.end), zorder=2.5 if snapshot.alternative else 3, **style)
        for joint in (*snapshot.joints, *snapshot.ground):
            artists.append(ax.add_patch(Circle(joint, 0.33 * size * weight, facecolor="white", edgecolor=ink,
                                               linewidth=1.8 * s, zorder=4.6 if snapshot.alternative else 5)))
    return artists


def _links(frame: Frame, size: float) -> list[tuple[Point, Point]]:
    """The segments a letter must not cover: every bar, every traced point's carrying link and the
    upright of each ground triangle (drawn ``size`` high under its pivot)."""
    return [segment for snapshot in frame.snapshots
            for segment in [(bar.start, bar.end) for bar in snapshot.bars] +
            [(traced.joint, traced.position) for traced in snapshot.points] +
            [(pivot, (pivot[0], pivot[1] - size)) for pivot in snapshot.ground]]


def _letters(ax, lettered: list, span: float, s: float, links=()) -> list:
    """The joints' letters on ``ax``, each placed away from the joints, the links and the letters before it
    (``span``: how much of the mechanism, in its units, the picture's height shows at this scale)."""
    from matplotlib import patheffects

    outline = [patheffects.withStroke(linewidth=4 * s, foreground="white")]
    return [ax.annotate(name, position, xytext=(dx * 16 * s, dy * 16 * s), textcoords="offset points",
                        fontsize=19 * s, weight="bold", color="#1f3a93", zorder=7, ha="center", va="center",
                        path_effects=outline, annotation_clip=False)
            for (position, name), (dx, dy) in zip(lettered, _label_offsets(span, [p for p, _ in lettered], links))]


def draw_frame(ax, scene: Scene, number: int, title: str = "") -> None:
    """Draw frame ``number`` of ``scene`` on an empty ``ax`` (background and mechanism)."""
    draw_background(ax, scene)
    draw_moving(ax, scene, number, title)


def lettered_joints(scene: Scene, frame: Frame) -> list[tuple[Point, str]]:
    """Each lettered joint of ``frame`` once: (position, letter), with the letters of the first frame."""
    span = max(scene.bounds[1] - scene.bounds[0], scene.bounds[3] - scene.bounds[2])
    letters = scene.letters if scene.letters is not None else letter_joints(frame.snapshots, span)
    placed: dict[str, Point] = {}
    for index, snapshot in enumerate(frame.snapshots):
        if snapshot.alternative:
            continue  # the other branch shares the letters of the joints it moves
        for joint in joints(snapshot):
            name = letters.get((index, joint.role))
            if name is not None and name not in placed:
                placed[name] = joint.position
    return [(position, name) for name, position in placed.items()]


DIRECTIONS = ((0.7, 0.7), (-0.7, 0.7), (0.7, -0.7), (-0.7, -0.7), (0.0, 1.0), (1.0, 0.0), (0.0, -1.0), (-1.0, 0.0))
LABEL_ROOM = 0.035  # share of the scene's span a label keeps clear of other labels and joints


def _label_offsets(span: float, positions: list[Point], links=()) -> list[tuple[float, float]]:
    """A direction for each label (unit vector): away from the joints, the ``links`` (segments) and the
    labels placed before it; ``span`` is the size of the picture in the mechanism's units."""
    reach = 0.04 * span  # the label's centre, roughly, in the scene's units
    taken: list[Point] = list(positions)
    chosen = []
    for x, y in positions:
        def clearance(direction):
            cx, cy = x + direction[0] * reach, y + direction[1] * reach
            near = min((((cx - px) ** 2 + (cy - py) ** 2) ** 0.5 for px, py in taken), default=span)
            return min([near] + [_to_segment((cx, cy), start, end) for start, end in links])
        best = next((d for d in DIRECTIONS if clearance(d) >= LABEL_ROOM * span), None)
        best = best or max(DIRECTIONS, key=clearance)
        chosen.append(best)
        taken.append((x + best[0] * reach, y + best[1] * reach))
    return chosen


def _to_segment(point: Point, start: Point, end: Point) -> float:
    """The distance from ``point`` to the segment start-end."""
    dx, dy = end[0] - start[0], end[1] - start[1]
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0.0 else max(0.0, min(1.0, ((point[0] - start[0]) * dx + (point[1] - start[1]) * dy) / length2))
    return _apart(point, (start[0] + t * dx, start[1] + t * dy))


def _panel(figure, frame: Frame, look: Look) -> list:
    """The crank angle and the printed values, each under its name, right of the mechanism."""
    s = look.scale
    x, y = PANEL_LEFT + 0.01, 0.84
    artists = [figure.text(x, y, "crank angle", fontsize=15 * s, color="0.35", va="top"),
               figure.text(x, y - 0.045, f"{frame.crank_angle:.1f}\N{DEGREE SIGN}", fontsize=30 * s,
                           weight="bold", va="top")]
    y -= 0.15
    values = _column_values(frame.printed, look.names)
    names = look.names
    if names is not None and values is not None:
        shown = [(name, value) for name, value in zip(names, values)]
        if shown and all(_same_angle(value, frame.crank_angle) for value in shown[0][1].split(" / ")):
            shown = shown[1:]  # the first column is the crank angle (of every branch), shown above
        room = 0.75 / max(len(shown), 1)
        fit = min(1.0, room / 0.125)
        for name, value in shown:
            label = textwrap.fill(name, 34)
            artists.append(figure.text(x, y, label, fontsize=13 * s * fit, color="0.35", va="top",
                                       linespacing=1.0))
            y -= (0.032 * (label.count("\n") + 1)) * fit
            artists.append(figure.text(x, y, value, fontsize=min(22 * s * fit, _fitting(value, look)),
                                       family="monospace", weight="bold", va="top"))
            y -= 0.075 * fit
    elif frame.printed.strip():
        artists.append(figure.text(x, y, "printed", fontsize=15 * s, color="0.35", va="top"))
        lines = [wrapped for line in frame.printed.splitlines()
                 for wrapped in textwrap.wrap(" ".join(line.split()), 24) or [""]][:12]
        artists.append(figure.text(x, y - 0.045, "\n".join(lines), fontsize=16 * s, family="monospace",
                                   va="top"))
    return artists


MONOSPACE_WIDTH = 0.62  # a monospace character's advance, a share of the type size (DejaVu Sans Mono: 0.602)


def _fitting(text: str, look: Look) -> float:
    """The type size (points) at which ``text`` in bold monospace fits the panel's width (two branches'
    values side by side, ``9.477612728 / -6.477612728``, would run off the frame at full size)."""
    room = (1.0 - PANEL_LEFT - 0.02) * look.size[0] * 72.0 / DPI
    return room / (MONOSPACE_WIDTH * max(len(text), 1))


def _column_values(printed: str, names: tuple[str, ...] | None) -> list[str] | None:
    """Each named column's printed values at this position, as printed: the first line's, and a
    second branch's shorter line under the last columns (``-114.62 / 114.62``); None if they do not fit."""
    first = _printed_values(printed)
    if names is None or first is None or len(first) != len(names):
        return None
    columns = [[value] for value in first]
    for line in printed.splitlines()[1:]:
        more = _printed_values(line)
        if more is None or len(more) > len(names):
            return None
        for column, value in zip(columns[len(names) - len(more):], more):
            column.append(value)
    return [" / ".join(column) for column in columns]


def _printed_values(printed: str) -> list[str] | None:
    """The numbers of the first printed line, as printed; None when one is not a number."""
    line = printed.splitlines()[0] if printed.strip() else ""
    words = line.split()
    try:
        [float(word) for word in words]
    except ValueError:
        return None
    return words or None


def _same_angle(text: str, angle: float) -> bool:
    return abs(float(text) - angle) < 0.051


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


class Painter:
    """Paints frames fast: the background is drawn once, each frame only adds its moving parts."""

    def __init__(self, scene: Scene, look: Look) -> None:
        self.figure, self.ax = make_figure(scene, look)
        self.scene, self.look = scene, look
        from matplotlib.backends.backend_agg import FigureCanvasAgg

        self.canvas = FigureCanvasAgg(self.figure)
        self.canvas.draw()
        self.background = self.canvas.copy_from_bbox(self.figure.bbox)

    def image(self, number: int):
        """Frame ``number`` as a PIL RGB image of ``look.size``."""
        import numpy as np
        from PIL import Image

        self.canvas.restore_region(self.background)
        artists = draw_moving(self.ax, self.scene, number, self.look, animated=True)
        renderer = self.canvas.get_renderer()
        for artist in sorted(artists, key=lambda a: a.get_zorder()):
            if artist.axes is None:  # the panel's text, on the figure
                artist.draw(renderer)
            else:
                self.ax.draw_artist(artist)
        pixels = np.asarray(self.canvas.buffer_rgba())
        image = Image.fromarray(pixels[..., :3].copy(), "RGB")
        for artist in artists:
            artist.remove()
        return image

    def close(self) -> None:
        """Nothing to release: the figure is not pyplot's."""
