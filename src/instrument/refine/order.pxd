# The strategies' priority keys (order.py).
from libc.string cimport memcpy

cpdef enum:       # strategy ids (instrument.strategies() names them)
    TRIANGLE = 0
    WORST_ANGLE = 1
    FIFO = 2
    LIFO = 3
    RANDOM = 4
    LARGEST = 5
    SMALLEST = 6
    ADVERSARY = 7



# Defined here so that the kernels inline them (every queued triangle needs
# a key); order.py repeats them for the pure-Python mode.

cpdef inline int triangle_bucket(double key) noexcept nogil:
    # Triangle's bucket (0..4095) for a squared shortest edge key: L = key or
    # 1 / key, whichever is at least 1, written 2^e f with f in [1, 2);
    # x = 2e + [f > sqrt 2] (f = 1 with e > 0 counts as 2^(e-1) 2); bucket
    # 2047 - x for key >= 1, 2048 + x below.  e and f are read from L's bits
    # (L >= 1 is a normal double: L = (1 + frac 2^-52) 2^(E - 1023)), which is
    # what order.py's frexp gives, without a library call per queued triangle;
    # f > sqrt 2 compares the fractions (both have exponent 0)
    if key <= 0.0 or key != key:
        return 4095
    cdef bint big = key >= 1.0
    cdef double length = key if big else 1.0 / key
    if not length <= 1.7976931348623157e308:  # infinite
        return 0 if big else 4095
    cdef unsigned long long bits
    memcpy(&bits, &length, sizeof(double))
    cdef int e = <int>(bits >> 52) - 1023  # the sign bit is 0
    cdef unsigned long long frac = bits & 0xFFFFFFFFFFFFFULL
    cdef int x
    if frac == 0 and e > 0:  # exact power of two: f = 2, one exponent lower
        x = 2 * (e - 1) + 1
    else:
        x = 2 * e + (1 if frac > 0x6A09E667F3BCDULL else 0)  # sqrt(2.0)'s fraction
    if x > 2047:
        x = 2047
    return 2047 - x if big else 2048 + x


cpdef inline double priority(int strategy, double min_edge2, double cos2_min_angle, double circumradius2,
                             long long created_estimate, long long seq, double rnd) noexcept nogil:
    # the queue key of a bad triangle (smaller first); seq breaks ties
    if strategy == TRIANGLE:
        return -<double>triangle_bucket(min_edge2)
    if strategy == WORST_ANGLE:
        return -cos2_min_angle
    if strategy == FIFO:
        return 0.0
    if strategy == LIFO:
        return -<double>seq
    if strategy == RANDOM:
        return rnd
    if strategy == LARGEST:
        return -circumradius2
    if strategy == SMALLEST:
        return circumradius2
    return -<double>created_estimate  # ADVERSARY
