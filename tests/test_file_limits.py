"""Files a program cannot use are BASIC errors at once: FIFOs and other non-regular files are
refused at OPEN, LOAD, CHAIN, MERGE, LOAD# and ``GOSUB "LIB0:label"`` (never waiting for a
writer), a part of a name over 255 bytes is ``Bad file name`` (64) in OPEN, KILL, NAME, SAVE#
and the session's LOAD and SAVE, never an Internal error; a link that leads out of the
directory is refused by every statement that reads or writes a file.  Each run has a watchdog:
a statement that blocks fails the test instead of hanging it."""

from __future__ import annotations

import io
import os
import signal
from contextlib import contextmanager
from pathlib import Path

import pytest

from alarm_support import stop_alarm

from yaseer.basic.errors import BasicError
from yaseer.basic.machine.machine import Machine
from yaseer.session import MachineEngine, Session

LONG = "N" * 256  # one byte over Linux's NAME_MAX


@contextmanager
def watchdog(seconds: int = 5):
    """Fail the test if the body blocks: after ``seconds``, a TimeoutError is raised into it, and
    again every second (a blocked open is interrupted even if the first one is swallowed)."""
    fired = []

    def expired(*_):
        fired.append(True)
        raise TimeoutError("the statement blocked")

    previous = signal.signal(signal.SIGALRM, expired)
    signal.setitimer(signal.ITIMER_REAL, seconds, 1.0)
    try:
        yield
    finally:
        stop_alarm(previous)
    assert not fired, "a statement blocked"


def run(source: str, directory: Path, dialect: str = "gw") -> str:
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect=dialect, files=directory)
    machine.load(source)
    with watchdog():
        try:
            machine.run()
        except BasicError as err:
            return screen.getvalue() + str(err)
    return screen.getvalue()


@pytest.mark.parametrize("dialect", ["gw", "casio"])
@pytest.mark.parametrize("statement", ['OPEN "I", 1, "PIPE"', 'OPEN "O", 1, "PIPE"', 'OPEN "A", 1, "PIPE"'])
def test_a_fifo_is_refused_at_once(tmp_path, statement, dialect):
    os.mkfifo(tmp_path / "PIPE")
    assert run(f"10 {statement}\n", tmp_path, dialect) == "Path/File access error in 10"


def test_a_directory_is_not_a_file(tmp_path):
    (tmp_path / "D").mkdir()
    assert run('10 OPEN "I", 1, "D"\n', tmp_path) == "File not found in 10"
    assert run('10 OPEN "O", 1, "D"\n', tmp_path) == "Path/File access error in 10"


def test_a_hard_link_is_not_written(tmp_path):
    (tmp_path / "A").write_bytes(b"keep")
    os.link(tmp_path / "A", tmp_path / "B")  # two names: one of them could be outside
    assert run('10 OPEN "O", 1, "B": PRINT #1, 1: CLOSE\n', tmp_path) == "Path/File access error in 10"
    assert (tmp_path / "A").read_bytes() == b"keep"
    assert run('10 OPEN "I", 1, "B": LINE INPUT #1, A$: PRINT A$\n', tmp_path) == "keep\n"


WIDE = 'N$ = STRING$(200, 233)'  # 200 characters, 400 bytes in the file system's UTF-8


@pytest.mark.parametrize("statement", ['OPEN "I", 1, N$', 'OPEN "O", 1, N$', "KILL N$", 'NAME N$ AS "B"',
                                       'NAME "A" AS N$', 'OPEN "O", 1, "sub/" + N$ + ".TXT"'])
def test_a_name_part_over_255_bytes_is_bad_file_name(tmp_path, statement):
    (tmp_path / "A").write_bytes(b"x")
    assert run(f"10 {WIDE}: {statement}\n", tmp_path) == "Bad file name in 10"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["A"]


def test_the_error_is_trapped_with_its_number(tmp_path):
    os.mkfifo(tmp_path / "PIPE")
    program = (f'10 ON ERROR GOTO 100: {WIDE}\n20 OPEN "I", 1, N$\n30 OPEN "I", 1, "PIPE"\n40 END\n'
               '100 PRINT ERR;: RESUME NEXT\n')
    assert run(program, tmp_path) == " 64  75 "


def session_says(directory: Path, *lines: str) -> str:
    shown: list[str] = []
    session = Session(write=shown.append, engine=MachineEngine(shown.append, files=directory), directory=directory)
    with watchdog():
        for line in lines:
            session.handle(line)
    return "".join(shown)


def test_the_session_refuses_a_fifo_and_a_long_name(tmp_path):
    os.mkfifo(tmp_path / "PIPE.bas")
    said = session_says(tmp_path, 'LOAD "PIPE"', f'LOAD "{LONG}"', "10 PRINT 1", f'SAVE "{LONG}"', 'SAVE "PIPE"',
                        'RUN "PIPE"')
    assert said.splitlines() == ["Path/File access error", "Bad file name", "Bad file name",
                                 "Path/File access error", "Path/File access error"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["PIPE.bas"]


@pytest.mark.parametrize("statement, dialect", [
    ('CHAIN "PIPE.BAS"', "gw"), ('MERGE "PIPE.BAS"', "gw"), ('LOAD "PIPE.BAS"', "gw"), ('RUN "PIPE.BAS"', "gw"),
    ('LOAD# "PIPE.BAS"', "casio"), ('GOSUB "LIB0:PIPE"', "casio"), ('GOSUB "PIPE:"', "casio"),
])
def test_a_fifo_program_or_bank_is_refused_at_once(tmp_path, statement, dialect):
    os.mkfifo(tmp_path / "PIPE.BAS")
    os.mkfifo(tmp_path / "LIBPIPE.bas")
    assert run(f"10 {statement}\n", tmp_path, dialect) == "Path/File access error in 10"


@pytest.mark.parametrize("statement, dialect", [
    ('CHAIN "OUT.BAS"', "gw"), ('MERGE "OUT.BAS"', "gw"), ('LOAD "OUT.BAS"', "gw"), ('RUN "OUT.BAS"', "gw"),
    ('OPEN "I", 1, "OUT.BAS"', "gw"), ('OPEN "R", 1, "OUT.BAS"', "gw"), ('OPEN "O", 1, "OUT.BAS"', "gw"),
    ('OPEN "A", 1, "OUT.BAS"', "gw"), ('SAVE "OUT.BAS"', "gw"), ('NAME "OUT.BAS" AS "IN.BAS"', "gw"),
    ('KILL "OUT.BAS"', "gw"), ('LOAD# "OUT.BAS"', "casio"), ('SAVE# "CAS0:OUT.BAS"', "casio"),
    ('GOSUB "LIB0:OUT"', "casio"), ('GOSUB "OUT.BAS:"', "casio"), ('OPEN "CAS0:OUT.BAS" FOR OUTPUT AS #1', "casio"),
])
def test_a_link_out_of_the_directory_is_refused_by_every_statement(tmp_path, statement, dialect):
    box, outside = tmp_path / "box", tmp_path / "outside"
    box.mkdir()
    outside.mkdir()
    (outside / "OUT.BAS").write_bytes(b'10 PRINT "SECRET"\r\n')
    (outside / "LIBOUT.bas").write_bytes(b'10 PRINT "SECRET"\r\n')
    (box / "OUT.BAS").symlink_to(outside / "OUT.BAS")
    (box / "LIBOUT.bas").symlink_to(outside / "LIBOUT.bas")
    shown = run(f"10 {statement}\n20 PRINT \"NO\"\n", box, dialect)
    assert shown == "Path/File access error in 10"
    assert (outside / "OUT.BAS").read_bytes() == b'10 PRINT "SECRET"\r\n'
    assert sorted(p.name for p in outside.iterdir()) == ["LIBOUT.bas", "OUT.BAS"]
    assert sorted(p.name for p in box.iterdir()) == ["LIBOUT.bas", "OUT.BAS"]


def test_a_link_inside_the_directory_is_followed(tmp_path):
    (tmp_path / "REAL.TXT").write_bytes(b"INSIDE\r\n")
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "L.TXT").symlink_to("../REAL.TXT")
    (tmp_path / "ALIAS").symlink_to("sub")
    program = '10 OPEN "I", 1, "ALIAS/L.TXT": LINE INPUT #1, A$: CLOSE: PRINT A$\n20 OPEN "A", 1, "sub/L.TXT"\n' \
              '30 PRINT #1, "MORE": CLOSE: KILL "sub/L.TXT"\n'
    assert run(program, tmp_path) == "INSIDE\n"
    assert (tmp_path / "REAL.TXT").read_bytes() == b"INSIDE\r\nMORE\r\n\x1a"
    assert not (tmp_path / "sub" / "L.TXT").is_symlink() and not (tmp_path / "sub" / "L.TXT").exists()


@pytest.mark.skipif(not os.path.exists("/dev/full"), reason="no /dev/full here")
@pytest.mark.parametrize("dialect, number", [("gw", 57), ("casio", 7)])
def test_a_session_printer_that_cannot_be_written_is_device_io_error(tmp_path, dialect, number):
    """``yaseer --printer /dev/full``: LPRINT in a program (trapped: ERR is 57, the Casio's RW
    is 7, then not trapped), LLIST and LPRINT typed are each ``Device I/O error``, once an
    Internal error; the session goes on."""
    import subprocess
    import sys

    typed = ('10 ON ERROR GOTO 100\n20 LPRINT "HELLO"\n30 PRINT "ON": END\n100 PRINT ERR: RESUME NEXT\nRUN\n'
             '5 LPRINT "X"\nRUN\nLLIST\nLPRINT 5\nPRINT 6\nSYSTEM\n')
    done = subprocess.run([sys.executable, "-m", "yaseer", "--dialect", dialect, "--printer", "/dev/full"],
                          input=typed, capture_output=True, text=True, timeout=120, cwd=tmp_path)
    shown = [line.rsplit("> ", 1)[-1] for line in done.stdout.splitlines() if "> " in line]
    shown = [text for text in shown if text][-5:]
    assert shown == [f" {number} ", "Device I/O error in 5", "Device I/O error", "Device I/O error", " 6 "], done.stdout
    assert "ON\n" in done.stdout and "Internal error" not in done.stdout and done.returncode == 0
