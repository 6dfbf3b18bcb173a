# Chew's deletion of free vertices (deletion.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.core.subsegments cimport Subsegments
from instrument.refine.state cimport Refiner

cpdef int delete_free_vertex(Refiner r, Mesh m, Subsegments segs, Index e0) noexcept nogil
cpdef bint chew_delete(Refiner r, Mesh m, Subsegments segs, Index e) noexcept nogil
