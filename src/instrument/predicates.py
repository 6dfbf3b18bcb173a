"""Adaptive exact geometric predicates: ``orient2d`` and ``incircle``.

Routines
--------
orient2d(ax, ay, bx, by, cx, cy)
    Positive iff a, b, c are counter-clockwise, negative iff clockwise, zero iff
    collinear. The value approximates twice the signed area of the triangle.
incircle(ax, ay, bx, by, cx, cy, dx, dy)
    For counter-clockwise a, b, c: positive iff d lies strictly inside their
    circumcircle, negative iff strictly outside, zero iff the four are cocircular.
orient2d_fast, incircle_fast
    The plain floating-point determinants (Triangle's ``-X`` switch): no guarantee.

The signs of ``orient2d`` and ``incircle`` are exact for every finite double input.

Method
------
These follow J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
Robust Geometric Predicates", Discrete & Computational Geometry 18 (1997), as used
by Triangle (see the reference document, section 5). The code is written afresh
from the paper's description.

*Stage 0 / A (inlined in the public functions).* The determinant is evaluated in
floating point exactly as Triangle does (same operations, same order), together
with its "permanent" (the same polynomial with absolute values). If the
determinant exceeds the a-priori error bound (``ccwerrboundA`` /
``iccerrboundA`` times the permanent) its sign is certain and the value is
returned: bit for bit the ``det`` Triangle returns. No allocation happens here.

*Stages B, C, D (separate functions, rarely called).* Expansion arithmetic: the
determinant of the rounded differences is formed exactly (stage B) and its
estimate tested against a smaller bound; then the first-order correction from
the rounding errors ("tails") of the differences (stage C); finally the
complete exact expansion (stage D), whose largest component carries the exact
sign. Each stage returns the same value Triangle's stage returns (the estimate,
or the largest component of the final expansion).

Underflow and overflow
----------------------
Shewchuk's error bounds and error-free transformations assume that no operation
underflows or overflows. Two facts make this checkable cheaply:

1. *The filter.* An underflowed product contributes an absolute error of at most
   2^-1075 times the factors that multiply it later. ``orient2d`` therefore
   trusts stage A only if ``2^-960 <= detsum <= DBL_MAX``: then either no
   product underflowed (Shewchuk's analysis applies verbatim) or exactly one did
   and the other product is 2^60 times larger, which fixes the sign anyway.
   ``incircle`` trusts stage A only if ``alift + blift + clift <= 2^300``
   (bounding every multiplier by 2^300, hence every underflow effect by
   2^-770), ``permanent >= 2^-660``, and ``|det| > iccerrboundA (1 + 2^-40)
   permanent``; the 2^-40 margin (>= 2^-752 absolutely) swamps the underflow
   effects. These tests reject NaN and infinity. Whenever they reject, the slow
   path below re-runs Triangle's own stage 0/A test, so the returned values are
   still Triangle's.
2. *The exact stages.* Every double is an integer multiple of 2^(e-53), where
   2^(e-1) <= |x| < 2^e. Sums, differences and products of such numbers stay on
   the product grid, and on a grid no coarser than 2^-1074 even subnormal
   results are exact; so Two_Sum, Two_Diff and Dekker's Two_Product are
   error-free as long as every product has total degree k with
   k (e_min - 53) >= -1074, and nothing overflows. ``orient2d`` has degree 2
   (safe if every nonzero coordinate has 2^-485 <= |x| < 2^500), ``incircle``
   degree 4 (safe if 2^-216 <= |x| < 2^250). This contains Triangle's own
   documented range of binary exponents [-148, 201].

Inputs outside the safe range are multiplied by an exact power of two 2^k
(uniform scaling multiplies orient2d by 2^2k and incircle by 2^4k, so the signs
are unchanged) chosen to bring the smallest nonzero and the largest coordinate
inside it; the result is scaled back, saturating to +-DBL_MAX or to the smallest
subnormal of the right sign so that a nonzero sign is never lost. Scaling is
impossible only if the coordinates of a single call span more than about 2^984
(orient2d) or 2^465 (incircle) in magnitude, e.g. 1e200 next to 1e-200. Then
the determinant is evaluated exactly with Python's ``fractions.Fraction``
(every double is a dyadic rational) inside a ``numba.objmode`` block; that works
with ``cache=True`` and under ``NUMBA_DISABLE_JIT=1``.

Infinite or NaN inputs are not supported (callers reject them); they return the
plain floating-point determinant, without looping.

All routines are compiled with ``@njit(cache=True)`` and strict IEEE semantics
(no reassociation, which would break the error-free transformations).
"""

from __future__ import annotations

import math
from fractions import Fraction

from numba import njit, objmode

from .jit import iscratch, scratch

__all__ = ["orient2d", "incircle", "orient2d_fast", "incircle_fast"]

# ---------------------------------------------------------------------------
# Constants (Triangle's exactinit, binary64 with round-to-nearest-even)
# ---------------------------------------------------------------------------
EPSILON = 2.0**-53
SPLITTER = 2.0**27 + 1.0
RESULTERRBOUND = (3.0 + 8.0 * EPSILON) * EPSILON
CCWERRBOUNDA = (3.0 + 16.0 * EPSILON) * EPSILON
CCWERRBOUNDB = (2.0 + 12.0 * EPSILON) * EPSILON
CCWERRBOUNDC = (9.0 + 64.0 * EPSILON) * EPSILON * EPSILON
ICCERRBOUNDA = (10.0 + 96.0 * EPSILON) * EPSILON
ICCERRBOUNDB = (4.0 + 48.0 * EPSILON) * EPSILON
ICCERRBOUNDC = (44.0 + 576.0 * EPSILON) * EPSILON * EPSILON

_DBL_MAX = 1.7976931348623157e308
_DBL_TRUE_MIN = 5e-324
# Fast-path guards (see the module docstring).
_O_LO = 2.0**-960
_I_LO = 2.0**-660
_I_SMAX = 2.0**300
_ICC_A_SAFE = ICCERRBOUNDA * (1.0 + 2.0**-40)
# Safe exponent windows [2^low, 2^high) for nonzero coordinates.
_O_LOW, _O_HIGH = -485, 500
_I_LOW, _I_HIGH = -216, 250
# Status codes of _choose_scale.
_OK, _ALLZERO, _WIDE, _NONFINITE = 0, 1, 2, 3
_FIN_SIZE = 1152  # Triangle's bound on the length of incircle's final expansion


# ---------------------------------------------------------------------------
# Error-free transformations (each returns (head, tail) with head + tail exact)
# ---------------------------------------------------------------------------
@njit(cache=True)
def _fast_two_sum(a, b):
    """x + y == a + b exactly; needs |a| >= |b| (or a == 0)."""
    x = a + b
    y = b - (x - a)
    return x, y


@njit(cache=True)
def _two_sum(a, b):
    """x + y == a + b exactly (Knuth)."""
    x = a + b
    bv = x - a
    av = x - bv
    return x, (a - av) + (b - bv)


@njit(cache=True)
def _two_diff_tail(a, b, x):
    """Rounding error of x = fl(a - b): a - b == x + tail exactly."""
    bv = a - x
    av = x + bv
    return (a - av) + (bv - b)


@njit(cache=True)
def _two_diff(a, b):
    """x + y == a - b exactly."""
    x = a - b
    return x, _two_diff_tail(a, b, x)


@njit(cache=True)
def _split(a):
    """Dekker split: a == hi + lo with at most 26 significant bits in each."""
    c = SPLITTER * a
    hi = c - (c - a)
    return hi, a - hi


@njit(cache=True)
def _two_product_presplit(a, b, bhi, blo):
    """x + y == a * b exactly, with b already split."""
    x = a * b
    ahi, alo = _split(a)
    err3 = ((x - ahi * bhi) - alo * bhi) - ahi * blo
    return x, alo * blo - err3


@njit(cache=True)
def _two_product(a, b):
    """x + y == a * b exactly (Dekker / Veltkamp)."""
    bhi, blo = _split(b)
    return _two_product_presplit(a, b, bhi, blo)


@njit(cache=True)
def _square(a):
    """x + y == a * a exactly."""
    x = a * a
    ahi, alo = _split(a)
    err3 = (x - ahi * ahi) - (ahi + ahi) * alo
    return x, alo * alo - err3


@njit(cache=True)
def _two_one_sum(a1, a0, b):
    """(x2, x1, x0): expansion of (a1 + a0) + b."""
    i, x0 = _two_sum(a0, b)
    x2, x1 = _two_sum(a1, i)
    return x2, x1, x0


@njit(cache=True)
def _two_one_diff(a1, a0, b):
    """(x2, x1, x0): expansion of (a1 + a0) - b."""
    i, x0 = _two_diff(a0, b)
    x2, x1 = _two_sum(a1, i)
    return x2, x1, x0


@njit(cache=True)
def _two_two_sum(a1, a0, b1, b0):
    """(x3, x2, x1, x0): expansion of (a1 + a0) + (b1 + b0)."""
    j, r0, x0 = _two_one_sum(a1, a0, b0)
    x3, x2, x1 = _two_one_sum(j, r0, b1)
    return x3, x2, x1, x0


@njit(cache=True)
def _two_two_diff(a1, a0, b1, b0):
    """(x3, x2, x1, x0): expansion of (a1 + a0) - (b1 + b0)."""
    j, r0, x0 = _two_one_diff(a1, a0, b0)
    x3, x2, x1 = _two_one_diff(j, r0, b1)
    return x3, x2, x1, x0


@njit(cache=True)
def _store4(h, x3, x2, x1, x0):
    """Write a 4-component expansion (smallest first) into h[0:4]."""
    h[0] = x0
    h[1] = x1
    h[2] = x2
    h[3] = x3


@njit(cache=True)
def _product_diff4(a, b, c, d, h):
    """h[0:4] = exact expansion of a*b - c*d."""
    s1, s0 = _two_product(a, b)
    t1, t0 = _two_product(c, d)
    x3, x2, x1, x0 = _two_two_diff(s1, s0, t1, t0)
    _store4(h, x3, x2, x1, x0)


# ---------------------------------------------------------------------------
# Expansion arithmetic (arrays of nonoverlapping components, smallest first)
# ---------------------------------------------------------------------------
@njit(cache=True)
def _expansion_sum(elen, e, flen, f, h):
    """h = e + f (Shewchuk's fast_expansion_sum_zeroelim); returns len(h).

    Parameters
    ----------
    elen, flen : int
        Numbers of components used from ``e`` and ``f`` (each >= 1).
    e, f : array of float64, shape (>= elen,), (>= flen,)
    h : array of float64, shape (>= elen + flen,)
        Output; must not alias ``e`` or ``f``.
    """
    ei = 0
    fi = 0
    enow = e[0]
    fnow = f[0]
    if (fnow > enow) == (fnow > -enow):
        q = enow
        ei += 1
    else:
        q = fnow
        fi += 1
    hi = 0
    if ei < elen and fi < flen:
        enow = e[ei]
        fnow = f[fi]
        if (fnow > enow) == (fnow > -enow):
            q, hh = _fast_two_sum(enow, q)
            ei += 1
        else:
            q, hh = _fast_two_sum(fnow, q)
            fi += 1
        if hh != 0.0:
            h[hi] = hh
            hi += 1
        while ei < elen and fi < flen:
            enow = e[ei]
            fnow = f[fi]
            if (fnow > enow) == (fnow > -enow):
                q, hh = _two_sum(q, enow)
                ei += 1
            else:
                q, hh = _two_sum(q, fnow)
                fi += 1
            if hh != 0.0:
                h[hi] = hh
                hi += 1
    while ei < elen:
        q, hh = _two_sum(q, e[ei])
        ei += 1
        if hh != 0.0:
            h[hi] = hh
            hi += 1
    while fi < flen:
        q, hh = _two_sum(q, f[fi])
        fi += 1
        if hh != 0.0:
            h[hi] = hh
            hi += 1
    if q != 0.0 or hi == 0:
        h[hi] = q
        hi += 1
    return hi


@njit(cache=True)
def _scale_expansion(elen, e, b, h):
    """h = e * b (Shewchuk's scale_expansion_zeroelim); returns len(h).

    Parameters
    ----------
    elen : int
        Number of components of ``e`` (>= 1).
    e : array of float64, shape (>= elen,)
    b : float
    h : array of float64, shape (>= 2 * elen,)
        Output; must not alias ``e``.
    """
    bhi, blo = _split(b)
    q, hh = _two_product_presplit(e[0], b, bhi, blo)
    hi = 0
    if hh != 0.0:
        h[hi] = hh
        hi += 1
    for i in range(1, elen):
        p1, p0 = _two_product_presplit(e[i], b, bhi, blo)
        s, hh = _two_sum(q, p0)
        if hh != 0.0:
            h[hi] = hh
            hi += 1
        q, hh = _fast_two_sum(p1, s)
        if hh != 0.0:
            h[hi] = hh
            hi += 1
    if q != 0.0 or hi == 0:
        h[hi] = q
        hi += 1
    return hi


@njit(cache=True)
def _estimate(elen, e):
    """Floating-point sum of the components, smallest first."""
    q = float(e[0])
    for i in range(1, elen):
        q += e[i]
    return q


# ---------------------------------------------------------------------------
# Range check and exact power-of-two rescaling
# ---------------------------------------------------------------------------
@njit(cache=True)
def _choose_scale(coords, low, high):
    """Pick k so that every nonzero |x * 2^k| lies in [2^low, 2^high).

    Parameters
    ----------
    coords : tuple of float
    low, high : int
        Safe exponent window of the predicate.

    Returns
    -------
    status : int
        ``_OK`` (use ``k``), ``_ALLZERO``, ``_WIDE`` (no k exists) or ``_NONFINITE``.
    k : int
        0 when the input is already safe.
    """
    mx = 0.0
    mn = _DBL_MAX
    for v in coords:
        if not math.isfinite(v):
            return _NONFINITE, 0
        a = abs(v)
        if a > mx:
            mx = a
        if a != 0.0 and a < mn:
            mn = a
    if mx == 0.0:
        return _ALLZERO, 0
    e_min = math.frexp(mn)[1]  # 2^(e_min - 1) <= mn < 2^e_min
    e_max = math.frexp(mx)[1]
    k_lo = low - e_min + 1
    k_hi = high - e_max
    if k_lo > k_hi:
        return _WIDE, 0
    if k_lo > 0:
        return _OK, k_lo
    if k_hi < 0:
        return _OK, k_hi
    return _OK, 0


@njit(cache=True)
def _unscale(v, p):
    """v * 2^p, saturating so that a nonzero v never becomes 0 or infinite."""
    if v == 0.0:
        return v
    m, e = math.frexp(v)
    if e + p > 1024:
        return math.copysign(_DBL_MAX, v)
    if e + p < -1074:
        return math.copysign(_DBL_TRUE_MIN, v)
    r = math.ldexp(m, e + p)
    if r == 0.0:
        return math.copysign(_DBL_TRUE_MIN, v)
    return r


def _fraction_to_float(x: Fraction) -> float:
    """Nearest double to x, saturating like `_unscale` (sign always kept)."""
    if x == 0:
        return 0.0
    sign = 1.0 if x > 0 else -1.0
    try:
        r = float(x)
    except OverflowError:
        return sign * _DBL_MAX
    if r == 0.0:
        return sign * _DBL_TRUE_MIN
    if math.isinf(r):
        return sign * _DBL_MAX
    return r


def _py_orient2d_exact(ax, ay, bx, by, cx, cy):
    """orient2d determinant in exact rational arithmetic (rare fallback)."""
    ax, ay, bx, by, cx, cy = (Fraction(v) for v in (ax, ay, bx, by, cx, cy))
    det = (ax - cx) * (by - cy) - (ay - cy) * (bx - cx)
    return _fraction_to_float(det)


def _py_incircle_exact(ax, ay, bx, by, cx, cy, dx, dy):
    """incircle determinant in exact rational arithmetic (rare fallback)."""
    ax, ay, bx, by, cx, cy, dx, dy = (
        Fraction(v) for v in (ax, ay, bx, by, cx, cy, dx, dy)
    )
    adx, ady, bdx, bdy = ax - dx, ay - dy, bx - dx, by - dy
    cdx, cdy = cx - dx, cy - dy
    det = (
        (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
        + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
        + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady)
    )
    return _fraction_to_float(det)


@njit(cache=True)
def _orient2d_rational(ax, ay, bx, by, cx, cy):
    """Exact orient2d through Python rationals (coordinates span > 2^984)."""
    with objmode(r="float64"):
        r = _py_orient2d_exact(ax, ay, bx, by, cx, cy)
    return r


@njit(cache=True)
def _incircle_rational(ax, ay, bx, by, cx, cy, dx, dy):
    """Exact incircle through Python rationals (coordinates span > 2^465)."""
    with objmode(r="float64"):
        r = _py_incircle_exact(ax, ay, bx, by, cx, cy, dx, dy)
    return r


# ---------------------------------------------------------------------------
# orient2d
# ---------------------------------------------------------------------------
@njit(cache=True)
def orient2d_fast(ax, ay, bx, by, cx, cy):
    """Plain floating-point orient2d (Triangle's ``-X``); sign not guaranteed.

    Parameters
    ----------
    ax, ay, bx, by, cx, cy : float
        Coordinates of a, b, c.

    Returns
    -------
    float
        ``(ax - cx) * (by - cy) - (ay - cy) * (bx - cx)``.
    """
    return (ax - cx) * (by - cy) - (ay - cy) * (bx - cx)


@njit(cache=True)
def orient2d(ax, ay, bx, by, cx, cy):
    """Exact-sign orientation of the triangle a, b, c.

    Parameters
    ----------
    ax, ay, bx, by, cx, cy : float
        Coordinates of a, b, c (finite).

    Returns
    -------
    float
        Positive iff a, b, c are counter-clockwise, negative iff clockwise, zero
        iff collinear. Approximately twice the signed area: exactly Triangle's
        ``det`` when the filter certifies it, else the adaptive stage's value.
    """
    detleft = (ax - cx) * (by - cy)
    detright = (ay - cy) * (bx - cx)
    det = detleft - detright
    detsum = abs(detleft) + abs(detright)
    if abs(det) >= CCWERRBOUNDA * detsum:
        if (detsum >= _O_LO) & (detsum <= _DBL_MAX):
            return det
    return _orient2d_slow(ax, ay, bx, by, cx, cy)


@njit(cache=True)
def _orient2d_slow(ax, ay, bx, by, cx, cy):
    """orient2d when the inlined filter could not decide: range check, then exact."""
    status, k = _choose_scale((ax, ay, bx, by, cx, cy), _O_LOW, _O_HIGH)
    if status == _ALLZERO:
        return 0.0
    if status == _NONFINITE:
        return orient2d_fast(ax, ay, bx, by, cx, cy)
    if status == _WIDE:
        return _orient2d_rational(ax, ay, bx, by, cx, cy)
    if k == 0:
        return _orient2d_exact(ax, ay, bx, by, cx, cy)
    s = math.ldexp(1.0, k)
    v = _orient2d_exact(ax * s, ay * s, bx * s, by * s, cx * s, cy * s)
    return _unscale(v, -2 * k)


@njit(cache=True)
def _orient2d_exact(ax, ay, bx, by, cx, cy):
    """Triangle's complete orient2d (stage 0, A, then adapt); inputs in safe range."""
    detleft = (ax - cx) * (by - cy)
    detright = (ay - cy) * (bx - cx)
    det = detleft - detright
    if detleft > 0.0:
        if detright <= 0.0:
            return det
        detsum = detleft + detright
    elif detleft < 0.0:
        if detright >= 0.0:
            return det
        detsum = -detleft - detright
    else:
        return det
    errbound = CCWERRBOUNDA * detsum
    if det >= errbound or -det >= errbound:
        return det
    return _orient2d_adapt(ax, ay, bx, by, cx, cy, detsum)


@njit(cache=True)
def _orient2d_adapt(ax, ay, bx, by, cx, cy, detsum):
    """Stages B, C, D of orient2d (Shewchuk's counterclockwiseadapt)."""
    acx = ax - cx
    bcx = bx - cx
    acy = ay - cy
    bcy = by - cy
    dl1, dl0 = _two_product(acx, bcy)
    dr1, dr0 = _two_product(acy, bcx)
    b3, b2, b1, b0 = _two_two_diff(dl1, dl0, dr1, dr0)
    det = ((b0 + b1) + b2) + b3
    errbound = CCWERRBOUNDB * detsum
    if det >= errbound or -det >= errbound:
        return det
    acxtail = _two_diff_tail(ax, cx, acx)
    bcxtail = _two_diff_tail(bx, cx, bcx)
    acytail = _two_diff_tail(ay, cy, acy)
    bcytail = _two_diff_tail(by, cy, bcy)
    if acxtail == 0.0 and acytail == 0.0 and bcxtail == 0.0 and bcytail == 0.0:
        return det
    errbound = CCWERRBOUNDC * detsum + RESULTERRBOUND * abs(det)
    det += (acx * bcytail + bcy * acxtail) - (acy * bcxtail + bcx * acytail)
    if det >= errbound or -det >= errbound:
        return det
    w = scratch(44)
    n = _orient2d_expansion_d(
        acx, acy, bcx, bcy, acxtail, acytail, bcxtail, bcytail, b3, b2, b1, b0, w
    )
    return float(w[28 + n - 1])


@njit(cache=True)
def _orient2d_expansion_d(
    acx, acy, bcx, bcy, acxtail, acytail, bcxtail, bcytail, b3, b2, b1, b0, w
):
    """Stage D of orient2d: the exact determinant, left in ``w[28:28 + n]``.

    Parameters
    ----------
    acx, acy, bcx, bcy : float
        Rounded differences a - c, b - c.
    acxtail, acytail, bcxtail, bcytail : float
        Their rounding errors.
    b3, b2, b1, b0 : float
        Stage B expansion of ``acx * bcy - acy * bcx``.
    w : array of float64, shape (44,)
        Workspace.

    Returns
    -------
    int
        Length n of the final expansion.
    """
    bexp = w[0:4]
    u = w[4:8]
    c1 = w[8:16]
    c2 = w[16:28]
    d = w[28:44]
    _store4(bexp, b3, b2, b1, b0)
    _product_diff4(acxtail, bcy, acytail, bcx, u)
    c1len = _expansion_sum(4, bexp, 4, u, c1)
    _product_diff4(acx, bcytail, acy, bcxtail, u)
    c2len = _expansion_sum(c1len, c1, 4, u, c2)
    _product_diff4(acxtail, bcytail, acytail, bcxtail, u)
    return _expansion_sum(c2len, c2, 4, u, d)


# ---------------------------------------------------------------------------
# incircle
# ---------------------------------------------------------------------------
@njit(cache=True)
def incircle_fast(ax, ay, bx, by, cx, cy, dx, dy):
    """Plain floating-point incircle (Triangle's ``-X``); sign not guaranteed.

    Parameters
    ----------
    ax, ay, bx, by, cx, cy, dx, dy : float
        Coordinates of a, b, c (counter-clockwise) and the query point d.

    Returns
    -------
    float
        Triangle's stage-0 determinant.
    """
    adx = ax - dx
    bdx = bx - dx
    cdx = cx - dx
    ady = ay - dy
    bdy = by - dy
    cdy = cy - dy
    alift = adx * adx + ady * ady
    blift = bdx * bdx + bdy * bdy
    clift = cdx * cdx + cdy * cdy
    return (
        alift * (bdx * cdy - cdx * bdy)
        + blift * (cdx * ady - adx * cdy)
        + clift * (adx * bdy - bdx * ady)
    )


@njit(cache=True)
def incircle(ax, ay, bx, by, cx, cy, dx, dy):
    """Exact-sign in-circle test of d against the circle through a, b, c.

    Parameters
    ----------
    ax, ay, bx, by, cx, cy : float
        Coordinates of a, b, c, assumed counter-clockwise (finite).
    dx, dy : float
        Coordinates of the query point d (finite).

    Returns
    -------
    float
        Positive iff d is strictly inside the circle, negative iff strictly
        outside, zero iff cocircular (signs flip if a, b, c are clockwise).
        Exactly Triangle's ``det`` when the filter certifies it, else the
        adaptive stage's value.
    """
    adx = ax - dx
    bdx = bx - dx
    cdx = cx - dx
    ady = ay - dy
    bdy = by - dy
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
    permanent = (
        (abs(bdxcdy) + abs(cdxbdy)) * alift
        + (abs(cdxady) + abs(adxcdy)) * blift
        + (abs(adxbdy) + abs(bdxady)) * clift
    )
    if abs(det) > _ICC_A_SAFE * permanent:
        if (permanent >= _I_LO) & (alift + blift + clift <= _I_SMAX):
            return det
    return _incircle_slow(ax, ay, bx, by, cx, cy, dx, dy)


@njit(cache=True)
def _incircle_slow(ax, ay, bx, by, cx, cy, dx, dy):
    """incircle when the inlined filter could not decide: range check, then exact."""
    status, k = _choose_scale((ax, ay, bx, by, cx, cy, dx, dy), _I_LOW, _I_HIGH)
    if status == _ALLZERO:
        return 0.0
    if status == _NONFINITE:
        return incircle_fast(ax, ay, bx, by, cx, cy, dx, dy)
    if status == _WIDE:
        return _incircle_rational(ax, ay, bx, by, cx, cy, dx, dy)
    if k == 0:
        return _incircle_exact(ax, ay, bx, by, cx, cy, dx, dy)
    s = math.ldexp(1.0, k)
    v = _incircle_exact(ax * s, ay * s, bx * s, by * s, cx * s, cy * s, dx * s, dy * s)
    return _unscale(v, -4 * k)


@njit(cache=True)
def _incircle_exact(ax, ay, bx, by, cx, cy, dx, dy):
    """Triangle's complete incircle (stage 0, A, then adapt); inputs in safe range."""
    adx = ax - dx
    bdx = bx - dx
    cdx = cx - dx
    ady = ay - dy
    bdy = by - dy
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
    permanent = (
        (abs(bdxcdy) + abs(cdxbdy)) * alift
        + (abs(cdxady) + abs(adxcdy)) * blift
        + (abs(adxbdy) + abs(bdxady)) * clift
    )
    errbound = ICCERRBOUNDA * permanent
    if det > errbound or -det > errbound:
        return det
    return _incircle_adapt(ax, ay, bx, by, cx, cy, dx, dy, permanent)


@njit(cache=True)
def _lifted_term(e, x, y, w, h):
    """h = e * (x*x + y*y) as an expansion; returns len(h).

    Parameters
    ----------
    e : array of float64, shape (4,)
        A 2x2 minor (e.g. bc) as an expansion.
    x, y : float
    w : array of float64, shape (48,)
        Workspace.
    h : array of float64, shape (32,)
    """
    ex = w[0:8]
    exx = w[8:24]
    n = _scale_expansion(4, e, x, ex)
    nxx = _scale_expansion(n, ex, x, exx)
    ey = w[24:32]
    eyy = w[32:48]
    n = _scale_expansion(4, e, y, ey)
    nyy = _scale_expansion(n, ey, y, eyy)
    return _expansion_sum(nxx, exx, nyy, eyy, h)


@njit(cache=True)
def _incircle_expansion_b(adx, bdx, cdx, ady, bdy, cdy, w):
    """Stage B of incircle: exact determinant of the rounded differences.

    Parameters
    ----------
    adx, bdx, cdx, ady, bdy, cdy : float
        Rounded differences a - d, b - d, c - d.
    w : array of float64, shape (>= 316,)
        Workspace. On return ``w[0:4]``, ``w[4:8]``, ``w[8:12]`` hold the minors
        bc, ca, ab and ``w[220:220 + n]`` the determinant.

    Returns
    -------
    int
        Length n of the determinant expansion.
    """
    bc = w[0:4]
    ca = w[4:8]
    ab = w[8:12]
    _product_diff4(bdx, cdy, cdx, bdy, bc)
    _product_diff4(cdx, ady, adx, cdy, ca)
    _product_diff4(adx, bdy, bdx, ady, ab)
    work = w[12:60]
    adet = w[60:92]
    bdet = w[92:124]
    cdet = w[124:156]
    alen = _lifted_term(bc, adx, ady, work, adet)
    blen = _lifted_term(ca, bdx, bdy, work, bdet)
    clen = _lifted_term(ab, cdx, cdy, work, cdet)
    abdet = w[156:220]
    ablen = _expansion_sum(alen, adet, blen, bdet, abdet)
    return _expansion_sum(ablen, abdet, clen, cdet, w[220:316])


@njit(cache=True)
def _incircle_adapt(ax, ay, bx, by, cx, cy, dx, dy, permanent):
    """Stages B, C, D of incircle (Shewchuk's incircleadapt)."""
    adx = ax - dx
    bdx = bx - dx
    cdx = cx - dx
    ady = ay - dy
    bdy = by - dy
    cdy = cy - dy
    w = scratch(316)
    finlen = _incircle_expansion_b(adx, bdx, cdx, ady, bdy, cdy, w)
    det = _estimate(finlen, w[220:316])
    errbound = ICCERRBOUNDB * permanent
    if det >= errbound or -det >= errbound:
        return det
    adxt = _two_diff_tail(ax, dx, adx)
    adyt = _two_diff_tail(ay, dy, ady)
    bdxt = _two_diff_tail(bx, dx, bdx)
    bdyt = _two_diff_tail(by, dy, bdy)
    cdxt = _two_diff_tail(cx, dx, cdx)
    cdyt = _two_diff_tail(cy, dy, cdy)
    if (
        adxt == 0.0 and bdxt == 0.0 and cdxt == 0.0
        and adyt == 0.0 and bdyt == 0.0 and cdyt == 0.0
    ):
        return det
    errbound = ICCERRBOUNDC * permanent + RESULTERRBOUND * abs(det)
    det += (
        (
            (adx * adx + ady * ady)
            * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt))
            + 2.0 * (adx * adxt + ady * adyt) * (bdx * cdy - bdy * cdx)
        )
        + (
            (bdx * bdx + bdy * bdy)
            * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt))
            + 2.0 * (bdx * bdxt + bdy * bdyt) * (cdx * ady - cdy * adx)
        )
        + (
            (cdx * cdx + cdy * cdy)
            * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt))
            + 2.0 * (cdx * cdxt + cdy * cdyt) * (adx * bdy - ady * bdx)
        )
    )
    if det >= errbound or -det >= errbound:
        return det
    # Stage D's work space lives in this frame (kernels may not allocate).
    fin = scratch(_FIN_SIZE)
    other = scratch(_FIN_SIZE)
    t = scratch(256)
    lifts = scratch(12)
    xt = scratch(48)
    xtlen = iscratch(6)
    small = scratch(20)
    fin, n = _incircle_expansion_d(
        adx, bdx, cdx, ady, bdy, cdy, adxt, bdxt, cdxt, adyt, bdyt, cdyt, w, finlen,
        fin, other, t, lifts.reshape((3, 4)), xt.reshape((6, 8)), xtlen, small,
    )
    return float(fin[n - 1])


@njit(cache=True)
def _lift4(x, y, h):
    """h[0:4] = exact expansion of x*x + y*y."""
    x1, x0 = _square(x)
    y1, y0 = _square(y)
    s3, s2, s1, s0 = _two_two_sum(x1, x0, y1, y0)
    _store4(h, s3, s2, s1, s0)


@njit(cache=True)
def _fin_add(fin, flen, other, elen, e):
    """other = fin + e; returns (new fin, new spare buffer, new length)."""
    n = _expansion_sum(flen, fin, elen, e, other)
    return other, fin, n


@njit(cache=True)
def _first_order(fin, flen, other, base, tail, two_head, e2, m2, e3, m3, xt, t):
    """Add one tail's first-order terms to ``fin``.

    Adds ``tail * (base * two_head + e2 * m2 + e3 * m3)`` where ``base`` is the
    point's own 2x2 minor (as a 4-expansion), ``e2``/``e3`` the other two lifts.
    Leaves ``base * tail`` in ``xt`` for the second-order terms.

    Parameters
    ----------
    fin, other : array of float64, shape (1152,)
        Current expansion (length ``flen``) and spare buffer.
    base, e2, e3 : array of float64, shape (4,)
    tail, two_head, m2, m3 : float
    xt : array of float64, shape (8,)
    t : array of float64, shape (>= 136,)
        Workspace.

    Returns
    -------
    xtlen : int
    fin, other : arrays (swapped as needed)
    flen : int
    """
    t8 = t[0:8]
    t16a = t[8:24]
    t16b = t[24:40]
    t16c = t[40:56]
    t32a = t[56:88]
    t48 = t[88:136]
    xtlen = _scale_expansion(4, base, tail, xt)
    n16a = _scale_expansion(xtlen, xt, two_head, t16a)
    n8 = _scale_expansion(4, e2, tail, t8)
    n16b = _scale_expansion(n8, t8, m2, t16b)
    n8 = _scale_expansion(4, e3, tail, t8)
    n16c = _scale_expansion(n8, t8, m3, t16c)
    n32a = _expansion_sum(n16a, t16a, n16b, t16b, t32a)
    n48 = _expansion_sum(n16c, t16c, n32a, t32a, t48)
    fin, other, flen = _fin_add(fin, flen, other, n48, t48)
    return xtlen, fin, other, flen


@njit(cache=True)
def _tail_minors(pt, q, p, qt, rt, s, r, st, tct, tctt, u):
    """First- and second-order tail parts of the minor (p+pt)(q+qt) - (r+rt)(s+st).

    ``tct`` gets ``pt*q + p*qt - rt*s - r*st`` and ``tctt`` gets ``pt*qt - rt*st``
    (both as expansions); returns their lengths. Both are [0] when all four tails
    are zero. ``u`` is work space of 8 elements.
    """
    if pt == 0.0 and qt == 0.0 and rt == 0.0 and st == 0.0:
        tct[0] = 0.0
        tctt[0] = 0.0
        return 1, 1
    i1, i0 = _two_product(pt, q)
    j1, j0 = _two_product(p, qt)
    x3, x2, x1, x0 = _two_two_sum(i1, i0, j1, j0)
    _store4(u[0:4], x3, x2, x1, x0)
    i1, i0 = _two_product(rt, -s)
    j1, j0 = _two_product(r, -st)
    x3, x2, x1, x0 = _two_two_sum(i1, i0, j1, j0)
    _store4(u[4:8], x3, x2, x1, x0)
    n = _expansion_sum(4, u[0:4], 4, u[4:8], tct)
    _product_diff4(pt, qt, rt, st, tctt)
    return n, 4


@njit(cache=True)
def _second_order(
    fin, flen, other, xt, xtlen, tct, tctlen, tctt, tcttlen, tail, head,
    c1e, c1s, c1m, c2e, c2s, c2m, t,
):
    """Add one tail's higher-order terms to ``fin``.

    Adds ``tail^2 * minor + (2 head tail + tail^2) * (tct + tctt)`` where ``xt`` is
    ``minor * tail``, plus the cross terms ``c1e * c1s * c1m`` and
    ``c2e * c2s * c2m`` (skipped when the multiplier ``c?m`` is zero).

    Parameters
    ----------
    fin, other : array of float64, shape (1152,)
    xt, tct, tctt : array of float64, shapes (8,), (8,), (4,)
    c1e, c2e : array of float64, shape (4,)
        Lifts used by the cross terms.
    t : array of float64, shape (>= 264,)
        Workspace.

    Returns
    -------
    fin, other : arrays (swapped as needed)
    flen : int
    """
    t8 = t[0:8]
    t16a = t[8:24]
    t16b = t[24:40]
    t32a = t[56:88]
    t48 = t[88:136]
    t32b = t[136:168]
    t64 = t[168:232]
    xtct = t[232:248]
    xtctt = t[248:256]
    n16a = _scale_expansion(xtlen, xt, tail, t16a)
    nxtct = _scale_expansion(tctlen, tct, tail, xtct)
    n32a = _scale_expansion(nxtct, xtct, 2.0 * head, t32a)
    n48 = _expansion_sum(n16a, t16a, n32a, t32a, t48)
    fin, other, flen = _fin_add(fin, flen, other, n48, t48)
    if c1m != 0.0:
        n8 = _scale_expansion(4, c1e, c1s, t8)
        n16a = _scale_expansion(n8, t8, c1m, t16a)
        fin, other, flen = _fin_add(fin, flen, other, n16a, t16a)
    if c2m != 0.0:
        n8 = _scale_expansion(4, c2e, c2s, t8)
        n16a = _scale_expansion(n8, t8, c2m, t16a)
        fin, other, flen = _fin_add(fin, flen, other, n16a, t16a)
    n32a = _scale_expansion(nxtct, xtct, tail, t32a)
    nxtctt = _scale_expansion(tcttlen, tctt, tail, xtctt)
    n16a = _scale_expansion(nxtctt, xtctt, 2.0 * head, t16a)
    n16b = _scale_expansion(nxtctt, xtctt, tail, t16b)
    n32b = _expansion_sum(n16a, t16a, n16b, t16b, t32b)
    n64 = _expansion_sum(n32a, t32a, n32b, t32b, t64)
    fin, other, flen = _fin_add(fin, flen, other, n64, t64)
    return fin, other, flen


@njit(cache=True)
def _incircle_expansion_d(
    adx, bdx, cdx, ady, bdy, cdy, adxt, bdxt, cdxt, adyt, bdyt, cdyt, wb, finlen,
    fin, other, t, lifts, xt, xtlen, small,
):
    """Stage D of incircle: add every term that involves a tail.

    The six tails are visited in Triangle's order (adx, ady, bdx, bdy, cdx, cdy),
    first for their first-order terms, then point by point for the higher-order
    ones. Point i's own minor is ``minors[i]`` (bc, ca, ab); j and k are the next
    two points in cyclic order.

    Parameters
    ----------
    adx, bdx, cdx, ady, bdy, cdy : float
        Rounded differences.
    adxt, bdxt, cdxt, adyt, bdyt, cdyt : float
        Their rounding errors.
    wb : array of float64, shape (316,)
        Stage B workspace (minors in ``wb[0:12]``, expansion in ``wb[220:]``).
    finlen : int
        Length of the stage B expansion.
    fin, other, t, lifts, xt, xtlen, small : arrays
        Work space from the caller, shapes (1152,), (1152,), (256,), (3, 4),
        (6, 8), int64 (6,) and (20,): nothing here allocates, so that the
        predicates can run inside kernels compiled without reference counting.

    Returns
    -------
    fin : array of float64, shape (1152,)
    n : int
        The exact determinant is ``fin[0:n]``; ``fin[n - 1]`` is its largest part.
    """
    dxs = (adx, bdx, cdx)
    dys = (ady, bdy, cdy)
    xts = (adxt, bdxt, cdxt)
    yts = (adyt, bdyt, cdyt)
    minors = wb[0:12].reshape((3, 4))
    for i in range(3):
        _lift4(dxs[i], dys[i], lifts[i])
    # explicit loops: slice copies need numba's runtime, which kernels lack
    for i in range(finlen):
        fin[i] = wb[220 + i]
    flen = finlen
    for i in range(6):  # minor * tail, kept for the higher-order terms
        xtlen[i] = 0
        for j in range(8):
            xt[i, j] = 0.0
    for q in range(6):
        i, is_y = q // 2, q % 2
        j, k = (i + 1) % 3, (i + 2) % 3
        tail = yts[i] if is_y else xts[i]
        if tail == 0.0:
            continue
        if is_y:
            e2, m2, e3, m3 = lifts[j], dxs[k], lifts[k], -dxs[j]
            head = dys[i]
        else:
            e2, m2, e3, m3 = lifts[k], dys[j], lifts[j], -dys[k]
            head = dxs[i]
        xtlen[q], fin, other, flen = _first_order(
            fin, flen, other, minors[i], tail, 2.0 * head, e2, m2, e3, m3, xt[q], t)
    tct = small[0:8]
    tctt = small[8:12]
    u = small[12:20]
    for i in range(3):
        if xts[i] == 0.0 and yts[i] == 0.0:
            continue
        j, k = (i + 1) % 3, (i + 2) % 3
        n1, n2 = _tail_minors(xts[j], dys[k], dxs[j], yts[k],
                              xts[k], dys[j], dxs[k], yts[j], tct, tctt, u)
        for is_y in range(2):
            tail = yts[i] if is_y else xts[i]
            if tail == 0.0:
                continue
            if is_y:  # the x'y' cross terms all sit with the x tails
                c1s, c1m, c2s, c2m = 0.0, 0.0, 0.0, 0.0
                head = dys[i]
            else:
                c1s, c1m, c2s, c2m = tail, yts[j], -tail, yts[k]
                head = dxs[i]
            fin, other, flen = _second_order(
                fin, flen, other, xt[2 * i + is_y], xtlen[2 * i + is_y], tct, n1, tctt, n2,
                tail, head, lifts[k], c1s, c1m, lifts[j], c2s, c2m, t)
    return fin, flen
