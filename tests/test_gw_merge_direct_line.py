"""MERGE of a file whose first line has no number, under ON ERROR GOTO (gw).

GW-BASIC's MERGE reads the file as typed lines: DSKCOM.ASM OKGETM jumps to GWMAIN.ASM
MAIN, which sets CURLIN to 65535 and reads a line from the file; a line without a number
is GIO86.ASM DIRDO's ``Direct statement in file`` (66).  Every line entered clears the
error trap (FINI's RUNC, CLEARC sets ONELIN to 0; LEVFRE before an insertion), so the
error is trapped only when it is the file's first line: ERR 66, ERL 65535 (GWMAIN.ASM
ERROR copies CURLIN).  RESUME goes back to ERRTXT, the line as MAIN crunched it: RESUME
runs it, RESUME NEXT skips its first statement, and then the direct line ends (the
handler's PRINT closed file #0: GIO86.ASM FINPRT with NLONLY cleared by ERROR), so the
rest of the file is not merged.  The expected outputs below are worked from those
routines; PC-BASIC 2.0.8 traps the error too (checked where it agrees: ERR) but names the
MERGE's line as ERL and goes on after the MERGE statement.
"""

from __future__ import annotations

import pytest

from test_gw_files import pcbasic_run, yaseer_run
from test_gw_protected import gw_session

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

FIRST_LINE_DIRECT = 'PRINT "X": PRINT "Y"\r\n50 PRINT "merged"\r\n'
PROGRAM = '10 ON ERROR GOTO 100\n20 MERGE "M"\n30 PRINT "after"\n40 END\n'


def run_with(tmp_path, handler: str, text: str = FIRST_LINE_DIRECT) -> str:
    (tmp_path / "M.BAS").write_bytes(text.encode("latin-1"))
    return yaseer_run(PROGRAM + handler + "\n", tmp_path)


@pytest.mark.parametrize("handler, expected", [
    ('100 PRINT "T";ERR;ERL: END', "T 66  65535 \n"),
    ('100 PRINT "T";ERR;ERL: RESUME NEXT', "T 66  65535 \nY\n"),
    ('100 PRINT "T";ERR;ERL: RESUME', "T 66  65535 \nX\nY\n"),
    ('100 PRINT "T";ERR;ERL: RESUME 30', "T 66  65535 \nafter\n"),
    ('100 PRINT "T";ERR;ERL: ON ERROR GOTO 0', "T 66  65535 \nDirect statement in file\n"),
])
def test_the_first_line_s_error_is_trapped_as_a_direct_line_s(tmp_path, handler, expected):
    assert run_with(tmp_path, handler) == expected


def test_the_rest_of_the_file_is_not_merged_after_resume(tmp_path):
    from yaseer.basic.machine.machine import Machine

    (tmp_path / "M.BAS").write_bytes(FIRST_LINE_DIRECT.encode())
    machine = Machine(dialect="gw", files=tmp_path)
    machine.load(PROGRAM + '100 RESUME NEXT\n')
    machine.run()
    assert sorted(machine.programs[0]) == [10, 20, 30, 40, 100]


@pytest.mark.parametrize("text", [
    '50 PRINT "merged"\r\nPRINT "X"\r\n',  # a line entered first clears the trap
    '30\r\nPRINT "X"\r\n',  # so does a line deleted (FINI's RUNC, no insertion; a bare
    # number of no line is Undefined line number: GWMAIN.ASM EDENT's USERR)
])
def test_a_later_line_without_number_is_not_trapped(tmp_path, text):
    assert run_with(tmp_path, '100 PRINT "T";ERR;ERL: END', text) == "Direct statement in file\n"


def test_pc_basic_traps_it_too(tmp_path):
    """Where PC-BASIC 2.0.8 agrees with the source: the handler runs with ERR 66."""
    handler = '100 PRINT "T";ERR: END\n'
    (tmp_path / "M.BAS").write_bytes(FIRST_LINE_DIRECT.encode())
    theirs = pcbasic_run(PROGRAM + handler, tmp_path)
    assert theirs == run_with(tmp_path, handler) == "T 66 \n"


def test_a_typed_merge_is_trapped_by_the_program_s_handler(tmp_path):
    """Typed after the program ended: ON ERROR GOTO is still set (END leaves ONELIN)."""
    (tmp_path / "M.BAS").write_bytes(FIRST_LINE_DIRECT.encode())
    session, shown = gw_session(tmp_path)
    for line in ["NEW", "10 ON ERROR GOTO 100", "20 END", '100 PRINT "T";ERR;ERL: RESUME NEXT', "RUN"]:
        session.handle(line)
    shown.clear()
    session.handle('MERGE "M"')
    assert "".join(shown) == "T 66  65535 \nY\n"


def test_a_stop_in_that_line_leaves_nothing_to_continue(tmp_path):
    """RESUME runs the file's ``STOP`` as a direct statement: a plain Break (no line), and
    CONT has no program point to go back to (BIMISC.ASM ENDCON keeps none for a direct
    line; RUN's CLEARC emptied OLDTXT)."""
    (tmp_path / "M.BAS").write_bytes(b'STOP\r\n50 PRINT "merged"\r\n')
    session, shown = gw_session(tmp_path)
    for line in ["NEW", "10 ON ERROR GOTO 100", '20 MERGE "M"', '30 PRINT "after"',
                 '100 PRINT "T";ERR;ERL: RESUME']:
        session.handle(line)
    shown.clear()
    session.handle("RUN")
    assert "".join(shown) == "T 66  65535 \nBreak\n"
    shown.clear()
    session.handle("CONT")
    assert "".join(shown) == "Can't continue\n"
