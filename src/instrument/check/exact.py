"""Exact orientation and incircle signs (the checker's arithmetic).

Every sign the checker relies on is exact.  A vectorised floating-point
filter (Shewchuk's stage-A error bounds) certifies most signs, and the
entries it cannot certify are recomputed with Python integers: every double
is an integer times a power of two, so a shared power-of-two scale turns a
row of coordinates into integers without rounding.  Differences too small or
too large for the filter's products go to the integer path as well.

Nothing here comes from the engine's predicates (``instrument.core``): the
checker is the oracle the engine is tested against, so it computes its signs
another way.
"""

from __future__ import annotations

import numpy as np


_EPS = 2.0**-53
_CCW_BOUND = (3.0 + 16.0 * _EPS) * _EPS
_ICC_BOUND = (10.0 + 96.0 * _EPS) * _EPS
# Differences outside this range (other than exact zeros) go to the exact
# path, so that no product in the filters can underflow or overflow.
_SAFE_LO = 2.0**-200
_SAFE_HI = 2.0**200


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


#: Rows sent to the integer path at once: over hundreds of decades an exact
#: coordinate is an integer of thousands of bits, so the 550,000 incircle
#: tests of a graded mesh held at once took over a gigabyte.
EXACT_CHUNK = 1 << 15


def _exact_rows(need):
    """The rows (indices) where ``need`` holds, in chunks of EXACT_CHUNK."""
    bad = np.flatnonzero(need)
    for i in range(0, bad.size, EXACT_CHUNK):
        yield bad[i:i + EXACT_CHUNK]


def _obj_sign(det):
    return (det > 0).astype(np.int8) - (det < 0).astype(np.int8)


def _safe(*diffs):
    ok = np.ones(diffs[0].shape, dtype=bool)
    for d in diffs:
        ad = np.abs(d)
        ok &= (ad == 0) | ((ad >= _SAFE_LO) & (ad <= _SAFE_HI))
    return ok


def sign2x2(a, b, c, d, e, f, g, h):
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
    for bad in _exact_rows(~sure):
        A, B, C, D, E, F, G, H = _object_ints([v[bad] for v in (a, b, c, d, e, f, g, h)])
        out[bad] = _obj_sign((A - B) * (C - D) - (E - F) * (G - H))
    return out


def orient_xy(ax, ay, bx, by, cx, cy):
    """Exact orientation signs (int8 array) of points given by coordinate arrays;
    0 when two of the three points coincide.  Inputs must be finite."""
    s = sign2x2(bx, ax, cy, ay, by, ay, cx, ax)
    same = ((ax == bx) & (ay == by)) | ((bx == cx) & (by == cy)) | ((ax == cx) & (ay == cy))
    s[same] = 0
    return s


def orient_signs(a, b, c):
    """Exact orientation signs of rows of point arrays a, b, c (n, 2)."""
    a, b, c = (np.asarray(p, dtype=np.float64).reshape(-1, 2) for p in (a, b, c))
    _require_finite(a, b, c)
    return orient_xy(a[:, 0], a[:, 1], b[:, 0], b[:, 1], c[:, 0], c[:, 1])


def incircle_xy(ax, ay, bx, by, cx, cy, dx, dy):
    """Exact incircle signs (int8 array) of points given by coordinate arrays
    (see incircle_exact); 0 when d coincides with a, b or c.  Inputs must be finite."""
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
    for bad in _exact_rows(~sure):
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
    return incircle_xy(
        a[:, 0], a[:, 1], b[:, 0], b[:, 1], c[:, 0], c[:, 1], d[:, 0], d[:, 1]
    )


def _require_finite(*arrays):
    for x in arrays:
        if not np.isfinite(x).all():
            raise ValueError("coordinates must be finite")


def dot_sign_scalar(p, q, u, v) -> int:
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

