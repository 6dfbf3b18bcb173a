"""Fixtures for the command-line tests: input copies and a record of the engine calls."""

from __future__ import annotations

import shutil

import pytest
from clihelpers import TRIANGLE_DATA


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    """A temporary working directory holding copies of Triangle's dots.node and A.poly."""
    for name in ("dots.node", "A.poly"):
        shutil.copy(TRIANGLE_DATA / name, tmp_path / name)
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.fixture
def engine_calls(monkeypatch):
    """Record every call the command makes to ``instrument.triangulate`` (the
    real engine still runs): a list of (input dict, opts, kwargs)."""
    import instrument

    calls = []
    real = instrument.triangulate

    def spy(tri, opts="", **kwargs):
        calls.append((tri, opts, kwargs))
        return real(tri, opts, **kwargs)

    monkeypatch.setattr(instrument, "triangulate", spy)
    return calls
