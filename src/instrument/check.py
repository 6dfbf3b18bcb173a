"""Independent checker for triangle meshes (the test oracle of ruppert).

This module judges the output of the engine without sharing any code with it:
it uses only numpy, Python integers and :mod:`math`.  Every geometric sign it
relies on is exact.  A vectorised floating-point filter (Shewchuk's stage-A
error bounds) certifies most signs, and the entries it cannot certify are
recomputed with exact integer arithmetic (every double is an integer times a
power of two).

Public API
----------
``check_mesh(result, pslg=None, min_angle=None, *, delaunay=True,
max_area=None, markers=True) -> list[str]``
    Human-readable problems; an empty list means the mesh is valid.
``quality_report(result, pslg=None, min_angle=None) -> dict``
    ``min_angle_deg``, ``max_angle_deg``, ``n_bad``, ``n_exempt``,
    ``area_total`` (plus ``n_triangles``).
``mesh_area(result) -> float``
    ``math.fsum`` of the signed triangle areas.
``orient_exact(a, b, c) -> int``, ``incircle_exact(a, b, c, d) -> int``
    Exact signs computed with integers.  ``orient_exact > 0`` iff a, b, c are
    counter-clockwise.  ``incircle_exact > 0`` iff d lies strictly inside the
    circle through the counter-clockwise a, b, c.
``orient_signs(a, b, c)``, ``incircle_signs(a, b, c, d)``
    The same signs for arrays of points of shape (n, 2), filtered and exact.

What ``check_mesh`` guarantees
------------------------------
If it returns no problem, the triangles (first three columns of
``triangles``):

* use indices in range, have three distinct corners that are pairwise
  distinct points, and are strictly counter-clockwise (exact orientation);
* no two triangles use the same corner set, and every directed edge is used
  by at most one triangle (so an undirected edge by at most two, in opposite
  directions);
* have pairwise disjoint interiors and meet only in common vertices or common
  edges: the union is an embedded simplicial complex.  Proof sketch: with all
  triangles counter-clockwise and every directed edge used once, the number
  of triangles covering a point p (not on an edge) equals the winding number
  around p of the chain of *boundary edges* (directed edges whose reverse is
  absent).  If some open region were covered twice, its frontier would
  contain a point x in the relative interior of a boundary edge, and a
  triangle other than the edge's own would contain x.  The checker therefore
  tests, exactly, every boundary edge (open segment) against every other
  triangle (closed) whose bounding box meets it (a multi-level grid finds the
  candidates).  The same test catches hanging vertices (T-junctions).

Vertices that no triangle uses are allowed (Triangle outputs duplicate and
eaten input vertices).

Also checked:

* every row of ``segments`` (the subsegments) is an edge of some triangle;
* constrained Delaunay (``delaunay=True``): for every edge shared by two
  triangles that is not a subsegment, the opposite apex is not strictly inside
  the other triangle's circumcircle (exact incircle; cocircular is fine);
* with ``pslg``: the output vertices lying on an input segment (exactly, or
  within ON_SEGMENT_RTOL: Triangle leaves split points up to ~1 ulp off the
  line) cut it into pieces, and every piece is covered by collinear output
  subsegments, or lies outside the mesh (Triangle deletes subsegments eaten
  with holes and the exterior).  Pass ``pslg`` only when the output has
  segments (not with ``-P``);
* ``min_angle``: see ``quality_report`` for the exemptions;
* ``max_area``: area <= max_area * (1 + 1e-12);
* ``markers``: lengths of the marker and attribute arrays, and nonzero
  markers on boundary subsegments and their endpoints (reference 2.12).
"""

from __future__ import annotations

import itertools
import math
from collections import defaultdict

import numpy as np

__all__ = [
    "check_mesh",
    "quality_report",
    "mesh_area",
    "orient_exact",
    "incircle_exact",
    "orient_signs",
    "incircle_signs",
    "SMALL_INPUT_ANGLE",
]

#: Largest number of messages reported per kind of problem.
MAX_MESSAGES = 20
#: Input angles (degrees) below which rule (a) of the angle exemption applies.
SMALL_INPUT_ANGLE = 60.0
#: Relative tolerance of the angle bound.
ANGLE_RTOL = 1e-9
#: Relative tolerance of the area bound.
AREA_RTOL = 1e-12
#: A vertex counts as lying on a segment if it is exactly on it, or if its
#: distance to the segment's line is at most this times (up to a factor 2) the
#: largest absolute coordinate involved.  Triangle moves split points onto the
#: line only once in floating point, so they are typically off by <= ~1 ulp.
ON_SEGMENT_RTOL = 2.0**-40
#: Miller-Pav-Walkington: squared distances equal within this factor.
MPW_RATIO = 0.001

_EPS = 2.0**-53
_CCW_BOUND = (3.0 + 16.0 * _EPS) * _EPS
_ICC_BOUND = (10.0 + 96.0 * _EPS) * _EPS
# Differences outside this range (other than exact zeros) go to the exact
# path, so that no product in the filters can underflow or overflow.
_SAFE_LO = 2.0**-200
_SAFE_HI = 2.0**200
_CELL_BITS = 30


# --------------------------------------------------------------------------
# Exact predicates
# --------------------------------------------------------------------------


def _scalar_ints(*vals):
    """Floats -> integers sharing one power-of-two scale (exact)."""
    ratios = [float(v).as_integer_ratio() for v in vals]
    den = max(d for _, d in ratios)
    return [n * (den // d) for n, d in ratios]


def _sign(x) -> int:
    return int(x > 0) - int(x < 0)


def orient_exact(a, b, c) -> int:
    """Exact sign of the orientation of (a, b, c): +1 counter-clockwise,
    -1 clockwise, 0 collinear.  Raises ValueError/OverflowError on NaN/inf."""
    ax, ay, bx, by, cx, cy = _scalar_ints(a[0], a[1], b[0], b[1], c[0], c[1])
    return _sign((bx - ax) * (cy - ay) - (by - ay) * (cx - ax))


def incircle_exact(a, b, c, d) -> int:
    """Exact incircle sign: +1 if d is strictly inside the circle through the
    counter-clockwise points a, b, c, 0 if on it, -1 outside.  (The sign is
    reversed when a, b, c are clockwise.)"""
    ax, ay, bx, by, cx, cy, dx, dy = _scalar_ints(
        a[0], a[1], b[0], b[1], c[0], c[1], d[0], d[1]
    )
    return _sign(_incircle_int(ax - dx, ay - dy, bx - dx, by - dy, cx - dx, cy - dy))


def _incircle_int(adx, ady, bdx, bdy, cdx, cdy):
    alift = adx * adx + ady * ady
    blift = bdx * bdx + bdy * bdy
    clift = cdx * cdx + cdy * cdy
    return (
        alift * (bdx * cdy - cdx * bdy)
        + blift * (cdx * ady - adx * cdy)
        + clift * (adx * bdy - bdx * ady)
    )


def _object_ints(cols):
    """Exact conversion of rows of floats to Python integers.

    ``cols`` is a list of K float arrays of length n.  Row i of the result is
    ``cols[k][i] * 2**-E_i`` for one exponent E_i per row, as object arrays.
    """
    x = np.stack(cols, axis=1)
    m, e = np.frexp(x)
    mant = (m * 2.0**53).astype(np.int64)
    e = e.astype(np.int64) - 53
    nz = mant != 0
    big = np.iinfo(np.int64).max
    emin = np.where(nz, e, big).min(axis=1, keepdims=True)
    emin = np.where(emin == big, 0, emin)
    shift = np.where(nz, e - emin, 0)
    ints = mant.astype(object) << shift.astype(object)
    return [ints[:, k] for k in range(x.shape[1])]


def _obj_sign(det):
    return (det > 0).astype(np.int8) - (det < 0).astype(np.int8)


def _safe(*diffs):
    ok = np.ones(diffs[0].shape, dtype=bool)
    for d in diffs:
        ad = np.abs(d)
        ok &= (ad == 0) | ((ad >= _SAFE_LO) & (ad <= _SAFE_HI))
    return ok


def _sign2x2(a, b, c, d, e, f, g, h):
    """Exact sign of (a-b)*(c-d) - (e-f)*(g-h), elementwise (finite inputs)."""
    with np.errstate(all="ignore"):
        d1 = a - b
        d2 = c - d
        d3 = e - f
        d4 = g - h
        left = d1 * d2
        right = d3 * d4
        det = left - right
        bound = _CCW_BOUND * (np.abs(left) + np.abs(right))
    sure = _safe(d1, d2, d3, d4) & (
        (det > bound)
        | (-det > bound)
        | (left == 0)
        | (right == 0)
        | ((left > 0) != (right > 0))
    )
    out = np.zeros(det.shape, dtype=np.int8)
    out[sure] = np.sign(det[sure])
    bad = np.flatnonzero(~sure)
    if bad.size:
        A, B, C, D, E, F, G, H = _object_ints([v[bad] for v in (a, b, c, d, e, f, g, h)])
        out[bad] = _obj_sign((A - B) * (C - D) - (E - F) * (G - H))
    return out


def _orient_xy(ax, ay, bx, by, cx, cy):
    s = _sign2x2(bx, ax, cy, ay, by, ay, cx, ax)
    same = ((ax == bx) & (ay == by)) | ((bx == cx) & (by == cy)) | ((ax == cx) & (ay == cy))
    s[same] = 0
    return s


def orient_signs(a, b, c):
    """Exact orientation signs of rows of point arrays a, b, c (n, 2)."""
    a, b, c = (np.asarray(p, dtype=np.float64).reshape(-1, 2) for p in (a, b, c))
    _require_finite(a, b, c)
    return _orient_xy(a[:, 0], a[:, 1], b[:, 0], b[:, 1], c[:, 0], c[:, 1])


def _incircle_xy(ax, ay, bx, by, cx, cy, dx, dy):
    with np.errstate(all="ignore"):
        adx = ax - dx
        ady = ay - dy
        bdx = bx - dx
        bdy = by - dy
        cdx = cx - dx
        cdy = cy - dy
        bdxcdy = bdx * cdy
        cdxbdy = cdx * bdy
        alift = adx * adx + ady * ady
        cdxady = cdx * ady
        adxcdy = adx * cdy
        blift = bdx * bdx + bdy * bdy
        adxbdy = adx * bdy
        bdxady = bdx * ady
        clift = cdx * cdx + cdy * cdy
        det = (
            alift * (bdxcdy - cdxbdy)
            + blift * (cdxady - adxcdy)
            + clift * (adxbdy - bdxady)
        )
        perm = (
            (np.abs(bdxcdy) + np.abs(cdxbdy)) * alift
            + (np.abs(cdxady) + np.abs(adxcdy)) * blift
            + (np.abs(adxbdy) + np.abs(bdxady)) * clift
        )
        bound = _ICC_BOUND * perm
    sure = _safe(adx, ady, bdx, bdy, cdx, cdy) & ((det > bound) | (-det > bound))
    out = np.zeros(det.shape, dtype=np.int8)
    out[sure] = np.sign(det[sure])
    on = ((ax == dx) & (ay == dy)) | ((bx == dx) & (by == dy)) | ((cx == dx) & (cy == dy))
    out[on] = 0
    sure |= on
    bad = np.flatnonzero(~sure)
    if bad.size:
        AX, AY, BX, BY, CX, CY, DX, DY = _object_ints(
            [v[bad] for v in (ax, ay, bx, by, cx, cy, dx, dy)]
        )
        det = _incircle_int(AX - DX, AY - DY, BX - DX, BY - DY, CX - DX, CY - DY)
        out[bad] = _obj_sign(det)
    return out


def incircle_signs(a, b, c, d):
    """Exact incircle signs of rows of point arrays (n, 2); see incircle_exact."""
    a, b, c, d = (np.asarray(p, dtype=np.float64).reshape(-1, 2) for p in (a, b, c, d))
    _require_finite(a, b, c, d)
    return _incircle_xy(
        a[:, 0], a[:, 1], b[:, 0], b[:, 1], c[:, 0], c[:, 1], d[:, 0], d[:, 1]
    )


def _require_finite(*arrays):
    for x in arrays:
        if not np.isfinite(x).all():
            raise ValueError("coordinates must be finite")


def _dot_sign_scalar(p, q, u, v) -> int:
    """Exact sign of (q - p) . (v - u) for 2-tuples of floats."""
    d1, d2 = q[0] - p[0], v[0] - u[0]
    d3, d4 = p[1] - q[1], v[1] - u[1]
    left, right = d1 * d2, d3 * d4
    det = left - right
    if all(x == 0 or _SAFE_LO <= abs(x) <= _SAFE_HI for x in (d1, d2, d3, d4)):
        if abs(det) > _CCW_BOUND * (abs(left) + abs(right)) or left == 0 or right == 0:
            return _sign(det)
    qx, px, vx, ux, py, qy, vy, uy = _scalar_ints(q[0], p[0], v[0], u[0], p[1], q[1], v[1], u[1])
    return _sign((qx - px) * (vx - ux) - (py - qy) * (vy - uy))


# --------------------------------------------------------------------------
# Input normalisation
# --------------------------------------------------------------------------


class _Problems:
    def __init__(self):
        self.lines: list[str] = []

    def add(self, what: str, items, total: int | None = None):
        """Report ``items`` (a list, or an iterable of ``total`` messages of
        which only the first MAX_MESSAGES are formatted)."""
        if total is None:
            items = list(items)
            total = len(items)
        if not total:
            return
        self.lines.extend(itertools.islice(items, MAX_MESSAGES))
        if total > MAX_MESSAGES:
            self.lines.append(f"... and {total - MAX_MESSAGES} more: {what}")


def _int_array(x, cols):
    a = np.asarray(x)
    if a.size == 0:
        return np.zeros((0, cols), dtype=np.int64)
    return a.astype(np.int64, copy=False)


class _Mesh:
    """Normalised arrays plus the per-triangle validity masks."""

    def __init__(self, result, probs: _Problems):
        self.ok = False
        v = np.asarray(result.get("vertices", np.zeros((0, 2))), dtype=np.float64)
        if v.size == 0:
            v = np.zeros((0, 2))
        if v.ndim != 2 or v.shape[1] != 2:
            probs.add("shape", [f"vertices must have shape (N, 2), got {v.shape}"])
            return
        self.V = v
        self.N = n = len(v)
        t = _int_array(result.get("triangles", np.zeros((0, 3))), 3)
        if t.ndim != 2 or t.shape[1] not in (3, 6):
            probs.add("shape", [f"triangles must have shape (M, 3) or (M, 6), got {t.shape}"])
            return
        self.T = t[:, :3]
        self.M = len(self.T)
        s = _int_array(result.get("segments", np.zeros((0, 2))), 2)
        if s.ndim != 2 or s.shape[1] != 2:
            probs.add("shape", [f"segments must have shape (S, 2), got {s.shape}"])
            return
        self.S = s
        self.ok = True

        T = self.T
        inrange = ((T >= 0) & (T < n)).all(axis=1)
        self.inrange = inrange
        Tc = np.where(inrange[:, None], T, 0)
        self.Tc = Tc
        distinct = (Tc[:, 0] != Tc[:, 1]) & (Tc[:, 1] != Tc[:, 2]) & (Tc[:, 0] != Tc[:, 2])
        self.topo = inrange & distinct  # usable for edge topology
        finite_v = np.isfinite(v).all(axis=1)
        self.finite = finite_v[Tc].all(axis=1)
        P = v[Tc]  # (M, 3, 2); rows with bad indices hold vertex 0, masked later
        self.P = P
        geo = self.topo & self.finite
        self.orient = np.zeros(self.M, dtype=np.int8)
        idx = np.flatnonzero(geo)
        if idx.size:
            q = P[idx]
            self.orient[idx] = _orient_xy(
                q[:, 0, 0], q[:, 0, 1], q[:, 1, 0], q[:, 1, 1], q[:, 2, 0], q[:, 2, 1]
            )
        self.geo = geo
        self.good = geo & (self.orient > 0)


# --------------------------------------------------------------------------
# Topology, orientation, overlap
# --------------------------------------------------------------------------


def _check_triangles(m: _Mesh, probs: _Problems):
    T = m.T
    bad = np.flatnonzero(~m.inrange)
    probs.add("triangles with an index out of range", (
        f"triangle {i} has a vertex index out of range [0, {m.N}): {T[i].tolist()}" for i in bad
    ), len(bad))
    bad = np.flatnonzero(m.inrange & ~m.topo)
    probs.add("degenerate triangles", (
        f"triangle {i} repeats a corner: {T[i].tolist()}" for i in bad
    ), len(bad))
    bad = np.flatnonzero(m.topo & ~m.finite)
    probs.add("non-finite coordinates", (
        f"triangle {i} {T[i].tolist()} has a non-finite vertex coordinate" for i in bad
    ), len(bad))
    bad = np.flatnonzero(m.geo & (m.orient < 0))
    probs.add("clockwise triangles", (
        f"triangle {i} {T[i].tolist()} is clockwise (exact orientation < 0)" for i in bad
    ), len(bad))
    bad = np.flatnonzero(m.geo & (m.orient == 0))
    probs.add("zero-area triangles", (
        f"triangle {i} {T[i].tolist()} has zero area (collinear or coincident corners)"
        for i in bad
    ), len(bad))

    # Duplicate triangles (same corner set).
    idx = np.flatnonzero(m.topo)
    if idx.size:
        st = np.sort(m.Tc[idx], axis=1)
        n = np.int64(m.N)
        key = (st[:, 0] * n + st[:, 1]) * n + st[:, 2] if m.N < 2**20 else None
        if key is None:
            _, inv, cnt = np.unique(st, axis=0, return_inverse=True, return_counts=True)
            inv = inv.ravel()
        else:
            _, inv, cnt = np.unique(key, return_inverse=True, return_counts=True)
        groups = np.flatnonzero(cnt > 1)
        probs.add("duplicate triangles", (
            f"duplicate triangles {idx[inv == g].tolist()} "
            f"(corners {sorted(m.Tc[idx[inv == g][0]].tolist())})" for g in groups
        ), len(groups))

    # Coincident vertices used by triangles.
    used = np.unique(m.Tc[m.topo & m.finite])
    if used.size > 1:
        pts = m.V[used]
        order = np.lexsort((pts[:, 1], pts[:, 0]))
        sp = pts[order]
        same = (sp[1:] == sp[:-1]).all(axis=1)
        k = np.flatnonzero(same)
        probs.add("coincident vertices", (
            f"vertices {int(used[order[j]])} and {int(used[order[j + 1]])} used by triangles "
            f"have the same coordinates {sp[j].tolist()}" for j in k
        ), len(k))


class _Edges:
    """Directed edges of the topologically usable triangles."""

    def __init__(self, m: _Mesh):
        idx = np.flatnonzero(m.topo)
        t = m.Tc[idx]
        self.tri = np.concatenate([idx, idx, idx])
        self.a = np.concatenate([t[:, 0], t[:, 1], t[:, 2]])
        self.b = np.concatenate([t[:, 1], t[:, 2], t[:, 0]])
        self.apex = np.concatenate([t[:, 2], t[:, 0], t[:, 1]])
        n = np.int64(max(m.N, 1))
        self.n = n
        self.key = self.a * n + self.b
        self.twin_key = self.b * n + self.a
        lo = np.minimum(self.a, self.b)
        hi = np.maximum(self.a, self.b)
        self.ukey = lo * n + hi
        order = np.argsort(self.key, kind="stable")
        self.sorted_key = self.key[order]
        self.order = order
        # Position of the twin directed edge, or -1.
        pos = np.searchsorted(self.sorted_key, self.twin_key)
        pos = np.minimum(pos, max(len(self.key) - 1, 0))
        if len(self.key):
            has = self.sorted_key[pos] == self.twin_key
            self.twin = np.where(has, order[pos], -1)
        else:
            self.twin = np.zeros(0, dtype=np.int64)


def _check_edges(m: _Mesh, e: _Edges, probs: _Problems):
    if len(e.key) == 0:
        return
    sk = e.sorted_key
    dkeys = np.unique(sk[1:][sk[1:] == sk[:-1]])

    def directed(k):
        a, b = divmod(int(k), int(e.n))
        tris = e.tri[e.key == k]
        return (f"directed edge ({a} -> {b}) is used by triangles {tris.tolist()} "
                "(inconsistent orientation, duplicate or overlapping triangles)")

    probs.add("directed edges used twice", map(directed, dkeys), len(dkeys))
    uk, cnt = np.unique(e.ukey, return_counts=True)
    many = np.flatnonzero(cnt > 2)

    def shared(j):
        a, b = divmod(int(uk[j]), int(e.n))
        tris = np.unique(e.tri[e.ukey == uk[j]])
        return f"edge {{{a}, {b}}} is shared by {int(cnt[j])} triangles {tris.tolist()}"

    probs.add("edges shared by more than two triangles", map(shared, many), len(many))


def _levels(dim, h0):
    with np.errstate(divide="ignore", over="ignore", invalid="ignore"):
        lev = np.ceil(np.log2(np.maximum(dim, h0 * 2.0**-60) / h0))
    lev = np.clip(np.nan_to_num(lev, posinf=2000), 0, 2000).astype(np.int64)
    with np.errstate(over="ignore"):
        lev += dim > np.ldexp(h0, lev)  # guard against log2 rounding
    return lev


def _cells(box, lev, h0, x0, y0):
    """Grid cells (at level lev, scalar) touched by the boxes: (object, key)."""
    s = math.ldexp(h0, int(min(lev, 2000)))  # may be inf: then one cell

    def index(x, origin):
        # monotone in x, so overlapping intervals always share a cell
        with np.errstate(all="ignore"):
            return np.floor(np.clip((x - origin) / s, 0.0, 2.0**29)).astype(np.int64)

    ix0, ix1 = index(box[:, 0], x0), index(box[:, 1], x0)
    iy0, iy1 = index(box[:, 2], y0), index(box[:, 3], y0)
    objs, keys = [], []
    ar = np.arange(len(box))
    for dx in range(3):
        for dy in range(3):
            mask = (ix0 + dx <= ix1) & (iy0 + dy <= iy1)
            objs.append(ar[mask])
            keys.append(((ix0[mask] + dx) << _CELL_BITS) + iy0[mask] + dy)
    return np.concatenate(objs), np.concatenate(keys)


def _join(a_obj, a_key, b_obj, b_key):
    order = np.argsort(b_key, kind="stable")
    bk = b_key[order]
    bo = b_obj[order]
    lo = np.searchsorted(bk, a_key, "left")
    hi = np.searchsorted(bk, a_key, "right")
    cnt = hi - lo
    tot = int(cnt.sum())
    if tot == 0:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    first = np.cumsum(cnt) - cnt
    pos = np.arange(tot) - np.repeat(first, cnt) + np.repeat(lo, cnt)
    return np.repeat(a_obj, cnt), bo[pos]


def _box_pairs(tbox, ebox):
    """Candidate (triangle, edge) pairs whose closed bounding boxes overlap."""
    allb = np.concatenate([tbox, ebox])
    x0, y0 = allb[:, 0].min(), allb[:, 2].min()
    span = max(allb[:, 1].max() - x0, allb[:, 3].max() - y0)
    tdim = np.maximum(tbox[:, 1] - tbox[:, 0], tbox[:, 3] - tbox[:, 2])
    edim = np.maximum(ebox[:, 1] - ebox[:, 0], ebox[:, 3] - ebox[:, 2])
    h0 = float(np.median(tdim)) if len(tdim) else 1.0
    h0 = max(h0, span * 2.0**-28, 2.0**-1000)
    h0 = 2.0 ** min(math.ceil(math.log2(h0)), 1000) if math.isfinite(h0) else 2.0**1000
    tl = _levels(tdim, h0)
    el = _levels(edim, h0)
    pairs_t, pairs_e = [], []
    for lev in np.unique(tl):
        ti = np.flatnonzero(tl == lev)
        ei = np.flatnonzero(el <= lev)
        if not ei.size:
            continue
        to, tk = _cells(tbox[ti], lev, h0, x0, y0)
        eo, ek = _cells(ebox[ei], lev, h0, x0, y0)
        a, b = _join(to, tk, eo, ek)
        pairs_t.append(ti[a])
        pairs_e.append(ei[b])
    for lev in np.unique(el):
        ei = np.flatnonzero(el == lev)
        ti = np.flatnonzero(tl < lev)
        if not ti.size:
            continue
        to, tk = _cells(tbox[ti], lev, h0, x0, y0)
        eo, ek = _cells(ebox[ei], lev, h0, x0, y0)
        a, b = _join(to, tk, eo, ek)
        pairs_t.append(ti[a])
        pairs_e.append(ei[b])
    if not pairs_t:
        return np.zeros(0, np.int64), np.zeros(0, np.int64)
    pt = np.concatenate(pairs_t)
    pe = np.concatenate(pairs_e)
    ne = np.int64(len(ebox))
    u = np.unique(pt * ne + pe)
    pt, pe = u // ne, u % ne
    keep = (
        (tbox[pt, 0] <= ebox[pe, 1]) & (ebox[pe, 0] <= tbox[pt, 1])
        & (tbox[pt, 2] <= ebox[pe, 3]) & (ebox[pe, 2] <= tbox[pt, 3])
    )
    return pt[keep], pe[keep]


def _open_segment_meets_triangle(p, q, a, b, c):
    """Exact: does the open segment (p, q) meet the closed CCW triangle abc?

    All arguments are (n, 2) arrays.  Closed disjointness is decided by the
    separating-axis theorem (the line pq, or one of the triangle's edges with
    p and q strictly outside); the closed intersection is only an endpoint of
    the segment if that endpoint is in the triangle and the segment leaves the
    triangle immediately across an edge line through it.
    """
    def o(u, v, w):
        return _orient_xy(u[:, 0], u[:, 1], v[:, 0], v[:, 1], w[:, 0], w[:, 1])

    sa, sb, sc = o(p, q, a), o(p, q, b), o(p, q, c)
    sep = ((sa > 0) & (sb > 0) & (sc > 0)) | ((sa < 0) & (sb < 0) & (sc < 0))
    p_in = np.ones(len(p), bool)
    q_in = np.ones(len(p), bool)
    exit_p = np.zeros(len(p), bool)
    exit_q = np.zeros(len(p), bool)
    for u, v in ((a, b), (b, c), (c, a)):
        op, oq = o(u, v, p), o(u, v, q)
        sep |= (op < 0) & (oq < 0)
        p_in &= op >= 0
        q_in &= oq >= 0
        exit_p |= (op == 0) & (oq < 0)
        exit_q |= (oq == 0) & (op < 0)
    only_end = (p_in & exit_p) | (q_in & exit_q)
    return ~sep & ~only_end


def _segments_meet_triangles(m: _Mesh, pa, pb, owner=None):
    """Pairs (good triangle, k) such that the open segment (pa[k], pb[k])
    meets the closed triangle (exact); ``owner[k]`` is skipped."""
    none = np.zeros(0, np.int64), np.zeros(0, np.int64)
    gidx = np.flatnonzero(m.good)
    if not gidx.size or not len(pa):
        return none
    P = m.P[gidx]
    tbox = np.stack([P[:, :, 0].min(1), P[:, :, 0].max(1), P[:, :, 1].min(1), P[:, :, 1].max(1)], 1)
    ebox = np.stack([
        np.minimum(pa[:, 0], pb[:, 0]), np.maximum(pa[:, 0], pb[:, 0]),
        np.minimum(pa[:, 1], pb[:, 1]), np.maximum(pa[:, 1], pb[:, 1]),
    ], 1)
    pt, pe = _box_pairs(tbox, ebox)
    tri = gidx[pt]
    if owner is not None:
        keep = tri != owner[pe]
        tri, pe = tri[keep], pe[keep]
    if not len(tri):
        return none
    hit = _open_segment_meets_triangle(
        pa[pe], pb[pe], m.V[m.Tc[tri, 0]], m.V[m.Tc[tri, 1]], m.V[m.Tc[tri, 2]]
    )
    return tri[hit], pe[hit]


def _check_overlap(m: _Mesh, e: _Edges, probs: _Problems):
    good = m.good
    if not good.any():
        return
    # Boundary edges among the good triangles.
    gmask = good[e.tri]
    key = e.key[gmask]
    twin = e.twin_key[gmask]
    skey = np.sort(key)
    pos = np.minimum(np.searchsorted(skey, twin), len(skey) - 1)
    boundary = skey[pos] != twin
    ea = e.a[gmask][boundary]
    eb = e.b[gmask][boundary]
    owner = e.tri[gmask][boundary]
    if not len(ea):
        probs.add("overlap", ["the triangles have no boundary edge (impossible for a plane mesh)"])
        return
    tri, pe = _segments_meet_triangles(m, m.V[ea], m.V[eb], owner)
    probs.add("overlapping triangles", (
        f"triangle {int(t)} {m.T[t].tolist()} meets the interior of boundary edge "
        f"({int(ea[k])}, {int(eb[k])}) of triangle {int(owner[k])}: overlapping triangles "
        "or a hanging vertex"
        for t, k in zip(tri, pe)
    ), len(tri))


# --------------------------------------------------------------------------
# Segments, Delaunay
# --------------------------------------------------------------------------


def _segment_keys(m: _Mesh):
    S = m.S
    ok = ((S >= 0) & (S < m.N)).all(axis=1) & (S[:, 0] != S[:, 1])
    lo = np.minimum(S[:, 0], S[:, 1])
    hi = np.maximum(S[:, 0], S[:, 1])
    return ok, lo * np.int64(max(m.N, 1)) + hi


def _check_segments(m: _Mesh, e: _Edges, probs: _Problems):
    if not len(m.S):
        return
    ok, skey = _segment_keys(m)
    probs.add("invalid subsegments", [
        f"segment {i} {m.S[i].tolist()} has an index out of range or repeats a vertex"
        for i in np.flatnonzero(~ok)
    ])
    if m.M == 0:
        return
    present = np.isin(skey, e.ukey)
    probs.add("subsegments missing from the triangles", [
        f"segment {i} {m.S[i].tolist()} is not an edge of any triangle"
        for i in np.flatnonzero(ok & ~present)
    ])


def _check_delaunay(m: _Mesh, e: _Edges, probs: _Problems):
    if not len(e.key):
        return
    g = m.good[e.tri]
    tw = e.twin
    sel = g & (tw >= 0) & (e.a < e.b)
    sel[sel] &= m.good[e.tri[tw[sel]]]
    if len(m.S):
        ok, skey = _segment_keys(m)
        sel &= ~np.isin(e.ukey, skey[ok])
    idx = np.flatnonzero(sel)
    if not idx.size:
        return
    A, B, C = m.V[e.a[idx]], m.V[e.b[idx]], m.V[e.apex[idx]]
    D = m.V[e.apex[tw[idx]]]
    s = _incircle_xy(A[:, 0], A[:, 1], B[:, 0], B[:, 1], C[:, 0], C[:, 1], D[:, 0], D[:, 1])
    bad = idx[s > 0]
    probs.add("non-Delaunay edges", (
        f"edge {{{int(e.a[k])}, {int(e.b[k])}}} is not locally Delaunay: vertex "
        f"{int(e.apex[e.twin[k]])} (triangle {int(e.tri[e.twin[k]])}) is strictly inside the "
        f"circumcircle of triangle {int(e.tri[k])}"
        for k in bad
    ), len(bad))


# --------------------------------------------------------------------------
# Input segments as chains of subsegments
# --------------------------------------------------------------------------


def _on_line(u, v, x) -> bool:
    """x lies on the line uv: exactly, or within ON_SEGMENT_RTOL."""
    if not all(map(math.isfinite, (*u, *v, *x))):
        return False
    scale = max(abs(u[0]), abs(u[1]), abs(v[0]), abs(v[1]), abs(x[0]), abs(x[1]))
    if scale == 0:
        return True
    k = -math.frexp(scale)[1]  # scale by a power of two: coordinates <= 1
    ux, uy, vx, vy, xx, xy = (math.ldexp(c, k) for c in (*u, *v, *x))
    dx, dy = vx - ux, vy - uy
    cross = dx * (xy - uy) - dy * (xx - ux)
    if abs(cross) <= ON_SEGMENT_RTOL * math.hypot(dx, dy):
        return True
    return orient_exact(u, v, x) == 0


class _Chains:
    """Segments as chains (J0, J1, interior output vertices)."""

    def __init__(self):
        self.chains: list[tuple[int, int, list[int]]] = []
        self.input_points: set | None = None


def _subseg_adjacency(m: _Mesh):
    ok, _ = _segment_keys(m)
    adj = defaultdict(list)
    for a, b in m.S[ok].tolist():
        adj[a].append(b)
        adj[b].append(a)
    return adj


def _pslg_chains(m: _Mesh, pslg, probs: _Problems) -> list:
    """Every input segment, where it meets the mesh, is a chain of subsegments.

    The output vertices (used by triangles or subsegments) lying on an input
    segment (exactly, or within ON_SEGMENT_RTOL) strictly between its
    endpoints cut it into pieces.  Each piece must be an output subsegment,
    or lie outside the mesh (its open segment meets no triangle): Triangle
    deletes subsegments that are eaten with holes and concavities.

    Returns the input segments as chains (J0, J1, inner output vertices).
    """
    iv = np.asarray(pslg.get("vertices", np.zeros((0, 2))), dtype=np.float64).reshape(-1, 2)
    iseg = _int_array(pslg.get("segments", np.zeros((0, 2))), 2).reshape(-1, 2)
    if not len(iseg):
        return []
    okidx = ((iseg >= 0) & (iseg < len(iv))).all(axis=1)
    probs.add("input segments out of range", (
        f"input segment {k} {iseg[k].tolist()} has an index out of range"
        for k in np.flatnonzero(~okidx)
    ), int((~okidx).sum()))
    U = np.where(okidx[:, None], iv[np.where(okidx[:, None], iseg, 0)[:, 0]], np.nan)
    W = np.where(okidx[:, None], iv[np.where(okidx[:, None], iseg, 0)[:, 1]], np.nan)
    keep = okidx & np.isfinite(U).all(1) & np.isfinite(W).all(1) & (U != W).any(1)
    segk = np.flatnonzero(keep)
    if not segk.size or not m.good.any():
        return []
    U, W = U[segk], W[segk]

    # Output vertices that matter: used by good triangles or by subsegments.
    ok, skey = _segment_keys(m)
    ids = np.unique(np.concatenate([m.Tc[m.good].ravel(), m.S[ok].ravel()]))
    ids = ids[np.isfinite(m.V[ids]).all(1)]
    X = m.V[ids]
    where = {}
    for w, p in zip(ids.tolist(), X.tolist()):
        where.setdefault(tuple(p), w)

    # Output vertices strictly inside each input segment.
    pbox = np.stack([X[:, 0], X[:, 0], X[:, 1], X[:, 1]], 1)
    # boxes widened by the tolerance: a vertex near a vertical or horizontal
    # segment may lie a rounding error outside its exact box
    slack = 2.0 * ON_SEGMENT_RTOL * np.abs(np.concatenate([U, W], 1)).max(1)
    sbox = np.stack([np.minimum(U[:, 0], W[:, 0]) - slack, np.maximum(U[:, 0], W[:, 0]) + slack,
                     np.minimum(U[:, 1], W[:, 1]) - slack, np.maximum(U[:, 1], W[:, 1]) + slack], 1)
    pp, ps = _box_pairs(pbox, sbox)
    if len(pp):
        u, w, x = U[ps], W[ps], X[pp]
        scale = np.maximum(np.abs(np.concatenate([u, w, x], 1)).max(1), 2.0**-1000)
        k = -np.frexp(scale)[1][:, None]
        su, sw, sx = np.ldexp(u, k), np.ldexp(w, k), np.ldexp(x, k)
        d = sw - su
        cross = d[:, 0] * (sx[:, 1] - su[:, 1]) - d[:, 1] * (sx[:, 0] - su[:, 0])
        near = np.abs(cross) <= ON_SEGMENT_RTOL * np.hypot(d[:, 0], d[:, 1])
        after_u = _sign2x2(x[:, 0], u[:, 0], w[:, 0], u[:, 0], u[:, 1], x[:, 1], w[:, 1], u[:, 1]) > 0
        before_w = _sign2x2(w[:, 0], x[:, 0], w[:, 0], u[:, 0], x[:, 1], w[:, 1], w[:, 1], u[:, 1]) > 0
        sel = near & after_u & before_w
        pp, ps = pp[sel], ps[sel]
        # position along the segment, in a per-segment power-of-two scale
        kk = -np.frexp(np.maximum(np.abs(np.concatenate([u, w], 1)).max(1), 2.0**-1000))[1]
        kk = kk[sel][:, None]
        su = np.ldexp(u[sel], kk)
        t = ((np.ldexp(x[sel], kk) - su) * (np.ldexp(w[sel], kk) - su)).sum(1)
    else:
        t = np.zeros(0)
    # Nodes: endpoints (t = -inf / +inf) and the inner vertices, per segment.
    ns = len(segk)
    uid = np.array([where.get(tuple(p), -1) for p in U.tolist()], dtype=np.int64)
    wid = np.array([where.get(tuple(p), -1) for p in W.tolist()], dtype=np.int64)
    node_seg = np.concatenate([np.arange(ns), ps, np.arange(ns)])
    node_t = np.concatenate([np.full(ns, -np.inf), t, np.full(ns, np.inf)])
    node_id = np.concatenate([uid, ids[pp], wid])
    node_xy = np.concatenate([U, X[pp], W])
    order = np.lexsort((node_t, node_seg))
    node_seg, node_id, node_xy = node_seg[order], node_id[order], node_xy[order]
    nn = len(order)
    # Piece i joins node i and node i + 1 of the same segment.  A subsegment
    # whose two ends are nodes of one segment covers every piece between them
    # (by rank, so that nearly coincident nodes may come in either order).
    S = m.S[ok]
    if len(S):
        ends = np.concatenate([S[:, 0], S[:, 1]])
        which = np.concatenate([np.arange(len(S)), np.arange(len(S))])
        valid = node_id >= 0
        nodes = np.flatnonzero(valid)
        nj, ej = _join(nodes, node_id[valid], np.arange(len(ends)), ends)
        # (subsegment, segment) pairs met at both ends
        key = which[ej].astype(np.int64) * np.int64(ns) + node_seg[nj]
        srt = np.lexsort((nj, key))
        key, nj = key[srt], nj[srt]
        same = np.flatnonzero(key[1:] == key[:-1])  # exactly two entries per pair
        lo = np.minimum(nj[same], nj[same + 1])
        hi = np.maximum(nj[same], nj[same + 1])
        cover = np.zeros(nn + 1, np.int64)
        np.add.at(cover, lo, 1)
        np.add.at(cover, hi, -1)
        covered_piece = np.cumsum(cover)[:-1] > 0
    else:
        covered_piece = np.zeros(nn, bool)
    a = np.arange(nn - 1)
    a = a[node_seg[a] == node_seg[a + 1]]
    b = a + 1
    ia, ib = node_id[a], node_id[b]
    covered = covered_piece[a]
    chains = []
    cuts = np.flatnonzero(node_seg[1:] != node_seg[:-1]) + 1
    for grp in np.split(node_id, cuts):
        if len(grp) >= 2 and grp[0] >= 0 and grp[-1] >= 0:
            chains.append((int(grp[0]), int(grp[-1]), grp[1:-1].tolist()))
    gaps = np.flatnonzero(~covered)
    if not gaps.size:
        return chains
    tri, g = _segments_meet_triangles(m, node_xy[a[gaps]], node_xy[b[gaps]])
    g = np.unique(g)
    msgs = []
    for j in g[:MAX_MESSAGES]:
        k = int(segk[node_seg[a[gaps[j]]]])
        i0, i1 = int(ia[gaps[j]]), int(ib[gaps[j]])
        msgs.append(
            f"input segment {k} {iseg[k].tolist()}: the piece from output vertex {i0} "
            f"{node_xy[a[gaps[j]]].tolist()} to {i1} {node_xy[b[gaps[j]]].tolist()} lies in "
            "the mesh but is not a chain of collinear subsegments"
        )
    probs.add("input segments missing", msgs, len(g))
    return chains


def _output_chains(m: _Mesh, chains: _Chains):
    """Segments as maximal straight chains of output subsegments.

    A chain passes through a vertex with exactly two subsegments that are
    collinear (see ON_SEGMENT_RTOL) and opposite, unless the vertex is an input
    vertex (when the input points are known).
    """
    adj = _subseg_adjacency(m)
    Vl = m.V.tolist()
    inp = chains.input_points
    through = set()
    for w, nb in adj.items():
        if inp is not None and tuple(Vl[w]) in inp:
            continue
        if len(nb) == 2 and nb[0] != nb[1]:
            a, b, p = tuple(Vl[nb[0]]), tuple(Vl[nb[1]]), tuple(Vl[w])
            if _on_line(a, b, p) and _dot_sign_scalar(p, a, p, b) < 0:
                through.add(w)
    done = set()
    for j, nb in adj.items():
        if j in through:
            continue
        for x in nb:
            if (j, x) in done:
                continue
            prev, cur, path = j, x, []
            while cur in through and len(path) <= len(adj):
                path.append(cur)
                n0, n1 = adj[cur]
                prev, cur = cur, (n1 if n0 == prev else n0)
            done.add((j, x))
            done.add((cur, prev))
            chains.chains.append((j, cur, path))


# --------------------------------------------------------------------------
# Angles and the exemption for small input angles
# --------------------------------------------------------------------------


def _angles(P):
    """Corner angles in degrees of the triangles P (M, 3, 2)."""
    out = np.empty(P.shape[:2])
    for i in range(3):
        a, b, c = P[:, i], P[:, (i + 1) % 3], P[:, (i + 2) % 3]
        u, w = b - a, c - a
        # exact power-of-two normalisation: no overflow or underflow below
        big = np.maximum(np.abs(u).max(axis=1), np.abs(w).max(axis=1))
        e = np.frexp(big)[1][:, None]
        u, w = np.ldexp(u, -e), np.ldexp(w, -e)
        cross = u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]
        dot = u[:, 0] * w[:, 0] + u[:, 1] * w[:, 1]
        out[:, i] = np.degrees(np.arctan2(np.abs(cross), dot))
    return out


def _wedges(m: _Mesh, chains: _Chains, limit: float):
    """Small wedges (angle < limit): apex id -> [(start direction, angle)] in degrees."""
    rays = defaultdict(list)
    V = m.V
    for j0, j1, path in chains.chains:
        first = path[0] if path else j1
        last = path[-1] if path else j0
        rays[j0].append(first)
        rays[j1].append(last)
    out = {}
    for j, ends in rays.items():
        d = sorted({math.degrees(math.atan2(V[x, 1] - V[j, 1], V[x, 0] - V[j, 0])) % 360.0
                    for x in ends})
        if len(d) < 2:
            continue
        w = []
        for k, a in enumerate(d):
            gap = (d[(k + 1) % len(d)] - a) % 360.0
            if gap < limit:
                w.append((a, gap))
        if w:
            out[j] = w
    return out


def _rel_angle(x, start):
    r = (x - start) % 360.0
    return r - 360.0 if r > 360.0 - 1e-7 else r


def _exempt(m: _Mesh, t: int, ang, chains: _Chains, wedges, mpw, subsegs) -> bool:
    tri = m.Tc[t].tolist()
    P = m.P[t]
    # (a) the smallest angle is at a corner J inside a wedge at J narrower than
    # both 60 degrees and the bound: every triangle there has a bad angle at J.
    i = int(np.argmin(ang))
    j = tri[i]
    if j in wedges:
        pj = P[i]
        b, c = P[(i + 1) % 3], P[(i + 2) % 3]
        db = math.degrees(math.atan2(b[1] - pj[1], b[0] - pj[0])) % 360.0
        dc = math.degrees(math.atan2(c[1] - pj[1], c[0] - pj[0])) % 360.0
        for start, gap in wedges[j]:
            rb, rc = _rel_angle(db, start), _rel_angle(dc, start)
            if -1e-7 <= rb <= rc <= gap + 1e-7:
                return True
    # (b) Miller-Pav-Walkington: a shortest edge joins two points on two
    # segments sharing an endpoint J, at equal distances from J.
    L = [math.hypot(*(P[(k + 2) % 3] - P[(k + 1) % 3]).tolist()) for k in range(3)]
    lmin = min(L)
    for k in range(3):
        if L[k] > lmin * (1.0 + 5e-13):
            continue
        p1, p2 = tri[(k + 1) % 3], tri[(k + 2) % 3]
        if (min(p1, p2), max(p1, p2)) in subsegs:
            continue
        for c1, J1, d1 in mpw.get(p1, ()):
            for c2, J2, d2 in mpw.get(p2, ()):
                # squared distances within a factor 1 +- MPW_RATIO, as Triangle
                if c1 != c2 and J1 == J2 and d2 > 0 and (
                        1 - MPW_RATIO < (d1 / d2) ** 2 < 1 + MPW_RATIO):
                    return True
    return False


def _mpw_table(m: _Mesh, chains: _Chains):
    V = m.V
    table = defaultdict(list)
    inp = chains.input_points
    for c, (j0, j1, path) in enumerate(chains.chains):
        J0, J1 = tuple(V[j0].tolist()), tuple(V[j1].tolist())
        for p in path:
            pp = tuple(V[p].tolist())
            if inp is not None and pp in inp:
                continue  # input vertices are not Steiner points
            for J in (J0, J1):
                table[p].append((c, J, math.hypot(pp[0] - J[0], pp[1] - J[1])))
    return table


def _quality(m: _Mesh, pslg, min_angle, probs: _Problems | None, pslg_chains=None):
    """Angles of the good triangles; bad and exempt triangle indices."""
    idx = np.flatnonzero(m.good)
    ang = _angles(m.P[idx]) if idx.size else np.zeros((0, 3))
    bad_t, exempt_t = [], []
    if min_angle is not None and idx.size:
        mins = ang.min(axis=1)
        badpos = np.flatnonzero(mins < min_angle * (1.0 - ANGLE_RTOL))
        if badpos.size:
            sink = probs if probs is not None else _Problems()
            chains = _Chains()
            if pslg is not None:
                iv = np.asarray(pslg.get("vertices", np.zeros((0, 2))), dtype=np.float64)
                chains.input_points = {(float(x), float(y)) for x, y in iv.reshape(-1, 2).tolist()}
                if pslg_chains is None:
                    pslg_chains = _pslg_chains(m, pslg, _Problems())
                chains.chains.extend(pslg_chains)
            _output_chains(m, chains)
            wedges = _wedges(m, chains, min(SMALL_INPUT_ANGLE, min_angle))
            mpw = _mpw_table(m, chains)
            ok, _ = _segment_keys(m)
            subsegs = {(min(a, b), max(a, b)) for a, b in m.S[ok].tolist()}
            for pos in badpos:
                t = int(idx[pos])
                (exempt_t if _exempt(m, t, ang[pos], chains, wedges, mpw, subsegs) else bad_t).append(t)
            sink.add("triangles below the angle bound", (
                f"triangle {t} {m.T[t].tolist()} has minimum angle "
                f"{ang[np.searchsorted(idx, t)].min():.6f} < {min_angle} degrees "
                "(no small input angle explains it)"
                for t in bad_t
            ), len(bad_t))
    return idx, ang, bad_t, exempt_t


def _signed_areas(m: _Mesh, mask):
    P = m.P[mask]
    u = P[:, 1] - P[:, 0]
    w = P[:, 2] - P[:, 0]
    return 0.5 * (u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])


def _check_area(m: _Mesh, max_area, probs: _Problems):
    idx = np.flatnonzero(m.good)
    area = _signed_areas(m, idx)
    bad = np.flatnonzero(area > max_area * (1.0 + AREA_RTOL))
    probs.add("triangles above the area bound", (
        f"triangle {int(idx[k])} {m.T[idx[k]].tolist()} has area {area[k]:.17g} > {max_area}"
        for k in bad
    ), len(bad))


def _check_markers(m: _Mesh, result, e: _Edges, probs: _Problems):
    msgs = []
    vm = result.get("vertex_markers")
    sm = result.get("segment_markers")
    if vm is not None:
        vm = np.asarray(vm).reshape(-1)
        if len(vm) != m.N:
            msgs.append(f"vertex_markers has {len(vm)} entries for {m.N} vertices")
            vm = None
    if sm is not None:
        sm = np.asarray(sm).reshape(-1)
        if len(sm) != len(m.S):
            msgs.append(f"segment_markers has {len(sm)} entries for {len(m.S)} segments")
            sm = None
    for name in ("triangle_attributes", "triangle_max_area", "neighbors"):
        x = result.get(name)
        if x is not None and len(np.asarray(x)) != m.M:
            msgs.append(f"{name} has {len(np.asarray(x))} rows for {m.M} triangles")
    probs.add("array lengths", msgs)
    if not len(m.S) or not len(e.key):
        return
    # Boundary subsegments carry nonzero markers, and so do their endpoints
    # (reference 2.12 rules 3-5).
    ok, skey = _segment_keys(m)
    bmask = m.topo[e.tri] & (e.twin < 0)
    bkeys = e.ukey[bmask]
    onb = ok & np.isin(skey, bkeys)
    msgs = []
    if sm is not None:
        msgs += [f"boundary segment {i} {m.S[i].tolist()} has marker 0"
                 for i in np.flatnonzero(onb & (sm == 0))]
    if vm is not None:
        ends = np.unique(m.S[onb].ravel())
        msgs += [f"vertex {int(v)} on a boundary segment has marker 0"
                 for v in ends[vm[ends] == 0]]
    probs.add("boundary markers", msgs)


# --------------------------------------------------------------------------
# Public entry points
# --------------------------------------------------------------------------


def check_mesh(result, pslg=None, min_angle=None, *, delaunay=True, max_area=None,
               markers=True) -> list[str]:
    """Check a mesh in the ``triangle`` package's output format.

    result     dict with ``vertices`` (N, 2), ``triangles`` (M, 3) or (M, 6)
               (a missing key means an empty mesh), optional ``segments``
               (the constrained subsegments) and markers.
    pslg       the input dict; every input segment must appear as a chain of
               collinear output subsegments (see ON_SEGMENT_RTOL), except for
               pieces lying outside the mesh (eaten with holes/exterior).
    min_angle  degrees; triangles below it are problems unless a small input
               angle explains them (see ``quality_report``).
    delaunay   check the constrained Delaunay property (exact incircle) on
               every edge that is shared by two triangles and is not a segment.
    max_area   every triangle's area must be <= max_area * (1 + 1e-12).
    markers    check array lengths, and that boundary subsegments and their
               endpoints have nonzero markers (when markers are present).

    Returns a list of human-readable problems; empty means valid.
    """
    probs = _Problems()
    m = _Mesh(result, probs)
    if not m.ok:
        return probs.lines
    _check_triangles(m, probs)
    e = _Edges(m)
    _check_edges(m, e, probs)
    _check_overlap(m, e, probs)
    _check_segments(m, e, probs)
    if delaunay:
        _check_delaunay(m, e, probs)
    pslg_chains = _pslg_chains(m, pslg, probs) if pslg is not None else None
    if min_angle is not None:
        _quality(m, pslg, min_angle, probs, pslg_chains)
    if max_area is not None:
        _check_area(m, max_area, probs)
    if markers:
        _check_markers(m, result, e, probs)
    return probs.lines


def quality_report(result, pslg=None, min_angle=None) -> dict:
    """Angle statistics of the strictly counter-clockwise triangles.

    n_bad     triangles whose smallest angle is below min_angle (relative
              tolerance 1e-9), exempt ones included;
    n_exempt  those of them explained by a small input angle:
      (a) the smallest angle is at a corner J, J is the apex of a wedge
          between two angularly consecutive segments at J whose angle is
          below both SMALL_INPUT_ANGLE (60 degrees) and min_angle (so every
          triangle at J inside it has a bad angle at J), and the triangle
          lies inside that wedge;
      (b) Miller-Pav-Walkington (reference 4.8.4): an edge of minimum length
          (relative 1e-12) that is not a subsegment joins two Steiner
          points lying on two different segments that share an endpoint J,
          with squared distances to J equal within a factor 1 +- 0.001.
      Segments are the maximal straight chains of output subsegments (cut at
      input vertices when ``pslg`` is given, since input vertices are not
      Steiner points), plus, when ``pslg`` is given, the input segments with
      the output vertices on them (so J is the input segment's endpoint even
      when other segments cross it, as in Triangle).
    """
    m = _Mesh(result, _Problems())
    if not m.ok:
        raise ValueError("malformed mesh arrays")
    idx, ang, bad_t, exempt_t = _quality(m, pslg, min_angle, None)
    return {
        "n_triangles": int(idx.size),
        "min_angle_deg": float(ang.min()) if idx.size else float("nan"),
        "max_angle_deg": float(ang.max()) if idx.size else float("nan"),
        "n_bad": len(bad_t) + len(exempt_t),
        "n_exempt": len(exempt_t),
        "area_total": mesh_area(result),
    }


def mesh_area(result) -> float:
    """math.fsum of the signed areas of the triangles (first three columns)."""
    v = np.asarray(result.get("vertices", np.zeros((0, 2))), dtype=np.float64).reshape(-1, 2)
    t = _int_array(result.get("triangles", np.zeros((0, 3))), 3)
    if not len(t):
        return 0.0
    P = v[t[:, :3]]
    u = P[:, 1] - P[:, 0]
    w = P[:, 2] - P[:, 0]
    return math.fsum((0.5 * (u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])).tolist())
