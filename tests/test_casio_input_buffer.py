"""The Casio's input buffer: the line last typed at the prompt (the command that started the
program, a direct statement) stays in RAM from address 512, in the machine's codes with a 0
after it, for PEEK to read; and a bad statement in an IF's branch is the SN error only when
that branch runs (part 6, "Errors").

Reference values: the character code table (part-12-1: space 32, ``"`` 34, ``1`` 49, ``A``
65, ``R`` 82, ``U`` 85, ``N`` 78) and the two-byte codes the library's conversion program
compares (PBLOAD 4,179; PBGET 4,180; ALL 7,187).  The programs are our own.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

import yaseer
from yaseer.basic.machine.console import typed_codes
from yaseer.run_arguments import ArgumentError
from yaseer.session import MachineEngine, Session

BUFFER = "10 FOR I=0 TO 11: PRINT PEEK(512+I);: NEXT\n"


def buffer_after(typed: str | None = None) -> list[int]:
    """The 12 bytes from address 512 a program reads when ``typed`` started it."""
    extra = {} if typed is None else {"typed": typed}
    result = yaseer.run(BUFFER, **extra)
    assert result.error is None
    return [int(word) for word in result.text.split()]


def test_the_command_that_started_the_program_is_in_the_buffer_in_the_machines_codes():
    assert buffer_after('PBLOAD ALL 1"AB"') == [4, 179, 32, 7, 187, 32, 49, 34, 65, 66, 34, 0]
    assert buffer_after("PBGET1")[:4] == [4, 180, 49, 0]


def test_a_plain_run_leaves_run_in_the_buffer_as_its_letters():
    assert buffer_after()[:4] == [82, 85, 78, 0]


def test_a_stored_word_inside_quotes_stays_letters():
    assert typed_codes('PBGET "ALL"', {"PBGET": (4, 180), "ALL": (7, 187)}) == [4, 180, 32, 34, 65, 76, 76, 34]


def test_poke_can_overwrite_the_buffer():
    result = yaseer.run("10 POKE 512,4: POKE 513,180: PRINT PEEK(512); PEEK(513); PEEK(514)\n", typed="RUN")
    assert result.text.split() == ["4", "180", "78"]


def test_a_program_reading_its_command_line(tmp_path):
    """A program that, like the library's PB program, stops with SN unless PBLOAD ran it."""
    program = ('10 M=512\n'
               '20 IF PEEK(M)<>4 OR PEEK(M+1)<>179 THEN a\n'
               '30 N=PEEK(M+2): IF N=32 THEN M=M+1: GOTO 30\n'
               '40 IF N=34 THEN PRINT "NAMED" ELSE PRINT "FIRST FILE"\n')
    assert yaseer.run(program).error == "Syntax error in 20"
    assert yaseer.run(program, typed="PBLOAD").text == "FIRST FILE\n"
    assert yaseer.run(program, typed='PBLOAD  "X"').text == "NAMED\n"
    listing = tmp_path / "reads.bas"
    listing.write_text(program)
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", "--typed", 'PBLOAD "X"', str(listing)],
                          capture_output=True, text=True)
    assert (done.returncode, done.stdout, done.stderr) == (0, "NAMED\n", "")


@pytest.mark.parametrize("x, y, shown, error", [
    (1, 1, "T U\n", None),
    (1, 0, "T\n", "Syntax error in 10"),  # the inner IF's ELSE
    (0, 1, "", "Syntax error in 10"),  # the outer IF's ELSE
])
def test_a_bad_else_branch_is_the_error_only_when_it_runs(x, y, shown, error):
    program = f'5 X={x}: Y={y}\n10 IF X=1 THEN PRINT "T";: IF Y=1 THEN PRINT " U" ELSE a ELSE a\n'
    result = yaseer.run(program)
    assert (result.text, result.error) == (shown, error)


def test_a_bad_then_branch_keeps_its_else_and_statements_before_the_if_run():
    program = '10 PRINT "A";: IF 1=2 THEN a ELSE PRINT "B"\n20 PRINT "C";: IF 1=1 THEN a\n'
    result = yaseer.run(program)
    assert (result.text, result.error) == ("AB\nC\n", "Syntax error in 20")


def test_a_bad_statement_outside_a_branch_still_stops_the_whole_line():
    result = yaseer.run('10 PRINT "A": a\n')
    assert (result.text, result.error) == ("", "Syntax error in 10")


def test_the_session_keeps_the_line_typed_last():
    shown = []
    session = Session(write=shown.append, engine=MachineEngine(shown.append))
    session.handle("PRINT PEEK(512);PEEK(513)")
    session.handle('10 PRINT PEEK(512);PEEK(513);PEEK(514);PEEK(515)')
    session.handle("RUN")
    assert "".join(shown).split() == ["80", "82", "82", "85", "78", "0"]


def test_gw_has_no_input_buffer():
    from yaseer.basic.machine.machine import Machine

    machine = Machine(dialect="gw")
    machine.type_line("PBLOAD")
    assert machine.memory == {}
    assert yaseer.run("10 PRINT 1\n", dialect="gw", typed="PBLOAD").text == " 1 \n"


def test_typed_is_one_line_of_text():
    with pytest.raises(ArgumentError, match="typed is one line"):
        yaseer.run(BUFFER, typed="RUN\nLIST")
    with pytest.raises(ArgumentError, match="typed is one line"):
        yaseer.run(BUFFER, typed=5)


def test_a_key_script_may_name_the_line_typed(tmp_path):
    """The library measurement's key scripts: ``NAME | keys | pattern [| typed: line]``,
    a pattern holding ``|`` itself."""
    from casio_library import DEFAULT_RESULT, key_scripts

    script = tmp_path / "keys.txt"
    script.write_text("A | 1\\n | x=|y= \nB |  |  | typed: PBLOAD 1\nC | 2\\n | Accept|Reject | typed: PBGET\n",
                      encoding="utf-8")
    assert key_scripts(script) == {"A": ("1\n", "x=|y=", "RUN"), "B": ("", DEFAULT_RESULT, "PBLOAD 1"),
                                   "C": ("2\n", "Accept|Reject", "PBGET")}
