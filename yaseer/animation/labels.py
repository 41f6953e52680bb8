"""The joints' letters, as the paper names them.

The contract names each program's joints: Program 1 AoAB (crank pivot Ao, crank
pin A, piston B), Program 2 AoABBo, Program 3 Ao, A and the follower's pivot Bo,
Program 5 the virtual link from Ao.  A listing that calls several programs names
a point that is new to the mechanism with the next free letter (C, D, E, ...;
a new fixed pivot gets the letter and ``o``, as Co), while a point where an
earlier call already put a joint keeps that joint's letter.  So in Example 1
the first slider-crank is AoAB, the point of interest on its rod (the virtual
link's tip and the second crank's pin) is C, and the second piston is D — the
paper's "piston D".

Letters are given once, from the first frame, to (call index, role) pairs, so
a joint keeps its letter as the mechanism moves.
"""

from __future__ import annotations

from dataclasses import dataclass

from yaseer.animation.geometry import Point, Snapshot, distance

LETTERS = "ABCDEFGHIJKLMNPQRSTUVWXYZ"  # no O: "Oo" would read as a pivot's suffix


@dataclass(frozen=True)
class Joint:
    """A named point of one call: ``role`` in the contract ("Ao", "A", "B", "Bo", "P1"...).

    ``partner``: for a fixed pivot, the role of the moving joint its link reaches
    (the follower's other end), whose letter it takes with ``o`` when it is new.
    """

    role: str
    position: Point
    fixed: bool
    partner: str | None = None


def joints(snapshot: Snapshot) -> list[Joint]:
    """The contract's joints of one call, then its points of interest, in that order."""
    bars = snapshot.bars
    found: list[Joint] = [Joint("Ao", bars[0].start, True)]
    if snapshot.area == 1:
        found += [Joint("A", bars[0].end, False), Joint("B", bars[1].end, False)]
    elif snapshot.area == 2:
        found += [Joint("A", bars[0].end, False), Joint("B", bars[1].end, False),
                  Joint("Bo", bars[2].end, True, partner="B")]
    elif snapshot.area == 3:
        found += [Joint("A", bars[0].end, False), Joint("Bo", bars[1].start, True, partner="A")]
    elif snapshot.area == 5:
        found += [Joint("tip", bars[0].end, False)]
    found += [Joint(f"P{k}", point.position, False) for k, point in enumerate(snapshot.points)
              if distance(point.position, point.joint) > 0.0]
    return found


def letter_joints(snapshots: tuple[Snapshot, ...], scale: float) -> dict[tuple[int, str], str]:
    """(call index, role) -> letter for the calls of one frame; points within 1e-9 ``scale`` share one.

    Within a call the moving joints and points are lettered first, then the
    fixed pivots: a new pivot whose partner was lettered anew takes the
    partner's letter and ``o`` (the output member CCoD of Example 3).
    """
    tiny = 1e-9 * max(scale, 1e-300)
    named: list[tuple[Point, str]] = []
    letters: dict[tuple[int, str], str] = {}
    used: set[str] = set()
    for index, snapshot in enumerate(snapshots):
        for joint in sorted(joints(snapshot), key=lambda j: j.fixed and j.partner is not None):
            name = next((n for p, n in named if distance(p, joint.position) <= tiny), None)
            if name is None:
                if snapshot.area == 5:
                    continue  # a virtual link's tip is named by the joint it reaches, if any
                partner = letters.get((index, joint.partner or ""))
                name = _new_name(joint, partner if partner != joint.partner else None, used)
                used.add(name)
                named.append((joint.position, name))
            letters[(index, joint.role)] = name
    return letters


def _new_name(joint: Joint, partner: str | None, used: set[str]) -> str:
    """A renamed partner's letter with ``o``, else the contract's name if free, else the next free letter."""
    if partner is not None and len(partner) == 1 and partner + "o" not in used:
        return partner + "o"
    if not joint.role.startswith("P") and joint.role not in used:
        return joint.role
    for letter in LETTERS:
        if letter not in used and letter + "o" not in used:
            return letter + "o" if joint.fixed else letter
    return "?"
