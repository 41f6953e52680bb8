"""FRE as GW-BASIC reports it (yaseer/basic/machine/memory_model.py): the bytes of its
segment the program, its variables, arrays and strings leave, against PC-BASIC 2.0.8 (which
counts GW-BASIC's layout the same way) on programs whose every variable gets a value other
than 0 or "" from an expression, and on two of the classic workloads.  Where the model
differs (a string literal GW-BASIC leaves in the program text, a variable given 0) is
written in the module's docstring and docs/compatibility.md."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from test_differential_support import run_gw

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

PROGRAMS = [
    "10 PRINT FRE(0)\n", "10 PRINT FRE(0):REM ABCDEFGHIJ\n", "10 A=1: PRINT FRE(0)\n",
    "10 A=1: AB=1: ABC=2: PRINT FRE(0)\n", "10 A%=1: B#=2: PRINT FRE(0)\n", '10 C$="XYZ"+"": PRINT FRE(0)\n',
    "10 DIM A(100): PRINT FRE(0)\n", "10 DIM A%(100): PRINT FRE(0)\n", "10 DIM A$(100): PRINT FRE(0)\n",
    "10 DIM A(10,10): PRINT FRE(0)\n", '10 A$=STRING$(100,"X"): PRINT FRE(0); FRE("")\n',
    "10 PRINT FRE(0)\n20 PRINT FRE(0)\n", "10 GOSUB 20\n20 PRINT FRE(0): END\n",
    "10 FOR I=1 TO 1: PRINT FRE(0): NEXT\n", "10 DEF FNA(X)=X: PRINT FRE(0)\n", "10 PRINT FRE(A)\n",
    '10 GOTO 20\n20 X = 3.25: Y# = 1D+20: Z = 12345678: ON 1 GOTO 30\n30 PRINT FRE(0); CHR$(65); LEFT$("AB", 1)\n',
]
CLASSIC = Path(__file__).parent / "benchmarks" / "classic"


def with_fre_at_the_end(name: str) -> str:
    """A classic workload run once round its loop, printing FRE before its END."""
    text = (CLASSIC / f"{name}.bas").read_text()
    text = re.sub(r"(?m)^(\d+\s+)END\s*$", r"\1PRINT FRE(0): END", text)
    return re.sub(r"(FOR K=1 TO |FOR N=1 TO |IF K<)\d+", r"\g<1>1", text)


@pytest.mark.parametrize("source", PROGRAMS + [with_fre_at_the_end("ahl"), with_fre_at_the_end("bm7")])
def test_fre_as_pcbasic_counts_it(pc, source):
    pc.statement("ON ERROR GOTO 0")
    assert run_gw(source) == pc.program(source)


def test_fre_is_about_60000_and_falls_as_arrays_grow():
    free = [float(run_gw(f"10 DIM A({n}): PRINT FRE(0)\n")) for n in (1000, 2000, 3000)]
    assert 55000 < free[0] < 60300 and free[0] - free[1] == free[1] - free[2] == 4000
