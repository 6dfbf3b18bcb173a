"""Delaunay triangulation of a point set.

Two methods:

* divide and conquer (divconq.py), the default, as in Triangle: with its tie
  rules the triangulation of cocircular points is the one Triangle makes;
  cuts alternate between vertical and horizontal unless ``vertical`` (``-l``);
* randomized incremental insertion (``-i``): points in a biased randomized
  insertion order (BRIO: rounds of doubling size, each sorted along a Hilbert
  curve), located by walking from the previous insertion, inserted with
  Lawson flips.

Ghost triangles keep the outside of the hull symbolic while the mesh is
built; they are removed at the end, leaving ``NO_EDGE`` across the convex
hull.  Exact duplicates are never inserted: ``duplicate_of[i]`` names the
surviving copy (the lowest input index), as Triangle keeps duplicates in the
output numbering but out of the mesh.
"""

from __future__ import annotations

import numpy as np

from .counters import C_CREATED, C_DUPLICATE, C_ORIENT
from .divconq import cut_order, triangulate_sorted
from .insert import lawson, split_edge, split_triangle, star_edges
from .jit import allocating, kernel, kernel_inline
from .locate import (
    LOC_FAILED,
    LOC_ON_EDGE,
    LOC_ON_VERTEX,
    LOC_OUTSIDE,
    finite_start,
    walk,
)
from .mesh import (
    GHOST,
    NO_EDGE,
    S_NSLOT,
    Mesh,
    bond,
    kill_triangle,
    lnext,
    new_mesh,
    new_triangle,
)
from .predicates import orient2d

# ------------------------------------------------------------ insertion order


@allocating
def _hilbert_keys(xy, ids, xmin, ymin, scale):
    """Index along a 2^16 x 2^16 Hilbert curve of each point in ``ids``."""
    side = 1 << 16
    keys = np.empty(ids.shape[0], dtype=np.int64)
    for j in range(ids.shape[0]):
        i = ids[j]
        x = int((xy[i, 0] - xmin) * scale)
        y = int((xy[i, 1] - ymin) * scale)
        x = min(max(x, 0), side - 1)
        y = min(max(y, 0), side - 1)
        d = 0
        s = side >> 1
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
        keys[j] = d
    return keys


def insertion_order(xy: np.ndarray, ids: np.ndarray, seed: int = 0) -> np.ndarray:
    """BRIO of ``ids`` (Amenta, Choi and Rote): each point joins round r with
    probability 2^-(r+1), later rounds first being the smaller; within a
    round, points follow a Hilbert curve.  One sort on (round, curve index)."""
    ids = np.asarray(ids, dtype=np.int64)
    if ids.size == 0:
        return ids
    pts = xy[ids]
    lo = pts.min(axis=0)
    span = float((pts.max(axis=0) - lo).max())
    scale = 65535.0 / span if span > 0 else 0.0
    if not np.isfinite(scale):
        scale = 0.0
    keys = _hilbert_keys(xy, ids, float(lo[0]), float(lo[1]), scale)
    # round of each point: position in a random permutation, halved per round
    pos = np.random.default_rng(seed).permutation(ids.size)
    rounds = np.floor(np.log2(np.maximum(pos, 1))).astype(np.int64)
    rounds[pos < 64] = 0  # the first few points form one round
    return ids[np.argsort((rounds << 32) | keys, kind="stable")]


# ------------------------------------------------------------------ building


@kernel
def _first_triangle(m, work, order):
    """Make the first triangle from order[0], the first point different from
    it and the first point not collinear with both, plus its three ghosts.

    Returns (its slot, position of the second point, position of the third)
    in ``order``, or (-1, -1, -1) if every point is collinear.
    """
    xy = m.xy
    a = order[0]
    jb = 1
    while jb < order.shape[0] and xy[order[jb], 0] == xy[a, 0] and xy[order[jb], 1] == xy[a, 1]:
        jb += 1
    for j in range(jb + 1, order.shape[0]):
        b = order[jb]
        c = order[j]
        work[C_ORIENT] += 1
        s = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1])
        if s != 0.0:
            if s < 0.0:
                a, b = b, a
            t = new_triangle(m, a, b, c)
            work[C_CREATED] += 1
            g_ab = new_triangle(m, b, a, GHOST)
            g_bc = new_triangle(m, c, b, GHOST)
            g_ca = new_triangle(m, a, c, GHOST)
            bond(m, 3 * t + 2, 3 * g_ab + 2)
            bond(m, 3 * t + 0, 3 * g_bc + 2)
            bond(m, 3 * t + 1, 3 * g_ca + 2)
            bond(m, 3 * g_ab + 0, 3 * g_ca + 1)
            bond(m, 3 * g_ca + 0, 3 * g_bc + 1)
            bond(m, 3 * g_bc + 0, 3 * g_ab + 1)
            return t, jb, j
    return -1, -1, -1


@kernel
def _scan_locate(m, work, px, py, state):
    """Fallback location: test every live finite triangle (never expected)."""
    xy = m.xy
    for t in range(m.size[S_NSLOT]):
        if m.stamp[t] <= 0:
            continue
        a, b, c = m.corner[3 * t], m.corner[3 * t + 1], m.corner[3 * t + 2]
        if a == GHOST or b == GHOST or c == GHOST:
            continue
        work[C_ORIENT] += 3
        s0 = orient2d(xy[b, 0], xy[b, 1], xy[c, 0], xy[c, 1], px, py)
        s1 = orient2d(xy[c, 0], xy[c, 1], xy[a, 0], xy[a, 1], px, py)
        s2 = orient2d(xy[a, 0], xy[a, 1], xy[b, 0], xy[b, 1], px, py)
        if s0 >= 0 and s1 >= 0 and s2 >= 0:
            return walk(m, work, t, px, py, state, 2)  # classifies at once
    # outside the hull: find a hull edge that sees the point
    for t in range(m.size[S_NSLOT]):
        if m.stamp[t] <= 0:
            continue
        for k in range(3):
            if m.corner[3 * t + k] == GHOST:
                e = 3 * t + k
                o = m.corner[3 * t + (k + 1) % 3]
                d = m.corner[3 * t + (k + 2) % 3]
                work[C_ORIENT] += 1
                if orient2d(xy[o, 0], xy[o, 1], xy[d, 0], xy[d, 1], px, py) > 0:
                    return LOC_OUTSIDE, e
    return LOC_FAILED, -1


@kernel_inline
def insert_point(m, work, q, hint, stack, state):
    """Insert vertex ``q`` into a Delaunay triangulation with ghosts.

    Returns ``(status, t)``: ``status`` is the location result (LOC_ON_VERTEX
    means ``q`` duplicates the origin of edge ``t`` and was not inserted) and
    ``t`` a triangle incident to ``q``, the next walk's start.
    """
    px = m.xy[q, 0]
    py = m.xy[q, 1]
    start = finite_start(m, hint)
    status, e = walk(m, work, start, px, py, state, 4 * m.stamp.shape[0] + 64)
    if status == LOC_FAILED:
        status, e = _scan_locate(m, work, px, py, state)
    if status == LOC_ON_VERTEX:
        work[C_DUPLICATE] += 1
        return status, e
    if status == LOC_ON_EDGE:
        first = split_edge(m, work, e, q) // 3
    else:  # inside a finite triangle, or inside a ghost (outside the hull)
        first = split_triangle(m, work, e // 3, q)
    n = star_edges(m, first, stack)
    return status, lawson(m, work, stack, n)


@kernel
def _insert_all(m, work, order, jb, jc, t, stack, state, dup):
    """Insert ``order[1:]`` except the first triangle's corners; a point equal
    to an inserted vertex is recorded in ``dup`` and left out."""
    for j in range(1, order.shape[0]):
        if j == jb or j == jc:
            continue
        q = order[j]
        status, t2 = insert_point(m, work, q, t, stack, state)
        if status == LOC_ON_VERTEX:
            dup[q] = m.corner[lnext(t2)]
        else:
            t = t2


@kernel
def remove_ghosts(m):
    """Delete every ghost triangle, leaving NO_EDGE across the hull.  Returns the hull size."""
    hull = 0
    for t in range(m.size[S_NSLOT]):
        if m.stamp[t] <= 0:
            continue
        for k in range(3):
            if m.corner[3 * t + k] == GHOST:
                tw = m.twin[3 * t + k]
                if tw != NO_EDGE:
                    m.twin[tw] = NO_EDGE
                    hull += 1
                kill_triangle(m, t)
                break
    return hull


def _keep_lowest_copy(m: Mesh, dup: np.ndarray) -> None:
    """Make the lowest input index of each set of equal points the one in the
    mesh (the walk keeps whichever copy came first in insertion order)."""
    copies = np.flatnonzero(dup >= 0)
    if copies.size == 0:
        return
    best = np.arange(dup.size)
    np.minimum.at(best, dup[copies], copies)
    kept = dup[copies]
    moved = kept[best[kept] != kept]
    if moved.size == 0:
        return
    label = np.arange(dup.size)
    label[moved] = best[moved]
    n = int(m.size[S_NSLOT])
    live = m.corner[: 3 * n] >= 0
    m.corner[: 3 * n][live] = label[m.corner[: 3 * n][live]]
    group = np.concatenate([copies, np.unique(moved)])
    root = np.where(dup[group] >= 0, dup[group], group)
    dup[group] = best[root]
    dup[best[root]] = -1


METHODS = ("divconq", "vertical", "incremental")


def delaunay(
    xy: np.ndarray,
    work: np.ndarray,
    *,
    method: str = "divconq",
    seed: int = 0,
    extra_vertices: int = 0,
    extra_triangles: int = 0,
) -> tuple[Mesh, np.ndarray]:
    """Delaunay triangulation of the rows of ``xy`` (finite float64 coordinates).

    Returns the mesh (ghosts removed; no triangles if the points are all
    collinear) and ``duplicate_of``: -1, or the index of the copy of that
    point which is in the mesh (the lowest index of the copies).
    ``method`` is one of ``METHODS``; ``seed`` drives the incremental
    method's insertion order.  ``extra_vertices`` and ``extra_triangles``
    reserve room for later stages.
    """
    if method == "incremental":
        return _incremental(xy, work, seed, extra_vertices, extra_triangles)
    if method not in METHODS:
        raise ValueError(f"unknown Delaunay method {method!r}")
    n = xy.shape[0]
    order = np.argsort(xy[:, 0], kind="stable")
    xs = xy[order, 0]
    if np.any(xs[1:] == xs[:-1]):  # ties in x: sort by (x, y); stable, so equal points keep index order
        order = np.lexsort((xy[:, 1], xy[:, 0]))
    dup = np.full(n, -1, dtype=np.int64)
    if n > 1:
        s = xy[order]
        new = np.empty(n, dtype=bool)
        new[0] = True
        np.any(s[1:] != s[:-1], axis=1, out=new[1:])
        if not new.all():
            keeper = order[np.maximum.accumulate(np.where(new, np.arange(n), 0))]
            dup[order[~new]] = keeper[~new]
            work[C_DUPLICATE] += int(n - new.sum())
            order = order[new]
    ids = order.astype(np.int64)
    pts = cut_order(xy, ids, method == "divconq")
    # The kernel sees the points renumbered in cut order, which keeps the
    # points of each group together in memory; ids are mapped back at the end.
    room = np.empty((n + extra_vertices, 2), dtype=np.float64)
    room[: ids.size] = pts
    del pts
    m = new_mesh(room, 2 * n + 8 + extra_triangles)
    m.size[0] = n
    triangulate_sorted(m, work, ids.size, method == "divconq")
    remove_ghosts(m)
    used = m.corner[: 3 * int(m.size[S_NSLOT])]
    live = used >= 0
    used[live] = ids[used[live]]
    room[:n] = xy
    return m, dup


def _incremental(
    xy: np.ndarray, work: np.ndarray, seed: int, extra_vertices: int, extra_triangles: int
) -> tuple[Mesh, np.ndarray]:
    """The randomized incremental method (see the module's docstring)."""
    n = xy.shape[0]
    order = insertion_order(xy, np.arange(n), seed)  # first: its temporaries die before the mesh exists
    # The kernel sees the points renumbered in insertion order, so that it
    # reads coordinates (of each new point, and mostly of its neighbours)
    # in sequence rather than at random; the ids are mapped back at the end.
    room = np.empty((n + extra_vertices, 2), dtype=np.float64)
    np.take(xy, order, axis=0, out=room[:n])
    dup = np.full(n, -1, dtype=np.int64)
    m = new_mesh(room, 2 * n + 8 + extra_triangles)
    m.size[0] = n
    in_order = np.arange(n)
    t, jb, jc = _first_triangle(m, work, in_order)
    if t >= 0:  # else all collinear (or fewer than 3 distinct points): no triangles, no error
        stack = np.empty(n + 8, dtype=np.int32)
        state = np.array([seed * 2654435761 + 1], dtype=np.int64)
        _insert_all(m, work, in_order, jb, jc, t, stack, state, dup)
        remove_ghosts(m)
        used = m.corner[: 3 * int(m.size[S_NSLOT])]
        live = used >= 0
        used[live] = order[used[live]]
        copies = np.flatnonzero(dup >= 0)
        kept = order[dup[copies]]
        dup[:] = -1
        dup[order[copies]] = kept
    room[:n] = xy
    _keep_lowest_copy(m, dup)
    return m, dup
