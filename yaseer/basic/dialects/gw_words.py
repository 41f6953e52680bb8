"""GW-BASIC's words for the PC's devices: the tables the gw dialect adds (data only).

The words that reach a port, the DOS environment, a device driver, the speaker, a file
lock, DOS's directories or machine code (``INP OUT WAIT IOCTL IOCTL$ ENVIRON ENVIRON$ ERDEV
ERDEV$ EXTERR LCOPY LOCK UNLOCK SOUND BEEP CHDIR MKDIR RMDIR CALL CALLS``).  yaseer has none of those devices: each word
reads its arguments as GW-BASIC 3.23 reads them and gives its errors in the same order
(GWEVAL.ASM FNINP/SETIO/FNWAIT, GWSTS.ASM SOUNDS/BEEPS/LCOPYS, CALL86.ASM), then does what a
PC without the device would: the machine's side is yaseer/basic/machine/devices.py, the
behaviour and its sources are docs/compatibility.md's row "Device words".  The words the
released source only stubs (GWSTS.ASM: ERDEV, IOCTL, ENVIRON jump to ADVERR) follow the
outputs of real GW-BASIC 3.23 recorded in PC-BASIC's test suite and PC-BASIC 2.0.8 where
the two agree.  The scanner reads these words as keywords in gw only.
"""

from __future__ import annotations

# Functions: word -> (token type, argument forms, result, helper of the compiled code); the
# kinds are those of compile/expressions.py ("i" an integer as FRCINT makes it, "x" either).
FUNCTIONS = {
    "INP": ("FUNC", ("n",), "n", "_M.devices.inp"),  # GWEVAL.ASM FNINP: FRQINT (-32768..65535), the port
    "EXTERR": ("FUNC", ("i",), "n", "_M.devices.extended_error"),
    # IOCTL$([#]n): a file's number, as a call (FUNCN: its "#" read as VARPTR(#n)'s, and a call
    # the text cuts short read as one: IOCTL$("A" Type mismatch, the recorded IOCTL$ test)
    "IOCTL$": ("FUNCN", ("i",), "s", "_M.devices.control_string"),
    "ENVIRON$": ("FUNC", ("x",), "s", "_M.devices.environment"),
    # GWMAIN.ASM PEEK: FRQINT (-32768..65535), the byte at DEF SEG's segment (machine/address_space.py)
    "PEEK": ("FUNC", ("n",), "n", "_M.address_space.peek"),
    # GWEVAL.ASM VARPTR: "(" then a variable (PTRGTN; form "v": a variable, else Syntax error)
    "VARPTR": ("FUNCN", ("v",), "n", "_M.address_space.variable_pointer"),
    # GWEVAL.ASM VARPTR with "$": the variable's type byte and address as a 3-byte string
    "VARPTR$": ("FUNCN", ("v",), "s", "_M.address_space.variable_pointer_string"),
    # the game port and the light pen (GWSTS.ASM STICKF, STRIGF, PENF: ONESUB reads a byte)
    "STICK": ("FUNC", ("i",), "n", "_M.devices.stick"),
    "STRIG": ("FUNC", ("i",), "n", "_M.devices.trigger"),
    "PEN": ("FUNC", ("i",), "n", "_M.devices.pen"),
    # the music queue's notes waiting (machine/music.py): n a byte; also a statement (below)
    "PLAY": ("FUNC", ("i",), "n", "_M.music.count"),
    # the graphics screen (machine/graphics_words.py): POINT(n) or POINT(x, y), each number
    # checked as the function reads it (a string in POINT(x, y) is the text mode's Illegal
    # function call there: the recorded POINT test); PMAP(value, n)
    "POINT": ("FUNCN", ("x", "xx"), "n", "_M.graphics.point"),
    "PMAP": ("FUNCN", ("nn",), "n", "_M.graphics.pmap"),
}
# Functions of a file number: ``WORD(#n)`` -> helper (GWEVAL.ASM VARPTR: "#", GTBYTC, GETPTR;
# IOCTL$ reads an optional "#" before its number, as the recordings show).
FILE_FUNCTIONS = {"VARPTR": "_M.address_space.file_pointer", "IOCTL$": "_M.devices.control_string"}
# ... and what each checks of its file before it asks for the ")" (a call cut there: VARPTR's
# whole value, GETPTR; IOCTL$ the file open, then the ")", then the device: the recorded FILEXPR test).
FILE_CHECKS = {"VARPTR": "_M.address_space.file_pointer", "IOCTL$": "_M.devices.control_file"}
# Functions whose routine checks an argument as it reads it, before it looks for the ``,`` or
# ``)`` after it: word -> the check of each argument (returning it), for a call the text cuts
# short (``IOCTL$(1.5``: file 2 not open is Bad file number before the missing ``)``: the
# recorded IOCTL$ test).
ARGUMENT_CHECKS = {"IOCTL$": ("_M.devices.open_file_number",),
                   # POINT's first argument with whether the screen draws (its reading's choice)
                   "POINT": ("_M.graphics.point_argument",)}
# Statements that may change variables the compiled block holds: its values are stored before
# and taken back after (a POKE into a FIELD buffer changes the variables fielded over it).
WRITES_VARIABLES = frozenset({"POKE", "PLAY", "BLOAD"})  # (PLAY's X and = read variables: they are stored first)
# Values without arguments: name -> (Python expression, "s" or None for an integer).
SYSTEM_VALUES = {"ERDEV": ("0", None), "ERDEV$": ('""', "s")}

# Statements: word -> (argument kinds in order, least arguments, helper, first marks).  A kind:
# "i" an integer (FRCINT: beyond -32768..32767 Overflow), "u" a port (FRQINT: -32768..65535),
# "n" a number, "s" a string, "v" CALL's routine (a numeric variable, optionally with
# variables in parentheses).  "first marks": what may stand before the first argument ("#":
# a file number).  A word's arguments are read one by one: a wrong type is Type mismatch at
# that argument, too few is Syntax error (Missing operand where a comma or the word itself
# was read and no expression follows), and what follows the last argument is Syntax error
# after the statement has run (NEWSTT finds no end of statement: GWMAIN.ASM GONZER).
STATEMENTS = {
    "OUT": ("ui", 2, "_M.devices.out", ""),  # SETIO: FRMQNT, ",", GETBYT
    "POKE": ("ui", 2, "_M.address_space.poke", ""),  # GWMAIN.ASM POKE: FRMQNT, ",", GETBYT
    "WAIT": ("uii", 2, "_M.devices.wait", ""),  # FNWAIT: SETIO, then an optional "," GETBYT
    "LCOPY": ("i", 0, "_M.devices.screen_copy", ""),  # LCOPYS: an optional byte
    "SOUND": ("in", 2, "_M.music.sound", ""),  # SOUNDS: GETIN2, ",", FRMEVL (machine/music.py)
    # PLAY string (GWSTS.ASM PLAYS, MACLNG.ASM): at a statement's start; elsewhere the
    # function above (source/event_tokens.py)
    "PLAY": ("s", 1, "_M.music.play", ""),
    "IOCTL": ("is", 2, "_M.devices.control", "#"),
    "ENVIRON": ("s", 1, "_M.devices.set_environment", ""),
    "LOCK": ("inn", 1, "_M.devices.lock", "#"),  # LOCK [#]n [, [start] [TO end]]
    "UNLOCK": ("inn", 1, "_M.devices.unlock", "#"),
    "CALL": ("v", 1, "_M.devices.call", ""),
    # DOS's directories, inside the program's directory (machine/sandbox.py: its top is the
    # drive's root): one string each, as a real GW-BASIC 3.23 recorded them (PC-BASIC's DISK
    # and DISK2 tests: alone Missing operand, a number Type mismatch, "" Bad file name)
    "CHDIR": ("s", 1, "_M.files.sandbox.change_directory", ""),
    "MKDIR": ("s", 1, "_M.files.sandbox.make_directory", ""),
    "RMDIR": ("s", 1, "_M.files.sandbox.remove_directory", ""),
    "CALLS": ("v", 1, "_M.devices.call", ""),
    # BEEPS reads nothing: it beeps, then NEWSTT finds what follows (``BEEP 10`` beeps and
    # is Syntax error: PC-BASIC 2.0.8; the recorded real run of such lines never ended)
    "BEEP": ("", 0, "_M.music.beep", ""),
    # the cassette's motor: a byte or nothing (the recordings: MOTOR -1 and MOTOR 256 are
    # Illegal function call, MOTOR 0 and MOTOR 255 do nothing; GIOCAS.ASM's stub, Device
    # unavailable, is not what GW-BASIC 3.23 did)
    "MOTOR": ("i", 0, "_M.devices.motor", ""),
    # a page of the screen mode to another (the recorded PCOPY test: alone or after a comma
    # Missing operand, one page Syntax error, a page the mode lacks Illegal function call)
    "PCOPY": ("ii", 2, "_M.screen_words.copy_page", ""),
    # memory to a file and back (machine/address_space.py; a graphics mode's pixels are
    # its adapter's memory: machine/video_memory.py)
    "BSAVE": ("suu", 3, "_M.address_space.binary_save", ""),
    "BLOAD": ("su", 1, "_M.address_space.binary_load", ""),
}
# Statements that check the end of the statement before they act (GWSTS.ASM SOUNDS calls
# EOSCHK before the note: ``SOUND 1,1,1`` is Syntax error, not the frequency's error); the
# others act, then NEWSTT finds what follows (``LOCK #1, 1 TO 2 TO 3`` locks first).
ENDS_FIRST = frozenset({"SOUND"})
# Statements whose arguments are read and checked, and the statement done, before the text
# after them is looked at: bad text after a whole argument is found only then (the recorded
# IOCTL test: ``IOCTL #1, "" X`` is the disk file's Illegal function call); for the others
# such text is the statement's Syntax error before it acts (the recorded LOCK, OUT, POKE and
# SOUND tests).
READS_BEFORE_END = frozenset({"IOCTL"})
# The word between LOCK's first and last record (the other arguments: commas).
RANGE_WORDS = {"LOCK": "TO", "UNLOCK": "TO"}
# Words whose ``$`` form GW-BASIC tokenises as the word and a ``$``, so blanks may stand
# between them (``ENVIRON $(1)`` is ENVIRON$(1): the recordings).
DOLLAR_APART = frozenset({"ENVIRON", "IOCTL", "ERDEV"})


# Event traps: word -> (what ``ON word(n) GOSUB line`` reads in parentheses, what ``word(n)
# ON|OFF|STOP`` reads there, how many events the word has, the states ``word ON|OFF|STOP``
# may set without parentheses).  What is read: "byte" a number GETBYT reads (0..255), the
# event n-1; "trigger" a trigger number (0, 2, 4, 6: n/2 is the event); "seconds" a number
# of seconds above 0; None: no parentheses.  GWSTS.ASM ONGOTP, SEVSTT, PENS, STRIGS for KEY,
# COM, PEN and STRIG (14 keys there; 20 on the real GW-BASIC 3.23, whose KEY 15 takes a
# definition, and in PC-BASIC 2.0.8); TIMER and PLAY, which the released source lacks, as
# the recordings and PC-BASIC 2.0.8 read them (PLAY's queue holds 32 notes).
EVENTS = {
    "KEY": ("byte", "byte", 20, ()),
    "COM": ("byte", "byte", 2, ()),
    "STRIG": ("trigger", "trigger", 4, ("ON", "OFF")),  # STRIG ON/OFF: IBM BASIC's form, read and ignored
    "PEN": (None, None, 1, ("ON", "OFF", "STOP")),
    "TIMER": ("seconds", None, 1, ("ON", "OFF", "STOP")),
    "PLAY": ("byte", None, 32, ("ON", "OFF", "STOP")),
}


class Words:
    """The tables above as one object, ``Dialect.device_words``: its attributes are the
    tables' names in lower case (hashed by identity, as a dialect is a key of the scanner's
    cache; its repr names it: a dialect's repr is part of the compile cache's key)."""

    def __init__(self, **tables):
        self.__dict__.update(tables)

    def __repr__(self) -> str:
        return "gw_words.Words()"


WORDS = Words(functions=FUNCTIONS, system_values=SYSTEM_VALUES, statements=STATEMENTS, range_words=RANGE_WORDS,
              ends_first=ENDS_FIRST, dollar_apart=DOLLAR_APART, file_functions=FILE_FUNCTIONS, file_checks=FILE_CHECKS,
              writes_variables=WRITES_VARIABLES, events=EVENTS, argument_checks=ARGUMENT_CHECKS,
              reads_before_end=READS_BEFORE_END)
