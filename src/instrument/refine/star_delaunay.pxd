# The Delaunay triangulation of a deleted vertex's star (star_delaunay.py).
from instrument.core.mesh cimport Index
from instrument.core.predicates cimport incircle
from instrument.counters cimport C_INCIRCLE

cpdef Index delaunay_star(double[:, ::1] xy, long long[:] chain, Index n, double vx, double vy, long long[:] tv,
                          long long[:] nb, long long[:] links, long long[:] aux, long long[:] rim,
                          long long[::1] work) noexcept nogil


# Defined here so that the deletion inlines it (every base edge of every
# deleted star calls it); star_delaunay.py repeats it for the pure-Python mode.

cpdef inline Index scan_apex(double[:, ::1] xy, long long[:] chain, Index i, Index j, long long[::1] work) noexcept nogil:
    # the scan's choice over the base chain[i] -> chain[j] (the other positions
    # i + 1 .. j - 1 to its left): the first position whose circle through the
    # base holds none of the others strictly inside
    cdef Index ci = chain[i]
    cdef Index cj = chain[j]
    cdef Index k = i + 1
    cdef Index q, ck, cq
    for q in range(i + 2, j):
        work[C_INCIRCLE] += 1
        ck = chain[k]
        cq = chain[q]
        if incircle(xy[ci, 0], xy[ci, 1], xy[cj, 0], xy[cj, 1], xy[ck, 0], xy[ck, 1], xy[cq, 0], xy[cq, 1]) > 0.0:
            k = q
    return k
