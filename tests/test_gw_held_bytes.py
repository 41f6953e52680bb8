"""A single or double whose exponent byte is 0 and other bytes set (gwfunctions.HeldBytes), found by
a review: made a double (MATH2.ASM $CDS keeps the four bytes above zeros) and negated (MATH1.ASM
$NEG flips the sign bit), it keeps its bytes, as in PC-BASIC 2.0.8."""

import pytest

from test_gw_files import pcbasic_run, yaseer_run

pytest.importorskip("pcbasic")

SOURCES = {
    "to double": '10 X!=CVS(CHR$(1)+CHR$(2)+CHR$(3)+CHR$(0)): E#=X!\n'
                 '20 FOR I=1 TO 8: PRINT ASC(MID$(MKD$(E#),I,1));: NEXT: PRINT\n',
    "array to double": '10 DIM A!(2): A!(1)=CVS(CHR$(1)+CHR$(2)+CHR$(3)+CHR$(0)): E#=A!(1)\n'
                       '20 FOR I=1 TO 8: PRINT ASC(MID$(MKD$(E#),I,1));: NEXT: PRINT\n',
    "double negated": '10 D#=-CVD(STRING$(7,1)+CHR$(0))\n'
                      '20 FOR I=1 TO 8: PRINT ASC(MID$(MKD$(D#),I,1));: NEXT: PRINT D#\n',
    "negated": '10 X!=CVS(CHR$(1)+CHR$(2)+CHR$(3)+CHR$(0)): G!=-X!\n'
               '20 FOR I=1 TO 4: PRINT ASC(MID$(MKS$(G!),I,1));: NEXT: PRINT\n',
}


@pytest.mark.parametrize("name", sorted(SOURCES))
def test_held_bytes_like_pcbasic(name, tmp_path):
    source = SOURCES[name]
    (tmp_path / "p").mkdir()
    (tmp_path / "y").mkdir()
    assert yaseer_run(source, tmp_path / "y") == pcbasic_run(source, tmp_path / "p")
