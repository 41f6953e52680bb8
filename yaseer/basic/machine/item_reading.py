"""INPUT #'s and LINE INPUT #'s reading of one item, a character at a time, in the order
GW-BASIC's reader (DSKCOM.ASM ``INPDOR``) asks the file for them.

The reader works on a *source* with three operations:

``first()``
    the item's first character (GIO86.ASM ``INCHR``: the end of the file is ``Input
    past end``), also each blank skipped before it;
``next()``
    any later character, or None at the end of the file (``INDSKC``: the end ends the item);
``back(ch)``
    give ``ch`` back, the next ``first()`` or ``next()`` returns it (``BAKCHR``).

A source may raise errors of its own (a random file's record buffer: ``FIELD overflow``
when the reader asks beyond the record).  The order of the calls is therefore part of the
behaviour: after a closing quote or a blank the reader asks for one more character (to
skip blanks and one comma or CR LF), after a CR for one more (a LF), and an unterminated
item asks until the end.
"""

from __future__ import annotations

NUMBER, TEXT, LINE = "n", "s", "l"  # an item's kind: a number, a string, a LINE INPUT line
LONGEST = 255  # characters one item holds (STRCHR's count): the rest begins the next item


def read_item(source, kind: str, longest: int = LONGEST) -> str:
    """One item of ``kind`` from ``source``, as text: a number's text for the number
    reader, a string without its quotes (unquoted: without trailing blanks), a line
    without its CR (LF)."""
    # the two characters that end the item: blank and comma for a number, comma for a
    # string (quotes once it starts with one), none for a line
    ends = " ," if kind == NUMBER else "," if kind == TEXT else ""
    ch = source.first()
    while ch == " " and kind != LINE:  # blanks before an item are skipped
        ch = source.first()
    quoted = False
    if ch == '"' and kind == TEXT:
        quoted, ends = True, '"'
        ch = source.next()
    out: list[str] = []
    if ch is not None:
        ch = _characters(source, kind, ch, ends, quoted, out, longest)
        if ch is not _FULL:
            _after(source, ch)
    text = "".join(out)
    return text.rstrip(" ") if kind == TEXT and not quoted else text


_FULL = object()  # the item took ``longest`` characters: nothing after it is read


def _characters(source, kind, ch, ends, quoted, out, longest):
    """Store the item's characters from ``ch`` on; the character that ended it (None: the
    end of the file, "\\r" after its LF was dealt with, _FULL)."""
    after_lf = False  # LPISLF: in a run of LFs, which a number and a line keep
    while True:
        if not quoted and ch == "\n":
            after_lf = True
            if kind != TEXT and _stored(out, ch, longest):
                return _FULL
        elif not quoted and ch == "\r" and not (after_lf and kind == LINE):
            if not after_lf:
                _line_feed(source)
                return "\r"
            after_lf = False  # a CR right after LFs is skipped (a line keeps it)
        else:
            after_lf = False
            if ch in ends:
                return ch
            if ch != "\0" and _stored(out, ch, longest):  # a zero byte is never stored
                return _FULL
        ch = source.next()
        if ch is None:
            return None


def _stored(out: list, ch: str, longest: int) -> bool:
    """Store ``ch``; whether the item is now full (STRCHR)."""
    out.append(ch)
    return len(out) >= longest


def _after(source, ch) -> None:
    """After a closing quote or a blank: blanks, then one comma or CR (LF) are consumed
    (MORSPC); another character is given back."""
    if ch not in ('"', " "):
        return
    ch = source.next()
    while ch == " ":
        ch = source.next()
    if ch is None or ch == ",":
        return
    if ch == "\r":
        _line_feed(source)
    else:
        source.back(ch)


def _line_feed(source) -> None:
    """After a CR: a LF is consumed, another character given back (ICASLF)."""
    ch = source.next()
    if ch is not None and ch != "\n":
        source.back(ch)
