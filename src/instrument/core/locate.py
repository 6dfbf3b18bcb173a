# cython: language_level=3
"""Point location by a remembering stochastic visibility walk.

From a start triangle, cross any edge that has the query point strictly on
its outer side, testing the three edges from a random first one (Devillers,
Pion and Teillaud's stochastic walk, which cannot cycle in any
triangulation).  The walk stops when no edge separates the point, in a ghost
triangle (the point is outside the convex hull) or at a mesh-boundary edge.
Every walk is bounded; a walk that runs out of steps reports ``LOC_FAILED``
and the caller falls back to a scan.

Refinement locates its new points with ``precise_walk`` (Triangle's rule, so
the same subsegments stop it as stop Triangle), falling back to
``line_walk`` (the straight line from the triangle that wants the point).

Each walk returns ``(status, e)`` with ``status`` one of the ``LOC_*``
values of locate.pxd and ``e`` an edge whose meaning the status gives.
"""

from __future__ import annotations

import cython
from cython.cimports.instrument.core.mesh import GHOST, NO_EDGE, Index, Mesh, is_ghost, lnext, lprev, next_random
from cython.cimports.instrument.core.predicates import orient2d
from cython.cimports.instrument.core.scaling import scaled_dot
from cython.cimports.instrument.counters import C_ORIENT, C_WALK

if not cython.compiled:  # compiled, these are locate.pxd's enum
    LOC_INSIDE = 0  # strictly inside triangle e // 3
    LOC_ON_EDGE = 1  # on the open edge e
    LOC_ON_VERTEX = 2  # equal to org(e)
    LOC_OUTSIDE = 3  # across edge e: a ghost triangle's finite edge, or a boundary edge
    LOC_FAILED = 4  # the walk ran out of steps
    LOC_BLOCKED = 5  # the straight path crosses a subsegment or leaves the mesh at e


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def finite_start(m: Mesh, t: Index) -> Index:
    """A finite triangle at or next to ``t`` (a ghost's neighbour across its hull edge)."""
    if not is_ghost(m, t):
        return t
    for k in range(3):
        if m.corner[3 * t + k] == GHOST:
            return m.twin[3 * t + k] // 3
    return t


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _classify(m: Mesh, t: Index, px: cython.double, py: cython.double, zeros: Index, zero_edge: Index) -> tuple[cython.int, Index]:
    """Where in triangle ``t`` the point lies, given how many of its edges'
    lines pass through it (``zeros``) and one such edge."""
    if zeros == 0:
        return LOC_INSIDE, 3 * t
    if zeros == 1:
        return LOC_ON_EDGE, zero_edge
    e: Index
    v: Index
    for k in range(3):
        e = 3 * t + k
        v = m.corner[lnext(e)]
        if m.xy[v, 0] == px and m.xy[v, 1] == py:
            return LOC_ON_VERTEX, e
    return LOC_ON_EDGE, zero_edge  # unreachable for exact predicates


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def walk(m: Mesh, t: Index, px: cython.double, py: cython.double, max_steps: Index) -> tuple[cython.int, Index]:
    """Locate ``(px, py)`` starting from finite triangle ``t``.

    Returns ``(status, e)``: for LOC_INSIDE ``e = 3 * triangle``; for
    LOC_ON_EDGE the edge; for LOC_ON_VERTEX an edge whose origin is the
    vertex; for LOC_OUTSIDE the ghost triangle's finite edge (or, in a mesh
    without ghosts, the boundary edge the point lies beyond).
    """
    steps: Index = 0
    r: Index
    zeros: Index
    zero_edge: Index
    moved: cython.bint
    k: Index
    e: Index
    o: Index
    d: Index
    tw: Index
    s: cython.double
    while steps < max_steps:
        steps += 1
        m.work[C_WALK] += 1
        r = next_random(m)
        zeros = 0
        zero_edge = -1
        moved = False
        for i in range(3):
            k = r + i
            if k >= 3:
                k -= 3
            e = 3 * t + k
            o = m.corner[lnext(e)]
            d = m.corner[lprev(e)]
            m.work[C_ORIENT] += 1
            s = orient2d(m.xy[o, 0], m.xy[o, 1], m.xy[d, 0], m.xy[d, 1], px, py)
            if s < 0.0:
                tw = m.twin[e]
                if tw == NO_EDGE:
                    return LOC_OUTSIDE, e
                t = tw // 3
                if is_ghost(m, t):
                    return LOC_OUTSIDE, tw
                moved = True
                break
            if s == 0.0:
                zeros += 1
                zero_edge = e
        if moved:
            continue
        return _classify(m, t, px, py, zeros, zero_edge)
    return LOC_FAILED, -1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def line_walk(m: Mesh, t: Index, px: cython.double, py: cython.double, max_steps: Index) -> tuple[cython.int, Index]:
    """Locate ``(px, py)`` by walking the straight line to it from the centroid
    of triangle ``t``, stopping at subsegments (refinement's rule: a point
    across a segment from the triangle that wants it is not inserted).

    Returns ``(status, e)`` as ``walk`` does, or ``(LOC_BLOCKED, e)`` with the
    subsegment or boundary edge ``e`` the line crosses.
    """
    a: Index = m.corner[3 * t]
    b: Index = m.corner[3 * t + 1]
    c: Index = m.corner[3 * t + 2]
    sx: cython.double = (m.xy[a, 0] + m.xy[b, 0] + m.xy[c, 0]) / 3.0
    sy: cython.double = (m.xy[a, 1] + m.xy[b, 1] + m.xy[c, 1]) / 3.0
    entered: Index = -1  # the edge we came in through
    exit_edge: Index
    zeros: Index
    zero_edge: Index
    e: Index
    o: Index
    d: Index
    tw: Index
    s: cython.double
    so: cython.double
    sd: cython.double
    for _ in range(max_steps):
        m.work[C_WALK] += 1
        exit_edge = -1
        zeros = 0
        zero_edge = -1
        for k in range(3):
            e = 3 * t + k
            if e == entered:
                continue
            o = m.corner[lnext(e)]
            d = m.corner[lprev(e)]
            m.work[C_ORIENT] += 1
            s = orient2d(m.xy[o, 0], m.xy[o, 1], m.xy[d, 0], m.xy[d, 1], px, py)
            if s < 0.0:
                # the line leaves through this edge if it passes between o and d
                m.work[C_ORIENT] += 2
                so = orient2d(sx, sy, px, py, m.xy[o, 0], m.xy[o, 1])
                sd = orient2d(sx, sy, px, py, m.xy[d, 0], m.xy[d, 1])
                if so <= 0.0 and sd >= 0.0:
                    exit_edge = e
                    break
                if exit_edge < 0:
                    exit_edge = e  # fallback if the line grazes a vertex
            elif s == 0.0:
                zeros += 1
                zero_edge = e
        if exit_edge < 0:
            return _classify(m, t, px, py, zeros, zero_edge)
        tw = m.twin[exit_edge]
        if tw == NO_EDGE or m.seg[exit_edge] >= 0:
            return LOC_BLOCKED, exit_edge
        t = tw // 3
        entered = tw
    return LOC_FAILED, -1


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def precise_walk(m: Mesh, e: Index, px: cython.double, py: cython.double, max_steps: Index) -> tuple[cython.int, Index]:
    """Locate ``(px, py)`` from edge ``e`` by Triangle's ``preciselocate``
    rule, stopping at subsegments; the point must lie left of ``e``.

    At a triangle entered through edge (o, d) with apex a: if the point is
    beyond both other edges, cross the one the point's direction from a
    favours; if beyond one, cross it.  Refinement walks this way so that a
    new vertex finds the same triangle and edge, and runs into the same
    subsegments, as it does in Triangle.

    Returns ``(status, e)``: LOC_INSIDE with the last edge crossed (or the
    start) as ``e``; LOC_ON_EDGE with the edge, oriented as the walk found
    it; LOC_ON_VERTEX with an edge whose origin is the vertex; LOC_BLOCKED
    with the subsegment or boundary edge in the way; LOC_FAILED after
    ``max_steps``.
    """
    o: Index
    d: Index
    a: Index
    cross: Index
    tw: Index
    left: cython.double
    right: cython.double
    go_left: cython.bint
    for _ in range(max_steps):
        m.work[C_WALK] += 1
        o = m.corner[lnext(e)]
        d = m.corner[lprev(e)]
        a = m.corner[e]
        if m.xy[a, 0] == px and m.xy[a, 1] == py:
            return LOC_ON_VERTEX, lprev(e)
        m.work[C_ORIENT] += 2
        left = orient2d(m.xy[o, 0], m.xy[o, 1], m.xy[a, 0], m.xy[a, 1], px, py)
        right = orient2d(m.xy[a, 0], m.xy[a, 1], m.xy[d, 0], m.xy[d, 1], px, py)
        if left > 0.0 and right > 0.0:
            go_left = scaled_dot(m.xy[a, 0] - px, m.xy[a, 1] - py, m.xy[d, 0] - m.xy[o, 0], m.xy[d, 1] - m.xy[o, 1]) > 0.0
        elif left > 0.0:
            go_left = True
        elif right > 0.0:
            go_left = False
        elif left == 0.0:
            return _on_edge(m, lprev(e), px, py)
        elif right == 0.0:
            return _on_edge(m, lnext(e), px, py)
        else:
            return LOC_INSIDE, e
        cross = lprev(e) if go_left else lnext(e)
        tw = m.twin[cross]
        if m.seg[cross] >= 0 or tw == NO_EDGE or is_ghost(m, tw // 3):
            return LOC_BLOCKED, cross
        e = tw
    return LOC_FAILED, -1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _on_edge(m: Mesh, e: Index, px: cython.double, py: cython.double) -> tuple[cython.int, Index]:
    """On edge ``e``'s line inside its triangle: on the edge or at an end."""
    o: Index = m.corner[lnext(e)]
    d: Index = m.corner[lprev(e)]
    if m.xy[o, 0] == px and m.xy[o, 1] == py:
        return LOC_ON_VERTEX, e
    if m.xy[d, 0] == px and m.xy[d, 1] == py:
        return LOC_ON_VERTEX, lnext(e)
    return LOC_ON_EDGE, e
