# Subsegment records (subsegments.py), for the kernels.
from instrument.core.mesh cimport Index

cdef class Subsegments:
    cdef public int[::1] marker     # boundary marker
    cdef public int[::1] source     # input segment, -1 for hull segments
    cdef public int[:, ::1] ends    # the segment's end vertices (the piece first recovered)
    cdef public Index count         # records in use

cpdef Index new_record(Subsegments s, int marker, int source, Index a, Index b) noexcept nogil
