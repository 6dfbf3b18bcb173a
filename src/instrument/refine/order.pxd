# The strategies' priority keys (order.py).
from libc.math cimport frexp, ldexp
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


# Triangle's buckets and the wider ones the queue has for squared edges
# beyond the doubles (queues.py, state.NBUCKETS)
cdef enum:
    TOP_BUCKET = 4095        # Triangle's last (finest) bucket
    WIDE_BUCKETS = 10496     # 2048 + 2 * 4200 + spare: every squared edge between doubles, in any units


cpdef inline int wide_bucket(double dx, double dy, int unit_exp) noexcept nogil:
    # the bucket of the squared length of (dx, dy) * 2^unit_exp, computed
    # without squaring out of range: Triangle's formula (triangle_bucket) with
    # x going on past 2047, for squares too small for a double (the vector is
    # brought to [0.5, 1) by a power of two, squared, and the exponents added
    # back); where triangle_bucket does not saturate it gives the same bucket,
    # as 1 / (key 2^2k) is (1 / key) 2^-2k exactly.  Only keys below 1 come
    # here (edges no longer than the extent, measured in units of about it).
    cdef double big = dx if dx >= 0.0 else -dx
    cdef double ay = dy if dy >= 0.0 else -dy
    if ay > big:
        big = ay
    if not (big > 0.0 and big <= 1.7976931348623157e308):  # a zero, infinite or NaN edge
        return TOP_BUCKET
    cdef int eb
    frexp(big, &eb)
    cdef double sx = ldexp(dx, -eb)
    cdef double sy = ldexp(dy, -eb)
    cdef double length = 1.0 / (sx * sx + sy * sy)  # in (0.5, 4]
    cdef int e
    cdef double mant = frexp(length, &e)
    cdef double f = 2.0 * mant
    e = e - 1 - 2 * (eb + unit_exp)  # L = 1 / key = 2^e f
    if f == 1.0 and e > 0:  # exact power of two: f = 2, one exponent lower
        f = 2.0
        e -= 1
    cdef int x = 2 * e + (1 if f > 1.4142135623730951 else 0)
    if x < 0:  # a key of 1 or more (not reached: see above)
        return 2047
    if x > WIDE_BUCKETS - 2049:
        x = WIDE_BUCKETS - 2049
    return 2048 + x


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
