"""A small generic planar kinetostatic (d'Alembert) solver, shared by every linkage.

For each rigid body:  sum F = m a_G  and  sum M_G = I_G alpha  (a particle has
no moment equation).  Gravity G acts in -y on every mass.  The unknowns are the
joint reactions (a pin: two components; a slide: a force along a given
direction; a couple) and one selected load; everything else is known.  One
linear system per position, all positions solved by one batched
``numpy.linalg.solve``.

Sign conventions: a joint's unknown is the action of its ``upstream`` body on
its ``downstream`` body (``upstream=None`` is the ground); the downstream body
receives +value, the upstream body -value.  Forces are complex numbers
``Fx + 1j*Fy``; couples are counter-clockwise positive.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from yaseer.linkages.errors import SingularForceError, UnknownLoadError
from yaseer.linkages.planar import Motion, cross

# Singularity test: with the rows scaled to unit size, a solution component more
# than this many times the largest right-hand side means the matrix is singular
# or nearly so (the unknowns cannot balance the loads).  An exactly singular
# matrix makes LAPACK stop; a nearly singular one with an all-zero right-hand
# side (nothing to balance) gives the zero solution.
SINGULAR_GAIN = 1e9


@dataclass(frozen=True)
class Body:
    """A rigid body: mass (kg), inertia about its mass centre (kg m**2), the
    motion of the mass centre and the angular acceleration (rad/s**2)."""

    name: str
    mass: np.ndarray | float
    inertia: np.ndarray | float
    centre: Motion
    alpha: np.ndarray | float
    particle: bool = False


@dataclass(frozen=True)
class Load:
    """A load of scalar value on ``body``: a force along unit ``direction`` acting
    at ``point``, or (``direction is None``) a couple."""

    body: str
    direction: np.ndarray | complex | None = None
    point: np.ndarray | complex | None = None


def point_loads(body: str, point, perpendicular) -> dict[str, "Load"]:
    """The three point loads the contract puts at a point of interest of ``body``:
    ``<body>_fx`` along +x, ``<body>_fy`` along +y and ``<body>_perpendicular`` along
    the unit vector ``perpendicular`` (see :func:`planar.perpendicular_direction`)."""
    return {
        f"{body}_fx": Load(body, 1.0, point),
        f"{body}_fy": Load(body, 1j, point),
        f"{body}_perpendicular": Load(body, perpendicular, point),
    }


@dataclass(frozen=True)
class Joint:
    """An unknown reaction, the action of ``upstream`` (None: ground) on ``downstream``.

    ``kind`` is ``"pin"`` (two components, result complex), ``"slide"`` (a force
    along unit ``direction``) or ``"couple"``.
    """

    name: str
    upstream: str | None
    downstream: str
    kind: str
    point: np.ndarray | complex | None = None
    direction: np.ndarray | complex | None = None


def _columns(joints: list[Joint], unknown_load: Load) -> list[list[tuple[str, float, object, object]]]:
    """The unknowns as columns: each a list of (body, sign, direction|None, point)."""
    columns = []
    for joint in joints:
        directions = [1.0, 1j] if joint.kind == "pin" else [joint.direction if joint.kind == "slide" else None]
        for direction in directions:
            actions = [(joint.downstream, 1.0, direction, joint.point)]
            if joint.upstream is not None:
                actions.append((joint.upstream, -1.0, direction, joint.point))
            columns.append(actions)
    columns.append([(unknown_load.body, 1.0, unknown_load.direction, unknown_load.point)])
    return columns


def _effect(direction, point, centre) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(Fx, Fy, moment about the mass centre) of a unit load."""
    if direction is None:
        return 0.0, 0.0, 1.0
    direction = np.asarray(direction, dtype=complex)
    return direction.real, direction.imag, cross(np.asarray(point, dtype=complex) - centre, direction)


def _rows(bodies: list[Body]) -> dict[str, int]:
    """The first equation row of each body (3 rows a body, 2 for a particle)."""
    rows, row = {}, 0
    for body in bodies:
        rows[body.name] = row
        row += 2 if body.particle else 3
    return rows


def _add_load(target, column, body: Body, row: int, scale, direction, point) -> None:
    """Add ``scale`` times a unit load's (Fx, Fy, moment about G) to the body's rows.

    ``target`` is the matrix (then ``column`` is the unknown's column) or the
    right-hand side (``column is None``).  The arrays are laid out equations-first,
    (rows, [columns,] *positions), so each entry is a contiguous vector over the
    positions and ``+=`` broadcasts the value over them.
    """
    components = _effect(direction, point, body.centre.pos)
    for offset, component in enumerate(components[: 2 if body.particle else 3]):
        index = (row + offset,) if column is None else (row + offset, column)
        target[index] += scale * component


def _add_inertia(rhs, body: Body, row: int, gravity) -> None:
    """The d'Alembert side of a body's equations: m a_G (+ m G upward balance), I alpha."""
    inertial = body.mass * body.centre.acc
    rhs[row] += inertial.real
    rhs[row + 1] += inertial.imag + body.mass * gravity
    if not body.particle:
        rhs[row + 2] += body.inertia * body.alpha


def solve_kinetostatics(
    bodies: list[Body],
    joints: list[Joint],
    loads: dict[str, Load],
    values: dict[str, np.ndarray | float],
    unknown: str,
    gravity: float,
    shape: tuple[int, ...],
) -> tuple[dict[str, np.ndarray], np.ndarray]:
    """Solve the kinetostatics of ``bodies`` at every position of ``shape``.

    ``loads`` names every load the linkage knows; ``values`` gives the known ones
    (missing names are 0); ``unknown`` names the one solved for.  Returns the
    joint reactions by name (complex for pins) and the unknown load's value.
    Raises :class:`SingularForceError` where the system has no unique solution.
    """
    if unknown not in loads:
        raise UnknownLoadError(f"unknown load {unknown!r} (known: {', '.join(loads)})")
    rows = _rows(bodies)
    by_name = {body.name: body for body in bodies}
    size = sum(2 if body.particle else 3 for body in bodies)
    columns = _columns(joints, loads[unknown])
    if len(columns) != size:
        raise ValueError(f"{len(columns)} unknowns for {size} equations")
    matrix = np.zeros((size, size) + shape)
    rhs = np.zeros((size,) + shape)
    for column, actions in enumerate(columns):
        for body_name, sign, direction, point in actions:
            _add_load(matrix, column, by_name[body_name], rows[body_name], sign, direction, point)
    for body in bodies:
        _add_inertia(rhs, body, rows[body.name], gravity)
    for name, load in loads.items():
        value = values.get(name, 0.0)
        if name != unknown and np.any(value):
            _add_load(rhs, None, by_name[load.body], rows[load.body], -value, load.direction, load.point)
    solution = _solve(matrix, rhs)
    return _unpack(joints, solution), solution[..., -1]


def _solve(matrix: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """Solve the equations-first system at every position with one batched
    ``numpy.linalg.solve``; singular systems raise.

    Scaling a row does not change the solution, so the rows are scaled only in
    the singularity test: no component may exceed SINGULAR_GAIN times the largest
    right-hand side of the rows scaled to unit size."""
    if not (np.all(np.isfinite(matrix)) and np.all(np.isfinite(rhs))):
        raise OverflowError("the force system overflows (non-finite coefficients)")
    row_scale = np.max(np.abs(matrix), axis=1)
    row_scale[row_scale == 0] = 1.0
    try:
        solution = np.linalg.solve(np.moveaxis(matrix, (0, 1), (-2, -1)), np.moveaxis(rhs, 0, -1)[..., None])[..., 0]
    except np.linalg.LinAlgError:
        raise SingularForceError("the selected unknown cannot balance the loads") from None
    gain_bound = SINGULAR_GAIN * np.moveaxis(np.max(np.abs(rhs) / row_scale, axis=0, keepdims=True), 0, -1)
    if not np.all(np.abs(solution) <= gain_bound):
        raise SingularForceError("the selected unknown cannot balance the loads")
    return solution


def _unpack(joints: list[Joint], solution: np.ndarray) -> dict[str, np.ndarray]:
    """Joint reactions by name from the solution vector (pins as complex)."""
    reactions, column = {}, 0
    for joint in joints:
        if joint.kind == "pin":
            reactions[joint.name] = solution[..., column] + 1j * solution[..., column + 1]
            column += 2
        else:
            reactions[joint.name] = solution[..., column]
            column += 1
    return reactions


@dataclass(frozen=True)
class MassProps:
    """Mass (kg), inertia about the mass centre (kg m**2) and where the mass centre
    lies: ``distance`` from the link's reference joint at ``offset_deg`` degrees
    counter-clockwise from the link's reference line."""

    mass: np.ndarray | float = 0.0
    inertia: np.ndarray | float = 0.0
    distance: np.ndarray | float = 0.0
    offset_deg: np.ndarray | float = 0.0


@dataclass(frozen=True)
class ForceResult:
    """A solved force analysis: the name and value of the unknown load, and the
    joint reactions by name (pins complex ``Fx + 1j*Fy``, slides and couples real)."""

    unknown: str
    value: np.ndarray
    reactions: dict[str, np.ndarray]


def analysis_shape(*arrays) -> tuple[int, ...]:
    """The broadcast shape of every array taking part in a force analysis."""
    return np.broadcast_shapes(*(np.shape(array) for array in arrays))


def analyse(bodies: list[Body], joints: list[Joint], loads: dict[str, Load], values: dict, unknown: str,
            gravity) -> ForceResult:
    """:func:`solve_kinetostatics` over the common shape of everything given."""
    shape = analysis_shape(
        gravity, *values.values(),
        *(item for body in bodies for item in (body.mass, body.inertia, body.centre.pos, body.alpha)),
        *(item for joint in joints for item in (joint.point, joint.direction) if item is not None),
        *(item for load in loads.values() for item in (load.point, load.direction) if item is not None),
    )
    reactions, value = solve_kinetostatics(bodies, joints, loads, values, unknown, gravity, shape)
    return ForceResult(unknown, value, reactions)
