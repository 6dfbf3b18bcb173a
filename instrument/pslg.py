"""The ``-p`` pipeline: Delaunay triangulation, segment recovery, carving.

``Mesher`` holds everything the stages share and grows the arrays when a
kernel reports that it ran out of room (kernels never allocate).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from . import cdt
from .carve import infect_hull, locate_points, plague, spread_regions
from .counters import C_STEINER
from .delaunay import delaunay
from .mesh import S_NVERT, Mesh, grow_triangles, grow_vertices, spare_triangles
from .switches import Options


@dataclass
class Mesher:
    """The mesh being built and its side tables."""

    m: Mesh
    work: np.ndarray
    n_input: int
    dup: np.ndarray  # duplicate_of for input vertices
    vmark: np.ndarray  # (V,) int32 vertex markers
    # (V, 5) p0, p1, p2, s, t: a new vertex's attributes are a0 + s (a1 - a0) + t (a2 - a0);
    # no rows when the input has no vertex attributes (40 bytes a vertex saved)
    parent: np.ndarray
    segs: cdt.Segs
    vtri: np.ndarray  # (V,) int64 an edge leaving each vertex
    state: np.ndarray = field(default_factory=lambda: np.array([12345], dtype=np.int64))
    warnings: list[str] = field(default_factory=list)
    # Per triangle slot, as long as the mesh's slot arrays: ``grow`` widens
    # them with the mesh (and the refiner works on these very arrays), so no
    # kernel can index one past its end.
    region_attr: np.ndarray | None = None  # with -A (with -r: the input triangle each descends from)
    region_area: np.ndarray | None = None  # with a bare -a; <= 0: no bound
    dead: np.ndarray | None = None  # vertices refinement deleted (not output)

    @property
    def collinear(self) -> bool:
        """True if the input vertices had no triangulation at all."""
        return self.n_triangles_initial == 0

    n_triangles_initial: int = 0

    @property
    def n_vertices(self) -> int:
        return int(self.m.size[S_NVERT])

    def grow(self, vertices: int = 0, triangles: int = 0, records: int = 0) -> None:
        """Make room for at least that many more of each."""
        m = self.m
        nv = self.n_vertices
        if nv + vertices > m.xy.shape[0]:
            m = grow_vertices(m, nv + vertices)
            cap = m.xy.shape[0]
            self.vmark = _widen(self.vmark, cap, 0)
            if self.parent.shape[0]:
                self.parent = _widen(self.parent, cap, -1.0)
            self.vtri = _widen(self.vtri, cap, -1)
        if spare_triangles(m) < triangles:
            m = grow_triangles(m, m.stamp.shape[0] + triangles)
        # every per-triangle table grows here, with the mesh: a table left at
        # its old length let the refiner write past its end (issue 18 item 1)
        slots = m.stamp.shape[0]
        if self.region_attr is not None and self.region_attr.shape[0] < slots:
            self.region_attr = _widen(self.region_attr, slots, 0.0)
        if self.region_area is not None and self.region_area.shape[0] < slots:
            self.region_area = _widen(self.region_area, slots, -1.0)
        if int(self.segs.size[cdt.R_NREC]) + records > self.segs.marker.shape[0]:
            self.segs = cdt.grow_segs(self.segs, int(self.segs.size[cdt.R_NREC]) + records)
        self.m = m


def _widen(a: np.ndarray, n: int, fill) -> np.ndarray:
    out = np.full((n,) + a.shape[1:], fill, dtype=a.dtype)
    out[: a.shape[0]] = a
    return out


def start(
    xy: np.ndarray,
    markers: np.ndarray,
    work: np.ndarray,
    seed: int,
    spare_vertices: int,
    method: str = "divconq",
    parents: bool = True,
) -> Mesher:
    """Delaunay-triangulate the input vertices by ``method`` (see delaunay.py),
    with room for more; ``parents``: record what each new vertex's
    attributes interpolate."""
    n = xy.shape[0]
    spare = max(spare_vertices, 16)
    m, dup = delaunay(xy, work, method=method, seed=seed, extra_vertices=spare, extra_triangles=2 * spare)
    cap = n + spare
    vmark = np.zeros(cap, dtype=np.int32)
    vmark[:n] = markers
    mesher = Mesher(
        m=m,
        work=work,
        n_input=n,
        dup=dup,
        vmark=vmark,
        parent=np.full((cap if parents else 0, 5), -1.0),
        segs=cdt.new_segs(max(16, 2 * spare_vertices)),
        vtri=np.full(cap, -1, dtype=np.int64),
        n_triangles_initial=int(m.size[3]),
    )
    return mesher


def clean_segments(segments: np.ndarray, xy: np.ndarray, dup: np.ndarray, warnings: list[str]) -> np.ndarray:
    """Input segments as rows (a, b, input index), with Triangle's warnings for
    invalid endpoints and coincident endpoints; endpoints that are duplicate
    vertices are mapped to the copy in the mesh."""
    n = xy.shape[0]
    seg = np.asarray(segments, dtype=np.int64).reshape(-1, 2)
    bad_first = (seg[:, 0] < 0) | (seg[:, 0] >= n)
    bad_second = ~bad_first & ((seg[:, 1] < 0) | (seg[:, 1] >= n))
    ok = ~(bad_first | bad_second)
    ends = np.where(ok[:, None], seg, 0)
    ends = np.where(dup[ends] >= 0, dup[ends], ends)
    coincident = ok & (xy[ends[:, 0]] == xy[ends[:, 1]]).all(axis=1)
    for i in np.flatnonzero(~ok | coincident):
        if bad_first[i]:
            warnings.append(f"Warning:  Invalid first endpoint of segment {i} in input.")
        elif bad_second[i]:
            warnings.append(f"Warning:  Invalid second endpoint of segment {i} in input.")
        else:
            warnings.append(f"Warning:  Endpoints of segment {i} are coincident in input.")
    keep = ok & ~coincident
    return np.c_[ends[keep], np.flatnonzero(keep)].astype(np.int64)


def recover_segments(ms: Mesher, rows: np.ndarray, seg_markers: np.ndarray) -> None:
    """Insert the segments ``rows`` (from ``clean_segments``) in input order."""
    if rows.shape[0] == 0 or int(ms.m.size[1]) == 0:
        return
    rows, in_marker = _merge_duplicates(rows, np.asarray(seg_markers, dtype=np.int32))
    cdt.build_vertex_edges(ms.m, ms.vtri)
    pieces = np.zeros((rows.shape[0] + 64, 3), dtype=np.int64)
    pieces[: rows.shape[0]] = rows[::-1]
    ms.segs.size[cdt.R_SP] = rows.shape[0]
    steps = np.array([0, rows.shape[0]], dtype=np.int64)
    # every pair of segments crosses at most once
    most_vertices = ms.n_vertices + rows.shape[0] * (rows.shape[0] + 1) // 2
    buf = np.zeros(4 * (ms.n_vertices + 64), dtype=np.int64)
    while True:
        status = cdt.insert_segments(
            ms.m, ms.work, ms.segs, pieces, in_marker, ms.vmark, ms.vtri, buf, ms.parent, ms.state, steps
        )
        if status == cdt.DONE:
            if ms.work[C_STEINER] and cdt.count_inverted(ms.m):
                # rounded intersection points of nearly concurrent segments
                # can fold the mesh; never hand back a folded mesh
                raise RuntimeError(_TOO_CLOSE)
            return
        # a segment cannot cross more triangles than there are
        lost = status == cdt.NEED_BUFFER and buf.shape[0] > 8 * (ms.m.stamp.shape[0] + 64)
        if status == cdt.FAILED or lost or ms.n_vertices > most_vertices:
            a, b, i = pieces[int(ms.segs.size[cdt.R_SP]) - 1]
            raise RuntimeError(
                f"could not recover segment {i} between ({ms.m.xy[a, 0]:.17g}, {ms.m.xy[a, 1]:.17g}) and "
                f"({ms.m.xy[b, 0]:.17g}, {ms.m.xy[b, 1]:.17g}): " + _TOO_CLOSE
            )
        if status == cdt.NEED_BUFFER:
            buf = np.zeros(2 * buf.shape[0], dtype=np.int64)
            continue
        ms.grow(vertices=ms.n_vertices // 2 + 16, triangles=ms.m.stamp.shape[0] // 2 + 64, records=ms.segs.marker.shape[0])
        if int(ms.segs.size[cdt.R_SP]) + 4 > pieces.shape[0]:
            pieces = _widen(pieces, 2 * pieces.shape[0], 0)


_TOO_CLOSE = (
    "segments cross at points too close together for double precision "
    "(nearly concurrent or overlapping segments); the constrained triangulation could not be built"
)


def _merge_duplicates(rows: np.ndarray, markers: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Drop repeats of a segment (same two endpoints, either direction).

    The first copy is kept and takes the first non-zero marker among its
    copies, as recovering the copies one after another would do; dropping
    them up front keeps a copy from crossing its own first copy after a
    crossing point has bent that (rounded crossing points are not exactly on
    the line).
    """
    key = np.sort(rows[:, :2], axis=1)
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


def enclose_hull(ms: Mesher) -> None:
    """-c: every hull edge becomes a subsegment with marker 1."""
    while not cdt.mark_hull(ms.m, ms.segs, ms.vmark, -1):
        ms.grow(records=ms.segs.marker.shape[0])


def carve(ms: Mesher, o: Options, holes: np.ndarray | None, regions: np.ndarray | None, xy_in: np.ndarray) -> None:
    """Remove concavities (unless -c) and holes (unless -O), then spread regions."""
    m = ms.m
    slots = m.stamp.shape[0]
    lo = xy_in.min(axis=0)
    hi = xy_in.max(axis=0)
    found_regions = None
    if regions is not None and len(regions):
        found_regions = np.zeros((len(regions), 2), dtype=np.int64)
        locate_points(m, ms.work, np.ascontiguousarray(regions[:, :2]), lo, hi, found_regions, ms.state)
    infected = np.zeros(slots, dtype=np.uint8)
    queue = np.zeros(slots, dtype=np.int64)
    n = 0
    if not o.c:
        n = infect_hull(m, ms.segs, ms.vmark, infected, queue)
    if holes is not None and len(holes) and not o.O:
        found = np.zeros((len(holes), 2), dtype=np.int64)
        locate_points(m, ms.work, np.ascontiguousarray(holes), lo, hi, found, ms.state)
        for t in found[found[:, 0] >= 0, 0]:
            if not infected[t]:
                infected[t] = 1
                queue[n] = t
                n += 1
    plague(m, ms.work, ms.segs, ms.vmark, infected, queue, n)
    stack = queue
    if found_regions is not None:
        seen = np.zeros(slots, dtype=np.int64)
        if o.A:
            ms.region_attr = np.zeros(slots)
            spread_regions(m, found_regions, np.ascontiguousarray(regions[:, 2]), ms.region_attr, seen, stack)
        if o.var_area:
            ms.region_area = np.full(slots, -1.0)
            seen[:] = 0
            spread_regions(m, found_regions, np.ascontiguousarray(regions[:, 3]), ms.region_area, seen, stack)
