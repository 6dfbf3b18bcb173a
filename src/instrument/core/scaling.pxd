# Exact rescaling by powers of two (scaling.py).
from libc.math cimport fabs

cpdef double unit_scale(double m) noexcept nogil
cpdef double scaled_dot(double ux, double uy, double vx, double vy) noexcept nogil
cpdef (double, double) crossing_terms(double ax, double ay, double bx, double by, double rx, double ry, double lx, double ly, double ox, double oy) noexcept nogil


cdef inline (double, double, double, double) scaled_pair(double ux, double uy, double vx, double vy, double limit) noexcept nogil:
    # the vectors u and v, times unit_scale of their largest component when
    # that lies outside [1/limit, limit] (limit a power of two): products of
    # them of the degree the caller chose limit for neither overflow nor
    # vanish, and their signs and ratios are those of the unscaled vectors
    cdef double big = max(max(fabs(ux), fabs(uy)), max(fabs(vx), fabs(vy)))
    cdef double f
    if not (big <= limit and big >= 1.0 / limit) and big > 0.0:
        f = unit_scale(big)
        return ux * f, uy * f, vx * f, vy * f
    return ux, uy, vx, vy
