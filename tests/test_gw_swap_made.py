"""SWAP whose second variable is a simple variable no statement has made yet is Illegal
function call (BIMISC.ASM SWAP compares ARYTAB around the second PTRGET; the variable
stays made).  A statement makes a variable by assigning it, INPUT, READ, FOR, a DEF FN
parameter or SWAP; an expression that only reads it does not (BIPTRG.ASM SMKVAR: EVAL's
PTRGET returns 0 without making one); CLEAR unmakes them all.  Generated programs
against PC-BASIC 2.0.8, which follows the source here."""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count
from test_gw_files import yaseer_run
from test_gw_language_rules import pc  # noqa: F401 - the module's PC-BASIC session

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def _statement(rng: random.Random) -> str:
    a, b = rng.sample("ABCD", 2)
    s = rng.choice(["", "", "$"])
    value = f'"{a.lower()}"' if s else rng.choice(["0", "1", "2.5"])
    return rng.choice([
        f"SWAP {a}{s},{b}{s}", f"SWAP {a}{s},{b}{s}", f"SWAP {a},E({rng.randint(0, 3)})",
        f"{a}{s}={value}", f"PRINT {a}{s};{b}{s}", f"X=LEN(STR$({a}))", f"READ {a}{s}",
        f"FOR {a}=1 TO 1: NEXT", f"DEF FN{a}({b})={b}*2", f"IF 0 THEN {a}{s}={value}", "CLEAR",
        f"IF 1 THEN {a}{s}={value}",
    ])


def program(rng: random.Random) -> str:
    lines = ["10 ON ERROR GOTO 900"]
    for k in range(rng.randint(2, 6)):
        lines.append(f"{20 + 10 * k} " + ": ".join(_statement(rng) for _ in range(rng.randint(1, 3))))
    lines += ['800 PRINT A;B;C;D;A$;B$;C$;D$: END', '900 PRINT "e";ERR;ERL: RESUME NEXT',
              '910 DATA 7,8,9,1,2,3,4,5,6,7,8,9,1,2,3,4,5,6,7,8,9,1']
    return "\n".join(lines)


@pytest.mark.parametrize("source, expected", [
    ("10 A=2: SWAP A,B: PRINT A;B", "Illegal function call in 10\n"),
    ("10 B=2: SWAP A,B: PRINT A;B", " 2  0 \n"),
    ("10 PRINT B: SWAP A,B", " 0 \nIllegal function call in 10\n"),  # reading B does not make it
    ('10 A$="x": SWAP A$,B$', "Illegal function call in 10\n"),
    ("10 SWAP A,C(3): PRINT A", " 0 \n"),
    ("10 B=0: SWAP A,B: PRINT A;B", " 0  0 \n"),  # made by the assignment, whatever the value
])
def test_swap_needs_its_second_variable_made(pc, tmp_path, source, expected):
    assert yaseer_run(source, tmp_path) == pc.program(source) == expected


def test_generated_programs_swap_as_pcbasic(pc, tmp_path):
    rng = random.Random(base_seed() + 2404)
    for _ in range(case_count(60)):
        source = program(rng)
        assert yaseer_run(source, tmp_path) == pc.program(source), source


def test_direct_lines_make_variables_too(pc):
    from test_gw_direct_types import gw_session, typed

    session, shown = gw_session()
    pc._session.execute("NEW")
    pc.statement("CLEAR")
    for line in ("A=1: SWAP A,B", "B=0", "SWAP A,B: PRINT A;B", "CLEAR", "PRINT C: SWAP A,C", "SWAP A,C: PRINT A;C"):
        assert typed(session, shown, line) == pc.statement(line), line


def _chaining_pair(rng: random.Random) -> tuple[str, str]:
    """A first program that makes some variables (0 or "" among the values), names some
    in COMMON and CHAINs (with ALL or not); a second that SWAPs each of them second."""
    names = ["X", "Y", "Z$", "W"]
    values = {"$": ['""', '"q"'], "": ["0", "1"]}
    made = [f"{n} = {rng.choice(values['$' if n.endswith('$') else ''])}" for n in names if rng.random() < 0.6]
    first = ["10 " + (": ".join(made) or "REM")]
    common = [n for n in names if rng.random() < 0.5]
    if common:
        first.append(f"{rng.choice([5, 20])} COMMON " + ", ".join(common))
    first.append('30 CHAIN "NEXT"' + (", , ALL" if rng.random() < 0.3 else ""))
    second = ["10 ON ERROR GOTO 100"]
    second += [f"{20 + k} SWAP {'A$' if n.endswith('$') else 'A'}, {n}" for k, n in enumerate(names)]
    second += ['90 PRINT "done"; A; A$: END', '100 PRINT "E"; ERR; ERL: RESUME NEXT']
    return "\n".join(sorted(first, key=lambda line: int(line.split()[0]))) + "\n", "\r\n".join(second) + "\r\n"


def test_variables_a_chain_passes_on_made_stay_made_as_pcbasic(tmp_path):
    """CHAIN passes COMMON's variables (with ALL every one) on as they are (FIVEO.ASM
    CHAIN): one the first program made, with 0 or "" too, exists for the second program's
    SWAP; one it named in COMMON but never made does not (PC-BASIC 2.0.8, which follows
    the source).  The first program records those makings (compiler._watched_names)."""
    from test_gw_files import pcbasic_run

    rng = random.Random(base_seed() + 2405)
    for k in range(case_count(30)):
        first, second = _chaining_pair(rng)
        theirs, ours = tmp_path / f"p{k}", tmp_path / f"y{k}"
        for directory in (theirs, ours):
            directory.mkdir()
            (directory / "NEXT.BAS").write_text(second)
        assert yaseer_run(first, ours) == pcbasic_run(first, theirs), (first, second)


def test_field_makes_its_variables_as_pcbasic(tmp_path):
    """FIELD's PTRGET makes each variable (a field of width 0 holds ""): SWAP may take it."""
    from test_gw_files import pcbasic_run

    source = ('10 ON ERROR GOTO 100: OPEN "R", 1, "F.DAT", 10: FIELD #1, 0 AS B$, 10 AS C$\n'
              '20 SWAP A$, B$: PRINT "ok"; LEN(A$): END\n100 PRINT "E"; ERR; ERL: RESUME NEXT\n')
    (tmp_path / "p").mkdir()
    (tmp_path / "y").mkdir()
    assert yaseer_run(source, tmp_path / "y") == pcbasic_run(source, tmp_path / "p") == "ok 0 \n"
