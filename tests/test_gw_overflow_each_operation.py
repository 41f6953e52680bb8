"""gw: an operation that leaves MBF's range prints ``Overflow`` where it happens and the
next operation works on the signed largest value (or ON ERROR traps it there).

GW-BASIC's source, MATH1.ASM/MATH2.ASM: ``$FADDS``, ``$FMULS`` (``$SEXPS``), ``$FDIVS``
and ``$ROUNS`` jump to ``$OVFLS`` themselves, which puts the signed largest single in
the FAC (``DOINF``), traps through ``TRAPER`` when ON ERROR is set, else prints the
message (``DV010``) and returns to the expression.  ``$FPWR`` sets the once-only
overflow mode (``$FLGOV`` = 1: the first message of a power is printed, later ones not)
and, for a negative exponent, inverts the power unless it underflowed to 0 (then
Overflow).  The generated programs are compared with PC-BASIC 2.0.8, which agrees with
the source on ``+ - * /`` and ``^2``; where PC-BASIC's own power routine differs (its
recursion, its sign of an overflowed odd power) the source's steps are asserted.
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import run_gw
from test_differential_gw_runtime import assert_generated_match

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def program(*lines: str) -> str:
    return "".join(f"{10 * (k + 1)} {text}\n" for k, text in enumerate(lines))


# ---------------------------------------------------------------- cases from the source

@pytest.mark.parametrize("lines, shown", [
    # the product overflows: Overflow, then 1.701412E+38 / 100
    (["PRINT 1E38*10/100"], "Overflow\n 1.701412E+36 \n"),
    (["PRINT -1E38*10/100"], "Overflow\n-1.701412E+36 \n"),
    # each product overflows on its own; their difference is 0
    (["PRINT 1E38*10-1E38*10"], "Overflow\nOverflow\n 0 \n"),
    (["A = 1E38: B = A*10 - A*10: PRINT B"], "Overflow\nOverflow\n 0 \n"),
    (["A = 1E38: PRINT A*A/A"], "Overflow\n 1.701412 \n"),
    (["A = 1E38: A = A + A + A: PRINT A"], "Overflow\nOverflow\n 1.701412E+38 \n"),
    # a sum of two overflows of opposite signs
    (["PRINT 1E38*10 + (-1E38)*10"], "Overflow\nOverflow\n 0 \n"),
    # doubles: $FMULD, $FADDD go to $OVFLS the same way
    (["PRINT 1D38*10#/100"], "Overflow\n 1.701411834604692D+36 \n"),
    (["PRINT 1D38*2-1D38*2"], "Overflow\nOverflow\n 0 \n"),
    # a double made single ($CSD) beyond the single range
    (["PRINT CSNG(1.7014118D38)/10"], "Overflow\n 1.701412E+37 \n"),
    # division by zero goes on with the signed largest ($DIV0S)
    (["PRINT 1/0/10"], "Division by zero\n 1.701412E+37 \n"),
    (["PRINT -1/0*0"], "Division by zero\n 0 \n"),
    # an integer sum beyond 16 bits is a single (IADD), not an error ...
    (["PRINT 32767+1"], " 32768 \n"),
    # ... storing it in an integer is the Overflow error, which stops (CINT: $OVERR)
    (["A% = 32767: B% = A% + 1: PRINT B%"], "Overflow in 10\n"),
    (["PRINT 1E38*10 + CINT(40000)"], "Overflow\nOverflow in 10\n"),
    # $FPWR: one message for a whole power, each product goes on with the largest
    (["PRINT (-1E38)^3"], "Overflow\n-1.701412E+38 \n"),
    (["A = 2: PRINT A^200"], "Overflow\n 1.701412E+38 \n"),
    # a negative power whose positive power overflowed: 1 / the largest (its digits by
    # $FOFMT's steps: tests/single_digits_support.py; PC-BASIC's tens give 5.877473E-39)
    (["PRINT (1E20)^-2"], "Overflow\n 5.877472E-39 \n"),
    # ... and one that underflowed to 0: Overflow, signed for an odd power of a negative
    (["PRINT (-1E-30)^-3"], "Overflow\n-1.701412E+38 \n"),
    (["PRINT (1E-20)^-2"], "Overflow\n 1.701412E+38 \n"),
])
def test_each_operation_handles_its_own_overflow(lines, shown):
    assert run_gw(program(*lines)) == shown


def test_on_error_traps_the_first_operation_that_overflows():
    """With ON ERROR set, $OVFLS traps at once (TRAPER): the rest of the statement does not
    run and the variable keeps its value; RESUME NEXT goes on with the next statement
    (PC-BASIC 2.0.8 prints the same)."""
    source = program("ON ERROR GOTO 100", "A = 5", 'PRINT "X"; : A = 1E38*10/100 : PRINT "Y"', "PRINT A",
                     "END") + "100 PRINT \"E\"; ERR; ERL: RESUME NEXT\n"
    assert run_gw(source) == "XE 6  30 \nY\n 5 \n"


def test_the_power_prints_once_and_traps_once_under_on_error():
    source = program("ON ERROR GOTO 100", "PRINT (-1E38)^3", "END") + "100 PRINT ERR; ERL: RESUME NEXT\n"
    assert run_gw(source) == " 6  20 \n"


# ---------------------------------------------------------------- generated, against PC-BASIC

ATOMS = ["1E38", "-1E38", "1.5E38", "3E37", "A", "B", "C", "2", "10", ".5", "4", "0", "I%", "-2", "1E-30", "E"]


def expression(rng: random.Random, depth: int = 0) -> str:
    """A single-precision expression whose steps may leave the range, in either direction;
    divisors are powers of two or 0 (every quotient exact or an overflow: PC-BASIC's
    inexact quotients are not the source's, see single_arith.divide)."""
    if depth >= 3 or rng.random() < 0.3:
        return rng.choice(ATOMS)
    op = rng.choice(["+", "-", "*", "*", "/", "^"])
    if op == "^":
        return f"({expression(rng, depth + 1)}) ^ 2"
    if op == "/":
        return f"({expression(rng, depth + 1)}) / {rng.choice(['2', '4', '.5', '0', '8', '-2', 'E'])}"
    return f"({expression(rng, depth + 1)} {op} {expression(rng, depth + 1)})"


def overflow_program(rng: random.Random) -> str:
    lines = ["D# = 1D38: A = 1E38: B = -2E37: C = 1.7E38: I% = 32767: E = 1E-30"]
    if rng.random() < 0.3:
        lines.append("ON ERROR GOTO 1000")
    for _ in range(rng.randint(1, 3)):
        form = rng.random()
        if form < 0.5:
            lines.append(f"PRINT {expression(rng)}")
        elif form < 0.8:
            lines.append(f"X = {expression(rng)}: PRINT X")
        else:
            factor = rng.choice(["2", "1", "-1.5", ".5"])
            lines.append(f"PRINT {expression(rng)}; CSNG(D# * {factor} + {expression(rng)})")
    lines.append("END")
    return program(*lines) + '1000 PRINT "E"; ERR; ERL: RESUME NEXT\n'


def test_generated_overflows_as_pcbasic(pc):
    assert_generated_match(pc, overflow_program, 24, 300)
