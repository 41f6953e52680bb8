"""A string holds at most the dialect's ``string_length`` characters (255 in both: GW-BASIC's
string descriptor keeps the length in one byte; the Casio manual, part 6, "string variables
(up to 255 characters)", ST error) wherever a program gets it: a literal, DATA, INPUT, LINE
INPUT and ``+`` give ``String too long`` (15; casio's ST is 3) for one more character; 255
exactly is kept whole.  INPUT # and LINE INPUT # read at most 255 characters into one string
and leave the rest for the next read (GW-BASIC's 255-byte field buffer, as PC-BASIC 2.0.8
splits a longer line or field)."""

from __future__ import annotations

import pytest

import yaseer
from yaseer.basic.dialects.dialect import CASIO, GW


def sources(length: int) -> list[tuple[str, str, str | None]]:
    """(what, listing, INPUT answers) giving A$ a string of ``length`` characters."""
    text = "Q" * length
    return [
        ("literal", f'10 A$ = "{text}"\n', None),
        ("PRINT literal", f'10 PRINT "{text}";: A$ = "{text}"\n', None),
        ("DATA", f"10 READ A$\n5 DATA {text}\n", None),
        ("quoted DATA", f'10 READ A$\n5 DATA "{text}"\n', None),
        ("INPUT", "10 INPUT A$\n", text),
        ("LINE INPUT", "10 LINE INPUT A$\n", text),
        ("+", f'10 B$ = "{text[:200]}": A$ = B$ + "{text[200:]}"\n', None),
    ]


def run(listing: str, answers, dialect: str) -> yaseer.Result:
    return yaseer.run(listing + "20 PRINT LEN(A$)\n", input=answers, dialect=dialect)


def test_both_dialects_hold_strings_to_255_characters():
    assert CASIO.string_length == GW.string_length == 255


@pytest.mark.parametrize("dialect", ["casio", "gw"])
@pytest.mark.parametrize("index", range(7))
def test_one_character_too_many_is_string_too_long(index, dialect):
    what, listing, answers = sources(256)[index]
    result = run(listing, answers, dialect)
    where = 5 if "DATA" in what else 10  # a READ's error names the DATA line, as PC-BASIC 2.0.8 does
    assert result.error == f"String too long in {where}", what


@pytest.mark.parametrize("dialect", ["casio", "gw"])
@pytest.mark.parametrize("index", range(7))
def test_255_characters_are_kept_whole(index, dialect):
    what, listing, answers = sources(255)[index]
    result = run(listing, answers, dialect)
    assert result.error is None and result.text.endswith(" 255 \n"), (what, result.error)


def test_a_longer_limit_in_the_dialect_is_the_limit_everywhere():
    """The number comes from the dialect object: a variant holding 300 takes 300."""
    from yaseer.basic.machine.machine import Machine
    import io

    for listing, answers in (('10 A$ = "' + "Z" * 300 + '"\n', None), ("10 READ A$\n5 DATA " + "Z" * 300 + "\n", None),
                             ("10 LINE INPUT A$\n", "Z" * 300), ('10 A$ = STRING$(200, "Z") + STRING$(100, "Z")\n', None)):
        screen = io.StringIO()
        machine = Machine(screen=screen, dialect=GW._replace(string_length=300), input_stream=io.StringIO(answers or ""))
        machine.load(listing + "20 PRINT LEN(A$)\n")
        machine.run()
        assert screen.getvalue().endswith(" 300 \n"), listing


@pytest.mark.parametrize("dialect", ["casio", "gw"])
def test_file_reads_split_a_longer_line_or_field_at_255(tmp_path, dialect):
    # reference: PC-BASIC 2.0.8 reads these files so (255, then the other 45 characters; a
    # quoted field's rest runs to the comma, its closing quote included)
    (tmp_path / "L.TXT").write_bytes(b"Q" * 300 + b"\r\n")
    (tmp_path / "F.TXT").write_bytes(b'"' + b"R" * 300 + b'",5\r\n' + b"S" * 300 + b",7\r\n")
    program = ('10 OPEN "I", 1, "L.TXT": LINE INPUT #1, A$: LINE INPUT #1, B$: CLOSE: PRINT LEN(A$); LEN(B$)\n'
               '20 OPEN "I", 1, "F.TXT": INPUT #1, A$, B$, N, C$, D$, M: PRINT LEN(A$); LEN(B$); RIGHT$(B$, 2); N\n'
               '30 PRINT LEN(C$); LEN(D$); M\n')
    result = yaseer.run(program, files=tmp_path, dialect=dialect)
    assert (result.error, result.text) == (None, ' 255  45 \n 255  46 R" 5 \n 255  45  7 \n')


def test_the_error_is_trapped_as_15_in_gw_and_3_on_the_casio():
    program = f'10 ON ERROR GOTO 100\n20 A$ = "{"Q" * 300}"\n30 PRINT "on"; LEN(A$): END\n100 PRINT ERR; ERL: RESUME NEXT\n'
    assert yaseer.run(program, dialect="gw").text == " 15  20 \non 0 \n"
    assert yaseer.run(program, dialect="casio").text == " 3  20 \non 0 \n"
