# The bad-triangle queue (queues.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.refine.state cimport Refiner

cpdef Index queue_used(Refiner r) noexcept nogil
cpdef void queue_clear(Refiner r) noexcept nogil
cpdef void queue_push(Refiner r, double key, Index t, long long stamp) noexcept nogil
cpdef Index queue_pop(Refiner r) noexcept nogil
cpdef void queue_compact(Refiner r, Mesh m) noexcept nogil
