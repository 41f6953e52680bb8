"""A FOR's control variable in GW-BASIC is a simple variable.

GWMAIN.ASM FOR sets SUBFLG before PTRGET, so ``A(1)`` is read as ``A`` and the SYNCHR for
"=" meets the ``(``: a Syntax error when the statement is reached (the statements before it
on the line have run), before the variable's type is looked at (``FOR A$(1)`` is a Syntax
error too, ``FOR A$`` a Type mismatch).  The casio accepts an element because the paper's
Example 3 runs ``FOR T(2) = .1 TO 360.1 STEP 20``.  Generated programs against PC-BASIC
2.0.8, which agrees with the source here.
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import PcBasic, base_seed, case_count, run_yaseer

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def test_a_subscripted_for_variable_is_a_syntax_error_when_reached():
    program = '10 PRINT "a": FOR A(1) = 1 TO 3: PRINT A(1): NEXT\n'
    assert run_yaseer(program, dialect="gw") == "a\nSyntax error in 10\n"
    assert run_yaseer('10 FOR A$(1) = 1 TO 3\n', dialect="gw") == "Syntax error in 10\n"
    assert run_yaseer('10 FOR A$ = 1 TO 3\n', dialect="gw") == "Type mismatch in 10\n"
    # trapped as any Syntax error: RESUME NEXT goes on after the FOR
    trapped = '10 ON ERROR GOTO 100: FOR B(2) = 1 TO 3: PRINT "n"\n20 END\n100 PRINT ERR; ERL: RESUME NEXT\n'
    assert run_yaseer(trapped, dialect="gw") == " 2  10 \nn\n"


def test_next_of_an_element_is_no_loop_s_next_as_the_source_says():
    """The FOR runs the NEXT its scan found for the first test (GWMAIN.ASM NXTSCN, NEXT86.ASM
    NEXTS): PTRGET reads ``A(1)`` as the element, FNDFOR finds no loop of it.  (PC-BASIC 2.0.8
    runs the loop, then says Syntax error.)"""
    assert run_yaseer("10 FOR A = 1 TO 2: PRINT A: NEXT A(1)\n", dialect="gw") == "NEXT without FOR in 10\n"


def test_the_casio_runs_the_papers_form():
    assert run_yaseer("10 FOR T(2) = 1 TO 3: PRINT T(2);: NEXT T(2)\n", dialect="casio") == " 1  2  3 "


FOR_VARIABLES = ("A", "A(1)", "A (1)", "B%(2)", "C#(0,1)", "A$(1)", "I", "I%")


def test_generated_for_statements_against_pc_basic():
    rng = random.Random(base_seed() + 3061)
    pc = PcBasic()
    for _ in range(case_count(40)):
        var = rng.choice(FOR_VARIABLES)
        before = rng.choice(("", 'PRINT "x": ', "A=5: "))
        program = (f"10 {before}FOR {var} = 1 TO {rng.randint(0, 3)}: PRINT {var.replace(' ', '')};: NEXT\n"
                   f'20 PRINT "end"\n')
        assert run_yaseer(program, dialect="gw") == pc.program(program), program
    pc.close()
