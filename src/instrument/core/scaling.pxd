# Exact rescaling by powers of two (scaling.py).
cpdef double unit_scale(double m) noexcept nogil
cpdef bint in_safe_range(double m) noexcept nogil
