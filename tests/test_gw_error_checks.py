"""GW-BASIC's error codes and the order of its checks, as a real GW-BASIC 3.23 recorded them in
PC-BASIC's test suite (github robhagemans/pcbasic, tests/basic: each test's ``model/`` files).
Our own small programs, each naming the recording and the source routine it follows."""

from __future__ import annotations

from test_differential_support import run_gw

TRAP = "\n900 PRINT ERR; ERL: RESUME NEXT"


def test_rnd_of_a_double_beyond_single_range_is_overflow():
    # recorded unsorted/RND1: RND of the largest MBF double is error 6; MATH2.ASM $RND works on
    # a single, so the argument is made one first (FRCSNG), which overflows.
    out = run_gw("10 ON ERROR GOTO 900\n20 PRINT RND(1.701411834604692D+38)\n30 X# = 1.70141183D+38: PRINT RND(X#)"
                 "\n40 PRINT RND(1D+38) > 0\n50 END" + TRAP)
    assert out == " 6  20 \n 6  30 \n-1 \n"
