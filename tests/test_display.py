"""The shared display model (yaseer/basic/machine/display.py): the Casio's 32 x 8 virtual screen with
its 2-line window, and an 80 x 25 text screen, as the owner's manual describes the LCD (part 6,
LOCATE, CLS and PRINT pages).  Expected screens are written out by hand from those pages."""

from yaseer.basic.dialects.charset import CASIO_CONTROLS
from yaseer.basic.machine.display import Display


def casio():
    return Display(32, 8, 2, CASIO_CONTROLS)


def test_text_starts_top_left_and_window_shows_two_rows():
    d = casio()
    d.write("AB")
    assert d.shown_lines() == ["AB", ""]
    assert (d.x, d.y) == (2, 0)
    assert not d.drawn  # plain text: a transcript keeps streaming it


def test_locate_corners_of_the_virtual_screen():
    d = casio()
    d.locate(31, 7)
    d.write("Z")  # the last cell: the cursor reaches the lower right, the screen scrolls up
    assert d.lines()[6] == " " * 31 + "Z"
    assert d.lines()[7] == ""
    assert (d.x, d.y) == (0, 7)
    assert d.drawn


def test_window_follows_the_cursor_down_and_back_up():
    d = casio()
    for k in range(5):
        d.write(f"L{k}\n")
    # the cursor is on row 5: rows 4 and 5 are shown
    assert d.shown_lines() == ["L4", ""]
    d.locate(0, 0)
    assert d.shown_lines() == ["L0", "L1"]


def test_a_32_character_line_wraps_onto_the_next_row():
    d = casio()
    d.write("x" * 32 + "yz")
    assert d.lines()[:2] == ["x" * 32, "yz"]


def test_scrolling_moves_every_row_up_one():
    d = casio()
    for k in range(9):
        d.write(f"R{k}\n")
    assert d.lines() == ["R2", "R3", "R4", "R5", "R6", "R7", "R8", ""]


def test_cls_blanks_and_homes():
    d = casio()
    d.write("ABC\nDEF")
    d.clear()
    assert d.lines() == [""] * 8 and (d.x, d.y, d.top) == (0, 0, 0)
    d.write("Q\x0c")  # PRINT CHR$(12) clears as CLS does (CLS page)
    assert d.lines() == [""] * 8


def test_line_cancel_blanks_the_row_and_starts_it_again():
    d = casio()
    d.write("OLD TEXT ON LINE")
    d.locate(4, 0)
    d.write("\x05new")
    assert d.shown_lines()[0] == "new"


def test_cursor_codes_and_backspace():
    d = casio()
    d.write("ABC\x1d\x1dX")  # two left, then overwrite B
    assert d.lines()[0] == "AXC"
    d.write("\x08")  # back over X, erasing it
    assert d.lines()[0] == "A C"
    d.write("\x1f\x1cY")  # down one, right one
    assert d.lines()[1] == "  Y"  # from column 1 after the backspace
    d.write("\x0bH")  # home
    assert d.lines()[0] == "H C"


def test_unknown_control_codes_show_nothing():
    d = casio()
    d.write("A\x07\x01B")  # BEL and an unassigned code
    assert d.lines()[0] == "AB"


def test_text_screen_of_80_by_25_shows_all_rows():
    d = Display(80, 25)
    d.locate(10, 24)
    d.write("bottom")
    assert d.shown_lines()[24] == " " * 10 + "bottom"
    assert len(d.shown_lines()) == 25
    d.write("\n")
    assert d.lines()[23] == " " * 10 + "bottom"  # scrolled up


def test_screen_text_is_the_window_one_line_each():
    d = casio()
    d.write("TOP\nSECOND")
    assert d.screen_text() == "TOP\nSECOND\n"


def test_a_view_scrolls_only_its_rows():
    # gw's VIEW PRINT 2 TO 4 (rows 1..3 here, 0-based): the rows outside stay
    d = Display(80, 25)
    d.locate(0, 0)
    d.write("KEPT ABOVE")
    d.locate(0, 24)
    d.write("KEPT BELOW")
    d.set_view(1, 3)
    for k in range(5):
        d.write(f"V{k}\n")
    assert d.lines()[:5] == ["KEPT ABOVE", "V3", "V4", "", ""]
    assert d.lines()[24] == "KEPT BELOW"
    d.clear()
    assert d.lines()[:4] == ["KEPT ABOVE", "", "", ""] and (d.x, d.y) == (0, 1)
