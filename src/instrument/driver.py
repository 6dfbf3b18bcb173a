"""``triangulate``: validate the input dict, run the pipeline, build the Result.

Pipeline: Delaunay triangulation -> segment recovery, holes, regions (``p``)
-> quality refinement (``quality``) -> output arrays.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from . import counters, limits, quality, reconstruct, secondorder, statistics
from .mesh import NO_EDGE, NO_SEG, S_NLIVE, S_NVERT, live_triangles
from .errors import TriangleError
from .output import Result, _col, _put, edge_ends, interpolate_attributes, unique_edges
from .pslg import Mesher, carve, clean_segments, enclose_hull, recover_segments, start
from .strategies import strategy_id
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
        "triangle_neighbors",  # what the package's ``load`` names a .neigh file's array; ignored, as neighbors are
    }
)


def _rows(tri: dict, key: str, cols: int, dtype) -> np.ndarray | None:
    if tri.get(key) is None:
        return None
    a = np.asarray(tri[key], dtype=dtype)
    if a.size == 0:
        return np.zeros((0, cols), dtype=dtype)
    if a.ndim != 2 or a.shape[1] != cols:
        raise TriangleError(f"{key} must have shape (N, {cols}), not {a.shape}")
    return np.ascontiguousarray(a)


def _column(tri: dict, key: str, n: int, dtype) -> np.ndarray | None:
    if tri.get(key) is None:
        return None
    a = np.asarray(tri[key], dtype=dtype).reshape(-1)
    if a.shape[0] != n:
        raise TriangleError(f"{key} has {a.shape[0]} entries for {n} rows")
    return a.copy()


def _validate(tri: dict, o: Options) -> dict:
    unknown = set(tri) - INPUT_KEYS
    if unknown:
        raise KeyError(f"unknown input key(s): {', '.join(sorted(map(str, unknown)))}")
    xy = np.asarray(tri.get("vertices", []), dtype=np.float64)
    if xy.size == 0 or xy.reshape(-1, 2).shape[0] < 3:
        raise TriangleError("Input must have at least three vertices.")
    xy = _rows(tri, "vertices", 2, np.float64)
    if not np.isfinite(xy).all():
        bad = int(np.flatnonzero(~np.isfinite(xy).all(axis=1))[0])
        raise TriangleError(f"vertex {bad} has a coordinate that is not finite: {tuple(xy[bad])}")
    n = xy.shape[0]
    out = {"vertices": xy}
    vm = _column(tri, "vertex_markers", n, np.int32)
    out["vertex_markers"] = vm if vm is not None else np.zeros(n, dtype=np.int32)
    va = tri.get("vertex_attributes")
    if va is not None and np.asarray(va).size:
        va = np.asarray(va, dtype=np.float64).reshape(n, -1)
        out["vertex_attributes"] = np.ascontiguousarray(va)
    if o.p:
        segs = _rows(tri, "segments", 2, np.int64)
        out["segments"] = segs if segs is not None else np.zeros((0, 2), dtype=np.int64)
        sm = _column(tri, "segment_markers", out["segments"].shape[0], np.int32)
        out["segment_markers"] = sm if sm is not None else np.zeros(out["segments"].shape[0], dtype=np.int32)
        for key in ("holes", "regions"):
            arr = _rows(tri, key, 2 if key == "holes" else 4, np.float64)
            if arr is not None and len(arr):
                if not np.isfinite(arr[:, :2]).all():
                    raise TriangleError(f"{key} must have finite coordinates")
                out[key] = arr
    return out


def triangulate(
    tri: dict,
    opts: str = "",
    *,
    strategy: str = "triangle",
    seed: int = 0,
    trace: bool = False,
    steiner: str = "offcenter",
    triunsuitable=None,
    max_vertices: int | None = None,
    progress=None,
) -> Result:
    """Triangulate, mesh or refine ``tri`` (the `triangle` package's dict) under
    Triangle's switches ``opts`` (library rules: no dash, 0-based indices).

    Returns a ``Result`` (a dict with the `triangle` package's keys) whose
    ``work`` attribute holds the work counters and ``warnings`` Triangle's
    warnings (duplicate vertices, invalid segments).  ``strategy`` picks the
    next bad triangle (``instrument.strategies()``); ``steiner`` is
    "offcenter" (Triangle's) or "circumcenter" (Ruppert's original points).
    ``triunsuitable(org, dest, apex, area) -> bool`` replaces Triangle's
    built-in size test for the ``u`` switch (``u`` without it uses the
    built-in one, as the `triangle` package does).

    Refinement stops with ``SizeLimitError`` (a ``TriangleError``) when the
    mesh passes ``max_vertices`` (default: derived from the input's size and
    area bound, see ``instrument.limits``) instead of running out of memory;
    a minimum angle above 34 degrees adds a warning to ``warnings``.
    ``progress(vertices, limit)`` is called now and then during refinement.
    With ``V`` (and no ``Q``) the statistics are printed to stdout, as
    Triangle's library mode does.
    """
    o = parse(opts)
    inp = _validate(tri, o)
    strategy_id(strategy)  # reject unknown names before any work
    work = counters.new_work()
    attrs = None
    if o.r:  # the given triangles, as they are
        ms, inp, attrs = reconstruct.reconstruct(tri, inp, o, work, seed)
    else:
        ms = mesh_input(inp, o, work, seed)
    refining = o.quality and int(ms.m.size[S_NLIVE]) > 0
    if refining and o.r:
        reconstruct.make_delaunay(ms)  # Bowyer-Watson needs a Delaunay mesh
    rows = None
    if refining:
        warning = limits.angle_warning(o.min_angle) if o.q else None
        if warning:
            ms.warnings.append(warning)
        rows = quality.run(
            ms,
            o,
            strategy=strategy,
            steiner=steiner,
            trace=trace,
            triunsuitable=triunsuitable,
            max_vertices=max_vertices,
            progress=progress,
        )
    # with r, -j leaves out only undead vertices (duplicates, eaten ones),
    # which reconstruction never makes: unused input vertices stay, as in Triangle
    result = _assemble(ms, inp, dataclasses.replace(o, j=False) if o.r else o)
    if attrs is not None and not o.E and "triangles" in result:
        ancestor = ms.region_attr[live_triangles(ms.m)].astype(np.int64)
        _put(result, "triangle_attributes", attrs[ancestor])
    if rows is not None:
        result.trace = rows
    result.work = counters.as_dict(work)
    result.warnings = ms.warnings
    if o.V and not o.Q:
        statistics.emit(statistics.library_report(tri, o, result, warnings=result.warnings))
    return result


def mesh_input(inp: dict, o: Options, work: np.ndarray, seed: int = 0) -> Mesher:
    """The (constrained) Delaunay triangulation of the validated input
    ``inp`` under ``o``, carved, with the hull as segments where refinement
    needs them: everything ``triangulate`` does before refining."""
    xy = inp["vertices"]
    spare = 2 * len(inp.get("segments", ())) + 16
    method = "incremental" if o.i else "vertical" if o.l else "divconq"  # -F: no sweepline; divide and conquer
    ms = start(xy, inp["vertex_markers"], work, seed, spare, method=method, parents="vertex_attributes" in inp)
    for i in np.flatnonzero(ms.dup >= 0):
        ms.warnings.append(f"Warning:  A duplicate vertex at ({xy[i, 0]:.12g}, {xy[i, 1]:.12g}) appeared and was ignored.")
    if o.p:
        rows = clean_segments(inp["segments"], xy, ms.dup, ms.warnings)
        recover_segments(ms, rows, inp["segment_markers"])
        if o.c:
            enclose_hull(ms)
        carve(ms, o, inp.get("holes"), inp.get("regions"), xy)
    elif o.c or o.quality:  # refinement needs the hull as segments
        enclose_hull(ms)
    else:
        _mark_hull_vertices(ms)
    return ms


def _mark_hull_vertices(ms: Mesher) -> None:
    """Triangulating a point set marks every hull vertex whose marker is 0 with 1."""
    m = ms.m
    n = int(m.size[1])
    alive = np.repeat(m.stamp[:n] > 0, 3)
    e = np.flatnonzero(alive & (m.twin[: 3 * n] == NO_EDGE))
    ends = edge_ends(m, e).ravel()
    ms.vmark[ends[ms.vmark[ends] == 0]] = 1


def _vertex_attributes(ms: Mesher, attrs: np.ndarray, nv: int) -> np.ndarray:
    """Input attributes, then interpolated ones for the vertices the engine added."""
    out = np.zeros((nv, attrs.shape[1]))
    out[: ms.n_input] = attrs
    interpolate_attributes(out, ms.parent, ms.n_input)
    return out


def _assemble(ms: Mesher, inp: dict, o: Options) -> Result:
    m = ms.m
    nv = int(m.size[S_NVERT])
    tris = live_triangles(m)
    tri_index = np.full(m.stamp.shape[0], -1, dtype=np.int32)
    tri_index[tris] = np.arange(tris.size, dtype=np.int32)
    corners = m.corner.reshape(-1, 3)[tris]

    if o.j:
        keep = np.zeros(nv, dtype=bool)
        keep[corners.ravel()] = True
        if ms.collinear:  # no triangle ever existed: only duplicates are unused
            keep[: ms.n_input] = ms.dup < 0
    else:
        keep = np.ones(nv, dtype=bool)
    if ms.dead is not None and ms.dead.size:
        keep[ms.dead] = False
    renumber = o.j or not keep.all()
    new_id = (np.cumsum(keep) - 1).astype(np.int32)

    def ids(a):
        return np.take(new_id, a) if renumber else a.astype(np.int32, copy=False)

    def edge_listing() -> tuple[np.ndarray, np.ndarray]:
        """The edges as ``e`` lists them, and their markers."""
        e = unique_edges(m, tris, tri_index)
        if o.p or o.c:
            marks = np.where(m.seg[e] != NO_SEG, ms.segs.marker[np.maximum(m.seg[e], 0)], 0)
        else:
            marks = m.twin[e] == NO_EDGE
        return ids(edge_ends(m, e)), marks

    verts = m.xy[:nv][keep]
    vattrs = _vertex_attributes(ms, inp["vertex_attributes"], nv)[keep] if "vertex_attributes" in inp else None
    vmarks = ms.vmark[:nv][keep]
    triangles = ids(corners)
    if o.order == 2 and tris.size:  # the midpoint nodes come after every other vertex
        ends, marks = edge_listing()
        extra = secondorder.midpoints(
            triangles, ends, verts, first=verts.shape[0], attributes=vattrs, edge_markers=marks
        )
        triangles = extra.triangles
        verts = np.vstack([verts, extra.vertices])
        vmarks = np.concatenate([vmarks, extra.vertex_markers])
        if vattrs is not None:
            vattrs = np.vstack([vattrs, extra.vertex_attributes])

    out = Result()
    if not o.N:
        _put(out, "vertices", verts)
        if vattrs is not None:
            _put(out, "vertex_attributes", vattrs)
        if not o.B:
            _put(out, "vertex_markers", _col(vmarks))
    if not o.E:
        _put(out, "triangles", triangles)
        if o.A and ms.region_attr is not None:
            _put(out, "triangle_attributes", ms.region_attr[tris].reshape(-1, 1))
    constrained = None
    if (o.p or o.c) and not o.P:
        constrained = unique_edges(m, tris, tri_index, constrained=True)
        # a subsegment made on triangle edge a -> b is listed b -> a (Triangle's order)
        _put(out, "segments", ids(edge_ends(m, constrained)[:, ::-1]))
        if not o.B:
            _put(out, "segment_markers", _col(ms.segs.marker[m.seg[constrained]]))
        if o.p:
            for key in ("holes", "regions"):
                if key in inp:
                    _put(out, key, inp[key])
    if o.e:
        ends, marks = edge_listing()
        _put(out, "edges", ends)
        if not o.B:
            _put(out, "edge_markers", _col(marks))
    if o.n:
        tw = m.twin.reshape(-1, 3)[tris]
        nb = np.where(tw == NO_EDGE, -1, tri_index[np.maximum(tw, 0) // 3])
        _put(out, "neighbors", nb.astype(np.int32))
    return out
