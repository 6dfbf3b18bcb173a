# Segment recovery kernels (recover.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.core.subsegments cimport Subsegments

cdef class Recovery:
    cdef public long long[:, ::1] rows     # the input rows (a, b, input segment), in order
    cdef public Index taken                # rows moved to the stack so far
    cdef public long long[:, ::1] pieces   # stack of (a, b, input segment); the top is next
    cdef public Index top                  # pieces on the stack
    cdef public int[::1] markers           # the input segments' markers
    cdef public long long[::1] buf         # scratch: crossed edges, flip stack
    cdef public Index handled              # pieces handled so far
    cdef public Index inputs               # input segments
    cdef public Index plain                # vertices below it are input vertices (exact)
    cdef public long long[:, ::1] ends     # each input segment's endpoints (-1: none)
    cdef public long long[:, ::1] copies   # (copy, vertex): crossings made as copies of an input vertex
    cdef public Index ncopies              # rows of copies in use

cpdef (Index, int) turn_to(Mesh m, Index a, Index b, Index e0, Index plain, Index sa, Index sb) noexcept nogil
cpdef double crossing_parameter(double ax, double ay, double bx, double by,
                                double rx, double ry, double lx, double ly) noexcept nogil
cpdef void mark_subsegment(Mesh m, Subsegments segs, Index e, int marker, int source, bint against) noexcept nogil
cpdef bint restore_delaunay(Mesh m, long long[::1] stack) noexcept nogil
cpdef int insert_segments(Mesh m, Subsegments segs, Recovery work) noexcept nogil
cpdef bint mark_hull(Mesh m, Subsegments segs, int source, Index start) noexcept nogil
cpdef Index count_inverted(Mesh m) noexcept nogil
