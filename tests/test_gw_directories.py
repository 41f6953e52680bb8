"""MKDIR, CHDIR, RMDIR and names read from CHDIR's folder (gw), inside the program's
directory only.

DOS's directory words as a real GW-BASIC 3.23 recorded them (PC-BASIC's DISK and DISK2
tests) and as PC-BASIC 2.0.8 runs them (compared here program by program, files and
folders left afterwards included); the program's directory is the drive's root: no name,
``..`` however many, absolute name or symbolic link leads out of it (machine/sandbox.py).
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def tree(directory: Path) -> dict[str, bytes | None]:
    """Every path under ``directory`` (names in capitals, as DOS shows them): a file's bytes,
    None for a folder."""
    return {str(p.relative_to(directory)).upper(): (None if p.is_dir() else p.read_bytes())
            for p in sorted(directory.rglob("*"))}


def both(source: str, tmp_path: Path) -> tuple[str, str, dict, dict]:
    ours, theirs = tmp_path / "yaseer", tmp_path / "pcbasic"
    ours.mkdir()
    theirs.mkdir()
    printed = yaseer_run(source, ours), pcbasic_run(source, theirs)
    return (*printed, tree(ours), tree(theirs))


def test_folders_made_entered_and_removed_as_pcbasic(tmp_path):
    source = "\n".join([
        '10 ON ERROR GOTO 900', '20 MKDIR "D1": MKDIR "D2": CHDIR "D1"',
        '30 OPEN "F.TXT" FOR OUTPUT AS 1: PRINT #1, "in d1": CLOSE 1',
        '40 NAME "F.TXT" AS "G.TXT": CHDIR "..\\D2"',
        '50 OPEN "F.TXT" FOR OUTPUT AS 1: PRINT #1, "in d2": CLOSE 1: KILL "F.TXT"',
        '60 OPEN "..\\D1\\G.TXT" FOR INPUT AS 1: LINE INPUT #1, A$: PRINT A$: CLOSE 1',
        '70 CHDIR "..": RMDIR "D2": OPEN "TOP.TXT" FOR OUTPUT AS 1: PRINT #1, "top": CLOSE',
        '80 RMDIR "D1"', '90 CHDIR "NONE"', '100 MKDIR "D1"', '110 RMDIR "NONE"', '120 MKDIR ""',
        '130 CHDIR 0', '140 RMDIR', '150 KILL ""', '160 CHDIR "D1\\..\\D1": PRINT "back"',
        '800 END', '900 PRINT "E"; ERR; ERL: RESUME NEXT']) + "\n"
    ours, theirs, our_tree, their_tree = both(source, tmp_path)
    assert ours == theirs
    assert our_tree == their_tree
    assert our_tree["D1/G.TXT"] == b"in d1\r\n\x1a" and "D2" not in our_tree
    assert "E 75  80" in ours and "E 76  90" in ours and "E 22  140" in ours


def test_files_shows_the_folder_entered(tmp_path):
    (tmp_path / "SUB").mkdir()
    (tmp_path / "SUB" / "IN.TXT").write_bytes(b"x")
    out = yaseer_run('10 CHDIR "SUB": FILES\n', tmp_path)
    assert out.startswith("C:\\SUB\n") and "IN      .TXT" in out


@pytest.mark.parametrize("statement", [
    'CHDIR ".."', 'CHDIR "SUB\\..\\.."', 'MKDIR "..\\OUT"', 'MKDIR "/tmp/yaseer-out"', 'MKDIR "C:\\OUT"',
    'CHDIR "LINK"', 'MKDIR "LINK\\NEW"', 'RMDIR "LINK"', 'RMDIR "..\\OUTSIDE"',
    'CHDIR "SUB": MKDIR "..\\..\\OUT"', 'CHDIR "SUB": OPEN "..\\..\\OUT.TXT" FOR OUTPUT AS 1',
    'CHDIR "SUB": KILL "..\\..\\OUTSIDE\\KEEP.TXT"', 'CHDIR "SUB": NAME "..\\IN.TXT" AS "..\\..\\OUT.TXT"',
    'CHDIR "SUB": RMDIR "..\\SUB"', 'CHDIR "SUB": RMDIR "."', 'RMDIR "SUB"',
])
def test_no_directory_word_leads_out_of_the_directory(tmp_path, statement):
    box, outside = tmp_path / "box", tmp_path / "outside"
    box.mkdir()
    outside.mkdir()
    (outside / "KEEP.TXT").write_bytes(b"keep")
    (box / "SUB").mkdir()
    (box / "SUB" / "X.TXT").write_bytes(b"x")
    (box / "IN.TXT").write_bytes(b"in")
    (box / "LINK").symlink_to(outside)
    before = {str(p): (p.is_symlink(), p.is_dir() and not p.is_symlink()) for p in tmp_path.rglob("*")}
    out = yaseer_run(f"10 {statement}\n", box)
    assert out.endswith(" in 10\n") and ("Path/File access error" in out or "Path not found" in out)
    after = {str(p): (p.is_symlink(), p.is_dir() and not p.is_symlink()) for p in tmp_path.rglob("*")}
    assert after == before  # nothing made, removed or renamed anywhere
    assert (outside / "KEEP.TXT").read_bytes() == b"keep" and not Path("/tmp/yaseer-out").exists()


def test_a_link_inside_leads_to_its_folder(tmp_path):
    (tmp_path / "SUB").mkdir()
    (tmp_path / "INSIDE").symlink_to(tmp_path / "SUB")
    assert yaseer_run('10 CHDIR "INSIDE": OPEN "F" FOR OUTPUT AS 1: CLOSE: CHDIR "..": FILES "F"\n', tmp_path) \
        .startswith("C:\\\nFile not found in 10")
    assert (tmp_path / "SUB" / "F").read_bytes() == b"\x1a"


def test_casio_has_no_directory_words(tmp_path):
    assert "Unsupported word MKDIR" in yaseer_run('10 MKDIR "A"\n', tmp_path, "casio")
    assert not os.listdir(tmp_path)


def test_output_to_a_name_open_in_another_folder_is_file_already_open(tmp_path):
    # GIODSK.ASM CHKFOP compares the FCBs' names, which hold no folder (PC-BASIC's recorded
    # FileNameExclusion test); INPUT of the same name elsewhere is no error
    source = ('10 ON ERROR GOTO 900\n20 MKDIR "D": OPEN "D\\O.TXT" FOR OUTPUT AS 1: CLOSE\n'
              '30 OPEN "O.TXT" FOR OUTPUT AS 1\n40 OPEN "D\\O.TXT" FOR OUTPUT AS 2\n'
              '50 OPEN "D\\O.TXT" FOR INPUT AS 2: PRINT EOF(2)\n800 END\n900 PRINT "E"; ERR; ERL: RESUME NEXT\n')
    ours, theirs, our_tree, their_tree = both(source, tmp_path)
    assert ours == theirs == "E 55  40 \n-1 \n"
    assert our_tree == their_tree
