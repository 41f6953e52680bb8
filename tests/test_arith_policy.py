"""Division by zero and overflow: casio stops, gw prints GW-BASIC's message and goes on
with the signed largest value unless ON ERROR traps it (yaseer/basic/arithmetic/arith_policy.py).

The gw expectations are PC-BASIC 2.0.8's output for the same programs;
tests/test_differential_gw_runtime.py compares generated ones live.
"""

from __future__ import annotations

import math

from test_basic_helpers import error_of, run_text
from yaseer.basic.arithmetic.arith_policy import LARGEST

# PC-BASIC 2.0.8, line by line (a message where the cursor is, then a line end):
PROGRAM = """10 PRINT "A";1/0;"B"
20 X = -1/0: PRINT X
30 PRINT 5 \\ 0
40 PRINT 5 MOD 0
50 PRINT 0^-1
60 PRINT EXP(1000)
70 Y = 1E38*10: PRINT Y
80 PRINT -1E38*10
100 PRINT 1#/0
110 PRINT -5\\0
120 PRINT 0/0
125 PRINT 1E38+1E38
130 A% = 40000
"""
PCBASIC = """ADivision by zero
 1.701412E+38 B
Division by zero
-1.701412E+38 
Division by zero
 1.701412E+38 
Division by zero
 1.701412E+38 
Division by zero
 1.701412E+38 
Overflow
 1.701412E+38 
Overflow
 1.701412E+38 
Overflow
-1.701412E+38 
Division by zero
 1.701411834604692D+38 
Division by zero
-1.701412E+38 
Division by zero
 1.701412E+38 
Overflow
 1.701412E+38 
"""


def test_gw_goes_on_with_the_largest_value():
    assert error_of(PROGRAM, dialect="gw") == "Overflow in 130"  # an integer overflow still stops
    assert run_text(PROGRAM.replace("130 A% = 40000\n", ""), dialect="gw") == PCBASIC


def test_gw_on_error_traps_them():
    program = '10 ON ERROR GOTO 100\n20 PRINT "A";1/0;"B"\n30 X = 2^200: PRINT X\n40 END\n100 PRINT "ERR";ERR;ERL: RESUME NEXT\n'
    assert run_text(program, dialect="gw") == "AERR 11  20 \nERR 6  30 \n 0 \n"  # PC-BASIC's output


def test_casio_stops():
    assert error_of("10 PRINT 1/0") == "Division by zero in 10"
    assert error_of("10 X = 1E300*1E300") == "Overflow in 10"


def test_largest_values_are_mbf_maxima():
    # MBF: exponent byte 255 (2**127 scale) with a 24- or 56-bit mantissa of ones
    assert LARGEST["!"] == math.ldexp(2 ** 24 - 1, 127 - 24)
    assert math.isclose(LARGEST["#"], math.ldexp(2 ** 56 - 1, 127 - 56), rel_tol=2 ** -53)
