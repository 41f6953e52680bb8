"""gw's screen statements read their numbers as GW-BASIC's SCNINT reads them, and check them
in its order (yaseer/basic/source/byte_lists.py, yaseer/basic/machine/screen_words.py).

The expected errors are what a real GW-BASIC 3.23 did in the recordings of PC-BASIC's test
suite (its tests CLS, LOCATE, LOCATE2, SCREEN, COLOR, WIDTH, WIDTH2, VIEWPRNT, PCOPY:
the programs are not copied here; each case below is written anew from what the recorded
output shows), read against GWSTS.ASM (SCNINT, EOSCHK, CLS, LOCATE, GWWID, GTPRMS) where
the source holds the routine.  docs/compatibility.md, row "Screen statements' arguments".
"""

from __future__ import annotations

import io

import pytest

from yaseer.basic.dialects.dialect import CASIO, GW
from yaseer.basic.machine.machine import Machine


def errors(*statements: str, before: str = "", files=None) -> list[tuple[int, int]]:
    """(ERR, ERL) of each statement that fails, each on a line of its own (10, 20, ...),
    after ``before`` on line 5 (``files``: the folder of the files it opens)."""
    lines = ["1 DIM E(20), L(20): ON ERROR GOTO 9000"] + ([f"5 {before}"] if before else [])
    lines += [f"{10 * (k + 1)} {text}" for k, text in enumerate(statements)]
    # (the errors kept until the end: CLS and SCREEN clear the screen)
    lines += ["8999 FOR I = 1 TO N: PRINT E(I); L(I): NEXT: END", "9000 N = N + 1: E(N) = ERR: L(N) = ERL: RESUME NEXT"]
    out = io.StringIO()
    machine = Machine(screen=out, dialect=GW, files=files)
    machine.load("\n".join(lines) + "\n")
    machine.run()
    machine.screen.catch_up()
    found = []
    for line in machine.display.lines():
        numbers = line.split()
        if len(numbers) == 2 and all(n.isdigit() for n in numbers):
            found.append((int(numbers[0]), int(numbers[1])))
    return found


def test_cls_reads_one_number_then_the_end():
    """GWSTS.ASM CLS: SCNINT (a comma after the number is read with it: ``CLS ,``, ``CLS 0,``
    are fine), then EOSCHK (``CLS ,0`` Syntax error), then the mode's range (CLS 3, checked
    after the end: ``CLS 3,0`` is Syntax error); GETBYT's Overflow; a number followed by
    anything but a comma is Illegal function call (``CLS 0 X``), text no number starts
    with Syntax error (``CLS , PRINT``); ``CLS X`` is CLS with X's value.  (Recorded CLS test.)"""
    assert errors("CLS ,", "CLS 0,", "CLS ,0", "CLS 32768", "CLS 3", "CLS 3,0", "CLS 0 X", "CLS , PRINT",
                  "CLS X", "CLS 0,0 PRINT") == [(2, 30), (6, 40), (5, 50), (2, 60), (5, 70), (2, 80), (2, 100)]


def test_cls_in_a_graphics_mode():
    """SCREEN 1 is a mode of the machine (the recorded CLS test runs CLS 0..2 there; its
    text is 40 columns wide: ScreenMode.columns); CLS -1 is still Illegal function call."""
    assert errors("SCREEN 1", "CLS 0", "CLS 1", "CLS 2", "CLS -1") == [(5, 50)]
    assert errors("SCREEN 1", 'PRINT STRING$(41, "A")', "PRINT CSRLIN") == []


def test_locate_reads_five_numbers_and_one_comma_after_them():
    """GWSTS.ASM LOCATE: five SCNINTs, then EOSCHK, then CSRATR: a comma after the fifth is
    read with it (``LOCATE 1,2,1,4,5,`` fine; ``LOCATE ,,,,,`` fine), a sixth number is
    Syntax error; a cursor of 3 is found only after the end (``LOCATE 1,2,3,4,5,`` Illegal
    function call, not Syntax error).  (Recorded LOCATE and LOCATE2 tests.)"""
    assert errors("LOCATE 1,2,1,4,5,", "LOCATE ,,,,,", "LOCATE 1,2,1,4,5,6", "LOCATE 1,2,3,4,5,",
                  "LOCATE ,,,4,5,", "LOCATE ,,,4,5,6", "LOCATE 1 X", "LOCATE 32768, 1, 0") == [
        (2, 30), (5, 40), (2, 60), (5, 70), (6, 80)]


def test_screen_reads_every_number_first():
    """GWSTS.ASM SCREEN: GTPRMS reads every number (GETBYT's Overflow for the fifth comes
    before the count's Illegal function call), then the OEM's checks: the colour switch takes
    any byte, a page beyond the text mode's 4 (80 columns) is Illegal function call, a
    mode the machine lacks too; a last number left out is Missing operand.  (Recorded
    SCREEN test.)"""
    assert errors("SCREEN 0,255", "SCREEN 0,0,0,0,32768", "SCREEN 0,0,0,0,0", "SCREEN 0,0,3,3", "SCREEN 0,0,4",
                  "SCREEN 0,0,0,4", "SCREEN 3", "SCREEN 0,0,") == [(6, 20), (5, 30), (5, 50), (5, 60), (5, 70),
                                                                   (22, 80)]


@pytest.mark.parametrize("mode, expected", [
    (0, [(5, 10), (5, 30), (5, 40), (5, 50), (5, 60)]),  # text: foreground 0..31, background, border 0..15
    (1, [(5, 10)]),  # CGA's background and palette: any byte
    (2, [(5, 10), (5, 20), (5, 30), (5, 40), (5, 50), (5, 60)]),  # no COLOR at all
    (7, [(5, 10), (5, 20), (5, 30), (5, 40), (5, 60)]),  # foreground 1..15, background 0..15, border any byte
    (9, [(5, 10), (5, 20), (5, 30), (5, 40)]),  # 64 colours: a background of 40 is fine
])
def test_color_in_each_mode(mode, expected):
    """COLOR's ranges depend on the mode SCREEN chose (SETCLR, the OEM's: the recorded COLOR
    test runs the same COLORs in modes 0, 1, 2, 7, 8 and 9); GETBYT's own range comes first
    in every mode (COLOR -1)."""
    assert errors("COLOR -1", "COLOR 0", "COLOR 32", "COLOR ,16" if mode != 9 else "COLOR 1,64", "COLOR ,,255",
                  "COLOR 1,40", before=f"SCREEN {mode}") == expected


def test_width_reads_a_number_that_starts_it_alone(tmp_path):
    """WIDTH n where n starts with a number reads that number alone (``WIDTH 39+1``: the 39,
    then Illegal function call; ``WIDTH (39+1)`` is 40: the recorded WIDTH test), and then
    GWSTS.ASM GWWID: two SCNINTs and EOSCHK (``WIDTH 40,``, ``WIDTH 40,25,`` fine,
    ``WIDTH 40,25,1`` Syntax error, ``WIDTH 40 X`` Illegal function call: the recorded WIDTH2
    test); WIDTH alone is Missing operand (FRMEVL).  WIDTH #n, 0 is taken (recorded WIDTH)."""
    assert errors("WIDTH 39+1", "WIDTH (39+1)", "WIDTH 80,", "WIDTH 80, 25,", "WIDTH 80, 25, 1", "WIDTH 40 X",
                  "WIDTH", "WIDTH 80, 24", 'OPEN "O", 1, "W.TXT": WIDTH #1, 0', files=tmp_path) == [
        (5, 10), (2, 50), (5, 60), (22, 70), (5, 80)]


def test_width_as_the_other_statements_in_casio():
    """The Casio reads WIDTH, CLS and LOCATE as before: no byte reading (its dialect has no
    byte statements)."""
    assert CASIO.screen.byte_statements == () and not CASIO.screen.literal_width


def test_view_print_rows_overflow():
    """VIEW PRINT's rows beyond -32768..32767 are Overflow, before the range (the recorded
    VIEWPRNT test)."""
    assert errors("VIEW PRINT 1 TO 32768", "VIEW PRINT 1 TO 256", "VIEW PRINT 1 TO 24") == [(6, 10), (5, 20)]


def test_pcopy_copies_between_the_modes_pages():
    """PCOPY source, target: two integers (alone or after its comma Missing operand, one page
    Syntax error, a third number Syntax error), each a page of the mode (4 at 80 columns in
    the text mode), else Illegal function call; FRCINT's Overflow.  (Recorded PCOPY test.)"""
    assert errors("PCOPY 0,3", "PCOPY", "PCOPY 0", "PCOPY 0,", "PCOPY 0,0,", "PCOPY 0,4", "PCOPY 0,32768",
                  "PCOPY -1,0") == [(22, 20), (2, 30), (22, 40), (2, 50), (5, 60), (6, 70), (5, 80)]


def test_screen_function_reads_as_scnint_does():
    """SCREEN(row, column[, z]) reads its numbers with SCNINT (GWSTS.ASM SCRENF): a number
    missing where the text ends or a comma stands is Illegal function call (``SCREEN(``,
    ``SCREEN(1``, ``SCREEN(1)``), so is text after the column other than ``)`` or ``, z)``
    (``SCREEN(0, 0``: the z is missing); each number GETBYT's (a string Type mismatch, beyond an
    integer Overflow, -1 Illegal function call); ``#`` where a number starts Syntax error.
    A row or a column of 0 reads as 1, but not both (the recorded SCREENFN test)."""
    assert errors('PRINT SCREEN(', 'PRINT SCREEN("A"', "PRINT SCREEN(1", "PRINT SCREEN(1)", "PRINT SCREEN(-1)",
                  "PRINT SCREEN(1, 32768", "PRINT SCREEN(1, 1, 256", "PRINT SCREEN(0, 0", "PRINT SCREEN(#1)",
                  "PRINT SCREEN(0, 0)", "PRINT SCREEN(1, 1, 1, 1)") == [
        (5, 10), (13, 20), (5, 30), (5, 40), (5, 50), (6, 60), (5, 70), (5, 80), (2, 90), (5, 100), (5, 110)]
    out = io.StringIO()
    machine = Machine(screen=out, dialect=GW)
    machine.load('10 LOCATE 1, 1: PRINT "QR": A = SCREEN(0, 1): B = SCREEN(1, 0): C = SCREEN(1, 2)\n'
                 "20 LOCATE 5, 1: PRINT A; B; C\n")
    machine.run()
    machine.screen.catch_up()
    assert machine.display.lines()[4] == " 81  81  82"
