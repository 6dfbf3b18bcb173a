# Refinement's splits and loop (splits.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.core.subsegments cimport Subsegments
from instrument.refine.state cimport Refiner

cpdef int acute_ends(Mesh m, Index e) noexcept nogil
cpdef int split_subsegment(Refiner r, Mesh m, Subsegments segs, Index e, bint triangles, int acute) noexcept nogil
cpdef int split_encroached(Refiner r, Mesh m, Subsegments segs, bint triangles) noexcept nogil
cpdef int split_bad_triangle(Refiner r, Mesh m, Subsegments segs, Index h) noexcept nogil
cpdef void check_subsegments(Refiner r, Mesh m, long long[::1] edges) noexcept nogil
cpdef Index first_side(Mesh m, Subsegments segs, long long[::1] first) noexcept nogil
cpdef int refine(Refiner r, Mesh m, Subsegments segs) noexcept nogil
