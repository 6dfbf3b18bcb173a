# Incremental insertion's state between insertions (incremental.py).
from instrument.core.mesh cimport Index

cdef class Insertion:
    cdef public long long seed         # Triangle's random generator
    cdef public Index samples          # records a location samples
    cdef public Index recent           # the last insertion's handle, or -1
    cdef public Index outer_space      # Triangle's outer-space handle (a box edge, then a hull edge)
    cdef public Index first_block      # records in the first block of Triangle's pool
    cdef public Index first_hull       # the first hull edge the removal of the box left, or NO_EDGE
