"""GW-BASIC's reserved words are never variables (yaseer/basic/dialects/reserved.py).

The table is checked against PC-BASIC 2.0.8's own keyword table (an independent
list of GW-BASIC's tokens); a word not implemented stops its statement with
``Unsupported word X in N`` in both dialects instead of reading an array.
"""

from __future__ import annotations

import io

import pytest

from yaseer.basic.errors import BasicError
from yaseer.basic.machine.machine import Machine
from yaseer.basic.dialects.reserved import GW_RESERVED_WORDS

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def test_table_holds_every_word_pcbasic_tokenises():
    from pcbasic.basic.base import tokens as tk

    theirs = {w.decode().rstrip("(") for w in tk.TokenKeywordDict("advanced").to_token}
    words = {w for w in theirs if w[:1].isalpha()}
    assert words - GW_RESERVED_WORDS == set()
    # ours adds only the $ forms, which GW-BASIC reads as a keyword followed by "$"
    assert GW_RESERVED_WORDS - words == {"ENVIRON$", "ERDEV$", "INPUT$", "IOCTL$", "VARPTR$"}


def outcome(program: str, dialect: str) -> tuple[str, str]:
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect=dialect, input_stream=io.StringIO(""))
    machine.load(program)
    try:
        machine.run()
    except BasicError as err:
        return screen.getvalue(), str(err)
    return screen.getvalue(), ""


CASIO_MACHINE_WORDS = ("PEEK", "INKEY$", "LOCATE")  # the FX-850P's display, keyboard and memory
GW_SCREEN_WORDS = ("INKEY$", "CSRLIN", "LOCATE")  # GW-BASIC's text screen and keyboard
GW_DEVICE_WORDS = ("SOUND", "STICK")  # ... and the PC's devices (dialects/gw_words.py: a keyword, DIM SOUND(3) Syntax error)
GW_MEMORY_WORDS = ("PEEK", "VARPTR")  # ... and its memory (machine/address_space.py)


UNIMPLEMENTED = [
    ("10 PRINT PEEK(10)", "PEEK"), ("10 PRINT INKEY$", "INKEY$"), ("10 PRINT VARPTR(7)", "VARPTR"),
    ("10 PRINT CSRLIN", "CSRLIN"), ("10 X = STICK(0)", "STICK"), ("10 LOCATE 1, 1", "LOCATE"),
    ("10 DIM SOUND(3)", "SOUND"),
]


@pytest.mark.parametrize("program, word, dialect", [
    (program, word, dialect) for program, word in UNIMPLEMENTED for dialect in ("casio", "gw")
    if not (dialect == "casio" and word in CASIO_MACHINE_WORDS)
    and not (dialect == "gw" and word in GW_SCREEN_WORDS + GW_DEVICE_WORDS + GW_MEMORY_WORDS)])
def test_unimplemented_word_stops_with_its_name(program, word, dialect):
    assert outcome(program, dialect) == ("", f"Unsupported word {word} in 10")


def test_gw_runs_the_statements_before_it():
    assert outcome('10 PRINT 50: SHELL "DIR"', "gw") == (" 50 \n", "Unsupported word SHELL in 10")


def test_names_that_only_contain_a_reserved_word_are_names():
    assert outcome("10 XVARPTR = 2: HEXA = 3: PRINT XVARPTR + HEXA", "casio") == (" 5 \n", "")
