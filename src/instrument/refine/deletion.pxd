# Chew's deletion of free vertices (deletion.py).
from instrument.core.mesh cimport Index, Mesh
from instrument.core.subsegments cimport Subsegments
from instrument.refine.state cimport Refiner

cpdef enum:
    # Stars of this many vertices or more go to Chew's randomized algorithm
    # first (star_delaunay.py): below it the scan makes fewer incircle tests
    # than the randomized algorithm's few per vertex with its checks
    # (tests/unit/test_star_delaunay.py's docstring has the counts), and
    # ordinary free vertices have degree 5 to 8. deletion.py repeats it for
    # the pure-Python mode.
    SCAN_DEGREE = 24

cpdef int delete_free_vertex(Refiner r, Mesh m, Subsegments segs, Index e0) noexcept nogil
cpdef bint chew_delete(Refiner r, Mesh m, Subsegments segs, Index e) noexcept nogil
