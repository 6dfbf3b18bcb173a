# cython: language_level=3
"""Delaunay triangulation by randomized incremental insertion (``-i``).

Points are inserted in a biased randomized insertion order (BRIO: rounds of
doubling size, each sorted along a Hilbert curve; ``insertion_order``),
located by walking from the previous insertion, and inserted with Lawson
flips.  Ghost triangles keep the outside of the hull symbolic while the
mesh is built (see mesh.py).  A point equal to an inserted vertex is not
inserted; the caller learns which vertex it duplicates.
"""

from __future__ import annotations

import numpy as np

import cython
from cython.cimports.instrument.core.insert import lawson, split_edge, split_triangle, star_edges
from cython.cimports.instrument.core.locate import LOC_FAILED, LOC_ON_EDGE, LOC_ON_VERTEX, LOC_OUTSIDE, finite_start, walk
from cython.cimports.instrument.core.mesh import GHOST, Index, Mesh, bond, lnext, new_triangle
from cython.cimports.instrument.core.predicates import orient2d
from cython.cimports.instrument.counters import C_CREATED, C_DUPLICATE, C_ORIENT

# ------------------------------------------------------------ insertion order


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _hilbert_key(x: cython.longlong, y: cython.longlong, side: cython.longlong) -> cython.longlong:
    """Index of cell (x, y) along a side x side Hilbert curve (side a power of two)."""
    d: cython.longlong = 0
    s: cython.longlong = side >> 1
    rx: cython.longlong
    ry: cython.longlong
    while s > 0:
        rx = 1 if (x & s) else 0
        ry = 1 if (y & s) else 0
        d += s * s * ((3 * rx) ^ ry)
        if ry == 0:
            if rx == 1:
                x = side - 1 - x
                y = side - 1 - y
            x, y = y, x
        s >>= 1
    return d


def hilbert_keys(xy, ids, xmin: float, ymin: float, scale: float):
    """Index along a 2^16 x 2^16 Hilbert curve of each point in ``ids``."""
    side: cython.longlong = 1 << 16
    pts: cython.double[:, ::1] = np.ascontiguousarray(xy, dtype=np.float64)
    which: cython.longlong[::1] = np.ascontiguousarray(ids, dtype=np.int64)
    keys = np.empty(which.shape[0], dtype=np.int64)
    out: cython.longlong[::1] = keys
    x0: cython.double = xmin
    y0: cython.double = ymin
    s: cython.double = scale
    x: cython.longlong
    y: cython.longlong
    i: Index
    with cython.nogil:
        for j in range(which.shape[0]):
            i = which[j]
            x = cython.cast(cython.longlong, (pts[i, 0] - x0) * s)
            y = cython.cast(cython.longlong, (pts[i, 1] - y0) * s)
            x = min(max(x, 0), side - 1)
            y = min(max(y, 0), side - 1)
            out[j] = _hilbert_key(x, y, side)
    return keys


def insertion_order(xy, ids, seed: int = 0):
    """BRIO of ``ids`` (Amenta, Choi and Rote): each point joins round r with
    probability 2^-(r+1), later rounds first being the smaller; within a
    round, points follow a Hilbert curve.  One sort on (round, curve index)."""
    ids = np.asarray(ids, dtype=np.int64)
    if ids.size == 0:
        return ids
    pts = xy[ids]
    # column by column: a reduction along axis 0 of an (n, 2) array is many times slower
    lo = (float(pts[:, 0].min()), float(pts[:, 1].min()))
    span = max(float(pts[:, 0].max()) - lo[0], float(pts[:, 1].max()) - lo[1])
    scale = 65535.0 / span if span > 0 else 0.0
    if not np.isfinite(scale):
        scale = 0.0
    keys = hilbert_keys(xy, ids, float(lo[0]), float(lo[1]), scale)
    # round of each point: position in a random permutation, halved per round
    pos = np.random.default_rng(seed).permutation(ids.size)
    rounds = np.floor(np.log2(np.maximum(pos, 1))).astype(np.int64)
    rounds[pos < 64] = 0  # the first few points form one round
    return ids[np.argsort((rounds << 32) | keys, kind="stable")]


# ------------------------------------------------------------------ building


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _first_triangle(m: Mesh, n: Index) -> tuple[Index, Index, Index]:
    """Make the first triangle from point 0, the first point different from
    it and the first point not collinear with both, plus its three ghosts.

    Returns (its slot, the second point, the third), or (-1, -1, -1) if
    every point is collinear."""
    xy = m.xy
    a: Index = 0
    jb: Index = 1
    while jb < n and xy[jb, 0] == xy[a, 0] and xy[jb, 1] == xy[a, 1]:
        jb += 1
    b: Index
    s: cython.double
    t: Index
    g_ab: Index
    g_bc: Index
    g_ca: Index
    for c in range(jb + 1, n):
        b = jb
        m.work[C_ORIENT] += 1
        s = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1])
        if s != 0.0:
            if s < 0.0:
                a, b = b, a
            t = new_triangle(m, a, b, c)
            m.work[C_CREATED] += 1
            g_ab = new_triangle(m, b, a, GHOST)
            g_bc = new_triangle(m, c, b, GHOST)
            g_ca = new_triangle(m, a, c, GHOST)
            bond(m, 3 * t + 2, 3 * g_ab + 2)
            bond(m, 3 * t + 0, 3 * g_bc + 2)
            bond(m, 3 * t + 1, 3 * g_ca + 2)
            bond(m, 3 * g_ab + 0, 3 * g_ca + 1)
            bond(m, 3 * g_ca + 0, 3 * g_bc + 1)
            bond(m, 3 * g_bc + 0, 3 * g_ab + 1)
            return t, jb, c
    return -1, -1, -1


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _scan_locate(m: Mesh, px: cython.double, py: cython.double) -> tuple[cython.int, Index]:
    """Fallback location: test every live finite triangle (never expected)."""
    xy = m.xy
    a: Index
    b: Index
    c: Index
    s0: cython.double
    s1: cython.double
    s2: cython.double
    for t in range(m.nslot):
        if m.stamp[t] <= 0:
            continue
        a, b, c = m.corner[3 * t], m.corner[3 * t + 1], m.corner[3 * t + 2]
        if a == GHOST or b == GHOST or c == GHOST:
            continue
        m.work[C_ORIENT] += 3
        s0 = orient2d(xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1], px, py)
        s1 = orient2d(xy[c, 0], xy[c, 1], xy[a, 0], xy[a, 1], px, py)
        s2 = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], px, py)
        if s0 >= 0 and s1 >= 0 and s2 >= 0:
            return walk(m, t, px, py, 2)  # classifies at once
    # outside the hull: find a hull edge that sees the point
    e: Index
    o: Index
    d: Index
    for t in range(m.nslot):
        if m.stamp[t] <= 0:
            continue
        for k in range(3):
            if m.corner[3 * t + k] == GHOST:
                e = 3 * t + k
                o = m.corner[3 * t + (k + 1) % 3]
                d = m.corner[3 * t + (k + 2) % 3]
                m.work[C_ORIENT] += 1
                if orient2d(xy[o, 0], xy[o, 1], xy[d, 0], xy[d, 1], px, py) > 0:
                    return LOC_OUTSIDE, e
    return LOC_FAILED, -1


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _insert_point(m: Mesh, q: Index, hint: Index, stack: cython.longlong[::1]) -> tuple[cython.int, Index]:
    """Insert vertex ``q`` into a Delaunay triangulation with ghosts.

    Returns ``(status, t)``: ``status`` is the location result (LOC_ON_VERTEX
    means ``q`` duplicates the origin of edge ``t`` and was not inserted) and
    ``t`` a triangle incident to ``q``, the next walk's start.
    """
    px: cython.double = m.xy[q, 0]
    py: cython.double = m.xy[q, 1]
    start: Index = finite_start(m, hint)
    status: cython.int
    e: Index
    status, e = walk(m, start, px, py, 4 * m.stamp.shape[0] + 64)
    if status == LOC_FAILED:
        status, e = _scan_locate(m, px, py)
    if status == LOC_ON_VERTEX:
        m.work[C_DUPLICATE] += 1
        return status, e
    first: Index
    if status == LOC_ON_EDGE:
        first = split_edge(m, e, q) // 3
    else:  # inside a finite triangle, or inside a ghost (outside the hull)
        first = split_triangle(m, e // 3, q)
    n: Index = star_edges(m, first, stack)
    return status, lawson(m, stack, n)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _insert_all(m: Mesh, n: Index, jb: Index, jc: Index, t: Index, stack: cython.longlong[::1], dup: cython.longlong[::1]) -> cython.void:
    """Insert points ``1 .. n-1`` except the first triangle's corners; a point
    equal to an inserted vertex is recorded in ``dup`` and left out."""
    status: cython.int
    t2: Index
    for q in range(1, n):
        if q == jb or q == jc:
            continue
        status, t2 = _insert_point(m, q, t, stack)
        if status == LOC_ON_VERTEX:
            dup[q] = m.corner[lnext(t2)]
        else:
            t = t2


def triangulate(m: Mesh, seed: int):
    """Triangulate the vertices of ``m`` (in insertion order) with ghosts around
    the hull, by Lawson insertion; returns ``dup`` (per vertex: -1, or the
    vertex it duplicates), or None when every point is collinear (no
    triangle then).  ``m`` has room for 2n + 8 triangles."""
    n: Index = m.nvert
    m.rng = seed * 2654435761 + 1
    t: Index
    jb: Index
    jc: Index
    t, jb, jc = _first_triangle(m, n)
    if t < 0:
        return None
    stack: cython.longlong[::1] = np.empty(n + 8, dtype=np.int64)
    dup = np.full(n, -1, dtype=np.int64)
    d: cython.longlong[::1] = dup
    with cython.nogil:
        _insert_all(m, n, jb, jc, t, stack, d)
    return dup
