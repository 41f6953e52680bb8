"""casio: VAL and READ give the number the digits name over the machine's whole range.

specifications.md: the calculation range is 1E-99 to 9.999999999E99; VAL.md converts the
numeric characters up to the first that is not one.  yaseer's binary arithmetic holds IEEE
doubles, so the reference for a string of digits is the double those digits name
(Python's ``float`` of the same text, a reader independent of the machine's).  GW-BASIC's
reader (56-bit MBF doubles, whose range ends near 1.7E38) is gw's only: casio read
``VAL("1E50")`` as Overflow and about one value in twenty one unit in the last place off.
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import run_yaseer


def casio_output(source: str) -> str:
    return run_yaseer(source, angle=None, dialect="casio")


def random_numbers(count: int) -> list[str]:
    rng = random.Random(2026)
    texts = []
    for _ in range(count):
        digits = "".join(rng.choice("0123456789") for _ in range(rng.randint(1, 10)))
        texts.append(f"{rng.choice(['', '-'])}{digits[0]}.{digits[1:] or '0'}E{rng.randint(-99, 99)}")
    return texts


@pytest.mark.parametrize("reader", ["VAL", "READ"])
def test_the_digits_name_their_double_across_the_range(reader):
    texts = random_numbers(200) + ["1E50", "9.999999999E99", "1E-99", ".17", "0.1"]
    if reader == "VAL":
        lines = [f'{10 + k} IF VAL("{t}") <> {float(t)!r} THEN PRINT "{t}"' for k, t in enumerate(texts)]
    else:
        lines = [f'{10 + k} READ A: IF A <> {float(t)!r} THEN PRINT "{t}"' for k, t in enumerate(texts)]
        lines.append(f"{10 + len(texts)} DATA {', '.join(texts)}")
    assert casio_output("\n".join(lines) + "\n") == ""


def test_val_of_1e50_prints_it():
    assert casio_output('10 PRINT VAL("1E50"); VAL("-2.5E77")\n') == " 1E+50 -2.5E+77 \n"
