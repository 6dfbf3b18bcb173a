# cython: language_level=3
"""Delaunay triangulation by divide and conquer (Guibas and Stolfi's merge,
Dwyer's alternating cuts), the method Triangle uses by default.

Written from the description of the method in the literature and in the
spec (§4.2); nothing here is taken from Triangle's source.  Why the same
method as Triangle: where points are cocircular the Delaunay triangulation
is not unique, and the merge's tie rules (strict tests: an edge is deleted
only if a point is strictly inside a circle; on a tie the left candidate
wins) pick the same diagonals as Triangle does, so that the meshes agree
edge for edge.

The points are first cut in halves at the median, alternately by ``(x, y)``
and by ``(y, x)`` order ("frames" 0 and 1), down to groups of two or three.
Each half is triangulated with ghost triangles around its convex hull (see
mesh.py); a merge finds the lower common tangent of the two hulls and knits
the halves together upwards.  The seam's ghosts become the new triangles,
and an edge that fails the circle test is deleted by flipping it with its
ghost, so a merge allocates just two triangles: the ghosts of the two
tangents.

In frame 1 the "left" half is the one lower in ``(y, x)`` order; the merge
code is the same, since it only uses orientation and incircle tests, which do
not depend on the frame.  It only needs, for each half, the hull edge leaving
the half's last vertex (in the frame of the cut) and leaving its first
vertex: ``hull_at[v]`` keeps the ghost of the hull edge leaving ``v``, which
is unique for such extreme vertices.

(About 650 lines: the cuts, the base cases and the merge are one algorithm,
whose merge runs millions of times at 10^6 points and inlines every helper
here.)
"""

from __future__ import annotations

import functools

import numpy as np

from ..core.filled import filled

import cython
from cython.cimports.instrument.core.mesh import GHOST, Index, Mesh, bond, dest, lnext, lprev, new_triangle, org
from cython.cimports.instrument.core.predicates import incircle, orient2d
from cython.cimports.instrument.counters import C_CREATED, C_DELETED, C_INCIRCLE, C_ORIENT

# ------------------------------------------------------------ the cuts


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _less(a1: cython.double, a2: cython.double, b1: cython.double, b2: cython.double) -> cython.bint:
    """Lexicographic order of the keys (a1, a2) and (b1, b2)."""
    return a1 < b1 or (a1 == b1 and a2 < b2)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _before(xy: cython.double[:, ::1], a: Index, b: Index, f: Index) -> cython.bint:
    """True if point ``a`` comes before point ``b`` in frame ``f``:
    ``(x, y)`` order for f = 0, ``(y, x)`` order for f = 1."""
    g: Index = 1 - f
    return _less(xy[a, f], xy[a, g], xy[b, f], xy[b, g])


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _swap(pts: cython.double[:, ::1], ids: cython.longlong[::1], i: Index, j: Index) -> cython.void:
    ids[i], ids[j] = ids[j], ids[i]
    for c in range(2):
        pts[i, c], pts[j, c] = pts[j, c], pts[i, c]


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _less_flat(a1: cython.double, a2: cython.double, b1: cython.double, b2: cython.double) -> cython.bint:
    """``_less`` without branches (bitwise, not short-circuit), for the partition loop."""
    lt: cython.bint = a1 < b1
    eq: cython.bint = a1 == b1
    lt2: cython.bint = a2 < b2
    return lt | (eq & lt2)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _select(pts: cython.double[:, ::1], ids: cython.longlong[::1], lo: Index, hi: Index, k: Index, f: Index) -> cython.void:
    """Quickselect: reorder rows ``lo .. hi-1`` of ``pts`` (and ``ids`` with
    them) so that row ``k`` holds the point that sorting in frame ``f`` would
    put there, the points before it in front and the points after it behind.
    The points must be distinct.  Rows move with their ids, so comparisons
    read memory in sequence.

    The pivot is the median of three; the partition is Lomuto's without
    branches (each row is swapped with the first row not below the pivot,
    whose position advances by the comparison's outcome): a branch on the
    comparison goes wrong half the time on points in no order, which made
    the cuts take as long as a third of the triangulation.  Which rows end
    where within each side does not matter: the cut order is a function of
    the points alone, as every group's content is (its rows are the ones a
    sort would put there) and groups of two or three end sorted."""
    g: Index = 1 - f
    a: Index
    b: Index
    c: Index
    p: Index
    i: Index
    j: Index
    b1: cython.double
    b2: cython.double
    x0: cython.double
    x1: cython.double
    xi: cython.longlong
    while hi - lo > 3:
        # the median of the rows lo, mid, hi-1 is the pivot, moved to hi-1
        a = lo
        b = (lo + hi - 1) >> 1
        c = hi - 1
        if _less(pts[b, f], pts[b, g], pts[a, f], pts[a, g]):
            a, b = b, a
        if _less(pts[c, f], pts[c, g], pts[b, f], pts[b, g]):
            b = c
            if _less(pts[b, f], pts[b, g], pts[a, f], pts[a, g]):
                b = a
        p = b
        _swap(pts, ids, p, hi - 1)
        b1 = pts[hi - 1, f]
        b2 = pts[hi - 1, g]
        j = lo
        for i in range(lo, hi - 1):
            x0 = pts[i, 0]
            x1 = pts[i, 1]
            xi = ids[i]
            pts[i, 0] = pts[j, 0]
            pts[i, 1] = pts[j, 1]
            ids[i] = ids[j]
            pts[j, 0] = x0
            pts[j, 1] = x1
            ids[j] = xi
            j += _less_flat(x1 if f else x0, x0 if f else x1, b1, b2)
        _swap(pts, ids, j, hi - 1)
        if k == j:
            return
        if k < j:
            hi = j
        else:
            lo = j + 1
    # two or three rows left: sort them
    for i in range(lo + 1, hi):
        j = i
        while j > lo and _less(pts[j, f], pts[j, g], pts[j - 1, f], pts[j - 1, g]):
            _swap(pts, ids, j, j - 1)
            j -= 1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _cut(pts: cython.double[:, ::1], ids: cython.longlong[::1], stack: cython.longlong[:, ::1], top: Index) -> cython.void:
    """The recursion of ``cut_order`` on an explicit stack (depth <= 64),
    from the ``top`` groups (lo, hi, frame of their cut) already on it."""
    lo: Index
    hi: Index
    f: Index
    size: Index
    mid: Index
    while top > 0:
        top -= 1
        lo, hi, f = stack[top, 0], stack[top, 1], stack[top, 2]
        size = hi - lo
        if size <= 3:
            _select(pts, ids, lo, hi, lo + 1, 0)  # frame 0 order
            if size == 3:
                _select(pts, ids, lo + 1, hi, lo + 2, 0)
            continue
        mid = lo + (size >> 1)
        _select(pts, ids, lo, hi, mid, f)
        stack[top, 0], stack[top, 1], stack[top, 2] = lo, mid, 1 - f
        stack[top + 1, 0], stack[top + 1, 1], stack[top + 1, 2] = mid, hi, 1 - f
        top += 2


def cut_group(pts, ids, lo: int, hi: int, frame: int) -> None:
    """Put rows ``lo .. hi-1`` of ``pts`` (and ``ids``) in cut order, the
    group being cut in ``frame`` (its rows already lie in its parent's cut);
    releases the GIL, so groups that do not overlap can be cut at once."""
    p: cython.double[:, ::1] = pts
    i: cython.longlong[::1] = ids
    s: cython.longlong[:, ::1] = np.empty((130, 3), dtype=np.int64)
    s[0, 0], s[0, 1], s[0, 2] = lo, hi, frame
    with cython.nogil:
        _cut(p, i, s, 1)


def split_group(pts, ids, lo: int, hi: int, frame: int) -> int:
    """Cut rows ``lo .. hi-1`` once, at their median in ``frame``; returns
    where the second half starts (the halves are then cut in ``1 - frame``)."""
    p: cython.double[:, ::1] = pts
    i: cython.longlong[::1] = ids
    mid: Index = lo + ((hi - lo) >> 1)
    a: Index = lo
    b: Index = hi
    f: Index = frame
    with cython.nogil:
        _select(p, i, a, b, mid, f)
    return mid


def cut_order(xy, ids, alternate: bool, pts=None):
    """Order ``ids`` (int64, distinct points sorted in frame 0) for the
    recursion, in place, and return their coordinates in that order: each
    group of more than three is split at ``size >> 1`` into halves separated
    in the frame of its cut, the frames alternating from 0 at the top
    (``alternate``) or always 0; groups of two or three end in frame 0 order.
    (The top cut is in frame 0, where the points already are sorted.)
    ``pts``: the rows ``xy[ids]`` (C-contiguous float64) if the caller has
    them, which are then reordered in place and returned."""
    if pts is None:
        pts = np.ascontiguousarray(np.asarray(xy)[ids], dtype=np.float64)
    n = ids.shape[0]
    if not alternate or n <= 3:
        return pts
    half = n >> 1
    cut_group(pts, ids, 0, half, 1)
    cut_group(pts, ids, half, n, 1)
    return pts


# ------------------------------------------------------------ hull ghosts
#
# A ghost's finite edge h runs against the hull edge it stands for (the hull
# runs counter-clockwise, the mesh on its left): that hull edge runs from
# dest(h) (its tail) to org(h) (its head).


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _next_ccw(m: Mesh, h: Index) -> Index:
    """The ghost of the next hull edge counter-clockwise."""
    return lprev(m.twin[lprev(h)])


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _prev_cw(m: Mesh, h: Index) -> Index:
    """The ghost of the previous hull edge (clockwise)."""
    return lnext(m.twin[lnext(h)])


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _ghost(m: Mesh, hull_at: cython.int[::1], a: Index, b: Index) -> Index:
    """A ghost on hull edge ``a -> b``; returns its finite edge."""
    g: Index = new_triangle(m, b, a, GHOST)
    h: Index = 3 * g + 2
    hull_at[a] = h
    return h


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _link(m: Mesh, h1: Index, h2: Index) -> cython.void:
    """Make hull edge ``h2`` follow ``h1`` counter-clockwise."""
    bond(m, lprev(h1), lnext(h2))


# ------------------------------------------------------------ base cases


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _two(m: Mesh, hull_at: cython.int[::1], a: Index, b: Index) -> cython.void:
    h_ba: Index = _ghost(m, hull_at, b, a)
    h_ab: Index = _ghost(m, hull_at, a, b)
    bond(m, h_ab, h_ba)
    _link(m, h_ab, h_ba)
    _link(m, h_ba, h_ab)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _three(m: Mesh, hull_at: cython.int[::1], a: Index, b: Index, c: Index) -> cython.void:
    """Points in frame 0 order: a triangle, or a chain of two edges if collinear."""
    xy = m.xy
    m.work[C_ORIENT] += 1
    s: cython.double = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1])
    h_ab: Index
    h_bc: Index
    if s == 0.0:  # in Triangle's slots: (a, b), (b, a), (c, b), (b, c), each with the ghost third
        h_ba: Index = _ghost(m, hull_at, b, a)
        h_ab = _ghost(m, hull_at, a, b)
        h_bc = _ghost(m, hull_at, b, c)
        h_cb: Index = _ghost(m, hull_at, c, b)
        hull_at[b] = cython.cast(cython.int, h_ba)
        bond(m, h_ab, h_ba)
        bond(m, h_bc, h_cb)
        _link(m, h_ab, h_bc)
        _link(m, h_bc, h_cb)
        _link(m, h_cb, h_ba)
        _link(m, h_ba, h_ab)
        return
    if s < 0.0:
        b, c = c, b
    t: Index = new_triangle(m, a, b, c)
    m.work[C_CREATED] += 1
    h_ab = _ghost(m, hull_at, a, b)
    h_bc = _ghost(m, hull_at, b, c)
    h_ca: Index = _ghost(m, hull_at, c, a)
    bond(m, 3 * t + 2, h_ab)
    bond(m, 3 * t + 0, h_bc)
    bond(m, 3 * t + 1, h_ca)
    _link(m, h_ab, h_bc)
    _link(m, h_bc, h_ca)
    _link(m, h_ca, h_ab)


# ------------------------------------------------------------ the merge


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _below(xy: cython.double[:, ::1], a: Index, b: Index, p: Index) -> cython.bint:
    """True if ``p`` lies strictly right of the line ``a -> b``."""
    return orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[p, 0], xy[p, 1]) < 0.0


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _above(xy: cython.double[:, ::1], a: Index, b: Index, p: Index) -> cython.bint:
    return orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[p, 0], xy[p, 1]) > 0.0


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _inside(xy: cython.double[:, ::1], a: Index, b: Index, c: Index, d: Index) -> cython.bint:
    """True if ``d`` is strictly inside the circle through counter-clockwise ``a, b, c``."""
    return incircle(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1], xy[d, 0], xy[d, 1]) > 0.0


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _unhull(m: Mesh, hull_at: cython.int[::1], h: Index, left: cython.bint) -> Index:
    """Delete the triangle inside hull edge ``h`` from its half: the hull edge
    ``u -> w`` of the triangle ``(u, w, x)`` becomes the two hull edges
    ``u -> x -> w``.  Returns the finite edge of the ghost on the seam side:
    ``u -> x`` for the left half, ``x -> w`` for the right."""
    t_in: Index = m.twin[h]
    x: Index = m.corner[t_in]
    u: Index = dest(m, h)
    w: Index = org(m, h)
    n_ux: Index = m.twin[lprev(t_in)]  # across u -> x (t_in's edge x -> u)
    n_xw: Index = m.twin[lnext(t_in)]  # across x -> w (t_in's edge w -> x)
    before: Index = m.twin[lnext(h)]  # the ghost chain on both sides; the seam
    after: Index = m.twin[lprev(h)]  # side's pointer is stale (rebonded by the knit)
    # Slots and rotations as Triangle's flip leaves them (found by comparing
    # its output order): relative to the rotation of the handle on the edge
    # u - w in each slot, the ghost of u -> x is (org, dest, apex) =
    # (GHOST, x, u) and the ghost of x -> w is (x, GHOST, w); the right half
    # puts the first in the triangle's slot, the left half the second.
    s_ux: Index
    s_xw: Index
    if left:
        s_ux, s_xw = h, t_in
    else:
        s_ux, s_xw = t_in, h
    k: Index = s_ux % 3
    g: Index = s_ux - k
    m.corner[g + k] = u
    m.corner[g + (k + 1) % 3] = GHOST
    m.corner[g + (k + 2) % 3] = x
    h_ux: Index = g + (k + 1) % 3
    k = s_xw % 3
    g = s_xw - k
    m.corner[g + k] = w
    m.corner[g + (k + 1) % 3] = x
    m.corner[g + (k + 2) % 3] = GHOST
    h_xw: Index = g + (k + 2) % 3
    bond(m, h_ux, n_ux)
    bond(m, h_xw, n_xw)
    if left:
        bond(m, lprev(h_xw), after)
    else:
        bond(m, lnext(h_ux), before)
    _link(m, h_ux, h_xw)
    hull_at[u] = h_ux
    hull_at[x] = h_xw
    return h_ux if left else h_xw


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _clear(m: Mesh, hull_at: cython.int[::1], g: Index, ll: Index, lr: Index, left: cython.bint) -> Index:
    """Delete a half's edges from the base's end to its candidate ``g`` while
    the candidate triangle's circle holds the far corner of the triangle
    inside the edge; returns the candidate left standing."""
    cand: Index
    while m.corner[m.twin[g]] != GHOST:
        cand = org(m, g) if left else dest(m, g)
        m.work[C_INCIRCLE] += 1
        if not _inside(m.xy, ll, lr, cand, m.corner[m.twin[g]]):
            break
        g = _unhull(m, hull_at, g, left)
        m.work[C_DELETED] += 1
    return g


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _merge(m: Mesh, hull_at: cython.int[::1], l: Index, r: Index) -> Index:
    """Merge the triangulations left and right of a cut; ``l`` is the left
    half's last vertex and ``r`` the right half's first, in the cut's frame."""
    xy = m.xy
    hl: Index = hull_at[l]  # hull edge leaving l (counter-clockwise)
    hr: Index = hull_at[r]
    # Lower common tangent: walk l clockwise and r counter-clockwise while
    # the next hull vertex lies strictly below the line l -> r.
    moved: cython.bint = True
    pl: Index
    while moved:
        moved = False
        pl = _prev_cw(m, hl)
        m.work[C_ORIENT] += 1
        if _below(xy, l, r, dest(m, pl)):
            hl = pl
            l = dest(m, pl)
            moved = True
        m.work[C_ORIENT] += 1
        if _below(xy, l, r, org(m, hr)):
            r = org(m, hr)
            hr = _next_ccw(m, hr)
            moved = True
    gl: Index = hl  # left candidate: the left hull's edge ll -> ul
    gr: Index = _prev_cw(m, hr)  # right candidate: the right hull's edge ur -> lr
    outer: Index = _prev_cw(m, hl)
    g: Index = new_triangle(m, l, GHOST, r)  # Triangle's rotation (matters to the pool order only)
    bottom: Index = 3 * g + 1
    hull_at[l] = bottom
    _link(m, outer, bottom)
    _link(m, bottom, hr)
    base: Index = bottom  # the edge lr -> ll seen from below
    ll: Index = l
    lr: Index = r
    ul: Index
    ur: Index
    nxt: Index
    left_ok: cython.bint
    right_ok: cython.bint
    take_left: cython.bint
    while True:
        ul = org(m, gl)
        ur = dest(m, gr)
        m.work[C_ORIENT] += 2
        left_ok = _above(xy, ll, lr, ul)
        right_ok = _above(xy, ll, lr, ur)
        if left_ok:
            gl = _clear(m, hull_at, gl, ll, lr, True)
            ul = org(m, gl)
        if right_ok:
            gr = _clear(m, hull_at, gr, ll, lr, False)
            ur = dest(m, gr)
        if not left_ok and not right_ok:
            break
        take_left = left_ok
        if left_ok and right_ok:
            m.work[C_INCIRCLE] += 1
            take_left = not _inside(xy, ul, ll, lr, ur)
        m.work[C_CREATED] += 1
        if take_left:
            # the ghost of ll -> ul takes lr as its third corner
            nxt = _next_ccw(m, gl)
            m.corner[gl] = lr
            bond(m, lnext(gl), base)
            base = lprev(gl)
            gl = nxt
            ll = ul
        else:
            # the ghost of ur -> lr takes ll as its third corner
            nxt = _prev_cw(m, gr)
            m.corner[gr] = ll
            bond(m, lprev(gr), base)
            base = lnext(gr)
            gr = nxt
            lr = ur
    top: Index = _ghost(m, hull_at, lr, ll)
    bond(m, top, base)
    _link(m, gr, top)
    _link(m, top, gl)
    return top


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _find_hull_edge(m: Mesh, hull_at: cython.int[::1], v: Index, h: Index) -> cython.void:
    """Make ``hull_at[v]`` the hull edge leaving ``v``, walking from hull edge
    ``h`` if it is stale.  Needed for a merged half's extreme vertices only,
    which the hull passes once; ``hull_at`` goes stale where a deletion left
    a half's hull passing a vertex twice, as a tree of edges."""
    g: Index = hull_at[v]
    if m.corner[g] != GHOST or dest(m, g) != v:
        while dest(m, h) != v:
            h = _next_ccw(m, h)
        hull_at[v] = h


# ------------------------------------------------------------ recursion


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _first(xy: cython.double[:, ::1], a: Index, b: Index, f: Index) -> Index:
    return b if _before(xy, b, a, f) else a


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _last(xy: cython.double[:, ::1], a: Index, b: Index, f: Index) -> Index:
    return b if _before(xy, a, b, f) else a


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _base(m: Mesh, hull_at: cython.int[::1], lo: Index, hi: Index, found: cython.longlong[:, ::1], row: Index) -> cython.void:
    """Triangulate a group of two or three (in frame 0 order); write its
    first and last points in frames 0 and 1 to ``found[row]``."""
    xy = m.xy
    if hi - lo == 2:
        _two(m, hull_at, lo, lo + 1)
    else:
        _three(m, hull_at, lo, lo + 1, lo + 2)
    found[row, 0] = lo
    found[row, 1] = hi - 1
    found[row, 2] = lo
    found[row, 3] = lo
    for v in range(lo + 1, hi):
        found[row, 2] = _first(xy, found[row, 2], v, 1)
        found[row, 3] = _last(xy, found[row, 3], v, 1)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _merge_found(m: Mesh, hull_at: cython.int[::1], found: cython.longlong[:, ::1], a: Index, b: Index, f: Index) -> cython.void:
    """Merge the triangulated groups whose extremes are ``found[a]`` (left)
    and ``found[b]`` (right), cut in frame ``f``; the merged group's
    extremes replace ``found[a]``."""
    xy = m.xy
    top_edge: Index
    if f == 0:
        top_edge = _merge(m, hull_at, found[a, 1], found[b, 0])
    else:
        top_edge = _merge(m, hull_at, found[a, 3], found[b, 2])
    found[a, 0] = _first(xy, found[a, 0], found[b, 0], 0)
    found[a, 1] = _last(xy, found[a, 1], found[b, 1], 0)
    found[a, 2] = _first(xy, found[a, 2], found[b, 2], 1)
    found[a, 3] = _last(xy, found[a, 3], found[b, 3], 1)
    for k in range(4):
        _find_hull_edge(m, hull_at, found[a, k], top_edge)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _build(
    m: Mesh, hull_at: cython.int[::1], lo0: Index, hi0: Index, f0: Index, alternate: cython.bint,
    frames: cython.longlong[:, ::1], found: cython.longlong[:, ::1],
) -> cython.void:
    """Triangulate points ``lo0 .. hi0-1`` (distinct, in cut order, at least
    two), a group cut in frame ``f0``; its first and last points in frames
    0 and 1 end in ``found[0]``.

    The recursion runs on explicit stacks: ``frames`` rows are (lo, hi,
    frame of the cut, stage), and each finished group leaves its first and
    last points in frames 0 and 1 (first0, last0, first1, last1) on
    ``found``.
    """
    frames[0, 0] = lo0
    frames[0, 1] = hi0
    frames[0, 2] = f0
    frames[0, 3] = 0
    top: Index = 1
    nfound: Index = 0
    lo: Index
    hi: Index
    f: Index
    stage: Index
    mid: Index
    while top > 0:
        lo, hi, f, stage = frames[top - 1, 0], frames[top - 1, 1], frames[top - 1, 2], frames[top - 1, 3]
        if hi - lo <= 3:
            _base(m, hull_at, lo, hi, found, nfound)
            nfound += 1
            top -= 1
        elif stage < 2:
            frames[top - 1, 3] = stage + 1
            mid = lo + ((hi - lo) >> 1)
            frames[top, 0] = lo if stage == 0 else mid
            frames[top, 1] = mid if stage == 0 else hi
            frames[top, 2] = 1 - f if alternate else 0
            frames[top, 3] = 0
            top += 1
        else:
            _merge_found(m, hull_at, found, nfound - 2, nfound - 1, f)
            nfound -= 1
            top -= 1


@functools.lru_cache(maxsize=None)
def group_slots(n: int) -> int:
    """Triangle slots the triangulation of a group of ``n`` >= 2 points uses:
    2 for a pair, 4 for a triple (a triangle and three ghosts, or four
    ghosts), and 2 for each merge (its bottom and top ghosts; a merge
    reuses the slots of the edges it deletes).  Known in advance, so the
    groups of a parallel run can take the slots the sequential run gives
    them."""
    if n <= 3:
        return 2 if n == 2 else 4
    half = n >> 1
    return group_slots(half) + group_slots(n - half) + 2


def triangulate_group(m: Mesh, hull_at, lo: int, hi: int, frame: int, alternate: bool) -> tuple[int, int, int, int]:
    """Triangulate points ``lo .. hi-1`` (a group cut in ``frame``) with
    ghosts around its hull, allocating from ``m.nslot`` on; returns its
    first and last points in frames 0 and 1.  Releases the GIL."""
    h: cython.int[::1] = hull_at
    # the two stacks, 130 rows each, share one array (taking an array as a
    # typed memoryview costs more than a small run's whole recursion)
    stacks: cython.longlong[:, ::1] = np.zeros((260, 4), dtype=np.int64)
    frames: cython.longlong[:, ::1] = stacks[0:130]
    found: cython.longlong[:, ::1] = stacks[130:260]
    a: Index = lo
    b: Index = hi
    f: Index = frame
    alt: cython.bint = alternate
    with cython.nogil:
        _build(m, h, a, b, f, alt, frames, found)
    return found[0, 0], found[0, 1], found[0, 2], found[0, 3]


def merge_groups(m: Mesh, hull_at, left, right, frame: int) -> tuple[int, int, int, int]:
    """Merge two triangulated groups, ``left`` and ``right`` their extremes
    (as ``triangulate_group`` returns them), cut in ``frame``; returns the
    merged group's extremes.  Releases the GIL."""
    h: cython.int[::1] = hull_at
    found: cython.longlong[:, ::1] = np.array([left, right], dtype=np.int64)
    f: Index = frame
    with cython.nogil:
        _merge_found(m, h, found, 0, 1, f)
    return found[0, 0], found[0, 1], found[0, 2], found[0, 3]


def triangulate_sorted(m: Mesh, n: int, alternate: bool) -> None:
    """Triangulate points ``0 .. n-1`` of ``m`` (distinct, in cut order) with
    ghosts around the hull; ``m`` has room for 2n + 8 triangles."""
    if n >= 2:
        triangulate_group(m, filled(n, -1, np.int32), 0, n, 0, alternate)
