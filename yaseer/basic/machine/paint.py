"""PAINT on a graphics canvas (machine/graphics.py's Canvas): a flood fill up to a border
attribute, solid or with a tile, drawn as the recordings of a real GW-BASIC 3.23 show
(PC-BASIC's PAINT_* tests; PC-BASIC 2.0.8 draws the same, and its order of spans is the
one followed here, as the fill's extent depends on it with tiles).

The fill goes by spans of a row: from a span it looks at the row above and below for runs
of pixels that are not the border, and fills each such run unless the run already shows
the tile's row there (so a fill never comes back over what it painted); a tile row that is
all background (0) does not count as painted, unless the fill is solid.  A background
string (PAINT's fourth argument) names a row that may be painted over even when it matches
the tile; a tile with three rows in a row (or all its rows) equal to that row is Illegal
function call (the recorded PAINT_tile_background test).

A tile: the string's bytes, one row each; in a mode of packed pixels (SCREEN 1, 2) a byte
holds 8 / bits pixels, the highest bits first; in a mode of planes (SCREEN 7, 8, 9) each
row takes one byte a plane (the first byte plane 0), 8 pixels wide.
"""

from __future__ import annotations

from yaseer.basic.errors import ILLEGAL_FUNCTION_CALL, error_for

PLANED_BITS = 4  # the EGA modes keep their 4 bits a pixel in planes


def tile_rows(pattern: bytes, bits: int) -> list[tuple[int, ...]]:
    """The tile of a pattern string: rows of attributes."""
    if bits >= PLANED_BITS:
        planes = bits
        pattern = bytes(pattern) + bytes(-len(pattern) % planes)
        rows = []
        for start in range(0, len(pattern), planes):
            row = [0] * 8
            for plane in range(planes):
                byte = pattern[start + plane]
                for k in range(8):
                    if byte >> (7 - k) & 1:
                        row[k] |= 1 << plane
            rows.append(tuple(row))
        return rows
    per_byte = 8 // bits
    mask = (1 << bits) - 1
    return [tuple(byte >> (8 - bits * (k + 1)) & mask for k in range(per_byte)) for byte in pattern]


def check_background(tile: list, background: tuple) -> None:
    """Illegal function call when three rows in a row of the tile (all, if fewer) equal the
    background row."""
    height = len(tile)
    for start in range(max(1, height - 2)):
        if all(row == background for row in tile[start:start + 3]):
            raise error_for(ILLEGAL_FUNCTION_CALL)


class Fill:
    """One PAINT on ``canvas`` (view coordinates; the view bounds it)."""

    def __init__(self, canvas, tile: list, border: int, solid: bool, background: tuple | None):
        self.canvas = canvas
        self.tile = tile
        self.border = border
        self.solid = solid
        self.background = background
        x1, y1, x2, y2 = canvas.view
        if getattr(canvas, "view_absolute", True):
            self.left, self.top, self.right, self.bottom = x1, y1, x2, y2
        else:
            self.left, self.top, self.right, self.bottom = 0, 0, x2 - x1, y2 - y1

    def row_pattern(self, y: int, x: int, length: int) -> tuple:
        """The tile's row for ``y`` from column x, ``length`` pixels (tiles align to x = 0)."""
        row = self.tile[y % len(self.tile)]
        width = len(row)
        return tuple(row[(x + k) % width] for k in range(length))

    def run_from(self, y: int, x: int, step: int, limit: int) -> int:
        """How many pixels from x (going by ``step``, x itself included) up to the border
        or the view's edge ``limit`` (excluded)."""
        get, border = self.canvas.get_pixel, self.border
        count = 0
        while x != limit and get(x, y) != border:
            count += 1
            x += step
        return count

    def painted(self, y: int, x: int, run: tuple) -> bool:
        """Whether a run of pixels already shows the fill there (then it is not filled)."""
        pattern = self.row_pattern(y, x, len(run))
        if not self.solid and not any(self.tile[y % len(self.tile)]):
            return False  # an empty tile row: do not stop on it
        if run != pattern:
            return False
        background = self.background
        if background is not None and len(run) >= len(background):
            back = tuple(background[(x + k) % len(background)] for k in range(len(run)))
            if run == back:
                return False
        return True

    def seeds(self, out: list, x_from: int, x_to: int, y: int, direction: int) -> None:
        """The runs between borders of row y from x_from to x_to, onto ``out`` unless
        painted already."""
        get, border = self.canvas.get_pixel, self.border
        x = x_from
        while x <= x_to:
            start = x
            while x <= x_to and get(x, y) != border:
                x += 1
            if x > start:
                run = tuple(get(k, y) for k in range(start, x))
                if not self.painted(y, start, run):
                    out.append((start, x - 1, y, direction))
            x += 1

    def fill(self, x: int, y: int) -> None:
        """Fill from view point (x, y): nothing when it is outside the view or on the
        border."""
        canvas = self.canvas
        if not (self.left <= x <= self.right and self.top <= y <= self.bottom):
            return
        if canvas.get_pixel(x, y) == self.border:
            return
        pending = [(x, x, y, 0)]
        while pending:
            start, stop, y, direction = pending.pop()
            left = start - self.run_from(y, start - 1, -1, self.left - 1)
            right = stop + self.run_from(y, stop + 1, 1, self.right + 1)
            if direction == 0:
                for onward in (1, -1):
                    if self.top <= y + onward <= self.bottom:
                        self.seeds(pending, left, right, y + onward, onward)
            else:
                if self.top <= y + direction <= self.bottom:
                    self.seeds(pending, left, right, y + direction, direction)
                back = y - direction
                if self.top <= back <= self.bottom:  # round corners: the widened ends, backward
                    self.seeds(pending, left, start - 1, back, -direction)
                    self.seeds(pending, stop + 1, right, back, -direction)
            for k, attr in enumerate(self.row_pattern(y, left, right - left + 1)):
                canvas.set_pixel(left + k, y, attr)


def paint(canvas, x: int, y: int, fill_attr: int, border: int, pattern: bytes | None = None,
          background: bytes | None = None) -> None:
    """PAINT from view point (x, y): ``pattern`` a tile string (None: solid ``fill_attr``),
    up to ``border``; ``background`` the background string (its first row counts)."""
    if pattern is None:
        tile, solid, back = [(fill_attr,) * 8], True, None
    else:
        bits = getattr(canvas, "bits", 1)
        tile, solid = tile_rows(pattern, bits), False
        back = None
        if background:
            back = tile_rows(background, bits)[0]
            check_background(tile, back)
    Fill(canvas, tile, border, solid, back).fill(x, y)
