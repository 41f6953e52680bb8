"""FRE as GW-BASIC reports it (yaseer/basic/machine/memory_model.py): the bytes of its
segment the program, its variables, arrays and strings leave, against PC-BASIC 2.0.8 (which
counts GW-BASIC's layout the same way) on programs whose every variable gets a value other
than 0 or "" from an expression, and on two of the classic workloads.  Where the model
differs (a literal of one character) is written in the module's docstring and
docs/compatibility.md; variables given 0 or "" and arrays used without DIM:
tests/test_gw_memory_making.py."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from test_differential_support import run_gw

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

PROGRAMS = [
    "10 PRINT FRE(0)\n", "10 PRINT FRE(0):REM ABCDEFGHIJ\n", "10 A=1: PRINT FRE(0)\n",
    "10 A=1: AB=1: ABC=2: PRINT FRE(0)\n", "10 A%=1: B#=2: PRINT FRE(0)\n", '10 C$="XYZ"+"": PRINT FRE(0)\n',
    "10 DIM A(100): PRINT FRE(0)\n", "10 DIM A%(100): PRINT FRE(0)\n", "10 DIM A$(100): PRINT FRE(0)\n",
    "10 DIM A(10,10): PRINT FRE(0)\n", '10 A$=STRING$(100,"X"): PRINT FRE(0); FRE("")\n',
    "10 PRINT FRE(0)\n20 PRINT FRE(0)\n", "10 GOSUB 20\n20 PRINT FRE(0): END\n",
    "10 FOR I=1 TO 1: PRINT FRE(0): NEXT\n", "10 DEF FNA(X)=X: PRINT FRE(0)\n", "10 PRINT FRE(A)\n",
    '10 GOTO 20\n20 X = 3.25: Y# = 1D+20: Z = 12345678: ON 1 GOTO 30\n30 PRINT FRE(0); CHR$(65); LEFT$("AB", 1)\n',
]
CLASSIC = Path(__file__).parent / "benchmarks" / "classic"


def with_fre_at_the_end(name: str) -> str:
    """A classic workload run once round its loop, printing FRE before its END."""
    text = (CLASSIC / f"{name}.bas").read_text()
    text = re.sub(r"(?m)^(\d+\s+)END\s*$", r"\1PRINT FRE(0): END", text)
    return re.sub(r"(FOR K=1 TO |FOR N=1 TO |IF K<)\d+", r"\g<1>1", text)


@pytest.mark.parametrize("source", PROGRAMS + [with_fre_at_the_end("ahl"), with_fre_at_the_end("bm7")])
def test_fre_as_pcbasic_counts_it(pc, source):
    pc.statement("ON ERROR GOTO 0")
    assert run_gw(source) == pc.program(source)


def test_fre_is_about_60000_and_falls_as_arrays_grow():
    free = [float(run_gw(f"10 DIM A({n}): PRINT FRE(0)\n")) for n in (1000, 2000, 3000)]
    assert 55000 < free[0] < 60300 and free[0] - free[1] == free[1] - free[2] == 4000


def _string_space_program(rng) -> str:
    """A program that fills GW's string space with array elements and garbage: each pass
    makes a string (STRING$, SPACE$, +, LEFT$, MID$, a copy, a string read back), now and
    then empties an element, and prints FRE(0) (garbage counted) and FRE("") (collected);
    an error prints its code, the pass and FRE(0)."""
    size = rng.randint(200, 600)
    makers = [f'STRING$({rng.randint(100, 255)}, "X")', f"SPACE$({rng.randint(100, 255)})",
              f'B$ + "{"Y" * rng.randint(1, 20)}"', "B$"]
    # (no LEFT$ or MID$ of a variable: PC-BASIC copies the variable's string first, which a
    # collection then keeps, where GW's EVAL hands the operation the variable's own string;
    # nor a + of a new string: GW's collection keeps both sides while it makes the sum (CAT
    # calls STRINI before FRETMP), PC-BASIC neither: tests/test_gw_string_temporaries.py)
    body = [f"A$(I) = {rng.choice(makers)}" for _ in range(rng.randint(1, 3))]
    if rng.random() < 0.6:
        body.append(f"IF I MOD {rng.randint(2, 7)} = 0 THEN A$(I \\ 3) = \"\"")
    if rng.random() < 0.5:
        body.append(f'T$ = STRING$({rng.randint(50, 255)}, "T")')  # garbage each pass
    every = rng.randint(5, 40)
    return "\n".join([
        f"10 DIM A$({size}): ON ERROR GOTO 900", f'20 B$ = STRING$({rng.randint(100, 255)}, "B")',
        f"30 FOR I = 1 TO {size}", "40 " + ": ".join(body),
        f'50 IF I MOD {every} = 0 THEN PRINT I; FRE(0);: IF I MOD {2 * every} = 0 THEN PRINT FRE("") ELSE PRINT',
        "60 NEXT", "70 PRINT FRE(0); FRE(\"\"): END", '900 PRINT "E"; ERR; I; FRE(0): END']) + "\n"


def test_string_space_fills_and_is_collected_as_pcbasic(pc):
    """Out of string space (14) where GW's string space has no room even after its garbage
    collection, at the same pass and with the same FRE(0), and FRE(0) with the garbage and
    FRE("") without it as PC-BASIC 2.0.8 reports them (BISTRS.ASM GETSPA, GARBAG, FRE)."""
    import random

    from test_differential_support import base_seed, case_count, gw_programs_differing

    rng = random.Random(base_seed() + 51)
    count = max(case_count() // 10, 12)
    bad, errors = gw_programs_differing(pc, lambda: _string_space_program(rng), count, "E 14", tail=200)
    assert not bad, f"{len(bad)} of {count} differ, e.g. {bad[:2]}"
    assert errors >= count // 5, errors  # the programs reach the limit, not only collect


def test_a_collection_keeps_no_copy_of_a_functions_variable_argument():
    """MID$(B$, 6) of a variable: GW's EVAL hands MID$ the variable's own string (no
    temporary copy), so the collection its GETSPA makes leaves no garbage (BISTRS.ASM GETSPA,
    GARBAG): FRE(0) after it is FRE("") less the variable X then made.  PC-BASIC 2.0.8 copies
    B$ first and keeps the copy: 195 bytes less (59445)."""
    source = ('10 B$=STRING$(195,"B"): DIM A$(2)\n20 FOR I=1 TO 10000: T$=SPACE$(100): IF FRE(0) < 190 THEN 40\n'
              '30 NEXT\n40 PRINT FRE(0): A$(1)=MID$(B$,6): PRINT FRE(0): X=FRE(""): PRINT FRE(0)\n')
    assert run_gw(source) == " 130 \n 59640 \n 59632 \n"


def test_strings_typed_at_input_take_string_space_as_pcbasic(tmp_path):
    """A string typed at INPUT or LINE INPUT is copied out of the keyboard buffer into the
    string space (GWMAIN.ASM LETCN6 copies a string whose bytes lie in BUF), so the answer a
    variable held before becomes garbage: FRE(0) counts it until FRE("") collects it.  (A
    string READ from DATA stays in the program text, LETCN6 does not copy it:
    test_literals_and_data_take_no_string_space_as_pcbasic.)"""
    import io
    import random

    import pcbasic

    from test_differential_support import base_seed, case_count
    from yaseer.basic.machine.machine import Machine

    rng = random.Random(base_seed() + 52)
    for _ in range(max(case_count() // 20, 6)):
        passes = rng.randint(3, 30)
        statement = rng.choice(["INPUT A$", "LINE INPUT B$", "INPUT A$, C$", "LINE INPUT B$: A$=B$+\"\""])
        every = rng.randint(1, 5)
        source = (f'10 FOR I = 1 TO {passes}: {statement}\n'
                  f'20 IF I MOD {every} = 0 THEN PRINT "F"; FRE(0)\n'
                  f'30 NEXT: PRINT "F"; FRE(0); FRE(""); FRE(0)\n40 DATA {"D" * rng.randint(1, 40)}\n')
        answers = ["".join(rng.choice("ABCXYZ ") for _ in range(rng.randint(0, 60))).strip() or "Q"
                   for _ in range(2 * passes)]
        if "A$, C$" in statement:
            answers = [f"{a},{b}" for a, b in zip(answers[::2], answers[1::2])] * 2
        session = pcbasic.Session(output_streams=None, input_streams=io.BytesIO("\r".join(answers).encode() + b"\r"))
        session.start()
        session.execute(source)
        theirs = [row for row in session.execute("RUN").replace("\r\n", "\n").split("\n") if row.startswith("F")]
        session.close()
        screen = io.StringIO()
        machine = Machine(screen=screen, dialect="gw", input_stream=io.StringIO("\n".join(answers) + "\n"))
        machine.load(source)
        machine.run()
        ours = [row for row in screen.getvalue().split("\n") if row.startswith("F")]
        assert ours == theirs, (source, answers)


def test_arrays_beyond_the_64_kb_segment_are_out_of_memory_as_pcbasic(pc):
    """An array that does not fit in GW-BASIC's segment with the program, the variables and
    their strings is Out of memory (7) and is not made; where the string space's garbage is
    in the way it is collected first (GWMAIN.ASM REASON, BISTRS.ASM GARBAG): generated
    programs against PC-BASIC 2.0.8's FRE(0) and errors."""
    import random

    from test_differential_support import base_seed, case_count

    rng = random.Random(base_seed() + 53)
    out_of_memory = 0
    for _ in range(max(case_count() // 5, 20)):
        kind = rng.choice(["", "%", "#", "$"])
        before = rng.choice(["", 'FOR I=1 TO 100: T$=STRING$(200,"x"): NEXT: ',
                             "DIM C$(100): FOR I=1 TO 100: C$(I)=SPACE$(100): NEXT: ", "X=1: Y#=2: "])
        source = (f"10 ON ERROR GOTO 100\n20 {before}PRINT FRE(0): DIM A{kind}({rng.randint(1000, 16000)}): PRINT FRE(0)\n"
                  f"30 DIM D({rng.randint(1, 9000)}): PRINT FRE(0): ERASE A{kind}: PRINT FRE(0): END\n"
                  '100 PRINT "E";ERR;ERL;FRE(0): END\n')
        pc.statement("ON ERROR GOTO 0")
        theirs = pc.program(source)
        out_of_memory += "E 7 " in theirs
        assert run_gw(source) == theirs, source
    assert out_of_memory >= 4, out_of_memory  # the programs reach the limit, not only use memory


def _programs_match_pcbasic(pc, make, seed: int) -> None:
    """Programs ``make(rng)`` (the generator seeded ``seed`` past the base seed) print in
    yaseer's gw what they print in PC-BASIC session ``pc``."""
    import random

    from test_differential_support import base_seed, case_count

    rng = random.Random(base_seed() + seed)
    for _ in range(max(case_count() // 5, 20)):
        source = make(rng)
        pc.statement("ON ERROR GOTO 0")
        assert run_gw(source) == pc.program(source), source


def _literal(rng) -> str:
    """A string literal of 2 to 30 characters."""
    return '"' + "".join(rng.choice("ABCXYZ ") for _ in range(rng.randint(2, 30))) + '"'


def _string_lines(rng, forms) -> list:
    """Lines 20 and 30 of a generated string program: 3 to 10 statements, each chosen from
    ``forms(v, w)`` (v, w: two of A$, B$, C$, D$), FRE(0) printed between the halves."""
    names = ["A$", "B$", "C$", "D$"]
    statements = [rng.choice(forms(rng.choice(names), rng.choice(names))) for _ in range(rng.randint(3, 10))]
    half = len(statements) // 2
    return ["20 " + ": ".join(statements[:half] or ["X = 1"]), "30 PRINT FRE(0): " + ": ".join(statements[half:])]


def _literal_program(rng) -> str:
    """Strings that stay in the program text (literals of two characters or more, DATA
    read, copies of either) mixed with made ones, in simple variables and an array's
    elements, FRE(0) and FRE("") printed between."""
    lines = _string_lines(rng, lambda v, w: [
        f"{v} = {_literal(rng)}", f"READ {v}", f"{v} = {w}", f"E$(I) = {v}", f"E$(I) = {_literal(rng)}", "READ E$(I)",
        f'{v} = STRING$({rng.randint(2, 40)}, "Q")', f"{v} = {w} + {_literal(rng)}", "I = I + 1", "PRINT FRE(0)",
        'PRINT FRE("")'])
    data = ", ".join(rng.choice(["ABCD", '"QU OTED"', "XY", "LONGER ITEM", '"Z,Z"', "12"]) for _ in range(12))
    return "\n".join([
        "10 DIM E$(20): I = 1: A$ = STRING$(2, 65): B$ = A$: C$ = A$: D$ = A$: PRINT FRE(0)", *lines,
        '40 PRINT FRE(0); FRE(""): PRINT A$; B$; C$; D$: END', f"50 DATA {data}"]) + "\n"


def test_literals_and_data_take_no_string_space_as_pcbasic(pc):
    """A string assigned from a literal or READ from DATA points into the program text and
    takes no string space, nor does a copy of such a variable (GWMAIN.ASM LETCN6 copies
    only a string in BUF, a file buffer or the string space); the string it replaces is
    garbage until a collection (FRE("") counts from then on): FRE(0) and FRE("") against
    PC-BASIC 2.0.8.  (A literal of one character is left out: the model counts it.)"""
    _programs_match_pcbasic(pc, _literal_program, 56)


def _empty_side_program(rng) -> str:
    """Sums with an empty side (a variable holding "", or the literal ""): the other side a
    literal of two characters or more, a made string, or a variable, stored in simple
    variables and an array's elements, FRE(0) and FRE("") printed between."""
    lines = _string_lines(rng, lambda v, w: [
        f"{v} = Z$ + {_literal(rng)}", f"{v} = {_literal(rng)} + Z$", f'{v} = {_literal(rng)} + ""', f"{v} = Z$ + {w}",
        f"{v} = {w} + Z$", f"E$(I) = Z$ + {_literal(rng)}", f"E$(I) = {v} + Z$", f"{v} = Z$ + Z$",
        f"{v} = {_literal(rng)}", f'{v} = STRING$({rng.randint(2, 40)}, "Q")', f"{v} = {w} + {_literal(rng)}",
        "I = I + 1", f'{v} = ""', "PRINT FRE(0)", 'PRINT FRE("")'])
    return "\n".join([
        f'10 DIM E$(20): I = 1: Z$ = "": A$ = Z$ + {_literal(rng)}: B$ = A$: C$ = "": D$ = "XY": PRINT FRE(0)',
        *lines, '40 PRINT FRE(0); FRE(""): PRINT A$; B$; C$; D$; E$(1); E$(2): END']) + "\n"


def test_a_sum_with_an_empty_side_is_a_new_string_as_pcbasic(pc):
    """``+`` makes a new string of both sides' characters even where one side is empty
    (BISTRS.ASM CAT: STRINI takes the summed length from the string space, MOVINS copies
    both in), so ``Z$ + "ABC"`` with Z$ empty takes 3 bytes of string space where the
    literal ``"ABC"`` takes none: FRE(0) and FRE("") against PC-BASIC 2.0.8."""
    _programs_match_pcbasic(pc, _empty_side_program, 57)


def _whole_part_program(rng) -> str:
    """LEFT$, RIGHT$ and MID$ asking for a whole string or more, of literals, variables
    holding a literal (in the program text), DATA and made strings, stored in simple
    variables and an array's elements, FRE(0) and FRE("") printed between."""
    def part(w: str) -> str:
        n = rng.randint(30, 255)
        return rng.choice([f"LEFT$({w}, {n})", f"RIGHT$({w}, {n})", f"MID$({w}, 1)", f"MID$({w}, 1, {n})",
                           f"LEFT$({w}, {rng.randint(1, 3)})", f"MID$({w}, 2)"])
    lines = _string_lines(rng, lambda v, w: [
        f"{v} = {part(w)}", f"{v} = {part(_literal(rng))}", f"E$(I) = {part(w)}", f"{v} = {_literal(rng)}",
        f"READ {v}", f"{v} = {w}", f"{v} = {w} + {_literal(rng)}", "I = I + 1", 'PRINT FRE("")'])
    data = ", ".join(rng.choice(["ABCD", '"QU OTED"', "XY", "LONGER ITEM"]) for _ in range(12))
    return "\n".join([
        f"10 DIM E$(20): I = 1: A$ = {_literal(rng)}: B$ = A$: C$ = STRING$(5, 66): D$ = A$: PRINT FRE(0)",
        *lines, '40 PRINT FRE(0); FRE(""): PRINT A$; B$; C$; D$; E$(1): END', f"50 DATA {data}"]) + "\n"


def test_a_whole_string_s_left_right_or_mid_is_a_new_string_as_pcbasic(pc):
    """LEFT$, RIGHT$ and MID$ make a new string even where they take all of one that stays
    in the program text (BISTRS.ASM LEFT$/RIGHT$/MID$ all reach GETSPA for the result), so
    ``LEFT$(A$, 10)`` with A$ = "ABCDEF" takes 6 bytes of string space: FRE(0) and FRE("")
    against PC-BASIC 2.0.8."""
    _programs_match_pcbasic(pc, _whole_part_program, 58)


def option_base_program(rng) -> str:
    """Arrays made with and without DIM, of each type and up to 3 dimensions, under OPTION
    BASE 0 or 1: the bytes each takes (FRE before and after) and its largest subscripts."""
    base = rng.choice((0, 1))
    lines = [f"OPTION BASE {base}"]
    for k in range(rng.randint(1, 4)):
        name = f"A{k}{rng.choice(('', '%', '#', '$'))}"
        ndim = rng.randint(1, 3)
        value = '""' if name.endswith("$") else "1"  # (a literal's bytes: see the literals test)
        if rng.random() < 0.5:
            sizes = [rng.randint(base, 6) for _ in range(ndim)]
            lines.append(f"X=FRE(0): DIM {name}({','.join(map(str, sizes))}): PRINT X-FRE(0)")
        else:
            sizes = [10] * ndim
            lines.append(f"X=FRE(0): {name}({','.join(['1'] * ndim)})={value}: PRINT X-FRE(0)")
        last = ",".join(map(str, sizes))
        lines.append(f"{name}({last})={value}: PRINT {name}({last})")
    lines.append(f"{name}({','.join(['11'] * ndim)})={value}")  # beyond the last: Subscript out of range
    return "".join(f"{10 * (k + 1)} {text}\n" for k, text in enumerate(lines))


def test_arrays_under_option_base_take_the_bytes_pcbasic_counts(pc):
    # under OPTION BASE 1 an array has one entry fewer a dimension (BIPTRG.ASM: 10 without DIM)
    import random

    from test_differential_support import base_seed, case_count, gw_programs_differing

    rng = random.Random(base_seed() + 41)
    bad, marked = gw_programs_differing(pc, lambda: option_base_program(rng), case_count(60), "Subscript out of range")
    assert not bad, bad[0]
    assert marked == case_count(60)
