# Exact rescaling by powers of two (scaling.py).
cpdef double unit_scale(double m) noexcept nogil
cpdef double scaled_dot(double ux, double uy, double vx, double vy) noexcept nogil
