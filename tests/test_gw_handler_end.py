"""Running past the program's last line inside an error handler.

GW-BASIC's statement fetcher, at the end of the program text, goes to PRGEND (GWMAIN.ASM):
when the line is a program line and ONEFLG says an error handler is running, that is the
error No RESUME (19) in the last line run, itself not trapped; a direct line's end goes to
ENDCON, which leaves ONEFLG alone (BIMISC.ASM), and only END clears it (ENDST).  So a
handler that STOPs, and is CONTinued after other direct lines, still ends in No RESUME.
An error no handler takes still sets ERR and ERL (ERROR stores ERRLIN and ERRFLG before
NTMDCN looks for a trap) and leaves a running handler (NOTRAP resets ONEFLG).
Generated programs and sessions against PC-BASIC 2.0.8, which follows the source here but
in one case pinned apart.  The Casio's RESUME page is silent; its run simply ends.
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import PcBasic, base_seed, case_count, run_yaseer
from test_gw_direct_errors import session_of, typed

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

LAST_LINE_HANDLER = '10 ON ERROR GOTO 100\n20 ERROR 5\n30 PRINT "after"\n100 PRINT "trap";ERR;ERL\n'


def test_a_handler_running_off_the_end_is_no_resume_in_its_last_line():
    assert run_yaseer(LAST_LINE_HANDLER, dialect="gw") == "trap 5  20 \nNo RESUME in 100\n"
    # END leaves the handler quietly (ENDST clears ONEFLG)
    assert run_yaseer(LAST_LINE_HANDLER + "110 END\n", dialect="gw") == "trap 5  20 \n"


def test_the_casio_run_simply_ends():
    assert run_yaseer(LAST_LINE_HANDLER, dialect="casio") == "trap 5  20 \n"  # no error line


HANDLER_BODIES = (
    "", ": END", ": RESUME NEXT", ": GOTO 200", ": GOSUB 300", ": X=X+1", ": ERROR 7",
    ": IF X THEN 200", ": ON ERROR GOTO 0",
)
TAILS = ("", '200 PRINT "t"\n', '200 PRINT "t": END\n', '200 PRINT "t"\n300 PRINT "s": RETURN\n')  # no way back to 30: every program ends


def _program(rng: random.Random) -> str:
    body = "".join(rng.choice(HANDLER_BODIES) for _ in range(rng.randint(1, 2)))
    return (f"10 ON ERROR GOTO 100\n20 X={rng.randint(0, 1)}: ERROR {rng.choice((5, 6, 11, 200))}\n"
            f'30 PRINT "after"\n40 {rng.choice(("END", "PRINT X", "ERROR 9"))}\n'
            f'100 PRINT "trap";ERR;ERL{body}\n{rng.choice(TAILS)}')


def test_generated_programs_against_pc_basic():
    rng = random.Random(base_seed() + 1973)
    pc = PcBasic()
    for _ in range(case_count(40)):
        program = _program(rng)
        assert run_yaseer(program, dialect="gw") == pc.program(program), program
    pc.close()


def test_generated_sessions_with_stop_and_cont_against_pc_basic():
    """A handler STOPped, direct lines typed, then CONT: the direct lines' ends keep the
    handler running, so running off the end after CONT is still No RESUME."""
    rng = random.Random(base_seed() + 1974)
    for _ in range(case_count(20)):
        session, shown = session_of("gw")
        pc = PcBasic()
        program = ["10 ON ERROR GOTO 100", "20 ERROR 5", '30 PRINT "after"',
                   '100 PRINT "trap";ERR;ERL: STOP' + rng.choice(("", ": PRINT X", ": END", ": RESUME NEXT")),
                   rng.choice(("", '110 PRINT "more"', "110 GOTO 30"))]
        steps = [line for line in program if line] + ["RUN"]
        for _ in range(rng.randint(0, 3)):
            steps.append(rng.choice(("PRINT 7", "X=X+1", "PRINT ERR;ERL", 'PRINT "d"')))
        steps.append("CONT")
        for step in steps:
            assert typed(session, shown, step) == pc.statement(step), (step, steps)
        pc.close()


ERRORS = ("ERROR 5", "ERROR 200", "X=1/0", "Y=LOG(-1)", "GOTO 999", "RETURN", "A$=5", "NEXT", "PRINT 1:RESUME")


def test_generated_untrapped_errors_set_err_and_erl_against_pc_basic():
    rng = random.Random(base_seed() + 1975)
    for _ in range(case_count(20)):
        session, shown = session_of("gw")
        pc = PcBasic()
        steps = [f"{10 * k} {rng.choice(ERRORS)}" for k in range(1, rng.randint(2, 4))]
        steps += ["PRINT ERR;ERL", "RUN", "PRINT ERR;ERL", rng.choice(ERRORS), "PRINT ERR;ERL", "RUN 20", "PRINT ERL"]
        for step in steps:
            assert typed(session, shown, step) == pc.statement(step), (step, steps)
        pc.close()


def test_an_untrapped_error_leaves_the_handler_as_the_source_says():
    """A handler STOPped, a direct line's error (untrapped: ONEFLG is set) resets ONEFLG
    (GWMAIN.ASM NOTRAP), so CONT then meets RESUME without error (BIMISC.ASM RESUME checks
    ONEFLG).  PC-BASIC 2.0.8 keeps the handler and resumes."""
    session, shown = session_of("gw")
    for line in ("10 ON ERROR GOTO 100", "20 ERROR 5", '100 PRINT "t": STOP: RESUME NEXT', "RUN"):
        typed(session, shown, line)
    assert typed(session, shown, "ERROR 6") == "Overflow\n"
    assert typed(session, shown, "PRINT ERR;ERL") == " 6  65535 \n"
    assert typed(session, shown, "CONT") == "RESUME without error in 100\n"


def test_the_casio_keeps_err_for_trapped_errors_only():
    session, shown = session_of("casio")
    for line in ("10 A=1/0", "RUN"):
        typed(session, shown, line)
    assert typed(session, shown, "PRINT ERR;ERL") == " 0  0 \n"
