"""yaseer.linkages.chunks: chunked angles are exactly numpy.linspace's, and a
chunked force analysis gives exactly the numbers of one call over all positions."""

from __future__ import annotations

import numpy as np
import pytest

from yaseer.linkages import MassProps, fourbar
from yaseer.linkages.chunks import angle_chunks


@pytest.mark.parametrize("count,chunk", [(1, 4), (2, 4), (13, 4), (16, 4), (3601, 1000), (3601, 5000)])
def test_chunks_are_linspace(count, chunk):
    pieces = list(angle_chunks(-30.0, 330.0, count, chunk))
    assert all(len(piece) <= chunk for piece in pieces)
    assert np.array_equal(np.concatenate(pieces), np.linspace(-30.0, 330.0, count))


def torque(angles):
    kin = fourbar(1.2, 20.0, 0.3, 1.0, 0.8, angles, 4.0, -1.0, branch=-1)
    return kin.forces(crank=MassProps(3.0, 0.05, 0.1, 5.0), coupler=MassProps(2.0, 0.2, 0.4, 10.0),
                      follower=MassProps(1.0, 0.1, 0.3, -15.0), loads=dict(follower_perpendicular=1.5),
                      gravity=9.81).value


def test_chunked_forces_equal_one_call():
    whole = torque(np.linspace(0.0, 360.0, 1001))
    chunked = np.concatenate([torque(angles) for angles in angle_chunks(0.0, 360.0, 1001, 64)])
    assert np.array_equal(whole, chunked)
