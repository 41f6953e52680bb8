"""gw reads a double's decimal as GW-BASIC's number reader ``$FIN`` does, bit for bit.

The reference is the source's algorithm written again here on exact rationals
(fractions), not the code under test: MATH2.ASM ``$FIDIG`` takes the digits one by one,
the number so far times ten (``$FMULD``: the exact product rounded half to even to 56
bits) plus the digit (``$FADDD``: for numbers below 2**64 every bit of the digit stays
in the 64-bit register, so the exact sum rounded half to even); MATH1.ASM
``$FINE``/``MDPTEN`` then multiply by 10**n (n up to 38) or divide by it (down to
10**-38; below, by 10**(n + 38) and then by 10**38), 10**n as the table ``$DP00..``
holds it: the nearest 56 bits (exact up to 10**24).  With more than 16 digits or a power
beyond 10**24 this rounds twice, and the last bit is not always the nearest's.

PC-BASIC 2.0.8 reads decimals its own way (the digits exactly, then ten by ten): it is
no reference here.  Literals, VAL, READ and INPUT all go through the reader; each case
prints the 8 bytes of MKD$.
"""

from __future__ import annotations

import io
import random
import re
from fractions import Fraction

from test_differential_support import base_seed, case_count, run_gw
from test_mbf_double import nearest as nearest_parts, value
from test_mbf_double_whole import encoded
from yaseer.basic.machine.machine import Machine


def nearest(x: Fraction) -> Fraction:
    """``x`` rounded half to even to 56 significant bits (test_mbf_double's rounding)."""
    return value(nearest_parts(x))


def source_reads(digits: str, power: int) -> Fraction:
    """``$FIN``'s double for the digit string ``digits`` times 10**power (see the module)."""
    number = Fraction(0)
    for digit in digits:
        number = nearest(number * 10) if number else Fraction(0)
        number = nearest(number + int(digit)) if number + int(digit) else Fraction(0)
    if not number:
        return number
    table = lambda n: nearest(Fraction(10) ** n)
    if power > 0:
        return nearest(number * table(power))
    if power < -38:
        number = nearest(number / table(-power - 38))
        power = -38
    return nearest(number / table(-power)) if power else number


def test_the_reference_rounds_twice_where_the_nearest_differs():
    """Not vacuous: the two roundings give another last bit than the nearest for some
    long decimals (17-19 digits) and for powers beyond 10**24."""
    rng = random.Random(5)
    long_apart = sum(source_reads(str(d), -17) != nearest(Fraction(d, 10 ** 17))
                     for d in (rng.randint(10 ** 16, 10 ** 17 - 1) for _ in range(400)))
    power_apart = sum(source_reads(str(d), 27) != nearest(Fraction(d * 10 ** 27))
                      for d in (rng.randint(1, 10 ** 8) for _ in range(400)))
    assert long_apart > 10 and power_apart > 10


def decimal_cases(count: int) -> list[tuple[str, int]]:
    """(digit string of at most 19 digits, power of ten) pairs where the reading rounds
    twice: 17 to 19 digits, or powers beyond 10**24 (to 10**-60)."""
    rng = random.Random(base_seed() + 51)
    cases = [("12345678901234567", -17), ("1", 30), ("123456789", -45), ("99999999999999999", 0)]
    while len(cases) < count:
        if rng.random() < 0.5:
            digits, power = str(rng.randint(10 ** 16, 10 ** 19 - 1)), rng.randint(-30, 5)
        else:
            digits, power = str(rng.randint(1, 10 ** rng.randint(1, 16))), rng.choice(
                [rng.randint(25, 38), rng.randint(-60, -25)])
        value = Fraction(int(digits)) * Fraction(10) ** power
        if Fraction(2) ** -120 < value < Fraction(2) ** 120:
            cases.append((digits, power))
    return cases


def as_text(digits: str, power: int) -> str:
    """A decimal of the digits and power: the point inside the digits where it can be."""
    if -len(digits) < power < 0:
        return f"{digits[:power]}.{digits[power:]}"
    return f"{digits}D{power}"


def expected_rows(cases) -> str:
    return "".join("".join(f" {byte} " for byte in encoded(source_reads(d, p))) + "\n" for d, p in cases)


def bytes_of(expression: str) -> str:
    return f"FOR K=1 TO 8: PRINT ASC(MID$(MKD$({expression}),K,1));: NEXT: PRINT"


def test_literals_read_as_the_source_reads_them():
    cases = decimal_cases(case_count(200))
    # (a D exponent makes a double; a type character after it would be a syntax error)
    literal = lambda text: text if "D" in text else text + "#"
    source = "".join(f"{10 + 10 * k} A#={literal(as_text(d, p))}: {bytes_of('A#')}\n" for k, (d, p) in enumerate(cases))
    assert run_gw(source) == expected_rows(cases)


def test_val_and_read_read_as_the_source_reads_them():
    cases = decimal_cases(case_count(100))
    lines = []
    for k, (d, p) in enumerate(cases):
        lines.append(f'{10 + 10 * k} {bytes_of(f"VAL({chr(34)}{as_text(d, p)}{chr(34)})")}: READ A#: {bytes_of("A#")}')
    lines.append("9999 DATA " + ",".join(as_text(d, p) for d, p in cases))
    rows = expected_rows(cases).splitlines(keepends=True)
    assert run_gw("\n".join(lines) + "\n") == "".join(row + row for row in rows)


def test_input_reads_as_the_source_reads():
    cases = decimal_cases(case_count(40))
    source = "".join(f"{10 + 10 * k} INPUT A#: {bytes_of('A#')}\n" for k in range(len(cases)))
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect="gw", input_stream=io.StringIO("".join(as_text(d, p) + "\n" for d, p in cases)))
    machine.load(source)
    machine.run()
    # (the screen shows each prompt and the answer typed; the rows of bytes are the rest)
    rows = [row for row in screen.getvalue().splitlines(keepends=True) if re.fullmatch(r"( \d+ ){8}\n", row)]
    assert "".join(rows) == expected_rows(cases)
