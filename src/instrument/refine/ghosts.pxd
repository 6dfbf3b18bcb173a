# Triangle's triangle records through an insertion (ghosts.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.refine.state cimport Refiner

cpdef bint rejected_fan_records(Refiner r, Mesh m, Index e, Index nb, bint on_edge) noexcept nogil
cpdef void rejected_bounds(Refiner r, Mesh m, Index e, bint on_edge) noexcept nogil
cpdef void revive_ghosts(Refiner r, Mesh m, Index e, Index nb) noexcept nogil
