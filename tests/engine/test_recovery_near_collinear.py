"""Segment recovery next to a vertex nearly on the segment's line, past its end
(issue 18, item 4: the guitar outline).

Recovery treats a vertex within a few units in the last place of a segment's
line as on it (rounded crossing points must end pieces).  On the guitar
outline the vertex (32.6, 8.57) is that close to the line of the segment
(33.6, 8.17)-(33.4, 8.25), five segment lengths past its end, and an edge
led to it: recovery marked that edge (and one more) as the segment, left
the segment's own edge unmarked, the spurious subsegments closed a pocket
outside the outline that carving could not reach (eight extra triangles)
and, thin and crossing the domain, kept refinement splitting for ever.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest
import triangle

import instrument
import ruppert_io
from instrument.check import check_mesh

# the shared corpus beside the checkout, or where RUPPERT_CORPUS says
CORPUS = Path(os.environ.get("RUPPERT_CORPUS", Path(__file__).resolve().parents[3] / "shared" / "corpus"))
GUITAR = "caow13__Rupers_Algorithm__guitar.poly"

# 21 vertices of the guitar's outline around (33, 8), closed below
PEGS = [
    [34.2, 7.93], [34.0, 7.72], [34.0, 7.43], [33.9, 7.18], [33.3, 7.42], [33.4, 7.67], [33.6, 7.88],
    [33.6, 8.17], [33.4, 8.25], [33.2, 8.04], [33.2, 7.75], [33.1, 7.5], [32.5, 7.74], [32.6, 7.99],
    [32.8, 8.2], [32.8, 8.49], [32.6, 8.57], [32.4, 8.36], [32.4, 8.07], [32.3, 7.82], [31.7, 8.06],
    [31.7, 6.5], [34.2, 6.5],
]  # fmt: skip


def _outline(points) -> dict:
    n = len(points)
    return {"vertices": np.asarray(points, dtype=float), "segments": np.c_[np.arange(n), (np.arange(n) + 1) % n]}


def test_segment_edge_is_marked_not_the_edge_past_its_end():
    """Before the fix: 29 triangles (Triangle 21), and the segment
    (33.6, 8.17)-(33.4, 8.25) was no subsegment; pq20 did not finish."""
    d = _outline(PEGS)
    r = instrument.triangulate(d, "p")
    t = triangle.triangulate(d, "p")
    assert check_mesh(r, d) == []
    assert len(r["triangles"]) == len(t["triangles"]) == len(PEGS) - 2
    segs = {frozenset(s) for s in np.asarray(r["segments"]).tolist()}
    assert segs == {frozenset(s) for s in d["segments"].tolist()}


@pytest.mark.parametrize("opts", ["pq20", "pq30"])
def test_pegs_refine(opts):
    d = _outline(PEGS)
    r = instrument.triangulate(d, opts)
    t = triangle.triangulate(d, opts)
    assert check_mesh(r, d, min_angle=float(opts[2:])) == []
    assert len(r["vertices"]) <= 1.02 * len(t["vertices"])


def _guitar() -> dict:
    if not (CORPUS / GUITAR).is_file():
        pytest.skip("needs the shared corpus beside the checkout")
    keys = ("vertices", "vertex_markers", "segments", "segment_markers", "holes")
    return {k: v for k, v in ruppert_io.read(CORPUS / GUITAR).items() if k in keys and np.size(v)}


@pytest.mark.parametrize("opts", ["p", "pq20", "pq30"])
def test_guitar_like_triangle(opts):
    d = _guitar()
    r = instrument.triangulate(d, opts)
    t = triangle.triangulate(d, opts)
    assert check_mesh(r, d, min_angle=float(opts[2:]) if "q" in opts else None) == []
    if opts == "p":
        assert (len(r["vertices"]), len(r["triangles"])) == (len(t["vertices"]), len(t["triangles"]))
    else:  # Triangle: 177 and 251 vertices
        assert len(r["vertices"]) <= 1.02 * len(t["vertices"])
        assert len(r["triangles"]) <= 1.02 * len(t["triangles"])
