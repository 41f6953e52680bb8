"""``--dialect gw`` at run time against PC-BASIC 2.0.8: PRINT layout at 80 (and 40)
columns, RND/RANDOMIZE sequences, and syntax errors found where execution reaches
them.  Generated and seeded (``YASEER_DIFF_SEED``, ``YASEER_DIFF_CASES``), many
programs through one PC-BASIC session.

PC-BASIC's captured text holds logical lines (a row that wraps on its screen is not
broken in the text); yaseer writes one line per screen row, so PC-BASIC's lines are
cut into rows of the screen width before comparing (:func:`screen_rows`).

Kept differences, where GW-BASIC's source decides (docs/compatibility.md), are not
generated: ``TAB`` of a negative number (column 1 in GIO86.ASM ``TABER``; PC-BASIC
wraps it modulo the width).  Programs these tests once
failed on are kept in tests/corpus/gw/ with PC-BASIC's rows (run by
tests/test_differential_programs.py).
"""

from __future__ import annotations

import random
import pytest

from test_differential_support import base_seed, case_count, screen_rows, run_gw as gw

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def assert_generated_match(pc, generate, seed: int, count: int, width_of=lambda source: 80) -> None:
    """``count`` programs from ``generate(rng)`` print the same screen rows in both."""
    rng = random.Random(base_seed() + seed)
    programs = [generate(rng) for _ in range(case_count(count))]
    found = differing(pc, programs, width_of)
    assert not found, f"{len(found)} of {len(programs)} differ; first:\n" + "\n---\n".join(found[0])


def differing(pc, programs: list[str], width_of=lambda source: 80) -> list[tuple[str, str, str]]:
    out = []
    for source in programs:
        pc.statement("WIDTH 80")  # PC-BASIC keeps a WIDTH from one run to the next,
        pc.statement("ON ERROR GOTO 0")  # and ON ERROR's hold on Overflow (RUN resets both in GW-BASIC)
        theirs, ours = screen_rows(pc.program(source), width_of(source)), gw(source)
        if theirs != ours:
            out.append((source, theirs, ours))
    return out


# ---------------------------------------------------------------- PRINT layout

def print_item(rng: random.Random) -> tuple[str, bool]:
    """One PRINT item and whether it is a number (a number is never followed by a comma)."""
    kind = rng.random()
    if kind < 0.35:
        length = rng.choice([rng.randint(0, 12), rng.randint(0, 90)])
        return '"' + "".join(rng.choice("ABXYZ.-") for _ in range(length)) + '"', False
    if kind < 0.65:
        return str(rng.choice([rng.randint(0, 9), rng.randint(-999, 999), rng.randint(-999999, 999999)])), True
    if kind < 0.82:
        return f"TAB({rng.choice([rng.randint(1, 90), rng.randint(1, 250)])})", False
    return f"SPC({rng.choice([rng.randint(0, 20), rng.randint(0, 200)])})", False


def print_statement(rng: random.Random) -> str:
    parts = []
    for _ in range(rng.randint(1, 7)):
        item, number = print_item(rng)
        parts.append(item)
        separator = rng.choice([";", ";", ","]) if not number else rng.choice([";", ";,"])
        parts.append(separator)
    if rng.random() < 0.6:
        parts.pop()  # end without a separator: the line ends
    return "PRINT " + "".join(parts)


def layout_program(rng: random.Random) -> str:
    lines = ["WIDTH 40" if rng.random() < 0.2 else "WIDTH 80"]  # PC-BASIC keeps WIDTH from run to run
    lines += [print_statement(rng) for _ in range(rng.randint(1, 4))]
    lines.append('PRINT "."')
    return "\n".join(f"{10 * (k + 1)} {text}" for k, text in enumerate(lines)) + "\n"


def test_generated_print_layout_matches_pcbasic(pc):
    assert_generated_match(pc, layout_program, 11, 150, lambda source: 40 if "WIDTH 40" in source else 80)


# ---------------------------------------------------------------- RND and RANDOMIZE

def rnd_program(rng: random.Random) -> str:
    lines = []
    for _ in range(rng.randint(2, 8)):
        kind = rng.random()
        if kind < 0.45:
            argument = rng.choice(["", "(1)", "(7.5)", "(0)"])
            lines.append(f"PRINT INT(RND{argument} * 4096)")  # 12 bits: exact in single precision
        elif kind < 0.6:
            lines.append(f"PRINT INT(RND(-{rng.choice([1, 2, 3, 0.5, 7, 100, 12345, 0.1, 3.75])}) * 4096)")
        elif kind < 0.8:
            lines.append(f"RANDOMIZE {rng.choice([rng.randint(0, 32767), rng.randint(-32768, -1), rng.randint(32768, 99999)])}")
        elif kind < 0.9:
            lines.append(f"X = {rng.randint(-500, 500) / 4}: RANDOMIZE X")
        elif kind < 0.95:
            lines.append(f"X% = {rng.randint(-32768, 32767)}: RANDOMIZE X%")
        else:
            lines.append(f"D# = {rng.randint(-500, 500) / 8}: RANDOMIZE D#: RANDOMIZE 1.5#")
    return "\n".join(f"{10 * (k + 1)} {text}" for k, text in enumerate(lines)) + "\n"


def test_generated_rnd_sequences_match_pcbasic(pc):
    assert_generated_match(pc, rnd_program, 12, 150)


# ---------------------------------------------------------------- errors where execution reaches them

GOOD = ["PRINT {k}", "A = {k}: PRINT A", "PRINT {k};", "IF {k} > 2 THEN PRINT {k}"]
BAD = ["X =", "PRINT 1 +", "Y = 2 * (", "FOR I = 1 TO", "X = 5 Y", "PRINT (1", "Y = Y + * 2",
       "GOTO", ")", "X = -", "PRINT 1 2 +"]


def error_program(rng: random.Random) -> str:
    statements = [rng.choice(GOOD).format(k=rng.randint(0, 5)) for _ in range(rng.randint(0, 3))]
    bad = rng.choice(BAD)
    if rng.random() < 0.3:
        bad = f"IF {rng.randint(0, 5)} > 2 THEN PRINT 9: {bad}"
    statements.append(bad)
    if rng.random() < 0.3:
        statements.append("PRINT 99")
    return f"10 PRINT \"START\"\n20 {': '.join(statements)}\n30 PRINT \"NEXT LINE\"\n"


def test_generated_errors_where_execution_reaches_them_match_pcbasic(pc):
    assert_generated_match(pc, error_program, 13, 100)


# Statements the whole-line reading refuses in other ways: a reserved word as a variable
# (``NAME$``: the word, then a ``$`` no token starts with), brackets, stray operators, a
# bad THEN branch before a good ELSE.
BROKEN = ['NAME$ = ""', "NAME = 1", "PRINT$ = 1", "LEN$ = 2", "TO = 1", "CLS$ = \"A\"",
          "X = (1", "X = 1)", "X = *2", "X = [1]", "X == 1", "X = 1 2 3 @", "@", "A = 1 = ",
          "IF {k} > 2 THEN NAME$ = 1 ELSE PRINT {k}", "IF {k} > 2 THEN PRINT {k} ELSE END$ = 1"]


def broken_program(rng: random.Random) -> str:
    statements = [rng.choice(GOOD).format(k=rng.randint(0, 5)) for _ in range(rng.randint(1, 3))]
    statements.append(rng.choice(BROKEN).format(k=rng.randint(0, 5)))
    if rng.random() < 0.4:
        statements.append(rng.choice(["PRINT 99", "NAME$ = 2", "X = (", "PRINT 98;"]))
    handler = rng.random() < 0.3  # RESUME NEXT runs the statements after the bad one
    head = "5 ON ERROR GOTO 100\n" if handler else ""
    tail = "40 END\n100 PRINT \"ERR\"; ERR: RESUME NEXT\n" if handler else ""
    return f"{head}10 PRINT \"START\"\n20 {': '.join(statements)}\n30 PRINT \"NEXT LINE\"\n{tail}"


def test_generated_unscannable_statements_run_what_precedes_them_as_pcbasic(pc):
    assert_generated_match(pc, broken_program, 17, 120)


# ---------------------------------------------------------------- FOR bound to its NEXT

def loop_program(rng: random.Random) -> str:
    """Nested loops whose NEXTs may name the wrong variable, be missing, or be jumped to."""
    names = rng.sample("IJK", rng.randint(1, 3))
    lines, opened = [], []
    for name in names:
        lines.append(f"FOR {name} = 1 TO {rng.randint(0, 2)}")
        opened.append(name)
        if rng.random() < 0.5:
            lines.append(f"PRINT {name};")
    while opened:
        name = opened.pop()
        kind = rng.random()
        if kind < 0.6:
            lines.append(f"NEXT {name}")
        elif kind < 0.75:
            lines.append("NEXT")
        elif kind < 0.9:
            lines.append(f"NEXT {rng.choice('IJK')}")
        # else: no NEXT for this loop
    if rng.random() < 0.3 and len(lines) > 2:
        at = rng.randint(1, len(lines) - 1)
        lines.insert(at, f"IF I = 1 THEN {10 * (len(lines) + 1)}")
    lines.append('PRINT "END"')
    return "\n".join(f"{10 * (k + 1)} {text}" for k, text in enumerate(lines)) + "\n"


def test_generated_for_next_binding_matches_pcbasic(pc):
    assert_generated_match(pc, loop_program, 14, 150)


# ---------------------------------------------------------------- division by zero and overflow

FAILING = ["1/0", "-3/0", "0/0", "5\\0", "-5\\0", "7 MOD 0", "0^-1", "EXP(100)", "1E38*10", "-1E38*10",
           "2^200", "1E38+1E38", "A/B", "-A/B", "1#/0", "A*1E37", "(1/0)*0"]


def arithmetic_program(rng: random.Random) -> str:
    """Failing operations printed or stored, with or without ON ERROR (GW-BASIC goes on
    with the largest value after the message unless ON ERROR traps the error)."""
    lines = ["A = 30: B = 0"]
    if rng.random() < 0.3:
        lines.append("ON ERROR GOTO 900")
    for _ in range(rng.randint(1, 4)):
        expr = rng.choice(FAILING)
        if rng.random() < 0.5:
            lines.append(f'PRINT "X"; {expr}; "Y"')
        else:
            lines.append(f"Z = {expr}: PRINT Z")
    lines.append('PRINT "END"')
    lines.append("END")
    body = "\n".join(f"{10 * (k + 1)} {text}" for k, text in enumerate(lines))
    return body + '\n900 PRINT "ERR"; ERR; ERL: RESUME NEXT\n'


def test_generated_arithmetic_errors_match_pcbasic(pc):
    assert_generated_match(pc, arithmetic_program, 15, 150)
