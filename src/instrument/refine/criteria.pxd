# What makes a triangle bad, and where it is split (criteria.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.core.subsegments cimport Subsegments
from instrument.refine.state cimport Refiner

cpdef bint builtin_unsuitable(Mesh m, Index o, Index d, Index a) noexcept nogil
cpdef (double, double, double, double, bint) steiner_point(Refiner r, Mesh m, Index h) noexcept nogil
cpdef void test_triangle(Refiner r, Mesh m, Subsegments segs, Index t) noexcept nogil
cpdef void queue_triangles(Refiner r, Mesh m, long long[::1] ts) noexcept nogil
cpdef void test_fan(Refiner r, Mesh m, Subsegments segs, Index nb, bint triangles, bint apex_clear) noexcept nogil
cpdef void queue_rejected_fan(Refiner r, Mesh m, Subsegments segs, Index nb, double px, double py) noexcept nogil
