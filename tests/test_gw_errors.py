"""GW-BASIC's error statements against PC-BASIC 2.0.8: ERROR n for every code, and the
parse errors (Syntax error or Missing operand) of statements typed in direct mode, in the gw dialect."""

from __future__ import annotations

import pytest

from test_differential_support import run_direct as direct

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def test_error_statement_raises_every_code_with_gw_basics_message(pc):
    codes = list(range(-1, 258)) + [1.4, 1.6, 254.5, 255.4]
    ours = [direct(f"ERROR {n}") for n in codes]
    theirs = [pc.statement(f"ERROR {n}") for n in codes]
    assert ours == theirs


@pytest.mark.parametrize("text", [
    "PRINT 1+", "X=", "PRINT ABS(", "PRINT (1", "X=1+*2", "PRINT SIN()", "X=(", "FOR I=1 TO",
    "GOTO", 'PRINT MID$("A",', "X=-", "PRINT 1: X=", "IF 1 THEN X=", "IF 0 THEN PRINT ELSE X=",
])
def test_a_statement_that_ends_too_early_is_missing_operand(pc, text):
    ours = direct(text).splitlines()[-1]
    theirs = pc.statement(text).strip().splitlines()[-1]
    assert ours == theirs
