"""PRINT #, PRINT # USING, WRITE #, INPUT #, LINE INPUT # and INPUT$ on a random file: they
write into and read from the file's record buffer (yaseer/basic/machine/random_files.py).

GW-BASIC's source: GIODSK.ASM ``DSKSOT`` and ``DSKSIN`` send a random file's bytes to and
from the buffer at its position ``FD_OPS``, each byte checking it first (``FOVCHK``: at the
record's length ``FIELD overflow``); ``DSKRND`` (GET and PUT) sets it back to 0 and leaves
the column ``F_POS`` alone; ``DSKSIN`` ends an item at a Ctrl-Z, after which GIO86.ASM
``INCHSI``/``INCEOF`` mark the file at its end (``EOF`` -1, the next item ``Input past
end``) until a GET reads the record again.

References: PC-BASIC 2.0.8 on whole programs (output and the bytes of the file), generated
from a seed and by hand, where it does what the source does; the source's rules, written
out here by hand, where PC-BASIC differs (each such test says so): PC-BASIC raises ``FIELD
overflow`` as soon as the record's last byte is written or read (the source: only for a byte
beyond it), keeps the buffer position over a PUT, reads zero bytes after a GET beyond the
file's end and goes on after a Ctrl-Z.
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count
from test_gw_files import contents, pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

# Shows S$ with its zero bytes as "~" and its CR and LF as "<" and "/".
SHOW = """\
1000 FOR K=1 TO LEN(S$): Z$=MID$(S$,K,1): IF Z$=CHR$(0) THEN Z$="~"
1005 IF Z$=CHR$(13) THEN Z$="<" ELSE IF Z$=CHR$(10) THEN Z$="/"
1010 PRINT Z$;: NEXT: PRINT "|";: RETURN
2000 PRINT "E"; ERR; ERL: RESUME NEXT
"""


def run_both(tmp_path, source: str, name: str = "x"):
    """(yaseer's output, PC-BASIC's output, yaseer's files, PC-BASIC's files)."""
    ours_dir, theirs_dir = tmp_path / f"ya-{name}", tmp_path / f"pc-{name}"
    ours_dir.mkdir()
    theirs_dir.mkdir()
    ours, theirs = yaseer_run(source, ours_dir), pcbasic_run(source, theirs_dir)
    return ours, theirs, contents(ours_dir), contents(theirs_dir)


def numbered(lines: list[str]) -> str:
    return "".join(f"{10 * (k + 1)} {text}\n" for k, text in enumerate(lines)) + SHOW


# -- generated programs against PC-BASIC

def random_text(rng: random.Random) -> str:
    return "".join(rng.choice("abcXYZ 09-.") for _ in range(rng.randint(0, 10)))


def random_number(rng: random.Random) -> str:
    # (fractions in eighths: a literal like 9.06 reads as another single in PC-BASIC, see
    # docs/compatibility.md, Single precision)
    return rng.choice([str(rng.randint(-999, 999)), str(rng.randint(-799, 799) / 8), str(rng.randint(0, 9))])


def print_items(rng: random.Random) -> tuple[str, int]:
    """A PRINT # list and the most bytes it can write.  A comma follows only a string."""
    text, most, after_string = "", 2, False
    for k in range(rng.randint(1, 4)):
        if k:
            separator = rng.choice([";", ",", ";"]) if after_string else ";"
            most += 14 if separator == "," else 0
            text += separator
        after_string = rng.random() < 0.5
        item = f'"{random_text(rng)}"' if after_string else random_number(rng)
        text += item
        most += len(item) + 2
    if rng.random() < 0.3:
        text += rng.choice([";", ","]) if after_string else ";"
        most += 14
    return text, most


def random_sequential_program(rng: random.Random) -> str:
    """FIELD, LSET/RSET, PRINT #, PRINT # USING, PUT, GET, INPUT #, LINE INPUT #,
    INPUT$ and the fielded variables, LOC, LOF, EOF shown (WRITE # fills the rest of the
    record with blanks, as PC-BASIC 2.0.8's does not: tests/test_gw_recorded_files.py).  The program keeps to what the
    source and PC-BASIC do alike (see the source tests below for the rest): what one buffer
    takes between two GETs stays well inside the record and its fields leave its last bytes
    zero (PC-BASIC's FIELD overflow comes a byte early); a PUT is followed by a GET
    (PC-BASIC's PUT keeps the buffer position); it reads only after a GET of a record that
    starts with printed text (not after one beyond the end; and PC-BASIC skips zero bytes
    and blanks alike, where a blank after zero bytes ends a number in the source), writes
    only before reading; EOF is shown only where no character can be waiting (the source's
    EOF is 0 while one waits, and its next read, after a GET too, starts with it)."""
    length = rng.choice([64, 96, 128])
    names = ["A$", "B$", "C$"][:rng.randint(1, 3)]
    widths = [rng.randint(3, min(60, (length - 16) // len(names))) for _ in names]
    opening = rng.choice([f'OPEN "R", #1, "R.DAT", {length}', f'OPEN "R.DAT" AS #1 LEN = {length}',
                          f'OPEN "R.DAT" FOR RANDOM AS 1 LEN={length}'])
    lines = ["ON ERROR GOTO 2000", opening, "FIELD #1, " + ", ".join(f"{w} AS {n}" for w, n in zip(widths, names))]
    written, reading = 0, False  # bytes the buffer took since the last GET; an input since
    text_first, records = False, {}  # the buffer starts with printed text; so does record r
    given_back = stale = False  # a character may wait; a GET came after that
    beyond = False  # the last GET was beyond the file's end
    fields = ": ".join(f"S$={n}: GOSUB 1000: PRINT" for n in names)
    for _ in range(rng.randint(6, 16)):
        kind = rng.random()
        if kind < 0.15:
            name = rng.choice(names)
            lines.append(f'{rng.choice(["LSET", "RSET"])} {name} = "{random_text(rng)}"')
            text_first = text_first and name != names[0]
            continue
        if kind < 0.45 and not reading:
            choice = rng.random()
            if choice < 0.6:
                text, most = print_items(rng)
                statement = f"PRINT #1, {text}"
            elif choice < 0.8:  # (WRITE # fills the record, PC-BASIC's does not: test_gw_recorded_files)
                items = [f'"{random_text(rng)}"' if rng.random() < 0.5 else random_number(rng)
                         for _ in range(rng.randint(1, 3))]
                statement, most = "PRINT #1, " + "; \",\"; ".join(items), sum(len(i) + 6 for i in items) + 2
            else:
                statement = f'PRINT #1, USING "##.## \\  \\"; {random_number(rng)}; "{random_text(rng)}"'
                most = 20
            if written + most < length - 24:
                lines.append(statement)
                text_first = text_first or written == 0
                written += most
            continue
        if kind < 0.6:
            record, other = rng.randint(1, 4), rng.randint(1, 4)
            if rng.random() < 0.6:
                lines.append(f"PUT #1, {record}: GET #1, {other}")
                records[record] = text_first
            else:
                lines.append(f"GET #1, {other}")
            written, reading, text_first = 0, False, records.get(other, False)
            beyond = other > max(records, default=0)
            stale = stale or given_back
        elif kind < 0.85 and text_first and not stale and not beyond:
            reading = True
            lines.append(statement := rng.choice([
                'INPUT #1, X$: PRINT "<"; X$; ">"',
                'INPUT #1, N: PRINT N',
                'INPUT #1, X$, N: PRINT "<"; X$; ">"; N',
                'LINE INPUT #1, X$: PRINT "<"; X$; ">"',
                'X$ = INPUT$(3, #1): PRINT "<"; X$; ">"',
            ]))
            given_back = "INPUT$" not in statement
        else:
            lines.append(f"PRINT LOC(1); LOF(1){'' if given_back else '; EOF(1)'}: {fields}")
    lines += [f"PRINT LOC(1); LOF(1): {fields}", "CLOSE", "END"]
    return numbered(lines)


def test_generated_programs_match_pcbasic(tmp_path):
    rng = random.Random(base_seed() + 24)
    for k in range(case_count(30)):
        source = random_sequential_program(rng)
        ours, theirs, our_files, their_files = run_both(tmp_path, source, str(k))
        assert ours == theirs, source
        assert our_files == their_files, source


# -- by hand, against PC-BASIC

BY_HAND = """\
5 ON ERROR GOTO 2000
10 OPEN "R", #1, "R.DAT", 40
20 FIELD #1, 10 AS A$, 30 AS B$
30 PRINT #1, "HELLO";: PRINT "[";A$;"]"
40 PRINT #1, 12, "X": S$ = A$ + B$: GOSUB 1000: PRINT
50 LSET A$ = "ab": PRINT #1, "c";: S$ = A$ + B$: GOSUB 1000: PRINT
60 PUT #1, 2: GET #1, 2: INPUT #1, C$, D$: PRINT "<";C$;"><";D$;">"; LOC(1); LOF(1); EOF(1)
70 GET #1, 2: LINE INPUT #1, E$: PRINT "<";E$;">": GET #1, 2: PRINT "<";INPUT$(5, #1);">"
80 GET #1, 1: PRINT #1, CHR$(34); "a,b"; CHR$(34); ","; -1.5; ","; 7: PRINT #1, USING "##.##_!&"; 3.14159; "yes"
90 S$ = A$ + B$: GOSUB 1000: PUT #1, 1: GET #1, 1: INPUT #1, F$, G, H, I$: PRINT F$; G; H; "<";I$;">"
100 WIDTH #1, 10: GET #1, 2: PRINT #1, "abcdefgh"; "ijk": S$ = A$: GOSUB 1000: PRINT
110 GET #1, 2: PRINT #1, "AB";: GET #1, 2: PRINT #1, TAB(5); "X";: S$ = A$: GOSUB 1000: PRINT
120 INPUT #1, J$: PRINT "<";J$;">": INPUT #1, K$
130 CLOSE: END
"""


def test_statements_by_hand_match_pcbasic(tmp_path):
    """The buffer as the FIELD variables see it after PRINT # (the variables share it), after
    LSET, PUT after PRINT #, GET then INPUT #, LINE INPUT #, INPUT$, PRINT # USING,
    WIDTH #, the column kept over a GET (TAB), reading zero bytes to the record's end."""
    ours, theirs, our_files, their_files = run_both(tmp_path, BY_HAND + SHOW)
    assert ours == theirs
    assert our_files == their_files
    assert ours.endswith("<X>\nE 50  120 \n")


# -- the source where PC-BASIC differs

def run(tmp_path, lines: list[str]) -> str:
    """Run ``lines`` (numbered from 20) after an ON ERROR that prints an error and goes on."""
    return yaseer_run(numbered(["ON ERROR GOTO 2000"] + lines + ["END"]), tmp_path)


def test_the_record_filled_to_its_last_byte_is_no_overflow(tmp_path):
    """GIODSK.ASM DSKSOT/DSKSIN call FOVCHK before each byte, which raises FIELD overflow only
    when the position already is the record length: writing or reading the last byte is no
    error (PC-BASIC 2.0.8 raises it there), the byte after it is, and the bytes before that
    byte are written."""
    assert run(tmp_path, ['OPEN "R", 1, "R.DAT", 8: FIELD 1, 8 AS A$', 'PRINT #1, "ABCDEF"',
                          "S$ = A$: GOSUB 1000: PRINT", 'PUT #1, 1: GET #1, 1: LINE INPUT #1, L$: PRINT L$',
                          'GET #1, 1: PRINT #1, "123456789";', "S$ = A$: GOSUB 1000: PRINT"]) \
        == "ABCDEF</|\nABCDEF\nE 50  60 \n12345678|\n"
    assert (tmp_path / "R.DAT").read_bytes() == b"ABCDEF\r\n"


def test_put_and_get_set_the_buffer_position_back(tmp_path):
    """GIODSK.ASM DSKRND clears FD_OPS for a PUT as for a GET: PRINT # after a PUT writes at
    the buffer's start (PC-BASIC 2.0.8 goes on where the last PRINT # stopped); the column
    (F_POS) stays, so TAB counts from where the text before the PUT ended."""
    assert run(tmp_path, ['OPEN "R", 1, "R.DAT", 16: FIELD 1, 16 AS A$', 'PRINT #1, "ABCDEF";: PUT #1',
                          'PRINT #1, "XY";: PUT #1: PRINT #1, TAB(11); "Q";: PUT #1',
                          "S$ = A$: GOSUB 1000: PRINT LOC(1)"]) == "  QDEF~~~~~~~~~~| 3 \n"
    assert (tmp_path / "R.DAT").read_bytes() == (b"ABCDEF" + bytes(10) + b"XYCDEF" + bytes(10)
                                                 + b"  QDEF" + bytes(10))


def test_input_after_a_get_beyond_the_end_is_field_overflow(tmp_path):
    """A GET beyond the file's end leaves EOF -1, but INPUT # still reads the buffer's zero
    bytes to the record's end: FIELD overflow, as a real GW-BASIC recorded it (PC-BASIC's
    FLDOVFL test) and PC-BASIC 2.0.8 does.  (The source, GIODSK.ASM $READS setting F_ORCT 0
    and GIO86.ASM INCHSI answering the end at once, would say Input past end.)"""
    assert run(tmp_path, ['OPEN "R", 1, "R.DAT", 16: GET #1, 3: PRINT EOF(1)', "INPUT #1, A$", 'PRINT "on"']) \
        == "-1 \nE 50  30 \non\n"


def test_a_ctrl_z_ends_the_input_and_the_file_until_the_next_get(tmp_path):
    """GIODSK.ASM DSKSIN: a Ctrl-Z is the end of the file for an input (an ASCII file's);
    GIO86.ASM INCEOF then marks the file at its end: the item ends there, EOF is -1, the
    next INPUT # is Input past end; a GET reads the record again (PC-BASIC 2.0.8 goes on
    after the Ctrl-Z and keeps EOF 0)."""
    assert run(tmp_path, ['OPEN "R", 1, "R.DAT", 32: FIELD 1, 32 AS A$',
                          'LSET A$ = "ab, cd" + CHR$(26) + "ef,gh": PUT #1, 1: GET #1, 1',
                          'INPUT #1, X$, Y$: PRINT X$; "|"; Y$; EOF(1)', "INPUT #1, Z$",
                          'GET #1, 1: PRINT EOF(1): LINE INPUT #1, Z$: PRINT Z$']) \
        == "ab|cd-1 \nE 62  50 \n 0 \nab, cd\n"


def test_a_character_given_back_is_read_first_even_after_a_get(tmp_path):
    """After a closing quote INPUT # reads on over blanks; a character that is neither a comma
    nor a CR is given back (GIO86.ASM BAKCHR keeps it in the file's block, FL_BKC): the next
    item starts with it, also after a GET, and EOF is 0 while it waits (GIO86.ASM EOF); after
    a GET beyond the end the item then reads on through the zero bytes to FIELD overflow (as
    a real GW-BASIC recorded a read after such a GET: tests/test_gw_random_beyond_end.py)."""
    assert run(tmp_path, ['OPEN "R", 1, "R.DAT", 16: FIELD 1, 16 AS A$',
                          'LSET A$ = CHR$(34) + "ab" + CHR$(34) + " x,": PUT #1, 1: GET #1, 1',
                          'INPUT #1, X$: PRINT X$', 'GET #1, 1: INPUT #1, Y$: PRINT Y$']) \
        == 'ab\nx"ab" x\n'
    assert run(tmp_path, ['OPEN "R", 1, "R.DAT", 16: FIELD 1, 16 AS A$',
                          'LSET A$ = "12 x": PUT #1, 1: GET #1, 1: INPUT #1, N: PRINT N',
                          'GET #1, 9: PRINT EOF(1): INPUT #1, V$: PRINT V$; EOF(1)']) \
        == " 12 \n 0 \nE 50  40 \n-1 \n"


def test_field_overflow_is_one_line_naming_the_line(tmp_path):
    assert run(tmp_path, ['OPEN "R", 1, "R.DAT", 4', 'PRINT #1, "ABCDE"']).endswith("E 50  30 \n")
    assert yaseer_run('10 OPEN "R", 1, "R.DAT", 4: PRINT #1, "ABCDE"\n', tmp_path) == "FIELD overflow in 10\n"
