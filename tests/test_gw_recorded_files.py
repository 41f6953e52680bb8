"""Program files, CHAIN and random files as a real GW-BASIC 3.23 recorded them.

Each case is a small program of our own that shows one behaviour PC-BASIC's test suite
recorded on the real machine (tests/basic: the recording named in each test), with the
GW-BASIC routine behind it; where PC-BASIC 2.0.8 agrees, its run is the reference,
else the value the recording and the source give.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def _both(source: str, tmp_path: Path) -> tuple[str, str]:
    ours, theirs = tmp_path / "yaseer", tmp_path / "pcbasic"
    ours.mkdir()
    theirs.mkdir()
    return yaseer_run(source, ours), pcbasic_run(source, theirs)


def test_field_variable_takes_no_string_space(tmp_path):
    """FLDGARB: a FIELDed variable points into the file's buffer (DSKCOM.ASM FIELD), so
    FRE("") does not count its characters, after FIELD, LSET and GET alike; a copy of it
    made by a string operation is a string of the string space."""
    source = ('10 OPEN "R.DAT" FOR RANDOM AS 1\n20 A$="": F=FRE("")\n30 FIELD #1, 100 AS A$\n'
              '40 PRINT F-FRE("")\n50 LSET A$="XY": GET #1, 1: PRINT F-FRE("")\n'
              '60 A$=A$+"": PRINT F-FRE("")\n')
    ours, theirs = _both(source, tmp_path)
    assert ours == theirs == " 0 \n 0 \n 100 \n"
