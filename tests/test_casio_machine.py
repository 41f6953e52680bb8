"""The FX-850P/880P as a machine (casio dialect): its LCD, keyboard, memory, program areas and
program files, each checked against what the owner's manual describes (page named per test).
The programs are our own, written in the manner of Becker's library (LOCATE0,1: CHR$(5),
INPUT @n;, INPUT$(1,@)), so CI covers what the library needs without the library."""

from __future__ import annotations

import re

import yaseer
from yaseer.basic.dialects.charset import CASIO as CHARACTERS


def screens(program: str, keys: str = "", **options) -> tuple[list[str], str | None]:
    result = yaseer.run(program, input=keys, **options)
    return result.screens, result.error


def test_a_program_that_only_prints_streams_its_text_as_before():
    result = yaseer.run('10 PRINT "A";1\n20 PRINT "B"')
    assert result.text == "A 1 \nB\n" and result.screens == []


def test_locate_and_cls_draw_on_the_two_line_lcd():
    # LOCATE's page: (0,0) upper left, x to the right, y down; CLS's page: cleared, cursor home
    program = '10 PRINT "OLD";\n20 CLS: PRINT "TITLE";\n30 LOCATE 5,1: PRINT "X=";7;'
    result = yaseer.run(program)
    assert result.screens == ["TITLE\n     X= 7\n"]
    assert result.text == "OLD" + "TITLE\n     X= 7\n"  # the streamed text up to the first CLS, then the screen


def test_each_key_wait_shows_the_screen_once():
    program = ('10 CLS: PRINT "Area of a circle";\n'
               '20 LOCATE 0,1: PRINT CHR$(5);"r=";R;"?";: INPUT @42; R: LOCATE 0,0\n'
               '30 LOCATE 0,1: PRINT CHR$(5);"Area =";PI*R*R;: Z$=INPUT$(1,@): GOTO 20\n')
    shown, error = screens(program, "2\n\n3\n")  # r=2, EXE, r=3
    assert shown == [
        "Area of a circle\nr= 0 ?\n",
        "Area of a circle\nArea = 12.56637061\n",   # PI*4 to the display's 10 digits
        "Area of a circle\nr= 2 ?\n",
        "Area of a circle\nArea = 28.27433388\n",  # PI*9
    ]
    assert error == "Input past end in 30"  # the key script is over while the program waits for a key


def test_input_moves_the_cursor_to_the_next_row_as_exe_does():
    # without the library's LOCATE 0,0 after INPUT the window follows the cursor down
    shown, _ = screens('10 CLS: PRINT "TOP";: LOCATE 0,1: INPUT @1; R: PRINT "NEXT";', "5\n")
    assert shown == ["TOP\n\n", "5\nNEXT\n"]


def test_input_takes_the_screen_from_the_cursor_to_the_end_of_the_logical_line():
    # INPUT.md item 8: all data from the cursor position to the end of the current logical
    # line are input when EXE is pressed; the keys typed replace what was under them
    program = '10 CLS: PRINT "VALUE 12345"\n20 LOCATE 6,0: INPUT A\n30 PRINT A*2;'
    result = yaseer.run(program, input="9\n")
    assert result.screens[-1] == "VALUE ? 945\n 1890\n"  # "? " over 12, 9 over 3: the line reads 945
    program = '10 CLS: PRINT "NAME JOHN SMITH"\n20 LOCATE 0,0: INPUT "NAME ",N$\n30 PRINT "[";N$;"]";'
    assert yaseer.run(program, input="\n").screens[-1] == "NAME JOHN SMITH\n[JOHN SMITH]\n"  # EXE alone: the screen's text
    # a logical line goes on into the row its text wrapped into (32 columns a row)
    program = ('10 CLS: PRINT STRING$(30,"-");"ABCDEF"\n20 LOCATE 29,0: INPUT "",S$\n'
               '30 PRINT S$;')
    # EXE took the whole logical line: the cursor goes on from the row after it, not from the
    # row after the cursor's (row 1 keeps CDEF, S$ is printed on row 2)
    assert yaseer.run(program, input="\n").screens[-1] == "CDEF\n-ABCDEF\n"
    # a row begun by a line end is a logical line of its own
    program = '10 CLS: PRINT "AB"\n20 PRINT "CD"\n30 LOCATE 0,0: INPUT "",S$\n40 PRINT S$;'
    assert yaseer.run(program, input="\n").screens[-1] == "AB\nAB\n"


def test_input_takes_only_the_keys_while_nothing_was_placed():
    # a program that only PRINTs: INPUT reads the keys, as the paper's listings always did
    assert yaseer.run('10 PRINT "12345";: INPUT A: PRINT A', input="9\n").text == "12345? 9\n 9 \n"
    # gw: GW-BASIC's INPUT takes the keys typed
    result = yaseer.run('10 CLS: PRINT "12345": LOCATE 1,1: INPUT A: PRINT A', input="9\n", dialect="gw")
    assert "\n 9\n" in result.text  # (the screen shows "? 945": the keys over the old text)


def test_lprint_without_a_printer_goes_beside_the_screens_and_cls_keeps_it():
    # the printer is a device of its own (part 7; LPRINT.md): its text is not on the LCD
    result = yaseer.run('10 CLS: PRINT "SHOWN";: LPRINT "PAPER"\n20 A$=INPUT$(1): CLS: PRINT "NEXT";', input="x")
    assert result.text == "PAPER\nSHOWN\n\nNEXT\n\n"  # printed at once; the screens at the key wait and the end
    assert result.screens == ["SHOWN\n\n", "NEXT\n\n"]
    # a program that only prints: the two streams' text in the order printed, as before
    assert yaseer.run('10 PRINT "A": LPRINT "B": PRINT "C"').text == "A\nB\nC\n"


def test_a_beep_shows_a_changed_screen_once():
    # a program that beeps in a loop (LIB0400's failure loop) shows its screen at the first beep
    result = yaseer.run('10 CLS: PRINT "NG";\n20 FOR I=1 TO 3: BEEP: NEXT\n30 PRINT "END";')
    assert result.screens == ["NG\n\n", "NGEND\n\n"]


def test_the_window_follows_the_cursor_over_the_virtual_screen():
    # part 6 "Virtual screen function": 8 lines, 2 shown; LOCATE's range 0..31, 0..7
    program = '10 CLS: FOR I=0 TO 7: LOCATE 0,I: PRINT "LINE";I;: NEXT\n20 LOCATE 0,3: A$=INPUT$(1)'
    shown, _ = screens(program, "x")
    assert shown[0] == "LINE 3\nLINE 4\n"  # the window moved up to the cursor's row 3
    program = '10 CLS: LOCATE 31,7: PRINT "Z";: LOCATE 0,7: PRINT "BOTTOM";'
    shown, _ = screens(program)
    # the last cell written: the screen scrolled up (PRINT's page, item 4)
    assert shown == [" " * 31 + "Z\nBOTTOM\n"]


def test_locate_beyond_the_screen_is_an_error():
    assert screens("10 LOCATE 32,0")[1] == "Illegal function call in 10"
    assert screens("10 LOCATE 0,8")[1] == "Illegal function call in 10"


def test_print_chr12_clears_as_cls_does():
    assert screens('10 PRINT "GONE";CHR$(12);"NEW";')[0] == ["NEW\n\n"]


def test_input_dollar_reads_keys_and_a_line_break_is_exe():
    # INPUT$'s page: characters of the keyboard buffer, not shown; the library tests 13 for EXE
    program = '10 A$=INPUT$(3): PRINT ASC(MID$(A$,1,1));ASC(MID$(A$,2,1));ASC(MID$(A$,3,1))'
    result = yaseer.run(program, input="a\nb")
    assert result.text == " 97  13  98 \n"


def test_inkey_sees_a_key_only_when_it_looks_again():
    # INKEY$'s page: the key pressed *while* it looks, else "": a key of the script is pressed
    # after the program has looked once and found none (the page's sample polls in a loop)
    program = ('10 K$=INKEY$: IF K$="" THEN N=N+1: IF N<9 THEN 10 ELSE PRINT "NONE": END\n'
               '20 PRINT K$;N;: N=0: GOTO 10')
    # the API ends a text input with a line break: the third key is EXE, CHR$(13), a new line
    assert yaseer.run(program, input="OK").text == "O 1 K 1 \n 1 NONE\n"  # CHR$(13): a new line


def test_inkey_before_input_dollar_leaves_the_key_to_it():
    # the library's menus: IF INKEY$="" THEN A=ASC(INPUT$(1)) waits at INPUT$ for the key
    program = '10 A=0: IF INKEY$="" THEN A=ASC(INPUT$(1))\n20 PRINT A: IF A<>13 THEN 10'
    assert yaseer.run(program, input="I").text == " 73 \n 13 \n"


def test_empty_input_answer_keeps_the_numeric_value():
    # INPUT's page, item 7: EXE alone keeps a numeric variable's value, gives "" to a string
    program = '10 A=5: A$="X": INPUT A: INPUT A$: PRINT A; LEN(A$)'
    assert yaseer.run(program, input="\n\n").text.splitlines()[-1] == " 5  0 "


def test_peek_of_the_last_input_key_is_exe():
    program = "10 INPUT @3; Z: W=PEEK(1627)-13: PRINT Z; W"  # &H65B: the key that ended INPUT
    assert yaseer.run(program, input="4\n").text.splitlines()[-1] == " 4  0 "


def test_input_at_shows_no_question_mark_of_its_own():
    result = yaseer.run('10 PRINT "N";: INPUT @10; N: PRINT N*2', input="21\n")
    assert result.text == "N21\n 42 \n"


def test_goto_and_gosub_a_program_area(tmp_path):
    # GOSUB's and GOTO's pages: "# program area number", a single character 0-9
    area = tmp_path / "p3.bas"
    area.write_text('10 PRINT "IN AREA";X: X=X+1: RETURN\n')
    result = yaseer.run('10 X=1: GOSUB #3: GOSUB #3: PRINT "BACK";X', prog={3: area})
    assert result.text == "IN AREA 1 \nIN AREA 2 \nBACK 3 \n"
    result = yaseer.run('10 X=7: GOTO #3\n20 PRINT "NOT REACHED"', prog={3: area})
    assert result.text == "IN AREA 7 \n" and result.error is None


def test_gosub_a_library_program_file(tmp_path):
    # The library's form: GOSUB "LIB0:S6210" runs its subprogram file LIBS6210.bas
    (tmp_path / "LIBS0001.bas").write_text("10 p=x*x: RETURN\n")
    (tmp_path / "LIB0002.bas").write_text('10 PRINT "MENU ITEM";x\n')
    program = '10 x=3: GOSUB "LIB0:S0001": PRINT p\n20 r$="LIB0:0002": GOTO r$\n30 PRINT "NOT REACHED"'
    result = yaseer.run(program, files=tmp_path)
    assert result.text == " 9 \nMENU ITEM 3 \n" and result.error is None
    missing = yaseer.run('10 GOSUB "LIB0:S9999"', files=tmp_path)
    assert missing.error == "File not found: LIB0:S9999 in 10"


def test_the_character_codes_are_the_manuals_table():
    # part 12's table, and its example: PRINT CHR$(132) displays the sigma sign
    assert yaseer.run("10 PRINT CHR$(132);CHR$(&HE1 - 0);CHR$(177)".replace("&HE1 - 0", "225")).text == "∑≤ｱ\n"
    assert yaseer.run('10 PRINT ASC("π"); ASC("A")').text == " 231  65 \n"
    assert all(CHARACTERS.code(CHARACTERS.char(n)) == n for n in range(256))


def test_a_program_file_saved_on_the_machine_reads_in_its_codes(tmp_path):
    listing = tmp_path / "casio.bas"
    listing.write_bytes(b'10 PRINT "0<x\xe170 ";CHR$(225)="\xe1"\n')  # &HE1 is the less-or-equal sign
    assert yaseer.run(listing).text == "0<x≤70 -1 \n"


def test_input_at_takes_at_most_n_characters():
    # LIB5260's form: LOCATE 2,1: INPUT @3; n$ into a three-column field
    assert yaseer.run("10 INPUT @3; N$: PRINT N$", input="12345\n").text.splitlines()[-1] == "123"


def test_then_star_ends_the_program_as_the_library_writes_it():
    assert yaseer.run('10 SR=1: IF SR THEN *\n20 PRINT "GOES ON"').text == ""
    assert yaseer.run('10 IF 0 THEN * ELSE PRINT "ELSE"').text == "ELSE\n"
    assert yaseer.run("10 IF 1 THEN *", dialect="gw").error == "Syntax error in 10"  # gw has no such form


def test_files_on_the_cassette_are_in_the_programs_directory_in_the_machines_codes(tmp_path):
    # OPEN's samples: "CAS0:TEST" FOR OUTPUT, PRINT #1, CLOSE; then FOR INPUT, INPUT #1
    program = ('10 OPEN "CAS0:TEST" FOR OUTPUT AS #1\n20 PRINT #1, "X";CHR$(225);"Y"\n30 CLOSE\n'
               '40 OPEN "CAS0:TEST" FOR INPUT AS #1\n50 INPUT #1, A$\n60 CLOSE: PRINT A$; LEN(A$)')
    result = yaseer.run(program, files=tmp_path)
    assert result.text == "X≤Y 3 \n" and result.error is None
    assert (tmp_path / "TEST").read_bytes().startswith(b"X\xe1Y\r\n")  # &HE1: the machine's code


def test_the_data_bank_writes_searches_reads_saves_and_loads(tmp_path):
    # WRITE#'s sample: every item beginning with YOU becomes SHE (RESTORE# "YOU", 0, 50 jumps
    # to 50 when none is left); READ# reads items across records; SAVE#/LOAD# keep them in a file
    program = ('10 NEW#: WRITE# "YOU": WRITE# "HE", 12: WRITE# "YOUR DOG"\n'
               '20 RESTORE#\n30 RESTORE# "YOU", 0, 50\n40 WRITE# "SHE": GOTO 30\n'
               '50 LIST#: RESTORE#: READ# A$, B$, N, C$: PRINT A$; B$; N * 2; C$\n'
               '60 SAVE# "CAS0:BANK": NEW#: LOAD# "BANK": LOAD# "BANK", M\n'
               '70 RESTORE# "E", 1: RESTORE# "HE": READ# D$, M: PRINT D$; M\n'
               '80 RESTORE# "DOG"')
    result = yaseer.run(program, files=tmp_path)
    assert result.text == "1 SHE\n2 HE, 12\n3 SHE\nSHEHE 24 SHE\nHE 12 \n"  # LIST#: record numbers
    assert result.error == "Out of DATA in 80"  # the manual's DA error: no item begins with DOG
    assert (tmp_path / "BANK").read_text() == "SHE\nHE, 12\nSHE\n"


def test_text_printed_before_the_first_drawing_is_on_the_display():
    # a long stream of text, then LOCATE: the rows the virtual screen still holds are shown
    program = '10 FOR I=1 TO 500: PRINT "ROW";I: NEXT\n20 LOCATE 0,7: PRINT "END";'
    result = yaseer.run(program)
    assert result.screens == ["ROW 500\nEND\n"]
    assert result.text.startswith("ROW 1 \nROW 2 \n")  # streamed until the LOCATE


def test_defchr_defines_the_dots_of_a_user_character():
    # the library's form: DEFCHR$(255)="82FE8280C0" (five columns of dots); codes &HFC-&HFF only
    result = yaseer.run('10 DEFCHR$(255)="82FE8280C0": PRINT CHR$(255)')
    assert result.text == "➃\n" and result.error is None
    assert yaseer.run('10 DEFCHR$(250)="82FE8280C0"').error == "Illegal function call in 10"
    assert yaseer.run('10 DEFCHR$(252)="82FE"').error == "Illegal function call in 10"
    # gw reads DEFCHR$ as an array name, as it always did
    assert yaseer.run('10 DEFCHR$(255)="82FE8280C0"', dialect="gw").error == "Subscript out of range in 10"


def test_defchr_characters_are_drawn_on_the_html_lcd():
    # the library's subscript one: five columns of dots, the high bit the top dot
    from yaseer.lcd import glyph_svg, lcd_html

    result = yaseer.run('10 DEFCHR$(252)="123E020000": CLS: PRINT "H";CHR$(252)', input="")
    assert result.glyphs == [{252: "123E020000"}]
    html = lcd_html(result.screens, result.glyphs)
    assert html.count("<svg") == 1 and "H<svg" in html
    dots = {(int(x), int(y)) for x, y in re.findall(r'x="(\d)" y="(\d)"', glyph_svg("123E020000"))}
    assert dots == {(0, 3), (0, 6), (1, 2), (1, 3), (1, 4), (1, 5), (1, 6), (2, 6)}  # a small "1" on its foot


def test_calcjmp_executes_the_formula_of_calc_in_the_cal_mode():
    # part 5, the data bank example: CALC executes the stored formula Y=3*X^2+4, the display
    # cleared, "X?" asking for its variable; the value goes to the left-hand side
    result = yaseer.run('10 CLS: PRINT "MENU";: CALC$="Y=3*X^2+4": CALCJMP\n20 PRINT "NOT HERE"', input="2\n")
    assert result.screens == ["X?\n\n", "X?2\nY= 16\n"]  # 3*2^2+4
    assert result.error == "Input past end in 10"  # the result waits for EXE, which asks again
    # the library's form (LIB5950-5980): a [...] comment after a variable is shown, not computed;
    # each variable is asked in the order it first appears; EXE repeats; EXE alone keeps a value
    program = '10 CALC$="S[cm2]=PI*R[cm]^2+H*R[cm]": CALCJMP'
    result = yaseer.run(program, input="2\n1\n\n3\n\n")
    assert result.screens[:4] == ["R[cm]?\n\n", "R[cm]?2\nH?\n", "H?1\nS[cm2]= 14.56637061\n", "R[cm]?\n\n"]
    assert result.screens[4:] == ["R[cm]?3\nH?\n", "H?\nS[cm2]= 31.27433388\n"]  # PI*4+2, PI*9+3 (H kept)
    assert result.text.count("NOT HERE") == 0
    # a formula without "=" shows its value alone; a variable the program never named starts at 0
    result = yaseer.run('10 CALC$="2*A+B": A=1: CALCJMP', input="3\n\n")
    assert result.screens == ["A?\n\n", "A?3\nB?\n", "B?\n 6\n"]


def test_mode_33_copies_the_cursors_line_into_calc():
    # the library's memory calculator (LIB1000): the expression typed on the LCD's line goes to
    # CALC$ (MODE 33, a ROM routine the manual does not describe), which VALF evaluates
    program = '10 CLS: PRINT "MEMORY";: LOCATE 0,1: PRINT "12/4+1";\n20 MODE 33(32,1024,223): PRINT: PRINT VALF(CALC$);'
    assert yaseer.run(program).screens[-1] == "12/4+1\n 4\n"
    assert yaseer.run('10 MODE 30(1)').error == "MODE 30(...): a machine-code routine of the ROM is not emulated in 10"


def test_tab_counts_the_columns_from_zero():
    # TAB.md: "counting from the left end of the line (position 0)"; less than the current
    # position: a new line first; the tab specification truncated, 0..256
    result = yaseer.run('10 PRINT TAB(5);"ABC"\n20 PRINT TAB(0);"A";TAB(3);"B";TAB(1.9);"C"\n30 PRINT "WXYZ";TAB(4);"!"')
    assert result.text == "     ABC\nA  B\n C\nWXYZ!\n"
    assert yaseer.run('10 PRINT TAB(-1);"A"').error == "Illegal function call in 10"
    assert yaseer.run('10 PRINT TAB(5);"ABC"', dialect="gw").text == "    ABC\n"  # GW-BASIC's TAB(1) is the first


def test_peek_reads_the_ram_size_the_library_reads():
    # specifications.md: the FX-880P's standard 32 KB; LIB0400 reads the size in pages of 256 bytes
    program = "10 DEFSEG=0: PRINT PEEK(&H6B4)/4+PEEK(&H6B5)*64"
    assert yaseer.run(program).text == " 32 \n"
