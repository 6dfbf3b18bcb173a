# Refinement's state (state.py): its configuration, and what the loop keeps between calls.
from instrument.core.mesh cimport Index
from libc.string cimport memcpy

cpdef enum:         # trace rows' kinds (state.TRACE_KINDS names them)
    T_SEGMENT = 0
    T_CIRCUMCENTER = 1
    T_OFFCENTER = 2
    T_REJECTED = 3
    T_DELETED = 4

cdef class Config:
    cdef public int strategy         # order.pxd's ids
    cdef public bint diametral       # -D: diametral circles instead of lenses
    cdef public int keep_segments    # -Y: 1 keeps boundary subsegments whole, 2 (-YY) all of them
    cdef public bint fixed_area      # -a<A>: the bound max_area
    cdef public double max_area
    cdef public bint regional_area   # a bare -a: per-triangle bounds (Mesh.area_bound)
    cdef public bint offcenter       # off-centers (Üngör's, as Triangle), else circumcenters
    cdef public bint angle_test      # -q: the minimum-angle test is on
    cdef public bint builtin_user    # -u without a Python test: Triangle's sample triunsuitable
    cdef public double good_angle    # cos^2 of the minimum angle
    cdef public double lens          # (2 cos^2 - 1)^2, the diametral lens test
    cdef public double off_constant  # the off-center's distance from the shortest edge, over its length
    cdef public double key_unit      # a power of two: Triangle's bucket keys are squared edges in these units

cdef class Refiner:
    cdef public Config cfg
    # the loop
    cdef public int phase            # 0 split the input's encroached subsegments, 1 queue bad triangles, 2 main loop
    cdef public long long budget     # Steiner points left, -1 = unlimited
    cdef public Index current        # triangle being split, kept across a NEED_ROOM (-1 none)
    cdef public long long current_stamp  # and its stamp when it was queued
    cdef public double current_key   # and its queue key
    cdef public Index since_pause    # queue pops and subsegment splits since the last PAUSE
    cdef public Index need           # with NEED_ROOM: the triangles (and queue entries) one step needs
    cdef public Index error_org      # with PRECISION: the subsegment's end vertices
    cdef public Index error_dest
    cdef public Index error_apex     # with PRECISION from a bad triangle: its third vertex (else -1)
    cdef public long long[::1] work_begun  # the work counters as the current step began (step_begins)
    # the bad-triangle queue: a heap, or Triangle's buckets (queues.py)
    cdef public double[::1] hkey     # key (smaller first)
    cdef public long long[::1] hseq  # insertion number (ties); in the bucket log: the next entry
    cdef public int[::1] htri        # triangle slot (int32, as the mesh's links: a smaller queue)
    cdef public int[::1] hstamp      # and its stamp when queued (int32, as Mesh.stamp)
    cdef public long long[:, ::1] bucket  # (2, NBUCKETS) each bucket's first and last log entry, -1 empty
    cdef public Index bucket_ready   # buckets from here on are not set yet (queues.bucket_make_ready)
    cdef public Index hsize          # entries queued
    cdef public long long seq        # insertions so far
    cdef public Index top_bucket     # the highest non-empty bucket, -1 none
    cdef public Index log_length     # bucket log entries (live, served and stale)
    cdef public Index compact_at     # compact the queue when it grows past this
    # entries a rejected insertion queued (queues.queue_push_ghost): rows (org, dest, the vertex
    # that may revive them, Triangle's record (ghosts.py), its orientation or GHOST_LIVE); a
    # bucket log entry with htri = -1 - row is one of them
    cdef public long long[:, ::1] ghost
    cdef public Index nghost         # rows in use
    cdef public bint ghost_swapped   # the pending rows' new-record names read swapped (ghosts.ghost_name)
    # the encroached-subsegment pool (encroach.py)
    cdef public long long[:, ::1] enc  # (E, 4): ends (-1: free slot), edge, its triangle's stamp
    cdef public Index enc_live       # records in the pool
    cdef public Index enc_fresh      # slots ever used
    cdef public Index enc_free       # last freed slot, -1 none (freed slots chain through column 1)
    cdef public Index enc_cursor     # the slot the current pass is at
    cdef public Index enc_low        # no record lies below this slot (a pass starts here, not at 0)
    cdef public bint enc_busy        # a pass is under way (resume at enc_cursor)
    cdef public Index acute_slot     # the pool record whose ends' flags ``acute`` holds (-1 none)
    cdef public int acute            # its ends next to another subsegment as it was pooled: 1 org, 2 dest
    # scratch of one insertion (cavity.py)
    cdef public long long[::1] cav   # cavity triangles (and, from the end, those tested outside)
    cdef public long long[::1] fan   # the rim's rows in order (cavity.order_rim), then the triangles an insertion made
    cdef public long long[:, ::1] bnd  # cavity rim edges: (outer twin, org, dest, record, edge)
    cdef public double[:, ::1] bval  # and the area bound and attribute each passes on
    cdef public double[::1] carry    # the area bound each cavity triangle passes on (cavity.py)
    cdef public long long[:, ::1] lineage  # ghosts.py: the flips' stack (edge, record, orientation, known)
    cdef public long long[:, ::1] fan_rec  # ghosts.py: each fan triangle's record, orientation, known
    cdef public long long[:, ::1] flips    # ghosts.py: the two records of each flip, in Triangle's order
    cdef public Index nflips         # rows in use
    # ghosts.py: per slot, the entry its insertion queued it with (log index), that entry's
    # orientation in its record if the insertion made the record (else -1), and the slot's stamp then
    cdef public long long[:, ::1] born
    # ghosts.py: per slot, the orientation in its Triangle record of the handle on its edge 0,
    # with the slot's stamp and corner 0 then (read only where both still hold), and whether
    # the table holds anything yet (the first list of bad triangles sets it: ghosts.records_known)
    cdef public long long[:, ::1] orient
    cdef public bint orient_ready
    # the trace (empty: off)
    cdef public long long[:, ::1] trace  # rows: kind, created, deleted, walk steps, queue length
    cdef public Index ntrace

# Defined here so that the kernels inline them (every step calls them);
# state.py repeats them for the pure-Python mode.

cpdef inline void step_begins(Refiner r, long long[::1] work) noexcept nogil:
    # remember the work counters as a step (a split) begins (one block copy:
    # every step does it, and the element loop cost ~1% of refinement)
    memcpy(&r.work_begun[0], &work[0], work.shape[0] * sizeof(long long))


cpdef inline void step_undone(Refiner r, long long[::1] work) noexcept nogil:
    # a step that returns NEED_ROOM changed nothing and runs again once the
    # arrays have grown: its tests go back out of the counters
    memcpy(&work[0], &r.work_begun[0], work.shape[0] * sizeof(long long))


cpdef inline bint trace_full(Refiner r) noexcept nogil:
    # the trace (if on) lacks room for the rows one more step may write
    return r.trace.shape[0] > 0 and r.ntrace + 64 > r.trace.shape[0]


cpdef inline void trace_row(Refiner r, long long kind, long long created, long long deleted, long long steps,
                            long long queue) noexcept nogil:
    # append a trace row (if the trace is on)
    cdef Index i = r.ntrace
    if i < r.trace.shape[0]:
        r.trace[i, 0] = kind
        r.trace[i, 1] = created
        r.trace[i, 2] = deleted
        r.trace[i, 3] = steps
        r.trace[i, 4] = queue
        r.ntrace = i + 1
