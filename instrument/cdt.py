"""Segment recovery: from a Delaunay triangulation to a constrained one.

Segments are inserted in input order from a work stack of pieces ``(a, b,
segment)``, so the kernel can stop when the arrays are full and resume after
the driver grows them.  One piece is recovered as follows.

1. Turn around ``a`` to the triangle the ray ``a -> b`` enters.  If the edge
   ``a b`` exists, mark it.  If a vertex ``v`` lies exactly on the ray
   (exact orientation), mark ``a v`` and continue with ``v -> b``.
2. Otherwise walk along the segment through the triangles it crosses,
   collecting the crossed edges.  The walk stops at ``b``, at a vertex
   exactly on the segment (the rest becomes a new piece), or at a
   subsegment it would cross.
3. Crossing a subsegment: the two segments intersect.  The intersection point
   (computed along the crossed subsegment) becomes a new vertex that splits
   it; the piece is replaced by ``a -> p`` and ``p -> b``.
4. Otherwise flip the crossed edges away (Sloan's algorithm: flip any
   crossed edge whose quadrilateral is strictly convex, until none crosses;
   one always is), mark the segment, and restore the constrained Delaunay
   property by Lawson flips of the new edges.  Flipping, unlike deleting the
   crossed triangles and re-filling the two sides, needs no assumption about
   the shape of the crossed region (it can wrap around a vertex whose whole
   star it crosses).

Subsegment records: every constrained edge piece has its own record (marker,
input segment); ``seg[e]`` holds the record id on both sides of the edge.
Splitting a subsegment gives one half a new record, as Triangle does.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .counters import C_ORIENT, C_STEINER
from .insert import flip, lawson, should_flip, split_edge, split_triangle, star_edges
from .jit import kernel, kernel_inline
from .locate import LOC_INSIDE, LOC_ON_EDGE, LOC_ON_VERTEX, walk
from .mesh import NO_EDGE, NO_SEG, S_NSLOT, S_NVERT, lnext, lprev, spare_triangles
from .predicates import orient2d

# status codes of insert_segments
DONE = 0
NEED_ROOM = 1  # grow the mesh, records or piece stack
FAILED = 2
NEED_BUFFER = 3  # a segment crosses more triangles than the scratch buffer holds

# Segs.size slots
R_NREC = 0  # subsegment records in use
R_SP = 1  # pieces on the work stack


class Segs(NamedTuple):
    """Subsegment records: one per constrained edge piece."""

    marker: np.ndarray  # (R,) int32 boundary marker
    source: np.ndarray  # (R,) int32 input segment it lies on, -1 for hull segments
    ends: np.ndarray  # (R, 2) int32 the segment's end vertices (the piece first recovered)
    size: np.ndarray  # (2,) int64, see R_*


def new_segs(capacity: int) -> Segs:
    return Segs(
        marker=np.zeros(capacity, dtype=np.int32),
        source=np.full(capacity, -1, dtype=np.int32),
        ends=np.full((capacity, 2), -1, dtype=np.int32),
        size=np.zeros(2, dtype=np.int64),
    )


def grow_segs(s: Segs, capacity: int) -> Segs:
    cap = max(capacity, 2 * s.marker.shape[0])
    marker = np.zeros(cap, dtype=np.int32)
    source = np.full(cap, -1, dtype=np.int32)
    ends = np.full((cap, 2), -1, dtype=np.int32)
    marker[: s.marker.shape[0]] = s.marker
    source[: s.source.shape[0]] = s.source
    ends[: s.ends.shape[0]] = s.ends
    return Segs(marker=marker, source=source, ends=ends, size=s.size)


@kernel
def _org_edge(m, vtri, v):
    """Some edge whose origin is ``v``: the remembered one if still valid,
    otherwise found by walking to the vertex from the last live triangle."""
    e = vtri[v]
    if e >= 0 and m.stamp[e // 3] > 0 and m.corner[lnext(e)] == v:
        return e
    return -1


@kernel
def _find_vertex(m, work, vtri, v, state):
    e = _org_edge(m, vtri, v)
    if e >= 0:
        return e
    t = m.size[S_NSLOT] - 1
    while t >= 0 and m.stamp[t] <= 0:
        t -= 1
    status, e = walk(m, work, t, m.xy[v, 0], m.xy[v, 1], state, 4 * m.stamp.shape[0] + 64)
    if status != LOC_ON_VERTEX:
        return -1
    vtri[v] = e
    return e


@kernel
def _remember(m, vtri, t):
    """Record triangle ``t``'s edges as starting edges of its corners."""
    for k in range(3):
        vtri[m.corner[3 * t + k]] = 3 * t + (k + 2) % 3


@kernel
def new_record(segs, marker, source, a, b):
    """A new subsegment record on the segment from ``a`` to ``b``; -1 if the table is full."""
    r = segs.size[R_NREC]
    if r >= segs.marker.shape[0]:
        return -1
    segs.size[R_NREC] = r + 1
    segs.marker[r] = marker
    segs.source[r] = source
    segs.ends[r, 0] = a
    segs.ends[r, 1] = b
    return r


@kernel
def mark_subsegment(m, segs, vmark, e, marker, source):
    """Make edge ``e`` (both sides) a subsegment of input segment ``source``.

    A new edge gets a new record.  An edge that already is a subsegment (a
    duplicate segment) keeps its record, taking ``marker`` if its own is 0.
    Endpoints whose marker is 0 take the subsegment's.
    """
    old = m.seg[e]
    if old == NO_SEG:
        old = new_record(segs, marker, source, m.corner[lnext(e)], m.corner[lprev(e)])
        m.seg[e] = old
        if m.twin[e] != NO_EDGE:
            m.seg[m.twin[e]] = old
    elif segs.marker[old] == 0:
        segs.marker[old] = marker
    mk = segs.marker[old]
    o = m.corner[lnext(e)]
    d = m.corner[lprev(e)]
    if vmark[o] == 0:
        vmark[o] = mk
    if vmark[d] == 0:
        vmark[d] = mk


@kernel
def _side(ax, ay, bx, by, px, py):
    """orient2d of p against the line a -> b, but 0 for a point within a few
    units in the last place of the line: a rounded crossing vertex starts
    pieces that are off their segment's line by that much, and the input
    vertices on the segment must still end those pieces."""
    s = orient2d(ax, ay, bx, by, px, py)
    length = np.sqrt((bx - ax) ** 2 + (by - ay) ** 2)
    tol = 2.0**-48 * (abs(ax) + abs(ay) + abs(bx) + abs(by))
    return 0.0 if abs(s) <= tol * length else s


@kernel
def _ahead(xy, a, b, v):
    """For ``v`` on the line ``a -> b`` (up to ``_side``'s tolerance): is it
    ``b`` or between ``a`` and ``b``?  A vertex past ``b`` (or behind ``a``)
    is not on the segment: with the tolerance it can look collinear while
    both ``a b`` and ``a v`` are edges (the guitar outline: taking it marked
    an edge that is no segment and left the segment's own edge unmarked)."""
    if v == b:
        return True
    dot = (xy[v, 0] - xy[a, 0]) * (xy[b, 0] - xy[a, 0]) + (xy[v, 1] - xy[a, 1]) * (xy[b, 1] - xy[a, 1])
    return 0.0 < dot < (xy[b, 0] - xy[a, 0]) ** 2 + (xy[b, 1] - xy[a, 1]) ** 2


@kernel
def _turn_to(m, work, a, b, e0):
    """Turn around ``a`` (from edge ``e0``, origin ``a``) to the edge ``e``
    (origin ``a``) whose triangle contains the start of the ray ``a -> b``.

    Returns ``(e, where)``: where = 0 if ``b`` is strictly inside the wedge
    (the ray crosses the edge opposite ``a``), 1 if ``dest(e)`` lies on the
    ray, 2 if ``apex(e)`` lies on the ray; (-1, -1) if no triangle is found.
    """
    xy = m.xy
    ax, ay, bx, by = xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1]
    for direction in range(2):  # counter-clockwise, then clockwise from e0
        e = e0
        for _ in range(m.stamp.shape[0]):
            d = m.corner[lprev(e)]
            x = m.corner[e]
            work[C_ORIENT] += 2
            od = -_side(ax, ay, bx, by, xy[d, 0], xy[d, 1])
            ox = -_side(ax, ay, bx, by, xy[x, 0], xy[x, 1])
            if od == 0.0 and _ahead(xy, a, b, d):
                return e, 1
            if ox == 0.0 and _ahead(xy, a, b, x):
                return e, 2
            if od > 0.0 and ox < 0.0:
                return e, 0
            if direction == 0:
                nxt = m.twin[lprev(e)]
            else:
                tw = m.twin[e]
                nxt = NO_EDGE if tw == NO_EDGE else lnext(tw)
            if nxt == NO_EDGE or nxt == e0:
                break
            e = nxt
    return -1, -1


@kernel
def _recover(m, work, segs, vmark, vtri, a, b, marker, source, buf, state):
    """Recover one piece ``a -> b`` of input segment ``source``.

    Returns ``(kind, v, e)``: kind 0 = done; 1 = continue with ``v -> b``;
    2 = the walk met subsegment edge ``e`` (the caller splits it); 3 = failed;
    4 = ``buf`` is too small (nothing was changed).
    """
    xy = m.xy
    e0 = _find_vertex(m, work, vtri, a, state)
    if e0 < 0:
        return 3, -1, -1
    e, where = _turn_to(m, work, a, b, e0)
    if e < 0:
        return 3, -1, -1
    if where == 1:  # dest(e) on the ray
        d = m.corner[lprev(e)]
        mark_subsegment(m, segs, vmark, e, marker, source)
        return (0 if d == b else 1), d, -1
    if where == 2:  # apex(e) on the ray: the edge apex -> a is lprev(e)
        x = m.corner[e]
        mark_subsegment(m, segs, vmark, lprev(e), marker, source)
        return (0 if x == b else 1), x, -1
    # Walk through the crossed triangles, queueing the crossed edges as
    # vertex pairs (right, left): flips change edge ids, not vertex pairs.
    n = buf.shape[0] // 4
    qr, ql = buf[0:n], buf[n:2 * n]
    stack = buf[2 * n:]
    nq = 0
    c = lnext(e)  # the crossed edge, right -> left
    ax, ay, bx, by = xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1]
    end = -1
    while end < 0:
        if m.seg[c] != NO_SEG:
            return 2, -1, c
        tw = m.twin[c]
        if tw == NO_EDGE:
            return 3, -1, -1
        if nq >= n:
            return 4, -1, -1
        qr[nq] = m.corner[lnext(c)]
        ql[nq] = m.corner[lprev(c)]
        nq += 1
        y = m.corner[tw]
        if y == b:
            s = 0.0
        else:
            work[C_ORIENT] += 1
            s = _side(ax, ay, bx, by, xy[y, 0], xy[y, 1])
        if s > 0.0:
            c = lnext(tw)
        elif s < 0.0:
            c = lprev(tw)
        else:  # y is b, or a vertex exactly on the segment
            end = y
    if not _flip_out(m, work, vtri, a, end, qr, ql, nq, n, stack, state):
        return 3, -1, -1
    e = _edge(m, work, vtri, a, end, state)
    if e < 0:
        return 3, -1, -1
    mark_subsegment(m, segs, vmark, e, marker, source)
    if not _restore(m, work, vtri, stack, state):
        return 3, -1, -1
    return (0 if end == b else 1), end, -1


@kernel
def _hit(m, e, v):
    return m.corner[lprev(e)] == v if v >= 0 else m.seg[e] != NO_SEG


@kernel
def edge_around(m, e0, v):
    """Rotate about ``org(e0)``: the first edge out of it whose destination is
    ``v``, or with ``v < 0`` the first subsegment at it (incoming edges are
    checked too, so a subsegment on the boundary is found).  -1 if none."""
    e = e0
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


@kernel
def _edge(m, work, vtri, u, v, state):
    """The edge ``u -> v``, or -1 if the two are not joined."""
    e0 = _find_vertex(m, work, vtri, u, state)
    if e0 < 0:
        return -1
    return edge_around(m, e0, v)


@kernel
def _flip_and_remember(m, work, vtri, e):
    t1 = flip(m, work, e)
    _remember(m, vtri, t1)
    _remember(m, vtri, m.twin[3 * t1 + 1] // 3)
    return t1


@kernel
def _flip_out(m, work, vtri, a, b, qr, ql, nq, n, stack, state):
    """Flip every queued edge (a circular queue of ``nq`` vertex pairs that
    cross ``a b``) until none crosses; new edges that do not cross go on
    ``stack`` (from ``stack[0]`` = count) for the Delaunay pass."""
    xy = m.xy
    ax, ay, bx, by = xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1]
    stack[0] = 0
    head = 0
    left = nq
    tries = 0
    while left > 0:
        tries += 1
        if tries > 4 * nq * nq + 64:  # Sloan's loop always finds a flip
            return False
        u = qr[head]
        v = ql[head]
        head = (head + 1) % n
        left -= 1
        e = _edge(m, work, vtri, u, v, state)
        if e < 0:
            return False
        x = m.corner[e]
        y = m.corner[m.twin[e]]
        # the flipped triangles (x, u, y) and (x, y, v) must be counter-clockwise
        work[C_ORIENT] += 2
        convex = (
            orient2d(xy[x, 0], xy[x, 1], xy[u, 0], xy[u, 1], xy[y, 0], xy[y, 1]) > 0.0
            and orient2d(xy[x, 0], xy[x, 1], xy[y, 0], xy[y, 1], xy[v, 0], xy[v, 1]) > 0.0
        )
        if not convex:
            qr[(head + left) % n] = u
            ql[(head + left) % n] = v
            left += 1
            continue
        _flip_and_remember(m, work, vtri, e)
        work[C_ORIENT] += 2
        sx = orient2d(ax, ay, bx, by, xy[x, 0], xy[x, 1])
        sy = orient2d(ax, ay, bx, by, xy[y, 0], xy[y, 1])
        if x != a and x != b and y != a and y != b and sx * sy < 0.0:
            # still crosses: queue it again, right end first
            r, l = (x, y) if sx < 0.0 else (y, x)
            qr[(head + left) % n] = r
            ql[(head + left) % n] = l
            left += 1
        else:
            k = stack[0]
            if 2 * k + 3 > stack.shape[0]:
                return False
            stack[2 * k + 1] = x
            stack[2 * k + 2] = y
            stack[0] = k + 1
    return True


@kernel
def _restore(m, work, vtri, stack, state):
    """Lawson's flips over the edges (vertex pairs) on ``stack`` until every
    unconstrained one is locally Delaunay; each flip queues its quadrilateral's
    four sides."""
    k = stack[0]
    while k > 0:
        k -= 1
        u = stack[2 * k + 1]
        v = stack[2 * k + 2]
        e = _edge(m, work, vtri, u, v, state)
        if e < 0 or not should_flip(m, work, e):  # flipped away since, or fine
            continue
        x = np.int64(m.corner[e])
        y = np.int64(m.corner[m.twin[e]])
        if 2 * (k + 4) + 1 > stack.shape[0]:
            return False
        _flip_and_remember(m, work, vtri, e)
        for side in range(4):  # the quadrilateral x, u, y, v
            stack[2 * k + 1] = (x, u, y, v)[side]
            stack[2 * k + 2] = (u, y, v, x)[side]
            k += 1
    return True


@kernel
def _near(xy, v, px, py, tol):
    return abs(xy[v, 0] - px) <= tol and abs(xy[v, 1] - py) <= tol


@kernel_inline
def set_parent(parent, v, p0, p1, p2, s, t):
    """Record that new vertex ``v``'s attributes are a0 + s (a1 - a0) + t (a2 - a0)
    of vertices p0, p1, p2 (``output.interpolate_attributes`` reads it); the
    table has no rows when the input has no vertex attributes."""
    if v < parent.shape[0]:
        parent[v, 0] = p0
        parent[v, 1] = p1
        parent[v, 2] = p2
        parent[v, 3] = s
        parent[v, 4] = t


@kernel
def _split_at_crossing(m, work, segs, vmark, vtri, a, b, c, stack, parent, state):
    """Make a vertex where segment ``a b`` crosses subsegment edge ``c``.

    Returns ``(v, reroute)``, ``v = -1`` if the tables are full.  The
    crossing point is rounded, so it is inserted where it actually lies:
    exactly on ``c`` it splits ``c``; anywhere else (or on an existing
    vertex) ``reroute`` is True and the caller re-routes ``c`` through it.
    The mesh stays a valid triangulation either way; forcing a rounded
    point onto ``c`` could fold it.  A point within a few units in the last
    place of one of the four endpoints is taken to be that endpoint: a
    crossing vertex made earlier is only nearly on its lines, so later
    segments through the same point would otherwise cross them again a
    rounding error away, for ever.
    """
    xy = m.xy
    nv = m.size[S_NVERT]
    r = m.seg[c]
    left = m.corner[lprev(c)]
    right = m.corner[lnext(c)]
    # parameter along the crossed subsegment, right -> left
    ex, ey = xy[b, 0] - xy[a, 0], xy[b, 1] - xy[a, 1]
    tx, ty = xy[left, 0] - xy[right, 0], xy[left, 1] - xy[right, 1]
    den = ty * ex - tx * ey
    t = 0.5
    if den != 0.0:
        t = (ey * (xy[right, 0] - xy[a, 0]) - ex * (xy[right, 1] - xy[a, 1])) / den
        t = min(max(t, 0.0), 1.0)
    px = xy[right, 0] + t * tx
    py = xy[right, 1] + t * ty
    tol = 2.0**-48 * (abs(px) + abs(py)) + 1e-300
    if _near(xy, right, px, py, tol):
        return right, False
    if _near(xy, left, px, py, tol):
        return left, False
    if _near(xy, a, px, py, tol):
        return a, True
    if _near(xy, b, px, py, tol):
        return b, True
    status, e = walk(m, work, c // 3, px, py, state, 4 * m.stamp.shape[0] + 64)
    if status == LOC_ON_VERTEX:
        return m.corner[lnext(e)], True
    if status != LOC_INSIDE and status != LOC_ON_EDGE:
        # rounded off the mesh (c is on the boundary): use c's nearer end
        return (right if t < 0.5 else left), False
    half = new_record(segs, segs.marker[r], segs.source[r], segs.ends[r, 0], segs.ends[r, 1])
    if half < 0:
        return -1, False
    xy[nv, 0] = px
    xy[nv, 1] = py
    set_parent(parent, nv, right, left, right, t, 0.0)
    m.size[S_NVERT] = nv + 1
    vmark[nv] = segs.marker[r]
    work[C_STEINER] += 1
    reroute = True
    if status == LOC_INSIDE:
        first = split_triangle(m, work, e // 3, nv)
    else:
        reroute = e != c and e != m.twin[c]
        split = m.seg[e]
        on_line = split_edge(m, work, e, nv)  # edge nv -> dest(e), first new triangle
        if split != NO_SEG:  # the half nv -> dest(e) gets the new record
            m.seg[on_line] = half
            if m.twin[on_line] != NO_EDGE:
                m.seg[m.twin[on_line]] = half
        first = on_line // 3
    n = star_edges(m, first, stack)
    last = lawson(m, work, stack, n)
    _remember(m, vtri, last)
    return nv, reroute


@kernel
def insert_segments(m, work, segs, pieces, in_marker, vmark, vtri, buf, parent, state, steps):
    """Recover every piece ``(a, b, input segment)`` on the ``pieces`` stack
    (the top is next); ``in_marker`` holds the input segments' markers.

    Returns DONE, NEED_ROOM or NEED_BUFFER (grow and call again: nothing was
    half done) or FAILED.  ``steps = [pieces handled, input segments]``:
    the pieces handled are bounded by the segments and vertices, so that
    rounded crossing points that re-route each other cannot loop for ever.
    """
    while segs.size[R_SP] > 0:
        if steps[0] > 8 * (steps[1] + m.size[S_NVERT]) + 1024:
            return FAILED
        steps[0] += 1
        if (
            m.size[S_NVERT] >= m.xy.shape[0]
            or spare_triangles(m) < 8
            or segs.size[R_NREC] + 2 > segs.marker.shape[0]
            or segs.size[R_SP] + 4 > pieces.shape[0]
        ):
            return NEED_ROOM
        sp = segs.size[R_SP] - 1
        a = pieces[sp, 0]
        b = pieces[sp, 1]
        src = pieces[sp, 2]
        marker = 1 if src < 0 else in_marker[src]  # -c hull segments have no input row
        kind, v, c = _recover(m, work, segs, vmark, vtri, a, b, marker, src, buf, state)
        if kind == 0:
            segs.size[R_SP] = sp
        elif kind == 1:
            pieces[sp, 0] = v
        elif kind == 4:
            steps[0] -= 1
            return NEED_BUFFER
        elif kind == 2:
            cross = buf
            r = m.seg[c]
            cr = m.corner[lnext(c)]
            cl = m.corner[lprev(c)]
            p, reroute = _split_at_crossing(m, work, segs, vmark, vtri, a, b, c, cross, parent, state)
            if p < 0:
                return NEED_ROOM
            if reroute:
                # re-route the crossed subsegment through p: free the edge
                # and queue its two halves as pieces of its own segment
                c = _edge(m, work, vtri, cr, cl, state)  # its id may have changed
                if c < 0:
                    return FAILED
                m.seg[c] = NO_SEG
                if m.twin[c] != NO_EDGE:
                    m.seg[m.twin[c]] = NO_SEG
                # freed, the edge may no longer be Delaunay
                cross[0] = 1
                cross[1] = cr
                cross[2] = cl
                if not _restore(m, work, vtri, cross, state):
                    return FAILED
                src_c = segs.source[r]
                pieces[sp + 1, 0] = cr
                pieces[sp + 1, 1] = p
                pieces[sp + 1, 2] = src_c
                pieces[sp + 2, 0] = p
                pieces[sp + 2, 1] = cl
                pieces[sp + 2, 2] = src_c
                sp += 2
            elif p == a or p == b:  # cannot happen: c never ends at a or b
                return FAILED
            if p != a and p != b:
                pieces[sp + 1, 0] = pieces[segs.size[R_SP] - 1, 0]  # a
                pieces[segs.size[R_SP] - 1, 0] = p  # p -> b later
                pieces[sp + 1, 1] = p  # a -> p first
                pieces[sp + 1, 2] = src
                sp += 1
            segs.size[R_SP] = sp + 1
        else:
            return FAILED
    return DONE


@kernel
def mark_hull(m, segs, vmark, source):
    """-c (or refinement of a point set): every boundary edge becomes a
    subsegment with marker 1; one that already is keeps its record but takes
    marker 1 if its own is 0.  Returns False if records ran out."""
    for t in range(m.size[S_NSLOT]):
        if m.stamp[t] <= 0:
            continue
        for k in range(3):
            e = 3 * t + k
            if m.twin[e] == NO_EDGE:
                if segs.size[R_NREC] >= segs.marker.shape[0]:
                    return False
                mark_subsegment(m, segs, vmark, e, 1, source)
    return True


@kernel
def build_vertex_edges(m, vtri):
    """``vtri[v]`` = an edge with origin ``v`` for every vertex in the mesh."""
    for t in range(m.size[S_NSLOT]):
        if m.stamp[t] > 0:
            for k in range(3):
                v = m.corner[3 * t + k]
                if v >= 0:
                    vtri[v] = 3 * t + (k + 2) % 3


@kernel
def count_inverted(m):
    """Live finite triangles that are not strictly counter-clockwise (exact)."""
    xy = m.xy
    bad = 0
    for t in range(m.size[S_NSLOT]):
        if m.stamp[t] <= 0:
            continue
        a, b, c = m.corner[3 * t], m.corner[3 * t + 1], m.corner[3 * t + 2]
        if a < 0 or b < 0 or c < 0:
            continue
        if orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1]) <= 0.0:
            bad += 1
    return bad
