# cython: language_level=3
"""The bad-triangle queue.

The bad triangles wait in a binary heap ordered by (key, insertion number),
except under strategy "triangle", whose keys are Triangle's 4096 bucket
numbers (and more past its finest, order.wide_bucket): there, as in
Triangle, a FIFO list per bucket queues and serves in constant time.  Both
orders are the same; the buckets are just faster.

The bucket lists live in an append-only log (entries linked through
``hseq``; -1 ends a list, POPPED marks an entry served): a push writes the
next entry in order, so the writes stream through memory, and a
compaction is one sweep in log order, which within a bucket is FIFO order.
(A free list of served entries made every push a cache miss.)

An entry remembers its triangle's stamp: a triangle split or deleted since
it was queued has another stamp, and the entry is stale (lazy deletion, as
Triangle checks its records).

A Steiner point Triangle rejects has queued bad triangles before it is
rejected (ghost entries, ``queue_push_ghost``): they are served, in their
place, if the vertex that next takes its record rebuilds their triangle in
the same triangle record (ghosts.py).
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import Index, Mesh
from cython.cimports.instrument.core.navigate import find_edge
from cython.cimports.instrument.refine.order import TRIANGLE
from cython.cimports.instrument.refine.state import Refiner

#: The bucket log marks a served entry so.
POPPED = cython.declare(cython.longlong, -2)

if not cython.compiled:  # compiled, these are queues.pxd's
    #: A ghost row's orientation once its vertex's insertion has revived it.
    GHOST_LIVE = 9

    #: How many Chew deletions a ghost row may wait through (ghosts_orphaned):
    #: each puts its vertex one later.  The rows of the vertices made since
    #: are then the last ones, whose vertex is at most this many + 1 before
    #: the next (ghost_recent).
    GHOST_DEFER = 2


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def queue_clear(r: Refiner) -> cython.void:
    """Empty the queue.

    Only a bucket that holds an entry of the log can be non-empty (a new
    queue, a compaction and this leave every bucket empty, and pops empty
    them), and none does when no entry is queued: so only those are reset,
    and only then.  (Refinement clears a new queue, all 4,096 buckets, 64
    KB, where la.poly's whole run queues 2,700 entries.)"""
    b: Index
    if r.hsize > 0 and _bucketed(r):
        for i in range(r.log_length):
            b = cython.cast(Index, -r.hkey[i])
            r.bucket[0, b] = -1
            r.bucket[1, b] = -1
    r.hsize = 0
    r.top_bucket = -1
    r.log_length = 0
    r.nghost = 0


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def bucket_make_ready(r: Refiner, b: Index) -> cython.void:
    """Set up the empty buckets up to ``b`` (past Triangle's 4096, only a
    mesh graded beyond the doubles' squares needs them: order.wide_bucket)."""
    for k in range(r.bucket_ready, b + 1):
        r.bucket[0, k] = -1
        r.bucket[1, k] = -1
    if b >= r.bucket_ready:
        r.bucket_ready = b + 1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _sift_down(r: Refiner, i: Index, n: Index) -> cython.void:
    c: Index
    while True:
        c = 2 * i + 1
        if c >= n:
            break
        if c + 1 < n and _heap_less(r, c + 1, c):
            c += 1
        if not _heap_less(r, c, i):
            break
        _heap_swap(r, i, c)
        i = c


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def queue_pop(r: Refiner) -> Index:
    """Take the first entry off the queue and return its slot, whose fields
    stay readable until the next push (the next compaction for buckets)."""
    n: Index = r.hsize - 1
    r.hsize = n
    b: Index
    i: Index
    nxt: Index
    if _bucketed(r):
        b = r.top_bucket
        i = r.bucket[0, b]
        nxt = r.hseq[i]
        r.bucket[0, b] = nxt
        if nxt < 0:
            r.bucket[1, b] = -1
            while b >= 0 and r.bucket[0, b] < 0:
                b -= 1
            r.top_bucket = b
        r.hseq[i] = POPPED
        return i
    _heap_swap(r, 0, n)
    _sift_down(r, 0, n)
    return n


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def queue_compact(r: Refiner, m: Mesh) -> cython.void:
    """Drop the stale entries (triangles split or gone since they were
    queued; in the bucket log also the served ones), keeping the order of
    the rest; without this, an order that re-queues the same region
    (``smallest`` on I(n)) keeps quadratically many dead entries."""
    n: Index = 0
    if _bucketed(r):
        for k in range(r.bucket_ready):
            r.bucket[0, k] = -1
            r.bucket[1, k] = -1
        r.top_bucket = -1
        ng: Index = 0
        g: Index
        for i in range(r.log_length):
            if r.hseq[i] == POPPED:
                continue
            if r.htri[i] < 0:  # a ghost (rows in log order): kept while it may be served
                g = -1 - r.htri[i]
                if not ghost_pending(r, m, g) and ghost_slot(r, m, g) < 0:
                    continue
                for c in range(5):
                    r.ghost[ng, c] = r.ghost[g, c]
                r.htri[i] = cython.cast(cython.int, -1 - ng)
                ng += 1
            elif m.stamp[r.htri[i]] != r.hstamp[i]:
                continue
            elif r.born[r.htri[i], 0] == i:  # the entry its insertion queued it with moves
                r.born[r.htri[i], 0] = n
            r.hkey[n] = r.hkey[i]
            r.htri[n] = r.htri[i]
            r.hstamp[n] = r.hstamp[i]
            _bucket_append(r, n)
            n += 1
        r.nghost = ng
        r.log_length = n
        r.hsize = n
        return
    # (key, insertion number) orders entries totally: rebuilding the heap
    # leaves the pop order of the rest unchanged
    for i in range(r.hsize):
        if m.stamp[r.htri[i]] == r.hstamp[i]:
            r.hkey[n] = r.hkey[i]
            r.hseq[n] = r.hseq[i]
            r.htri[n] = r.htri[i]
            r.hstamp[n] = r.hstamp[i]
            n += 1
    r.hsize = n
    for i in range(n // 2 - 1, -1, -1):
        _sift_down(r, i, n)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def queue_push_ghost(r: Refiner, key: cython.double, org: Index, dest: Index, v: Index, rec: Index, k: Index) -> cython.void:
    """Queue the triangle (org, dest, v) that a rejected Steiner point's
    insertion made, as Triangle does before it finds that the point
    encroaches a subsegment and undoes it (bucket order only; the caller
    made sure there is room, ``ghost_room``).

    Triangle's entry holds the triangle's record and orientation and its
    corners' vertex records, and is served only if they still match.  The
    point's vertex record goes back to the pool and the next vertex made
    takes it (``v``: that vertex's number here).  Should that vertex's
    insertion leave (org, dest, v) in the same triangle record (``rec``)
    and orientation (``k``), which ghosts.revive_ghosts decides, the entry
    matches again, in its queued place (``ghost_slot``)."""
    g: Index = r.nghost
    r.nghost = g + 1
    r.ghost[g, 0] = org
    r.ghost[g, 1] = dest
    r.ghost[g, 2] = v
    r.ghost[g, 3] = rec
    r.ghost[g, 4] = k
    i: Index = r.log_length
    r.log_length = i + 1
    r.hsize += 1
    r.seq += 1
    r.hkey[i] = key
    r.htri[i] = cython.cast(cython.int, -1 - g)
    r.hstamp[i] = 0
    _bucket_append(r, i)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def ghost_room(r: Refiner, n: Index) -> cython.bint:
    """Room for ``n`` more ghost entries' rows?  If not, says how many the
    driver must add (``r.need``)."""
    if r.nghost + n <= r.ghost.shape[0]:
        return True
    r.need = max(r.need, n + 4)
    return False


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def ghost_slot(r: Refiner, m: Mesh, g: Index) -> Index:
    """The live triangle ghost row ``g`` matches now, or -1: the row was
    revived (its record holds the triangle again, ghosts.revive_ghosts) and
    the triangle with edge org -> dest and its vertex as apex is still the
    one it revived (the stamp ghosts_made noted: a triangle split and made
    again, by a deletion say, is in another record)."""
    if r.ghost[g, 0] < 0 or r.ghost[g, 4] != GHOST_LIVE:
        return -1
    v: Index = r.ghost[g, 2]
    e: Index = find_edge(m, r.ghost[g, 0], r.ghost[g, 1])
    if e < 0 or m.corner[e] != v or m.stamp[e // 3] != r.ghost[g, 3]:
        return -1
    return e // 3


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def ghost_revive(r: Refiner, g: Index, live: cython.bint) -> cython.void:
    """Ghost row ``g``'s vertex has been inserted: its record holds its
    triangle again (``live``: served when popped), or not (dropped)."""
    if live:
        r.ghost[g, 4] = GHOST_LIVE
        r.ghost[g, 3] = -1  # its triangle's stamp: ghosts_made
    else:
        r.ghost[g, 0] = -1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def ghosts_made(r: Refiner, m: Mesh, v: Index) -> cython.void:
    """Vertex ``v``'s fan is made: note the stamps of the triangles that
    the ghosts it revived stand for (the last rows, waiting for ``v``)."""
    g: Index = r.nghost - 1
    e: Index
    # (rows of earlier vertices may come after these: ghosts_orphaned)
    while g >= 0 and ghost_recent(r, m, g):
        if r.ghost[g, 2] == v and r.ghost[g, 0] >= 0 and r.ghost[g, 4] == GHOST_LIVE and r.ghost[g, 3] == -1:
            e = find_edge(m, r.ghost[g, 0], r.ghost[g, 1])
            if e >= 0 and m.corner[e] == v:
                r.ghost[g, 3] = m.stamp[e // 3]
            else:
                r.ghost[g, 0] = -1
        g -= 1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def entry_waiting(r: Refiner, m: Mesh, i: Index, t: Index) -> cython.bint:
    """Is bucket log entry ``i`` a queued, unserved entry of triangle
    ``t`` as it is now?  (``i`` may be any number: a slot's record of it
    outlives the entry, ghosts.note_born.)"""
    return (0 <= i < r.log_length and r.htri[i] == t and r.hstamp[i] == m.stamp[t]
            and r.hseq[i] != POPPED)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def entry_to_ghost(r: Refiner, i: Index, g: Index) -> cython.void:
    """Bucket log entry ``i`` now waits, in its place, as ghost row ``g``."""
    r.htri[i] = cython.cast(cython.int, -1 - g)
    r.hstamp[i] = 0


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def ghosts_orphaned(r: Refiner, m: Mesh) -> cython.void:
    """A vertex is deleted before the ghosts' vertex was made: Triangle's
    pools hand out its records first (last in, first out), so the vertex
    made next (the subsegment's split point) takes the deleted vertex's
    record, and the split's two triangle records are the two the deletion
    freed; the vertex after takes the record the ghosts wait for, with the
    triangle records as they were.  So the waiting ghosts (the last rows)
    now wait for the vertex after the next (revive_ghosts keeps them only
    if the next split takes two triangle records), as the 20-point star,
    step 8, under pq30 shows (Triangle rejects (0.57953, 0.31312), deletes
    (0.57445, 0.29750), splits a subsegment, and serves the rejected
    point's entry of (0.59663, 0.34549) (0.57873, 0.34549) when its next
    circumcenter, (0.58768, 0.32792), remakes it).  Ghosts already waiting
    so GHOST_DEFER times are dropped (the 13-point star, step 5, under
    pq30 serves a rejected point's entry two vertices after two deletions:
    the split point takes the second deleted vertex's record, the next
    circumcenter the first's, the one after the rejected point's)."""
    g: Index = r.nghost - 1
    while g >= 0 and ghost_recent(r, m, g):
        if ghost_pending(r, m, g):
            if r.ghost[g, 2] < m.nvert + GHOST_DEFER:
                r.ghost[g, 2] += 1
            else:
                r.ghost[g, 0] = -1
        g -= 1


# Pushing, the room check and the ghost rows' walk: compiled, queues.pxd's
# inline definitions (every bad triangle is pushed, every step checks the
# room, each insertion walks back over the last ghost rows); the same
# functions for the pure-Python mode.
if not cython.compiled:

    def ghost_pending(r: Refiner, m: Mesh, g: Index) -> bool:
        """Does ghost row ``g`` wait for its vertex (not made yet)?"""
        return r.ghost[g, 0] >= 0 and r.ghost[g, 4] != GHOST_LIVE and r.ghost[g, 2] >= m.nvert

    def ghost_recent(r: Refiner, m: Mesh, g: Index) -> bool:
        """Is ghost row ``g`` among the last rows, those that may wait for a
        vertex not made yet, or were made for one of the last vertices?  Rows
        are added as their entries are queued, for the next vertex made, and
        wait at most GHOST_DEFER vertices more: a walk back from the last row
        while this holds meets every row still waiting."""
        return r.ghost[g, 2] >= m.nvert - GHOST_DEFER - 1

    def _bucketed(r: Refiner) -> bool:
        return r.cfg.strategy == TRIANGLE

    def _heap_less(r: Refiner, i: Index, j: Index) -> bool:
        if r.hkey[i] != r.hkey[j]:
            return r.hkey[i] < r.hkey[j]
        return r.hseq[i] < r.hseq[j]

    def _heap_swap(r: Refiner, i: Index, j: Index) -> None:
        r.hkey[i], r.hkey[j] = r.hkey[j], r.hkey[i]
        r.hseq[i], r.hseq[j] = r.hseq[j], r.hseq[i]
        r.htri[i], r.htri[j] = r.htri[j], r.htri[i]
        r.hstamp[i], r.hstamp[j] = r.hstamp[j], r.hstamp[i]

    def _bucket_append(r: Refiner, i: Index) -> None:
        """Link entry ``i`` at the tail of its bucket (key = -bucket)."""
        b = int(-r.hkey[i])
        r.hseq[i] = -1
        tail = r.bucket[1, b]
        if tail >= 0:
            r.hseq[tail] = i
        else:
            r.bucket[0, b] = i
        r.bucket[1, b] = i
        if b > r.top_bucket:
            r.top_bucket = b

    def queue_push(r: Refiner, key: float, t: Index, stamp: int) -> None:
        """Queue triangle ``t`` (the caller made sure there is room)."""
        if _bucketed(r):
            i = r.log_length
            r.log_length = i + 1
            r.hsize += 1
            r.seq += 1
            r.hkey[i] = key
            r.htri[i] = t
            r.hstamp[i] = stamp
            _bucket_append(r, i)
            return
        i = r.hsize
        r.hsize = i + 1
        r.hkey[i] = key
        r.hseq[i] = r.seq
        r.seq += 1
        r.htri[i] = t
        r.hstamp[i] = stamp
        while i > 0:
            up = (i - 1) // 2
            if not _heap_less(r, i, up):
                break
            _heap_swap(r, i, up)
            i = up

    def queue_used(r: Refiner) -> Index:
        """Queue entries in use: the heap's size, or the bucket log's length
        (served and stale entries included, until a compaction)."""
        return r.log_length if _bucketed(r) else r.hsize
