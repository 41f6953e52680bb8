"""docs/contract.md and yaseer/binding.py cannot drift apart.

The tables of docs/contract.md are parsed (the first cell of each row names its
elements: `L(1)`, `W(2)`, `A(2)` ..., or a scalar variable `G`).  Each program
then runs through the binding on a stand-in machine that records every element
the binding reads and every output it writes, in a static call, a moving call
and a call with forces for every Q(n), and:

* the inputs it reads at every call are the rows marked "always", those it
  reads only with Z(n) = 2 the rows marked "Z(n) = 2": no element more or less;
* it writes the rows of kind position and rate at every call (rates exactly 0
  in a static call), the reactions only with Z(n) = 2, and of the unknowns only
  the one the doc's Q(n) table names;
* the array sizes the doc lists are the machine's, and every element fits;
* every row of the error table is what the binding raises (message and ERR);
* the later calls, which run a compiled recording of the first, write the same;
* the "Points on a link" table: the reference joint and line of each link, checked
  through the positions the binding writes (and the doc's directions of T(3), T(13),
  T(14), T(9) and L(5) with them).
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from test_binding import P1_INPUTS, P2_INPUTS, P3_INPUTS
from test_binding_fake import PAPER_DIMS, FakeMachine
from yaseer import binding
from yaseer.basic.dialects.dialect import AL_YASEER_DIMENSIONS
from yaseer.basic.errors import BasicError

DOC = Path(__file__).resolve().parents[1] / "docs" / "contract.md"
HEADING = re.compile(r"^#{2,3} (.*)$")
SECTION = re.compile(r"^Program (\d): (inputs|outputs|the unknown Q\(\d\) selects)$")
ELEMENT = re.compile(r"`([A-Z])(?:\((\d+)\))?`")


def tables(text: str) -> dict[str, list[list[str]]]:
    """The body rows (cells stripped) of the first table under each heading."""
    found: dict[str, list[list[str]]] = {}
    heading = None
    for line in text.splitlines():
        match = HEADING.match(line)
        if match:
            heading = match.group(1).strip()
            continue
        if line.startswith("|") and heading is not None:
            cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
            rows = found.setdefault(heading, [])
            rows.append(cells)
    # drop each table's header and separator rows
    return {name: rows[2:] for name, rows in found.items()}


def elements(cell: str) -> set:
    """The elements a first cell names: ("L", 1) for `L(1)`, "G" for `G`."""
    return {(name, int(index)) if index else name for name, index in ELEMENT.findall(cell)}


TABLES = tables(DOC.read_text())


def contract(program: int):
    """(inputs by 'read', outputs by 'kind', {q: unknown element}) of one program, from the doc."""
    inputs: dict[str, set] = {}
    outputs: dict[str, set] = {}
    unknowns: dict[int, object] = {}
    for row in TABLES[f"Program {program}: inputs"]:
        inputs.setdefault(row[3], set()).update(elements(row[0]))
    for row in TABLES[f"Program {program}: outputs"]:
        outputs.setdefault(row[3], set()).update(elements(row[0]))
    for heading, rows in TABLES.items():
        if heading.startswith(f"Program {program}: the unknown"):
            for row in rows:
                (element,) = elements(row[1])
                unknowns[int(row[0])] = element
    return inputs, outputs, unknowns


class Recorded:
    """What the binding read and wrote in one call."""

    def __init__(self):
        self.reads: set = set()
        self.writes: dict = {}


@pytest.fixture
def record(monkeypatch):
    """``record(machine, n)`` calls area n and returns a :class:`Recorded`."""
    log = Recorded()
    frame = binding._Frame
    get, scalar, put, put_scalar = frame.get, frame.scalar, frame.put, frame.put_scalar

    def recording_get(self, name, index):
        log.reads.add((name, index))
        return get(self, name, index)

    def recording_scalar(self, name):
        log.reads.add(name)
        return scalar(self, name)

    def recording_put(self, element, value):
        log.writes[element] = float(value)
        return put(self, element, value)

    def recording_put_scalar(self, name, value):
        log.writes[name] = float(value)
        return put_scalar(self, name, value)

    monkeypatch.setattr(frame, "get", recording_get)
    monkeypatch.setattr(frame, "scalar", recording_scalar)
    monkeypatch.setattr(frame, "put", recording_put)
    monkeypatch.setattr(frame, "put_scalar", recording_put_scalar)

    def call(machine, area):
        # a first call, as in a fresh process without the cache: the plain code, not a recording of
        # an earlier call nor a path kept on disk
        monkeypatch.setattr(binding, "_recordings", {})
        monkeypatch.setattr(binding, "_calls", {})
        monkeypatch.setenv("YASEER_CACHE_DIR", "")
        log.reads.clear()
        log.writes.clear()
        machine.call(area)
        return log

    return call


# Valid inputs per program, the crank's rate elements, and its Z(n) and Q(n).
INPUTS = {1: P1_INPUTS, 2: P2_INPUTS, 3: P3_INPUTS}
CRANK_RATES = {1: [("W", 2), ("A", 2), ("D", 0), ("E", 0)], 2: [("W", 5), ("A", 5), ("D", 2), ("E", 2)],
               3: [("W", 0), ("A", 0), ("D", 3), ("E", 3)]}


def machine_with(program: int, z: float, q: float = 0.0, static: bool = False, methods=None) -> FakeMachine:
    m = FakeMachine(PAPER_DIMS)
    binding.install(m, methods)
    m.set(**INPUTS[program], Z={program: z}, Q={program: q}, G=9.81)
    if static:
        for name, index in CRANK_RATES[program]:
            m.array(name)[index] = 0.0
    return m


@pytest.mark.parametrize("program", [1, 2, 3])
def test_without_forces_the_binding_reads_and_writes_what_the_doc_says(program, record):
    inputs, outputs, _ = contract(program)
    moving = dict(record(machine_with(program, z=0), program).writes)
    static = record(machine_with(program, z=0, static=True), program)
    assert static.reads == inputs["always"]
    assert set(static.writes) == set(moving) == outputs["position"] | outputs["rate"]
    # positions do not depend on the crank's rates; rates are 0 in a static call, and
    # (generic inputs) none is 0 in a moving one
    assert {e: static.writes[e] for e in outputs["position"]} == {e: moving[e] for e in outputs["position"]}
    assert all(static.writes[element] == 0.0 for element in outputs["rate"])
    assert all(moving[element] != 0.0 for element in outputs["rate"])


@pytest.mark.parametrize("program", [1, 2, 3])
def test_with_forces_it_reads_every_input_and_writes_the_reactions_and_the_selected_unknown(program, record):
    inputs, outputs, unknowns = contract(program)
    assert set(inputs) == {"always", f"Z({program}) = 2"}
    assert set(outputs) == {"position", "rate", "reaction", "unknown"}
    assert set(unknowns.values()) == outputs["unknown"]
    assert sorted(unknowns) == sorted(binding.UNKNOWNS[program])
    for q, unknown in unknowns.items():
        log = record(machine_with(program, z=2, q=q), program)
        assert log.reads == inputs["always"] | inputs[f"Z({program}) = 2"], q
        assert set(log.writes) == outputs["position"] | outputs["rate"] | outputs["reaction"] | {unknown}, q


@pytest.mark.parametrize("program", [1, 2, 3])
def test_a_q_outside_the_doc_table_is_refused(program):
    _, _, unknowns = contract(program)
    for q in set(range(0, 6)) - set(unknowns):
        with pytest.raises(BasicError, match=rf"Q\({program}\) = {q} is not"):
            machine_with(program, z=2, q=q).call(program)


@pytest.mark.parametrize("l10", [0, 1, -1])
def test_program_2_reads_the_same_elements_on_every_branch_setting(l10, record):
    inputs, _, _ = contract(2)
    m = machine_with(2, z=0)
    m.set(L={10: l10})
    assert record(m, 2).reads == inputs["always"]


@pytest.mark.parametrize("method", [None, "paper"])
def test_program_5_reads_and_writes_what_the_doc_says(method, record):
    inputs, outputs, unknowns = contract(5)
    assert set(inputs) == {"always"} and set(outputs) == {"position", "rate"} and not unknowns
    m = FakeMachine(PAPER_DIMS)
    binding.install(m, {5: method} if method else None)
    m.set(X={10: 3.0}, Y={10: 4.0}, V={17: 1.0, 18: -2.0}, A={49: 0.5, 50: 0.25})
    moving = dict(record(m, 5).writes)
    assert record(m, 5).reads == inputs["always"]
    assert set(moving) == outputs["position"] | outputs["rate"]
    assert all(moving[element] != 0.0 for element in outputs["rate"])
    m = FakeMachine(PAPER_DIMS)  # the point at rest: the same positions, every rate 0
    binding.install(m, {5: method} if method else None)
    m.set(X={10: 3.0}, Y={10: 4.0})
    resting = record(m, 5).writes
    assert {e: resting[e] for e in outputs["position"]} == {e: moving[e] for e in outputs["position"]}
    assert all(resting[element] == 0.0 for element in outputs["rate"])


class LoggedArray(list):
    """An array of the machine that logs every element written to it."""

    def __init__(self, name, values, log):
        super().__init__(values)
        self.name, self.log = name, log

    def __setitem__(self, index, value):
        self.log.add((self.name, index))
        super().__setitem__(index, value)


class LoggedMachine(FakeMachine):
    """A stand-in machine that logs every array element and scalar written."""

    def __init__(self, dims):
        super().__init__(dims)
        self.written: set = set()
        self.arrays = {name: LoggedArray(name, values, self.written) for name, values in self.arrays.items()}

    def set_scalar(self, name, value):
        self.written.add(name)
        super().set_scalar(name, value)


@pytest.mark.parametrize("program, z, q", [(1, 0, 0), (1, 2, 4), (2, 0, 0), (2, 2, 3), (3, 2, 3), (5, 0, 0)])
def test_later_calls_write_the_same_elements(program, z, q, monkeypatch):
    """From the second call on, the binding runs a compiled recording of the first; the
    elements written (seen by the machine itself) stay those of the doc's tables."""
    monkeypatch.setattr(binding, "_recordings", {})
    monkeypatch.setattr(binding, "_calls", {})
    _, outputs, unknowns = contract(program)
    expected = outputs["position"] | outputs["rate"]
    if z == 2:
        expected |= outputs["reaction"] | {unknowns[q]}
    m = LoggedMachine(PAPER_DIMS)
    binding.install(m)
    if program == 5:
        m.set(X={10: 3.0}, Y={10: 4.0}, V={17: 1.0, 18: -2.0}, A={49: 0.5, 50: 0.25})
    else:
        m.set(**INPUTS[program], Z={program: z}, Q={program: q}, G=9.81)
    values = []
    for _ in range(3):  # plain, recorded while it runs, the recording
        m.written.clear()
        m.call(program)
        assert m.written == expected
        values.append({element: (m.array(element[0])[element[1]] if isinstance(element, tuple) else m.scalar(element))
                       for element in expected})
    assert values[1] == values[0] and values[2] == values[0]
    assert binding._recordings.get((program, None)), "no recording was made: the test checks nothing new"


def test_the_array_sizes_are_the_machines_and_every_element_fits():
    rows = TABLES["The arrays"]
    sizes = {}
    for row in rows:
        for name_cell, size_cell in zip(row[0::2], row[1::2]):
            sizes[name_cell.strip("`")] = int(size_cell)
    assert sizes == dict(AL_YASEER_DIMENSIONS) == PAPER_DIMS
    for program in (1, 2, 3, 5):
        inputs, outputs, _ = contract(program)
        for element in set().union(*inputs.values(), *outputs.values()):
            if isinstance(element, tuple):
                assert element[1] <= sizes[element[0]], (program, element)


def error_cases():
    """(row start, program, v, machine) that raise each error of the doc's table."""
    def m(inputs=None, methods=None, dims=PAPER_DIMS, **values):
        machine = FakeMachine(dims)
        binding.install(machine, methods)
        machine.set(**(inputs or {}), **values)
        return machine

    two_d = m()
    two_d.arrays["X"] = [[0.0, 0.0] for _ in range(12)]
    return {
        "Mechanism cannot be assembled": (2, None, m(L={11: 10.0, 12: 1.0, 13: 2.0, 14: 2.0})),
        "Mechanism locks": (2, None, m(L={11: 1.0, 12: 0.5, 13: 0.5, 14: 1.0}, T={12: 0.0}, W={5: 1.0})),
        "Force system is singular": (1, None, m(L={2: 0.1, 3: 0.3}, T={2: 30.0}, W={2: 5.0}, U={1: 1.0}, Z={1: 2},
                                                 Q={1: 2})),
        "Q(n) = v": (1, 7, m(P1_INPUTS, Z={1: 2}, Q={1: 7})),
        "Division by zero": (5, None, m(methods={5: "paper"}, X={10: 0.0}, Y={10: 2.0}, V={17: 1.0})),
        "Subscript out of range": (1, None, m(dims={}, L={1: -2, 2: 3, 3: 8}, T={2: -30}, W={2: -15})),
        "Overflow": (5, None, m(X={10: 1e-300}, V={18: 1e300})),
        "Type mismatch": (5, None, two_d),
    }


def test_every_row_of_the_error_table_is_what_the_binding_raises():
    rows = TABLES["Errors"]
    cases = error_cases()
    assert len(rows) == len(cases)
    for row in rows:
        template = row[1].strip("`")
        code = int(row[2])
        (key,) = [key for key in cases if template.startswith(key)]
        program, value, machine = cases[key]
        with pytest.raises(BasicError) as caught:
            machine.call(program)
        expected = template.replace("(PROG n)", f"(PROG {program})").replace("Q(n)", f"Q({program})")
        expected = expected.replace("= v ", f"= {value} ")
        assert (str(caught.value), caught.value.code) == (expected, code)


def test_no_document_points_outside_the_repository():
    root = Path(__file__).resolve().parents[1]
    for path in [root / "README.md", *sorted((root / "docs").glob("*.md")), *sorted((root / "yaseer").rglob("*.py"))]:
        text = path.read_text()
        assert "shared/spec" not in text and "../shared" not in text and "/work/" not in text, path


# Where each link's point elements are (the doc's "Points on a link" table is checked
# against these): (R, H) inputs and the (X, Y) outputs of its point of interest.
POINT_ELEMENTS = {
    (1, "crank"): (("R", 1), ("H", 1), ("X", 1), ("Y", 1)),
    (1, "connecting rod"): (("R", 4), ("H", 4), ("X", 2), ("Y", 2)),
    (2, "crank"): (("R", 9), ("H", 9), ("X", 3), ("Y", 3)),
    (2, "coupler"): (("R", 11), ("H", 11), ("X", 4), ("Y", 4)),
    (2, "follower"): (("R", 13), ("H", 13), ("X", 5), ("Y", 5)),
    (3, "crank"): (("R", 0), ("H", 23), ("X", 6), ("Y", 6)),
    (3, "follower"): (("R", 7), ("H", 6), ("X", 7), ("Y", 7)),
}


def joints(program: int, m: FakeMachine) -> dict[str, complex]:
    """The joints of a program after a call, from its inputs and the doc's angle outputs:
    T(3) is A->B, T(13) A->B, T(14) B->Bo, T(9) Bo->A, L(5) = |Bo->A|."""
    import cmath
    import math

    a, t = m.array("L"), m.array("T")

    def u(degrees):
        return cmath.exp(1j * math.radians(degrees))

    if program == 1:
        pin_a = a[2] * u(t[2])
        return {"Ao": 0j, "A": pin_a, "B": pin_a + a[3] * u(t[3])}
    if program == 2:
        pin_a, pivot = a[12] * u(t[12]), a[11] * u(t[11])
        pin_b = pin_a + a[13] * u(t[13])
        assert abs(pin_b - (pivot - a[14] * u(t[14]))) < 1e-9  # T(14) is B->Bo: the loop closes
        return {"Ao": 0j, "A": pin_a, "B": pin_b, "Bo": pivot}
    pin_a, pivot = a[7] * u(t[7]), -a[6] * u(t[6])
    assert abs(pivot + a[5] * u(t[9]) - pin_a) < 1e-9  # L(5), T(9): the vector Bo->A
    return {"Ao": 0j, "A": pin_a, "Bo": pivot}


def test_points_on_a_link_are_measured_as_the_doc_says():
    """For each row of the doc's table: R = 0 is the reference joint, R = the joint-to-joint
    length with H = 0 is the other joint, and H = 90 turns counter-clockwise from that line."""
    rows = TABLES["Conventions every program follows"]
    assert {(int(row[0]), row[1]) for row in rows} == set(POINT_ELEMENTS)
    for program_text, link, joint_text, line_text in rows:
        program = int(program_text)
        start, end = joint_text.split()[0], line_text.split("→")[1]
        assert line_text.split("→")[0] == start, line_text
        r, h, x, y = POINT_ELEMENTS[(program, link)]

        def point(distance, angle):
            m = machine_with(program, z=0)
            m.set(**{r[0]: {r[1]: distance}})
            m.set(**{h[0]: {h[1]: angle}})
            m.call(program)
            return complex(m.array(x[0])[x[1]], m.array(y[0])[y[1]]), joints(program, m)

        at_start, places = point(0.0, 30.0)
        assert abs(at_start - places[start]) < 1e-9, (program, link)
        length = abs(places[end] - places[start])
        at_end, _ = point(length, 0.0)
        assert abs(at_end - places[end]) < 1e-9, (program, link)
        turned, _ = point(length, 90.0)
        assert abs(turned - (places[start] + 1j * (places[end] - places[start]))) < 1e-9, (program, link)
