"""`yaseer run` on mutated listings: one error line, no traceback, no file but the ones named.

A few seeded mutants run as real processes (``python -m yaseer run MUTANT --printer
OUT``) in an empty directory: the exit status is 0 or 1, standard error is empty or
one line naming a line, and afterwards the directory holds only the listing and the
printer file the command named.  A run still going after ``SECONDS`` (a mutant may
loop for ever) gets Ctrl-C and must stop with ``Break``.  ``YASEER_FUZZ_CLI`` sets how
many mutants (default 6).
"""

from __future__ import annotations

import os
import random
import re
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from test_fuzz_listings import ROOT, SEEDS

SECONDS = 3  # a run still going after this long is interrupted
ERROR_LINE = re.compile(r"^.+ in \d+( \(PROG \d+\))?$")


def mutate(rng: random.Random, text: str) -> str:
    """Delete, duplicate or corrupt a few characters (a cheap cousin of the Hypothesis mutations)."""
    for _ in range(rng.randint(1, 4)):
        at = rng.randrange(max(len(text), 1))
        choice = rng.random()
        if choice < 0.4:
            text = text[:at] + text[at + rng.randint(1, 3):]
        elif choice < 0.7:
            text = text[:at] + rng.choice(["9E99", "(((", ":", "GOTO 1", "\x00\xff", "NEXT", '"']) + text[at:]
        else:
            text = text[:at] + text[at:at + 5] + text[at:]
    return text


def cases() -> list[tuple[int, str]]:
    rng = random.Random(int(os.environ.get("YASEER_DIFF_SEED", 2026)))
    count = int(os.environ.get("YASEER_FUZZ_CLI", 6))
    return [(i, mutate(rng, rng.choice(SEEDS))) for i in range(count)]


@pytest.mark.parametrize("index, source", cases(), ids=lambda value: str(value)[:12])
def test_run_command_on_a_mutant(index, source, tmp_path):
    listing = tmp_path / "mutant.bas"
    listing.write_text(source, encoding="latin-1")
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    returncode, stderr = run_with_ctrl_c(tmp_path, env)
    assert returncode in (0, 1), stderr
    assert "Traceback" not in stderr
    lines = stderr.splitlines()
    assert len(lines) <= 1, stderr
    if lines:
        assert ERROR_LINE.match(lines[0]) or lines[0].startswith("Syntax error (no line number"), lines[0]
    assert sorted(path.name for path in tmp_path.iterdir()) == ["mutant.bas", "out.txt"]


def run_with_ctrl_c(workdir: Path, env: dict) -> tuple[int, str]:
    """Run the mutant; a run still going after ``SECONDS`` gets Ctrl-C (SIGINT), as a user would."""
    process = subprocess.Popen(
        [sys.executable, "-m", "yaseer", "run", "mutant.bas", "--printer", "out.txt"],
        cwd=workdir, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
    )
    try:
        _, stderr = process.communicate(timeout=SECONDS)
    except subprocess.TimeoutExpired:
        process.send_signal(signal.SIGINT)
        try:
            _, stderr = process.communicate(timeout=10)
        except subprocess.TimeoutExpired:
            process.kill()
            pytest.fail("the run ignored Ctrl-C")
        assert stderr.startswith("Break"), stderr
    return process.returncode, stderr
