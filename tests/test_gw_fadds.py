"""GW's single ``+`` and ``-`` on every path that computes them, against
tests/fadds_reference.py (a transcription of ``$FADDS``'s 8086 registers, MATH1.ASM).

The paths: single_arith.add/subtract (float fast paths and the long way on integers, no
accelerator), the C accelerator's add (when built), the compiled code's inline tests with
and without its binade caches and with the helpers alone, the NEXT of a single FOR
variable (the runtime's loop helpers and the compiled loop), and a program's ``+`` through
MKS$/CVS.  The operands are random singles of every exponent gap from 0 to 34, both signs,
cancelling differences, and sums at the top of MBF's range (an overflow: the signed largest
single under GW's continuing policy).

The recorded sums: a real GW-BASIC 3.23 added fourteen pairs of singles given by their MBF
bytes (PC-BASIC's test suite, unsorted/ROUNDING, model/OUTPUT); PC-BASIC 2.0.8 gets six of
them one unit off.
"""

from __future__ import annotations

import io
from math import inf, ldexp

import fadds_reference as ref
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from test_binade_cache import _compiled

from yaseer.basic.arithmetic import single_arith
from yaseer.basic.machine import runtime
from yaseer.basic.machine.machine import Machine

try:
    from yaseer.basic.arithmetic import _mbf_fast
except ImportError:  # (built by setup.py where a compiler is found)
    _mbf_fast = None

LARGEST = single_arith.LARGEST

# (left operand, right operand, the sum a real GW-BASIC 3.23 wrote), MBF bytes: low
# mantissa byte, middle, sign and high byte, exponent; each right operand is negative
RECORDED = [
    ("aa771772", "41e8d661", "3e771772"),
    ("aa001772", "4180d661", "3e001772"),
    ("aa000072", "4180d661", "3e000072"),
    ("aa000072", "0080d661", "3f000072"),
    ("aa000072", "0180d661", "3e000072"),
    ("aa000072", "0100d661", "3f000072"),
    ("aa000072", "0140d661", "3f000072"),
    ("01000072", "0180d661", "2bff7f71"),
    ("01000072", "0080d661", "2cff7f71"),
    ("00000072", "0180d661", "29ff7f71"),
    ("00000072", "0080d661", "2aff7f71"),
    ("00000072", "0180d660", "94ff7f71"),
    ("00000072", "0080d660", "95ff7f71"),
    ("00000072", "0180d65f", "caff7f71"),
]


@pytest.mark.parametrize(("left", "right", "recorded"), RECORDED)
def test_the_recorded_sums(left, right, recorded):
    a, b = ref.from_mbf(bytes.fromhex(left)), ref.from_mbf(bytes.fromhex(right))
    expected = ref.from_mbf(bytes.fromhex(recorded))
    assert ref.fadds(bytes.fromhex(right), bytes.fromhex(left)).hex() == recorded  # the reference itself
    assert single_arith.add(a, b) == expected == single_arith.add(b, a)
    assert single_arith.subtract(a, -b) == expected
    if _mbf_fast is not None:
        assert _mbf_fast.add(a, b) == expected


def test_the_recorded_sums_in_a_program():
    """The sums as a program makes them: MKS$ of the sum of two CVS."""
    lines = []
    for k, (left, right, _) in enumerate(RECORDED):
        chars = ["+".join(f"CHR$(&H{text[i:i + 2]})" for i in range(0, 8, 2)) for text in (left, right)]
        lines.append(f"{10 + k} S$=MKS$(CVS({chars[0]})+CVS({chars[1]})): "
                     "FOR J=1 TO 4: PRINT RIGHT$(\"0\"+HEX$(ASC(MID$(S$,J))),2);: NEXT: PRINT")
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect="gw")
    machine.load("\n".join(lines) + "\n")
    machine.run()
    assert screen.getvalue().split() == [recorded.upper() for _, _, recorded in RECORDED]


def test_the_source_rounds_as_the_reference_on_its_own_examples():
    """Cases read off the routine: 1 - 2**-24 is .99999994 (exponents 24 apart: the 1 kept
    in the guard byte, the difference normalised; exact); 1 - 1.5 * 2**-25 is 1 (25 apart:
    the larger as it is, where the nearest single is .99999994); after a carry the sticky
    bit is dropped: 16777215 + 32770.125 = 16809985.125, whose nearest single is 16809986,
    is 16809984 (the 1.125 below the even mantissa read as a tie: half to even); 2**24 - 1
    is 16777215."""
    assert ref.subtract(1.0, 2.0 ** -24) == 1 - 2.0 ** -24 == single_arith.subtract(1.0, 2.0 ** -24)
    assert ref.add(1.0, -1.5 * 2.0 ** -25) == 1.0 == single_arith.add(1.0, -1.5 * 2.0 ** -25)
    assert ref.add(16777215.0, 32770.125) == 16809984.0 == single_arith.add(16777215.0, 32770.125)
    assert single_arith.nearest(16777215.0 + 32770.125) == 16809986.0
    assert ref.subtract(16777216.0, 1.0) == 16777215.0 == single_arith.subtract(16777216.0, 1.0)


def _mantissas():
    return st.one_of(
        st.integers(1 << 23, (1 << 24) - 1),
        st.sampled_from([1 << 23, (1 << 24) - 1, (1 << 23) + 1, 3 << 22, (1 << 24) - 2]),
        st.integers(0x80, 0xFF).map(lambda v: v << 16),  # few bits
        st.integers(0, 0xFF).map(lambda v: (0xFFFF00 | v)),  # all ones but the low byte
        st.integers(0, 0xFF).map(lambda v: (0x800000 | v)),  # a power of two and a low byte
    )


@st.composite
def pairs(draw):
    """Two singles of MBF's range: any exponent, a gap of 0 to 34 binades, both signs;
    now and then a cancelling pair (the same exponent, mantissas a few units apart)."""
    exponent = draw(st.one_of(st.integers(-127, 127), st.sampled_from([127, 126, -127, -126, -120])))
    gap = draw(st.integers(0, 34))
    m = draw(_mantissas())
    if draw(st.integers(0, 9)) == 0:
        n, gap = max(1 << 23, min((1 << 24) - 1, m + draw(st.integers(-4, 4)))), 0
    else:
        n = draw(_mantissas())
    a = ldexp(m, exponent - 24)
    b = ldexp(n, max(-127, exponent - gap) - 24)
    if draw(st.booleans()):
        a = -a
    if draw(st.booleans()):
        b = -b
    return (a, b) if draw(st.booleans()) else (b, a)


COMPILED = {(op, inline, caching): _compiled(f"n_A {op} n_B", inline=inline, caching=caching)[0]
            for op in "+-" for inline, caching in ((True, True), (True, False), (False, False))}


def _policy(x: float) -> float:
    return x if x - x == 0 else (-LARGEST if x < 0 else LARGEST)


@settings(max_examples=1500)
@given(pairs())
def test_every_path_adds_as_the_reference(pair):
    a, b = pair
    for op, routine, reference in (("+", single_arith.add, ref.add), ("-", single_arith.subtract, ref.subtract)):
        expected = reference(a, b)
        assert routine(a, b) == expected, (op, a.hex(), b.hex())
        for (o, inline, caching), f in COMPILED.items():
            if o == op:
                assert f(a, b) == _policy(expected), (op, inline, caching, a.hex(), b.hex())
        if _mbf_fast is not None:
            assert _mbf_fast.add(a, b if op == "+" else -b) == expected, (op, a.hex(), b.hex())


@settings(max_examples=300)
@given(pairs())
def test_a_cached_sum_walk_is_the_reference(pair):
    """A = A + B repeated (the binade cache hit again and again, then left), both ways."""
    start, step = pair
    for op, reference in (("+", ref.add), ("-", ref.subtract)):
        for (o, inline, caching), f in COMPILED.items():
            if o != op:
                continue
            a = expected = start
            for _ in range(12):
                a, expected = f(a, step), _policy(reference(expected, step))
                assert a == expected, (op, inline, caching, start.hex(), step.hex())


@settings(max_examples=300)
@given(pairs())
def test_the_loop_helpers_step_as_the_reference(pair):
    """The runtime's FOR helpers of a single variable: each ``+ STEP`` is $FADDS."""
    start, step = pair
    limit = inf if step > 0 else -inf
    helpers = runtime.single_loop_helpers()
    expected, got = [start], []
    for _ in range(4):
        following = ref.add(expected[-1], step)
        if following - following != 0:  # (an overflow: the policy's, elsewhere)
            break
        expected.append(following)
    values_ = helpers["_frange"](start, limit, step)
    for _ in range(len(expected)):
        try:
            got.append(next(values_))
        except StopIteration:
            break
    assert got == expected[:len(got)] and len(got) >= min(2, len(expected))


def test_a_program_loop_steps_as_the_reference():
    """The compiled NEXT of single FOR variables, with starts and steps of every kind, in
    the fast code and the general code: each pass prints its value's MBF bytes (MKS$)."""
    import random

    rng = random.Random(24)
    loops = []
    for _ in range(60):
        exponent = rng.randrange(-40, 40)
        start = ldexp(rng.randrange(1 << 23, 1 << 24), exponent - 23) * rng.choice([1, -1])
        # (exponents 25 or more apart: the step changes nothing and the loop would never end)
        step = ldexp(rng.randrange(1 << 23, 1 << 24), exponent - 23 - rng.randrange(0, 20)) * rng.choice([1, -1])
        loops.append((start, step))
    text = "\n".join(
        [f"{10 + k} S!={start!r}: T!={step!r}: FOR I!=S! TO S!+T!*4.5 STEP T!: "
         "FOR J=1 TO 4: PRINT RIGHT$(\"0\"+HEX$(ASC(MID$(MKS$(I!),J))),2);: NEXT: PRINT \" \";: NEXT: PRINT"
         for k, (start, step) in enumerate(loops)]) + "\n"
    printed = {}
    for general in (False, True):
        screen = io.StringIO()
        machine = Machine(screen=screen, dialect="gw")
        machine.load(text + ("64999 END\n65000 RESUME NEXT\n" if general else ""))  # (never reached)
        machine.run()
        printed[general] = [line.split() for line in screen.getvalue().splitlines() if line.strip()]
    assert printed[False] == printed[True] and len(printed[False]) == len(loops)
    for (start, step), line in zip(loops, printed[False]):
        s, t = single_arith.from_double(start), single_arith.from_double(step)  # (as the literals were read)
        expected = [s]
        for _ in range(len(line) - 1):
            expected.append(ref.add(expected[-1], t))
        assert [ref.from_mbf(bytes.fromhex(b)) for b in line] == expected, (start, step)
        assert len(line) >= 4
