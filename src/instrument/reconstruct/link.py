# cython: language_level=3
"""Refining a given mesh (``-r``): the kernels.

``link_triangles`` checks the given triangles and links neighbours by
matching each directed edge with its reverse; ``attach_segments`` makes the
input segments that are edges subsegments; ``leaves_mesh`` tells whether a
segment that is not an edge lies in the mesh (core/insert.py's
``make_delaunay`` then flips the mesh to a constrained Delaunay one);
``spread_origin`` gives the triangles
segment insertion made an input triangle to descend from.
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.insert import flip, should_flip
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, Index, Mesh, lnext, lprev
from cython.cimports.instrument.core.navigate import vertex_edge
from cython.cimports.instrument.core.predicates import orient2d
from cython.cimports.instrument.core.subsegments import Subsegments
from cython.cimports.instrument.segments.recover import mark_subsegment, turn_to

if not cython.compiled:  # compiled, these are link.pxd's enum
    LINK_OK = 0
    REPEATED_CORNER = 1  # bad = (code, triangle)
    COLLINEAR = 2  # (code, triangle)
    CLOCKWISE = 3  # (code, triangle)
    SAME_SIDE = 4  # (code, triangle, other triangle): a directed edge used twice
    GIVEN_TWICE = 5  # (code, triangle, other triangle)
    THREE_SIDES = 6  # (code, triangle, org, dest): an edge in more than two triangles
    FOLDED = 7  # (code, vertex)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _lower(dx: cython.double, dy: cython.double) -> cython.bint:
    """The direction (dx, dy) has its angle in [pi, 2 pi)."""
    return dy < 0.0 or (dy == 0.0 and dx < 0.0)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def link_triangles(
    corner: cython.int[::1], xy: cython.double[:, ::1], start: cython.longlong[::1], count: cython.longlong[::1],
    order: cython.longlong[::1], dst: cython.int[::1], twin: cython.int[::1], bad: cython.longlong[::1],
) -> cython.int:
    """Check the triangles ``corner`` (3 per triangle) and fill ``twin``.

    ``start`` (V + 1), ``count`` (V), ``order`` and ``dst`` (3T) are scratch:
    on success ``order[start[v]:start[v + 1]]`` lists the edges whose origin
    is ``v`` and ``dst`` their destinations (side by side, so that searching
    a vertex's edges reads one run of memory).  Returns a status code
    (LINK_*); ``bad`` says where the first problem is.
    """
    ne: Index = corner.shape[0]
    nv: Index = count.shape[0]
    a: Index
    b: Index
    c: Index
    s: cython.double
    for t in range(ne // 3):
        a, b, c = corner[3 * t], corner[3 * t + 1], corner[3 * t + 2]
        if a == b or b == c or c == a:
            bad[1] = t
            return REPEATED_CORNER
        s = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1])
        if s <= 0.0:
            bad[1] = t
            return COLLINEAR if s == 0.0 else CLOCKWISE
    # counting sort of the edges by origin
    o: Index
    for v in range(nv + 1):
        start[v] = 0
    for e in range(ne):
        start[corner[lnext(e)] + 1] += 1
    for v in range(nv):
        start[v + 1] += start[v]
        count[v] = start[v]
    for e in range(ne):
        o = corner[lnext(e)]
        order[count[o]] = e
        dst[count[o]] = corner[lprev(e)]
        count[o] += 1
    e2: Index
    d: Index
    same: Index
    tw: Index
    back: Index
    for o2 in range(nv):  # bucket by bucket: the runs of o and d are all we read
        for j in range(start[o2], start[o2 + 1]):
            e2 = order[j]
            d = dst[j]
            same = -1
            for i in range(j + 1, start[o2 + 1]):
                if dst[i] == d:
                    same = order[i]
            if same < 0 and o2 > d:
                continue  # linked (or left on the boundary) from d's run
            tw = NO_EDGE
            back = 0
            for i in range(start[d], start[d + 1]):
                if dst[i] == o2:
                    back += 1
                    tw = order[i]
            if same >= 0 or back > 1:
                bad[1] = e2 // 3
                if same >= 0 and back == 0:
                    bad[2] = same // 3
                    return GIVEN_TWICE if corner[same] == corner[e2] else SAME_SIDE
                bad[2] = o2
                bad[3] = d
                return THREE_SIDES
            twin[e2] = cython.cast(cython.int, tw)
            if tw != NO_EDGE:
                twin[tw] = cython.cast(cython.int, e2)
    # A fan of counter-clockwise triangles turns around its vertex once at
    # most; count how often the fans pass the direction of angle 0.
    for v in range(nv):
        count[v] = 0
    for e in range(ne):
        v2: Index = corner[e]
        a = corner[lnext(e)]
        b = corner[lprev(e)]
        if _lower(xy[a, 0] - xy[v2, 0], xy[a, 1] - xy[v2, 1]) and not _lower(xy[b, 0] - xy[v2, 0], xy[b, 1] - xy[v2, 1]):
            count[v2] += 1
            if count[v2] > 1:
                bad[1] = v2
                return FOLDED
    return LINK_OK


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def attach_segments(
    m: Mesh, segs: Subsegments, start: cython.longlong[::1], order: cython.longlong[::1],
    rows: cython.longlong[:, ::1], in_marker: cython.int[::1], unmatched: cython.longlong[::1],
) -> Index:
    """Make each segment ``rows[i] = (a, b, index)`` that is an edge a
    subsegment, in input order; list the row numbers of the others in
    ``unmatched`` and return how many.  Endpoints of the others take their
    marker here too, so that the first segment in input order wins."""
    n: Index = 0
    a: Index
    b: Index
    s: Index
    e: Index
    mk: cython.int
    for i in range(rows.shape[0]):
        a, b, s = rows[i, 0], rows[i, 1], rows[i, 2]
        e = NO_EDGE
        for j in range(start[a], start[a + 1]):
            if m.corner[lprev(order[j])] == b:
                e = order[j]
        for j in range(start[b], start[b + 1]):
            if m.corner[lprev(order[j])] == a:
                e = order[j]
        if e != NO_EDGE:
            mark_subsegment(m, segs, e, in_marker[s], cython.cast(cython.int, s), False)
        else:
            unmatched[n] = i
            n += 1
            mk = in_marker[s]
            if m.vmark[a] == 0:
                m.vmark[a] = mk
            if m.vmark[b] == 0:
                m.vmark[b] = mk
    return n


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def leaves_mesh(m: Mesh, a: Index, b: Index) -> cython.bint:
    """True if the segment ``a -> b`` does not lie in the mesh (it crosses the
    boundary or a hole).  Walks along it as segment recovery does, through
    vertices exactly on it."""
    xy = m.xy
    v: Index = a
    e0: Index
    e: Index
    where: cython.int
    c: Index
    tw: Index
    y: Index
    s: cython.double
    vx: cython.double
    vy: cython.double
    bx: cython.double
    by: cython.double
    for _ in range(m.nvert + 1):
        if v == b:
            return False
        e0 = vertex_edge(m, v)
        if e0 < 0:
            return True
        e, where = turn_to(m, v, b, e0, 0, -1, -1)  # every vertex may be rounded
        if e < 0:
            return True  # the ray leaves v outside its triangles
        if where == 1:
            v = m.corner[lprev(e)]
            continue
        if where == 2:
            v = m.corner[e]
            continue
        c = lnext(e)  # the edge the segment crosses next
        vx, vy, bx, by = xy[v, 0], xy[v, 1], xy[b, 0], xy[b, 1]
        for _ in range(m.nslot + 1):
            tw = m.twin[c]
            if tw == NO_EDGE:
                return True
            y = m.corner[tw]
            if y == b:
                return False
            s = orient2d(vx, vy, bx, by, xy[y, 0], xy[y, 1])
            if s > 0.0:
                c = lnext(tw)
            elif s < 0.0:
                c = lprev(tw)
            else:  # a vertex exactly on the segment: go on from there
                v = y
                break
    return True


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def spread_origin(m: Mesh, origin: cython.longlong[::1]) -> Index:
    """Give each live triangle without an origin (made by segment insertion)
    that of a neighbour, preferring one not across a subsegment.  Returns how
    many are still without one."""
    left: Index = 1
    changed: cython.bint = True
    best: Index
    tw: Index
    while left > 0 and changed:
        left = 0
        changed = False
        for t in range(m.nslot):
            if m.stamp[t] <= 0 or origin[t] >= 0:
                continue
            best = -1
            for k in range(3):
                tw = m.twin[3 * t + k]
                if tw != NO_EDGE and origin[tw // 3] >= 0 and (best < 0 or m.seg[3 * t + k] == NO_SEG):
                    best = origin[tw // 3]
            if best >= 0:
                origin[t] = best
                changed = True
            else:
                left += 1
    return left
