"""Fixtures for the command-line tests: input copies and a stand-in engine."""

from __future__ import annotations

import shutil

import pytest
import triangle
from clihelpers import TRIANGLE_DATA


@pytest.fixture
def workdir(tmp_path, monkeypatch):
    """A temporary working directory holding copies of Triangle's dots.node and A.poly."""
    for name in ("dots.node", "A.poly"):
        shutil.copy(TRIANGLE_DATA / name, tmp_path / name)
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.fixture
def triangle_engine(monkeypatch):
    """Replace ``instrument.triangulate`` by Triangle itself (the `triangle` wheel).

    Lets the whole command line run on switches our engine does not handle yet
    (p, q, a, r).  Returns the list of (input dict, opts, kwargs) of every call.
    """
    import instrument
    from instrument import Result

    calls = []

    def fake(tri, opts="", **kwargs):
        calls.append((tri, opts, kwargs))
        result = Result(triangle.triangulate(tri, opts))
        result.work = {"triangles_created": 7, "incircle_tests": 5, "orient_tests": 3}
        return result

    monkeypatch.setattr(instrument, "triangulate", fake)
    return calls
