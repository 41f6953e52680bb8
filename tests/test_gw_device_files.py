"""Devices opened by name in gw (machine/device_files.py): the screen, the printer and the
null device, never a file of the program's directory.

GW-BASIC reads a name with a colon after two or more characters as one of its own devices
(GIO86.ASM PARDEV, GIOTBL.ASM's table: SCRN:, KYBD:, CONS:, LPTn:, CASn:, COMn:; another
such name is Bad file name); DOS takes CON, NUL, PRN, AUX, LPTn, COMn as its devices
whatever extension follows.  PC-BASIC 2.0.8 is the reference where it agrees (NUL, AUX,
KYBD:, COM1:, CAS1:); it makes files of CON.TXT and NUL.TXT and says Bad file number for
CON:, which DOS and PARDEV decide otherwise.
"""

from __future__ import annotations

import io

import pytest

from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

WRITES = 'PRINT #1, "hello"; 5, -2: WRITE #1, 1, "a,b": PRINT #1, USING "##.#"; 3.14159: PRINT #1, "x";'


@pytest.mark.parametrize("name", ["CON", "con", "Con.txt", "CON.BAS", "SCRN:", "CONS:"])
def test_the_screen_as_a_file_prints_as_print_does(tmp_path, name):
    """PRINT #, WRITE # and PRINT # USING to the screen lay their items out as PRINT, WRITE
    and PRINT USING do (the same program printing directly is the reference)."""
    ours = yaseer_run(f'10 OPEN "O", 1, "{name}": {WRITES}\n20 CLOSE: PRINT "|"\n', tmp_path)
    direct = yaseer_run("10 " + WRITES.replace(" #1,", "") + '\n20 PRINT "|"\n', tmp_path)
    assert ours == direct == 'hello 5       -2 \n1,"a,b"\n 3.1\nx|\n'
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("name", ["NUL", "nul", "NUL.TXT", "nul.bas"])
def test_the_null_device_drops_output_and_reads_nothing(tmp_path, name):
    """Output goes nowhere (LOF 0); input is at its end at once: EOF -1, a read Input past end
    (PC-BASIC 2.0.8 for NUL; DOS's NUL whatever the extension)."""
    source = (f'10 ON ERROR GOTO 90\n20 OPEN "O", 1, "{name}": PRINT #1, "gone": PRINT LOF(1); LOC(1): CLOSE\n'
              f'30 OPEN "I", 1, "{name}": PRINT EOF(1): LINE INPUT #1, A$\n40 INPUT #1, B: END\n'
              '90 PRINT ERR; ERL: RESUME NEXT\n')
    ours = yaseer_run(source, tmp_path)
    assert ours == " 0  0 \n-1 \n 62  30 \n 62  40 \n"
    assert not list(tmp_path.iterdir())
    if name == "NUL":  # PC-BASIC 2.0.8 fails inside on LOF and INPUT # of NUL: the rest
        theirs = tmp_path / "pc"
        theirs.mkdir()
        reading = source.replace(': PRINT LOF(1); LOC(1)', '').replace("INPUT #1, B: ", "")  # and INPUT #
        assert pcbasic_run(reading, theirs) == yaseer_run(reading, tmp_path) == "-1 \n 62  30 \n"


@pytest.mark.parametrize("name", ["LPT1:", "PRN", "lpt1", "PRN.TXT"])
def test_the_printer_as_a_file_prints_as_lprint_does(tmp_path, name):
    """LPT1: (GW's device), PRN and LPT1 (DOS's): the text goes where LPRINT's goes."""
    from yaseer.basic.machine.machine import Machine

    def printed(source: str) -> str:
        printer, screen = io.StringIO(), io.StringIO()
        machine = Machine(screen=screen, printer=printer, dialect="gw", files=tmp_path)
        machine.load(source)
        machine.run()
        machine.end_line()
        assert screen.getvalue() == ""
        return printer.getvalue()

    printing = 'PRINT #2, "hello"; 5, -2: PRINT #2, USING "##.#"; 3.14159: PRINT #2, "x";'
    ours = printed(f'10 OPEN "O", 2, "{name}": {printing}\n20 CLOSE\n')
    assert ours == printed("10 " + printing.replace("PRINT #2,", "LPRINT") + "\n") == "hello 5       -2 \n 3.1\nx"
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("name, code", [
    ("AUX", 68), ("COM1:", 68), ("CAS1:", 68), ("KYBD:", 54),  # as PC-BASIC 2.0.8
])
def test_devices_yaseer_has_not_as_pcbasic(tmp_path, name, code):
    source = f'10 ON ERROR GOTO 90\n20 OPEN "O", 1, "{name}": PRINT "open"\n30 END\n90 PRINT ERR; ERL: RESUME NEXT\n'
    ours = yaseer_run(source, tmp_path)
    assert ours == f" {code}  20 \nopen\n"
    theirs = tmp_path / "pc"
    theirs.mkdir()
    assert ours == pcbasic_run(source, theirs)
    assert list(tmp_path.iterdir()) == [theirs]


@pytest.mark.parametrize("source, message", [
    ('10 OPEN "O", 1, "CON:"', "Bad file name"),  # PARDEV: not in GIOTBL.ASM's table (PC-BASIC: Bad file number)
    ('10 OPEN "I", 1, "NUL:"', "Bad file name"),
    ('10 OPEN "O", 1, "XYZ:A"', "Bad file name"),
    ('10 OPEN "I", 1, "LPT1:"', "Bad file mode"),  # output devices
    ('10 OPEN "I", 1, "SCRN:"', "Bad file mode"),
    ('10 OPEN "R", 1, "NUL"', "Bad file mode"),
    ('10 OPEN "I", 1, "CON"', "Bad file mode"),  # yaseer's choice: the keys are INPUT's
    ('10 OPEN "O", 1, "LPT2:"', "Device Unavailable"),
    ('10 SAVE "CON"', "Path/File access error"),  # never a file named as a device
    ('10 SAVE "nul.bas",A', "Path/File access error"),
    ('10 OPEN "O", 1, "A": CLOSE: NAME "A" AS "PRN.TXT"', "Path/File access error"),
])
def test_device_names_that_are_no_file(tmp_path, source, message):
    assert yaseer_run(source + "\n", tmp_path) == f"{message} in 10\n"
    assert [p.name for p in tmp_path.iterdir()] in ([], ["A"])


def test_casio_knows_no_dos_device(tmp_path):
    """The casio dialect has no DOS: CON is a file name as any other (Dialect.device_files ())."""
    assert yaseer_run('10 OPEN "CON" FOR OUTPUT AS #1: PRINT #1, "x": CLOSE\n', tmp_path, "casio") == ""
    assert (tmp_path / "CON").read_bytes() == b"x\r\n\x1a"
