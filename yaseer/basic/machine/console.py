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

import re
import sys

from yaseer.basic.machine import runtime
from yaseer.basic.machine.display import Display, boxed
from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL, INPUT_PAST_END
from yaseer.basic.machine.screen import OutputStream

# Memory the FX-850P's programs read (Becker's library): the code of the key that ended
# the last INPUT (EXE: 13; its programs test PEEK(&H65B)-13), and a byte that is 0 while no
# shift key is held (PEEK(206) after INPUT$).  Every other address holds what POKE left, 0 at first.
# (POKE and DEFSEG are the casio words' statements; they share ``memory`` and ``segment``.)
LAST_INPUT_KEY = 0x65B
EMPTY_POLLS = 1000
TAIL_PIECES = 1024  # pieces of streamed text kept before they are cut to the screen's last rows
# Control codes that place text where the program chooses (the display's DRAWING_ACTIONS).
_DRAWING = re.compile("[\x02\x05\x06\x08\x0b\x0c\x1c-\x1f]")  # INKEY$ answers "" this many times at the end of the key stream, then Input past end


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

    def write(self, text: str):
        return self.stream.write(self.charset.symbols(text))

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

    def write(self, text: str) -> None:
        if not text:
            return
        display = self.display
        if not display.drawn and (text.isprintable() or not _DRAWING.search(text)):
            tail = self._tail
            tail.append(text)
            if len(tail) > TAIL_PIECES:
                self._shorten_tail()
            OutputStream.write(self, text)
            return
        self.catch_up()
        display.write(text)
        if display.drawn:  # drawn, before or by this text: screens from now on, not streamed text
            self.column = display.x
            return
        super().write(text)

    def new_row(self) -> None:
        self.write("\n")

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


class Console:
    """The display, the screens shown, the key stream and what PEEK reads (a mixin of Machine)."""

    def _init_console(self, screen) -> OutputStream:
        """The screen stream for output ``screen``; sets up the display, memory and keys."""
        self.screens: list[str] = []  # the screens shown so far (see module docstring)
        self.memory: dict[int, int] = {}  # address -> the byte POKE left there
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
        self.display = Display(columns, rows, shown, dict(self.dialect.controls))
        return DisplayStream(screen, self.display, self.dialect.width)

    def shown(self, stream):
        """``stream`` as the machine's output reaches it: codes 128..255 as the dialect's
        symbols (casio), or as they are."""
        charset = self.dialect.charset
        return SymbolStream(stream, charset) if charset.own_symbols else stream

    # ------------------------------------------------------------ the display
    def locate(self, x, y) -> None:
        """LOCATE x, y: the cursor to column x of row y of the virtual screen (0-based;
        beyond the screen is Illegal function call, the manual's FC error)."""
        display = self.display
        if display is None:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        column, row = runtime.cint(runtime.fix(x)), runtime.cint(runtime.fix(y))
        if not (0 <= column < display.columns and 0 <= row < display.rows):
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.screen.catch_up()
        display.locate(column, row)
        self.screen.column = column

    def show_screen(self, final: bool = False) -> None:
        """Show the display's screen on the output (a program that drew waits for a key, or
        ends: ``final``, shown only when something changed since the last screen)."""
        display = self.display
        if display is None or not display.drawn or self.csv:
            return
        text = display.screen_text()
        shown = self.dialect.charset.symbols(text)
        if final and self.screens and self.screens[-1] == shown and not display.changed:
            return
        display.changed = False
        self.screens.append(shown)
        stream = self.screen.stream
        stream.write(boxed(display.shown_lines(), display.columns) if self.boxed_screens else text)
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
        dots.  Kept (``user_characters``); the LCD's text still shows the table's symbol."""
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
        self.show_screen()
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
    def peek(self, address) -> float:
        """PEEK(address): the byte at segment * 16 + address (a negative address counts from
        65536, as the manual's PEEK page says)."""
        where = self._address(address)
        if where == LAST_INPUT_KEY:
            return float(self.last_input_key)
        return float(self.memory.get(where, 0))

    def _address(self, address) -> int:
        offset = int(runtime.fix(address))
        if not -32769 < offset < 65536:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        return (self.segment * 16 + offset % 65536) % 0x100000
