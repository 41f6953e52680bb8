"""PRINT, STR$ and PRINT USING against PC-BASIC 2.0.8, byte for byte.

Seeded random cases (``YASEER_DIFF_CASES`` / ``YASEER_DIFF_SEED`` to run
more or others by hand).  Values are exact in single precision with at most
7 significant digits, so GW-BASIC's single precision decides no digit; plain
PRINT is compared only where GW-BASIC's 7-digit rule and yaseer's 10-digit
rule give the same notation.
"""

from __future__ import annotations

import random
from decimal import Decimal
from fractions import Fraction

import pytest

from test_differential_support import (
    PcBasic,
    base_seed,
    basic_number,
    case_count,
    exact_single,
    in_pcbasic_rounding_quirk,
    is_string_field,
    mantissa_digits,
    random_format,
    random_string,
    random_using_case,
    significant_digits,
    using_statement,
)
from yaseer.basic.errors import BasicError
from yaseer.basic.arithmetic.formatting import number_to_text, str_dollar, using


# PC-BASIC 2.0.8 uses importlib.resources calls deprecated in Python 3.11.
pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")


def yaseer_using(fmt: str, values) -> str:
    """yaseer's PRINT USING text, or its error message."""
    try:
        return using(fmt, values)
    except BasicError as err:
        return str(err)


def pcbasic_using(pc: PcBasic, fmt: str, values) -> str:
    """PC-BASIC's PRINT USING text (its 80-column wrap undone), or its error message."""
    out = pc.statement(using_statement(fmt, values)).rstrip("\n")
    lines = out.split("\n")
    if lines[-1] in ("Type mismatch", "Illegal function call", "Overflow"):
        return lines[-1]  # the text printed before the error is not compared
    return out.replace("\n", "")


def mismatches(pairs):
    """The (case, ours, theirs) triples that differ."""
    return [(case, ours, theirs) for case, ours, theirs in pairs if ours != theirs]


def test_print_using_random_formats_match_pcbasic(pc):
    rng = random.Random(base_seed())
    results = []
    for _ in range(case_count()):
        fmt, values = random_using_case(rng)
        results.append(((fmt, values), yaseer_using(fmt, values), pcbasic_using(pc, fmt, values)))
    bad = mismatches(results)
    assert not bad, f"{len(bad)} of {len(results)} differ, e.g. {bad[:5]}"


@pytest.mark.parametrize(
    "fmt, values",
    [
        ("##.##", ["x"]),
        ("&", [1]),
        ("A!B", [1]),
        ("abc", [1]),
        ("##.##", [3.125, "x"]),
    ],
)
def test_print_using_errors_match_pcbasic(pc, fmt, values):
    assert yaseer_using(fmt, values) == pcbasic_using(pc, fmt, values)


def shared_notation(x: float) -> bool:
    """Whether GW-BASIC (7 digits) and yaseer (10 digits) both use fixed notation for ``x``."""
    if x == 0:
        return True
    digits, exponent = f"{abs(x):.6e}".split("e")
    significant = digits.replace(".", "").rstrip("0")
    return int(exponent) <= 6 and len(significant) - int(exponent) <= 8


def test_plain_print_and_str_dollar_match_pcbasic(pc):
    rng = random.Random(base_seed() + 1)
    results = []
    while len(results) < case_count() // 2:
        x = exact_single(rng) / rng.choice([1, 16, 256, 4096])
        if significant_digits(Fraction(x)) > 7 or not shared_notation(x):
            continue
        literal = basic_number(x)
        theirs = pc.statement(f'PRINT {literal}: PRINT "["; STR$({literal}); "]"')
        ours = number_to_text(x) + "\n[" + str_dollar(x) + "]\n"
        results.append((literal, ours, theirs))
    bad = mismatches(results)
    assert not bad, f"{len(bad)} of {len(results)} differ, e.g. {bad[:5]}"


# ---------------------------------------------------------------------------
# Doubles: PC-BASIC with /D and # literals, up to 12 significant digits
# ---------------------------------------------------------------------------

def decimal_half(x: float, field: str) -> bool:
    """Whether rounding ``x`` for ``field`` meets an exact decimal half (yaseer rounds the typed
    decimal, PC-BASIC the binary value, so the two may go different ways)."""
    digits = Decimal(repr(abs(x)))
    if is_scientific(field):
        places = mantissa_digits(field) - 1 - digits.adjusted()
    else:
        places = field.partition(".")[2].count("#")
    scaled = digits.scaleb(places)
    return scaled - int(scaled) == Decimal("0.5")


def random_double(rng: random.Random) -> float:
    """A decimal of 1 to 12 significant digits, either sign, never -0."""
    digits = rng.randint(1, 12)
    value = rng.randint(0, 10 ** digits - 1) / 10 ** rng.randint(0, digits + 2)
    return float(repr(value * rng.choice([1, -1]))) or 0.0


def is_scientific(field: str) -> bool:
    return field.endswith(("^^^^", "^^^^+", "^^^^-"))


def double_using_case(rng: random.Random):
    """A format and values for it; no ``^^^^`` field without mantissa digits (PC-BASIC's
    exponent is degenerate there, and zero, the one value both agree on, is excluded)."""
    fmt, fields = random_format(rng)
    while any(is_scientific(f) and mantissa_digits(f) == 0 for f in fields if not is_string_field(f)):
        fmt, fields = random_format(rng)
    values = []
    for i in range(rng.randint(1, 4)):
        field = fields[i % len(fields)]
        if is_string_field(field):
            values.append(random_string(rng))
            continue
        x = random_double(rng)
        while in_pcbasic_rounding_quirk(x, field) or decimal_half(x, field) or (is_scientific(field) and x == 0):
            x = random_double(rng)
        values.append(x)
    return fmt, values


def double_literal(x: float) -> str:
    """A GW-BASIC double literal without exponent: ``0.0000941#``."""
    return format(Decimal(repr(x)), "f") + "#"


@pytest.fixture(scope="module")
def pc_double():
    session = PcBasic(double=True)
    yield session
    session.close()


def test_print_using_doubles_match_pcbasic_double(pc_double):
    rng = random.Random(base_seed() + 5)
    results = []
    for _ in range(case_count() // 2):
        fmt, values = double_using_case(rng)
        literals = "; ".join(f'"{v}"' if isinstance(v, str) else double_literal(v) for v in values)
        out = pc_double.statement(f'PRINT USING "{fmt}"; {literals}').rstrip("\n")
        lines = out.split("\n")
        theirs = lines[-1] if lines[-1] in ("Type mismatch", "Illegal function call") else out.replace("\n", "")
        theirs = theirs.replace("D+", "E+").replace("D-", "E-")  # GW-BASIC's D marks a double
        results.append(((fmt, values), yaseer_using(fmt, values), theirs))
    bad = mismatches(results)
    assert not bad, f"{len(bad)} of {len(results)} differ, e.g. {bad[:5]}"
