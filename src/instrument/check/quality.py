"""Quality: angles against a bound, with the small-input-angle exemptions, and areas.

A triangle below the angle bound is a problem unless a small input angle
explains it: (a) it lies in a wedge between two consecutive segments at a
vertex narrower than both ``SMALL_INPUT_ANGLE`` and the bound, or (b) its
shortest edge joins Steiner points at equal distances from a shared segment
endpoint (Miller, Pav and Walkington; ``MPW_RATIO``).  A point set refined
without segments has its boundary edges as segments (``_hull_segments``).  ``quality_report`` in
the package documents the rules in full.
"""

from __future__ import annotations

import copy
import math
from collections import defaultdict

import numpy as np

from .chains import Chains, input_chains, output_chains
from .view import Edges, MeshView, Problems, int_array, segment_keys


#: Input angles (degrees) below which rule (a) of the angle exemption applies.
SMALL_INPUT_ANGLE = 60.0
#: Relative tolerance of the angle bound.
ANGLE_RTOL = 1e-9
#: Relative tolerance of the area bound.
AREA_RTOL = 1e-12
#: Miller-Pav-Walkington: squared distances equal within this factor.
MPW_RATIO = 0.001


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


def _wedges(m: MeshView, chains: Chains, limit: float):
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


def _exempt(m: MeshView, t: int, ang, chains: Chains, wedges, mpw, subsegs) -> bool:
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
                # (the ratio first: distances 1e-300 and 1e300 apart made
                # its square overflow, an OverflowError out of the checker)
                if c1 != c2 and J1 == J2 and d2 > 0 and 0.5 < d1 / d2 < 2.0 and (
                        1 - MPW_RATIO < (d1 / d2) ** 2 < 1 + MPW_RATIO):
                    return True
    return False


def _mpw_table(m: MeshView, chains: Chains):
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


def _hull_segments(m: MeshView) -> MeshView:
    """``m`` with the boundary edges of its good triangles as its subsegments.

    A point set refined without ``-p`` or ``-c`` has no segments in its input
    or output, but Triangle (and ours) makes the boundary edges subsegments
    before refining, and the Miller-Pav-Walkington exemption applies to
    Steiner points on them: two hull edges meeting at J at any angle (the
    rule does not measure it) leave a triangle whose shortest edge joins
    points on the same shell around J.  Without these segments such a
    triangle would look unexplained."""
    e = Edges(m)
    good = m.good[e.tri]
    twin_good = np.zeros(len(e.tri), dtype=bool)
    has = e.twin >= 0
    twin_good[has] = m.good[e.tri[e.twin[has]]]
    rim = good & ~twin_good
    view = copy.copy(m)
    view.S = np.stack([e.a[rim], e.b[rim]], axis=1).astype(np.int64)
    return view


def classify_angles(m: MeshView, pslg, min_angle, probs: Problems | None, pslg_chains=None):
    """Angles of the good triangles; bad and exempt triangle indices."""
    idx = np.flatnonzero(m.good)
    ang = _angles(m.P[idx]) if idx.size else np.zeros((0, 3))
    bad_t, exempt_t = [], []
    if min_angle is not None and idx.size:
        mins = ang.min(axis=1)
        badpos = np.flatnonzero(mins < min_angle * (1.0 - ANGLE_RTOL))
        if badpos.size:
            sink = probs if probs is not None else Problems()
            in_segs = int_array(pslg.get("segments", np.zeros((0, 2))), 2) if pslg is not None else ()
            seg_view = _hull_segments(m) if not len(m.S) and not len(in_segs) else m
            chains = Chains()
            if pslg is not None:
                iv = np.asarray(pslg.get("vertices", np.zeros((0, 2))), dtype=np.float64)
                chains.input_points = {(float(x), float(y)) for x, y in iv.reshape(-1, 2).tolist()}
                if pslg_chains is None:
                    pslg_chains = input_chains(m, pslg, Problems())
                chains.chains.extend(pslg_chains)
            output_chains(seg_view, chains)
            wedges = _wedges(m, chains, min(SMALL_INPUT_ANGLE, min_angle))
            mpw = _mpw_table(m, chains)
            ok, _ = segment_keys(seg_view)
            subsegs = {(min(a, b), max(a, b)) for a, b in seg_view.S[ok].tolist()}
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


def _signed_areas(m: MeshView, mask):
    P = m.P[mask]
    u = P[:, 1] - P[:, 0]
    w = P[:, 2] - P[:, 0]
    return 0.5 * (u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0])


def check_area(m: MeshView, max_area, probs: Problems):
    """Every good triangle's area is at most max_area * (1 + AREA_RTOL)."""
    idx = np.flatnonzero(m.good)
    area = _signed_areas(m, idx)
    bad = np.flatnonzero(area > max_area * (1.0 + AREA_RTOL))
    probs.add("triangles above the area bound", (
        f"triangle {int(idx[k])} {m.T[idx[k]].tolist()} has area {area[k]:.17g} > {max_area}"
        for k in bad
    ), len(bad))
