"""OPEN's ACCESS and LOCK clauses (gw), against PC-BASIC 2.0.8, which reproduces what a
real GW-BASIC 3.23 recorded (PC-BASIC's OPEN2, LockOPEN, LockOpenShared and
LockOpenAllRANDOM tests): which clause suits which mode, which second opening of a file
is ``Permission denied``, and which GET, PUT, PRINT # or INPUT # is ``Path/File access
error``.  The released GW-BASIC source has no such clause (machine/file_locks.py).
"""

from __future__ import annotations

import itertools

import pytest

from test_gw_files import both_runs

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

ACCESS = ["", " ACCESS READ", " ACCESS WRITE", " ACCESS READ WRITE"]
LOCKS = ["", " SHARED", " LOCK READ", " LOCK WRITE", " LOCK READ WRITE"]
MODES = ["INPUT", "OUTPUT", "APPEND", "RANDOM"]


def agreed(source: str, tmp_path) -> str:
    """``source``'s screen output, after checking that yaseer and PC-BASIC print the same
    and leave the same files."""
    ours, theirs, our_files, their_files = both_runs(source, tmp_path)
    assert ours == theirs
    assert our_files == their_files
    return ours


def test_each_clause_with_each_mode_as_pcbasic(tmp_path):
    lines = ['10 ON ERROR GOTO 900', '20 OPEN "D.DAT" FOR OUTPUT AS 1: PRINT #1, "x": CLOSE']
    number = 100
    for mode, access, lock in itertools.product(MODES, ACCESS, LOCKS):
        lines.append(f'{number} OPEN "D.DAT" FOR {mode}{access}{lock} AS #2 LEN = 64: PRINT {number};: CLOSE 2')
        number += 10
    lines += ["800 END", '900 PRINT "E"; ERR; ERL: RESUME NEXT']
    ours = agreed("\n".join(lines) + "\n", tmp_path)
    assert "E 2 " in ours and "E 75 " in ours  # INPUT ACCESS WRITE; APPEND ACCESS WRITE


@pytest.mark.parametrize("first_lock", LOCKS)
def test_a_second_opening_and_its_records_as_pcbasic(tmp_path, first_lock):
    lines = ['10 ON ERROR GOTO 900', f'20 OPEN "D.DAT" FOR RANDOM{first_lock} AS 1 LEN = 8',
             '30 LSET A$ = "": FIELD #1, 8 AS A$: LSET A$ = "first": PUT #1, 1: GET #1, 1']
    number = 100
    for access, lock in itertools.product(ACCESS, LOCKS):
        lines.append(f'{number} OPEN "D.DAT" FOR RANDOM{access}{lock} AS 2 LEN = 8: PRINT {number};')
        lines.append(f'{number + 1} GET #2, 1: PUT #2, 2: GET #1, 1: PUT #1, 1: CLOSE 2')
        number += 10
    lines += ["800 CLOSE: END", '900 PRINT "E"; ERR; ERL: RESUME NEXT']
    agreed("\n".join(lines) + "\n", tmp_path)


def test_a_sequential_file_with_clauses_as_pcbasic(tmp_path):
    source = "\n".join([
        '10 ON ERROR GOTO 900',
        '20 OPEN "S.TXT" FOR OUTPUT ACCESS WRITE LOCK WRITE AS 1: PRINT #1, "one"',
        '30 OPEN "S.TXT" FOR INPUT AS 2',
        '40 OPEN "S.TXT" FOR INPUT ACCESS READ SHARED AS 2',
        '50 OPEN "S.TXT" FOR RANDOM ACCESS READ AS 3: GET #3, 1: CLOSE 3',
        '60 CLOSE 1: OPEN "S.TXT" FOR INPUT ACCESS READ LOCK READ AS 1: INPUT #1, A$: PRINT A$',
        '70 OPEN "S.TXT" FOR INPUT ACCESS READ AS 2',
        '80 OPEN "S.TXT" FOR APPEND AS 3',
        '800 CLOSE: END', '900 PRINT "E"; ERR; ERL: RESUME NEXT']) + "\n"
    assert "E 70 " in agreed(source, tmp_path)


def test_input_or_random_may_open_a_file_open_for_output(tmp_path):
    # GIODSK.ASM DSKOPN calls CHKFOP (File already open) for OUTPUT and APPEND only
    source = ('10 OPEN "S.TXT" FOR OUTPUT AS 1: OPEN "S.TXT" FOR INPUT AS 2: PRINT EOF(2)\n'
              '20 OPEN "S.TXT" FOR RANDOM AS 3: PRINT LOF(3)\n30 OPEN "S.TXT" FOR APPEND AS 3\n')
    assert agreed(source, tmp_path) == "-1 \n 0 \nFile already open in 30\n"


def test_casio_has_no_clauses(tmp_path):
    from test_gw_files import yaseer_run

    assert yaseer_run('10 OPEN "S.TXT" FOR OUTPUT ACCESS WRITE AS 1\n', tmp_path, "casio").startswith("Syntax error")


def test_save_over_an_open_file_is_file_already_open(tmp_path):
    # SAVE opens its file for output (GIODSK.ASM CHKFOP): PC-BASIC's recorded OpenSave test
    source = ('10 ON ERROR GOTO 900\n20 OPEN "PROG.BAS" FOR OUTPUT AS 1: PRINT #1, "text"\n30 SAVE "PROG"\n'
              '40 CLOSE: SAVE "PROG": PRINT "saved"\n800 END\n900 PRINT "E"; ERR; ERL: RESUME NEXT\n')
    assert agreed(source, tmp_path) == "E 55  30 \nsaved\n"
