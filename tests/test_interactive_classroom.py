"""The session's classroom commands typed on a real pseudo-terminal (pexpect), as a user types them.

AUTO, LIST of crunched lines, TRON/TROFF (gw's [n]; casio's P0-n, halting at each line), CLS, LLIST, a syntax error put up
for editing, CONT after Ctrl-C.  The GW-BASIC behaviour each one copies is
stated where it is asserted (PC-BASIC 2.0.8 gave the traces; its AUTO prompt
is the number followed by ``*`` for a line that exists, a space otherwise).
"""

from __future__ import annotations

import re

import pexpect
import pytest

from test_interactive import PROMPT, Terminal, plain

# AUTO's prompt: the offered line number and "*" (the line exists) or " " (drawn as a cursor move).
AUTO_PROMPT = re.compile(r"\x1b\[\?2004h(?:\x1b\[[0-9;?]*[A-Za-z])*(\d+)(\*?)(?=\x1b)")


@pytest.fixture
def terminal(tmp_path):
    term = Terminal(tmp_path)
    yield term
    if term.child.isalive():
        term.child.terminate(force=True)


def auto_prompt(terminal, keys: str) -> tuple[int, str]:
    """Send ``keys``; the AUTO number offered next and its mark."""
    terminal.child.send(keys)
    terminal.child.expect(AUTO_PROMPT)
    return int(terminal.child.match.group(1)), terminal.child.match.group(2) or " "


def test_auto_offers_numbers_marks_existing_lines_and_ends(terminal):
    terminal.type("20 PRINT 20")
    assert auto_prompt(terminal, "AUTO 10,10\r") == (10, " ")
    assert auto_prompt(terminal, "PRINT 10\r") == (20, "*")  # line 20 exists: GW marks it *
    assert auto_prompt(terminal, "\r") == (30, " ")  # Enter after * keeps line 20
    assert auto_prompt(terminal, "PRINT 30\r") == (40, " ")
    terminal.keys("\r")  # Enter on a free number ends AUTO: the P0> prompt is back
    assert terminal.type("LIST") == "10 PRINT 10\n20 PRINT 20\n30 PRINT 30\n"
    assert auto_prompt(terminal, "AUTO 100,5\r") == (100, " ")
    assert auto_prompt(terminal, "X=1\r") == (105, " ")
    terminal.child.send("Y=2")
    terminal.keys("\x03")  # Ctrl-C ends AUTO; the line being typed is not stored (GW-BASIC)
    assert terminal.type("LIST 100-") == "100 X=1\n"
    assert auto_prompt(terminal, "AUTO\r") == (10, "*")  # AUTO alone: from 10 by 10
    terminal.keys("\x03")
    terminal.close()


def test_list_shows_crunched_lines_as_the_pocket_computer_lists_them(terminal):
    terminal.type("10 L=X/COST")
    terminal.type("20 forj=1to3:printj;:nextj")
    terminal.type('30 ifx<0then100else print"cost";x')
    assert terminal.type("LIST") == (
        "10 L=X/COS T\n"
        "20 FOR j=1 TO 3:PRINT j;:NEXT j\n"  # (names keep the case they were typed in)
        '30 IF x<0 THEN 100 ELSE PRINT "cost";x\n'
    )
    assert terminal.type("RUN 20") == " 1  2  3 cost 0 \n"
    terminal.close()


def test_tron_traces_lines_as_gw_basic_in_programs_and_direct_mode(tmp_path):
    terminal = Terminal(tmp_path, args=("--dialect", "gw"))  # GW-BASIC's [n] (casio's form: below)
    for line in ("10 FOR I=1 TO 2", "20 PRINT I", "30 NEXT I", "40 GOSUB 60: PRINT \"B\"", "50 END",
                 "60 PRINT \"S\": RETURN"):
        terminal.type(line)
    terminal.type("TRON")
    # PC-BASIC 2.0.8 prints exactly this for the same program after TRON
    assert terminal.type("RUN") == "[10][20] 1 \n[30][20] 2 \n[30][40][60]S\nB\n[50]\n"
    assert terminal.type("GOTO 60") == "[60]S\nRETURN without GOSUB in 60\n"
    terminal.type("TROFF")
    assert terminal.type("RUN") == " 1 \n 2 \nS\nB\n"
    terminal.type("5 TRON")  # as a statement: the lines after it are traced
    terminal.type("45 TROFF")
    assert terminal.type("RUN") == "[10][20] 1 \n[30][20] 2 \n[30][40][60]S\nB\n[45]\n"
    terminal.close()


def test_casio_tron_shows_area_and_line_and_waits_for_exe_at_each(terminal):
    # TRON.md: "P0-10" (program area, line) and execution suspended until EXE (Enter) is pressed
    for line in ("10 PRINT 1", "20 PRINT 2"):
        terminal.type(line)
    terminal.type("TRON")
    terminal.child.send("RUN\r")
    terminal.child.expect_exact("P0-10")
    with pytest.raises(pexpect.TIMEOUT):  # halted: line 10 has not run
        terminal.child.expect_exact(" 1 ", timeout=1)
    terminal.child.send("\r")
    terminal.child.expect_exact(" 1 ")
    terminal.child.expect_exact("P0-20")
    with pytest.raises(pexpect.TIMEOUT):
        terminal.child.expect_exact(" 2 ", timeout=1)
    assert plain(terminal.keys("\r")).split() == ["2"]
    terminal.type("TROFF")
    assert terminal.type("RUN") == " 1 \n 2 \n"
    terminal.close()


def test_cls_clears_the_terminal(terminal):
    terminal.type("PRINT 1")
    terminal.child.send("CLS\r")
    terminal.child.expect_exact("\x1b[H\x1b[2J")
    terminal.wait()
    assert terminal.type('10 CLS: PRINT "TOP"') == ""
    terminal.child.send("RUN\r")
    terminal.child.expect_exact("\x1b[H\x1b[2J")
    assert "\u2502TOP " in plain(terminal.wait())  # a program that drew ends showing the LCD
    terminal.close()


def test_llist_and_lprint_go_to_the_printer_file(tmp_path):
    terminal = Terminal(tmp_path, args=("--printer", "printer.txt"))
    try:
        terminal.type("10 lprint\"paper\";2*3")
        assert terminal.type("LLIST") == ""
        assert terminal.type("RUN") == ""
        assert (tmp_path / "printer.txt").read_text() == '10 LPRINT "paper";2*3\npaper 6 \n'
        assert terminal.type("LIST") == '10 LPRINT "paper";2*3\n'
        terminal.close()
    finally:
        if terminal.child.isalive():
            terminal.child.terminate(force=True)


def test_a_syntax_error_in_run_puts_the_line_up_for_editing(terminal):
    terminal.type("10 PRINT 1")
    terminal.type("20 PRINT (")
    terminal.type("30 PRINT 3")
    assert terminal.type("RUN") == " 1 \nSyntax error in 20\n"
    # GW-BASIC shows line 20 for editing: it is under the cursor; finish it and Enter
    terminal.child.expect_exact("20 PRINT (")
    terminal.keys("\x05" + "2)\r")
    assert terminal.type("LIST 20") == "20 PRINT (2)\n"
    assert terminal.type("RUN") == " 1 \n 2 \n 3 \n"
    terminal.close()


def test_a_partly_printed_line_is_ended_before_the_prompt(terminal):
    assert terminal.type("PRINT 1;") == " 1 \n"
    terminal.close()


def test_classroom_commands_from_a_pipe(tmp_path):
    from test_interactive import session_from_pipe

    result = session_from_pipe("AUTO 10,5\nprint 1\nprint 2\n\nCLS\nLIST\nTRON\nRUN\n", tmp_path)
    assert result.returncode == 0
    assert "\x1b" not in result.stdout  # CLS clears nothing on a pipe
    assert "P0> 10 15 20 P0> P0> 10 PRINT 1\n15 PRINT 2\nP0> P0> P0-10\n 1 \nP0-15\n 2 \n" in result.stdout


def test_cont_after_ctrl_c_goes_on_exactly_where_the_run_was_broken(terminal):
    """GW-BASIC resumes after Ctrl-C; the result is the unbroken run's (closed forms below)."""
    terminal.type('10 PRINT "GO": FOR I=1 TO 1000000: S=S+I-INT(I/7)*7: NEXT I')  # (casio's MOD: 16 bits)
    terminal.type('15 PRINT "HALF"')
    terminal.type("20 N=N+1: IF N<300000 THEN 20")
    terminal.type("30 PRINT S;I;N")
    terminal.child.send("RUN\r")
    terminal.child.expect("GO")
    terminal.child.sendintr()  # inside the FOR loop of line 10 (compiled as a native loop)
    assert plain(terminal.wait()).endswith("Break in 10\n")
    assert 1 <= float(terminal.type("PRINT I")) < 1000000
    terminal.child.send("CONT\r")
    terminal.child.expect("HALF")
    terminal.child.sendintr()  # inside line 20, a block that jumps back to itself
    assert plain(terminal.wait()).endswith("Break in 20\n")
    assert 0 <= float(terminal.type("PRINT N")) < 300000
    total = sum(i % 7 for i in range(1, 1000001))
    assert terminal.type("CONT") == f" {total}  1000001  300000 \n"
    assert terminal.type("CONT") == "Can't continue\n"  # the run has ended
    terminal.close()



def test_width_32_folds_what_the_screen_shows_as_the_fx850p_display(tmp_path):
    terminal = Terminal(tmp_path, args=("--width", "32"))
    try:
        letters = "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
        assert terminal.type(f'PRINT "{letters}"') == letters[:32] + "\n" + letters[32:] + "\n"
        terminal.type("10 FOR I=1 TO 12: PRINT I;: NEXT I: PRINT")
        row = "".join(f" {i} " for i in range(1, 13))  # printed by twelve PRINTs, folded as one row
        assert terminal.type("RUN") == row[:32] + "\n" + row[32:] + "\n"
        terminal.type('20 PRINT "A LINE THAT IS LONGER THAN THE SCREEN"')
        listed = '20 PRINT "A LINE THAT IS LONGER THAN THE SCREEN"'
        assert terminal.type("LIST 20") == listed[:32] + "\n" + listed[32:] + "\n"
        assert terminal.type("PRINT 2") == " 2 \n"  # a typed line starts a new row
        terminal.close()
    finally:
        if terminal.child.isalive():
            terminal.child.terminate(force=True)


def test_width_is_checked(tmp_path):
    import os
    import subprocess
    import sys

    from test_interactive import REPO

    result = subprocess.run([sys.executable, "-m", "yaseer", "--width", "3"], input="", capture_output=True,
                            text=True, cwd=tmp_path, env=dict(os.environ, PYTHONPATH=str(REPO)), timeout=60)
    assert result.returncode == 2
    assert "from 16 to 255" in result.stderr and "Traceback" not in result.stderr


def test_ctrl_c_while_input_waits_then_cont_asks_again(terminal):
    """GW-BASIC: Ctrl-C at an INPUT question is a break; CONT asks the question again."""
    for line in ("10 FOR K=1 TO 2", '20 INPUT "VALUE"; A', "30 S=S+A", "40 NEXT K", "50 PRINT S"):
        terminal.type(line)
    terminal.child.send("RUN\r")
    terminal.child.expect_exact("VALUE? ")
    terminal.child.send("5\r")
    terminal.child.expect_exact("VALUE? ")
    terminal.child.sendintr()
    assert plain(terminal.wait()).endswith("Break in 20\n")
    assert terminal.type("PRINT K; S") == " 2  5 \n"
    terminal.child.send("CONT\r")
    terminal.child.expect_exact("VALUE? ")
    terminal.child.send("7\r")
    assert plain(terminal.wait()).endswith(" 12 \n")
    terminal.close()
