"""gw's screen transcript (what ``yaseer run`` prints of a screen a program drew, when standard
output is not a terminal) holds no control characters: a cell holding code 1..31 or 127 is
drawn as the IBM PC's font draws it (☺ for 1, ◘ for 8, ⌂ for 127), as on GW-BASIC's screen.
Reference: PC-BASIC 2.0.8's screen cells (``Session.get_chars`` as text), row for row.
"""

from __future__ import annotations

import subprocess
import sys

import pytest

from test_differential_support import PcBasic

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

# the codes GW's screen stores in a cell when printed (the others act: BEL, TAB, LF, home,
# CLS, CR and the cursor moves 28..31 of GW_CONTROLS), and a few of 128..255 beside them
STORED = [1, 2, 3, 4, 5, 6, 8, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 127, 130, 176, 219, 254]


def program() -> str:
    lines = ["10 CLS"]
    for row, start in enumerate(range(0, len(STORED), 9), start=2):
        codes = STORED[start:start + 9]
        items = "; ".join(f'CHR$({c}); "."' for c in codes)
        lines.append(f"{10 * row} LOCATE {row}, 3: PRINT {items}")
    lines.append("90 LOCATE 8, 1: END")
    return "\n".join(lines) + "\n"


def test_cells_with_control_codes_show_as_the_pc_font_draws_them(tmp_path):
    source = program()
    path = tmp_path / "cells.bas"
    path.write_text(source)
    ours = subprocess.run([sys.executable, "-m", "yaseer", "run", "--dialect", "gw", str(path)],
                          capture_output=True, text=True, encoding="utf-8", timeout=120).stdout
    pc = PcBasic()
    try:
        pc.program(source)
        rows = pc._session.get_chars(as_type=str)
    finally:
        pc.close()
    theirs = ["".join(row).rstrip(" ") for row in rows]
    assert ours.split("\n")[:8] == theirs[:8]
    assert not any(ch < " " or ch == "\x7f" for ch in ours.replace("\n", ""))
