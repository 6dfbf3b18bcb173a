# Finding edges by their end vertices (navigate.py), for the kernels.
from instrument.core.mesh cimport Index, Mesh

cpdef Index origin_edge(Mesh m, Index v) noexcept nogil
cpdef Index vertex_edge(Mesh m, Index v) noexcept nogil
cpdef Index edge_around(Mesh m, Index e0, Index v) noexcept nogil
cpdef Index find_edge(Mesh m, Index u, Index v) noexcept nogil
cpdef void build_vertex_edges(Mesh m) noexcept nogil
cpdef void turn_vertex_edges(Mesh m, Index shift) noexcept nogil
cpdef Index list_edges(Mesh m, bint constrained, long long[::1] out) noexcept nogil
cpdef void edge_ends(Mesh m, long long[::1] edges, int[:, ::1] out) noexcept nogil


# Defined here so that the kernels inline it (every new triangle calls it);
# navigate.py repeats it for the pure-Python mode.
cpdef inline void remember_corners(Mesh m, Index t) noexcept nogil:
    # record triangle t's edges as the starting edges of its corners
    cdef Index e = 3 * t
    m.vtri[m.corner[e]] = e + 2
    m.vtri[m.corner[e + 1]] = e
    m.vtri[m.corner[e + 2]] = e + 1
