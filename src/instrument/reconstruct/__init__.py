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
at the end.  (Triangle averages attributes over an insertion's flips, as it
does area bounds below, so after refinement the attributes of triangles
that straddle two input triangles differ from Triangle's; the meshes do
not.)  Per-triangle area bounds (``triangle_max_area`` with a bare ``a``;
<= 0 means none) are the refiner's per-triangle bounds, carried as Triangle
carries them.  ``j`` keeps unused input vertices: Triangle jettisons only
undead ones, which reconstruction never makes.

How Triangle carries a triangle's area bound (found by experiment)
------------------------------------------------------------------
* An insertion splits the triangle the new vertex falls in (or the two on
  the edge it falls on) and the pieces copy its bound; each Lawson flip
  that follows gives both of its triangles the mean of their two bounds,
  or no bound if either has none (<= 0).  The cavity of the insertion is a
  tree rooted at the split triangle(s) and each flip crosses one of its
  edges, so a new triangle's bound is that fold along the path to its rim
  edge, in whatever order the flips run: refine/cavity.py's ``collect_cavity`` computes
  it.  Subsegment splits are insertions too.
* A rejected insertion (the new vertex encroaches a subsegment) runs its
  split and flips, then undoes them last first: an undo leaves both
  triangles' bounds as they are, so the triangles the flips touched keep
  the flips' means (-VVV's "Area constraint" lines, e.g. 58.17 and 48.07
  both 53.12 after a rejection; refine/ghosts.py's ``rejected_bounds``).
* A deletion (a free vertex in a subsegment's diametral circle) flips the
  star into shape without averaging: the triangle on the subsegment keeps
  the bound of the star triangle on it; every other new triangle, with
  apex ``w[k]`` over its base, the bound of the star triangle
  ``(v, w[k-1], w[k])`` (counter-clockwise around the deleted ``v``).
  Triangle tests the new triangles in the post-order of its polygon
  split, the triangle on the subsegment last (``delete_free_vertex``).
* Triangle tests and splits the triangles of the initial mesh from their
  orientation-0 handle, the ones an insertion makes from the handle with
  the new vertex as apex; refine.run turns the initial triangles so that
  the refiner's handle is Triangle's for both.

The experiments (the `triangle` package, 20250106):
1. Two triangles, ``T0 = (0,0) (2,0) (1,1.6)`` with attribute 10 and
   ``T1 = (2,0) (0,0) (1,-0.3)`` with 20, ``rVVa1S1``: one circumcenter,
   (1, 0.4875), whose insertion flips the shared edge.  The two triangles
   left from ``T0`` have attribute 10, the two made by the flip 15.
2. The same mesh with bounds instead, ``rVVa``: bounds (0.5, 0.35) and
   (0.5, 0.45): the flipped triangles (area 0.394) are not split next, as
   they would be with T1's 0.35 copied (their means are 0.425, 0.475);
   (0.5, 0.2): T1 (area 0.3) is split first, as its own bound says.
3. ``T1``'s third corner at (1, -1) (flipped triangles of area 0.744) and
   bounds (0.6, -0.1), (0.6, 0), (0.6, -1): after T0's split nothing more is
   split, so the flipped triangles have no bound: not the mean (0.25 would
   split them) and not the positive one (0.6 would too).
4. ``-VVVV`` prints every triangle record with its "Area constraint" after
   each split, flip and deletion.  bbox.1 ``raVVVV``: in 16 of 16 flips of
   a deletion both records keep their bounds, and the triangle without the
   deleted vertex keeps the record of the star triangle before the flipped
   edge (counter-clockwise), which gives the rule above by induction.  The
   pq30VVVV logs of A, la and face (102 deletions): where both sides of a
   base have a sub-polygon, the one from the base's first corner
   (counter-clockwise) is triangulated first (62 of 62), and the triangle
   on the subsegment is queued last, as (new apex, w0, w1) (37 of 37).
5. Result: bbox.1 with ``ra`` (its .area bounds one triangle to 0.02) makes
   21 vertices and 27 triangles, as Triangle (copying the bounds made 114
   and 204); ``rpaa.5`` 27 and 39 (was 20 and 27).
"""

from __future__ import annotations

import numpy as np

from ..core import insert
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
    return int(insert.make_delaunay(ms.mesh, np.zeros(edges, dtype=np.int64), np.zeros(edges, dtype=np.uint8)))
