"""CHAIN and COMMON as a real GW-BASIC 3.23 recorded them (gw), checked against PC-BASIC
2.0.8, which runs them so.

COMMON with a bracket after a name (PC-BASIC's COMMONA, COMMONC and COMMONI tests):
``COMMON A[2]`` keeps neither the array A nor the variable A, with no error; ``COMMON B[]``
stops the CHAIN with Syntax error in the COMMON's line (source/common_lists.py).  What
follows a CHAIN's DELETE range is never read (CHAIN_with_dummy_fifth_argument; FIVEO.ASM
CHAIN reads the range with SCNLIN and chains)."""

from __future__ import annotations

from pathlib import Path

import pytest

from test_gw_files import contents, pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

NEXT = b'10 PRINT A(1); A(2); A; B; C(1)\r\n'


def chained(source: str, tmp_path: Path) -> tuple[str, str]:
    outputs = []
    for who, run in (("yaseer", yaseer_run), ("pcbasic", pcbasic_run)):
        directory = tmp_path / who
        directory.mkdir()
        (directory / "NEXT.BAS").write_bytes(NEXT)
        outputs.append(run(source, directory))
        assert set(contents(directory)) == {"NEXT.BAS"}
    return outputs[0], outputs[1]


@pytest.mark.parametrize("common", ["COMMON A[2]", "COMMON A[1], B", "COMMON B, A[1 + 1], C()", "COMMON A[]",
                                    "COMMON B, C[]: COMMON A()", "COMMON A(1), B"])
def test_a_bracket_in_common_as_pcbasic(tmp_path, common):
    source = ('10 ON ERROR GOTO 100\n20 A(1) = 1: A(2) = 2: A = 3: B = 4: C(1) = 5\n'
              f'30 {common}\n40 CHAIN "NEXT"\n50 PRINT "back"\n60 END\n100 PRINT "E"; ERR; ERL: RESUME NEXT\n')
    ours, theirs = chained(source, tmp_path)
    assert ours == theirs


@pytest.mark.parametrize("tail", [",PRINT", ", 5", " PRINT 7", ", ,", ""])
def test_what_follows_the_delete_range_after_a_comma_is_not_read(tmp_path, tail):
    # GWMAIN.ASM SCNLIN: the range ends at the statement's end or a comma, else Syntax error
    source = f'10 A(1) = 7: CHAIN "NEXT", , ALL, DELETE 10-20{tail}\n20 PRINT "kept"\n'
    ours, theirs = chained(source, tmp_path)
    assert ours == theirs == ("Syntax error in 10\n" if tail == " PRINT 7" else " 7  0  0  0  0 \n")
