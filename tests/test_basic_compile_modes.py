"""The block compiler's fast forms against its plainest form, on generated programs.

A program that contains a ``RESUME`` is compiled with every statement in a block of
its own, no native loops and no self-loops: the plainest form.  Appending a never
reached ``RESUME`` line therefore gives an independent second compilation of the same
program; both must print exactly the same values.
"""

import io
import random

import pytest

from yaseer.basic.errors import BasicError
from yaseer.basic.machine.machine import Machine


def outcome(program: str) -> tuple[str, str]:
    """(what the program printed in csv mode, the error it stopped with or "")."""
    machine = Machine(screen=io.StringIO(), output_format="csv")
    machine.load(program)
    try:
        machine.run()
        error = ""
    except BasicError as err:
        error = str(err)
    return machine.screen.stream.getvalue(), error

VARIABLES = ["A", "B", "K", "QQ", "X1"]
LOOP_VARIABLES = ["I", "J", "N"]


def _expr(rng: random.Random, loop_vars: list, depth: int = 0) -> str:
    choices = VARIABLES + loop_vars + [str(rng.randint(0, 9)), f"{rng.uniform(-5, 5):.2f}", "L(2)", "SIN QQ"]
    if depth > 2 or rng.random() < 0.4:
        return rng.choice(choices)
    op = rng.choice(["+", "-", "*", "+", "-"])
    return f"({_expr(rng, loop_vars, depth + 1)} {op} {_expr(rng, loop_vars, depth + 1)})"


def _statement(rng: random.Random, loop_vars: list) -> str:
    kind = rng.random()
    if kind < 0.35:
        return f"{rng.choice(VARIABLES)} = {_expr(rng, loop_vars)}"
    if kind < 0.5:
        return f"PRINT {_expr(rng, loop_vars)}; {rng.choice(VARIABLES)}"
    if kind < 0.6 and loop_vars:
        return f"L({rng.choice(loop_vars)}) = {_expr(rng, loop_vars)}"
    if kind < 0.75:
        return (f"IF {_expr(rng, loop_vars)} > {rng.randint(-3, 3)} THEN "
                f"{rng.choice(VARIABLES)} = {_expr(rng, loop_vars)} ELSE PRINT {rng.choice(VARIABLES)}")
    if kind < 0.85:
        return "GOSUB 1000"
    return f"K = K + 1: PRINT K"


def _program(seed: int) -> str:
    rng = random.Random(seed)
    lines, number, open_loops = [], 10, []
    count = rng.randint(4, 12)
    for k in range(count):
        statements = []
        for _ in range(rng.randint(1, 3)):
            r = rng.random()
            if r > 0.93 and k < count - 1:  # a forward jump (into or out of loop bodies)
                target = number + 10 * rng.randint(1, count - 1 - k)
                jump = rng.choice([f"IF K > {rng.randint(-1, 2)} THEN {target}", f"GOTO {target}",
                                   f"ON K GOTO {target}, {target}"])
                statements.append(jump)
                continue
            free = [v for v in LOOP_VARIABLES if v not in open_loops]
            if r < 0.25 and free and len(open_loops) < 2:
                var = rng.choice(free)
                start, stop = rng.randint(-2, 3), rng.randint(-1, 6)
                step = rng.choice(["", " STEP 2", " STEP -1", " STEP .5"])
                statements.append(f"FOR {var} = {start} TO {stop}{step}")
                open_loops.append(var)
            elif r < 0.4 and open_loops:
                statements.append(f"NEXT {open_loops.pop()}")
            else:
                statements.append(_statement(rng, open_loops))
        lines.append(f"{number} " + ": ".join(statements))
        number += 10
    while open_loops:
        lines.append(f"{number} NEXT {open_loops.pop()}")
        number += 10
    lines.append(f"{number} PRINT A; B; K; QQ; X1; L(2); I; J; N: END")
    lines.append("1000 X1 = X1 + 1: QQ = QQ + 15: RETURN")
    return "\n".join(lines) + "\n"


@pytest.mark.parametrize("seed", range(200))
def test_fast_and_plain_compilations_print_the_same(seed):
    program = _program(seed)
    plain = program + "65000 RESUME\n"
    fast = outcome(program)
    assert fast == outcome(plain), program
    assert "Internal" not in fast[1]
