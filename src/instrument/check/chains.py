"""Segments as chains of subsegments: the input's, and the output's own.

``input_chains`` checks that every input segment, where it lies in the mesh,
is covered by collinear output subsegments, and returns it as a chain (its
endpoints and the output vertices on it).  ``output_chains`` rebuilds the
segments of an output alone as its maximal straight chains of subsegments.
The quality check uses both to find small input angles.

Triangle moves split points onto a segment's line only once in floating
point, so "on the segment" allows ``ON_SEGMENT_RTOL``.
"""

from __future__ import annotations

import math
from collections import defaultdict

import numpy as np

from .boxes import overlapping
from .exact import dot_sign_scalar, orient_exact, orient_signs, sign2x2
from .structure import segments_meet_triangles
from .view import MAX_MESSAGES, MeshView, Problems, int_array, join_keys, segment_keys


#: A vertex counts as lying on a segment if it is exactly on it, or if its
#: distance to the segment's line is at most this times (up to a factor 2) the
#: largest absolute coordinate involved.  Triangle moves split points onto the
#: line only once in floating point, so they are typically off by <= ~1 ulp.
ON_SEGMENT_RTOL = 2.0**-40


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


def _exact_ranks(node_seg, node_t, node_xy, U, W) -> np.ndarray:
    """A tie-break for nodes of one segment whose rounded positions ``t`` are
    equal: their exact order along the segment (Fractions, only for the tied
    nodes).  Without it two vertices a hair apart (an input vertex at (1,
    1e-50) beside the segment's own vertex at (1, 0)) could come in the wrong
    order, and the piece between the wrong pair would seem to cross the mesh."""
    rank = np.zeros(len(node_t), dtype=np.int64)
    finite = np.isfinite(node_t)
    key = np.lexsort((node_t, node_seg))
    same = (node_seg[key][1:] == node_seg[key][:-1]) & (node_t[key][1:] == node_t[key][:-1]) & finite[key][1:]
    if not same.any():
        return rank
    from fractions import Fraction

    groups = defaultdict(list)
    for i in np.flatnonzero(same):
        for j in (key[i], key[i + 1]):
            groups[(int(node_seg[j]), float(node_t[j]))].append(int(j))
    for (k, _), members in groups.items():
        ux, uy = (Fraction(c) for c in U[k])
        dx, dy = Fraction(W[k][0]) - ux, Fraction(W[k][1]) - uy
        exact = sorted(set(members), key=lambda j: (Fraction(node_xy[j][0]) - ux) * dx + (Fraction(node_xy[j][1]) - uy) * dy)
        for r, j in enumerate(exact):
            rank[j] = r
    return rank


class Chains:
    """Segments as chains (J0, J1, interior output vertices)."""

    def __init__(self):
        self.chains: list[tuple[int, int, list[int]]] = []
        self.input_points: set | None = None


def _subseg_adjacency(m: MeshView):
    ok, _ = segment_keys(m)
    adj = defaultdict(list)
    for a, b in m.S[ok].tolist():
        adj[a].append(b)
        adj[b].append(a)
    return adj


def _positions(u, w, x):
    """Positions of the points x along the segments u w (rows): the dot
    product of x - u with w - u brought to [0.5, 1] by a power of two.  Only
    the order matters (exact ties are broken by ``_exact_ranks``); the
    difference x - u is not scaled first, so that points 1e-300 from the end
    of a segment 1e300 long do not all come out at 0, which would tie
    (hundreds of thousands of them on a mesh graded over 600 decades) and
    send them all to the exact, Fraction-based tie-break."""
    kk = -np.frexp(np.maximum(np.abs(np.concatenate([u, w], 1)).max(1), 2.0**-1000))[1][:, None]
    d = np.ldexp(w, kk) - np.ldexp(u, kk)  # w - u, scaled: no overflow
    d = np.ldexp(d, -np.frexp(np.maximum(np.abs(d).max(1), 2.0**-1074))[1][:, None])
    with np.errstate(over="ignore", invalid="ignore"):
        t = ((x - u) * d).sum(1)
    bad = ~np.isfinite(t)  # x - u beyond the largest double: scaled as well
    if bad.any():
        t[bad] = ((np.ldexp(x[bad], kk[bad]) - np.ldexp(u[bad], kk[bad])) * d[bad]).sum(1)
    return t


def _inner_vertices(U, W, X, pbox, sbox):
    """(vertex, segment, position) for the vertices X lying on the segments
    U W strictly between their ends (see ON_SEGMENT_RTOL), found among the
    pairs whose boxes meet, chunk by chunk; sorted by vertex, then segment."""
    found_p, found_s, found_t = [np.zeros(0, np.int64)], [np.zeros(0, np.int64)], [np.zeros(0)]
    for pp, ps in overlapping(pbox, sbox):
        u, w, x = U[ps], W[ps], X[pp]
        scale = np.maximum(np.abs(np.concatenate([u, w, x], 1)).max(1), 2.0**-1000)
        k = -np.frexp(scale)[1][:, None]
        su, sw, sx = np.ldexp(u, k), np.ldexp(w, k), np.ldexp(x, k)
        d = sw - su
        cross = d[:, 0] * (sx[:, 1] - su[:, 1]) - d[:, 1] * (sx[:, 0] - su[:, 0])
        near = np.abs(cross) <= ON_SEGMENT_RTOL * np.hypot(d[:, 0], d[:, 1])
        after_u = sign2x2(x[:, 0], u[:, 0], w[:, 0], u[:, 0], u[:, 1], x[:, 1], w[:, 1], u[:, 1]) > 0
        before_w = sign2x2(w[:, 0], x[:, 0], w[:, 0], u[:, 0], x[:, 1], w[:, 1], w[:, 1], u[:, 1]) > 0
        sel = near & after_u & before_w
        found_t.append(_positions(u[sel], w[sel], x[sel]))
        found_p.append(pp[sel])
        found_s.append(ps[sel])
    pp, ps, t = np.concatenate(found_p), np.concatenate(found_s), np.concatenate(found_t)
    order = np.lexsort((ps, pp))
    return pp[order], ps[order], t[order]


def _partners(S) -> defaultdict:
    """Output vertex -> the other ends of its subsegments (rows of S)."""
    partners = defaultdict(list)
    for a, b in S.tolist():
        partners[a].append(b)
        partners[b].append(a)
    return partners


def _drop_bypassed_inputs(pp, ps, t, ids, X, U, W, iv, S):
    """Leave out of a segment's nodes the input vertices that lie within
    the tolerance of it but not exactly on it, where no output subsegment
    along that segment ends at them: such a vertex is on one side of the
    segment, and the chain may pass it by (Triangle's rule, and ours: an
    input vertex is on a segment only when exactly on it).  Counted as a node
    it made a piece that no subsegment covers: an input vertex 2^-1022 inside
    the side x = 0 of a square, an ulp from where a segment crosses that
    side, projected beyond the crossing along the segment (concurrent-segments,
    seed 2); the same at 2^-126 where the vertex is the end of another
    segment, whose subsegment ends there but runs elsewhere (crossing-segments,
    campaign seed 3201).  Where a subsegment on the segment's line ends at
    it, it stays a node."""
    if not len(pp):
        return pp, ps, t
    def rows(a):  # points as byte strings (+ 0.0: -0.0 is 0.0)
        return np.ascontiguousarray(a + 0.0).view(np.dtype((np.void, 16))).ravel()

    candidates = np.flatnonzero(np.isin(rows(X[pp]), rows(iv)))
    if not len(candidates):
        return pp, ps, t
    partners = _partners(S)
    where = {w: k for k, w in enumerate(ids.tolist())}
    keep = np.ones(len(pp), bool)
    for k in candidates.tolist():
        p = tuple(X[pp[k]].tolist())
        u, w = tuple(U[ps[k]].tolist()), tuple(W[ps[k]].tolist())
        if orient_exact(u, w, p) == 0:
            continue
        along = (q for q in partners.get(int(ids[pp[k]]), ()) if q in where)
        keep[k] = any(_on_line(u, w, tuple(X[where[q]].tolist())) for q in along)
    return pp[keep], ps[keep], t[keep]


def _same_line(U, W, j, k) -> bool:
    """Input segments j and k lie on one line within the tolerance (the ends
    of one are on the other's line)."""
    return (all(_on_line(U[k], W[k], p) for p in (U[j], W[j]))
            or all(_on_line(U[j], W[j], p) for p in (U[k], W[k])))


def _drop_other_lines(pp, ps, t, ids, X, U, W, S, ends):
    """Leave out of a segment k's nodes the vertices within the tolerance of
    k but not exactly on it that lie exactly on another input segment j (not
    on k's line), where no subsegment joins them to a node or an end of k off
    j's line: their subsegments run along j, near k only where j meets k
    within the tolerance's reach.  Counted as nodes they made pieces that no
    subsegment covers: segment 8 of regressions/concurrent-crossings-fold-pq.json crosses
    the top side of the unit square 7 ulps beside the corner (1, 1), and under
    pq the right side's vertices (1, 1 - 2^-48 ... 1 - 2^-40), each within
    2^-40 of segment 8's line, came before that crossing along segment 8,
    after its end outside the mesh (Triangle's mesh and ours alike).  A
    crossing vertex of j and k stays a node: its subsegments along k leave j's
    line.  ``ends`` maps each segment to its ends' output vertices."""
    if not len(pp):
        return pp, ps, t
    exact = orient_signs(U[ps], W[ps], X[pp]) == 0
    on = defaultdict(list)  # vertex (row of X) -> the segments it is exactly on
    for k in np.flatnonzero(exact).tolist():
        on[int(pp[k])].append(int(ps[k]))
    candidates = [k for k in np.flatnonzero(~exact).tolist() if int(pp[k]) in on]
    if not candidates:
        return pp, ps, t
    keep = np.ones(len(pp), bool)
    nodes = defaultdict(set)  # segment -> its nodes and ends (output vertices)
    for v, k in zip(ids[pp].tolist(), ps.tolist()):
        nodes[k].add(v)
    partners = _partners(S)
    xy = dict(zip(ids.tolist(), map(tuple, X.tolist())))
    for c in candidates:
        k = int(ps[c])
        others = [j for j in on[int(pp[c])] if j != k and not _same_line(U, W, j, k)]
        if not others:
            continue
        along = [q for q in partners.get(int(ids[pp[c]]), ()) if q in nodes[k] or q in ends[k]]
        keep[c] = any(all(orient_exact(U[j], W[j], xy[q]) != 0 for j in others) for q in along if q in xy)
    return pp[keep], ps[keep], t[keep]


def input_chains(m: MeshView, pslg, probs: Problems) -> list:
    """Every input segment, where it meets the mesh, is a chain of subsegments.

    The output vertices (used by triangles or subsegments) lying on an input
    segment (exactly, or within ON_SEGMENT_RTOL) strictly between its
    endpoints cut it into pieces.  Each piece must be an output subsegment,
    or lie outside the mesh (its open segment meets no triangle): Triangle
    deletes subsegments that are eaten with holes and concavities.

    Returns the input segments as chains (J0, J1, inner output vertices).
    """
    iv = np.asarray(pslg.get("vertices", np.zeros((0, 2))), dtype=np.float64).reshape(-1, 2)
    iseg = int_array(pslg.get("segments", np.zeros((0, 2))), 2).reshape(-1, 2)
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
    ok, skey = segment_keys(m)
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
    pp, ps, t = _inner_vertices(U, W, X, pbox, sbox)
    pp, ps, t = _drop_bypassed_inputs(pp, ps, t, ids, X, U, W, iv, m.S[ok])
    ns = len(segk)
    uid = np.array([where.get(tuple(p), -1) for p in U.tolist()], dtype=np.int64)
    wid = np.array([where.get(tuple(p), -1) for p in W.tolist()], dtype=np.int64)
    pp, ps, t = _drop_other_lines(pp, ps, t, ids, X, U, W, m.S[ok], list(zip(uid.tolist(), wid.tolist())))
    # Nodes: endpoints (t = -inf / +inf) and the inner vertices, per segment.
    node_seg = np.concatenate([np.arange(ns), ps, np.arange(ns)])
    node_t = np.concatenate([np.full(ns, -np.inf), t, np.full(ns, np.inf)])
    node_id = np.concatenate([uid, ids[pp], wid])
    node_xy = np.concatenate([U, X[pp], W])
    node_rank = _exact_ranks(node_seg, node_t, node_xy, U, W)
    order = np.lexsort((node_rank, node_t, node_seg))
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
        nj, ej = join_keys(nodes, node_id[valid], np.arange(len(ends)), ends)
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
    tri, g = segments_meet_triangles(m, node_xy[a[gaps]], node_xy[b[gaps]])
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


def output_chains(m: MeshView, chains: Chains):
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
            if _on_line(a, b, p) and dot_sign_scalar(p, a, p, b) < 0:
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
