"""The program text's share of GW-BASIC's 64 KB as FRE(0) shows it: a number after one of
the words CRUNCH takes line numbers after (GWMAIN.ASM LINRES: GOTO, GOSUB, THEN, ELSE,
RESTORE, RUN, RESUME, RETURN, LIST, LLIST, DELETE, EDIT, AUTO, RENUM and ERL) is stored as
a 3-byte line-number token, also after an operator, a comma or a bracket (NOTRS1 keeps
DONUM), where elsewhere a small number takes 1 or 2 bytes; generated lines against
PC-BASIC 2.0.8."""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count, gw_programs_differing
from yaseer.basic.machine.memory_model import line_bytes

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def _number(rng) -> str:
    return str(rng.choice([rng.randint(0, 9), rng.randint(10, 255), rng.randint(256, 6552),
                           rng.randint(6553, 65529), rng.randint(65530, 99999)]))


def _statement(rng) -> str:
    n = lambda: _number(rng)  # noqa: E731 (a fresh number each time)
    op = rng.choice(["=", "<>", "<", ">=", " = "])
    return rng.choice([
        f"IF ERL{op}{n()} THEN {n()}", f"IF ERL{op}({n()}) THEN PRINT {n()},{n()}", f"ON X GOTO {n()},{n()}",
        f"GOSUB {n()}", f"LIST {n()}-{n()}", f"LLIST -{n()}", f"DELETE {n()}-{n()}", f"RENUM {n()},{n()},{n()}",
        f"AUTO {n()},{n()}", f"EDIT {n()}", f"RESTORE {n()}", f"RESUME {n()}", f"RETURN {n()}",
        f"X=ERL*{n()}+{n()}-ERL", f"PRINT ERL;{n()};{n()}", f"IF A THEN {n()} ELSE {n()}", f"RUN {n()}",
        f"Y=ERL: Z={n()}", f"PRINT {n()}+{n()}", f"X=(ERL)+({n()})", f"IF X THEN Y={n()} ELSE GOTO {n()}",
    ])


def test_line_numbers_take_three_bytes_where_crunch_takes_them_as_pcbasic(pc):
    rng = random.Random(base_seed() + 61)
    count = max(case_count() // 5, 30)

    def program() -> str:
        lines = [f"{20 + i} " + ": ".join(_statement(rng) for _ in range(rng.randint(1, 3)))
                 for i in range(rng.randint(1, 4))]
        return "10 GOTO 100\n" + "\n".join(lines) + "\n100 PRINT FRE(0)\n"

    bad, _ = gw_programs_differing(pc, program, count)
    assert not bad, f"{len(bad)} of {count} differ, e.g. {bad[:3]}"


def test_a_number_after_a_line_number_word_is_a_line_number_token():
    """Worked from CRUNCH by hand: ``ERL=100`` is the token ERL (1 byte), = (1) and a
    line-number token (3), where ``X=100`` stores X (1), = and a 2-byte integer token; ``LIST 1-2``
    keeps line numbers after the minus; 70000 is read as 7000 and 0 (LINGET stops past 6552)."""
    assert line_bytes("ERL=100") - line_bytes("X=100") == 1
    assert line_bytes("LIST 1-2") == 5 + 1 + 1 + 3 + 1 + 3
    assert line_bytes("ERL=70000") == 5 + 1 + 1 + 3 + 3
