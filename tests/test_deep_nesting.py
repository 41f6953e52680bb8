"""Loops nest as deep as the documented limit says (docs/interpreter.md: 10,000 open FOR loops
and GOSUB returns), not 20: Python refuses a function with more than 20 nested blocks, so only
the innermost loops are native Python loops and the outer ones run on the FOR stack.  The
counts are worked out by hand: k nested loops of 2 passes each run the body 2**k times."""

from __future__ import annotations

import pytest

import yaseer

NAMES = [f"{a}{b}" for a in "ABDEGHJKLMPQRSUVWXYZ" for b in "0123456789"]  # 200 two-character names


def nested(depth: int, passes, one_line: bool = False) -> str:
    """``depth`` nested FOR loops (loop k runs passes(k) times) around ``C = C + 1``, then PRINT C."""
    fors = [f"FOR {NAMES[k % len(NAMES)]}{'' if k < len(NAMES) else k // len(NAMES)} = 1 TO {passes(k)}"
            for k in range(depth)]
    body = fors + ["C = C + 1"] + ["NEXT"] * depth + ["PRINT C"]
    if one_line:
        return "10 " + ": ".join(body) + "\n"
    return "".join(f"{10 * (n + 1)} {statement}\n" for n, statement in enumerate(body))


@pytest.mark.parametrize("dialect", ["casio", "gw"])
@pytest.mark.parametrize("depth", [9, 12, 21])
def test_deep_loops_of_two_passes_each_run_two_to_the_depth(depth, dialect):
    """Once: 21 nested loops were Out of memory; 9 and 12 mix native and stacked loops."""
    result = yaseer.run(nested(depth, lambda k: 2 if k < 16 else 1), dialect=dialect)
    assert (result.error, result.text) == (None, f" {2 ** min(depth, 16)} \n")


@pytest.mark.parametrize("one_line", [False, True])
def test_500_nested_loops_compile_and_run(one_line):
    """Once a RecursionError traceback from the compiler."""
    result = yaseer.run(nested(500, lambda k: 3 if k in (0, 250, 499) else 1, one_line), dialect="gw")
    assert (result.error, result.text) == (None, " 27 \n")


def test_a_subroutine_called_from_the_deepest_loop():
    """GOSUB and RETURN from inside 30 loops (the return shares the stack with the loops)."""
    program = nested(30, lambda k: 2 if k < 3 else 1).replace("C = C + 1", "GOSUB 9000")
    result = yaseer.run(program + "8999 END\n9000 C = C + 1: RETURN\n", dialect="gw")
    assert (result.error, result.text) == (None, " 8 \n")
