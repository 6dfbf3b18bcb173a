# Encroached subsegments (encroach.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.refine.state cimport Refiner

cpdef void enc_push(Refiner r, Mesh m, Index e) noexcept nogil
cpdef void enc_free(Refiner r, Index i) noexcept nogil
cpdef Index enc_edge(Refiner r, Mesh m, Index i) noexcept nogil
cpdef bint in_lens(Refiner r, Mesh m, Index e0, Index e1, double ax, double ay) noexcept nogil
cpdef bint may_split(Refiner r, Mesh m, Index e) noexcept nogil
cpdef bint queue_side(Refiner r, Mesh m, Index e, bint hit) noexcept nogil
cpdef bint check_subsegment(Refiner r, Mesh m, Index e) noexcept nogil
