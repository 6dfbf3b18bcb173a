# The bad-triangle queue (queues.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.refine.order cimport TRIANGLE
from instrument.refine.state cimport Refiner

cpdef void queue_clear(Refiner r) noexcept nogil
cpdef void queue_push(Refiner r, double key, Index t, long long stamp) noexcept nogil
cpdef Index queue_pop(Refiner r) noexcept nogil
cpdef void queue_compact(Refiner r, Mesh m) noexcept nogil


# Defined here so that the kernels inline it (every step's room check calls
# it); queues.py repeats it for the pure-Python mode.
cpdef inline Index queue_used(Refiner r) noexcept nogil:
    # queue entries in use: the heap's size, or the bucket log's length
    # (served and stale entries included, until a compaction)
    return r.log_length if r.cfg.strategy == TRIANGLE else r.hsize
