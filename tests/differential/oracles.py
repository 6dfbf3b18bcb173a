"""What ours must do, given what Triangle did on the same case.

``judge`` returns a ``Verdict``: the failures (each with a ``signature``,
a short stable cause used to deduplicate, e.g. ``ours-exception:
ZeroDivisionError``) and notes (what Triangle did, sizes, which oracles
applied).  The rules:

* ours never crashes, hangs, or raises anything but ``ValueError`` /
  ``RuntimeError`` (and their engine subclasses ``SwitchError``,
  ``PrecisionError``) with a message; and it raises those only where
  Triangle makes no valid mesh either (at extreme scales, where Triangle's
  own predicates under- or overflow, an empty answer of Triangle's counts
  as no mesh);
* every mesh of ours passes ``check_mesh`` (with the input as PSLG under
  ``p``; the fixed area bound and the angle bound where Triangle's own mesh
  meets them: ``Y``/``YY`` can make both unreachable), loses no input vertex
  that lies in the mesh, has only segments as boundary edges under ``p`` or
  ``c`` (Triangle eats up to segments), and under ``p`` without ``c`` only
  subsegments that lie on input segments;
* where Triangle made a mesh that passes the same checker:
  - non-refining switches (no q, a, u, D): equal counts (vertices,
    triangles, segments, edges, neighbours), marker multisets, input-vertex
    markers, area per triangle attribute, total area, ``o2`` node counts;
  - refining switches: ours uses no more vertices than Triangle's count
    plus 2 % or 3, or, failing that, than Triangle's largest count over the
    exact re-expressions of the input plus 1 % or 2 (Triangle's own count
    moves that much when the input is mirrored); regional and per-triangle
    (``r``) area bounds where Triangle meets them; attributes per region;
    the same total area.  Under ``S`` (a Steiner budget) only the size.

Switches are read here with a small parser of our own, not the engine's.
"""

from __future__ import annotations

import math
import re
from collections import Counter, defaultdict
from dataclasses import dataclass, field

import numpy as np

from instrument.check import check_mesh, mesh_area, orient_exact, orient_signs, quality_report

from .cases import Case
from .runners import Outcome

#: what the engine may raise on input it cannot mesh (class names; the
#: engine's SwitchError is a ValueError, its PrecisionError a RuntimeError)
ALLOWED_ERRORS = frozenset({"ValueError", "SwitchError", "RuntimeError", "PrecisionError"})
#: the engine's own error (TriangleError: a ValueError and a RuntimeError, as
#: the triangle package's users catch either) and everything derived from it
#: (SwitchError, PrecisionError, SizeLimitError) is a clear error too
ENGINE_ERROR = "TriangleError"
AREA_RTOL = 1e-9
SIZE_SLACK = (0.02, 3)
SPREAD_SLACK = (0.01, 2)


@dataclass
class Failure:
    kind: str
    detail: str
    message: str

    @property
    def signature(self) -> str:
        return f"{self.kind}:{self.detail}" if self.detail else self.kind


@dataclass
class Verdict:
    failures: list[Failure] = field(default_factory=list)
    notes: dict = field(default_factory=dict)

    def fail(self, kind: str, detail: str, message: str) -> None:
        self.failures.append(Failure(kind, detail, message))

    @property
    def ok(self) -> bool:
        return not self.failures

    def signatures(self) -> list[str]:
        return sorted({f.signature for f in self.failures})


@dataclass
class Switches:
    """What the oracles need to know of a switch string."""

    p: bool = False
    r: bool = False
    q: bool = False
    angle: float = 0.0
    area: float | None = None
    bare_a: bool = False
    D: bool = False
    u: bool = False
    A: bool = False
    c: bool = False
    j: bool = False
    i: bool = False  # incremental Delaunay (Triangle's start hull edge and kept duplicates differ)
    Y: int = 0
    S: int | None = None
    o2: bool = False

    @property
    def refining(self) -> bool:
        return self.q or self.area is not None or self.bare_a or self.D or self.u

    @property
    def variable_area(self) -> bool:
        return self.bare_a and (self.p or self.r)


def read_switches(s: str) -> Switches:
    o = Switches()
    i = 0
    while i < len(s):
        ch = s[i]
        i += 1
        num = re.match(r"[0-9.]*", s[i:]).group()
        if ch == "q":
            o.q = True
            o.angle = float(num) if num.strip(".") else 20.0
            i += len(num)
        elif ch == "a":
            if num:
                o.area = float(num)
                i += len(num)
            else:
                o.bare_a = True
        elif ch == "S":
            digits = re.match(r"[0-9]*", s[i:]).group()
            o.S = int(digits) if digits else 0
            i += len(digits)
        elif ch == "o" and s[i : i + 1] == "2":
            o.o2 = True
            i += 1
        elif ch == "Y":
            o.Y += 1
        elif ch in "prDuAcji":
            setattr(o, ch, True)
    if o.r or not o.p:
        o.A = False
    return o


# ---------------------------------------------------------------- mesh helpers


def _arr(result: dict, key: str, cols: int) -> np.ndarray:
    a = result.get(key)
    if a is None or np.size(a) == 0:
        return np.zeros((0, cols))
    return np.asarray(a).reshape(len(a), -1)


def n_rows(result: dict, key: str) -> int:
    a = result.get(key)
    return 0 if a is None else len(a)


def used_vertices(result: dict) -> int:
    t = _arr(result, "triangles", 3)
    return int(np.unique(t[:, :3].astype(np.int64)).size)


def _vertices(result: dict) -> np.ndarray:
    return np.asarray(result.get("vertices", np.zeros((0, 2))), dtype=np.float64).reshape(-1, 2)


def _tri_areas(result: dict) -> np.ndarray:
    v = _vertices(result)
    t = _arr(result, "triangles", 3)[:, :3].astype(np.int64)
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    with np.errstate(over="ignore", invalid="ignore"):
        return 0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))


def _total_area(result: dict) -> float:
    """The mesh's area; inf when the sum overflows (math.fsum raises on that at ~2^512)."""
    try:
        return mesh_area({"vertices": _vertices(result), "triangles": _arr(result, "triangles", 3)[:, :3]})
    except OverflowError:
        return math.inf


def _close(x: float, y: float, scale: float, slack: float = 0.0) -> bool:
    return abs(x - y) <= AREA_RTOL * max(abs(scale), 1e-300) + slack or (math.isinf(x) and x == y)


def rounding_slack(*results: dict) -> float:
    """How much the domain's area may move because split points on segments
    are rounded (each by about an ulp of the coordinates, times a segment
    length): one unit roundoff times extent squared per vertex.  It matters
    for slivers, whose area is tiny next to their extent."""
    n = max(len(_vertices(r)) for r in results)
    extent = max(float(np.abs(_vertices(r)).max(initial=0.0)) for r in results)
    return 4.0 * n * 2.0**-53 * extent * extent


def components(result: dict) -> np.ndarray:
    """For each triangle, the label of its region: triangles joined across
    edges that are not subsegments (Triangle spreads regions that way)."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    t = _arr(result, "triangles", 3)[:, :3].astype(np.int64)
    m = len(t)
    if m == 0:
        return np.zeros(0, dtype=np.int64)
    nv = len(_vertices(result))
    a = np.concatenate([t[:, 0], t[:, 1], t[:, 2]])
    b = np.concatenate([t[:, 1], t[:, 2], t[:, 0]])
    owner = np.tile(np.arange(m), 3)
    key = np.minimum(a, b) * nv + np.maximum(a, b)
    segs = _arr(result, "segments", 2).astype(np.int64)
    seg_keys = np.minimum(segs[:, 0], segs[:, 1]) * nv + np.maximum(segs[:, 0], segs[:, 1]) if len(segs) else np.zeros(0)
    order = np.argsort(key, kind="stable")
    k, o = key[order], owner[order]
    pair = np.flatnonzero(k[1:] == k[:-1])
    pair = pair[~np.isin(k[pair], seg_keys)]
    g = coo_matrix((np.ones(len(pair)), (o[pair], o[pair + 1])), shape=(m, m))
    return connected_components(g, directed=False)[1]


def unsegmented_boundary(result: dict) -> int:
    """Boundary edges (one triangle) that are not subsegments.  Under ``p``
    or ``c`` (without ``r``) there are none: Triangle eats triangles from the
    hull inwards until segments stop it, and ``c`` makes the hull segments."""
    t = _arr(result, "triangles", 3)[:, :3].astype(np.int64)
    if not len(t):
        return 0
    nv = len(_vertices(result))
    a = np.concatenate([t[:, 0], t[:, 1], t[:, 2]])
    b = np.concatenate([t[:, 1], t[:, 2], t[:, 0]])
    key = np.minimum(a, b) * nv + np.maximum(a, b)
    uniq, count = np.unique(key, return_counts=True)
    boundary = uniq[count == 1]
    segs = _arr(result, "segments", 2).astype(np.int64)
    seg_keys = np.minimum(segs[:, 0], segs[:, 1]) * nv + np.maximum(segs[:, 0], segs[:, 1]) if len(segs) else np.zeros(0)
    return int((~np.isin(boundary, seg_keys)).sum())


def phantom_segments(result: dict, tri: dict, rtol: float = 1e-9) -> list[int]:
    """Output subsegments that lie on no input segment (under ``p`` without
    ``c``, every subsegment is a piece of an input segment).  Coordinates
    are scaled by a power of two first, so inputs at 2^512 do not overflow;
    split points may sit an ulp or so off their segment, hence ``rtol``."""
    segs = _arr(result, "segments", 2).astype(np.int64)
    ins = np.asarray(tri.get("segments", np.zeros((0, 2))), dtype=np.int64).reshape(-1, 2)
    if not len(segs):
        return []
    iv, ov = _vertices(tri), _vertices(result)
    big = max(float(np.abs(iv).max(initial=0.0)), float(np.abs(ov).max(initial=0.0)))
    if not math.isfinite(big) or big == 0:
        return []
    k = -math.frexp(big)[1]
    iv, ov = np.ldexp(iv, k), np.ldexp(ov, k)
    if not len(ins):
        return list(range(len(segs)))
    a, b = iv[ins[:, 0]][None], iv[ins[:, 1]][None]  # (1, S, 2)
    d = b - a
    length = np.hypot(d[..., 0], d[..., 1])
    ok = np.ones(len(segs), dtype=bool)
    for end in (0, 1):
        p = ov[segs[:, end]][:, None]  # (M, 1, 2)
        cross = d[..., 0] * (p[..., 1] - a[..., 1]) - d[..., 1] * (p[..., 0] - a[..., 0])
        t = (d[..., 0] * (p[..., 0] - a[..., 0]) + d[..., 1] * (p[..., 1] - a[..., 1])) / np.maximum(length**2, 1e-300)
        on = (np.abs(cross) <= rtol * np.maximum(length, 1e-300) + 1e-300) & (t >= -rtol) & (t <= 1 + rtol)
        ok_end = on if end == 0 else on & ok_pair
        ok_pair = on
    ok = ok_end.any(axis=1)
    return np.flatnonzero(~ok).tolist()


def _containing(result: dict, xy) -> np.ndarray:
    """Indices of the triangles whose closed interior holds point ``xy`` (exact)."""
    v = _vertices(result)
    t = _arr(result, "triangles", 3)[:, :3].astype(np.int64)
    if not len(t):
        return np.zeros(0, dtype=np.int64)
    p = np.broadcast_to(np.asarray(xy, dtype=np.float64), (len(t), 2))
    s = [np.asarray(orient_signs(v[t[:, i]], v[t[:, (i + 1) % 3]], p)) for i in range(3)]
    return np.flatnonzero((s[0] >= 0) & (s[1] >= 0) & (s[2] >= 0))


def region_labels(result: dict, regions) -> tuple[dict, list]:
    """(component -> (attribute, max_area)) as Triangle spreads ``regions``
    (each region overwrites the component it lies in, in list order), and
    the regions whose point is ambiguous (on a segment between two regions)."""
    comp = components(result)
    label: dict = {}
    ambiguous = []
    for i, (x, y, attr, area) in enumerate(np.asarray(regions, dtype=np.float64).reshape(-1, 4)):
        inside = _containing(result, (x, y))
        if not len(inside):
            continue
        cs = set(comp[inside].tolist())
        if len(cs) > 1:
            ambiguous.append(i)
            continue
        label[cs.pop()] = (attr, area)
    return label, ambiguous


def attribute_areas(result: dict) -> dict:
    """Total triangle area per triangle attribute value (first column)."""
    att = _arr(result, "triangle_attributes", 1)
    if not len(att):
        return {}
    areas = _tri_areas(result)
    out = defaultdict(float)
    for a, w in zip(att[:, 0].tolist(), areas.tolist()):
        out[a] += w
    return dict(out)


def region_violations(result: dict, regions, comp_label=None) -> tuple[int, int]:
    """(attribute mismatches, area-bound violations) of ``result`` against
    the regions spread over its own components."""
    label, _ = region_labels(result, regions) if comp_label is None else comp_label
    comp = components(result)
    att = _arr(result, "triangle_attributes", 1)
    areas = _tri_areas(result)
    bad_attr = bad_area = 0
    for i, c in enumerate(comp.tolist()):
        attr, bound = label.get(c, (0.0, -1.0))
        if len(att) and att[i, 0] != attr:
            bad_attr += 1
        if bound > 0 and areas[i] > bound * (1 + 1e-12):
            bad_area += 1
    return bad_attr, bad_area


def per_triangle_violations(result: dict, mesh_in: dict) -> int:
    """Triangles of ``result`` larger than the ``triangle_max_area`` of the
    input triangle holding their centroid (``r`` with a bare ``a``)."""
    bounds = np.asarray(mesh_in.get("triangle_max_area", np.zeros(0)), dtype=np.float64).reshape(-1)
    if not len(bounds) or not (bounds > 0).any():
        return 0
    v = _vertices(result)
    t = _arr(result, "triangles", 3)[:, :3].astype(np.int64)
    cen = v[t].mean(axis=1)
    iv = np.asarray(mesh_in["vertices"], dtype=np.float64)
    it = np.asarray(mesh_in["triangles"], dtype=np.int64)[:, :3]
    a, b, c = iv[it[:, 0]], iv[it[:, 1]], iv[it[:, 2]]
    areas = _tri_areas(result)
    bad = 0
    for k in range(0, len(cen), 512):
        p = cen[k : k + 512, None, :]

        def side(u, w):
            return (w[None, :, 0] - u[None, :, 0]) * (p[..., 1] - u[None, :, 1]) - (w[None, :, 1] - u[None, :, 1]) * (p[..., 0] - u[None, :, 0])

        score = np.minimum(np.minimum(side(a, b), side(b, c)), side(c, a))
        host = np.argmax(score, axis=1)
        bnd = bounds[host]
        bad += int(((bnd > 0) & (areas[k : k + 512] > bnd * (1 + 1e-12))).sum())
    return bad


# ---------------------------------------------------------------- judging


def _pslg(case: Case, sw: Switches) -> dict | None:
    return case.input if sw.p else None


def _problem_kind(line: str) -> str:
    words = re.sub(r"[-+0-9.e]+(?=[\s,)\]]|$)", "#", line).replace("(", " ").split()
    return " ".join(w for w in words[:5] if w != "#")


def extreme_extent(tri: dict) -> bool:
    """The whole input lies within 2^-200 of the origin or reaches beyond
    2^200: every product of coordinate differences Triangle forms under- or
    overflows, so none of its answers is a reference.  (Mixed inputs, tiny
    coordinates beside ordinary ones, are not: most of Triangle's work is
    still sound there.)"""
    v = np.abs(_vertices(tri))
    return bool(v.size and (v.max() < 2.0**-200 or v.max() > 2.0**200))


def ordinary_scale(tri: dict) -> bool:
    """Every nonzero coordinate between 2^-200 and 2^200: Triangle's exact
    predicates (products of up to four coordinate differences) neither
    underflow nor overflow, so its answer, even an empty mesh, is a reference."""
    v = np.abs(_vertices(tri))
    v = v[v > 0]
    return bool(not v.size or (v.min() >= 2.0**-200 and v.max() <= 2.0**200))


def dropped_vertices(result: dict, tri: dict) -> list[int]:
    """Input vertices that lie in the mesh (exactly, closed triangles) but are
    not vertices of it: silently lost.  (A vertex eaten with a hole or
    outside the domain lies in no triangle; a duplicate has its twin's
    coordinates.)  Compared by coordinates, so ``j``'s renumbering is fine."""
    out = _vertices(result)
    t = _arr(result, "triangles", 3)[:, :3].astype(np.int64)
    if not len(t):
        return []
    corners = {tuple(p) for p in out[np.unique(t)].tolist()}
    lost = []
    for i, p in enumerate(_vertices(tri).tolist()):
        if tuple(p) not in corners and len(_containing(result, p)):
            lost.append(i)
    return lost


def unused_points(result: dict, tri: dict) -> list[int]:
    """Without ``p`` or ``r`` the mesh is the Delaunay triangulation of the
    points: every input point is a corner of it (a duplicate through its
    twin's coordinates), unless all are collinear (no triangle).  The input
    points this one leaves out.  (Triangle's orientation test is exact only
    while its products stay normal: (1.6e-319, 1.2e-33) (0, 0) (1.2e-30,
    1.2e-30) (0, 1.2e-30) gives it one triangle, without (0, 0), whose
    corners do not span the points' hull; concurrent-segments, seed 2.)"""
    out = _vertices(result)
    t = _arr(result, "triangles", 3)[:, :3].astype(np.int64)
    if not len(t):
        return []
    corners = {tuple(p) for p in out[np.unique(t)].tolist()}
    return [i for i, p in enumerate(_vertices(tri).tolist()) if tuple(p) not in corners]


def bent_at_input_vertices(result: dict, tri: dict) -> list[int]:
    """Input vertices at which the output's subsegments bend an input
    segment: a subsegment ends at the vertex and lies along the segment
    within rounding (the vertex is within ``phantom_segments``' tolerance of
    the segment, strictly between its ends), yet the vertex is not exactly on
    the segment.  Triangle's orientation test is exact only while its
    products stay normal: beside (1.6e-319, 1.2e-33) the side x = 0 of a
    square of side 1.2e-30 is split at that vertex (its orientation
    underflows to 0), where the exact answer leaves the side whole
    (concurrent-segments, seed 2)."""
    segs = _arr(result, "segments", 2).astype(np.int64)
    ins = np.asarray(tri.get("segments", np.zeros((0, 2))), dtype=np.int64).reshape(-1, 2)
    if not len(segs) or not len(ins):
        return []
    iv, ov = _vertices(tri), _vertices(result)
    where = {tuple(p): i for i, p in enumerate(iv.tolist())}
    ends = np.unique(segs)
    candidates = [(int(o), where[tuple(ov[o])]) for o in ends.tolist() if tuple(ov[o]) in where]
    bent = set()
    for o, i in candidates:
        p = iv[i]
        for a, b in ins.tolist():
            if i in (a, b) or not _on_segment_loosely(iv[a], iv[b], p):
                continue
            if orient_exact(tuple(iv[a]), tuple(iv[b]), tuple(p)) != 0:
                bent.add(i)
    return sorted(bent)


def _on_segment_loosely(a, b, p, rtol: float = 1e-9) -> bool:
    """``p`` within ``rtol`` of segment ``a b``'s length of its line,
    strictly between its ends (coordinates scaled by a power of two)."""
    big = float(max(np.abs(a).max(), np.abs(b).max(), np.abs(p).max()))
    if not math.isfinite(big) or big == 0:
        return False
    k = -math.frexp(big)[1]
    a, b, p = np.ldexp(a, k), np.ldexp(b, k), np.ldexp(p, k)
    d = b - a
    length2 = float(d @ d)
    if length2 == 0:
        return False
    cross = d[0] * (p[1] - a[1]) - d[1] * (p[0] - a[0])
    t = float(d @ (p - a)) / length2
    return abs(cross) <= rtol * math.sqrt(length2) and 0.0 < t < 1.0


def reflex_hull_vertices(result: dict) -> list[int]:
    """Boundary vertices of a point set's triangulation where the boundary
    turns right, exactly: the triangles do not cover the points' convex
    hull.  (Under Triangle's underflowing orientation test (1.6e-319,
    1.2e-33) lies on the side x = 0 of the square of side 1.2e-30; it is
    inside, and the hull runs past it.)"""
    t = _arr(result, "triangles", 3)[:, :3].astype(np.int64)
    if not len(t):
        return []
    xy = _vertices(result)
    directed = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    if orient_exact(*(tuple(xy[k]) for k in t[0].tolist())) < 0:
        directed = directed[:, ::-1]  # clockwise triangles: turn the boundary round
    inner = {tuple(e) for e in directed.tolist()}
    nxt = {a: b for a, b in directed.tolist() if (b, a) not in inner}
    prev = {b: a for a, b in nxt.items()}
    return sorted(v for v, n in nxt.items()
                  if v in prev and orient_exact(tuple(xy[prev[v]]), tuple(xy[v]), tuple(xy[n])) < 0)


def triangle_meets_angle(result: dict, pslg, angle: float) -> bool:
    try:
        rep = quality_report(result, pslg, angle)
    except OverflowError:  # quality_report's area sum overflows at ~2^512: ask check_mesh instead
        probs = check_mesh(result, pslg, min_angle=angle, delaunay=False, markers=False)
        return not any("minimum angle" in p for p in probs)
    return rep["n_bad"] - rep["n_exempt"] == 0


def judge(case: Case, tri: Outcome, ours: Outcome, spread=None) -> Verdict:
    with np.errstate(over="ignore", invalid="ignore", under="ignore"):
        return _judge(case, tri, ours, spread)


def _judge(case: Case, tri: Outcome, ours: Outcome, spread) -> Verdict:
    """Judge ours against Triangle on ``case``.  ``spread()`` returns Triangle's
    vertex counts (used vertices) over the exact re-expressions of the input;
    it is called only when ours is above the plain size bound."""
    v = Verdict()
    sw = read_switches(case.switches)
    v.notes["triangle"] = tri.summary()
    v.notes["ours"] = ours.summary()
    v.notes["ours_seconds"] = round(ours.seconds, 3)
    pslg = _pslg(case, sw)

    # is Triangle's answer a valid mesh? (then ours must make one too)
    t_ok = tri.status == "ok"
    # with r the given triangles come back as they are (and refinement only
    # flips around new vertices): Delaunay is asked of ours where Triangle's is
    delaunay = not sw.r
    if t_ok:
        t_probs = check_mesh(tri.result, pslg=pslg if "segments" in tri.result else None, delaunay=delaunay)
        if sw.r and not t_probs:
            delaunay = not check_mesh(tri.result, pslg=pslg if "segments" in tri.result else None, markers=False)
        if not t_probs and (lost := dropped_vertices(tri.result, case.input)):
            # an input vertex strictly inside Triangle's triangles, a corner of
            # none: a fold of Triangle's, carved away (a segment exactly
            # through (0, 0), crossed first elsewhere, passes it by 1e-21 and
            # the crossing triangle holds it: Triangle 1 triangle, ours 3;
            # regressions/crossing-through-vertex-counts.json); ours is
            # judged by the same test below
            t_probs = [f"input vertices {lost[:5]} lie in Triangle's mesh but are not vertices of it"]
        if not t_probs and not sw.p and not sw.r and (lost := unused_points(tri.result, case.input)):
            t_probs = [f"input points {lost[:5]} are corners of no triangle of Triangle's point-set triangulation"]
        if (not t_probs and not sw.p and not sw.r and not ordinary_scale(case.input)
                and (reflex := reflex_hull_vertices(tri.result))):
            t_probs = [f"Triangle's point-set triangulation turns inward at {len(reflex)} hull vertices "
                       "(it does not cover the points' convex hull)"]
        if (not t_probs and sw.p and not ordinary_scale(case.input)
                and (bent := bent_at_input_vertices(tri.result, case.input))):
            t_probs = [f"Triangle's subsegments bend input segments at input vertices {bent[:5]}, "
                       "which are not exactly on them"]
        if t_probs:
            v.notes["triangle_invalid"] = t_probs[:3]
            t_ok = False

    if ours.status in ("crash", "timeout"):
        v.fail(f"ours-{ours.status}", "", f"ours: {ours.message}; Triangle: {tri.summary()}")
        return v
    if ours.status == "error":
        allowed = ours.exc_type in ALLOWED_ERRORS or ENGINE_ERROR in ours.exc_mro
        if not allowed or not ours.message.strip():
            v.fail("ours-exception", ours.exc_type, f"ours raises {ours.exc_type}: {ours.message}\n{ours.traceback}")
        elif ours.exc_type == "SizeLimitError" and sw.refining and extreme_extent(case.input):
            # Triangle's quality test overflows there and stops early: its mesh
            # is no size reference (a 1 x 1e-14 parallelogram at 1e200 under
            # pq: Triangle keeps 2 triangles; at 1e100 it makes 96, at scale 1
            # it fails; a 20-degree mesh of it has ~1e14 triangles, and ours
            # stops at its vertex limit at every scale)
            v.notes["triangle_no_reference"] = "extreme scale: ours stops at its vertex limit"
        elif t_ok and (n_rows(tri.result, "triangles") or ordinary_scale(case.input)):
            # at extreme scales an empty answer of Triangle's is no better than a clear error
            v.fail("ours-error-where-triangle-meshes", ours.exc_type,
                   f"ours raises {ours.exc_type}: {ours.message}; Triangle: {tri.summary()}")
        return v

    res = ours.result
    t_res = tri.result if t_ok else None
    if t_res is not None and not n_rows(t_res, "triangles") and n_rows(res, "triangles") and not ordinary_scale(case.input):
        # Triangle found no triangle (its predicates under- or overflow at
        # extreme scales, and it calls the input collinear): ours' mesh is
        # judged on its own
        v.notes["triangle_empty"] = True
        t_res = None
    if t_res is not None and extreme_extent(case.input):
        # beyond 2^+-200 Triangle's predicates and quality test under- or
        # overflow: it calls inputs collinear, keeps triangles that p eats at
        # scale 1 (11 points at 7e-155 under p: Triangle 3 triangles, none
        # at scale 1 or in ours), stops refining early; its answer is no
        # reference there, and ours' mesh is judged on its own
        v.notes["triangle_no_reference"] = "extreme scale"
        t_res = None
    angle = sw.angle if (sw.q and sw.angle > 0 and sw.S is None) else None
    max_area = sw.area if (sw.area is not None and sw.S is None) else None
    if t_res is None:
        angle = max_area = None  # no reference for the bounds: only validity is asked
    elif n_rows(t_res, "triangles"):
        # Y, YY (no splitting of segments) can make both bounds unreachable:
        # a bound is asked of ours where Triangle's own mesh meets it
        if angle is not None:
            meets = triangle_meets_angle(t_res, pslg, angle)
            v.notes["triangle_meets_angle"] = meets
            if not meets:
                angle = None
        if max_area is not None:
            meets = bool((_tri_areas(t_res) <= max_area * (1 + 1e-12)).all())
            v.notes["triangle_meets_area"] = meets
            if not meets:
                max_area = None
    try:
        probs = check_mesh(res, pslg=pslg if "segments" in res else None, min_angle=angle, max_area=max_area,
                           delaunay=delaunay)
    except Exception as exc:  # the checker itself must cope with whatever it is given
        v.fail("checker-error", type(exc).__name__, f"check_mesh raised {type(exc).__name__}: {exc}")
        return v
    if probs:
        v.fail("invalid-mesh", _problem_kind(probs[0]), "; ".join(probs[:4]))
    if lost := dropped_vertices(res, case.input):
        v.fail("dropped-vertex", "", f"input vertices {lost[:5]} lie in ours' mesh but are not vertices of it")
    if not sw.p and not sw.r and (lost := unused_points(res, case.input)):
        v.fail("dropped-vertex", "points", f"input points {lost[:5]} are corners of no triangle of ours")
    if sw.p and not sw.c and not sw.r and (phantom := phantom_segments(res, case.input)):
        v.fail("phantom-segment", "", f"{len(phantom)} output segments of ours lie on no input segment "
               f"(first: {_arr(res, 'segments', 2)[phantom[0]].tolist()})")
    if (sw.p or sw.c) and not sw.r and (open_edges := unsegmented_boundary(res)):
        v.fail("boundary-not-segment", "", f"{open_edges} boundary edges of ours are not segments "
               "(under p or c, triangles are eaten up to segments)")

    if t_res is None:
        return v

    # both made a valid mesh: compare
    if sw.o2 and n_rows(t_res, "triangles") and n_rows(res, "triangles"):  # (no triangle: the counts differ)
        t_cols, o_cols = _arr(t_res, "triangles", 3).shape[1], _arr(res, "triangles", 3).shape[1]
        if o_cols != t_cols:
            v.fail("o2", "", f"o2: Triangle gives {t_cols}-node triangles ({n_rows(t_res, 'vertices')} nodes), "
                   f"ours {o_cols}-node ({n_rows(res, 'vertices')} nodes)")

    scale = t_area = _total_area(t_res)
    o_area = _total_area(res)
    finite = math.isfinite(t_area) and math.isfinite(o_area)  # areas of ~1e300 meshes overflow
    slack = rounding_slack(t_res, res) if finite else 0.0
    if finite and not _close(t_area, o_area, scale, slack):
        if sw.p and not sw.r and n_rows(res, "segments") > n_rows(t_res, "segments") and (
                left_off := vertices_left_off_segments(case, t_res, res)):
            # Triangle's subsegments skip an input vertex that lies exactly on
            # an input segment (a crossing came first), ours end there: the
            # triangles that piece encloses are eaten by Triangle, kept by ours
            # (three crossing segments through a vertex under p: Triangle 0
            # triangles, ours 1; regressions/crossing-through-vertex-domain.json).
            # Domains differ, so Triangle's mesh is no reference
            v.notes["triangle_no_reference"] = f"{len(left_off)} input vertices on segments left off its subsegments"
            return v
        v.fail("area-total", "", f"total area: Triangle {t_area!r}, ours {o_area!r}")

    if sw.A and "regions" in case.input and finite:
        ta, oa = attribute_areas(t_res), attribute_areas(res)
        if set(ta) != set(oa) or any(not _close(ta[k], oa.get(k, 0.0), scale, slack) for k in ta):
            v.fail("attributes", "", f"area per attribute: Triangle {ta}, ours {oa}")

    if not sw.refining:
        _equal_counts(v, case, sw, t_res, res)
    else:
        _refining(v, case, sw, pslg, t_res, res, spread)
    if sw.p and not sw.r and "regions" in case.input and (sw.A or sw.variable_area) and sw.S is None:
        _regions(v, case, sw, t_res, res)
    return v


def near_duplicate_merges(result: dict, rtol: float = 1e-12, inputs=None) -> int:
    """How many vertices merge into others within ``rtol`` of the mesh's extent.
    Triangle computes the crossing of one segment with two overlapping
    collinear segments twice, and the two roundings can differ by an ulp:
    two vertices for one crossing.  It also keeps a crossing within rounding
    of an input vertex (two segments crossing 1e-203 from the end of one)
    as a vertex of its own, where ours takes the input vertex.

    Vertices at the coordinates of ``inputs`` (a set of input points) never
    merge with one another, however near (an input vertex 1e-203 from
    another is a vertex of both meshes): a group of near vertices merges
    into as many vertices as it holds input vertices (at least one)."""
    found = _near_duplicate_groups(result, rtol)
    if found is None:
        return 0
    xy, pairs, count, label = found
    if inputs is None:
        return len(xy) - count
    grouped = np.unique(pairs)
    size = np.bincount(label[grouped], minlength=count)
    held = np.bincount(label[grouped], weights=[tuple(p) in inputs for p in xy[grouped].tolist()], minlength=count)
    return int((size - np.maximum(held, 1))[size > 0].sum())


def near_duplicate_labels(result: dict, rtol: float = 1e-12) -> np.ndarray | None:
    """A cluster label per vertex, vertices within ``rtol`` of the mesh's
    extent of each other (and not equal: exact duplicates are input
    duplicates) sharing one; None when there are no such pairs."""
    found = _near_duplicate_groups(result, rtol)
    return None if found is None else found[3]


def _near_duplicate_groups(result: dict, rtol: float):
    """(vertices, near pairs, component count, component label per vertex)
    of the graph joining vertices within ``rtol`` of the mesh's extent (and
    not equal), or None when it has no edge."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components
    from scipy.spatial import cKDTree

    xy = _vertices(result)
    if len(xy) < 2 or not np.isfinite(xy).all():
        return None
    extent = float(np.abs(xy).max())
    tree = cKDTree(xy)
    # at mixed scales (1e-303 beside 1e300) the radius swallows whole
    # clusters: their pairs are no near-duplicates, and listing them took the
    # campaign to 23 GB (killed); count around a sample first, without listing
    # (in the max norm: Euclidean squares overflow at 1e300)
    probe = xy[:: max(1, len(xy) // 256)]
    if np.mean(tree.query_ball_point(probe, rtol * extent, p=np.inf, return_length=True)) > 4:
        return None
    pairs = np.array(sorted(tree.query_pairs(rtol * extent, p=np.inf)), dtype=np.int64).reshape(-1, 2)
    pairs = pairs[(xy[pairs[:, 0]] != xy[pairs[:, 1]]).any(axis=1)]  # exact duplicates are input duplicates
    if not len(pairs):
        return None
    g = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(len(xy), len(xy)))
    count, label = connected_components(g, directed=False)
    return xy, pairs, count, label


def near_duplicates_merged(result: dict, jettison: bool) -> dict[str, int] | None:
    """The counts (vertices, triangles, segments) of ``result`` with its
    near-duplicate vertices merged (``near_duplicate_labels``), or None when
    it has none.

    Triangle's two roundings of one crossing (``near_duplicate_merges``) can
    be corners of a triangle of their own: the third corner an input vertex
    on the overlapping segments, the three sides pieces of segments, so that
    carving keeps it where nothing else survives (a segment through the
    origin crossing y = 0.0004024505615234375, on which two input segments
    overlap, under pQ: Triangle's crossings lie an ulp above and below that
    line, its one triangle has an area of ~1e-23; ours rounds the exact
    crossing once, onto the line, and encloses nothing).  Merged, such a
    triangle has a repeated corner and goes, and with it the subsegments it
    alone had and, under ``j``, the vertices (and ``o2`` nodes) no other
    triangle uses; ``o2`` nodes of the triangles that go leave the count
    in any case."""
    labels = near_duplicate_labels(result)
    if labels is None:
        return None
    tri = _arr(result, "triangles", 3).astype(np.int64)
    corners = labels[tri[:, :3]]
    kept = (corners[:, 0] != corners[:, 1]) & (corners[:, 1] != corners[:, 2]) & (corners[:, 0] != corners[:, 2])
    edges = {frozenset(e) for t in corners[kept].tolist() for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))}
    segs = {frozenset(labels[s].tolist()) for s in _arr(result, "segments", 2).astype(np.int64)}
    segs = {s for s in segs if len(s) == 2 and s in edges}
    if jettison:
        nodes = np.unique(labels[tri[kept].ravel()])
    else:
        gone = np.setdiff1d(tri[~kept, 3:].ravel(), tri[kept, 3:].ravel())  # o2 nodes of the merged triangles only
        nodes = np.unique(np.delete(labels, gone))
    return {"vertices": int(nodes.size), "triangles": int(kept.sum()), "segments": len(segs)}


def crossing_copies(case: Case, t_res: dict) -> int:
    """Vertices Triangle added at exactly the place of an input vertex."""
    iv = np.asarray(case.input["vertices"], dtype=np.float64).reshape(-1, 2)
    tv = _vertices(t_res)
    if len(tv) <= len(iv):
        return 0
    inputs = {tuple(p) for p in iv.tolist()}
    return sum(tuple(p) in inputs for p in tv[len(iv):].tolist())


def _within_rounding(u, w, p) -> bool:
    """Is ``p`` within a few units in the last place of the line u -> w (the
    tolerance segment recovery gives a rounded crossing vertex)?"""
    cross = (w[0] - u[0]) * (p[1] - u[1]) - (w[1] - u[1]) * (p[0] - u[0])
    length = math.hypot(w[0] - u[0], w[1] - u[1])
    return abs(cross) <= 2.0**-48 * (abs(u[0]) + abs(u[1]) + abs(w[0]) + abs(w[1])) * length


def _crossed_near(t_res: dict, n_in: int, u, w) -> bool:
    """Has Triangle a vertex of its own (a crossing) within rounding of the segment u -> w?"""
    return any(_within_rounding(u, w, q) for q in _vertices(t_res)[n_in:].tolist())


def vertices_left_off_segments(case: Case, t_res: dict, res: dict) -> dict[int, int]:
    """Input vertices inside an input segment where a subsegment of ours
    along that segment ends, and none of Triangle's: index -> that segment's
    marker (0 without markers).

    A segment through an input vertex is split there (Triangle does so too
    when nothing else interferes), but when another segment crosses it first,
    Triangle joins the far end straight to the rounded crossing vertex, which
    no longer has the input vertex exactly on the way: one subsegment where
    ours has two (docs/differential.md).  The same happens to an input vertex
    within rounding of a segment that another segment crosses (not exactly
    on it): ours' correctly rounded crossing keeps the vertex on the side it
    is, the segment meets the vertex's other segment at the vertex itself,
    and Triangle's crossing, an ulp away, puts it on the other side, where
    the segment passes it by (regressions/crossing-near-vertex-segments.json)."""
    iv = np.asarray(case.input["vertices"], dtype=np.float64).reshape(-1, 2)
    segs = np.asarray(case.input.get("segments", np.zeros((0, 2))), dtype=np.int64).reshape(-1, 2)
    smark = np.asarray(case.input.get("segment_markers", np.zeros(len(segs))), dtype=np.int64).reshape(-1)
    if len(smark) != len(segs):
        smark = np.zeros(len(segs), dtype=np.int64)
    if not len(segs) or len(iv) * len(segs) > 10**5 or not np.isfinite(iv).all():
        return {}
    if (segs < 0).any() or (segs >= len(iv)).any():
        return {}

    def pieces_at(result):
        """vertex -> directions of the subsegments that end there"""
        xy = _vertices(result)
        s = _arr(result, "segments", 2).astype(np.int64)
        out = defaultdict(list)
        for i, j in s.tolist():
            if 0 <= i < len(xy) and 0 <= j < len(xy):
                out[tuple(xy[i].tolist())].append(xy[j] - xy[i])
                out[tuple(xy[j].tolist())].append(xy[i] - xy[j])
        return out

    def along(pieces, d):
        """some piece runs along direction d (within rounding: Triangle's pieces end at rounded crossings)"""
        return any(abs(d[0] * q[1] - d[1] * q[0]) <= 1e-9 * math.hypot(*d) * math.hypot(*q) for q in pieces)

    theirs, ours = pieces_at(t_res), pieces_at(res)
    first = {}
    for i, p in enumerate(iv.tolist()):
        first.setdefault(tuple(p), i)
    out = {}
    for p, i in first.items():
        if p not in ours:
            continue
        for k, (a, b) in enumerate(segs.tolist()):
            u, w = iv[a].tolist(), iv[b].tolist()
            between = (p[0] - u[0]) * (w[0] - p[0]) >= 0 and (p[1] - u[1]) * (w[1] - p[1]) >= 0
            if not between or tuple(u) == p or tuple(w) == p:
                continue
            if orient_exact(u, w, list(p)) != 0 and not (
                    _within_rounding(u, w, p) and _crossed_near(t_res, len(iv), u, w)):
                continue
            d = (w[0] - u[0], w[1] - u[1])
            if along(ours[p], d) and not along(theirs.get(p, ()), d):
                out[i] = int(smark[k])
                break
    return out


def eaten_left_off(case: Case, t_res: dict, res: dict, candidates) -> dict[int, int]:
    """Of the input vertices ``candidates``, those in no triangle of either
    mesh, exactly inside an input segment, that Triangle's chain of pieces
    along that segment passes by: index -> the segment's marker.

    ``vertices_left_off_segments`` for eaten vertices, whose subsegments
    neither mesh outputs: the chain is the segment's endpoints and Triangle's
    vertices within rounding of it in order along it, and the vertex is
    passed by when it is not exactly on the line of its two neighbours in
    that chain (the segment (0.65625, 0.23828125)-(0.1796875, 0.23828125)
    through (0.4375, 0.23828125), crossed at (0.49972091241568206,
    0.23828125000000006) by Triangle under pQ: its marker is 0, ours' the
    segment's)."""
    iv = np.asarray(case.input["vertices"], dtype=np.float64).reshape(-1, 2)
    segs = np.asarray(case.input.get("segments", np.zeros((0, 2))), dtype=np.int64).reshape(-1, 2)
    smark = np.asarray(case.input.get("segment_markers", np.zeros(len(segs))), dtype=np.int64).reshape(-1)
    if len(smark) != len(segs):
        smark = np.zeros(len(segs), dtype=np.int64)
    if not len(segs) or (segs < 0).any() or (segs >= len(iv)).any() or not np.isfinite(iv).all():
        return {}
    used = set()
    for r in (t_res, res):
        used.update(_arr(r, "triangles", 3)[:, :3].astype(np.int64).ravel().tolist())
    txy = _vertices(t_res).tolist()
    out = {}
    for i in (int(c) for c in candidates):
        if i in used:
            continue
        p = iv[i].tolist()
        for k, (a, b) in enumerate(segs.tolist()):
            u, w = iv[a].tolist(), iv[b].tolist()
            between = (p[0] - u[0]) * (w[0] - p[0]) >= 0 and (p[1] - u[1]) * (w[1] - p[1]) >= 0
            if not between or u == p or w == p or orient_exact(u, w, p) != 0:
                continue
            d = (w[0] - u[0], w[1] - u[1])
            t_p = (p[0] - u[0]) * d[0] + (p[1] - u[1]) * d[1]
            chain = [(0.0, u), ((w[0] - u[0]) * d[0] + (w[1] - u[1]) * d[1], w)]
            for q in txy:
                if q != p and q != u and q != w and _within_rounding(u, w, q):
                    chain.append(((q[0] - u[0]) * d[0] + (q[1] - u[1]) * d[1], q))
            before = max((c for c in chain if c[0] < t_p), key=lambda c: c[0], default=None)
            after = min((c for c in chain if c[0] > t_p), key=lambda c: c[0], default=None)
            if before and after and orient_exact(before[1], after[1], p) != 0:
                out[i] = int(smark[k])
                break
    return out


def _equal_counts(v: Verdict, case: Case, sw: Switches, t_res: dict, res: dict) -> None:
    inputs = {tuple(p) for p in np.asarray(case.input["vertices"], dtype=np.float64).reshape(-1, 2).tolist()}
    merges = near_duplicate_merges(t_res, inputs=inputs) if n_rows(t_res, "vertices") != n_rows(res, "vertices") else 0
    if merges and n_rows(t_res, "vertices") - merges == n_rows(res, "vertices"):
        v.notes["triangle_near_duplicates"] = merges  # counts follow from Triangle's extra vertices
        return
    merged = near_duplicates_merged(t_res, sw.j) if merges else None
    if merged and merged["triangles"] < n_rows(t_res, "triangles") and all(
            merged[k] == n_rows(res, k) for k in merged):
        # the triangles Triangle's near-duplicates alone make (and what only
        # they keep) explain the difference in full
        v.notes["triangle_near_duplicate_triangles"] = n_rows(t_res, "triangles") - merged["triangles"]
        return
    o2_differs = any(f.kind == "o2" for f in v.failures)  # the midpoint nodes are missing: counted once
    # Triangle computes a crossing of two segments that lands exactly on an
    # input vertex (both pass through it) as a new vertex, a copy, and leaves
    # the input vertex unused; ours uses the input vertex
    # (regressions/crossing-at-input-vertex.json: 10 vertices against 9)
    copies = crossing_copies(case, t_res)
    if copies and n_rows(t_res, "vertices") - copies == n_rows(res, "vertices"):
        v.notes["triangle_crossing_copies"] = copies
        o2_differs = True  # (skips the vertex count and the vertex-marker multiset alike)
    if merges and copies and n_rows(t_res, "vertices") - merges - copies == n_rows(res, "vertices"):
        # both at once: a segment through an input vertex crossed first
        # elsewhere reaches another segment an ulp beside that vertex (a near
        # copy), and another crossing rounds exactly onto an input vertex (a
        # copy): Triangle 11 vertices, ours 9 under pQ
        # (regressions/crossing-copy-and-near-copy.json)
        v.notes["triangle_near_duplicates"] = merges
        v.notes["triangle_crossing_copies"] = copies
        return
    left_off: dict[int, int] = {}
    if n_rows(res, "segments") > n_rows(t_res, "segments"):
        left_off = vertices_left_off_segments(case, t_res, res)
        if left_off:
            v.notes["triangle_left_vertices_off_segments"] = sorted(left_off)
    for key in ("vertices", "triangles", "segments", "edges", "neighbors"):
        if key == "vertices" and (o2_differs or (left_off and sw.j)):
            continue  # (under j Triangle jettisons such a vertex when no triangle uses it)
        if key == "segments" and left_off and n_rows(res, key) - n_rows(t_res, key) == len(left_off):
            continue  # ours splits the segments at those vertices
        if key in ("triangles", "edges", "neighbors") and left_off:
            # that vertex is a corner of ours' triangles along the segment, of
            # none of Triangle's (three segments crossing around (0, 0) on one of
            # them under pQ: Triangle's crossing triangle is one, ours two;
            # regressions/crossing-through-vertex-counts.json); the areas agree
            continue
        if n_rows(t_res, key) != n_rows(res, key):
            v.fail("count", key, f"{key}: Triangle {n_rows(t_res, key)}, ours {n_rows(res, key)}")
    n_in = len(case.input["vertices"])
    explained: list[int] = []  # input vertices whose marker differs within what Triangle's order decides
    aligned = None  # ours' input-vertex markers with duplicate copies aligned to Triangle's
    if not sw.j and n_rows(t_res, "vertex_markers") >= n_in and n_rows(res, "vertex_markers") >= n_in:
        tm = _arr(t_res, "vertex_markers", 1)[:n_in, 0]
        om = copies_aligned(case, tm, _arr(res, "vertex_markers", 1)[:n_in, 0])
        aligned = om
        diff = np.flatnonzero(tm != om)
        if len(diff) and sw.p and not sw.r:
            free = eaten_on_zero_segments(case, t_res, res, diff)
            explained = [i for i in diff.tolist() if i in free and {int(tm[i]), int(om[i])} <= {0, 1}]
            if explained:
                v.notes["markers_order_decided"] = explained
            diff = np.setdiff1d(diff, explained)
        if len(diff) and sw.p and not sw.r:
            # a vertex Triangle's pieces pass by (a rounded crossing came first)
            # has ours' segment marker there and no marker from that segment in
            # Triangle's (vertices_left_off_segments, eaten_left_off)
            passed = dict(left_off) | eaten_left_off(case, t_res, res, diff)
            bypassed = [i for i in diff.tolist() if i in passed and int(om[i]) == passed[i]]
            if bypassed:
                v.notes["markers_of_bypassed_vertices"] = bypassed
                explained += bypassed
            diff = np.setdiff1d(diff, bypassed)
        if len(diff):
            used = np.zeros(max(n_rows(t_res, "vertices"), n_in), dtype=bool)
            used[_arr(t_res, "triangles", 3)[:, :3].astype(np.int64).ravel()] = True
            i = int(diff[0])
            # a vertex in no triangle of Triangle's (eaten, outside the domain, or no triangle at all)
            detail = "input-vertex" if used[diff].any() else "outside-domain"
            v.fail("markers", detail, f"input vertex {i}: Triangle's marker {tm[i]}, ours {om[i]} "
                   f"({len(diff)} input vertices differ)")
    for key in ("vertex_markers", "segment_markers", "edge_markers"):
        if key == "vertex_markers" and (o2_differs or (left_off and sw.j)):
            continue
        if key == "edge_markers" and left_off:
            continue
        tm = Counter(_arr(t_res, key, 1).reshape(-1).tolist())
        ours_markers = _arr(res, key, 1).reshape(-1)
        if key == "vertex_markers" and aligned is not None:
            ours_markers = np.concatenate([aligned, ours_markers[n_in:]])  # (copies_aligned)
        om = Counter(ours_markers.tolist())
        if key == "vertex_markers" and sw.j:
            for c, picked in zip((tm, om), kept_copy_markers(case, t_res, res)):
                c.subtract(picked)
            tm, om = +tm, +om
        if key == "vertex_markers" and sw.p and not sw.r and not sw.j:
            # the eaten vertices whose marker the order of carving decides
            # (above), and likewise the eaten crossing vertices, which are
            # numbered in each one's own order
            for r, c in ((t_res, tm), (res, om)):
                c.subtract(_arr(r, key, 1)[explained, 0].tolist())
                c.subtract(_arr(r, key, 1)[eaten_crossings(case, r), 0].tolist())
            tm, om = +tm, +om
        if key == "segment_markers" and left_off and not tm - om and sum((om - tm).values()) == len(left_off):
            continue  # one more subsegment of ours per such vertex
        if tm != om:
            v.fail("markers", key, f"{key} multiset: Triangle {dict(tm)}, ours {dict(om)}")


def kept_copy_markers(case: Case, t_res: dict, res: dict) -> tuple[list[int], list[int]]:
    """Under ``j``, the markers (Triangle's, ours) of the output vertices at
    places where duplicate input vertices have different input markers, when
    they follow from which copy each kept; empty lists otherwise.

    ``j`` leaves out the copies that are not in the mesh, so only the kept
    copy's marker is output: its own if nonzero, else the one it gains in
    the mesh (``copies_aligned``).  Which copy Triangle keeps follows its
    random pivots (docs/differential.md), so the marker at such a place may
    be any nonzero input marker of the copies, or one gained marker, the
    same for both meshes.  8 random points with one duplicate of another
    marker under pzjQ, pjQ, zjQ, pcjQ: 24 of 160 runs differed in these
    markers alone before this rule."""
    xy = np.asarray(case.input["vertices"], dtype=np.float64).reshape(-1, 2)
    marks = np.asarray(case.input.get("vertex_markers", np.zeros(len(xy))), dtype=np.int64).reshape(-1)
    if len(marks) != len(xy):
        return [], []
    places = defaultdict(set)
    for i, p in enumerate(xy.tolist()):
        places[(p[0], p[1])].add(int(marks[i]))
    mixed = {p: m for p, m in places.items() if len(m) > 1}
    if not mixed:
        return [], []
    picked: tuple[list[int], list[int]] = ([], [])
    gained: set[int] = set()
    for side, r in zip(picked, (t_res, res)):
        v = _arr(r, "vertices", 2)
        vm = _arr(r, "vertex_markers", 1).reshape(-1)
        if len(vm) != len(v):
            return [], []
        for i, p in enumerate(v.tolist()):
            given = mixed.get((p[0], p[1]))
            if given is not None:
                side.append(int(vm[i]))
                if int(vm[i]) not in given - {0}:
                    gained.add(int(vm[i]))
    if len(gained) > 1 or (gained and 0 not in set().union(*mixed.values())):
        return [], []  # not what keeping one copy gives: compared as they are
    return picked


def copies_aligned(case: Case, tm: np.ndarray, om: np.ndarray) -> np.ndarray:
    """Ours' input-vertex markers ``om`` with each group of duplicate input
    vertices (identical coordinates, equal input markers) given Triangle's
    markers ``tm`` where the group's markers agree as multisets.

    Which copy of a duplicate Triangle keeps follows its randomized
    quicksort's pivots (docs/differential.md: adding far-away points flips
    it), so a hull marker 1 lands on another copy than ours (ours keeps the
    lowest index): ``[[0,0],[1,1],[0,0]]`` under ``Q`` gives Triangle
    ``[0, 0, 1]``, ours ``[1, 0, 0]``.  With equal input markers the copies
    are interchangeable and only the multiset is determined.  With other
    input markers, the copies neither mesh keeps keep their input markers and
    the kept one its own if nonzero, else the one it gains in the mesh:
    ``[[0.5, 0.5] marker 1, [0.5, 0.5] marker 0]`` with a segment of marker 2
    from the second copy under ``pQ``: Triangle keeps the second (markers
    [1, 2]), ours the first ([1, 0]); the group is aligned when both follow
    that rule, with the same gained marker where both kept copies had input
    marker 0.  (Incremental
    insertion keeps the first copy in both, so under ``i`` this changes
    nothing where ours agrees.)"""
    xy = np.asarray(case.input["vertices"], dtype=np.float64).reshape(-1, 2)
    marks = np.asarray(case.input.get("vertex_markers", np.zeros(len(xy))), dtype=np.int64).reshape(-1)
    if len(marks) != len(xy):
        marks = np.zeros(len(xy), dtype=np.int64)
    groups = defaultdict(list)
    for i, p in enumerate(xy.tolist()):
        groups[(p[0], p[1], int(marks[i]))].append(i)
    out = om.copy()
    for g in groups.values():
        if len(g) > 1 and Counter(tm[g].tolist()) == Counter(om[g].tolist()):
            out[g] = tm[g]
    places = defaultdict(list)
    for (x, y, _), g in groups.items():
        places[(x, y)].extend(g)
    for g in places.values():
        if len(g) > 1 and len({int(marks[i]) for i in g}) > 1 and _one_copy_kept_each(marks, tm, om, g):
            out[g] = tm[g]
    return out


def _one_copy_kept_each(marks: np.ndarray, tm: np.ndarray, om: np.ndarray, g: list[int]) -> bool:
    """Do Triangle's markers ``tm`` and ours' ``om`` of the copies ``g`` each
    come from keeping one copy (``copies_aligned``)?"""
    def kept(markers):
        """the copies that may be the kept one: all others keep their input markers"""
        off = [i for i in g if markers[i] != marks[i]]
        if len(off) > 1 or (off and marks[off[0]] != 0):
            return []
        return off or list(g)

    for j in kept(tm):
        for k in kept(om):
            if marks[j] != 0 or marks[k] != 0 or tm[j] == om[k]:
                return True
    return False


def eaten_crossings(case: Case, result: dict) -> list[int]:
    """Vertices of ``result`` after the input's in no triangle, with marker 0
    or 1, that lie (within rounding) on input segments whose markers are
    all 0: crossing vertices eaten with the exterior or a hole, whose marker
    the order of carving decides (``eaten_on_zero_segments``)."""
    iv = np.asarray(case.input["vertices"], dtype=np.float64).reshape(-1, 2)
    segs = np.asarray(case.input.get("segments", np.zeros((0, 2))), dtype=np.int64).reshape(-1, 2)
    smark = np.asarray(case.input.get("segment_markers", np.zeros(len(segs))), dtype=np.int64).reshape(-1)
    xy = _vertices(result)
    marks = _arr(result, "vertex_markers", 1)[:, 0]
    if not len(segs) or len(smark) != len(segs) or len(xy) <= len(iv) or len(marks) != len(xy):
        return []
    if (segs < 0).any() or (segs >= len(iv)).any() or not np.isfinite(iv).all():
        return []
    used = np.zeros(len(xy), dtype=bool)
    used[_arr(result, "triangles", 3).astype(np.int64).ravel()] = True  # (o2's midpoint nodes too)
    a, b = iv[segs[:, 0]], iv[segs[:, 1]]
    d = b - a
    length = np.hypot(d[:, 0], d[:, 1])
    out = []
    for i in range(len(iv), len(xy)):
        if used[i] or marks[i] not in (0, 1):
            continue
        p = xy[i]
        cross = d[:, 0] * (p[1] - a[:, 1]) - d[:, 1] * (p[0] - a[:, 0])
        t = ((p - a) * d).sum(axis=1) / np.maximum(length**2, 1e-300)
        on = (np.abs(cross) <= 1e-9 * np.maximum(length, 1e-300) * max(1.0, float(np.abs(p).max()))) & (t >= -1e-9) & (t <= 1 + 1e-9)
        if on.any() and not smark[on].any():
            out.append(i)
    return out


def eaten_on_zero_segments(case: Case, t_res: dict, res: dict, candidates) -> set[int]:
    """Of the input vertices ``candidates``, those in no triangle of either
    mesh that lie on an input segment (an endpoint, or exactly inside) and
    would have marker 0 before carving: input marker 0, and every input
    segment through them with marker 0 (an endpoint takes the first nonzero
    segment marker when the segment is inserted).

    Such a vertex is an endpoint of eaten subsegments, and carving gives it
    marker 1 when the infection reaches one of them while the triangle on
    its other side is still alive, which follows the order in which
    Triangle's triangles are infected: that order, not the geometry, decides.
    Reversing one segment's direction (a square with the segment
    (0.875, 0.375)-(-0.25, 1.375) under pQ: identical meshes, marker of
    (-0.25, 1.375) 1 or 0) or the segment list's order changes Triangle's
    markers (docs/differential.md), so either 0 or 1 is accepted there."""
    iv = np.asarray(case.input["vertices"], dtype=np.float64).reshape(-1, 2)
    vmark = np.asarray(case.input.get("vertex_markers", np.zeros(len(iv))), dtype=np.int64).reshape(-1)
    segs = np.asarray(case.input.get("segments", np.zeros((0, 2))), dtype=np.int64).reshape(-1, 2)
    smark = np.asarray(case.input.get("segment_markers", np.zeros(len(segs))), dtype=np.int64).reshape(-1)
    if not len(segs) or len(vmark) != len(iv) or len(smark) != len(segs):
        return set()
    used = set()
    for r in (t_res, res):
        used.update(_arr(r, "triangles", 3)[:, :3].astype(np.int64).ravel().tolist())
    out = set()
    for i in (int(c) for c in candidates):
        if i in used or vmark[i] != 0:
            continue
        p = iv[i].tolist()
        on = []
        for k, (a, b) in enumerate(segs.tolist()):
            if not (0 <= a < len(iv) and 0 <= b < len(iv)):
                continue
            u, w = iv[a].tolist(), iv[b].tolist()
            between = (p[0] - u[0]) * (w[0] - p[0]) >= 0 and (p[1] - u[1]) * (w[1] - p[1]) >= 0
            if a == i or b == i or (between and orient_exact(u, w, p) == 0):
                on.append(int(smark[k]))
        if on and not any(on):
            out.add(i)
    return out


def _only_ours_meets_bounds(v: Verdict, sw: Switches, pslg, res: dict) -> bool:
    """Triangle's mesh misses the angle or area bound of the switches and ours meets both."""
    if v.notes.get("triangle_meets_angle") is not False and v.notes.get("triangle_meets_area") is not False:
        return False
    angle = sw.angle if (sw.q and sw.angle > 0) else None
    try:
        return not check_mesh(res, pslg=pslg if "segments" in res else None, min_angle=angle, max_area=sw.area)
    except Exception:  # the checker's own failure is reported by the validity oracle
        return False


def _refining(v: Verdict, case: Case, sw: Switches, pslg, t_res: dict, res: dict, spread) -> None:
    t_n, o_n = used_vertices(t_res), used_vertices(res)
    v.notes["vertices"] = {"triangle": t_n, "ours": o_n}
    if _only_ours_meets_bounds(v, sw, pslg, res):
        # Triangle's mesh misses a bound it was asked for and ours meets it:
        # a mesh that does less is no size reference
        v.notes["size_rule"] = "not applied: Triangle's mesh misses a bound that ours meets"
        return
    bound = t_n * (1 + SIZE_SLACK[0]) + SIZE_SLACK[1]
    if o_n > bound and spread is not None:
        counts = spread()
        v.notes["triangle_spread"] = counts
        if counts:
            bound = max(bound, max(counts) * (1 + SPREAD_SLACK[0]) + SPREAD_SLACK[1])
    v.notes["size_bound"] = bound
    if o_n > bound:
        v.fail("size", "", f"ours uses {o_n} vertices, Triangle {t_n} (bound {bound:.1f}, "
               f"Triangle over re-expressions {v.notes.get('triangle_spread')})")

    if sw.S is not None:
        return  # a Steiner budget stops both early, where their orders differ
    if sw.variable_area and sw.r:
        t_bad = per_triangle_violations(t_res, case.input)
        o_bad = per_triangle_violations(res, case.input)
        v.notes["triangle_per_triangle_violations"] = t_bad
        if t_bad == 0 and o_bad:
            v.fail("triangle-area", "", f"{o_bad} triangles of ours exceed the bound of the input triangle "
                   "holding them (Triangle: none)")


def _regions(v: Verdict, case: Case, sw: Switches, t_res: dict, res: dict) -> None:
    """Attributes (``A``) and area bounds (bare ``a``) per region, where
    Triangle's own mesh follows the same spreading rule."""
    labels = region_labels(t_res, case.input["regions"])
    if labels[1]:
        v.notes["ambiguous_regions"] = labels[1]
        return
    t_attr, t_area = region_violations(t_res, case.input["regions"], labels)
    o_attr, o_area = region_violations(res, case.input["regions"])
    v.notes["triangle_region_violations"] = {"attribute": t_attr, "area": t_area}
    if sw.variable_area and t_area == 0 and o_area:
        v.fail("region-area", "", f"{o_area} triangles of ours exceed their region's area bound (Triangle: none)")
    if sw.A and t_attr == 0 and o_attr:
        v.fail("region-attribute", "", f"{o_attr} triangles of ours carry another region's attribute (Triangle: none)")
