# Inserting a vertex during refinement (cavity.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.refine.state cimport Refiner

cpdef (double, double) inherited(Mesh m, Index t) noexcept nogil
cpdef void inherit(Mesh m, Index t, double area, double attr) noexcept nogil
cpdef (Index, Index) collect_cavity(Refiner r, Mesh m, double px, double py, Index t0, Index t1, Index skip) noexcept nogil
cpdef void forget_cavity(Refiner r, Mesh m, Index n) noexcept nogil
cpdef void order_rim(Refiner r, Mesh m, Index nb, Index first) noexcept nogil
cpdef void fill_cavity(Refiner r, Mesh m, Index p, Index n, Index nb) noexcept nogil
cpdef bint has_room(Refiner r, Mesh m, Index nb) noexcept nogil
cpdef Index new_vertex(Mesh m, double px, double py, int kind, int marker, Index p0, Index p1, Index p2,
                       double s, double t) noexcept nogil
cpdef void mark_both(Mesh m, Index e, Index rec) noexcept nogil
