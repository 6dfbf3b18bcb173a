"""Segment recovery, the pipeline's second stage (``-p``, ``-c``): the input
segments become chains of constrained edges of the triangulation.

The kernels (recover.py) insert one piece at a time and stop when the mesh
is full; the driver here grows it and lets them go on, and turns a failure
into an error that names the segment.
"""

from __future__ import annotations

import numpy as np

from ..carve.infect import start_hull_edge
from ..core.insert import make_delaunay
from ..core.navigate import build_vertex_edges
from ..core.status import DONE, FAILED, NEED_BUFFER
from ..counters import C_STEINER
from ..errors import TriangleError
from ..state import MeshState
from .endpoints import BAD_FIRST, BAD_SECOND, COINCIDENT, KEPT, all_different, check_endpoints, pair_keys
from .recover import Recovery, count_inverted, insert_segments, mark_hull

TOO_CLOSE = (
    "segments cross at points too close together for double precision "
    "(nearly concurrent or overlapping segments); the constrained triangulation could not be built"
)


def clean_segments(segments: np.ndarray, xy: np.ndarray, dup: np.ndarray, warnings: list[str]) -> np.ndarray:
    """Input segments as rows (a, b, input index), with Triangle's warnings for
    invalid endpoints and coincident endpoints; endpoints that are duplicate
    vertices are mapped to the copy in the mesh."""
    seg = np.ascontiguousarray(np.asarray(segments, dtype=np.int64).reshape(-1, 2))
    rows = np.empty((seg.shape[0], 3), dtype=np.int64)
    verdict = np.empty(seg.shape[0], dtype=np.int8)
    dup = np.ascontiguousarray(dup, dtype=np.int64)
    kept = check_endpoints(seg, dup, np.ascontiguousarray(xy, dtype=np.float64), rows, verdict)
    if kept < seg.shape[0]:
        for i in np.flatnonzero(verdict != KEPT):
            warnings.append(_WARNINGS[int(verdict[i])].format(i))
    return rows[:kept]


_WARNINGS = {
    BAD_FIRST: "Warning:  Invalid first endpoint of segment {} in input.",
    BAD_SECOND: "Warning:  Invalid second endpoint of segment {} in input.",
    COINCIDENT: "Warning:  Endpoints of segment {} are coincident in input.",
}


def recover_segments(ms: MeshState, rows: np.ndarray, seg_markers: np.ndarray) -> None:
    """Insert the segments ``rows`` (from ``clean_segments``) in input order."""
    m = ms.mesh
    m.add_constraint_tables()
    if rows.shape[0] == 0 or m.nlive == 0:
        # no triangle (fewer than three vertices, or all of them exactly
        # collinear): there is no edge to make a segment of, and Triangle
        # outputs the vertices alone, without segments
        return
    rows, in_marker = merge_duplicates(rows, np.asarray(seg_markers, dtype=np.int32))
    build_vertex_edges(m)
    work = Recovery(rows, in_marker, 4 * (m.nvert + 64), plain=m.nvert)
    # every pair of segments crosses at most once
    most_vertices = m.nvert + rows.shape[0] * (rows.shape[0] + 1) // 2
    while True:
        status = insert_segments(m, ms.segs, work)
        if status == DONE:
            if work.ncopies:
                ms.copies = work.copied if ms.copies is None else np.vstack([ms.copies, work.copied])
            if ms.work[C_STEINER]:
                if count_inverted(m):
                    # rounded intersection points of nearly concurrent segments
                    # can fold the mesh; never hand back a folded mesh
                    raise TriangleError(TOO_CLOSE)
                # A crossing rounded beside another segment's endpoint can
                # leave an edge that recovery's local repairs do not reach
                # not locally Delaunay (the square with segments through
                # (0.0175, 0.1453) and the origin, under pQ:
                # regressions/crossing-beside-an-end-delaunay.json): one
                # Lawson pass over the whole mesh, which changes nothing in
                # a mesh that is constrained Delaunay already.
                edges = 3 * m.triangle_capacity
                make_delaunay(m, np.zeros(edges, dtype=np.int64), np.zeros(edges, dtype=np.uint8))
            return
        # a segment cannot cross more triangles than there are
        lost = status == NEED_BUFFER and work.buf.shape[0] > 8 * (m.triangle_capacity + 64)
        if status == FAILED or lost or m.nvert > most_vertices:
            a, b, i = work.current
            xy = m.xy
            raise TriangleError(
                f"could not recover segment {i} between ({xy[a, 0]:.17g}, {xy[a, 1]:.17g}) and "
                f"({xy[b, 0]:.17g}, {xy[b, 1]:.17g}): " + TOO_CLOSE
            )
        if status == NEED_BUFFER:
            work.grow_buffer()
            continue
        # NEED_ROOM: the mesh, the records or the stack of pieces (which
        # starts small and grows alone)
        if m.nvert >= m.vertex_capacity or m.spare() < 8 or ms.segs.count + 2 > ms.segs.capacity:
            ms.grow(vertices=m.nvert // 2 + 16, triangles=m.triangle_capacity // 2 + 64, records=ms.segs.capacity)
        work.grow_pieces()


def mark_copies(ms: MeshState) -> None:
    """Give each crossing copy (``MeshState.copies``) the marker of the
    vertex it copies, once carving has set the markers: Triangle's copy
    is in its mesh, an end of the same subsegments as the vertex, so the
    boundary marks that vertex (regressions/crossing-beside-an-end-error.json:
    both 1 after the hull is eaten)."""
    if ms.copies is None or not len(ms.copies):
        return
    vmark = np.asarray(ms.mesh.vmark)
    vmark[ms.copies[:, 0]] = vmark[ms.copies[:, 1]]


def merge_duplicates(rows: np.ndarray, markers: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Drop repeats of a segment (same two endpoints, either direction).

    The first copy is kept and takes the first non-zero marker among its
    copies, as recovering the copies one after another would do; dropping
    them up front keeps a copy from crossing its own first copy after a
    crossing point has bent that (rounded crossing points are not exactly on
    the line).
    """
    keys = np.empty(rows.shape[0], dtype=np.int64)
    if pair_keys(np.ascontiguousarray(rows), keys):
        keys.sort()  # (in place: np.sort is the same through a Python wrapper and a copy)
        if all_different(keys):
            return rows, markers  # the usual case, found without numpy's unique
    lo, hi = np.minimum(rows[:, 0], rows[:, 1]), np.maximum(rows[:, 0], rows[:, 1])
    if hi.max() < 2**31:  # one integer per endpoint pair: a 1-D unique, several times faster than axis=0
        key = lo * (int(hi.max()) + 1) + hi
        _, first, inverse = np.unique(key, return_index=True, return_inverse=True)
    else:
        key = np.stack([lo, hi], axis=1)
        _, first, inverse = np.unique(key, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.ravel()
    if first.shape[0] == rows.shape[0]:
        return rows, markers
    markers = markers.copy()
    group_marker = np.zeros(first.shape[0], dtype=np.int32)
    for i in range(rows.shape[0] - 1, -1, -1):  # the earliest non-zero wins
        mk = markers[rows[i, 2]]
        if mk != 0:
            group_marker[inverse[i]] = mk
    keep = np.sort(first)
    kept = rows[keep]
    markers[kept[:, 2]] = np.where(markers[kept[:, 2]] == 0, group_marker[inverse[keep]], markers[kept[:, 2]])
    return kept, markers


def enclose_hull(ms: MeshState) -> None:
    """-c: every hull edge becomes a subsegment with marker 1, in Triangle's
    order: around the hull from the edge its outer-space handle holds."""
    ms.mesh.add_constraint_tables()
    start = start_hull_edge(ms.mesh)
    while not mark_hull(ms.mesh, ms.segs, -1, start):
        ms.grow(records=ms.segs.capacity)
