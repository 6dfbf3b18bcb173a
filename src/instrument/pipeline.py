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

import numpy as np

from .delaunay import delaunay
from .carve import carve
from .core.subsegments import Subsegments
from .segments import clean_segments, enclose_hull, recover_segments
from .state import MeshState
from .switches import Options


def mesh_input(inp: dict, o: Options, work: np.ndarray, seed: int = 0) -> MeshState:
    """The (constrained) Delaunay triangulation of the validated input
    ``inp`` under ``o``, carved, with the hull as segments where refinement
    needs them: everything ``triangulate`` does before refining."""
    xy = inp["vertices"]
    nseg = len(inp.get("segments", ()))
    spare = 2 * nseg + 16
    method = "incremental" if o.i else "vertical" if o.l else "divconq"  # -F: no sweepline; divide and conquer
    m, dup = delaunay(
        xy, work, method=method, seed=seed, extra_vertices=spare, extra_triangles=2 * spare,
        parents="vertex_attributes" in inp,
    )
    np.asarray(m.vmark)[: xy.shape[0]] = inp["vertex_markers"]
    ms = MeshState(mesh=m, segs=Subsegments(max(16, 2 * spare)), n_input=xy.shape[0], dup=dup, n_triangles_initial=m.nlive)
    for i in np.flatnonzero(dup >= 0):
        ms.warnings.append(f"Warning:  A duplicate vertex at ({xy[i, 0]:.12g}, {xy[i, 1]:.12g}) appeared and was ignored.")
    if o.p:
        rows = clean_segments(inp["segments"], xy, dup, ms.warnings)
        recover_segments(ms, rows, inp["segment_markers"])
        if o.c:
            enclose_hull(ms)
        carve(ms, o, inp.get("holes"), inp.get("regions"), xy)
    elif o.c or o.quality:  # refinement needs the hull as segments
        enclose_hull(ms)
    else:
        mark_hull_vertices(ms)
    return ms


def mark_hull_vertices(ms: MeshState) -> None:
    """Triangulating a point set marks every hull vertex whose marker is 0 with 1."""
    m = ms.mesh
    n = m.nslot
    alive = np.repeat(np.asarray(m.stamp)[:n] > 0, 3)
    e = np.flatnonzero(alive & (np.asarray(m.twin)[: 3 * n] == -1))
    corner = np.asarray(m.corner)
    nxt = np.where(e % 3 == 2, e - 2, e + 1)
    prv = np.where(e % 3 == 0, e + 2, e - 1)
    ends = np.concatenate([corner[nxt], corner[prv]])
    vmark = np.asarray(m.vmark)
    vmark[ends[vmark[ends] == 0]] = 1
