"""Nothing outside the program's directory is created or changed, even while another process
swaps the names the programs use for links that lead out (a check-then-use race).

One process runs BASIC programs again and again for a few seconds: a GW-BASIC one that
writes sequential files (OUTPUT, APPEND, one in a subdirectory), a random file (PUT),
NAMEs and KILLs one, MERGEs and CHAINs nothing it cannot read, and ends with SAVE; a Casio
one that writes through ``CAS0:`` and SAVE#s its data bank.  Meanwhile a second process
replaces each of those names, again and again, by a symbolic link to a file outside, by a
hard link to a file outside, by a link to a name outside that does not exist yet, and by a
plain file again (each replacement atomic, ``os.replace``); the subdirectory becomes a link
to the outside directory and back.  Afterwards the outside holds exactly what it held
before: the same names, the same bytes.
"""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

SWAP_SECONDS = 4.0

# name in the program's directory -> the file outside its link leads to (None: a name that
# does not exist outside, so following the link would create it)
NAMES = ("T.TXT", "A.TXT", "R.DAT", "N.TXT", "M.TXT", "P.BAS", "BANK", "C.TXT")

SWAPPER = textwrap.dedent("""
    import os, sys, time
    box, outside, seconds = sys.argv[1], sys.argv[2], float(sys.argv[3])
    names = sys.argv[4:]
    deadline = time.monotonic() + seconds
    swaps = 0

    def put(make, name):
        temporary = os.path.join(box, ".swap")
        try:
            make(temporary)
            os.replace(temporary, os.path.join(box, name))
        except OSError:
            try:
                os.unlink(temporary)
            except OSError:
                pass

    def plain(temporary):
        with open(temporary, "w") as handle:
            handle.write("in")

    while time.monotonic() < deadline:
        for name in names:
            put(lambda t: os.symlink(os.path.join(outside, name), t), name)  # a link to a file outside
            put(plain, name)
            put(lambda t: os.link(os.path.join(outside, name), t), name)  # the outside file's inode
            put(plain, name)
            put(lambda t: os.symlink(os.path.join(outside, "new-" + name), t), name)  # would create it
            put(plain, name)
        try:  # the subdirectory: a link to the outside directory, then a directory again
            os.symlink(outside, os.path.join(box, ".sublink"))
            os.rename(os.path.join(box, "sub"), os.path.join(box, ".subdir"))
            os.replace(os.path.join(box, ".sublink"), os.path.join(box, "sub"))
            os.unlink(os.path.join(box, "sub"))
            os.rename(os.path.join(box, ".subdir"), os.path.join(box, "sub"))
        except OSError:
            pass
        swaps += 1
    print(swaps)
""")

GW_PROGRAM = """\
10 ON ERROR GOTO 100
20 FOR I = 1 TO 20
30 OPEN "O", 1, "T.TXT": PRINT #1, "OUT": CLOSE 1
40 OPEN "A", 2, "A.TXT": PRINT #2, "APPENDED": CLOSE 2
50 OPEN "O", 3, "sub/S.TXT": PRINT #3, "SUB": CLOSE 3
60 OPEN "R", 1, "R.DAT", 16: FIELD #1, 16 AS F$: LSET F$ = "RANDOM": PUT #1, 3: CLOSE 1
70 OPEN "O", 1, "N.TXT": PRINT #1, "N": CLOSE 1: NAME "N.TXT" AS "M.TXT": KILL "M.TXT"
80 NEXT
90 SAVE "P.BAS"
100 IF ERL = 90 THEN END ELSE RESUME 80
"""

CASIO_PROGRAM = """\
10 ON ERROR GOTO 100
20 FOR I = 1 TO 20
30 NEW#: WRITE# "BANKED", I: SAVE# "CAS0:BANK"
40 OPEN "CAS0:C.TXT" FOR OUTPUT AS #1: PRINT #1, "CASIO": CLOSE
50 NEXT
60 END
100 RESUME 50
"""

RUNNER = textwrap.dedent("""
    import sys, time
    import yaseer
    box, seconds, gw, casio = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
    deadline = time.monotonic() + seconds
    runs = 0
    while time.monotonic() < deadline:
        for program, dialect in ((gw, "gw"), (casio, "casio")):
            result = yaseer.run(program, dialect=dialect, files=box)
            assert "Internal" not in (result.error or ""), result.error
            runs += 1
    print(runs)
""")


def snapshot(directory: Path) -> dict:
    return {str(p.relative_to(directory)): (p.read_bytes() if p.is_file() and not p.is_symlink() else "other")
            for p in sorted(directory.rglob("*"))}


@pytest.mark.skipif(not hasattr(os, "O_NOFOLLOW"), reason="no O_NOFOLLOW on this system")
def test_swapping_links_in_never_lets_a_write_out(tmp_path):
    box, outside = tmp_path / "box", tmp_path / "outside"
    (box / "sub").mkdir(parents=True)
    outside.mkdir()
    for name in NAMES + ("S.TXT",):
        (outside / name).write_bytes(b"keep " + name.encode() + b"\r\n")
    before = snapshot(outside)
    runner = subprocess.Popen([sys.executable, "-c", RUNNER, str(box), str(SWAP_SECONDS + 0.5), GW_PROGRAM,
                               CASIO_PROGRAM], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        swapper = subprocess.run([sys.executable, "-c", SWAPPER, str(box), str(outside), str(SWAP_SECONDS), *NAMES],
                                 capture_output=True, text=True, timeout=120)
    finally:
        out, err = runner.communicate(timeout=120)
    assert swapper.returncode == 0, swapper.stderr
    assert int(swapper.stdout) > 10  # it did swap, many times
    assert runner.returncode == 0, err
    assert int(out) > 4  # the programs ran, several times over
    assert snapshot(outside) == before


def test_a_hard_link_swapped_back_between_open_and_check_is_not_written(tmp_path, monkeypatch):
    """The one interleaving the race above hits only now and then, made certain: the name
    is a hard link to a file outside when it is opened, and a plain file again (the outside
    file back to one name) before the link count is checked."""
    import yaseer
    from yaseer.basic.machine import sandbox

    box, outside = tmp_path / "box", tmp_path / "outside"
    box.mkdir()
    outside.mkdir()
    (outside / "N.TXT").write_bytes(b"keep\r\n")
    os.link(outside / "N.TXT", box / "N.TXT")
    real_open = os.open

    def open_then_swap_back(path, flags, *args, **kwargs):
        descriptor = real_open(path, flags, *args, **kwargs)
        if path == "N.TXT" and not flags & os.O_CREAT:
            (box / ".plain").write_bytes(b"in")
            os.replace(box / ".plain", box / "N.TXT")
        return descriptor

    monkeypatch.setattr(sandbox.os, "open", open_then_swap_back)
    result = yaseer.run('10 OPEN "O", 1, "N.TXT": PRINT #1, "OUT": CLOSE 1\n', dialect="gw", files=str(box))
    monkeypatch.undo()
    assert (outside / "N.TXT").read_bytes() == b"keep\r\n"
    assert "Path/File access error" in (result.error or result.text)
