"""Fuzzing gw's text-screen and language statements: random programs of LOCATE, COLOR,
CLS, KEY, SCREEN, VIEW PRINT, WIDTH, CSRLIN, POS, SCREEN(), INKEY$, PRINT of control
codes, FRE, RETURN's forms, DEF FN bodies, bad IF branches, MID$ onto itself, WHILE,
RANDOMIZE, LPOS, PRINT USING, DEFINT/DEFSTR run as statements, CLEAR, blanks inside
numbers, filling the string space, RENUM, ``.`` as the current line, DEF SEG, PEEK, POKE and VARPTR,
event traps (ON KEY(n) GOSUB, TIMER ON ...), STICK, STRIG, PEN, MOTOR, SWAP, OPTION BASE, MKI$/CVI and the
other conversions, USR, the device words, PLAY's music language, PLAY(n), ON PLAY(n) and SOUND,
the graphics statements (PSET, PRESET, LINE, VIEW, WINDOW, GET, PUT, PALETTE, PCOPY) and POINT, PMAP,
CIRCLE, PAINT and DRAW's macro language, with arguments in and out of range,
left out or of the wrong type.  Each program ends normally or with a BASIC error line
naming its line (never a Python exception), and writes nothing in its directory.

``YASEER_FUZZ_EXAMPLES`` sets the number of programs (60 by default).
"""

from __future__ import annotations

import io
import os
from pathlib import Path

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from yaseer.basic.dialects.dialect import GW
from yaseer.basic.errors import BasicError
from yaseer.basic.machine.machine import INTERNAL_ERROR, Machine

ARGUMENTS = ["1", "0", "-1", "25", "24", "80", "81", "255", "256", "32767", "32768", "1E10", '"A"', "X", "", "2.5"]
# pieces of PLAY's music language (machine/mml.py), good and bad
MUSIC = ["C", "D#", "E-", "F+", "B#", "A.", "G64..", "N40", "N0", "N85", "O3", "O9", ">", "<", "P8", "P0", "P",
         "T200", "T20", "L8", "L0", "MB", "MF", "ML", "MN", "MS", "MQ", "XA$;", "XX;", "X", "N=X;", "L=X;",
         "O=Q(1);", "T=-X;", "Z", ";", " ", "c+2.", "l64;a;", "=", "+", "65536"]


# pieces of DRAW's macro language (machine/draw_macro.py), good and bad
SKETCH = ["U", "D5", "L-3", "R=X;", "E", "F99999", "G2", "H", "M10,10", "M+5,-5", "M", "M1", "B", "N", "A1",
          "A4", "TA45", "TA400", "T", "C2", "C", "S8", "S0", "S300", "P1,3", "P1", "XA$;", "X", "Z", ";", " "]


def music(data) -> str:
    return "".join(data.draw(st.lists(st.sampled_from(MUSIC), max_size=6)))


def argument(data) -> str:
    return data.draw(st.sampled_from(ARGUMENTS))


def statement(data) -> str:
    a, b, c = argument(data), argument(data), argument(data)
    code = data.draw(st.integers(0, 40))
    tune = music(data)
    sketch = "".join(data.draw(st.lists(st.sampled_from(SKETCH), max_size=6)))
    choices = [
        f"LOCATE {a}, {b}", f"LOCATE {a}", f"LOCATE , {b}", f"LOCATE {a}, {b}, {c}, {a}, {b}", f"LOCATE {a},{b},{c},{a},{b},{c}",
        f"COLOR {a}, {b}, {c}", f"COLOR {a}", f"COLOR , {b}", "COLOR", f"CLS {a}", "CLS",
        "KEY ON", "KEY OFF", "KEY LIST", f'KEY {a}, "TEXT"', f"KEY {a}, {b}",
        f"SCREEN {a}", f"SCREEN {a}, {b}, {c}", f"VIEW PRINT {a} TO {b}", "VIEW PRINT",
        f"WIDTH {a}", f"WIDTH {a}, {b}", f"PRINT SCREEN({a}, {b}); SCREEN({a}, {b}, {c})",
        "PRINT CSRLIN; POS(0)", f"PRINT CHR$({code}); \"AB\"; CHR$({code});", f'PRINT STRING$(80, "*");',
        "K$ = INKEY$", f"X = {a}: PRINT X", "FOR I = 1 TO 30: PRINT I: NEXT",
        # the language items: FRE, RETURN's forms, DEF FN bodies, IF branches, elements, USING, MID$
        "X = FRE(0)", 'X = FRE("")', f"RETURN {a}", "GOSUB 1000", f"DEF FNA(X) = X + {a}", "DEF FNB(X) = X +",
        "PRINT FNA(1); FNB(2)", f"IF {a} THEN EXIT FOR ELSE )", f"DIMA$({a})", f'PRINT USING "##.#"; {a}',
        f'A$ = "ABCDEFGH": MID$(A$, {a}) = A$', "WHILE I < 2: I = I + 1: WEND", f"RANDOMIZE {a}", f"IF {a}, THEN 1000",
        f"PRINT LPOS({a}); CHR$({a}); LEFT$(\"AB\", {a})", "PRINT -NOT 1",
        # DEF types run as statements (switching the compiled variant), CLEAR, blanks in numbers
        f"DEFINT A-{chr(65 + code % 26)}", "DEFSTR X", "DEFDBL A, X-Z", "DEFSNG A-Z", f"A = {a}: PRINT A; X",
        f'X = {a}: A$ = "S": PRINT A$; X', "IF X THEN DEFSTR X ELSE DEFINT X", "CLEAR", "PRINT 1 2; &O 7 7; & H1F; 1 . 5 E 1",
        "PRINT FNA(1)", "N = N + 1: IF N < 3 THEN 10",
        # GW's string space: filled (Out of string space), garbage collected, FRE with and without garbage
        f"DIM S$(300): FOR K = 0 TO 300: S$(K) = SPACE$({a}): NEXT", f'T$ = STRING$({a}, "T") + T$',
        'PRINT FRE(0); FRE(""); FRE(X)', "ERASE S$",
        f"RENUM {a}, , {b}", f"RENUM , {a}", "RENUM",
        # "." as the current line (GW's DOT) where a line number may stand, and where it may not
        "LIST .", "LIST 10-.", "LLIST .-", f"DELETE .-{a}", "DELETE .", "EDIT .", f"AUTO ., {a}", "AUTO .",
        f"RENUM {a}, .", "RENUM ., ., .", "LIST .5", "LIST . - .", 'CHAIN "NONE", , DELETE .-', "GOTO .",
        # memory: the text screen's at &HB800 (and WIDTH 40's pages), the data segment, any other
        "DEF SEG = &HB800", "DEF SEG", f"DEF SEG = {a}", f"POKE {a}, {b}", f"POKE {a}", f"PRINT PEEK({a})",
        f"POKE {a} * 2 + 1, {b}: PRINT PEEK({a} * 2 + 1)", f"X = PEEK({a}, {b})",
        f"P = VARPTR(#{a}) + 188: POKE P, {b}: PRINT PEEK(P)", "PRINT VARPTR(X)", f"PRINT VARPTR({a})",
        # event traps and the game port
        f"ON KEY({a}) GOSUB 1000", f"ON TIMER({a}) GOSUB 1000", "ON PEN GOSUB 1000", f"ON STRIG({a}) GOSUB 1000",
        f"KEY({a}) ON", f"COM({a}) STOP", f"STRIG({a}) OFF", "TIMER ON", "TIMER STOP", "TIMER OFF", "PEN ON",
        f"PLAY({a}) ON", f"PRINT STICK({a}); STRIG({b}); PEN({c})", f"MOTOR {a}", "ON TIMER GOSUB 1000",
        # SWAP, OPTION BASE, the MKx$/CVx conversions, DEF SEG and USR, the device words
        f"SWAP X, A$", f"SWAP X, Y: PRINT X; Y", f'A$ = "Q": SWAP A$, B$: PRINT A$; B$', f"OPTION BASE {a}",
        f"DIM Q({a}): OPTION BASE 1", f"PRINT CVI(MKI$({a})); CVS(MKS$({a})); CVD(MKD$({a}))",
        f'PRINT CVI("{chr(65 + code % 26)}"); CVS(""); CVD(A$)', f"DEF USR{code % 10} = {a}",
        f"PRINT USR({a})", f"OUT {a}, {b}", f"PRINT INP({a})", f"SOUND {a}, {b}", "BEEP", f"PRINT ENVIRON$({a})",
        # PLAY, its music language, PLAY(n) and its trap, SOUND into the music queue
        f'PLAY "{tune}"', f'A$ = "{tune}": PLAY "XA$;"', 'A$ = "XA$;": PLAY A$', f"PLAY {a}", f'PLAY "{tune}", {a}',
        f"PRINT PLAY({a})", "WHILE PLAY(0) > 0: WEND", f"ON PLAY({a}) GOSUB 1000", "PLAY ON", "PLAY STOP",
        f'PLAY "MB{tune}": PRINT PLAY(0)', f"SOUND {a}, {b}: PRINT PLAY(0)", "SOUND 440, 0",
        # the graphics statements (machine/graphics_words.py) in a graphics mode and out of one
        "SCREEN 1", "SCREEN 9", f"PSET ({a}, {b}), {c}", f"PRESET STEP ({a}, {b})", f"PSET ({a}, {b}",
        f"LINE ({a}, {b})-({c}, {a}), {b}, BF", f"LINE -({a}, {b}), , B, {c}", f"LINE ({a}, {b})-STEP({c}, {a}), {b}",
        f"LINE ({a},{b})-({c},{a}),{b},{c}", f"VIEW ({a}, {b})-({c}, {a}), {b}, {c}", f"VIEW SCREEN ({a}, {b})-({c}, {a})",
        "VIEW", f"WINDOW ({a}, {b})-({c}, {a})", f"WINDOW SCREEN ({a}, {b})-({c}, 1)", "WINDOW",
        f"PRINT POINT({a}, {b}); POINT({c}); PMAP({a}, {b})", f"DIM G%(50): GET ({a}, {b})-({c}, {a}), G%",
        f"PUT ({a}, {b}), G%, {'PSET' if code % 2 else 'XOR'}", f"PUT ({a}, {b}), G%", f"GET ({a}, {b})-(1, 1), G$",
        f"PALETTE {a}, {b}", "PALETTE", f"DIM P%(16): PALETTE USING P%({a})", f"PCOPY {a}, {b}", f"CLS {a}",
        # CIRCLE, PAINT and DRAW (machine/figures.py)
        f"CIRCLE ({a}, {b}), {c}", f"CIRCLE STEP ({a}, {b}), {c}, {a}, {b}, {c}, {a}",
        f"CIRCLE (90, 90), {a}, , {b}, {c},", f"PAINT ({a}, {b}), {c}, {a}", f'PAINT STEP ({a}, {b}), "{tune}", {c}, "{tune}"',
        f'PAINT (5, 5), {a}, , {b}', f'DRAW "{sketch}"', f'A$ = "{sketch}": DRAW "XA$;"', f"DRAW {a}",
    ]
    return data.draw(st.sampled_from(choices))


def example_count() -> int:
    return int(os.environ.get("YASEER_FUZZ_EXAMPLES", 60))


@settings(max_examples=example_count(), deadline=None, derandomize=True, database=None,
          suppress_health_check=list(HealthCheck))
@given(data=st.data())
def test_screen_statements_end_normally_or_with_a_basic_error_line(data, tmp_path_factory):
    lines = [statement(data) for _ in range(data.draw(st.integers(1, 10)))]
    source = "".join(f"{10 * (k + 1)} {line}\n" for k, line in enumerate(lines)) + "999 END\n1000 RETURN\n"
    workdir = tmp_path_factory.mktemp("fuzzgw")
    before = Path.cwd()
    os.chdir(workdir)
    try:
        machine = Machine(screen=io.StringIO(), dialect=GW, input_stream=io.StringIO("ab\n"))
        try:
            machine.load(source)
            machine.run()
        except BasicError as err:
            assert err.code != INTERNAL_ERROR, f"a Python exception inside: {err}\n{source}"
            assert err.line is not None, f"no line named: {err}\n{source}"
    finally:
        os.chdir(before)
    assert list(workdir.iterdir()) == [], "the run wrote a file"
