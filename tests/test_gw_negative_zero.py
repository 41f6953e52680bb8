"""The zero with the sign bit (gw): what ``-Z!`` of a zero single or double is.

GW-BASIC negates a single or double by flipping the sign bit of its bytes (GWEVAL.ASM
DOMIN calls VNEG; MATH1.ASM ``$NEG`` is an XOR of the sign byte), a zero's too, and an
integer by NEG (``$INEG``), which leaves 0 as 0.  A real GW-BASIC 3.23 shows it (the
recorded unsorted/NEGZERO test of PC-BASIC's suite): ``MKS$(-Z!)`` is 00 00 80 00 and
``MKD$(-Z#)`` six zero bytes, 80, 00, while ``MKI$(-Z%)`` is 00 00; the value is still
equal to zero and SGN gives 0.  CVS and CVD keep the sign bit of a zero's bytes.  A second
negation flips the bit back (``$NEG`` again); PC-BASIC 2.0.8 keeps it there, and the
source decides.
"""

from __future__ import annotations

from test_differential_support import run_gw

BYTES = "FOR K = 1 TO LEN(B$): PRINT ASC(MID$(B$, K, 1));: NEXT: PRINT\n"


def bytes_of(expression: str, setup: str = "") -> str:
    """The screen of a program printing the codes of string ``expression``."""
    return run_gw(f"10 {setup or 'REM'}\n20 B$ = {expression}: {BYTES}")


def test_minus_zero_has_the_sign_bit_in_its_bytes():
    assert bytes_of("MKS$(N!)", "Z! = 0: N! = -Z!") == " 0  0  128  0 \n"
    assert bytes_of("MKD$(N#)", "Z# = 0: N# = -Z#") == " 0  0  0  0  0  0  128  0 \n"
    assert bytes_of("MKI$(N%)", "Z% = 0: N% = -Z%") == " 0  0 \n"
    assert bytes_of("MKS$(-0.0)") == " 0  0  128  0 \n"


def test_minus_zero_is_zero_otherwise():
    program = "10 Z! = 0: N! = -Z!: Z# = 0: N# = -Z#\n20 PRINT N!; N#; N! = Z!; N# = Z#; SGN(N!); SGN(N#); STR$(N!)\n"
    assert run_gw(program) == " 0  0 -1 -1  0  0  0\n"


def test_a_second_negation_clears_the_bit_and_integers_have_none():
    assert bytes_of("MKS$(-N!)", "Z! = 0: N! = -Z!") == " 0  0  0  0 \n"
    assert bytes_of("MKS$(-(0))") == " 0  0  0  0 \n"  # an integer 0 negated, then made single


def test_cvs_and_cvd_keep_the_sign_of_a_zero():
    assert bytes_of("MKS$(CVS(MKS$(N!)))", "Z! = 0: N! = -Z!") == " 0  0  128  0 \n"
    assert bytes_of("MKD$(CVD(MKD$(N#)))", "Z# = 0: N# = -Z#") == " 0  0  0  0  0  0  128  0 \n"
    assert bytes_of('MKS$(CVS(CHR$(0) + CHR$(0) + CHR$(0) + CHR$(0)))') == " 0  0  0  0 \n"
