# Point location (locate.py), for the kernels.
from instrument.core.mesh cimport Index, Mesh

cpdef enum:
    LOC_INSIDE = 0     # strictly inside triangle e // 3
    LOC_ON_EDGE = 1    # on the open edge e
    LOC_ON_VERTEX = 2  # equal to org(e)
    LOC_OUTSIDE = 3    # across edge e: a ghost triangle's finite edge, or a boundary edge
    LOC_FAILED = 4     # the walk ran out of steps
    LOC_BLOCKED = 5    # the straight path crosses a subsegment or leaves the mesh at e

cpdef Index finite_start(Mesh m, Index t) noexcept nogil
cpdef (int, Index) walk(Mesh m, Index t, double px, double py, Index max_steps) noexcept nogil
cpdef (int, Index) line_walk(Mesh m, Index t, double px, double py, Index max_steps) noexcept nogil
cpdef (int, Index) precise_walk(Mesh m, Index e, double px, double py, Index max_steps) noexcept nogil
