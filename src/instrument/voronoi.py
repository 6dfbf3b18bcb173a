"""The Voronoi diagram of a triangulation, as Triangle's ``-v`` switch gives it.

The engine computes it from a finished mesh (the `triangle` package's output
dict); ``ruppert_io`` writes it to ``.v.node``/``.v.edge`` files and
``instrument.voronoi`` (the `triangle` package's function, see ``compat``)
splits it into edges and rays.

Note: ``instrument.voronoi`` is that function, not this module (the package
exports the function under the `triangle` package's name); import from here
with ``from instrument.voronoi import diagram``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

__all__ = ["diagram", "triangle_rows"]


def triangle_rows(mesh: Mapping[str, Any]) -> np.ndarray:
    """The mesh's triangles as int64 rows; a missing or empty key means none."""
    t = mesh.get("triangles")
    if t is None or np.size(t) == 0:
        return np.zeros((0, 3), dtype=np.int64)
    t = np.asarray(t, dtype=np.int64)
    return t.reshape(len(t), -1)


def diagram(mesh: Mapping[str, Any]) -> dict[str, np.ndarray]:
    """Triangle's Voronoi diagram of a mesh (reference §2.8).

    Returns ``vertices`` (M, 2), ``vertex_attributes`` (M, k) when the mesh has
    vertex attributes, ``edges`` (E, 2) int64 with -1 as the second end of a
    ray, and ``normals`` (E, 2) when there is at least one ray (zero rows for
    finite edges).

    Voronoi vertex i is the circumcenter of triangle i, computed with Triangle's
    formula (org, dest, apex = the triangle's first three columns); vertex
    attributes are interpolated there.  Edges are listed triangle by triangle,
    edges (c0, c1), (c1, c2), (c2, c0), each once (when the neighbour is absent
    or comes later); a hull edge org -> dest gives a ray from the circumcenter
    in the direction (dest.y - org.y, org.x - dest.x), which is not normalised:
    its length is the hull edge's.
    """
    xy = np.asarray(mesh["vertices"], dtype=np.float64).reshape(-1, 2)
    t = triangle_rows(mesh)[:, :3]
    m = len(t)
    torg, tdest, tapex = xy[t[:, 0]], xy[t[:, 1]], xy[t[:, 2]]
    # The same operations in the same order as Triangle, so that the numbers
    # agree to the last bit; flat triangles give inf/nan, as in Triangle.
    with np.errstate(all="ignore"):
        xdo, ydo = (tdest - torg).T
        xao, yao = (tapex - torg).T
        dodist = xdo * xdo + ydo * ydo
        aodist = xao * xao + yao * yao
        denominator = 0.5 / (xdo * yao - ydo * xao)
        dx = (yao * dodist - ydo * aodist) * denominator
        dy = (xdo * aodist - xao * dodist) * denominator
        centers = np.column_stack([torg[:, 0] + dx, torg[:, 1] + dy])
        xi = (yao * dx - xao * dy) * (2.0 * denominator)
        eta = (xdo * dy - ydo * dx) * (2.0 * denominator)
    vor: dict[str, np.ndarray] = {"vertices": centers}
    attr = mesh.get("vertex_attributes")
    if attr is not None and np.size(attr):
        a = np.asarray(attr, dtype=np.float64).reshape(len(xy), -1)
        ao, ad, aa = a[t[:, 0]], a[t[:, 1]], a[t[:, 2]]
        vor["vertex_attributes"] = ao + xi[:, None] * (ad - ao) + eta[:, None] * (aa - ao)
    # Directed edges (org, dest) in Triangle's order, and the triangle across each.
    org = t[:, [0, 1, 2]].ravel()
    dest = t[:, [1, 2, 0]].ravel()
    owner = np.repeat(np.arange(m), 3)
    n = len(xy)
    key = org.astype(np.int64) * n + dest
    rev = dest.astype(np.int64) * n + org
    order = np.argsort(key, kind="stable")
    pos = np.searchsorted(key[order], rev)
    pos = np.minimum(pos, max(len(key) - 1, 0))
    found = (key[order][pos] == rev) if len(key) else np.zeros(0, dtype=bool)
    neighbour = np.where(found, owner[order][pos] if len(key) else owner, -1)
    keep = (neighbour < 0) | (neighbour > owner)
    edges = np.column_stack([owner[keep], neighbour[keep]]).astype(np.int64)
    normals = np.zeros((len(edges), 2))
    ray = neighbour[keep] < 0
    o_xy, d_xy = xy[org[keep][ray]], xy[dest[keep][ray]]
    normals[ray, 0] = d_xy[:, 1] - o_xy[:, 1]
    normals[ray, 1] = o_xy[:, 0] - d_xy[:, 0]
    vor["edges"] = edges
    if ray.any():
        vor["normals"] = normals
    return vor
