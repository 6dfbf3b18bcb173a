# Triangle's triangle records through an insertion (ghosts.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.refine.state cimport Refiner

cpdef bint rejected_fan_records(Refiner r, Mesh m, Index e, bint on_edge, Index nb) noexcept nogil
cpdef void rejected_bounds(Refiner r, Mesh m, Index e, bint on_edge) noexcept nogil
cpdef bint insertion_records(Refiner r, Mesh m, Index e, bint on_edge, Index nb) noexcept nogil
cpdef bint revive_ghosts(Refiner r, Mesh m, bint ok, Index nb, bint two) noexcept nogil
cpdef void note_born(Refiner r, Mesh m, bint ok, Index nb, Index first) noexcept nogil
cpdef void records_known(Refiner r, Mesh m) noexcept nogil
cpdef void requeued(Refiner r, Index t) noexcept nogil
cpdef void deletion_ghosts(Refiner r, Mesh m, Index v, long long[:] tris, Index d) noexcept nogil
cpdef void deletion_freed(Refiner r, Mesh m, Index j, Index d) noexcept nogil
cpdef void star_orientations(Refiner r, Mesh m, Index v, long long[:] tris, Index d) noexcept nogil
cpdef void deletion_orientations(Refiner r, Mesh m, long long[:] order, Index made, long long[:] slot, Index d) noexcept nogil
cpdef void note_deleted(Refiner r, Mesh m, Index first) noexcept nogil
