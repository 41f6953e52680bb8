"""VAL of a number followed by CHR$(28), CHR$(29) or CHR$(31) is 0 in gw.

Those bytes mark an embedded integer, single and double constant in a tokenised line
(GWMAIN.ASM INTCON, SNGCON, DBLCON); VAL's number reader scans with CHRGTR, which takes
them as such (``CHRCON``).  A real GW-BASIC 3.23 gives 0 for ``VAL("1" + CHR$(n) + "2")``
with n 28, 29, 31 and 12 with CHR$(30) or a blank (the recorded unsorted/VAL test of
PC-BASIC's suite); PC-BASIC 2.0.8 agrees, also with the byte after a sign, a point, an
exponent or a blank.  The casio's VAL is another reader and keeps its rules.
"""

from __future__ import annotations

import pytest

from test_differential_support import run_gw

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

PROGRAM = """\
10 FOR I = 28 TO 31
20 PRINT I; VAL("1" + CHR$(I) + "2"); VAL("12" + CHR$(I)); VAL("-3" + CHR$(I) + "4");
30 PRINT VAL("1.5" + CHR$(I)); VAL("1E" + CHR$(I) + "2"); VAL("7 " + CHR$(I)); VAL(CHR$(I) + "5")
40 NEXT
"""

EXPECTED = (
    " 28  0  0  0  0  0  0  0 \n"
    " 29  0  0  0  0  0  0  0 \n"
    " 30  1  12 -3  1.5  1  7  0 \n"
    " 31  0  0  0  0  0  0  0 \n"
)


def test_val_of_a_number_before_a_constant_token_is_zero():
    assert run_gw(PROGRAM) == EXPECTED


def test_other_control_bytes_end_the_number():
    """A tab or line feed is a blank (skipped); any other byte ends the number."""
    assert run_gw('10 PRINT VAL("1" + CHR$(9) + "2"); VAL("1" + CHR$(27) + "2"); VAL("1" + CHR$(11))\n') == \
        " 12  1  1 \n"


def test_pc_basic_agrees():
    from pathlib import Path
    import tempfile

    from test_gw_files import pcbasic_run

    with tempfile.TemporaryDirectory() as folder:
        assert pcbasic_run(PROGRAM, Path(folder)) == EXPECTED
