# Exact rescaling by powers of two (scaling.py).
from libc.math cimport fabs
from libc.string cimport memcpy
from instrument.core.mesh cimport Index

cpdef double unit_scale(double m) noexcept nogil
cpdef double scaled_dot(double ux, double uy, double vx, double vy) noexcept nogil
cpdef (double, double) crossing_terms(double ax, double ay, double bx, double by, double rx, double ry, double lx, double ly, double ox, double oy) noexcept nogil
cpdef double half_extent(double[:, ::1] xy, Index n) noexcept nogil
cpdef bint all_finite(double[:, ::1] xy) noexcept nogil


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



cdef inline (double, double, double, double, double, double) scaled_triple(double ux, double uy, double vx, double vy, double wx, double wy, double limit) noexcept nogil:
    # scaled_pair for three vectors (a triangle's edges, say)
    cdef double big = max(max(max(fabs(ux), fabs(uy)), max(fabs(vx), fabs(vy))), max(fabs(wx), fabs(wy)))
    cdef double f
    if not (big <= limit and big >= 1.0 / limit) and big > 0.0:
        f = unit_scale(big)
        return ux * f, uy * f, vx * f, vy * f, wx * f, wy * f
    return ux, uy, vx, vy, wx, wy

cdef inline unsigned long long double_bits(double x) noexcept nogil:
    # the bits of x (unit_scale reads its exponent)
    cdef unsigned long long bits
    memcpy(&bits, &x, sizeof(double))
    return bits


cdef inline double bits_double(unsigned long long bits) noexcept nogil:
    # the double with these bits
    cdef double x
    memcpy(&x, &bits, sizeof(double))
    return x
