# cython: language_level=3
"""The bad-triangle queue.

The bad triangles wait in a binary heap ordered by (key, insertion number),
except under strategy "triangle", whose keys are Triangle's 4096 bucket
numbers: there, as in Triangle, a FIFO list per bucket queues and serves in
constant time.  Both orders are the same; the buckets are just faster.

The bucket lists live in an append-only log (entries linked through
``hseq``; -1 ends a list, POPPED marks an entry served): a push writes the
next entry in order, so the writes stream through memory, and a
compaction is one sweep in log order, which within a bucket is FIFO order.
(A free list of served entries made every push a cache miss.)

An entry remembers its triangle's stamp: a triangle split or deleted since
it was queued has another stamp, and the entry is stale (lazy deletion, as
Triangle checks its records).
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import Index, Mesh
from cython.cimports.instrument.refine.order import TRIANGLE
from cython.cimports.instrument.refine.state import Refiner

#: The bucket log marks a served entry so.
POPPED = cython.declare(cython.longlong, -2)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def queue_clear(r: Refiner) -> cython.void:
    """Empty the queue."""
    r.hsize = 0
    r.top_bucket = -1
    r.log_length = 0
    for k in range(r.bucket.shape[1]):
        r.bucket[0, k] = -1
        r.bucket[1, k] = -1


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
        for k in range(r.bucket.shape[1]):
            r.bucket[0, k] = -1
            r.bucket[1, k] = -1
        r.top_bucket = -1
        for i in range(r.log_length):
            if r.hseq[i] != POPPED and m.stamp[r.htri[i]] == r.hstamp[i]:
                r.hkey[n] = r.hkey[i]
                r.htri[n] = r.htri[i]
                r.hstamp[n] = r.hstamp[i]
                _bucket_append(r, n)
                n += 1
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


# Pushing, and the room check: compiled, queues.pxd's inline definitions
# (every bad triangle is pushed, every step checks the room); the same
# functions for the pure-Python mode.
if not cython.compiled:

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
