# Vertex insertion primitives (insert.py), for the kernels.
from instrument.core.mesh cimport Index, Mesh

cpdef Index split_triangle(Mesh m, Index t, Index p) noexcept nogil
cpdef Index split_edge(Mesh m, Index e, Index p) noexcept nogil
cpdef Index flip(Mesh m, Index e) noexcept nogil
cpdef void flip_in_place(Mesh m, Index e) noexcept nogil
cpdef Index split_edge_in_place(Mesh m, Index h, Index v, int half, Index zero) noexcept nogil
cpdef void lawson_in_place(Mesh m, Index h) noexcept nogil
cpdef bint should_flip(Mesh m, Index e) noexcept nogil
cpdef Index star_edges(Mesh m, Index t, long long[::1] stack) noexcept nogil
cpdef Index lawson(Mesh m, long long[::1] stack, Index n) noexcept nogil
cpdef Index make_delaunay(Mesh m, long long[::1] stack, unsigned char[::1] queued) noexcept nogil
cpdef bint splits_cleanly(Mesh m, Index c, double px, double py) noexcept nogil
cpdef bint splits_after_a_flip(Mesh m, Index c, double px, double py) noexcept nogil
