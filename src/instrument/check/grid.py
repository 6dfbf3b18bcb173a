"""Candidate pairs of overlapping bounding boxes, found with a multi-level grid.

The overlap and segment checks test exact predicates on pairs (triangle,
segment) whose boxes meet; testing all pairs would be quadratic.  Each box
goes to the grid level whose cell size is at least its size (powers of two
times a base size near the median triangle), so it touches at most 3 x 3
cells there; a pair is found at the level of the larger of its two boxes.
"""

from __future__ import annotations

import math

import numpy as np


_CELL_BITS = 30


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


def join_keys(a_obj, a_key, b_obj, b_key):
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


def box_pairs(tbox, ebox):
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
        a, b = join_keys(to, tk, eo, ek)
        pairs_t.append(ti[a])
        pairs_e.append(ei[b])
    for lev in np.unique(el):
        ei = np.flatnonzero(el == lev)
        ti = np.flatnonzero(tl < lev)
        if not ti.size:
            continue
        to, tk = _cells(tbox[ti], lev, h0, x0, y0)
        eo, ek = _cells(ebox[ei], lev, h0, x0, y0)
        a, b = join_keys(to, tk, eo, ek)
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
