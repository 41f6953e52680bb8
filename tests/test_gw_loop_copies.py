"""The copies of loop code that let later passes skip the tests of their makings share one
budget (compiler._copies).

A gw block tests each variable it makes where the statement makes it (compiler.made:
GW's PTRGET makes a variable when a statement first names it, and ``Out of memory`` may
come there).  A block that loops back to its own start, and a native FOR loop, run their
passes in two loops: with the tests while one of their names is not made, then without;
the second loop is a second copy of the code to compile.  Both kinds together add at
most a quarter of the area's code, or 16,000 characters: a program of many FOR loops
that make variables compiles to about 1.25 times the code, not twice.  The loops left
whole still test their makings on every pass, so what the program prints (FRE, and where
``Out of memory`` comes) is the same: checked against PC-BASIC 2.0.8 (with GW's room
test, as tests/test_gw_memory_making.py) and against the same program compiled without
any copy.
"""

from __future__ import annotations

import io
import random

import pytest

from test_differential_support import base_seed, run_gw
from test_gw_memory_making import pc_reason  # noqa: F401  (the fixture)

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def _loops_program(rng: random.Random, count: int, room: int | None = None) -> str:
    """``count`` lines, each a loop whose body makes variables: a FOR loop, two FOR loops
    one inside the other, or a line jumped back to; then FRE(0) and some of the values.
    ``room``: a DIM first leaves about that many bytes, so that the variables run out
    (an ON ERROR handler prints where)."""
    lines = ["5 ON ERROR GOTO 9000"]
    if room is not None:
        lines.append(f"6 DIM Z(FRE(0) / 4 - {room // 4})")
    for k in range(count):
        form = rng.choice(["for", "for", "for", "nested", "goto"])
        number = 10 + k
        if form == "for":
            text = f"FOR I = 1 TO {rng.randint(1, 4)}: V{k} = I: W{k}% = V{k} * 2 + W{k}%: NEXT I"
        elif form == "nested":
            text = f"FOR I = 1 TO 2: FOR J = 1 TO 3: V{k} = I * J: NEXT J: W{k}% = V{k}: NEXT I"
        else:
            text = f"K = K + 1: V{k} = K: W{k}% = W{k}% + 1: IF K MOD 3 THEN {number}"
        lines.append(f"{number} {text}")
    picks = ", ".join(f"V{k}; W{k}%" for k in sorted(rng.sample(range(count), 5)))
    lines += [f"8000 PRINT FRE(0); K; {picks}: END", '9000 PRINT "E"; ERR; ERL; FRE(0): END']
    return "\n".join(lines) + "\n"


def _compiled(source: str) -> tuple[str, str]:
    """(yaseer's screen for ``source`` in gw, the length of its area's Python source)."""
    from yaseer.basic.machine.machine import Machine

    screen = io.StringIO()
    machine = Machine(screen=screen, dialect="gw")
    machine.load(source)
    machine.run()
    return screen.getvalue(), machine.compiled[0].source


@pytest.fixture
def uncached(monkeypatch):
    """Each run compiles its program (no compiled-program cache)."""
    monkeypatch.setenv("YASEER_CACHE_DIR", "")
    return monkeypatch


def _without_copies(monkeypatch) -> None:
    from yaseer.basic.compile import compiler

    monkeypatch.setattr(compiler, "COPIES_LEAST", 0)
    monkeypatch.setattr(compiler, "COPIES_SHARE", 10 ** 12)


def test_many_for_loops_stay_within_the_copies_budget(uncached):
    """A program of 150 loops that make variables: the code the copies add is at most a
    quarter of the code compiled without copies (or 16,000 characters), some loops of both
    kinds are still copied, and the output is that of the program compiled without them."""
    rng = random.Random(base_seed() + 281)
    source = _loops_program(rng, 150)
    printed, code = _compiled(source)
    _without_copies(uncached)
    printed_whole, code_whole = _compiled(source)
    assert printed == printed_whole and not printed.startswith("E")
    assert len(code) - len(code_whole) <= max(16_000, len(code_whole) // 4)
    assert "iter(" in code and "iter(" not in code_whole  # (a FOR loop's two loops share an iterator)
    assert "while _f:" in code and "while _f:" not in code_whole  # (a block's checked passes)


@pytest.mark.parametrize("room", [None, 700, 1500])
def test_the_loops_make_their_variables_as_pcbasic(pc_reason, uncached, room):  # noqa: F811
    """The same kind of programs print FRE(0) and the values, or run out of memory at the
    statement and pass where PC-BASIC 2.0.8 (with GW's room test) does, copied or not."""
    rng = random.Random(base_seed() + 282 + (room or 0))
    source = _loops_program(rng, 120, room)
    pc_reason.statement("ON ERROR GOTO 0")
    theirs = pc_reason.program(source)
    assert (room is not None) == ("E 7 " in theirs)
    assert run_gw(source) == theirs
    _without_copies(uncached)
    assert run_gw(source) == theirs
