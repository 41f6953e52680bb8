"""`yaseer run` shows a line counter on a terminal's stderr when its output goes to a file
and the run takes more than a second; a short run shows none, and the output file never
holds bar characters.  Driven through a real pseudo-terminal."""

from __future__ import annotations

import sys
from pathlib import Path

import pexpect

ROOT = Path(__file__).resolve().parents[1]

# about 150 million loop passes: seconds on any machine (45 million took 0.9 s here), far over the
# one-second delay
SLOW = "10 FOR K = 1 TO 30\n20 FOR J = 1 TO 5000000: A = A + 1: NEXT J\n30 PRINT K\n40 NEXT K\n"
FAST = "10 PRINT 1\n20 PRINT 2\n"


def _run_on_terminal(tmp_path: Path, program: str) -> tuple[str, str]:
    listing, out = tmp_path / "p.bas", tmp_path / "out.txt"
    listing.write_text(program)
    command = f"{sys.executable} -m yaseer run {listing} > {out}"
    terminal = pexpect.spawn("/bin/sh", ["-c", command], cwd=str(ROOT), encoding="utf-8", timeout=120,
                             env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin", "TERM": "xterm"})
    terminal.expect(pexpect.EOF)
    terminal.close()
    assert terminal.exitstatus == 0, terminal.before
    return terminal.before, out.read_text()


def test_long_run_to_a_file_counts_lines_on_the_terminal(tmp_path):
    terminal, output = _run_on_terminal(tmp_path, SLOW)
    assert output.split() == [str(k) for k in range(1, 31)]
    assert "running" in terminal and "line" in terminal
    assert "running" not in output


def test_short_run_shows_no_bar(tmp_path):
    terminal, output = _run_on_terminal(tmp_path, FAST)
    assert output.split() == ["1", "2"]
    assert terminal.strip() == ""
