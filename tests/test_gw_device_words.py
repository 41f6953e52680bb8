"""gw's words for the PC's devices (dialects/gw_words.py, machine/devices.py): INP, OUT,
WAIT, LCOPY, SOUND, BEEP, IOCTL, IOCTL$, ENVIRON, ENVIRON$, ERDEV, ERDEV$, EXTERR, LOCK,
UNLOCK, CALL, CALLS.

Each program runs in PC-BASIC 2.0.8 and in yaseer: every line one statement, the handler
printing ERR and ERL, so the errors and their order (type before syntax, the statement's
work before what follows it) are compared line by line.  Where PC-BASIC and GW-BASIC's
source differ, or yaseer decides what a PC without the device does, the test says so.
"""

from __future__ import annotations

import io

import pytest

from test_differential_support import run_gw
from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

GROUPS = {
    "ports": [
        "OUT 100, 7", "OUT", "OUT 5", "OUT 5,", "OUT 5, 6,", "OUT 5, 6, 7", "OUT A$", "OUT 3, B$",
        "OUT 40000, 1", "OUT 70000, 1", "OUT -5, 1", "OUT 1, 300", "OUT 1, -2", "OUT 1, 40000",
        "WAIT 2, 1, 1", "WAIT", "WAIT 2", "WAIT 2,", "WAIT 2, 300", "WAIT 2, 1, 300", "WAIT 2, 1, 1,",
        "WAIT 2, 40000", "WAIT X$, 1", "PRINT INP(5)", "PRINT INP(70000)", 'PRINT INP("A")', "PRINT INP",
        "PRINT INP(3, 4)",
    ],
    "printer and speaker": [
        "LCOPY", "LCOPY 3", "LCOPY 300", "LCOPY -2", "LCOPY 2,", "LCOPY Z$", "LCOPY 2, 3",
        "SOUND 440, 2", "SOUND", "SOUND 440", "SOUND 440,", "SOUND 20, 2", "SOUND 0, 2", "SOUND 440, 0",
        "SOUND 440, 70000", "SOUND 40000, 2", "SOUND A$, 2", "SOUND 440, A$", "SOUND 1, 1, 1",
        "BEEP", "BEEP 3", 'BEEP: PRINT "b"', 'BEEP "x"',
    ],
    "environment and errors": [
        'ENVIRON "ABC=1": PRINT ENVIRON$("abc"); ENVIRON$("ABC")',
        'ENVIRON "ABC=1": ENVIRON "ABC=": PRINT LEN(ENVIRON$("ABC"))',
        'ENVIRON "XYZ"', 'ENVIRON ""', "ENVIRON", "ENVIRON 5", 'ENVIRON "=5"',
        'PRINT ENVIRON$("")', "PRINT ENVIRON$(0)", "PRINT ENVIRON$(256)", "PRINT ENVIRON$(40000)",
        "PRINT ENVIRON$", "PRINT EXTERR(0); EXTERR(3)", "PRINT EXTERR(4)", "PRINT EXTERR(-1)",
        "PRINT EXTERR(40000)", 'PRINT EXTERR("A")', "PRINT EXTERR", 'PRINT ERDEV; ERDEV$; "."',
        'PRINT ERDEV $; "."', 'PRINT ENVIRON $("Q"); "."',
    ],
    "files": [
        'IOCTL #2, "X"', 'IOCTL 2, "X"', 'IOCTL #4, "X"', "IOCTL #2, 5", "IOCTL", "IOCTL #2", "IOCTL #2,",
        "PRINT IOCTL$(2)", "PRINT IOCTL$(4)", "PRINT IOCTL$(0)", "PRINT IOCTL$(300)", 'PRINT IOCTL$("A")',
        # (the recorded IOCTL and IOCTL$ tests: the statement runs before the text after it is
        # found bad; IOCTL$ reads # and looks for its file before its ")")
        'IOCTL #2, "X" Z', 'IOCTL "A" LPRINT', "PRINT IOCTL$(#2)", 'PRINT IOCTL$("A"', "PRINT IOCTL$(2",
        "PRINT IOCTL$(5", "PRINT IOCTL$(2, 1)",
        # (but LOCK finds bad text before it locks: the recorded LOCK test; OUT's the recorded OUT)
        "LOCK #3 LPRINT", "LOCK #3, LPRINT", "OUT LPRINT",
        "LOCK #3", "LOCK #3: LOCK #3", "LOCK #3, 2 TO 4: LOCK #3, 5: UNLOCK #3, 2 TO 4: UNLOCK #3, 5",
        "LOCK #3, 2 TO 4: LOCK #3, 3", "LOCK #3, 2 TO 4: UNLOCK #3, 2", "LOCK #2, 5: UNLOCK #2", "LOCK #4",
        "LOCK #3, 0", "UNLOCK #3", "LOCK", "LOCK #3,", "LOCK #3, 1 TO", "LOCK 3, 1 TO 2 TO 3",
        "CALL A$", "CALL 5", "CALL", "CALL A(1)", 'CALLS B(C, "")',
    ],
}


def _program(statements: list[str]) -> str:
    lines = ['5 OPEN "Q.DAT" FOR OUTPUT AS 2: OPEN "R.DAT" FOR RANDOM AS 3', "10 ON ERROR GOTO 900"]
    lines += [f"{20 + 10 * k} {statement}" for k, statement in enumerate(statements)]
    lines += ['800 PRINT "end": END', '900 PRINT "E"; ERR; ERL: RESUME NEXT']
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("group", sorted(GROUPS))
def test_statements_as_pcbasic(tmp_path, group):
    """Each statement's output and errors, line by line, as PC-BASIC 2.0.8 gives them (a
    type before a missing comma: ``OUT A$`` Type mismatch; ``OUT 5,`` Missing operand;
    ``OUT 5, 6, 7`` Syntax error after the OUT; ``LOCK #3: LOCK #3`` Permission Denied)."""
    source = _program(GROUPS[group])
    theirs, ours = tmp_path / "pcbasic", tmp_path / "yaseer"
    theirs.mkdir()
    ours.mkdir()
    assert yaseer_run(source, ours) == pcbasic_run(source, theirs)


@pytest.mark.parametrize("statement, expected", [
    # GWSTS.ASM SOUNDS: FRMEVL the duration, then EOSCHK: a comma after it is Syntax error
    # (PC-BASIC 2.0.8 reads it as Tandy's third argument and goes on)
    ("SOUND 440, 2,", "E 2  20 \n"),
    # GWSTS.ASM SOUNDS checks the end (EOSCHK) before the frequency (PC-BASIC agrees)
    ("SOUND 1, 1, 1", "E 2  20 \n"),
    # LOCK acts, then NEWSTT finds what follows: the second range meets the first
    ("LOCK #3: LOCK #3, 1 TO 2 TO 3", "E 70  20 \n"),
    ("LOCK #3, 1 TO 2 TO 3", "E 2  20 \n"),
])
def test_where_the_source_decides(tmp_path, statement, expected):
    assert yaseer_run(_program([statement]), tmp_path) == expected + "end\n"


@pytest.mark.parametrize("port, value", [
    (0, 0), (1, 0), ("&H1F", 0), (2.4, 0), ("&H20", 255), (150, 255), (256, 255), (-1, 255), (32768, 255),
    ("&H3DA", 255), (-1.5, 255),
])
def test_ports_read_as_a_pc_with_nothing_attached(port, value):
    """yaseer emulates no port: the DMA controller's (0..&H1F) read 0, as the IBM PC behind
    PC-BASIC's recordings read INP(0)..INP(2); no device answers the others, whose floating
    bus reads 255 (the recordings: INP(150), INP(256), INP(-1)).  PC-BASIC 2.0.8 reads 0
    wherever it emulates nothing.  The port is FRQINT's: -32768..65535."""
    assert run_gw(f"10 PRINT INP({port})\n") == f" {value} \n"


def test_a_wait_that_would_never_end_ends_the_run():
    """FNWAIT loops until (byte XOR flip) AND mask is not 0; the ports never change here, so
    WAIT ends at once or the run ends naming it (no handler can make a port change)."""
    assert run_gw('10 WAIT &H3DA, 8: PRINT "a"\n20 WAIT 5, 1, 0: PRINT "b"\n') == "a\n" + (
        "WAIT for port &H5 to change (yaseer's ports never change) is not emulated in 20\n")
    assert run_gw("10 ON ERROR GOTO 30\n20 WAIT 0, 1\n30 PRINT ERR\n").endswith("is not emulated in 20\n")


def test_call_of_machine_code_ends_the_run():
    """CALL/CALLS of a well-formed routine would jump into memory: the run ends there with one
    line (PC-BASIC 2.0.8 ignores it); its malformed forms are GW's errors (above)."""
    for statement in ("CALL A", "CALL A(B, C$)", "CALLS X"):
        source = f"10 ON ERROR GOTO 40\n20 {statement}\n30 END\n40 PRINT ERR\n"
        assert run_gw(source) == "CALL of a machine-code routine is not emulated in 20\n"


def test_environ_is_the_programs_own_table(monkeypatch):
    """The host's environment is never read (it may hold secrets, and differs by host): the
    table starts empty; ENVIRON sets names in capitals, an empty value removes one, and
    ENVIRON$(n) lists the entries in the order they were set."""
    monkeypatch.setenv("PATH", "/secret/bin")
    monkeypatch.setenv("YASEER_TEST_SECRET", "x")
    source = ('10 PRINT ENVIRON$("PATH"); "|"; ENVIRON$(1); "|"; ENVIRON$("YASEER_TEST_SECRET"); "|"\n'
              '20 ENVIRON "b=2": ENVIRON "A=1": ENVIRON "C=3": ENVIRON "A="\n'
              '30 PRINT ENVIRON$(1); " "; ENVIRON$(2); " "; ENVIRON$(3); "|"; ENVIRON$("b")\n')
    assert run_gw(source) == "|||\nB=2 C=3 |2\n"


def test_environment_lasts_from_run_to_run():
    """ENVIRON changes DOS's copy of the environment, which RUN does not clear."""
    from yaseer.basic.dialects.dialect import GW
    from yaseer.basic.machine.machine import Machine

    screen = io.StringIO()
    machine = Machine(screen=screen, dialect=GW)
    machine.load('10 PRINT ENVIRON$("K"): ENVIRON "K=V"\n')
    machine.run()
    machine.run()
    assert screen.getvalue() == "\nV\n"


def test_words_apart_from_their_dollar():
    """GW-BASIC tokenises ENVIRON$, IOCTL$ and ERDEV$ as the word and a ``$``: blanks may
    stand between them (real GW-BASIC 3.23 reads ``ENVIRON $ (0)`` as ENVIRON$(0))."""
    source = '10 ON ERROR GOTO 30\n20 PRINT ENVIRON $ (0)\n30 PRINT ERR; ERDEV  $; ".": RESUME 40\n40 END\n'
    assert run_gw(source) == " 5 .\n"


def _casio(source: str) -> str:
    from yaseer.basic.dialects.dialect import CASIO
    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.machine import Machine

    screen = io.StringIO()
    machine = Machine(screen=screen, dialect=CASIO)
    try:
        machine.load(source)
        machine.run()
    except BasicError as err:
        return screen.getvalue() + str(err) + "\n"
    return screen.getvalue()


def test_casio_is_unchanged():
    """The casio dialect has none of these words: its own statements still take no ``#``, TO
    or comma after the last argument, and LOCK is no word of its (not LOC K)."""
    assert _casio("10 POKE 1, 2,\n") == "Syntax error in 10\n"
    assert _casio("10 BEEP #1\n") == "Syntax error in 10\n"
    assert _casio("10 POKE 1 TO 2\n") == "Syntax error in 10\n"
    assert _casio("10 DEFSEG = 1: BEEP: PRINT 5\n") == " 5 \n"
    assert _casio("10 PRINT INP(1)\n").startswith("Unsupported word INP")
    assert _casio("10 LOCK 1\n").startswith("Unsupported word LOCK")
