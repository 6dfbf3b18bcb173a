"""Triangle's console statistics, computed from an output mesh dict with numpy.

The command line (``ruppert_io.cli``, through ``ruppert_io.stats``) prints
them after writing its files; ``instrument.triangulate`` prints them for the
``V`` switch (``library_report`` and ``emit``), since the engine may not
import ``ruppert_io``.

``statistics_block`` is the block every run prints (reference §3.4),
``quality_statistics`` / ``format_quality`` the ``-V`` quality statistics (§3.5),
``format_algorithmic`` Triangle's algorithmic statistics (§3.7) from our work
counters, and ``format_work`` our addition: every work counter the engine keeps.

The quality numbers follow Triangle's arithmetic step by step (same corner order,
same operations, same bin rules, same sentinels), so that the printed text matches
Triangle's for the same mesh.  The one difference: Triangle computes twice the
area with its adaptive exact ``orient2d``; we use the floating-point determinant,
which is the same number except for nearly degenerate triangles.

Corner order: a row ``(a, b, c)`` of ``triangles`` is Triangle's (org, dest, apex)
of orientation 0, which is the order Triangle writes to the .ele file.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from .voronoi import triangle_rows

__all__ = [
    "emit",
    "library_report",
    "phase_lines",
    "triangle_rows",
    "MeshCounts",
    "QualityStats",
    "mesh_counts",
    "statistics_block",
    "quality_statistics",
    "format_quality",
    "format_algorithmic",
    "format_work",
    "WORK_LABELS",
]

#: Aspect-ratio bin limits of Triangle's histogram (longest edge / shortest altitude).
RATIO_TABLE = (1.5, 2.0, 2.5, 3.0, 4.0, 6.0, 10.0, 15.0, 25.0, 50.0,
               100.0, 300.0, 1000.0, 10000.0, 100000.0)

#: cos^2 of 10, 20, ..., 80 degrees, computed as Triangle does.
COS_SQUARE_TABLE = tuple(math.cos(math.pi / 18.0 * (i + 1)) ** 2 for i in range(8))

#: Readable labels of the work counters; the first two are printed first.
WORK_LABELS = {
    "triangles_created": "Triangles created",
    "incircle_tests": "Incircle tests",
    "triangles_deleted": "Triangles deleted",
    "orient_tests": "Orientation tests",
    "circumcenters": "Circumcenter computations",
    "flips": "Edge flips",
    "walk_steps": "Point-location walk steps",
    "segment_splits": "Segment splits",
    "steiner_points": "Steiner points inserted",
    "rejected_vertices": "Rejected vertices",
    "deleted_vertices": "Deleted vertices",
    "queue_pops": "Bad-triangle queue pops",
    "stale_pops": "Stale queue pops",
    "duplicate_vertices": "Duplicate vertices",
    "undone_triangles": "Undone triangles",
}


# --------------------------------------------------------------------------
# The statistics block (§3.4)
# --------------------------------------------------------------------------


@dataclass
class MeshCounts:
    """The "Mesh ..." numbers of Triangle's statistics block."""

    vertices: int
    triangles: int
    edges: int
    hull_edges: int
    subsegments: int


def _array(mesh: Mapping[str, Any], key: str, cols: int, dtype) -> np.ndarray:
    value = mesh.get(key)
    if value is None:
        return np.zeros((0, cols), dtype=dtype)
    return np.asarray(value, dtype=dtype).reshape(-1, cols) if np.size(value) else \
        np.zeros((0, cols), dtype=dtype)




def _distinct_count(values: np.ndarray) -> int:
    """How many different values ``values`` holds, by sorting them: numpy's
    ``unique`` without a ``return_*`` flag asks ``np.ma.is_masked`` and so
    imports numpy.ma (numpy 2.4), which was a tenth of the ``ruppert``
    command's time on a small input."""
    s = np.sort(np.asarray(values).ravel())
    return int(s.size and 1 + np.count_nonzero(s[1:] != s[:-1]))


def _edge_keys(corners: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Unique undirected edges of triangles (M, 3) as keys, and their multiplicities."""
    if not len(corners):
        return np.zeros(0, dtype=np.int64), np.zeros(0, dtype=np.int64)
    a = corners[:, [1, 2, 0]].ravel()
    b = corners[:, [2, 0, 1]].ravel()
    lo, hi = np.minimum(a, b), np.maximum(a, b)
    n = int(max(hi.max(), 0)) + 1
    return np.unique(lo * n + hi, return_counts=True)


def mesh_counts(mesh: Mapping[str, Any], *, refine: bool = False) -> MeshCounts:
    """Mesh vertices, triangles, edges, hull edges and subsegments of an output mesh.

    Mesh vertices are those the triangles use (Triangle's live vertices minus the
    "undead" ones: duplicates and vertices eaten by holes); with no triangles, the
    distinct vertex positions.  Subsegments are the output ``segments``; without
    them, a refined mesh (``refine``) has one subsegment per hull edge, as Triangle's
    reconstruction makes.
    """
    tris = triangle_rows(mesh)
    corners = tris[:, :3]
    _, mult = _edge_keys(corners)
    hull = int(np.count_nonzero(mult == 1))
    if len(tris):
        nverts = _distinct_count(tris)
    else:
        xy = _array(mesh, "vertices", 2, np.float64)
        nverts = int(np.unique(xy, axis=0).shape[0]) if len(xy) else 0
    segs = mesh.get("segments")
    if segs is not None:
        nsub = int(np.asarray(segs).reshape(-1, 2).shape[0]) if np.size(segs) else 0
    else:
        nsub = hull if refine else 0
    return MeshCounts(nverts, len(tris), int(mult.size), hull, nsub)


def statistics_block(
    counts: MeshCounts,
    *,
    input_vertices: int,
    input_triangles: int = 0,
    input_segments: int = 0,
    input_holes: int = 0,
    poly: bool = False,
    refine: bool = False,
) -> str:
    """Triangle's statistics block, from "\\nStatistics:" to its closing blank line."""
    lines = ["", "Statistics:", "", f"  Input vertices: {input_vertices}"]
    if refine:
        lines.append(f"  Input triangles: {input_triangles}")
    if poly:
        lines.append(f"  Input segments: {input_segments}")
        if not refine:
            lines.append(f"  Input holes: {input_holes}")
    lines += [
        "",
        f"  Mesh vertices: {counts.vertices}",
        f"  Mesh triangles: {counts.triangles}",
        f"  Mesh edges: {counts.edges}",
        f"  Mesh exterior boundary edges: {counts.hull_edges}",
    ]
    if poly or refine:
        lines += [
            f"  Mesh interior boundary edges: {counts.subsegments - counts.hull_edges}",
            f"  Mesh subsegments (constrained edges): {counts.subsegments}",
        ]
    lines.append("")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------
# Quality statistics (§3.5)
# --------------------------------------------------------------------------


@dataclass
class QualityStats:
    """Triangle's ``-V`` quality statistics.  Angles are in degrees."""

    smallest_area: float
    largest_area: float
    shortest_edge: float
    longest_edge: float
    shortest_altitude: float
    largest_aspect_ratio: float
    aspect_histogram: list[int]  # 16 bins, see RATIO_TABLE
    smallest_angle: float
    largest_angle: float
    angle_histogram: list[int]  # 18 bins of 10 degrees, [lo, hi)


def quality_statistics(mesh: Mapping[str, Any]) -> QualityStats:
    """Triangle's quality statistics of ``mesh`` (its first three triangle columns)."""
    xy = _array(mesh, "vertices", 2, np.float64)
    corners = triangle_rows(mesh)[:, :3]
    if len(xy):
        span = (xy[:, 0].max() - xy[:, 0].min()) + (xy[:, 1].max() - xy[:, 1].min())
        sentinel = float(span * span)
    else:
        sentinel = 0.0
    with np.errstate(all="ignore"):
        p = xy[corners]  # (M, 3, 2): p[:, i] is org, dest, apex for i = 0, 1, 2
        plus1, minus1 = [1, 2, 0], [2, 0, 1]
        d = p[:, plus1] - p[:, minus1]  # d[:, i] = p[i+1] - p[i-1]
        dx, dy = d[..., 0], d[..., 1]
        length2 = dx * dx + dy * dy  # (M, 3)
        longest2 = np.max(length2, axis=1, initial=0.0)
        # orient2d(p0, p1, p2) as Triangle writes it: twice the signed area.
        area2 = (p[:, 0, 0] - p[:, 2, 0]) * (p[:, 1, 1] - p[:, 2, 1]) - (
            p[:, 0, 1] - p[:, 2, 1]
        ) * (p[:, 1, 0] - p[:, 2, 0])
        altitude2 = area2 * area2 / longest2
        aspect2 = longest2 / altitude2

        ratio2 = np.array(RATIO_TABLE) ** 2
        aspect_bin = np.count_nonzero(aspect2[:, None] > ratio2[None, :], axis=1)
        aspect_hist = np.bincount(aspect_bin, minlength=16)[:16]

        dot = dx[:, plus1] * dx[:, minus1] + dy[:, plus1] * dy[:, minus1]  # (M, 3)
        cos2 = dot * dot / (length2[:, plus1] * length2[:, minus1])
        table = np.array(COS_SQUARE_TABLE)
        tendegree = 8 - np.count_nonzero(cos2[..., None] > table, axis=-1)
        acute = dot <= 0.0
        angle_bin = np.where(acute, tendegree, 17 - tendegree)
        angle_hist = np.bincount(angle_bin.ravel(), minlength=18)[:18]

    def smallest(values: np.ndarray, start: float) -> float:
        values = values[values < start]  # NaN compares false, as in C
        return float(values.min()) if values.size else start

    def largest(values: np.ndarray, start: float) -> float:
        values = values[values > start]
        return float(values.max()) if values.size else start

    acute_cos2 = cos2[acute]
    obtuse_cos2 = cos2[~acute]
    smallest_cos2 = largest(acute_cos2, 0.0)
    if smallest_cos2 >= 1.0:
        smallest_angle = 0.0
    else:
        smallest_angle = math.degrees(math.acos(math.sqrt(smallest_cos2)))
    if obtuse_cos2.size:
        # Triangle's first obtuse corner sets the value unconditionally.
        first = float(obtuse_cos2[0])
        big = first if math.isnan(first) else largest(obtuse_cos2, first)
        largest_angle = 180.0 if big >= 1.0 else 180.0 - math.degrees(math.acos(math.sqrt(big)))
    else:
        big = smallest(acute_cos2, 2.0)
        largest_angle = 180.0 if big >= 1.0 else math.degrees(math.acos(math.sqrt(big)))

    return QualityStats(
        smallest_area=0.5 * smallest(area2, sentinel),
        largest_area=0.5 * largest(area2, 0.0),
        shortest_edge=math.sqrt(smallest(length2.ravel(), sentinel)),
        longest_edge=math.sqrt(largest(length2.ravel(), 0.0)),
        shortest_altitude=math.sqrt(smallest(altitude2, sentinel)),
        largest_aspect_ratio=math.sqrt(largest(aspect2, 0.0)),
        aspect_histogram=[int(x) for x in aspect_hist],
        smallest_angle=smallest_angle,
        largest_angle=largest_angle,
        angle_histogram=[int(x) for x in angle_hist],
    )


def format_quality(q: QualityStats) -> str:
    """The "Mesh quality statistics:" section, with Triangle's printf formats."""
    r, a = RATIO_TABLE, q.aspect_histogram
    lines = [
        "Mesh quality statistics:",
        "",
        "  Smallest area: %16.5g   |  Largest area: %16.5g" % (q.smallest_area, q.largest_area),
        "  Shortest edge: %16.5g   |  Longest edge: %16.5g" % (q.shortest_edge, q.longest_edge),
        "  Shortest altitude: %12.5g   |  Largest aspect ratio: %8.5g"
        % (q.shortest_altitude, q.largest_aspect_ratio),
        "",
        "  Triangle aspect ratio histogram:",
        "  1.1547 - %-6.6g    :  %8d    | %6.6g - %-6.6g     :  %8d"
        % (r[0], a[0], r[7], r[8], a[8]),
    ]
    for i in range(1, 7):
        lines.append(
            "  %6.6g - %-6.6g    :  %8d    | %6.6g - %-6.6g     :  %8d"
            % (r[i - 1], r[i], a[i], r[i + 7], r[i + 8], a[i + 8])
        )
    lines += [
        "  %6.6g - %-6.6g    :  %8d    | %6.6g -            :  %8d"
        % (r[6], r[7], a[7], r[14], a[15]),
        "  (Aspect ratio is longest edge divided by shortest altitude)",
        "",
        "  Smallest angle: %15.5g   |  Largest angle: %15.5g" % (q.smallest_angle, q.largest_angle),
        "",
        "  Angle histogram:",
    ]
    h = q.angle_histogram
    for i in range(9):
        lines.append(
            "    %3d - %3d degrees:  %8d    |    %3d - %3d degrees:  %8d"
            % (10 * i, 10 * i + 10, h[i], 10 * i + 90, 10 * i + 100, h[i + 9])
        )
    lines.append("")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------
# Algorithmic statistics (§3.7) and the work counters
# --------------------------------------------------------------------------


def format_algorithmic(work: Mapping[str, int], ntriangles: int, *, voronoi: bool = False) -> str:
    """Triangle's "Algorithmic statistics:" section from our counters.

    Triangle's printed orientation count includes one test per output triangle,
    made by the quality statistics before printing; ``quality_statistics`` makes
    the same computation, so ``ntriangles`` is added to the engine's count.  With
    ``voronoi`` (-v), Triangle computes one more circumcenter per triangle for the
    Voronoi diagram, as the command line does; those are added too.
    """
    lines = ["Algorithmic statistics:", ""]
    lines.append(f"  Number of incircle tests: {int(work.get('incircle_tests', 0))}")
    lines.append(
        f"  Number of 2D orientation tests: {int(work.get('orient_tests', 0)) + ntriangles}"
    )
    circumcenters = int(work.get("circumcenters", 0)) + (ntriangles if voronoi else 0)
    if circumcenters > 0:
        lines.append(f"  Number of triangle circumcenter computations: {circumcenters}")
    lines.append("")
    return "\n".join(lines) + "\n"


def _label(name: str) -> str:
    return WORK_LABELS.get(name) or name.replace("_", " ").capitalize()


def format_work(work: Mapping[str, int]) -> str:
    """"Work statistics:": every counter, triangles created and incircle tests first."""
    first = [k for k in ("triangles_created", "incircle_tests") if k in work]
    names = first + [k for k in work if k not in first]
    lines = ["Work statistics:", ""]
    lines += [f"  {_label(k)}: {int(work[k])}" for k in names]
    lines.append("")
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------
# What a run prints: phase lines, and the library-mode report for V
# --------------------------------------------------------------------------


def phase_lines(o, ntriangles: int) -> list[str]:
    """Triangle's phase lines (reference §3.1) for switches ``o``, without its
    timing lines; ``ntriangles`` is the size of the mesh (no refinement line
    when it is empty)."""
    lines = []
    if o.r:
        lines.append("Reconstructing mesh.")
    else:
        # the method that ran: -F has no sweepline here and runs divide and conquer
        method = "incremental" if o.i else "divide-and-conquer"
        lines.append(f"Constructing Delaunay triangulation by {method} method.")
    if o.uses_segments and not o.r:
        lines.append("Recovering segments in Delaunay triangulation.")
    if o.p and not o.r and not (o.O and o.c):
        lines.append("Removing unwanted triangles.")
    if o.quality and ntriangles > 0:
        lines.append("Adding Steiner points to enforce quality.")
    if o.order == 2:
        lines.append("Adding vertices for second-order triangles.")
    return lines


#: Library mode's "Writing ..." lines (reference §1.5), by what asks for them.
_WRITING = (
    ("vertices", "Writing vertices."),
    ("triangles", "Writing triangles."),
    ("segments", "Writing segments."),
    ("edges", "Writing edges."),
    ("voronoi", "Writing Voronoi vertices."),
    ("voronoi", "Writing Voronoi edges."),
    ("neighbors", "Writing neighbors."),
)


def _rows(tri: Mapping[str, Any], key: str) -> int:
    value = tri.get(key)
    if value is None or np.size(value) == 0:
        return 0
    return int(np.shape(value)[0])


def library_report(tri: Mapping[str, Any], o, result, *, warnings=()) -> str:
    """What Triangle's library mode prints for ``V`` without ``Q``: the phase
    lines (and ``warnings``), the "Writing ..." lines, the statistics block,
    the quality and algorithmic statistics, then ruppert's work counters.

    (The `triangle` package always adds ``Q``, so its ``V`` prints only
    Triangle's indented progress lines and never these statistics; the
    statistics are what a user asking for ``V`` can use.)
    """
    asked = {
        "vertices": not o.N,
        "triangles": not o.E,
        "segments": (o.p or o.c) and not o.P,
        "edges": o.e,
        "voronoi": o.v,
        "neighbors": o.n,
    }
    lines = phase_lines(o, len(triangle_rows(result)))
    lines += list(warnings)
    lines.append("")
    lines += [text for key, text in _WRITING if asked[key]]
    counts = mesh_counts(result, refine=o.r)
    text = "\n".join(lines) + "\n"
    text += statistics_block(
        counts,
        input_vertices=_rows(tri, "vertices"),
        input_triangles=_rows(tri, "triangles"),
        input_segments=_rows(tri, "segments"),
        input_holes=_rows(tri, "holes"),
        poly=o.p,
        refine=o.r,
    )
    work = dict(getattr(result, "work", {}) or {})
    text += format_quality(quality_statistics(result))
    text += format_algorithmic(work, counts.triangles, voronoi=o.v)
    text += format_work(work)
    return text


def emit(text: str) -> None:
    """Write ``text`` to standard output.  The library's one console output:
    Triangle's documented ``V`` switch prints its statistics to stdout in
    library mode too (the `triangle` package's ``V`` prints Triangle's text
    there), so this is asked-for output, not a stray print."""
    sys.stdout.write(text)
    sys.stdout.flush()
