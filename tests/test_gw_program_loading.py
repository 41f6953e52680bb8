"""Program files as GW-BASIC's ASCII LOAD reads them, and LIST [range], "f" (gw).

A file's lines end at a CR; a LF inside a line stays in it and a CR right after that LF
is dropped (SCNEDT.ASM DSKCHI); more than 255 characters is ``Line buffer overflow``;
the reading stops at a zero byte (the line's end for MAIN); a line number takes digits
while it is at most 6552 (GWMAIN.ASM LINGET), the rest of the digits are the line's
text.  LIST writes a line's LF as LF CR to a file (SCNEDT.ASM OUTCH1) and no blank
after the number of a line that starts with a TAB (GWLIST.ASM NOSPAL).  Each program is
written into a fresh directory and run (``RUN "P.BAS"``) by yaseer and, where it reads
the file as the source does, by PC-BASIC 2.0.8: the files they leave must match.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from test_gw_files import contents, pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def runs_of(program: bytes, tmp_path: Path, driver: str = '10 RUN "P.BAS"\n') -> tuple[str, str, dict, dict]:
    """``program`` written as P.BAS into a directory for each, then ``driver`` run: (yaseer's
    screen, PC-BASIC's, yaseer's files, PC-BASIC's files)."""
    ours, theirs = tmp_path / "yaseer", tmp_path / "pcbasic"
    for directory in (ours, theirs):
        directory.mkdir(parents=True)
        (directory / "P.BAS").write_bytes(program)
    printed = yaseer_run(driver, ours), pcbasic_run(driver, theirs)
    return (*printed, contents(ours), contents(theirs))


def yaseer_files(program: bytes, tmp_path: Path, driver: str = '10 RUN "P.BAS"\n') -> tuple[str, dict]:
    """``program`` written as P.BAS, then ``driver`` run by yaseer alone: (screen, files)."""
    (tmp_path / "P.BAS").write_bytes(program)
    return yaseer_run(driver, tmp_path), contents(tmp_path)


# A lone LF: PC-BASIC 2.0.8 ends a program line there (Direct statement in file); a real
# GW-BASIC 3.23 keeps it in the line (PC-BASIC's recorded LITERALS and TABS2 tests), as
# DSKCHI does: these expected bytes follow the source.
def test_a_lf_inside_a_line_keeps_the_line_whole(tmp_path):
    program = (b'10 OPEN "O", 1, "OUT.TXT": PRINT #1, "A";:\n\rPRINT #1, "B\nC"\r\n'
               b'20 CLOSE\r\n30 LIST 10-20, "L.ASC"\r\n\x1a')
    screen, files = yaseer_files(program, tmp_path)
    assert screen == ""
    assert files["OUT.TXT"] == b"AB\nC\r\n\x1a"
    assert files["L.ASC"] == b'10 OPEN "O", 1, "OUT.TXT": PRINT #1, "A";:\n\rPRINT #1, "B\n\rC"\r\n20 CLOSE\r\n\x1a'


def test_a_file_listed_with_lfs_loads_back_the_same_lines(tmp_path):
    program = b'10 A = 1:\n\r\tB = 2:\n\rPRINT A + B\r\n20 LIST , "L.ASC"\r\n'
    screen, files = yaseer_files(program, tmp_path)
    assert screen == " 3 \n"
    assert files["L.ASC"] == program + b"\x1a"


def test_lfs_that_begin_a_line_are_dropped(tmp_path):
    # DSKCHI: "LEADING LINE FEEDS MUST BE IGNORED"; PC-BASIC 2.0.8 keeps them and calls
    # the line a direct statement: the source decides
    (tmp_path / "P.BAS").write_bytes(b'10 PRINT 1\r\n\n\n20 PRINT 2\r\n')
    assert yaseer_run('10 RUN "P.BAS"\n', tmp_path) == " 1 \n 2 \n"


def test_list_to_a_file_writes_no_blank_before_a_tab(tmp_path):
    program = b'10\tA = 1\r\n20  C = 3\r\n30 LIST , "L.ASC"\r\n'
    ours, theirs, our_files, their_files = runs_of(program, tmp_path)
    assert our_files == their_files
    assert our_files["L.ASC"].startswith(b"10\tA = 1\r\n20  C = 3\r\n")


def test_a_line_number_takes_digits_only_up_to_6552(tmp_path):
    program = b'1234567 REM x\r\n10 LIST 12000-12399, "L.ASC"\r\n65535 REM y\r\n'
    ours, theirs, our_files, their_files = runs_of(program, tmp_path)
    assert our_files == their_files
    assert our_files["L.ASC"] == b"12345 67 REM x\r\n\x1a"


def test_a_zero_byte_ends_the_line(tmp_path):
    program = b'10 OPEN "O", 1, "OUT.TXT": WRITE #1, "ab\x00cd": CLOSE\r\n20 END\r\n'
    ours, theirs, our_files, their_files = runs_of(program, tmp_path)
    assert our_files == their_files
    assert our_files["OUT.TXT"] == b'"ab"\r\n\x1a'


def test_a_line_of_256_characters_is_line_buffer_overflow(tmp_path):
    long_line = b"20 REM " + b"x" * 249
    program = b'10 OPEN "O", 1, "OUT.TXT": PRINT #1, 1: CLOSE\r\n' + long_line + b"\r\n30 END\r\n"
    ours, theirs, our_files, their_files = runs_of(program, tmp_path)
    assert "Line buffer overflow" in ours and "Line buffer overflow" in theirs
    assert "OUT.TXT" not in our_files and our_files == their_files
    ours, theirs, our_files, their_files = runs_of(program.replace(b"x" * 249, b"x" * 248), tmp_path / "255")
    assert our_files["OUT.TXT"] == b" 1 \r\n\x1a" and our_files == their_files


def test_line_zero_keeps_its_blank_and_lists_with_one(tmp_path):
    program = b"0 'zero\r\n1 'one\r\n2 LIST , \"L.ASC\"\r\n"
    ours, theirs, our_files, their_files = runs_of(program, tmp_path)
    assert our_files["L.ASC"] == b"0 'zero\r\n1 'one\r\n2 LIST , \"L.ASC\"\r\n\x1a"
    assert our_files == their_files


def test_a_tokenised_line_with_a_lf_runs_and_lists_whole(tmp_path):
    # 10 PRINT 1:<LF>PRINT 2 and 20 LIST,"L.ASC" as GW-BASIC's SAVE stores them (link, number,
    # tokens, 0): PC-BASIC 2.0.8 runs it the same, and lists the LF as LF CR
    line_10 = b"\x0a\x00\x91\x20\x12\x3a\x0a\x91\x20\x13\x00"
    line_20 = b"\x14\x00\x93,\"L.ASC\"\x00"
    start = 0x126E + 1
    first = start + 2 + len(line_10)
    second = first + 2 + len(line_20)
    program = (b"\xff" + first.to_bytes(2, "little") + line_10 + second.to_bytes(2, "little") + line_20
               + b"\x00\x00\x1a")
    ours, theirs, our_files, their_files = runs_of(program, tmp_path)
    assert ours == theirs == " 1 \n 2 \n"
    assert our_files["L.ASC"] == b"10 PRINT 1:\n\rPRINT 2\r\n20 LIST,\"L.ASC\"\r\n\x1a"
    assert our_files == their_files


def test_casio_lists_to_the_display_only(tmp_path):
    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.machine import Machine
    import io

    machine = Machine(screen=io.StringIO(), dialect="casio", files=tmp_path)
    machine.load('10 LIST , "L.ASC"\n')
    with pytest.raises(BasicError, match="Syntax error"):
        machine.run()
    assert not list(tmp_path.iterdir())
