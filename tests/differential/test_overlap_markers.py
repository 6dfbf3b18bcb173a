"""Markers on overlapping collinear segments agree with Triangle (issue 18).

Two segments of one line overlap: (0.025390625, y)-(0.912109375, y) and
(0.03125, y)-(0.947265625, y), y = 0.001953125, inside the unit square with
its four sides.  Measured on Triangle (36 variants: either segment first,
either direction, markers 0/1, 2/3, 0/2 in both orders): the segment
inserted first marks the overlapping stretch, an endpoint takes the marker
of the first segment through it whose marker is nonzero, and a marker 0
marks nothing.  Every variant, with and without a segment crossing the
stretch, runs through the differential harness (Triangle in a worker,
``check_mesh`` on ours, equal counts and markers).
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest

from .cases import Case
from .harness import run_case

Y = 0.001953125
STRETCH = [(0.025390625, Y), (0.912109375, Y), (0.03125, Y), (0.947265625, Y)]
CROSSERS = {
    "none": [],
    "across-both": [(0.5, 0.0), (0.6, 0.5)],
    "across-one": [(0.93, 0.0), (0.94, 0.5)],
    "slanted": [(0.3125, 0.5), (0.5234375, 0.0)],
}


def _case(first: int, reverse: bool, markers: tuple[int, int], crosser: str) -> Case:
    square = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
    pts = square + STRETCH + CROSSERS[crosser]
    pair = [[4, 5], [6, 7]]
    segs = [pair[first], pair[1 - first]]
    marks = [markers[first], markers[1 - first]]
    if reverse:
        segs[1] = segs[1][::-1]
    if crosser != "none":
        segs.append([8, 9])
        marks.append(2)
    return Case("crafted-overlap", "pzQ", {
        "vertices": np.array(pts, dtype=np.float64),
        "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]] + segs, dtype=np.int32),
        "segment_markers": np.array([1, 1, 1, 1] + marks, dtype=np.int32),
    })


PARAMS = [
    pytest.param(first, reverse, markers, crosser, id=f"{crosser}-first{first}-{'rev' if reverse else 'fwd'}-{markers[0]}{markers[1]}")
    for crosser in CROSSERS
    for first, reverse in itertools.product((0, 1), (False, True))
    for markers in ((0, 1), (1, 0), (2, 3))
]


@pytest.mark.parametrize("first, reverse, markers, crosser", PARAMS)
def test_overlap_markers_like_triangle(runners, first, reverse, markers, crosser):
    run = run_case(runners, _case(first, reverse, markers, crosser), confirmed={}, confirmations=1)
    assert run is not None
    assert run.triangle.status == "ok" and run.ours.status == "ok"
    assert run.verdict.ok, [f"{f.signature}: {f.message}" for f in run.verdict.failures]
    if crosser == "none":  # same vertices, and the markers themselves, not only what the oracles allow
        t, o = run.triangle.result, run.ours.result
        assert np.array_equal(np.asarray(t["vertex_markers"]), np.asarray(o["vertex_markers"]))
