"""RESUME NEXT after an error inside an IF's THEN or ELSE goes on with the statement after
the failing one inside that branch (GW-BASIC's RESUME NEXT goes to the statement after the
failing one by its place in the text; PC-BASIC 2.0.8 agrees): generated programs whose
branches hold failing statements, nested IFs and loops, against PC-BASIC."""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count
from test_gw_language_rules import pc  # noqa: F401 - the module's PC-BASIC session
from test_gw_files import yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

_FAILING = ("X=1/0", "X=SQR(-1)", "X=LOG(0)", "ERROR 200", "X=A(11)", 'X=VAL("1"+CHR$(0))*ASC("")')


def _branch(rng: random.Random, depth: int) -> str:
    parts = []
    for _ in range(rng.randint(1, 4)):
        choice = rng.random()
        if choice < 0.35:
            parts.append(rng.choice(_FAILING))
        elif choice < 0.5 and depth < 2:
            parts.append(_if(rng, depth + 1))
            break  # an IF takes the rest of the line
        else:
            parts.append(f'PRINT "p{rng.randint(0, 99)}"')
    return ": ".join(parts)


def _if(rng: random.Random, depth: int = 0) -> str:
    text = f"IF {rng.choice(['1', '0', 'I MOD 2', 'I>1'])} THEN {_branch(rng, depth)}"
    if rng.random() < 0.5:
        text += f" ELSE {_branch(rng, depth)}"
    return text


def program(rng: random.Random) -> str:
    lines = ["10 ON ERROR GOTO 900: DIM A(10)", "20 FOR I=1 TO 3"]
    for k in range(rng.randint(1, 4)):
        lead = rng.choice(["", 'PRINT "s": ', f"{rng.choice(_FAILING)}: "])
        lines.append(f"{30 + 10 * k} {lead}{_if(rng)}")
    lines += ['800 NEXT I: PRINT "end": END', '900 PRINT "e";ERR;ERL: RESUME NEXT']
    return "\n".join(lines)


def test_resume_next_goes_on_inside_the_branch(pc, tmp_path):
    rng = random.Random(base_seed() + 2403)
    source = '10 ON ERROR GOTO 100: IF 1 THEN PRINT 1/0: PRINT "in branch"\n20 END\n100 RESUME NEXT'
    assert yaseer_run(source, tmp_path) == pc.program(source) == "in branch\n"
    for _ in range(case_count(40)):
        source = program(rng)
        assert yaseer_run(source, tmp_path) == pc.program(source), source
