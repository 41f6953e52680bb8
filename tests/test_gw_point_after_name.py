"""A number that begins with ``.`` after a name and blanks is a Syntax error in gw.

CRUNCH keeps the digits and points that follow a name (and blanks) as text: its number
flag DONUM stays a name's (GWMAIN.ASM NOTRFN sets it, a blank leaves it, any other
character resets it at NOTRS1, so ``A$ .5`` and ``A<tab>.5`` crunch the number).  When
the statement runs, EVAL reads a number from such text only where it starts with a
digit (GWEVAL.ASM EVAL: FIN when CHRGTR says digit), so ``.6`` there is a Syntax error
and ``0.6`` the number.  A real GW-BASIC 3.23 shows it (the recorded unsorted/NUMLIT2
test of PC-BASIC's suite: ``OPEN "a" FOR OUTPUT AS .6`` is error 2, ``AS 0.6`` opens #1,
and the program file saved has both as text); PC-BASIC 2.0.8 agrees where the name has
no type character (it also refuses ``A$ .5``: the source's crunch does not).
"""

from __future__ import annotations

import pytest

from test_differential_support import run_gw, run_yaseer

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

CASES = {
    '10 ON ERROR GOTO 90\n20 OPEN "P.TXT" FOR OUTPUT AS .6\n30 OPEN "P.TXT" FOR OUTPUT AS 0.6\n'
    '40 PRINT "OPEN"; LOC(1)\n50 CLOSE: END\n90 PRINT "E"; ERR; ERL: RESUME NEXT\n': "E 2  20 \nOPEN 0 \n",
    "10 A = 1: PRINT A .5\n": " 1 \nSyntax error in 10\n",  # PRINT's item before it is printed
    "10 A = 2: PRINT A 5; A 0.5\n": " 2  5  2  .5 \n",  # a digit first: FIN reads the text
    "10 X = A .5E1\n": "Syntax error in 10\n",
    "10 A = 3: PRINT A;.5; A.5\n": " 3  .5  0 \n",  # after a ; (and A.5 is a name)
}


@pytest.mark.parametrize("source", list(CASES))
def test_a_point_after_a_name_is_text(source, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert run_gw(source) == CASES[source]


def test_a_type_character_or_a_tab_ends_the_name():
    """NOTRS1 resets DONUM at the ``$`` or the tab: the number is crunched (the source)."""
    assert run_gw('10 A$ = "Q": PRINT A$ .5\n') == "Q .5 \n"
    assert run_gw("10 A = 4: PRINT A\t.5\n") == " 4  .5 \n"


def test_casio_reads_the_number():
    assert run_yaseer("10 A = 1: PRINT A .5\n") == " 1  .5 \n"


def test_pc_basic_agrees(tmp_path):
    from test_gw_files import pcbasic_run

    for source, expected in CASES.items():
        assert pcbasic_run(source, tmp_path) == expected, source
