"""The geometry a recorded call leaves: points, bars, sliders, traced points, snapshots, frames.

Conventions are those of the programs' contract (docs/programs.md): crank pivot
Ao at the origin, x right, y up, angles in degrees counter-clockwise from +x,
any consistent length unit.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

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
    Program 5), ``crank_angle`` its angle in degrees.  ``alternative``: a call
    at the same crank angle as the frame's first, printed on the next line (the
    other branch of seed 003's four-bar).
    """

    area: int
    crank_angle: float
    bars: tuple[Bar, ...]
    joints: tuple[Point, ...]
    ground: tuple[Point, ...]
    sliders: tuple[Slider, ...] = ()
    points: tuple[TracedPoint, ...] = ()
    crank: int | None = 0
    alternative: bool = False  # another assembly at the same position (drawn lighter, not lettered)

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
