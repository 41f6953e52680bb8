"""Fuzzing the file statements (issue 12): random OPEN / PRINT # / WRITE # / INPUT # /
LINE INPUT # / INPUT$ / EOF / LOF / LOC / CLOSE / KILL / NAME / FILES programs, and the
random-access files' OPEN ... LEN / FIELD / GET / PUT / LSET / RSET / RESET, and
CHAIN / MERGE / COMMON / SAVE (,A ,P) / LOAD (,R) / RUN "file" / LIST to a file, OPEN with
ACCESS and LOCK clauses, with
names that try to leave the directory (absolute, ``..``, a symbolic link out), run in
both dialects.  Each ends normally or with a BASIC error line, and no file ever
appears, changes or disappears outside the program's directory.

``YASEER_FUZZ_EXAMPLES`` sets the number of programs (60 by default).
"""

from __future__ import annotations

import io
import os

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

NAMES = ["A.TXT", "B", "c.dat", "sub/x", "../up.txt", "../outside/victim.txt", "/tmp/yaseer-fuzz-abs",
         "link/victim.txt", "loop", "..", ".", "", "a:b", "link", "inside_link", "fifo", "sub/../A.TXT",
         "L" * 255, "sub/" + "M" * 250, "\xe9" * 200, "sub", "hard", "CAS0:A.TXT", "LIB0:victim"]
# (a FIFO, the longest plain part, 400 UTF-8 bytes, a hard link to the file outside, devices)
MODES = ['"O"', '"I"', '"A"', '"R"', '"X"']
VALUES = ['1', '-2.5', '"s"', '"a,b"', 'X', 'A$', '1E300']


def statement(data) -> str:
    name = '"' + data.draw(st.sampled_from(NAMES)) + '"'
    other = '"' + data.draw(st.sampled_from(NAMES)) + '"'
    n = data.draw(st.sampled_from(["1", "2", "3", "0", "4", "#1", "#2"]))
    number = n.lstrip("#")
    value = data.draw(st.sampled_from(VALUES))
    choices = [
        f"OPEN {data.draw(st.sampled_from(MODES))}, {n}, {name}",
        f"OPEN {name} FOR {data.draw(st.sampled_from(['INPUT', 'OUTPUT', 'APPEND']))} AS {n}",
        f"PRINT #{number}, {value}; {value}", f"PRINT #{number}, USING \"##.#\"; 1.25",
        f"WRITE #{number}, {value}, {value}", f"INPUT #{number}, X, A$", f"LINE INPUT #{number}, A$",
        f"A$ = INPUT$(2, #{number})", f"X = EOF({number}) + LOF({number}) + LOC({number})",
        f"CLOSE {n}", "CLOSE", f"KILL {name}", f"NAME {name} AS {other}",
        f"WIDTH #{number}, {data.draw(st.sampled_from(['1', '10', '0', '255', '256']))}",
        f"PRINT #{number}, CHR$(13); CHR$(10); CHR$(28); STRING$(250, 65); TAB(5); 1",
        f"FILES {name}", "FILES",
        # random-access files
        f"OPEN {name} AS {n} LEN = {data.draw(st.sampled_from(['1', '16', '0', '40000']))}",
        f"OPEN {name} FOR RANDOM AS {n}", f"OPEN \"R\", {n}, {name}, 8", f"FIELD {n}, 4 AS A$, 2 AS B$",
        f"GET {n}, {data.draw(st.sampled_from(['1', '3', '0', '32768']))}", f"PUT {n}", f"GET {n}",
        f"LSET A$ = {value}", f"RSET B$ = {value}", "RESET",
        # programs read from files (the chained program is this one again, or a file there)
        f"CHAIN {name}", f"CHAIN MERGE {name}, 999, ALL", f"MERGE {name}", "COMMON A$, X",
        f"SAVE {name}", f"SAVE {name}, A", f"LOAD {name}", "LIST", "DELETE 10-20", "NEW",
        f"SAVE {name}, P", f"RUN {name}", f"LOAD {name}, R", f"CHAIN {name}, 10, ALL, DELETE 10-20",
        f"LIST , {name}", f"LIST 10-20, {name}",
        # OPEN's ACCESS and LOCK clauses (gw; casio: Syntax error)
        f"OPEN {name} FOR {data.draw(st.sampled_from(['INPUT', 'OUTPUT', 'APPEND', 'RANDOM']))}"
        f"{data.draw(st.sampled_from(['', ' ACCESS READ', ' ACCESS WRITE', ' ACCESS READ WRITE']))}"
        f"{data.draw(st.sampled_from(['', ' SHARED', ' LOCK READ', ' LOCK WRITE', ' LOCK READ WRITE', ' LOCK']))} AS {n}",
        # the Casio's data bank and program files (gw: a Syntax error)
        f"NEW#: WRITE# {value}: SAVE# {name}", f"LOAD# {name}", f"GOSUB {name}",
        # strings at the limit
        'A$ = STRING$(255, "Q")', f"A$ = A$ + {value}",
    ]
    return data.draw(st.sampled_from(choices))


def arena(tmp_path_factory):
    """(root, box, outside): the program's directory ``box`` with a subdirectory, a link
    out to ``outside`` (which holds a file to protect), a link inside and a link loop."""
    root = tmp_path_factory.mktemp("fuzzfiles")
    box, outside = root / "box", root / "outside"
    box.mkdir()
    outside.mkdir()
    (outside / "victim.txt").write_bytes(b"keep\r\n")
    (box / "sub").mkdir()
    (box / "link").symlink_to(outside)
    (box / "inside_link").symlink_to(box / "A.TXT")
    (box / "loop").symlink_to(box / "loop")
    os.mkfifo(box / "fifo")  # refused at once, never waited on
    os.link(outside / "victim.txt", box / "hard")  # its bytes are outside's too: never written
    return root, box, outside


def snapshot(root) -> dict:
    """Every path under ``root`` (links not followed) with its bytes (files) or target (links)."""
    found = {}
    for folder, dirs, files in os.walk(root):
        for entry in dirs + files:
            path = os.path.join(folder, entry)
            if os.path.islink(path):
                found[path] = "->" + os.readlink(path)
            elif os.path.isfile(path):
                with open(path, "rb") as handle:
                    found[path] = handle.read()
            else:
                found[path] = "dir"
    return found


@settings(max_examples=int(os.environ.get("YASEER_FUZZ_EXAMPLES", 60)), deadline=None, derandomize=True,
          database=None, suppress_health_check=list(HealthCheck))
@given(data=st.data())
def test_file_statements_never_touch_anything_outside_the_directory(data, tmp_path_factory):
    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.machine import Machine

    root, box, outside = arena(tmp_path_factory)
    before_outside, before_root = snapshot(outside), set(os.listdir(root))
    lines = [f"{10 * (k + 1)} {statement(data)}" for k in range(data.draw(st.integers(1, 12)))]
    source = "5 ON ERROR GOTO 1000\n" + "\n".join(lines) + "\n999 END\n1000 RESUME NEXT\n"
    dialect = data.draw(st.sampled_from(["casio", "gw"]))
    machine = Machine(screen=io.StringIO(), dialect=dialect, files=box, input_stream=io.StringIO(""))
    machine.load(source)
    try:
        machine.run()
    except BasicError as err:
        assert "Internal error" not in str(err), source
    assert snapshot(outside) == before_outside, source
    assert set(os.listdir(root)) == before_root, source
    assert not os.path.exists("/tmp/yaseer-fuzz-abs"), source


@settings(max_examples=int(os.environ.get("YASEER_FUZZ_EXAMPLES", 60)) // 2, deadline=None, derandomize=True,
          database=None, suppress_health_check=list(HealthCheck))
@given(commands=st.lists(st.tuples(st.sampled_from(["SAVE", "LOAD", "FILES", "RUN"]), st.sampled_from(NAMES)),
                         min_size=1, max_size=6))
def test_session_save_load_files_stay_in_the_directory(commands, tmp_path_factory):
    """The interactive session's SAVE, LOAD, FILES and RUN "file" with the same hostile names."""
    from yaseer.session import MachineEngine, Session

    root, box, outside = arena(tmp_path_factory)
    before_outside, before_root = snapshot(outside), set(os.listdir(root))
    shown: list[str] = []
    session = Session(write=shown.append, engine=MachineEngine(shown.append, files=box), directory=box)
    session.handle('10 OPEN "O", 1, "prog.out": PRINT #1, 1: CLOSE')
    for command, name in commands:
        session.handle(f'{command} "{name}"')
    assert snapshot(outside) == before_outside, commands
    assert set(os.listdir(root)) == before_root, commands
    assert not any("Internal error" in text or "Traceback" in text for text in shown), shown
