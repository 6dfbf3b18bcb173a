# cython: language_level=3
"""A subsegment split as Triangle makes it, record for record: for the
splits of the encroached input subsegments that come before the first list
of bad triangles.

Triangle queues its first bad triangles by walking its triangle records in
memory order (``refine``'s phase 1, over our slots), so that list follows
where its insertions left their triangles.  Triangle splits the edge in
place (the two triangles beside it keep their records, two new ones are
taken) and then flips around the new vertex, each flip rewriting its two
records (core/insert.py: ``split_edge_in_place``, ``flip_in_place``);
``splits.split_subsegment`` instead replaces a cavity by a fan of new
triangles, which gives the same triangles in other slots.  Before any
triangle is queued that is all the difference, and this module makes the
split Triangle's way (later splits keep the cavity: their triangles are
queued as they are made, in the fan's order, and slots matter no more).

The walk around the new vertex meets its edges in the order Triangle's
does, and pools the encroached subsegments among them as it meets them, as
``test_fan`` does in the cavity's rim order, which is the same.
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.insert import flip_in_place, split_edge_in_place
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, V_SEGMENT, Index, Mesh, lnext, lprev
from cython.cimports.instrument.core.navigate import find_edge, remember_corners
from cython.cimports.instrument.core.predicates import incircle
from cython.cimports.instrument.core.subsegments import Subsegments, new_record
from cython.cimports.instrument.counters import C_INCIRCLE, C_SEGMENT_SPLIT, C_STEINER
from cython.cimports.instrument.refine.cavity import inherit, inherited, new_vertex
from cython.cimports.instrument.refine.encroach import check_subsegment
from cython.cimports.instrument.refine.state import T_SEGMENT, Refiner, trace_row

#: Triangle's orientation 0 of a record is edge 0 of a slot during
#: refinement (refine.run turns every triangle so)
ZERO = cython.declare(Index, 0)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _flip(m: Mesh, e: Index) -> cython.void:
    """``flip_in_place``, with the area bound Triangle's insertion flips give
    both triangles (the mean of the two, or none if either has none); the
    regional attributes stay with the slots (no subsegment is flipped, so
    both lie in one region)."""
    tw: Index = m.twin[e]
    a: cython.double
    b: cython.double
    attr: cython.double
    if m.area_bound.shape[0]:
        a = m.area_bound[e // 3]
        b = m.area_bound[tw // 3]
        a = 0.5 * (a + b) if a > 0.0 and b > 0.0 else -1.0
        m.area_bound[e // 3] = a
        m.area_bound[tw // 3] = a
    flip_in_place(m, e)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def split_in_place(
    r: Refiner, m: Mesh, segs: Subsegments, e: Index, px: cython.double, py: cython.double,
    e0: Index, e1: Index, split: cython.double,
) -> cython.void:
    """Split subsegment edge ``e`` (``o -> d``) at (px, py), ``split`` of the
    way from ``e0`` to ``e1`` (its ends as the split point was computed
    from them), Triangle's way (see the module docstring): the caller
    checked ``splits_cleanly`` and made room for the vertex, two triangles
    and a subsegment record, and pools nothing itself.

    The new vertex takes the record's marker; the half from ``o`` takes a
    new record, the half to ``d`` keeps the edge's, as Triangle keeps
    them.  Then the subsegments around the vertex are pooled if
    encroached, in the order Triangle's flips meet them, and both halves
    last, the one to ``d`` first."""
    o: Index = m.corner[lnext(e)]
    d: Index = m.corner[lprev(e)]
    tw: Index = m.twin[e]
    h: Index = e // 3
    t: Index = tw // 3 if tw != NO_EDGE else -1
    rec: Index = m.seg[e]
    half: Index = new_record(segs, segs.marker[rec], segs.source[rec], segs.ends[rec, 0], segs.ends[rec, 1])
    v: Index = new_vertex(m, px, py, V_SEGMENT, segs.marker[rec], e0, e1, e0, split, 0.0)
    area_h: cython.double
    attr_h: cython.double
    area_t: cython.double = -1.0
    attr_t: cython.double = 0.0
    area_h, attr_h = inherited(m, h)
    if t >= 0:
        area_t, attr_t = inherited(m, t)
    nslot: Index = m.nslot
    nfree: Index = m.nfree
    g: Index = split_edge_in_place(m, e, v, cython.cast(cython.int, half), ZERO)
    # the new triangles, (o, x, v) beyond e (if any) then (b, o, v), copy the
    # bounds and attributes of the triangles they were split from
    made: Index = 2 if t >= 0 else 1
    nt: Index
    for i in range(made):
        nt = _taken(m, nslot, nfree, i)
        if t >= 0 and i == 0:
            inherit(m, nt, area_t, attr_t)
        else:
            inherit(m, nt, area_h, attr_h)
    xy = m.xy
    first: Index = m.corner[lnext(g)]
    around: Index = 0
    tt: Index
    rr: Index
    ll: Index
    f: Index
    nx: Index
    flipping: cython.bint
    while True:  # Triangle's flips around v (core/insert.py: lawson_in_place), pooling as it goes
        tt = m.twin[g]
        rr = m.corner[lnext(g)]
        ll = m.corner[lprev(g)]
        flipping = False
        if m.seg[g] != NO_SEG:
            check_subsegment(r, m, g)
        elif tt != NO_EDGE:
            f = m.corner[tt]
            m.work[C_INCIRCLE] += 1
            flipping = incircle(xy[ll, 0], xy[ll, 1], xy[v, 0], xy[v, 1], xy[rr, 0], xy[rr, 1], xy[f, 0], xy[f, 1]) > 0.0
        if flipping:
            _flip(m, g)
            g = lprev(g)
            continue
        remember_corners(m, g // 3)
        around += 1
        nx = m.twin[lnext(g)]
        if ll == first or nx == NO_EDGE:
            break
        g = lnext(nx)
    m.work[C_SEGMENT_SPLIT] += 1
    m.work[C_STEINER] += 1
    if r.budget > 0:
        r.budget -= 1
    eb: Index = find_edge(m, v, d)
    ea: Index = find_edge(m, o, v)
    if eb >= 0:
        check_subsegment(r, m, eb)
    if ea >= 0:
        check_subsegment(r, m, ea)
    trace_row(r, T_SEGMENT, around, around - made, 0, r.hsize)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _taken(m: Mesh, nslot: Index, nfree: Index, i: Index) -> Index:
    """The slot of the ``i``-th triangle taken since the free stack held
    ``nfree`` slots and ``nslot`` were in use (free slots first, the last
    freed first, as ``new_triangle`` takes them)."""
    if i < nfree:
        return m.free[nfree - 1 - i]
    return nslot + (i - nfree)
