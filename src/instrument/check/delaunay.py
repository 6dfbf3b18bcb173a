"""Subsegments are edges of the mesh, and the mesh is constrained Delaunay.

Every row of ``segments`` must be an edge of some triangle; every edge shared
by two triangles that is not a subsegment must be locally Delaunay (the
opposite apex not strictly inside the circumcircle, by the exact incircle
sign: cocircular is fine).
"""

from __future__ import annotations

import numpy as np

from .exact import incircle_xy
from .view import Edges, MeshView, Problems, segment_keys


def check_segments(m: MeshView, e: Edges, probs: Problems):
    """Every subsegment is valid and, when there are triangles, an edge of one."""
    if not len(m.S):
        return
    ok, skey = segment_keys(m)
    probs.add("invalid subsegments", [
        f"segment {i} {m.S[i].tolist()} has an index out of range or repeats a vertex"
        for i in np.flatnonzero(~ok)
    ])
    if m.M == 0:
        return
    present = np.isin(skey, e.ukey)
    probs.add("subsegments missing from the triangles", [
        f"segment {i} {m.S[i].tolist()} is not an edge of any triangle"
        for i in np.flatnonzero(ok & ~present)
    ])


def check_delaunay(m: MeshView, e: Edges, probs: Problems):
    """Every edge shared by two good triangles that is not a subsegment is
    locally Delaunay (exact incircle; cocircular is fine)."""
    if not len(e.key):
        return
    g = m.good[e.tri]
    tw = e.twin
    sel = g & (tw >= 0) & (e.a < e.b)
    sel[sel] &= m.good[e.tri[tw[sel]]]
    if len(m.S):
        ok, skey = segment_keys(m)
        sel &= ~np.isin(e.ukey, skey[ok])
    idx = np.flatnonzero(sel)
    if not idx.size:
        return
    A, B, C = m.V[e.a[idx]], m.V[e.b[idx]], m.V[e.apex[idx]]
    D = m.V[e.apex[tw[idx]]]
    s = incircle_xy(A[:, 0], A[:, 1], B[:, 0], B[:, 1], C[:, 0], C[:, 1], D[:, 0], D[:, 1])
    bad = idx[s > 0]
    probs.add("non-Delaunay edges", (
        f"edge {{{int(e.a[k])}, {int(e.b[k])}}} is not locally Delaunay: vertex "
        f"{int(e.apex[e.twin[k]])} (triangle {int(e.tri[e.twin[k]])}) is strictly inside the "
        f"circumcircle of triangle {int(e.tri[k])}"
        for k in bad
    ), len(bad))
