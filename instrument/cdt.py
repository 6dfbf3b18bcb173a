"""Segment recovery: from a Delaunay triangulation to a constrained one.

Segments are inserted in input order from a work stack of pieces ``(a, b,
segment)``, so the kernel can stop when the arrays are full and resume after
the driver grows them.  One piece is recovered as follows.

1. Turn around ``a`` to the triangle the ray ``a -> b`` enters.  If the edge
   ``a b`` exists, mark it.  If a vertex ``v`` lies exactly on the ray
   (exact orientation), mark ``a v`` and continue with ``v -> b``.
2. Otherwise walk along the segment through the triangles it crosses,
   collecting the vertices left and right of it into two chains.  The walk
   stops at ``b``, at a vertex exactly on the segment (the rest becomes a new
   piece), or at a subsegment it would cross.
3. Crossing a subsegment: the two segments intersect.  The intersection point
   (computed along the crossed subsegment) becomes a new vertex that splits
   it; the piece is replaced by ``a -> p`` and ``p -> b``.
4. Otherwise delete the crossed triangles and fill the two pseudo-polygons
   (chain plus segment) with their constrained Delaunay triangulations: the
   chain vertex whose circle through the base edge contains no other chain
   vertex is the apex, and each side recurses (Anglada's algorithm, the one
   Triangle uses to delete vertices).

Subsegment records: every constrained edge piece has its own record (marker,
input segment); ``seg[e]`` holds the record id on both sides of the edge.
Splitting a subsegment gives one half a new record, as Triangle does.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from .counters import C_CREATED, C_DELETED, C_INCIRCLE, C_ORIENT, C_STEINER
from .insert import lawson, split_edge, star_edges
from .jit import kernel
from .locate import LOC_ON_VERTEX, walk
from .mesh import NO_EDGE, NO_SEG, S_NSLOT, S_NVERT, bond, kill_triangle, lnext, lprev, new_triangle, spare_triangles
from .predicates import incircle, orient2d

# status codes of insert_segments
DONE = 0
NEED_ROOM = 1
FAILED = 2

# Segs.size slots
R_NREC = 0  # subsegment records in use
R_SP = 1  # pieces on the work stack


class Segs(NamedTuple):
    """Subsegment records: one per constrained edge piece."""

    marker: np.ndarray  # (R,) int32 boundary marker
    source: np.ndarray  # (R,) int32 input segment it lies on, -1 for hull segments
    size: np.ndarray  # (2,) int64, see R_*


def new_segs(capacity: int) -> Segs:
    return Segs(
        marker=np.zeros(capacity, dtype=np.int32),
        source=np.full(capacity, -1, dtype=np.int32),
        size=np.zeros(2, dtype=np.int64),
    )


def grow_segs(s: Segs, capacity: int) -> Segs:
    cap = max(capacity, 2 * s.marker.shape[0])
    marker = np.zeros(cap, dtype=np.int32)
    source = np.full(cap, -1, dtype=np.int32)
    marker[: s.marker.shape[0]] = s.marker
    source[: s.source.shape[0]] = s.source
    return Segs(marker=marker, source=source, size=s.size)


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
def new_record(segs, marker, source):
    """A new subsegment record; -1 if the table is full."""
    r = segs.size[R_NREC]
    if r >= segs.marker.shape[0]:
        return -1
    segs.size[R_NREC] = r + 1
    segs.marker[r] = marker
    segs.source[r] = source
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
        old = new_record(segs, marker, source)
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
def _fill(m, work, vtri, chain, outer, outer_seg, count, stack):
    """Triangulate the pseudo-polygon ``chain[0..count-1]`` (all but the ends
    left of ``chain[0] -> chain[count-1]``) and return its base edge.

    ``outer[i]`` / ``outer_seg[i]`` are the twin and subsegment record of the
    polygon edge between ``chain[i]`` and ``chain[i+1]``.
    """
    xy = m.xy
    root = -1
    sp = 0
    stack[0] = 0
    stack[1] = count - 1
    stack[2] = -1
    sp = 1
    while sp > 0:
        sp -= 1
        i = stack[3 * sp]
        j = stack[3 * sp + 1]
        pe = stack[3 * sp + 2]
        if j == i + 1:  # a polygon edge: link to the outside
            bond(m, pe, outer[i])
            m.seg[pe] = outer_seg[i]
            continue
        ci = chain[i]
        cj = chain[j]
        k = i + 1
        for q in range(i + 2, j):
            work[C_INCIRCLE] += 1
            ck = chain[k]
            cq = chain[q]
            if incircle(xy[ci, 0], xy[ci, 1], xy[cj, 0], xy[cj, 1], xy[ck, 0], xy[ck, 1], xy[cq, 0], xy[cq, 1]) > 0.0:
                k = q
        t = new_triangle(m, chain[k], ci, cj)
        work[C_CREATED] += 1
        _remember(m, vtri, t)
        if pe < 0:
            root = 3 * t
        else:
            bond(m, 3 * t, pe)
        stack[3 * sp] = i
        stack[3 * sp + 1] = k
        stack[3 * sp + 2] = 3 * t + 2
        stack[3 * sp + 3] = k
        stack[3 * sp + 4] = j
        stack[3 * sp + 5] = 3 * t + 1
        sp += 2
    return root


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
            od = orient2d(ax, ay, xy[d, 0], xy[d, 1], bx, by)
            ox = orient2d(ax, ay, xy[x, 0], xy[x, 1], bx, by)
            if od == 0.0 and (xy[d, 0] - ax) * (bx - ax) + (xy[d, 1] - ay) * (by - ay) > 0.0:
                return e, 1
            if ox == 0.0 and (xy[x, 0] - ax) * (bx - ax) + (xy[x, 1] - ay) * (by - ay) > 0.0:
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
    2 = the walk met subsegment edge ``e`` (the caller splits it); 3 = failed.
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
    # Walk through the crossed triangles.  Chains start at a.  buf holds ten
    # blocks of n: left chain, its twins and records, the same for the right
    # chain, the dead triangles, and three blocks of stack for _fill.
    n = buf.shape[0] // 10
    left, lout, lseg = buf[0:n], buf[n:2 * n], buf[2 * n:3 * n]
    right, rout, rseg = buf[3 * n:4 * n], buf[4 * n:5 * n], buf[5 * n:6 * n]
    dead = buf[6 * n:7 * n]
    ndead = 1
    dead[0] = e // 3
    left[0] = a
    right[0] = a
    left[1] = m.corner[e]
    lout[0] = m.twin[lprev(e)]
    lseg[0] = m.seg[lprev(e)]
    right[1] = m.corner[lprev(e)]
    rout[0] = m.twin[e]
    rseg[0] = m.seg[e]
    nl = 2
    nr = 2
    c = lnext(e)  # the crossed edge, right -> left
    ax, ay, bx, by = xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1]
    end = -1
    while end < 0:
        if m.seg[c] != NO_SEG:
            return 2, -1, c
        tw = m.twin[c]
        if tw == NO_EDGE or ndead >= n or nl >= n or nr >= n:
            return 3, -1, -1
        dead[ndead] = tw // 3
        ndead += 1
        y = m.corner[tw]
        if y == b:
            s = 0.0
        else:
            work[C_ORIENT] += 1
            s = orient2d(ax, ay, bx, by, xy[y, 0], xy[y, 1])
        if s > 0.0:
            lout[nl - 1] = m.twin[lprev(tw)]
            lseg[nl - 1] = m.seg[lprev(tw)]
            left[nl] = y
            nl += 1
            c = lnext(tw)
        elif s < 0.0:
            rout[nr - 1] = m.twin[lnext(tw)]
            rseg[nr - 1] = m.seg[lnext(tw)]
            right[nr] = y
            nr += 1
            c = lprev(tw)
        else:  # y is b, or a vertex exactly on the segment
            lout[nl - 1] = m.twin[lprev(tw)]
            lseg[nl - 1] = m.seg[lprev(tw)]
            left[nl] = y
            nl += 1
            rout[nr - 1] = m.twin[lnext(tw)]
            rseg[nr - 1] = m.seg[lnext(tw)]
            right[nr] = y
            nr += 1
            end = y
    for i in range(ndead):
        kill_triangle(m, dead[i])
        work[C_DELETED] += 1
    stack = buf[7 * n:]
    top = _fill(m, work, vtri, left, lout, lseg, nl, stack)
    # the right chain, reversed, lies left of end -> a
    for i in range(nr // 2):
        j = nr - 1 - i
        right[i], right[j] = right[j], right[i]
    for i in range((nr - 1) // 2):
        j = nr - 2 - i
        rout[i], rout[j] = rout[j], rout[i]
        rseg[i], rseg[j] = rseg[j], rseg[i]
    bottom = _fill(m, work, vtri, right, rout, rseg, nr, stack)
    bond(m, top, bottom)
    mark_subsegment(m, segs, vmark, top, marker, source)
    return (0 if end == b else 1), end, -1


@kernel
def _split_at_crossing(m, work, segs, vmark, vtri, a, b, c, stack, parent, state):
    """Split subsegment edge ``c`` where segment ``a b`` crosses it.

    Returns ``(v, snapped)``: ``v`` is the new vertex, or ``-1`` if the tables
    are full.  If the crossing point rounds onto an existing vertex (three
    segments through one point, or nearly parallel segments), no vertex is
    made: ``v`` is that vertex and ``snapped`` is True when it is not an
    endpoint of ``c`` (the caller then re-routes the crossed subsegment
    through ``v``).
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
    if px == xy[right, 0] and py == xy[right, 1]:
        return right, False
    if px == xy[left, 0] and py == xy[left, 1]:
        return left, False
    status, e = walk(m, work, c // 3, px, py, state, 4 * m.stamp.shape[0] + 64)
    if status == LOC_ON_VERTEX:
        return m.corner[lnext(e)], True
    half = new_record(segs, segs.marker[r], segs.source[r])
    if half < 0:
        return -1, False
    xy[nv, 0] = px
    xy[nv, 1] = py
    parent[nv, 0] = right
    parent[nv, 1] = left
    parent[nv, 2] = t
    m.size[S_NVERT] = nv + 1
    vmark[nv] = segs.marker[r]
    work[C_STEINER] += 1
    on_line = split_edge(m, work, c, nv)  # edge nv -> left, first new triangle
    # the half nv -> left gets the new record, on both sides
    m.seg[on_line] = half
    if m.twin[on_line] != NO_EDGE:
        m.seg[m.twin[on_line]] = half
    n = star_edges(m, on_line // 3, stack)
    last = lawson(m, work, stack, n)
    _remember(m, vtri, last)
    return nv, False


@kernel
def insert_segments(m, work, segs, pieces, in_marker, vmark, vtri, buf, parent, state):
    """Recover every piece ``(a, b, input segment)`` on the ``pieces`` stack
    (the top is next); ``in_marker`` holds the input segments' markers.

    Returns DONE, NEED_ROOM (grow the arrays and call again: nothing was
    half done) or FAILED.
    """
    while segs.size[R_SP] > 0:
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
        kind, v, c = _recover(m, work, segs, vmark, vtri, a, b, in_marker[src], src, buf, state)
        if kind == 0:
            segs.size[R_SP] = sp
        elif kind == 1:
            pieces[sp, 0] = v
        elif kind == 2:
            cross = buf[7 * (buf.shape[0] // 10):]
            r = m.seg[c]
            cr = m.corner[lnext(c)]
            cl = m.corner[lprev(c)]
            p, snapped = _split_at_crossing(m, work, segs, vmark, vtri, a, b, c, cross, parent, state)
            if p < 0:
                return NEED_ROOM
            if snapped:
                # re-route the crossed subsegment through p: free the edge
                # and queue its two halves as pieces of its own segment
                m.seg[c] = NO_SEG
                if m.twin[c] != NO_EDGE:
                    m.seg[m.twin[c]] = NO_SEG
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
