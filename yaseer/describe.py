"""What a listing's output means: its title and the names and units of its printed columns.

The paper's five examples print quantities the paper names (the contract's last
table); :data:`PAPER_EXAMPLES` holds their meanings and units.  Any other listing
is described by itself: its first ``REM`` is its title, a printed header names its
columns, else the expressions of its last ``PRINT``.  Nothing here imports more
than the standard library.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence


@dataclass(frozen=True)
class Quantity:
    """A printed quantity: what it means and its unit (empty when unknown)."""

    meaning: str
    unit: str = ""

    def axis_label(self) -> str:
        return f"{self.meaning} ({self.unit})" if self.unit else self.meaning


@dataclass(frozen=True)
class FigureSpec:
    """Title, the abscissa (first printed column) and the other printed columns."""

    title: str
    x: Quantity
    columns: tuple[Quantity, ...]


DEG, RAD_S, RAD_S2 = "deg", "rad/s", "rad/s²"

# What the paper's examples print (the contract's last table), with the units each
# listing works in (Example 1 and 4: mm; Example 3: cm; Examples 2 and 5: m, kg, s).
PAPER_EXAMPLES: dict[str, FigureSpec] = {
    "example1": FigureSpec(
        "Example 1: kinematics of piston D (paper Fig. 7)",
        Quantity("crank angle QQ", DEG),
        (
            Quantity("position of piston D, Y(2)", "mm"),
            Quantity("velocity of piston D, V(4)", "mm/s"),
            Quantity("acceleration of piston D, A(36)", "mm/s²"),
        ),
    ),
    "example2": FigureSpec(
        "Example 2: churning mechanism, torque and reactions (paper Fig. 9)",
        Quantity("crank angle QQ", DEG),
        (
            Quantity("input torque on AoA, U(1)", "N·m"),
            Quantity("normal reaction at B, N(1)", "N"),
            Quantity("bearing reaction at Ao, |F(3), F(4)|", "N"),
        ),
    ),
    "example3": FigureSpec(
        "Example 3: indexing mechanism, output member CCoD (paper Fig. 10)",
        Quantity("crank angle T(2)", DEG),
        (
            Quantity("inclination of CCoD (Co→C), T(9)", DEG),
            Quantity("angular velocity of CCoD, W(4)", RAD_S),
            Quantity("angular acceleration of CCoD, A(4)", RAD_S2),
            Quantity("x of point D, X(7)", "cm"),
        ),
    ),
    "example4": FigureSpec(
        "Example 4: film transport, member DE and point E (paper Fig. 12)",
        Quantity("crank angle QQ", DEG),
        (
            Quantity("angular velocity of DE, W(6)", RAD_S),
            Quantity("angular acceleration of DE, A(6)", RAD_S2),
            Quantity("horizontal velocity of E, V(7)", "mm/s"),
            Quantity("horizontal acceleration of E, A(39)", "mm/s²"),
        ),
    ),
    "example5": FigureSpec(
        "Example 5: jaw crusher, crank torque and main reactions (paper Fig. 14)",
        Quantity("crank angle QQ", DEG),
        (
            Quantity("crank torque, U(2)", "N·m"),
            Quantity("bearing reaction at Bo, |F(27), F(28)|", "N"),
            Quantity("bearing reaction at Ao, |F(21), F(22)|", "N"),
        ),
    ),
}


def printed_expressions(listing_text: str, width: int | None = None) -> list[str]:
    """The expressions of the last ``PRINT``/``LPRINT`` statement of a listing, as written
    (with ``width``: of the last one that prints ``width`` items, the one a table of that
    many columns comes from, when a labelled line is printed after it).

    ``60 PRINT USING "###.##"; QQ; Y(2): NEXT QQ`` gives ``["QQ", "Y(2)"]``.  Only what
    is needed for labels: the statement ends at a ``:`` outside strings and parentheses,
    and the items are split at ``;`` and ``,`` outside them.
    """
    last: list[str] = []
    for line in listing_text.splitlines():
        for statement in _split_top_level(line, ":"):
            items = _print_items(statement)
            if items is not None and (width is None or len(items) == width):
                last = items
    return last


def _print_items(statement: str) -> list[str] | None:
    """The items of a PRINT/LPRINT statement (after any USING format), else None."""
    words = statement.strip().split(None, 1)
    if words and words[0].isdigit():  # the line number before the first statement
        words = words[1].split(None, 1) if len(words) > 1 else []
    if not words or words[0].upper() not in ("PRINT", "LPRINT"):
        return None
    rest = words[1] if len(words) > 1 else ""
    if rest.upper().startswith("USING"):
        parts = _split_top_level(rest, ";")
        rest = ";".join(parts[1:])
    items = [item.strip() for part in _split_top_level(rest, ";") for item in _split_top_level(part, ",")]
    return [item for item in items if item]


def _split_top_level(text: str, separator: str) -> list[str]:
    """Split ``text`` at ``separator`` where it is outside quotes and parentheses."""
    parts, depth, quoted, start = [], 0, False, 0
    for index, char in enumerate(text):
        if char == '"':
            quoted = not quoted
        elif not quoted and char == "(":
            depth += 1
        elif not quoted and char == ")":
            depth -= 1
        elif not quoted and depth == 0 and char == separator:
            parts.append(text[start:index])
            start = index + 1
    parts.append(text[start:])
    return parts




def listing_title(listing_text: str, name: str | None) -> str:
    """The paper's title of an example, else the listing's first ``REM`` (its text), else ``name``."""
    known = PAPER_EXAMPLES.get((name or "").lower())
    if known is not None:
        return known.title
    for line in listing_text.splitlines():
        words = line.strip().split(None, 1)
        rest = words[1].strip() if len(words) > 1 and words[0].isdigit() else ""
        if rest[:3].upper() == "REM":
            remark = rest[3:].strip().rstrip(",;:")
            if remark:
                return remark
        elif rest.startswith("'") and rest[1:].strip():
            return rest[1:].strip()
    return name or "listing"


def column_names(name: str | None, width: int, header: Sequence[str] | None,
                 listing_text: str = "") -> tuple[str, ...] | None:
    """Names of a ``width``-column table, the one naming that the rows, the plot and the animation share:
    the paper's meanings and units for its examples, else the listing's printed ``header``, else the
    expressions of its last PRINT (``X(2)``, ``V(3)``) when they are as many as the columns, else None."""
    known = PAPER_EXAMPLES.get((name or "").lower())
    if known is not None and len(known.columns) == width - 1:
        return tuple(q.axis_label() for q in (known.x, *known.columns))
    if header is not None:
        return tuple(header)
    expressions = printed_expressions(listing_text, width) if listing_text else []
    return tuple(expressions) if len(expressions) == width else None


# The length unit each paper example works in (docs: Examples 1 and 4 mm, 3 cm, 2 and 5 m).
LENGTH_UNITS = {"example1": "mm", "example2": "m", "example3": "cm", "example4": "mm", "example5": "m"}


# Joints a listing's own text names otherwise than the contract (AoABBo): seed 003's Fortran calls
# the crank pivot A, the crank pin B, the coupler-follower joint C and the follower pivot D, and
# prints VELB, VELC, ... by those letters (listings/fortran_fourbar.bas, lines 20-60).
JOINT_LETTERS = {"fortran_fourbar": (("Ao", "A"), ("A", "B"), ("B", "C"), ("Bo", "D"))}


def joint_letters(name: str | None) -> tuple[tuple[str, str], ...]:
    """(contract letter, the listing's letter) pairs for a listing that names its joints itself, else ()."""
    return JOINT_LETTERS.get((name or "").lower(), ())


def length_unit(name: str | None) -> str:
    """The unit of the mechanism's lengths where it is known (the paper's examples), else ""."""
    return LENGTH_UNITS.get((name or "").lower(), "")
