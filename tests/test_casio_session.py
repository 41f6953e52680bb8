"""The interactive session shows the pocket computer's LCD: a program that draws (CLS,
LOCATE) shows the 32-column, 2-line screen in a frame each time it waits for a key and
when it ends, typed on a real pseudo-terminal (pexpect)."""

from __future__ import annotations

from test_interactive import terminal  # noqa: F401  (the pseudo-terminal fixture)

TOP = "\u250c" + "\u2500" * 32 + "\u2510"
BOTTOM = "\u2514" + "\u2500" * 32 + "\u2518"


def lcd(first: str, second: str) -> str:
    return f"{TOP}\n\u2502{first.ljust(32)}\u2502\n\u2502{second.ljust(32)}\u2502\n{BOTTOM}\n"


def test_a_drawing_program_shows_the_lcd_at_each_key_and_at_its_end(terminal):
    terminal.type('10 CLS: PRINT "Circle area";')
    terminal.type('20 LOCATE 0,1: PRINT CHR$(5);"r=";R;"?";: INPUT @42; R: LOCATE 0,0')
    terminal.type('30 LOCATE 0,1: PRINT CHR$(5);"Area =";PI*R*R;')
    terminal.child.send("RUN\r")
    terminal.child.expect_exact(lcd("Circle area", "r= 0 ?").replace("\n", "\r\n"))  # waiting for the radius
    terminal.child.send("2\r")
    shown = terminal.wait()
    assert lcd("Circle area", "Area = 12.56637061") in shown.replace("\r", "")
    terminal.close()


def test_printing_in_direct_mode_still_scrolls_as_text(terminal):
    assert terminal.type("PRINT 6*7") == " 42 \n"
    terminal.close()
