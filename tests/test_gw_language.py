"""GW-BASIC's statements and functions (issue 12) against PC-BASIC 2.0.8, in both dialects.

The cases are batched: tests/gw/functions.txt holds direct statements run one after
the other in one PC-BASIC session; tests/gw/statements.bas one program exercising
WHILE/WEND, SWAP, the MID$ statement, ERASE, OPTION BASE, WRITE, RETURN n, GO TO,
GO SUB, CLEAR n, DIM of a scalar name and their errors.  Values are exact in single
precision, so GW-BASIC's precision decides no printed digit.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from test_differential_support import run_direct as direct, clean_output, run_yaseer

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

CASES = Path(__file__).parent / "gw"
DIALECTS = ["gw", "casio"]


def statements(dialect: str) -> list[str]:
    """The direct statements of tests/gw/functions.txt (and functions_gw.txt: typed literals, gw only)."""
    files = ["functions.txt"] + (["functions_gw.txt"] if dialect == "gw" else [])
    return [line for name in files for line in (CASES / name).read_text().splitlines() if line.strip()]


@pytest.fixture(scope="module")
def pcbasic_functions(pc):
    return {text: pc.statement(text) for text in statements("gw")}


@pytest.mark.parametrize("dialect", DIALECTS)
def test_functions_and_operators_match_pcbasic(pcbasic_functions, dialect):
    """VAL, INSTR, STRING$, SPACE$, HEX$, OCT$, MKI$/MKS$/MKD$ bytes, CVI/CVS/CVD, XOR EQV IMP,
    POS, DATE$/TIME$ shapes, TIMER range, and their errors."""
    differing = [(text, mine, pcbasic_functions[text]) for text in statements(dialect)
                 if (mine := direct(text, dialect)) != pcbasic_functions[text]]
    assert not differing, differing[:3]


@pytest.mark.parametrize("dialect", DIALECTS)
def test_statements_match_pcbasic(pc, dialect):
    source = (CASES / "statements.bas").read_text()
    angle = None if dialect == "gw" else "rad"
    assert run_yaseer(source, angle=angle, dialect=dialect) == pc.program(source)


INPUT_ANSWERS = ["1_2", "12", " 1 2 ", "&H10", "1D2", "inf", "nan", "", "1e3", "-.5", "1,2", "abc",
                 "0x10", "1e", "  .5  "] + ["7"] * 20
INPUT_PROGRAM = "10 FOR I=1 TO 14\n20 INPUT A\n30 PRINT A\n40 NEXT\n"


def with_answers(program: str, answers: list[str], dialect: str) -> tuple[str, str]:
    """(yaseer's screen, PC-BASIC's screen) for ``program`` answered with ``answers``
    (PC-BASIC's singles with the source's digits, as test_differential_support's oracle)."""
    import pcbasic
    from single_digits_support import source_single_digits

    from yaseer.basic.machine.machine import Machine

    session = pcbasic.Session(input_streams=io.BytesIO(("\r".join(answers) + "\r").encode()),
                              output_streams=None)
    session.start()
    session.execute(program)
    with source_single_digits():
        theirs = clean_output(session.execute("RUN"))
    session.close()
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect=dialect, input_stream=io.StringIO("\n".join(answers) + "\n"))
    machine.load(program)
    machine.run()
    return screen.getvalue(), theirs


@pytest.mark.parametrize("dialect", DIALECTS)
def test_input_reads_numbers_as_gw_basic(dialect):
    """Python's float syntax does not leak into INPUT: inf, nan, 1_2 ask again.  (casio: a
    name typed is the numeric expression of its variable, INPUT.md item 9, so the answers
    that are names are left out here; tests/test_casio_pages.py reads them as variables.)"""
    answers = [a for a in INPUT_ANSWERS if dialect == "gw" or a not in ("inf", "nan", "abc")]
    ours, theirs = with_answers(INPUT_PROGRAM, answers, dialect)
    if dialect == "casio":  # the FX-850P keeps A's value (1D2) on an empty answer (its INPUT page, item 7)
        assert "? \n 0 \n" in theirs
        theirs = theirs.replace("? \n 0 \n", "? \n 100 \n", 1)
    assert ours == theirs


def test_input_beyond_the_mbf_range_is_overflow_and_the_largest_of_the_target():
    """gw: INPUT of a number beyond 1.7D+38 prints Overflow and stores the signed largest
    value of the variable's type (double or single), as PC-BASIC does."""
    program = "10 INPUT A#: PRINT A#: INPUT B: PRINT B: INPUT C#: PRINT C#: INPUT D: PRINT D\n"
    ours, theirs = with_answers(program, ["1D+39", "-1E+39", "1D+400", "1D+38"], "gw")
    assert "Overflow" in theirs and ours == theirs


@pytest.mark.parametrize("dialect", DIALECTS)
def test_line_input_takes_the_whole_line(dialect):
    program = '10 LINE INPUT A$: LINE INPUT "say: "; B$: PRINT "["; A$; "]["; B$; "]"\n'
    ours, theirs = with_answers(program, ['  a, "b" ,c  ', "x,y"], dialect)
    assert ours == theirs


READ_PROGRAM = ('10 READ A, B, C, D, E: PRINT A; B; C; D; E\n20 READ F\n'
                '30 DATA 1 2, &H1F, 1D2, -.5E1, , 1_2\n')


@pytest.mark.parametrize("dialect", DIALECTS)
def test_read_takes_numbers_as_gw_basic(pc, dialect):
    angle = None if dialect == "gw" else "rad"
    assert run_yaseer(READ_PROGRAM, angle=angle, dialect=dialect) == pc.program(READ_PROGRAM)


def test_mbf_bytes_of_generated_values_match_pcbasic(pc):
    """MKS$, MKD$ and MKI$ of seeded random values (exact in single precision, so both
    BASICs hold the same number), and CVS / CVI of random byte strings: one PC-BASIC
    program, compared byte for byte (gw) and the decoded values within single precision's
    last digit (casio prints 10 digits)."""
    import random

    from test_differential_support import base_seed, basic_number, exact_single, numbers_and_text

    rng = random.Random(base_seed() + 12)
    lines = []
    for k in range(60):
        literal = basic_number(exact_single(rng))  # at most 7 digits: single in GW-BASIC, exact in both
        scale = rng.choice(["", "", " * 2^-60", " * 2^70"])
        lines.append(f"{10 + 10 * k} X={literal}{scale}: A$=MKS$(X): B$=MKD$(X): GOSUB 2000")
    for k in range(40):
        chars = "+".join(f"CHR$({rng.randint(0, 255)})" for _ in range(4))
        lines.append(f"{1000 + 10 * k} C$={chars}: PRINT CVS(C$); CVI(C$); CVS(MKS$(CVS(C$))) = CVS(C$)")
    lines.append("1990 END")
    lines.append('2000 FOR K=1 TO 4: PRINT ASC(MID$(A$,K,1));: NEXT: PRINT "|";')
    lines.append("2010 FOR K=1 TO 8: PRINT ASC(MID$(B$,K,1));: NEXT: PRINT: RETURN")
    source = "\n".join(lines) + "\n"
    theirs = pc.program(source)
    assert run_yaseer(source, angle=None, dialect="gw") == theirs
    ours_numbers, ours_text = numbers_and_text(run_yaseer(source, angle="rad", dialect="casio"))
    their_numbers, their_text = numbers_and_text(theirs)
    assert ours_text == their_text and len(ours_numbers) == len(their_numbers)
    assert all(abs(a - b) <= 1e-6 * max(abs(a), abs(b)) for a, b in zip(ours_numbers, their_numbers))
