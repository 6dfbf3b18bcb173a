"""The Triangle and ours workers, started once per test session."""

from __future__ import annotations

import pytest

pytest.importorskip("triangle")
pytest.importorskip("hypothesis")
pytest.importorskip("scipy")

from .runners import Runners  # noqa: E402


@pytest.fixture(scope="session")
def runners():
    r = Runners()
    yield r
    r.close()
