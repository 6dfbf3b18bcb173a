"""Turn the engine's mesh into the `triangle` package's output dict.

Keys, shapes and dtypes follow the `triangle` package: (N, 1) int32 markers,
int32 indices, float64 coordinates, and keys for empty arrays left out.
"""

from __future__ import annotations

import numpy as np

from .jit import kernel
from .mesh import NO_EDGE, NO_SEG, Mesh


class Result(dict):
    """The output dict, plus ``work`` (counters), ``trace``, ``steps`` and
    ``warnings`` (Triangle's warning lines, which the library never prints)."""

    work: dict[str, int]
    trace: object
    steps: object
    warnings: list[str]

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.work = {}
        self.trace = None
        self.steps = None
        self.warnings = []


def _col(a, dtype=np.int32) -> np.ndarray:
    return np.ascontiguousarray(np.asarray(a, dtype=dtype).reshape(-1, 1))


def _put(out: dict, key: str, arr: np.ndarray) -> None:
    if arr is not None and arr.size > 0:
        out[key] = np.ascontiguousarray(arr)


@kernel
def interpolate_attributes(out, parent, first):
    """Fill the attribute rows ``out[first:]`` of vertices the engine added,
    each from its parents' rows: ``parent[v]`` = (p0, p1, p2, s, t) gives
    a0 + s (a1 - a0) + t (a2 - a0); p0 < 0 leaves zeros.  Vertices come in
    creation order, so parents are filled first."""
    for v in range(first, out.shape[0]):
        p0 = int(parent[v, 0])
        if p0 < 0:
            continue
        p1 = int(parent[v, 1])
        p2 = int(parent[v, 2])
        s = parent[v, 3]
        t = parent[v, 4]
        for k in range(out.shape[1]):
            a0 = out[p0, k]
            out[v, k] = a0 + s * (out[p1, k] - a0) + t * (out[p2, k] - a0)


# A triangle's edges in Triangle's listing order: (c0, c1), (c1, c2), (c2, c0).
_LISTING = np.array([2, 0, 1])


def unique_edges(m: Mesh, tris: np.ndarray, tri_index: np.ndarray, *, constrained: bool = False) -> np.ndarray:
    """Each edge once, as Triangle lists them: triangle by triangle, the edges
    (c0, c1), (c1, c2), (c2, c0) -- our edges 2, 0, 1 -- taking an edge when
    its neighbour is absent or comes later.  ``constrained``: subsegments only
    (picked before the edge arrays are built: a few of millions)."""
    if constrained:
        rows, k = np.nonzero(m.seg.reshape(-1, 3)[tris][:, _LISTING] != NO_SEG)
        e = 3 * tris[rows] + _LISTING[k]
    else:
        e = (3 * tris[:, None] + _LISTING).ravel()
    tw = m.twin[e]
    keep = (tw == NO_EDGE) | (tri_index[np.maximum(tw, 0) // 3] > tri_index[e // 3])
    return e[keep]


def edge_ends(m: Mesh, e: np.ndarray) -> np.ndarray:
    nxt = np.where(e % 3 == 2, e - 2, e + 1)
    prv = np.where(e % 3 == 0, e + 2, e - 1)
    return np.stack([m.corner[nxt], m.corner[prv]], axis=1)
