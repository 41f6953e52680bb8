"""A PRINT USING numeric field of more than 24 digit positions is ``Illegal function call`` in gw.

GW-BASIC's PRINT USING scanner (BIPRTU.ASM, NUMNUM .. ENDNUM) counts in [E] the positions
before the point (each ``#`` and comma, the two of ``**`` or ``$$``, the three of ``**$``)
and a leading ``+``, in [C] the point and each ``#`` after it; once FRMEVL has read the
value for the field, ``[E] + [C]`` of 25 or more is FCERR, before PUFOUT looks at the value
(so a string there is Illegal function call too, not Type mismatch).  A field no value
reaches is no error.

PC-BASIC 2.0.8 checks ``digits before + decimals > 24`` with ``$$`` one position, ``**$``
two and neither the point nor a leading ``+``: it is the reference where the two counts
agree (fields of ``#``, commas and ``**``, no point, no ``+``), the source elsewhere.
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, run_gw, run_yaseer

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

HANDLER = "1000 PRINT \"ERR\"; ERR; ERL: RESUME NEXT\n"


def source_count(field: str) -> int:
    """BIPRTU.ASM's [E] + [C] for a numeric field, counted here from the characters."""
    body = field.rstrip("+-^") if not field.startswith("+") else field.rstrip("^")
    lead_plus = body.startswith("+")
    body = body.lstrip("+")
    whole, point, after = body.partition(".")
    return len(whole) + lead_plus + len(point) + len(after)


def pcbasic_count(field: str) -> int:
    """PC-BASIC 2.0.8's ``digits_before + decimals`` (formatter.py NumberField)."""
    body = field.lstrip("+").rstrip("+-^")
    whole, _, after = body.partition(".")
    dollar = whole.startswith("$$")
    return len(whole) - dollar - whole.startswith("**$") + len(after)


def agreeing_field(rng: random.Random, count: int) -> str:
    """A field of ``count`` positions counted alike by both: ``#``, commas, ``**``, no point or ``+``."""
    lead = "**" if rng.random() < 0.3 else ""
    rest = count - len(lead)
    chars = ["#"] * rest
    for _ in range(rng.randint(0, 3)):
        at = rng.randrange(1, rest) if rest > 1 else 0
        if at:
            chars[at] = ","
    tail = rng.choice(["", "", "^^^^", "-", "+"])
    return lead + "".join(chars) + (tail if not (tail == "^^^^" and "," in chars) else "")


def source_field(rng: random.Random, count: int) -> str:
    """A field of ``count`` positions by the source's count, with a point, a leading ``+``,
    ``$$`` or ``**$``: PC-BASIC counts it fewer."""
    kind = rng.choice(["point", "plus", "dollars", "stars_dollar"])
    if kind == "plus":
        return "+" + "#" * (count - 1)
    if kind == "dollars":
        return "$$" + "#" * (count - 2)
    if kind == "stars_dollar":
        return "**$" + "#" * (count - 3)
    before = rng.randint(1, count - 2)
    return "#" * before + "." + "#" * (count - 1 - before)


def program(fields: list[str], value: str = "1") -> str:
    lines = "".join(f'{10 * k + 10} PRINT USING "X{field}Y"; {value}\n' for k, field in enumerate(fields))
    return "5 ON ERROR GOTO 1000\n" + lines + "999 END\n" + HANDLER


def outcome(printed: str) -> list[str]:
    return printed.replace("\r", "").splitlines()


def test_the_counts_here_are_the_scanners():
    """The counting helpers on hand-counted fields (BIPRTU.ASM's increments)."""
    assert source_count("#" * 24) == 24 and pcbasic_count("#" * 24) == 24
    assert source_count("**$##") == 5 and pcbasic_count("**$##") == 4
    assert source_count("$$##") == 4 and pcbasic_count("$$##") == 3
    assert source_count("+##.##") == 6 and pcbasic_count("+##.##") == 4
    assert source_count(".##^^^^-") == 3 and pcbasic_count(".##^^^^-") == 2
    assert source_count("#,###") == 5 == pcbasic_count("#,###")


def test_fields_counted_alike_are_pcbasics(pc):
    """Generated fields of 20 to 30 positions that both count alike: yaseer's output (the
    field or ``Illegal function call`` and its line) is PC-BASIC's, the literal before it
    printed first."""
    rng = random.Random(base_seed() + 91)
    fields = [agreeing_field(rng, rng.randint(20, 30)) for _ in range(60)]
    assert all(source_count(f) == pcbasic_count(f) for f in fields)
    source = program(fields)
    theirs, ours = outcome(pc.program(source)), outcome(run_gw(source))
    assert ours == theirs
    errors = sum(line.startswith("XERR 5") for line in theirs)
    assert errors == sum(source_count(f) > 24 for f in fields) and 0 < errors < len(fields)


def test_the_point_the_plus_and_the_dollars_count_as_the_source_says(pc):
    """Fields with a point, a leading ``+``, ``$$`` or ``**$``: 24 positions by the source's
    count print as PC-BASIC prints them; 25 (PC-BASIC counts 23 or 24 and prints) are
    Illegal function call."""
    rng = random.Random(base_seed() + 92)
    fitting = [source_field(rng, 24) for _ in range(20)]
    wide = [source_field(rng, 25) for _ in range(20)]
    assert all(pcbasic_count(f) <= 24 for f in fitting + wide)
    theirs, ours = outcome(pc.program(program(fitting))), outcome(run_gw(program(fitting)))
    assert ours == theirs and not any("ERR" in line for line in ours)
    ours = outcome(run_gw(program(wide)))
    assert ours == [f"XERR 5  {10 * k + 10} " for k in range(len(wide))]


def test_a_string_in_a_field_too_wide_is_illegal_function_call():
    """The width is checked before the value's type (PC-BASIC: Type mismatch)."""
    assert outcome(run_gw(program(["#" * 25], '"A"'))) == ["XERR 5  10 "]
    assert outcome(run_gw(program(["#" * 24], '"A"'))) == ["XERR 13  10 "]


def test_a_field_no_value_reaches_is_no_error(pc):
    source = f'10 PRINT USING "#_ {"#" * 30}"; 1\n'
    assert run_gw(source) == outcome(pc.program(source))[0] + "\n" == "1 \n"


def test_casio_has_no_such_limit():
    """The dialect's ``using_digits`` is None for casio (its manual has no PRINT USING)."""
    assert run_yaseer(f'10 PRINT USING "{"#" * 30}"; 1\n', dialect="casio") == " " * 29 + "1\n"
