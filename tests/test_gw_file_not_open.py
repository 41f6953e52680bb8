"""A file number that names no open file, as GW-BASIC's source maps it.

Every statement and function that finds an open file looks for it along the chain of open
files (GIO86.ASM ``FDBPTR``), whatever the number of files; finding none it jumps to
``DERFNO``, and GWDATA.ASM gives ``ERRFNO`` the code of ``ERRBFM`` ("Map File Not Open to
Bad file mode"): ``Bad file mode`` (54).  The number is read first: above 255 ``Illegal
function call`` (``GETBYT``, ``CONINT``), 0 ``Bad file number`` (52) where the reader checks
it (``GETNZB`` for ``#n``; ``FACDSP`` for LOC and LOF), but EOF looks for file 0 like any
other (``FACFPT``).  PC-BASIC 2.0.8 says ``Bad file number`` for all but GET, PUT and
INPUT$; the source decides, and casio keeps PC-BASIC's codes.
"""

from __future__ import annotations

import pytest

from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

# (statement, the routine that finds the file) for a file number n; the file never opened
FINDERS = [
    ("PRINT #{n}, 1", "FILGET"), ('PRINT #{n}, USING "##"; 1', "FILGET"), ("WRITE #{n}, 1", "FILGET"),
    ("INPUT #{n}, A", "FILSTI: FILINP, FILGET"), ("LINE INPUT #{n}, A$", "DLINE: FILINP, FILGET"),
    ("WIDTH #{n}, 40", "FILWID: PRFNUM, FDBPTR"), ("FIELD #{n}, 5 AS A$", "FIELD: FILSCN"),
    ("GET #{n}", "DPUTG: POFNUM, FDBPTR"), ("PUT #{n}", "DPUTG"), ("A$ = INPUT$(1, #{n})", "FIXINP: FILSCN"),
    ("PRINT EOF({n})", "EOF: FACFPT"), ("PRINT LOC({n})", "LOC: FACDSP, FILDSP"), ("PRINT LOF({n})", "LOF: FACDSP"),
]


def _program(n: int) -> str:
    lines = "".join(f"{10 * k + 20} {statement.format(n=n)}\n" for k, (statement, _) in enumerate(FINDERS))
    return f"10 ON ERROR GOTO 900\n{lines}800 END\n900 PRINT ERR; ERL: RESUME NEXT\n"


def _errors(codes: list[int]) -> str:
    return "".join(f" {code}  {10 * k + 20} \n" for k, code in enumerate(codes))


@pytest.mark.parametrize("n", [1, 3, 4, 255])
def test_a_file_not_open_is_bad_file_mode(tmp_path, n):
    """1..3 are GW's default files, 4 and 255 beyond them: FDBPTR looks for each all the same."""
    assert yaseer_run(_program(n), tmp_path) == _errors([54] * len(FINDERS))


def test_file_zero_and_numbers_beyond_a_byte(tmp_path):
    """0: ``Bad file number`` where GETNZB or FACDSP checks it, not for EOF (FACFPT goes straight
    to FDBPTR, which finds no file 0 while a program runs: Bad file mode); 256: CONINT's and
    GETBYT's ``Illegal function call``."""
    zero = [54 if statement.startswith("PRINT EOF") else 52 for statement, _ in FINDERS]
    assert yaseer_run(_program(0), tmp_path) == _errors(zero)
    assert yaseer_run(_program(256), tmp_path) == _errors([5] * len(FINDERS))


@pytest.mark.parametrize("n", [0, 2, 4])
def test_pcbasic_differs_only_by_the_mapping(tmp_path, n):
    """PC-BASIC 2.0.8's output, its ``Bad file number`` for a file not open and its 0 for
    EOF(0) read as the source's ``Bad file mode``: the only differences."""
    theirs_dir, ours_dir = tmp_path / "pc", tmp_path / "ya"
    theirs_dir.mkdir()
    ours_dir.mkdir()
    source = _program(n)
    theirs = pcbasic_run(source, theirs_dir)
    if n:
        assert theirs.count(" 52 ") == len(FINDERS) - 3  # all but GET, PUT and INPUT$
        theirs = theirs.replace(" 52 ", " 54 ")
    else:
        eof = 10 * [statement for statement, _ in FINDERS].index("PRINT EOF({n})") + 20
        assert " 0 \n" in theirs
        theirs = theirs.replace(" 0 \n", f" 54  {eof} \n")
    assert yaseer_run(source, ours_dir) == theirs


def test_casio_keeps_bad_file_number(tmp_path):
    """The casio dialect's file table keeps PC-BASIC 2.0.8's codes (its own ERR table maps
    them: dialects/casio.py), statement by statement as PC-BASIC reports them."""
    source = ('10 ON ERROR GOTO 900\n20 PRINT #2, 1\n30 INPUT #2, A\n40 LINE INPUT #2, A$\n'
              '50 PRINT EOF(2); LOC(2); LOF(2)\n60 PRINT #5, 1\n800 END\n900 PRINT ERR; ERL: RESUME NEXT\n')
    theirs_dir, ours_dir = tmp_path / "pc", tmp_path / "ya"
    theirs_dir.mkdir()
    ours_dir.mkdir()
    ours = yaseer_run(source, ours_dir, "casio")
    assert ours == " 52  20 \n 52  30 \n 52  40 \n 52  50 \n 52  60 \n"
    assert ours == pcbasic_run(source, theirs_dir)
