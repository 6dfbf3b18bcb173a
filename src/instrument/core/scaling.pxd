# Exact rescaling by powers of two (scaling.py).
cpdef double unit_scale(double m) noexcept nogil
