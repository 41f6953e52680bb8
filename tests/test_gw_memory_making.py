"""Simple variables in GW-BASIC's 64 KB as PTRGET makes them (BIPTRG.ASM SMKVAR): a
variable exists from the statement that first names it as a target (LET, FOR, READ ...),
before that statement works out its value, whatever the value is, so ``F = FRE("")``
counts F and ``A = 0`` counts A; where a new variable does not fit (BLTU's REASON, after a
garbage collection) it is ``Out of memory`` (7) and is not made.  Generated programs with
variables given 0, "" and other values, strings, an array that leaves little room and
FRE(0)/FRE("") printed between, against PC-BASIC 2.0.8 (machine/memory_model.py,
compiler.made)."""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count, gw_programs_differing, run_gw

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

_NAMES = ["A", "B", "AB", "XY1", "LONGER", "Q%", "R%", "COUNT%", "D#", "BIG#", "S$", "T$", "NAM$", "K!", "P1!"]


def _statement(rng, names) -> str:
    name = rng.choice(names)
    string = name.endswith("$")
    value = rng.choice(['""', '"AB"', f'STRING$({rng.randint(1, 60)}, "x")', 'S$ + "Z"']) if string else \
        rng.choice(["0", "1", str(rng.randint(2, 999)), "FRE(0)", "-0"])
    return rng.choice([
        f"{name} = {value}", f"{name} = {value}", "PRINT FRE(0)", 'PRINT FRE("")', f"READ {name}",
        f'F = FRE("")', "PRINT F", "FOR I = 0 TO 0: NEXT" if not string else f"{name} = {name}",
        f"PRINT {name}", f"SWAP {name}, {name}",
    ])


def _program(rng) -> str:
    names = rng.sample(_NAMES, rng.randint(4, len(_NAMES)))
    lines = ["10 ON ERROR GOTO 900"]
    if rng.random() < 0.7:  # an array that leaves a few hundred bytes, so that variables run out
        lines.append(f"20 DIM Z(FRE(0) / 4 - {rng.randint(8, 40)}): PRINT FRE(0)")
    for k in range(rng.randint(2, 6)):
        lines.append(f"{30 + k} " + ": ".join(_statement(rng, names) for _ in range(rng.randint(2, 6))))
    lines += ['800 PRINT FRE(0); FRE(""): END', "850 DATA 00, 07, \"\", ABC, 00, 12, \"\", 00, 05, QQ, 00, 00, 03, \"\", 09",
              '900 PRINT "E"; ERR; ERL; FRE(0): END']
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def pc_reason():
    """PC-BASIC 2.0.8 with its room test made GW-BASIC's: REASON (BIMISC.ASM) refuses a new
    end of the variables only past FRETOP, so a variable that fits exactly (FRE = its
    bytes) is made, where PC-BASIC's ``check_free`` refuses it (``free <= size``)."""
    from pcbasic.basic.memory.memory import DataSegment

    from test_differential_support import PcBasic

    original = DataSegment.check_free

    def check_free(self, size, err):
        if self._get_free() < size:
            self._collect_garbage()
            if self._get_free() < size:
                from pcbasic.basic.base import error

                raise error.BASICError(err)

    DataSegment.check_free = check_free
    session = PcBasic()
    yield session
    session.close()
    DataSegment.check_free = original


def test_variables_are_made_and_counted_as_pcbasic(pc_reason):
    rng = random.Random(base_seed() + 71)
    count = max(case_count() // 3, 40)
    bad, out_of_memory = gw_programs_differing(pc_reason, lambda: _program(rng), count, "E 7 ")
    assert not bad, f"{len(bad)} of {count} differ, e.g. {bad[:2]}"
    assert out_of_memory >= count // 8, out_of_memory  # the programs reach the limit


@pytest.mark.parametrize("source, expected", [
    ('10 F = FRE(""): PRINT F\n', " 60272 \n"),  # the line 20 bytes, F (4 + 4) made before FRE runs
    ('10 A = 0: B$ = "": C% = 0: PRINT FRE(0)\n', " 60243 \n"),  # A 8, B$ 4 + 3, C% 4 + 2
    ("10 FOR I = 0 TO 0: NEXT: PRINT FRE(0)\n", " 60264 \n"),
    ("10 PRINT A: PRINT FRE(0): A = A: PRINT FRE(0)\n", " 0 \n 60267 \n 60259 \n"),  # reading makes none
])
def test_a_variable_holding_zero_is_counted_from_its_making(source, expected):
    """Values worked out from the layout (60300 less the line: link 2, number 2, tokens, 0;
    less 4 bytes of header and the value's bytes a variable; FRE's token 2 bytes) and as
    PC-BASIC 2.0.8 prints them."""
    assert run_gw(source) == expected


_ARRAYS = ["A(I)", "B(2, I)", "C%(I + 1)", "D$(I)", "E#(3)", "LONG(I, 1)"]


def _array_statement(rng) -> str:
    element = rng.choice(_ARRAYS)
    value = '"XY"' if "$" in element else rng.choice(["0", "I", "FRE(0)", str(rng.randint(2, 99))])
    return rng.choice([
        f"{element} = {value}", f"PRINT FRE(0); {element}; FRE(0)", "PRINT FRE(0)", 'PRINT FRE("")',
        f"IF I > {rng.randint(0, 3)} THEN {element} = {value}", f"X = FRE(0) + LEN(STR$({element}))" if "$" not in element
        else f"X = FRE(0) + LEN({element})", "I = I + 1", f"FOR J = 1 TO 2: PRINT FRE(0): {element} = {value}: NEXT",
        f"READ {element}" if "$" not in element else f"{element} = {value}", "PRINT X",
    ])


def _array_program(rng) -> str:
    lines = [f"{10 + k} " + ": ".join(_array_statement(rng) for _ in range(rng.randint(1, 5)))
             for k in range(rng.randint(1, 5))]
    if rng.random() < 0.4:  # a jump over a line: its arrays are not made
        lines.insert(0, f"5 GOTO {lines[0].split()[0]}")
        lines.insert(1, "6 " + ": ".join(_array_statement(rng) for _ in range(2)))
    return "\n".join(lines + ['800 PRINT FRE(0); FRE(""): END', "850 DATA 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12"]) + "\n"


def test_arrays_used_without_dim_are_made_where_they_are_first_used_as_pcbasic(pc):
    """An array used without DIM is made with 11 elements a dimension by the PTRGET of the
    statement that first evaluates it (BIPTRG.ASM ``NOTFDD``: not found and not a DIM, made
    with the default size, ``NOTDIM``), so FRE(0) printed before it, in the same statement
    or line, does not count it; generated programs against PC-BASIC 2.0.8."""
    rng = random.Random(base_seed() + 72)
    count = max(case_count() // 3, 40)
    bad, _ = gw_programs_differing(pc, lambda: _array_program(rng), count)
    assert not bad, f"{len(bad)} of {count} differ, e.g. {bad[:2]}"


def _many_variables_program(rng) -> str:
    """A long program that makes simple variables until the 64 KB run out: a few each line,
    a count of the lines passed, and an error handler printing ERR, ERL, the count and
    FRE(0)."""
    letters = "ABCDEGHJKLMNPQSUVWXYZ"  # (no F: FN starts a function)
    numbers = rng.sample(range(1, 9999), 4000)
    names = [f"{rng.choice(letters)}{n}{rng.choice(['', '', '%', '!', '#', '$'])}" for n in numbers]
    lines, k = ["10 ON ERROR GOTO 9000"], 0
    number = 20
    while k < len(names):
        step = rng.randint(1, 8)
        parts = [f'{name}={"" if not name.endswith("$") else chr(34) + "AB" + chr(34)}'
                 f'{rng.randint(0, 9) if not name.endswith("$") else ""}' for name in names[k:k + step]]
        lines.append(f"{number} " + ":".join(parts + ["C=C+1"]))
        k += step
        number += 1
    lines += ['8999 PRINT "DONE"; C: END', '9000 PRINT "E"; ERR; ERL; C; FRE(0): END']
    return "\n".join(lines) + "\n"


def test_a_program_that_makes_many_variables_runs_out_of_memory_as_pcbasic(pc_reason):
    """A new simple variable that does not fit is ``Out of memory`` at the statement that
    makes it (BIPTRG.ASM SMKVAR, MATH1.ASM BLTU, BIMISC.ASM REASON), here in a program
    that reads FRE; against PC-BASIC 2.0.8 with GW's room test."""
    rng = random.Random(base_seed() + 73)
    for _ in range(3):
        source = _many_variables_program(rng)
        pc_reason.statement("ON ERROR GOTO 0")
        theirs = pc_reason.program(source)
        assert "E 7 " in theirs
        assert run_gw(source) == theirs


_FUNCTIONS = ["FNA(X)", "FNB%(X, Y)", "FNC#(Q%)", "FNLONG(Z$, X)", "FNE", "FNS$(W$)", "FNT!(LONGER)"]


def _function_statement(rng) -> str:
    head = rng.choice(_FUNCTIONS)
    body = '"AB"' if "$" in head.split("(")[0] else str(rng.randint(0, 9))
    return rng.choice([
        f"DEF {head} = {body}", f"DEF {head} = {body}", f'S$ = STRING$({rng.randint(1, 40)}, "x")',
        f'T$ = S$ + "{"y" * rng.randint(1, 9)}"', "PRINT FRE(0)", 'PRINT FRE("")', f"X = {rng.randint(0, 3)}",
        f"Y = {rng.randint(0, 3)}", "PRINT X; Y",
    ])


def _function_program(rng) -> str:
    lines = ["10 ON ERROR GOTO 900", f"20 DIM Z(FRE(0) / 4 - {rng.randint(10, 45)}): PRINT FRE(0)",
             f'25 S$ = STRING$({rng.randint(1, 9)}, "s")']  # (a sum with "" is not a new string in yaseer)
    for k in range(rng.randint(2, 6)):
        lines.append(f"{30 + k} " + ": ".join(_function_statement(rng) for _ in range(rng.randint(1, 5))))
    lines += ['800 PRINT FRE(0); FRE(""): END', '900 PRINT "E"; ERR; ERL; FRE(0): END']
    return "\n".join(lines) + "\n"


def test_def_fn_makes_its_entry_and_its_parameters_as_pcbasic(pc_reason):
    """DEF FN makes a simple variable's entry of the function's type (GWEVAL.ASM DEF,
    GETFNM's PTRGT2) and then each parameter's variable that does not exist yet (SCNLIS's
    PTRGET), each taking its bytes from the room the strings leave: a DEF after a string
    was stored leaves that much less room to the next strings (Out of string space where
    it no longer fits) and one that does not fit is Out of memory; generated programs
    against PC-BASIC 2.0.8 with GW's room test."""
    rng = random.Random(base_seed() + 74)
    count = max(case_count() // 3, 40)
    bad, full = gw_programs_differing(pc_reason, lambda: _function_program(rng), count, "E 14 ")
    assert not bad, f"{len(bad)} of {count} differ, e.g. {bad[:2]}"
    assert full >= count // 10, full  # the programs reach the limit


def test_a_program_that_never_reads_fre_runs_out_of_memory_where_gw_does(pc_reason):
    """The same long programs with a handler that does not read FRE: every gw program
    checks a new variable where it is made (compiler.made: once a block's names are all
    made, its makings cost a local's test), so ``Out of memory`` comes at the statement
    where PC-BASIC 2.0.8 (with GW's room test) gives it, after as many lines."""
    rng = random.Random(base_seed() + 75)
    for _ in range(3):
        source = _many_variables_program(rng).replace("; FRE(0): END", ": END")
        assert "FRE" not in source
        pc_reason.statement("ON ERROR GOTO 0")
        theirs = pc_reason.program(source)
        assert "E 7 " in theirs
        assert run_gw(source) == theirs


def _loop_program(rng) -> str:
    """A loop whose statements make their variables on chosen passes (``IF K = 7 THEN AB
    = 1``, ``IF K > 3 ...``, every pass), and an array used without DIM, after a DIM that
    leaves a few hundred bytes: no FRE anywhere, ``Out of memory`` on the pass where a new
    one does not fit.  The loop: a line jumped back to, or FOR ... NEXT counting up to a
    constant or a variable, with a variable STEP, down, or with a variable of its own the
    body does not read (each a different native loop: loops.loop_mode)."""
    pool = ["A", "B", "AB", "XY1", "LONGER", "Q%", "R%", "COUNT%", "D#", "BIG#", "S$", "T$", "NAM$", "P1!",
            "W", "V2", "U%", "H#", "G$", "M1"]
    names = rng.sample(pool, rng.randint(5, len(pool)))
    passes = rng.randint(5, 40)
    body = []
    for name in names:
        value = '"AB"' if name.endswith("$") else rng.choice(["0", "1", "K", "K * 2"])
        test = rng.choice([f"K = {rng.randint(1, passes)}", f"K > {rng.randint(0, passes)}", "1"])
        body.append(f"IF {test} THEN {name} = {value}")
    body.append(rng.choice(["E(K MOD 10) = K", "E(1) = E(1) + 1", "C = C + 1"]))
    rng.shuffle(body)
    form = rng.choice(["goto", "for", "to n", "step s", "down", "count"])
    head = {"goto": "K = K + 1", "for": f"FOR K = 1 TO {passes}", "to n": "FOR K = 1 TO N",
            "step s": f"FOR K = 1 TO {passes} STEP S", "down": f"FOR K = {passes} TO 1 STEP -1",
            "count": "FOR J = 1 TO N: K = K + 1"}[form]
    tail = {"goto": f"IF K < {passes} THEN 30", "count": "NEXT J"}.get(form, "NEXT K")
    lines = ["10 ON ERROR GOTO 900", f"20 DIM Z({rng.randint(14920, 14990)}): K = 0: N = {passes}: S = 1",
             f"30 {head}", *(f"{31 + i} {text}" for i, text in enumerate(body)), f"{31 + len(body)} {tail}",
             f'800 PRINT "DONE"; K; {"; ".join(names[:4])}: END', '900 PRINT "E"; ERR; ERL; K: END']
    return "\n".join(lines) + "\n"


def test_a_loop_makes_its_variables_on_the_passes_gw_makes_them(pc_reason):
    """A block that loops back to its own start, or a native FOR loop, tests its makings
    while one is not made and runs its later passes without the tests
    (compiler._copies, loops.unchecked_passes): the pass and the
    statement where a new variable is ``Out of memory`` are PC-BASIC 2.0.8's (with GW's
    room test), in programs that never read FRE."""
    rng = random.Random(base_seed() + 76)
    count = max(case_count() // 4, 30)
    bad, out_of_memory = gw_programs_differing(pc_reason, lambda: _loop_program(rng), count, "E 7 ")
    assert not bad, f"{len(bad)} of {count} differ, e.g. {bad[:2]}"
    assert out_of_memory >= count // 3, out_of_memory  # the programs reach the limit
