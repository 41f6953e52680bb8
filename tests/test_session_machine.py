"""The session on the real BASIC machine, by calling it (fast; the terminal is tested elsewhere)."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings, strategies as st

from yaseer.session import MachineEngine, Session

REPO_PROGRAMS = __import__("pathlib").Path(__file__).resolve().parents[1] / "programs"


@pytest.fixture
def session(tmp_path):
    shown = []
    s = Session(write=shown.append, engine=MachineEngine(shown.append), directory=tmp_path)
    s.shown = shown
    return s


def after(session, *lines) -> str:
    """What the session shows after typing ``lines``."""
    session.shown.clear()
    for line in lines:
        session.handle(line)
    return "".join(session.shown)


def test_run_stop_direct_and_cont_share_the_variables(session):
    after(session, "10 A = 1", "20 STOP", "30 PRINT A * 10")
    assert after(session, "RUN") == "Break in 20\n"
    assert after(session, "A = 4", "CONT") == " 40 \n"
    assert after(session, "CONT") == "Can't continue\n"


def test_editing_after_stop_forbids_cont(session):
    after(session, "10 STOP", "20 PRINT 2")
    after(session, "RUN")
    assert after(session, "20 PRINT 3", "CONT") == "Can't continue\n"


def test_direct_goto_runs_the_program_as_typed_now(session):
    after(session, "10 PRINT 1", "RUN")
    assert after(session, "20 PRINT 2", "GOTO 20") == " 2 \n"


def test_gosub_prog_5_in_direct_mode_is_the_library_virtual_link(session):
    shown = after(session, "X(10) = -1: Y(10) = -1: GOSUB PROG 5: PRINT T; L")
    angle, length = map(float, shown.split())
    assert angle == pytest.approx(225.0) and length == pytest.approx(math.sqrt(2))


def test_a_typed_program_area_replaces_the_library_until_new(session):
    after(session, "PROG 5", "10 L = 99: RETURN", "PROG 0")
    assert after(session, "GOSUB PROG 5: PRINT L") == " 99 \n"
    after(session, "PROG 5", "NEW", "PROG 0")
    assert after(session, "X(10) = 3: Y(10) = 4: GOSUB PROG 5: PRINT L") == " 5 \n"


def test_the_printed_program_5_loaded_into_its_area(session):
    # LOAD reads inside the session's directory only: an absolute name is refused
    assert after(session, f'LOAD "{REPO_PROGRAMS / "prog5.bas"}"') == "Path/File access error\n"
    session.directory = REPO_PROGRAMS
    after(session, "PROG 5", 'LOAD "prog5"', "PROG 0")
    # the printed subroutine divides by COS T: at T = 90 degrees it breaks, as the paper's listings avoid
    assert after(session, "X(10) = 0: Y(10) = 1: GOSUB PROG 5") == "Division by zero in 10 (PROG 5)\n"
    shown = after(session, "X(10) = 3: Y(10) = 4: GOSUB PROG 5: PRINT L")
    assert float(shown) == pytest.approx(5.0)


def test_library_errors_name_the_program_and_line(session):
    after(session, "10 L(2) = 1: L(3) = 9: L(1) = 20: GOSUB PROG 1")
    assert "cannot be assembled (PROG 1) in 10" in after(session, "RUN")


def test_a_slip_inside_the_engine_is_shown_not_raised(tmp_path):
    class BrokenEngine:
        def direct(self, statement, programs):
            raise RuntimeError("boom")

    shown = []
    Session(write=shown.append, engine=BrokenEngine(), directory=tmp_path).handle("PRINT 1")
    assert shown == ["Internal error (RuntimeError: boom)\n"]


# No THEN and no GOTO: "10 IF 1 THEN 10" then RUN would loop for ever.
WORDS = ["PRINT", "X", "L(2)", "(", ")", "1", "/", "0", "GOSUB", "PROG", "5", "2", ":", "=", '"', "T",
         ",", ";", "SQR", "-", "LIST", "RENUM", "DELETE", "EDIT", "10", "20", "RUN", "CONT", "STOP", "NEW",
         "RETURN", "END", "IF", "ELSE", "DIM", "A$", "LOAD", "SAVE", " "]


@settings(max_examples=120, deadline=None)
@given(st.lists(st.lists(st.sampled_from(WORDS), max_size=8).map(" ".join), max_size=6))
def test_whatever_is_typed_the_session_answers_with_basic_messages(tmp_path_factory, typed):
    shown = []
    directory = tmp_path_factory.mktemp("typed")
    session = Session(write=shown.append, engine=MachineEngine(shown.append), directory=directory)
    for line in typed:
        session.handle(line)  # never raises
    assert not any("Internal error" in text or "Traceback" in text for text in shown)


def test_run_file_loads_it_into_prog_0_and_runs_it(session, tmp_path):
    (tmp_path / "two.bas").write_text("10 PRINT 1 + 1\n")
    after(session, "PROG 3")
    assert after(session, 'RUN "two"') == " 2 \n"
    assert after(session, "PROG 0", "LIST") == "10 PRINT 1+1\n"


def test_tron_stays_on_across_run_and_new_turns_it_off(session):
    after(session, "10 PRINT 1", "TRON")
    # the Casio's mark (TRON.md); no key is awaited: the session's keys are not a terminal here
    assert after(session, "RUN") == "P0-10\n 1 \n"
    assert after(session, "RUN") == "P0-10\n 1 \n"  # RUN makes a fresh machine; the trace stays (TRON.md item 3)
    after(session, "NEW", "10 PRINT 2")
    assert after(session, "RUN") == " 2 \n"  # NEW turns it off (GW-BASIC, PC-BASIC's new_)


def test_llist_without_a_printer_lists_on_the_screen(session):
    after(session, "10 x=1:?x")
    assert after(session, "LLIST") == "10 x=1:PRINT x\n"  # (casio names keep their case)


def test_auto_step_defaults_and_the_last_step(session):
    after(session, "AUTO 100,5", "A=1", "", "AUTO 200,", "B=2", "")
    assert after(session, "LIST") == "100 A=1\n200 B=2\n"
    assert session.prompt == "P0> "
    after(session, "AUTO 200,")
    assert session.prompt == "200*"
    after(session, "")  # Enter on a line that exists keeps it and offers the next
    assert session.prompt == "205 "
    assert after(session, "AUTO X") == ""  # in AUTO what is typed is line 205's text
    assert after(session, "") == "" and session.prompt == "P0> "  # Enter on free 210 ends AUTO
    assert after(session, "LIST 205") == "205 AU TO X\n"  # keyword-first: TO inside AUTO
    assert after(session, "AUTO X") == "Syntax error\n"


def test_auto_offers_the_numbers_and_marks_pcbasic_offers(session):
    """The same keys typed into PC-BASIC 2.0.8's interactive loop: the offered numbers and marks
    (``20*`` for a line that exists; Enter after it keeps the line) and the program they leave."""
    import io
    import re

    import pcbasic

    typed = ["20 PRINT 20", "AUTO 10,10", "PRINT 10", "", "PRINT 30"]
    keys = "".join(line + "\r" for line in typed) + "\x03LIST\rSYSTEM\r"
    screen = io.BytesIO()
    with pcbasic.Session(input_streams=io.BytesIO(keys.encode()), output_streams=screen) as pc:
        with pytest.raises(BaseException):  # SYSTEM leaves its loop by an exception
            pc.interact()
    rows = screen.getvalue().decode("latin-1").replace("\r\n", "\n").split("\n")
    start = rows.index("AUTO 10,10") + 1
    end = rows.index("LIST")
    theirs_offered = [re.match(r"(\d+)([ *])", row).groups() for row in rows[start:end] if row[:1].isdigit()]
    theirs_listing = rows[end + 1:rows.index("SYSTEM") - 1]

    offered = []
    for line in typed:
        if session.auto is not None:
            offered.append((session.prompt[:-1], session.prompt[-1]))
        after(session, line)
    offered.append((session.prompt[:-1], session.prompt[-1]))
    session.interrupt()  # Ctrl-C
    assert offered == theirs_offered == [("10", " "), ("20", "*"), ("30", " "), ("40", " ")]
    assert after(session, "LIST").splitlines() == theirs_listing


def test_list_reads_a_line_as_the_dialect_reads_it(tmp_path):
    shown = []
    gw = Session(write=shown.append, engine=MachineEngine(shown.append, dialect="gw"), directory=tmp_path,
                 dialect="gw")
    casio = Session(write=shown.append, engine=MachineEngine(shown.append), directory=tmp_path)
    for session in (gw, casio):
        session.handle("10 cost=1:print cost")
    shown.clear()
    gw.handle("LIST")
    casio.handle("LIST")
    # GW-BASIC reads a run of letters as one word (COST is a name); the Casio finds keywords
    # first, and its names keep the case they were typed in
    assert shown == ["10 COST=1:PRINT COST\n", "10 COS t=1:PRINT COS t\n"]


@pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use
def test_gw_overflow_of_a_literal_is_shown_when_the_line_is_typed_as_pcbasic(tmp_path):
    """GW-BASIC reads a literal when the line is entered: ``Overflow`` then, once (not at
    each RUN), and the literal is the largest number; a direct statement shows it first."""
    from test_differential_support import PcBasic

    typed = ["10 A = 1E+39: PRINT A; -1D+39", '20 PRINT "1E+39"; 1E+38: REM 1E+39', "PRINT 2E+39 * 0; 3",
             "RUN", "RUN", "20 PRINT 4E+39", "RUN"]
    pc = PcBasic()
    shown = []
    gw = Session(write=shown.append, engine=MachineEngine(shown.append, dialect="gw"), directory=tmp_path,
                 dialect="gw")
    theirs, ours = [], []
    for line in typed:
        theirs.append(pc.statement(line))
        gw.handle(line)
        ours.append("".join(shown))
        shown.clear()
    pc.close()
    assert theirs[0] == "Overflow\nOverflow\n" and theirs[3] == theirs[4]
    assert ours == theirs


def test_gw_load_and_run_of_a_file_show_the_overflow_of_its_literals_once(tmp_path):
    (tmp_path / "big.bas").write_text("10 PRINT 1E+39; 1D+39\n20 PRINT 5\n")
    shown = []
    gw = Session(write=shown.append, engine=MachineEngine(shown.append, dialect="gw"), directory=tmp_path,
                 dialect="gw")
    gw.shown = shown
    assert after(gw, 'LOAD "big"') == "Overflow\nOverflow\n"
    assert after(gw, "RUN") == " 1.701412E+38  1.701411834604692D+38 \n 5 \n"
    assert after(gw, 'RUN "big"') == "Overflow\nOverflow\n 1.701412E+38  1.701411834604692D+38 \n 5 \n"


def test_list_all_and_new_all_cover_every_program_area(session):
    # LIST.md item 13: all programs from P0 through P9 in turn; NEW.md item 6: NEW ALL clears
    # every area's program and all variables (NEW alone: the current area's)
    after(session, "10 PRINT 1", "PROG 4", "10 PRINT 4", "PROG 0", "A=7")
    assert after(session, "LIST ALL") == "P0\n10 PRINT 1\nP4\n10 PRINT 4\n"
    after(session, "NEW ALL")
    assert after(session, "LIST ALL") == ""
    assert after(session, "PRINT A") == " 0 \n"


def test_list_and_edit_period_show_the_line_most_recently_handled(session):
    # LIST.md item 4, EDIT.md item 2: "." is the line most recently written, edited or
    # executed; after an error, the line in which the error was generated
    after(session, "10 PRINT 1", "20 X = 1/0", "30 PRINT 3")
    assert after(session, "LIST .") == "30 PRINT 3\n"  # written last
    assert after(session, "RUN") == " 1 \nDivision by zero in 20\n"
    assert after(session, "LIST .") == "20 X=1/0\n"  # the error's line
    after(session, "EDIT 10")
    assert after(session, "LIST .") == "10 PRINT 1\n"  # edited last
    after(session, "20 END")
    assert after(session, "RUN", "LIST .") == " 1 \n20 END\n"  # executed last
    session.handle("EDIT .")
    assert session.edit_text == "20 END"
    session.handle("EDIT")  # EDIT.md: without a line number, the first line
    assert session.edit_text == "10 PRINT 1"


def test_edit_in_a_program_puts_its_line_up_for_editing(session):
    # EDIT.md items 1, 3: the edit mode shows the program from the line (or the first one
    # above it) and that line can be edited: the session offers it as the typed EDIT does
    after(session, "10 PRINT 1", "20 EDIT 15", "30 PRINT 3")
    assert after(session, "RUN") == " 1 \n20 EDIT 15\n30 PRINT 3\n"
    assert session.edit_text == "20 EDIT 15"  # was None: the run ended with nothing to edit
    after(session, "20 PRINT 2")  # the line as the user edited it, EXE
    assert after(session, "RUN") == " 1 \n 2 \n 3 \n" and session.edit_text is None


def test_a_registered_password_protects_every_program_area(session, tmp_path):
    # PASS.md: one password for P0-P9; while it is registered no program is written, listed,
    # edited, erased or saved (item 5: PR error); RUN and LOAD go on (LOAD.md item 5); the
    # same password again cancels it
    after(session, "10 PRINT 1", "PROG 3", "10 PRINT 3", "PROG 0")
    (tmp_path / "OTHER.bas").write_text("10 PRINT 2\n")
    assert after(session, 'PASS "SECRET"') == ""
    for typed in ("20 PRINT 9", "10", "LIST", "LIST ALL", "LLIST", "EDIT 10", "EDIT", "NEW", "NEW ALL",
                  'SAVE "MINE"'):
        assert after(session, typed) == "Password protected\n", typed
    assert after(session, "PROG 3", "LIST", "10 END") == "Password protected\n" * 2
    assert after(session, "PROG 0", "RUN") == " 1 \n"  # the password outlives RUN's fresh machine
    assert after(session, "LIST") == "Password protected\n"
    assert after(session, 'LOAD "OTHER"', "RUN") == " 2 \n"
    assert after(session, 'PASS "WRONG"') == "Wrong password\n"
    assert after(session, 'PASS "SECRET"', "LIST", "20 END", "LIST") == "10 PRINT 2\n10 PRINT 2\n20 END\n"
    assert not (tmp_path / "MINE.bas").exists()


def test_a_program_that_loads_another_leaves_it_in_the_session(tmp_path):
    # LOAD_LOAD_ALL.md: LOAD in a program replaces the program, then command standby: the
    # session's LIST and RUN see the program the machine now holds (gw: NEW likewise)
    (tmp_path / "NEXT.BAS").write_text("10 PRINT 2\n")
    shown = []
    casio = Session(write=shown.append, engine=MachineEngine(shown.append, files=tmp_path), directory=tmp_path)
    for line in ('10 LOAD "NEXT"', "RUN", "LIST", "RUN"):
        casio.handle(line)
    assert "".join(shown) == "10 PRINT 2\n 2 \n"
    shown.clear()
    gw = Session(write=shown.append, engine=MachineEngine(shown.append, dialect="gw"), directory=tmp_path,
                 dialect="gw")
    for line in ("10 PRINT 7", "20 NEW", "RUN", "LIST"):
        gw.handle(line)
    assert "".join(shown) == " 7 \n"


def test_save_in_the_session_refuses_a_file_a_stopped_program_holds_open(tmp_path):
    # GW-BASIC's SAVE opens its file for output (GIODSK.ASM CHKFOP): a file the STOPped
    # program still has open is File already open, as the program's own SAVE says; DOS
    # ignores case, so SAVE "x" writes over the X.BAS the program made, not beside it
    shown = []
    gw = Session(write=shown.append, engine=MachineEngine(shown.append, dialect="gw", files=tmp_path),
                 directory=tmp_path, dialect="gw")
    for line in ('10 OPEN "O",1,"X.BAS"', "20 STOP", "RUN", 'SAVE "x"'):
        gw.handle(line)
    assert "".join(shown).endswith("File already open\n")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["X.BAS"]
    assert (tmp_path / "X.BAS").read_bytes() in (b"", b"\x1a")  # still the program's empty file
    shown.clear()
    for line in ("CONT", 'SAVE "x"'):  # the program ends: END closes its files
        gw.handle(line)
    assert "".join(shown) == ""
    assert sorted(p.name for p in tmp_path.iterdir()) == ["X.BAS"]
    assert (tmp_path / "X.BAS").read_bytes().startswith(b"\xff")  # the tokenised program
