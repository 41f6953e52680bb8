"""AUTO run by a program (GWMAIN.ASM AUTO): the program stops there and the command level
numbers the lines typed next, from the start (10) by the step (10; after a comma alone the
step AUTO used last; 0 is Illegal function call).  Run without the session (``yaseer
run``), the program ends there as at END: nothing is typed after it."""

from __future__ import annotations

import subprocess
import sys

from test_gw_direct_types import gw_session, typed


def test_auto_in_a_program_stops_it_and_numbers_the_lines_typed_next():
    session, shown = gw_session()
    assert typed(session, shown, '10 PRINT "a": AUTO 100, 5: PRINT "b"') == ""
    assert typed(session, shown, "RUN") == "a\n"
    assert session.prompt == "100 "
    typed(session, shown, "PRINT 1")
    assert session.prompt == "105 "
    typed(session, shown, "PRINT 2")
    typed(session, shown, "")  # Enter on a free number ends AUTO
    # LIST shows the line's blanks as typed (its tokens listed back, as PC-BASIC lists it)
    assert typed(session, shown, "LIST") == '10 PRINT "a": AUTO 100, 5: PRINT "b"\n100 PRINT 1\n105 PRINT 2\n'


def test_auto_in_a_program_takes_the_last_step_after_a_comma_and_refuses_zero():
    session, shown = gw_session()
    typed(session, shown, "AUTO 500, 7")
    typed(session, shown, "")
    typed(session, shown, "10 AUTO 20,")
    typed(session, shown, "RUN")
    assert session.prompt == "20 "
    typed(session, shown, "X=1")
    assert session.prompt == "27 "
    typed(session, shown, "")
    assert typed(session, shown, "10 AUTO 30, 0") == ""
    assert typed(session, shown, "RUN") == "Illegal function call in 10\n"
    assert session.prompt == "P0> "


def test_auto_ends_a_run_without_the_session(tmp_path):
    program = tmp_path / "auto.bas"
    program.write_text('10 PRINT "a": AUTO: PRINT "b"\n20 PRINT "c"\n')
    done = subprocess.run([sys.executable, "-m", "yaseer", "--dialect", "gw", "run", str(program)],
                          capture_output=True, text=True, timeout=120)
    assert (done.stdout, done.stderr, done.returncode) == ("a\n", "", 0)


def test_auto_after_a_comma_with_no_auto_before_is_illegal_function_call(tmp_path):
    # recorded gwbasic/various_syntax_errors: ``AUTO 10,`` in a program run first thing is
    # error 5: GWMAIN.ASM AUTO takes the step AUTINC after a comma alone, 0 until an AUTO sets it
    program = tmp_path / "auto.bas"
    program.write_text('10 ON ERROR GOTO 90\n20 AUTO 10,\n30 PRINT "c": END\n90 PRINT ERR; ERL: RESUME NEXT\n')
    done = subprocess.run([sys.executable, "-m", "yaseer", "--dialect", "gw", "run", str(program)],
                          capture_output=True, text=True, timeout=120)
    assert (done.stdout, done.returncode) == (" 5  20 \nc\n", 0)
