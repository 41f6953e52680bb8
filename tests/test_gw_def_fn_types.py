"""DEF FN and DEFINT/DEFSNG/DEFDBL/DEFSTR in the order they run (gw).

A function's own type is its name's type when its DEF runs (GWEVAL.ASM DEF makes the
function's variable; FNDOFN finds it by the name typed as the call runs, and checks the
body's value against it); its parameters and the names of its body take the types of the
DEF table when it is called.  A name DEFSTR makes a string is a string argument of the
string functions (LEN, ASC, MID$) too.  What the recorded real-machine test
unsorted/FNTYPE3 of PC-BASIC's suite shows (a function defined under DEFSTR called as
FNx$ after DEFINT, Undefined user function by its new type, Type mismatch once its
parameter's letter is an integer); PC-BASIC 2.0.8 agrees with the program below.
"""

from __future__ import annotations

import pytest

from test_differential_support import run_gw

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

PROGRAM = """\
10 ON ERROR GOTO 900
20 DEFSTR N, P
30 DEF FNN(P) = P + "!"
40 PRINT FNN("AB")
50 DEFINT N
60 PRINT FNN$("CD")
70 PRINT FNN("CD")
80 DEFINT P
90 PRINT FNN$(5)
100 PRINT FNN$("X")
110 DEFDBL D: DEF FND(X) = X / 3
120 DEFSNG D: PRINT FND#(1); FND(1)
130 DEFSTR P: P = "ABC": PRINT LEN(P); ASC(P); MID$(P, 2)
140 DEFDBL X: PRINT FND#(1)
150 END
900 PRINT "E"; ERR; ERL: RESUME NEXT
"""

EXPECTED = (
    "AB!\n"                       # FNN is FNN$ (N a string letter when DEF ran), P$ its parameter
    "CD!\n"                       # after DEFINT N it is still FNN$ ...
    "E 18  70 \n"                 # ... and FNN now means FNN%: Undefined user function
    "E 13  90 \n"                 # P% now: the body P + "!" is Type mismatch
    "E 13  100 \n"                # and a string argument for P% too
    " .3333333432674408 E 18  120 \n"  # FND#, a single X's quotient made double; FND! undefined
    " 3  65 BC\n"                 # LEN, ASC, MID$ of a DEFSTR name
    " .3333333333333333 \n"       # X# when called: the quotient of doubles
)


def test_def_fn_types_follow_the_def_statements_as_they_run():
    assert run_gw(PROGRAM) == EXPECTED


def test_string_functions_take_a_name_defstr_made_a_string():
    """Applied before the run (the DEFSTR first): LEN(T) of T$, not Type mismatch."""
    assert run_gw('10 DEFSTR T\n20 T = "ABCD": PRINT LEN(T); RIGHT$(T, 2)\n') == " 4 CD\n"


def test_pc_basic_agrees():
    from pathlib import Path
    import tempfile

    from test_gw_files import pcbasic_run

    with tempfile.TemporaryDirectory() as folder:
        assert pcbasic_run(PROGRAM, Path(folder)) == EXPECTED
