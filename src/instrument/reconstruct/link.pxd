# Refining a given mesh: the kernels (link.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.core.subsegments cimport Subsegments

cpdef enum:     # link_triangles' verdicts; bad[1:] say where
    LINK_OK = 0
    REPEATED_CORNER = 1  # (code, triangle)
    COLLINEAR = 2        # (code, triangle)
    CLOCKWISE = 3        # (code, triangle)
    SAME_SIDE = 4        # (code, triangle, other triangle): a directed edge used twice
    GIVEN_TWICE = 5      # (code, triangle, other triangle)
    THREE_SIDES = 6      # (code, triangle, org, dest): an edge in more than two triangles
    FOLDED = 7           # (code, vertex)

cpdef int link_triangles(int[::1] corner, double[:, ::1] xy, long long[::1] start, long long[::1] count,
                         long long[::1] order, int[::1] dst, int[::1] twin, long long[::1] bad) noexcept nogil
cpdef Index attach_segments(Mesh m, Subsegments segs, long long[::1] start, long long[::1] order,
                            long long[:, ::1] rows, int[::1] in_marker, long long[::1] unmatched) noexcept nogil
cpdef bint leaves_mesh(Mesh m, Index a, Index b) noexcept nogil
cpdef Index spread_origin(Mesh m, long long[::1] origin) noexcept nogil
