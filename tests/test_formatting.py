"""PRINT, STR$ and PRINT USING text (yaseer.basic.arithmetic.formatting).

Expected texts come from the GW-BASIC 3.2 user's manual's PRINT USING
examples, from the rule documented in formatting.py worked by hand, and from
PC-BASIC runs of the same statements (tests/test_differential_pcbasic.py
checks hundreds more against PC-BASIC itself).
"""

from __future__ import annotations

import math

import pytest

from yaseer.basic.errors import ILLEGAL_FUNCTION_CALL, OVERFLOW, TYPE_MISMATCH, BasicError
from yaseer.basic.arithmetic.formatting import number_to_text, parse_format, str_dollar, using

# ---------------------------------------------------------------------------
# Plain PRINT / STR$: 10 significant digits
# ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    "value, text",
    [
        (0.0, " 0 "),
        (-0.0, " 0 "),
        (1.0, " 1 "),
        (-1.5, "-1.5 "),
        (0.5, " .5 "),
        (-0.0625, "-.0625 "),
        (1200.0, " 1200 "),
        (1 / 3, " .3333333333 "),  # 10 digits, rounded down
        (2 / 3, " .6666666667 "),  # 10 digits, rounded up
        (0.1 + 0.2, " .3 "),  # binary noise below the 10th digit vanishes
        (9999999999.0, " 9999999999 "),  # 10 digits before the point: still fixed
        (99999999999.0, " 1E+11 "),  # rounds to 10 digits, then needs 11
        (1e10, " 1E+10 "),
        (12345678901.0, " 1.23456789E+10 "),
        (-2.5e15, "-2.5E+15 "),
        (1e-10, " .0000000001 "),  # 11 places after the point: still fixed
        (1.5e-10, " 1.5E-10 "),  # would need 12 places
        (1e-11, " 1E-11 "),
        (1.25e-5, " .0000125 "),
        (1e100, " 1E+100 "),
        (-1e-100, "-1E-100 "),
        (360.1, " 360.1 "),
        (123456.7891, " 123456.7891 "),
        (123456.78912, " 123456.7891 "),
        (math.pi, " 3.141592654 "),
    ],
)
def test_print_shows_up_to_ten_significant_digits(value, text):
    assert number_to_text(value) == text


def test_str_dollar_has_leading_space_or_minus_and_no_trailing_space():
    assert str_dollar(42.0) == " 42"
    assert str_dollar(-0.25) == "-.25"
    assert str_dollar(1e12) == " 1E+12"


@pytest.mark.parametrize("value", [math.inf, -math.inf, math.nan])
def test_values_that_cannot_be_shown_are_overflow(value):
    with pytest.raises(BasicError) as caught:
        number_to_text(value)
    assert caught.value.code == OVERFLOW
    with pytest.raises(BasicError):
        using("##.##", [value])


# ---------------------------------------------------------------------------
# PRINT USING: the GW-BASIC manual's examples
# ---------------------------------------------------------------------------

MANUAL_EXAMPLES = [
    ("##.##", [0.78], " 0.78"),
    ("###.##", [987.654], "987.65"),
    ("##.## ", [10.2, 5.3, 66.789, 0.234], "10.20  5.30 66.79  0.23 "),
    ("+##.## ", [-68.95, 2.4, 55.6, -0.9], "-68.95  +2.40 +55.60  -0.90 "),
    ("##.##- ", [-68.95, 22.449, -7.01], "68.95- 22.45   7.01- "),
    ("**#.# ", [12.39, -0.9, 765.1], "*12.4 *-0.9 765.1 "),
    ("$$###.##", [456.78], " $456.78"),
    ("**$##.##", [2.34], "***$2.34"),
    ("####,.##", [1234.5], "1,234.50"),
    ("##.##", [111.22], "%111.22"),
    (".##", [0.999], "%1.00"),
    ("##.##^^^^", [234.56], " 2.35E+02"),
    (".####^^^^-", [888888.0], ".8889E+06 "),
    ("+.##^^^^", [123.0], "+.12E+03"),
    ("_!##.##_!", [12.34], "!12.34!"),
    ("!", ["Looking", "Out"], "LO"),
    ("\\  \\", ["Looking", "Out"], "LookOut "),
    ("&", ["Looking", "Out"], "LookingOut"),
]


@pytest.mark.parametrize("fmt, values, text", MANUAL_EXAMPLES)
def test_manual_examples(fmt, values, text):
    assert using(fmt, values) == text


@pytest.mark.parametrize(
    "fmt, values, text",
    [
        ("#####", [-1234.0], "-1234"),  # the minus takes a digit position
        ("####", [-1234.0], "%-1234"),
        ("#.##", [0.5], "0.50"),  # leading zero when there is room
        ("#.##", [-0.5], "-.50"),  # ... and not when the minus needs it
        ("##.##", [3.125], " 3.13"),  # exact halves round away from zero
        ("##.##", [-3.125], "-3.13"),
        ("##.##", [2.675], " 2.68"),  # the typed decimal, not the binary neighbour
        ("##.#", [-0.01], "-0.0"),  # a negative value keeps its sign when it rounds to zero
        ("###-", [-0.001], "  0-"),
        ("$$##.##", [-3.5], " -$3.50"),
        ("**$##.##", [-3.5], "**-$3.50"),
        ("$$.##", [0.5], " $.50"),  # no leading zero after a dollar sign
        ("#,###,###", [1234567.0], "1,234,567"),
        ("+###.#^^^^", [12.5], "+125.0E-01"),
        ("###.#^^^^", [12.5], " 12.5E+00"),
        ("##.##^^^^", [0.0], " 0.00E+00"),
        ("##^^^^", [0.0], "  E+00"),
        ("#^^^^", [2114.0], " E+04"),  # no mantissa digit: only the exponent
        ("##.##^^^^^", [12.5], " 1.25E+001"),  # five carets: three exponent digits
        ("##.##^^^^", [1.5e200], "%1.50E+200"),
        ("#.", [3.0], "3."),
        ("!", [""], " "),
        ("\\\\", ["abc"], "ab"),
        ("-##", [5.0], "- 5"),  # a leading minus is literal text
        ("##^^^", [5.0], " 5^^^"),  # three carets are literal text
        ("a_#b##", [5.0], "a#b 5"),
        ("ab_", [], "ab_"),
    ],
)
def test_field_rules(fmt, values, text):
    if values:
        assert using(fmt, values) == text
    else:
        with pytest.raises(BasicError):
            using(fmt, values)


def test_format_is_reused_and_output_stops_at_the_first_field_after_the_last_value():
    assert using("X##Y", [1.0, 2.0]) == "X 1YX 2Y"
    assert using("A##B##C", [1.0]) == "A 1B"
    assert using("A##B##C", [1.0, 2.0, 3.0]) == "A 1B 2CA 3B"


def test_point_after_decimals_starts_a_second_field():
    fields = [token for token in parse_format("###.###.##") if type(token).__name__ == "NumericField"]
    assert len(fields) == 2
    assert using("###.###.##", [1.5, 2.25]) == "  1.500%2.25"
    assert using("###.###.##", [1.5, 0.25]) == "  1.500.25"


@pytest.mark.parametrize(
    "fmt, value",
    [("##.##", "text"), ("!", 1.0), ("&", 2.5), ("\\  \\", -1.0)],
)
def test_wrong_kind_of_value_is_type_mismatch(fmt, value):
    with pytest.raises(BasicError) as caught:
        using(fmt, [value])
    assert caught.value.code == TYPE_MISMATCH
    assert str(caught.value) == "Type mismatch"


@pytest.mark.parametrize("fmt", ["", "abc", "+", "-", "$", "*", "_#", "\\ x\\"])
def test_format_without_a_field_is_illegal_function_call(fmt):
    with pytest.raises(BasicError) as caught:
        using(fmt, [1.0])
    assert caught.value.code == ILLEGAL_FUNCTION_CALL
    assert str(caught.value) == "Illegal function call"


# ---------------------------------------------------------------------------
# Properties (Hypothesis): any format, any value
# ---------------------------------------------------------------------------

from fractions import Fraction  # noqa: E402

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

FORMAT_CHARS = "#.,+-*$^!&\\ _AB%"
finite = st.floats(allow_nan=False, allow_infinity=False)


@settings(max_examples=300, deadline=None, derandomize=True, database=None)
@given(fmt=st.text(alphabet=FORMAT_CHARS, max_size=14),
       values=st.lists(st.one_of(finite, st.text(alphabet="ab ", max_size=4)), max_size=4))
def test_any_format_and_values_give_text_or_a_basic_error(fmt, values):
    try:
        text = using(fmt, values)
    except BasicError as err:
        assert err.code in (ILLEGAL_FUNCTION_CALL, TYPE_MISMATCH)
    else:
        assert isinstance(text, str) and "\n" not in text


def half_away_from_zero(value: Fraction, decimals: int) -> Fraction:
    """``value`` rounded to ``decimals`` places, halves away from zero (Fraction arithmetic)."""
    scaled = abs(value) * 10 ** decimals
    rounded = (scaled + Fraction(1, 2)).__floor__()
    return Fraction(rounded if value >= 0 else -rounded, 10 ** decimals)


@settings(max_examples=300, deadline=None, derandomize=True, database=None)
@given(x=st.floats(min_value=-1e12, max_value=1e12), positions=st.integers(1, 8), decimals=st.integers(0, 5),
       commas=st.booleans())
def test_fixed_field_shows_the_value_rounded_to_its_decimals(x, positions, decimals, commas):
    fmt = "#" * positions + ("," if commas else "") + "." + "#" * decimals
    text = using(fmt, [x])
    overflowed = text.startswith("%")
    assert overflowed or len(text) == len(fmt)
    shown = Fraction(text.lstrip("%").replace(",", "").strip())
    expected = half_away_from_zero(Fraction(repr(x)), decimals)
    assert shown == expected


@settings(max_examples=300, deadline=None, derandomize=True, database=None)
@given(x=finite)
def test_print_text_reads_back_within_ten_digits(x):
    text = number_to_text(x)
    assert text.endswith(" ") and text[0] in " -"
    mantissa = text.strip().lstrip("-").split("E")[0].replace(".", "").lstrip("0")
    assert len(mantissa) <= 10
    shown = Fraction(text.strip())  # exact: near 1.8E308 the rounded text is beyond the largest double
    assert abs(shown - Fraction(x)) <= abs(Fraction(x)) * Fraction(5, 10 ** 10) * (1 + Fraction(1, 10 ** 6))


def test_integers_and_integral_floats_print_alike():
    assert number_to_text(5) == number_to_text(5.0) == " 5 "
    assert number_to_text(-3) == "-3 "
    assert number_to_text(9999999999) == " 9999999999 "
    assert number_to_text(10000000000) == " 1E+10 "


@settings(max_examples=500, deadline=None, derandomize=True, database=None)
@given(x=st.floats(allow_nan=False, allow_infinity=False), decimals=st.integers(0, 30))
def test_fixed_digits_are_the_shortest_decimal_rounded_half_up_over_the_whole_range(x, decimals):
    """The digits of a plain float's fixed field, from 5E-324 to 1.8E308 and up to 30 places:
    the float's shortest decimal (its repr) rounded half away from zero in Fractions."""
    from yaseer.basic.arithmetic.formatting import _rounded_half_up

    whole, fraction = _rounded_half_up(x, decimals)
    assert whole.isdigit() and len(fraction) == decimals and (whole == "0" or whole[0] != "0")
    assert Fraction(whole + "." + fraction + "0") == abs(half_away_from_zero(Fraction(repr(x)), decimals))
