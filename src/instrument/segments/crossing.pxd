# Correctly rounded crossing points (crossing.py).
cpdef (double, double) crossing_point(double ax, double ay, double bx, double by,
                                      double rx, double ry, double lx, double ly) noexcept nogil
