"""Fixtures shared by the test modules."""

from __future__ import annotations

import pytest
from hypothesis import settings

# Tests never assert wall-clock time: hypothesis's default 200 ms deadline per example is
# such an assertion, and it failed under load on a busy machine.  No example has a deadline.
settings.register_profile("yaseer", deadline=None)
settings.load_profile("yaseer")


@pytest.fixture(scope="module")
def pc():
    """One PC-BASIC 2.0.8 session (the GW-BASIC reference) for a whole test module."""
    from test_differential_support import PcBasic

    session = PcBasic()
    yield session
    session.close()
