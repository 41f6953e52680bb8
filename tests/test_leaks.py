"""Nothing survives a run that its result does not need: no machine outlives its run.

Machines are counted by weak references (every Machine made is noted) after a
garbage collection: 300 runs through the API (END, an error, STOP, a library
call, falling off the last line) and 300 RUNs in one interactive session leave
no machine behind but the session's current one, even when every result is kept.
"""

from __future__ import annotations

import gc
import weakref

import pytest

import yaseer
from yaseer.basic.machine.machine import Machine
from yaseer.session import MachineEngine, Session

PROGRAMS = ("10 PRINT 1: END\n", "10 PRINT 1/0\n", "10 STOP\n",
            "10 X(10) = 1: Y(10) = 1: GOSUB PROG 5: PRINT T\n", "10 PRINT 2\n",
            "10 ON ERROR GOTO 30\n20 ERROR 5\n30 RESUME 40\n40 END\n", "10 FOR I = 1 TO 3: GOSUB 30: NEXT: END\n30 RETURN\n")


@pytest.fixture
def machines(monkeypatch) -> list:
    """Weak references to every Machine made while the test runs."""
    made = []
    real = Machine.__init__

    def noted(self, *args, **kwargs):
        made.append(weakref.ref(self))
        real(self, *args, **kwargs)

    monkeypatch.setattr(Machine, "__init__", noted)
    return made


def alive(made: list) -> int:
    gc.collect()
    return sum(1 for ref in made if ref() is not None)


def test_300_api_runs_leave_no_machine(machines):
    results = [yaseer.run(PROGRAMS[n % len(PROGRAMS)]) for n in range(300)]
    assert len(machines) == 300
    assert {r.status for r in results} == {"end", "error", "stop"}
    assert results[1].error == "Division by zero in 10" and results[1].exception.code == 11
    assert alive(machines) == 0


def test_300_session_runs_keep_only_the_current_machine(machines, tmp_path):
    shown = []
    session = Session(write=shown.append, engine=MachineEngine(shown.append), directory=tmp_path)
    for number in range(300):
        session.handle("NEW")
        for line in PROGRAMS[number % len(PROGRAMS)].splitlines():
            session.handle(line)
        session.handle("RUN")
    assert "Division by zero in 10\n" in shown
    assert len(machines) >= 300
    assert alive(machines) <= 1


def test_an_error_raised_to_the_caller_still_carries_its_line():
    with pytest.raises(Exception) as raised:
        yaseer.run("10 PRINT 1\n20 PRINT 1/0\n", raise_errors=True)
    assert str(raised.value) == "Division by zero in 20"
