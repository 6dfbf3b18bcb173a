# cython: language_level=3
"""Inserting a vertex during refinement: the Bowyer-Watson cavity.

The cavity of a point is every triangle reachable from the point's triangle
without crossing a subsegment whose circumcircle strictly contains the
point.  Its incircle tests are exactly the ones Lawson's flips would make,
so the counts compare with Triangle's, and an encroaching point is rejected
before the mesh is touched (Triangle inserts it and undoes the flips).  The
cavity is collected, its rim listed in Triangle's order, and then replaced by
the fan of triangles from the new vertex to the rim; ``triangles_created``
of an insertion is the new vertex's degree, the paper's measure.

A new triangle takes the regional attribute of the triangle inside the rim
edge it stands on, and the area bound Triangle's insertion leaves on it
(``collect_cavity``; the rule was found by experiment, see
reconstruct/__init__.py).

Scratch: ``Refiner.cav`` (the cavity, and from its end the triangles
tested outside it), ``Refiner.bnd``/``bval`` (the rim), ``Refiner.fan``
(the rim's order, then the new triangles), ``Mesh.tflag`` (1 in the cavity, 2 tested outside;
all 0 again when a function here returns) and ``Mesh.vslot``.
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import (
    NO_EDGE,
    NO_SEG,
    Index,
    Mesh,
    bond,
    kill_triangle,
    new_triangle,
    set_parent,
    spare_triangles,
)
from cython.cimports.instrument.core.insert import flip, should_flip
from cython.cimports.instrument.core.navigate import remember_corners
from cython.cimports.instrument.core.predicates import incircle
from cython.cimports.instrument.counters import C_CREATED, C_DELETED, C_INCIRCLE
from cython.cimports.instrument.refine.queues import queue_used
from cython.cimports.instrument.refine.state import Refiner


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def collect_cavity(r: Refiner, m: Mesh, px: cython.double, py: cython.double, t0: Index, t1: Index, skip: Index) -> tuple[Index, Index]:
    """Collect the cavity of point (px, py) from triangles ``t0`` (and ``t1``
    if >= 0), not crossing subsegments or edge ``skip`` (and its twin).

    Returns ``(ntri, nbnd)``: ``r.cav[:ntri]`` the triangles, ``r.bnd[:nbnd]``
    the rim edges as (outer twin, org, dest, record, edge), each with the
    area bound and attribute its new triangle takes in ``r.bval``.  Leaves
    ``m.tflag`` set on the cavity's triangles; ``fill_cavity`` or
    ``forget_cavity`` clears it.

    The attribute is the inner triangle's.  The area bound is the one
    Triangle's insertion (a 1-3 or 2-4 split, then Lawson flips) leaves on
    that edge's new triangle: the split copies the bound of ``t0`` (or
    ``t1``), each flip gives both of its triangles ``flip_bound`` of the
    two.  The cavity's triangles form a tree rooted at ``t0`` (and ``t1``)
    and each flip crosses one tree edge, so the bound is that fold along
    the path from the root, whatever the order of the flips:
    ``r.carry[i]`` holds it for ``r.cav[i]``.  A run without area bounds
    and attributes (the tables have no rows) has nothing to pass on: then
    ``r.carry`` and ``r.bval`` are left alone (``fill_cavity`` reads them
    only when there is).
    """
    area: cython.double
    attr: cython.double
    inherits: cython.bint = m.area_bound.shape[0] > 0 or m.attribute.shape[0] > 0
    n: Index = 1
    r.cav[0] = t0
    if inherits:
        area, attr = inherited(m, t0)
        r.carry[0] = area
    m.tflag[t0] = 1
    if t1 >= 0:
        r.cav[1] = t1
        if inherits:
            area, attr = inherited(m, t1)
            r.carry[1] = area
        m.tflag[t1] = 1
        n = 2
    tested: Index = r.cav.shape[0]  # triangles tested outside go at the end of r.cav
    nb: Index = 0
    i: Index = 0
    skip_twin: Index = m.twin[skip] if skip >= 0 else -2
    t: Index
    e: Index
    tw: Index
    u: Index
    a: Index
    b: Index
    c: Index
    flag: cython.schar
    outside: cython.bint
    passed: cython.double = -1.0
    while i < n:
        t = r.cav[i]
        if inherits:
            passed = r.carry[i]
        i += 1
        for k in range(3):
            e = 3 * t + k
            if e == skip or e == skip_twin:
                continue
            tw = m.twin[e]
            outside = tw == NO_EDGE or m.seg[e] != NO_SEG
            if not outside:
                u = cython.cast(cython.size_t, tw) // 3  # (tw >= 0: the unsigned division is shorter)
                flag = m.tflag[u]
                if flag == 1:
                    continue
                if flag == 0:
                    a, b, c = m.corner[3 * u], m.corner[3 * u + 1], m.corner[3 * u + 2]
                    m.work[C_INCIRCLE] += 1
                    if incircle(m.xy[a, 0], m.xy[a, 1], m.xy[b, 0], m.xy[b, 1], m.xy[c, 0], m.xy[c, 1], px, py) > 0.0:
                        m.tflag[u] = 1
                        r.cav[n] = u
                        if inherits:
                            area, attr = inherited(m, u)
                            r.carry[n] = flip_bound(passed, area)  # the flip across e
                        n += 1
                        continue
                    m.tflag[u] = 2
                    tested -= 1
                    r.cav[tested] = u
                outside = True
            r.bnd[nb, 0] = tw
            r.bnd[nb, 1] = m.corner[e + 1 if k < 2 else e - 2]  # org: lnext(e), known from k
            r.bnd[nb, 2] = m.corner[e + 2 if k == 0 else e - 1]  # dest: lprev(e)
            r.bnd[nb, 3] = m.seg[e]
            r.bnd[nb, 4] = e
            if inherits:
                area, attr = inherited(m, t)
                r.bval[nb, 0] = passed
                r.bval[nb, 1] = attr
            nb += 1
    for j in range(tested, r.cav.shape[0]):
        m.tflag[r.cav[j]] = 0
    return n, nb


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def forget_cavity(r: Refiner, m: Mesh, n: Index) -> cython.void:
    """Clear the cavity marks of an insertion that will not happen."""
    for i in range(n):
        m.tflag[r.cav[i]] = 0


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def order_rim(r: Refiner, m: Mesh, nb: Index, first: Index) -> cython.void:
    """List the cavity's rim rows ``r.bnd[:nb]`` in counter-clockwise order
    from the edge leaving vertex ``first`` in ``r.fan[:nb]`` (row numbers;
    ``fill_cavity`` makes the fan in that order): the order in which
    Triangle's flips meet the new vertex's triangles, so bad triangles and
    encroached subsegments are queued in its order.

    The rim is a cycle (a path from ``first`` when a boundary subsegment is
    split), walked from row to row by the vertex each ends at.  Should the
    walk end or close before it has listed every row, positions are swapped
    instead until each holds the row whose origin the previous one's
    destination is, leaving the rest as the swaps left them (how the rows
    themselves were once moved).  (The rows stay where they are: moving
    their seven fields, or a swap per step on the walk's critical path,
    cost more than the rest of the insertion's bookkeeping.)"""
    j: Index
    want: Index
    k: Index
    pos: Index = 0
    for j in range(nb):
        m.vslot[r.bnd[j, 1]] = j  # the row leaving that vertex
    want = first
    while pos < nb:
        j = m.vslot[want]
        if j < 0 or (pos > 0 and want == first):
            break
        r.fan[pos] = j
        pos += 1
        want = r.bnd[j, 2]
    if pos < nb:  # the swaps, from the rows in place (vslot: where each is listed)
        for j in range(nb):
            r.fan[j] = j
        want = first
        for pos in range(nb):
            j = m.vslot[want]
            if j < 0:
                break
            if j != pos:
                k = r.fan[j]
                r.fan[j] = r.fan[pos]
                r.fan[pos] = k
                m.vslot[r.bnd[r.fan[j], 1]] = j
                m.vslot[r.bnd[k, 1]] = pos
            want = r.bnd[r.fan[pos], 2]
    for j in range(nb):
        m.vslot[r.bnd[j, 1]] = -1


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _remake(m: Mesh, t: Index, a: Index, b: Index, c: Index, outer: Index, rec: Index) -> Index:
    """Live slot ``t`` as ``kill_triangle`` then ``new_triangle(m, a, b, c)``
    would leave it when the kill's slot is the one taken (its stamp one
    higher, corners ``a b c``, edges 1 and 2 unlinked and no subsegments),
    with its edge 0 (``b -> c``) bonded to ``outer`` and part of record
    ``rec``, as the fan's rim edge: each table entry written once."""
    e: Index = 3 * t
    m.stamp[t] += 1
    m.corner[e] = cython.cast(cython.int, a)
    m.corner[e + 1] = cython.cast(cython.int, b)
    m.corner[e + 2] = cython.cast(cython.int, c)
    m.twin[e] = cython.cast(cython.int, outer)
    if outer >= 0:
        m.twin[outer] = cython.cast(cython.int, e)
    m.twin[e + 1] = NO_EDGE
    m.twin[e + 2] = NO_EDGE
    m.seg[e] = cython.cast(cython.int, rec)
    m.seg[e + 1] = NO_SEG
    m.seg[e + 2] = NO_SEG
    return t


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def fill_cavity(r: Refiner, m: Mesh, p: Index, n: Index, nb: Index) -> cython.void:
    """Replace the cavity by the fan of triangles from ``p`` to its rim, in
    the order ``order_rim`` listed in ``r.fan[:nb]``; the new triangles
    take those places in ``r.fan``."""
    t: Index
    u: Index
    v: Index
    k: Index
    nxt: Index
    # Killing the cavity pushes r.cav[0], ..., r.cav[n-1] on the free stack
    # and the fan's new triangles pop it: new triangle j takes r.cav[n-1-j]
    # while they last (the rest as new_triangle finds them), and a cavity
    # larger than its fan leaves r.cav[0], ..., r.cav[n-nb-1] free.  Done so
    # directly: the same slots and stamps, without the round trip.
    for i in range(n):
        m.tflag[r.cav[i]] = 0
    for i in range(n - nb):
        kill_triangle(m, r.cav[i])
    m.work[C_DELETED] += n
    links: Index = 0
    first_org: Index = -1
    prev_dest: Index = -1
    prev: Index = -1
    inherits: cython.bint = m.area_bound.shape[0] > 0 or m.attribute.shape[0] > 0  # see collect_cavity
    for j in range(nb):
        k = r.fan[j]
        u = r.bnd[k, 1]
        v = r.bnd[k, 2]
        if j < n:
            t = _remake(m, r.cav[n - 1 - j], p, u, v, r.bnd[k, 0], r.bnd[k, 3])
        else:
            t = new_triangle(m, p, u, v)
            bond(m, 3 * t, r.bnd[k, 0])  # (the other edges are left unlinked)
            m.seg[3 * t] = cython.cast(cython.int, r.bnd[k, 3])
        if inherits:
            inherit(m, t, r.bval[k, 0], r.bval[k, 1])
        r.fan[j] = t
        remember_corners(m, t)
        # link the fan: edge v -> p of (p, u, v) to p -> v of the next, which
        # the rim's order puts right after it
        if prev_dest == u:
            bond(m, 3 * prev + 1, 3 * t + 2)
            links += 1
        if j == 0:
            first_org = u
        prev_dest = v
        prev = t
    if nb > 1 and prev_dest == first_org:  # around the cycle
        bond(m, 3 * prev + 1, 3 * r.fan[0] + 2)
        links += 1
    m.work[C_CREATED] += nb
    # Each link joins a vertex's one outgoing and one incoming rim edge, so
    # nb - 1 links (a path) or nb (a cycle) made every one there is; fewer
    # mean a rim not listed in order (order_rim's fallback): link by vertex
    if links < nb - 1:
        for j in range(nb):
            t = r.fan[j]
            m.vslot[m.corner[3 * t + 1]] = t
        for j in range(nb):
            t = r.fan[j]
            nxt = m.vslot[m.corner[3 * t + 2]]
            if nxt >= 0:
                bond(m, 3 * t + 1, 3 * nxt + 2)
        for j in range(nb):
            m.vslot[m.corner[3 * r.fan[j] + 1]] = -1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def has_room(r: Refiner, m: Mesh, nb: Index) -> cython.bint:
    """Enough room to add a vertex and ``nb`` triangles and queue them?  If
    not, says how much is needed (``r.need``) for the driver."""
    ok: cython.bint = (
        m.nvert < m.xy.shape[0]
        and spare_triangles(m) >= nb + 2
        and queue_used(r) + nb + 2 <= r.hkey.shape[0]
        and r.enc_live + nb + 4 <= r.enc.shape[0]
    )
    if not ok:
        r.need = max(r.need, nb + 4)
    return ok


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def new_vertex(
    m: Mesh, px: cython.double, py: cython.double, kind: cython.int, marker: cython.int,
    p0: Index, p1: Index, p2: Index, s: cython.double, t: cython.double,
) -> Index:
    """A new vertex at (px, py) of ``kind`` (mesh.pxd's V_*), with its boundary
    marker and its attributes' interpolation record (see ``set_parent``)."""
    v: Index = m.nvert
    m.nvert = v + 1
    m.xy[v, 0] = px
    m.xy[v, 1] = py
    m.vtype[v] = kind
    m.vmark[v] = marker
    set_parent(m, v, p0, p1, p2, s, t)
    return v


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def legalize_fan(r: Refiner, m: Mesh, made: Index) -> Index:
    """Lawson's flips around a vertex that is corner 0 of the triangles
    ``r.fan[:made]`` (it became their corner without an insertion: a
    subsegment split at an existing vertex, splits._split_at_apex), until
    every edge facing it is locally Delaunay.  Each flip gives its two
    triangles the bound an insertion's flip gives (``flip_bound``) and the
    attribute of the side at the vertex (no subsegment is flipped, so both
    sides lie in one region).  Leaves the triangles around the vertex in
    ``r.fan``, corner 0 the vertex (``flip`` keeps it there), and returns
    their count.  ``r.cav`` is the stack; the caller made sure the queue
    has room for every triangle around the vertex."""
    v: Index = m.corner[3 * r.fan[0]]
    n: Index = 0
    for i in range(made):
        r.cav[n] = 3 * r.fan[i]
        n += 1
    count: Index = made
    e: Index
    t1: Index
    t2: Index
    near: cython.double
    far: cython.double
    attr: cython.double
    unused: cython.double
    while n > 0:
        n -= 1
        e = r.cav[n]
        if not should_flip(m, e):
            continue
        near, attr = inherited(m, e // 3)
        far, unused = inherited(m, m.twin[e] // 3)
        t1 = flip(m, e)
        t2 = m.twin[3 * t1 + 1] // 3
        inherit(m, t1, flip_bound(near, far), attr)
        inherit(m, t2, flip_bound(near, far), attr)
        remember_corners(m, t1)
        remember_corners(m, t2)
        r.fan[count] = t1
        r.fan[count + 1] = t2
        count += 2
        r.cav[n] = 3 * t1
        r.cav[n + 1] = 3 * t2
        n += 2
    # the flips reuse the slots they free: keep each live slot once
    kept: Index = 0
    seen: cython.bint
    for i in range(count):
        t1 = r.fan[i]
        if m.stamp[t1] <= 0 or m.corner[3 * t1] != v:
            continue
        seen = False
        for j in range(kept):
            if r.fan[j] == t1:
                seen = True
        if not seen:
            r.fan[kept] = t1
            kept += 1
    return kept


# The small helpers every split and deletion calls: compiled, cavity.pxd's
# inline definitions; the same functions for the pure-Python mode.
if not cython.compiled:

    def inherited(m: Mesh, t: Index) -> tuple[float, float]:
        """Triangle slot ``t``'s area bound and regional attribute, which a new
        triangle inherits: (-1, 0) when the run has none (the tables have no rows)."""
        area = m.area_bound[t] if m.area_bound.shape[0] else -1.0
        attr = m.attribute[t] if m.attribute.shape[0] else 0.0
        return area, attr

    def flip_bound(a: float, b: float) -> float:
        """The area bound both triangles of one of Triangle's flips get from
        bounds ``a`` and ``b``: their mean, or none (-1) if either has none."""
        return 0.5 * (a + b) if a > 0.0 and b > 0.0 else -1.0

    def inherit(m: Mesh, t: Index, area: float, attr: float) -> None:
        """Give triangle slot ``t`` an area bound and a regional attribute (if the run has them)."""
        if m.area_bound.shape[0]:
            m.area_bound[t] = area
        if m.attribute.shape[0]:
            m.attribute[t] = attr

    def mark_both(m: Mesh, e: Index, rec: Index) -> None:
        """Make edge ``e`` (both sides) part of subsegment record ``rec``."""
        m.seg[e] = rec
        if m.twin[e] != NO_EDGE:
            m.seg[m.twin[e]] = rec
