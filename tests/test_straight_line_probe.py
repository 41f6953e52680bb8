"""An independent reviewer's cases for the recorded paths' C accelerator (_straight_fast.c):
inputs where a program once wrote other bits than the path's Python function.

The reference is CPython on the same input (the path's Python function, or the single Python
operation), as in test_straight_line.py."""

from __future__ import annotations

import random

import pytest

from test_straight_line import FUNCTIONS, PROGRAMS, same_or_refused

pytest.importorskip("yaseer.linkages._straight_fast", reason="the C accelerator is not built")


def test_a_square_is_libm_pow_not_a_product():
    # Python's x ** 2 is float_pow's pow(x, 2.0) of the C library, which for this x gives
    # 0.34485933794512486 where x * x (correctly rounded) gives 0.3448593379451249; a C compiler
    # may turn pow(x, 2.0) into x * x, so the program must call pow itself.  Found through PROG 1
    # (Z(1)=0) with L(3) = 0.5872472545232756: V(4) two units in the last place off.
    x = 0.5872472545232756
    assert x ** 2 != x * x  # the case is a real one on this C library
    ran = same_or_refused(FUNCTIONS["v0 ** 2"], PROGRAMS["v0 ** 2"], {"X": [x, 1.0], "Y": [0.0, 0.0]}, {})
    assert ran


def test_squares_of_many_numbers_are_pythons():
    state = random.Random(7)
    differ = 0
    for _ in range(20000):
        x = state.uniform(-4.0, 4.0)
        differ += x ** 2 != x * x
        assert same_or_refused(FUNCTIONS["v0 ** 2"], PROGRAMS["v0 ** 2"], {"X": [x, 1.0], "Y": [0.0, 0.0]}, {})
    assert differ  # some of them are squares where pow and the product differ
