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
Each run is a process of its own with a time limit (:data:`SECONDS`); a key script may also
give the line typed that starts the program (``--typed``, the machine's input buffer).  A
program that stops at a device yaseer does not have (:data:`ABSENT_DEVICE`) and a self-test
that beeps without end after its first result (:data:`ENDLESS`, stopped once that result is
on the screen) are counted apart and named in the summary; every other program that does not
load or run is listed as a failure.  LIB_INFO.bas, a text in the folder that the manual's list
does not hold, is checked to be no program.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
KEYS = HERE / "casio_library" / "keys.txt"
ENVIRONMENT = "YASEER_CASIO_LIBRARY"
SECONDS = 20
# The manual's list of the library (part-11-scientific-library.md) holds 141 programs; the
# folder's 142nd .bas file, LIB_INFO.bas, is not in it: a plain text (the table of contents,
# in German, without line numbers), which no LOAD reads as a program.  The measurement checks
# that it is such a text and counts it apart.
NOT_PROGRAMS = {"LIB_INFO.BAS"}
LISTED = 141
# A number after "=" on a screen line that is not a prompt (prompts end with "?"): how the
# library's programs show a result.
DEFAULT_RESULT = r"(?m)^(?!.*\?\s*$).*=\s*-?\.?\d"
# Keys for a program without a script of its own: a menu's first choice, then 2 for each number.
DEFAULT_KEYS = "1" + "2\n" * 8
END_OF_KEYS = "Input past end"
# Programs that stop where they reach a device yaseer does not have: LIB0900 is the BASIC
# program behind the PB commands (PBLOAD, PBLOAD ALL, PBLOAD#, PBGET; PBLOAD_PBGET.md names
# its work variables a-y and a$-p$).  It reads the command typed from the input buffer (the
# key script's typed line, ``yaseer run --typed``: PBLOAD), then opens the PB-100 series' tape
# (PMT0:) for the files on it, and shows nothing before it has read one.  yaseer has no such
# tape (the manual documents neither the device nor the tape's format), so the run ends there
# with one line naming the device.  PROGRAM -> that line.
ABSENT_DEVICE = {"LIB0900": "PMT0: (the PB-100 series' tape) is not emulated in 460"}
# PROGRAM -> the lines that do not parse on purpose: LIB0900's ``READ$`` (READ with no
# variable) in 6040, an SN error only when the run reaches it (part 6 "Errors"); the machine
# stores a line as typed, so LOAD takes the program whole.  (Its ``a`` statements are IF
# branches, the error only when their branch runs: casio.BRANCH_ERRORS_WHEN_REACHED.)  A
# program loads when the lines yaseer cannot read are exactly these.
DELIBERATE_LINES = {"LIB0900": (6040,)}
# Hardware self-tests that never wait for a key once a test fails: the first result on the
# screen, then the program's own endless failure beep.  LIB0400 shows the RAM size, then reads
# the bytes at the top of the RAM (&H7FFF down to &H7F7F: it expects &H20 and &H80 there
# without having POKEd them) and the ROM (DEFSEG=&H4000), which the manual does not document
# (PEEK.md, POKE.md and DEFSEG.md give only the addressing); yaseer's RAM holds 0 there, so
# the test says NG RAM 2 and beeps without end.  The measurement stops the run as soon as its
# first result is on the screen (at most ENDLESS_SECONDS).
ENDLESS = {"LIB0400"}
ENDLESS_SECONDS = 30


def library() -> Path | None:
    """The library's ``sources`` folder (``YASEER_CASIO_LIBRARY``), or None."""
    where = os.environ.get(ENVIRONMENT)
    return Path(where) if where and Path(where).is_dir() else None


def programs(folder: Path) -> list[Path]:
    return sorted(p for p in folder.iterdir() if p.suffix.lower() == ".bas" and p.name.upper() not in NOT_PROGRAMS)


def key_scripts(path: Path = KEYS) -> dict[str, tuple[str, str, str]]:
    """PROGRAM -> (keys, result pattern, typed line) from the key-script file.

    One program a line: ``NAME | keys | pattern [| typed: line]``; in keys ``\\n`` is EXE (a
    line break) and other backslash escapes are Python's (``\\x1f``: the cursor-down key); an
    empty pattern is the default (a number after ``=`` on a line that is no prompt).  The
    typed line is the command typed at the prompt that starts the program (default ``RUN``;
    ``yaseer run --typed``: the machine's input buffer).  ``#`` starts a comment line.  A
    program without a line gets :data:`DEFAULT_KEYS`.  Keys ``@CALLER keys``: a subprogram
    is run by its caller (LIBS6210 by LIB6210's ``GOSUB "LIB0:S6210"``) with those keys."""
    scripts = {}
    for raw in path.read_text(encoding="utf-8").splitlines():
        if not raw.strip() or raw.lstrip().startswith("#"):
            continue
        name, keys, rest = (part.strip() for part in raw.split("|", 2))
        typed = re.search(r"\|\s*typed:(.*)$", rest)  # (a pattern may hold "|" itself)
        pattern = rest[:typed.start()].strip() if typed else rest
        scripts[name.upper()] = (keys.encode("latin-1", "backslashreplace").decode("unicode_escape"),
                                 pattern or DEFAULT_RESULT, typed.group(1).strip() if typed else "RUN")
    return scripts


def not_a_program(text: Path, folder: Path) -> str | None:
    """None when ``text`` is no program: its first line has no line number and ``yaseer run``
    refuses it with one line saying so; else what is wrong."""
    first = next((line for line in text.read_text(encoding="utf-8", errors="replace").splitlines() if line.strip()), "")
    if re.match(r"\s*\d", first):
        return f"its first line has a line number: {first[:40]!r}"
    stdout, stderr, status = run(text, "", folder)
    if status != 1 or "no line number" not in stderr:
        return f"expected LOAD to refuse it (no line number), got status {status}: {stderr.strip()[:80]!r}"
    return None


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
            done = subprocess.run(_command(program, key_file, folder, extra),
                                  capture_output=True, text=True, timeout=seconds, cwd=str(HERE.parent))
        except subprocess.TimeoutExpired as late:
            out = late.stdout.decode() if isinstance(late.stdout, bytes) else (late.stdout or "")
            return out, f"timed out after {seconds} s", -1
    return done.stdout, done.stderr, done.returncode


def _command(program: Path, key_file: Path, folder: Path, extra: tuple) -> list[str]:
    return [sys.executable, "-m", "yaseer", "run", "--input", str(key_file), "--files", str(folder), *extra,
            str(program)]


def run_to_result(program: Path, keys: str, folder: Path, pattern: str, seconds: float,
                  extra: tuple = ()) -> tuple[str, str, int]:
    """As :func:`run`, for a program that never ends by itself: the run is stopped as soon as
    its screen matches ``pattern`` (status 0 and what it wrote to standard error so far: no
    error line), or after ``seconds`` (status -1)."""
    with tempfile.TemporaryDirectory() as scratch:
        key_file = Path(scratch) / "keys.txt"
        key_file.write_text(keys, encoding="utf-8")
        process = subprocess.Popen(_command(program, key_file, folder, extra), stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True, cwd=str(HERE.parent))
        shown: list[str] = []
        reader = threading.Thread(target=lambda: shown.extend(iter(process.stdout.readline, "")), daemon=True)
        reader.start()
        deadline = time.monotonic() + seconds
        while process.poll() is None and time.monotonic() < deadline and not re.search(pattern, "".join(shown)):
            time.sleep(0.05)
        found = re.search(pattern, "".join(shown)) is not None
        if process.poll() is None:
            process.kill()  # the process this function started, by its own handle
        process.wait()
        reader.join(5)
        errors = process.stderr.read()
        process.stdout.close()
        process.stderr.close()
    if process.returncode is not None and process.returncode > 0 and not found:
        return "".join(shown), errors, process.returncode
    return "".join(shown), errors, 0 if found else -1


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
    loaded = ran = absent = endless = deliberate = 0
    failures = []
    for program in chosen:
        name = program.stem.upper()
        errors = syntax_errors(program)
        if errors and sorted(int(e.split(":")[0]) for e in errors) == sorted(DELIBERATE_LINES.get(name, ())):
            errors, deliberate = [], deliberate + 1  # its own SN lines, as the machine stores them
        if not errors:
            loaded += 1
        keys, pattern, typed = scripts.get(name, (DEFAULT_KEYS, DEFAULT_RESULT, "RUN"))
        typing = ("--typed", typed)
        runs = program
        if keys.startswith("@"):  # a subprogram: run by the program that calls it (GOSUB "LIB0:...")
            caller, _, keys = keys[1:].partition(" ")
            runs = folder / f"{caller}.bas"
        if name in ABSENT_DEVICE:
            stdout, stderr, status = run(runs, keys, folder, typing)
            first = next((line for line in stderr.splitlines() if line.strip()), "")
            problem = None if first == ABSENT_DEVICE[name] else f"expected {ABSENT_DEVICE[name]!r}, got {first!r}"
            absent += problem is None
        elif name in ENDLESS:
            stdout, stderr, status = run_to_result(runs, keys, folder, pattern, ENDLESS_SECONDS, typing)
            problem = verdict(stdout, stderr, status, pattern)
            endless += problem is None
            ran += problem is None and not errors
        else:
            problem = verdict(*run(runs, keys, folder, typing), pattern)
            if problem is None and not errors:  # a bad line an ON ERROR handler hid is no run
                ran += 1
        if errors or problem:
            failures.append(name)
        if verbose and (errors or problem):
            print(f"{program.name}: {'load: ' + errors[0] + ' ' if errors else ''}"
                  f"{'run: ' + problem if problem else ''}")
    texts = [p for p in folder.iterdir() if p.name.upper() in NOT_PROGRAMS and (not wanted or p.stem.upper() in wanted)]
    for text in texts:
        problem = not_a_program(text, folder)
        if problem:
            failures.append(text.stem.upper())
            if verbose:
                print(f"{text.name}: {problem}")
    files = sum(1 for p in folder.iterdir() if p.suffix.lower() == ".bas")
    print(f"casio library: {len(chosen)} programs, the {LISTED} the manual lists (part-11-scientific-library.md), "
          f"of {files} .bas files ({', '.join(sorted(NOT_PROGRAMS))}: a text without line numbers, not in the "
          f"manual's list, which LOAD refuses: checked {len(texts)}).  "
          f"Load: {loaded} of {len(chosen)} ({loaded - deliberate} with every line read; "
          f"{deliberate} with only its deliberate SN lines unread, which the machine stores as typed and "
          f"reports when run, part 6 \"Errors\": "
          f"{'; '.join(f'{k} {list(v)}' for k, v in DELIBERATE_LINES.items())}).  "
          f"Run: {ran} of {len(chosen)} reach their first result without an error line "
          f"({endless} of them a hardware self-test stopped after its first result, as it then beeps without "
          f"end on RAM and ROM bytes the manual does not document: {', '.join(sorted(ENDLESS))}); "
          f"{absent} of {len(ABSENT_DEVICE)} reads the command typed (PBLOAD) and stops at a device yaseer "
          f"does not have ({'; '.join(f'{k}: {v}' for k, v in ABSENT_DEVICE.items())}; "
          f"the BASIC program behind PBLOAD/PBGET, PBLOAD_PBGET.md, shows nothing before it reads the tape).  "
          f"Failures: {len(failures)}{' (' + ', '.join(failures) + ')' if failures else ''}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
