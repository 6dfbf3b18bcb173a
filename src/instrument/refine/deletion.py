# cython: language_level=3
"""Chew's rule: before a subsegment is split, the free vertices inside its
diametral circle are deleted, and each one's star is re-triangulated.

A free vertex's star is a polygon; ``_fill_polygon`` triangulates it by
taking, for each base edge, the vertex whose circle through the edge holds
no other candidate (the constrained Delaunay choice), then recursing on
both sides.  That scan is quadratic in the degree when the sides split
unevenly, so a star of ``SCAN_DEGREE`` vertices or more is triangulated
first by Chew's randomized algorithm (star_delaunay.py: the same triangles,
ties included, in expected linear time) and ``_fill_polygon`` then reads
each base edge's apex from it; a star that algorithm leaves (not Delaunay,
degenerate) is scanned as before.  Deleting is only attempted from a side
of the subsegment where no other segment meets it.
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, V_DEAD, V_FREE, Index, Mesh, bond, kill_triangle, lnext, lprev, new_triangle, spare_triangles
from cython.cimports.instrument.core.navigate import find_edge, remember_corners
from cython.cimports.instrument.core.predicates import incircle
from cython.cimports.instrument.core.scaling import scaled_dot
from cython.cimports.instrument.core.status import DONE, FAILED, NEED_ROOM
from cython.cimports.instrument.core.subsegments import Subsegments
from cython.cimports.instrument.counters import C_CREATED, C_DELETED, C_DELETED_VERTEX, C_INCIRCLE
from cython.cimports.instrument.refine.cavity import inherit, inherited
from cython.cimports.instrument.refine.criteria import test_triangle
from cython.cimports.instrument.refine.ghosts import deletion_freed, deletion_ghosts, deletion_orientations, note_deleted, star_orientations
from cython.cimports.instrument.refine.order import TRIANGLE
from cython.cimports.instrument.refine.queues import ghost_room, queue_used
from cython.cimports.instrument.refine.star_delaunay import delaunay_star
from cython.cimports.instrument.refine.state import T_DELETED, Refiner, trace_row

# SCAN_DEGREE (deletion.pxd): stars of that many vertices or more go to
# Chew's randomized algorithm first; the same constant for the pure-Python mode.
if not cython.compiled:
    SCAN_DEGREE = 24


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _fill_polygon(
    r: Refiner, m: Mesh, chain: cython.longlong[:], outer: cython.longlong[:], outer_seg: cython.longlong[:],
    count: Index, base: Index,
) -> tuple[Index, Index]:
    """Triangulate the polygon ``chain[0..count-1]`` whose other vertices lie
    left of ``chain[0] -> chain[count-1]``: each base edge takes the vertex
    whose circle through it holds no other candidate (the constrained
    Delaunay choice; of cocircular ones the last in chain order, as
    Triangle does: a deleted vertex's star with the cocircular (0.0556, 0),
    (0.1111, 0), (0, 0.1111), (0, 0.0556) on base (0, 0.0556) -> (0.0556, 0)
    is connected to (0.1111, 0) in its -VVV "Connecting edge to" lines),
    then both sides recurse.  ``outer[i]`` is the outside
    twin of the polygon edge ``chain[i] chain[i+1]``.  With ``base >= 0``
    the choices are read from star_delaunay's local triangulation in
    ``r.bnd``'s columns 0 and 1 (``base``: its edge on the polygon's base;
    column 4 holds each pending base edge's local edge) instead of scanned.
    The stack (3 per level, ``count`` levels at most) is column 2.  New
    triangles go on ``r.fan``; returns (base edge of the first, how many)."""
    bnd: cython.longlong[:, ::1] = r.bnd
    root: Index = -1
    made: Index = 0
    bnd[0, 2] = 0
    bnd[1, 2] = count - 1
    bnd[2, 2] = -1
    if base >= 0:
        bnd[0, 4] = base
    sp: Index = 1
    i: Index
    j: Index
    pe: Index
    ci: Index
    cj: Index
    k: Index
    ck: Index
    cq: Index
    q: Index
    le: Index
    t: Index
    while sp > 0:
        sp -= 1
        i = bnd[3 * sp, 2]
        j = bnd[3 * sp + 1, 2]
        pe = bnd[3 * sp + 2, 2]
        if j == i + 1:  # a polygon edge: link to the outside
            bond(m, pe, outer[i])
            m.seg[pe] = cython.cast(cython.int, outer_seg[i])
            continue
        le = -1
        if base < 0:  # the scan
            ci = chain[i]
            cj = chain[j]
            k = i + 1
            for q in range(i + 2, j):
                m.work[C_INCIRCLE] += 1
                ck = chain[k]
                cq = chain[q]
                if incircle(m.xy[ci, 0], m.xy[ci, 1], m.xy[cj, 0], m.xy[cj, 1], m.xy[ck, 0], m.xy[ck, 1],
                            m.xy[cq, 0], m.xy[cq, 1]) >= 0.0:
                    k = q
        else:  # local edge i -> j, its apex k
            le = bnd[sp, 4]
            k = bnd[le, 0]
        t = new_triangle(m, chain[k], chain[i], chain[j])
        m.work[C_CREATED] += 1
        r.fan[made] = t
        made += 1
        remember_corners(m, t)
        if pe < 0:
            root = 3 * t
        else:
            bond(m, 3 * t, pe)
        bnd[3 * sp, 2] = i
        bnd[3 * sp + 1, 2] = k
        bnd[3 * sp + 2, 2] = 3 * t + 2
        bnd[3 * sp + 3, 2] = k
        bnd[3 * sp + 4, 2] = j
        bnd[3 * sp + 5, 2] = 3 * t + 1
        if base >= 0:  # the twins of k -> i and j -> k
            bnd[sp, 4] = bnd[lprev(le), 1]
            bnd[sp + 1, 4] = bnd[lnext(le), 1]
        sp += 2
    return root, made


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def delete_free_vertex(r: Refiner, m: Mesh, segs: Subsegments, e0: Index) -> cython.int:
    """Remove the free vertex ``v`` at the origin of edge ``e0`` (Chew's
    rule: ``v`` sits in the diametral circle of the subsegment opposite it
    in ``e0``'s triangle) and re-triangulate its star from that subsegment
    as the base, as Triangle does.  Returns DONE, FAILED (nothing changed:
    ``v`` is on the boundary, or its star is degenerate) or NEED_ROOM
    (nothing changed: the scratch space, the mesh or the queue is short;
    ``r.need`` says how much).

    Area bounds and attributes (found by experiment, see
    reconstruct/__init__.py): Triangle's deletion flips move the triangles'
    values without averaging, so the triangle on the base keeps the value
    of the star triangle on the base, and every other new triangle, with
    apex ``w[k]`` over its base, the value of the star triangle
    ``(v, w[k-1], w[k])``."""
    v: Index = m.corner[lnext(e0)]
    # the star, counter-clockwise: w[i] = dest of the i-th edge out of v
    w: cython.longlong[:] = r.cav  # vertices
    outer: cython.longlong[:] = r.bnd[:, 0]  # outside twin of w[i] -> w[i+1]
    tris: cython.longlong[:] = r.bnd[:, 1]
    rec: cython.longlong[:] = r.bnd[:, 3]  # record of w[i] -> w[i+1]
    area: cython.double[:] = r.bval[:, 0]
    attr: cython.double[:] = r.bval[:, 1]
    d: Index = 0
    e: Index = e0
    t: Index
    nxt: Index
    for _ in range(m.stamp.shape[0]):
        if d + 2 >= w.shape[0] // 4:
            r.need = max(r.need, 4 * (d + 2))
            return NEED_ROOM
        t = e // 3
        w[d] = m.corner[lprev(e)]
        outer[d] = m.twin[lnext(e)]  # edge dest -> apex, opposite v
        rec[d] = m.seg[lnext(e)]
        tris[d] = t
        area[d], attr[d] = inherited(m, t)
        d += 1
        nxt = m.twin[lprev(e)]
        if nxt == NO_EDGE:
            return FAILED
        e = nxt
        if e == e0:
            break
    if d < 3:
        return FAILED
    if spare_triangles(m) < d or queue_used(r) + d + 2 > r.hkey.shape[0] or not ghost_room(r, d):
        r.need = max(r.need, d + 2)
        return NEED_ROOM
    if r.cfg.strategy == TRIANGLE:  # Triangle's entries of the star wait for v's vertex record
        deletion_ghosts(r, m, v, tris, d)
        star_orientations(r, m, v, tris, d)  # and its flips carry the records on
    # the polygon w0 .. w[d-1]; base w0 -> w1, chain w0, w[d-1], ..., w1
    half: Index = w.shape[0] // 2
    chain: cython.longlong[:] = w[half:]
    ring: cython.longlong[:] = r.fan  # outside twins in chain order (fan is overwritten later)
    ring_seg: cython.longlong[:] = m.vslot  # and records (vslot is all -1 between insertions)
    chain[0] = w[0]
    for i in range(1, d):
        chain[i] = w[d - i]
    # chain edge (chain[i], chain[i+1]) is the star's edge w[d-1-i] -> w[d-i]
    for i in range(d - 1):
        ring[i] = outer[(d - 1 - i) % d]
        ring_seg[i] = rec[(d - 1 - i) % d]
    base_outer: Index = outer[0]
    base_seg: Index = rec[0]
    for i in range(d):
        kill_triangle(m, tris[i])
    m.work[C_DELETED] += d
    area0: cython.double = area[0]
    attr0: cython.double = attr[0]
    for i in range(d):  # the outside twins move to w's place: fan is the fill's output
        w[i] = ring[i] if i < d - 1 else -1
    for i in range(d - 1):  # records too: vslot must be all -1 again after
        rec[i] = ring_seg[i]
        ring_seg[i] = -1
    root: Index
    made: Index
    base: Index = -1
    if d >= SCAN_DEGREE:
        # a large star: its triangles from Chew's algorithm (scratch: bnd's
        # columns but 3, the records, and fan, whose outside twins are in w now)
        base = delaunay_star(m.xy, chain, d, m.xy[v, 0], m.xy[v, 1], r.bnd[:, 0], r.bnd[:, 1], r.fan, r.bnd[:, 2],
                             r.bnd[:, 4], m.work)
    root, made = _fill_polygon(r, m, chain, w, rec, d, base)
    bond(m, root, base_outer)
    m.seg[root] = cython.cast(cython.int, base_seg)
    # vslot is all -1 again here: map each star vertex to its place (chain[i]
    # = w[d - i]; w0 closes the polygon, as place d)
    slot = m.vslot
    slot[chain[0]] = d
    for i in range(1, d):
        slot[chain[i]] = d - i
    if r.cfg.strategy == TRIANGLE:  # the star's records it frees (the base's apex at place j)
        deletion_freed(r, m, slot[m.corner[3 * r.fan[0]]], d)
    # the values by apex (see the docstring); fill triangles are (apex, base org, base dest)
    inherit(m, r.fan[0], area0, attr0)  # the base triangle (the fill makes it first)
    k: Index
    for i in range(1, made):
        k = slot[m.corner[3 * r.fan[i]]]
        inherit(m, r.fan[i], area[k - 1], attr[k - 1])
    # Triangle tests the new triangles as its flips make them, in post-order
    # of the polygon's split (the side from w1 first), the base triangle
    # last: sorted by the place of their last vertex (base org), then of
    # their first (base dest) downwards.  w[:made - 1] is free now.
    order: cython.longlong[:] = w
    hi: Index
    lo: Index
    j: Index
    u: Index
    uhi: Index
    if made > SCAN_DEGREE:  # a large star: two counting sorts (bnd is free scratch now)
        _sort_by_places(m, r.fan, made, slot, d, order, r.bnd[:, 2], r.bnd[:, 4])
    else:  # a small one: insertion
        for i in range(1, made):
            t = r.fan[i]
            hi = slot[m.corner[3 * t + 1]]
            lo = slot[m.corner[3 * t + 2]]
            j = i - 1
            while j > 0:
                u = order[j - 1]
                uhi = slot[m.corner[3 * u + 1]]
                if uhi < hi or (uhi == hi and slot[m.corner[3 * u + 2]] > lo):
                    break
                order[j] = u
                j -= 1
            order[j] = t
    if r.cfg.strategy == TRIANGLE:  # the orientations the flips give their triangles
        deletion_orientations(r, m, order, made, slot, d)
    slot[chain[0]] = -1
    for i in range(1, d):
        slot[chain[i]] = -1
    # Triangle's base triangle keeps the deleted vertex's base triangle and
    # its handle: (new apex, w0, w1) as org, dest, apex, so handle 3 t
    _turn_back(m, r.fan[0])
    order[made - 1] = r.fan[0]
    for i in range(made):  # back to fan: the adversary's test overwrites cav
        r.fan[i] = order[i]
    m.vtype[v] = V_DEAD
    m.work[C_DELETED_VERTEX] += 1
    trace_row(r, T_DELETED, made, d, 0, r.hsize)
    if r.cfg.keep_segments == 0:
        queued: Index = r.log_length
        for i in range(made):
            test_triangle(r, m, segs, r.fan[i])
        if r.cfg.strategy == TRIANGLE:
            note_deleted(r, m, queued)
    return DONE


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _sort_by_places(m: Mesh, fan: cython.longlong[:], made: Index, slot: cython.longlong[:], d: Index,
                    out: cython.longlong[:], tmp: cython.longlong[:], count: cython.longlong[:]) -> cython.void:
    """``out[:made - 1]`` = the triangles ``fan[1:made]`` in the deletion's
    testing order: the place of their base org ascending, then of their
    base dest descending (the pairs differ: one triangle per base), by two
    stable counting sorts over the places 1 .. d, in time linear in the
    degree where the insertion sort is quadratic."""
    p: Index
    i: Index
    t: Index
    running: Index
    c: Index
    for p in range(d + 2):  # by base dest, descending, into tmp
        count[p] = 0
    for i in range(1, made):
        count[slot[m.corner[3 * fan[i] + 2]]] += 1
    running = 0
    for p in range(d + 1, -1, -1):
        c = count[p]
        count[p] = running
        running += c
    for i in range(1, made):
        t = fan[i]
        p = slot[m.corner[3 * t + 2]]
        tmp[count[p]] = t
        count[p] += 1
    for p in range(d + 2):  # then stably by base org, ascending, into out
        count[p] = 0
    for i in range(made - 1):
        count[slot[m.corner[3 * tmp[i] + 1]]] += 1
    running = 0
    for p in range(d + 2):
        c = count[p]
        count[p] = running
        running += c
    for i in range(made - 1):
        t = tmp[i]
        p = slot[m.corner[3 * t + 1]]
        out[count[p]] = t
        count[p] += 1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _turn_back(m: Mesh, t: Index) -> cython.void:
    """Rotate triangle ``t``'s corners (a, b, c) to (c, a, b), with its
    edges (edge k moves with corner k) and its neighbours' links."""
    e: Index = 3 * t
    c0: cython.int = m.corner[e]
    c1: cython.int = m.corner[e + 1]
    c2: cython.int = m.corner[e + 2]
    w0: Index = m.twin[e]
    w1: Index = m.twin[e + 1]
    w2: Index = m.twin[e + 2]
    s0: cython.int = m.seg[e]
    s1: cython.int = m.seg[e + 1]
    s2: cython.int = m.seg[e + 2]
    m.corner[e], m.corner[e + 1], m.corner[e + 2] = c2, c0, c1
    m.seg[e], m.seg[e + 1], m.seg[e + 2] = s2, s0, s1
    bond(m, e, w2)
    bond(m, e + 1, w0)
    bond(m, e + 2, w1)
    remember_corners(m, t)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def chew_delete(r: Refiner, m: Mesh, segs: Subsegments, e: Index) -> cython.bint:
    """Before splitting subsegment ``e``: delete free vertices inside its
    diametral circle on a side where no other segment meets it.  Returns
    False if there was no room (nothing changed on that side)."""
    u: Index = m.corner[lnext(e)]
    v: Index = m.corner[lprev(e)]
    f: Index
    o: Index
    d: Index
    a: Index
    dot: cython.double
    status: cython.int
    for side in range(2):
        if side == 0:
            f = e
        else:  # found afresh: deletions on the first side re-make e's triangle
            f = find_edge(m, v, u)
        if f < 0:  # (NO_EDGE too)
            continue
        if m.seg[lnext(f)] != NO_SEG or m.seg[lprev(f)] != NO_SEG:
            continue
        for _ in range(m.stamp.shape[0]):
            o = m.corner[lnext(f)]
            d = m.corner[lprev(f)]
            a = m.corner[f]
            if m.vtype[a] != V_FREE:
                break
            dot = scaled_dot(m.xy[o, 0] - m.xy[a, 0], m.xy[o, 1] - m.xy[a, 1], m.xy[d, 0] - m.xy[a, 0], m.xy[d, 1] - m.xy[a, 1])
            if dot >= 0.0:
                break
            if queue_used(r) + 64 > r.hkey.shape[0]:
                return False
            status = delete_free_vertex(r, m, segs, lprev(f))  # the edge a -> o
            if status == NEED_ROOM:
                return False
            if status != DONE:  # kept: on the boundary
                break
            f = find_edge(m, o, d)  # the same side again
            if f < 0:
                return True
    return True
