"""GW-BASIC's graphics statements (PSET, PRESET, LINE, VIEW, WINDOW, GET, PUT, PALETTE,
POINT, PMAP, PCOPY, CLS) in ``--dialect gw``.

References: our own programs in tests/gw_graphics/ run by PC-BASIC 2.0.8 (its VGA machine,
the one its recorded tests ran on), which prints the pixels read back with POINT and the
GET arrays; the errors of bad statements are those a real GW-BASIC 3.23 recorded in
PC-BASIC's test suite (the tests named beside each case), on statements of our own.
"""

from __future__ import annotations

from pathlib import Path

import pytest

HERE = Path(__file__).parent / "gw_graphics"
PROGRAMS = sorted(p.name for p in HERE.glob("*.bas"))


def run(source: str, directory: Path | None = None) -> str:
    from test_gw_files import yaseer_run

    return yaseer_run(source, directory or Path("."))


def pcbasic_vga(source: str, directory: Path) -> str:
    pytest.importorskip("pcbasic")
    from test_gw_files import pcbasic_run

    return pcbasic_run(source, directory, video="vga")


@pytest.mark.parametrize("name", PROGRAMS)
def test_program_as_pcbasic(name, tmp_path):
    source = (HERE / name).read_text()
    ours, theirs = tmp_path / "ours", tmp_path / "theirs"
    ours.mkdir()
    theirs.mkdir()
    assert run(source, ours) == pcbasic_vga(source, theirs)


def errors(lines: str) -> list[tuple[int, int]]:
    """(error code, line) of each line of ``lines`` that fails, as an ON ERROR handler sees them."""
    source = "1 ON ERROR GOTO 9000\n" + lines + "\n8999 END\n9000 PRINT ERR; ERL: RESUME NEXT\n"
    out = run(source)
    return [tuple(int(v) for v in row.split()) for row in out.splitlines() if row.strip()]


def test_text_mode_refuses_before_reading():
    # the recorded PSET and WINDOW tests: in SCREEN 0 every form is Illegal function call
    assert errors("10 PSET (2,3)\n20 PSET\n30 WINDOW (1,1)-(2,2)\n40 WINDOW \"A\"\n50 LINE (1,1)-(2,2)") == [
        (5, 10), (5, 20), (5, 30), (5, 40), (5, 50)]


def test_pset_errors():
    # the recorded PSET test's kinds of error, on other numbers
    assert errors("5 SCREEN 2\n10 PSET\n20 PSET 7\n30 PSET (40000, 1)\n40 PSET (3,3),300\n"
                  "50 PSET (3,3),-2\n60 PSET (3,3),40000\n70 PSET (2000,-5)\n80 PRESET \"X\"") == [
        (2, 10), (2, 20), (6, 30), (5, 40), (5, 50), (6, 60), (2, 80)]


def test_line_errors():
    # the recorded LINE and LINE2 tests' kinds of error
    assert errors("5 SCREEN 1\n10 LINE\n20 LINE (1,1)\n30 LINE (1,1)-(5,5),2,\n40 LINE (1,1)-(5,5),2,X\n"
                  "50 LINE (1,1)-(5,5),,,40000\n60 LINE (1,1)-(5,5),,,\"A\"\n70 LINE (1,1)-(5,5),\"A\"\n"
                  "80 LINE (1,1)-(5,5),2,\"A\"\n90 LINE (3,3) -\n100 LINE - STEP (3,3)\n110 LINE (1,1)-(5,5),,B\n"
                  "120 LINE (1,1)-(5,5),,BF,7") == [
        (2, 10), (2, 20), (2, 30), (2, 40), (6, 50), (13, 60), (13, 70), (2, 80), (2, 90)]


def test_view_errors():
    # the recorded VIEW test's kinds of error
    assert errors("5 SCREEN 1\n10 VIEW SCREEN\n20 VIEW (5,5)\n30 VIEW (5,5)-(50,50),\n40 VIEW (5,5)-(50,50),1,2,\n"
                  "50 VIEW (5,5)-(5,50)\n60 VIEW (5,5)-(50,300)\n70 VIEW (5,5)-(50,40000)\n80 VIEW (\"A\",1)-(2,2)\n"
                  "90 VIEW (5,5)-(50,50),300\n100 VIEW (5,5)-(50,50),,1\n110 VIEW") == [
        (2, 10), (2, 20), (22, 30), (2, 40), (5, 50), (5, 60), (6, 70), (13, 80), (5, 90)]


def test_window_errors():
    # the recorded WINDOW test's kinds of error in a graphics mode
    assert errors("5 SCREEN 7\n10 WINDOW SCREEN\n20 WINDOW 3\n30 WINDOW (1,1)\n40 WINDOW (1,1)-(1,5)\n"
                  "50 WINDOW (1,\"A\")-(2,2)\n60 WINDOW (-5E4,1)-(5E4,-1)\n70 WINDOW") == [
        (2, 10), (2, 20), (2, 30), (5, 40), (13, 50)]


def test_pmap_and_point_in_text_mode():
    # the recorded PMAP and POINT tests: 0 in the text mode; POINT(x, y) Illegal function call
    out = run("10 PRINT PMAP(7, 0); PMAP(9, 3); POINT(0); POINT(3)\n20 PRINT POINT(1, 1)\n")
    assert out == " 0  0  0  0 \nIllegal function call in 20\n"


def test_point_reads_as_gw():
    # the recorded POINT and POINT2 tests: after POINT's first number a ")" makes POINT(n);
    # anything else is POINT(x, y), refused in the text mode before its numbers are checked
    text = "10 PRINT POINT(2, \"Q\")\n20 PRINT POINT(\"Q\"\n30 PRINT POINT(7\n40 PRINT POINT(7, #1)\n" \
           "50 PRINT POINT(\"Q\")\n60 PRINT POINT(1, 1, 1)\n70 PRINT POINT(4)\n"
    assert errors(text) == [(5, 10), (5, 20), (5, 30), (5, 40), (13, 50), (5, 60), (5, 70)]
    assert errors("5 SCREEN 2\n" + text) == [(13, 10), (13, 20), (2, 30), (2, 40), (13, 50), (2, 60), (5, 70)]


def test_pmap_reads_as_gw():
    # the recorded PMAP test: each number checked as it is read; the value made a single first
    assert errors("10 X = PMAP(\"Q\"\n20 X = PMAP(3\n30 X = PMAP(\"Q\")\n40 X = PMAP(3, 1, 1)\n"
                  "50 X = PMAP(1.701411834604692D+38, 9)\n60 X = PMAP(70000, 2)\n70 X = PMAP(70000, 1)\n80 X = PMAP(1, 4)") == [
        (13, 10), (2, 20), (13, 30), (2, 40), (6, 50), (6, 60), (5, 80)]


def test_line_box_letters_may_stand_apart():
    # the recorded LINE test: ``B F`` is BF (GW skips the blank between the letters)
    out = run("10 SCREEN 1\n20 LINE (1,1)-(3,3),2,B F\n30 PRINT POINT(2,2)\n")
    assert out == " 2 \n"


def test_palette_checks():
    # the recorded PALETTE and PALETUSI tests' kinds of error (text mode: 16 attributes, 64
    # colours, a colour's low byte 255 leaving it as it is)
    assert errors("5 DIM P%(20), S!(20)\n10 PALETTE 1, 100\n20 PALETTE 3, 255\n30 PALETTE 3, 511\n40 PALETTE 16, 1\n"
                  "50 PALETTE 1, 40000\n60 PALETTE 1 X\n70 PALETTE USING P%\n80 PALETTE USING S!(0)\n"
                  "90 PALETTE USING P%(10)\n100 PALETTE USING P%(4)\n110 PALETTE") == [
        (5, 10), (5, 40), (6, 50), (2, 60), (2, 70), (13, 80), (5, 90)]


def test_view_without_colours_leaves_the_pixels():
    # the GW-BASIC user's guide: VIEW fills and frames the view only with the colours given
    # (PC-BASIC 2.0.8 fills it with 0 and frames it in 0 all the same)
    out = run("10 SCREEN 1: LINE (0,0)-(50,50),2,BF\n20 VIEW (10,10)-(40,40)\n30 VIEW\n"
              "40 PRINT POINT(20,20); POINT(9,9)\n50 VIEW (10,10)-(40,40),1,3: VIEW\n60 PRINT POINT(20,20); POINT(9,9)\n")
    assert out == " 2  2 \n 1  3 \n"


def test_put_checks_the_view_before_the_array():
    # PC-BASIC 2.0.8: an array GET never filled still puts its corners in the view
    assert errors("10 SCREEN 1: DIM G%(10)\n20 PUT (400, 10), G%\n30 PUT (10, 10), G%\n40 GET (0,0)-(9,9), G%\n"
                  "50 DIM H%(1): GET (0,0)-(9,9), H%\n60 GET (0,0)-(400,9), G%") == [(5, 20), (5, 40), (5, 50), (5, 60)]


def test_cga_bank_padding_is_no_text():
    # the recorded BSAVBLOK test: in SCREEN 1 the bytes after each bank's 100 rows read 0,
    # not the text screen's cells (PC-BASIC 2.0.8 agrees)
    out = run('10 SCREEN 1: PRINT "AB": DEF SEG = &HB800\n20 PRINT PEEK(&H1F40); PEEK(&H1F41); PEEK(&H3F40)\n')
    assert out == "AB\n 0  0  0 \n"



@pytest.mark.parametrize("dimensions, name, element", [("A%(10)", "A%", "A%(I)"), ("B%(3, 3)", "B%", "B%(I, 1)")])
def test_get_and_put_under_option_base_1(dimensions, name, element, tmp_path):
    """Under OPTION BASE 1 an array's elements start at subscript 1: GET fills them from
    there (the header in the first bytes), as PC-BASIC 2.0.8; PUT draws the pixels back
    (the PSETs' colours: PC-BASIC 2.0.8 puts back 3 0 0 here, reading elsewhere)."""
    source = ("10 OPTION BASE 1: SCREEN 1: PSET (0, 0), 3: PSET (2, 0), 2: PSET (1, 1), 1\n"
              f"20 DIM {dimensions}: GET (0, 0)-(3, 1), {name}\n"
              f"30 FOR I = 1 TO 3: PRINT {element};: NEXT: PRINT\n")
    assert run(source, tmp_path) == pcbasic_vga(source, tmp_path)
    put = source + f"40 PUT (10, 10), {name}: PRINT POINT(10, 10); POINT(12, 10); POINT(11, 11)\n"
    assert run(put, tmp_path).splitlines()[1] == " 3  2  1 "
