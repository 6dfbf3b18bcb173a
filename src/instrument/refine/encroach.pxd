# Encroached subsegments (encroach.py).
from instrument.core.mesh cimport NO_EDGE, Index, Mesh, lnext, lprev
from instrument.core.scaling cimport scaled_pair
from instrument.refine.state cimport Refiner

cpdef void enc_push(Refiner r, Mesh m, Index e) noexcept nogil
cpdef void enc_free(Refiner r, Index i) noexcept nogil
cpdef Index enc_edge(Refiner r, Mesh m, Index i) noexcept nogil


# Defined here so that the kernels inline them (every new subsegment side and
# every rim edge is tested); encroach.py repeats them for the pure-Python mode.
cpdef inline bint in_lens(Refiner r, Mesh m, Index e0, Index e1, double ax, double ay) noexcept nogil:
    # does the point (ax, ay) lie in the diametral lens (or circle with -D) of
    # e0 e1?  Of degree 4: beyond 2^+-120 it would over- or underflow, and
    # there the vectors are scaled by a power of two (see encroach.py)
    cdef double ux = m.xy[e0, 0] - ax
    cdef double uy = m.xy[e0, 1] - ay
    cdef double vx = m.xy[e1, 0] - ax
    cdef double vy = m.xy[e1, 1] - ay
    ux, uy, vx, vy = scaled_pair(ux, uy, vx, vy, 1.329227995784916e+36)  # 2^120
    cdef double dot = ux * vx + uy * vy
    if dot >= 0.0:
        return False
    if r.cfg.diametral:
        return True
    return dot * dot >= r.cfg.lens * (ux * ux + uy * uy) * (vx * vx + vy * vy)


cpdef inline bint may_split(Refiner r, Mesh m, Index e) noexcept nogil:
    # -Y keeps boundary subsegments whole, -YY every subsegment
    cdef int y = r.cfg.keep_segments
    return y == 0 or (y == 1 and m.twin[e] != NO_EDGE)


cpdef inline bint queue_side(Refiner r, Mesh m, Index e, bint hit) noexcept nogil:
    # pool subsegment edge e (whose own apex encroaches if hit) on an
    # encroaching side: the other side if its apex encroaches, as Triangle
    # orients its records (the side decides where shells are measured from);
    # returns whether it is encroached
    cdef Index tw = m.twin[e]
    cdef Index b
    if tw != NO_EDGE:
        b = m.corner[tw]
        if in_lens(r, m, m.corner[lnext(e)], m.corner[lprev(e)], m.xy[b, 0], m.xy[b, 1]):
            e = tw
            hit = True
    if hit and may_split(r, m, e):
        enc_push(r, m, e)
    return hit


cpdef inline bint check_subsegment(Refiner r, Mesh m, Index e) noexcept nogil:
    # pool subsegment edge e if an apex on either side encroaches it
    cdef Index a = m.corner[e]
    return queue_side(r, m, e, in_lens(r, m, m.corner[lnext(e)], m.corner[lprev(e)], m.xy[a, 0], m.xy[a, 1]))
