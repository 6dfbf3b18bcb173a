"""Candidate pairs of overlapping bounding boxes, found with a multi-level grid.

The overlap and segment checks test exact predicates on pairs (triangle,
segment) whose boxes meet; testing all pairs would be quadratic.  Each box
goes to the grid level whose cells are the smallest power of two at least
its size, so it touches at most 2 x 2 cells there; a pair is found at the
level of the larger of its two boxes.

The levels are not bounded below by the input's extent: a mesh graded over
hundreds of decades (1e-304 near one corner, 1e300 across) puts its tiny
triangles in cells of their own size, not all in one cell at the finest
level a fixed-width integer index allows, where every pair of them would be
a candidate.  A cell's index is ``floor(x / 2^level)`` as a double: dividing
by a power of two and flooring are exact (or monotone where they round, near
the subnormals), so boxes whose intervals overlap always share a cell, and a
box is never narrower than the spacing of doubles at its coordinates, so the
index stays below 2^53 and the neighbouring index ``+ 1`` is exact.
"""

from __future__ import annotations

import numpy as np

_TOP = 1024  # 2^1024 is no double: a box that size (or larger) is at the top level, one cell
_BOTTOM = -1074  # the smallest subnormal
_LARGEST = np.finfo(np.float64).max


def _levels(dim: np.ndarray) -> np.ndarray:
    """The smallest exponent e with dim <= 2^e, per box."""
    mant, exp = np.frexp(dim)  # dim = mant * 2^exp, mant in [0.5, 1) (0 for 0)
    lev = exp.astype(np.int64) - (mant == 0.5)  # a power of two is its own cell size
    lev = np.where(dim > 0, lev, _BOTTOM)
    lev = np.where(np.isinf(dim), _TOP, lev)
    return np.clip(lev, _BOTTOM, _TOP)


def _cells(box: np.ndarray, lev: int) -> tuple[np.ndarray, np.ndarray]:
    """Grid cells of level ``lev`` that the boxes touch: (box, cell) pairs,
    a cell as a complex number (x index + y index * 1j)."""
    def index(x):
        if lev >= _TOP:
            return np.zeros_like(x)
        with np.errstate(all="ignore"):  # beyond the doubles (only a zero-size box's level): the largest one
            return np.clip(np.floor(np.ldexp(x, -lev)), -_LARGEST, _LARGEST)

    ix0, ix1 = index(box[:, 0]), index(box[:, 1])
    iy0, iy1 = index(box[:, 2]), index(box[:, 3])
    objs, keys = [], []
    ar = np.arange(len(box))
    for dx in range(3):  # a box at most one cell wide touches 2 cells per axis; 3 allows for rounding
        for dy in range(3):
            mask = (ix0 + dx <= ix1) & (iy0 + dy <= iy1)
            objs.append(ar[mask])
            key = np.empty(int(mask.sum()), dtype=np.complex128)  # not x + 1j * y: 1j * inf is nan + inf j
            key.real = ix0[mask] + dx
            key.imag = iy0[mask] + dy
            keys.append(key)
    return np.concatenate(objs), np.concatenate(keys)


def join_keys(a_obj, a_key, b_obj, b_key):
    """Every (a, b) pair with equal keys (any sortable dtype)."""
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
    """Candidate (triangle, edge) pairs whose closed bounding boxes overlap.
    Boxes are rows (xmin, xmax, ymin, ymax) of finite doubles."""
    with np.errstate(over="ignore"):  # a width beyond the largest double: inf, the top level
        tdim = np.maximum(tbox[:, 1] - tbox[:, 0], tbox[:, 3] - tbox[:, 2])
        edim = np.maximum(ebox[:, 1] - ebox[:, 0], ebox[:, 3] - ebox[:, 2])
        tl = _levels(tdim)
        el = _levels(edim)
    pairs_t, pairs_e = [], []
    for big, small, blev, slev, flip in ((tbox, ebox, tl, el, False), (ebox, tbox, el, tl, True)):
        for lev in np.unique(blev):
            bi = np.flatnonzero(blev == lev)
            # the larger box's level finds the pair; ties (equal levels) once, with the triangles
            si = np.flatnonzero(slev < lev if flip else slev <= lev)
            if not si.size:
                continue
            bo, bk = _cells(big[bi], int(lev))
            so, sk = _cells(small[si], int(lev))
            a, b = join_keys(bo, bk, so, sk)
            if flip:
                pairs_t.append(si[b])
                pairs_e.append(bi[a])
            else:
                pairs_t.append(bi[a])
                pairs_e.append(si[b])
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
