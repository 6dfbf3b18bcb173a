"""Delaunay triangulation of a point set: the pipeline's first stage.

Two methods:

* divide and conquer (``divconq``), the default, as in Triangle: with its
  tie rules the triangulation of cocircular points is the one Triangle
  makes; cuts alternate between vertical and horizontal unless
  ``vertical`` (``-l``);
* randomized incremental insertion (``incremental``, ``-i``).

Ghost triangles keep the outside of the hull symbolic while the mesh is
built; they are removed at the end, leaving ``NO_EDGE`` across the convex
hull.  Exact duplicates are never inserted: ``duplicate_of[i]`` names the
surviving copy (the lowest input index), as Triangle keeps duplicates in
the output numbering but out of the mesh.

Both kernels see the points renumbered (in cut order, or insertion order),
which keeps the points of each group together in memory; the vertex ids
are mapped back at the end.
"""

from __future__ import annotations

import numpy as np

from ..core.mesh import Mesh, relabel_corners, remove_ghosts, remove_ghosts_around_hull
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
    seed: int = 0,
    extra_vertices: int = 0,
    extra_triangles: int = 0,
    threads: int = 1,
    **tables,
) -> tuple[Mesh, np.ndarray]:
    """Delaunay triangulation of the rows of ``xy`` (finite float64 coordinates).

    Returns the mesh (ghosts removed; no triangles if the points are all
    collinear) and ``duplicate_of``: -1, or the index of the copy of that
    point which is in the mesh (the lowest index of the copies).
    ``method`` is one of ``METHODS``; ``seed`` drives the incremental
    method's insertion order.  ``extra_vertices`` and ``extra_triangles``
    reserve room for later stages; ``tables`` are ``Mesh``'s optional
    tables (``parents``, ``area_bounds``, ``attributes``, ``constraints``;
    the incremental method always has the constraint tables: its flips
    keep subsegment records).  Divide and
    conquer runs on up to ``threads`` threads on large inputs (parallel.py),
    with the same result as on one.
    """
    if method not in METHODS:
        raise ValueError(f"unknown Delaunay method {method!r}")
    if method == "incremental":
        return _incremental(xy, work, seed, extra_vertices, extra_triangles, tables)
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


def _incremental(xy, work, seed, extra_vertices, extra_triangles, tables) -> tuple[Mesh, np.ndarray]:
    """The randomized incremental method (see incremental.py; imported here,
    as only -i runs it)."""
    from . import incremental

    n = xy.shape[0]
    tables = dict(tables, constraints=True)
    order = incremental.insertion_order(xy, np.arange(n), seed)  # first: its temporaries die before the mesh exists
    m = Mesh(xy[order], 2 * n + 8 + extra_triangles, vertices=n + extra_vertices, work=work, **tables)
    dup = np.full(n, -1, dtype=np.int64)
    found = incremental.triangulate(m, seed)
    if found is not None:  # else all collinear (or fewer than 3 distinct points): no triangles, no error
        remove_ghosts(m)
        _restore_numbering(m, xy, order)
        copies = np.flatnonzero(found >= 0)
        dup[order[copies]] = order[found[copies]]
    else:
        np.asarray(m.xy)[:n] = xy
        dup[:] = _copies(xy)  # no walk found them, but -j and the warnings still need them
        work[C_DUPLICATE] += int((dup >= 0).sum())
    m.rng = 12345  # the later stages' walks start their own sequence, as before this stage had one
    _keep_lowest_copy(m, dup)
    return m, dup


def _copies(xy: np.ndarray) -> np.ndarray:
    """Per row: -1, or the lowest index of an earlier row with the same coordinates."""
    _, first, inverse = np.unique(xy, axis=0, return_index=True, return_inverse=True)
    keeper = first[inverse.reshape(-1)]
    return np.where(keeper == np.arange(len(xy)), -1, keeper).astype(np.int64)


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
    label = np.arange(dup.size, dtype=np.int64)
    label[moved] = best[moved]
    relabel_corners(m, label)
    group = np.concatenate([copies, np.unique(moved)])
    root = np.where(dup[group] >= 0, dup[group], group)
    dup[group] = best[root]
    dup[best[root]] = -1

