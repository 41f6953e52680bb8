"""The pocket computer's LCD as HTML: the screens a program drew (``Result.screens``), for
the notebook's %basic and ``yaseer report``; a user-defined character (DEFCHR$, codes
&HFC-&HFF) is drawn from its dots (``Result.glyphs``)."""

from __future__ import annotations

import html

LCD_STYLE = ("display:inline-block;margin:2px 4px 2px 0;padding:4px 6px;background:#c8d4b0;"
             "color:#1c2414;border:3px solid #4a4a4a;border-radius:4px;font:14px/1.2 monospace;"
             "white-space:pre")
USER_CODES = range(0xFC, 0x100)  # the character code table's user-defined characters


def glyph_svg(dots: str) -> str:
    """The 5 x 8 dots of DEFCHR$'s 10 hexadecimal digits (a pair a column, left to right; the
    high bit the top dot) as an inline SVG one character cell wide."""
    cells = []
    for column in range(5):
        byte = int(dots[2 * column:2 * column + 2], 16)
        cells += [f'<rect x="{column}" y="{row}" width="0.9" height="0.9"/>'
                  for row in range(8) if byte & (0x80 >> row)]
    return ('<svg viewBox="0 0 6 8" style="width:1ch;height:1.2em;vertical-align:bottom" '
            f'fill="currentColor">{"".join(cells)}</svg>')


def _row_html(row: str, drawn: dict) -> str:
    return "".join(drawn.get(ch) or html.escape(ch) for ch in row)


def lcd_html(screens: list[str], glyphs: list[dict] | None = None) -> str:
    """The screens as the pocket computer's LCD (one grey-green panel each), in order;
    ``glyphs[i]``: the DEFCHR$ characters defined when screen i was shown (code -> dots)."""
    from yaseer.basic.dialects.charset import CASIO

    panels = []
    for k, screen in enumerate(screens):
        defined = glyphs[k] if glyphs and k < len(glyphs) else {}
        drawn = {CASIO.symbols(chr(code)): glyph_svg(dots) for code, dots in defined.items() if code in USER_CODES}
        rows = screen.split("\n")[:-1] if screen.endswith("\n") else screen.split("\n")
        width = max([32] + [len(row) for row in rows])
        panels.append(f'<div style="{LCD_STYLE}">'
                      + "\n".join(_row_html(row.ljust(width), drawn) for row in rows) + "</div>")
    return "<div>" + "".join(panels) + "</div>"
