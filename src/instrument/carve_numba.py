"""(Transitional: the numba version of carve/infect.py, used until the old pipeline goes.)

Holes, concavities and regions (Triangle's ``carveholes``, ``-p`` without ``-r``).

Triangles are "infected" from the convex hull (unless ``-c``) and from each
hole point, and the infection spreads across every edge that is not a
subsegment.  Infected triangles are deleted; a subsegment that ends up with
live triangles on one side only becomes a boundary (marker 0 -> 1, and its
endpoints likewise).  Regions are then flood-filled the same way, each in
input order, so later regions overwrite earlier ones.
"""

from __future__ import annotations

from .counters import C_DELETED
from .jit import kernel
from .locate import LOC_INSIDE, LOC_ON_EDGE, LOC_ON_VERTEX, walk
from .mesh import NO_EDGE, NO_SEG, S_NSLOT, kill_triangle, lnext, lprev


@kernel
def _boundary_marks(m, segs, vmark, e, endpoints_always):
    r = m.seg[e]
    was_zero = segs.marker[r] == 0
    if was_zero:
        segs.marker[r] = 1
    if was_zero or endpoints_always:
        for v in (m.corner[lnext(e)], m.corner[lprev(e)]):
            if vmark[v] == 0:
                vmark[v] = 1


@kernel
def _first_hull_edge(m):
    """The hull edge leaving the hull vertex with the least (x, y), or NO_EDGE."""
    xy = m.xy
    best = NO_EDGE
    for t in range(m.size[S_NSLOT]):
        if m.stamp[t] <= 0:
            continue
        for k in range(3):
            e = 3 * t + k
            if m.twin[e] == NO_EDGE:
                o = m.corner[lnext(e)]
                if best == NO_EDGE:
                    best = e
                else:
                    b = m.corner[lnext(best)]
                    if xy[o, 0] < xy[b, 0] or (xy[o, 0] == xy[b, 0] and xy[o, 1] < xy[b, 1]):
                        best = e
    return best


@kernel
def infect_hull(m, segs, vmark, infected, queue):
    """Walk the convex hull counter-clockwise from the edge leaving its
    lowest vertex (least x, then y), as Triangle does: a triangle on a hull
    edge that is not a subsegment is infected and appended to ``queue``; a
    hull subsegment with marker 0 becomes a boundary, but only if its
    triangle was not infected earlier in the walk (through another of its
    hull edges), so the walk's order decides some endpoints' markers.
    Returns the queue length."""
    n = 0
    e0 = _first_hull_edge(m)
    e = e0
    while e != NO_EDGE:
        t = e // 3
        if not infected[t]:
            if m.seg[e] == NO_SEG:
                infected[t] = 1
                queue[n] = t
                n += 1
            else:
                _boundary_marks(m, segs, vmark, e, False)
        # the next hull edge leaves this one's destination
        f = lnext(e)
        while m.twin[f] != NO_EDGE:
            f = lnext(m.twin[f])
        e = f if f != e0 else NO_EDGE
    return n


@kernel
def locate_points(m, work, pts, lo, hi, found, state):
    """For each point inside the box ``lo..hi``: the triangle holding it
    (``found[i, 0]``) and that triangle's stamp (``found[i, 1]``); -1 if it is
    outside the box or the mesh."""
    t0 = m.size[S_NSLOT] - 1
    while t0 >= 0 and m.stamp[t0] <= 0:
        t0 -= 1
    for i in range(pts.shape[0]):
        found[i, 0] = -1
        found[i, 1] = 0
        x, y = pts[i, 0], pts[i, 1]
        if t0 < 0 or not (lo[0] <= x <= hi[0] and lo[1] <= y <= hi[1]):
            continue
        status, e = walk(m, work, t0, x, y, state, 4 * m.stamp.shape[0] + 64)
        if status == LOC_INSIDE or status == LOC_ON_EDGE or status == LOC_ON_VERTEX:
            found[i, 0] = e // 3
            found[i, 1] = m.stamp[e // 3]


@kernel
def plague(m, work, segs, vmark, infected, queue, n):
    """Spread the infection from ``queue[:n]`` across non-subsegment edges and
    delete the infected triangles.  Returns how many were deleted.

    As in Triangle, a subsegment is made a boundary (marker 0 -> 1, endpoints
    0 -> 1) when the infection reaches it while the other side is still
    healthy, even if that side is infected later; so the endpoints of
    segments inside holes get marker 1 too.
    """
    head = 0
    while head < n:
        t = queue[head]
        head += 1
        for k in range(3):
            e = 3 * t + k
            tw = m.twin[e]
            if tw == NO_EDGE or infected[tw // 3]:
                continue
            if m.seg[e] != NO_SEG:
                _boundary_marks(m, segs, vmark, e, True)
            else:
                infected[tw // 3] = 1
                queue[n] = tw // 3
                n += 1
    killed = 0
    for i in range(n):
        t = queue[i]
        for k in range(3):
            tw = m.twin[3 * t + k]
            if tw != NO_EDGE and not infected[tw // 3]:
                m.twin[tw] = NO_EDGE
        kill_triangle(m, t)
        work[C_DELETED] += 1
        killed += 1
    return killed


@kernel
def spread_regions(m, found, values, out, seen, stack):
    """Flood-fill each located region (in order) across non-subsegment edges,
    writing ``values[i]`` into ``out[t]`` for its triangles."""
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
