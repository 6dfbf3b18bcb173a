"""Refining a mesh given as triangles (Triangle's ``-r``): the stage that
replaces Delaunay triangulation, segment recovery and carving.

The given triangulation is kept as it is: the mesh is built from the
triangles themselves, not re-triangulated, so a quad with four cocircular
corners keeps its diagonal.  Steps:

1. Check the triangles (indices in range, three distinct corners, strictly
   counter-clockwise by the exact predicate) and link neighbours by matching
   each directed edge with its reverse.  Edges are bucketed by origin with a
   counting sort, so linking is linear in the number of triangles.  An edge
   used twice in the same direction (a triangle given twice, or two triangles
   on the same side of an edge) or by more than two triangles is an error,
   and so is a fold: triangles that wind around one of their vertices more
   than once.  Overlaps between triangles that share no vertex are not
   detected (Triangle assumes a valid mesh and checks nothing).
2. The extra nodes of six-node triangles are dropped from the vertex set, as
   Triangle deletes them; the other vertices keep their order.  Vertices that
   no triangle uses stay (Triangle writes them too).
3. With ``p``: segments that are edges of the mesh become subsegments, in
   input order.  A segment that is not an edge is inserted with the segment
   recovery of cdt.py if it lies in the mesh, and ignored if it crosses the
   boundary or a hole; both get a warning (Triangle silently keeps such a
   segment out of the mesh but lists it in its output).  An invalid index
   is an error, as in Triangle.  Holes and regions are not carved or
   spread: Triangle ignores them with ``-r`` (they are echoed, as the
   `triangle` package does).
4. Every edge with one triangle becomes a subsegment with marker 1 (if it
   is not one already), and its endpoints get marker 1 if theirs is 0.
5. Before refinement only: non-constrained edges that are not locally
   Delaunay are flipped.  The refiner inserts vertices by Bowyer-Watson
   cavities, which are only star-shaped in a constrained Delaunay mesh; a
   mesh Triangle made is one already, and then nothing changes (cocircular
   quads are not flipped).

Triangle attributes travel with the refiner's per-triangle value, which new
triangles copy from the triangle they replace: it carries the index of the
input triangle each one descends from, and the attribute rows are looked up
at the end.  Per-triangle area bounds (``triangle_max_area`` with a bare
``a``; <= 0 means none) are the refiner's per-triangle bounds.  Triangle
averages both over the flips of an insertion; the cavity insertion copies
instead.  ``j`` keeps unused input vertices: Triangle jettisons only undead
ones, which reconstruction never makes.
"""

from __future__ import annotations

import numpy as np

from ..core.mesh import NO_EDGE, Mesh
from ..core.navigate import build_vertex_edges
from ..core.subsegments import Subsegments
from ..counters import C_CREATED, new_work
from ..errors import TriangleError
from ..segments import enclose_hull, recover_segments
from ..state import MeshState
from ..switches import Options
from . import link

_PROBLEMS = {
    link.REPEATED_CORNER: "triangle {0} uses the same vertex twice",
    link.COLLINEAR: "triangle {0} is degenerate: its corners are collinear",
    link.CLOCKWISE: "triangle {0} is clockwise; list the corners of every triangle counter-clockwise",
    link.SAME_SIDE: "triangles {0} and {1} overlap: they lie on the same side of a shared edge",
    link.GIVEN_TWICE: "triangle {1} repeats triangle {0}",
    link.THREE_SIDES: "the edge between vertices {1} and {2} is shared by more than two triangles (one is triangle {0})",
    link.FOLDED: "the triangles around vertex {0} overlap: they wind around it more than once",
}


def _triangles(tri: dict, n: int) -> np.ndarray:
    """The ``triangles`` key as an (M, k >= 3) int64 array with indices in range."""
    if tri.get("triangles") is None:
        raise TriangleError("refining (r) needs the mesh's 'triangles'")
    raw = np.asarray(tri["triangles"])
    if raw.size == 0:
        return np.zeros((0, 3), dtype=np.int64)
    if raw.ndim != 2 or raw.shape[1] < 3:
        raise TriangleError(f"triangles must have shape (M, 3) or (M, 6), not {raw.shape}")
    if raw.dtype.kind not in "iu" and (raw.dtype.kind != "f" or not np.array_equal(raw, np.round(raw))):
        raise TriangleError("triangles must hold integer vertex indices")
    t = raw.astype(np.int64)
    out = (t < 0) | (t >= n)
    if out.any():
        i, j = np.argwhere(out)[0]
        raise TriangleError(f"triangle {i} has an invalid vertex index {t[i, j]} (there are {n} vertices)")
    return t


def _per_triangle(tri: dict, key: str, m: int) -> np.ndarray | None:
    if tri.get(key) is None or np.size(tri[key]) == 0:
        return None
    a = np.asarray(tri[key], dtype=np.float64)
    a = a.reshape(a.shape[0], -1) if a.ndim else a.reshape(1, 1)
    if a.shape[0] != m:
        raise TriangleError(f"{key} has {a.shape[0]} rows for {m} triangles")
    return np.ascontiguousarray(a)


def _drop_extra_nodes(t: np.ndarray, inp: dict) -> tuple[np.ndarray, dict, np.ndarray]:
    """Remove the extra nodes of higher-order triangles from the vertex set
    (unless some triangle uses one as a corner).  Returns the corners, the
    input with the vertex rows compacted, and the map old -> new id (-1 for
    removed ones)."""
    n = inp["vertices"].shape[0]
    new_id = np.arange(n, dtype=np.int64)
    corners = t[:, :3]
    if t.shape[1] == 3:
        return corners, inp, new_id
    keep = np.ones(n, dtype=bool)
    keep[t[:, 3:].ravel()] = False
    keep[corners.ravel()] = True
    if keep.all():
        return corners, inp, new_id
    new_id = np.where(keep, np.cumsum(keep) - 1, -1)
    inp = dict(inp)
    for key in ("vertices", "vertex_markers", "vertex_attributes"):
        if key in inp:
            inp[key] = np.ascontiguousarray(inp[key][keep])
    return new_id[corners], inp, new_id


def _check_and_link(corners: np.ndarray, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Run ``link.link_triangles``; returns (twin, start, order) or raises TriangleError."""
    nv = xy.shape[0]
    flat = np.ascontiguousarray(corners.ravel(), dtype=np.int32)
    start = np.zeros(nv + 1, dtype=np.int64)
    order = np.zeros(flat.shape[0], dtype=np.int64)
    dst = np.zeros(flat.shape[0], dtype=np.int32)
    twin = np.full(flat.shape[0], NO_EDGE, dtype=np.int32)
    bad = np.zeros(4, dtype=np.int64)
    status = link.link_triangles(flat, np.ascontiguousarray(xy), start, np.zeros(nv, dtype=np.int64), order, dst, twin, bad)
    if status != link.LINK_OK:
        raise TriangleError("cannot refine: " + _PROBLEMS[status].format(*bad[1:].tolist()))
    return twin, start, order


def reconstruct(tri: dict, inp: dict, o: Options, work: np.ndarray, seed: int = 0) -> tuple[MeshState, dict, np.ndarray | None]:
    """Build the MeshState for ``-r`` from ``tri['triangles']`` (steps 1-4 above).

    ``inp`` is the pipeline's validated input.  Returns the state, the input
    with the vertex rows that remain, and the triangle attributes (M, k) or
    None.  With attributes, the mesh's per-triangle attribute holds for
    each triangle slot the input triangle it descends from.
    """
    t = _triangles(tri, inp["vertices"].shape[0])
    attrs = _per_triangle(tri, "triangle_attributes", t.shape[0])
    bounds = _per_triangle(tri, "triangle_max_area", t.shape[0]) if o.var_area else None
    corners, inp, new_id = _drop_extra_nodes(t, inp)
    xy_in = inp["vertices"]
    n, nt = xy_in.shape[0], corners.shape[0]
    twin, start, order = _check_and_link(corners, xy_in)

    nseg = inp["segments"].shape[0] if o.p else 0
    spare = 2 * nseg + 16
    m = Mesh(xy_in, nt + 2 * spare, vertices=n + spare, parents="vertex_attributes" in inp, work=work)
    a = m.arrays()
    a["corner"][: 3 * nt] = corners.ravel()
    a["twin"][: 3 * nt] = twin
    a["stamp"][:nt] = 1
    a["vmark"][:n] = inp["vertex_markers"]
    m.nslot = nt
    m.nlive = nt
    m.rng = seed * 2654435761 + 12345
    work[C_CREATED] += nt  # every triangle that appears in the mesh is counted
    nboundary = int(np.count_nonzero(twin == NO_EDGE))
    ms = MeshState(
        mesh=m, segs=Subsegments(nseg + nboundary + 16), n_input=n, dup=np.full(n, -1, dtype=np.int64), n_triangles_initial=nt
    )
    inserted = False
    if o.p and nseg:
        inserted = _segments(ms, inp, new_id, corners, start, order)
    enclose_hull(ms)  # every boundary edge is a subsegment
    if attrs is not None or bounds is not None:
        origin = np.full(m.nslot, -1, dtype=np.int64)
        origin[:nt] = np.arange(nt)
        if inserted and link.spread_origin(m, origin):  # triangles made by segment insertion: a neighbour's
            origin[origin < 0] = 0  # a component made entirely anew
        if bounds is not None:
            b = bounds[:, 0]
            area = np.where(b > 0, b, -1.0)
            m.add_area_bounds(np.where(origin >= 0, area[np.maximum(origin, 0)], -1.0))
        if attrs is not None:
            m.add_attributes(origin.astype(np.float64))  # copied to descendants
    return ms, inp, attrs


def _segments(ms: MeshState, inp: dict, new_id: np.ndarray, corners: np.ndarray, start, order) -> bool:
    """Attach the input segments (step 3); True if some had to be inserted."""
    m = ms.mesh
    seg = inp["segments"]
    n_old = new_id.shape[0]
    out = (seg < 0) | (seg >= n_old)
    if out.any():
        i = int(np.flatnonzero(out.any(axis=1))[0])
        raise TriangleError(f"Segment {i} has an invalid vertex index.")
    seg = new_id[seg]
    used = np.zeros(inp["vertices"].shape[0] + 1, dtype=bool)
    used[corners.ravel()] = True
    unused = ~used[seg].all(axis=1)  # new_id -1 reads the last, always False
    for i in np.flatnonzero(unused):
        ms.warnings.append(f"Warning:  Segment {i} has an endpoint that is in no triangle; it was ignored.")
    seg = np.maximum(seg, 0)
    xy = inp["vertices"]
    coincident = ~unused & (xy[seg[:, 0]] == xy[seg[:, 1]]).all(axis=1)
    for i in np.flatnonzero(coincident):
        ms.warnings.append(f"Warning:  Endpoints of segment {i} are coincident in input.")
    keep = ~(unused | coincident)
    rows = np.ascontiguousarray(np.c_[seg[keep], np.flatnonzero(keep)], dtype=np.int64)
    markers = np.ascontiguousarray(inp["segment_markers"], dtype=np.int32)
    unmatched = np.zeros(rows.shape[0], dtype=np.int64)
    k = link.attach_segments(m, ms.segs, start, order, rows, markers, unmatched)
    if k == 0:
        return False
    build_vertex_edges(m)
    counted = m.work
    m.work = new_work()  # the walks below only ask: their work is not the run's
    insert = []
    try:
        for i in unmatched[:k]:
            a, b, s = rows[i]
            if link.leaves_mesh(m, a, b):
                ms.warnings.append(f"Warning:  Segment {s} does not lie in the mesh; it was ignored.")
            else:
                ms.warnings.append(f"Warning:  Segment {s} is not an edge of the mesh; it was inserted.")
                insert.append(i)
    finally:
        m.work = counted
    if not insert:
        return False
    recover_segments(ms, np.ascontiguousarray(rows[insert]), markers)
    return True


def make_delaunay(ms: MeshState) -> int:
    """Step 5: flip the mesh to a constrained Delaunay one; returns the flips."""
    edges = 3 * ms.mesh.triangle_capacity
    return int(link.make_delaunay(ms.mesh, np.zeros(edges, dtype=np.int64), np.zeros(edges, dtype=np.uint8)))
