"""A PRINT # cut inside its first item writes nothing to the file: GW-BASIC reads the item
before it prints anything, so ``PRINT #1, ABS(`` finds the file, then stops with Missing
operand and leaves the file as it was (GIO86.ASM: the file is found first; GWEVAL.ASM EVAL
then meets the cut).  yaseer used to end the row of the file there.  The first case comes
from PC-BASIC's recorded test of ABS (a real GW-BASIC's OUTPUT.TXT has no empty rows);
each case is compared with PC-BASIC 2.0.8, which agrees with the source here."""

import pytest

from test_gw_files import contents, pcbasic_run, yaseer_run

CUTS = ['PRINT #1, ABS(', 'PRINT#1, ABS(', 'PRINT #1, "A"; ABS(', 'PRINT #1, "A", ABS(', 'PRINT #1, 1 + ',
        'PRINT #1, USING "##"; ABS(', 'PRINT #1, (', 'PRINT #1, "A";: PRINT #1, ABS(']


@pytest.mark.parametrize("cut", CUTS)
def test_a_cut_print_to_a_file_writes_what_pcbasic_writes(tmp_path, cut):
    source = ('10 OPEN "O.TXT" FOR OUTPUT AS 1: ON ERROR GOTO 100\n'
              f'20 {cut}\n30 PRINT #1, "B": CLOSE: END\n100 PRINT #1, ERR; ERL: RESUME NEXT\n')
    theirs, ours = tmp_path / "pc", tmp_path / "ya"
    theirs.mkdir()
    ours.mkdir()
    assert yaseer_run(source, ours) == pcbasic_run(source, theirs)
    assert contents(ours) == contents(theirs)


def test_the_screen_print_of_a_cut_item_prints_nothing(tmp_path):
    source = '10 ON ERROR GOTO 100\n20 PRINT ABS(\n30 PRINT "B": END\n100 PRINT ERR; ERL: RESUME NEXT\n'
    assert yaseer_run(source, tmp_path) == pcbasic_run(source, tmp_path)
