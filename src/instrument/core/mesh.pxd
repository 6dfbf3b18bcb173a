# The triangulation's data (mesh.py) as the engine's kernels see it.
#
# The navigation and allocation primitives are defined here, not only
# declared, so that every kernel inlines them (each is a few instructions
# and they are called in every inner loop); mesh.py repeats them for the
# pure-Python mode, and the tests check that both agree.

ctypedef Py_ssize_t Index   # a vertex, triangle slot or edge number

cpdef enum:
    GHOST = -1      # the vertex at infinity
    NO_EDGE = -1    # no twin: the edge is on the boundary of the mesh
    NO_SEG = -1     # the edge is not a subsegment

cpdef enum:         # kinds of vertex (Mesh.vtype), as refinement classifies them
    V_INPUT = 0
    V_SEGMENT = 1   # made by splitting a subsegment
    V_FREE = 2      # made by splitting a triangle
    V_DEAD = 3      # a free vertex deleted again (left out of the output)


cdef class Mesh:
    # per vertex (rows 0 .. nvert-1 in use; all grow together, see grow_vertices)
    cdef public double[:, ::1] xy          # coordinates
    cdef public int[::1] vmark             # boundary marker
    cdef public long long[::1] vtri        # an edge whose origin is the vertex (a hint, may be stale), or no rows
    cdef public signed char[::1] vtype     # refinement's kind of vertex (input, segment, free, dead)
    cdef public double[:, ::1] parent      # attribute interpolation record, or no rows
    cdef public long long[::1] vslot       # scratch, -1 between uses, or no rows
    # per triangle slot (all grow together, see grow_triangles)
    cdef public int[::1] corner            # 3 per slot, counter-clockwise
    cdef public int[::1] twin              # 3 per slot: the same edge seen from the neighbour
    cdef public int[::1] seg               # 3 per slot: subsegment record, or NO_SEG; or no rows
    cdef public int[::1] stamp             # > 0 alive; a queue entry is current iff its stamp still matches
    cdef public int[::1] free              # stack of dead slots
    cdef public double[::1] area_bound     # per-triangle area bound (<= 0: none), or no rows
    cdef public double[::1] attribute      # regional attribute, or no rows
    cdef public signed char[::1] tflag     # scratch, 0 between uses
    # counts and the rest
    cdef public Index nvert           # vertices in use
    cdef public Index nslot           # triangle slots ever used (high-water mark)
    cdef public Index nfree           # dead slots on the free stack
    cdef public Index nlive           # live triangles (ghosts included)
    cdef public long long[::1] work        # the work counters (counters.py)
    cdef public long long rng              # the walks' random generator state
    cdef public Index outer_space_edge     # the hull edge Triangle's outer-space handle holds (NO_EDGE: none known)


# Of an edge e >= 0: e % 3 unsigned, the shorter division (the signed one
# corrects for negative remainders; these two run in every inner loop)
cdef inline Index lnext(Index e) noexcept nogil:
    return e - 2 if <size_t>e % 3 == 2 else e + 1


cdef inline Index lprev(Index e) noexcept nogil:
    return e + 2 if <size_t>e % 3 == 0 else e - 1


cdef inline Index org(Mesh m, Index e) noexcept nogil:
    return m.corner[lnext(e)]


cdef inline Index dest(Mesh m, Index e) noexcept nogil:
    return m.corner[lprev(e)]


cdef inline Index apex(Mesh m, Index e) noexcept nogil:
    return m.corner[e]


cdef inline Index next_hull_edge(Mesh m, Index e) noexcept nogil:
    # the hull edge after hull edge e counter-clockwise (in a mesh without
    # ghosts): it leaves e's destination, found by turning around that vertex
    cdef Index f = lnext(e)
    while m.twin[f] != NO_EDGE:
        f = lnext(m.twin[f])
    return f


cdef inline bint is_ghost(Mesh m, Index t) noexcept nogil:
    return m.corner[3 * t] == GHOST or m.corner[3 * t + 1] == GHOST or m.corner[3 * t + 2] == GHOST


cdef inline bint alive(Mesh m, Index t) noexcept nogil:
    return m.stamp[t] > 0


cdef inline bint in_output(Mesh m, Index t) noexcept nogil:
    # alive and no ghost: a triangle the output lists
    return m.stamp[t] > 0 and m.corner[3 * t] >= 0 and m.corner[3 * t + 1] >= 0 and m.corner[3 * t + 2] >= 0


cdef inline void bond(Mesh m, Index e1, Index e2) noexcept nogil:
    if e1 >= 0:
        m.twin[e1] = <int>e2
    if e2 >= 0:
        m.twin[e2] = <int>e1


cdef inline Index new_triangle(Mesh m, Index a, Index b, Index c) noexcept nogil:
    cdef Index t = -1
    cdef Index e
    if m.nfree > 0:
        m.nfree -= 1
        t = m.free[m.nfree]
        m.stamp[t] = -m.stamp[t] + 1
    elif m.nslot < m.stamp.shape[0]:
        t = m.nslot
        m.nslot = t + 1
        m.stamp[t] = 1
    if t >= 0:
        m.nlive += 1
        e = 3 * t
        m.corner[e] = <int>a
        m.corner[e + 1] = <int>b
        m.corner[e + 2] = <int>c
        m.twin[e] = NO_EDGE
        m.twin[e + 1] = NO_EDGE
        m.twin[e + 2] = NO_EDGE
        if m.seg.shape[0] > 0:  # a mesh without constraint tables (Mesh.add_constraint_tables)
            m.seg[e] = NO_SEG
            m.seg[e + 1] = NO_SEG
            m.seg[e + 2] = NO_SEG
    return t


cdef inline void kill_triangle(Mesh m, Index t) noexcept nogil:
    m.stamp[t] = -m.stamp[t]
    m.free[m.nfree] = <int>t
    m.nfree += 1
    m.nlive -= 1


cdef inline Index spare_triangles(Mesh m) noexcept nogil:
    return m.nfree + m.stamp.shape[0] - m.nslot


cdef inline Index next_random(Mesh m) noexcept nogil:
    # the walks' LCG; products stay below 2^62, so Python ints agree
    m.rng = (m.rng * 1103515245 + 12345) & 0x7FFFFFFF
    return (m.rng >> 16) % 3


cpdef Index remove_ghosts(Mesh m) noexcept nogil
cpdef Index least_hull_edge(Mesh m) noexcept nogil
cpdef Index remove_ghosts_around_hull(Mesh m) noexcept nogil
cpdef void relabel_corners(Mesh m, long long[::1] label) noexcept nogil
cpdef void turn_corners(Mesh m, Index shift) noexcept nogil
cpdef void set_parent(Mesh m, Index v, Index p0, Index p1, Index p2, double s, double t) noexcept nogil
cpdef void interpolate_attributes(Mesh m, double[:, ::1] out, Index first) noexcept nogil
