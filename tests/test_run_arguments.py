"""One validation of a run's arguments: what the command line refuses, ``yaseer.run`` and ``%%basic`` refuse.

Each wrong argument is tried in the API (an ``ArgumentError``, a ValueError with
one line), in the command line (a usage error or an error naming the file) and
where it exists in the magic (IPython's one-line UsageError, no traceback), and
a run with a wrong argument never starts (nothing printed).
"""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

import yaseer
from yaseer.run_arguments import ArgumentError

LISTING = "10 PRINT 7\n"


@pytest.mark.parametrize("arguments, says", [
    ({"prog": {0: "10 RETURN\n"}}, "area 0 is the listing itself"),  # once replaced the listing silently
    ({"prog": {10: "10 RETURN\n"}}, "program areas are 1-9, got 10"),  # once ignored
    ({"prog": {-1: "10 RETURN\n"}}, "program areas are 1-9, got -1"),
    ({"prog": {True: "10 RETURN\n"}}, "program areas are the numbers 1-9"),
    ({"prog": {5: "10 PRINT 1\n"}}, "prog 5: no RETURN, so GOSUB PROG 5 could never come back"),
    ({"prog": {5: "\n"}}, "prog 5: the file holds no numbered program lines"),
    ({"angle": "grad"}, "angle is one of deg, rad, not 'grad'"),
    ({"angle": 1}, "angle is one of deg, rad"),
    ({"output_format": "xml"}, "output_format is one of text, csv, not 'xml'"),
    ({"dialect": 3}, "a dialect is one of casio, gw, not 3"),  # once an AttributeError
    ({"dialect": "pascal"}, "unknown dialect 'pascal'"),
    ({"method": {5: "fast"}}, "unknown method 'fast' for PROG 5 (known: polar, paper)"),
    ({"method": {7: "polar"}}, "no library program 7 to choose a method for"),
    ({"files": 3}, "files is the path of a directory, not int 3"),
])
def test_the_api_refuses_what_the_command_line_refuses(arguments, says):
    screen = []

    class Screen:
        def write(self, text):
            screen.append(text)

        def flush(self):
            pass

    with pytest.raises(ArgumentError, match=re.escape(says)) as raised:
        yaseer.run(LISTING, screen=Screen(), **arguments)
    assert "\n" not in str(raised.value) and screen == []
    assert isinstance(raised.value, ValueError)


def test_files_naming_a_file_or_nothing_is_refused(tmp_path):
    plain = tmp_path / "plain.txt"
    plain.write_text("x")
    with pytest.raises(ArgumentError, match="plain.txt: not a directory"):
        yaseer.run(LISTING, files=plain)
    with pytest.raises(ArgumentError, match="nowhere: no such directory"):
        yaseer.run(LISTING, files=str(tmp_path / "nowhere"))
    assert yaseer.run(LISTING, files=tmp_path).text == " 7 \n"


def test_right_arguments_still_run():
    result = yaseer.run("10 GOSUB PROG 5\n20 PRINT 8\n", prog={5: "10 PRINT 6: RETURN\n"}, angle="rad",
                        output_format="text", dialect="gw", method={5: "paper"})
    assert result.error is None and result.text == " 6 \n 8 \n"


def test_the_command_line_names_the_same_problem(tmp_path):
    """The wrong --files and --prog texts give the messages the API gives."""
    listing = tmp_path / "l.bas"
    listing.write_text(LISTING)
    plain = tmp_path / "plain.txt"
    plain.write_text("x")
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(listing), "--files", str(plain)],
                          capture_output=True, text=True)
    assert (done.returncode, done.stderr) == (1, f"yaseer run: --files {plain}: not a directory\n")
    area = tmp_path / "area.bas"
    area.write_text("10 PRINT 1\n")
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(listing), "--prog", f"5={area}"],
                          capture_output=True, text=True)
    assert (done.returncode, done.stderr) == (
        1, f"yaseer run: --prog 5={area}: no RETURN, so GOSUB PROG 5 could never come back\n")


@pytest.mark.parametrize("option, says", [("--fps 0", "Frames per second must be a positive number"),
                                          ("--fps nan", "Frames per second must be a positive number"),
                                          ("--size 100000x100000", "A frame size must be from 160x120"),
                                          ("--max-frames 1", "at least 2 frames")])
def test_animate_refuses_what_the_magic_refuses(option, says, tmp_path):
    listing = tmp_path / "l.bas"
    listing.write_text(LISTING)
    done = subprocess.run([sys.executable, "-m", "yaseer", "animate", str(listing), *option.split()],
                          capture_output=True, text=True, cwd=tmp_path)
    assert done.returncode == 2 and says in done.stderr.splitlines()[-1] and "Traceback" not in done.stderr
    assert list(tmp_path.iterdir()) == [listing]


IPython = pytest.importorskip("IPython", reason="the magic needs yaseer[jupyter] (IPython)")


@pytest.fixture(scope="module")
def shell():
    from IPython.testing.globalipapp import get_ipython, start_ipython

    ip = start_ipython() or get_ipython()  # one shell per process: another module may have started it
    ip.run_line_magic("load_ext", "yaseer")
    return ip


@pytest.mark.parametrize("line, says", [
    ("--fps 0", "Frames per second must be a positive number"),  # once a ZeroDivisionError
    ("--fps -3", "Frames per second must be a positive number"),
    ("--size 100000x100000", "A frame size must be from 160x120"),  # once a MemoryError
    ("--size 10x10", "A frame size must be from 160x120"),
    ("--max-frames 0", "at least 2 frames"),
    ("--prog 0=x.bas", "area 0 is the listing itself"),
    ("--prog 12=x.bas", "program areas are 1-9"),
    ("--method 2=bogus", "unknown method 'bogus' for PROG 2"),
    ("--dialect 3", "unknown dialect '3'"),
])
def test_the_magic_refuses_with_one_line(shell, line, says, capsys):
    from IPython.core.error import UsageError

    shell.user_ns.pop("_basic", None)
    with pytest.raises(UsageError, match=says):
        shell.run_cell_magic("basic", line + " --animate", LISTING)
    assert "_basic" not in shell.user_ns and capsys.readouterr().out == ""


def test_the_magic_refuses_an_area_without_return(shell, tmp_path):
    from IPython.core.error import UsageError

    area = Path(tmp_path / "area.bas")
    area.write_text("10 PRINT 1\n")
    with pytest.raises(UsageError, match="prog 5: no RETURN"):
        shell.run_cell_magic("basic", f"--prog 5={area}", LISTING)
