# The strategies' priority keys (order.py).
cpdef enum:       # strategy ids (instrument.strategies() names them)
    TRIANGLE = 0
    WORST_ANGLE = 1
    FIFO = 2
    LIFO = 3
    RANDOM = 4
    LARGEST = 5
    SMALLEST = 6
    ADVERSARY = 7

cpdef int triangle_bucket(double key) noexcept nogil
cpdef double priority(int strategy, double min_edge2, double cos2_min_angle, double circumradius2,
                      long long created_estimate, long long seq, double rnd) noexcept nogil
