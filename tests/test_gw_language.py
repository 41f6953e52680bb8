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

from test_differential_support import PcBasic, run_direct as direct, clean_output, run_yaseer

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

CASES = Path(__file__).parent / "gw"
DIALECTS = ["gw", "casio"]


@pytest.fixture(scope="module")
def pc():
    session = PcBasic()
    yield session
    session.close()


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


@pytest.mark.parametrize("dialect", DIALECTS)
def test_input_reads_numbers_as_gw_basic(dialect):
    """Python's float syntax does not leak into INPUT: inf, nan, 1_2 ask again."""
    import pcbasic

    from yaseer.basic.machine import Machine

    session = pcbasic.Session(input_streams=io.BytesIO(("\r".join(INPUT_ANSWERS) + "\r").encode()),
                              output_streams=None)
    session.start()
    session.execute(INPUT_PROGRAM)
    theirs = clean_output(session.execute("RUN"))
    session.close()
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect=dialect, input_stream=io.StringIO("\n".join(INPUT_ANSWERS) + "\n"))
    machine.load(INPUT_PROGRAM)
    machine.run()
    assert screen.getvalue() == theirs


READ_PROGRAM = ('10 READ A, B, C, D, E: PRINT A; B; C; D; E\n20 READ F\n'
                '30 DATA 1 2, &H1F, 1D2, -.5E1, , 1_2\n')


@pytest.mark.parametrize("dialect", DIALECTS)
def test_read_takes_numbers_as_gw_basic(pc, dialect):
    angle = None if dialect == "gw" else "rad"
    assert run_yaseer(READ_PROGRAM, angle=angle, dialect=dialect) == pc.program(READ_PROGRAM)
