"""A lone ``.`` after GOTO, GOSUB, THEN, ELSE, ON ... GOTO, RESUME, RUN, and after EDIT's line,
in a gw program (``Dialect.line_dot_words``, ``Dialect.edit_tail_error``).

GWMAIN.ASM CRUNCH stores a ``.`` that follows a line-number word as a plain character, never
as a line constant ("EDIT ." is what it keeps it for): GOTO and GOSUB (GOTO2, also reached by
THEN, ELSE and ON ... GOTO) want a line constant and give Syntax error; RESUME's LINGET reads
no digits and finds the statement not ended (Syntax error); RUN finds no line constant and
reads a file name expression (DSKCOM.ASM LRUN, GIO86.ASM NAMSCN), which ``.`` makes the
number 0; SCNEDT.ASM EDIT reads its line with LINSPC and calls anything after it
Illegal function call.  Reference: PC-BASIC 2.0.8, run beside yaseer where it agrees with
the source; where it does not, the source decides and the test says so.
"""

from __future__ import annotations

import pytest

from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")

TRAPPED = "10 ON ERROR GOTO 100\n20 {}\n30 END\n100 PRINT ERR; ERL: RESUME NEXT\n"

AGREED = [  # (statement, the error PC-BASIC 2.0.8 and the source give; yaseer before in the comment)
    ("GOTO .", "Syntax error"),  # was Undefined line number
    ("GOSUB .", "Syntax error"),  # was Undefined line number
    ("X=1: ON X GOTO .", "Syntax error"),  # was Undefined line number
    ("X=2: ON X GOSUB 10,.", "Syntax error"),  # was Undefined line number
    ("IF 1 THEN .", "Syntax error"),  # was Undefined line number
    ("IF 0 THEN 10 ELSE .", "Syntax error"),  # was Undefined line number
    ("EDIT .+1", "Illegal function call"),  # was Syntax error
    ("EDIT .,", "Illegal function call"),  # was Syntax error
]


@pytest.mark.parametrize("statement, error", AGREED)
def test_dot_after_a_line_word_stops_as_pcbasic(tmp_path, statement, error):
    (tmp_path / "y").mkdir()
    (tmp_path / "p").mkdir()
    source = f"10 {statement}\n"
    assert yaseer_run(source, tmp_path / "y") == f"{error} in 10\n"
    assert pcbasic_run(source, tmp_path / "p") == f"{error} in 10\n"


@pytest.mark.parametrize("statement, code", [
    ("GOTO .", 2), ("GOSUB .", 2), ("IF 1 THEN .", 2), ("IF 0 THEN 30 ELSE .", 2), ("X=1: ON X GOTO .", 2),
    ("EDIT .+1", 5), ("RESTORE .", 8),
])
def test_dot_error_trapped_with_its_code_and_line(tmp_path, statement, code):
    """ERR and ERL under ON ERROR, as PC-BASIC 2.0.8 (RESTORE . is line 0: BIMISC.ASM RESTORE's LINGET)."""
    (tmp_path / "y").mkdir()
    (tmp_path / "p").mkdir()
    source = TRAPPED.format(statement)
    assert yaseer_run(source, tmp_path / "y") == f" {code}  20 \n"
    assert pcbasic_run(source, tmp_path / "p") == f" {code}  20 \n"


def test_resume_dot_is_a_syntax_error_in_the_handler(tmp_path):
    """RESUME . : LINGET reads no digits, the statement has not ended (GWMAIN.ASM RESUME),
    as PC-BASIC 2.0.8; before, yaseer read it as RESUME 0 and ran the failing line forever."""
    source = "10 ON ERROR GOTO 100\n20 ERROR 5\n30 END\n100 PRINT ERR; ERL: RESUME .\n"
    assert yaseer_run(source, tmp_path) == " 5  20 \nSyntax error in 100\n"


def test_run_dot_is_a_file_name_expression(tmp_path):
    """RUN . and RUN .+1: no line constant, so DSKCOM.ASM LRUN reads a file name and
    GIO86.ASM NAMSCN finds the number 0 there: Type mismatch.  PC-BASIC 2.0.8 says
    Syntax error for both: the source decides.  Before, RUN . was RUN 0 (Undefined line
    number, without the line)."""
    assert yaseer_run("10 RUN .\n", tmp_path) == "Type mismatch in 10\n"
    assert yaseer_run("10 RUN .+1\n", tmp_path) == "Type mismatch in 10\n"
    assert yaseer_run(TRAPPED.format("RUN ."), tmp_path) == " 13  20 \n"


def test_llist_dot_comma_reads_a_device_as_list_does(tmp_path):
    """LLIST ., : GWLIST.ASM LLIST falls into LIST, whose SCNLIN takes ``.`` and the comma,
    then NAMSCN evaluates a missing file name: Missing operand, as LIST ., gives in both.
    PC-BASIC 2.0.8 says Syntax error for LLIST only: the source decides."""
    assert yaseer_run("10 LLIST .,\n", tmp_path) == "Missing operand in 10\n"
    assert yaseer_run("10 LIST .,\n", tmp_path) == "Missing operand in 10\n"


def test_dot_still_the_number_elsewhere(tmp_path):
    """A ``.`` that is no line number is the number 0 (a branch's statement, a .5), and
    casio's GOTO . stays what it was (its scanner reads ``.`` after GOTO as the current line
    marker of LIST ., refused where a line number must stand)."""
    assert yaseer_run("10 IF 1 THEN PRINT .; .5 ELSE 10\n", tmp_path) == " 0  .5 \n"
    assert yaseer_run("10 EDIT .\n", tmp_path) == ""
    assert yaseer_run("10 GOTO .\n", tmp_path, dialect="casio") == "Syntax error in 10\n"
    assert yaseer_run("10 RUN .+1\n", tmp_path, dialect="casio") == "Syntax error in 10\n"
    assert yaseer_run("10 EDIT .+1\n", tmp_path, dialect="casio") == "Syntax error in 10\n"
