# cython: language_level=3
"""Holes, concavities and regions (Triangle's ``carveholes``, ``-p`` without
``-r``): the kernels.

Triangles are "infected" from the convex hull (unless ``-c``) and from each
hole point, and the infection spreads across every edge that is not a
subsegment.  Infected triangles are deleted; a subsegment that ends up with
live triangles on one side only becomes a boundary (marker 0 -> 1, and its
endpoints likewise).  Regions are then flood-filled the same way, each in
input order, so later regions overwrite earlier ones.

``Mesh.tflag`` marks the infected triangles while a carve runs (and is
cleared after).
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.locate import LOC_INSIDE, LOC_ON_EDGE, LOC_ON_VERTEX, walk
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, Index, Mesh, kill_triangle, least_hull_edge, lnext, lprev, next_hull_edge
from cython.cimports.instrument.core.predicates import orient2d
from cython.cimports.instrument.core.subsegments import Subsegments
from cython.cimports.instrument.counters import C_DELETED


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _boundary_marks(m: Mesh, segs: Subsegments, e: Index, endpoints_always: cython.bint) -> cython.void:
    r: Index = m.seg[e]
    was_zero: cython.bint = segs.marker[r] == 0
    if was_zero:
        segs.marker[r] = 1
    v: Index
    if was_zero or endpoints_always:
        v = m.corner[lnext(e)]
        if m.vmark[v] == 0:
            m.vmark[v] = 1
        v = m.corner[lprev(e)]
        if m.vmark[v] == 0:
            m.vmark[v] = 1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def start_hull_edge(m: Mesh) -> Index:
    """The hull edge Triangle's outer-space handle holds, where its hull
    walk and its location of hole and region points start: NO_EDGE without
    a hull.  Only points strictly left of its line are located, so a hole
    point on that edge's line is ignored.

    The handle is ``Mesh.outer_space_edge``: each triangulator sets it
    (delaunay/__init__.py says where), and the in-place flips and splits of
    segment recovery move it as Triangle's bonds to outer space do.  The
    scan for the edge leaving the least (x, y) hull vertex (Triangle's
    handle after divide and conquer) stands in only where no handle is
    known: a mesh read back from triangles (``-r``), which no triangulator
    built, and a handle left on an edge no longer on the hull by the
    rewrites that do not follow it (the plain flips and splits of
    near-degenerate segment recovery, which Triangle does not make)."""
    e: Index = m.outer_space_edge
    if e >= 0 and m.stamp[e // 3] > 0 and m.twin[e] == NO_EDGE:
        return e
    return least_hull_edge(m)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def infect_hull(m: Mesh, segs: Subsegments, queue: cython.longlong[::1], start: Index) -> Index:
    """Walk the convex hull counter-clockwise from hull edge ``start``
    (``start_hull_edge``), as Triangle does: a triangle on a hull
    edge that is not a subsegment is infected and appended to ``queue``; a
    hull subsegment with marker 0 becomes a boundary, but only if its
    triangle was not infected earlier in the walk (through another of its
    hull edges), so the walk's order decides some endpoints' markers.
    Returns the queue length."""
    n: Index = 0
    e0: Index = start
    e: Index = e0
    t: Index
    f: Index
    while e != NO_EDGE:
        t = e // 3
        if not m.tflag[t]:
            if m.seg[e] == NO_SEG:
                m.tflag[t] = 1
                queue[n] = t
                n += 1
            else:
                _boundary_marks(m, segs, e, False)
        f = next_hull_edge(m, e)
        e = f if f != e0 else NO_EDGE
    return n


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def locate_points(
    m: Mesh, pts: cython.double[:, ::1], lo: cython.double[::1], hi: cython.double[::1], found: cython.longlong[:, ::1],
    start: Index,
) -> cython.void:
    """For each point inside the box ``lo..hi`` and strictly left of the
    line of hull edge ``start`` (``start_hull_edge``; NO_EDGE: no such
    test), as Triangle locates hole and region points: the triangle holding
    it (``found[i, 0]``) and that triangle's stamp (``found[i, 1]``); -1
    otherwise, or if it is outside the mesh."""
    t0: Index = m.nslot - 1
    while t0 >= 0 and m.stamp[t0] <= 0:
        t0 -= 1
    x: cython.double
    y: cython.double
    status: cython.int
    e: Index
    for i in range(pts.shape[0]):
        found[i, 0] = -1
        found[i, 1] = 0
        x = pts[i, 0]
        y = pts[i, 1]
        if t0 < 0 or not (lo[0] <= x <= hi[0] and lo[1] <= y <= hi[1]):
            continue
        if start != NO_EDGE and orient2d(
            m.xy[m.corner[lnext(start)], 0], m.xy[m.corner[lnext(start)], 1],
            m.xy[m.corner[lprev(start)], 0], m.xy[m.corner[lprev(start)], 1], x, y,
        ) <= 0.0:
            continue
        status, e = walk(m, t0, x, y, 4 * m.stamp.shape[0] + 64)
        if status == LOC_INSIDE or status == LOC_ON_EDGE or status == LOC_ON_VERTEX:
            found[i, 0] = e // 3
            found[i, 1] = m.stamp[e // 3]


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def plague(m: Mesh, segs: Subsegments, queue: cython.longlong[::1], n: Index) -> Index:
    """Spread the infection from ``queue[:n]`` across non-subsegment edges and
    delete the infected triangles (clearing their flags).  Returns how many
    were deleted.

    As in Triangle, a subsegment is made a boundary (marker 0 -> 1, endpoints
    0 -> 1) when the infection reaches it while the other side is still
    healthy, even if that side is infected later; so the endpoints of
    segments inside holes get marker 1 too.
    """
    head: Index = 0
    t: Index
    e: Index
    tw: Index
    while head < n:
        t = queue[head]
        head += 1
        for k in range(3):  # edges 2, 0, 1: Triangle's orientations 0, 1, 2 (the order it infects in)
            e = 3 * t + (k + 2) % 3
            tw = m.twin[e]
            if tw == NO_EDGE or m.tflag[tw // 3]:
                continue
            if m.seg[e] != NO_SEG:
                _boundary_marks(m, segs, e, True)
            else:
                m.tflag[tw // 3] = 1
                queue[n] = tw // 3
                n += 1
    for i in range(n):
        t = queue[i]
        for k in range(3):
            tw = m.twin[3 * t + k]
            if tw != NO_EDGE and not m.tflag[tw // 3]:
                m.twin[tw] = NO_EDGE
        kill_triangle(m, t)
        m.work[C_DELETED] += 1
    for i in range(n):
        m.tflag[queue[i]] = 0
    return n


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def spread_regions(
    m: Mesh, found: cython.longlong[:, ::1], values: cython.double[::1], out: cython.double[::1],
    seen: cython.longlong[::1], stack: cython.longlong[::1],
) -> cython.void:
    """Flood-fill each located region (in order) across non-subsegment edges,
    writing ``values[i]`` into ``out[t]`` for its triangles."""
    t0: Index
    mark: Index
    n: Index
    t: Index
    e: Index
    tw: Index
    for i in range(found.shape[0]):
        t0 = found[i, 0]
        if t0 < 0 or m.stamp[t0] != found[i, 1]:
            continue  # outside the mesh, or eaten by a hole
        mark = i + 1
        seen[t0] = mark
        stack[0] = t0
        n = 1
        while n > 0:
            n -= 1
            t = stack[n]
            out[t] = values[i]
            for k in range(3):
                e = 3 * t + k
                tw = m.twin[e]
                if tw != NO_EDGE and m.seg[e] == NO_SEG and seen[tw // 3] != mark:
                    seen[tw // 3] = mark
                    stack[n] = tw // 3
                    n += 1
