# The exact predicates (predicates.py) as the engine's kernels see them.
#
# orient2d and incircle are defined here, not only declared, so that every
# module that cimports them inlines their fast path (stage A), as numba did;
# only undecided cases call the adaptive stages.  predicates.py repeats the
# two bodies for the pure-Python mode, and the tests check that both agree.
# The literals are predicates.py's constants: CCWERRBOUNDA = (3 + 16 eps) eps,
# ICC_A_SAFE = ICCERRBOUNDA (1 + 2^-40), O_LO = 2^-960, I_LO = 2^-660,
# I_SMAX = 2^300, DBL_MAX (see the module docstring for why these guards).

cdef double orient2d_adaptive(double ax, double ay, double bx, double by, double cx, double cy) noexcept nogil
cdef double incircle_adaptive(double ax, double ay, double bx, double by, double cx, double cy,
                              double dx, double dy) noexcept nogil
cpdef double orient2d_fast(double ax, double ay, double bx, double by, double cx, double cy) noexcept nogil
cpdef int dot_sign(double ax, double ay, double bx, double by, double cx, double cy,
                   double dx, double dy) noexcept nogil
cpdef double incircle_fast(double ax, double ay, double bx, double by, double cx, double cy,
                           double dx, double dy) noexcept nogil


cpdef inline double orient2d(double ax, double ay, double bx, double by, double cx, double cy) noexcept nogil:
    cdef double detleft = (ax - cx) * (by - cy)
    cdef double detright = (ay - cy) * (bx - cx)
    cdef double det = detleft - detright
    cdef double detsum = abs(detleft) + abs(detright)
    if abs(det) >= 3.3306690738754716e-16 * detsum:
        if (detsum >= 1.0261342003245941e-289) & (detsum <= 1.7976931348623157e308):
            return det
    return orient2d_adaptive(ax, ay, bx, by, cx, cy)


cpdef inline double incircle(double ax, double ay, double bx, double by, double cx, double cy,
                             double dx, double dy) noexcept nogil:
    cdef double adx = ax - dx
    cdef double bdx = bx - dx
    cdef double cdx = cx - dx
    cdef double ady = ay - dy
    cdef double bdy = by - dy
    cdef double cdy = cy - dy
    cdef double bdxcdy = bdx * cdy
    cdef double cdxbdy = cdx * bdy
    cdef double alift = adx * adx + ady * ady
    cdef double cdxady = cdx * ady
    cdef double adxcdy = adx * cdy
    cdef double blift = bdx * bdx + bdy * bdy
    cdef double adxbdy = adx * bdy
    cdef double bdxady = bdx * ady
    cdef double clift = cdx * cdx + cdy * cdy
    cdef double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady)
    cdef double permanent = ((abs(bdxcdy) + abs(cdxbdy)) * alift + (abs(cdxady) + abs(adxcdy)) * blift
                             + (abs(adxbdy) + abs(bdxady)) * clift)
    if abs(det) > 1.1102230246261675e-15 * permanent:
        if (permanent >= 2.0902722826084166e-199) & (alift + blift + clift <= 2.037035976334486e+90):
            return det
    return incircle_adaptive(ax, ay, bx, by, cx, cy, dx, dy)
