"""PRINT, STR$ and PRINT USING against PC-BASIC 2.0.8, byte for byte.

Seeded random cases (``YASEER_DIFF_CASES`` / ``YASEER_DIFF_SEED`` to run
more or others by hand).  Values are exact in single precision with at most
7 significant digits, so GW-BASIC's single precision decides no digit; plain
PRINT is compared only where GW-BASIC's 7-digit rule and yaseer's 10-digit
rule give the same notation.
"""

from __future__ import annotations

import random
from fractions import Fraction

import pytest

from test_differential_support import (
    PcBasic,
    base_seed,
    basic_number,
    case_count,
    exact_single,
    random_using_case,
    significant_digits,
    using_statement,
)
from yaseer.basic.errors import BasicError
from yaseer.basic.formatting import number_to_text, str_dollar, using


# PC-BASIC 2.0.8 uses importlib.resources calls deprecated in Python 3.11.
pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")


@pytest.fixture(scope="module")
def pc():
    session = PcBasic()
    yield session
    session.close()


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
