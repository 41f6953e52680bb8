"""How a dialect's text screen behaves: the rules the shared display model
(yaseer/basic/machine/display.py) and the screen statements follow, as plain data.

A :class:`ScreenRules` is part of a :class:`~yaseer.basic.dialects.dialect.Dialect`
(its ``screen`` field); the display's size is the dialect's ``display`` and what each
control code does its ``controls``.

* ``late_wrap``: True keeps the cursor past the last column after a row is filled,
  until the next character arrives (GW-BASIC: SCNDRV.ASM keeps CSRX at LINLEN+1 and
  CHWRAP wraps before the next character; so a full bottom row does not scroll the
  screen); False wraps at once (the Casio's PRINT page: "a line feed results when the
  cursor reaches the last column").
* ``origin``: the number of the first row and column in LOCATE, CSRLIN, POS and
  SCREEN() (0 on the Casio, 1 in GW-BASIC).
* ``row_first``: True when LOCATE names the row first (GW's ``LOCATE row, col``),
  False for the Casio's ``LOCATE x, y``.
* ``locate_arguments``: (fewest, most) arguments LOCATE takes (the Casio's x and y;
  GW's five optional ones, GWSTS.ASM LOCATE).
* ``function_keys``: the texts of the function keys the last row shows under KEY ON
  (GW-BASIC's defaults; ``()``: no key line).  A screen with a key line keeps its last
  row out of the rows that scroll, whether the keys are shown or not (SCNDRV.ASM: the
  window ends at LINCNT-1).
* ``key_label``: characters of each key's text on the key line (GWSTS.ASM KEYDSP
  writes the key's number, this many characters, then a blank: 8 columns a key).
* ``clear_draws``: True makes CLS turn a transcript from streamed text into screens
  (the Casio, whose 2-line LCD is all one sees); False leaves the text streaming
  after CLS (a GW program that clears the screen and PRINTs reads in order), and
  only placing text (LOCATE, cursor codes, VIEW PRINT) shows screens.
* ``attributes``: True when cells carry a colour attribute (COLOR, SCREEN(r, c, 1)).
* ``trace_mark``: what TRON shows as a line starts, a format of ``area`` (the program
  area's name: ``P0`` .. ``P9``, a program file's name) and ``line``: GW-BASIC's ``[n]`` inline (as PC-BASIC 2.0.8 prints it), the Casio's ``P0-10`` (TRON.md: the area and the line number).
* ``trace_halts``: True puts the mark on a row of its own and suspends the run there
  until EXE is pressed (TRON.md, item 2; part 6 "Irregular execution"); the keys must
  come from a person at a terminal for that (see InputOutput.trace_line).
* ``input_reads_screen``: True makes INPUT, on a drawn display, take everything from the
  cursor (after its prompt) to the end of the logical line when EXE is pressed: the keys
  typed over what the screen held there (the Casio's INPUT.md, item 8); False takes the
  keys typed alone.
* ``printer_apart``: True sends LPRINT without a printer (no ``--printer``) to the output as
  it is printed, beside the screens and never part of them (CLS does not erase it; CSRLIN,
  POS and SCREEN() do not see it): the Casio's printer is a device of its own (part 7), and
  GW-BASIC's LPRINT writes to LPT1: only (GIO86.ASM LPRINT sets PTRFIL to the printer),
  leaving the screen as it was; False lets it share the screen's text.
* ``video_segment``: the segment (a paragraph number) where the text screen's memory starts
  for PEEK and POKE (machine/address_space.py): &HB800 on GW-BASIC's colour PC (the CGA's
  text memory; a monochrome adapter's would be &HB000); None: the screen has no memory a
  program reaches (the Casio's PEEK reads its own RAM).
* ``byte_statements``: the screen statements whose arguments are read one small number at a
  time, as (word, how many) pairs: GW-BASIC's GWSTS.ASM SCNINT reads each (left out where
  a comma or the statement's end comes first, else GETBYT: beyond -32768..32767 Overflow,
  outside 0..255 Illegal function call, and a number followed by anything but ``,``, ``)``
  or the statement's end Illegal function call); after ``how many`` of them the statement
  must end (EOSCHK: Syntax error; one comma after the last is read with it).  ``None``:
  any number of them (GTPRMS, COLOR and SCREEN).  Empty (the Casio): the statements read
  their arguments as expressions.
* ``modes``: the screen modes SCREEN n may choose (:class:`ScreenMode`, the first is the
  text mode the machine starts in); empty: SCREEN is text mode 0 only.
* ``literal_width``: True when ``WIDTH n`` with n starting with a number reads that number
  alone (``WIDTH 39+1`` is Illegal function call: a real GW-BASIC 3.23's recorded WIDTH
  test, as PC-BASIC 2.0.8 reads it).
"""

from __future__ import annotations

from collections import namedtuple

ScreenRules = namedtuple("ScreenRules", ("late_wrap", "origin", "row_first", "locate_arguments",
                                         "function_keys", "key_label", "clear_draws", "attributes",
                                         "trace_mark", "trace_halts", "input_reads_screen",
                                         "printer_apart", "video_segment", "byte_statements", "modes",
                                         "literal_width"), defaults=(None, (), (), False))

# One mode SCREEN n chooses: its number, the columns it sets (None: the width stays, as
# the text mode keeps WIDTH 40 after a 40-column mode), its pages at 40 and at 80 columns,
# the attribute text starts in, and what COLOR accepts there: "text" (foreground 0..31,
# background and border 0..15), "palette" (CGA's background and palette: any byte), "none"
# (Illegal function call) or "ega" (foreground 1..15, background 0..``colours``-1, the
# third number any byte).  A graphics mode also has its pixels: ``width`` x ``height``,
# ``bits`` of video memory a pixel (2 in CGA's mode 1, 1 in mode 2, 4 in EGA's modes: their
# GET arrays and BSAVE images pack pixels so); a text mode has 0 of each.
ScreenMode = namedtuple("ScreenMode", ("number", "columns", "pages", "attribute", "color", "colours",
                                       "width", "height", "bits"), defaults=(0, 0, 0))

CASIO_SCREEN = ScreenRules(late_wrap=False, origin=0, row_first=False, locate_arguments=(2, 2),
                           function_keys=(), key_label=0, clear_draws=True, attributes=False,
                           trace_mark="{area}-{line}", trace_halts=True, input_reads_screen=True,
                           printer_apart=True)

# GW-BASIC's soft keys at start (F1..F10; GWSTS.ASM's table is the OEM's, these are the
# IBM PC's as PC-BASIC 2.0.8 has them); a carriage return ends several.
GW_FUNCTION_KEYS = ("LIST ", "RUN\r", 'LOAD"', 'SAVE"', "CONT\r", ',"LPT1:"\r', "TRON\r", "TROFF\r",
                    "KEY ", "SCREEN 0,0,0\r")

# The modes of a colour PC with a VGA (as PC-BASIC 2.0.8's default machine, which its
# recorded tests ran against): text mode 0 (8 pages at 40 columns, 4 at 80), CGA's
# 4-colour mode 1 and 2-colour mode 2, EGA's 16-colour modes 7, 8 and 9 (the recorded COLOR
# test: COLOR 0 is refused in 2, 7, 8, 9, a background of 255 in 7 to 9, nothing but the
# byte range in 1).  The graphics modes' pixels live in machine/graphics.py.
GW_MODES = (
    ScreenMode(0, None, (8, 4), 7, "text", 16),
    ScreenMode(1, 40, (1, 1), 3, "palette", 4, 320, 200, 2),
    ScreenMode(2, 80, (1, 1), 1, "none", 2, 640, 200, 1),
    ScreenMode(7, 40, (8, 8), 15, "ega", 16, 320, 200, 4),
    ScreenMode(8, 80, (4, 4), 15, "ega", 16, 640, 200, 4),
    ScreenMode(9, 80, (2, 2), 15, "ega", 64, 640, 350, 4),
)

GW_SCREEN = ScreenRules(late_wrap=True, origin=1, row_first=True, locate_arguments=(0, 5),
                        function_keys=GW_FUNCTION_KEYS, key_label=6, clear_draws=False, attributes=True,
                        trace_mark="[{line}]", trace_halts=False, input_reads_screen=False,
                        printer_apart=True, video_segment=0xB800,
                        byte_statements=(("CLS", 1), ("LOCATE", 5), ("WIDTH", 2), ("COLOR", None), ("SCREEN", None)),
                        modes=GW_MODES, literal_width=True)

# What each control code does on GW-BASIC's text screen when PRINTed (the OEM's PRTMAP is
# not in the published source; PC-BASIC 2.0.8's console does this): TAB to the next
# multiple of 8, CR and LF a new row, ^K home within the window, ^L clear it, ^\ ^] ^^ ^_
# move the cursor within the window (SCNDRV.ASM WCSADV WCSREG WCSUP WCSDWN); BEL (7) sounds
# and shows nothing; every other code shows as its character (CHR$(0), CHR$(8) ...).
GW_CONTROLS = {code: "glyph" for code in range(32)}
GW_CONTROLS.update({
    7: "bell", 9: "tab", 10: "carriage_return", 11: "window_home", 12: "clear", 13: "carriage_return",
    28: "advance", 29: "regress", 30: "window_up", 31: "window_down",
})
