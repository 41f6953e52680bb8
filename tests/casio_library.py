"""Manfred Becker's program library for the Casio FX-850P/880P, run on yaseer's casio dialect.

The library (142 programs; github urbancamo/casio-basic, folder
src/main/basic/MB-Casio-Basic-Library/sources) is not part of this repository: point
``YASEER_CASIO_LIBRARY`` at a local copy of that ``sources`` folder.  Without it this
script prints one line and exits 0.

    YASEER_CASIO_LIBRARY=/path/to/sources python tests/casio_library.py [-v] [PROGRAM ...]

For every program it counts (1) whether every line parses (no ``Syntax error`` and no
``Unsupported word``: the program *loads*; the lines a program holds as deliberate errors,
:data:`DELIBERATE_LINES`, are stored by the machine as every line is and so do not stop it
loading), and (2) whether it runs with its key script
(tests/casio_library/keys.txt, our own inputs) to its first result: ``yaseer run
--input KEYS --files LIBRARY PROGRAM`` shows a screen that matches the script's result
pattern, and stops with no error line other than ``Input past end`` (the key script is
over: the program was waiting for the next key, as it does on the machine).
Each run is a process of its own with a time limit (:data:`SECONDS`).  A program the machine
itself stops at RUN (:data:`OWN_ERROR`) is counted as doing what the machine does when it stops
with the machine's error; the summary names it and the evidence, and every other program that
does not load or run is listed as a failure.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
KEYS = HERE / "casio_library" / "keys.txt"
ENVIRONMENT = "YASEER_CASIO_LIBRARY"
SECONDS = 20
NOT_PROGRAMS = {"LIB_INFO.BAS"}  # the library's table of contents, not a program
# A number after "=" on a screen line that is not a prompt (prompts end with "?"): how the
# library's programs show a result.
DEFAULT_RESULT = r"(?m)^(?!.*\?\s*$).*=\s*-?\.?\d"
# Keys for a program without a script of its own: a menu's first choice, then 2 for each number.
DEFAULT_KEYS = "1" + "2\n" * 8
END_OF_KEYS = "Input past end"
# Programs that end in an error of their own when RUN: LIB0900 is the BASIC program behind the
# PB commands (PBLOAD, PBLOAD ALL, PBLOAD#, PBGET; PBLOAD_PBGET.md names its work variables a-y
# and a$-p$, which its lines 110-120 clear but for j and l$).  It reads the command typed (the two-byte
# codes of PBLOAD or PBGET at address 512) and, where the command is none of its forms,
# executes ``a`` (lines 220, 260, 300, 2150, 2230; ``READ`` alone in 735 and 6040): a
# statement of no format, stored as every line is and the SN error when it runs (part 6,
# "Errors": a syntax error is reported as the line executes).  RUN typed is no PB command,
# so the machine stops at line 220 with its SN error; nothing of the copy is damaged.
# PROGRAM -> the error line the run must stop with; counted apart, neither loaded nor run.
OWN_ERROR = {"LIB0900": "Syntax error in 220"}
# PROGRAM -> the lines that do not parse on purpose: LIB0900's ``a`` statements and its
# ``READ$`` (READ with no variable), each an SN error only when the run reaches it (part 6
# "Errors"); the machine stores a line as typed, so LOAD takes the program whole.  A program
# loads when the lines yaseer cannot read are exactly these.
DELIBERATE_LINES = {"LIB0900": (220, 260, 300, 735, 2150, 2230, 6040)}
# Hardware self-tests that never wait for a key once a test fails: the first result on the
# screen, then the program's own endless failure beep (LIB0400 shows the RAM size, then reads
# bytes the system keeps at the top of the RAM, which the manual does not document (PEEK.md,
# POKE.md and DEFSEG.md give only the addressing), then the ROM, the printer, the RS-232C
# port and the cassette); run for ENDLESS_SECONDS: it runs to its first result without an
# error line, and the summary says that yaseer cannot follow it further.
ENDLESS = {"LIB0400"}
# (5 s was too short on a loaded machine: at a load of 7 the first screen came later.)
ENDLESS_SECONDS = 15


def library() -> Path | None:
    """The library's ``sources`` folder (``YASEER_CASIO_LIBRARY``), or None."""
    where = os.environ.get(ENVIRONMENT)
    return Path(where) if where and Path(where).is_dir() else None


def programs(folder: Path) -> list[Path]:
    return sorted(p for p in folder.iterdir() if p.suffix.lower() == ".bas" and p.name.upper() not in NOT_PROGRAMS)


def key_scripts(path: Path = KEYS) -> dict[str, tuple[str, str]]:
    """PROGRAM -> (keys, result pattern) from the key-script file.

    One program a line: ``NAME | keys | pattern``; in keys ``\\n`` is EXE (a line
    break) and other backslash escapes are Python's (``\\x1f``: the cursor-down key); an
    empty pattern is the default (a number after ``=`` on a line that is no prompt).  ``#``
    starts a comment line.  A program without a line gets :data:`DEFAULT_KEYS`.  Keys
    ``@CALLER keys``: a subprogram is run by its caller (LIBS6210 by LIB6210's
    ``GOSUB "LIB0:S6210"``) with those keys."""
    scripts = {}
    for raw in path.read_text(encoding="utf-8").splitlines():
        if not raw.strip() or raw.lstrip().startswith("#"):
            continue
        name, keys, pattern = (part.strip() for part in raw.split("|", 2))
        scripts[name.upper()] = (keys.encode("latin-1", "backslashreplace").decode("unicode_escape"),
                                 pattern or DEFAULT_RESULT)
    return scripts


def syntax_errors(program: Path) -> list[str]:
    """The lines of ``program`` that do not parse, as ``line: error``."""
    from yaseer.basic.dialects.charset import CASIO as CHARACTERS
    from yaseer.basic.dialects.dialect import CASIO
    from yaseer.basic.source.parser import parse_line
    from yaseer.basic.source.scanner import split_lines

    text = CHARACTERS.program_text(program.read_bytes()).replace("\r\n", "\n")
    errors = []
    for number, statement, _ in split_lines(text):
        line = parse_line(number, statement, CASIO)
        if line.error is not None:
            errors.append(f"{number}: {line.error}")
    return errors


def run(program: Path, keys: str, folder: Path, extra: tuple = (), seconds: float = SECONDS) -> tuple[str, str, int]:
    """(standard output, standard error, status) of ``yaseer run`` with ``keys``; a run
    that outlasts ``seconds`` is stopped (status -1)."""
    with tempfile.TemporaryDirectory() as scratch:
        key_file = Path(scratch) / "keys.txt"
        key_file.write_text(keys, encoding="utf-8")
        try:
            done = subprocess.run([sys.executable, "-m", "yaseer", "run", "--input", str(key_file),
                                   "--files", str(folder), *extra, str(program)],
                                  capture_output=True, text=True, timeout=seconds, cwd=str(HERE.parent))
        except subprocess.TimeoutExpired as late:
            out = late.stdout.decode() if isinstance(late.stdout, bytes) else (late.stdout or "")
            return out, f"timed out after {seconds} s", -1
    return done.stdout, done.stderr, done.returncode


def verdict(stdout: str, stderr: str, status: int, pattern: str) -> str | None:
    """None when the run reached its result without an error line; else what went wrong."""
    lines = [line for line in stderr.splitlines() if line.strip()]
    errors = [line for line in lines if not line.startswith(END_OF_KEYS)]
    if status < 0:
        return stderr
    if errors:
        return errors[0]
    if not re.search(pattern, stdout):
        return f"no result matching {pattern!r} on the screen"
    return None


def main(argv: list[str]) -> int:
    folder = library()
    if folder is None:
        print(f"casio library: skipped ({ENVIRONMENT} is not set to the library's sources folder)")
        return 0
    verbose = "-v" in argv
    wanted = {a.upper().removesuffix(".BAS") for a in argv if not a.startswith("-")}
    scripts = key_scripts()
    chosen = [p for p in programs(folder) if not wanted or p.stem.upper() in wanted]
    loaded = ran = own_error = endless = deliberate = 0
    failures = []
    for program in chosen:
        name = program.stem.upper()
        errors = syntax_errors(program)
        if errors and sorted(int(e.split(":")[0]) for e in errors) == sorted(DELIBERATE_LINES.get(name, ())):
            errors, deliberate = [], deliberate + 1  # its own SN lines, as the machine stores them
        if not errors:
            loaded += 1
        keys, pattern = scripts.get(name, (DEFAULT_KEYS, DEFAULT_RESULT))
        runs = program
        if keys.startswith("@"):  # a subprogram: run by the program that calls it (GOSUB "LIB0:...")
            caller, _, keys = keys[1:].partition(" ")
            runs = folder / f"{caller}.bas"
        if name in OWN_ERROR:
            stdout, stderr, status = run(runs, keys, folder)
            first = next((line for line in stderr.splitlines() if line.strip()), "")
            problem = None if first == OWN_ERROR[name] else f"expected {OWN_ERROR[name]!r}, got {first!r}"
            own_error += problem is None
        elif name in ENDLESS:
            stdout, stderr, status = run(runs, keys, folder, seconds=ENDLESS_SECONDS)
            errors_shown = [line for line in stderr.splitlines() if line.strip() and not line.startswith("timed out")]
            problem = (f"no result matching {pattern!r} on the screen" if not re.search(pattern, stdout)
                       else errors_shown[0] if errors_shown else None)
            endless += problem is None
            ran += problem is None and not errors
        else:
            problem = verdict(*run(runs, keys, folder), pattern)
            if problem is None and not errors:  # a bad line an ON ERROR handler hid is no run
                ran += 1
        if errors or problem:
            failures.append(name)
        if verbose and (errors or problem):
            print(f"{program.name}: {'load: ' + errors[0] + ' ' if errors else ''}"
                  f"{'run: ' + problem if problem else ''}")
    files = sum(1 for p in folder.iterdir() if p.suffix.lower() == ".bas")
    own = ", ".join(f"{k}: {v}" for k, v in OWN_ERROR.items())
    print(f"casio library: {len(chosen)} programs ({files} .bas files, {', '.join(sorted(NOT_PROGRAMS))} the table "
          f"of contents).  Load: {loaded} of {len(chosen)} ({loaded - deliberate} with every line read; "
          f"{deliberate} with only its deliberate SN lines unread, which the machine stores as typed and "
          f"reports when run, part 6 \"Errors\": "
          f"{'; '.join(f'{k} {list(v)}' for k, v in DELIBERATE_LINES.items())}).  "
          f"Run: {ran} of {len(chosen)} reach their first result without an error line "
          f"({endless} of them a hardware self-test that then beeps without end: {', '.join(sorted(ENDLESS))}, "
          f"whose next bytes the manual does not document); "
          f"{own_error} of {len(OWN_ERROR)} stops at RUN with the machine's own error, as the machine does "
          f"({own}: the BASIC program behind PBLOAD/PBGET, PBLOAD_PBGET.md, not one to RUN).  "
          f"Failures: {len(failures)}{' (' + ', '.join(failures) + ')' if failures else ''}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
