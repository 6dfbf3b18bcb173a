# Correctly rounded crossing points (crossing.py).
cpdef (double, double) crossing_point(double ax, double ay, double bx, double by,
                                      double rx, double ry, double lx, double ly) noexcept nogil
cpdef (double, double, double) scouted_crossing(double e1x, double e1y, double e2x, double e2y,
                                                double rx, double ry, double lx, double ly) noexcept nogil
