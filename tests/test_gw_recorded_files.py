"""Program files, CHAIN and random files as a real GW-BASIC 3.23 recorded them.

Each case is a small program of our own that shows one behaviour PC-BASIC's test suite
recorded on the real machine (tests/basic: the recording named in each test), with the
GW-BASIC routine behind it; where PC-BASIC 2.0.8 agrees, its run is the reference,
else the value the recording and the source give.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def _both(source: str, tmp_path: Path) -> tuple[str, str]:
    ours, theirs = tmp_path / "yaseer", tmp_path / "pcbasic"
    ours.mkdir()
    theirs.mkdir()
    return yaseer_run(source, ours), pcbasic_run(source, theirs)


def test_field_variable_takes_no_string_space(tmp_path):
    """FLDGARB: a FIELDed variable points into the file's buffer (DSKCOM.ASM FIELD), so
    FRE("") does not count its characters, after FIELD, LSET and GET alike; a copy of it
    made by a string operation is a string of the string space."""
    source = ('10 OPEN "R.DAT" FOR RANDOM AS 1\n20 A$="": F=FRE("")\n30 FIELD #1, 100 AS A$\n'
              '40 PRINT F-FRE("")\n50 LSET A$="XY": GET #1, 1: PRINT F-FRE("")\n'
              '60 A$=A$+"": PRINT F-FRE("")\n')
    ours, theirs = _both(source, tmp_path)
    assert ours == theirs == " 0 \n 0 \n 100 \n"


@pytest.mark.parametrize("length, record, error", [
    (12, b'"AB",5    \r\n', ""),  # blanks up to the record's last two bytes, then CR LF
    (6, b'"AB"  ', " 50 \n"),  # exactly two left: the count runs past 0, FIELD overflow
    (5, b'"AB"\r', " 50 \n"),  # fewer than two: no blank, the CR LF overflows
])
def test_write_to_a_random_file_fills_its_record(tmp_path, length, record, error):
    """RandomWidth: WRITE # to a random file sends blanks up to the record's last two bytes
    before its CR LF (FIVEO.ASM WRITE, WRTFIN: CMPFBC's bytes left less two); PRINT # does
    not.  The recording and the source decide: PC-BASIC 2.0.8 writes no blanks."""
    source = (f'10 ON ERROR GOTO 100\n20 OPEN "R.DAT" FOR RANDOM AS 1 LEN={length}\n'
              '30 WRITE #1, "AB"' + (", 5" if length == 12 else "") + '\n40 PUT #1, 1: CLOSE: END\n'
              '100 PRINT ERR: RESUME NEXT\n')
    assert yaseer_run(source, tmp_path) == error
    assert (tmp_path / "R.DAT").read_bytes() == record + bytes(length - len(record))


def test_print_to_a_random_file_is_not_filled(tmp_path):
    """RandomWidth: PRINT # ends its line with CR LF alone (the rest of the buffer as it was)."""
    source = '10 OPEN "R.DAT" FOR RANDOM AS 1 LEN=10\n20 PRINT #1, "AB"\n30 PUT #1, 1: CLOSE\n'
    assert yaseer_run(source, tmp_path) == ""
    assert (tmp_path / "R.DAT").read_bytes() == b"AB\r\n" + bytes(6)


def test_directory_words_and_kill_act_before_their_leftover(tmp_path):
    """DISK2: KILL, MKDIR, RMDIR and CHDIR read their name and act before NEWSTT meets what
    follows (GIODSK.ASM KILL: NAMFIL, the delete, RET; GWMAIN.ASM GONZER): ``CHDIR ""
    LPRINT`` is Bad file name (the recording), ``KILL "K.TXT" X`` deletes the file, then
    Syntax error; with no name read (``CHDIR MKDIR``) the expression's Syntax error.  As
    PC-BASIC 2.0.8."""
    source = ('10 ON ERROR GOTO 100\n15 OPEN "K.TXT" FOR OUTPUT AS 1: CLOSE\n20 KILL "K.TXT" X\n'
              '30 KILL "K.TXT"\n40 MKDIR "SUB" LPRINT\n50 CHDIR MKDIR\n60 RMDIR "SUB" 5\n70 RMDIR "SUB"\n'
              '80 CHDIR "" LPRINT\n90 KILL "" LPRINT\n99 END\n100 PRINT ERR; ERL: RESUME NEXT\n')
    ours, theirs = _both(source, tmp_path)
    assert ours == theirs == " 2  20 \n 53  30 \n 2  40 \n 2  50 \n 2  60 \n 76  70 \n 64  80 \n 64  90 \n"


@pytest.mark.parametrize("merge", ["", "MERGE "])
def test_option_base_holds_in_the_chained_program(tmp_path, merge):
    """CHAIN: the chained program runs under the first one's OPTION BASE (FIVEO.ASM CHAIN
    saves OPTFLG and OPTVAL in TOPTFG and TOPTVL, CHNRET puts them back), also where its
    subscript 0 is a constant: a COMMON array and a new one alike refuse it (Subscript out
    of range, as a real GW-BASIC 3.23 recorded it: PC-BASIC's CHAIN test).  As PC-BASIC
    2.0.8."""
    from test_gw_chain import run_both

    first = f'10 OPTION BASE 1: COMMON D()\n20 DIM D(2): D(1)=7\n30 CHAIN {merge}"B", 1000\n'
    chained = ('1000 ON ERROR GOTO 1090\r\n1010 PRINT D(1): PRINT D(0)\r\n1020 PRINT H(0): H(1)=2: PRINT H(1)\r\n'
               '1030 END\r\n1090 PRINT ERR; ERL: RESUME NEXT\r\n')
    ours, theirs, _, _ = run_both(tmp_path, 0, first, {"B.BAS": chained})
    assert ours == theirs == " 7 \n 9  1010 \n 9  1020 \n 2 \n"


_REMARKS = "".join(f"{1000 + 10 * k} REM {'*' * 60}\r\n" for k in range(40))  # 40 lines of 67 bytes


@pytest.mark.parametrize("chain, kept", [
    ('CHAIN MERGE "B", 1000, ALL', True),  # every variable stays: the lines do not fit beside them
    ('COMMON A(): CHAIN "B", 1000', True),  # the COMMON array stays
    ('CHAIN "B", 1000', False),  # the array goes: room enough
    ('CHAIN MERGE "B", 1000', False),
])
def test_chained_lines_must_fit_beside_the_variables_kept(tmp_path, chain, kept):
    """FULLCHN: CHAIN moves the variables it keeps to the top of memory and loads the new
    lines below them (FIVEO.ASM CHAIN; the insertion's BIMISC.ASM REASON): with ALL or a
    COMMON array holding most of the 64 KB, 2680 bytes of lines are Out of memory, as a
    real GW-BASIC 3.23 stopped such a CHAIN MERGE (PC-BASIC's FULLCHN test).  FRE and the
    verdicts as PC-BASIC 2.0.8 (which names the CHAIN's line for ALL; the program text's
    Out of memory names none here, as for MERGE: chaining.Chaining.chained)."""
    from test_gw_chain import run_both

    first = f'10 DIM A(14682): A(1)=1\n20 PRINT FRE(0)\n30 {chain}\n'
    ours, theirs, _, _ = run_both(tmp_path, 0, first, {"B.BAS": "1000 PRINT FRE(0)\r\n" + _REMARKS})
    assert ours.split("\n")[0] == theirs.split("\n")[0]
    assert ours.split("\n")[1].startswith("Out of memory") == theirs.split("\n")[1].startswith("Out of memory") == kept


def _pcbasic_commands(directory: Path, commands: list[str]) -> str:
    import pcbasic
    from test_differential_support import clean_output

    session = pcbasic.Session(output_streams=None, input_streams=None, devices={"C:": str(directory)},
                              current_device="C:", peek_values={})
    session.start()
    out = "".join(clean_output(session.execute(command)) for command in commands)
    session.close()
    return out


@pytest.mark.parametrize("text", [
    "10 PRINT 1\r\n20 PRINT 2\r\n20\r\n30 PRINT 3\r\n",  # deletes line 20, as typed
    "10 PRINT 1\r\n15\r\n20 PRINT 2\r\n",  # no line 15: loading stops, line 20 never read
    "10 PRINT 1\r\n20 PRINT 2\r\n20\r\n20  \r\n30 PRINT 3\r\n",  # deleted already: stops
])
def test_a_bare_line_number_in_a_file(tmp_path, text):
    """undefined_line_number: a file's line number with nothing after it is read as typed
    (GWMAIN.ASM EDENT): it deletes its line, and where there is none loading stops with
    Undefined line number (FNDLIN, USERR), the lines before it kept; the program then runs
    (a real GW-BASIC 3.23 ran it so).  LOAD then RUN in PC-BASIC 2.0.8, which agrees; and
    RUN "file" in a program, whose error is not trapped (PC-BASIC agrees)."""
    ours_dir, theirs_dir = tmp_path / "yaseer", tmp_path / "pcbasic"
    for folder in (ours_dir, theirs_dir):
        folder.mkdir()
        (folder / "P.BAS").write_bytes(text.encode())
    theirs = _pcbasic_commands(theirs_dir, ['LOAD "P"', "RUN"])
    assert yaseer_run(text, ours_dir) == theirs
    program = '5 ON ERROR GOTO 9\n6 RUN "P"\n9 PRINT "E";ERR;ERL: END\n'
    assert yaseer_run(program, ours_dir) == _pcbasic_commands(theirs_dir, ["NEW", program, "RUN"])


def test_a_bare_line_number_only_deletes_in_casio():
    """``Dialect.bare_line_must_exist`` False (casio): a bare number deletes its line if any."""
    from yaseer.basic.dialects.dialect import CASIO
    from yaseer.basic.source.scanner import program_lines

    assert program_lines("10 PRINT 1\n15\n20 PRINT 2\n", CASIO) == ({10: "PRINT 1", 20: "PRINT 2"}, None)


@pytest.mark.parametrize("text", ["20\r\n40 PRINT 4\r\n", "20\r\n22\r\n40 PRINT 4\r\n"])
def test_a_bare_line_number_in_a_merged_file(tmp_path, text):
    """undefined_line_number, MERGE: a merged file's bare number deletes the program's line
    (the lines are entered as typed: GWMAIN.ASM EDENT), and one of no line stops the merge
    with Undefined line number.  As PC-BASIC 2.0.8."""
    from test_gw_chain import run_both

    first = '10 PRINT 1\n20 PRINT 2\n25 IF X THEN END\n26 X=1\n30 CHAIN MERGE "M", 10, ALL\n'
    ours, theirs, _, _ = run_both(tmp_path, 0, first, {"M.BAS": text})
    assert ours == theirs


def test_record_locks_bind_the_other_openings_of_a_file(tmp_path):
    """LockFiles, LockFilesOutput: LOCK holds records (a sequential file whole) against
    the file's other openings, as DOS's SHARE holds a handle's region: their PUT of a
    locked record, their GET of one the file holds and their LOCK of a range that meets it
    are Permission Denied (70); the opening that locked uses its records freely; a GET
    of bytes beyond the file's end reads none of them and goes on; UNLOCK frees them.  As
    a real GW-BASIC 3.23 recorded it; PC-BASIC 2.0.8 agrees but for that GET beyond the
    end (line 30's first GET: Permission Denied there, where the recording's GET #3, 2 of
    the empty file went on)."""
    source = ('10 ON ERROR GOTO 100\n20 OPEN "R.DAT" FOR RANDOM AS 1: OPEN "R.DAT" FOR RANDOM AS 2\n'
              '30 LOCK #1, 1 TO 3: GET #2, 2: PUT #1, 2: GET #2, 2: GET #2, 5: PUT #2, 4: PUT #2, 3\n'
              '40 LOCK #2, 3 TO 4: LOCK #2, 4: GET #1, 4: UNLOCK #1, 1 TO 3: PUT #2, 2: GET #1, 4\n'
              '50 CLOSE: OPEN "S.DAT" FOR OUTPUT AS 1: LOCK #1, 7 TO 9: OPEN "S.DAT" FOR RANDOM AS 2\n'
              '60 GET #2, 1: PUT #2, 9: UNLOCK #1, 1: PUT #2, 9: END\n100 PRINT ERR; ERL: RESUME NEXT\n')
    assert yaseer_run(source, tmp_path) == " 70  30 \n 70  30 \n 70  40 \n 70  40 \n 70  40 \n 70  60 \n"


def _tokenised(*lines: tuple[int, bytes]) -> bytes:
    """A tokenised program file (0xFF, then each line's link, number, tokens and 0, a zero link)."""
    from yaseer.basic.machine.program_crunch import TEXT_START

    body = bytearray()
    for number, tokens in lines:
        line = number.to_bytes(2, "little") + tokens + b"\0"
        body += (TEXT_START + len(body) + 2 + len(line)).to_bytes(2, "little") + line
    return b"\xff" + bytes(body) + b"\0\0\x1a"


_PRINT, _EQUALS, _ELSE, _THEN, _IF, _COLON = b"\x91", b"\xe7", b"\xa1", b"\xcd", b"\x8b", b":"


def test_a_tokenised_file_s_name_that_spells_a_keyword(tmp_path):
    """keyword_as_varname_in_tokenised_file: a tokenised file may hold a name whose letters
    spell a reserved word (``PRINT=1``, the name stored as letters): it is a variable when
    the program runs and when it is listed and saved again (the program's text marks it:
    scanner.STORED_NAME; CRUNCH stores the letters back).  A real GW-BASIC 3.23 printed 1;
    so does PC-BASIC 2.0.8, which runs the tokens."""
    from yaseer.basic.machine.program_crunch import crunch_line
    from yaseer.basic.machine.program_file import detokenise, line_text

    first, second = b"PRINT" + _EQUALS + b"\x12", _PRINT + b" PRINT"
    data = _tokenised((10, first), (20, second))
    for folder in (tmp_path / "yaseer", tmp_path / "pcbasic"):
        folder.mkdir()
        (folder / "T.BAS").write_bytes(data)
    program = '10 CHAIN "T"\n'
    assert yaseer_run(program, tmp_path / "yaseer") == pcbasic_run(program, tmp_path / "pcbasic") == " 1 \n"
    text = detokenise(data[1:], exact=True).split("\r\n")
    assert [crunch_line(line.split(" ", 1)[1]) for line in text[:2]] == [first, second]
    assert (line_text(first), line_text(second)) == ("PRINT=1", "PRINT PRINT")


@pytest.mark.parametrize("tokens, listed", [
    (_IF + b" X " + _THEN + b" \x0e\x32\x00" + _COLON + _ELSE + b" \x0e\x3c\x00", "IF X THEN 50ELSE 60"),
    (_COLON + _ELSE, "ELSE"),  # a typed ELSE alone
    (_ELSE, "LSE"),  # no ':' before it: LIST steps back over nothing and loses the E
    (b"AB " + _ELSE, "ABELSE"),  # the blank before it is stepped over
    (b"AB" + _ELSE, "A ELSE"),  # the B is, and a letter before gets its blank
])
def test_a_tokenised_file_s_else_as_list_shows_it(tokens, listed):
    """detokenise_ELSE: GWLIST.ASM LIST steps back one character for ELSE (the ``:`` CRUNCH
    stores before it), so an ELSE stored without it loses the character before, or its own
    E, as a real GW-BASIC 3.23 listed them; loaded and crunched again the line keeps its
    bytes (scanner.STORED_ELSE for the token alone).  The recording decides: PC-BASIC
    2.0.8 lists ``50 ELSE`` and ``ELSE``."""
    from yaseer.basic.machine.program_crunch import crunch_line
    from yaseer.basic.machine.program_file import detokenise, line_text

    assert line_text(tokens) == listed
    loaded = detokenise(_tokenised((10, tokens))[1:], exact=True)
    assert crunch_line(loaded[3:].split("\r\n")[0]) == tokens


def test_a_tokenised_file_s_lone_else_runs_as_else(tmp_path):
    """An ELSE token with no ':' before it, loaded from a tokenised file, is the statement
    ELSE (the rest of its line skipped), as any ELSE no IF owns."""
    (tmp_path / "T.BAS").write_bytes(_tokenised((10, _ELSE + _PRINT + b" 1"), (20, _PRINT + b" 2")))
    assert yaseer_run('10 CHAIN "T"\n', tmp_path) == " 2 \n"


def test_a_tokenised_file_s_words_in_small_letters_are_syntax_errors(tmp_path):
    """LOWRCASE: CRUNCH makes every letter outside strings a capital, but a tokenised file
    written elsewhere may hold small ones; the words a statement reads as letters are
    compared with capitals (SYNCHR), so LINE's ``bf``, OPTION ``base``, DEF ``seg`` and
    OPEN's ``output`` are Syntax errors (2) where the capitals run, as a real GW-BASIC 3.23
    recorded them (each error line of the recording; PC-BASIC not consulted)."""
    number = lambda n: b"\x0e" + n.to_bytes(2, "little")  # a line number constant
    on_error, screen, line, option, def_ = b"\x95 \xa7 \x89 ", b"\xc8 ", b"\xb0 ", b"\xb8 ", b"\x97 "
    open_, for_, end = b"\xba ", b" \x82 ", b"\x81"
    print_, err, erl, resume_next = b"\x91 ", b"\xd5", b"\xd4", b"\xa8 \x83"
    box = b"(\x11,\x11)\xea(\x12,\x12),,"
    data = _tokenised((10, on_error + number(100)), (20, screen + b"\x12"),
                      (30, line + box + b"bf"), (40, line + box + b"BF"),
                      (50, option + b"base \x12"), (60, def_ + b"seg"),
                      (70, open_ + b'"X"' + for_ + b"output AS \x12"), (80, end),
                      (100, print_ + err + b";" + erl + b":" + resume_next))
    (tmp_path / "T.BAS").write_bytes(data)
    assert yaseer_run('10 CHAIN "T"\n', tmp_path) == " 2  30 \n 2  50 \n 2  60 \n 2  70 \n"
