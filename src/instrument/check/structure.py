"""Structural checks: the triangles form an embedded simplicial complex.

Indices in range, distinct corners, finite and strictly counter-clockwise
triangles, no duplicate triangle or coincident used vertices
(``check_triangles``); every directed edge used at most once
(``check_edges``); and no triangle meets the open interior of a boundary
edge of another (``check_overlap``), which with the former proves that the
interiors are disjoint and that no vertex hangs (the package docstring gives
the proof sketch).
"""

from __future__ import annotations

import numpy as np

from .exact import orient_xy
from .boxes import octagons, overlapping
from .view import Edges, MeshView, Problems


def check_triangles(m: MeshView, probs: Problems):
    """Each triangle: indices in range, distinct corners, finite, strictly CCW;
    no two with the same corner set; no two used vertices at one point."""
    T = m.T
    bad = np.flatnonzero(~m.inrange)
    probs.add("triangles with an index out of range", (
        f"triangle {i} has a vertex index out of range [0, {m.N}): {T[i].tolist()}" for i in bad
    ), len(bad))
    bad = np.flatnonzero(m.inrange & ~m.topo)
    probs.add("degenerate triangles", (
        f"triangle {i} repeats a corner: {T[i].tolist()}" for i in bad
    ), len(bad))
    bad = np.flatnonzero(m.topo & ~m.finite)
    probs.add("non-finite coordinates", (
        f"triangle {i} {T[i].tolist()} has a non-finite vertex coordinate" for i in bad
    ), len(bad))
    bad = np.flatnonzero(m.geo & (m.orient < 0))
    probs.add("clockwise triangles", (
        f"triangle {i} {T[i].tolist()} is clockwise (exact orientation < 0)" for i in bad
    ), len(bad))
    bad = np.flatnonzero(m.geo & (m.orient == 0))
    probs.add("zero-area triangles", (
        f"triangle {i} {T[i].tolist()} has zero area (collinear or coincident corners)"
        for i in bad
    ), len(bad))

    # Duplicate triangles (same corner set).
    idx = np.flatnonzero(m.topo)
    if idx.size:
        st = np.sort(m.Tc[idx], axis=1)
        n = np.int64(m.N)
        key = (st[:, 0] * n + st[:, 1]) * n + st[:, 2] if m.N < 2**20 else None
        if key is None:
            _, inv, cnt = np.unique(st, axis=0, return_inverse=True, return_counts=True)
            inv = inv.ravel()
        else:
            _, inv, cnt = np.unique(key, return_inverse=True, return_counts=True)
        groups = np.flatnonzero(cnt > 1)
        probs.add("duplicate triangles", (
            f"duplicate triangles {idx[inv == g].tolist()} "
            f"(corners {sorted(m.Tc[idx[inv == g][0]].tolist())})" for g in groups
        ), len(groups))

    # Coincident vertices used by triangles.
    used = np.unique(m.Tc[m.topo & m.finite])
    if used.size > 1:
        pts = m.V[used]
        order = np.lexsort((pts[:, 1], pts[:, 0]))
        sp = pts[order]
        same = (sp[1:] == sp[:-1]).all(axis=1)
        k = np.flatnonzero(same)
        probs.add("coincident vertices", (
            f"vertices {int(used[order[j]])} and {int(used[order[j + 1]])} used by triangles "
            f"have the same coordinates {sp[j].tolist()}" for j in k
        ), len(k))


def check_edges(m: MeshView, e: Edges, probs: Problems):
    """Every directed edge is used by at most one triangle, every edge by at most two."""
    if len(e.key) == 0:
        return
    sk = e.sorted_key
    dkeys = np.unique(sk[1:][sk[1:] == sk[:-1]])

    def directed(k):
        a, b = divmod(int(k), int(e.n))
        tris = e.tri[e.key == k]
        return (f"directed edge ({a} -> {b}) is used by triangles {tris.tolist()} "
                "(inconsistent orientation, duplicate or overlapping triangles)")

    probs.add("directed edges used twice", map(directed, dkeys), len(dkeys))
    uk, cnt = np.unique(e.ukey, return_counts=True)
    many = np.flatnonzero(cnt > 2)

    def shared(j):
        a, b = divmod(int(uk[j]), int(e.n))
        tris = np.unique(e.tri[e.ukey == uk[j]])
        return f"edge {{{a}, {b}}} is shared by {int(cnt[j])} triangles {tris.tolist()}"

    probs.add("edges shared by more than two triangles", map(shared, many), len(many))


def _open_segment_meets_triangle(p, q, a, b, c):
    """Exact: does the open segment (p, q) meet the closed CCW triangle abc?

    All arguments are (n, 2) arrays.  Closed disjointness is decided by the
    separating-axis theorem (the line pq, or one of the triangle's edges with
    p and q strictly outside); the closed intersection is only an endpoint of
    the segment if that endpoint is in the triangle and the segment leaves the
    triangle immediately across an edge line through it.
    """
    def o(u, v, w):
        return orient_xy(u[:, 0], u[:, 1], v[:, 0], v[:, 1], w[:, 0], w[:, 1])

    sa, sb, sc = o(p, q, a), o(p, q, b), o(p, q, c)
    sep = ((sa > 0) & (sb > 0) & (sc > 0)) | ((sa < 0) & (sb < 0) & (sc < 0))
    p_in = np.ones(len(p), bool)
    q_in = np.ones(len(p), bool)
    exit_p = np.zeros(len(p), bool)
    exit_q = np.zeros(len(p), bool)
    for u, v in ((a, b), (b, c), (c, a)):
        op, oq = o(u, v, p), o(u, v, q)
        sep |= (op < 0) & (oq < 0)
        p_in &= op >= 0
        q_in &= oq >= 0
        exit_p |= (op == 0) & (oq < 0)
        exit_q |= (oq == 0) & (op < 0)
    only_end = (p_in & exit_p) | (q_in & exit_q)
    return ~sep & ~only_end


def segments_meet_triangles(m: MeshView, pa, pb, owner=None):
    """Pairs (good triangle, k) such that the open segment (pa[k], pb[k])
    meets the closed triangle (exact); ``owner[k]`` is skipped."""
    none = np.zeros(0, np.int64), np.zeros(0, np.int64)
    gidx = np.flatnonzero(m.good)
    if not gidx.size or not len(pa):
        return none
    tbox = octagons(m.P[gidx])
    ebox = octagons(np.stack([pa, pb], 1))
    hits_t, hits_e = [none[0]], [none[1]]
    for pt, pe in overlapping(tbox, ebox):  # in chunks: only the hits are kept
        tri = gidx[pt]
        if owner is not None:
            keep = tri != owner[pe]
            tri, pe = tri[keep], pe[keep]
        if not len(tri):
            continue
        hit = _open_segment_meets_triangle(
            pa[pe], pb[pe], m.V[m.Tc[tri, 0]], m.V[m.Tc[tri, 1]], m.V[m.Tc[tri, 2]]
        )
        hits_t.append(tri[hit])
        hits_e.append(pe[hit])
    tri, pe = np.concatenate(hits_t), np.concatenate(hits_e)
    order = np.lexsort((pe, tri))  # chunks come in the tree's order: report by triangle, then segment
    return tri[order], pe[order]


def check_overlap(m: MeshView, e: Edges, probs: Problems):
    """No good triangle meets the open interior of another's boundary edge
    (overlapping triangles or a hanging vertex)."""
    good = m.good
    if not good.any():
        return
    # Boundary edges among the good triangles.
    gmask = good[e.tri]
    key = e.key[gmask]
    twin = e.twin_key[gmask]
    skey = np.sort(key)
    pos = np.minimum(np.searchsorted(skey, twin), len(skey) - 1)
    boundary = skey[pos] != twin
    ea = e.a[gmask][boundary]
    eb = e.b[gmask][boundary]
    owner = e.tri[gmask][boundary]
    if not len(ea):
        probs.add("overlap", ["the triangles have no boundary edge (impossible for a plane mesh)"])
        return
    tri, pe = segments_meet_triangles(m, m.V[ea], m.V[eb], owner)
    probs.add("overlapping triangles", (
        f"triangle {int(t)} {m.T[t].tolist()} meets the interior of boundary edge "
        f"({int(ea[k])}, {int(eb[k])}) of triangle {int(owner[k])}: overlapping triangles "
        "or a hanging vertex"
        for t, k in zip(tri, pe)
    ), len(tri))
