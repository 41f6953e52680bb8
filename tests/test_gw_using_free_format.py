"""A gw number of 10**16 or more in a fixed PRINT USING field, as MATH2.ASM's ``$PUF`` prints it.

``$PUF`` first compares the number with ``$DP16`` (MATH1.ASM: 10**16 as a double; a single
is compared with its top four bytes, 10**16 cut to 24 bits, 9999999198822400) and, when it
is not below, prints it in free format (``$FOUT``, as PRINT shows it) and puts a ``%`` in
front.  PUFOUT has made the number positive before (``$VNEG``) and ``$FOUT`` writes its own
blank for the sign, so the field's minus, ``+``, ``$``, ``**``, commas and trailing sign
are not shown: ``PRINT USING "##.##"; -1D17`` is ``% 1D+17``.  PC-BASIC 2.0.8 fills the
field instead (``%-100000000000000000.00``); the source decides.

References: the free format's digits from the source's steps on fractions (a double's:
tests/test_mbf_double.py ``source_digits``; a single's: tests/single_digits_support.py),
laid out here (16 or 7 digits, ``D`` or ``E``); PC-BASIC's STR$ of the magnitude where its
digits are the source's; below the limit and in ``^^^^`` fields PC-BASIC's whole text.
The values come from their bytes (CVD, CVS): no reading stands between.
"""

from __future__ import annotations

import random
from fractions import Fraction

import pytest

from single_digits_support import source_digits as single_source_digits
from test_differential_support import base_seed, case_count, run_gw
from test_mbf_double import pc_agrees_with_the_source, source_digits
from test_mbf_double_whole import basic_bytes, encoded, exact

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

SINGLE_LIMIT = Fraction(0x8E1BC9) * 2 ** 30  # $DP16's top four bytes as a single


def free_text(n: int, power: int, digits: int, marker: str) -> str:
    """PRINT's text of a magnitude of 10**16 or more shown as the ``digits`` digits of ``n``
    times 10**power: always E (D) notation there, one digit before the point."""
    shown = str(n).rstrip("0")
    exponent = power + len(str(n)) - 1
    return shown[0] + ("." + shown[1:] if shown[1:] else "") + f"{marker}+{exponent:02d}"


def random_fixed_field(rng: random.Random) -> str:
    """A fixed field with any of the signs, fills, ``$`` and commas (at most 24 digits)."""
    lead = rng.choice(["", "", "+", "**", "$$", "**$", "+$$"])
    whole = "#" * rng.randint(1, 12)
    if rng.random() < 0.3:
        whole = whole[:1] + "," + whole[1:]
    field = lead + whole + ("." + "#" * rng.randint(0, 6) if rng.random() < 0.7 else "")
    return field + (rng.choice("+-") if not lead.startswith("+") and rng.random() < 0.3 else "")


def large_double(rng: random.Random) -> bytes:
    """A double of 10**16 or more (exponent bytes 182 .. 255), either sign."""
    while True:
        mantissa = rng.getrandbits(56)
        if rng.random() < 0.3:
            mantissa &= ~((1 << rng.randint(0, 55)) - 1)
        data = mantissa.to_bytes(7, "little") + bytes((rng.randint(182, 255),))
        if abs(exact(data)) >= 10 ** 16:
            return data


def single_bytes(x: Fraction) -> bytes:
    """MKS$'s four bytes of a single ``x`` (24 bits at most)."""
    data = encoded(x)  # the double's bytes: the single's 24 bits are its top three bytes
    assert not any(data[:4])
    return data[4:]


def large_single(rng: random.Random) -> Fraction:
    while True:
        x = Fraction(rng.randrange(1 << 23, 1 << 24)) * Fraction(2) ** rng.randint(29, 103)
        if x >= SINGLE_LIMIT:
            return -x if rng.random() < 0.5 else x


def test_known_fields_print_the_free_format_after_the_percent():
    source = "".join(f"{10 * k + 10} {statement}\n" for k, statement in enumerate([
        'PRINT USING "##.##"; 1D17',
        'PRINT USING "##.##"; -1D17',  # PUFOUT's $VNEG: the sign is lost
        'PRINT USING "+#####.##"; 1D16',
        'PRINT USING "**$#,###.##-"; -12345678901234567#',
        'PRINT USING "########################"; 1D16',  # a field wide enough is not used
        'PRINT USING "##.##"; 1E17',
        'PRINT USING "##.##"; 1.5E+38',
    ]))
    assert run_gw(source).splitlines() == [
        "% 1D+17", "% 1D+17", "% 1D+16", "% 1.234567890123457D+16", "% 1D+16", "% 1E+17", "% 1.5E+38"]


def test_the_limits_are_ten_to_the_16_and_its_single_cut(pc):
    """10**16 itself is free format, the double below it (9999999999999999.75) fixed; a
    single from 9999999198822400 (``$DP16``'s top four bytes) up is free format, the single
    below it fixed (as PC-BASIC fills the field there)."""
    below = (Fraction(10 ** 16) - Fraction(1, 4), Fraction(0x8E1BC9 - 1) * 2 ** 30)
    lines = [f'PRINT USING "##.##"; CVD({basic_bytes(encoded(Fraction(10 ** 16)))})',
             f'PRINT USING "##.##"; CVD({basic_bytes(encoded(below[0]))})',
             f'PRINT USING "##.##"; CVS({basic_bytes(single_bytes(SINGLE_LIMIT))})',
             f'PRINT USING "##.##"; CVS({basic_bytes(single_bytes(below[1]))})']
    printed = run_gw("".join(f"{10 * k + 10} {line}\n" for k, line in enumerate(lines))).splitlines()
    assert printed[0] == "% 1D+16" and printed[2] == "% 9.999999E+15"  # its 7 digits: $FOFMT's
    theirs = pc.program("".join(f"{10 * k + 10} {line}\n" for k, line in enumerate(lines))).splitlines()
    assert printed[1] == theirs[1] == "%10000000000000000.00"
    assert printed[3] == theirs[3] == "%9999998000000000.00"


def test_generated_doubles_and_singles_print_the_sources_free_format():
    """Doubles (exponent bytes 182 .. 255) and singles from the limit up, in generated fixed
    fields: ``%``, a blank, and PRINT's digits of the magnitude by the source's steps."""
    rng = random.Random(base_seed() + 71)
    rows = []
    for _ in range(case_count(200)):
        field = random_fixed_field(rng)
        if rng.random() < 0.5:
            data = large_double(rng)
            rows.append((f'PRINT USING "{field}"; CVD({basic_bytes(data)})', free_text(*source_digits(data), 16, "D")))
        else:
            x = large_single(rng)
            expression = f"CVS({basic_bytes(single_bytes(abs(x)))})"
            rows.append((f'PRINT USING "{field}"; {"-" if x < 0 else ""}{expression}',
                         free_text(*single_source_digits(abs(x)), 7, "E")))
    printed = run_gw("".join(f"{10 * k + 10} {line}\n" for k, (line, _) in enumerate(rows))).splitlines()
    assert len(printed) == len(rows)
    bad = [(line, text, want) for (line, want), text in zip(rows, printed) if text != "% " + want]
    assert not bad, f"{len(bad)} of {len(rows)} differ, e.g. {bad[:3]}"


def test_the_free_format_is_pcbasics_str_where_its_digits_are_the_sources(pc):
    """PC-BASIC 2.0.8's STR$ of the magnitude (its free format) is the text after ``%``
    where its 16 digits are the source's; ``^^^^`` fields of the same doubles are its whole
    text."""
    rng = random.Random(base_seed() + 72)
    cases = [(large_double(rng), random_fixed_field(rng)) for _ in range(case_count(200))]
    cases = [(data, field) for data, field in cases if pc_agrees_with_the_source(data)]
    assert len(cases) >= 0.9 * case_count(200)
    fixed = "".join(f'{10 * k + 10} PRINT USING "{field}"; CVD({basic_bytes(data)})\n'
                    for k, (data, field) in enumerate(cases))
    free = "".join(f'{10 * k + 10} PRINT "%"; STR$(ABS(CVD({basic_bytes(data)})))\n'
                   for k, (data, _) in enumerate(cases))
    assert run_gw(fixed).splitlines() == pc.program(free).splitlines()
    scientific = "".join(f'{10 * k + 10} PRINT USING "##.####^^^^"; CVD({basic_bytes(data)})\n'
                         for k, (data, _) in enumerate(cases))
    assert run_gw(scientific) == pc.program(scientific)
