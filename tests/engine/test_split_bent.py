"""A subsegment split whose point is rounded off the segment's line keeps the
mesh constrained Delaunay (splits._bent_away).

The split point p of o d (length 0.82) lands 5.3e-17 off the line, toward
the apex c, while the far apex y lies 1.25e-16 off it on the other side,
half a length beyond d: p is outside the far triangle's circumcircle.  Taking that
triangle into the cavity anyway (as a point on o d would) left the spoke
p y not locally Delaunay (chains of nearly collinear points under pucS19njQ,
regressions/near-collinear-chain-split-bent.json); the constrained Delaunay
mesh keeps o d as an edge, no longer a subsegment, with the thin triangle
(o, d, p) beside it and the pieces o p and p d as the subsegments, which is
what Triangle's own -p makes of the same vertices and pieces (at unit
scale: at 1e200 the triangle package crashes on them).

The four vertices were found by a search over such configurations (slope
0.7, o and d on a 1/64 grid, c 1e-3 off the midpoint, y half a length beyond
d, one unit of 2^-52 below the line); scaled by 2^-664 and 2^664 (about
1e-200 and 1e200) every predicate sees the same configuration.
"""

from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

import triangle

import instrument
from instrument.check import check_mesh

#: o, d, c, y
VERTICES = [
    ("0x1.8000000000000p-3", "0x1.d999999999999p-3"),
    ("0x1.b800000000000p-1", "0x1.6733333333333p-1"),
    ("0x1.0bc25aee631f9p-1", "0x1.de49ba5e353f8p-2"),
    ("0x1.3200000000000p+0", "0x1.df99999999998p-1"),
]


def _input(scale_exponent: int) -> dict:
    xy = np.array([[float.fromhex(a), float.fromhex(b)] for a, b in VERTICES])
    return {"vertices": np.ldexp(xy, scale_exponent), "segments": np.array([[0, 1]]), "segment_markers": np.array([7])}


def _orient(a, b, c) -> int:
    """Exact sign of orient2d (coordinates are dyadic rationals)."""
    (ax, ay), (bx, by), (cx, cy) = ([Fraction(float(v)) for v in p] for p in (a, b, c))
    det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
    return (det > 0) - (det < 0)


@pytest.mark.parametrize("scale_exponent", [0, -664, 664])
def test_bent_split_keeps_the_edge(scale_exponent):
    tri = _input(scale_exponent)
    result = instrument.triangulate(tri, "pceqS1Q")  # the one Steiner point splits o d (e: edges)
    assert check_mesh(result, pslg=tri) == []
    xy = result["vertices"]
    assert len(xy) == 5
    o, d, c, y, p = range(5)
    # the configuration: p rounded off o d toward c, y on the other side
    assert _orient(xy[o], xy[d], xy[p]) == _orient(xy[o], xy[d], xy[c]) == 1
    assert _orient(xy[o], xy[d], xy[y]) == -1
    triangles = {frozenset(t) for t in result["triangles"].tolist()}
    assert frozenset((o, d, p)) in triangles  # the thin triangle, o d kept
    assert frozenset((o, d, y)) in triangles
    assert not any({p, y} <= t for t in triangles)  # no spoke p y
    # the pieces are the subsegments, with the segment's marker; o d is an
    # edge of no segment (the others are -c's hull)
    segments = {frozenset(s) for s in result["segments"].tolist()}
    assert {frozenset((o, p)), frozenset((p, d))} <= segments
    assert frozenset((o, d)) not in segments
    markers = dict(zip(map(frozenset, result["edges"].tolist()), result["edge_markers"].ravel().tolist()))
    assert markers[frozenset((o, p))] == markers[frozenset((p, d))] == 7
    assert markers[frozenset((o, d))] == 0
    if scale_exponent == 0:  # the same triangles as Triangle's CDT of these vertices and subsegments
        cdt = triangle.triangulate({"vertices": xy, "segments": result["segments"]}, "pQ")
        assert {frozenset(t) for t in cdt["triangles"].tolist()} == triangles


@pytest.mark.parametrize("scale_exponent", [0, -664, 664])
@pytest.mark.parametrize("switches", ["pcqQ", "pcq30Q", "pcDQ", "pcuQ"])
def test_bent_configuration_refines_to_valid_meshes(scale_exponent, switches):
    """Refined on: d lies within 1e-16 of the hull edge o y, so the hull and
    the segment's pieces come within rounding of each other, and the thin
    triangles the bent splits keep are later bounded by subsegments on every
    side (a split point rounded out of one is moved across the line:
    splits._across_line).  Triangle hangs under pcqQ and pcq30Q and runs out
    of precision under pcDQ and pcuQ."""
    tri = _input(scale_exponent)
    result = instrument.triangulate(tri, switches)
    min_angle = {"pcqQ": 20.0, "pcq30Q": 30.0}.get(switches)
    assert check_mesh(result, pslg=tri, min_angle=min_angle) == []
