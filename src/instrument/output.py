"""Turn the engine's mesh into the `triangle` package's output dict.

Keys, shapes and dtypes follow the `triangle` package: (N, 1) int32 markers,
int32 indices, float64 coordinates, and keys for empty arrays left out.
"""

from __future__ import annotations

import numpy as np

from .core.filled import filled
from .core.mesh import NO_EDGE, NO_SEG
from .core.gather import kept_vertices, live_slots, number_vertices, subsegment_rows, triangle_corners
from .core.navigate import edge_ends, list_edges
from .core.mesh import interpolate_attributes as interpolate


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


# ---------------------------------------------------------------- assembly


def assemble(ms, inp: dict, o) -> Result:
    """The output dict of the mesh in ``ms`` (a ``MeshState``) under the
    switches ``o``, with the input ``inp`` (for its attributes, holes and
    regions): Triangle's keys, numbering and order.  The usual outputs
    (vertices, markers, triangles, segments) are gathered by the kernels of
    ``core.gather``, one pass each; the rarer ones by numpy."""

    m = ms.mesh
    nv = m.nvert
    # (memory: at 10^6 points the output is as large as the mesh, so the
    # temporaries here are kept to what each output needs)
    tris = np.empty(m.nslot, dtype=np.int64)
    tris = tris[: live_slots(m, tris)]
    tri_index = None

    def slot_index() -> np.ndarray:
        """The output number of the triangle in each slot (-1: none)."""
        nonlocal tri_index
        if tri_index is None:
            tri_index = np.full(m.triangle_capacity, -1, dtype=np.int32)
            tri_index[tris] = np.arange(tris.size, dtype=np.int32)
        return tri_index

    if o.j:
        keep = np.zeros(nv, dtype=np.uint8)
        keep[np.asarray(m.corner).reshape(-1, 3)[tris].ravel()] = 1
        if ms.collinear:  # no triangle ever existed: only duplicates are unused
            keep[: ms.n_input] = ms.dup < 0
    else:
        keep = filled(nv, 1, np.uint8)  # (np.ones: the same through two more Python calls)
    if ms.dead is not None and ms.dead.size:
        keep[ms.dead] = 0
    new_id = np.empty(nv, dtype=np.int32)  # the identity when every vertex is kept
    nkept = number_vertices(keep, new_id)

    def ids(a):
        return np.take(new_id, a)

    def edge_listing() -> tuple[np.ndarray, np.ndarray]:
        """The edges as ``e`` lists them, and their markers."""
        e = listed_edges(m)
        seg, twin = np.asarray(m.seg), np.asarray(m.twin)
        if o.p or o.c:
            marks = np.where(seg[e] != NO_SEG, np.asarray(ms.segs.marker)[np.maximum(seg[e], 0)], 0)
        else:
            marks = twin[e] == NO_EDGE
        return ids(ends_of(m, e)), marks

    verts = np.empty((nkept, 2))
    vmarks = np.empty((nkept, 1), dtype=np.int32)
    kept_vertices(m, keep, verts, vmarks)
    vattrs = None
    if "vertex_attributes" in inp:
        attrs = np.zeros((nv, inp["vertex_attributes"].shape[1]))
        attrs[: ms.n_input] = inp["vertex_attributes"]
        interpolate(m, attrs, ms.n_input)
        vattrs = attrs[keep.view(bool)]
    triangles = np.empty((tris.size, 3), dtype=np.int32)
    triangle_corners(m, tris, new_id, triangles)
    if o.order == 2 and tris.size:  # the midpoint nodes come after every other vertex
        from .secondorder import midpoints  # (only o2 needs it: not imported at start-up)

        ends, marks = edge_listing()
        extra = midpoints(triangles, ends, verts, first=verts.shape[0], attributes=vattrs, edge_markers=marks)
        triangles = extra.triangles
        verts = np.vstack([verts, extra.vertices])
        vmarks = _col(np.concatenate([vmarks.ravel(), extra.vertex_markers]))
        if vattrs is not None:
            vattrs = np.vstack([vattrs, extra.vertex_attributes])

    out = Result()
    if not o.N:
        _put(out, "vertices", verts)
        if vattrs is not None:
            _put(out, "vertex_attributes", vattrs)
        if not o.B:
            _put(out, "vertex_markers", vmarks)
    if not o.E:
        _put(out, "triangles", triangles)
        attribute = np.asarray(m.attribute)
        if o.A and attribute.shape[0]:
            _put(out, "triangle_attributes", attribute[tris].reshape(-1, 1))
    if (o.p or o.c) and not o.P:
        constrained = listed_edges(m, constrained=True)
        ends = np.empty((constrained.size, 2), dtype=np.int32)
        marks = np.empty((constrained.size, 1), dtype=np.int32)
        subsegment_rows(m, ms.segs, constrained, new_id, ends, marks)
        _put(out, "segments", ends)
        if not o.B:
            _put(out, "segment_markers", marks)
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
        tw = np.asarray(m.twin).reshape(-1, 3)[tris]
        nb = np.where(tw == NO_EDGE, -1, slot_index()[np.maximum(tw, 0) // 3])
        _put(out, "neighbors", nb.astype(np.int32))
    return out


def listed_edges(m, *, constrained: bool = False) -> np.ndarray:
    """Each edge once, as Triangle lists them (``navigate.list_edges``):
    triangle by triangle, the edges (c0, c1), (c1, c2), (c2, c0), taking an
    edge when its neighbour is absent or comes later; ``constrained``:
    subsegments only."""
    out = np.empty(3 * m.nslot, dtype=np.int64)
    return out[: list_edges(m, constrained, out)]


def ends_of(m, e: np.ndarray) -> np.ndarray:
    """(origin, destination) of the edges ``e`` (int32, as the corners)."""
    out = np.empty((e.shape[0], 2), dtype=np.int32)
    edge_ends(m, np.ascontiguousarray(e, dtype=np.int64), out)
    return out
