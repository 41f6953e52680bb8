"""Program files as GW-BASIC writes and reads them, against PC-BASIC 2.0.8 where it agrees with
the source: the characters 128..255 of a program are the IBM PC's codes (code page 437) in
every form SAVE writes (one writer, program_crunch.saved_program, for the session's SAVE and a
program's; GIODSK.ASM BINSAV/PROSAV and the ASCII save store the bytes of the line as CRUNCH
left them) and read back through the same character set (LOAD, RUN "f", CHAIN); a program from
a protected file keeps its protection however it is run (GIODSK.ASM PROCHK).
"""

from __future__ import annotations

import random
import subprocess
import sys
from pathlib import Path

import pytest

from test_differential_support import base_seed, case_count, clean_output
from test_gw_files import contents, pcbasic_run, yaseer_run
from test_gw_protected import generated_lines, gw_session, pc, typed  # noqa: F401 (pc: the fixture)

import yaseer
from yaseer.basic.dialects.dialect import GW
from yaseer.basic.machine.program_file import program_text

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

# Codes 128..255 as code page 437 shows them (what a GW-BASIC screen shows and a person types).
HIGH = bytes(range(128, 256)).decode("cp437")
# Lines holding every code 128..255 in a string and after REM (CRUNCH copies both as they are).
HIGH_LINES = [f'{10 * (k + 1)} PRINT "{HIGH[32 * k:32 * k + 32]}": REM {HIGH[32 * k:32 * k + 32]}'
              for k in range(4)]
HIGH_OUTPUT = "".join(HIGH[32 * k:32 * k + 32] + "\n" for k in range(4))


def pc_file(pc, lines, save: str, name: str) -> bytes:
    """The bytes PC-BASIC writes for ``lines`` typed and then ``save`` (a SAVE command)."""
    session, directory = pc
    session.execute("NEW")
    session.execute("\n".join(lines))
    session.execute(save)
    return (directory / f"{name}.BAS").read_bytes()


@pytest.mark.parametrize("option", ["", ",A", ",P"])
def test_the_session_saves_codes_128_to_255_as_pc_basic(pc, tmp_path, option):
    session, shown = gw_session(tmp_path)
    theirs = pc_file(pc, HIGH_LINES, f'SAVE "HIGH"{option}', "HIGH")
    assert typed(session, shown, ["NEW"] + HIGH_LINES + [f'SAVE "HIGH"{option}']) == ""
    mine = (tmp_path / "HIGH.bas").read_bytes()
    assert mine == theirs
    assert bytes(range(128, 256)) in b"".join(mine.split(b'"')[1::2]) or option != ",A"


@pytest.mark.parametrize("option", ["", ",A", ",P"])
def test_a_program_saves_codes_128_to_255_as_pc_basic(pc, tmp_path, option):
    """The defect this file was written for: a program's SAVE "f",P wrote ``│`` as ``?`` and
    ``é`` as 0xE9, not code page 437's 0xB3 and 0x82."""
    lines = [f'10 PRINT "│é{HIGH}"', f'20 SAVE "SELF"{option}']
    pc_session, pc_directory = pc
    pc_session.execute("NEW")
    pc_session.execute("\n".join(lines))
    pc_session.execute("RUN")
    session, shown = gw_session(tmp_path)
    typed(session, shown, ["NEW"] + lines + ["RUN"])
    mine = (tmp_path / "SELF.BAS").read_bytes()
    assert mine == (pc_directory / "SELF.BAS").read_bytes()
    if option == ",A":
        assert mine.startswith(b'10 PRINT "\xb3\x82\x80\x81')


@pytest.mark.parametrize("option", ["", ",A", ",P"])
def test_codes_128_to_255_read_back_through_every_reader(pc, tmp_path, option):
    """A file SAVEd by the session: LOAD lists the characters typed; RUN "f", a program's
    LOAD, CHAIN and ``yaseer run`` print them; PC-BASIC prints the same from the same file."""
    session, shown = gw_session(tmp_path)
    typed(session, shown, ["NEW"] + HIGH_LINES + [f'SAVE "HIGH"{option}'])
    listed = typed(session, shown, ["NEW", 'LOAD "HIGH"', "LIST"])
    if option != ",P":
        assert listed == "".join(line + "\n" for line in HIGH_LINES)
    assert typed(session, shown, ['RUN "HIGH"']) == HIGH_OUTPUT
    assert typed(session, shown, ["NEW", '10 LOAD "HIGH",R']) + typed(session, shown, ["RUN"]) == HIGH_OUTPUT
    assert typed(session, shown, ["NEW", '10 CHAIN "HIGH"', "RUN"]) == HIGH_OUTPUT
    assert typed(session, shown, ["NEW", '10 RUN "HIGH"', "RUN"]) == HIGH_OUTPUT
    pc_session, pc_directory = pc
    (pc_directory / "MINE.BAS").write_bytes((tmp_path / "HIGH.bas").read_bytes())
    pc_session.execute("NEW")
    assert clean_output(pc_session.execute('RUN "MINE"')) == clean_output(HIGH_OUTPUT)  # it drops code 255 (NBSP) with the cursor
    assert yaseer.run(tmp_path / "HIGH.bas", dialect="gw").text == HIGH_OUTPUT
    assert program_text((tmp_path / "HIGH.bas").read_bytes(), GW.charset).startswith(HIGH_LINES[0])


def test_codes_show_as_the_pc_shows_them(pc):
    """CHR$ and ASC answer code page 437's codes, as GW-BASIC's and PC-BASIC's."""
    source = '10 PRINT CHR$(130); CHR$(179); CHR$(233); ASC("é"); ASC("│")'
    pc_session, _ = pc
    pc_session.execute("NEW")
    theirs = clean_output(pc_session.execute(source + "\nRUN"))
    assert yaseer.run(source, dialect="gw").text == theirs == "é│Θ 130  179 \n"


def protected_file(tmp_path: Path, lines) -> Path:
    session, shown = gw_session(tmp_path)
    typed(session, shown, ["NEW"] + list(lines) + ['SAVE "PROT",P'])
    return tmp_path / "PROT.bas"


@pytest.mark.parametrize("refused", ["LIST", "LLIST", 'SAVE "COPY"', 'SAVE "COPY",A', "EDIT 10"])
def test_a_protected_file_run_by_the_api_stays_protected(tmp_path, refused):
    """GIODSK.ASM PROCHK: a program loaded from a ,P file may not show itself, however it is
    started (before, ``yaseer.run`` and ``yaseer run`` ran it unprotected)."""
    path = protected_file(tmp_path, ['10 PRINT "A"', f"20 {refused}", '30 PRINT "B"'])
    result = yaseer.run(path, dialect="gw", files=tmp_path)
    assert (result.text, result.error, result.protected) == ("A\n", "Illegal function call in 20", True)
    assert not (tmp_path / "COPY.BAS").exists()
    assert yaseer.run(path.read_bytes(), dialect="gw", files=tmp_path).error == "Illegal function call in 20"


def test_a_protected_program_may_save_itself_with_p(tmp_path):
    path = protected_file(tmp_path, ['10 PRINT "A"', '20 SAVE "AGAIN",P'])
    assert yaseer.run(path, dialect="gw", files=tmp_path).error is None
    assert (tmp_path / "AGAIN.BAS").read_bytes() == path.read_bytes()


def test_yaseer_run_keeps_the_protection(tmp_path):
    path = protected_file(tmp_path, ['10 PRINT "A"', "20 LIST"])
    for arguments, stdin in (([str(path)], None), (["-"], path.read_bytes())):
        done = subprocess.run([sys.executable, "-m", "yaseer", "--dialect", "gw", "run", *arguments],
                              input=stdin, capture_output=True, cwd=tmp_path, timeout=60)
        assert (done.stdout, done.stderr, done.returncode) == (b"A\n", b"Illegal function call in 20\n", 1)


def test_an_ascii_program_is_not_protected(tmp_path):
    (tmp_path / "OPEN.BAS").write_text('10 PRINT "A"\n20 LIST\n')
    result = yaseer.run(tmp_path / "OPEN.BAS", dialect="gw")
    assert (result.text, result.error, result.protected) == ('A\n10 PRINT "A"\n20 LIST\n', None, False)


def test_the_api_reads_bytes_as_a_file(tmp_path):
    assert yaseer.run(b'10 PRINT "\x82"\r\n\x1a', dialect="gw").text == "é\n"


def blanked(rng: random.Random, lines: dict[int, str]) -> list[str]:
    """``lines`` typed with blanks before the number, after it and after the text."""
    return [" " * rng.choice([0, 0, 1, 2]) + str(n) + " " * rng.choice([0, 1, 1, 2, 3]) + text
            + " " * rng.choice([0, 0, 1, 3]) for n, text in sorted(lines.items())]


def test_generated_programs_save_and_list_as_pc_basic(pc, tmp_path):
    """Generated lines (every rule of CRUNCH, test_gw_protected's generator) typed with blanks
    around them: plain SAVE (tokenised, 0xFF), ,A and ,P write PC-BASIC's bytes, and LIST
    shows PC-BASIC's listing (the blanks kept as typed, but the one after the number)."""
    pc_session, _ = pc
    rng = random.Random(base_seed() + 4096)
    session, shown = gw_session(tmp_path)
    for k in range(case_count(30)):
        typed_lines = blanked(rng, generated_lines(rng))
        for option in ("", ",A", ",P"):
            theirs = pc_file(pc, typed_lines, f'SAVE "GEN{k}"{option}', f"GEN{k}")
            typed(session, shown, ["NEW"] + typed_lines + [f'SAVE "GEN{k}"{option}'])
            assert (tmp_path / f"GEN{k}.bas").read_bytes() == theirs, (option, typed_lines)
        assert typed(session, shown, ["LIST"]) == clean_output(pc_session.execute("LIST")), typed_lines


def test_a_program_saves_itself_tokenised_as_pc_basic(pc, tmp_path):
    lines = ["10 A=1.5:  B%=-300  ", '20 SAVE "PLAIN"', '30 PRINT "goes on"']
    pc_session, pc_directory = pc
    pc_session.execute("NEW")
    pc_session.execute("\n".join(lines))
    pc_session.execute("RUN")
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ["NEW"] + lines + ["RUN"]) == "goes on\n"
    mine = (tmp_path / "PLAIN.BAS").read_bytes()
    assert mine == (pc_directory / "PLAIN.BAS").read_bytes() and mine[0] == 0xFF


@pytest.mark.parametrize("option", ["", ",P", ",A"])
def test_a_program_goes_on_after_a_plain_or_protected_save(tmp_path, option):
    """GIO86.ASM BINSAV ends in DSKCOM.ASM PRGFIN and GIODSK.ASM PROSAV in GTMPRT: both go
    back to the statement after the SAVE, with the variables and open files as they were;
    SAVE ,A is LIST's work, which ends the run.  Output and files as PC-BASIC 2.0.8's."""
    source = (f'10 A=7: OPEN "O",1,"LOG.TXT": PRINT #1,"before"\n20 SAVE "GOES"{option}: PRINT "then";A\n'
              '30 PRINT #1,"after": CLOSE: PRINT "closed"\n')
    theirs_dir, ours_dir = tmp_path / "pcbasic", tmp_path / "yaseer"
    theirs_dir.mkdir()
    ours_dir.mkdir()
    theirs, ours = pcbasic_run(source, theirs_dir), yaseer_run(source, ours_dir)
    assert ours == theirs
    assert ("then 7 \nclosed" in ours) == (option != ",A")
    assert contents(ours_dir) == contents(theirs_dir)


def test_merge_refuses_a_tokenised_file(tmp_path):
    """GW-BASIC merges ASCII files only (DSKCOM.ASM OKGET2: a first byte 0xFF or 0xFE is Bad
    file mode; PC-BASIC 2.0.8 says Direct statement in file here, the source decides); SAVE
    "f",A writes one that merges."""
    session, shown = gw_session(tmp_path)
    typed(session, shown, ["NEW", '20 PRINT "merged"', 'SAVE "PART"', 'SAVE "TEXT",A'])
    assert typed(session, shown, ["NEW", '10 MERGE "PART"', "RUN"]) == "Bad file mode in 10\n"
    assert typed(session, shown, ["NEW", '10 MERGE "TEXT"', "RUN", "LIST"]) == \
        '10 MERGE "TEXT"\n20 PRINT "merged"\n'


def test_blanks_around_a_line_are_kept_as_gw_keeps_them(tmp_path):
    """GWMAIN.ASM MAIN skips one blank after the line number (LIST prints one) and CRUNCH
    keeps every other blank; a line of blanks only deletes the line."""
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ["NEW", "  10   PRINT 1  ", "20PRINT 2", "30 PRINT 3", "30   ", "LIST"]) == \
        "10   PRINT 1  \n20 PRINT 2\n"
    (tmp_path / "BLANKS.BAS").write_bytes(b"10   PRINT 1  \r\n20 PRINT 2\t\r\n\x1a")
    assert typed(session, shown, ['LOAD "BLANKS"', "LIST"]) == "10   PRINT 1  \n20 PRINT 2\t\n"
    assert typed(session, shown, ['10 LOAD "BLANKS"', "RUN", "LIST"]) == "10   PRINT 1  \n20 PRINT 2\t\n"


def test_the_current_line_is_gw_s_dot(pc, tmp_path):
    """``.`` in LIST, LLIST, DELETE, EDIT, AUTO and RENUM is GW's DOT (GWMAIN.ASM LINSPC): the
    line last typed, listed (GWLIST.ASM LIST), edited (SCNEDT.ASM EDIT) or stopped in by an
    error or Break; a run that ends leaves it.  The same commands typed into PC-BASIC give
    the same listings."""
    pc_session, _ = pc
    session, shown = gw_session(tmp_path)
    steps = ["NEW", "10 PRINT 1", "20 PRINT 2", "30 PRINT 3", "40 PRINT 4", "LIST .", "25 PRINT 25",
             "LIST .", "LIST 10-20", "LIST .", "RUN", "LIST .", "30 X=1/0: PRINT 7: ERROR 5", "RUN", "LIST .",
             "20 STOP", "RUN", "LIST .", "LIST .-", "LIST -.", "DELETE .", "LIST", "LIST 25", "RENUM 100, .", "LIST"]
    for step in steps:
        assert typed(session, shown, [step]) == clean_output(pc_session.execute(step)), step
    assert typed(session, shown, ["LIST 100", "EDIT ."]) == "100 PRINT 25\n"
    assert session.edit_text == "100 PRINT 25"
    typed(session, shown, ["LIST 20", "AUTO ., 5"])
    assert session.auto == (20, 5)


def test_a_period_beside_digits_is_no_line(tmp_path):
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ["NEW", "10 PRINT 1", "LIST 1.5", "DELETE .5"]) == "Syntax error\nSyntax error\n"
    assert typed(session, shown, ["NEW", "LIST ."]) == ""  # DOT before any line: line 0, none here


DIRECT_FILE = b"10 PRINT 1\r\n20 PRINT 2\r\nPRINT 3\r\n30 PRINT 4\r\n"


def test_the_session_s_load_stops_at_a_line_without_number(pc, tmp_path):
    """GIO86.ASM DIRDO: an ASCII file's line without a number is ``Direct statement in file``;
    the lines before it are the program and the last of them the current line (GWMAIN.ASM
    keeps each line entered in DOT).  The session's LOAD joined the line onto line 20."""
    pc_session, pc_directory = pc
    (pc_directory / "DIRECT.BAS").write_bytes(DIRECT_FILE)
    (tmp_path / "DIRECT.BAS").write_bytes(DIRECT_FILE)
    session, shown = gw_session(tmp_path)
    for step in ["NEW", 'LOAD "DIRECT"', "LIST", "LIST .", "NEW", 'RUN "DIRECT"', "LIST"]:
        assert typed(session, shown, [step]) == clean_output(pc_session.execute(step)), step


@pytest.mark.parametrize("command", ['LOAD "DIRECT"', 'CHAIN "DIRECT"', 'LOAD "DIRECT",R'])
def test_a_program_s_load_stops_at_a_line_without_number(pc, tmp_path, command):
    """LOAD and CHAIN in a program: the lines before the line without a number replace the
    program, and ``Direct statement in file`` ends the run (the old program's ON ERROR went
    with it), as PC-BASIC 2.0.8 does; before, yaseer trapped it and kept the old program."""
    pc_session, pc_directory = pc
    (pc_directory / "DIRECT.BAS").write_bytes(DIRECT_FILE)
    (tmp_path / "DIRECT.BAS").write_bytes(DIRECT_FILE)
    session, shown = gw_session(tmp_path)
    steps = ["NEW", "5 ON ERROR GOTO 100", '7 PRINT "A"', f"8 {command}", '9 PRINT "B"',
             '100 PRINT "TRAP";ERR: END', "RUN", "LIST", "LIST ."]
    for step in steps:
        assert typed(session, shown, [step]) == clean_output(pc_session.execute(step)), step


def test_run_file_and_merge_stop_at_a_line_without_number(tmp_path):
    """RUN "f" reads the file as LOAD does (DIRDO's error: PC-BASIC 2.0.8 says Undefined line
    number here, the source decides); MERGE enters the lines before it into the program."""
    (tmp_path / "DIRECT.BAS").write_bytes(DIRECT_FILE)
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ["NEW", '10 PRINT "A"', '15 RUN "DIRECT"', "RUN", "LIST"]) == \
        "A\nDirect statement in file\n10 PRINT 1\n20 PRINT 2\n"
    typed(session, shown, ["NEW", '5 PRINT "A"', '15 MERGE "DIRECT"', "RUN"])
    assert typed(session, shown, ["LIST"]) == '5 PRINT "A"\n10 PRINT 1\n15 MERGE "DIRECT"\n20 PRINT 2\n'


def test_the_api_and_yaseer_run_stop_at_a_line_without_number(tmp_path):
    (tmp_path / "DIRECT.BAS").write_bytes(DIRECT_FILE)
    for listing in (tmp_path / "DIRECT.BAS", DIRECT_FILE):
        result = yaseer.run(listing, dialect="gw")
        assert (result.text, result.error) == ("", "Direct statement in file")
    done = subprocess.run([sys.executable, "-m", "yaseer", "--dialect", "gw", "run", "DIRECT.BAS"],
                          capture_output=True, cwd=tmp_path, timeout=60)
    assert (done.stdout, done.stderr, done.returncode) == (b"", b"Direct statement in file\n", 1)


@pytest.mark.parametrize("steps", [
    ["10 PRINT 1", "20 LIST .", "30 PRINT 3", "RUN", "LIST 10", "RUN", "LIST ."],
    ["10 LIST 20", "20 LIST .", "30 PRINT 3", "RUN", "LIST ."],
    ["10 PRINT 1", "20 LIST 10-.", "30 PRINT 3", "LIST 10", "RUN", "LIST .", "LIST -.", "LIST .-"],
    ["10 PRINT 1", "20 DELETE .", "30 PRINT 3", "RUN", "LIST"],
    ["10 PRINT 1", "20 DELETE 10-.", "30 PRINT 3", "40 PRINT 4", "LIST 30", "RUN", "LIST"],
    ["10 PRINT 1", "20 RENUM 100,.", "30 PRINT 3", "LIST 20", "RUN", "LIST"],
    ["10 PRINT 1", "20 RENUM .,.", "30 PRINT 3", "LIST 30", "RUN", "LIST"],
    ["10 PRINT 1", "20 LIST . - .", "30 PRINT 3", "RUN"],
], ids=["list", "list-sets-dot", "range", "delete", "delete-range", "renum", "renum-both", "blanks"])
def test_a_running_program_reads_dot(pc, tmp_path, steps):
    """``.`` in a program's LIST, LLIST, DELETE and RENUM is GW's DOT as the statement runs
    (GWMAIN.ASM LINSPC): the line last typed or listed; the program's LIST sets it
    (GWLIST.ASM LIST).  Before, a program's ``.`` was line 0.  PC-BASIC 2.0.8 shows the same."""
    pc_session, _ = pc
    session, shown = gw_session(tmp_path)
    for step in ["NEW"] + steps:
        assert typed(session, shown, [step]) == clean_output(pc_session.execute(step)), (steps, step)


def test_an_ascii_file_s_last_line_is_dot(pc, tmp_path):
    """An ASCII file's lines are entered as typed ones (GWMAIN.ASM keeps each in DOT): the
    session's LOAD, the API and ``yaseer run`` start the program with its last line current."""
    pc_session, pc_directory = pc
    data = b"10 PRINT 1\r\n20 LIST .\r\n30 PRINT 3\r\n"
    (pc_directory / "DOTS.BAS").write_bytes(data)
    (tmp_path / "DOTS.BAS").write_bytes(data)
    session, shown = gw_session(tmp_path)
    for step in ["NEW", "LIST 10", 'LOAD "DOTS"', "RUN"]:
        assert typed(session, shown, [step]) == clean_output(pc_session.execute(step)), step
    expected = clean_output(pc_session.execute('RUN "DOTS"'))
    assert yaseer.run(tmp_path / "DOTS.BAS", dialect="gw").text == expected == " 1 \n30 PRINT 3\n"
    done = subprocess.run([sys.executable, "-m", "yaseer", "--dialect", "gw", "run", "DOTS.BAS"],
                          capture_output=True, cwd=tmp_path, timeout=60)
    assert done.stdout.decode() == expected


def test_a_tokenised_file_leaves_dot(tmp_path):
    """A tokenised file's lines are not entered as typed ones (DSKCOM.ASM's binary LOAD copies
    them; only GWMAIN.ASM's line entry and LIST store DOT): the API and ``yaseer run`` start
    it with DOT 0, as a fresh PC-BASIC 2.0.8 runs it (before, the last line was current)."""
    import pcbasic

    (tmp_path / "DOTS.BAS").write_bytes(b"\xff")  # replaced below by PC-BASIC's own SAVE
    session = pcbasic.Session(output_streams=None, input_streams=None, devices={"C:": str(tmp_path)},
                              current_device="C:")
    session.start()
    try:
        session.execute("NEW")
        session.execute("10 PRINT 1\n20 LIST .\n30 PRINT 3")
        session.execute('SAVE "DOTS"')
    finally:
        session.close()
    fresh = pcbasic.Session(output_streams=None, input_streams=None, devices={"C:": str(tmp_path)},
                            current_device="C:")
    fresh.start()
    try:
        expected = clean_output(fresh.execute('RUN "DOTS"'))
    finally:
        fresh.close()
    data = (tmp_path / "DOTS.BAS").read_bytes()
    assert data[0] == 0xFF and expected == " 1 \n"
    assert yaseer.run(data, dialect="gw").text == expected
    done = subprocess.run([sys.executable, "-m", "yaseer", "--dialect", "gw", "run", "DOTS.BAS"],
                          capture_output=True, cwd=tmp_path, timeout=60)
    assert done.stdout.decode() == expected


def test_dot_in_a_program_as_the_source_keeps_it(tmp_path):
    """Where PC-BASIC 2.0.8 differs the source decides: GWMAIN.ASM ERROR stores the error's line
    in DOT before it looks for a trap (PC-BASIC leaves DOT), so a handler's ``LIST .`` and a
    later ``LIST .`` show the line in error; SCNEDT.ASM EDIT stores its line in DOT before it
    looks for it; AUTO reads its start with LINSPC; RENUM's step is read by LINGET (no ``.``)."""
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ["NEW", "10 ON ERROR GOTO 100", "20 ERROR 5", "30 END", "100 LIST .",
                                  "110 RESUME 30", "RUN", "LIST ."]) == "20 ERROR 5\n20 ERROR 5\n"
    assert typed(session, shown, ["NEW", "10 PRINT 1", "20 ERROR 5", "30 LIST .", "RUN", "RUN 30"]) == \
        " 1 \nIllegal function call in 20\n20 ERROR 5\n"
    typed(session, shown, ["NEW", "10 PRINT 1", "20 AUTO ., 5", "30 PRINT 3", "LIST 10", "RUN"])
    assert session.auto == (10, 5)
    session.interrupt()
    assert typed(session, shown, ["NEW", "10 EDIT 30", "20 LIST .", "30 PRINT 3", "LIST 10", "RUN", "RUN 20"]) == \
        "10 EDIT 30\n30 PRINT 3\n"
    assert typed(session, shown, ["NEW", "10 EDIT 25", "20 LIST .", "RUN", "RUN 20"]) == \
        "Undefined line number in 10\n10 EDIT 25\n"  # EDIT's 25, then the error's 10
    assert typed(session, shown, ["NEW", "10 RENUM 100, ., ."]) == ""
    assert typed(session, shown, ["RUN"]) == "Syntax error in 10\n"


def test_the_api_and_the_report_do_not_list_a_protected_program(tmp_path):
    """GW-BASIC never lists a program SAVEd with ,P (GIODSK.ASM PROCHK: LIST is Illegal
    function call): ``Result.listing`` is "" (``Result.protected`` says why) and ``yaseer
    report`` puts a note where the listing goes; the program still runs.  Before, both
    showed the program's text."""
    path = protected_file(tmp_path, ['10 PRINT "SECRET" + "WORD"', "20 PRINT 1"])
    for listing in (path, path.read_bytes()):
        result = yaseer.run(listing, dialect="gw", files=tmp_path)
        assert (result.listing, result.protected, result.text) == ("", True, "SECRETWORD\n 1 \n")
    page = tmp_path / "page.html"
    done = subprocess.run([sys.executable, "-m", "yaseer", "--dialect", "gw", "report", str(path), "--out", str(page)],
                          capture_output=True, text=True, cwd=tmp_path, timeout=300)
    assert done.returncode == 0, done.stderr
    text = page.read_text()
    assert 'id="protected"' in text and "SECRETWORD" in text and "SECRET&quot;" not in text and "PRINT" not in text


def test_the_api_lists_a_tokenised_file_as_list_shows_it(pc):
    """``Result.listing`` of a tokenised file is PC-BASIC 2.0.8's LIST of it, while the program
    computes with its double constant's 56 bits (1/3 rounded up in the last bit, which the
    listing's 16 digits do not give): it prints what PC-BASIC prints."""
    data = pc_file(pc, ["10 A#=1.5#: PRINT A#*3#; A#"], 'SAVE "THIRD"', "THIRD")
    at = data.index(0x1F) + 1
    data = data[:at] + bytes.fromhex("ABAAAAAAAAAA2A7F") + data[at + 8:]
    session, directory = pc
    (directory / "THIRD.BAS").write_bytes(data)
    session.execute("NEW")
    printed = clean_output(session.execute('RUN "THIRD"'))
    result = yaseer.run(data, dialect="gw")
    assert (result.listing, result.text) == (clean_output(session.execute("LIST")), printed)


def test_chain_s_delete_range_and_a_direct_error_as_the_source_reads_dot(tmp_path):
    """CHAIN MERGE's DELETE range is read by GWMAIN.ASM SCNLIN, whose LINSPC takes ``.`` as DOT
    (FIVEO.ASM CHAIN; PC-BASIC 2.0.8 calls it Illegal function call, the source decides); a
    direct statement's error, even one a program's ON ERROR catches, leaves DOT (GWMAIN.ASM
    ERROR stores it only when the line is not the direct one)."""
    (tmp_path / "OV.BAS").write_bytes(b'100 PRINT "OVERLAY"\r\n110 LIST\r\n')
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ["NEW", '10 PRINT "A"', '20 CHAIN MERGE "OV", 100, DELETE .-40', "30 PRINT 3",
                                  "40 PRINT 4", "50 PRINT 5", "LIST 30", "RUN"]) == \
        '30 PRINT 3\nA\nOVERLAY\n10 PRINT "A"\n20 CHAIN MERGE "OV", 100, DELETE .-40\n50 PRINT 5\n' \
        '100 PRINT "OVERLAY"\n110 LIST\n'
    typed(session, shown, ["NEW", "10 ON ERROR GOTO 100", "20 STOP", "100 RESUME NEXT", "RUN", "LIST 10"])
    assert typed(session, shown, ["ERROR 5", "LIST ."])[-len("10 ON ERROR GOTO 100\n"):] == "10 ON ERROR GOTO 100\n"


@pytest.mark.parametrize("dialect, code", [("gw", 52), ("casio", 64)])
def test_an_empty_program_name_names_nothing(tmp_path, dialect, code):
    """SAVE, LOAD, RUN, CHAIN and MERGE of "" (or of a device and nothing, or of blanks) are
    the error OPEN's "" gives, and write nothing: in gw Bad file number, as a real GW-BASIC
    recorded ``SAVE ""`` (PC-BASIC's SAVE test; PC-BASIC 2.0.8 agrees), in casio Bad file
    name (Dialect.nameless_file_error).  A file called ``.BAS`` or ``" .BAS"``, which yaseer
    used to write, is a file nobody asked for."""
    device = "" if dialect == "gw" else "CAS0:"
    statements = [f'SAVE "{device}"', 'SAVE ""', 'SAVE "",A', 'LOAD ""', 'LOAD "",R', 'RUN ""', 'OPEN "O",1,""',
                  'SAVE " "', 'OPEN "O",1,"  .TXT"']
    if dialect == "gw":  # (words casio has not)
        statements += ['SAVE "",P', 'CHAIN ""', 'CHAIN MERGE "",10', 'MERGE ""', 'OPEN CHR$(0) FOR OUTPUT AS 1']
    lines = [f"{10 * (k + 2)} {s}" for k, s in enumerate(statements)]
    source = "10 ON ERROR GOTO 900\n" + "\n".join(lines) + '\n800 PRINT "end": END\n900 PRINT ERR;: RESUME NEXT\n'
    out = yaseer_run(source, tmp_path, dialect)
    assert out == f" {code} " * len(statements) + "end\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == []
