# cython: language_level=3
"""Which of Triangle's triangle records holds each triangle a vertex's
insertion makes, and in which orientation: what decides whether a queued
entry of a rejected Steiner point is served again (queues.queue_push_ghost).

Triangle inserts a vertex by splitting the triangle that holds it (1 -> 3),
or the two beside the edge it lies on (2 -> 4; 1 -> 2 on the boundary), and
flipping.  A queued bad triangle is checked, when popped, by its record,
its orientation in that record and its three vertex records.  A rejected
point's fan triangles were queued and the insertion undone; the next vertex
made reuses the point's vertex record, and an entry is served again if that
vertex's insertion leaves its triangle, with the new vertex in place of the
point, in the same record and orientation.

The model of Triangle's insertion these functions follow (checked against
its -VVV queue events, scripts/queue_trace.py: with it the campaign's q34
and q32.5 point sets are refined split for split as Triangle does):

* a 1 -> 3 split of the located handle's triangle keeps that record on the
  handle's edge, in the handle's orientation, and puts the two new ones
  (orientation 0) on the edges dest -> apex and apex -> org;
* a 2 -> 4 split on edge o -> d keeps that triangle's record on d -> apex
  (one orientation up) and the twin's on apex' -> d (two up), and puts new
  records on apex -> o and o -> apex' (the latter first, from the pool);
* a flip of the fan triangle on edge a -> b with the triangle b -> a, f
  beyond leaves the fan triangle's record holding the part at a (one
  orientation lower), going on with a -> f, and the other record the part
  at f (one above its orientation on b -> a);
* the undo restores every record and returns the split's new records to
  the pool, which hands them out last freed first.

Records are named by the slot of the triangle ours holds at the time (the
mesh does not change between a rejection and the next vertex but for
Chew's deletions, which drop the ghosts: queues.ghosts_orphaned), or by
NEW_FIRST / NEW_SECOND for a split's new records; orientations are
relative to ours' slot layout, the same at both times.
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, Index, Mesh, lnext, lprev
from cython.cimports.instrument.refine.cavity import flip_bound
from cython.cimports.instrument.refine.queues import ghost_pending, ghost_revive
from cython.cimports.instrument.refine.state import Refiner

#: The new records of a rejected 1 -> 3 split: the one on the split
#: triangle's edge dest -> apex, and the one on apex -> org.
NEW_FIRST = cython.declare(cython.longlong, -1)
NEW_SECOND = cython.declare(cython.longlong, -2)

#: Which of the two the undo frees last (the next split takes it first):
#: the second, the choice that reproduces Triangle's queue on the q32.5 point
#: set (regressions/points-q32.5-stale-record-size.json: 1243 vertices as
#: Triangle; the first gives 1248; the q34 set agrees either way).
FREED_LAST = cython.declare(cython.longlong, -2)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _lineage(r: Refiner, m: Mesh, top: Index, nb: Index) -> cython.bint:
    """Run the flips from the split's fan triangles on ``r.lineage[:top]``
    (edge, record, orientation; the first to flip on top) over the cavity
    (``m.tflag`` 1) and write each final fan triangle's record and
    orientation in ``r.fan_rec``, in the order the flips finish them, and
    the two records of each flip in ``r.flips[:r.nflips]``, in the order
    they flip.  False if that order is not the rim's (``r.fan[:nb]``) or
    the stack is too small (nothing to rely on)."""
    out: Index = 0
    r.nflips = 0
    e: Index
    rec: Index
    k: Index
    tw: Index
    y: Index
    while top > 0:
        top -= 1
        e = r.lineage[top, 0]
        rec = r.lineage[top, 1]
        k = r.lineage[top, 2]
        tw = m.twin[e]
        if tw != NO_EDGE and m.seg[e] == NO_SEG and m.tflag[tw // 3] == 1:
            # flip: this record goes on with a -> f (lnext of the twin b -> a),
            # the other triangle's with f -> b, one above its edge b -> a
            if top + 2 > r.lineage.shape[0]:
                return False
            y = tw // 3
            r.flips[r.nflips, 0] = rec
            r.flips[r.nflips, 1] = y
            r.nflips += 1
            r.lineage[top, 0] = lprev(tw)
            r.lineage[top, 1] = y
            r.lineage[top, 2] = (tw - 3 * y + 1) % 3
            r.lineage[top + 1, 0] = lnext(tw)
            r.lineage[top + 1, 1] = rec
            r.lineage[top + 1, 2] = (k + 2) % 3
            top += 2
            continue
        if out >= nb or r.bnd[r.fan[out], 4] != e:
            return False
        r.fan_rec[out, 0] = rec
        r.fan_rec[out, 1] = k
        out += 1
    return out == nb


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _split_stack(r: Refiner, m: Mesh, e: Index, on_edge: cython.bint) -> Index:
    """Lay Triangle's split of a point inside edge ``e``'s triangle (1 -> 3)
    or on edge ``e`` (org o -> dest d: 2 -> 4, 1 -> 2 without a twin) on
    ``r.lineage``, the first to flip on top; returns the stack's height."""
    t: Index = e // 3
    if not on_edge:
        # e (org -> dest) keeps its record, dest -> apex and apex -> org get
        # the new ones
        r.lineage[0, 0] = lprev(e)
        r.lineage[0, 1] = NEW_SECOND
        r.lineage[0, 2] = 0
        r.lineage[1, 0] = lnext(e)
        r.lineage[1, 1] = NEW_FIRST
        r.lineage[1, 2] = 0
        r.lineage[2, 0] = e
        r.lineage[2, 1] = t
        r.lineage[2, 2] = e - 3 * t
        return 3
    tw: Index = m.twin[e]
    first: Index = FREED_LAST  # the new records, last freed first
    second: Index = NEW_FIRST + NEW_SECOND - FREED_LAST
    # d -> apex keeps e's record one orientation up, apex -> o and
    # o -> apex' get new ones, apex' -> d keeps the twin's two up
    top: Index = 0
    if tw != NO_EDGE:
        r.lineage[0, 0] = lprev(tw)
        r.lineage[0, 1] = tw // 3
        r.lineage[0, 2] = (tw - 3 * (tw // 3) + 2) % 3
        r.lineage[1, 0] = lnext(tw)
        r.lineage[1, 1] = first
        r.lineage[1, 2] = 0
        top = 2
    r.lineage[top, 0] = lprev(e)
    r.lineage[top, 1] = second if tw != NO_EDGE else first
    r.lineage[top, 2] = 0
    r.lineage[top + 1, 0] = lnext(e)
    r.lineage[top + 1, 1] = t
    r.lineage[top + 1, 2] = (e - 3 * t + 1) % 3
    return top + 2


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def rejected_fan_records(r: Refiner, m: Mesh, e: Index, nb: Index, on_edge: cython.bint) -> cython.bint:
    """``r.fan_rec[:nb]``: the records and orientations of the fan of a
    point inside edge ``e``'s triangle (Triangle's located handle) or on
    edge ``e``, and ``r.flips`` its flips (the cavity marked, the rim in
    order).  False if they cannot be told."""
    return _lineage(r, m, _split_stack(r, m, e, on_edge), nb)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def rejected_bounds(r: Refiner, m: Mesh, e: Index, on_edge: cython.bint) -> cython.void:
    """The area bounds a rejected insertion leaves behind (after
    ``rejected_fan_records`` told its flips): Triangle inserts the point,
    flips, and undoes the flips before it rejects the point.  Each flip
    gives both of its records the mean of their bounds (cavity.flip_bound);
    an undo keeps both as they are, and puts every record back on its own
    triangle.  So the triangles a rejected point's flips touched keep the
    means, and with them a different verdict on being too large (found in
    Triangle's -VVV "Area constraint" lines: face.1 refined under rpq30a
    with a bound per triangle parted from Triangle at its 82nd split
    without this, tests/engine/test_refine_existing.py).  The split's new
    records are freed, their bounds with them."""
    # the bounds of the split's new records: their triangles' own
    fresh = cython.declare(cython.double[2])
    fresh[0] = -1.0
    fresh[1] = -1.0
    top: Index = _split_stack(r, m, e, on_edge)
    for k in range(top):
        if r.lineage[k, 1] < 0:
            fresh[NEW_FIRST - r.lineage[k, 1]] = m.area_bound[r.lineage[k, 0] // 3]
    a: Index
    b: Index
    mean: cython.double
    for i in range(r.nflips):
        a = r.flips[i, 0]  # the fan triangle's record (maybe a new one)
        b = r.flips[i, 1]  # the cavity triangle's, beyond it
        mean = flip_bound(fresh[NEW_FIRST - a] if a < 0 else m.area_bound[a], m.area_bound[b])
        if a < 0:
            fresh[NEW_FIRST - a] = mean
        else:
            m.area_bound[a] = mean
        m.area_bound[b] = mean


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def revive_ghosts(r: Refiner, m: Mesh, e: Index, nb: Index) -> cython.void:
    """The vertex about to be made splits subsegment edge ``e`` (org o ->
    dest d; the cavity marked, the rim in order from d): revive the ghosts
    waiting for it whose record and orientation its fan gives their
    triangle again, and drop the others."""
    g: Index = r.nghost - 1
    if g < 0 or not ghost_pending(r, m, g):
        return
    ok: cython.bint = _lineage(r, m, _split_stack(r, m, e, True), nb)
    live: cython.bint
    j: Index
    while g >= 0 and ghost_pending(r, m, g):
        live = False
        if ok:
            for j in range(nb):
                if (r.bnd[r.fan[j], 1] == r.ghost[g, 0] and r.bnd[r.fan[j], 2] == r.ghost[g, 1]
                        and r.fan_rec[j, 0] == r.ghost[g, 3] and r.fan_rec[j, 1] == r.ghost[g, 4]):
                    live = True
                    break
        ghost_revive(r, g, live)
        g -= 1
