"""How many programs recorded on real GW-BASIC yaseer reproduces byte for byte.

PC-BASIC's own test suite (github robhagemans/pcbasic, folder tests/basic) keeps, for each
test, a program (TEST.BAS), the interpreter's settings (PCBASIC.INI) and, in ``model/``, the
files the program wrote when it ran on a real IBM PC under GW-BASIC.  This script runs each
such program in ``yaseer run --dialect gw --files DIR`` in a scratch copy of its folder and
compares every model file with the file of that name yaseer's run left (names compared
without case, as on DOS).  Nothing of the suite is kept in this repository: point the
script at a local copy.

Only tests that fit what ``yaseer run`` is (a program run to its end with no keys typed on
a text screen) are counted: those whose settings run TEST.BAS and quit, with no keystrokes,
no other machine (Tandy, PCjr), no program loaded for typing, no video memory settings.
A test reads as passed when every model file matches.

    python tools/recorded_gw.py ~/pcbasic/tests/basic [--only gwbasic] [--list failed]

Prints the counts per folder and, with ``--list``, each test's verdict and the first
line of yaseer's error output.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
from collections import Counter
from pathlib import Path

# settings that make a test something other than a GW-BASIC program run to its end
OTHER_MACHINE = ("syntax", "preset", "video", "video-memory", "load", "keys", "input", "exec", "reserved-memory",
                 "allow-code-poke", "hide-protected", "lpt1", "ctrl-c-break")
SCRATCH_FOLDERS = {"model", "known", "accepted", "output"}


def settings(folder: Path) -> dict[str, str]:
    """PCBASIC.INI's ``key=value`` lines (comments and the section line left out)."""
    found = {}
    for line in (folder / "PCBASIC.INI").read_text(errors="replace").splitlines():
        line = line.strip()
        if "=" in line and not line.startswith(("#", ";", "[")):
            key, value = line.split("=", 1)
            found[key.strip().lower()] = value.strip()
    return found


def runnable(folder: Path) -> bool:
    """A program yaseer run can stand for: TEST.BAS run and quit, nothing typed, GW's own machine."""
    if not (folder / "PCBASIC.INI").is_file() or not (folder / "model").is_dir():
        return False
    found = settings(folder)
    return (found.get("run", "").upper() == "TEST.BAS" and found.get("quit", "").lower() == "true"
            and not any(key in found for key in OTHER_MACHINE))


def run_one(folder: Path, timeout: float) -> tuple[bool, str]:
    """(every model file matched, the first line yaseer wrote on standard error or a note)."""
    with tempfile.TemporaryDirectory(prefix="recorded_gw_") as scratch:
        work = Path(scratch) / "run"
        work.mkdir()
        # the settings file stays out, but for a test whose real machine had it in its
        # directory (its model/ holds it: LockFiles, built on another machine)
        ini_recorded = (folder / "model" / "PCBASIC.INI").is_file()
        for item in folder.iterdir():
            if item.name.lower() in SCRATCH_FOLDERS or (item.name == "PCBASIC.INI" and not ini_recorded):
                continue
            if item.is_file():
                shutil.copyfile(item, work / item.name)
            elif item.is_dir():
                shutil.copytree(item, work / item.name)
        program = next((p for p in work.iterdir() if p.name.upper() == "TEST.BAS"), None)
        if program is None:
            return False, "no TEST.BAS"
        command = [sys.executable, "-c", "from yaseer.entry import main; main()", "run", "--dialect", "gw",
                   "--files", str(work), str(program)]
        try:
            done = subprocess.run(command, cwd=work, stdin=subprocess.DEVNULL, capture_output=True,
                                  timeout=timeout, env={**os.environ, "YASEER_CACHE_DIR": str(Path(scratch) / "cache")})
        except subprocess.TimeoutExpired:
            return False, f"timed out after {timeout:g} s"
        error = next((line for line in done.stderr.decode(errors="replace").splitlines() if line.strip()), "")
        left = {p.name.upper(): p for p in work.iterdir() if p.is_file()}
        for model in sorted((folder / "model").iterdir()):
            if not model.is_file():
                continue
            ours = left.get(model.name.upper())
            if ours is None:
                return False, error or f"{model.name} not written"
            if ours.read_bytes() != model.read_bytes():
                return False, error or f"{model.name} differs"
        return True, error


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("corpus", type=Path, help="a copy of PC-BASIC's tests/basic folder")
    parser.add_argument("--only", nargs="*", default=None, help="only these folders (e.g. gwbasic unsorted)")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds a program may run (default 30)")
    parser.add_argument("--list", choices=("all", "failed"), default=None, help="print each test's verdict")
    parser.add_argument("--tests", nargs="*", default=None, help="only tests with these names (e.g. SWAP FORERR)")
    args = parser.parse_args(argv)
    if not args.corpus.is_dir():
        print(f"recorded_gw: no folder {args.corpus}", file=sys.stderr)
        return 1
    groups = sorted(p for p in args.corpus.iterdir() if p.is_dir() and (args.only is None or p.name in args.only))
    total_passed = total_run = 0
    causes: Counter = Counter()
    for group in groups:
        tests = sorted(p for p in group.iterdir()
                       if p.is_dir() and runnable(p) and (args.tests is None or p.name in args.tests))
        passed = 0
        for test in tests:
            ok, note = run_one(test, args.timeout)
            passed += ok
            if not ok:
                causes[note.split(" in ")[0][:60]] += 1
            if args.list == "all" or args.list == "failed" and not ok:
                print(f"  {'pass' if ok else 'FAIL'} {group.name}/{test.name}: {note}")
        if args.tests is not None and not tests:
            continue
        skipped = sum(1 for p in group.iterdir() if p.is_dir()) - len(tests)
        print(f"{group.name}: {passed} of {len(tests)} reproduced ({skipped} other tests not run)")
        total_passed += passed
        total_run += len(tests)
    print(f"all: {total_passed} of {total_run} reproduced byte for byte")
    if causes:
        print("most common first error lines of the failures:")
        for note, count in causes.most_common(15):
            print(f"  {count:4} {note}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
