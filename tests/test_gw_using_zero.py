"""PRINT USING's ``^^^^`` field of a zero in gw: a double shows a ``0``, a single none.

A real GW-BASIC 3.23 prints ``PRINT USING "####^^^^"; 0`` as ``    E+00`` and the same of
``0#`` as ``   0D+00`` (the recorded unsorted/USING test of PC-BASIC's suite); PC-BASIC
2.0.8 does the same, and keeps the digits of a field with a point (``.00D+00``).
"""

from __future__ import annotations

import pytest

from test_differential_support import run_gw

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

PROGRAM = """\
10 PRINT USING "####^^^^"; 0; 0#; CDBL(0); 0! * 1
20 PRINT USING "#^^^^"; 0; 0#
30 PRINT USING "###^^^^-"; 0; 0#
40 PRINT USING "#.##^^^^"; 0; 0#
"""

EXPECTED = (
    "    E+00   0D+00   0D+00    E+00\n"
    " E+000D+00\n"
    "   E+00   0D+00 \n"
    "0.00E+000.00D+00\n"
)


def test_a_double_zero_shows_its_digit():
    assert run_gw(PROGRAM) == EXPECTED


def test_pc_basic_agrees(tmp_path):
    from test_gw_files import pcbasic_run

    assert pcbasic_run(PROGRAM, tmp_path) == EXPECTED
