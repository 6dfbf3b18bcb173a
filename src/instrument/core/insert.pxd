# Vertex insertion primitives (insert.py), for the kernels.
from instrument.core.mesh cimport Index, Mesh

cpdef Index split_triangle(Mesh m, Index t, Index p) noexcept nogil
cpdef Index split_edge(Mesh m, Index e, Index p) noexcept nogil
cpdef Index flip(Mesh m, Index e) noexcept nogil
cpdef bint should_flip(Mesh m, Index e) noexcept nogil
cpdef Index star_edges(Mesh m, Index t, long long[::1] stack) noexcept nogil
cpdef Index lawson(Mesh m, long long[::1] stack, Index n) noexcept nogil
