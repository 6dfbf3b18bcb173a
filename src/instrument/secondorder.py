"""Second-order (6-node) triangles, Triangle's ``o2``: one new node at the
midpoint of every edge.

The layout, found by experiment with the `triangle` package (``'o2'`` against
the same run without it, over its samples, random point sets, duplicates with
and without ``j``, ``p``, ``q``, ``a``, ``c``, ``Y``, ``S``, ``A`` and ``r``;
``tests/engine/test_second_order.py`` keeps checking it):

* The corners keep their numbers; the new nodes come after every other vertex
  (unused ones included), one per edge, numbered in the order Triangle lists
  edges for ``e``: triangle by triangle, edges (c0, c1), (c1, c2), (c2, c0),
  each the first time it is met.
* A row is ``c0, c1, c2, m12, m20, m01``: node 3 + k is the midpoint of the
  edge opposite corner k.
* A node's coordinates and attributes are ``0.5 * (a + b)`` of its edge's ends
  (bit for bit), and its marker is the edge's marker as ``e`` reports it: the
  subsegment's marker, 1 on a boundary without segments, else 0.
* Edges of a mesh with no triangles make no nodes; ``E`` (no triangles in the
  output) still adds the nodes to the vertices.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

__all__ = ["SecondOrder", "midpoints"]

# A triangle's edges in listing order, and the column each one's node goes to.
_EDGES = ((0, 1), (1, 2), (2, 0))
_COLUMN = (5, 3, 4)


class SecondOrder(NamedTuple):
    triangles: np.ndarray  # (M, 6) int32
    vertices: np.ndarray  # (E, 2) the new nodes
    vertex_attributes: np.ndarray | None  # (E, k)
    vertex_markers: np.ndarray | None  # (E,)


def midpoints(
    triangles: np.ndarray,
    edges: np.ndarray,
    vertices: np.ndarray,
    *,
    first: int,
    attributes: np.ndarray | None = None,
    edge_markers: np.ndarray | None = None,
) -> SecondOrder:
    """The 6-node rows of ``triangles`` (M, 3) and their new nodes.

    ``edges`` (E, 2) are the mesh's edges in Triangle's listing order (what
    ``e`` outputs); node ``first + i`` is the midpoint of ``edges[i]``.
    ``vertices``, ``attributes`` and ``edge_markers`` give the new nodes'
    coordinates, attributes and markers.
    """
    t = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    e = np.asarray(edges, dtype=np.int64).reshape(-1, 2)
    n = int(max(t.max(initial=-1), e.max(initial=-1))) + 1
    keys = np.minimum(e[:, 0], e[:, 1]) * n + np.maximum(e[:, 0], e[:, 1])
    order = np.argsort(keys, kind="stable")
    sorted_keys = keys[order]
    out = np.zeros((t.shape[0], 6), dtype=np.int64)
    out[:, :3] = t
    for (i, j), col in zip(_EDGES, _COLUMN):
        a, b = t[:, i], t[:, j]
        k = np.minimum(a, b) * n + np.maximum(a, b)
        at = np.searchsorted(sorted_keys, k)
        if t.shape[0] and (at.max() >= len(sorted_keys) or not np.array_equal(sorted_keys[at], k)):
            raise ValueError("a triangle edge is missing from the edge list")
        out[:, col] = first + order[at]
    xy = np.asarray(vertices, dtype=np.float64)
    mid = 0.5 * (xy[e[:, 0]] + xy[e[:, 1]])
    attrs = None
    if attributes is not None:
        va = np.asarray(attributes, dtype=np.float64)
        attrs = 0.5 * (va[e[:, 0]] + va[e[:, 1]])
    marks = None if edge_markers is None else np.asarray(edge_markers, dtype=np.int32).reshape(-1)
    return SecondOrder(out.astype(np.int32), mid, attrs, marks)
