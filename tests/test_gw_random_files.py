"""Random-access files (yaseer/basic/machine/random_files.py) against PC-BASIC 2.0.8: seeded
generated programs (OPEN in its three forms with a record length, FIELD, LSET, RSET,
PUT and GET with and without a record number, LOC, LOF, EOF, a field variable detached
by LET) print the same text and leave the same bytes in the same files; and the one
place where GW-BASIC's source decides against PC-BASIC: more FIELD bytes than a
record is ``FIELD overflow`` (DSKCOM.ASM ``FIELD`` jumps to ``DERFOV``; PC-BASIC 2.0.8
says nothing).
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count
from test_gw_files import contents, pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

# Prints S$ with its zero bytes as "~" (a record never written reads as zero bytes).
SHOW = """\
1000 FOR K=1 TO LEN(S$): Z$=MID$(S$,K,1): IF Z$=CHR$(0) THEN Z$="~"
1010 PRINT Z$;: NEXT: PRINT "|";: RETURN
"""


def random_text(rng: random.Random) -> str:
    return "".join(rng.choice("abcXYZ 09-") for _ in range(rng.randint(0, 14)))


def field_widths(rng: random.Random, count: int, length: int, least: int, most: int) -> list[int]:
    """``count`` random field widths of ``least`` to ``most`` bytes that fit a record of
    ``length`` bytes (each at most its share of what the ones before left)."""
    widths, left = [], length
    for _ in range(count):
        width = rng.randint(least, max(least, min(most, left // count)))
        widths.append(width)
        left -= width
    return widths


def random_file_program(rng: random.Random) -> str:
    length = rng.choice([8, 16, 20, 32, 128])
    names = ["A$", "B$", "C$", "D$"][:rng.randint(1, 4)]
    widths = field_widths(rng, len(names), length, 2, 12)
    opening = rng.choice([f'OPEN "R", #1, "R.DAT", {length}', f'OPEN "R.DAT" AS #1 LEN = {length}',
                          f'OPEN "R.DAT" FOR RANDOM AS 1 LEN={length}'])
    lines = [opening, "FIELD #1, " + ", ".join(f"{w} AS {n}" for w, n in zip(widths, names))]
    size = last = 0  # records in the file, the last one read or written
    for _ in range(rng.randint(4, 14)):
        kind = rng.random()
        name = rng.choice(names)
        if kind < 0.35:
            lines.append(f'{rng.choice(["LSET", "RSET"])} {name} = "{random_text(rng)}"')
        elif kind < 0.55:
            # PUT without a number after a GET beyond the end: the source's next record,
            # PC-BASIC's end of file (a known difference, not generated)
            record = rng.randint(1, 6) if rng.random() < 0.7 or last > size else None
            lines.append("PUT #1" + (f", {record}" if record else ""))
            last = record or last + 1
            size = max(size, last)
        elif kind < 0.75:
            record = rng.randint(1, 7) if rng.random() < 0.7 else None
            lines.append("GET #1" + (f", {record}" if record else ""))
            last = record or last + 1
        elif kind < 0.92:
            lines.append("PRINT LOC(1); LOF(1); EOF(1);: " + ": ".join(f"S$={n}: GOSUB 1000" for n in names)
                         + ": PRINT")
        elif kind < 0.96:
            lines.append(f'{name} = "{random_text(rng)}!"')  # detached from the buffer
        else:
            lines.append(f'Q$ = "{random_text(rng)}": {rng.choice(["LSET", "RSET"])} Q$ = "{random_text(rng)}": '
                         'S$ = Q$: GOSUB 1000: PRINT')
    lines += ["CLOSE", "END"]
    return "".join(f"{10 * (k + 1)} {text}\n" for k, text in enumerate(lines)) + SHOW


def programs_match_pcbasic(tmp_path, generate, seed: int, cases: int) -> None:
    """Each of ``cases`` programs ``generate(rng)`` prints what PC-BASIC 2.0.8 prints and
    leaves the same files."""
    rng = random.Random(base_seed() + seed)
    for k in range(case_count(cases)):
        source = generate(rng)
        theirs_dir, ours_dir = tmp_path / f"pc{k}", tmp_path / f"ya{k}"
        theirs_dir.mkdir()
        ours_dir.mkdir()
        assert yaseer_run(source, ours_dir) == pcbasic_run(source, theirs_dir), source
        assert contents(ours_dir) == contents(theirs_dir), source


def test_generated_random_file_programs_match_pcbasic(tmp_path):
    programs_match_pcbasic(tmp_path, random_file_program, 3, 25)


FIXED = """\
10 OPEN "R", #1, "R.DAT", 16
20 FIELD #1, 4 AS A$, 6 AS B$
30 LSET A$ = "ab": RSET B$ = "xyz"
40 PUT #1, 3: PRINT LOC(1); LOF(1); EOF(1)
50 LSET A$ = "toolongvalue": PUT #1: PRINT LOC(1); LOF(1)
60 GET #1, 3: PRINT "[";A$;"][";B$;"]"; LOC(1); EOF(1)
70 GET #1, 9: PRINT LOC(1); EOF(1); LEN(A$); ASC(A$)
80 C$ = "hello": LSET C$ = "ab": PRINT "[";C$;"]": RSET C$="x": PRINT "[";C$;"]"
90 A$ = "plain": GET #1, 3: PRINT "[";A$;"]": LSET A$="q": PUT #1,1: GET #1,1: PRINT "[";A$;"]"
100 CLOSE: OPEN "R.DAT" AS #2 LEN = 8: PRINT LOF(2): FIELD #2, 8 AS D$: GET #2, 7: PRINT "[";D$;"]"
110 OPEN "R.DAT" FOR RANDOM AS 3: PRINT LOF(3): RESET: OPEN "R.DAT" FOR INPUT AS 1: CLOSE
120 OPEN "R", 1, "R.DAT": FIELD 1, 128 AS E$: GET 1: PRINT LEN(E$); LOC(1): CLOSE
"""


def test_random_file_statements_match_pcbasic(tmp_path):
    theirs_dir, ours_dir = tmp_path / "pc", tmp_path / "ya"
    theirs_dir.mkdir()
    ours_dir.mkdir()
    assert yaseer_run(FIXED, ours_dir) == pcbasic_run(FIXED, theirs_dir)
    assert contents(ours_dir) == contents(theirs_dir)


@pytest.mark.parametrize("source, message", [
    ('10 OPEN "R", 1, "F", 16: FIELD #1, 9 AS A$, 8 AS B$', "FIELD overflow in 10"),  # the source: DERFOV
    ('10 OPEN "R", 1, "F", 0', "Illegal function call in 10"),
    ('10 OPEN "R", 1, "F", 16: GET #1, 0', "Bad record number in 10"),
    ('10 OPEN "R", 1, "F", 16: PUT #1, -1', "Bad record number in 10"),
    ('10 OPEN "R", 1, "F", 16: PUT #1, 40000', "Bad record number in 10"),  # DSKRND: signed
    ('10 OPEN "R", 1, "F", 16: PUT #1, 70000', "Overflow in 10"),  # ADRGET: 16 bits
    ('10 OPEN "O", 1, "F": FIELD #1, 2 AS A$', "Bad file mode in 10"),
    ('10 OPEN "O", 1, "F": GET #1', "Bad file mode in 10"),
    ('10 GET #2', "Bad file mode in 10"),  # not open: DERFNO, which is Bad file mode (GWDATA.ASM)
    ('10 OPEN "R", 1, "F", 16: FIELD #1, 2 AS A', "Type mismatch in 10"),
    ('10 OPEN "F" AS 1 SIZE 4', "Syntax error in 10"),
    # INPUT # reads the record buffer: its zero bytes are skipped to the record's end (GIODSK.ASM FOVCHK)
    ('10 OPEN "R", 1, "F": INPUT #1, A', "FIELD overflow in 10"),
])
def test_random_file_errors(tmp_path, source, message):
    assert yaseer_run(source + "\n", tmp_path).splitlines()[-1] == message


def test_a_field_overflow_keeps_the_fields_before_it(tmp_path):
    """DSKCOM.ASM FIELD checks the total after each width and variable and points the variable
    into the buffer before it reads the next: after ``FIELD overflow`` the variables before
    the one that did not fit keep their fields (PC-BASIC 2.0.8 reports no overflow)."""
    source = ('10 ON ERROR GOTO 100: OPEN "R", 1, "F", 16\n20 FIELD #1, 12 AS A$, 8 AS B$\n'
              '30 LSET A$ = "X": PRINT LEN(A$); LEN(B$): END\n100 PRINT ERR; ERL: RESUME NEXT\n')
    assert yaseer_run(source, tmp_path) == " 50  20 \n 12  0 \n"


def test_casio_has_no_random_file_words(tmp_path):
    assert yaseer_run('10 OPEN "R", 1, "F", 16: FIELD #1, 2 AS A$\n', tmp_path, "casio") \
        == "Unsupported word FIELD in 10\n"


def test_put_after_a_get_beyond_the_end_takes_the_next_record(tmp_path):
    """GIODSK.ASM DSKRND: GET and PUT without a number use the logical record + 1, also after
    a GET beyond the end (PC-BASIC 2.0.8 writes the PUT at the file's end: LOF 24)."""
    source = ('10 OPEN "R.DAT" AS #1 LEN = 8: FIELD #1, 2 AS A$: PUT #1, 2: GET #1: PRINT LOC(1); EOF(1)\n'
              '20 PUT #1: PRINT LOC(1); LOF(1)\n')
    assert yaseer_run(source, tmp_path) == " 3 -1 \n 4  32 \n"


def overlapping_fields_program(rng: random.Random) -> str:
    """FIELD statements laying variables over the same bytes in different widths, then LSET
    and RSET into some of them, each followed by every variable printed in brackets."""
    names = ["A$", "B$", "C$", "D$", "E$", "F$"]
    length = rng.randint(6, 16)
    lines = [f'10 OPEN "R", 1, "OVER.DAT", {length}']
    fields, number = [], 20
    for group in (names[:3], names[3:]):
        widths, room = [], length
        for name in group:
            width = rng.randint(0, min(room, 6))
            widths.append(f"{width} AS {name}")
            room -= width
        lines.append(f"{number} FIELD 1, {', '.join(widths)}")
        fields += group
        number += 10
    shown = ": ".join(f'PRINT "[";{name};"]";' for name in fields) + ": PRINT"
    for _ in range(4):
        word = rng.choice(["LSET", "RSET"])
        lines.append(f'{number} {word} {rng.choice(fields)} = "{random_text(rng)}": {shown}')
        number += 10
    lines.append(f"{number} PUT 1, 1: CLOSE")
    return "\n".join(lines) + "\n"


def test_fields_over_the_same_bytes_share_them(tmp_path):
    """DSKCOM.ASM FIELD points each variable into the buffer, so an LSET or RSET into one
    shows in every variable fielded over the same bytes; output and file against PC-BASIC 2.0.8."""
    programs_match_pcbasic(tmp_path, overlapping_fields_program, 24, 12)


def element_fields_program(rng: random.Random) -> str:
    """FIELD into array elements (DSKCOM.ASM FIELD finds each variable with PTRGET: an element
    as well, its array made with the default size where there is no DIM) mixed with scalars:
    LSET, RSET, PUT, GET, an element given another string (detached), ERASE and a new DIM
    of the array (its elements detached), SWAP with another variable or with F$, fielded
    nowhere (the fields go with the descriptors), each variable shown in brackets."""
    length = rng.choice([10, 16, 24])
    names = ["A$(1)", "A$(7)", "B$(2,1)", "B$(0,0)", "C$", "D$"]
    rng.shuffle(names)
    names = names[:rng.randint(2, 5)]
    lines = [f'OPEN "R", #1, "E.DAT", {length}', "DIM B$(2,1)"]
    widths = field_widths(rng, len(names), length, 1, 8)
    lines.append("FIELD #1, " + ", ".join(f"{w} AS {n}" for w, n in zip(widths, names)))
    if rng.random() < 0.3:  # a second FIELD over the first field's bytes
        names.append(rng.choice(["A$(3)", "B$(1,1)", "E$"]))
        lines.append(f"FIELD #1, {widths[0]} AS {names[-1]}")
    shown = ": ".join(f"S$={n}: GOSUB 1000" for n in dict.fromkeys(names)) + ": PRINT"
    statements = [  # (weight, the statement for a variable)
        (35, lambda name: f'{rng.choice(["LSET", "RSET"])} {name} = "{random_text(rng)}"'),
        (15, lambda name: f"PUT #1, {rng.randint(1, 4)}"),
        (15, lambda name: f"GET #1, {rng.randint(1, 5)}"),
        (20, lambda name: shown),
        (8, lambda name: f'{name} = "{random_text(rng)}!"'),  # detached from the buffer
        (7, lambda name: "ERASE B$: DIM B$(2,1)"),  # the elements fielded are gone with the array
        (12, lambda name: f"SWAP {name}, {rng.choice(names + ['F$'])}: {shown}: S$=F$: GOSUB 1000: PRINT"),
    ]
    for _ in range(rng.randint(5, 12)):
        make = rng.choices([make for _, make in statements], [weight for weight, _ in statements])[0]
        lines.append(make(rng.choice(names)))
    lines += [shown, "CLOSE", "END"]
    return "".join(f"{10 * (k + 1)} {text}\n" for k, text in enumerate(lines)) + SHOW


def test_fields_of_array_elements_match_pcbasic(tmp_path):
    """Array elements and scalars fielded together: output and file against PC-BASIC 2.0.8."""
    programs_match_pcbasic(tmp_path, element_fields_program, 41, 20)


SWAPPED = """\
10 OPEN "R", 1, "S.DAT", 8
20 FIELD #1, 5 AS A$, 3 AS B$
30 LSET A$ = "hello": LSET B$ = "xyz": SWAP A$, B$: PRINT A$; "|"; B$
40 LSET A$ = "QQ": RSET B$ = "w": PRINT A$; "|"; B$: PUT #1, 1
50 LSET A$ = "12345678": LSET B$ = "": PUT #1, 2: GET #1, 1: PRINT A$; "|"; B$
60 C$ = "free": SWAP A$, C$: LSET C$ = "abcdefgh": PRINT A$; "|"; B$; "|"; C$
70 GET #1, 2: PRINT A$; "|"; B$; "|"; C$
80 DIM D$(2): FIELD #1, 2 AS D$(1), 6 AS D$(2): LSET D$(1) = "mm": SWAP D$(1), B$: RSET B$ = "k"
90 PRINT D$(1); "|"; D$(2); "|"; B$: SWAP B$, B$: LSET B$ = "n": PRINT B$; "|"; D$(1): PUT #1, 3: CLOSE
"""


def test_swap_moves_the_fields_with_the_descriptors(tmp_path):
    """BIMISC.ASM SWAP exchanges the two string descriptors (VMOVE), and a fielded variable's
    descriptor points into the record buffer (DSKCOM.ASM FIELD): after SWAP A$, B$ the name
    A$ writes and reads B$'s old bytes, and one swapped with a variable fielded nowhere hands
    it its field.  PC-BASIC 2.0.8 does the same: output and file against it."""
    theirs_dir, ours_dir = tmp_path / "pc", tmp_path / "ya"
    theirs_dir.mkdir()
    ours_dir.mkdir()
    ours = yaseer_run(SWAPPED, ours_dir)
    assert ours == ("xyz|hello\nQQ |    w\nQQ |    w\nfree|    w|abc\nfree|     |123\n k   |   123| k\n"
                    "n |n    \n")
    assert ours == pcbasic_run(SWAPPED, theirs_dir)
    assert contents(ours_dir) == contents(theirs_dir)


ELEMENTS = """\
10 OPEN "R",#1,"R.DAT",10
20 DIM A$(2):FIELD #1,3 AS A$(1),7 AS A$(2)
30 LSET A$(2)="hello":PUT 1:GET 1,1:PRINT A$(2)
40 FIELD #1, 4 AS N$(10), 2 AS M$(1,2): RSET N$(10)="ab": LSET M$(1,2)="xyz": PUT 1, 2
50 GET 1, 2: PRINT "[";N$(10);"][";M$(1,2);"][";A$(1);"]"
"""


def test_field_into_array_elements(tmp_path):
    """The issue's example and arrays without DIM: PC-BASIC 2.0.8 prints ``hello`` and R.DAT
    starts with three zero bytes, then ``hello`` and two blanks."""
    theirs_dir, ours_dir = tmp_path / "pc", tmp_path / "ya"
    theirs_dir.mkdir()
    ours_dir.mkdir()
    assert yaseer_run(ELEMENTS, ours_dir) == pcbasic_run(ELEMENTS, theirs_dir)
    assert contents(ours_dir) == contents(theirs_dir)
    assert contents(ours_dir)["R.DAT"][:10] == b"\0\0\0hello  "


@pytest.mark.parametrize("source, message", [
    ('10 OPEN "R", 1, "F", 16: FIELD #1, 2 AS A$(11)', "Subscript out of range in 10"),
    ('10 OPEN "R", 1, "F", 16: FIELD #1, 2 AS A$(-1)', "Illegal function call in 10"),
    ('10 OPEN "R", 1, "F", 16: FIELD #1, 300 AS A$(11)', "Illegal function call in 10"),  # GTBYTC first
    ('10 OPEN "R", 1, "F", 16: FIELD #1, 17 AS A$(1)', "FIELD overflow in 10"),  # the source: DERFOV
    ('10 OPEN "R", 1, "F", 16: FIELD #1, 2 AS A(1)', "Type mismatch in 10"),
    ('10 OPTION BASE 1: OPEN "R", 1, "F", 16: FIELD #1, 2 AS A$(0)', "Subscript out of range in 10"),
])
def test_field_element_errors(tmp_path, source, message):
    """As PC-BASIC 2.0.8 reports them, FIELD overflow as the source (PC-BASIC says nothing);
    the width is read before the variable is found (DSKCOM.ASM FIELD calls GTBYTC, then
    PTRGET, then tests the record's room)."""
    assert yaseer_run(source + "\n", tmp_path).splitlines()[-1] == message


@pytest.mark.parametrize("source, message", [
    ("10 GET #3, 1", "Bad file mode"),  # not open
    ("10 PUT 2", "Bad file mode"),
    ("10 GET #4, 1", "Bad file mode"),  # beyond the three files: looked for all the same
    ("10 PUT #255", "Bad file mode"),
    ('10 OPEN "R", 1, "F", 16: GET #1: GET #2', "Bad file mode"),
    ("10 GET #0", "Bad file number"),  # GETNZB
    ("10 PUT #0.4, 1", "Bad file number"),
    ("10 GET #256", "Illegal function call"),  # GETBYT
    ("10 PUT #-1", "Illegal function call"),
    ("10 GET #32768", "Overflow"),  # GETBYT's FRCINT
    ("10 FIELD #-32769, 2 AS A$", "Overflow"),
    ("10 PRINT INPUT$(1, #5)", "Bad file mode"),  # DSKCOM.ASM FIXINP: FILSCN, DERFNO
    ("10 PRINT INPUT$(1, #0)", "Bad file number"),
])
def test_get_put_input_chars_of_a_file_not_open(tmp_path, source, message):
    """GET and PUT find their file as GIO86.ASM DPUTG does (POFNUM: GETBYT, 0 ``Bad file
    number``; FDBPTR finds no open file: DERFNO, which GWDATA.ASM maps to ``Bad file mode``),
    INPUT$ as DSKCOM.ASM FIXINP; PC-BASIC 2.0.8 says the same."""
    theirs_dir, ours_dir = tmp_path / "pc", tmp_path / "ya"
    theirs_dir.mkdir()
    ours_dir.mkdir()
    ours = yaseer_run(source + "\n", ours_dir)
    assert ours == f"{message} in 10\n"
    assert ours == pcbasic_run(source + "\n", theirs_dir)
