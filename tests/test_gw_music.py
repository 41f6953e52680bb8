"""gw's music: PLAY and its Music Macro Language, PLAY(n), ON PLAY(n), SOUND and BEEP
(machine/music.py, machine/mml.py).

References: the outputs of a real GW-BASIC 3.23 recorded in PC-BASIC's test suite (PLAY,
more_mml_syntax_in_PLAY and PLAYFN for the errors; SoundQueue, MusicQueueLength's legato
line, PlayLegato, PlayStaccato and PlayStaccato18 for the queue and its trap), and the
GW-BASIC source's arithmetic written out by hand here: GWSTS.ASM PLAYS (a 1/L note at T
beats a minute lasts 96000/(T x L) units of 1/400 s; MN sounds 7/8 of it and is silent for
1/8, MS 3/4 and 1/4, each part an entry of the queue), BEEPS (100 units), SOUNDS (ticks x 22
units).  Time is what the machine's clock shows: a wait moves it on instead of sleeping, so
TIMER differences are the music's durations (never the host's time), shown to a tenth.
"""

from __future__ import annotations

import pytest

from test_gw_files import yaseer_run
from test_startup_imports import warm_run


def run(source: str, tmp_path) -> str:
    return yaseer_run(source, tmp_path)


def errors_program(lines: list[str]) -> str:
    body = "".join(f"{10 * (k + 1)} {line}\n" for k, line in enumerate(lines))
    return f"5 ON ERROR GOTO 900\n{body}899 END\n900 PRINT ERR; ERL: RESUME NEXT\n"


def test_the_music_language_is_read_as_maclng_reads_it(tmp_path):
    """Each command checked where it is read (recordings PLAY, more_mml_syntax_in_PLAY: Missing
    operand, Type mismatch, Illegal function call; the source's PLYTAB, NOTXLT, PLYLEN ...)."""
    lines = [
        "PLAY",  # FRMEVL finds no operand
        "PLAY 5",  # not a string
        'PLAY "H"',  # not a command
        'PLAY "L65C"', 'PLAY "L64C"',  # lengths 1..64
        'PLAY "B.16"',  # the dot ends the note: 16 is no command
        'PLAY "P0.."', 'PLAY "P2.."',  # P0 plays nothing and reads no dot
        'PLAY "B#"', 'PLAY "C-"', 'PLAY "e-f+"',  # no B#, C-; E- is D#, F+ is F#
        'PLAY "MX"', 'PLAY "M"',
        'PLAY "T31"', 'PLAY "T32"', 'PLAY "O7"', 'PLAY "O0<<C>>>>>>>>C"',  # > and < stop at 6 and 0
        'PLAY "N85"', 'PLAY "N84N0"', 'PLAY "N"',
        'PLAY "L32;;C"', 'PLAY "L32;C;D"',  # one ; ends a number, a second is a command
        'N = 3: PLAY "XN;"', 'Q$ = "": PLAY "N=Q$;"', 'PLAY "P"', 'PLAY "X"',
        'PLAY "C", "D"',  # the comma after PLAY's string is Syntax error once it has played
    ]
    expected = (" 22  10 \n 13  20 \n 5  30 \n 5  40 \n 5  60 \n 5  70 \n 5  90 \n 5  100 \n 5  120 \n"
                " 5  130 \n 5  140 \n 5  160 \n 5  180 \n 5  200 \n 5  210 \n 13  230 \n 13  240 \n 5  250 \n 5  260 \n"
                " 2  270 \n")
    assert run(errors_program(lines), tmp_path) == expected


def test_play_function_counts_the_notes_waiting(tmp_path):
    """PLAY(n): n a byte after CINT (recording PLAYFN: -1 and 256 Illegal function call, 32768
    Overflow, a string Type mismatch); nothing queued: 0; the argument is read and checked
    before the ``)`` is looked for (PLAYFN: ``PLAY("ABC"`` Type mismatch, ``PLAY(1`` Syntax error)."""
    lines = ["PRINT PLAY(300)", "PRINT PLAY(-2)", "PRINT PLAY(40000)", 'PRINT PLAY("X")', "PRINT PLAY(7.4)",
             "PRINT PLAY", "PRINT PLAY(1, 2)", 'X = PLAY("Y"', "X = PLAY(3", "X = PLAY(999", "X = PLAY("]
    assert run(errors_program(lines), tmp_path) == (" 5  10 \n 5  20 \n 6  30 \n 13  40 \n 0 \n 2  60 \n 2  70 \n"
                                                    " 13  80 \n 2  90 \n 5  100 \n 22  110 \n")


def timed(statement: str) -> str:
    """A line that runs ``statement`` and prints how long it took on the machine's clock."""
    return f'T = TIMER: {statement}: PRINT USING "##.#"; TIMER - T;: PRINT PLAY(0)'


def timed_program(lines: list[str]) -> str:
    return "".join(f"{10 * (k + 1)} {line}\n" for k, line in enumerate(lines))


def test_foreground_music_waits_until_its_last_entry_has_started(tmp_path):
    """MF: a legato note of 4 s (T60 L1: 96000/60 = 1600 units) does not wait; MN waits for
    its 3.5 s tone, MS for its 3 s tone (their silences start then); SOUND 800, 18.2 twice
    waits for the first (recording SoundQueue: one second); BEEP is 100 units in the
    foreground even after MB."""
    lines = [
        'PLAY "T60 L1 MF"', "SOUND 40, 0",
        timed('PLAY "ML C"'), "SOUND 40, 0",
        timed('PLAY "MN C"'), "SOUND 40, 0",
        timed('PLAY "MS C"'), "SOUND 40, 0",
        timed("SOUND 800, 18.2: SOUND 800, 18.2"), "SOUND 40, 0",
        'PLAY "MB"', timed("BEEP: BEEP: BEEP"),
    ]
    assert run(timed_program(lines), tmp_path) == " 0.0 0 \n 3.5 0 \n 3.0 0 \n 1.0 0 \n 0.5 0 \n"


def test_background_music_waits_for_room_for_32_entries(tmp_path):
    """MB: 35 legato notes at T60 L4 (one second each) wait two seconds and leave 32 waiting
    (recording MusicQueueLength); 33 legato notes do not wait; MN and MS notes are two
    entries each, so 16 fit (15 counted waiting behind the one playing) and the 17th waits
    for the first note's tone to end: 3.5 s at T60 L1 for MN, 3 s for MS; SOUND 40, 0
    empties the queue."""
    lines = [
        'PLAY "T60 MB ML L4"', timed(f'PLAY "{"CDEFG" * 7}"'), "SOUND 40, 0",
        timed(f'PLAY "{"C" * 33}"'), "SOUND 40, 0",
        'PLAY "L1 MN"', timed(f'PLAY "{"C" * 16}"'), "SOUND 40, 0",
        timed(f'PLAY "{"C" * 17}"'), "SOUND 40, 0",
        'PLAY "MS"', timed(f'PLAY "{"C" * 17}"'), "SOUND 40, 0", "PRINT PLAY(0)",
    ]
    expected = " 2.0 32 \n 0.0 32 \n 0.0 15 \n 3.5 16 \n 3.0 16 \n 0 \n"
    assert run(timed_program(lines), tmp_path) == expected


def test_the_language_reads_variables_and_strings(tmp_path):
    """X plays a string variable where it stands, =name; gives a number (MCLXEQ, VARGET):
    a 1 s C (T60 L4), then L2 from an array element, N40 from a variable and a C of 2 s each:
    the last note starts after 3 s; a - before = negates (VALSC3): T120, three notes of .5 s."""
    lines = ['A$ = "C": L(2) = 2: N = 40: PLAY "T60 ML"', timed('PLAY "XA$; L=L(2); N=N; C"'),
             timed('SOUND 40, 0: K = -120: B$ = "XA$;XA$;": PLAY "T-=K; L4 XB$; C"')]
    assert run(timed_program(lines), tmp_path) == " 3.0 0 \n 1.0 0 \n"


def test_clear_puts_play_back_to_its_start(tmp_path):
    """CLEAR (and RUN) call SNDINI: foreground, T120, L4, MN, O4 again; a L1 note at T120 is
    800 units, MN's tone 700 (1.75 s, shown to a tenth)."""
    lines = ['PLAY "MB T60 ML"', "CLEAR", timed('PLAY "L1 C"')]
    assert run(timed_program(lines), tmp_path) == " 1.8 0 \n"


def test_on_play_traps_when_the_count_goes_below_n(tmp_path):
    """ON PLAY(n) GOSUB: once, when the notes waiting go from n to n-1 (recordings PlayLegato,
    PlayStaccato); never if they are never n (PlayStaccato18: 16 staccato notes at most); the
    program waiting in a loop on PLAY(n) ends after the music's time."""
    program = ("10 ON PLAY(4) GOSUB 100: PLAY ON\n20 T = TIMER: PLAY \"T60 MB ML L4 CDEFGAB\"\n"
               "30 WHILE PLAY(0) > 0: WEND\n40 PRINT USING \"##.#\"; TIMER - T\n"
               "50 ON PLAY(9) GOSUB 100: PLAY \"CDEFGA\"\n60 WHILE PLAY(0): WEND: END\n"
               "100 PRINT \"TRAP\"; PLAY(0): RETURN\n")
    assert run(program, tmp_path) == "TRAP 3 \n 6.0\n"


def test_play_is_still_unsupported_in_casio(tmp_path):
    assert yaseer_run('10 PLAY "C"\n', tmp_path, dialect="casio") == "Unsupported word PLAY in 10\n"


MUSIC_MODULES = ("yaseer.basic.machine.music", "yaseer.basic.machine.mml")


@pytest.mark.parametrize("listing, imported", [("10 PRINT 1\n", set()), ('10 PLAY "MBC": PRINT 1\n', set(MUSIC_MODULES))])
def test_only_programs_with_music_import_it(tmp_path, listing, imported):
    path = tmp_path / "music.bas"
    path.write_text(listing)
    assert warm_run(path, tmp_path / "cache", MUSIC_MODULES, ("--dialect", "gw"))[1] == imported


def test_a_varptr_string_is_read_at_its_address(tmp_path):
    """X and = followed by a type byte below 9 and an address read the variable there
    (MACLNG.ASM SCNVAR, RETVAR): here bytes POKEd into the data segment, a string descriptor
    (length 3, address 1010) over "CDE" and an integer 40 at 1020: four notes of 1 s (T60
    ML L4), the last starting after 3 s; type byte 7 is no variable's."""
    program = ("10 DEF SEG: POKE 1000, 3: POKE 1001, 1010 MOD 256: POKE 1002, 1010 \\ 256\n"
               "20 POKE 1010, 67: POKE 1011, 68: POKE 1012, 69: POKE 1020, 40: POKE 1021, 0\n"
               '30 PLAY "T60 ML": ' + timed('PLAY "X" + CHR$(3) + MKI$(1000) + "N=" + CHR$(2) + MKI$(1020)') + "\n"
               '40 PLAY "N=" + CHR$(7) + MKI$(1020)\n')
    assert run(program, tmp_path) == " 3.0 0 \nIllegal function call in 40\n"
