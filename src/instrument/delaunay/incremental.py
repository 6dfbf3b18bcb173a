# cython: language_level=3
"""Delaunay triangulation by incremental insertion (``-i``), made the way
Triangle's incremental method makes it: the same triangles in the same
records, in the same rotation, and the same records left free.

Why the records: the Delaunay triangulation is unique up to cocircular
ties, but refinement makes its first list of bad triangles in record
order, the ``u`` test reads a triangle's origin, and new triangles reuse
freed records last-in first-out, so a refined mesh depends on where each
triangle of the first triangulation sits and how it is turned.

What Triangle does was read off its ``-VVVV`` trace (every record it
writes, every point-location step; ``scripts/incremental_trace.py``
replays ours against it) and the spec (sections 4.2 and 4.3); none of
its code is used.  In Triangle's terms a triangle record holds corners
v0, v1, v2 and a handle (record, k) has org v[k+1], dest v[k+2], apex
v[k]; ours stores corners (v1, v2, v0) (the output order), so handle
(t, k) is our edge 3t + (k + 2) % 3, with the same org, dest and apex.

* A bounding triangle, record 0, with corners B1 (xmin - 50w, ymin - 40w),
  B2 (xmax + 50w, ymin - 40w), B3 ((xmin + xmax) / 2, ymax + 60w), w the
  larger extent (1 if both are 0); the outside is "outer space", and one
  handle on a box edge (``dummy``, Triangle's outer-space pointer) is
  updated whenever a record takes over a box edge.
* The points are inserted in input order.  Point location: the start is
  the nearest, by its origin's squared distance, of the dummy handle, the
  last insertion's handle (``recent``) and s records sampled with
  Triangle's random generator (s grows while 11 s^3 is below the number
  of triangles; the samples are drawn per memory block of Triangle's
  pool), then a walk (``_walk``).  A point equal to a vertex is a
  duplicate and is not inserted.
* Inside triangle (a, b, c) (the located handle's org, dest, apex): the
  record keeps a and b and takes the point as apex; two new records get
  (q, b, c) and (q, c, a) (in Triangle's corner order).  On edge a-b
  between (a, b, c) and (b, a, d): the first record's org and the second's
  dest become q, and two new records get (q, a, d) and (q, c, a).
* Flips: the edges facing the new point are tested counter-clockwise
  around it, from the located record's edge opposite it, until the edge
  ending where that one began is found locally Delaunay; after a flip of
  x-y (far vertex d) the edge x-d is tested next.  Flipping a handle with
  (org, dest, apex) = (o, t, x) across to far vertex y rewrites it as
  (y, x, o), on both sides.  Box corners count as infinitely far: an
  edge with one is tested by orientation (``_should_flip``).
* At the end the records touching the box are freed in the order of a
  walk around the box corners, from the dummy handle's record (freed
  last); the first hull edge that walk meets becomes the outer-space
  handle, the edge Triangle starts its hull walks and its hole location
  from (``triangulate`` sets it as ``Mesh.outer_space_edge``).

The tests are the exact predicates, where Triangle's adaptive ones agree
with them (docs/fidelity.md names the ties where they do not).  The work
counters count this method's own tests, walk steps, flips and finite
triangles made and unmade.
"""

from __future__ import annotations

import numpy as np

import cython
from cython.cimports.instrument.core.mesh import NO_EDGE, Index, Mesh, bond, dest, kill_triangle, lnext, lprev, new_triangle, org
from cython.cimports.instrument.core.predicates import incircle, orient2d
from cython.cimports.instrument.counters import C_CREATED, C_DELETED, C_DUPLICATE, C_FLIP, C_INCIRCLE, C_ORIENT, C_WALK

# where a point lies
INSIDE = cython.declare(cython.int, 0)
ON_EDGE = cython.declare(cython.int, 1)
ON_VERTEX = cython.declare(cython.int, 2)

#: Triangle's pool blocks: the first holds max(BLOCK, 2n - 2) triangles, the others BLOCK.
BLOCK = cython.declare(cython.Py_ssize_t, 4092)


@cython.cclass
class Insertion:
    """What the method carries from one insertion to the next, besides the
    mesh (fields in incremental.pxd): Triangle's random generator
    (``seed``), how many records a location samples (``samples``, which
    only grows), the last insertion's handle (``recent``, -1 before the
    first), the outer-space handle (``outer_space``: the box edge Triangle's
    dummy points at, where the removal of the box starts), the size of the
    first block of Triangle's pool (``first_block``, where the sampling's
    blocks start), and the first hull edge the removal of the box left
    (``first_hull``, NO_EDGE until then): the outer-space handle after."""

    def __init__(self, outer_space: Index, first_block: Index):
        self.seed = 1
        self.samples = 1
        self.recent = -1
        self.outer_space = outer_space
        self.first_block = first_block
        self.first_hull = NO_EDGE


# ------------------------------------------------------------ small helpers


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _random(st: Insertion, choices: Index) -> Index:
    """Triangle's generator: a number in 0 .. choices - 1."""
    st.seed = (st.seed * 1366 + 150889) % 714025
    return st.seed // (714025 // choices + 1)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _distance(m: Mesh, v: Index, px: cython.double, py: cython.double) -> cython.double:
    """Squared distance from vertex v to p, in plain floating point as Triangle computes it."""
    dx: cython.double = px - m.xy[v, 0]
    dy: cython.double = py - m.xy[v, 1]
    return dx * dx + dy * dy


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _orient(m: Mesh, a: Index, b: Index, px: cython.double, py: cython.double) -> cython.double:
    m.work[C_ORIENT] += 1
    return orient2d(m.xy[a, 0], m.xy[a, 1], m.xy[b, 0], m.xy[b, 1], px, py)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _same(m: Mesh, v: Index, px: cython.double, py: cython.double) -> cython.bint:
    return m.xy[v, 0] == px and m.xy[v, 1] == py


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _rewrite(m: Mesh, t: Index, c0: Index, c1: Index, c2: Index, nb: Index) -> cython.void:
    """Give record t the corners (c0, c1, c2), counting a finite triangle that
    goes and one that comes (corners ``>= nb`` are the box's)."""
    e: Index = 3 * t
    if m.corner[e] < nb and m.corner[e + 1] < nb and m.corner[e + 2] < nb:
        m.work[C_DELETED] += 1
    if c0 < nb and c1 < nb and c2 < nb:
        m.work[C_CREATED] += 1
    m.corner[e] = cython.cast(cython.int, c0)
    m.corner[e + 1] = cython.cast(cython.int, c1)
    m.corner[e + 2] = cython.cast(cython.int, c2)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _make(m: Mesh, c0: Index, c1: Index, c2: Index, nb: Index) -> Index:
    """A new record (there is always room: the mesh has 2n + 8 slots)."""
    t: Index = new_triangle(m, c0, c1, c2)
    if c0 < nb and c1 < nb and c2 < nb:
        m.work[C_CREATED] += 1
    return t


# ------------------------------------------------------------ point location


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _walk(m: Mesh, e: Index, px: cython.double, py: cython.double, st: Insertion) -> tuple[cython.int, Index]:
    """Walk from handle e (p to its left) to p, as Triangle's ``preciselocate``:
    at (o, d, a), cross o-a if p is beyond it only, a-d if beyond it only,
    and if beyond both the one the dot product (a - p).(d - o) picks.
    Returns (INSIDE, e), (ON_EDGE, the edge), or (ON_VERTEX, an edge whose
    origin equals p; it becomes the recent handle).  The walk cannot leave
    the box, which contains every point; it is bounded all the same."""
    xy = m.xy
    o: Index
    d: Index
    a: Index
    left: cython.bint
    sl: cython.double
    sr: cython.double
    steps: Index = 4 * m.nslot + 64
    while steps > 0:
        steps -= 1
        m.work[C_WALK] += 1
        o = org(m, e)
        d = dest(m, e)
        a = m.corner[e]
        if _same(m, a, px, py):
            st.recent = lprev(e)
            return ON_VERTEX, lprev(e)
        sl = _orient(m, o, a, px, py)
        sr = _orient(m, a, d, px, py)
        if sl > 0.0:
            if sr > 0.0:
                left = (xy[a, 0] - px) * (xy[d, 0] - xy[o, 0]) + (xy[a, 1] - py) * (xy[d, 1] - xy[o, 1]) > 0.0
            else:
                left = True
        elif sr > 0.0:
            left = False
        elif sl == 0.0:
            return ON_EDGE, lprev(e)
        elif sr == 0.0:
            return ON_EDGE, lnext(e)
        else:
            return INSIDE, e
        e = m.twin[lprev(e)] if left else m.twin[lnext(e)]
        if e == NO_EDGE:
            break
    return _scan(m, px, py)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _scan(m: Mesh, px: cython.double, py: cython.double) -> tuple[cython.int, Index]:
    """Fallback location by testing every record (never expected: a walk in a
    Delaunay triangulation reaches its point)."""
    s0: cython.double
    s1: cython.double
    s2: cython.double
    e: Index
    t: Index
    k: Index
    for t in range(m.nslot):
        e = 3 * t
        for k in range(3):
            if _same(m, m.corner[e + k], px, py):
                return ON_VERTEX, lprev(e + k)
        s0 = _orient(m, m.corner[e + 1], m.corner[e + 2], px, py)
        s1 = _orient(m, m.corner[e + 2], m.corner[e], px, py)
        s2 = _orient(m, m.corner[e], m.corner[e + 1], px, py)
        if s0 >= 0.0 and s1 >= 0.0 and s2 >= 0.0:
            if s0 == 0.0:
                return ON_EDGE, e
            if s1 == 0.0:
                return ON_EDGE, e + 1
            if s2 == 0.0:
                return ON_EDGE, e + 2
            return INSIDE, e
    return INSIDE, 0  # unreachable: the box contains every point


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _locate(m: Mesh, px: cython.double, py: cython.double, st: Insertion) -> tuple[cython.int, Index]:
    """Triangle's ``locate`` in a mesh without dead records: the start is the
    nearest (strictly, in this order) of the outer-space handle, the recent
    handle and the sampled records (each at its handle 0), by their origins.
    A point equal to the start's origin or destination is ON_VERTEX; a point
    on the start edge's line strictly between its ends is ON_EDGE; a point
    right of it starts from the other side; then ``_walk``."""
    start: Index = st.outer_space
    best: cython.double = _distance(m, org(m, start), px, py)
    dist: cython.double
    recent: Index = st.recent
    if recent >= 0:
        if _same(m, org(m, recent), px, py):
            return ON_VERTEX, recent
        dist = _distance(m, org(m, recent), px, py)
        if dist < best:
            start = recent
            best = dist
    # samples, block by block of Triangle's pool (every record is alive here)
    items: Index = m.nslot
    s: Index = st.samples
    while 11 * s * s * s < items:
        s += 1
    st.samples = s
    base: Index = 0
    block: Index = st.first_block
    population: Index
    t: Index
    i: Index
    while base < items:
        population = min(block, items - base)
        for i in range((s * population - 1) // items + 1):
            t = base + _random(st, population)
            dist = _distance(m, m.corner[3 * t], px, py)  # handle 0's origin: corner 0
            if dist < best:
                start = 3 * t + 2
                best = dist
        base += population
        block = BLOCK
    o: Index = org(m, start)
    d: Index = dest(m, start)
    if _same(m, o, px, py):
        st.recent = start
        return ON_VERTEX, start
    if _same(m, d, px, py):
        st.recent = lnext(start)
        return ON_VERTEX, lnext(start)
    ahead: cython.double = _orient(m, o, d, px, py)
    xy = m.xy
    if ahead < 0.0:
        start = m.twin[start]
    elif ahead == 0.0:
        if ((xy[o, 0] < px) == (px < xy[d, 0])) and ((xy[o, 1] < py) == (py < xy[d, 1])):
            return ON_EDGE, start
    return _walk(m, start, px, py, st)


# ------------------------------------------------------------ insertion


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _take_box_edge(m: Mesh, e: Index, st: Insertion) -> cython.void:
    """Edge e now holds a box edge (no twin): outer space points at it."""
    if m.twin[e] == NO_EDGE:
        st.outer_space = e


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _split_triangle(m: Mesh, e: Index, q: Index, nb: Index, st: Insertion) -> cython.void:
    """Point q inside the triangle of handle e = (a, b, c): the record keeps
    (a, b, q), new records (b, c, q) and (c, a, q) in our corner order."""
    t: Index = e // 3
    a: Index = org(m, e)
    b: Index = dest(m, e)
    c: Index = m.corner[e]
    w_bc: Index = m.twin[lnext(e)]
    w_ca: Index = m.twin[lprev(e)]
    left: Index = _make(m, b, c, q, nb)
    right: Index = _make(m, c, a, q, nb)
    _set_corner(m, e, q, nb)
    bond(m, 3 * left + 2, w_bc)
    bond(m, 3 * right + 2, w_ca)
    bond(m, lnext(e), 3 * left + 1)
    bond(m, lprev(e), 3 * right)
    bond(m, 3 * left, 3 * right + 1)
    _take_box_edge(m, 3 * left + 2, st)
    _take_box_edge(m, 3 * right + 2, st)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _split_edge(m: Mesh, e: Index, q: Index, nb: Index, st: Insertion) -> cython.void:
    """Point q on the edge of handle e = (a, b, c), whose other side is
    f = (b, a, d): e's record becomes (q, b, c), f's (b, q, d), and new
    records take (a, d, q) and (c, a, q) in our corner order."""
    f: Index = m.twin[e]
    a: Index = org(m, e)
    b: Index = dest(m, e)
    c: Index = m.corner[e]
    d: Index = m.corner[f]
    w_ca: Index = m.twin[lprev(e)]
    w_ad: Index = m.twin[lnext(f)]
    top: Index = _make(m, a, d, q, nb)
    bottom: Index = _make(m, c, a, q, nb)
    _set_corner(m, lnext(e), q, nb)
    _set_corner(m, lprev(f), q, nb)
    bond(m, 3 * top + 2, w_ad)
    bond(m, 3 * bottom + 2, w_ca)
    bond(m, lprev(e), 3 * bottom + 1)
    bond(m, 3 * bottom, 3 * top + 1)
    bond(m, 3 * top, lnext(f))
    _take_box_edge(m, 3 * bottom + 2, st)  # (Triangle's order: c-a first, a-d last)
    _take_box_edge(m, 3 * top + 2, st)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _set_corner(m: Mesh, i: Index, v: Index, nb: Index) -> cython.void:
    """Corner i (3t + k) of record t becomes v."""
    t: Index = i // 3
    k: Index = i - 3 * t
    c0: Index = v if k == 0 else m.corner[3 * t]
    c1: Index = v if k == 1 else m.corner[3 * t + 1]
    c2: Index = v if k == 2 else m.corner[3 * t + 2]
    _rewrite(m, t, c0, c1, c2, nb)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _should_flip(m: Mesh, e: Index, nb: Index) -> cython.bint:
    """Is edge e = (x, y) with apex q (the new point) to be flipped towards
    the far vertex d?  Seen from q, y is left and x right; a box corner is
    infinitely far away, so a circle through it is a half-plane: left a
    corner, flip if d is left of q -> x; right a corner, if d is left of
    y -> q; d a corner, never.  Otherwise the strict incircle test, with
    Triangle's order of arguments (y, q, x, d)."""
    f: Index = m.twin[e]
    if f == NO_EDGE:
        return False
    xy = m.xy
    x: Index = org(m, e)
    y: Index = dest(m, e)
    q: Index = m.corner[e]
    d: Index = m.corner[f]
    if y >= nb:
        m.work[C_ORIENT] += 1
        return orient2d(xy[q, 0], xy[q, 1], xy[x, 0], xy[x, 1], xy[d, 0], xy[d, 1]) > 0.0
    if x >= nb:
        m.work[C_ORIENT] += 1
        return orient2d(xy[d, 0], xy[d, 1], xy[y, 0], xy[y, 1], xy[q, 0], xy[q, 1]) > 0.0
    if d >= nb:
        return False
    m.work[C_INCIRCLE] += 1
    return incircle(xy[y, 0], xy[y, 1], xy[q, 0], xy[q, 1], xy[x, 0], xy[x, 1], xy[d, 0], xy[d, 1]) > 0.0


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _flip(m: Mesh, e: Index, nb: Index, st: Insertion) -> cython.void:
    """Flip edge e = (x, y, apex q) with its twin f = (y, x, apex d): each
    handle (o, t, apex) becomes (far, apex, o), so e's record holds
    (x, d, q) and f's (d, y, q); both keep their handle numbers."""
    f: Index = m.twin[e]
    x: Index = org(m, e)
    y: Index = dest(m, e)
    q: Index = m.corner[e]
    d: Index = m.corner[f]
    w_yq: Index = m.twin[lnext(e)]
    w_qx: Index = m.twin[lprev(e)]
    w_xd: Index = m.twin[lnext(f)]
    w_dy: Index = m.twin[lprev(f)]
    _set_handle(m, e, d, q, x, nb)
    _set_handle(m, f, q, d, y, nb)
    bond(m, lnext(e), w_qx)
    bond(m, lprev(e), w_xd)
    bond(m, lnext(f), w_dy)
    bond(m, lprev(f), w_yq)
    _take_box_edge(m, lprev(e), st)
    _take_box_edge(m, lnext(f), st)
    m.work[C_FLIP] += 1


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _set_handle(m: Mesh, e: Index, o: Index, d: Index, a: Index, nb: Index) -> cython.void:
    """Handle e's record gets org o, dest d, apex a."""
    t: Index = e // 3
    k: Index = e - 3 * t
    if k == 0:
        _rewrite(m, t, a, o, d, nb)
    elif k == 1:
        _rewrite(m, t, d, a, o, nb)
    else:
        _rewrite(m, t, o, d, a, nb)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _legalize(m: Mesh, e: Index, stop: Index, nb: Index, st: Insertion) -> cython.void:
    """Test the edges facing the new point counter-clockwise around it from
    handle e (whose apex it is) until the edge ending at ``stop`` is
    accepted; a flipped edge x-y is followed by x-d.  The last handle,
    turned to start at the new point, is the next location's recent one."""
    while True:
        if _should_flip(m, e, nb):
            _flip(m, e, nb, st)
            e = lprev(e)
            continue
        if dest(m, e) == stop:
            break
        e = lnext(m.twin[lnext(e)])
    st.recent = lprev(e)


# ------------------------------------------------------------ the box


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _free_box_record(m: Mesh, t: Index, nb: Index, st: Insertion) -> cython.void:
    """Free a record that touches the box; across its edge between two
    points (if any) a triangle of points is left with a hull edge (none if
    the points are collinear); the first one is kept in ``st.first_hull``."""
    e: Index
    w: Index
    u: Index
    k: Index
    for k in range(3):
        e = 3 * t + k
        if org(m, e) < nb and dest(m, e) < nb:
            w = m.twin[e]
            if w == NO_EDGE:
                continue
            u = 3 * (w // 3)
            if m.corner[u] < nb and m.corner[u + 1] < nb and m.corner[u + 2] < nb:
                m.twin[w] = NO_EDGE
                if st.first_hull == NO_EDGE:
                    st.first_hull = w
    kill_triangle(m, t)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _remove_box(m: Mesh, nb: Index, st: Insertion) -> cython.void:
    """Free every record touching the box: walk around the box corners from
    the outer-space handle's record, crossing from each record to the next
    through the edge leaving the current corner (turning to the next corner
    at a box edge), freeing each one met and the first one last."""
    h0: Index = st.outer_space
    h: Index = h0
    e: Index
    s: Index
    while True:
        e = lprev(h) if m.corner[h] >= nb else lnext(h)
        s = m.twin[e]
        if s == NO_EDGE or s // 3 == h0 // 3:
            break
        _free_box_record(m, s // 3, nb, st)
        h = s
    _free_box_record(m, h0 // 3, nb, st)


# ------------------------------------------------------------ building


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _insert_all(m: Mesh, n: Index, st: Insertion, dup: cython.longlong[::1]) -> cython.void:
    """Insert points 0 .. n-1 in order; a point equal to an inserted vertex
    is recorded in ``dup`` and left out."""
    status: cython.int
    e: Index
    q: Index
    px: cython.double
    py: cython.double
    for q in range(n):
        px = m.xy[q, 0]
        py = m.xy[q, 1]
        status, e = _locate(m, px, py, st)
        if status == ON_VERTEX:
            m.work[C_DUPLICATE] += 1
            dup[q] = org(m, e)
        elif status == ON_EDGE:
            _split_edge(m, e, q, n, st)  # e is (q, b, c) now: the flips start at b-c
            _legalize(m, lnext(e), dest(m, e), n, st)
        else:
            _split_triangle(m, e, q, n, st)
            _legalize(m, e, org(m, e), n, st)


def box_corners(xy) -> np.ndarray:
    """Triangle's bounding triangle for the points ``xy`` (rows B1, B2, B3)."""
    xmin = float(xy[:, 0].min())
    xmax = float(xy[:, 0].max())
    ymin = float(xy[:, 1].min())
    ymax = float(xy[:, 1].max())
    w = max(xmax - xmin, ymax - ymin)
    if w == 0.0:
        w = 1.0
    return np.array([
        [xmin - 50.0 * w, ymin - 40.0 * w],
        [xmax + 50.0 * w, ymin - 40.0 * w],
        [0.5 * (xmin + xmax), ymax + 60.0 * w],
    ])  # fmt: skip


def triangulate(m: Mesh, box) -> np.ndarray:
    """Triangulate the first ``m.nvert`` vertices of ``m`` (whose rows must
    leave room for three more: the bounding triangle's corners ``box``), in
    input order.

    Returns ``dup``: per vertex -1 or the inserted vertex it duplicates.
    ``m.outer_space_edge`` becomes the first hull edge the removal of the
    box met, Triangle's outer-space handle afterwards (NO_EDGE: no hull,
    every point collinear, no triangle).  The box records are freed in
    Triangle's order; ``m.nvert`` is unchanged."""
    n: Index = m.nvert
    xy = np.asarray(m.xy)
    xy[n : n + 3] = box
    t: Index = new_triangle(m, n, n + 1, n + 2)  # Triangle's (B3, B1, B2): ours in output order
    st: Insertion = Insertion(3 * t + 2, max(BLOCK, 2 * n - 2))  # outer space: handle 0, B1 -> B2
    dup = np.full(n, -1, dtype=np.int64)
    d: cython.longlong[::1] = dup
    with cython.nogil:
        _insert_all(m, n, st, d)
        _remove_box(m, n, st)
    xy[n : n + 3] = 0.0
    m.outer_space_edge = st.first_hull
    return dup
