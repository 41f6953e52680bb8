"""Every ``yaseer`` command driven as a user drives it: a child process, its exit status, its one error line.

Statuses (the same in every command): 0 success, 1 an error, 2 a wrong command
line, 130 after Ctrl-C.  An error is exactly one line on standard error, never a
traceback.
"""

from __future__ import annotations

import importlib.metadata
import os
import select
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
COMMANDS = ("run", "diff", "plot", "animate", "bench", "stability", "centrode", "report")
RUNNING_COMMANDS = ("run", "diff", "plot", "animate", "report")  # the commands that take the run options


def yaseer(*args: str, cwd: Path | None = None, **options) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "yaseer", *args], capture_output=True, text=True,
                          cwd=cwd or ROOT, timeout=120, **options)


def one_error_line(done: subprocess.CompletedProcess, status: int) -> str:
    """The single line on stderr of a command that ended with ``status``."""
    assert done.returncode == status, (done.returncode, done.stderr)
    lines = done.stderr.splitlines()
    assert len(lines) == 1, done.stderr
    assert "Traceback" not in done.stderr
    return lines[0]


@pytest.fixture
def listing(tmp_path) -> Path:
    path = tmp_path / "two.bas"
    path.write_text("10 FOR I = 1 TO 3: PRINT I; I * I: NEXT\n")
    return path


# ---------------------------------------------------------------- the command line


def test_version_is_the_installed_distributions():
    done = yaseer("--version")
    assert done.returncode == 0
    assert done.stdout == f"yaseer {importlib.metadata.version('yaseer')}\n"


def test_top_level_help_names_every_command_and_the_session():
    done = yaseer("--help")
    assert done.returncode == 0
    for command in COMMANDS:
        assert f"\n    {command}" in done.stdout
    assert "`yaseer` alone to open the interactive pocket-computer session" in done.stdout.replace("\n", " ")


def test_method_help_lists_every_programs_methods_from_the_registry():
    from yaseer.binding import LINKAGES
    from yaseer.linkages.registry import method_names

    for command in RUNNING_COMMANDS:
        shown = " ".join(yaseer(command, "--help").stdout.split())
        for number, linkage in LINKAGES.items():
            names = method_names(linkage)
            assert len(names) >= 2
            assert f"{number}: " in shown
            for name in names:
                assert name in shown, (command, number, name)


@pytest.mark.parametrize("command", COMMANDS)
def test_an_unknown_option_prints_that_commands_usage(command, listing, tmp_path):
    operands = {"run": [str(listing)], "plot": [str(listing)], "animate": [str(listing)], "report": [str(listing)], "report": [str(listing)],
                "diff": [str(listing), str(tmp_path / "t.csv")]}.get(command, [])
    done = yaseer(command, *operands, "--no-such-option")
    assert done.returncode == 2
    assert done.stderr.startswith(f"usage: yaseer {command} ")
    assert done.stderr.splitlines()[-1] == f"yaseer {command}: error: unrecognized arguments: --no-such-option"


def test_an_unknown_command_is_a_usage_error():
    done = yaseer("frobnicate")
    assert done.returncode == 2 and "invalid choice: 'frobnicate'" in done.stderr


def test_session_options_written_before_a_command_go_to_the_command(tmp_path):
    # The top-level usage line reads `yaseer [--dialect ...] [--printer FILE] COMMAND`; 1/3 is
    # .3333334 in GW-BASIC's single (as PC-BASIC prints it) and .3333333333 on the pocket computer.
    listing = tmp_path / "third.bas"
    listing.write_text("10 PRINT 1/3\n20 LPRINT 2/3\n")
    printer = tmp_path / "printer.txt"
    before = yaseer("--dialect", "gw", f"--printer={printer}", "run", str(listing))
    assert (before.returncode, before.stdout, before.stderr) == (0, " .3333334 \n", "")
    assert printer.read_text() == " .6666667 \n"
    assert yaseer("run", str(listing)).stdout.startswith(" .3333333333 ")
    refused = yaseer("--width", "40", "run", str(listing))
    assert refused.returncode == 2
    assert refused.stderr.splitlines()[-1] == "yaseer run: error: unrecognized arguments: --width=40"


def test_run_dash_reads_the_listing_from_standard_input():
    done = yaseer("run", "-", input="10 PRINT 6 * 7\n")
    assert (done.returncode, done.stdout, done.stderr) == (0, " 42 \n", "")


def test_run_of_a_basic_only_listing_imports_no_numerics(listing):
    code = ("import sys; from yaseer.cli import main; status = main(['run', sys.argv[1]]); "
            "print(sorted(m for m in ('numpy', 'matplotlib', 'yaseer.commands.plot') if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", code, str(listing)], capture_output=True, text=True, check=True)
    assert done.stdout.splitlines()[-1] == "[]"


# ---------------------------------------------------------------- the run options, in every command


@pytest.mark.parametrize("command", RUNNING_COMMANDS)
@pytest.mark.parametrize("prog, says", [("12=x.bas", "program areas are 1-9"),
                                        ("0=x.bas", "area 0 is the listing itself")])
def test_prog_outside_areas_1_to_9_is_a_usage_error(command, prog, says, listing):
    done = yaseer(command, str(listing), *(["t.csv"] if command == "diff" else []), "--prog", prog)
    assert done.returncode == 2
    assert done.stderr.startswith(f"usage: yaseer {command} ")
    assert says in done.stderr.splitlines()[-1]


@pytest.mark.parametrize("command", RUNNING_COMMANDS)
@pytest.mark.parametrize("text, says", [("", "the file holds no numbered program lines"),
                                        ("10 PRINT 1\n", "no RETURN, so GOSUB PROG 5 could never come back")])
def test_an_area_file_without_lines_or_return_is_refused_naming_it(command, text, says, listing, tmp_path):
    area = tmp_path / "area.bas"
    area.write_text(text)
    table = tmp_path / "t.csv"
    table.write_text("1,1\n")
    done = yaseer(command, str(listing), *([str(table)] if command == "diff" else []), "--prog", f"5={area}",
                  cwd=tmp_path)
    assert one_error_line(done, 1) == f"yaseer {command}: --prog 5={area}: {says}"
    assert done.stdout == ""


def test_unknown_method_is_a_usage_error_naming_the_known_ones(listing):
    done = yaseer("run", str(listing), "--method", "5=fast")
    assert done.returncode == 2
    assert done.stderr.splitlines()[-1] == ("yaseer run: error: argument --method: unknown method 'fast' for PROG 5 "
                                            "(known: polar, paper)")


# ---------------------------------------------------------------- output that cannot be written


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full")
def test_a_full_printer_or_standard_output_is_one_line(tmp_path):
    listing = tmp_path / "p.bas"
    listing.write_text("10 LPRINT 1: PRINT 2\n")
    assert one_error_line(yaseer("run", str(listing), "--printer", "/dev/full"), 1) == \
        "yaseer run: /dev/full: No space left on device"
    with open("/dev/full", "w") as full:
        done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(listing)], stdout=full,
                              stderr=subprocess.PIPE, text=True, cwd=ROOT)
    assert one_error_line(done, 1) == "yaseer run: standard output: No space left on device"


def test_a_closed_standard_output_is_one_line(listing):
    done = subprocess.run(f'"{sys.executable}" -m yaseer run "{listing}" >&-', shell=True, capture_output=False,
                          stderr=subprocess.PIPE, text=True, cwd=ROOT)
    assert one_error_line(done, 1) == "yaseer: standard output is closed"


def test_a_reader_going_away_stops_quietly(tmp_path):
    listing = tmp_path / "many.bas"
    listing.write_text("10 FOR I = 1 TO 100000: PRINT I: NEXT\n")
    child = subprocess.Popen([sys.executable, "-m", "yaseer", "run", str(listing)], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, cwd=ROOT)
    assert child.stdout.readline() == b" 1 \n"
    child.stdout.close()
    status = child.wait(timeout=60)
    assert (status, child.stderr.read()) == (0, b"")


@pytest.mark.parametrize("command", ["bench", "stability"])
def test_out_that_cannot_be_made_a_directory_is_one_line(command, tmp_path):
    done = yaseer(command, "--out", "/proc/nope/x")
    assert one_error_line(done, 1).startswith(f"yaseer {command}: --out /proc/nope/x: cannot create the directory: ")
    occupied = tmp_path / "occupied.csv"
    occupied.write_text("a file")
    done = yaseer(command, "--out", str(occupied))
    assert one_error_line(done, 1) == (f"yaseer {command}: --out {occupied}: is a file; --out names a directory "
                                       "here (several files are written)")


def test_animate_frame_without_png_is_a_usage_error(listing, tmp_path):
    done = yaseer("animate", str(listing), "--out", str(tmp_path / "a.gif"), "--frame", "3")
    assert one_error_line(done, 2) == ("yaseer animate: --frame chooses the frame of a .png; "
                                       f"{tmp_path / 'a.gif'} is a whole animation")
    assert list(tmp_path.iterdir()) == [listing]


# ---------------------------------------------------------------- diff's table


def test_diff_of_a_binary_table_is_one_line(tmp_path):
    program, table = tmp_path / "p.csv", tmp_path / "t.txt"
    program.write_text("0,1\n")
    table.write_bytes(b"\x89PNG\r\n\x1a\n\0\0\0")
    assert one_error_line(yaseer("diff", str(program), str(table)), 1) == \
        f"yaseer diff: bad table {table}: not a text table (it holds binary data)"


def test_diff_reads_a_latin1_table(tmp_path):
    program, table = tmp_path / "p.csv", tmp_path / "t.txt"
    program.write_text("0,1.5\n30,2.5\n")
    table.write_bytes("angle,\xb0 lift\n0,1.5\n30,2.5\n".encode("latin-1"))
    done = yaseer("diff", str(program), str(table))
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines()[-1].startswith("AGREE: 2 rows matched")


# ---------------------------------------------------------------- Ctrl-C


def _interrupted(args: list[str], started, cwd: Path) -> subprocess.CompletedProcess:
    """Start ``yaseer ARGS``, wait until ``started(child)`` says it is running, send SIGINT; its outcome."""
    child = subprocess.Popen([sys.executable, "-m", "yaseer", *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, cwd=cwd)
    try:
        deadline = time.monotonic() + 60
        while not started(child):
            assert child.poll() is None, child.communicate()
            assert time.monotonic() < deadline, "the command never started"
            time.sleep(0.05)
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=60)
    finally:
        if child.poll() is None:
            child.kill()
            child.wait()
    return subprocess.CompletedProcess(args, child.returncode, out, err)


def test_ctrl_c_in_run_is_break_in_the_line_running(tmp_path):
    """Output appears on the pipe once the machine has printed a buffer full: it is running the loop."""
    listing = tmp_path / "loop.bas"
    listing.write_text("10 I = I + 1\n20 PRINT I\n30 GOTO 10\n")

    def started(child) -> bool:
        return bool(select.select([child.stdout], [], [], 0)[0])

    line = one_error_line(_interrupted(["run", str(listing)], started, tmp_path), 130)
    assert line in ("Break in 10", "Break in 20", "Break in 30")


@pytest.mark.parametrize("command", ["diff", "plot", "animate", "report"])
def test_ctrl_c_while_a_listing_waits_for_input(command, tmp_path):
    """The listing reads INPUT from a FIFO: once the FIFO is opened the run has started; nothing is written."""
    listing = tmp_path / "ask.bas"
    listing.write_text("10 PRINT 1; 2\n20 INPUT A\n30 PRINT A; 3\n")
    fifo = tmp_path / "answers"
    os.mkfifo(fifo)
    writer = []

    def started(child) -> bool:  # the FIFO's write end opens once the run is opening its read end
        try:
            writer.append(os.open(fifo, os.O_WRONLY | os.O_NONBLOCK))
        except OSError:
            return False
        return True

    extra = {"diff": ["t.csv"], "plot": ["--out", "pictures"], "animate": ["--out", "a.gif"],
             "report": ["--out", "page.html"]}[command]
    (tmp_path / "t.csv").write_text("1,2\n")
    try:
        done = _interrupted([command, str(listing), *extra, "--input", str(fifo)], started, tmp_path)
    finally:
        for descriptor in writer:
            os.close(descriptor)
    assert one_error_line(done, 130) == f"yaseer {command}: interrupted (Ctrl-C)"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["answers", "ask.bas", "t.csv"]


@pytest.mark.parametrize("command", ["bench", "stability"])
def test_ctrl_c_during_a_long_command(command, tmp_path):
    out = tmp_path / "out"
    done = _interrupted([command, "--out", str(out)], lambda child: out.exists(), tmp_path)
    assert one_error_line(done, 130) == f"yaseer {command}: interrupted (Ctrl-C)"


def test_the_readmes_commands_write_only_where_they_say():
    """A README command that writes files names the place (--out); run and diff write nothing."""
    import re

    writers = ("plot", "animate", "report", "bench", "stability", "centrode")
    commands = re.findall(r"(?:^|\$ |bin/)yaseer (\w+)([^\n`#]*)", (ROOT / "README.md").read_text(), re.MULTILINE)
    shown = [(name, rest) for name, rest in commands if name in writers and not rest.strip().startswith("[")]
    assert {name for name, _ in shown} >= {"plot", "bench", "stability"}
    for name, rest in shown:
        assert "--out" in rest, f"yaseer {name}{rest}"
