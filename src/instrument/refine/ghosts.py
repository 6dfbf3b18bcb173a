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
Chew's deletions and their subsegment's split, which a ghost with such a
name must not touch: queues.ghosts_orphaned, revive_ghosts), or by
NEW_FIRST / NEW_SECOND for a split's new records.  Orientations are
Triangle's own where the slot's is known (``r.orient``: records_known,
note_born, deletion_orientations), else relative to ours' slot layout,
the same at both times.

Chew's deletions free vertex records too: the subsegment's split point
takes the deleted vertex's, and an entry of the deleted vertex's star is
served again if the split remakes its triangle in that entry's record and
orientation (deletion_ghosts, deletion_freed).  That needs the entry's
orientation in Triangle's terms: known for entries queued by an insertion
(in a new record, or a kept one whose orientation was known) or by a
deletion's flips (note_born, note_deleted).  Such an entry whose record
the deletion keeps, as an ear of its polygon, waits there until a later
deletion frees that record, and is served again when the vertex after that
deletion's subsegment split takes it (deletion_freed, _kept_ghosts).
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import NO_EDGE, NO_SEG, Index, Mesh, lnext, lprev
from cython.cimports.instrument.refine.cavity import flip_bound
from cython.cimports.instrument.refine.queues import entry_to_ghost, entry_waiting, ghost_pending, ghost_recent, ghost_revive, ghosts_orphaned
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

#: A deletion's ghost waits past the next vertex in one of the two records
#: the deletion freed (deletion_freed): the one handed out first (POOL_TOP)
#: or the one under it (POOL_BELOW).  A subsegment's split point on the
#: boundary takes one record, the top: the one under it is the next
#: split's first (revive_ghosts).
POOL_TOP = cython.declare(cython.longlong, -3)
POOL_BELOW = cython.declare(cython.longlong, -4)

#: A deletion's ghost whose record outlives the deletion as one of its
#: polygon's triangles (deletion_orientations): KEPT_BY - that slot, until a
#: later deletion frees the record (deletion_freed) or the next vertex comes
#: (revive_ghosts drops it: Triangle's serving such an entry again when a
#: split remakes its triangle there is not established).
KEPT_BY = cython.declare(cython.longlong, -(1 << 40))


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _ghost_name(r: Refiner, k: Index) -> Index:
    """A new record's name (NEW_FIRST, NEW_SECOND) as a pending ghost row
    stores it, or the name a row stores read back (the same swap both
    ways; a slot, k >= 0, or a star place is its own name).

    Every rejection of a split that takes two new records swaps the names
    of all the ghosts waiting (rejected_fan_records).  Under -Y/-YY
    thousands of points can be rejected in a row (trimesh.poly under
    pq30YY: 6,358 before its last vertex, and 158,000 after it, each
    queueing some 25 ghosts): swapping every row made each rejection cost
    as many steps as ghosts wait, quadratic in all.  The rows store their
    names relative to one parity, ``r.ghost_swapped``, which a rejection
    flips instead."""
    if r.ghost_swapped and (k == NEW_FIRST or k == NEW_SECOND):
        return NEW_FIRST + NEW_SECOND - k
    return k


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _up(k: Index, n: Index) -> Index:
    """Orientation (or corner) ``k`` turned ``n`` up, both 0, 1 or 2: (k + n)
    % 3 without a division (every flip and kept record takes some)."""
    k += n
    return k - 3 if k >= 3 else k


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _slot(e: Index) -> Index:
    """The slot of edge ``e`` (>= 0): e // 3, the unsigned division being the shorter."""
    return cython.cast(Index, cython.cast(cython.size_t, e) // 3)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _edge_orientation(r: Refiner, m: Mesh, e: Index) -> Index:
    """The orientation of edge ``e``'s handle in its triangle's Triangle
    record, or -1 if not known (records_known, note_born)."""
    t: Index = _slot(e)
    if not r.orient_ready or r.orient[t, 1] != m.stamp[t] or r.orient[t, 2] != m.corner[3 * t]:
        return -1
    return _up(e - 3 * t, r.orient[t, 0])


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _kept(r: Refiner, m: Mesh, row: Index, e: Index, h: Index, up: Index) -> cython.void:
    """Lineage row ``row``: edge ``e`` in the record of handle ``h``'s
    triangle (which keeps it), ``up`` orientations above ``h``'s.  Known
    (Triangle's own orientation) where the slot's is (_edge_orientation);
    else relative to ours' slot layout, which serves where both times of a
    comparison see the same layout (a rejected point's ghosts)."""
    o: Index = _edge_orientation(r, m, h)
    t: Index = _slot(h)
    r.lineage[row, 0] = e
    r.lineage[row, 1] = t
    r.lineage[row, 2] = _up(h - 3 * t if o < 0 else o, up)
    r.lineage[row, 3] = o >= 0


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _new(r: Refiner, row: Index, e: Index, rec: Index) -> cython.void:
    """Lineage row ``row``: edge ``e`` in new record ``rec``, orientation 0
    (Triangle's own)."""
    r.lineage[row, 0] = e
    r.lineage[row, 1] = rec
    r.lineage[row, 2] = 0
    r.lineage[row, 3] = 1


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
    e: Index = 0
    rec: Index = 0
    k: Index = 0
    known: Index = 0
    tw: Index
    y: Index
    held: cython.bint = False  # the stack's top row is (e, rec, k, known), not stored
    while held or top > 0:
        if not held:
            top -= 1
            e = r.lineage[top, 0]
            rec = r.lineage[top, 1]
            k = r.lineage[top, 2]
            known = r.lineage[top, 3]
        held = False
        tw = m.twin[e]
        if tw != NO_EDGE and m.seg[e] == NO_SEG and m.tflag[_slot(tw)] == 1:
            # flip: this record goes on with a -> f (lnext of the twin b -> a,
            # on top: held), the other triangle's with f -> b, one above its
            # edge b -> a
            if top + 2 > r.lineage.shape[0]:
                return False
            y = _slot(tw)
            r.flips[r.nflips, 0] = rec
            r.flips[r.nflips, 1] = y
            r.nflips += 1
            _kept(r, m, top, lprev(tw), tw, 1)
            top += 1
            e = lnext(tw)
            k = _up(k, 2)
            held = True
            continue
        if out >= nb or r.bnd[r.fan[out], 4] != e:
            return False
        r.fan_rec[out, 0] = rec
        r.fan_rec[out, 1] = k
        r.fan_rec[out, 2] = known
        out += 1
    return out == nb


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _split_lineage(r: Refiner, m: Mesh, e: Index, on_edge: cython.bint, first: Index, second: Index) -> Index:
    """Put Triangle's split of the located edge ``e`` on ``r.lineage``
    (first to flip on top) and return its height: a 1 -> 3 split of e's
    triangle (``on_edge`` False), or a 2 -> 4 split of edge e (1 -> 2
    without a twin).  ``first`` and ``second`` name the new records in the
    order the split takes them from the pool."""
    t: Index = e // 3
    tw: Index = m.twin[e]
    top: Index = 0
    if not on_edge:
        # e (org -> dest) keeps its record, dest -> apex gets the first new
        # one, apex -> org the second
        _new(r, 0, lprev(e), second)
        _new(r, 1, lnext(e), first)
        _kept(r, m, 2, e, e, 0)
        return 3
    # on e (o -> d): d -> apex keeps e's record one orientation up, o ->
    # apex' takes the first new one, apex -> o the second (the first without
    # a twin), apex' -> d keeps the twin's two up
    if tw != NO_EDGE:
        _kept(r, m, 0, lprev(tw), tw, 2)
        _new(r, 1, lnext(tw), first)
        top = 2
    _new(r, top, lprev(e), second if tw != NO_EDGE else first)
    _kept(r, m, top + 1, lnext(e), e, 1)
    return top + 2


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _rejected_split(r: Refiner, m: Mesh, e: Index, on_edge: cython.bint) -> Index:
    """``_split_lineage`` for a point about to be rejected, its new records
    named as ``rejected_fan_records`` names them: by the order the next
    split takes them, FREED_LAST first.  The undo of a split inside a
    triangle frees them so that the next split takes the second first; the
    undo of a split on an edge (2 -> 4) so that it takes the first first,
    as Triangle's -VVV "Creating ... triangle" lines show: the corpus's
    A.poly under pq33 rejects 55 points on edges whose next vertex is on
    an edge too, and each takes the records in the rejected split's order,
    where after 150 rejected points inside a triangle the order is swapped."""
    if on_edge and m.twin[e] == NO_EDGE:
        return _split_lineage(r, m, e, True, FREED_LAST, FREED_LAST)
    if on_edge:
        return _split_lineage(r, m, e, True, FREED_LAST, NEW_FIRST + NEW_SECOND - FREED_LAST)
    return _split_lineage(r, m, e, on_edge, NEW_FIRST, NEW_SECOND)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def rejected_fan_records(r: Refiner, m: Mesh, e: Index, on_edge: cython.bint, nb: Index) -> cython.bint:
    """``r.fan_rec[:nb]``: the records and orientations of the fan of a
    point inside edge ``e``'s triangle, or on edge ``e`` (``on_edge``;
    Triangle's located handle; the cavity marked, the rim in order).  False
    if they cannot be told.

    The point is about to be rejected: the ghosts waiting already (an
    earlier rejected point's, for the same vertex record) see the split
    take the two records that point's undo freed.  A split inside a
    triangle has its undo free them again the other way round (the second
    one taken is handed out first next: FREED_LAST), so their names swap:
    the rows' parity flips (_ghost_name).  A split on an edge gives them
    back in the order it took them (_rejected_split), and without a twin
    it takes one record: nothing swaps.  The names in ``r.fan_rec`` are
    the ones the point's ghost rows store."""
    if not on_edge:
        r.ghost_swapped = not r.ghost_swapped
    if not _lineage(r, m, _rejected_split(r, m, e, on_edge), nb):
        return False
    for j in range(nb):
        r.fan_rec[j, 0] = _ghost_name(r, r.fan_rec[j, 0])
    return True


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
    top: Index = _rejected_split(r, m, e, on_edge)
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
def insertion_records(r: Refiner, m: Mesh, e: Index, on_edge: cython.bint, nb: Index) -> cython.bint:
    """``r.fan_rec[:nb]``: the records and orientations of the fan of the
    vertex about to be made inside edge ``e``'s triangle, or on edge ``e``
    (``on_edge``: org o -> dest d, a subsegment's split point or a Steiner
    point on an edge; the rim in order from d), the cavity marked; its new
    records named as the pool hands them out (the last freed first).
    False if they cannot be told."""
    first: Index = FREED_LAST
    second: Index = NEW_FIRST + NEW_SECOND - FREED_LAST
    return _lineage(r, m, _split_lineage(r, m, e, on_edge, first, second), nb)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def revive_ghosts(r: Refiner, m: Mesh, ok: cython.bint, nb: Index, two: cython.bint) -> cython.bint:
    """The vertex about to be made takes the vertex record the ghosts wait
    for: revive those whose record and orientation its fan gives their
    triangle again (``r.fan_rec[:nb]``, if ``ok``: insertion_records), and
    drop the others.  Ghosts that wait for a later vertex (deletions came
    between, queues.ghosts_orphaned) go on waiting if their record is
    still theirs then: a new one if this split takes two new triangle
    records (``two``: the two the last deletion freed), a kept one if the
    split does not touch it.  Whether any was revived (the vertex's fan,
    once made, has triangles for queues.ghosts_made to note)."""
    g: Index = r.nghost - 1
    live: cython.bint
    revived: cython.bint = False
    j: Index
    k: Index
    # (the rows of the vertices made last, revived or dropped, may follow
    # those that wait for a later vertex)
    while g >= 0 and ghost_recent(r, m, g):
        if not ghost_pending(r, m, g):
            g -= 1
            continue
        if r.ghost[g, 3] <= KEPT_BY:
            # a record a deletion's polygon kept: only a later deletion that
            # frees it is followed (deletion_freed), not a split remaking it
            r.ghost[g, 0] = -1
            g -= 1
            continue
        if r.ghost[g, 2] != m.nvert:
            k = _ghost_name(r, r.ghost[g, 3])
            if k == POOL_TOP or k == POOL_BELOW:
                # one of the last deletion's records: a split point on the
                # boundary takes the top one, and the one under it is the
                # next split's first; a split taking two takes both
                if two or k == POOL_TOP:
                    r.ghost[g, 0] = -1
                else:
                    r.ghost[g, 3] = _ghost_name(r, FREED_LAST)
            # a new record's name holds if the pool is as it was (the split
            # took the two the deletion freed), a kept one if the split
            # leaves its triangle alone (outside the cavity, tflag 1)
            elif (k < 0 and not two) or (k >= 0 and m.tflag[k] == 1):
                r.ghost[g, 0] = -1
            g -= 1
            continue
        live = False
        if ok:
            for j in range(nb):
                if (r.bnd[r.fan[j], 1] == r.ghost[g, 0] and r.bnd[r.fan[j], 2] == r.ghost[g, 1]
                        and r.fan_rec[j, 0] == _ghost_name(r, r.ghost[g, 3]) and r.fan_rec[j, 1] == r.ghost[g, 4]):
                    live = True
                    break
        ghost_revive(r, g, live)
        revived = revived or live
        g -= 1
    return revived


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def note_born(r: Refiner, m: Mesh, ok: cython.bint, nb: Index, first: Index) -> cython.void:
    """The fan ``r.fan[:nb]`` is made and tested; the bucket log's entries
    from ``first`` on are the ones its test queued: remember, per slot,
    each one's entry and, where Triangle's orientation of the triangle in
    its record is known (``r.fan_rec``, if ``ok``: a record the insertion
    made, or one it kept whose orientation was known), the entry's
    orientation in it, which a deletion of the vertex may need
    (deletion_ghosts).  And each fan slot's orientation for the insertions
    to come (records_known): the fan triangle's rim edge is its edge 0."""
    t: Index
    j: Index
    for j in range(nb):
        t = r.fan[j]
        r.orient[t, 0] = r.fan_rec[j, 1] if ok else 0
        r.orient[t, 1] = m.stamp[t] if ok and r.fan_rec[j, 2] else 0
        r.orient[t, 2] = m.corner[3 * t]
    # the test queues fan triangles only, each once: an entry's orientation
    # is its slot's, just noted (known: the stamp, > 0 for a live slot)
    for i in range(first, r.log_length):
        t = r.htri[i]
        if t < 0:
            continue
        r.born[t, 0] = i
        r.born[t, 1] = r.orient[t, 0] if r.orient[t, 1] != 0 else -1
        r.born[t, 2] = m.stamp[t]


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def records_known(r: Refiner, m: Mesh) -> cython.void:
    """The first list of bad triangles is about to be made: from here on
    each slot's Triangle orientation is followed (``r.orient``: the
    handle on its edge 0).  Triangle makes that list walking its records,
    each in orientation 0, and ours' slots hold Triangle's records with
    edge 0 as that handle: the first list's entries are Triangle's
    triangle for triangle and corner for corner (la.poly under pq33: 317
    of 317, scripts/queue_trace.py; tests/engine/test_pool_order.py).
    Insertions then carry the orientations on (note_born: a record's
    orientation moves with the split and its flips), where other steps
    (Chew's deletions, splits made otherwise) leave their slots unknown:
    their stamps change."""
    for t in range(r.orient.shape[0]):
        r.orient[t, 0] = 0
        r.orient[t, 1] = m.stamp[t] if t < m.nslot and m.stamp[t] > 0 else 0
        r.orient[t, 2] = m.corner[3 * t] if t < m.nslot else -1
    r.orient_ready = True


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def requeued(r: Refiner, t: Index) -> cython.void:
    """Triangle ``t`` was queued again (the last bucket log entry) after
    its Steiner point was rejected, in the record and orientation of the
    entry served: that is the entry its insertion made now."""
    if r.born[t, 0] >= 0 and r.born[t, 0] < r.log_length and r.htri[r.born[t, 0]] == t:
        r.born[t, 0] = r.log_length - 1


#: A deletion ghost's record until the polygon's triangulation tells
#: whether it is freed: STAR_PLACE - i for the star's i-th triangle.
STAR_PLACE = cython.declare(cython.longlong, -100)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def deletion_ghosts(r: Refiner, m: Mesh, v: Index, tris: cython.longlong[:], d: Index) -> cython.void:
    """Chew's rule is about to delete free vertex ``v``, whose star is
    ``tris[:d]`` (``tris[i]`` = (v, w[i], w[i+1]), counter-clockwise;
    ``tris[0]`` on the subsegment).  Triangle's queue entries hold vertex
    records: an entry of a triangle of the star queued as ``v``'s
    insertion made it reads (w[i], w[i+1], v) and matches again if the
    next vertex made (the subsegment's split point, which takes ``v``'s
    vertex record) remakes (w[i], w[i+1], itself) in the same record and
    orientation.  The deletion frees two of the star's records
    (deletion_freed); those entries turn into ghosts, in their places, of
    the star triangles whose orientation in their records is known
    (note_born, note_deleted): queued by ``v``'s insertion, or by a later
    vertex's (``v`` then a corner of the entry's base edge), or by an
    earlier deletion's flips.  The ghosts waiting already wait for a later
    vertex (queues.ghosts_orphaned: the next takes ``v``'s record, the
    last freed)."""
    ghosts_orphaned(r, m)
    t: Index
    i: Index
    g: Index = r.nghost - 1
    c: Index
    # the ghosts that now wait for a later vertex keep a kept record only if
    # the deletion leaves it alone (not a triangle of the star), but for a
    # deletion's ghost in a record that outlived that deletion: this one
    # frees it or keeps it again (deletion_freed, deletion_orientations),
    # as with the star's own entries; and the records an earlier deletion
    # freed are under this one's in the pool (no longer followed)
    while g >= 0 and ghost_recent(r, m, g):
        if ghost_pending(r, m, g):
            c = r.ghost[g, 3]
            if c == POOL_TOP or c == POOL_BELOW:
                r.ghost[g, 0] = -1
            elif c >= 0 or c <= KEPT_BY:
                for k in range(d):
                    if tris[k] == (c if c >= 0 else KEPT_BY - c):
                        if c >= 0 or k == 0:
                            r.ghost[g, 0] = -1
                        else:
                            r.ghost[g, 3] = STAR_PLACE - k
                        break
        g -= 1
    for k in range(1, d):
        t = tris[k]
        i = r.born[t, 0]
        if (r.born[t, 1] < 0 or r.born[t, 2] != m.stamp[t]
                or not entry_waiting(r, m, i, t) or r.nghost >= r.ghost.shape[0]):
            continue
        # the entry reads (corner 1, corner 2, corner 0) in orientation
        # born[t, 1]; as a ghost it reads (w[k], w[k+1], v), the same
        # triangle from v: one orientation up per corner v is past corner 0
        c = 0
        while c < 3 and m.corner[3 * t + c] != v:
            c += 1
        if c == 3:
            continue
        g = r.nghost
        r.nghost = g + 1
        r.ghost[g, 0] = m.corner[3 * t + (c + 1) % 3]
        r.ghost[g, 1] = m.corner[3 * t + (c + 2) % 3]
        r.ghost[g, 2] = m.nvert
        r.ghost[g, 3] = STAR_PLACE - k
        r.ghost[g, 4] = _up(r.born[t, 1], c)
        entry_to_ghost(r, i, g)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def deletion_freed(r: Refiner, m: Mesh, j: Index, d: Index) -> cython.void:
    """The deletion's polygon joined its base to the star's ``j``-th
    vertex: Triangle flips the star's edges away until the vertex has three
    triangles left, each flip keeping the vertex in the later triangle's
    record (counter-clockwise), so the two that go with it are the last
    triangle of each side, (v, w[j-1], w[j]) and (v, w[d-1], w[0]), the
    first freed last (the subsegment's split takes it first).  Their
    ghosts wait under those names, the next vertex's (FREED_LAST and the
    other), or for the vertex after it POOL_TOP and POOL_BELOW (a ghost
    that an earlier deletion's record kept: revive_ghosts); the others
    are the polygon's records now (deletion_orientations).

    Case 50 of the near-collinear chains under pq34a0.000899cvi shows the
    latter (Triangle's -VVV record pointers): a deletion's flip queues a
    triangle in record R, orientation 0; the next deletion, of one of its
    vertices, keeps R as an ear of its polygon; a third frees R and a
    record under it in the pool; the boundary split point takes the
    third's vertex record and the top triangle record, the next
    circumcenter the second's vertex record and R as its split's first
    new record, and its flips leave the entry's triangle there again."""
    g: Index = r.nghost - 1
    k: Index
    later: cython.bint
    while g >= 0 and ghost_recent(r, m, g):
        k = STAR_PLACE - r.ghost[g, 3]
        if ghost_pending(r, m, g) and STAR_PLACE - d < r.ghost[g, 3] <= STAR_PLACE and (k == j - 1 or k == d - 1):
            later = r.ghost[g, 2] != m.nvert
            if later and r.ghost[g, 2] != m.nvert + 1:
                r.ghost[g, 0] = -1
            elif k == j - 1:
                r.ghost[g, 3] = POOL_TOP if later else _ghost_name(r, FREED_LAST)
            else:
                r.ghost[g, 3] = POOL_BELOW if later else _ghost_name(r, NEW_FIRST + NEW_SECOND - FREED_LAST)
        g -= 1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _place(p: Index, d: Index) -> Index:
    """A star place as deletion.py's vertex map gives it (w0 as d) -> 0 .. d-1."""
    return 0 if p == d else p


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def star_orientations(r: Refiner, m: Mesh, v: Index, tris: cython.longlong[:], d: Index) -> cython.void:
    """Chew's rule is about to delete ``v``, whose star is ``tris[:d]``
    (``tris[i]`` = (v, w[i], w[i+1]), counter-clockwise): per place i, in
    ``r.lineage[i]``, the orientation of the handle v -> w[i] in the
    record of the star triangle (v, w[i], w[i+1]), whether it is known
    (_edge_orientation), and the places before and after i around v, for
    deletion_orientations."""
    t: Index
    c: Index
    o: Index
    for i in range(d):
        t = tris[i]
        c = 0
        while c < 2 and m.corner[3 * t + c] != v:
            c += 1
        # the edge out of v (org v: corner (k + 1) % 3) is edge (c + 2) % 3
        o = _edge_orientation(r, m, 3 * t + (c + 2) % 3) if m.corner[3 * t + c] == v else -1
        r.lineage[i, 0] = o if o >= 0 else 0
        r.lineage[i, 1] = o >= 0
        r.lineage[i, 2] = (i + d - 1) % d
        r.lineage[i, 3] = (i + 1) % d


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def deletion_orientations(r: Refiner, m: Mesh, order: cython.longlong[:], made: Index, slot: cython.longlong[:],
                          d: Index) -> cython.void:
    """The deletion's polygon is triangulated: ``order[:made - 1]`` its
    triangles but the base one, (apex z, base org, base dest), in the
    order Triangle's flips make them (deletion.py), ``slot`` each star
    vertex's place (w0 as d).  Each flip removes z from v's star: the
    triangles (v, p, z) and (v, z, n) around it, p and n its neighbours
    there, become the ear (p, z, n) and (v, p, n).  As Triangle's -VVV
    "Edge flip results in left triangle ... and right triangle ..." lines
    show (the 21-point star's deletions, step 10), the ear takes the
    record of (v, p, z), with its handle n -> p in the orientation that
    record's handle z -> v had, and (v, p, n) takes the record of
    (v, z, n), its handle v -> p two above that record's v -> z.  So each
    ear's orientation is known where the star's were (star_orientations),
    for the entry the deletion queues it with (note_deleted) and the
    insertions to come (records_known); a triangulation that does not
    follow (a check that should not fail) leaves the rest unknown."""
    t: Index
    z: Index
    p: Index
    n: Index
    # which star place's record each place's triangle holds (r.fan_rec's
    # column 0), and which ear keeps each place's record (column 1; -1: freed
    # or the base's), for the ghosts in them (_kept_ghosts)
    for i in range(d):
        r.fan_rec[i, 0] = i
        r.fan_rec[i, 1] = -1
    for i in range(made - 1):
        t = order[i]
        z = _place(slot[m.corner[3 * t]], d)
        p = r.lineage[z, 2]
        n = r.lineage[z, 3]
        if _place(slot[m.corner[3 * t + 1]], d) != n or _place(slot[m.corner[3 * t + 2]], d) != p:
            for j in range(i, made - 1):
                r.orient[order[j], 1] = 0
            _kept_ghosts(r, m, d)
            return
        r.fan_rec[r.fan_rec[p, 0], 1] = t
        r.fan_rec[p, 0] = r.fan_rec[z, 0]
        # ours' edge 0 of (z, n, p) is n -> p, the ear's handle
        r.orient[t, 0] = _up(r.lineage[p, 0], 2)
        r.orient[t, 1] = m.stamp[t] if r.lineage[p, 1] else 0
        r.orient[t, 2] = m.corner[3 * t]
        r.lineage[p, 0] = _up(r.lineage[z, 0], 2)
        r.lineage[p, 1] = r.lineage[z, 1]
        r.lineage[p, 3] = n
        r.lineage[n, 2] = p
    _kept_ghosts(r, m, d)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _kept_ghosts(r: Refiner, m: Mesh, d: Index) -> cython.void:
    """The ghosts of the star places whose records the deletion's polygon
    keeps (``r.fan_rec[:d, 1]``: deletion_orientations) wait in them under
    their triangles' slots (KEPT_BY); the others (the base's record, or a
    triangulation not followed) are dropped."""
    g: Index = r.nghost - 1
    k: Index
    while g >= 0 and ghost_recent(r, m, g):
        k = STAR_PLACE - r.ghost[g, 3]
        if ghost_pending(r, m, g) and 0 <= k < d:
            if r.fan_rec[k, 1] >= 0:
                r.ghost[g, 3] = KEPT_BY - r.fan_rec[k, 1]
            else:
                r.ghost[g, 0] = -1
        g -= 1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def note_deleted(r: Refiner, m: Mesh, first: Index) -> cython.void:
    """A deletion's triangles are tested; the bucket log's entries from
    ``first`` on are the ones the test queued: remember, per slot, each
    one's entry and its orientation in its record where known
    (deletion_orientations), for a deletion of one of its vertices in turn
    (deletion_ghosts)."""
    t: Index
    for i in range(first, r.log_length):
        t = r.htri[i]
        if t < 0:
            continue
        r.born[t, 0] = i
        r.born[t, 1] = _edge_orientation(r, m, 3 * t)
        r.born[t, 2] = m.stamp[t]
