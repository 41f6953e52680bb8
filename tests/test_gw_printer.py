"""LPRINT in ``--dialect gw`` against PC-BASIC 2.0.8's printer (LPT1 written to a file):
the printer wraps at its width (80, ``WIDTH LPRINT n``: 0..255, 255 never wraps;
0 is taken as 1, where PC-BASIC writes extra line ends)
character by character, items included; ``,`` zones, TAB and SPC as on the screen."""

from __future__ import annotations

import io

import pytest

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

PROGRAM = """10 LPRINT STRING$(100, "A")
20 LPRINT "X"; TAB(70); "YYYYYYYYYYYYYYY"
30 WIDTH LPRINT 20
40 LPRINT "0123456789012345678901234": LPRINT STRING$(20, "D"): LPRINT "E"
50 LPRINT 1, 2, 3
60 FOR I = 1 TO 8: LPRINT "AB ";: NEXT: LPRINT
70 LPRINT 12345; 67890; 12345; 67890: LPRINT STRING$(19, "F"); 123
80 LPRINT "G"; TAB(25); "H": LPRINT "I"; SPC(30); "J"
90 WIDTH LPRINT 1: LPRINT "KL"
100 WIDTH LPRINT 255: LPRINT STRING$(100, "B")
110 WIDTH LPRINT 80: LPRINT 1, 2, 3, 4, 5, 6, 7: LPRINT STRING$(80, "M"): LPRINT "N"
120 PRINT LPOS(0): LPRINT "O";: PRINT LPOS(0)
130 WIDTH LPRINT 256
"""


def pcbasic_printer(source: str, tmp_path) -> tuple[str, str]:
    """(screen, printer text) of PC-BASIC running ``source``."""
    import pcbasic

    from test_differential_support import clean_output

    paper = tmp_path / "lpt1.txt"
    session = pcbasic.Session(output_streams=None, input_streams=None, devices={"LPT1:": f"FILE:{paper}"})
    session.start()
    session.execute("NEW")
    screen = clean_output(session.execute(source.rstrip("\n") + "\nRUN"))
    session.close()
    return screen, paper.read_bytes().decode("latin-1").replace("\r\n", "\n")


def yaseer_printer(source: str) -> tuple[str, str]:
    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.machine import Machine

    screen, paper = io.StringIO(), io.StringIO()
    machine = Machine(screen=screen, printer=paper, dialect="gw")
    machine.load(source)
    try:
        machine.run()
    except BasicError as err:
        machine.end_line()
        screen.write(str(err) + "\n")
    return screen.getvalue(), paper.getvalue()


def test_lprint_wraps_at_the_printer_width_as_pcbasic(tmp_path):
    theirs = pcbasic_printer(PROGRAM, tmp_path)
    assert "YYYYYYYYYYY\nYYYY\n" in theirs[1] and theirs[0].endswith("Illegal function call in 130\n")
    assert yaseer_printer(PROGRAM) == theirs


DEVICE_WIDTH_PROGRAM = """10 LPRINT STRING$(30, "A")
20 WIDTH "LPT1:", 20: LPRINT STRING$(30, "B")
30 WIDTH "lpt1:", 10: LPRINT STRING$(30, "C")
40 D$ = "LPT1:": WIDTH D$, 25.6: LPRINT STRING$(30, "D")
50 WIDTH "COM1:", 20: WIDTH "CAS1:", 200: LPRINT STRING$(30, "E")
60 WIDTH "LPT1:", 255: LPRINT STRING$(100, "F")
70 WIDTH "SCRN:", 40: PRINT "G": WIDTH "SCRN:", 80: WIDTH "LPT1:", 80: LPRINT "H"
80 ON ERROR GOTO 200
90 WIDTH "LPT1:", 256
100 WIDTH "FOO:", 20
110 WIDTH "LPT1", 20
120 WIDTH "", 20
130 WIDTH "KYBD:", 20
140 WIDTH "SCRN:", 50
150 WIDTH "LPT1:", -1
160 WIDTH "COM1:", 300
170 END
200 PRINT ERR; ERL: RESUME NEXT
"""


def test_width_of_a_device_as_pcbasic(tmp_path):
    """WIDTH "LPT1:", n sets the width LPRINT wraps at at once (GIOLPT.ASM LPTSWD),
    "SCRN:" the screen's; a name that is no device is Bad file name (64)."""
    theirs = pcbasic_printer(DEVICE_WIDTH_PROGRAM, tmp_path)
    assert "BBBBBBBBBBBBBBBBBBBB\nBBBBBBBBBB\n" in theirs[1] and " 64  100 \n" in theirs[0]
    assert yaseer_printer(DEVICE_WIDTH_PROGRAM) == theirs


def test_width_of_a_device_needs_a_string_and_a_width():
    """As PC-BASIC 2.0.8: no width is a Syntax error, a string width Type mismatch;
    ``WIDTH 80, 25`` is the screen's size (25 rows, the only number it has: GWSTS.ASM GWWID),
    ``WIDTH 80, 24`` Illegal function call."""
    for bad, error in (('WIDTH "LPT1:"', "Syntax error"), ('WIDTH "LPT1:", "A"', "Type mismatch"),
                       ("WIDTH 80, 24", "Illegal function call")):
        screen, _ = yaseer_printer(f"10 {bad}\n")
        assert screen == f"{error} in 10\n", (bad, screen)
    assert yaseer_printer("10 WIDTH 40, 25: PRINT 1\n")[0] == " 1 \n"


# LPRINT with no printer file: its text, on the output as printed, never touches the screen
APART_PROGRAM = """10 PRINT "A";: LPRINT "X";: LPRINT "Y": PRINT POS(0); CSRLIN
20 LPRINT STRING$(30, "L"): PRINT "B"; SCREEN(1, 2); SCREEN(3, 1)
30 WIDTH LPRINT 10: LPRINT STRING$(15, "W"): LOCATE 5, 3: PRINT "C": LPRINT "Z"
"""


def test_lprint_without_a_printer_leaves_the_screen_alone(tmp_path):
    """GW-BASIC's LPRINT writes to LPT1: only (GIO86.ASM LPRINT points PTRFIL at the printer):
    the screen keeps its cursor and cells, as PC-BASIC 2.0.8's screen shows.  Without
    ``--printer`` yaseer writes the printer's text on the output as it is printed (wrapping
    at the printer's width), beside the screens the transcript shows."""
    from test_differential_gw_screen import pcbasic_screen, yaseer_screen
    from test_differential_support import PcBasic

    pc = PcBasic()
    try:
        theirs = pcbasic_screen(pc, APART_PROGRAM)
    finally:
        pc.close()
    ours, written = yaseer_screen(APART_PROGRAM)
    assert ours == theirs
    assert theirs[:2] == ["A 2  1", "B 32  32"]
    # the text streamed in order (PRINT's open row, the printer's text after it) until LOCATE
    # places text: from then on the screen, shown when the run ends
    printed = "AXY\n 2  1 \n" + "L" * 30 + "\nB 32  32 \n" + "W" * 10 + "\nWWWWW\nZ\n"
    assert written == printed + "".join(row + "\n" for row in ours)
