"""RND and RANDOMIZE of both dialects (yaseer/basic/arithmetic/randomness.py).

The GW numbers below are PC-BASIC 2.0.8's output (GW-BASIC's generator), printed
as ``CDBL(RND) * 16777216#`` so that the 24-bit state shows exactly, recorded from
this program (one line per statement group):

    10 FOR I=1 TO 3: PRINT CDBL(RND)*16777216#: NEXT: PRINT CDBL(RND(0))*16777216#
    20 PRINT CDBL(RND(-1))*16777216#; CDBL(RND(-2))*16777216#; CDBL(RND(-0.5))*16777216#; CDBL(RND(-3))*16777216#
    30 RANDOMIZE 1.5#: PRINT CDBL(RND)*16777216#
    40 RANDOMIZE 40000: PRINT CDBL(RND)*16777216#

and separate runs of ``RANDOMIZE 5``, ``X%=-5: RANDOMIZE X%``, ``X=5: RANDOMIZE X``
and ``RANDOMIZE -1`` each followed by ``PRINT CDBL(RND)*16777216#``.
tests/test_differential_gw_runtime.py compares many more sequences live.
"""

from __future__ import annotations

import pytest

from yaseer.basic.arithmetic.randomness import GwRandom, RepeatableRandom, mbf_bytes, seed_word

TWO_24 = 16777216


def states(generator, calls):
    return [generator.rnd(x) * TWO_24 for x in calls]


def test_gw_sequence_from_run():
    g = GwRandom()
    assert g.rnd(0) * TWO_24 == 5228370  # RND(0) before any RND: the start state
    assert states(g, [1, 1, 1, 0]) == [2035917, 10936412, 14577071, 14577071]


def test_gw_negative_argument_reseeds_from_the_mantissa_only():
    g = GwRandom()
    assert states(g, [-1, -2, -0.5, -3]) == [10919619, 10919619, 10919619, 15113923]


@pytest.mark.parametrize("value, kind, expected", [
    (5, "%", 593500), (-5, "%", 16299100), (5.0, "!", 10289500), (-1, "!", 9331036),
])
def test_gw_randomize_from_a_fresh_run(value, kind, expected):
    g = GwRandom()
    g.randomize(value, kind)
    assert g.rnd() * TWO_24 == expected


def test_gw_randomize_after_rnd_keeps_the_low_byte():
    g = GwRandom()
    states(g, [1, 1, 1, 0, -1, -2, -0.5, -3])
    g.randomize(1.5, "#")
    assert g.rnd() * TWO_24 == 16125269
    g.randomize(40000.0, "!")
    assert g.rnd() * TWO_24 == 10950007


def test_mbf_layout():
    # 1.0 is 0.5 * 2**1: mantissa bits all zero after the hidden bit, exponent 129
    assert mbf_bytes(1.0, "!") == bytes([0, 0, 0, 0x81])
    assert mbf_bytes(-1.0, "!") == bytes([0, 0, 0x80, 0x81])
    assert mbf_bytes(0.25, "#") == bytes([0] * 7 + [0x7F])
    assert mbf_bytes(0.0, "#") == bytes(8)
    # 1# as a double reads as 0x8100 -> -32512; 0.25# as 0x7F00 = 32512 (PC-BASIC's documented cases)
    assert seed_word(1.0, "#") == -32512
    assert seed_word(0.25, "#") == 32512


def test_repeatable_generator_restarts_at_reset():
    r = RepeatableRandom()
    first = [r.rnd() for _ in range(3)]
    r.reset()
    assert [r.rnd() for _ in range(3)] == first
    assert r.rnd(0) == first[-1]  # RND(0) repeats the last number
    assert r.rnd() != first[-1]


def _gw_screen(program: str, answers: str = "") -> str:
    import io

    from yaseer.basic.machine.machine import Machine

    screen = io.StringIO()
    machine = Machine(screen=screen, dialect="gw", input_stream=io.StringIO(answers))
    machine.load(program)
    machine.run()
    return screen.getvalue()


def test_gw_machine_uses_gw_sequence_and_randomize_alone_asks():
    assert _gw_screen("10 PRINT RND * 16777216") == _gw_screen("10 PRINT 2035917")
    asked = _gw_screen("10 RANDOMIZE: PRINT RND * 16777216", "5\n")
    assert asked == "Random number seed (-32768 to 32767)? 5\n" + _gw_screen("10 PRINT 593500")


def test_repeatable_rnd_zero_reads_the_last_number_drawn_by_the_fast_drawer():
    """RND(0) after draws through ``drawer()`` (which records nothing) is the last
    number drawn, across the generator's regenerations (every 312 numbers), against
    Python's own generator seeded with 0 drawn one number at a time."""
    import random

    reference = random.Random(0)
    r = RepeatableRandom()
    assert r.rnd(0) == 0.0  # nothing drawn since RUN
    draw = r.drawer()
    for count in (1, 310, 1, 1, 1, 700):
        for _ in range(count):
            expected = reference.random()
            assert draw() == expected
        assert r.rnd(0) == expected
    r.randomize(7)
    reference.seed(7)
    assert r.rnd(0) == expected  # RANDOMIZE does not draw: RND(0) still gives the one before
    assert r.rnd() == reference.random()
    reference.seed(-2.5)
    assert r.rnd(-2.5) == reference.random() == r.rnd(0)
    r.reset()
    assert r.rnd(0) == 0.0 and draw() == random.Random(0).random()  # the drawer survives RUN
