"""The pocket computer's LCD as HTML: the screens a program drew (``Result.screens``), for
the notebook's %basic and ``yaseer report``."""

from __future__ import annotations

import html

LCD_STYLE = ("display:inline-block;margin:2px 4px 2px 0;padding:4px 6px;background:#c8d4b0;"
             "color:#1c2414;border:3px solid #4a4a4a;border-radius:4px;font:14px/1.2 monospace;"
             "white-space:pre")


def lcd_html(screens: list[str]) -> str:
    """The screens as the pocket computer's LCD (one grey-green panel each), in order."""
    panels = []
    for screen in screens:
        rows = screen.split("\n")[:-1] if screen.endswith("\n") else screen.split("\n")
        width = max([32] + [len(row) for row in rows])
        panels.append(f'<div style="{LCD_STYLE}">'
                      + "\n".join(html.escape(row.ljust(width)) for row in rows) + "</div>")
    return "<div>" + "".join(panels) + "</div>"
