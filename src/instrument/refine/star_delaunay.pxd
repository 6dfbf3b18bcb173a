# The Delaunay triangulation of a deleted vertex's star (star_delaunay.py).
from instrument.core.mesh cimport Index

cpdef Index delaunay_star(double[:, ::1] xy, long long[:] chain, Index n, double vx, double vy, long long[:] tv,
                          long long[:] nb, long long[:] links, long long[:] aux, long long[:] rim,
                          long long[::1] work) noexcept nogil
