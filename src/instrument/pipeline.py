"""``triangulate``: the pipeline, stage by stage.

    validate the input (switches.py, and the checks below)
    -> Delaunay triangulation of the vertices (delaunay/)
    -> segment recovery (segments/), with -p or -c
    -> carving: holes, concavities, regions (carve/), with -p
    -> quality refinement (refine/), with q, a, u or D
    -> the output arrays (output.py)

With ``r`` the first three stages are replaced by reconstructing the given
triangles (reconstruct/).  Every stage works on one ``MeshState``
(state.py).
"""

from __future__ import annotations

import dataclasses
import os

import numpy as np

from . import counters, limits, refine
from .carve import carve
from .core.scaling import all_finite
from .core.subsegments import Subsegments
from .delaunay import delaunay
from .errors import TriangleError
from .output import Result, assemble
from .segments import clean_segments, enclose_hull, mark_copies, recover_segments
from .state import MeshState
from .refine.order import strategy_id
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
    threads: int | None = None,
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
    built-in one, as the `triangle` package does).  ``trace=True`` records
    one row per insertion attempt in ``result.trace``.

    Refinement stops with ``SizeLimitError`` (a ``TriangleError``) when the
    mesh passes ``max_vertices`` (default: derived from the input's size and
    area bound, see ``instrument.limits``) instead of running out of memory;
    a minimum angle above 34 degrees adds a warning to ``warnings``.
    ``progress(vertices, limit)`` is called now and then during refinement.
    The Delaunay triangulation of a large input runs on ``threads`` threads
    (default: the cores this process may use); the mesh and the counts are
    the same on any number.
    With ``V`` (and no ``Q``) the statistics are printed to stdout, as
    Triangle's library mode does.
    """
    o = parse(opts)
    inp = validate(tri, o)
    strategy_id(strategy)  # reject unknown names before any work
    if threads is None:
        threads = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    elif threads < 1:
        raise ValueError(f"threads must be at least 1, not {threads}")
    work = counters.new_work()
    attrs = None
    if o.r:  # the given triangles, as they are
        from .reconstruct import reconstruct  # (only -r needs it: not imported at start-up)

        ms, inp, attrs = reconstruct(tri, inp, o, work, seed)
    else:
        ms = mesh_input(inp, o, work, threads=threads, room=refine.starting_room(inp["vertices"].shape[0], o))
    refining = o.quality and ms.mesh.nlive > 0
    if refining and o.r:
        from .reconstruct import make_delaunay

        make_delaunay(ms)  # Bowyer-Watson needs a Delaunay mesh
    rows = None
    if refining:
        warning = limits.angle_warning(o.min_angle) if o.q else None
        if warning:
            ms.warnings.append(warning)
        rows = refine.run(
            ms, o, strategy=strategy, steiner=steiner, trace=trace, triunsuitable=triunsuitable,
            max_vertices=max_vertices, progress=progress,
        )
    # with r, -j leaves out only undead vertices (duplicates, eaten ones),
    # which reconstruction never makes: unused input vertices stay, as in Triangle
    result = assemble(ms, inp, dataclasses.replace(o, j=False) if o.r else o)
    if attrs is not None and not o.E and "triangles" in result:
        ancestor = np.asarray(ms.mesh.attribute)[ms.mesh.live_triangles()].astype(np.int64)
        result["triangle_attributes"] = np.ascontiguousarray(attrs[ancestor])
    if trace:
        result.trace = rows if rows is not None else np.zeros(0, dtype=refine.TRACE_DTYPE)
    result.work = counters.as_dict(work)
    result.warnings = ms.warnings
    if o.V and not o.Q:
        from . import statistics  # (only V needs it: not imported at start-up)

        statistics.emit(statistics.library_report(tri, o, result, warnings=result.warnings))
    return result


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


def validate(tri: dict, o: Options) -> dict:
    """The input arrays ``triangulate`` uses, checked and converted (vertices,
    markers, attributes; with ``p`` segments, holes and regions)."""
    unknown = set(tri) - INPUT_KEYS
    if unknown:
        raise KeyError(f"unknown input key(s): {', '.join(sorted(map(str, unknown)))}")
    xy = np.asarray(tri.get("vertices", []), dtype=np.float64)
    if xy.size == 0 or xy.reshape(-1, 2).shape[0] < 3:
        raise TriangleError("Input must have at least three vertices.")
    xy = _rows(tri, "vertices", 2, np.float64)
    if not all_finite(xy):
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


def mesh_input(inp: dict, o: Options, work: np.ndarray, threads: int = 1, room: int = 16) -> MeshState:
    """The (constrained) Delaunay triangulation of the validated input
    ``inp`` under ``o``, carved, with the hull as segments where refinement
    needs them: everything ``triangulate`` does before refining.  ``room``
    vertices (and twice as many triangles) are reserved beyond the input;
    recovery and refinement grow the mesh when they need more, and neither
    the mesh nor the counts depend on it."""
    xy = inp["vertices"]
    nseg = len(inp.get("segments", ()))
    spare = room
    method = "incremental" if o.i else "vertical" if o.l else "divconq"  # -F: no sweepline; divide and conquer
    # the constraint tables (Mesh.add_constraint_tables) from the start when
    # a later stage needs them: made with the others, they cost no arrays of
    # their own; a plain triangulation does without
    m, dup = delaunay(
        xy, work, method=method, extra_vertices=spare, extra_triangles=2 * spare,
        parents="vertex_attributes" in inp, constraints=o.p or o.c or o.quality, threads=threads,
    )
    np.asarray(m.vmark)[: xy.shape[0]] = inp["vertex_markers"]
    ms = MeshState(mesh=m, segs=Subsegments(nseg + room), n_input=xy.shape[0], dup=dup, n_triangles_initial=m.nlive)
    duplicates = np.flatnonzero(dup >= 0) if work[counters.C_DUPLICATE] else ()  # (counted as found: none, no search)
    for i in duplicates:
        ms.warnings.append(f"Warning:  A duplicate vertex at ({xy[i, 0]:.12g}, {xy[i, 1]:.12g}) appeared and was ignored.")
    if o.p:
        rows = clean_segments(inp["segments"], xy, dup, ms.warnings)
        recover_segments(ms, rows, inp["segment_markers"])
        if o.c:
            enclose_hull(ms)
        carve(ms, o, inp.get("holes"), inp.get("regions"), xy)
        mark_copies(ms)
    elif o.c or o.quality:  # refinement needs the hull as segments
        enclose_hull(ms)
    else:
        mark_hull_vertices(ms, incremental=o.i)
    return ms


def mark_hull_vertices(ms: MeshState, incremental: bool = False) -> None:
    """Triangulating a point set marks every hull vertex whose marker is 0 with 1.

    When every point is collinear there is no hull, and Triangle (observed
    on the `triangle` package) marks the vertices its empty triangulation
    passed through: after incremental insertion every vertex in the mesh;
    after divide and conquer every one but the last in (x, y) order.
    Duplicates keep their input markers either way."""
    m = ms.mesh
    if ms.collinear:
        vmark = np.asarray(m.vmark)
        kept = np.flatnonzero(ms.dup < 0)
        if not incremental and kept.size:
            xy = np.asarray(m.xy)[kept]
            kept = np.delete(kept, np.lexsort((xy[:, 1], xy[:, 0]))[-1])
        vmark[kept[vmark[kept] == 0]] = 1
        return
    n = m.nslot
    alive = np.repeat(np.asarray(m.stamp)[:n] > 0, 3)
    e = np.flatnonzero(alive & (np.asarray(m.twin)[: 3 * n] == -1))
    corner = np.asarray(m.corner)
    nxt = np.where(e % 3 == 2, e - 2, e + 1)
    prv = np.where(e % 3 == 0, e + 2, e - 1)
    ends = np.concatenate([corner[nxt], corner[prv]])
    vmark = np.asarray(m.vmark)
    vmark[ends[vmark[ends] == 0]] = 1
