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
    """A named point of one call: ``role`` in the contract ("Ao", "A", "B", "Bo", "P1"...)."""

    role: str
    position: Point
    fixed: bool


def joints(snapshot: Snapshot) -> list[Joint]:
    """The contract's joints of one call, then its points of interest, in that order."""
    bars = snapshot.bars
    found: list[Joint] = [Joint("Ao", bars[0].start, True)]
    if snapshot.area == 1:
        found += [Joint("A", bars[0].end, False), Joint("B", bars[1].end, False)]
    elif snapshot.area == 2:
        found += [Joint("A", bars[0].end, False), Joint("B", bars[1].end, False), Joint("Bo", bars[2].end, True)]
    elif snapshot.area == 3:
        found += [Joint("A", bars[0].end, False), Joint("Bo", bars[1].start, True)]
    elif snapshot.area == 5:
        found += [Joint("tip", bars[0].end, False)]
    found += [Joint(f"P{k}", point.position, False) for k, point in enumerate(snapshot.points)
              if distance(point.position, point.joint) > 0.0]
    return found


def letter_joints(snapshots: tuple[Snapshot, ...], scale: float) -> dict[tuple[int, str], str]:
    """(call index, role) -> letter for the calls of one frame; points within 1e-9 ``scale`` share one."""
    tiny = 1e-9 * max(scale, 1e-300)
    named: list[tuple[Point, str]] = []
    letters: dict[tuple[int, str], str] = {}
    used: set[str] = set()
    for index, snapshot in enumerate(snapshots):
        for joint in joints(snapshot):
            name = next((n for p, n in named if distance(p, joint.position) <= tiny), None)
            if name is None:
                if joint.role.startswith("P") or joint.role == "tip":
                    if snapshot.area == 5:
                        continue  # a virtual link's tip is named by the joint it reaches, if any
                    name = _next_letter(used, joint.fixed)
                elif joint.role not in used:
                    name = joint.role
                else:
                    name = _next_letter(used, joint.fixed)
                used.add(name)
                named.append((joint.position, name))
            letters[(index, joint.role)] = name
    return letters


def _next_letter(used: set[str], fixed: bool) -> str:
    for letter in LETTERS:
        name = letter + "o" if fixed else letter
        if letter not in used and letter + "o" not in used:
            return name
    return "?"
