"""Fixtures shared by the test modules."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="module")
def pc():
    """One PC-BASIC 2.0.8 session (the GW-BASIC reference) for a whole test module."""
    from test_differential_support import PcBasic

    session = PcBasic()
    yield session
    session.close()
