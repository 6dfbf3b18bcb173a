"""``triangulate``: validate the input dict, run the pipeline, build the Result.

Pipeline: Delaunay triangulation -> (segments, holes, regions: issue 4)
-> (quality refinement: issue 5) -> output arrays.
"""

from __future__ import annotations

import numpy as np

from . import counters
from .delaunay import delaunay
from .output import Result, _col, _put, edge_ends, hull_edges, unique_edges
from .mesh import NO_EDGE, live_triangles
from .switches import Options, parse

INPUT_KEYS = frozenset(
    {
        "vertices",
        "vertex_markers",
        "vertex_attributes",
        "segments",
        "segment_markers",
        "holes",
        "regions",
        "triangles",
        "triangle_attributes",
        "triangle_max_area",
        "neighbors",
        "edges",
        "edge_markers",
    }
)


def _float2(tri: dict, key: str, cols: int | None = None) -> np.ndarray | None:
    if key not in tri or tri[key] is None:
        return None
    a = np.asarray(tri[key], dtype=np.float64)
    if a.ndim == 1:
        a = a.reshape(-1, 1) if cols is None else a.reshape(-1, cols)
    return np.ascontiguousarray(a)


def _validate(tri: dict) -> dict:
    unknown = set(tri) - INPUT_KEYS
    if unknown:
        raise KeyError(f"unknown input key(s): {', '.join(sorted(map(str, unknown)))}")
    xy = _float2(tri, "vertices", 2)
    if xy is None or xy.shape[0] < 3:
        raise ValueError("Input must have at least three vertices.")
    if xy.ndim != 2 or xy.shape[1] != 2:
        raise ValueError(f"vertices must have shape (N, 2), not {xy.shape}")
    if not np.isfinite(xy).all():
        bad = int(np.flatnonzero(~np.isfinite(xy).all(axis=1))[0])
        raise ValueError(f"vertex {bad} has a coordinate that is not finite: {tuple(xy[bad])}")
    n = xy.shape[0]
    out = {"vertices": xy}
    if tri.get("vertex_markers") is not None:
        vm = np.asarray(tri["vertex_markers"], dtype=np.int32).reshape(-1)
        if vm.shape[0] != n:
            raise ValueError(f"vertex_markers has {vm.shape[0]} entries for {n} vertices")
        out["vertex_markers"] = vm.copy()
    va = _float2(tri, "vertex_attributes")
    if va is not None and va.size:
        if va.shape[0] != n:
            raise ValueError(f"vertex_attributes has {va.shape[0]} rows for {n} vertices")
        out["vertex_attributes"] = va
    return out


def triangulate(tri: dict, opts: str = "", *, strategy: str = "triangle", seed: int = 0, trace: bool = False) -> Result:
    """Triangulate, mesh or refine ``tri`` (the `triangle` package's dict) under
    Triangle's switches ``opts`` (library rules: no dash, 0-based indices).

    Returns a ``Result`` (a dict with the `triangle` package's keys) whose
    ``work`` attribute holds the work counters.
    """
    o = parse(opts)
    inp = _validate(tri)
    if o.p or o.r or o.quality:
        raise NotImplementedError(
            "segments (p), refinement (r) and quality meshing (q, a, u, D) are not implemented yet"
        )
    work = counters.new_work()
    m, dup = delaunay(inp["vertices"], work, seed=seed)
    result = _assemble(m, inp, dup, o)
    result.work = counters.as_dict(work)
    return result


def _assemble(m, inp: dict, dup: np.ndarray, o: Options) -> Result:
    xy = inp["vertices"]
    n = xy.shape[0]
    tris = live_triangles(m)
    tri_index = np.full(m.stamp.shape[0], -1, dtype=np.int64)
    tri_index[tris] = np.arange(tris.size)
    markers = inp.get("vertex_markers", np.zeros(n, dtype=np.int32)).astype(np.int32)
    hull = hull_edges(m, tris)
    # Triangle marks hull vertices of a point set (and -c hull segments) with 1.
    on_hull = np.unique(hull.ravel())
    markers[on_hull[markers[on_hull] == 0]] = 1

    keep = dup < 0 if o.j else np.ones(n, dtype=bool)
    new_id = np.cumsum(keep) - 1 if o.j else np.arange(n)
    out = Result()
    if not o.N:
        _put(out, "vertices", xy[keep])
        if "vertex_attributes" in inp:
            _put(out, "vertex_attributes", inp["vertex_attributes"][keep])
        if not o.B:
            _put(out, "vertex_markers", _col(markers[keep]))
    corners = m.corner.reshape(-1, 3)[tris]
    if not o.E:
        _put(out, "triangles", (new_id[corners] if o.j else corners).astype(np.int32))
    if o.c and not o.P:
        # a subsegment made on edge a -> b is stored b -> a (Triangle's order)
        _put(out, "segments", new_id[hull[:, ::-1]].astype(np.int32))
        if not o.B:
            _put(out, "segment_markers", _col(np.ones(hull.shape[0])))
    if o.e:
        e = unique_edges(m, tris, tri_index)
        _put(out, "edges", new_id[edge_ends(m, e)].astype(np.int32))
        if not o.B:
            _put(out, "edge_markers", _col(m.twin[e] == NO_EDGE))
    if o.n:
        tw = m.twin.reshape(-1, 3)[tris]
        nb = np.where(tw == NO_EDGE, -1, tri_index[np.maximum(tw, 0) // 3])
        _put(out, "neighbors", nb.astype(np.int32))
    return out
