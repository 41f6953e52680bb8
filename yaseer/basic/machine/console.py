"""The machine's display and keyboard: the screen model behind PRINT, LOCATE and CLS, the
screens a transcript shows, the key stream INKEY$ and INPUT$ read, and the memory PEEK reads.

The :class:`Console` mixin of :class:`yaseer.basic.machine.Machine`.  Where the dialect
has a display (``Dialect.display``; casio's 32 x 8 virtual screen with its 2-line LCD),
the screen stream is a :class:`DisplayStream`: text goes to the display model
(yaseer/basic/machine/display.py) and, until the program first places text itself (LOCATE, CLS,
a cursor control code), on to the output as before, so a program that only PRINTs
prints exactly what it always did.  Once drawn, the output gets the display's shown rows
(a *screen*) each time the program waits for a key and when it ends, and
``Machine.screens`` keeps them (the API's ``Result.screens``).

The key stream is the input (``--input FILE``, or the keyboard): INPUT reads a line,
INKEY$ and INPUT$ take characters, a line break being the dialect's ``enter_key``
(casio: EXE, ``CHR$(13)``).
"""

from __future__ import annotations

import sys

from yaseer.basic.arithmetic.values import to_int
from yaseer.basic.machine import runtime
from yaseer.basic.machine.display import DRAWING_ACTIONS, Display, boxed
from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL, INPUT_PAST_END
from yaseer.basic.machine.screen import OutputStream
from yaseer.basic.machine.screen_words import ScreenWords
from yaseer.patterns import Pattern

# Memory the FX-850P's programs read (Becker's library): the code of the key that ended
# the last INPUT (EXE: 13; its programs test PEEK(&H65B)-13), and a byte that is 0 while no
# shift key is held (PEEK(206) after INPUT$).  Every other address holds what POKE left, at
# first the dialect's system bytes (casio.SYSTEM_MEMORY) or 0.
# (POKE and DEFSEG are the casio words' statements; they share ``memory`` and ``segment``.)
LAST_INPUT_KEY = 0x65B
EMPTY_POLLS = 1000  # INKEY$ answers "" this many times at the end of the key stream, then Input past end
TAIL_PIECES = 1024  # pieces of streamed text kept before they are cut to the screen's last rows
# SGR colours of the text screen's 16 (CGA order: blue is 1, red 4) for a terminal's COLOR
_ANSI = (0, 4, 2, 6, 1, 5, 3, 7)


def typed_codes(text: str, stored_words: dict) -> list[int]:
    """The bytes the input buffer holds for a typed line ``text`` (in the machine's codes):
    each of ``stored_words`` (word -> its codes) outside quotes as its codes, read where it
    starts as the Casio reads keywords (part 6: a reserved word cannot start a name), every
    other character as its code."""
    words = sorted(stored_words, key=len, reverse=True)
    upper = text.upper()  # keywords are read in either case
    codes: list[int] = []
    quoted = False
    at = 0
    while at < len(text):
        character = text[at]
        word = None if quoted else next((w for w in words if upper.startswith(w, at)), None)
        if word is not None:
            codes.extend(stored_words[word])
            at += len(word)
            continue
        quoted ^= character == '"'
        codes.append(ord(character) & 0xFF)
        at += 1
    return codes


def end_of_keys() -> BasicError:
    """The key stream is over: the run ends (no ON ERROR handler can catch it, since no key
    will ever come: a program's handler that asks again would wait for ever)."""
    err = BasicError("Input past end", INPUT_PAST_END)
    err.trappable = False
    return err


class SymbolStream:
    """An output stream that shows the machine's codes 128..255 as its character set's symbols."""

    def __init__(self, stream, charset):
        self.stream = stream
        self.charset = charset
        write, symbols = stream.write, charset.symbols_table

        def shown(text: str):  # one call a PRINT item (no method lookups): ASCII passes as it is
            return write(text if text.isascii() else text.translate(symbols))

        self.write = shown

    def flush(self) -> None:
        self.stream.flush()

    def isatty(self) -> bool:
        isatty = getattr(self.stream, "isatty", None)
        return bool(isatty is not None and isatty())

    def __getattr__(self, name):  # getvalue, close ...: the stream's own
        return getattr(self.stream, name)


class DisplayStream(OutputStream):
    """The screen stream of a machine with a display (see the module docstring).

    Until the program draws, the text is streamed on and only its last rows are kept
    (``_tail``): the display is brought up to date from them when the program first
    draws, so a program that only PRINTs pays almost nothing for the model."""

    def __init__(self, stream, display: Display, width: int | None = None):
        super().__init__(stream, width)
        self.display = display
        self._tail: list[str] = []
        # ASCII text needs no symbols: written past a SymbolStream (every PRINT item's path)
        self._ascii_write = stream.stream.write if isinstance(stream, SymbolStream) else stream.write
        controls = display.controls
        # codes that place text (the display is drawn on) and codes that move the cursor otherwise
        # than one column a character (the display must say where the column is)
        self._drawing = _codes_matching(controls, lambda action: action in DRAWING_ACTIONS)
        self._special = _codes_matching({code: action for code, action in controls.items() if code != 10},
                                        lambda action: action not in ("glyph", "carriage_return"))
        # ("\n" is the line end: a new row on every display, whatever its code 10 does)

    def write(self, text: str) -> None:
        display = self.display
        # (a line's end, "\n", is no special code: plain rows need no search, nor its pattern compiled)
        if display.drawn or not (text.isprintable() or (text[-1:] == "\n" and text[:-1].isprintable())
                                 or not self._special.search(text)):
            self._placed(text)
            return
        # streamed text: kept for the display, written on as OutputStream.write does (inline:
        # this is every PRINT item's path)
        tail = self._tail
        tail.append(text)
        if len(tail) > TAIL_PIECES:
            self._shorten_tail()
        if "\r" in text:
            text = text.replace("\r", "\n")
        width = self.width
        if width is not None:
            column = self.column
            if "\n" not in text and column + len(text) < width:
                if text.isascii():
                    self._ascii_write(text)
                else:
                    self.stream.write(text)
                self.column = column + len(text)
                return
            text = self._folded(text)
        if text.isascii():
            self._ascii_write(text)
        else:
            self.stream.write(text)
        newline = text.rfind("\n")
        self.column = len(text) - newline - 1 if newline >= 0 else self.column + len(text)

    def _placed(self, text: str) -> None:
        """Text with codes that draw or move the cursor, or any text once the display is drawn."""
        if not text:
            return
        display = self.display
        was_drawn = display.drawn
        self.catch_up()
        if not display.drawn and not self._drawing.search(text):
            display.write(text)  # TAB, BEL, ...: streamed on, the column as the display has it
            OutputStream.write(self, text)
            self.column = display.x
            return
        display.write(text)
        if display.drawn:  # drawn, before or by this text: screens from now on, not streamed text
            if not was_drawn and self.column:  # the streamed row left open: the screens start on their own row
                self.stream.write("\n")
            self.column = display.x
            return
        OutputStream.write(self, text)

    def new_row(self) -> None:
        """PRINT starts a new row (a full row's waiting wrap is that new row: no empty row)."""
        display = self.display
        if not display.drawn:
            if self.width is None or self.column < self.width:
                self._tail.append("\n")  # (a full row: the display's next character wraps it)
            OutputStream.new_row(self)
            return
        self.catch_up()
        display.new_line()
        display.changed = True
        self.column = 0

    def catch_up(self) -> None:
        """Put the streamed text kept so far on the display (before it is drawn on)."""
        if self._tail:
            text = "".join(self._tail)
            self._tail.clear()
            self.display.write(text)

    def _shorten_tail(self) -> None:
        """Keep only the text that can still be on the virtual screen: its last rows."""
        display = self.display
        text = "".join(self._tail)
        cut = len(text)
        for _ in range(display.rows + 1):  # the starts of the last lines
            cut = max(text.rfind("\n", 0, cut), text.rfind("\r", 0, cut))
            if cut < 0:
                break
        kept = text[cut + 1:] if cut >= 0 else text
        if cut < 0:  # one long line: drop whole rows from its start, keeping the columns aligned
            screen = display.columns * display.rows
            extra = len(kept) - screen
            if extra > 0:
                kept = kept[extra - extra % display.columns + display.columns:]
        self._tail = [kept]


def _codes_matching(controls: dict, wanted) -> Pattern:
    """A pattern of the control codes whose action is ``wanted`` (one that never matches if none),
    compiled when first searched (a run that prints only plain text never searches it)."""
    codes = "".join(f"\\U{code:08x}" for code, action in sorted(controls.items()) if wanted(action))
    return Pattern(f"[{codes}]" if codes else "(?!)")


class Console:
    """The display, the screens shown, the key stream and what PEEK reads (a mixin of Machine)."""

    def _init_console(self, screen) -> OutputStream:
        """The screen stream for output ``screen``; sets up the display, memory and keys."""
        self.screens: list[str] = []  # the screens shown so far (see module docstring)
        self.screen_glyphs: list[dict] = []  # for each screen, the DEFCHR$ characters defined then
        self.memory: dict[int, int] = {}  # address -> the byte POKE left there
        self.system_memory: dict[int, int] = {}  # address -> the byte there before any POKE
        self.segment = 0  # DEFSEG's segment: 0 at power-on
        self.last_input_key = 13
        self.user_characters: dict[int, str] = {}  # DEFCHR$: code -> its dots as hex digits
        self.boxed_screens = False  # True: screens are drawn in an LCD's frame (the interactive session)
        self._empty_polls = 0
        self._looked = False  # INKEY$ has looked since the last key was taken (see inkey)
        screen = self.shown(screen)
        geometry = self.dialect.display
        if geometry is None:
            self.display = None
            return OutputStream(screen, self.dialect.width)
        columns, rows, shown = geometry
        self.display = Display(columns, rows, shown, dict(self.dialect.controls), self.dialect.screen)
        self.screen_words = ScreenWords(self)
        return DisplayStream(screen, self.display, self.dialect.width)

    def shown(self, stream):
        """``stream`` as the machine's output reaches it: codes 128..255 as the dialect's
        symbols (casio), or as they are."""
        charset = self.dialect.charset
        return SymbolStream(stream, charset) if charset.own_symbols else stream

    # ------------------------------------------------------------ the display
    def _screen_model(self) -> Display:
        """The display, brought up to date with the text streamed so far (Illegal function
        call in a dialect without one)."""
        display = self.display
        if display is None:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.screen.catch_up()
        return display

    def locate(self, args: tuple) -> None:
        """LOCATE: the cursor to a cell of the screen (the dialect's rules: the Casio's
        0-based ``x, y``; GW's 1-based ``row, column`` with the cursor's visibility and
        shape after them, GWSTS.ASM LOCATE; an omitted row is CSRLIN's, GTLINE, an omitted column
        the cursor's own).  Outside the screen (GW: also row 25 while
        the keys are shown, outside a VIEW PRINT window as PC-BASIC 2.0.8 checks) is
        Illegal function call."""
        display = self._screen_model()
        rules = display.rules
        whole = [None if a is None else runtime.cint(runtime.fix(a)) for a in args]
        first, second = (whole + [None, None])[:2]
        row, column = (first, second) if rules.row_first else (second, first)
        origin = rules.origin
        row = display.row() if row is None else row - origin
        if column is None:  # the cursor's column, a full row's waiting wrap as the last (SCNDRV.ASM SCNPOS)
            column = min(display.x, display.columns - 1)
        else:
            column -= origin
        top, bottom = (display.view_top, display.view_bottom) if display.view_set else (0, display.rows - 1)
        if display.keys_on and display.keys:
            bottom = min(bottom, display.rows - 2)
        if not (0 <= column < display.columns and top <= row <= bottom):
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        cursor, start, stop = (whole[2:] + [None, None, None])[:3]
        if (cursor is not None and not 0 <= cursor <= 1) or (start is None and stop is not None) \
                or any(v is not None and not 0 <= v <= 31 for v in (start, stop)):
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        display.locate(column, row)
        self.screen.column = column

    def cursor_row(self) -> float:
        """CSRLIN: the row the next character goes to (GWSTS.ASM GTLINE)."""
        display = self._screen_model()
        return float(display.row() + display.rules.origin)

    def cursor_column(self, _dummy=None) -> float:
        """POS(x): the column the next character goes to, 1-based (GIOSCN.ASM POS: after a
        full row, 1); from the stream's column while nothing placed text."""
        width = self.screen.width
        column = self.screen.column
        return 1.0 if width is not None and column >= width else float(column + 1)

    def printer_column(self, number) -> float:
        """LPOS(n): the 1-based column of printer n: 0 and 1 the printer (LPT1:), 2 and 3
        printers nothing is printed on (column 1); negative is Illegal function call
        (GIOLPT.ASM LPOS: CONINT), so is above 3 (beyond the three printers' blocks: PC-BASIC
        2.0.8's check)."""
        n = runtime.cint(number)
        if not 0 <= n <= 3:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        return float(self.printer.column + 1) if n <= 1 else 1.0

    def screen_char(self, row, column, attribute=None) -> float:
        """SCREEN(row, column[, z]): the code of the character there, or with z not 0 its
        colour attribute (GWSTS.ASM SCRENF; inside a VIEW PRINT window only, as PC-BASIC).
        Each number is a byte first (beyond an integer Overflow, then 0..255).  A row or a
        column of 0 (one below the origin) reads as the first, but not both: a real GW-BASIC
        3.23 did so in the recorded SCREENFN test (SCRENF's DEC would refuse 0; PC-BASIC 2.0.8
        agrees with the recording)."""
        display = self._screen_model()
        origin = display.rules.origin
        r, c = runtime.byte_argument(to_int(row)) - origin, runtime.byte_argument(to_int(column)) - origin
        z = 0 if attribute is None else runtime.byte_argument(to_int(attribute))
        if origin and (r < 0) != (c < 0):
            r, c = max(r, 0), max(c, 0)
        inside = display.view_top <= r <= display.view_bottom if display.view_set else 0 <= r < display.rows
        if not (inside and 0 <= c < display.columns):
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if z:
            return float(display.attr_at(c, r))
        return float(ord(self.dialect.charset.codes(display.char_at(c, r))[0]))

    def clear_screen(self, mode=None) -> None:
        """CLS [n]: clear the screen (with a VIEW PRINT window, the window; CLS 0 all of it,
        CLS 2 the window, CLS 1 - the graphics window - nothing in text mode, as PC-BASIC
        2.0.8); the next PRINT starts at its first column."""
        whole = None
        canvas = self.screen_words.canvas if self.display is not None else None
        n = None
        if mode is not None:
            n = runtime.cint(mode)
            if not 0 <= n <= 2:
                raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
            whole = n == 0
        if canvas is not None:  # a graphics mode: CLS 1 (and CLS with a VIEW) the view's pixels
            if n == 1 or (n is None and canvas.view_set):
                canvas.clear()
                return
            if n == 0 or (n is None and not self.display.view_set):
                canvas.clear_all()
        if n == 1:
            return
        if self.on_clear_screen is not None:
            self.on_clear_screen()
        if self.display is not None:
            self.screen.catch_up()
            self.display.clear(whole)
        self.screen.column = 0

    def screen_statement(self, word: str, args: tuple) -> None:
        """COLOR [foreground][, background][, border] (0..31, 0..15, 0..15: the text mode's,
        PC-BASIC 2.0.8; a terminal shows the colours, other output ignores them), and
        SCREEN mode[, colour][, pages]: text mode 0 only.  (A dialect whose screen reads these
        statements' numbers one at a time, gw, runs them in machine/screen_words.py, which
        calls this for COLOR in the text mode.)"""
        display = self._screen_model()
        values = [None if a is None else runtime.cint(a) for a in args]
        if word == "SCREEN":  # (a mode left out keeps the mode, as PC-BASIC 2.0.8's SCREEN ,0)
            limits = (0, 1, 7, 7)
        else:
            limits = (31, 15, 15)
        for value, limit in zip(values, limits):
            if value is not None and not 0 <= value <= limit:
                raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if word == "SCREEN" or not display.rules.attributes:
            return
        fore, back = (values + [None, None])[:2]
        attr = display.attr
        blink = attr & 0x80 if fore is None else (0x80 if fore > 15 else 0)
        fore = attr & 0x0F if fore is None else fore & 0x0F
        back = (attr >> 4) & 7 if back is None else back & 7
        display.attr = blink | back << 4 | fore
        stream = self.screen.stream
        isatty = getattr(stream, "isatty", None)
        if isatty is not None and isatty():  # the terminal's own colours: SGR codes
            bright = 90 if fore & 8 else 30
            stream.write(f"\x1b[0;{bright + _ANSI[fore & 7]};{40 + _ANSI[back]}{';5' if blink else ''}m")

    def view_print(self, rows) -> None:
        """VIEW PRINT [first TO last]: only those rows scroll (1..24 as PC-BASIC 2.0.8 checks;
        last before first is Illegal function call; a row beyond -32768..32767 Overflow, as
        the recorded VIEWPRNT test); without rows, the whole screen again."""
        display = self._screen_model()
        if rows is None:
            display.reset_view()
            return
        origin = display.rules.origin
        first, last = to_int(rows[0]) - origin, to_int(rows[1]) - origin
        bottom = display.rows - 1 - (1 if display.keys else 0)
        if not (0 <= first <= last <= bottom):
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        display.set_view(first, last)
        self.screen.column = 0

    def key_line(self, action: str) -> None:
        """KEY ON / KEY OFF: show or blank the function keys' line (GWSTS.ASM KEYON KEYOF);
        KEY LIST prints each key's text, a carriage return shown as the arrow (KEYLST)."""
        display = self._screen_model()
        if not display.keys:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if action == "LIST":
            for k, text in enumerate(display.keys):
                self.screen.write(f"F{k + 1} " + text.replace("\r", "\u2190") + "\n")
            return
        display.set_keys_shown(action == "ON")

    def define_key(self, number, text: str) -> None:
        """KEY n, text: function key n (1..10) types ``text`` (its first 15 characters,
        GWSTS.ASM KEYS); another n with a text of two characters (a key to trap: a shift
        code and a scan code) is no error, a real GW-BASIC 3.23 recorded it so for 15 and for
        255 (PC-BASIC's KEY and KEY_definition_two_chars_no_error tests); else Illegal
        function call."""
        display = self._screen_model()
        n = self.key_number(number)
        if 1 <= n <= len(display.keys):
            display.define_key(n, text)
        elif len(text) != 2:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)

    @staticmethod
    def key_number(number) -> int:
        """A key's number as GETBYT reads it (GWEVAL.ASM): beyond -32768..32767 Overflow,
        outside 0..255 Illegal function call."""
        n = to_int(number)
        if not 0 <= n <= 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        return n

    def set_screen_size(self, columns, rows) -> None:
        """WIDTH columns, rows: 40 or 80 columns, and the screen's 25 rows (any other number
        of rows is Illegal function call; GWSTS.ASM GWWID)."""
        display = self._screen_model()
        if runtime.cint(rows) != display.rows:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.set_width(columns)

    def show_screen(self, final: bool = False) -> None:
        """Show the display's screen on the output (a program that drew waits for a key, or
        ends: ``final``, shown only when something changed since the last screen)."""
        display = self.display
        if display is None or not display.drawn or self.csv:
            return
        lines = [self.dialect.charset.cell_symbols(line) for line in display.shown_lines()]
        shown = "".join(line + "\n" for line in lines)
        if final and self.screens and self.screens[-1] == shown and not display.changed:
            return
        display.changed = False
        self.screens.append(shown)
        self.screen_glyphs.append(dict(self.user_characters))
        stream = self.screen.stream
        if isinstance(stream, SymbolStream):  # (the lines are symbols already)
            stream = stream.stream
        stream.write(boxed(lines, display.columns) if self.boxed_screens else shown)
        stream.flush()

    def end_drawing(self) -> None:
        """After a direct statement: a screen it drew (anything on it) is shown, and the
        next output streams again (the session's prompt is not on the LCD)."""
        display = self.display
        if display is None or not display.drawn:
            return
        if any(display.lines()):
            self.show_screen(final=True)
        display.drawn = False

    def define_character(self, code, pattern: str) -> None:
        """DEFCHR$(code) = pattern: the dots of user-defined character ``code`` (&HFC-&HFF, the
        character code table's user-defined ones): 10 hexadecimal digits, five columns of 8
        dots, the first digit pair the left column, its high bit the top dot.  Kept
        (``user_characters``) with each screen shown (``screen_glyphs``), which the HTML
        LCD (yaseer/lcd.py) draws; the text LCD still shows the table's symbol."""
        k = runtime.cint(runtime.fix(code))
        digits = pattern.strip()
        if not 252 <= k <= 255 or len(digits) != 10 or any(ch not in "0123456789ABCDEFabcdef" for ch in digits):
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.user_characters[k] = digits.upper()

    # ------------------------------------------------------------ the keys
    def _keys(self):
        return self.input_stream if self.input_stream is not None else sys.stdin

    def _key_text(self, text: str) -> str:
        """Keys as read, in the machine's codes: a line break is the dialect's enter key (EXE)."""
        enter = self.dialect.enter_key
        text = self.dialect.charset.codes(text)
        return text if enter == "\n" else text.replace("\n", enter)

    def inkey(self) -> str:
        """INKEY$: the key pressed while it looks (INKEY_STRING.md, item 1), else "".  A key of
        the stream is pressed only after the program has looked once and found none since the
        last key was taken: a person answers what the screen shows, slower than the machine
        polls, so ``IF INKEY$="" THEN A=ASC(INPUT$(1))`` waits at INPUT$ as on the machine and
        a polling loop gets each key.  A key script's end answers "" a while, then is Input
        past end, so a program polling for a key does not spin forever."""
        if self.display is None or self.display.changed or not self.screens:
            self.show_screen()  # (a program polling for a key shows a screen only when it changed)
        if not self._looked:
            self._looked = True
            return ""
        key = self._keys().read(1)
        if key:
            self._empty_polls = 0
            self._looked = False
            return self._key_text(key)
        self._empty_polls += 1
        if self._empty_polls > EMPTY_POLLS:
            raise end_of_keys()
        return ""

    def input_keys(self, count) -> str:
        """INPUT$(n) and INPUT$(n, @) from the keyboard: n keys (0..256), not shown."""
        k = runtime.cint(count)
        if not 0 <= k <= 256:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.show_screen()
        text = self._keys().read(k)
        self._looked = False
        if len(text) < k:
            raise end_of_keys()
        return self._key_text(text)

    # ------------------------------------------------------------ memory
    def define_machine(self, word: str, value) -> None:
        """DEF SEG [= s] (``word`` "SEG") and DEF USR[n] = a ("USR"): s or a is read as an
        unsigned 16-bit number (GWMAIN.ASM FRQINT: beyond -32768..65535 Overflow); DEF SEG
        sets the segment gw's PEEK and POKE use (alone: BASIC's own data segment;
        machine/address_space.py); DEF USR's address is not kept: no machine code runs
        (see :meth:`user_routine`)."""
        segment = None if value is None else runtime.unsigned_word(value)
        if word == "SEG":
            self.address_space.define_segment(segment)

    @staticmethod
    def user_routine(_argument) -> float:
        """USR[n](x): a machine-code routine, which yaseer cannot run: Illegal function call
        once x is read (GWEVAL.ASM USRFN: PARCHK, then FCERR for an address never set by
        DEF USR; as PC-BASIC 2.0.8 for any address)."""
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)

    def peek(self, address) -> float:
        """PEEK(address): the byte at segment * 16 + address (a negative address counts from
        65536, as the manual's PEEK page says)."""
        where = self._address(address)
        if where == LAST_INPUT_KEY:
            return float(self.last_input_key)
        return float(self.memory.get(where, self.system_memory.get(where, 0)))

    def type_line(self, text: str) -> None:
        """A line typed and ended with EXE: where the dialect has an input buffer
        (``words.input_buffer``), its bytes (:func:`typed_codes`) and a 0 after them go
        into RAM from that address, for PEEK to read (segment 0)."""
        words = self.dialect.words
        start = getattr(words, "input_buffer", None)
        if start is None:
            return
        codes = typed_codes(self.dialect.charset.codes(text), words.stored_words)
        for offset, code in enumerate(codes + [0]):
            self.memory[start + offset] = code

    def _address(self, address) -> int:
        offset = int(runtime.fix(address))
        if not -32769 < offset < 65536:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        return (self.segment * 16 + offset % 65536) % 0x100000
