"""A file number that names no open file, as a real GW-BASIC 3.23 answers it.

The published source would make every one of these Bad file mode (GIO86.ASM ``FDBPTR``
finds no file, the callers jump to ``DERFNO``, GWDATA.ASM maps ``ERRFNO`` to ``ERRBFM``).
The files PC-BASIC's test suite recorded on a real IBM PC under GW-BASIC say otherwise:
``PRINT #2`` with file 2 not open, EOF, LOC and LOF of a file not open, LOC(0) and LOF(0)
are Bad file number (52); INPUT$(1, #4) is Bad file mode (54); EOF(0) is 0.  The machine
decides over the source here.  The codes below are those recordings' (facts, not their
programs); PC-BASIC 2.0.8 gives the same, and the whole table is compared with it too."""

from __future__ import annotations

import pytest

from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

# (statement on a file never opened, the code a real GW-BASIC recorded or PC-BASIC gives)
NOT_OPEN = [
    ("PRINT #2, 1", 52), ("PRINT EOF(2)", 52), ("PRINT LOC(2)", 52), ("PRINT LOF(2)", 52),
    ("PRINT LOC(0)", 52), ("PRINT LOF(0)", 52), ("A$ = INPUT$(1, #4)", 54), ("A$ = INPUT$(1, 4)", 54),
    ('PRINT #2, USING "##"; 1', 52), ("WRITE #3, 1", 52), ("INPUT #2, A", 52), ("LINE INPUT #2, A$", 52),
    ("WIDTH #2, 40", 52), ("FIELD #2, 5 AS A$", 52), ("GET #2", 54), ("PUT #2", 54), ("PRINT #0, 1", 52),
    ("PRINT EOF(256)", 5), ("PRINT EOF(-1)", 5),
]


def _program(statements) -> str:
    lines = "".join(f"{10 * k + 20} {statement}\n" for k, statement in enumerate(statements))
    return f"10 ON ERROR GOTO 900\n{lines}800 END\n900 PRINT ERR; ERL: RESUME NEXT\n"


def test_a_file_not_open_gives_the_recorded_codes(tmp_path):
    expected = "".join(f" {code}  {10 * k + 20} \n" for k, (_, code) in enumerate(NOT_OPEN))
    source = _program([statement for statement, _ in NOT_OPEN])
    assert yaseer_run(source, tmp_path) == expected
    assert pcbasic_run(source, tmp_path) == expected


def test_eof_of_file_zero_is_zero(tmp_path):
    source = '10 PRINT EOF(0): OPEN "O", 1, "W.TXT": PRINT EOF(0)\n'
    assert yaseer_run(source, tmp_path) == " 0 \n 0 \n" == pcbasic_run(source, tmp_path)


def test_casio_keeps_bad_file_number_for_eof_of_file_zero(tmp_path):
    assert "Bad file number" in yaseer_run("10 PRINT EOF(0)\n", tmp_path, dialect="casio")
