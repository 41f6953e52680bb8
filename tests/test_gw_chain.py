"""CHAIN, CHAIN MERGE, COMMON and MERGE (yaseer/basic/machine/chaining.py) against PC-BASIC 2.0.8:
seeded generated pairs of programs (a first program setting scalars and arrays, naming
some in COMMON statements, opening a file, then chaining with a line, ALL, MERGE and
DELETE; a second program printing what it was left and writing to the open file)
print the same text and leave the same files.  Where GW-BASIC's source decides
(FIVEO.ASM), pinned apart: a missing file is the CHAIN statement's error and ON ERROR
traps it (PC-BASIC does not trap it), and a chained line that does not exist is
``Undefined line number`` (PC-BASIC: ``Illegal function call``).
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count
from test_gw_files import contents, pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

SHOW = 'PRINT "A";A;"B";B%;"C";C$;"D";D(1);D(2);"E";E#;'


def chained_pair(rng: random.Random) -> tuple[str, str, str]:
    """(first program, the chained file's name, its text)."""
    merge = rng.random() < 0.35
    everything = rng.random() < 0.4
    common = [name for name in ("A", "B%", "C$", "D()", "E#") if rng.random() < 0.5]
    first = ["DIM D(3): A=1.5: B%=7: C$=\"see\": D(1)=4: D(2)=-2: E#=1/3#"]
    if common and rng.random() < 0.8:
        first.insert(rng.randint(0, 1), "COMMON " + ", ".join(common))
    opened = rng.random() < 0.5
    if opened:
        first.append('OPEN "O", 1, "T.TXT": PRINT #1, "first"')
    options = ""
    start = rng.choice([None, 20]) if not merge else 1000
    if start is not None:
        options += f", {start}"
    if everything:
        options += ", ALL" if start is not None else ", , ALL"
    delete = merge and rng.random() < 0.5
    if delete:
        options += ", DELETE 30-40"
    first.append(f'CHAIN {"MERGE " if merge else ""}"NEXT"{options}')
    first.append('PRINT "not reached"')
    numbered = [f"{10 * (k + 1)} {text}" for k, text in enumerate(first)]
    if delete:  # lines 30 and 40 exist to be deleted; a GOTO 30 after the merge finds none
        numbered += ["30 PRINT \"thirty\"", "40 PRINT \"forty\""] if len(first) < 3 else []
    base = 1000 if merge else 10
    second = [f'PRINT "second"', SHOW, "PRINT"]
    if rng.random() < 0.4:  # a kept array is dimensioned already: Duplicate Definition
        second.insert(1, "DIM D(3): PRINT D(1)")
    if opened:
        second.append('PRINT #1, "second": CLOSE')
    if merge:
        second.append("LIST" if False else 'PRINT "merged"')
    second.append("END")
    lines = [f"{base + 10 * k} {text}" for k, text in enumerate(second)]
    if not merge:
        lines.insert(1, f"{base + 5} PRINT \"at start\"")
    text = "\r\n".join(lines) + "\r\n\x1a"
    return "\n".join(sorted(numbered, key=lambda s: int(s.split()[0]))) + "\n", "NEXT.BAS", text


def run_both(tmp_path, k: int, first: str, files: dict[str, str]) -> tuple[str, str, dict, dict]:
    theirs_dir, ours_dir = tmp_path / f"pc{k}", tmp_path / f"ya{k}"
    for folder in (theirs_dir, ours_dir):
        folder.mkdir()
        for name, text in files.items():
            (folder / name).write_bytes(text.encode("latin-1"))
    theirs = pcbasic_run(first, theirs_dir)
    ours = yaseer_run(first, ours_dir)
    return ours, theirs, contents(ours_dir), contents(theirs_dir)


def test_generated_chains_match_pcbasic(tmp_path):
    rng = random.Random(base_seed() + 2)
    for k in range(case_count(25)):
        first, name, text = chained_pair(rng)
        ours, theirs, our_files, their_files = run_both(tmp_path, k, first, {name: text})
        assert ours == theirs, first + "---\n" + text
        assert our_files == their_files, first


CASES = {
    "plain": ('10 A=1: B$="b": X=5\n20 CHAIN "B"\n', {"B.BAS": '10 PRINT A;B$;X\r\n'}),
    "line and all": ('10 A=1: B$="b"\n20 CHAIN "B", 30, ALL\n',
                     {"B.BAS": '10 PRINT "ten"\r\n30 PRINT A;B$\r\n'}),
    "common anywhere": ('10 A=1: B=2: C=3\n20 CHAIN "B"\n30 COMMON B\n40 IF 0 THEN COMMON C\n',
                        {"B.BAS": '10 PRINT A;B;C\r\n'}),
    "option base kept": ('10 OPTION BASE 1: COMMON D()\n20 DIM D(2): D(1)=5\n30 CHAIN "B"\n',
                         {"B.BAS": '10 PRINT D(1): DIM E(2): E(1)=1: PRINT E(1): I=0: PRINT E(I)\r\n'}),
    "case of the name": ('10 CHAIN "b"\n', {"B.BAS": '10 PRINT "found"\r\n'}),
    "merge statement stops": ('10 A=1: MERGE "M"\n20 PRINT "after"\n', {"M.BAS": '30 PRINT "merged"\r\n'}),
    "direct statement in file": ('10 CHAIN "D"\n', {"D.BAS": '10 PRINT 1\r\nPRINT 2\r\n'}),
    "delete range must end on a line": ('10 CHAIN MERGE "M", 30, DELETE 10-15\n', {"M.BAS": '30 PRINT 3\r\n'}),
    "missing file": ('10 CHAIN "NOPE"\n', {}),
    # the commands a program runs: RUN goes on, the others end the run (GW-BASIC returns to
    # direct mode)
    "run a file": ('10 PRINT "A": OPEN "O", 1, "T.TXT"\n20 RUN "B"\n', {"B.BAS": '10 PRINT "B";LOC(1)\r\n'}),
    "run a file keeping the files": ('10 OPEN "O", 1, "T.TXT": PRINT #1, "x"\n20 RUN "B", R\n',
                                     {"B.BAS": '10 PRINT #1, "y": CLOSE: PRINT "B"\r\n'}),
    "run a line": ('10 GOTO 30\n20 PRINT "twenty";X: END\n30 X=5: RUN 20\n', {}),
    "list": ('10 PRINT "A"\n20 LIST 10-20\n30 PRINT "after"\n', {}),
    "save and load": ('10 PRINT "A"\n20 SAVE "S1",A\n30 PRINT "after"\n', {}),
    "load": ('10 PRINT "A": LOAD "B"\n20 PRINT "after"\n', {"B.BAS": '10 PRINT "B"\r\n'}),
    "load and run": ('10 PRINT "A": LOAD "B",R\n20 PRINT "after"\n', {"B.BAS": '10 PRINT "B"\r\n'}),
    "new": ('10 PRINT "A"\n20 NEW\n30 PRINT "after"\n', {}),
    "delete": ('10 PRINT "A"\n20 DELETE 30\n30 PRINT "after"\n', {}),
    "delete a missing line": ('10 DELETE 35\n30 PRINT "after"\n', {}),
    "edit": ('10 PRINT "A"\n20 EDIT 10\n30 PRINT "C"\n', {}),
    "key off": ('10 PRINT "A": KEY OFF: KEY ON: PRINT "B"\n', {}),
    "run a missing line": ('10 RUN 50\n', {}),
}


@pytest.mark.parametrize("name", list(CASES))
def test_chain_cases_match_pcbasic(tmp_path, name):
    first, files = CASES[name]
    ours, theirs, our_files, their_files = run_both(tmp_path, 0, first, files)
    assert ours == theirs
    assert our_files == their_files


def test_a_missing_chained_file_is_trappable_as_the_source_says(tmp_path):
    """FIVEO.ASM CHAIN opens the file (PRGFLI) before anything is cleared, so the error is the
    statement's and ON ERROR traps it (PC-BASIC 2.0.8 does not trap it)."""
    source = '10 ON ERROR GOTO 100\n20 CHAIN "NOPE"\n30 END\n100 PRINT ERR; ERL: RESUME NEXT\n'
    assert yaseer_run(source, tmp_path) == " 53  20 \n"


def test_a_chained_line_that_does_not_exist(tmp_path):
    """FIVEO.ASM CHNRET: FNDLIN fails, USERR: Undefined line number (PC-BASIC: Illegal function call)."""
    (tmp_path / "B.BAS").write_bytes(b"10 PRINT 1\r\n")
    assert yaseer_run('10 CHAIN "B", 25\n', tmp_path) == "Undefined line number in 10\n"


@pytest.mark.parametrize("source, message", [
    ('10 CHAIN "B", 10, NONE', "Syntax error in 10"), ('10 CHAIN "B", DELETE 10', "Syntax error in 10"),
    ('10 COMMON: PRINT "x"', "x"), ('10 MERGE', "Missing operand in 10"), ('10 CHAIN', "Missing operand in 10"),
])
def test_chain_syntax_errors_as_pcbasic(tmp_path, source, message):
    (tmp_path / "B.BAS").write_bytes(b"10 PRINT 1\r\n")
    assert yaseer_run(source + "\n", tmp_path).splitlines()[-1] == pcbasic_run(source, tmp_path).splitlines()[-1] \
        == message


TOKENISED = b"\xff\x09\x12\x0a\x00\x91 \x12\x00\x00\x00\x1a"  # 10 PRINT 1, as GW-BASIC saves it


def test_chain_reads_a_tokenised_file_and_merge_refuses_one(tmp_path):
    """A CHAIN loads as LOAD does; MERGE wants ASCII (DSKCOM.ASM OKGET2: a binary or protected
    file is Bad file mode)."""
    (tmp_path / "T.BAS").write_bytes(TOKENISED)
    assert yaseer_run('10 CHAIN "T"\n', tmp_path) == " 1 \n"
    assert yaseer_run('10 CHAIN MERGE "T", 10\n', tmp_path) == "Bad file mode in 10\n"
    assert yaseer_run('10 MERGE "T"\n', tmp_path) == "Bad file mode in 10\n"


def test_chain_to_line_zero_starts_the_program(tmp_path):
    """FIVEO.ASM CHNRET: a line number 0 goes to NEWSTT at the program's start (PC-BASIC:
    Illegal function call)."""
    (tmp_path / "B.BAS").write_bytes(b'10 PRINT "ten";A\r\n')
    assert yaseer_run('10 A=1: COMMON A\n20 CHAIN "B", 0\n', tmp_path) == "ten 1 \n"


def test_chain_options_as_the_source_reads_them(tmp_path):
    """FIVEO.ASM CHAIN: after the line's comma a second comma must be followed by ALL or
    DELETE (``CHAIN "B",,`` Syntax error; PC-BASIC runs B); a first option is the line's
    expression, so ``CHAIN "B", ALL`` chains to line ALL = 0, the start (PC-BASIC: Illegal
    function call)."""
    (tmp_path / "B.BAS").write_bytes(b"10 PRINT 1\r\n")
    assert yaseer_run('10 CHAIN "B",,\n', tmp_path) == "Syntax error in 10\n"
    assert yaseer_run('10 CHAIN "B", ALL\n', tmp_path) == " 1 \n"


def test_system_ends_the_run(tmp_path):
    assert yaseer_run('10 PRINT "A": SYSTEM: PRINT "B"\n', tmp_path) == "A\n"


# COMMON skips its list as DATA skips its items (FIVEO.ASM COMMON jumps to GWMAIN.ASM DATA);
# only a CHAIN reads the lists (source/common_lists.py)
MALFORMED_LISTS = ["A(1)", ",", "1", "A B", "A,", "A(1+2)", "A(1", 'A("S")', "A(", "A B: PRINT 2"]


@pytest.mark.parametrize("listed", MALFORMED_LISTS)
def test_common_skips_its_list_where_it_runs(tmp_path, listed):
    """A COMMON whose list does not read is no error where it runs (PC-BASIC 2.0.8 agrees)."""
    source = f'10 COMMON {listed}: PRINT "x"\n20 PRINT "ok"\n'
    assert yaseer_run(source, tmp_path) == pcbasic_run(source, tmp_path)
    assert yaseer_run(source, tmp_path).endswith("ok\n")


B_PRINTS = b'10 PRINT "B";A;A(1);C;D\r\n'


@pytest.mark.parametrize("listed", ["A B", "1", ",", "A,", "A(1+2)", "A(1", "A(1,2)", "A(-)", "C: COMMON 1"])
def test_a_list_that_does_not_read_stops_the_chain_in_the_common_line(tmp_path, listed):
    """FIVEO.ASM CHAIN reads each COMMON list as it scans the program, with the COMMON's
    line in CURLIN: the error is the CHAIN's (ON ERROR traps it, RESUME NEXT goes on after
    the CHAIN) and ERL the COMMON's line; PC-BASIC 2.0.8 agrees."""
    (tmp_path / "B.BAS").write_bytes(B_PRINTS)
    plain = f'10 A=5\n20 CHAIN "B"\n30 COMMON {listed}\n'
    trapped = (f'10 A=5: ON ERROR GOTO 100\n20 CHAIN "B"\n25 PRINT "after"; ERL: END\n30 COMMON {listed}\n'
               '100 PRINT ERR; ERL: RESUME NEXT\n')
    for source in (plain, trapped):
        assert yaseer_run(source, tmp_path) == pcbasic_run(source, tmp_path)
    assert yaseer_run(plain, tmp_path) == "Syntax error in 30\n"


@pytest.mark.parametrize("first, expected", [
    ('10 A=5: DIM A(2): A(1)=7\n20 COMMON A\n30 CHAIN "B"\n', "B 5  0  0  0 \n"),
    ('10 A=5: DIM A(2): A(1)=7\n20 COMMON A()\n30 CHAIN "B"\n', "B 0  7  0  0 \n"),
    ('10 C=3: D=4\n20 IF 1 THEN C=3: COMMON C\n30 REM x: COMMON D\n40 CHAIN "B"\n', "B 0  0  3  0 \n"),
    ('10 C=3: D=4\n20 PRINT 1 \'x: COMMON D\n30 CHAIN "B"\n', " 1 \nB 0  0  0  0 \n"),
    ('10 C=3: D=4\n20 IF 1 THEN COMMON C ELSE COMMON D\n30 CHAIN "B"\n', "B 0  0  0  0 \n"),
])
def test_chain_finds_the_commons_that_begin_a_statement(tmp_path, first, expected):
    """FIVEO.ASM CHAIN looks at each statement's first token (after a colon too, inside a
    THEN branch; not right after THEN or ELSE, nor in a remark's text) and keeps a scalar
    for a name, an array for a name with parentheses; PC-BASIC 2.0.8 agrees."""
    (tmp_path / "B.BAS").write_bytes(B_PRINTS)
    assert yaseer_run(first, tmp_path) == pcbasic_run(first, tmp_path) == expected


@pytest.mark.parametrize("first, expected", [
    # EVAL reads the operand in the parentheses: a variable, a sign, a bracketed sum
    ('10 A=5: C=3\n20 CHAIN "B"\n30 COMMON A(X), C, D(-1), E((1+2))\n', "B 0  0  3  0 \n"),
    # GETYPR after EVAL: a string is Illegal function call
    ('10 A=5\n20 CHAIN "B"\n30 COMMON A("S")\n', "Illegal function call in 30\n"),
    # EVAL at the statement's end: Missing operand
    ('10 A=5\n20 CHAIN "B"\n30 COMMON A(\n', "Missing operand in 30\n"),
    ('10 A=5\n20 CHAIN "B"\n30 COMMON A(-\n', "Missing operand in 30\n"),
    # PRGFLI opens the file before the scan
    ('10 A=5\n20 CHAIN "NOPE"\n30 COMMON 1\n', "File not found in 20\n"),
    # with ALL CHAIN goes to DNCMDA without scanning
    ('10 A=5\n20 CHAIN "B",,ALL\n30 COMMON 1\n', "B 5  0  0  0 \n"),
    ('10 A=5\n20 CHAIN "B", 10, ALL\n30 COMMON 1\n', "B 5  0  0  0 \n"),
])
def test_chain_reads_the_lists_as_the_source_does(tmp_path, first, expected):
    """Where PC-BASIC 2.0.8 differs, FIVEO.ASM CHAIN decides: PC-BASIC takes only a number
    in an array's parentheses (Syntax error for the others), reports every list that does
    not read as Syntax error, scans before it opens the file, and scans with ALL too."""
    (tmp_path / "B.BAS").write_bytes(B_PRINTS)
    assert yaseer_run(first, tmp_path) == expected


@pytest.mark.parametrize("statement, with_file", [
    ('CHAIN "B", 10,', "Syntax error"), ('CHAIN "B" X', "Syntax error"),
    ('CHAIN MERGE "B", 10, DELETE', "Syntax error"), ('CHAIN MERGE "B", 10, DELETE 10-', "Illegal function call"),
])
def test_a_chain_whose_options_do_not_read_opens_its_file_first(tmp_path, statement, with_file):
    """FIVEO.ASM CHAIN opens its file (PRGFLI) before it reads its options: without a file
    B each is File not found (PC-BASIC 2.0.8 agrees but for a DELETE range, which it checks
    first: the source decides); with the file the options' own error."""
    source = f"10 {statement}\n20 PRINT \"no\"\n"
    assert yaseer_run(source, tmp_path) == "File not found in 10\n"
    (tmp_path / "B.BAS").write_bytes(b"10 PRINT 1\r\n")
    assert yaseer_run(source, tmp_path) == f"{with_file} in 10\n"
