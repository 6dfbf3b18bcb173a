# cython: language_level=3
"""Finding edges by their end vertices.

Flips and splits change edge numbers, so the later stages remember vertex
pairs and find the edge again when they need it.  ``Mesh.vtri[v]`` keeps,
for each vertex, some edge leaving it (a hint refreshed whenever a triangle
is made around it, see ``remember_corners``); from there ``edge_around``
turns around the vertex.  A stale hint is replaced by walking to the vertex.
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.locate import LOC_ON_VERTEX, walk
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, Index, Mesh, in_output, lnext, lprev


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def origin_edge(m: Mesh, v: Index) -> Index:
    """The remembered edge whose origin is ``v`` if it is still valid, else -1."""
    e: Index = m.vtri[v]
    if e >= 0 and m.stamp[e // 3] > 0 and m.corner[lnext(e)] == v:
        return e
    return -1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def vertex_edge(m: Mesh, v: Index) -> Index:
    """Some edge whose origin is ``v``: the remembered one, or found by
    walking to the vertex from the last live triangle; -1 if ``v`` is in no
    triangle."""
    e: Index = origin_edge(m, v)
    if e >= 0:
        return e
    t: Index = m.nslot - 1
    while t >= 0 and m.stamp[t] <= 0:
        t -= 1
    status: cython.int
    status, e = walk(m, t, m.xy[v, 0], m.xy[v, 1], 4 * m.stamp.shape[0] + 64)
    if status != LOC_ON_VERTEX:
        return -1
    m.vtri[v] = e
    return e


if not cython.compiled:  # compiled, navigate.pxd's inline definition (every insertion calls it)

    def remember_corners(m: Mesh, t: Index) -> None:
        """Record triangle ``t``'s edges as the starting edges of its corners."""
        for k in range(3):
            m.vtri[m.corner[3 * t + k]] = 3 * t + (k + 2) % 3


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _hit(m: Mesh, e: Index, v: Index) -> cython.bint:
    return m.corner[lprev(e)] == v if v >= 0 else m.seg[e] != NO_SEG


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def edge_around(m: Mesh, e0: Index, v: Index) -> Index:
    """Rotate about ``org(e0)``: the first edge out of it whose destination is
    ``v``, or with ``v < 0`` the first subsegment at it (incoming edges are
    checked too, so a subsegment on the boundary is found).  -1 if none."""
    e: Index = e0
    nxt: Index
    tw: Index
    for _ in range(m.stamp.shape[0]):  # counter-clockwise
        if _hit(m, e, v):
            return e
        if v < 0 and m.seg[lprev(e)] != NO_SEG:
            return lprev(e)
        nxt = m.twin[lprev(e)]
        if nxt == e0:
            return -1
        if nxt == NO_EDGE:
            break
        e = nxt
    e = e0
    for _ in range(m.stamp.shape[0]):  # clockwise, for a vertex on the boundary
        tw = m.twin[e]
        if tw == NO_EDGE:
            break
        e = lnext(tw)
        if e == e0:
            break
        if _hit(m, e, v):
            return e
    return -1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def find_edge(m: Mesh, u: Index, v: Index) -> Index:
    """The edge ``u -> v``, or -1 if the two are not joined."""
    e0: Index = vertex_edge(m, u)
    if e0 < 0:
        return -1
    return edge_around(m, e0, v)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def build_vertex_edges(m: Mesh) -> cython.void:
    """``vtri[v]`` = an edge with origin ``v`` for every vertex in the mesh."""
    v: Index
    for t in range(m.nslot):
        if m.stamp[t] > 0:
            for k in range(3):
                v = m.corner[3 * t + k]
                if v >= 0:
                    m.vtri[v] = 3 * t + (k + 2) % 3


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def turn_vertex_edges(m: Mesh, shift: Index) -> cython.void:
    """After ``Mesh.rotate_corners(shift)`` (1 or 2): each vertex's hint
    renumbered as its triangle's edges were (shift 1: lprev, shift 2:
    lnext), so it names the same edge again.  One pass over the vertices
    instead of ``build_vertex_edges``' over every triangle's corners (after
    refinement, six times as many); a stale hint stays a hint
    (``origin_edge`` checks it)."""
    e: Index
    for v in range(m.nvert):
        e = m.vtri[v]
        if e >= 0:
            m.vtri[v] = lprev(e) if shift == 1 else lnext(e)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def list_edges(m: Mesh, constrained: cython.bint, out: cython.longlong[::1]) -> Index:
    """Each edge once, as Triangle lists them, into ``out`` (room for three
    per triangle); returns how many.  Triangle by triangle in slot order, the
    edges (c0, c1), (c1, c2), (c2, c0) -- our edges 2, 0, 1 -- taking an edge
    when it has no neighbour or its neighbour comes later in the output
    (``constrained``: subsegments only)."""
    n: Index = 0
    e: Index
    tw: Index
    for t in range(m.nslot):
        if not in_output(m, t):
            continue
        for j in range(3):
            e = 3 * t + (j + 2) % 3
            if constrained and m.seg[e] < 0:
                continue
            tw = m.twin[e]
            if tw < 0 or (tw // 3 > t and in_output(m, tw // 3)):
                out[n] = e
                n += 1
    return n


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def edge_ends(m: Mesh, edges: cython.longlong[::1], out: cython.int[:, ::1]) -> cython.void:
    """``out[i]`` = (origin, destination) of edge ``edges[i]``."""
    e: Index
    for i in range(edges.shape[0]):
        e = edges[i]
        out[i, 0] = m.corner[lnext(e)]
        out[i, 1] = m.corner[lprev(e)]
