"""The errata of the paper's listings (``listings/ERRATA.md``) that apply to one example.

``ERRATA.md`` is markdown: a summary table (``| example | line | slip | kind |``)
a section on all examples, and a section per example (``## Example 3 (...)``)
with its table of corrections.  :func:`errata_for` finds the file next to the
listing (or one folder up, for ``listings/paper/``) and returns, for Example n,
its summary rows, its section, the all-examples section, and the Program 5 row
when the printed Program 5 is loaded.  Only the standard
library; the markdown is rendered to HTML by :func:`to_html` (tables,
paragraphs, ``code``, *emphasis* — what the file uses).
"""

from __future__ import annotations

import html
import re
from dataclasses import dataclass, field
from pathlib import Path

EXAMPLE = re.compile(r"example(\d)$", re.IGNORECASE)


@dataclass
class Errata:
    """The errata of one example: summary rows (markdown table lines) and its section (markdown)."""

    example: int
    summary: list[str] = field(default_factory=list)
    section: str = ""
    all_examples: str = ""  # the section on what every example shares (the universal line 2)


def example_number(name: str | None) -> int | None:
    """1-5 for a listing named ``exampleN`` (corrected or as printed), else None."""
    match = EXAMPLE.match(name or "")
    return int(match.group(1)) if match else None


def find_errata(listing: Path) -> Path | None:
    """``ERRATA.md`` in the listing's folder or the one above it, if there is one."""
    for folder in (listing.parent, listing.parent.parent):
        candidate = folder / "ERRATA.md"
        if candidate.is_file():
            return candidate
    return None


def errata_for(listing: Path, printed_program_5: bool = False) -> Errata | None:
    """The errata that apply to ``listing`` (an example of the paper), or None."""
    number = example_number(listing.stem)
    source = find_errata(listing) if number is not None else None
    if source is None:
        return None
    text = source.read_text(encoding="utf-8")
    found = Errata(number)
    for line in _section(text, "Summary").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if line.startswith("|") and (cells[0] == str(number) or (printed_program_5 and cells[0] == "Program 5")):
            found.summary.append(line)
    found.section = _section(text, f"Example {number}")
    found.all_examples = _section(text, "All examples")
    return found


def _section(text: str, heading: str) -> str:
    """The body of the ``## heading...`` section (up to the next ``## ``), or ""."""
    lines = text.splitlines()
    for index, line in enumerate(lines):
        if line.startswith("## ") and line[3:].startswith(heading):
            body = []
            for following in lines[index + 1:]:
                if following.startswith("## "):
                    break
                body.append(following)
            return "\n".join(body).strip()
    return ""


def to_html(markdown: str) -> str:
    """The little markdown the errata use, as HTML: tables, paragraphs, ``- `` lists, ``code``, *emphasis*."""
    blocks: list[str] = []
    table: list[str] = []
    paragraph: list[str] = []
    items: list[str] = []

    def close() -> None:
        if table:
            rows = [r for r in table if not re.fullmatch(r"\|[\s|:-]+\|?", r.strip())]
            cells = [[c.strip() for c in r.strip().strip("|").split("|")] for r in rows]
            head = "".join(f"<th>{_inline(c)}</th>" for c in cells[0])
            body = "".join("<tr>" + "".join(f"<td>{_inline(c)}</td>" for c in row) + "</tr>" for row in cells[1:])
            blocks.append(f"<table><thead><tr>{head}</tr></thead><tbody>{body}</tbody></table>")
            table.clear()
        if paragraph:
            blocks.append(f"<p>{_inline(' '.join(paragraph))}</p>")
            paragraph.clear()
        if items:
            blocks.append("<ul>" + "".join(f"<li>{_inline(item)}</li>" for item in items) + "</ul>")
            items.clear()

    for line in markdown.splitlines():
        if line.startswith("|"):
            if not table:
                close()
            table.append(line)
        elif not line.strip():
            close()
        elif line.startswith("- "):
            if not items:
                close()
            items.append(line[2:].strip())
        elif items and line.startswith("  "):  # an item's continued line
            items[-1] += " " + line.strip()
        else:
            if table or items:
                close()
            paragraph.append(line.strip())
    close()
    return "\n".join(blocks)


def _inline(text: str) -> str:
    parts = re.split(r"(`[^`]*`)", text)
    out = []
    for part in parts:
        if part.startswith("`") and part.endswith("`") and len(part) >= 2:
            out.append(f"<code>{html.escape(part[1:-1])}</code>")
        else:
            escaped = html.escape(part)
            out.append(re.sub(r"\*([^*]+)\*", r"<em>\1</em>", escaped))
    return "".join(out)
