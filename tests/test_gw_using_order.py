"""PRINT USING in gw evaluates each value when its field is reached.

GW-BASIC's PRINT USING loop (BIPRTU.ASM, PRINUS) evaluates the format first, then scans
it: literal characters are printed as they are met (OUTDO), and at each field FRMEVL
reads the next value of the list, the field is checked (24 digit positions) and printed,
and only then is the scan resumed.  So

* a value sees the fields before it: ``POS(0)`` counts them;
* a value's message (``Overflow``, ``Division by zero``: MATH1.ASM's OVFLS/DIV0S print it
  and go on) comes after the fields before it;
* an earlier field's error (Type mismatch, a field over 24 positions) stops the statement
  before a later value is evaluated, so the later value's message never appears;
* at the end of the format with values left the scan starts again at its beginning
  (REUSST), printing the literal text there before the next value is evaluated;
* what was printed stays when an error stops the statement; an ON ERROR handler goes on
  from that column.

PC-BASIC 2.0.8 agrees but for the last point of the reused format: it evaluates the
value before it prints the literal text that starts the format again; there the source
decides (test_a_reused_format_prints_its_leading_text_before_the_value).  PC-BASIC also
stops with the message of an Overflow or Division by zero whose value lands in a fixed
field (the value 1.7E+38 is too large for its fixed fields); ``^^^^`` fields, which it
fills, are used here.
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, basic_number, exact_single, random_format, \
    is_string_field, run_gw, run_yaseer
from test_gw_files import pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

AGREED = [
    # a later value's POS(0) counts the fields and the literal text printed before it
    '10 PRINT USING "a## b##"; 1; POS(0)\n',
    '10 A = 1: DEF FNA(X) = X + A\n20 PRINT USING "##_ "; FNA(1); FNA(2); POS(0)\n',
    '10 PRINT "xyz";\n20 PRINT USING "## ##"; POS(0); POS(0)\n',
    # a value's message after the fields before it
    '10 PRINT USING "##.##^^^^"; 1; 10^40; 3\n',
    '10 PRINT USING "##.##^^^^"; 1; 1/0; 3\n',
    '10 PRINT USING "&|##.##^^^^|"; "ab"; 1/0\n',
    # an earlier field's error before a later value is evaluated (no message)
    '10 PRINT USING "## ##.##^^^^"; "A"; 10^40\n',
    '10 PRINT USING "!##.##^^^^"; 1; 10^40\n',
    '10 PRINT USING "######################### ##.##^^^^"; 1; 10^40\n',
    '10 PRINT USING "x## y##.##^^^^"; 1; "A"; 10^40\n',
    # a later value's own error after the fields before it
    '10 DIM A(3): PRINT USING "x## y## z"; 1; A(11)\n',
    '10 PRINT USING "x## y## z"; 1; FNU(1)\n',
    # an ON ERROR handler goes on from the column the partly printed line reached
    '10 ON ERROR GOTO 100\n20 PRINT USING "x## y## z"; 1; FNU(2): PRINT "after"\n30 END\n'
    '100 PRINT "["; ERR; POS(0); "]": RESUME NEXT\n',
    '10 ON ERROR GOTO 100\n20 PRINT USING "x## y## z"; "A"; 2: PRINT "after"\n30 END\n'
    '100 PRINT "["; ERR; POS(0); "]": RESUME NEXT\n',
]


@pytest.mark.parametrize("source", AGREED)
def test_values_are_evaluated_field_by_field_as_pcbasic(pc, source):
    """Each program's screen (and error line) is PC-BASIC 2.0.8's."""
    assert run_gw(source) == pc.program(source)


def test_a_value_sees_the_fields_before_it():
    """The rule itself, without a reference program: ``POS(0)`` of the second value is one
    more than the length of the text printed before its field."""
    assert run_gw('10 PRINT USING "a## b##"; 1; POS(0)\n') == "a 1 b" + "%2d" % (len("a 1 b") + 1) + "\n"


def test_the_text_before_the_first_field_is_printed_before_its_value():
    """BIPRTU.ASM prints each literal character as the scan meets it (NEWUCH), then calls
    FRMEVL at the field: ``POS(0)`` as the first value sees ``ab``.  Source over PC-BASIC
    2.0.8, which evaluates the first value before it prints the text before the field
    (``ab 1``)."""
    assert run_gw('10 PRINT USING "ab##"; POS(0)\n') == "ab" + "%2d" % (len("ab") + 1) + "\n"


def test_a_reused_format_prints_its_leading_text_before_the_value():
    """At the end of the format with values left, BIPRTU.ASM prints the format's last
    character (REUSIN), starts again (REUSST) and prints the literal ``a`` (NEWUCH) before
    the numeric field calls FRMEVL: the third ``POS(0)`` sees that ``a``.  Source over
    PC-BASIC 2.0.8, which evaluates the value first (it prints ``a10``)."""
    before_third = "a 1 b 6 ca"
    expected = "a 1 b 6 " + "ca" + "%2d" % (len(before_third) + 1) + " b\n"
    assert run_gw('10 PRINT USING "a## b## c"; 1; POS(0); POS(0)\n') == expected


def test_division_by_zero_in_a_fixed_field_goes_on_as_the_source():
    """MATH1.ASM DIV0S prints its message and goes on with the largest number, also inside
    PRINT USING (FRMEVL is the same evaluator): the message after the first field, then
    ``$PUF``'s ``%`` and free format for the too-large value.  Source over PC-BASIC 2.0.8,
    which stops there with ``Division by zero in 10``."""
    assert run_gw('10 PRINT USING "##"; 1; 1/0; 3\n') == " 1Division by zero\n% 1.701412E+38 3\n"


def _values_case(rng: random.Random) -> tuple[str, str]:
    """A generated ``PRINT USING`` line whose later values cannot be evaluated all at once
    unseen: each is ``POS(0)`` or a value that reads it (``x + 0 * POS(0)``,
    ``"s" + LEFT$("", POS(0))``).  The first value does not read the column and there are
    at most as many values as fields: PC-BASIC evaluates the value of a scan's first field
    before it prints the text before that field, the source after (see
    test_the_text_before_the_first_field_is_printed_before_its_value).  Whole numbers
    (PC-BASIC's rounding of some fractions differs).  Returns (the statement, a PRINT
    that leaves the cursor somewhere before it)."""
    fmt, fields = random_format(rng)
    items = []
    for k, field in enumerate(fields[:rng.randint(1, len(fields))]):
        if is_string_field(field):
            text = "".join(rng.choice("abcXYZ019") for _ in range(rng.randint(0, 5)))
            items.append(f'"{text}"' + (' + LEFT$("", POS(0))' if k else ""))
        elif k and rng.random() < 0.5:
            items.append("POS(0)")
        else:
            items.append(str(rng.randint(-999, 999)) + (" + 0 * POS(0)" if k else ""))
    lead = rng.choice(["", 'PRINT "ab";: ', 'PRINT SPC(7);: '])
    return f'PRINT USING "{fmt}"; ' + "; ".join(items), lead


def test_generated_lines_see_their_own_fields_as_pcbasic(pc):
    """Generated lines (random formats, later values reading ``POS(0)``) print as PC-BASIC
    2.0.8 prints them (evaluating all values first shows the column the statement
    started in for each of them)."""
    rng = random.Random(base_seed() + 241)
    lines = []
    for k in range(40):
        statement, lead = _values_case(rng)
        lines.append(f"{10 * k + 10} {lead}{statement}\n")
    source = "".join(lines)
    theirs = pc.program(source)
    assert run_gw(source) == theirs
    assert len(theirs.splitlines()) == 40


def test_a_file_line_stops_at_the_first_failing_field(tmp_path):
    """PRINT #n, USING: the string for a numeric field is Type mismatch before the second
    value is evaluated, so its Overflow message never appears; a line that fits writes
    its first field before the second value's message is shown.  Both as PC-BASIC 2.0.8."""
    source = ('10 OPEN "O", #1, "OUT.TXT"\n'
              '20 PRINT #1, USING "## ##.##^^^^"; 2; 10^40\n'
              '30 PRINT #1, USING "## ##.##^^^^"; "A"; 10^40\n')
    theirs_dir, ours_dir = tmp_path / "pc", tmp_path / "ys"
    theirs_dir.mkdir()
    ours_dir.mkdir()
    theirs = pcbasic_run(source, theirs_dir)
    ours = yaseer_run(source, ours_dir)
    assert ours == theirs == "Overflow\nType mismatch in 30\n"
    assert (ours_dir / "OUT.TXT").read_bytes() == (theirs_dir / "OUT.TXT").read_bytes()


def test_casio_keeps_evaluating_the_list_first():
    """The Casio manual has no PRINT USING page: casio keeps yaseer's way, every value
    before the first field (``POS(0)`` sees the column the statement started in)."""
    ours = run_yaseer('10 PRINT "xyz";\n20 PRINT USING "## ##"; POS(0); POS(0)\n', dialect="casio")
    assert ours == "xyz 4  4\n"


def test_the_cursor_prints_what_the_whole_list_prints():
    """The field-by-field reading (formatting.UsingCursor) and the all-at-once one
    (formatting.using, the path of values that cannot fail) give the same text on
    generated formats and values, also with the format reused."""
    from test_differential_support import random_using_case

    from yaseer.basic.arithmetic import formatting

    rng = random.Random(base_seed() + 242)
    for _ in range(500):
        fmt, values = random_using_case(rng)
        cursor = formatting.UsingCursor(fmt, 24)
        text = cursor.literals(True)
        for k, value in enumerate(values):
            text += cursor.field(value) + cursor.literals(k < len(values) - 1)
        assert text == formatting.using(fmt, values, most_digits=24), (fmt, values)
