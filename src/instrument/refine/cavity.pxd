# Inserting a vertex during refinement (cavity.py).
from instrument.core.mesh cimport NO_EDGE, Index, Mesh
from instrument.refine.state cimport Refiner

cpdef (Index, Index) collect_cavity(Refiner r, Mesh m, double px, double py, Index t0, Index t1, Index skip) noexcept nogil
cpdef void forget_cavity(Refiner r, Mesh m, Index n) noexcept nogil
cpdef void order_rim(Refiner r, Mesh m, Index nb, Index first) noexcept nogil
cpdef void fill_cavity(Refiner r, Mesh m, Index p, Index n, Index nb) noexcept nogil
cpdef bint has_room(Refiner r, Mesh m, Index nb) noexcept nogil
cpdef Index legalize_fan(Refiner r, Mesh m, Index made) noexcept nogil
cpdef Index new_vertex(Mesh m, double px, double py, int kind, int marker, Index p0, Index p1, Index p2,
                       double s, double t) noexcept nogil


# Defined here so that the kernels inline them (every new triangle calls
# them); cavity.py repeats them for the pure-Python mode.

cpdef inline (double, double) inherited(Mesh m, Index t) noexcept nogil:
    # triangle slot t's area bound and regional attribute, which a new
    # triangle inherits: (-1, 0) when the run has none (the tables have no rows)
    cdef double area = m.area_bound[t] if m.area_bound.shape[0] else -1.0
    cdef double attr = m.attribute[t] if m.attribute.shape[0] else 0.0
    return area, attr


cpdef inline double flip_bound(double a, double b) noexcept nogil:
    # the area bound both triangles of one of Triangle's flips get from
    # bounds a and b: their mean, or none (-1) if either has none (found by
    # experiment: see reconstruct/__init__.py); its undo keeps them
    # (ghosts.rejected_bounds)
    return 0.5 * (a + b) if a > 0.0 and b > 0.0 else -1.0


cpdef inline void inherit(Mesh m, Index t, double area, double attr) noexcept nogil:
    # give triangle slot t an area bound and a regional attribute (if the run has them)
    if m.area_bound.shape[0]:
        m.area_bound[t] = area
    if m.attribute.shape[0]:
        m.attribute[t] = attr


cpdef inline void mark_both(Mesh m, Index e, Index rec) noexcept nogil:
    # make edge e (both sides) part of subsegment record rec
    m.seg[e] = <int>rec
    if m.twin[e] != NO_EDGE:
        m.seg[m.twin[e]] = <int>rec
