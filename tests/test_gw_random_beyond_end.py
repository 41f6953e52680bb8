"""INPUT # from a random file after a GET that read beyond the file's end reads the record
buffer's zero bytes and stops at the record's end with FIELD overflow, as a real GW-BASIC
recorded it (PC-BASIC's FLDOVFL test: an empty file of records of one byte); EOF stays -1
after such a GET.  The published source's ``F_ORCT`` of 0 would make it Input past end.
Each case against PC-BASIC 2.0.8, which agrees with the recording."""

import pytest

from test_gw_files import both_runs

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")

BODIES = [
    'GET #1, 1: INPUT #1, D$: PRINT LEN(D$); EOF(1)',
    'GET #1, 1: LINE INPUT #1, D$: PRINT LEN(D$)',
    'GET #1, 1: D$ = INPUT$(2, #1): PRINT LEN(D$); ASC(D$); EOF(1)',
    'GET #1, 5: PRINT EOF(1): INPUT #1, A: PRINT A; EOF(1)',
]


@pytest.mark.parametrize("body", BODIES)
def test_reading_a_record_beyond_the_end(tmp_path, body):
    source = ('10 ON ERROR GOTO 100\n20 OPEN "R.DAT" FOR RANDOM AS #1 LEN=3: FIELD #1, 3 AS A$\n'
              f'30 {body}\n40 END\n100 PRINT "E"; ERR; ERL: RESUME NEXT\n')
    ours, theirs, _, _ = both_runs(source, tmp_path)
    assert ours == theirs
