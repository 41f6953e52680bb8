"""A machine's character codes (0..255) and the Unicode characters yaseer holds for them.

Inside yaseer a string is Python text; a :class:`CharacterSet` says which character
stands for each of the machine's 256 codes, so that ``CHR$``/``ASC`` answer in the
machine's codes, a program file or data file written on the machine (bytes) reads
as text, and a file yaseer writes holds the machine's bytes again.

* :data:`LATIN1`: code n is ``chr(n)`` (GW-BASIC as yaseer has always run it).
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
    """The characters standing for codes 0..255 (``high``: the 128 for codes 128..255, or None
    for Latin-1)."""

    __slots__ = ("name", "_chars", "_codes", "_own_files", "_codec")

    def __init__(self, name: str, high: str | None = None, own_files: bool = True):
        self.name = name
        self._own_files = own_files  # False: a program file that is not UTF-8 reads with U+FFFD for its bad bytes
        chars = [chr(n) for n in range(128)] + (list(high) if high else [chr(n) for n in range(128, 256)])
        if len(chars) != 256 or len(set(chars)) != 256:
            raise ValueError(f"character set {name}: 256 distinct characters needed")
        self._chars = chars
        self._codes = {ch: n for n, ch in enumerate(chars)}
        self._codec = None

    def __repr__(self) -> str:  # stable across processes: the program cache keys on the dialect's repr
        return f"CharacterSet({self.name!r})"

    def char(self, code: int) -> str:
        """The character of ``code`` (0..255)."""
        return self._chars[code]

    def code(self, ch: str) -> int | None:
        """The code of character ``ch``, None if the machine has none."""
        return self._codes.get(ch)

    def decode(self, data: bytes) -> str:
        """Bytes in the machine's codes as text."""
        chars = self._chars
        return "".join([chars[b] for b in data])

    def encode(self, text: str) -> bytes:
        """Text as bytes in the machine's codes; a character it has no code for is ``?``."""
        codes = self._codes
        return bytes([codes.get(ch, 63) for ch in text])

    @property
    def encoding(self) -> str:
        """A name ``open()`` and ``bytes.decode`` accept for these codes (registered with
        :mod:`codecs` on first use; ``latin-1`` for Latin-1)."""
        if not self._own_files:
            return "latin-1"
        if self._codec is None:
            import codecs

            table = "".join(self._chars)
            mapping = codecs.charmap_build(table)
            codec_name = f"yaseer-{self.name}"

            def encode(text, errors="strict"):
                return codecs.charmap_encode(text, errors, mapping)

            def decode(data, errors="strict"):
                return codecs.charmap_decode(data, errors, table)

            class Encoder(codecs.IncrementalEncoder):
                def encode(self, text, final=False):
                    return codecs.charmap_encode(text, self.errors, mapping)[0]

            class Decoder(codecs.IncrementalDecoder):
                def decode(self, data, final=False):
                    return codecs.charmap_decode(data, self.errors, table)[0]

            info = codecs.CodecInfo(encode, decode, name=codec_name,
                                    incrementalencoder=Encoder, incrementaldecoder=Decoder)
            codecs.register(lambda name: info if name in (codec_name, codec_name.replace("-", "_")) else None)
            self._codec = codec_name
        return self._codec

    def program_text(self, data: bytes) -> str:
        """A program file's text: UTF-8 when it is UTF-8, else the machine's codes (a file
        saved on the machine itself)."""
        try:
            return data.decode("utf-8")
        except UnicodeDecodeError:
            return self.decode(data) if self._own_files else data.decode("utf-8", errors="replace")


LATIN1 = CharacterSet("latin-1", own_files=False)  # gw reads program files as it always has
CASIO = CharacterSet("casio", _CASIO_HIGH)
