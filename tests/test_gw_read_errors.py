"""A READ whose DATA item is not a number, as GW-BASIC's source does it (GWMAIN.ASM READ,
NUMINS, DOASIG, STRDN2, TRMNOK, DATSNE; BIMISC.ASM RESFIN).

The number at the start of the item (0 if there is none) is assigned to the variable
before the terminator after it is checked, so ``DATA 4X`` gives 4, then Syntax error in
the DATA line; the READ keeps the DATA pointer on the stack and only RESFIN, as the READ
ends, stores it in DATPTR, so a READ that fails leaves the pointer where that READ began:
an item it read before the bad one is read again.  PC-BASIC 2.0.8 assigns the same number
but leaves the pointer on the bad item (and reports ERL 65535 for a bad item in the
first DATA line), so programs whose READs read one item are compared with PC-BASIC and
those that read more with values worked out from the source.
"""

from __future__ import annotations

import random

import pytest

from test_differential_support import base_seed, case_count, run_gw

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use

ITEMS = ["5", "-2.5", "X1", "ABC", '"Q"', '"7"', "", " 3 ", "1E2", "&H10", "Z Z", "4X", "12AB", "-"]


def _program(rng: random.Random, most: int) -> str:
    lines = ["10 ON ERROR GOTO 900"]
    for k in range(rng.randint(2, 7)):
        names = [rng.choice(["A", "B", "C$", "D$", "E%"]) for _ in range(rng.randint(1, most))]
        lines.append(f"{20 + 10 * k} READ {', '.join(names)}: PRINT {';'.join(names)}")
    lines.append("800 END")
    for k in range(rng.randint(1, 3)):
        lines.append(f"{810 + k} DATA " + ", ".join(rng.choice(ITEMS) for _ in range(rng.randint(1, 4))))
    lines.append('900 PRINT "E"; ERR: RESUME NEXT')
    return "\n".join(lines) + "\n"


def test_one_item_reads_as_pcbasic(pc):
    """READs of one variable each: the bad item's number assigned, Syntax error, and the
    next READ reads the same item (here where the READ began and where it failed agree)."""
    rng = random.Random(base_seed() + 55)
    for _ in range(case_count(60)):
        source = _program(rng, 1)
        pc.statement("ON ERROR GOTO 0")
        assert run_gw(source) == pc.program(source), source


@pytest.mark.parametrize("source, expected", [
    # B is given X1's 0, then the error; the handler's READ reads 5 again
    ('10 ON ERROR GOTO 100\n20 READ A, B: PRINT A; B\n30 END\n100 PRINT ERR; ERL: READ B$: PRINT B$: '
     'RESUME 30\n200 DATA 5, X1, 7\n', " 2  200 \n5\n"),
    # RESUME NEXT prints the numbers given; the next READ starts at the first item again
    ('10 ON ERROR GOTO 100\n20 READ A, B, C: PRINT A; B; C\n30 READ D$, E$: PRINT D$; E$\n40 END\n'
     '100 PRINT "E"; ERR; ERL: RESUME NEXT\n200 DATA 1, 2\n210 DATA 4X, 9\n', "E 2  210 \n 1  2  4 \n12\n"),
    # Out of DATA in the middle of a READ also leaves the pointer where it began
    ('10 ON ERROR GOTO 100\n20 READ A, B: PRINT A; B\n30 READ C: PRINT C\n40 END\n'
     '100 PRINT "E"; ERR: RESUME NEXT\n200 DATA 7\n', "E 4 \n 7  0 \n 7 \n"),
    # a bad item stops the READ at its variable: D$ is not read
    ('10 ON ERROR GOTO 100\n20 D$ = "old": READ A, D$: PRINT A; D$\n30 END\n100 RESUME NEXT\n'
     '200 DATA 12AB, "x"\n', " 12 old\n"),
])
def test_a_failed_read_leaves_the_pointer_where_it_began(source, expected):
    assert run_gw(source) == expected
