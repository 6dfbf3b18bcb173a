"""Vertex insertion: 1-to-3 and 2-to-4 splits, edge flips and Lawson's flip loop.

Every new triangle puts the new vertex at corner 0, so the edge to test after
an insertion is always edge 0 (``3t``), the one opposite the new vertex.  The
flip test understands ghost triangles (corner ``GHOST``): a ghost ``(a, b,
GHOST)`` stands for the open half-plane left of ``a -> b``, which is its
"circumcircle" (see mesh.py).

Counting: finite triangles only, so that ``created - deleted`` is the number
of triangles in the mesh; a flip creates one and deletes one triangle, which
makes the created count of an insertion the number of triangles incident to
the new vertex afterwards.
"""

from __future__ import annotations


from .jit import kernel, kernel_inline
from .counters import C_CREATED, C_DELETED, C_FLIP, C_INCIRCLE, C_ORIENT
from .mesh import GHOST, NO_EDGE, NO_SEG, bond, is_ghost, kill_triangle, lnext, lprev, new_triangle
from .predicates import incircle, orient2d


@kernel_inline
def _finite3(a, b, c):
    return a != GHOST and b != GHOST and c != GHOST


@kernel_inline
def _make(m, work, a, b, c):
    """Allocate triangle (a, b, c) and count it if finite (caller ensured room)."""
    t = new_triangle(m, a, b, c)
    if _finite3(a, b, c):
        work[C_CREATED] += 1
    return t


@kernel_inline
def _kill(m, work, t):
    if not is_ghost(m, t):
        work[C_DELETED] += 1
    kill_triangle(m, t)


@kernel_inline
def split_triangle(m, work, t, p):
    """Replace triangle ``t`` by three triangles around vertex ``p`` inside it.

    Returns the slot of the first new triangle; the three new ones are
    ``(p, b, c), (p, c, a), (p, a, b)`` with edge 0 facing outwards.
    """
    e = 3 * t
    a = m.corner[e]
    b = m.corner[e + 1]
    c = m.corner[e + 2]
    n0 = m.twin[e]
    n1 = m.twin[e + 1]
    n2 = m.twin[e + 2]
    s0 = m.seg[e]
    s1 = m.seg[e + 1]
    s2 = m.seg[e + 2]
    _kill(m, work, t)
    t0 = _make(m, work, p, b, c)
    t1 = _make(m, work, p, c, a)
    t2 = _make(m, work, p, a, b)
    f0, f1, f2 = 3 * t0, 3 * t1, 3 * t2
    bond(m, f0, n0)
    bond(m, f1, n1)
    bond(m, f2, n2)
    m.seg[f0] = s0
    m.seg[f1] = s1
    m.seg[f2] = s2
    bond(m, f0 + 1, f1 + 2)
    bond(m, f1 + 1, f2 + 2)
    bond(m, f2 + 1, f0 + 2)
    return t0


@kernel
def split_edge(m, work, e, p):
    """Split edge ``e`` (and its twin, if any) at vertex ``p`` lying on it.

    The triangle of ``e`` is ``(o, d, x)``; it becomes ``(p, d, x)`` and
    ``(p, x, o)``.  The twin's triangle ``(d, o, y)`` becomes ``(p, o, y)`` and
    ``(p, y, d)``.  Both halves of the split edge keep its subsegment id.
    Returns the edge ``p -> d`` of the first new triangle (on the split line).
    """
    o = m.corner[lnext(e)]
    d = m.corner[lprev(e)]
    x = m.corner[e]
    tw = m.twin[e]
    s = m.seg[e]
    na = m.twin[lnext(e)]
    nb = m.twin[lprev(e)]
    sa = m.seg[lnext(e)]
    sb = m.seg[lprev(e)]
    _kill(m, work, e // 3)
    ta = _make(m, work, p, d, x)
    tb = _make(m, work, p, x, o)
    A, B = 3 * ta, 3 * tb
    bond(m, A, na)
    bond(m, B, nb)
    m.seg[A] = sa
    m.seg[B] = sb
    bond(m, A + 1, B + 2)
    m.seg[A + 2] = s
    m.seg[B + 1] = s
    if tw == NO_EDGE:
        m.twin[A + 2] = NO_EDGE
        m.twin[B + 1] = NO_EDGE
    else:
        y = m.corner[tw]
        nc = m.twin[lnext(tw)]
        nd = m.twin[lprev(tw)]
        sc = m.seg[lnext(tw)]
        sd = m.seg[lprev(tw)]
        _kill(m, work, tw // 3)
        tc = _make(m, work, p, o, y)
        td = _make(m, work, p, y, d)
        C, D = 3 * tc, 3 * td
        bond(m, C, nc)
        bond(m, D, nd)
        m.seg[C] = sc
        m.seg[D] = sd
        bond(m, C + 1, D + 2)
        bond(m, B + 1, C + 2)
        bond(m, D + 1, A + 2)
        m.seg[C + 2] = s
        m.seg[D + 1] = s
    return A + 2


@kernel_inline
def flip(m, work, e):
    """Flip edge ``e`` of triangle ``(o, d, x)`` whose twin is in ``(d, o, y)``.

    The result is ``(x, o, y)`` and ``(x, y, d)``, with ``x`` at corner 0 of
    both, so their edges 0 are the two edges that were opposite ``x``'s side.
    Returns the slot of the first new triangle.
    """
    tw = m.twin[e]
    o = m.corner[lnext(e)]
    d = m.corner[lprev(e)]
    x = m.corner[e]
    y = m.corner[tw]
    n_xo = m.twin[lprev(e)]  # edge x -> o
    n_dx = m.twin[lnext(e)]  # edge d -> x
    n_oy = m.twin[lnext(tw)]  # edge o -> y
    n_yd = m.twin[lprev(tw)]  # edge y -> d
    s_xo = m.seg[lprev(e)]
    s_dx = m.seg[lnext(e)]
    s_oy = m.seg[lnext(tw)]
    s_yd = m.seg[lprev(tw)]
    _kill(m, work, e // 3)
    _kill(m, work, tw // 3)
    t1 = _make(m, work, x, o, y)
    t2 = _make(m, work, x, y, d)
    T1, T2 = 3 * t1, 3 * t2
    bond(m, T1, n_oy)
    bond(m, T1 + 2, n_xo)
    bond(m, T2, n_yd)
    bond(m, T2 + 1, n_dx)
    bond(m, T1 + 1, T2 + 2)
    m.seg[T1] = s_oy
    m.seg[T1 + 2] = s_xo
    m.seg[T2] = s_yd
    m.seg[T2 + 1] = s_dx
    work[C_FLIP] += 1
    return t1


@kernel_inline
def should_flip(m, work, e):
    """Lawson's test for edge ``e`` = edge 0 of a triangle ``(p, u, v)``.

    True if the far vertex lies strictly inside the circumcircle of
    ``(p, u, v)``; ghosts use the half-plane rule of mesh.py.  Constrained
    edges and mesh-boundary edges never flip.
    """
    tw = m.twin[e]
    result = False
    if tw != NO_EDGE and m.seg[e] == NO_SEG:
        xy = m.xy
        p = m.corner[e]
        u = m.corner[lnext(e)]
        v = m.corner[lprev(e)]
        x = m.corner[tw]
        if u != GHOST and v != GHOST:
            if x != GHOST:
                work[C_INCIRCLE] += 1
                result = incircle(xy[p, 0], xy[p, 1], xy[u, 0], xy[u, 1], xy[v, 0], xy[v, 1], xy[x, 0], xy[x, 1]) > 0.0
        else:
            # (p, u, v) is a ghost; across its ghost edge lies the ghost whose
            # finite edge is x -> v (if u is the ghost) or u -> x (if v is).
            work[C_ORIENT] += 1
            if u == GHOST:
                result = orient2d(xy[x, 0], xy[x, 1], xy[v, 0], xy[v, 1], xy[p, 0], xy[p, 1]) > 0.0
            else:
                result = orient2d(xy[u, 0], xy[u, 1], xy[x, 0], xy[x, 1], xy[p, 0], xy[p, 1]) > 0.0
    return result


@kernel_inline
def star_edges(m, t, stack):
    """Push edge 0 of ``t`` and of every triangle after it counter-clockwise
    around its corner 0 (the new vertex); return how many were pushed."""
    n = 0
    s = t
    while True:
        stack[n] = 3 * t
        n += 1
        tw = m.twin[3 * t + 1]
        if tw == NO_EDGE:
            break
        t = tw // 3
        if t == s:
            break
    return n


@kernel_inline
def lawson(m, work, stack, n):
    """Restore the Delaunay property around a new vertex.

    ``stack[:n]`` holds edges 0 of the triangles just created around the new
    vertex.  Every flip replaces the popped edge's triangle and pushes the two
    new edges facing away from the vertex.  Returns a triangle incident to the
    new vertex (a good hint for the next point location).
    """
    last = stack[0] // 3
    while n > 0:
        n -= 1
        e = stack[n]
        if should_flip(m, work, e):
            t1 = flip(m, work, e)
            t2 = m.twin[3 * t1 + 1] // 3
            stack[n] = 3 * t1
            stack[n + 1] = 3 * t2
            n += 2
            last = t1
        else:
            last = e // 3
    return last
