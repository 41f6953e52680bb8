"""A direct statement's error under a program's ON ERROR GOTO, and what typing a line clears.

GW-BASIC traps an error wherever it happens (GWMAIN.ASM ERROR: ERRLIN is CURLIN, 65535 for a
direct line, and NTMDCN jumps through ONELIN whatever the line), so the handler a program left
behind runs for an error typed in direct mode, ERL is 65535 and RESUME NEXT goes on in the
direct line; typing or deleting a program line runs RUNC/CLEARC (GWMAIN.ASM FINI, GWLIST.ASM
DELETE): variables, ON ERROR and the rest are cleared.  Generated sessions against PC-BASIC
2.0.8, which follows the source here.  The Casio traps errors of a running program only
(ON_ERROR_GOTO.md: "limited to BASIC program execution").
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import PcBasic, base_seed, case_count
from test_gw_language_rules import pc  # noqa: F401 - the module's PC-BASIC session

from yaseer.session import MachineEngine, Session

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def session_of(dialect: str) -> tuple[Session, list]:
    shown: list[str] = []
    return Session(write=shown.append, engine=MachineEngine(shown.append, dialect=dialect), dialect=dialect), shown


def typed(session: Session, shown: list, line: str) -> str:
    shown.clear()
    session.handle(line)
    return "".join(shown)


HANDLER_ENDS = (": RESUME NEXT", ": RESUME 30", ": END", ": PRINT X: RESUME NEXT")

DIRECT_STATEMENTS = (
    'PRINT "a"', "ERROR 5", "ERROR 7", "ERROR 200", "A=LOG(-1)", "X=X+1", "PRINT X", "Y(11)=1",
    "PRINT 1/0", 'PRINT "b";"c"', "Z=SQR(-4): PRINT Z",
)


def _direct_line(rng: random.Random) -> str:
    return ": ".join(rng.choice(DIRECT_STATEMENTS) for _ in range(rng.randint(1, 4)))


def test_the_handler_traps_a_direct_error_and_resumes_in_the_direct_line(pc):
    session, shown = session_of("gw")
    program = ["10 ON ERROR GOTO 100", "20 X=41", "30 END", '100 PRINT "trap";ERR;ERL: RESUME NEXT']
    for line in program + ["RUN"]:
        typed(session, shown, line)
    assert typed(session, shown, 'ERROR 5: PRINT "after"; X') == "trap 5  65535 \nafter 41 \n"
    assert typed(session, shown, "PRINT ERL") == " 65535 \n"
    # a typed line clears the variables and ON ERROR: the error is not trapped now
    typed(session, shown, "40 REM")
    assert typed(session, shown, 'PRINT X: ERROR 5: PRINT "after"') == " 0 \nIllegal function call\n"


def test_generated_sessions_against_pc_basic():
    rng = random.Random(base_seed() + 2471)
    for _ in range(case_count(30)):
        session, shown = session_of("gw")
        pc = PcBasic()  # each case from a fresh machine (NEW leaves PC-BASIC's error state)
        steps = ["10 ON ERROR GOTO 100", "20 X=" + str(rng.randint(1, 9)), "30 END",
                 '100 PRINT "trap";ERR;ERL' + rng.choice(HANDLER_ENDS), "RUN"]
        for _ in range(rng.randint(2, 6)):
            steps.append(rng.choice([_direct_line(rng)] * 4 + ["40 REM", "ON ERROR GOTO 0", "DELETE 40", "RUN"]))
        for step in steps:
            if step == "DELETE 40" and not any(s == "40 REM" for s in steps[:steps.index(step)]):
                continue
            assert typed(session, shown, step) == pc.statement(step), (step, steps[5:])
        pc.close()


def test_a_division_by_zero_after_clear_goes_on_as_the_source_says():
    """CLEAR sets ONELIN to 0 (BIMISC.ASM CLEARC), and MATH1.ASM TRAPER traps a division by
    zero only while ONELIN is not 0: the message, the largest single, and the line goes on.
    (PC-BASIC 2.0.8 ends the line after the message once CLEAR or NEW ran: the source decides.)"""
    session, shown = session_of("gw")
    for line in ["10 ON ERROR GOTO 100", "20 END", '100 PRINT "trap": RESUME NEXT', "RUN", "CLEAR"]:
        typed(session, shown, line)
    assert typed(session, shown, "PRINT 1/0: PRINT 2") == "Division by zero\n 1.701412E+38 \n 2 \n"


def test_deleting_a_line_clears_too(pc):
    session, shown = session_of("gw")
    for line in ["10 REM", "20 REM", "A=3"]:
        typed(session, shown, line)
    typed(session, shown, "DELETE 20")
    assert typed(session, shown, "PRINT A") == " 0 \n"


def test_casio_traps_only_a_running_program():
    session, shown = session_of("casio")
    for line in ["10 ON ERROR GOTO 100", "20 A=5", "30 END", '100 PRINT "trap": RESUME 30', "RUN"]:
        typed(session, shown, line)
    plain, plain_shown = session_of("casio")
    untrapped = typed(plain, plain_shown, "B=SQR(-4)")  # the message with no handler anywhere
    assert untrapped.strip() and "trap" not in untrapped
    assert typed(session, shown, "B=SQR(-4)") == untrapped
    typed(session, shown, "40 REM")
    assert typed(session, shown, "PRINT A") == " 5 \n"  # the Casio keeps its variables when a line is typed
