"""Delaunay triangulation of a point set: the pipeline's first stage.

Two methods:

* divide and conquer (``divconq``), the default, as in Triangle: with its
  tie rules the triangulation of cocircular points is the one Triangle
  makes; cuts alternate between vertical and horizontal unless
  ``vertical`` (``-l``);
* incremental insertion (``incremental``, ``-i``), as Triangle's
  incremental method inserts: the same triangles in the same records.

Divide and conquer keeps the outside of the hull symbolic with ghost
triangles while the mesh is built, the incremental method with a bounding
triangle (as Triangle); either is removed at the end, leaving ``NO_EDGE``
across the convex hull.  Exact duplicates are never inserted:
``duplicate_of[i]`` names the surviving copy (the lowest input index), as
Triangle keeps duplicates in the output numbering but out of the mesh.

Divide and conquer sees the points renumbered (in cut order), which keeps
the points of each group together in memory; the vertex ids are mapped
back at the end.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.mesh import Mesh, relabel_corners, remove_ghosts_around_hull
from ..core.filled import filled
from ..counters import C_DUPLICATE
from . import divconq, parallel
from .distinct import has_x_ties, mark_duplicates

METHODS = ("divconq", "vertical", "incremental")
SMALL_SORT = 1024  # points: below this, _lexicographic_order sorts in one call


def delaunay(
    xy: np.ndarray,
    work: np.ndarray,
    *,
    method: str = "divconq",
    extra_vertices: int = 0,
    extra_triangles: int = 0,
    threads: int = 1,
    **tables,
) -> tuple[Mesh, np.ndarray]:
    """Delaunay triangulation of the rows of ``xy`` (finite float64 coordinates).

    Returns the mesh (ghosts removed; no triangles if the points are all
    collinear) and ``duplicate_of``: -1, or the index of the copy of that
    point which is in the mesh (the lowest index of the copies).  The
    mesh's ``outer_space_edge`` is the hull edge Triangle's outer-space
    handle holds afterwards, where its hull walks and its location of hole
    and region points start (divide and conquer: the edge leaving the
    least (x, y) vertex; incremental insertion: the first hull edge the
    removal of the bounding triangle met; NO_EDGE without a hull).
    ``method`` is one of ``METHODS`` (neither is randomized, so there is
    no seed: Triangle's incremental method inserts in input order).
    ``extra_vertices`` and ``extra_triangles`` reserve room for later
    stages; ``tables`` are ``Mesh``'s optional tables (``parents``,
    ``area_bounds``, ``attributes``, ``constraints``).  Divide and conquer
    runs on up to ``threads`` threads on large inputs (parallel.py), with
    the same result as on one.
    """
    if method not in METHODS:
        raise ValueError(f"unknown Delaunay method {method!r}")
    if method == "incremental":
        return _incremental(xy, work, extra_vertices, extra_triangles, tables)
    n = xy.shape[0]
    xy = np.ascontiguousarray(xy, dtype=np.float64)
    order = _lexicographic_order(xy).astype(np.int64, copy=False)
    dup = filled(n, -1, np.int64)
    copies = mark_duplicates(xy, order, dup)  # stable order: the first copy of each point is kept
    if copies:
        work[C_DUPLICATE] += copies
        order = order[dup[order] < 0]
    ids = order  # cut_order reorders it in place
    s = xy[ids]  # the points in order: the cuts start from them
    alternate = method == "divconq"
    # (a small input never splits: no plan to make)
    top = parallel.plan(ids.size, alternate, threads) if threads > 1 and ids.size >= 2 * parallel.MIN_LEAF else None
    if top is None or top.halves is None:
        pts = divconq.cut_order(xy, ids, alternate, s)
        del s
        m = Mesh(pts, 2 * n + 8 + extra_triangles, vertices=n + extra_vertices, work=work, **tables)
        del pts
        divconq.triangulate_sorted(m, ids.size, alternate)
    else:
        with parallel.workers(top) as pool:
            pts = parallel.cut_order(xy, ids, alternate, top, pool, s)
            del s
            m = Mesh(pts, 2 * n + 8 + extra_triangles, vertices=n + extra_vertices, work=work, **tables)
            del pts
            parallel.triangulate(m, top, alternate, pool)
    remove_ghosts_around_hull(m)
    _restore_numbering(m, xy, ids)
    return m, dup


def _lexicographic_order(xy: np.ndarray) -> np.ndarray:
    """The rows of ``xy`` in (x, y) order, equal rows in index order: the
    stable lexicographic order, by whichever numpy sort is fastest here.

    numpy orders complex numbers by (real, imaginary) part, and its stable
    sort of them is a timsort, which follows runs: on the vertices of
    polygons, whose x goes up and down a few times along each loop, it
    takes 1 ms at 10^5 points, but 13 on random points.  There, without
    ties in x, the order is unique, and the unstable (vectorised) sort of x
    alone gives it in 3 ms; ties in x need (x, y) after all.  One pass
    counting where x turns tells the two kinds of input apart.  A small
    input (up to ``SMALL_SORT`` points) takes numpy's stable lexsort at once:
    one call instead of the five above (19 us against 4.5 at 141 points)."""
    n = xy.shape[0]
    if n <= SMALL_SORT:
        return np.lexsort((xy[:, 1], xy[:, 0]))
    x = xy[:, 0]
    if n > 2:
        d = np.diff(x)
        runs = np.count_nonzero((d[1:] > 0) != (d[:-1] > 0))
    if n <= 2 or runs > n >> 6:
        order = np.argsort(x).astype(np.int64, copy=False)
        if not has_x_ties(np.ascontiguousarray(xy, dtype=np.float64), order):
            return order
    pairs = np.ascontiguousarray(xy, dtype=np.float64).view(np.complex128).reshape(-1)
    return np.argsort(pairs, kind="stable")


def _restore_numbering(m: Mesh, xy: np.ndarray, ids: np.ndarray) -> None:
    """Corner ``i`` of the kernel's numbering is input vertex ``ids[i]``; put
    the input's own numbering and coordinates back."""
    n = xy.shape[0]
    relabel_corners(m, ids)
    np.asarray(m.xy)[:n] = xy
    m.nvert = n


def _incremental(xy, work, extra_vertices, extra_triangles, tables) -> tuple[Mesh, np.ndarray]:
    """Triangle's incremental method (see incremental.py; imported here, as
    only -i runs it).  The points are inserted in input order, so the copy
    of a duplicated point that stays is the first, the lowest index."""
    from . import incremental

    n = xy.shape[0]
    xy = np.ascontiguousarray(xy, dtype=np.float64)
    scale = _working_scale(xy)
    if scale is None:
        return delaunay(xy, work, method="divconq", extra_vertices=extra_vertices,
                        extra_triangles=extra_triangles, **tables)  # fmt: skip
    pts = xy * scale if scale != 1.0 else xy
    m = Mesh(pts, 2 * n + 8 + extra_triangles, vertices=n + 3 + extra_vertices, work=work, **tables)
    dup = np.full(n, -1, dtype=np.int64)
    if n:
        dup = incremental.triangulate(m, incremental.box_corners(pts))
    if scale != 1.0:
        np.asarray(m.xy)[:n] = xy
    m.rng = 12345  # the later stages' walks start their own sequence
    return m, dup


#: Beyond 2^+-RANGE (coordinates' largest magnitude) the incremental method
#: works on scaled coordinates.
RANGE = 480


def _working_scale(xy: np.ndarray) -> float | None:
    """The power of two the incremental method multiplies the points by: 1
    while the largest magnitude M is within 2^+-RANGE, as Triangle (whose
    squared distances, with the bounding triangle 100 M wide, stay finite
    and normal there), else the one that brings M into [0.5, 1), so that
    the method neither overflows nor walks from the box for every point
    (all distances infinite or zero): the steps Triangle would take on the
    scaled points (subnormal ones are scaled up by 2^1000 at most).  None
    if that scaling is not exact (subnormal coordinates beside huge ones):
    divide and conquer then."""
    if xy.size == 0:
        return 1.0
    big = float(np.abs(xy).max())
    e = math.frexp(big)[1]
    if big == 0.0 or -RANGE <= e <= RANGE:
        return 1.0
    f = math.ldexp(1.0, min(-e, 1000))
    return f if np.array_equal((xy * f) / f, xy) else None
