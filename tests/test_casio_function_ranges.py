"""Each casio function is its page's error outside the argument its page allows, in binary
arithmetic as in decimal (casio_math.ARGUMENT_RANGES): EXP.md (argument <= 230.2585092),
HYP_SIN_COS_TAN.md (|argument| <= 230.2585092), HYP_ASN_ACS_ATN.md (|x| < 5E+99, 1 <= x <
5E+99, -1 < x < 1).  Values inside are checked against mpmath; the errors' codes against
part-12-2 (OV 13, MA 14).  The programs are our own."""

from __future__ import annotations

import pytest

import yaseer
from yaseer.basic.dialects.dialect import get_dialect

mpmath = pytest.importorskip("mpmath")
mp = mpmath.mp

ARITHMETICS = {"binary": "casio", "decimal": get_dialect("casio").with_arithmetic("decimal")}


def printed(expression: str, arithmetic: str):
    result = yaseer.run(f"10 PRINT {expression}\n", dialect=ARITHMETICS[arithmetic])
    return result.error if result.error else float(result.text)


@pytest.mark.parametrize("arithmetic", ARITHMETICS)
@pytest.mark.parametrize("expression, reference", [
    ("EXP(230.2585092)", lambda: mp.exp(mp.mpf("230.2585092"))),
    ("EXP(-231)", lambda: mp.exp(-231)),
    ("HYP SIN(230.2585092)", lambda: mp.sinh(mp.mpf("230.2585092"))),
    ("HYP SIN(-230.2585092)", lambda: mp.sinh(mp.mpf("-230.2585092"))),
    ("HYP COS(-230.2585092)", lambda: mp.cosh(mp.mpf("-230.2585092"))),
    ("HYP ASN(4.9E99)", lambda: mp.asinh(mp.mpf("4.9e99"))),
    ("HYP ACS(1)", lambda: mp.mpf(0)),
    ("HYP ATN(-.999)", lambda: mp.atanh(mp.mpf("-0.999"))),
])
def test_inside_the_pages_range_the_value(expression, reference, arithmetic):
    mp.dps = 30
    value = printed(expression, arithmetic)
    assert isinstance(value, float), value
    assert value == pytest.approx(float(reference()), rel=1e-9, abs=1e-99)


@pytest.mark.parametrize("arithmetic", ARITHMETICS)
@pytest.mark.parametrize("expression, error", [
    ("EXP(230.2585093)", "Overflow"),
    ("EXP(231)", "Overflow"),
    ("HYP SIN(230.2585093)", "Overflow"),
    ("HYP COS(-230.2585093)", "Overflow"),
    ("HYP ASN(5E99)", "Illegal function call"),
    ("HYP ASN(-5E99)", "Illegal function call"),
    ("HYP ACS(.999)", "Illegal function call"),
    ("HYP ACS(5E99)", "Illegal function call"),
    ("HYP ATN(1)", "Illegal function call"),
    ("HYP ATN(-1)", "Illegal function call"),
])
def test_beyond_the_pages_range_the_error(expression, error, arithmetic):
    assert printed(expression, arithmetic) == f"{error} in 10"


@pytest.mark.parametrize("arithmetic", ARITHMETICS)
def test_the_errors_codes_are_the_manuals(arithmetic):
    program = ("10 ON ERROR GOTO 100\n20 A=EXP(231)\n30 A=HYP ATN(1)\n40 END\n"
               "100 PRINT ERR;: RESUME NEXT\n")
    assert yaseer.run(program, dialect=ARITHMETICS[arithmetic]).text.split() == ["13", "14"]
