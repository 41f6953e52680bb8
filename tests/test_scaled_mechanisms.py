"""The methods' tolerances scale with the mechanism: the same mechanism measured in a tiny or a
huge unit gives the same angles and angular rates, and lengths, velocities and accelerations
scaled by the unit, with every method of every library program.

Reference: the unscaled run of the same listing (kinematics is homogeneous of degree one in
length: every angle is unchanged when every length is multiplied by the same factor, every
length and its rates are multiplied by it).  Before, at 1E-165 the products of two lengths
underflowed to 0: PROG 1 and PROG 2 reported a toggle that was not there, Newton's four-bar a
singular Jacobian, PROG 1's Newton stopped 1% off, the half-angle forms overflowed.
"""

from __future__ import annotations

import pytest

import yaseer
from yaseer.run_arguments import method_choices

INPUTS = {  # lengths (times S) and rates of a moving, flexible crank, and points on every link
    1: "L(1) = 10 * S: L(2) = 40 * S: L(3) = 120 * S: W(2) = 5: A(2) = 2: D(0) = 3 * S: E(0) = -2 * S: "
       "T(4) = 15: R(1) = 20 * S: H(1) = 30: R(4) = 50 * S: H(4) = -20",
    2: "L(11) = 100 * S: T(11) = 5: L(12) = 40 * S: W(5) = 10: A(5) = 3: D(2) = 4 * S: E(2) = S: "
       "L(13) = 120 * S: L(14) = 80 * S: R(9) = 20 * S: H(9) = 10: R(11) = 60 * S: H(11) = 25: "
       "R(13) = 30 * S: H(13) = -15",
    3: "L(6) = 100 * S: T(6) = 10: L(7) = 40 * S: W(0) = 5: A(0) = 2: D(3) = 2 * S: E(3) = S: "
       "R(0) = 20 * S: H(23) = 15: R(7) = 70 * S: H(6) = -10",
    5: "V(17) = -4 * S: V(18) = 2 * S: A(49) = S: A(50) = -3 * S",
}
CRANK = {1: "T(2) = Q", 2: "T(12) = Q", 3: "T(7) = Q", 5: "X(10) = 3 * S * COS(Q): Y(10) = 5 * S * SIN(Q)"}
ANGLES = ("T(3); W(3); A(3); W(2)", "T(13); W(6); A(6); T(14); W(7); A(7)", "T(9); W(4); A(4)", "T; D(5); E(5)")
LENGTHS = ("X(1); Y(1); V(1); V(2); A(33); A(34); A(10); A(11); X(2); Y(2); V(3); V(4); A(35); A(36)",
           "X(9); Y(9); V(5); V(6); X(10); Y(10); V(7); V(8); A(37); A(38); X(11); Y(11)",
           "L(5); D(4); E(4); X(6); Y(6); V(11); V(12); A(43); A(44); X(7); Y(7); V(13); V(14); A(45); A(46)",
           "L; D(6); E(6)")
PRINTED = dict(zip((1, 2, 3, 5), zip(ANGLES, LENGTHS)))
CASES = [(n, m) for n, methods in method_choices().items() for m in methods]


def printed(program: int, method: str, scale: str, extra: str = "") -> tuple[list, list]:
    """(angle columns, length columns) of each position of a cycle with every length times ``scale``."""
    angles, lengths = PRINTED[program]
    listing = (f"10 S = {scale}: {INPUTS[program]}{extra}\n"
               f"20 FOR Q = 3 TO 353 STEP 10: {CRANK[program]}: GOSUB PROG {program}\n"
               f"30 PRINT {angles}\n40 PRINT {lengths}: NEXT Q\n")
    result = yaseer.run(listing, method={program: method})
    assert result.error is None, (program, method, scale, result.error)
    return result.lines[0::2], result.lines[1::2]


@pytest.mark.parametrize("scale", ["1E-165", "1E+165", "1E-300"])
@pytest.mark.parametrize("program, method", CASES)
def test_a_scaled_mechanism_moves_as_the_unscaled_one(program, method, scale):
    factor = float(scale)
    angles, lengths = printed(program, method, "1")
    scaled_angles, scaled_lengths = printed(program, method, scale)
    assert len(angles) == len(scaled_angles) == 36
    for row, scaled in zip(angles, scaled_angles):
        assert scaled == pytest.approx(row, rel=1e-9, abs=1e-9)
    for row, scaled in zip(lengths, scaled_lengths):
        assert [value / factor for value in scaled] == pytest.approx(row, rel=1e-9, abs=1e-9 * max(map(abs, row)))


@pytest.mark.parametrize("scale", ["1E-165", "1E+165"])
def test_tracking_through_toggles_is_the_same_in_any_unit(scale):
    """PROG 2 following the motion (L(10) = -1) through a change-point four-bar's branch points."""
    change_point = ": L(11) = 100 * S: L(12) = 50 * S: L(13) = 100 * S: L(14) = 50 * S: L(10) = -1"
    angles, lengths = printed(2, "closed", "1", change_point)
    scaled_angles, scaled_lengths = printed(2, "closed", scale, change_point)
    for row, scaled in zip(angles, scaled_angles):
        assert scaled == pytest.approx(row, rel=1e-9, abs=1e-9)
