"""yaseer.linkages.chunks: chunked angles are exactly numpy.linspace's, a
chunked force analysis gives exactly the numbers of one call over all positions,
and the public functions chunk a call over many positions by themselves: the same
numbers as the unchunked computation, in the memory of one chunk."""

from __future__ import annotations

import tracemalloc

import numpy as np
import pytest

from yaseer.linkages import AssemblyError, MassProps, fourbar, virtual_link
from yaseer.linkages.chunks import CHUNK, angle_chunks


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


# --------------------------------------------------------------------------- one call over many positions

def fourbar_call(function, angles, crank=0.3):
    kin = function(1.2, 20.0, crank, 1.0, 0.8, angles, 4.0, -1.0, crank_length_rate=0.01, branch=-1)
    result = kin.forces(crank=MassProps(3.0, 0.05, 0.1, 5.0), coupler=MassProps(2.0, 0.2, 0.4, 10.0),
                        follower=MassProps(1.0, 0.1, 0.3, -15.0), crank_point=(0.2, 30.0),
                        coupler_point=(0.7, -20.0), follower_point=(0.5, 40.0),
                        loads=dict(follower_perpendicular=1.5), gravity=9.81)
    return kin, result


def test_a_call_over_many_positions_gives_the_numbers_of_one_unchunked_call():
    # more than three chunks (the last one short): every number read equals the
    # unchunked computation's (fourbar.__wrapped__: the function without chunking)
    angles = np.linspace(0.0, 360.0, 3 * CHUNK + 17)
    kin, result = fourbar_call(fourbar, angles)
    whole_kin, whole = fourbar_call(fourbar.__wrapped__, angles)
    assert type(whole_kin).__name__ == "FourBar" and type(kin).__name__ == "Lazy"
    assert np.array_equal(result.value, whole.value)
    for name in whole.reactions:
        assert np.array_equal(result.reactions[name], whole.reactions[name])
    assert sorted(result.reactions) == sorted(whole.reactions)
    assert result.unknown == "crank_torque" and kin.moving is True
    angle, omega, alpha = kin.follower
    assert np.array_equal(alpha, whole_kin.follower.alpha) and np.array_equal(angle, whole_kin.follower.angle)
    assert np.array_equal(kin.coupler.degrees, whole_kin.coupler.degrees)
    point, whole_point = kin.coupler_point(0.7, -20.0), whole_kin.coupler_point(0.7, -20.0)
    assert np.array_equal(point.acc, whole_point.acc) and point.acc.shape == (3 * CHUNK + 17,)
    assert kin.pivot.pos == whole_kin.pivot.pos  # the same at every position: one number


def test_per_position_masses_and_loads_are_cut_with_the_positions():
    angles = np.linspace(0.0, 720.0, 2 * CHUNK + 5)
    loads = np.cos(np.radians(angles))
    masses = 1.0 + 0.5 * np.sin(np.radians(angles))

    def torque(function):
        kin = function(1.2, 20.0, 0.3, 1.0, 0.8, angles, 4.0, -1.0)
        return kin.forces(coupler=MassProps(masses, 0.2, 0.4, 10.0), loads=dict(follower_perpendicular=loads),
                          gravity=9.81).value

    assert np.array_equal(torque(fourbar), torque(fourbar.__wrapped__))


def test_an_assembly_failure_in_a_later_chunk_is_raised_when_read():
    # a crank of 0.95: the loop cannot close near 200 deg (in the second chunk)
    angles = np.linspace(0.0, 200.0, 2 * CHUNK + 1)
    with pytest.raises(AssemblyError):
        fourbar_call(fourbar.__wrapped__, angles, crank=0.95)
    kin, result = fourbar_call(fourbar, angles, crank=0.95)  # nothing computed yet
    with pytest.raises(AssemblyError):
        result.value


def test_small_and_scalar_calls_are_made_as_they_are():
    assert type(fourbar(1.2, 20.0, 0.3, 1.0, 0.8, np.linspace(0, 360, CHUNK), 4.0)).__name__ == "FourBar"
    assert type(fourbar(1.2, 20.0, 0.3, 1.0, 0.8, 33.0, 4.0)).__name__ == "FourBar"
    assert type(virtual_link(np.ones(CHUNK + 1), np.zeros(CHUNK + 1))).__name__ == "Lazy"


def traced_peak(count: int) -> int:
    """Peak traced memory of one call's crank torque over ``count`` positions (angles included)."""
    tracemalloc.start()
    try:
        fourbar_call(fourbar, np.linspace(0.0, 360.0, count))[1].value
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def test_the_memory_of_one_call_is_its_angles_and_its_torque_plus_one_chunk():
    # unchunked, this call would hold about 1 kB a position (190 MB at 2 x 10^5); here
    # 16 bytes a position (the angles in, the torque out) plus the working memory of one
    # chunk, which does not grow with the positions
    small, large = 25_000, 200_000
    peak_small, peak_large = traced_peak(small), traced_peak(large)
    chunk_memory = peak_large - 16 * large
    assert chunk_memory < 2_000 * CHUNK  # about 1 kB a position of one chunk, with room
    assert peak_large - peak_small < 16 * (large - small) + 2 * 2**20
