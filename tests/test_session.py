"""The editing session's logic, driven by calling it (no terminal, no interpreter).

The BASIC machine is replaced by a recording double here so these tests pin
down what the session itself does; tests/test_session_machine.py runs the
same session against the real machine, and tests/test_interactive.py through
a pseudo-terminal.
"""

from __future__ import annotations

import re

import pytest
from hypothesis import given, strategies as st

from yaseer.basic.errors import BREAK, BasicError
from yaseer.session import (
    Session,
    parse_listing,
    parse_range,
    program_text,
    renumber,
    renumber_references,
)


class RecordingEngine:
    """Stands in for the machine: records what the session asks, raises what it is told to."""

    def __init__(self):
        self.calls = []
        self.fail_with = None

    def _act(self, *call):
        self.calls.append(call)
        if self.fail_with is not None:
            error, self.fail_with = self.fail_with, None
            raise error

    def run(self, areas, start):
        self._act("run", {area: dict(lines) for area, lines in areas.items() if lines}, start)

    def cont(self):
        self._act("cont")

    def direct(self, statement, areas):
        self._act("direct", statement)

    def reset(self):
        self.calls.append(("reset",))


@pytest.fixture
def session(tmp_path):
    shown = []
    s = Session(write=shown.append, engine=RecordingEngine(), directory=tmp_path)
    s.shown = shown
    return s


def screen(session) -> str:
    text = "".join(session.shown)
    session.shown.clear()
    return text


def after(session, line: str) -> str:
    """What the session shows after ``line`` is typed."""
    session.handle(line)
    return screen(session)


def type_lines(session, *lines):
    for line in lines:
        session.handle(line)


def test_numbered_lines_are_stored_in_order_replaced_and_deleted(session):
    type_lines(session, "30 END", "10 PRINT 1", "20 PRINT 2", "10 PRINT 10", "20")
    assert after(session, "LIST") == "10 PRINT 10\n30 END\n"


@pytest.mark.parametrize(
    "argument, shown",
    [("20", "20 B\n"), ("20-30", "20 B\n30 C\n"), ("25-", "30 C\n40 D\n"), ("-20", "10 A\n20 B\n"), ("", "10 A\n20 B\n30 C\n40 D\n")],
)
def test_list_ranges(session, argument, shown):
    type_lines(session, "10 A", "20 B", "30 C", "40 D")
    assert after(session, f"LIST {argument}") == shown


def test_list_accepts_lower_case_and_no_space(session):
    type_lines(session, "10 A", "20 B")
    assert after(session, "list20") == "20 B\n"


def test_delete_range_and_missing_single_line(session):
    type_lines(session, "10 A", "20 B", "30 C", "40 D")
    session.handle("DELETE 20-30")
    assert after(session, "LIST") == "10 A\n40 D\n"
    assert after(session, "DELETE 25") == "Illegal function call\n"
    assert after(session, "DELETE") == "Syntax error\n"


def test_bad_range_is_a_syntax_error_and_the_session_goes_on(session):
    assert after(session, "LIST 1-2-3") == "Syntax error\n"
    session.handle("10 A")
    assert after(session, "LIST") == "10 A\n"


def test_renum_rewrites_jumps_but_not_strings_remarks_or_program_areas(session):
    type_lines(
        session,
        '5 IF X THEN 7 ELSE 9: PRINT "GOTO 7"',
        "7 ON X GOTO 5,9, 7: GOSUB PROG 5",
        "9 GOSUB 5: REM GOTO 9",
        "11 RESTORE 9: GOTO 11",
    )
    session.handle("RENUM")
    assert after(session, "LIST") == (  # as the machine lists them (keywords spaced, no others)
        '10 IF X THEN 20 ELSE 30:PRINT "GOTO 7"\n'
        "20 ON X GOTO 10,30,20:GOSUB PROG 5\n"
        "30 GOSUB 10:REM GOTO 9\n"
        "40 RESTORE 30:GOTO 40\n"
    )


def test_renum_with_start_old_and_step_and_undefined_target(session):
    type_lines(session, "10 A", "20 GOTO 90", "30 GOTO 20")
    assert after(session, "RENUM 100,20,5") == "Undefined line 90 in 20\n"
    assert after(session, "LIST") == "10 A\n100 GOTO 90\n105 GOTO 100\n"


def test_renum_that_would_overrun_kept_lines_is_refused(session):
    type_lines(session, "10 A", "20 B", "30 C")
    assert after(session, "RENUM 5,20") == "Illegal function call\n"
    assert after(session, "LIST") == "10 A\n20 B\n30 C\n"


def _ordinal_form(program):
    """The program with every line number replaced by its rank: invariant under RENUM."""
    rank = {number: index for index, number in enumerate(sorted(program))}
    return [renumber_references(program[n], rank)[0] for n in sorted(program)]


@given(
    st.lists(st.integers(1, 9000), min_size=1, max_size=12, unique=True),
    st.data(),
    st.integers(1, 500),
    st.integers(1, 50),
)
def test_renum_keeps_every_jump_on_the_same_target(numbers, data, new, step):
    targets = [data.draw(st.sampled_from(numbers)) for _ in numbers]
    program = {n: f"IF X THEN {t} ELSE GOSUB {t}" for n, t in zip(numbers, targets)}
    renumbered, warnings = renumber(program, new, 0, step)
    assert warnings == []
    assert sorted(renumbered) == [new + i * step for i in range(len(numbers))]
    assert _ordinal_form(renumbered) == _ordinal_form(program)


def test_edit_puts_the_line_up_for_the_next_input(session):
    session.handle("10 PRINT X")
    session.handle("EDIT 10")
    assert session.edit_text == "10 PRINT X"
    assert after(session, "EDIT 20") == "Undefined line number\n"
    assert session.edit_text is None


def test_save_then_load_round_trip(session, tmp_path):
    type_lines(session, "20 PRINT 2", "10 PRINT 1")
    session.handle('SAVE "prog.bas"')
    # the listing a program's SAVE writes (program_crunch.saved_program): CR LF lines and a Ctrl-Z
    assert (tmp_path / "prog.bas").read_bytes() == b"10 PRINT 1\r\n20 PRINT 2\r\n\x1a"
    session.handle("NEW")
    assert after(session, "LIST") == ""
    session.handle('LOAD "prog"')  # .bas is tried when the name has no suffix
    assert after(session, "LIST") == "10 PRINT 1\n20 PRINT 2\n"


def test_load_joins_wrapped_lines_and_reports_a_missing_file(session, tmp_path):
    (tmp_path / "wrapped.bas").write_text("10 FOR I = 1 TO 3:\n   PRINT I\n\n20 NEXT I\n")
    session.handle('LOAD "wrapped.bas')
    assert after(session, "LIST") == "10 FOR I=1 TO 3:PRINT I\n20 NEXT I\n"
    assert after(session, 'LOAD "nothing.bas"') == "File not found\n"


def test_load_without_a_name_is_a_syntax_error(session):
    assert after(session, "LOAD") == "Syntax error\n"


def test_prog_switches_the_edited_area(session):
    session.handle("10 PRINT 0")
    assert after(session, "PROG 5") == "PROG 5: library program (Python); typed lines replace it\n"
    assert after(session, "LIST").startswith("PROG 5: the virtual link")  # what it computes (test_library_text)
    session.handle("10 RETURN")
    assert after(session, "LIST") == "10 RETURN\n"
    session.handle("PROG 0")
    assert after(session, "LIST") == "10 PRINT 0\n"
    assert after(session, "PROG 12") == "Illegal function call\n"


def test_run_hands_every_typed_area_to_the_machine(session):
    type_lines(session, "10 GOSUB PROG 7", "20 END", "PROG 7", "10 PRINT 7: RETURN", "PROG 0", "RUN")
    assert session.engine.calls[-1] == (
        "run", {0: {10: "GOSUB PROG 7", 20: "END"}, 7: {10: "PRINT 7: RETURN"}}, None)
    session.handle("RUN 20")
    assert session.engine.calls[-1][2] == 20
    session.handle("RUN 30")
    assert screen(session).endswith("Undefined line number\n")


def test_an_error_in_a_run_is_shown_and_the_session_stays(session):
    session.handle("10 PRINT 1/0")
    session.engine.fail_with = BasicError("Division by zero", 11, line=10)
    assert after(session, "RUN") == "Division by zero in 10\n"
    session.handle("PRINT 1")
    assert session.engine.calls[-1] == ("direct", "PRINT 1")


def test_cont_only_after_a_break_and_not_after_an_edit(session):
    session.handle("10 STOP")
    assert after(session, "CONT") == "Can't continue\n"
    session.engine.fail_with = BasicError("Break", BREAK, line=10)
    assert after(session, "RUN") == "Break in 10\n"
    session.handle("PRINT X")  # a direct statement keeps CONT possible
    session.handle("CONT")
    assert session.engine.calls[-1] == ("cont",)
    session.engine.fail_with = BasicError("Break", BREAK, line=10)
    session.handle("CONT")
    session.handle("20 END")  # editing the program forbids CONT
    screen(session)
    assert after(session, "CONT") == "Can't continue\n"


def test_direct_mode_statements_go_to_the_machine(session):
    for statement in ("PRINT 2*3", "GOSUB PROG 5", "X(10)=3"):
        session.handle(statement)
        assert session.engine.calls[-1] == ("direct", statement)


def test_keywords_that_start_a_variable_name_are_direct_statements(session):
    session.handle("RUNS=1")
    session.handle("LISTA=2")
    assert session.engine.calls == [("direct", "RUNS=1"), ("direct", "LISTA=2")]


def test_new_in_the_listing_clears_the_variables_too(session):
    session.handle("10 A")
    session.handle("NEW")
    assert session.engine.calls == [("reset",)]


def test_system_and_bye_end_the_session(session):
    session.handle("bye")
    assert session.finished


def test_line_numbers_beyond_65529_are_refused(session):
    assert after(session, "70000 PRINT") == "Syntax error\n"


def test_parse_range_and_listing_helpers():
    assert parse_range(" 10 - 20 ") == (10, 20)
    assert parse_range("7") == (7, 7)
    with pytest.raises(BasicError, match="Syntax error"):
        parse_range("-")
    program = parse_listing("10 A\n  B\n20 C\n")
    assert program == {10: "A B", 20: "C"}
    assert program_text(program) == "10 A B\n20 C\n"
    with pytest.raises(BasicError, match="Syntax error"):
        parse_listing("PRINT 1\n10 A\n")
    assert re.fullmatch(r"10 A B\n20 C\n", program_text(parse_listing(program_text(program))))


def test_files_lists_the_listings_in_the_directory(session, tmp_path):
    (tmp_path / "b.bas").write_text("10 END\n")
    (tmp_path / "a.bas").write_text("10 END\n")
    (tmp_path / "notes.txt").write_text("x")
    assert after(session, "FILES") == "a.bas\nb.bas\n"


def test_help_names_every_command(session):
    shown = after(session, "help")
    for command in ("LIST", "DELETE", "EDIT", "RENUM", "RUN", "CONT", "NEW", "PROG", "LOAD", "SAVE", "FILES", "SYSTEM"):
        assert command in shown


def test_renum_follows_erl_comparisons_too(session):
    type_lines(session, "170 X = 1 / 0", "210 END", "500 IF ERR = 5 AND ERL = 170 THEN RESUME 210")
    after(session, "RENUM")
    assert after(session, "LIST 30") == "30 IF ERR=5 AND ERL=10 THEN RESUME 20\n"
