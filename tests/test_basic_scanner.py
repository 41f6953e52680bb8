"""The keyword-first scanner and the listing splitter."""

import pytest
from hypothesis import given, settings, strategies as st

from yaseer.basic.dialects.dialect import CASIO, GW
from yaseer.basic.errors import BasicError
from yaseer.basic.source.scanner import split_lines, tokenize


def kinds(text, dialect=CASIO):
    return [(t.type, t.value) for t in tokenize(text, dialect)]


def test_function_name_inside_a_run_of_letters_is_a_keyword():
    assert kinds("COST") == [("FUNC", "COS"), ("NAME", "T")]
    assert kinds("SINT") == [("FUNC", "SIN"), ("NAME", "T")]


def test_gosubprog_is_gosub_prog_number():
    assert kinds("GOSUBPROG1") == [("GOSUB", "GOSUB"), ("PROG", "PROG"), ("NUMBER", 1.0)]


def test_if_without_spaces():
    assert [t for t, _ in kinds("IFX<0THENT=T+180")] == [
        "IF", "NAME", "LT", "NUMBER", "THEN", "NAME", "EQ", "NAME", "PLUS", "NUMBER"]


def test_keywords_in_any_case_and_names_as_typed():
    # the FX-850P manual (part 6, Variable Names) lists A and a as two names
    assert kinds("print qq") == [("PRINT", "PRINT"), ("NAME", "qq")]
    assert kinds("print qq", GW) == [("PRINT", "PRINT"), ("NAME", "QQ")]  # GW-BASIC: one case


def test_names_with_digits_and_string_names():
    assert kinds("A1=B$") == [("NAME", "A1"), ("EQ", "="), ("STRNAME", "B$")]


def test_keyword_wins_inside_a_longer_name():
    # the pocket computers' tokenisers read TOTAL as TO TAL
    assert kinds("TOTAL") == [("TO", "TO"), ("NAME", "TAL")]
    assert kinds("INPUTX") == [("INPUT", "INPUT"), ("NAME", "X")]
    assert kinds("INTX") == [("FUNC", "INT"), ("NAME", "X")]


@pytest.mark.parametrize("text, value", [
    (".1", 0.1), ("360.1", 360.1), ("1E-3", 0.001), ("2.5E+2", 250.0), ("15", 15.0), ("7.", 7.0),
])
def test_numbers(text, value):
    assert kinds(text) == [("NUMBER", value)]


def test_division_by_negative_literal():
    assert kinds("1.25/-.85") == [("NUMBER", 1.25), ("SLASH", "/"), ("MINUS", "-"), ("NUMBER", 0.85)]


def test_exponent_needs_digits_else_keyword_follows():
    assert kinds("1ELSE") == [("NUMBER", 1.0), ("ELSE", "ELSE")]


def test_relational_pairs():
    assert [t for t, _ in kinds("<= =< >= => <> >< < > =")] == [
        "LE", "LE", "GE", "GE", "NE", "NE", "LT", "GT", "EQ"]


def test_string_literal_keeps_case_and_colons():
    assert kinds('PRINT "a: b"') == [("PRINT", "PRINT"), ("STRING", "a: b")]


def test_rem_and_apostrophe_swallow_the_rest():
    assert kinds("REM X: Y") == [("REMARK", " X: Y")]
    assert kinds("' note: x") == [("REMARK", " note: x")]
    # after a statement (no colon needed) the remark is dropped
    assert kinds("A=1 ' note: x") == [("NAME", "A"), ("EQ", "="), ("NUMBER", 1.0)]


def test_data_text_is_raw_up_to_colon_in_gw():
    assert kinds('DATA 1, "a:b", x : PRINT', GW) == [("DATA_TEXT", ' 1, "a:b", x '), ("_COLON", ":"),
                                                     ("PRINT", "PRINT")]


def test_casio_data_runs_to_the_end_of_its_line():
    # the FX-850P's own library (LIB5760) reads the items "a:edge", "r:inside" of one DATA line
    assert kinds('DATA a:edge,r:inside') == [("DATA_TEXT", " a:edge,r:inside")]


def test_casio_closes_the_parentheses_a_statement_leaves_open():
    # LIB5760 (the machine's Regular Polyhedron program): a(0)=SQR(ABS(a(3)/b):GOTO200
    assert kinds("A=SQR(ABS(B:GOTO 9") == kinds("A=SQR(ABS(B)):GOTO 9")
    assert kinds("PRINT (1+(2") == kinds("PRINT (1+(2))")


def test_question_mark_is_print():
    assert kinds("?1") == [("PRINT", "PRINT"), ("NUMBER", 1.0)]


def test_unknown_character_is_a_syntax_error():
    with pytest.raises(BasicError, match="Syntax error"):
        tokenize("A = 1 ` 2")  # (@ is a token: INPUT @n; and INPUT$(n, @))


def test_huge_literal_is_overflow():
    with pytest.raises(BasicError, match="Overflow"):
        tokenize("A = 1E999")


def test_unnumbered_physical_lines_continue_the_previous_line():
    text = ("20 FOR QQ = .1 TO 360.1 STEP 15: T(2) = QQ:\n"
            "L(2) = 75: GOSUB\n"
            "   PROG 1\n"
            "30 L(11) = SQR(1.5^2 +\n"
            " 5.5^2)\n")
    assert split_lines(text) == [
        (20, "FOR QQ = .1 TO 360.1 STEP 15: T(2) = QQ: L(2) = 75: GOSUB PROG 1", 0),
        (30, "L(11) = SQR(1.5^2 + 5.5^2)", 3),
    ]


def test_text_before_the_first_line_number_is_an_error():
    with pytest.raises(BasicError, match="Syntax error"):
        split_lines("PRINT 1\n10 END\n")


# --- LIST: a line as the pocket computer lists it ----------------------------------

from pathlib import Path  # noqa: E402

from yaseer.basic.source.scanner import detokenize  # noqa: E402

REPO = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("typed, listed", [
    ("L=X/COST", "L=X/COS T"),  # the two examples
    ("forj=1to3:printj;:nextj", "FOR j=1 TO 3:PRINT j;:NEXT j"),  # names keep their case
    ("IFX<0THEN100ELSE200", "IF X<0 THEN 100 ELSE 200"),
    ("GOSUBPROG1", "GOSUB PROG 1"),
    ('?"A";x', 'PRINT "A";x'),  # ? is PRINT
    ("FOR I=10 TO 1 STEP -1", "FOR I=10 TO 1 STEP -1"),
    ("printtab(5);sin(x);erl", "PRINT TAB(5);SIN(x);ERL"),
    ("DEF FNA(X)=X*2", "DEF FNA(X)=X*2"),
    ("x=1e3 ' Keep This", "x=1E3 ' Keep This"),  # numbers and remarks as typed
    ("rem Keep  This", "REM Keep  This"),
    ('data 1, "Two" ,3', 'DATA 1, "Two" ,3'),
    ("PRINT X@", "PRINT X@"),  # a line the scanner cannot read is listed as typed
])
def test_detokenize_lists_keywords_in_capitals_and_spaced(typed, listed):
    assert detokenize(typed) == listed


def _all_listing_lines():
    for path in sorted((REPO / "listings").glob("*.bas")) + [REPO / "programs" / "prog5.bas"]:
        for number, text, _ in split_lines(path.read_text()):
            yield pytest.param(text, id=f"{path.stem}:{number}")


@pytest.mark.parametrize("text", list(_all_listing_lines()))
def test_a_listed_line_reads_back_as_the_same_tokens(text):
    """LIST then typing the listed line back in changes nothing (every listing line)."""
    try:
        expected = kinds(text)
    except BasicError:
        pytest.skip("the line does not scan")
    assert kinds(detokenize(text)) == expected


_LINE_NUMBER_PATTERN = r"\s*(\d+)(?=[\sA-Za-z'?]|$)\s?"  # the reading a line's number is written after
_LINE_ALPHABET = st.sampled_from(list(" \t\x0b\x0c\x1c\x85\xa0\u2003\u3000" "0123456789" "\u0663\u0664\uff11\U0001d7d9"
                                      "AZaz'?.:+-\u00e9\u00c0\u00b2\u2155\u00bd\u216b\"\r\n"))


@settings(max_examples=3000, deadline=None, derandomize=True, database=None)
@given(st.text(alphabet=_LINE_ALPHABET, max_size=12))
def test_a_physical_lines_number_is_read_as_the_regular_expression_reads_it(physical):
    """scanner._line_number against re's match of the same reading: Unicode blanks and
    decimal digits (Arabic-Indic, full-width, mathematical), superscripts and fractions
    (digits to isdigit or isnumeric, not decimals), letters outside ASCII, the one blank skipped."""
    import re

    from yaseer.basic.source.scanner import _line_number

    match = re.match(_LINE_NUMBER_PATTERN, physical)
    assert _line_number(physical) == (match and (int(match.group(1)), match.end()))


@settings(max_examples=1000, deadline=None, derandomize=True, database=None)
@given(st.text(alphabet=st.sampled_from(list("1 0AB\r\n\x1c\x1d\x85\u2028")), max_size=30))
def test_a_listing_splits_into_lines_where_the_line_break_expression_splits_it(source):
    """Lines end at CR LF, then a lone CR or LF (re.split(r"\\r\\n|\\n|\\r")); codes 28-31, 133
    and U+2028 stay in their line: each numbered line and its physical index as re would cut them."""
    import re

    from yaseer.basic.source.scanner import DirectStatementInFile, split_lines

    physical = re.split(r"\r\n|\n|\r", source)
    expected = [(int(m.group(1)), line[m.end():].strip(), index) for index, line in enumerate(physical)
                if line.strip() and (m := re.match(_LINE_NUMBER_PATTERN, line))]
    try:
        got = split_lines(source, joins_unnumbered=False)
    except DirectStatementInFile as stopped:
        got = stopped.lines
        unnumbered = [index for index, line in enumerate(physical)
                      if line.strip() and not re.match(_LINE_NUMBER_PATTERN, line)]
        expected = [line for line in expected if line[2] < unnumbered[0]]
    assert got == expected


@settings(max_examples=3000, deadline=None, derandomize=True, database=None)
@given(st.text(alphabet=st.sampled_from(list("EDed+-.1290 \u0663\uff11\u00b2A")), max_size=70))
def test_a_line_may_overflow_where_the_expression_finds_an_exponent_or_thirty_digits(text):
    import re

    from yaseer.basic.source.scanner import _may_overflow

    assert _may_overflow(text) == bool(re.search(r"[EDed][+]?\d\d|\d{30}", text))


def test_thirty_digits_in_a_row_may_overflow_and_thirty_apart_do_not():
    from yaseer.basic.source.scanner import _may_overflow

    assert _may_overflow("PRINT " + "9" * 30) and _may_overflow("X=" + "\u0663" * 30 + "!")
    assert not _may_overflow("PRINT " + "9" * 29 + " " + "9" * 29) and not _may_overflow("9" * 29 + "." + "9")
    assert _may_overflow("A=1E+38") and _may_overflow("A=1d12") and not _may_overflow("A=1E+3: E+ 12: D+")


@settings(max_examples=4000, deadline=None, derandomize=True, database=None)
@given(st.text(alphabet=st.sampled_from(list("0159..EEDD++--%!#e\u0663\u00b2")), max_size=9))
def test_a_typed_numbers_parts_are_the_groups_of_the_expression(text):
    import re

    from yaseer.basic.source.scanner import _typed_number_parts

    match = re.fullmatch(r"(\d+\.?\d*|\.\d+)(?:([ED])([+-]?\d*)|([%!#]?))", text)
    assert _typed_number_parts(text) == (match and match.groups())


@settings(max_examples=400, deadline=None)
@given(st.text(alphabet="0123456789.E+-D !#%&A\u0663\u00b2", min_size=1, max_size=12), st.integers(0, 11))
def test_a_number_read_without_the_pattern_is_what_the_pattern_reads(text, start):
    """The casio scanner reads digits alone by hand (a cold start then imports no re): whatever
    the text, its value and end, or its error, are the pattern's (\\d as re reads it: any
    Unicode decimal digit)."""
    import re

    from yaseer.basic.source import scanner

    start = min(start, len(text) - 1)

    def by_pattern():
        match = re.compile(r"(\d+\.?\d*|\.\d+)(E[+-]?\d+)?").match(text, start)
        if match is None:
            return "Syntax error"
        value = float(match.group(0))
        return "Overflow" if value == float("inf") else (value, match.end())

    try:
        read = scanner._scan_number(text, start)
    except BasicError as error:
        read = str(error)
    assert read == by_pattern()


def test_a_long_run_of_digits_is_overflow_read_either_way():
    from yaseer.basic.source import scanner

    for text in ("9" * 400, "9" * 400 + ".5"):
        with pytest.raises(BasicError, match="Overflow"):
            scanner._scan_number(text, 0)
    assert scanner._scan_number("12 ", 0) == (12.0, 2) and scanner._scan_number("X12E1", 1) == (120.0, 5)
