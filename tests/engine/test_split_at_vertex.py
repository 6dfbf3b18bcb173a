"""A subsegment split at an existing vertex that lies on it within rounding
(splits._split_at_apex) leaves a Delaunay mesh: the flip that puts the vertex
on the segment is refused where its new edge would not be locally Delaunay
(an ordinary split is made instead), and is followed by Lawson's flips around
the vertex (cavity.legalize_fan; regressions/near-collinear-chain-apex-flip-
far-edge.json is the case that needs them).

The input is a campaign case (seed 2701, crossing segments with vertices
within 2.6e-17 of other segments) scaled to unit size: one Steiner point
(S5: the four crossings use four) split the segment 22-23 at input vertex 20
and left edge {3, 27} not locally Delaunay."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh

CASE = Path(__file__).parents[1] / "differential" / "regressions" / "split-at-vertex-not-delaunay.json"


def _input(scale_exponent: int) -> dict:
    d = json.loads(CASE.read_text())["input"]
    xy = np.array([float.fromhex(h) for h in d["vertices"]["hex"]]).reshape(-1, 2)
    segs = np.array(d["segments"]["int"]).reshape(-1, 2)
    return {"vertices": np.ldexp(xy, scale_exponent), "segments": segs}


@pytest.mark.parametrize("switches", ["pq5cS5Q", "pq5cQ", "pqcQ", "pq5cAQ"])
@pytest.mark.parametrize("scale_exponent", [0, 664])
def test_split_at_vertex_keeps_the_mesh_delaunay(switches, scale_exponent):
    tri = _input(scale_exponent)
    result = instrument.triangulate(tri, switches)
    assert check_mesh(result, pslg=tri) == []
    if switches == "pq5cS5Q":
        assert len(result["vertices"]) == 29  # 24 input, 4 crossings, the one Steiner point

