"""The `triangle` package's point-set functions, built on ``instrument.triangulate``.

``delaunay``, ``convex_hull`` and ``voronoi`` take the same argument and return
the same types, shapes and dtypes as the package (version 20250106), so that
``import instrument as triangle`` keeps user code running.

Where the package has no answer we give an empty one: for input with no
triangle (all points collinear or coincident) the package raises ``KeyError``
or crashes the interpreter; here the arrays simply have zero rows.  Fewer than
three vertices raise ``ValueError('Input must have at least three vertices.')``
in both.

Triangle lists triangles in the order of its memory pool, which no other
implementation reproduces, so ``delaunay`` and ``voronoi`` agree with the
package up to the order of triangles (and so of Voronoi vertices and edges).
``convex_hull`` lists the hull in the package's order.
"""

from __future__ import annotations

import numpy as np

from .pipeline import triangulate
from .voronoi import diagram

__all__ = ["convex_hull", "delaunay", "voronoi"]


def _points(pts) -> dict:
    return {"vertices": pts}


def delaunay(pts):
    """Delaunay triangulation of the points ``pts`` (N, 2): triangles (M, 3) int32,
    counterclockwise, indices into ``pts``.  Duplicate points are left unused.

    >>> pts = [[0, 0], [0, 1], [0.5, 0.5], [1, 1], [1, 0]]
    >>> delaunay(pts).shape
    (4, 3)
    """
    result = triangulate(_points(pts))
    tris = result.get("triangles")
    if tris is None:
        return np.zeros((0, 3), dtype=np.int32)
    return np.ascontiguousarray(tris, dtype=np.int32)


def convex_hull(pts):
    """The segments (H, 2) int32 of the convex hull of ``pts``, each with the
    inside on its right, as one chain: every segment ends where the one before
    it starts, and the first ends at the leftmost (then lowest) hull vertex, as
    the package lists them.  Points on a hull edge are hull vertices.

    >>> convex_hull([[0, 0], [0, 1], [1, 1], [1, 0]]).tolist()
    [[3, 0], [2, 3], [1, 2], [0, 1]]
    """
    result = triangulate(_points(pts), "c")
    segs = result.get("segments")
    if segs is None:
        return np.zeros((0, 2), dtype=np.int32)
    segs = np.asarray(segs, dtype=np.int32)
    return np.ascontiguousarray(_hull_order(segs, result["vertices"]))


def _hull_order(segs: np.ndarray, xy: np.ndarray) -> np.ndarray:
    """Reorder hull segments into the package's chain; keep the engine's order if
    they do not form one cycle (which a convex hull always does)."""
    by_dest = {int(b): i for i, (_, b) in enumerate(segs)}
    if len(by_dest) != len(segs):
        return segs
    ends = segs[:, 1]
    first = int(ends[np.lexsort((xy[ends, 1], xy[ends, 0]))[0]])
    order = []
    v = first
    for _ in range(len(segs)):
        i = by_dest.get(v)
        if i is None:
            return segs
        order.append(i)
        v = int(segs[i, 0])
    if v != first or len(set(order)) != len(segs):
        return segs
    return segs[order]


def voronoi(pts):
    """The Voronoi diagram of ``pts``, as the package returns it:

    * ``points`` (V, 2) float64: the Voronoi vertices, one per Delaunay triangle
      (its circumcenter);
    * ``edges`` (E, 2) int32: finite edges, pairs of indices into ``points``;
    * ``ray_origin`` (R,) int32: the Voronoi vertex each infinite ray starts at;
    * ``ray_direct`` (R, 2) float64: each ray's direction, the outward normal of
      its hull edge, not normalised (its length is the hull edge's length).

    >>> points, edges, ray_origin, ray_direct = voronoi([[0, 0], [0, 1], [0.5, 0.5], [1, 1], [1, 0]])
    >>> points.shape, edges.shape, ray_origin.shape, ray_direct.shape
    ((4, 2), (4, 2), (4,), (4, 2))
    """
    vor = diagram(triangulate(_points(pts)))
    e = vor["edges"]
    finite = e[:, 1] != -1
    normals = vor.get("normals", np.zeros((len(e), 2)))
    return (
        np.ascontiguousarray(vor["vertices"], dtype=np.float64),
        np.ascontiguousarray(e[finite], dtype=np.int32),
        np.ascontiguousarray(e[~finite, 0], dtype=np.int32),
        np.ascontiguousarray(normals[~finite], dtype=np.float64),
    )
