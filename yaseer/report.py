"""A one-page handout of a run: one self-contained HTML file.

The page holds the listing (a note instead for a program saved protected: GW-BASIC lists
none), what it printed (the screen, and the rows as a table under their column names),
the plots as inline SVG, the animation as the same player ``yaseer animate --out x.html``
writes (frames as PNG data), and for the paper's examples the errata that apply.  Nothing is fetched: no scripts,
fonts, styles or images from anywhere (matplotlib's SVG draws its text as
paths).  An error that stopped the run is shown in red where the output ends.
"""

from __future__ import annotations

import html
import io
from pathlib import Path

from yaseer.errata import errata_for, to_html

STYLE = """
body { font-family: system-ui, sans-serif; max-width: 1320px; margin: 1.5em auto; padding: 0 1em; color: #111; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; } h2 { border-bottom: 2px solid #ddd; margin-top: 1.6em; }
pre { background: #f6f6f4; padding: 0.8em; overflow-x: auto; font-size: 0.95em; }
table { border-collapse: collapse; font-size: 0.92em; } td, th { border: 1px solid #ccc; padding: 0.25em 0.6em; }
table.rows td { text-align: right; font-family: monospace; } th { background: #eef; vertical-align: bottom; }
.error { color: #c00000; font-weight: bold; } .meta { color: #555; }
section.errata td { vertical-align: top; } section.errata table { margin: 0.8em 0; }
"""

SUMMARY_HEADER = "| example | line | slip | kind |\n|---|---|---|---|"


def build_page(result, listing_path: Path | None = None, printed_program_5: bool = False, fps: float = 6.0,
               size: tuple[int, int] = (1280, 720), max_frames: int = 120) -> str:
    """The handout of ``result`` (a :class:`yaseer.api.Result`) as one HTML document."""
    parts = [f"<h1>{html.escape(result.title)}</h1>"]
    if listing_path is not None:
        parts.append(f'<p class="meta">{html.escape(str(listing_path))}</p>')
    parts.append("<h2>The listing</h2>")
    if result.protected:  # GIODSK.ASM PROCHK: GW-BASIC never lists such a program
        parts.append('<p class="meta" id="protected">The program was saved protected (SAVE ,P): '
                     "it is not listed, as GW-BASIC does not list it.</p>")
    else:
        parts.append(f"<pre>{html.escape(result.listing)}</pre>")
    parts.append("<h2>What it printed</h2>")
    parts.append(f'<pre id="screen">{html.escape(result.text)}</pre>')
    if result.screens:  # a program that drew on the display: the LCD as it showed it
        from yaseer.lcd import lcd_html

        parts.append(f'<h2>The LCD</h2>\n<div id="lcd">{lcd_html(result.screens, result.glyphs)}</div>')
    if result.error is not None:
        parts.append(f'<p class="error" id="error">{html.escape(result.error)}</p>')
    parts += _tables(result)
    parts += _plot(result)
    parts += _player(result, fps, size, max_frames)
    if listing_path is not None:
        parts += _errata(listing_path, printed_program_5)
    body = "\n".join(parts)
    return (f'<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
            f"<title>{html.escape(result.title)}</title><style>{STYLE}</style></head>\n<body>\n{body}\n</body></html>\n")


def _tables(result) -> list[str]:
    """Each shape of printed rows as a table, full precision to 7 significant digits."""
    parts = []
    for group in result.row_groups():
        names = group.names or tuple(f"column {k + 1}" for k in range(group.width))
        head = "".join(f"<th>{html.escape(name)}</th>" for name in names)
        body = "".join("<tr>" + "".join(f"<td>{value:.7g}</td>" for value in row) + "</tr>" for row in group.rows)
        parts.append(f'<table class="rows"><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>')
    if parts:
        parts.insert(0, "<h2>The rows</h2>")
    return parts


def _plot(result) -> list[str]:
    try:
        figure = result.plot()
    except ValueError:
        return []
    buffer = io.StringIO()
    figure.savefig(buffer, format="svg")
    svg = buffer.getvalue()
    svg = svg[svg.index("<svg"):]  # drop the XML prologue and DOCTYPE: inline in HTML
    return ["<h2>The printed columns</h2>", f'<div class="plot">{svg}</div>']


def _player(result, fps: float, size: tuple[int, int], max_frames: int) -> list[str]:
    from yaseer.animation import AnimationError, html_player

    try:
        player = html_player(result.frames, result.look(size), fps=fps, max_frames=max_frames)
    except AnimationError:
        return []
    return ["<h2>The mechanism</h2>", player]


def _errata(listing_path: Path, printed_program_5: bool) -> list[str]:
    errata = errata_for(listing_path, printed_program_5)
    if errata is None or not (errata.summary or errata.section):
        return []
    parts = [f'<section class="errata"><h2>Errata: Example {errata.example} as printed in the paper</h2>']
    if errata.summary:
        parts.append(to_html(SUMMARY_HEADER + "\n" + "\n".join(errata.summary)))
    parts.append(to_html(errata.section))
    if errata.all_examples:
        parts.append("<h3>All examples</h3>")
        parts.append(to_html(errata.all_examples))
    parts.append("</section>")
    return parts
