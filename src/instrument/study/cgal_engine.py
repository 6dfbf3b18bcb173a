"""CGAL's Mesh_2 (the ``cgal`` SWIG bindings) as one of the study's engines.

The input becomes a constrained Delaunay triangulation of the same PSLG (hole
points become seeds) and the switches become CGAL's criteria: ``q<angle>`` ->
shape bound ``b = sin^2(angle)``, ``a<area>`` -> edge-length bound
``S = sqrt(4 area / sqrt 3)`` (the side of the equilateral triangle of that
area).  CGAL counts no work.
"""

from __future__ import annotations

import importlib.util
import math
import time
from collections.abc import Mapping

import numpy as np

from ..switches import parse
from .ours_engine import LONG_RUN_S


def has_cgal() -> bool:
    """Are CGAL's Python bindings (the ``cgal`` package) installed?"""
    return importlib.util.find_spec("CGAL") is not None


def cgal_criteria(opts: str) -> tuple[float, float, list[str]]:
    """CGAL's ``Delaunay_mesh_size_criteria_2(b, S)`` for Triangle's switches,
    plus notes on what cannot be carried over.

    * ``q<angle>``: CGAL's shape bound B = circumradius / shortest edge
      satisfies sin(min angle) = 1 / (2B), and ``b`` sets B = sqrt(1 / (4b)),
      so ``b = sin^2(angle)`` (0 without ``q``: no shape bound).  CGAL
      guarantees termination up to b = 0.125 (20.7 degrees) only; like
      Triangle beyond its 28.6 degrees, it usually finishes anyway.
    * ``a<area>``: CGAL bounds edge length, not area; ``S`` is the side of the
      equilateral triangle of that area, ``sqrt(4 area / sqrt 3)`` (0 without
      ``a``: no size bound).
    """
    o = parse(opts)
    notes = []
    b = math.sin(math.radians(o.min_angle)) ** 2 if o.q else 0.0
    size = math.sqrt(4.0 * o.max_area / math.sqrt(3.0)) if o.max_area > 0 else 0.0
    if o.var_area:
        notes.append("per-region/per-triangle areas ignored")
    if o.u:
        notes.append("u (triunsuitable) ignored")
    if o.D:
        notes.append("D ignored (CGAL: diametral circles, constrained Delaunay)")
    if o.S >= 0 or o.Y:
        notes.append("Steiner limits (S/Y) ignored")
    return b, size, notes


def cgal_build(M, Point_2, xy, segs, hull: bool):
    cdt = M.Mesh_2_Constrained_Delaunay_triangulation_2()
    vh = [cdt.insert(Point_2(float(x), float(y))) for x, y in xy]
    if segs is not None:
        for a, b in segs:
            a, b = int(a), int(b)
            if 0 <= a < len(vh) and 0 <= b < len(vh) and a != b:
                cdt.insert_constraint(vh[a], vh[b])
    if hull and cdt.dimension() == 2:
        inf = cdt.infinite_vertex()
        pairs = []
        for f in cdt.all_faces():
            if not cdt.is_infinite(f):
                continue
            i = f.index(inf)
            p, q = f.vertex((i + 1) % 3).point(), f.vertex((i + 2) % 3).point()
            pairs.append((Point_2(p.x(), p.y()), Point_2(q.x(), q.y())))
        for p, q in pairs:
            cdt.insert_constraint(p, q)
    return cdt


def mesh_cgal(tri: dict, opts: str, *, repeat: int = 3):
    """Mesh with CGAL, best of ``repeat`` runs: (the last run's constrained
    Delaunay triangulation, best wall time, notes).

    The time covers inserting the points and constraints from Python and the
    meshing.  Without a refinement switch the CDT is only marked (``init()``:
    the domain from the seeds), not refined."""
    from CGAL import CGAL_Mesh_2 as M
    from CGAL.CGAL_Kernel import Point_2

    o = parse(opts)
    if o.r:
        raise NotImplementedError("r (refine a given mesh) has no CGAL counterpart here")
    b, size, notes = cgal_criteria(opts)
    xy = np.asarray(tri["vertices"], dtype=np.float64).reshape(-1, 2)
    segs = tri.get("segments") if o.p else None
    segs = None if segs is None or len(segs) == 0 else np.asarray(segs).reshape(-1, 2)
    hull = not o.p or o.c  # Triangle treats the hull as segments then
    holes = tri.get("holes") if (o.p and not o.O) else None
    holes = [] if holes is None else np.asarray(holes, dtype=np.float64).reshape(-1, 2)
    if o.A:
        notes.append("regional attributes (A) ignored")
    best = math.inf
    cdt = None
    for _ in range(max(1, repeat)):
        cdt = None  # the previous run's triangulation goes before the next one is made
        t0 = time.perf_counter()
        cdt = cgal_build(M, Point_2, xy, segs, hull)
        mesher = M.Default_Delaunay_mesher_2(cdt, M.Delaunay_mesh_size_criteria_2(b, size))
        mesher.set_seeds([Point_2(float(x), float(y)) for x, y in holes], False)
        if o.quality:
            mesher.refine_mesh()
        else:
            mesher.init()  # marks the domain only
        best = min(best, time.perf_counter() - t0)
        if best > LONG_RUN_S:
            break
    return cdt, best, notes


def domain_triangles(cdt) -> int:
    """How many triangles of a Mesh_2 triangulation are in the domain (iterates in Python)."""
    if cdt.dimension() != 2:
        return 0
    return sum(1 for f in cdt.finite_faces() if f.is_in_domain())


def read_out(cdt) -> dict:
    """The mesh of a Mesh_2 triangulation as the `triangle` package's dict:
    vertices, the triangles in the domain, the constrained edges."""
    index: dict[tuple[float, float], int] = {}
    pts = []
    for v in cdt.finite_vertices():
        p = v.point()
        index[(p.x(), p.y())] = len(pts)
        pts.append((p.x(), p.y()))
    tris = []
    if cdt.dimension() == 2:
        for f in cdt.finite_faces():
            if f.is_in_domain():
                tris.append([index[(f.vertex(i).point().x(), f.vertex(i).point().y())] for i in range(3)])
    segs = []
    if cdt.dimension() == 2:
        for f, i in cdt.finite_edges():
            if cdt.is_constrained((f, i)):
                p, q = f.vertex((i + 1) % 3).point(), f.vertex((i + 2) % 3).point()
                segs.append([index[(p.x(), p.y())], index[(q.x(), q.y())]])
    return {
        "vertices": np.array(pts, dtype=np.float64).reshape(-1, 2),
        "triangles": np.array(tris, dtype=np.int32).reshape(-1, 3),
        "segments": np.array(segs, dtype=np.int32).reshape(-1, 2),
    }


def run_cgal(tri: dict, opts: str, *, repeat: int = 3):
    """Mesh with CGAL: (mesh dict with vertices/triangles/segments, best wall
    time, notes); ``mesh_cgal``, then the mesh read out (not timed)."""
    cdt, best, notes = mesh_cgal(tri, opts, repeat=repeat)
    return read_out(cdt), best, notes


#: points handed to CGAL per batch of Python floats (a whole 10^7-point
#: ``tolist()`` would hold 1.3 GB of Python objects)
POINT_BATCH = 65536


def delaunay_cgal(xy, *, repeat: int = 1):
    """CGAL's Delaunay triangulation of a point set: ``Delaunay_triangulation_2``
    with one bulk insert (which sorts the points spatially), best of
    ``repeat`` runs: (the last run's triangulation, best wall time).

    The time runs from the numpy array to the finished triangulation, so it
    includes making one ``Point_2`` per point in Python; they are made as the
    insert consumes them, a batch of coordinates at a time, so the bulk insert
    holds the only full copy of the points."""
    from CGAL import CGAL_Triangulation_2 as T2
    from CGAL.CGAL_Kernel import Point_2

    xy = np.asarray(xy, dtype=np.float64).reshape(-1, 2)

    def points():
        for start in range(0, len(xy), POINT_BATCH):
            for x, y in xy[start:start + POINT_BATCH].tolist():
                yield Point_2(x, y)

    best = math.inf
    dt = None
    for _ in range(max(1, repeat)):
        dt = None
        t0 = time.perf_counter()
        dt = T2.Delaunay_triangulation_2()
        dt.insert(points())
        best = min(best, time.perf_counter() - t0)
        if best > LONG_RUN_S:
            break
    return dt, best


def measure(data: dict, switches: str, *, strategy: str = "", seed: int = 0, repeat: int = 3,
            params: Mapping | None = None) -> dict:
    """The study's engine interface: output mesh (in the domain), best wall time, notes."""
    mesh, wall, notes = run_cgal(data, switches, repeat=repeat)
    return {"mesh": mesh, "wall_s": wall, "work": {}, "note": "; ".join(notes)}
