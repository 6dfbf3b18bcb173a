# The bad-triangle queue (queues.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.refine.order cimport TRIANGLE
from instrument.refine.state cimport Refiner

cpdef enum:
    GHOST_LIVE = 9   # a ghost row's orientation once its vertex's insertion has revived it
    # how many Chew deletions a ghost row may wait through (queues.ghosts_orphaned): each
    # puts its vertex one later, so the rows of the vertices made since are the last ones,
    # whose vertex is at most this many + 1 before the next (ghost_recent)
    GHOST_DEFER = 2

cpdef void queue_clear(Refiner r) noexcept nogil
cpdef void bucket_make_ready(Refiner r, Index b) noexcept nogil
cpdef Index queue_pop(Refiner r) noexcept nogil
cpdef void queue_compact(Refiner r, Mesh m) noexcept nogil
cpdef void queue_push_ghost(Refiner r, double key, Index org, Index dest, Index v, Index rec, Index k) noexcept nogil
cpdef bint ghost_room(Refiner r, Index n) noexcept nogil
cpdef Index ghost_slot(Refiner r, Mesh m, Index g) noexcept nogil
cpdef void ghost_revive(Refiner r, Index g, bint live) noexcept nogil
cpdef void ghosts_orphaned(Refiner r, Mesh m) noexcept nogil
cpdef void ghosts_made(Refiner r, Mesh m, Index v) noexcept nogil
cpdef bint entry_waiting(Refiner r, Mesh m, Index i, Index t) noexcept nogil
cpdef void entry_to_ghost(Refiner r, Index i, Index g) noexcept nogil


# Defined here so that the kernels inline them (every bad triangle is
# pushed, every step checks the room, each insertion walks back over the
# last ghost rows); queues.py repeats them for the pure-Python mode.

cpdef inline bint ghost_pending(Refiner r, Mesh m, Index g) noexcept nogil:
    # does ghost row g wait for its vertex (not made yet)?
    return r.ghost[g, 0] >= 0 and r.ghost[g, 4] != GHOST_LIVE and r.ghost[g, 2] >= m.nvert


cpdef inline bint ghost_recent(Refiner r, Mesh m, Index g) noexcept nogil:
    # is ghost row g among the last rows, those that may wait for a vertex
    # not made yet, or were made for one of the last vertices?  Rows are
    # added as their entries are queued, for the next vertex made, and wait
    # at most GHOST_DEFER vertices more: a walk back from the last row while
    # this holds meets every row still waiting
    return r.ghost[g, 2] >= m.nvert - GHOST_DEFER - 1


cdef inline bint _bucketed(Refiner r) noexcept nogil:
    return r.cfg.strategy == TRIANGLE


cdef inline bint _heap_less(Refiner r, Index i, Index j) noexcept nogil:
    if r.hkey[i] != r.hkey[j]:
        return r.hkey[i] < r.hkey[j]
    return r.hseq[i] < r.hseq[j]


cdef inline void _heap_swap(Refiner r, Index i, Index j) noexcept nogil:
    r.hkey[i], r.hkey[j] = r.hkey[j], r.hkey[i]
    r.hseq[i], r.hseq[j] = r.hseq[j], r.hseq[i]
    r.htri[i], r.htri[j] = r.htri[j], r.htri[i]
    r.hstamp[i], r.hstamp[j] = r.hstamp[j], r.hstamp[i]


cdef inline void _bucket_append(Refiner r, Index i) noexcept nogil:
    # link entry i at the tail of its bucket (key = -bucket)
    cdef Index b = <Index>(-r.hkey[i])
    r.hseq[i] = -1
    cdef Index tail = r.bucket[1, b]
    if tail >= 0:
        r.hseq[tail] = i
    else:
        r.bucket[0, b] = i
    r.bucket[1, b] = i
    if b > r.top_bucket:
        r.top_bucket = b


cpdef inline void queue_push(Refiner r, double key, Index t, long long stamp) noexcept nogil:
    # queue triangle t (the caller made sure there is room)
    cdef Index i
    cdef Index up
    if _bucketed(r):
        i = r.log_length
        r.log_length = i + 1
        r.hsize += 1
        r.seq += 1
        r.hkey[i] = key
        r.htri[i] = <int>t
        r.hstamp[i] = <int>stamp
        _bucket_append(r, i)
        return
    i = r.hsize
    r.hsize = i + 1
    r.hkey[i] = key
    r.hseq[i] = r.seq
    r.seq += 1
    r.htri[i] = <int>t
    r.hstamp[i] = <int>stamp
    while i > 0:
        up = (i - 1) // 2
        if not _heap_less(r, i, up):
            break
        _heap_swap(r, i, up)
        i = up


cpdef inline Index queue_used(Refiner r) noexcept nogil:
    # queue entries in use: the heap's size, or the bucket log's length
    # (served and stale entries included, until a compaction)
    return r.log_length if r.cfg.strategy == TRIANGLE else r.hsize
