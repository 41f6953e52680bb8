"""A machine's character codes (0..255) and the Unicode characters yaseer holds for them.

Inside the machine a string holds the machine's codes, one character each (``chr(0)`` to
``chr(255)``), so CHR$, ASC, PEEK, the files' bytes and GW's byte functions agree; a
:class:`CharacterSet` says which Unicode character *shows* each code.  Text crosses
between the two at the machine's edges: a program's text and typed keys are turned into
codes (:meth:`CharacterSet.codes`) as they come in, and what the screen, the printer and
the LCD's screens show is turned into symbols (:meth:`CharacterSet.symbols`) as it goes
out.

* :data:`LATIN1`: code n is ``chr(n)``.
* :data:`CP437`: GW-BASIC's, the IBM PC's code page 437 (``é`` is code 130, ``│`` 179).
* :data:`CASIO`: the FX-850P/880P's codes as the owner's manual's character code
  table (part 12) draws them: 0..127 are ASCII, 128..255 the symbols of the table
  (Greek letters, superscripts, half-width katakana, arrows, card suits ...).  Where the
  table's symbol is an ASCII character already (code &H83, a prime; &HEF, a
  backslash) another Unicode character with that look stands for it, so every code
  reads back as itself; code &H9E (the table's "-1" superscript, one cell) is U+1D7F7.
  Codes &H5C and &HEF are drawn as the table draws them only where yaseer shows an
  LCD; in program text &H5C stays ``\\`` (integer division, typed as on a PC).
"""

from __future__ import annotations

# What each control code does on the Casio (owner's manual, part 12 character code table,
# the codes in parentheses; the arrows are the cursor keys' codes &H1C-&H1F).
CASIO_CONTROLS = {
    2: "line_top", 5: "line_cancel", 6: "line_end", 8: "backspace", 10: "line_feed",
    11: "home", 12: "clear", 13: "carriage_return", 28: "right", 29: "left", 30: "up", 31: "down",
}
# 128..255 in table order, 16 to a line (the manual's columns 8..F).
_CASIO_HIGH = (
    "Å∫√′∑Ω▒█αβγεθμσφ"       # &H80  (&H83: the prime, U+2032)
    "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻ⁿ﹪\U0001D7F7÷"   # &H90  (&H9E: the superscript -1)
    "␣｡｢｣､･ｦｧｨｩｪｫｬｭｮｯ"      # &HA0  half-width katakana as JIS X 0201 numbers them
    "ｰｱｲｳｴｵｶｷｸｹｺｻｼｽｾｿ"      # &HB0
    "ﾀﾁﾂﾃﾄﾅﾆﾇﾈﾉﾊﾋﾌﾍﾎﾏ"      # &HC0
    "ﾐﾑﾒﾓﾔﾕﾖﾗﾘﾙﾚﾛﾜﾝﾞﾟ"      # &HD0
    "≥≤≠↑←↓→π♠♥♣♦◻▢△＼"       # &HE0  (&HEF: the backslash, U+FF3C)
    "×円年月日千万£¢±∓₀➀➁➂➃"   # &HF0  (&HFC-&HFF: the user-defined characters)
)


class CharacterSet:
    """The characters that show codes 128..255 (``high``; None: Latin-1, shown as they are)."""

    __slots__ = ("name", "_chars", "_codes", "_to_symbols", "_to_codes", "_cells")

    def __init__(self, name: str, high: str | None = None, cells: str | None = None):
        """``cells``: the 33 characters a screen cell holding code 0..31 or 127 is drawn with
        (the display's font has a picture for each; printed, most of these codes act, as
        the dialect's ``controls`` say, and what does not act is stored in a cell)."""
        self.name = name
        chars = [chr(n) for n in range(128)] + (list(high) if high else [chr(n) for n in range(128, 256)])
        if len(chars) != 256 or len(set(chars)) != 256:
            raise ValueError(f"character set {name}: 256 distinct characters needed")
        self._chars = chars
        self._codes = {ch: n for n, ch in enumerate(chars)}
        self._to_symbols = {n: chars[n] for n in range(128, 256)} if high else None
        self._to_codes = {ord(ch): n for n, ch in enumerate(chars) if n >= 128} if high else None
        self._cells = None
        if cells is not None:
            if len(cells) != 33:
                raise ValueError(f"character set {name}: 33 cell pictures needed (codes 0..31 and 127)")
            self._cells = {**(self._to_symbols or {}), **dict(zip([*range(32), 127], cells))}

    def __repr__(self) -> str:  # stable across processes: the program cache keys on the dialect's repr
        return f"CharacterSet({self.name!r})"

    @property
    def symbols_table(self) -> dict[int, str] | None:
        """:meth:`symbols`'s ``str.translate`` table (None: codes are shown as they are)."""
        return self._to_symbols

    @property
    def own_symbols(self) -> bool:
        """True when codes 128..255 are shown as symbols of their own (not Latin-1)."""
        return self._to_symbols is not None

    def char(self, code: int) -> str:
        """The character that shows ``code`` (0..255)."""
        return self._chars[code]

    def code(self, ch: str) -> int | None:
        """The code character ``ch`` shows, None if the machine has none."""
        return self._codes.get(ch)

    def symbols(self, text: str) -> str:
        """Text in the machine's codes (``chr(0..255)``) as it is shown: 128..255 as symbols."""
        if self._to_symbols is None or text.isascii():
            return text
        return text.translate(self._to_symbols)

    def cell_symbols(self, text: str) -> str:
        """A screen's cells (codes) as the display draws them: :meth:`symbols`, and the codes
        below 32 and 127 as the font's pictures where the set has them (a transcript of the
        screen then holds no control characters)."""
        if self._cells is None:
            return self.symbols(text)
        return text.translate(self._cells)

    def codes(self, text: str) -> str:
        """Text as typed or shown (symbols) in the machine's codes; other characters stay."""
        if self._to_codes is None or text.isascii():
            return text
        return text.translate(self._to_codes)

    def program_text(self, data: bytes) -> str:
        """A program file's text, shown: UTF-8 when it is UTF-8, else bytes in the machine's
        codes (a file saved on the machine) as their symbols; Latin-1's machine reads a bad
        byte as U+FFFD."""
        try:
            return data.decode("utf-8")
        except UnicodeDecodeError:
            if self._to_symbols is None:
                return data.decode("utf-8", errors="replace")
            return self.symbols(data.decode("latin-1"))


LATIN1 = CharacterSet("latin-1")  # code n is chr(n): a machine without symbols of its own
# The IBM PC's characters (code page 437, the table GW-BASIC's screen shows and its files hold):
# what PC-BASIC 2.0.8 shows and saves by default; 0..127 stay ASCII (their control actions
# are the screen's, dialects/screens.py).
# The IBM PC's font draws codes 1..31 and 127 as pictures (code 0 as a blank); the
# line breaks in a cell's row are the transcript's, so 10 and 13 are drawn too.
CP437 = CharacterSet("cp437", bytes(range(128, 256)).decode("cp437"),
                     cells=" \u263a\u263b\u2665\u2666\u2663\u2660\u2022\u25d8\u25cb\u25d9\u2642\u2640\u266a\u266b\u263c"
                     "\u25ba\u25c4\u2195\u203c\u00b6\u00a7\u25ac\u21a8\u2191\u2193\u2192\u2190\u221f\u2194\u25b2\u25bc"
                     "\u2302")
CASIO = CharacterSet("casio", _CASIO_HIGH)
