"""SAVE "f",P: GW-BASIC's protected program files, written as GWMAIN.ASM CRUNCH tokenises
the lines (machine/program_crunch.py) and GIODSK.ASM PENCOD scrambles them
(program_file.protect), against PC-BASIC 2.0.8: the file PC-BASIC saves with ,P is
byte for byte yaseer's for generated lines, each loads and runs the other's file, and a
program loaded from a protected file is not shown (LIST, EDIT, a SAVE other than ,P, a
line typed: Illegal function call, GIODSK.ASM PROCHK), in the session and in a program.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest

from single_digits_support import SourceDigitsSession
from test_differential_programgen import random_program
from test_differential_support import base_seed, case_count, clean_output

from yaseer.basic.machine.program_crunch import crunch_line
from yaseer.basic.machine.program_file import program_text, protect, unprotect
from yaseer.session import MachineEngine, Session

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


@pytest.fixture(scope="module")
def pc(tmp_path_factory):
    """A PC-BASIC session on drive C: (a fresh directory) that hides protected programs as
    GW-BASIC does: (session, directory)."""
    import pcbasic

    directory = tmp_path_factory.mktemp("pcbasic")
    session = pcbasic.Session(output_streams=None, input_streams=None, hide_protected=True,
                              devices={"C:": str(directory)}, current_device="C:")
    session.start()
    yield SourceDigitsSession(session), directory  # singles print the source's digits (LIST: FOUT)
    session.close()


def gw_session(directory: Path) -> tuple[Session, list]:
    shown: list[str] = []
    engine = MachineEngine(shown.append, dialect="gw", files=directory)
    return Session(write=shown.append, engine=engine, directory=directory, dialect="gw"), shown


def typed(session: Session, shown: list, lines) -> str:
    """What the session shows for ``lines`` typed one after the other."""
    shown.clear()
    for line in lines:
        session.handle(line)
    return "".join(shown)


# Pieces of statements that reach every rule of CRUNCH: numbers of each type and size,
# &H/&O, line numbers after the words that take them (and not after a name), names in
# lower case with digits and dots, keywords of the one- and two-byte tables, words that
# are names because a letter follows them, ELSE, ', REM, DATA with quotes, WHILE, ?,
# GO TO / GO SUB, operators and runs of blanks.
def _number(rng: random.Random) -> str:
    """A number literal; a double's value is exact in binary (a double with an inexact
    decimal fraction is read by $FIN's rounding, which is another test's subject)."""
    return rng.choice([
        str(rng.randint(0, 9)), str(rng.randint(10, 255)), str(rng.randint(256, 32767)),
        str(rng.randint(32768, 9999999)), str(rng.randint(10 ** 7, 10 ** 15)),
        f"{rng.randint(0, 999)}.{rng.randint(0, 9999)}", f".{rng.randint(1, 99999)}",
        f"{rng.randint(1, 99)}E{rng.choice(['', '+', '-'])}{rng.randint(0, 30)}",
        f"{rng.randint(1, 99)}D{rng.randint(0, 15)}", f"{rng.randint(0, 999)}#",
        f"{rng.randint(0, 999)}!", f"{rng.randint(0, 999)}%", f"{rng.randint(10 ** 7, 10 ** 12)}.{rng.choice(['5', '25', '125', '375'])}",
        f"&H{rng.randint(0, 65535):X}", f"&O{rng.randint(0, 65535):o}", f"&h{rng.randint(0, 255):x}",
    ])


def _name(rng: random.Random) -> str:
    name = rng.choice(["a", "B", "xy", "Cnt2", "r.s", "TOTAL", "fori", "printer", "GOTOX", "ab12"])
    return name + rng.choice(["", "", "%", "!", "#"])


def _expression(rng: random.Random) -> str:
    parts = [rng.choice([_number(rng), _name(rng), f"SIN({_number(rng)})", f"len(\"ab\")",
                         f"CVI(MKI$({_number(rng)}))", f"FNa({_name(rng)})", "TIMER*0", "ERR"])]
    for _ in range(rng.randint(0, 3)):
        parts.append(rng.choice(["+", "-", "*", "/", "^", "\\", " MOD ", " AND ", " OR ", "<", ">", "=", "<=", "<>"]))
        parts.append(rng.choice([_number(rng), _name(rng)]))
    return rng.choice([" ", "", "  "]).join(parts)


def _statement(rng: random.Random) -> str:
    line = rng.randint(1, 65529)
    return rng.choice([
        f"PRINT {_expression(rng)};{_expression(rng)}", f"? {_expression(rng)}", f"{_name(rng)}={_expression(rng)}",
        f"GOTO {line}", f"GO TO {line}", f"GO SUB {line}", f"gosub {line}", f"ON {_name(rng)} GOTO {line},{line}, {line}",
        f"IF {_expression(rng)} THEN {line} ELSE {line}", f"IF {_name(rng)} THEN PRINT 1 ELSE PRINT 2",
        f"RESTORE {line}", f"RESUME {line}", f"LIST {line}-{line}", f"OPTION BASE 1", f"DIM {_name(rng)}(20)",
        f"REM   a remark: PRINT 1 \"x", f"' note GOTO 10", f"DATA 1, two ,\"3:4\", 5", f"WHILE {_name(rng)}<3",
        "WEND", f"FOR I={_number(rng)} TO {_number(rng)} STEP 2: NEXT I", f"A$=\"PRINT \" + STRING$(3, \"*\")",
        f"x = {_expression(rng)} : y=2", f"DEF FNa(x)={_expression(rng)}", f"LOCATE 1,1: COLOR 7", f"RETURN {line}",
        f"PRINT USING \"##.#\";{_number(rng)}", f"POKE {_number(rng)},1", f"LINE INPUT \"a\";S$",
    ])


def generated_lines(rng: random.Random) -> dict[int, str]:
    numbers = sorted(rng.sample(range(1, 65530), rng.randint(1, 8)))
    return {n: ": ".join(_statement(rng) for _ in range(rng.randint(1, 3))) for n in numbers}


def listing(lines: dict[int, str]) -> str:
    return "\n".join(f"{n} {text}" for n, text in sorted(lines.items()))


def pc_saved(pc, source: str, name: str) -> bytes:
    session, directory = pc
    session.execute("NEW")
    session.execute(source)
    session.execute(f'SAVE "{name}",P')
    return (directory / f"{name}.BAS").read_bytes()


def test_the_scrambling_is_the_inverse_of_the_reading():
    data = bytes(random.Random(base_seed()).randrange(256) for _ in range(1000))
    assert unprotect(protect(data)) == data and protect(data) != data


def test_crunch_stores_each_kind_of_token_as_gw_basic_does():
    """Hand-checked against GWMAIN.ASM CRUNCH (the byte values of IBMRES.ASM's tables)."""
    assert crunch_line("PRINT 5") == bytes((0x91, 0x20, 0x16))
    assert crunch_line("a=300: GOTO 20") == b"A\xe7\x1c\x2c\x01: \x89 \x0e\x14\x00"
    assert crunch_line("OPTION BASE 1") == b"\xb8 BASE 1"  # after a name a digit stays text
    assert crunch_line("IF X THEN 5 ELSE 6") == b"\x8b X \xcd \x0e\x05\x00 :\xa1 \x0e\x06\x00"
    assert crunch_line("FORI=1TO9") == b"FORI\xe7\x12TO9"  # FOR and TO: a letter or digit follows, names
    assert crunch_line("X=1:'hi") == b"X\xe7\x12::\x8f\xd9hi"
    assert crunch_line("WHILE 1") == b"\xb1\xe9 \x12"
    assert crunch_line("?CHR$(65)") == b"\x91\xff\x96(\x0f\x41)"


def test_a_file_saved_with_p_is_byte_for_byte_pc_basics(pc, tmp_path):
    rng = random.Random(base_seed() + 1024)
    session, shown = gw_session(tmp_path)
    for k in range(case_count(60)):
        lines = generated_lines(rng)
        theirs = pc_saved(pc, listing(lines), f"GEN{k}")
        typed(session, shown, ["NEW"] + [f"{n} {t}" for n, t in sorted(lines.items())] + [f'SAVE "MINE{k}",P'])
        mine = (tmp_path / f"MINE{k}.bas").read_bytes()
        assert mine == theirs, listing(lines)


def test_each_runs_the_others_protected_file(pc, tmp_path):
    """Generated programs (the differential tests' generator): PC-BASIC runs yaseer's
    protected file as yaseer runs PC-BASIC's, and neither shows it."""
    pc_session, pc_directory = pc
    rng = random.Random(base_seed() + 1025)
    session, shown = gw_session(tmp_path)
    for k in range(case_count(8)):
        source = random_program(rng).source().rstrip("\n")
        theirs = pc_saved(pc, source, f"RUN{k}")
        (tmp_path / f"THEIRS{k}.BAS").write_bytes(theirs)
        typed(session, shown, ["NEW"] + source.split("\n") + [f'SAVE "MINE{k}",P'])
        (pc_directory / f"MINE{k}.BAS").write_bytes((tmp_path / f"MINE{k}.bas").read_bytes())
        pc_session.execute("NEW")
        pc_output = clean_output(pc_session.execute(f'RUN "MINE{k}"'))
        ours = typed(session, shown, [f'LOAD "THEIRS{k}"', "RUN"])
        assert ours == pc_output, source
        assert "Illegal function call" in clean_output(pc_session.execute("LIST"))
        assert typed(session, shown, ["LIST"]) == "Illegal function call\n"


def test_a_protected_program_is_not_shown_in_the_session(pc, tmp_path):
    source = '10 PRINT "HI"\n20 A=2: PRINT A*3'
    (tmp_path / "SECRET.BAS").write_bytes(pc_saved(pc, source, "SECRET"))
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ['LOAD "SECRET"']) == ""
    for refused in ("LIST", "LIST 10", "LLIST", "EDIT 10", 'SAVE "X"', 'SAVE "X",A', "30 PRINT 3"):
        assert typed(session, shown, [refused]) == "Illegal function call\n", refused
    assert typed(session, shown, ["RUN"]) == "HI\n 6 \n"
    assert typed(session, shown, ['SAVE "AGAIN",P']) == ""  # ,P may save it again, still protected
    assert (tmp_path / "AGAIN.bas").read_bytes() == (tmp_path / "SECRET.BAS").read_bytes()
    assert typed(session, shown, ["NEW", "10 PRINT 1", "LIST"]) == "10 PRINT 1\n"  # NEW ends it


def test_a_protected_program_does_not_list_itself(pc, tmp_path):
    """A protected program's own LIST and SAVE stop it as GW-BASIC's do (PC-BASIC agrees);
    a program that LOADs a protected file refuses to LIST it too."""
    pc_session, pc_directory = pc
    source = '10 PRINT "A"\n20 LIST\n30 PRINT "B"'
    data = pc_saved(pc, source, "SELF")
    (tmp_path / "SELF.BAS").write_bytes(data)
    pc_session.execute("NEW")
    theirs = clean_output(pc_session.execute('RUN "SELF"'))
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ['RUN "SELF"']) == theirs == "A\nIllegal function call in 20\n"
    (tmp_path / "SAVER.BAS").write_bytes(pc_saved(pc, '10 SAVE "PLAIN"', "SAVER"))
    assert typed(session, shown, ['RUN "SAVER"']) == "Illegal function call in 10\n"
    assert program_text(data) == "10 PRINT \"A\"\r\n20 LIST\r\n30 PRINT \"B\"\r\n"  # as LIST writes it to a file


def test_a_program_saves_itself_protected_as_pc_basic_does(pc, tmp_path):
    """... and goes on after it (GIODSK.ASM PROSAV returns through GTMPRT)."""
    source = '10 A=1.5: B%=-300\n20 SAVE "ITSELF",P\n30 PRINT "goes on"'
    pc_session, pc_directory = pc
    pc_session.execute("NEW")
    pc_session.execute(source)
    pc_session.execute("RUN")
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ["NEW"] + source.split("\n") + ["RUN"]) == "goes on\n"
    assert (tmp_path / "ITSELF.BAS").read_bytes() == (pc_directory / "ITSELF.BAS").read_bytes()


def test_a_program_that_loads_a_protected_file_leaves_it_protected(pc, tmp_path):
    (tmp_path / "INNER.BAS").write_bytes(pc_saved(pc, '10 PRINT "inner"', "INNER"))
    session, shown = gw_session(tmp_path)
    assert typed(session, shown, ['10 LOAD "INNER"', "RUN", "LIST"]) == "Illegal function call\n"
    assert typed(session, shown, ["RUN"]) == "inner\n"
