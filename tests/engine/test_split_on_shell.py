"""A split vertex on a later shell of a subsegment's acute end is left to the
later split that reaches it (splits._on_later_shell).

Six points within rounding of the line y = x / 3, a chain of five segments
(differential regression regressions/sliver-hull-limit.json), under
``pq34a0.000899cvi``: the chain and the hull are split on the same
power-of-two shells around their shared ends.  The 7th split is of the hull
subsegment (0.7003, ..) - (0.9375, ..), whose apex, the chain's shell vertex
(0.8782, ..), lies on it within 2^-50, 3/4 along it; Triangle splits at the
shell 1/2 along, (0.8189, ..), and so does ours since stop 33 (taking the
apex there joined the chain to the hull and grew fans of single vertices
across the sliver: max degree 545 at -S64000, 5,021 at -S512000).  The
later split of (0.8189, ..) - (0.9375, ..) lands beside the chain's vertex
(Triangle makes a vertex 3e-16 from it, at -S15); ours takes the chain's
vertex there instead.

The bent configuration of test_split_bent.py, where the split point would
land beside a vertex of its cavity, takes the apex at once (those tests).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

import triangle

import instrument
from instrument.check import check_mesh
from tests.differential.cases import read_case

CASE = Path(__file__).parents[1] / "differential" / "regressions" / "sliver-hull-limit.json"
SLIVER = read_case(CASE)[0].input
SWITCHES = "pq34a0.000899cviQ"


def _vertices(mesh) -> set:
    return {tuple(p) for p in np.asarray(mesh["vertices"]).tolist()}


def test_the_first_fourteen_splits_are_triangles():
    for k in (7, 14):
        ours = instrument.triangulate(SLIVER, f"{SWITCHES}S{k}")
        assert check_mesh(ours, pslg=SLIVER) == []
        theirs = triangle.triangulate(SLIVER, f"{SWITCHES}S{k}")
        assert _vertices(ours) == _vertices(theirs)
    shell_midpoint = (0.8189145877436858, 0.2729715292478941)  # the 7th split, 1/2 along the hull subsegment
    assert shell_midpoint in _vertices(ours)


def test_the_later_split_takes_the_vertex_it_lands_beside():
    ours = instrument.triangulate(SLIVER, f"{SWITCHES}S15")
    assert check_mesh(ours, pslg=SLIVER) == []
    xy = np.asarray(ours["vertices"])
    gaps = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
    np.fill_diagonal(gaps, np.inf)
    assert gaps.min() > 1e-6  # no vertex beside another (Triangle's -S15 has two 3e-16 apart)


def test_the_sliver_grows_no_fans():
    ours = instrument.triangulate(SLIVER, f"{SWITCHES[:-1]}eQS64000")
    assert check_mesh(ours, pslg=SLIVER) == []
    degree = np.bincount(np.asarray(ours["edges"]).ravel())
    assert degree.max() < 150  # 545 when the chain's shell vertex took the 7th split (68 since)
    assert ours.work["incircle_tests"] < 8 * len(ours["vertices"])
