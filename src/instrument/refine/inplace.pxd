# A subsegment split as Triangle makes it, record for record (inplace.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.core.subsegments cimport Subsegments
from instrument.refine.state cimport Refiner

cpdef void split_in_place(Refiner r, Mesh m, Subsegments segs, Index e, double px, double py,
                          Index e0, Index e1, double split) noexcept nogil
