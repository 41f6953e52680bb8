"""A small generic planar kinetostatic (d'Alembert) solver, shared by every linkage.

For each rigid body:  sum F = m a_G  and  sum M_G = I_G alpha  (a particle has
no moment equation).  Gravity G acts in -y on every mass.  The unknowns are the
joint reactions (a pin: two components; a slide: a force along a given
direction; a couple) and one selected load; everything else is known.  One
linear system per position, the same for Programs 1-3; the pin reactions are
eliminated exactly from the force equations (their coefficients are +-1) and
the small system left (k <= 3 unknowns) is solved at all positions at once
with its adjugate and one step of refinement.  The same code solves one
position in Python numbers and many in numpy arrays (:mod:`numerics`).

Sign conventions: a joint's unknown is the action of its ``upstream`` body on
its ``downstream`` body (``upstream=None`` is the ground); the downstream body
receives +value, the upstream body -value.  Forces are complex numbers
``Fx + 1j*Fy``; couples are counter-clockwise positive.
"""

from __future__ import annotations

import functools
from collections import namedtuple  # records (not dataclasses or typing.NamedTuple: start-up time)

from yaseer.linkages.errors import SingularForceError, UnknownLoadError
from yaseer.linkages.numerics import SCALAR, math_for
from yaseer.linkages.planar import Motion, cross

# Singularity test: with the couple columns of the reduced system multiplied by
# the largest moment arm and then every row scaled to a largest entry of 1, a
# determinant at most this small means the matrix is singular or nearly so (its
# condition number is then about 1e9 or more), whatever the loads.
SINGULAR_TOLERANCE = 1e-9


class Body(namedtuple("Body", "name mass inertia centre alpha particle", defaults=(False,))):
    """A rigid body ``name``: ``mass`` (kg), ``inertia`` about its mass centre (kg m**2),
    the :class:`Motion` of the mass ``centre`` and the angular acceleration ``alpha``
    (rad/s**2), each a float or an array; ``particle`` (default False): no moment equation."""

    __slots__ = ()


class Load(namedtuple("Load", "body direction point", defaults=(None, None))):
    """A load of scalar value on ``body`` (a name): a force along unit ``direction`` acting
    at ``point`` (complex numbers or arrays), or (``direction is None``) a couple."""

    __slots__ = ()


def point_loads(body: str, point, perpendicular) -> dict[str, "Load"]:
    """The three point loads the contract puts at a point of interest of ``body``:
    ``<body>_fx`` along +x, ``<body>_fy`` along +y and ``<body>_perpendicular`` along
    the unit vector ``perpendicular`` (see :func:`planar.perpendicular_direction`)."""
    return {
        f"{body}_fx": Load(body, 1.0, point),
        f"{body}_fy": Load(body, 1j, point),
        f"{body}_perpendicular": Load(body, perpendicular, point),
    }


class Joint(namedtuple("Joint", "name upstream downstream kind point direction", defaults=(None, None))):
    """An unknown reaction ``name``, the action of body ``upstream`` (None: ground) on body ``downstream``.

    ``kind`` is ``"pin"`` (two components, result complex), ``"slide"`` (a force
    along unit ``direction``) or ``"couple"``; ``point`` where it acts (``point`` and
    ``direction``: complex numbers or arrays, default None).
    """

    __slots__ = ()


class _Plan:
    """How the d'Alembert system of a linkage is reduced, from its structure alone
    (names only, so one plan serves every call on the same linkage: see :func:`_plan`).

    Every pin reaction enters the force equations of the bodies it joins with a
    coefficient of exactly +1 or -1, so it can be eliminated exactly: peeling the
    bodies from the ends of the chain, a body with only one pin still open gets that
    pin ("matched") from its force balance, in terms of what is left.  When no body
    has a single open pin, the last open pin in joint order stays unknown.  The
    ``reduced`` unknowns (slides, couples, pins left over, the unknown load) are then
    fixed by the moment equations (and the force equations of bodies without a
    matched pin): a k x k system, k <= 3 for Programs 1-3.

    ``bodies``: (name, particle) each; ``joints``: (name, upstream, downstream, kind)
    each; ``unknown``: (key, is a couple) of the unknown load.
    """

    def __init__(self, bodies: tuple, joints: tuple, unknown: tuple[str, bool]):
        self.pins = {name for name, _, _, kind in joints if kind == "pin"}
        self.order, self.matched = _peel([body for body, _ in bodies], joints)  # matched: body -> pin
        downstream = {name: down for name, _, down, _ in joints}
        self.pin_signs = {body: 1.0 if downstream[pin] == body else -1.0 for body, pin in self.matched.items()}
        self.index: dict[str, int] = {}  # first column of each reduced unknown (a pin: x, then y)
        self.couples: list[bool] = []  # per column: is the unknown a couple (N m) rather than a force (N)?
        reduced = [(name, kind) for name, _, _, kind in joints if name not in self.matched.values()]
        for key, kind in reduced + [(unknown[0], "couple" if unknown[1] else "force")]:
            self.index[key] = len(self.couples)
            self.couples += [False, False] if kind == "pin" else [kind == "couple"]
        self.size = len(self.couples)
        equations = sum(0 if particle else 1 for _, particle in bodies)
        equations += sum(2 for body, _ in bodies if body not in self.matched)
        if equations != self.size:
            raise ValueError(f"{self.size} reduced unknowns for {equations} equations")


def _peel(bodies: list[str], joints: tuple) -> tuple[list[str], dict[str, str]]:
    """The order in which the bodies give their pins, and the pin each gives: the
    first body with at most one pin still open goes next and takes it; when every
    waiting body has two or more, the last open pin in joint order is left unknown."""
    pins = [name for name, _, _, kind in joints if kind == "pin"]
    touching = {body: [name for name, up, down, kind in joints if kind == "pin" and body in (up, down)]
                for body in bodies}
    open_pins, order, matched, waiting = set(pins), [], {}, list(bodies)
    while waiting:
        still_open = {body: [pin for pin in touching[body] if pin in open_pins] for body in waiting}
        single = [body for body in waiting if len(still_open[body]) <= 1]
        if not single:
            open_pins.discard([pin for pin in pins if pin in open_pins][-1])
            continue
        body = single[0]
        waiting.remove(body)
        order.append(body)
        if still_open[body]:
            matched[body] = still_open[body][0]
            open_pins.discard(still_open[body][0])
    return order, matched


@functools.lru_cache(maxsize=64)
def _plan(bodies: tuple, joints: tuple, unknown: tuple[str, bool]) -> _Plan:
    """The (cached) :class:`_Plan` of a structure."""
    return _Plan(bodies, joints, unknown)


def _actions(bodies: list[Body], joints: list[Joint], unknown_key: str, unknown_load: Load) -> dict[str, list[tuple]]:
    """The unknowns acting on each body: (key, sign, force direction, point), the key
    a joint's name or ``unknown_key`` for the unknown load.

    A pin's direction is 1 (its form is already x + i y); a couple has direction and
    point None.  The downstream body of a joint receives +value, the upstream -value.
    """
    actions = {body.name: [] for body in bodies}
    for joint in joints:
        direction = {"pin": 1.0, "slide": joint.direction, "couple": None}[joint.kind]
        point = None if joint.kind == "couple" else joint.point
        actions[joint.downstream].append((joint.name, 1.0, direction, point))
        if joint.upstream is not None:
            actions[joint.upstream].append((joint.name, -1.0, direction, point))
    actions[unknown_load.body].append((unknown_key, 1.0, unknown_load.direction, unknown_load.point))
    return actions


def _targets(bodies: list[Body], loads: dict[str, Load], values: dict, unknown: str, gravity, xp):
    """What the unknowns must supply to each body: the force m a_G + m G (upward)
    minus the known loads (complex), and the moment I alpha minus theirs about G."""
    by_name = {body.name: body for body in bodies}
    force = {body.name: body.mass * body.centre.acc + 1j * (body.mass * gravity) for body in bodies}
    moment = {body.name: body.inertia * body.alpha for body in bodies}
    for name, load in loads.items():
        value = values.get(name, 0.0)
        if name == unknown or not xp.any(value):
            continue
        if load.direction is None:
            moment[load.body] = moment[load.body] - value
            continue
        direction = xp.complex(load.direction)
        force[load.body] = force[load.body] - value * direction
        arm = xp.complex(load.point) - by_name[load.body].centre.pos
        moment[load.body] = moment[load.body] - value * cross(arm, direction)
    return force, moment


# A "form" is a force (or, for a couple, a moment) that is linear in the reduced
# unknowns: a dict from column to coefficient (complex for a force, real for a
# moment; a scalar or an array over the positions), CONSTANT keying the part
# that does not depend on them.  Sparse: a term is an array only where it varies.
CONSTANT = -1


def _combined(*terms: tuple[float, dict]) -> dict:
    """The form sum of ``factor * form`` over ``terms``."""
    total: dict = {}
    for factor, form in terms:
        for key, value in form.items():
            total[key] = total.get(key, 0.0) + factor * value
    return total


def _moment_of(arm, form: dict) -> dict:
    """The moment form of a force form acting at ``arm`` from the mass centre."""
    return {key: _cross_with(arm, value) for key, value in form.items()}


def _cross_with(arm, value):
    """cross(arm, value), with one product fewer when ``value`` is a plain number on
    an axis (a pin's x or y coefficient, +-1 or +-1j)."""
    if isinstance(value, (float, complex)):
        if value.imag == 0:
            return -arm.imag * value.real
        if value.real == 0:
            return arm.real * value.imag
    return cross(arm, value)


def solve_kinetostatics(
    bodies: list[Body],
    joints: list[Joint],
    loads: dict[str, Load],
    values: dict,
    unknown: str,
    gravity: float,
    shape: tuple[int, ...],
    xp=SCALAR,
) -> tuple[dict, object]:
    """Solve the kinetostatics of ``bodies`` at every position of ``shape``
    (``xp``: the :mod:`numerics` namespace, Python numbers for shape ()).

    ``loads`` names every load the linkage knows; ``values`` gives the known ones
    (missing names are 0); ``unknown`` names the one solved for.  Returns the
    joint reactions by name (complex for pins) and the unknown load's value.

    The system is the d'Alembert one (3 equations a body, 2 a particle) with the
    pin reactions eliminated exactly (:class:`_Plan`), each held as a form (see
    CONSTANT).  Raises :class:`SingularForceError` where the system has no unique
    solution, whatever the loads (:func:`_solve_reduced`), and OverflowError
    where its coefficients are not finite.
    """
    if unknown not in loads:
        raise UnknownLoadError(f"unknown load {unknown!r} (known: {', '.join(loads)})")
    unknown_key = "load " + unknown  # kept apart from a joint of the same name
    plan = _plan(tuple((body.name, body.particle) for body in bodies),
                 tuple((joint.name, joint.upstream, joint.downstream, joint.kind) for joint in joints),
                 (unknown_key, loads[unknown].direction is None))
    reduction = _Reduction(plan, _actions(bodies, joints, unknown_key, loads[unknown]),
                           *_targets(bodies, loads, values, unknown, gravity, xp))
    reduction.eliminate_pins()
    rows, rhs = reduction.equations(bodies)
    solution = _solve_reduced(rows, rhs, plan.couples, xp)
    if not xp.scalar:  # every unknown over every position, also where its equations do not vary
        import numpy as np

        solution = [np.broadcast_to(x, shape).copy() for x in solution]
    return _reactions(plan, joints, reduction.pin_forms, solution, xp, shape), solution[plan.index[unknown_key]]


class _Reduction:
    """The pin reactions of one call eliminated as forms, and the k x k system left."""

    def __init__(self, plan: _Plan, actions: dict, force_target: dict, moment_target: dict):
        self.plan, self.actions = plan, actions
        self.force_target, self.moment_target = force_target, moment_target
        self.pin_forms: dict[str, dict] = {}  # matched pin name -> its reaction as a form

    def form(self, key: str, direction) -> dict:
        """The form of the action of ``key`` (a joint or the unknown load), sign +."""
        if key in self.pin_forms:
            return self.pin_forms[key]
        column = self.plan.index[key]
        if key in self.plan.pins:
            return {column: 1.0, column + 1: 1j}
        return {column: 1.0 if direction is None else direction}

    def eliminate_pins(self) -> None:
        """Each matched pin from its body's force balance, bodies in the plan's order:
        sign P + (the other forces) = target, sign +1 on the pin's downstream body."""
        for body in self.plan.order:
            pin = self.plan.matched.get(body)
            if pin is None:
                continue
            sign = self.plan.pin_signs[body]
            others = [(-sign * s, self.form(key, d)) for key, s, d, point in self.actions[body]
                      if key != pin and point is not None]
            self.pin_forms[pin] = _combined(*others, (sign, {CONSTANT: self.force_target[body]}))

    def equations(self, bodies: list[Body]) -> tuple[list[list], list]:
        """The reduced system as k rows of k coefficients and k right-hand sides (each a
        number or an array over the positions): each body's moment balance about its
        mass centre, and the force balance of a body without a matched pin."""
        rows, right = [], []
        for body in bodies:
            if body.name not in self.plan.matched:
                total = _combined(*((s, self.form(key, d)) for key, s, d, point in self.actions[body.name]
                                    if point is not None))
                remainder = self.force_target[body.name] - total.get(CONSTANT, 0.0)
                rows += [self._coefficients(total, _real), self._coefficients(total, _imag)]
                right += [remainder.real, remainder.imag]
            if not body.particle:
                centre = body.centre.pos
                total = _combined(*((s, self.form(key, d) if point is None else
                                     _moment_of(point - centre, self.form(key, d)))
                                    for key, s, d, point in self.actions[body.name]))
                rows.append(self._coefficients(total, _real))
                right.append(_real(self.moment_target[body.name] - total.get(CONSTANT, 0.0)))
        return rows, right

    def _coefficients(self, form: dict, part) -> list:
        """``part`` (:func:`_real` or :func:`_imag`) of the form's coefficient on each reduced unknown."""
        return [part(form.get(column, 0.0)) for column in range(self.plan.size)]


def _real(value):
    """The real part of a number or an array (a float's is itself)."""
    return value.real


def _imag(value):
    return value.imag


def _largest(values: list, xp):
    """The elementwise largest of ``values`` (numbers or arrays)."""
    largest = values[0]
    for value in values[1:]:
        largest = xp.maximum(largest, value)
    return largest


def _solve_reduced(rows: list[list], rhs: list, couples: list[bool], xp=SCALAR) -> list:
    """Solve the k x k systems ``rows`` x = ``rhs`` (k rows of k entries, k entries;
    each entry a number or an array over the positions) at every position.

    Scaling: the columns of couple unknowns (``couples``) are multiplied by the
    largest moment arm of the force columns (a couple counts as that force at that
    arm), so all columns are alike whatever the unit of length; then every row is
    scaled to a largest entry of 1.
    (Scaling each column to 1 instead would hide an unknown that has almost no
    effect, such as a piston force a hair from dead centre.)  The scaled system is
    solved with its adjugate (cofactors; k <= 3 here, so a handful of products)
    and one step of iterative refinement, which brings the error to that of a
    pivoted elimination.  Singular (:class:`SingularForceError`) where the
    determinant of the scaled matrix is at most SINGULAR_TOLERANCE: the unknowns
    cannot balance every load, and for the loads they can balance they are not
    unique, so it is an error even when nothing needs balancing.  Non-finite
    coefficients are an OverflowError.
    """
    if not all(xp.all(xp.isfinite(entry)) for entry in [*rhs, *(entry for row in rows for entry in row)]):
        raise OverflowError("the force system overflows (non-finite coefficients)")
    size = len(rows)
    forces = [column for column in range(size) if not couples[column]]
    arm = _largest([abs(row[column]) for row in rows for column in forces], xp) if forces else 1.0
    arm = xp.where(arm == 0, 1.0, arm)
    column_scale = [1.0 / arm if couple else 1.0 for couple in couples]
    rows = [[entry / scale for entry, scale in zip(row, column_scale)] for row in rows]
    row_scale = [_largest([abs(entry) for entry in row], xp) for row in rows]
    row_scale = [xp.where(scale == 0, 1.0, scale) for scale in row_scale]
    rows = [[entry / scale for entry in row] for row, scale in zip(rows, row_scale)]
    cofactors = [[_cofactor(rows, i, j) for j in range(size)] for i in range(size)]
    determinant = sum(rows[0][j] * cofactors[0][j] for j in range(size))
    if not xp.all(abs(determinant) > SINGULAR_TOLERANCE):
        raise SingularForceError("the selected unknown cannot balance the loads")

    def adjugate_solve(right):
        return [sum(cofactors[i][j] * right[i] for i in range(size)) / determinant for j in range(size)]

    right = [value / scale for value, scale in zip(rhs, row_scale)]
    solution = adjugate_solve(right)
    residual = [right[i] - sum(rows[i][j] * solution[j] for j in range(size)) for i in range(size)]
    solution = [(x + dx) / scale for x, dx, scale in zip(solution, adjugate_solve(residual), column_scale)]
    if not all(xp.all(xp.isfinite(x)) for x in solution):
        raise OverflowError("the force system overflows (non-finite reactions)")
    return solution


def _cofactor(rows: list[list], i: int, j: int):
    """(-1)**(i + j) times the minor of ``rows`` without row i and column j."""
    minor = [row[:j] + row[j + 1:] for k, row in enumerate(rows) if k != i]
    return (-1.0) ** (i + j) * _determinant(minor)


def _determinant(rows: list[list]):
    """The determinant of a small matrix given as rows of arrays (Laplace expansion
    along the first row: k! products, meant for k <= 3)."""
    if len(rows) == 1:
        return rows[0][0]
    if len(rows) == 2:
        return rows[0][0] * rows[1][1] - rows[0][1] * rows[1][0]
    return sum(rows[0][j] * _cofactor(rows, 0, j) for j in range(len(rows)))


def _reactions(plan: _Plan, joints: list[Joint], pin_forms: dict, solution: list, xp=SCALAR, shape=()) -> dict:
    """Joint reactions by name (pins complex): reduced unknowns read off the
    solution, eliminated pins evaluated from their forms."""
    reactions = {}
    for joint in joints:
        if joint.name in pin_forms:
            terms = pin_forms[joint.name]
            zero = 0j if xp.scalar else xp.zeros_like(solution[0], dtype=complex)
            reactions[joint.name] = sum((value * (1.0 if key == CONSTANT else solution[key])
                                         for key, value in terms.items()), zero)
        elif joint.kind == "pin":
            column = plan.index[joint.name]
            reactions[joint.name] = solution[column] + 1j * solution[column + 1]
        else:
            reactions[joint.name] = solution[plan.index[joint.name]]
    return reactions


class MassProps(namedtuple("MassProps", "mass inertia distance offset_deg", defaults=(0.0, 0.0, 0.0, 0.0))):
    """``mass`` (kg), ``inertia`` about the mass centre (kg m**2) and where the mass centre
    lies: ``distance`` from the link's reference joint at ``offset_deg`` degrees
    counter-clockwise from the link's reference line (floats or arrays, each 0 by default)."""

    __slots__ = ()


def rigid_body(linkage, body: str, props: MassProps) -> Body:
    """The moving ``body`` of a kinematics result ``linkage`` (a CrankedLinkage; body a
    key of its FRAMES) with the mass, inertia and mass centre given by ``props``."""
    _, link, _ = linkage.FRAMES[body]
    centre = linkage.body_point(body, props.distance, props.offset_deg)
    return Body(body, props.mass, props.inertia, centre, getattr(linkage, link).alpha)


def loads_at_point(linkage, body: str, point_of_interest) -> dict[str, Load]:
    """The contract's three point loads (:func:`point_loads`) at the point of interest
    (distance, offset_deg) of ``body`` of the kinematics result ``linkage``."""
    distance, offset = point_of_interest
    return point_loads(body, linkage.body_position(body, distance, offset),
                       linkage.load_direction(body, distance, offset))


class ForceResult(namedtuple("ForceResult", "unknown value reactions")):
    """A solved force analysis: the name (``unknown``) and ``value`` of the unknown load, and
    the joint ``reactions`` by name (pins complex ``Fx + 1j*Fy``, slides and couples real)."""

    __slots__ = ()


def analysis_shape(*arrays) -> tuple[int, ...]:
    """The broadcast shape of every array (or list) taking part in a force analysis;
    plain numbers are skipped (shape ()) without asking numpy."""
    arrays = [array for array in arrays if not isinstance(array, (int, float, complex))]
    if not arrays:
        return ()
    import numpy as np

    return np.broadcast_shapes(*(np.shape(array) for array in arrays))


def analyse(bodies: list[Body], joints: list[Joint], loads: dict[str, Load], values: dict, unknown: str,
            gravity) -> ForceResult:
    """:func:`solve_kinetostatics` over the common shape of everything given."""
    items = (
        gravity, *values.values(),
        *(item for body in bodies for item in (body.mass, body.inertia, body.centre.pos, body.alpha)),
        *(item for joint in joints for item in (joint.point, joint.direction) if item is not None),
        *(item for load in loads.values() for item in (load.point, load.direction) if item is not None),
    )
    xp = math_for(*items)
    shape = () if xp.scalar else analysis_shape(*items)
    reactions, value = solve_kinetostatics(bodies, joints, loads, values, unknown, gravity, shape, xp)
    return ForceResult(unknown, value, reactions)
