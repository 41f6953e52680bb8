"""DEFINT/DEFSNG/DEFDBL/DEFSTR in direct mode run in order as in a program (GWMAIN.ASM
DEFCON sets the table when the statement runs; a name takes its letter's type when the
reference runs), and RUN n typed directly starts with the table cleared (BIMISC.ASM
CLEARC), so the DEFs above line n are not in force.  Generated lines against PC-BASIC
2.0.8, which follows the source here."""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count, clean_output
from test_gw_language_rules import pc  # noqa: F401 - the module's PC-BASIC session

from yaseer.session import MachineEngine, Session

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def gw_session() -> tuple[Session, list]:
    shown: list[str] = []
    return Session(write=shown.append, engine=MachineEngine(shown.append, dialect="gw"), dialect="gw"), shown


def typed(session: Session, shown: list, line: str) -> str:
    shown.clear()
    session.handle(line)
    return "".join(shown)


def _def(rng: random.Random) -> str:
    first = rng.choice("ABC")
    return f"DEF{rng.choice(['INT', 'SNG', 'DBL'])} {first}" + rng.choice(["", f"-{rng.choice('CD')}"])


def _statement(rng: random.Random) -> str:
    name = rng.choice("ABCD")
    return rng.choice([
        _def(rng), f"{name}={rng.choice(['1.5', '2.7', '-3.25', '7', '1/3'])}",
        f"PRINT {name}; {name}!; {name}%", f"{name}!={rng.choice(['4.5', '.1'])}", f"PRINT {name}+1",
    ])


def test_direct_lines_apply_their_defs_in_order(pc):
    """``A=1.5: DEFINT A: PRINT A`` prints 0: A! stays 1.5, PRINT reads A%, never set."""
    session, shown = gw_session()
    assert typed(session, shown, "A=1.5: DEFINT A: PRINT A") == " 0 \n"
    assert typed(session, shown, "PRINT A!; A") == " 1.5  0 \n"
    rng = random.Random(base_seed() + 2402)
    for k in range(case_count(40)):
        pc.statement("CLEAR")
        session, shown = gw_session()
        for _ in range(rng.randint(2, 5)):
            line = ": ".join(_statement(rng) for _ in range(rng.randint(1, 4)))
            assert typed(session, shown, line) == pc.statement(line), line


def test_run_n_typed_directly_starts_with_the_table_cleared(pc):
    rng = random.Random(base_seed() + 2403)
    for k in range(case_count(25)):
        top = [_def(rng) for _ in range(rng.randint(1, 3))]
        body = [_statement(rng) for _ in range(rng.randint(2, 5))]
        if not any(s.startswith("PRINT") for s in body):
            body.append("PRINT A; B; C; D")
        lines = [f"{10 * (i + 1)} {s}" for i, s in enumerate(top + body)]
        start = 10 * rng.randint(1, len(lines))
        session, shown = gw_session()
        for line in lines:
            typed(session, shown, line)
        pc._session.execute("NEW")
        pc._session.execute("\n".join(lines))
        for command in (f"RUN {start}", "RUN", f"RUN {start}", "PRINT A; B!; C#"):
            theirs = clean_output(pc._session.execute(command))
            assert typed(session, shown, command) == theirs, (lines, command)
