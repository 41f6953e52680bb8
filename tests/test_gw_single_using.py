"""PRINT USING's digits of a gw single as MATH2.ASM's ``$PUF`` and MATH1.ASM's ``$PUFE`` find them.

``$FOTNV`` brackets the single so that its 7 printable digits are its whole part (the
same steps as PRINT's, tests/single_digits_support.py ``source_bracket``).  A field that
shows fewer of them divides the bracket by ten once per digit too many (``$DIV10``: a
``$FMULS`` by the double 0.1 made single) and only then rounds: ``$FOTCV`` adds .5
(``$FADDS``) unless the number is whole and cuts the fraction (``$PUFE``: ``$VADDH`` and
``$VINT``, and one more ``$DIV10`` when that carried into a new digit).  So the single
41.35 (41.3499985) shows as 41.3 in ``##.#``, not as its 7 printed digits 41.35 rounded.

The reference: the bracket on exact fractions, the single steps (``$FMULS``, ``$FADDS``)
by PC-BASIC 2.0.8's single arithmetic, which is the source's bit for bit
(tests/test_single_arith.py); apart from the code under test (mbf_digits).  PC-BASIC's own
PRINT USING divides the binary value by ten and rounds in between, so it prints other
digits now and then (``41.35`` in ``##.#``: 41.4): it is the reference of the whole text
where its digits are the source's.  The values come from their 4 bytes (CVS).
"""

from __future__ import annotations

import math
import random
import re
import struct
from decimal import Decimal
from fractions import Fraction

import pytest

from single_digits_support import pc_single, source_bracket
from test_differential_support import base_seed, case_count, run_gw
from test_gw_double_using import r56
from test_gw_single_literals import csd

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

TENTH = float(csd(r56(Fraction(1, 10))))  # $DPM01 made single by $CSD


def tenth(y: float) -> float:
    """``$DIV10`` of a single ``y`` > 0: PC-BASIC's ``$FMULS`` by the single 0.1."""
    return pc_single(y).clone().imul(pc_single(TENTH)).to_value()


def half_added_cut(y: float) -> int:
    """``$FADDS`` of ``y`` and .5 (PC-BASIC's), the fraction cut."""
    return math.floor(pc_single(y).clone().iadd(pc_single(0.5)).to_value()) if y else 0


def fotcv(y: float) -> int:
    """``$FOTCV``'s whole number: ``y`` if whole, else ``y`` + .5 cut."""
    return int(y) if y == int(y) else half_added_cut(y)


def fixed_value(x: Fraction, places: int) -> Decimal:
    """The magnitude ``$PUF`` prints for the single ``x`` > 0 with ``places`` decimals."""
    b, power = source_bracket(x)
    y = float(b)
    excess = -(places + power)
    if power < 0 and excess > 0:
        for _ in range(excess):
            y = tenth(y)
        return Decimal(fotcv(y)).scaleb(-places)
    return Decimal(fotcv(y)).scaleb(power)


def scientific_value(x: Fraction, digits: int) -> Decimal:
    """The magnitude ``$PUFE`` prints for the single ``x`` > 0 with ``digits`` (1 ..) digits."""
    b, power = source_bracket(x)
    y = float(b)
    if digits >= 7:
        return Decimal(fotcv(y)).scaleb(power)
    for _ in range(7 - digits):
        y = tenth(y)
    power += 7 - digits
    n = half_added_cut(y)
    if n >= 10 ** digits:
        n, power = fotcv(tenth(float(n))), power + 1
    return Decimal(n).scaleb(power)


def printed_value(text: str) -> Decimal:
    """The magnitude a PRINT USING field shows (``%``, sign, commas)."""
    return Decimal(text.strip().lstrip("%").replace(",", "").lstrip("+-").rstrip("+-"))


def single_bytes(x: Fraction) -> str:
    """CVS's argument for the nonzero single ``x``."""
    m, e = math.frexp(abs(float(x)))
    bits = int(m * 2 ** 24) & 0x7FFFFF | (x < 0) << 23
    return "+".join(f"CHR$({b})" for b in (bits & 255, (bits >> 8) & 255, bits >> 16, e + 128))


def random_single(rng: random.Random) -> Fraction:
    """A single from about 1E-9 to 1E+9: a random mantissa, sometimes with few bits."""
    mantissa = rng.randrange(1 << 23, 1 << 24)
    if rng.random() < 0.3:
        mantissa &= ~((1 << rng.randint(0, 20)) - 1)
    return Fraction(mantissa) * Fraction(2) ** (rng.randint(-30, 30) - 24)


def random_field(rng: random.Random) -> tuple[str, int, bool]:
    """A field, the digits it shows (decimals; for ``^^^^`` all of them), whether ``^^^^``."""
    if rng.random() < 0.5:
        places = rng.randint(0, 8)
        return "#" * rng.randint(1, 8) + "." + "#" * places, places, False
    before, places = rng.randint(2, 6), rng.randint(0, 6)
    return "#" * before + ("." + "#" * places if places else "") + "^^^^", before - 1 + places, True


def nearest_single(x: Fraction) -> Fraction:
    return Fraction(struct.unpack("f", struct.pack("f", float(x)))[0])


def tie_case(rng: random.Random) -> tuple[Fraction, str, int, bool]:
    """The nearest single to a decimal whose digit after the field's last is a 5, in the
    field: where rounding the 7 printed digits and the source's steps part most often."""
    shown = rng.randint(1, 6)
    digits = rng.randrange(10 ** (shown - 1), 10 ** shown) * 10 + 5
    if rng.random() < 0.5:
        power = rng.randint(-9, -1)  # the 5 at 10**power: the field shows down to 10**(power + 1)
        places = -power - 1
        field = "#" * max(shown + 1 + power, 1) + "." + "#" * places
        return nearest_single(digits * Fraction(10) ** power), field, places, False
    field = "##" + ("." + "#" * (shown - 1) if shown > 1 else "") + "^^^^"
    return nearest_single(digits * Fraction(10) ** rng.randint(-12, 6)), field, shown, True


def cases(count: int) -> list[tuple[Fraction, str, int, bool]]:
    rng = random.Random(base_seed() + 83)
    rows = [tie_case(rng) if rng.random() < 0.4 else (random_single(rng), *random_field(rng))
            for _ in range(count)]
    return [(-x if rng.random() < 0.3 else x, *rest) for x, *rest in rows]


def program(rows) -> str:
    return "".join(f'{10 + 10 * k} PRINT USING "{field}"; CVS({single_bytes(x)})\n'
                   for k, (x, field, _, _) in enumerate(rows))


def expected(x: Fraction, digits: int, scientific: bool) -> Decimal:
    """The magnitude shown (PUFOUT makes the number positive before ``$PUF``)."""
    return scientific_value(abs(x), digits) if scientific else fixed_value(abs(x), digits)


KNOWN = [  # (statement, printed): the field rounds the divided bracket, not the 7 digits
    ('PRINT USING "##.##"; 8.025', " 8.02"),  # bracket 8024999.5; 7 digits 8.025 (PC-BASIC: 8.02)
    ('PRINT USING "#####.##^^^^"; 31440246!', " 3144.02E+04"),  # bracket 3144024.5 (PC-BASIC too)
    ('PRINT USING "##.#"; 41.35', "41.3"),  # bracket 4134999.75 (PC-BASIC: 41.4)
    ('PRINT USING ".####"; .04085', ".0408"),  # bracket 4084999.75 (PC-BASIC: .0409)
    ('PRINT USING "#.##"; .005', "0.01"),  # bracket 5000000: 7 divisions to .5 (PC-BASIC: 0.00)
    ('PRINT USING "##.##"; 2.675', " 2.68"),  # bracket 2675000 (the single is 2.67499995)
]


@pytest.mark.parametrize(("statement", "printed"), KNOWN)
def test_known_cases_round_the_divided_bracket(statement, printed):
    assert run_gw(f"10 {statement}\n") == printed + "\n"


def test_the_known_cases_are_the_references():
    """The hand-worked values above are the reference's (the literals read as the nearest single)."""
    for statement, printed in KNOWN:
        fmt, literal = re.fullmatch(r'PRINT USING "([^"]*)"; ([0-9.]+)!?', statement).groups()
        x = Fraction(float(pc_single(float(literal)).to_value()))
        whole, _, rest = fmt.partition(".")
        scientific = rest.endswith("^^^^")
        digits = len(whole) - 1 + rest.count("#") if scientific else rest.count("#")
        assert printed_value(printed) == expected(x, digits, scientific), statement


def test_print_using_of_a_single_takes_the_sources_steps_and_is_pcbasics_where_it_agrees(pc):
    """Generated singles in fixed and ``^^^^`` fields showing fewer digits than 7 or more:
    the value printed is the reference's, digit for digit; where PC-BASIC 2.0.8's digits
    are the reference's (most cases), its whole text is yaseer's."""
    rows = cases(case_count(500))
    source = program(rows)
    ours = run_gw(source).splitlines()
    theirs = pc.program(source).replace("\r", "").splitlines()
    assert len(ours) == len(theirs) == len(rows)
    values = [expected(x, digits, sci) for x, _, digits, sci in rows]
    off = [(row[1], float(row[0]), text) for row, text, value in zip(rows, ours, values)
           if printed_value(text) != value]
    assert not off, f"{len(off)} of {len(rows)} differ from the reference, e.g. {off[:3]}"
    same_digits = [k for k, text in enumerate(theirs)
                   if re.fullmatch(r"[ %+\-0-9.,E]*", text) and printed_value(text) == values[k]]
    assert len(same_digits) >= 0.95 * len(rows)
    assert [theirs[k] for k in same_digits] == [ours[k] for k in same_digits]
