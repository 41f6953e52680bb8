"""``--dialect gw`` against PC-BASIC 2.0.8 where GW-BASIC's operators and number types
decide what a program prints: AND and OR evaluate both sides (an RND on the right is
drawn whatever the left gives), a single holding a whole number of 1E7 or more
prints as a single.  Generated and seeded (``YASEER_DIFF_SEED``, ``YASEER_DIFF_CASES``).
"""

from __future__ import annotations

import random

import pytest

from test_differential_gw_runtime import assert_generated_match

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


# ---------------------------------------------------------------- AND and OR

def relation(rng: random.Random) -> str:
    """A relation that may draw RND, read an array element or divide."""
    left = rng.choice(["RND(1)", "RND", "A", "B", "A(I)", "1", "0", "X / Y", "A + 1"])
    return f"{left} {rng.choice(['<', '>', '=', '<>', '<=', '>='])} {rng.choice(['.5', '0', '1', 'A', 'RND(1)'])}"


def condition(rng: random.Random, depth: int = 0) -> str:
    if depth > 1 or rng.random() < 0.4:
        text = relation(rng)
    else:
        text = f"{condition(rng, depth + 1)} {rng.choice(['AND', 'OR'])} {condition(rng, depth + 1)}"
        if rng.random() < 0.3:
            text = f"({text})"
    return f"NOT ({text})" if rng.random() < 0.15 else text


def and_or_program(rng: random.Random) -> str:
    lines = [f"DIM A(3): A = {rng.randint(0, 1)}: B = {rng.random():.2f}: I = {rng.randint(0, 4)}: "
             f"X = 1: Y = {rng.choice([0, 2])}"]
    for _ in range(rng.randint(1, 4)):
        kind = rng.random()
        if kind < 0.6:
            lines.append(f'IF {condition(rng)} THEN PRINT "T"; ELSE PRINT "F";')
        elif kind < 0.8:
            lines.append(f"Z = {condition(rng)}: PRINT Z;")
        else:
            lines.append(f'K = 0: WHILE K < 2 AND ({condition(rng)}): K = K + 1: WEND: PRINT "W"; K;')
        lines.append("PRINT INT(RND * 1000)")
    return "\n".join(f"{10 * (k + 1)} {text}" for k, text in enumerate(lines)) + "\n"


def test_and_or_evaluate_both_sides_as_pcbasic(pc):
    assert_generated_match(pc, and_or_program, 41, 80)


# ---------------------------------------------------------------- whole singles of 1E7 and more

def whole_single_program(rng: random.Random) -> str:
    n = rng.choice([rng.randint(9_999_990, 10_000_010), rng.randint(1, 2 ** 24), 2 ** rng.randint(20, 30)])
    half = n // 2
    routes = [
        f"A = {n}: PRINT A",
        f"A = {half}: A = A + A: PRINT A; STR$(A)",
        f"A% = {min(half, 32767)}: A = A% * {rng.randint(300, 1000)}: PRINT A",
        f"A = 1: FOR I = 1 TO {rng.randint(20, 30)}: A = A + A: NEXT: PRINT A",
        f"FOR I = {min(n, 2 ** 24 - 3)} TO {min(n, 2 ** 24 - 3) + 2}: PRINT I;: NEXT: PRINT",  # +1 stays exact
        f"DEF FNA(X) = {n}: PRINT FNA(0)",
        f"A# = {n}: PRINT A#: B = A#: PRINT B",
    ]
    lines = rng.sample(routes, rng.randint(1, 3))
    return "\n".join(f"{10 * (k + 1)} {text}" for k, text in enumerate(lines)) + "\n"


def test_whole_singles_print_as_pcbasic(pc):
    assert_generated_match(pc, whole_single_program, 42, 80)


# ---------------------------------------------------------------- INPUT of a number without digits

def test_input_of_a_sign_point_or_exponent_alone_is_zero():
    """GW's number reader ($FIN) takes ``D``, ``E``, ``-D``, ``.`` whole as the number 0
    (D and E start an exponent); what cannot continue a number still asks again."""
    from test_gw_language import with_answers

    answers = ["D", "E", "-D", "+E", ".", "-", "E+", "1D-", "-.", "e", "ED", "1E2E"] + ["7"] * 4
    program = f"10 FOR I=1 TO {len(answers) - 4}\n20 INPUT A\n30 PRINT A\n40 NEXT\n"
    ours, theirs = with_answers(program, answers, "gw")
    assert ours == theirs
    assert ours.count("?Redo from start") == 2


def test_input_of_an_exponent_without_a_mantissa_is_zero():
    """``D5`` is 0 times 10^5 to GW's $FIN (PC-BASIC reads 1.469368E-34 there)."""
    from test_gw_language import with_answers

    ours, _ = with_answers("10 INPUT A, B\n20 PRINT A; B\n", ["D5, e-2"], "gw")
    assert ours.endswith(" 0  0 \n")


# ---------------------------------------------------------------- what GW's evaluator lets through

EVALUATED_AS_GW = [
    '10 PRINT ABS("ABC"); LEN(ABS("ABCD")); -"Q"; +"R"\n',  # $VABS, $VNEG leave a string as it is
    '10 A$ = "X": PRINT -A$: B$ = -A$ + "Y": PRINT B$; LEN(-B$)\n',
    # INT of a string is the string (MATH1.ASM $VINT; the INT test recorded on real GW-BASIC
    # in PC-BASIC's suite prints it); SGN tests the type (VSIGN: TMERR), and so do FIX and CINT
    '10 PRINT INT("ABC"); LEN(INT("ABCD")): A$ = INT("Q") + "R": PRINT A$\n',
    '10 ON ERROR GOTO 100\n20 PRINT SGN("A")\n30 PRINT FIX("A")\n40 PRINT CINT("A"): END\n100 PRINT ERR; ERL: RESUME NEXT\n',
    '10 PRINT POS("A"): PRINT "XYZ"; POS(A$)\n',  # POS's argument is a dummy of any type
    '10 PRINT ABS(-3); -(-2); ABS(-2.5#); -ABS(-4)\n',
    '10 A = -"X"\n',  # a string where a number must be: Type mismatch
    '10 PRINT .: A = .: PRINT A; .#; -.; . + 1; .5\n',  # a lone point is the number 0
    '10 PRINT 1 + .: PRINT ., .5: A.B = 3: PRINT A.B\n',
    '10 OPTION BASE 1: DIM A(1), B(3, 0)\n',  # a dimension without an element
    '10 OPTION BASE 1: DIM A(1): A(1) = 5: PRINT A(1): DIM C(0)\n',
    # a READ that fails leaves the DATA pointer on its item
    '10 ON ERROR GOTO 100\n20 READ A: PRINT A\n30 END\n100 PRINT ERR: READ B$: PRINT B$: RESUME 30\n'
    '200 DATA ABC, DEF\n',
    # (where the READ read an item before the bad one: tests/test_gw_read_errors.py, from the source)
    # CLEAR ends error trapping: ON ERROR off, ERR and ERL 0, the handler left
    '10 ON ERROR GOTO 100: CLEAR: ERROR 5\n20 END\n100 PRINT "trapped": RESUME 20\n',
    '10 ON ERROR GOTO 100: ERROR 5\n20 PRINT "back": END\n100 PRINT ERR; ERL: CLEAR: PRINT ERR; ERL: '
    'ON ERROR GOTO 200: ERROR 7\n200 PRINT "h2"; ERR; ERL: RESUME 20\n',
    '10 ON ERROR GOTO 100\n20 A = 1/0: PRINT A\n30 END\n100 PRINT ERR: CLEAR: PRINT "Y": RESUME NEXT\n',
]


@pytest.mark.parametrize("source", EVALUATED_AS_GW)
def test_evaluated_as_pcbasic(pc, source):
    from test_differential_support import run_gw

    assert run_gw(source) == pc.program(source)


def test_casio_keeps_the_type_checks():
    from test_differential_support import run_yaseer

    for source in ('10 PRINT ABS("ABC")\n', '10 A$ = "X": PRINT -A$\n', '10 PRINT INT("ABC")\n'):
        assert "Type mismatch" in run_yaseer(source, dialect="casio")
