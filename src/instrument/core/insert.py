# cython: language_level=3
"""Vertex insertion: 1-to-3 and 2-to-4 splits, edge flips and Lawson's flip loop.

Every new triangle puts the new vertex at corner 0, so the edge to test after
an insertion is always edge 0 (``3t``), the one opposite the new vertex.  The
flip test understands ghost triangles (corner ``GHOST``): a ghost ``(a, b,
GHOST)`` stands for the open half-plane left of ``a -> b``, which is its
"circumcircle" (see mesh.py).

Counting: finite triangles only, so that ``created - deleted`` is the number
of triangles in the mesh; a flip creates one and deletes one triangle, which
makes the created count of an insertion the number of triangles incident to
the new vertex afterwards.  The caller makes sure the mesh has room for the
triangles an operation makes (two for a split, two for a flip).
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import (
    GHOST,
    Index,
    NO_EDGE,
    NO_SEG,
    Mesh,
    bond,
    is_ghost,
    kill_triangle,
    lnext,
    lprev,
    new_triangle,
    spare_triangles,
)
from cython.cimports.instrument.core.predicates import incircle, orient2d
from cython.cimports.instrument.counters import C_CREATED, C_DELETED, C_FLIP, C_INCIRCLE, C_ORIENT


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _make(m: Mesh, a: Index, b: Index, c: Index) -> Index:
    """Allocate triangle (a, b, c) and count it if finite."""
    t: Index = new_triangle(m, a, b, c)
    if a != GHOST and b != GHOST and c != GHOST:
        m.work[C_CREATED] += 1
    return t


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _kill(m: Mesh, t: Index) -> cython.void:
    if not is_ghost(m, t):
        m.work[C_DELETED] += 1
    kill_triangle(m, t)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def split_triangle(m: Mesh, t: Index, p: Index) -> Index:
    """Replace triangle ``t`` by three triangles around vertex ``p`` inside it.

    Returns the slot of the first new triangle; the three new ones are
    ``(p, b, c), (p, c, a), (p, a, b)`` with edge 0 facing outwards.
    """
    e: Index = 3 * t
    a: Index = m.corner[e]
    b: Index = m.corner[e + 1]
    c: Index = m.corner[e + 2]
    n0: Index = m.twin[e]
    n1: Index = m.twin[e + 1]
    n2: Index = m.twin[e + 2]
    s0: cython.int = m.seg[e]
    s1: cython.int = m.seg[e + 1]
    s2: cython.int = m.seg[e + 2]
    _kill(m, t)
    t0: Index = _make(m, p, b, c)
    t1: Index = _make(m, p, c, a)
    t2: Index = _make(m, p, a, b)
    f0: Index = 3 * t0
    f1: Index = 3 * t1
    f2: Index = 3 * t2
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


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def split_edge(m: Mesh, e: Index, p: Index) -> Index:
    """Split edge ``e`` (and its twin, if any) at vertex ``p`` lying on it.

    The triangle of ``e`` is ``(o, d, x)``; it becomes ``(p, d, x)`` and
    ``(p, x, o)``.  The twin's triangle ``(d, o, y)`` becomes ``(p, o, y)`` and
    ``(p, y, d)``.  Both halves of the split edge keep its subsegment record.
    Returns the edge ``p -> d`` of the first new triangle (on the split line).
    """
    o: Index = m.corner[lnext(e)]
    d: Index = m.corner[lprev(e)]
    x: Index = m.corner[e]
    tw: Index = m.twin[e]
    s: cython.int = m.seg[e]
    na: Index = m.twin[lnext(e)]
    nb: Index = m.twin[lprev(e)]
    sa: cython.int = m.seg[lnext(e)]
    sb: cython.int = m.seg[lprev(e)]
    _kill(m, e // 3)
    ta: Index = _make(m, p, d, x)
    tb: Index = _make(m, p, x, o)
    A: Index = 3 * ta
    B: Index = 3 * tb
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
        y: Index = m.corner[tw]
        nc: Index = m.twin[lnext(tw)]
        nd: Index = m.twin[lprev(tw)]
        sc: cython.int = m.seg[lnext(tw)]
        sd: cython.int = m.seg[lprev(tw)]
        _kill(m, tw // 3)
        tc: Index = _make(m, p, o, y)
        td: Index = _make(m, p, y, d)
        C: Index = 3 * tc
        D: Index = 3 * td
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


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def flip(m: Mesh, e: Index) -> Index:
    """Flip edge ``e`` of triangle ``(o, d, x)`` whose twin is in ``(d, o, y)``.

    The result is ``(x, o, y)`` and ``(x, y, d)``, with ``x`` at corner 0 of
    both, so their edges 0 are the two edges that were opposite ``x``'s side.
    Returns the slot of the first new triangle.
    """
    tw: Index = m.twin[e]
    o: Index = m.corner[lnext(e)]
    d: Index = m.corner[lprev(e)]
    x: Index = m.corner[e]
    y: Index = m.corner[tw]
    n_xo: Index = m.twin[lprev(e)]  # edge x -> o
    n_dx: Index = m.twin[lnext(e)]  # edge d -> x
    n_oy: Index = m.twin[lnext(tw)]  # edge o -> y
    n_yd: Index = m.twin[lprev(tw)]  # edge y -> d
    s_xo: cython.int = m.seg[lprev(e)]
    s_dx: cython.int = m.seg[lnext(e)]
    s_oy: cython.int = m.seg[lnext(tw)]
    s_yd: cython.int = m.seg[lprev(tw)]
    _kill(m, e // 3)
    _kill(m, tw // 3)
    t1: Index = _make(m, x, o, y)
    t2: Index = _make(m, x, y, d)
    T1: Index = 3 * t1
    T2: Index = 3 * t2
    bond(m, T1, n_oy)
    bond(m, T1 + 2, n_xo)
    bond(m, T2, n_yd)
    bond(m, T2 + 1, n_dx)
    bond(m, T1 + 1, T2 + 2)
    m.seg[T1] = s_oy
    m.seg[T1 + 2] = s_xo
    m.seg[T2] = s_yd
    m.seg[T2 + 1] = s_dx
    m.work[C_FLIP] += 1
    return t1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def flip_in_place(m: Mesh, e: Index) -> cython.void:
    """Flip edge ``e`` as Triangle does, in its two slots.

    ``e`` runs ``a -> b`` in triangle ``(a, b, c)`` (apex ``c``); its twin
    runs ``b -> a`` with apex ``d``.  Afterwards edge ``e`` (the same
    number) runs ``d -> c`` with apex ``a``, and the twin runs ``c -> d``
    with apex ``b``: each slot keeps its place in memory and the rotation
    of the edge it was flipped through, which is where Triangle's flip
    leaves its two triangle records (measured from its output order, which
    is its pool order: tests/engine/test_pool_order.py).  ``flip`` instead
    frees both slots and takes them again in the other order, the two new
    triangles each with the far vertex first.  Both slots' stamps move on
    (their triangles changed), the flip counts as ``flip`` counts it, and a
    side of the quadrilateral on the mesh's boundary becomes
    ``Mesh.outer_space_edge`` (where Triangle's outer space points after its flip
    bonds that side to it).
    """
    tw: Index = m.twin[e]
    e1: Index = lnext(e)
    e2: Index = lprev(e)
    t1: Index = lnext(tw)
    t2: Index = lprev(tw)
    a: Index = m.corner[e1]
    b: Index = m.corner[e2]
    c: Index = m.corner[e]
    d: Index = m.corner[tw]
    n_bc: Index = m.twin[e1]  # across b -> c
    n_ca: Index = m.twin[e2]  # across c -> a
    n_ad: Index = m.twin[t1]  # across a -> d
    n_db: Index = m.twin[t2]  # across d -> b
    has_seg: cython.bint = m.seg.shape[0] > 0
    s_bc: cython.int = NO_SEG
    s_ca: cython.int = NO_SEG
    s_ad: cython.int = NO_SEG
    s_db: cython.int = NO_SEG
    if has_seg:
        s_bc = m.seg[e1]
        s_ca = m.seg[e2]
        s_ad = m.seg[t1]
        s_db = m.seg[t2]
    m.corner[e] = cython.cast(cython.int, a)
    m.corner[e1] = cython.cast(cython.int, d)
    m.corner[e2] = cython.cast(cython.int, c)
    m.corner[tw] = cython.cast(cython.int, b)
    m.corner[t1] = cython.cast(cython.int, c)
    m.corner[t2] = cython.cast(cython.int, d)
    # (a, d, c): c -> a at e1, a -> d at e2; (b, c, d): d -> b at t1, b -> c at t2
    bond(m, e1, n_ca)
    bond(m, e2, n_ad)
    bond(m, t1, n_db)
    bond(m, t2, n_bc)
    if has_seg:
        m.seg[e1] = s_ca
        m.seg[e2] = s_ad
        m.seg[t1] = s_db
        m.seg[t2] = s_bc
    # Triangle's outer space points at the last triangle bonded to it
    if n_ca == NO_EDGE:
        m.outer_space_edge = e1
    if n_ad == NO_EDGE:
        m.outer_space_edge = e2
    if n_db == NO_EDGE:
        m.outer_space_edge = t1
    if n_bc == NO_EDGE:
        m.outer_space_edge = t2
    m.stamp[e // 3] += 1
    m.stamp[tw // 3] += 1
    if not is_ghost(m, e // 3):
        m.work[C_CREATED] += 1
        m.work[C_DELETED] += 1
    if not is_ghost(m, tw // 3):
        m.work[C_CREATED] += 1
        m.work[C_DELETED] += 1
    m.work[C_FLIP] += 1


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _remember(m: Mesh, t: Index) -> cython.void:
    """Triangle ``t``'s edges as its corners' edge hints (if the mesh keeps them)."""
    if m.vtri.shape[0] > 0:
        for k in range(3):
            m.vtri[m.corner[3 * t + k]] = 3 * t + (k + 2) % 3


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def split_edge_in_place(m: Mesh, h: Index, v: Index, half: cython.int, zero: Index) -> Index:
    """Split edge ``h`` (and its twin, if any) at vertex ``v`` as Triangle
    splits a triangle edge, keeping its records where Triangle keeps them.

    ``h`` runs ``r -> l`` in triangle ``(r, l, b)``; its twin ``l -> r`` in
    ``(l, r, x)``.  ``h``'s slot becomes ``(v, l, b)`` (its edge ``h`` runs
    ``v -> l``), the twin's slot ``(l, v, x)`` (the twin runs ``l -> v``),
    and two new triangles are taken, ``(r, x, v)`` first if there is a twin,
    then ``(b, r, v)``, each made with its edge ``zero`` (the one Triangle's
    new records start from: 2 before refinement, 0 during it, see
    refine.run) running from its first corner to its second.  The half
    ``v - l`` keeps the edge's subsegment record; the half ``r - v`` gets
    record ``half`` (NO_SEG if the edge is none).  Returns ``lnext(h)``, the
    edge ``l -> b`` opposite ``v``, where Triangle's flips around ``v``
    start (``lawson_in_place``); -1 if no triangle could be taken (nothing
    changed).  A new triangle's side on the mesh's boundary becomes
    ``Mesh.outer_space_edge``, as in ``flip_in_place``."""
    tw: Index = m.twin[h]
    need: Index = 2 if tw != NO_EDGE else 1
    if spare_triangles(m) < need:
        return -1
    z0: Index = zero
    z1: Index = (zero + 1) % 3
    z2: Index = (zero + 2) % 3
    r: Index = m.corner[lnext(h)]
    b: Index = m.corner[h]
    n_br: Index = m.twin[lprev(h)]  # across b -> r
    has_seg: cython.bint = m.seg.shape[0] > 0
    s_br: cython.int = m.seg[lprev(h)] if has_seg else NO_SEG
    x: Index
    n_rx: Index
    s_rx: cython.int
    tt: Index
    T: Index = -1
    m.corner[lnext(h)] = cython.cast(cython.int, v)
    m.stamp[h // 3] += 1
    m.work[C_DELETED] += 1
    if tw != NO_EDGE:
        x = m.corner[tw]
        n_rx = m.twin[lnext(tw)]
        s_rx = m.seg[lnext(tw)] if has_seg else NO_SEG
        m.corner[lprev(tw)] = cython.cast(cython.int, v)
        m.stamp[tw // 3] += 1
        m.work[C_DELETED] += 1
        # (r, x, v): its edge zero r -> x, then x -> v, then v -> r
        tt = _make(m, r, x, v) if zero == 2 else (_make(m, v, r, x) if zero == 0 else _make(m, x, v, r))
        T = 3 * tt
        bond(m, T + z1, lnext(tw))  # x -> v
        bond(m, T + z0, n_rx)  # r -> x
        if has_seg:
            m.seg[lnext(tw)] = NO_SEG
            m.seg[T + z0] = s_rx
            m.seg[T + z2] = half
        m.work[C_CREATED] += 1
    # (b, r, v): its edge zero b -> r, then r -> v, then v -> b
    tb: Index = _make(m, b, r, v) if zero == 2 else (_make(m, v, b, r) if zero == 0 else _make(m, r, v, b))
    B: Index = 3 * tb
    bond(m, B + z2, lprev(h))  # v -> b
    bond(m, B + z0, n_br)  # b -> r
    if tw != NO_EDGE:
        bond(m, B + z1, T + z2)  # r -> v
    if has_seg:
        m.seg[lprev(h)] = NO_SEG
        m.seg[B + z0] = s_br
        m.seg[B + z1] = half
    m.work[C_CREATED] += 1
    # sides on the boundary, bonded to Triangle's outer space in this order
    if tw != NO_EDGE and m.twin[T + z0] == NO_EDGE:
        m.outer_space_edge = T + z0
    if n_br == NO_EDGE:
        m.outer_space_edge = B + z0
    if tw == NO_EDGE:
        m.outer_space_edge = B + z1
    return lnext(h)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def lawson_in_place(m: Mesh, h: Index) -> cython.void:
    """Triangle's flips around a vertex ``v`` just inserted, from edge ``h``
    (opposite ``v``, which is its apex), with ``flip_in_place``.

    The edges opposite ``v`` are visited counter-clockwise around it:
    an edge that is no subsegment, has a triangle beyond and whose far
    vertex lies inside the circle of its triangle with ``v`` is flipped,
    and the first of the two edges it exposes is visited next; any other
    edge is accepted, and the walk moves on to the next triangle around
    ``v``, until it is back where it started (or at the mesh's boundary).
    The triangles around ``v`` are left where Triangle's records are, and
    the corners' edge hints point into them."""
    xy = m.xy
    first: Index = m.corner[lnext(h)]
    v: Index = m.corner[h]
    e: Index = h
    tw: Index
    rr: Index
    ll: Index
    f: Index
    nx: Index
    flipping: cython.bint
    while True:
        tw = m.twin[e]
        rr = m.corner[lnext(e)]
        ll = m.corner[lprev(e)]
        flipping = False
        if tw != NO_EDGE and (m.seg.shape[0] == 0 or m.seg[e] == NO_SEG):
            f = m.corner[tw]
            m.work[C_INCIRCLE] += 1
            flipping = incircle(xy[ll, 0], xy[ll, 1], xy[v, 0], xy[v, 1], xy[rr, 0], xy[rr, 1], xy[f, 0], xy[f, 1]) > 0.0
        if flipping:
            flip_in_place(m, e)  # e: far -> v now, apex rr
            e = lprev(e)  # rr -> far, apex v
            continue
        _remember(m, e // 3)
        nx = m.twin[lnext(e)]  # across ll -> v
        if ll == first or nx == NO_EDGE:
            return
        e = lnext(nx)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def should_flip(m: Mesh, e: Index) -> cython.bint:
    """Lawson's test for edge ``e`` = edge 0 of a triangle ``(p, u, v)``.

    True if the far vertex lies strictly inside the circumcircle of
    ``(p, u, v)``; ghosts use the half-plane rule of mesh.py.  Constrained
    edges and mesh-boundary edges never flip.
    """
    tw: Index = m.twin[e]
    result: cython.bint = False
    if tw != NO_EDGE and m.seg[e] == NO_SEG:
        xy = m.xy
        p: Index = m.corner[e]
        u: Index = m.corner[lnext(e)]
        v: Index = m.corner[lprev(e)]
        x: Index = m.corner[tw]
        if u != GHOST and v != GHOST:
            if x != GHOST:
                m.work[C_INCIRCLE] += 1
                result = incircle(xy[p, 0], xy[p, 1], xy[u, 0], xy[u, 1], xy[v, 0], xy[v, 1], xy[x, 0], xy[x, 1]) > 0.0
        else:
            # (p, u, v) is a ghost; across its ghost edge lies the ghost whose
            # finite edge is x -> v (if u is the ghost) or u -> x (if v is).
            m.work[C_ORIENT] += 1
            if u == GHOST:
                result = orient2d(xy[x, 0], xy[x, 1], xy[v, 0], xy[v, 1], xy[p, 0], xy[p, 1]) > 0.0
            else:
                result = orient2d(xy[u, 0], xy[u, 1], xy[x, 0], xy[x, 1], xy[p, 0], xy[p, 1]) > 0.0
    return result


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def star_edges(m: Mesh, t: Index, stack: cython.longlong[::1]) -> Index:
    """Push edge 0 of ``t`` and of every triangle after it counter-clockwise
    around its corner 0 (the new vertex); return how many were pushed."""
    n: Index = 0
    s: Index = t
    tw: Index
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


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def lawson(m: Mesh, stack: cython.longlong[::1], n: Index) -> Index:
    """Restore the Delaunay property around a new vertex.

    ``stack[:n]`` holds edges 0 of the triangles just created around the new
    vertex.  Every flip replaces the popped edge's triangle and pushes the two
    new edges facing away from the vertex.  Returns a triangle incident to the
    new vertex (a good hint for the next point location).
    """
    last: Index = stack[0] // 3
    e: Index
    t1: Index
    t2: Index
    while n > 0:
        n -= 1
        e = stack[n]
        if should_flip(m, e):
            t1 = flip(m, e)
            t2 = m.twin[3 * t1 + 1] // 3
            stack[n] = 3 * t1
            stack[n + 1] = 3 * t2
            n += 2
            last = t1
        else:
            last = e // 3
    return last


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def make_delaunay(m: Mesh, stack: cython.longlong[::1], queued: cython.uchar[::1]) -> Index:
    """Flip every non-constrained edge that is not locally Delaunay (Lawson).

    ``stack`` and ``queued`` have one entry per edge slot; each edge is on the
    stack at most once.  Returns the number of flips."""
    n: Index = 0
    e: Index
    tw: Index
    for t in range(m.nslot):
        if m.stamp[t] > 0:
            for k in range(3):
                e = 3 * t + k
                tw = m.twin[e]
                if tw > e and m.seg[e] == NO_SEG:  # each interior edge once
                    stack[n] = e
                    queued[e] = 1
                    n += 1
    flips: Index = 0
    t1: Index
    t2: Index
    f: Index
    sides = cython.declare(Index[4])
    while n > 0:
        n -= 1
        e = stack[n]
        queued[e] = 0
        if m.stamp[e // 3] <= 0 or not should_flip(m, e):
            continue
        t1 = flip(m, e)
        flips += 1
        t2 = m.twin[3 * t1 + 1] // 3
        # the four sides of the flipped quad (the new diagonal is fine)
        sides[0] = 3 * t1
        sides[1] = 3 * t1 + 2
        sides[2] = 3 * t2
        sides[3] = 3 * t2 + 1
        for k in range(4):
            f = sides[k]
            if not queued[f] and m.twin[f] != NO_EDGE and m.seg[f] == NO_SEG:
                queued[f] = 1
                stack[n] = f
                n += 1
    return flips


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def splits_cleanly(m: Mesh, c: Index, px: cython.double, py: cython.double) -> cython.bint:
    """Would splitting edge ``c`` (``r -> l``, apex ``b``; beyond it apex
    ``x``) at the point ``p`` leave four counter-clockwise triangles ``(p,
    l, b)``, ``(b, r, p)``, ``(p, x, l)``, ``(r, x, p)``?  Whether ``p`` is
    on ``c``'s line does not matter (a rounded crossing point, a subsegment's
    split point rounded off its line): only that it lies inside the
    quadrilateral the two triangles make, as seen from its corners (then
    Lawson's flips keep every triangle counter-clockwise).  Segment
    recovery's crossings and refinement's in-place splits both ask it."""
    xy = m.xy
    r: Index = m.corner[lnext(c)]
    l: Index = m.corner[lprev(c)]
    b: Index = m.corner[c]
    m.work[C_ORIENT] += 2
    if not (orient2d(px, py, xy[l, 0], xy[l, 1], xy[b, 0], xy[b, 1]) > 0.0
            and orient2d(xy[b, 0], xy[b, 1], xy[r, 0], xy[r, 1], px, py) > 0.0):
        return False
    tw: Index = m.twin[c]
    if tw == NO_EDGE:
        return True
    x: Index = m.corner[tw]
    m.work[C_ORIENT] += 2
    return (orient2d(px, py, xy[x, 0], xy[x, 1], xy[l, 0], xy[l, 1]) > 0.0
            and orient2d(xy[r, 0], xy[r, 1], xy[x, 0], xy[x, 1], px, py) > 0.0)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def splits_after_a_flip(m: Mesh, c: Index, px: cython.double, py: cython.double) -> cython.bint:
    """Would Triangle's split of edge ``c`` at ``p`` (``split_edge_in_place``,
    then ``lawson_in_place``) leave counter-clockwise triangles although it
    does not split ``c`` cleanly?  So where ``p`` lies outside the
    quadrilateral of the two triangles beside ``c`` across one of its four
    sides ``u -> w`` only: the split leaves the one clockwise triangle ``(p,
    u, w)``, and Triangle's flips test its side as any other (the far vertex
    ``f`` in its circle, by the same incircle, whose sign the clockwise
    triangle reverses).  Where that test flips the side (no subsegment, a
    triangle beyond it) and the two triangles the flip leaves, ``(p, u, f)``
    and ``(p, f, w)``, are counter-clockwise (``p`` lies inside the triangle
    beyond the side), the mesh is a valid one, and the flips go on as around
    any vertex.  (A segment's crossing an ulp beside the end (0.4845, 0.0021)
    of the subsegment it crosses rounds across a side of a sliver beside
    it: regressions/through-vertex-after-crossing-count.json.)"""
    tw: Index = m.twin[c]
    if tw == NO_EDGE:
        return False
    xy = m.xy
    across: Index = NO_EDGE
    side: Index
    u: Index
    w: Index
    s: cython.double
    for k in range(4):  # the sides l -> b, b -> r, x -> l, r -> x
        side = lnext(c) if k == 0 else (lprev(c) if k == 1 else (lprev(tw) if k == 2 else lnext(tw)))
        u = m.corner[lnext(side)]
        w = m.corner[lprev(side)]
        m.work[C_ORIENT] += 1
        s = orient2d(px, py, xy[u, 0], xy[u, 1], xy[w, 0], xy[w, 1])
        if s == 0.0 or (s < 0.0 and across != NO_EDGE):
            return False
        if s < 0.0:
            across = side
    if across == NO_EDGE or m.twin[across] == NO_EDGE or (m.seg.shape[0] > 0 and m.seg[across] != NO_SEG):
        return False
    u = m.corner[lnext(across)]
    w = m.corner[lprev(across)]
    f: Index = m.corner[m.twin[across]]
    if f == GHOST:
        return False
    m.work[C_INCIRCLE] += 1
    if not incircle(xy[w, 0], xy[w, 1], px, py, xy[u, 0], xy[u, 1], xy[f, 0], xy[f, 1]) > 0.0:
        return False
    m.work[C_ORIENT] += 2
    return (orient2d(px, py, xy[u, 0], xy[u, 1], xy[f, 0], xy[f, 1]) > 0.0
            and orient2d(px, py, xy[f, 0], xy[f, 1], xy[w, 0], xy[w, 1]) > 0.0)
