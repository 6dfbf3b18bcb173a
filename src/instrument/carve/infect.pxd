# Carving kernels (infect.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.core.subsegments cimport Subsegments

cpdef Index infect_hull(Mesh m, Subsegments segs, long long[::1] queue, Index start) noexcept nogil
cpdef Index start_hull_edge(Mesh m) noexcept nogil
cpdef void locate_points(Mesh m, double[:, ::1] pts, double[::1] lo, double[::1] hi, long long[:, ::1] found,
                        Index start) noexcept nogil
cpdef Index plague(Mesh m, Subsegments segs, long long[::1] queue, Index n) noexcept nogil
cpdef void spread_regions(Mesh m, long long[:, ::1] found, double[::1] values, double[::1] out,
                          long long[::1] seen, long long[::1] stack) noexcept nogil
