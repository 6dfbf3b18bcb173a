# cython: language_level=3
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
dot_sign(ax, ay, bx, by, cx, cy, dx, dy)
    The exact sign (-1, 0, 1) of the dot product (b - a) . (d - c): which way a
    point lies along a line (segment recovery asks whether a vertex near a
    crossing lies strictly between a segment's ends).  Not one of Triangle's.

The signs of ``orient2d``, ``incircle`` and ``dot_sign`` are exact for every
finite double input.

(One module of about 1,100 lines, half of it explanation: the error-free
transformations and expansion arithmetic exist only for these two
predicates' exact stages, and a kernel module cannot call another's small
helpers without an indirect call each, which the exact stages would pay on
every degenerate input.)
All four are callable from Python and, without the Python call, from the
engine's other compiled modules; the fast paths of ``orient2d`` and
``incircle`` are defined in ``predicates.pxd`` (so that every kernel inlines
them) and, for the pure-Python mode, again at the end of this file.

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
or the largest component of the final expansion).  Expansions live in arrays
on the stack of the function that needs them and are passed as (buffer,
offset) pairs, which reads the same compiled (a pointer) and in pure Python
(a list).

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
(orient2d) or 2^465 (incircle) in magnitude, e.g. 1e200 next to 1e-200 (a mesh
graded from 1e-300 to 1e300 makes many such calls). Then stage A is evaluated
again with an unbounded exponent: each value a double mantissa and a C int
exponent, so that no product under- or overflows and each operation rounds
once, relative to its result, as Shewchuk's bound assumes (a sum's smaller
operand may lose bits below 2^-1074 of the larger one, which the 2^-40 margin
swamps). That decides all but nearly degenerate calls in well under a
microsecond; the rest are evaluated exactly with Python integers (every double
is an integer over a power of two; scaled to one denominator no gcd is
needed, unlike ``fractions.Fraction``, about ten times slower), holding the
GIL for that one call.

Infinite or NaN inputs are not supported (callers reject them); they return the
plain floating-point determinant, without looping.

Compiled with strict IEEE semantics: no reassociation and no contraction into
fused multiply-adds (``setup.py`` passes ``-ffp-contract=off``), either of
which would break the error-free transformations.
"""

from __future__ import annotations

import math

import cython
from cython.cimports.libc.math import fabs, frexp, ldexp

__all__ = ["orient2d", "incircle", "orient2d_fast", "incircle_fast", "dot_sign"]

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

# The same, as C constants for the kernels below.
_SPLITTER = cython.declare(cython.double, 134217729.0)
_RESULTERRBOUND = cython.declare(cython.double, 3.3306690738754706e-16)
_CCWERRBOUNDA = cython.declare(cython.double, 3.3306690738754716e-16)
_CCWERRBOUNDB = cython.declare(cython.double, 2.2204460492503146e-16)
_CCWERRBOUNDC = cython.declare(cython.double, 1.1093356479670487e-31)
_ICCERRBOUNDA = cython.declare(cython.double, 1.1102230246251577e-15)
_ICCERRBOUNDB = cython.declare(cython.double, 4.440892098500632e-16)
_ICCERRBOUNDC = cython.declare(cython.double, 5.423418723394464e-31)
_DBL_MAX = cython.declare(cython.double, 1.7976931348623157e308)
_DBL_TRUE_MIN = cython.declare(cython.double, 5e-324)
# Fast-path guards (see the module docstring; predicates.pxd spells them as literals).
O_LO = 2.0**-960
I_LO = 2.0**-660
I_SMAX = 2.0**300
ICC_A_SAFE = ICCERRBOUNDA * (1.0 + 2.0**-40)
# Stage A's bounds with the same margin, for the wide-range filter.
_CCW_WIDE = cython.declare(cython.double, CCWERRBOUNDA * (1.0 + 2.0**-40))
_ICC_WIDE = cython.declare(cython.double, ICC_A_SAFE)
# Safe exponent windows [2^low, 2^high) for nonzero coordinates.
_O_LOW = cython.declare(cython.int, -485)
_O_HIGH = cython.declare(cython.int, 500)
_I_LOW = cython.declare(cython.int, -216)
_I_HIGH = cython.declare(cython.int, 250)
# Status codes of _choose_scale.
# which predicate ``_adaptive`` computes: its degree in the coordinates
_ORIENT2D = cython.declare(cython.int, 2)
_INCIRCLE = cython.declare(cython.int, 4)
_OK = cython.declare(cython.int, 0)
_ALLZERO = cython.declare(cython.int, 1)
_WIDE = cython.declare(cython.int, 2)
_NONFINITE = cython.declare(cython.int, 3)
# Triangle's bound on the length of incircle's final expansion.
_FIN_SIZE = cython.declare(cython.int, 1152)


# ---------------------------------------------------------------------------
# Error-free transformations (each returns (head, tail) with head + tail exact)
# ---------------------------------------------------------------------------
@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _fast_two_sum(a: cython.double, b: cython.double) -> tuple[cython.double, cython.double]:
    """x + y == a + b exactly; needs |a| >= |b| (or a == 0)."""
    x: cython.double = a + b
    return x, b - (x - a)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _two_sum(a: cython.double, b: cython.double) -> tuple[cython.double, cython.double]:
    """x + y == a + b exactly (Knuth)."""
    x: cython.double = a + b
    bv: cython.double = x - a
    av: cython.double = x - bv
    return x, (a - av) + (b - bv)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _two_diff_tail(a: cython.double, b: cython.double, x: cython.double) -> cython.double:
    """Rounding error of x = fl(a - b): a - b == x + tail exactly."""
    bv: cython.double = a - x
    av: cython.double = x + bv
    return (a - av) + (bv - b)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _split(a: cython.double) -> tuple[cython.double, cython.double]:
    """Dekker split: a == hi + lo with at most 26 significant bits in each."""
    c: cython.double = _SPLITTER * a
    hi: cython.double = c - (c - a)
    return hi, a - hi


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _two_product_presplit(
    a: cython.double, b: cython.double, bhi: cython.double, blo: cython.double
) -> tuple[cython.double, cython.double]:
    """x + y == a * b exactly, with b already split."""
    x: cython.double = a * b
    ahi: cython.double
    alo: cython.double
    ahi, alo = _split(a)
    err3: cython.double = ((x - ahi * bhi) - alo * bhi) - ahi * blo
    return x, alo * blo - err3


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _two_product(a: cython.double, b: cython.double) -> tuple[cython.double, cython.double]:
    """x + y == a * b exactly (Dekker / Veltkamp)."""
    bhi: cython.double
    blo: cython.double
    bhi, blo = _split(b)
    return _two_product_presplit(a, b, bhi, blo)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _square(a: cython.double) -> tuple[cython.double, cython.double]:
    """x + y == a * a exactly."""
    x: cython.double = a * a
    ahi: cython.double
    alo: cython.double
    ahi, alo = _split(a)
    err3: cython.double = (x - ahi * ahi) - (ahi + ahi) * alo
    return x, alo * alo - err3


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _store_four(
    x0: cython.double, x1: cython.double, j: cython.double, i: cython.double, h: cython.p_double, ho: cython.int
) -> cython.void:
    """The last step of both Two_Two_Sum and Two_Two_Diff: h[ho:ho + 4] =
    x0, x1 and the two components of j + i (smallest first)."""
    x3: cython.double
    x2: cython.double
    x3, x2 = _two_sum(j, i)
    h[ho] = x0
    h[ho + 1] = x1
    h[ho + 2] = x2
    h[ho + 3] = x3


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _store_two_two_sum(
    a1: cython.double, a0: cython.double, b1: cython.double, b0: cython.double, h: cython.p_double, ho: cython.int
) -> cython.void:
    """h[ho:ho + 4] = expansion of (a1 + a0) + (b1 + b0), smallest first."""
    i: cython.double
    x0: cython.double
    j: cython.double
    r0: cython.double
    x1: cython.double
    i, x0 = _two_sum(a0, b0)
    j, r0 = _two_sum(a1, i)
    i, x1 = _two_sum(r0, b1)
    _store_four(x0, x1, j, i, h, ho)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _store_two_two_diff(
    a1: cython.double, a0: cython.double, b1: cython.double, b0: cython.double, h: cython.p_double, ho: cython.int
) -> cython.void:
    """h[ho:ho + 4] = expansion of (a1 + a0) - (b1 + b0), smallest first."""
    i: cython.double = a0 - b0
    x0: cython.double = _two_diff_tail(a0, b0, i)
    j: cython.double
    r0: cython.double
    j, r0 = _two_sum(a1, i)
    i = r0 - b1
    x1: cython.double = _two_diff_tail(r0, b1, i)
    _store_four(x0, x1, j, i, h, ho)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _product_diff4(
    a: cython.double, b: cython.double, c: cython.double, d: cython.double, h: cython.p_double, ho: cython.int
) -> cython.void:
    """h[ho:ho + 4] = exact expansion of a*b - c*d."""
    s1: cython.double
    s0: cython.double
    t1: cython.double
    t0: cython.double
    s1, s0 = _two_product(a, b)
    t1, t0 = _two_product(c, d)
    _store_two_two_diff(s1, s0, t1, t0, h, ho)


# ---------------------------------------------------------------------------
# Expansion arithmetic (arrays of nonoverlapping components, smallest first)
# ---------------------------------------------------------------------------
@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _expansion_sum(
    elen: cython.int, e: cython.p_double, eo: cython.int,
    flen: cython.int, f: cython.p_double, fo: cython.int,
    h: cython.p_double, ho: cython.int,
) -> cython.int:
    """h[ho:] = e[eo:eo + elen] + f[fo:fo + flen] (Shewchuk's
    fast_expansion_sum_zeroelim); returns the length of h.  ``elen``,
    ``flen`` >= 1; h must not overlap e or f."""
    ei: cython.int = 0
    fi: cython.int = 0
    enow: cython.double = e[eo]
    fnow: cython.double = f[fo]
    q: cython.double
    hh: cython.double
    if (fnow > enow) == (fnow > -enow):
        q = enow
        ei += 1
    else:
        q = fnow
        fi += 1
    hi: cython.int = 0
    if ei < elen and fi < flen:
        enow = e[eo + ei]
        fnow = f[fo + fi]
        if (fnow > enow) == (fnow > -enow):
            q, hh = _fast_two_sum(enow, q)
            ei += 1
        else:
            q, hh = _fast_two_sum(fnow, q)
            fi += 1
        if hh != 0.0:
            h[ho + hi] = hh
            hi += 1
        while ei < elen and fi < flen:
            enow = e[eo + ei]
            fnow = f[fo + fi]
            if (fnow > enow) == (fnow > -enow):
                q, hh = _two_sum(q, enow)
                ei += 1
            else:
                q, hh = _two_sum(q, fnow)
                fi += 1
            if hh != 0.0:
                h[ho + hi] = hh
                hi += 1
    while ei < elen:
        q, hh = _two_sum(q, e[eo + ei])
        ei += 1
        if hh != 0.0:
            h[ho + hi] = hh
            hi += 1
    while fi < flen:
        q, hh = _two_sum(q, f[fo + fi])
        fi += 1
        if hh != 0.0:
            h[ho + hi] = hh
            hi += 1
    if q != 0.0 or hi == 0:
        h[ho + hi] = q
        hi += 1
    return hi


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _scale_expansion(
    elen: cython.int, e: cython.p_double, eo: cython.int, b: cython.double, h: cython.p_double, ho: cython.int
) -> cython.int:
    """h[ho:] = e[eo:eo + elen] * b (Shewchuk's scale_expansion_zeroelim);
    returns the length of h (at most 2 elen); h must not overlap e."""
    bhi: cython.double
    blo: cython.double
    bhi, blo = _split(b)
    q: cython.double
    hh: cython.double
    q, hh = _two_product_presplit(e[eo], b, bhi, blo)
    hi: cython.int = 0
    if hh != 0.0:
        h[ho + hi] = hh
        hi += 1
    p1: cython.double
    p0: cython.double
    s: cython.double
    for i in range(1, elen):
        p1, p0 = _two_product_presplit(e[eo + i], b, bhi, blo)
        s, hh = _two_sum(q, p0)
        if hh != 0.0:
            h[ho + hi] = hh
            hi += 1
        q, hh = _fast_two_sum(p1, s)
        if hh != 0.0:
            h[ho + hi] = hh
            hi += 1
    if q != 0.0 or hi == 0:
        h[ho + hi] = q
        hi += 1
    return hi


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _estimate(elen: cython.int, e: cython.p_double, eo: cython.int) -> cython.double:
    """Floating-point sum of the components, smallest first."""
    q: cython.double = e[eo]
    for i in range(1, elen):
        q += e[eo + i]
    return q


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _copy(n: cython.int, src: cython.p_double, so: cython.int, dst: cython.p_double, do: cython.int) -> cython.void:
    for i in range(n):
        dst[do + i] = src[so + i]


# ---------------------------------------------------------------------------
# Range check and exact power-of-two rescaling
# ---------------------------------------------------------------------------
@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _exponent(x: cython.double) -> cython.int:
    """e with 2^(e-1) <= |x| < 2^e, for finite nonzero x (frexp's exponent)."""
    if cython.compiled:
        e: cython.int = 0
        frexp(x, cython.address(e))
        return e
    else:
        return math.frexp(x)[1]


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _choose_scale(
    coords: cython.p_double, n: cython.int, low: cython.int, high: cython.int
) -> tuple[cython.int, cython.int]:
    """Pick k so that every nonzero |x * 2^k| of ``coords[:n]`` lies in
    [2^low, 2^high).  Returns (status, k): ``_OK`` (use k; 0 when already
    safe), ``_ALLZERO``, ``_WIDE`` (no k exists) or ``_NONFINITE``."""
    mx: cython.double = 0.0
    mn: cython.double = _DBL_MAX
    a: cython.double
    for i in range(n):
        a = fabs(coords[i])
        if not a <= _DBL_MAX:  # infinite or NaN
            return _NONFINITE, 0
        if a > mx:
            mx = a
        if a != 0.0 and a < mn:
            mn = a
    if mx == 0.0:
        return _ALLZERO, 0
    k_lo: cython.int = low - _exponent(mn) + 1
    k_hi: cython.int = high - _exponent(mx)
    if k_lo > k_hi:
        return _WIDE, 0
    if k_lo > 0:
        return _OK, k_lo
    if k_hi < 0:
        return _OK, k_hi
    return _OK, 0


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _unscale(v: cython.double, p: cython.int) -> cython.double:
    """v * 2^p, saturating so that a nonzero v never becomes 0 or infinite."""
    if v == 0.0:
        return v
    e: cython.int = _exponent(v)
    if e + p > 1024:
        return _DBL_MAX if v > 0.0 else -_DBL_MAX
    if e + p < -1074:
        return _DBL_TRUE_MIN if v > 0.0 else -_DBL_TRUE_MIN
    r: cython.double = ldexp(v, p)
    if r == 0.0:
        return _DBL_TRUE_MIN if v > 0.0 else -_DBL_TRUE_MIN
    return r


def _integers(values) -> tuple[list[int], int]:
    """Integers X_i and k >= 0 with values[i] == X_i / 2^k exactly, for at
    most 8 finite doubles.  Every nonzero double is an odd integer (at most
    53 bits) times 2^g, read off in C (frexp, then the mantissa's lowest set
    bit); k is minus the smallest such g, so the X_i are as short as exact
    integers over one power of two can be.  Python integers keep the whole
    exponent range, and need no gcd as fractions do."""
    n: cython.int = len(values)
    odd = cython.declare(cython.longlong[8])
    grid = cython.declare(cython.int[8])
    m: cython.double
    e: cython.int
    whole: cython.longlong
    t: cython.int
    low: cython.int = 0
    for i in range(n):
        m, e = _norm(values[i], 0)
        whole = cython.cast(cython.longlong, m * 9007199254740992.0)  # m 2^53, exact
        odd[i] = 0
        grid[i] = 0
        if whole != 0:
            t = _exponent(cython.cast(cython.double, whole & -whole)) - 1  # its trailing zero bits
            odd[i] = whole >> t
            grid[i] = e - 53 + t
            low = min(low, grid[i])
    k: cython.int = -low
    xs = []
    x: object
    for i in range(n):
        x = odd[i]
        xs.append(x << (grid[i] + k) if odd[i] != 0 else x)
    return xs, k


def _ratio_to_float(num: int, den_exp: int) -> float:
    """Nearest double to num / 2^den_exp, saturating like `_unscale` (sign
    always kept)."""
    if num == 0:
        return 0.0
    sign = 1.0 if num > 0 else -1.0
    try:
        r = num / (1 << den_exp)  # correctly rounded
    except OverflowError:
        return sign * 1.7976931348623157e308
    if r == 0.0:
        return sign * 5e-324
    return r


def _orient2d_integer(ax, ay, bx, by, cx, cy) -> float:
    """orient2d determinant in exact integer arithmetic (rare fallback)."""
    (ax, ay, bx, by, cx, cy), k = _integers((ax, ay, bx, by, cx, cy))
    return _ratio_to_float((ax - cx) * (by - cy) - (ay - cy) * (bx - cx), 2 * k)


def _incircle_integer(ax, ay, bx, by, cx, cy, dx, dy) -> float:
    """incircle determinant in exact integer arithmetic (rare fallback)."""
    (ax, ay, bx, by, cx, cy, dx, dy), k = _integers((ax, ay, bx, by, cx, cy, dx, dy))
    adx, ady, bdx, bdy = ax - dx, ay - dy, bx - dx, by - dy
    cdx, cdy = cx - dx, cy - dy
    det = (
        (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
        + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
        + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady)
    )
    return _ratio_to_float(det, 4 * k)


def _dot_integer(ax, ay, bx, by, cx, cy, dx, dy) -> int:
    """The sign of (b - a) . (d - c) in exact integer arithmetic (rare fallback)."""
    (ax, ay, bx, by, cx, cy, dx, dy), _ = _integers((ax, ay, bx, by, cx, cy, dx, dy))
    dot = (bx - ax) * (dx - cx) + (by - ay) * (dy - cy)
    return 1 if dot > 0 else (-1 if dot < 0 else 0)


# ---------------------------------------------------------------------------
# Wide-range filter: stage A with an unbounded exponent
# ---------------------------------------------------------------------------
# A number m * 2^e is a pair (m, e) with m = 0 or 0.5 <= |m| < 1 and e a C
# int: products and sums of such pairs never under- or overflow, and each
# one is rounded once, relative to its result (a sum's smaller operand can
# lose bits below 2^-1074 of the larger one, which the filter's 2^-40 margin
# swamps), which is all Shewchuk's bound for stage A assumes.
@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _norm(m: cython.double, e: cython.int) -> tuple[cython.double, cython.int]:
    """(m', e') with m' * 2^e' == m * 2^e and m' normalized (frexp)."""
    k: cython.int = 0
    if cython.compiled:
        m = frexp(m, cython.address(k))
    else:
        m, k = math.frexp(m)
    return m, e + k


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _wmul(am: cython.double, ae: cython.int, bm: cython.double, be: cython.int) -> tuple[cython.double, cython.int]:
    """a b of normalized pairs: the mantissas' product lies in [0.25, 1), so
    at most one exact doubling normalizes it (the pair frexp would give)."""
    m: cython.double = am * bm
    e: cython.int = ae + be
    if m != 0.0 and fabs(m) < 0.5:
        m *= 2.0
        e -= 1
    return m, e


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _wadd(am: cython.double, ae: cython.int, bm: cython.double, be: cython.int) -> tuple[cython.double, cython.int]:
    if bm == 0.0:
        return am, ae
    if am == 0.0:
        return bm, be
    if ae < be:
        am, ae, bm, be = bm, be, am, ae
    if ae - be > 1100:  # b is below every bit of a
        return am, ae
    s: cython.double = am + (ldexp(bm, be - ae) if cython.compiled else math.ldexp(bm, be - ae))
    if s == 0.0:
        return 0.0, 0
    return _norm(s, ae)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _wabove(am: cython.double, ae: cython.int, bm: cython.double, be: cython.int) -> cython.bint:
    """|a| > b for normalized pairs, b >= 0."""
    if am == 0.0:
        return False
    if bm == 0.0:
        return True
    if ae != be:
        return ae > be
    return fabs(am) > bm


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _wminor(pm: cython.double, pe: cython.int, qm: cython.double, qe: cython.int,
            um: cython.double, ue: cython.int, vm: cython.double, ve: cython.int,
            ) -> tuple[cython.double, cython.int, cython.double, cython.int]:
    """p q - u v and its permanent |p q| + |u v| of normalized pairs, as pairs."""
    m1: cython.double
    e1: cython.int
    m2: cython.double
    e2: cython.int
    m1, e1 = _wmul(pm, pe, qm, qe)
    m2, e2 = _wmul(um, ue, vm, ve)
    dm: cython.double
    de: cython.int
    am: cython.double
    ae: cython.int
    dm, de = _wadd(m1, e1, -m2, e2)
    am, ae = _wadd(fabs(m1), e1, fabs(m2), e2)
    return dm, de, am, ae


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _wsquares(xm: cython.double, xe: cython.int, ym: cython.double, ye: cython.int) -> tuple[cython.double, cython.int]:
    """x^2 + y^2 of normalized pairs, as a pair."""
    m1: cython.double
    e1: cython.int
    m2: cython.double
    e2: cython.int
    m1, e1 = _wmul(xm, xe, xm, xe)
    m2, e2 = _wmul(ym, ye, ym, ye)
    return _wadd(m1, e1, m2, e2)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _orient2d_wide_at(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double, cx: cython.double, cy: cython.double,
) -> tuple[cython.bint, cython.double]:
    """Stage A of orient2d in unbounded-exponent arithmetic, translated to c.  (True, the
    determinant saturated to the double range) if its sign is certain;
    (False, 0) when the rounded differences overflow or the sign is
    not certain."""
    acx: cython.double = ax - cx
    bcx: cython.double = bx - cx
    acy: cython.double = ay - cy
    bcy: cython.double = by - cy
    if not (fabs(acx) <= _DBL_MAX and fabs(bcx) <= _DBL_MAX and fabs(acy) <= _DBL_MAX and fabs(bcy) <= _DBL_MAX):
        return False, 0.0
    dm: cython.double
    de: cython.int
    sm: cython.double
    se: cython.int
    acxm: cython.double
    acxe: cython.int
    bcxm: cython.double
    bcxe: cython.int
    acym: cython.double
    acye: cython.int
    bcym: cython.double
    bcye: cython.int
    acxm, acxe = _norm(acx, 0)
    bcxm, bcxe = _norm(bcx, 0)
    acym, acye = _norm(acy, 0)
    bcym, bcye = _norm(bcy, 0)
    dm, de, sm, se = _wminor(acxm, acxe, bcym, bcye, acym, acye, bcxm, bcxe)
    bm: cython.double
    be: cython.int
    bm, be = _norm(_CCW_WIDE, 0)
    sm, se = _wmul(sm, se, bm, be)
    if not _wabove(dm, de, sm, se):
        return False, 0.0
    return True, _unscale(dm, de)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _orient2d_wide(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double, cx: cython.double, cy: cython.double,
) -> tuple[cython.bint, cython.double]:
    """``_orient2d_wide_at`` translated to each point in turn (the
    determinant is invariant under cyclic shifts): the differences from a
    point of a tiny cluster to the others in it are exact, where those from
    a point far away lose the cluster's coordinates to rounding."""
    ok: cython.bint
    v: cython.double
    ok, v = _orient2d_wide_at(ax, ay, bx, by, cx, cy)
    if not ok:
        ok, v = _orient2d_wide_at(bx, by, cx, cy, ax, ay)
    if not ok:
        ok, v = _orient2d_wide_at(cx, cy, ax, ay, bx, by)
    return ok, v


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _translated(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double,
) -> tuple[cython.double, cython.double, cython.double, cython.double, cython.double, cython.double]:
    """a, b and c less d, rounded, as every stage of incircle starts
    (Triangle's adx, bdx, cdx, ady, bdy, cdy, in that order)."""
    return ax - dx, bx - dx, cx - dx, ay - dy, by - dy, cy - dy


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _incircle_wide_at(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double,
) -> tuple[cython.bint, cython.double]:
    """Stage A of incircle in unbounded-exponent arithmetic (the operations
    of ``_incircle_exact``'s stage A, in the same order), for coordinates too
    far apart to be scaled into the exact stages' range, translated to d.  (True, the
    determinant saturated to the double range) if its sign is certain;
    (False, 0) when a rounded difference overflows or the sign is not
    certain."""
    adx: cython.double
    bdx: cython.double
    cdx: cython.double
    ady: cython.double
    bdy: cython.double
    cdy: cython.double
    adx, bdx, cdx, ady, bdy, cdy = _translated(ax, ay, bx, by, cx, cy, dx, dy)
    if not (fabs(adx) <= _DBL_MAX and fabs(bdx) <= _DBL_MAX and fabs(cdx) <= _DBL_MAX
            and fabs(ady) <= _DBL_MAX and fabs(bdy) <= _DBL_MAX and fabs(cdy) <= _DBL_MAX):
        return False, 0.0
    m1: cython.double
    e1: cython.int
    # the three minors and their permanents
    bcm: cython.double
    bce: cython.int
    bcpm: cython.double
    bcpe: cython.int
    # each difference normalized once
    adxm: cython.double
    adxe: cython.int
    bdxm: cython.double
    bdxe: cython.int
    cdxm: cython.double
    cdxe: cython.int
    adym: cython.double
    adye: cython.int
    bdym: cython.double
    bdye: cython.int
    cdym: cython.double
    cdye: cython.int
    adxm, adxe = _norm(adx, 0)
    bdxm, bdxe = _norm(bdx, 0)
    cdxm, cdxe = _norm(cdx, 0)
    adym, adye = _norm(ady, 0)
    bdym, bdye = _norm(bdy, 0)
    cdym, cdye = _norm(cdy, 0)
    bcm, bce, bcpm, bcpe = _wminor(bdxm, bdxe, cdym, cdye, cdxm, cdxe, bdym, bdye)
    cam: cython.double
    cae: cython.int
    capm: cython.double
    cape: cython.int
    cam, cae, capm, cape = _wminor(cdxm, cdxe, adym, adye, adxm, adxe, cdym, cdye)
    abm: cython.double
    abe: cython.int
    abpm: cython.double
    abpe: cython.int
    abm, abe, abpm, abpe = _wminor(adxm, adxe, bdym, bdye, bdxm, bdxe, adym, adye)
    # the lifts
    alm: cython.double
    ale: cython.int
    alm, ale = _wsquares(adxm, adxe, adym, adye)
    blm: cython.double
    ble: cython.int
    blm, ble = _wsquares(bdxm, bdxe, bdym, bdye)
    clm: cython.double
    cle: cython.int
    clm, cle = _wsquares(cdxm, cdxe, cdym, cdye)
    # det = alift * bc + blift * ca + clift * ab, and its permanent
    dm: cython.double
    de: cython.int
    dm, de = _wmul(alm, ale, bcm, bce)
    m1, e1 = _wmul(blm, ble, cam, cae)
    dm, de = _wadd(dm, de, m1, e1)
    m1, e1 = _wmul(clm, cle, abm, abe)
    dm, de = _wadd(dm, de, m1, e1)
    pm: cython.double
    pe: cython.int
    pm, pe = _wmul(bcpm, bcpe, alm, ale)
    m1, e1 = _wmul(capm, cape, blm, ble)
    pm, pe = _wadd(pm, pe, m1, e1)
    m1, e1 = _wmul(abpm, abpe, clm, cle)
    pm, pe = _wadd(pm, pe, m1, e1)
    m1, e1 = _norm(_ICC_WIDE, 0)
    pm, pe = _wmul(pm, pe, m1, e1)
    if not _wabove(dm, de, pm, pe):
        return False, 0.0
    return True, _unscale(dm, de)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _incircle_wide(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double,
) -> tuple[cython.bint, cython.double]:
    """``_incircle_wide_at`` translated to each point in turn (a cyclic
    shift of the four rows changes the determinant's sign): three points
    1e-152 apart and a fourth 1e139 away are undecided from the far one,
    whose differences lose the cluster's coordinates, and decided from any
    of the three."""
    ok: cython.bint
    v: cython.double
    ok, v = _incircle_wide_at(ax, ay, bx, by, cx, cy, dx, dy)
    if ok:
        return ok, v
    ok, v = _incircle_wide_at(bx, by, cx, cy, dx, dy, ax, ay)
    if ok:
        return ok, -v
    ok, v = _incircle_wide_at(cx, cy, dx, dy, ax, ay, bx, by)
    if ok:
        return ok, v
    ok, v = _incircle_wide_at(dx, dy, ax, ay, bx, by, cx, cy)
    return ok, -v


# ---------------------------------------------------------------------------
# Past the filter: the range check and the ways on from it
# ---------------------------------------------------------------------------
@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _adaptive(c: cython.p_double, degree: cython.int) -> cython.double:
    """orient2d (``degree`` ``_ORIENT2D``, 2: the points a, b, c in
    ``c[0:6]``) or incircle (``_INCIRCLE``, 4: a, b, c, d in ``c[0:8]``)
    where the inlined filter could not decide.  One range check decides the
    way on for both (see the module docstring): coordinates in the exact
    stages' safe range go to them as they are; a range an exact power of
    two 2^k brings into it is scaled in place, and the value scaled back by
    2^(-degree k); a range too wide for that goes to stage A with an
    unbounded exponent, then, if still undecided, to Python integers; an
    infinite or NaN coordinate gets the plain determinant."""
    orient: cython.bint = degree == _ORIENT2D
    n: cython.int = 6 if orient else 8
    status: cython.int
    k: cython.int
    status, k = _choose_scale(c, n, _O_LOW if orient else _I_LOW, _O_HIGH if orient else _I_HIGH)
    if status == _ALLZERO:
        return 0.0
    if status == _NONFINITE:
        if orient:
            return orient2d_fast(c[0], c[1], c[2], c[3], c[4], c[5])
        return incircle_fast(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7])
    ok: cython.bint
    v: cython.double
    if status == _WIDE:
        if orient:
            ok, v = _orient2d_wide(c[0], c[1], c[2], c[3], c[4], c[5])
        else:
            ok, v = _incircle_wide(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7])
        if ok:
            return v
        with cython.gil:
            if orient:
                return _orient2d_integer(c[0], c[1], c[2], c[3], c[4], c[5])
            return _incircle_integer(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7])
    s: cython.double
    if k != 0:
        s = ldexp(1.0, k)
        for i in range(n):
            c[i] = c[i] * s
    if orient:
        v = _orient2d_exact(c[0], c[1], c[2], c[3], c[4], c[5])
    else:
        v = _incircle_exact(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7])
    return v if k == 0 else _unscale(v, -degree * k)


# ---------------------------------------------------------------------------
# orient2d
# ---------------------------------------------------------------------------
@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def orient2d_fast(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double, cx: cython.double, cy: cython.double
) -> cython.double:
    """Plain floating-point orient2d (Triangle's ``-X``); sign not guaranteed:
    ``(ax - cx) * (by - cy) - (ay - cy) * (bx - cx)``."""
    return (ax - cx) * (by - cy) - (ay - cy) * (bx - cx)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def orient2d_adaptive(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double, cx: cython.double, cy: cython.double
) -> cython.double:
    """orient2d when the inlined filter could not decide (``_adaptive``)."""
    coords = cython.declare(cython.double[6])
    coords[0] = ax
    coords[1] = ay
    coords[2] = bx
    coords[3] = by
    coords[4] = cx
    coords[5] = cy
    return _adaptive(coords, _ORIENT2D)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _orient2d_exact(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double, cx: cython.double, cy: cython.double
) -> cython.double:
    """Triangle's complete orient2d (stage 0, A, then adapt); inputs in safe range."""
    detleft: cython.double = (ax - cx) * (by - cy)
    detright: cython.double = (ay - cy) * (bx - cx)
    det: cython.double = detleft - detright
    detsum: cython.double
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
    errbound: cython.double = _CCWERRBOUNDA * detsum
    if det >= errbound or -det >= errbound:
        return det
    return _orient2d_adapt(ax, ay, bx, by, cx, cy, detsum)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _orient2d_adapt(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    cx: cython.double, cy: cython.double, detsum: cython.double,
) -> cython.double:
    """Stages B, C, D of orient2d (Shewchuk's counterclockwiseadapt)."""
    acx: cython.double = ax - cx
    bcx: cython.double = bx - cx
    acy: cython.double = ay - cy
    bcy: cython.double = by - cy
    dl1: cython.double
    dl0: cython.double
    dr1: cython.double
    dr0: cython.double
    dl1, dl0 = _two_product(acx, bcy)
    dr1, dr0 = _two_product(acy, bcx)
    w = cython.declare(cython.double[44])
    _store_two_two_diff(dl1, dl0, dr1, dr0, w, 0)  # the stage B expansion in w[0:4]
    det: cython.double = ((w[0] + w[1]) + w[2]) + w[3]
    errbound: cython.double = _CCWERRBOUNDB * detsum
    if det >= errbound or -det >= errbound:
        return det
    acxtail: cython.double = _two_diff_tail(ax, cx, acx)
    bcxtail: cython.double = _two_diff_tail(bx, cx, bcx)
    acytail: cython.double = _two_diff_tail(ay, cy, acy)
    bcytail: cython.double = _two_diff_tail(by, cy, bcy)
    if acxtail == 0.0 and acytail == 0.0 and bcxtail == 0.0 and bcytail == 0.0:
        return det
    errbound = _CCWERRBOUNDC * detsum + _RESULTERRBOUND * fabs(det)
    det += (acx * bcytail + bcy * acxtail) - (acy * bcxtail + bcx * acytail)
    if det >= errbound or -det >= errbound:
        return det
    n: cython.int = _orient2d_expansion_d(acx, acy, bcx, bcy, acxtail, acytail, bcxtail, bcytail, w)
    return w[28 + n - 1]


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _orient2d_expansion_d(
    acx: cython.double, acy: cython.double, bcx: cython.double, bcy: cython.double,
    acxtail: cython.double, acytail: cython.double, bcxtail: cython.double, bcytail: cython.double,
    w: cython.p_double,
) -> cython.int:
    """Stage D of orient2d: the exact determinant, left in ``w[28:28 + n]``;
    returns n.  ``w`` (44 doubles) holds the stage B expansion in w[0:4];
    w[4:8] is u, w[8:16] c1, w[16:28] c2, w[28:44] the result."""
    _product_diff4(acxtail, bcy, acytail, bcx, w, 4)
    c1len: cython.int = _expansion_sum(4, w, 0, 4, w, 4, w, 8)
    _product_diff4(acx, bcytail, acy, bcxtail, w, 4)
    c2len: cython.int = _expansion_sum(c1len, w, 8, 4, w, 4, w, 16)
    _product_diff4(acxtail, bcytail, acytail, bcxtail, w, 4)
    return _expansion_sum(c2len, w, 16, 4, w, 4, w, 28)


# ---------------------------------------------------------------------------
# incircle
# ---------------------------------------------------------------------------
@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def incircle_fast(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double,
) -> cython.double:
    """Plain floating-point incircle (Triangle's ``-X``); sign not guaranteed:
    Triangle's stage-0 determinant."""
    adx: cython.double
    bdx: cython.double
    cdx: cython.double
    ady: cython.double
    bdy: cython.double
    cdy: cython.double
    adx, bdx, cdx, ady, bdy, cdy = _translated(ax, ay, bx, by, cx, cy, dx, dy)
    alift: cython.double = adx * adx + ady * ady
    blift: cython.double = bdx * bdx + bdy * bdy
    clift: cython.double = cdx * cdx + cdy * cdy
    return alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def incircle_adaptive(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double,
) -> cython.double:
    """incircle when the inlined filter could not decide (``_adaptive``)."""
    coords = cython.declare(cython.double[8])
    coords[0] = ax
    coords[1] = ay
    coords[2] = bx
    coords[3] = by
    coords[4] = cx
    coords[5] = cy
    coords[6] = dx
    coords[7] = dy
    return _adaptive(coords, _INCIRCLE)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _incircle_exact(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double,
) -> cython.double:
    """Triangle's complete incircle (stage 0, A, then adapt); inputs in safe range."""
    adx: cython.double
    bdx: cython.double
    cdx: cython.double
    ady: cython.double
    bdy: cython.double
    cdy: cython.double
    adx, bdx, cdx, ady, bdy, cdy = _translated(ax, ay, bx, by, cx, cy, dx, dy)
    bdxcdy: cython.double = bdx * cdy
    cdxbdy: cython.double = cdx * bdy
    alift: cython.double = adx * adx + ady * ady
    cdxady: cython.double = cdx * ady
    adxcdy: cython.double = adx * cdy
    blift: cython.double = bdx * bdx + bdy * bdy
    adxbdy: cython.double = adx * bdy
    bdxady: cython.double = bdx * ady
    clift: cython.double = cdx * cdx + cdy * cdy
    det: cython.double = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady)
    permanent: cython.double = (
        (fabs(bdxcdy) + fabs(cdxbdy)) * alift
        + (fabs(cdxady) + fabs(adxcdy)) * blift
        + (fabs(adxbdy) + fabs(bdxady)) * clift
    )
    errbound: cython.double = _ICCERRBOUNDA * permanent
    if det > errbound or -det > errbound:
        return det
    return _incircle_adapt(ax, ay, bx, by, cx, cy, dx, dy, permanent)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _lifted_term(
    e: cython.p_double, eo: cython.int, x: cython.double, y: cython.double,
    w: cython.p_double, wo: cython.int, h: cython.p_double, ho: cython.int,
) -> cython.int:
    """h[ho:] = e[eo:eo + 4] * (x*x + y*y) as an expansion; returns its length.
    ``w[wo:wo + 48]`` is workspace."""
    n: cython.int = _scale_expansion(4, e, eo, x, w, wo)
    nxx: cython.int = _scale_expansion(n, w, wo, x, w, wo + 8)
    n = _scale_expansion(4, e, eo, y, w, wo + 24)
    nyy: cython.int = _scale_expansion(n, w, wo + 24, y, w, wo + 32)
    return _expansion_sum(nxx, w, wo + 8, nyy, w, wo + 32, h, ho)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _incircle_expansion_b(
    adx: cython.double, bdx: cython.double, cdx: cython.double,
    ady: cython.double, bdy: cython.double, cdy: cython.double, w: cython.p_double,
) -> cython.int:
    """Stage B of incircle: exact determinant of the rounded differences.

    ``w`` (316 doubles) is workspace; on return ``w[0:4]``, ``w[4:8]``,
    ``w[8:12]`` hold the minors bc, ca, ab and ``w[220:220 + n]`` the
    determinant, whose length n is returned."""
    _product_diff4(bdx, cdy, cdx, bdy, w, 0)
    _product_diff4(cdx, ady, adx, cdy, w, 4)
    _product_diff4(adx, bdy, bdx, ady, w, 8)
    alen: cython.int = _lifted_term(w, 0, adx, ady, w, 12, w, 60)
    blen: cython.int = _lifted_term(w, 4, bdx, bdy, w, 12, w, 92)
    clen: cython.int = _lifted_term(w, 8, cdx, cdy, w, 12, w, 124)
    ablen: cython.int = _expansion_sum(alen, w, 60, blen, w, 92, w, 156)
    return _expansion_sum(ablen, w, 156, clen, w, 124, w, 220)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _incircle_adapt(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double, permanent: cython.double,
) -> cython.double:
    """Stages B, C, D of incircle (Shewchuk's incircleadapt)."""
    adx: cython.double
    bdx: cython.double
    cdx: cython.double
    ady: cython.double
    bdy: cython.double
    cdy: cython.double
    adx, bdx, cdx, ady, bdy, cdy = _translated(ax, ay, bx, by, cx, cy, dx, dy)
    w = cython.declare(cython.double[316])
    finlen: cython.int = _incircle_expansion_b(adx, bdx, cdx, ady, bdy, cdy, w)
    det: cython.double = _estimate(finlen, w, 220)
    errbound: cython.double = _ICCERRBOUNDB * permanent
    if det >= errbound or -det >= errbound:
        return det
    adxt: cython.double = _two_diff_tail(ax, dx, adx)
    adyt: cython.double = _two_diff_tail(ay, dy, ady)
    bdxt: cython.double = _two_diff_tail(bx, dx, bdx)
    bdyt: cython.double = _two_diff_tail(by, dy, bdy)
    cdxt: cython.double = _two_diff_tail(cx, dx, cdx)
    cdyt: cython.double = _two_diff_tail(cy, dy, cdy)
    if adxt == 0.0 and bdxt == 0.0 and cdxt == 0.0 and adyt == 0.0 and bdyt == 0.0 and cdyt == 0.0:
        return det
    errbound = _ICCERRBOUNDC * permanent + _RESULTERRBOUND * fabs(det)
    det += (
        (
            (adx * adx + ady * ady) * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt))
            + 2.0 * (adx * adxt + ady * adyt) * (bdx * cdy - bdy * cdx)
        )
        + (
            (bdx * bdx + bdy * bdy) * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt))
            + 2.0 * (bdx * bdxt + bdy * bdyt) * (cdx * ady - cdy * adx)
        )
        + (
            (cdx * cdx + cdy * cdy) * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt))
            + 2.0 * (cdx * cdxt + cdy * cdyt) * (adx * bdy - ady * bdx)
        )
    )
    if det >= errbound or -det >= errbound:
        return det
    # Stage D's work space lives in this frame: two alternating buffers for
    # the growing expansion, and workspace for the terms.
    fin = cython.declare(cython.double[2304])
    t = cython.declare(cython.double[256])
    lifts = cython.declare(cython.double[12])
    xt = cython.declare(cython.double[48])
    xtlen = cython.declare(cython.int[6])
    small = cython.declare(cython.double[20])
    base: cython.int
    n: cython.int
    base, n = _incircle_expansion_d(
        adx, bdx, cdx, ady, bdy, cdy, adxt, bdxt, cdxt, adyt, bdyt, cdyt, w, finlen, fin, t, lifts, xt, xtlen, small
    )
    return fin[base + n - 1]


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _lift4(x: cython.double, y: cython.double, h: cython.p_double, ho: cython.int) -> cython.void:
    """h[ho:ho + 4] = exact expansion of x*x + y*y."""
    x1: cython.double
    x0: cython.double
    y1: cython.double
    y0: cython.double
    x1, x0 = _square(x)
    y1, y0 = _square(y)
    _store_two_two_sum(x1, x0, y1, y0, h, ho)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _fin_add(
    fin: cython.p_double, base: cython.int, flen: cython.int, elen: cython.int, e: cython.p_double, eo: cython.int
) -> tuple[cython.int, cython.int]:
    """Add e[eo:eo + elen] to the expansion fin[base:base + flen], writing the
    sum into the other half of ``fin``; returns (its base, its length)."""
    other: cython.int = _FIN_SIZE - base
    return other, _expansion_sum(flen, fin, base, elen, e, eo, fin, other)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _first_order(
    fin: cython.p_double, base: cython.int, flen: cython.int,
    mnr: cython.p_double, mo: cython.int, tail: cython.double, two_head: cython.double,
    e2: cython.p_double, e2o: cython.int, m2: cython.double,
    e3: cython.p_double, e3o: cython.int, m3: cython.double,
    xt: cython.p_double, xto: cython.int, t: cython.p_double,
) -> tuple[cython.int, cython.int, cython.int]:
    """Add one tail's first-order terms to the expansion fin[base:base + flen]:
    ``tail * (minor * two_head + e2 * m2 + e3 * m3)`` where ``minor`` is the
    point's own 2x2 minor (4 components at mnr[mo:]), ``e2``/``e3`` the other
    two lifts.  Leaves ``minor * tail`` in ``xt[xto:]`` for the second-order
    terms.  ``t`` (>= 136) is workspace.  Returns (len(xt), new base, new
    length)."""
    xtlen: cython.int = _scale_expansion(4, mnr, mo, tail, xt, xto)
    n16a: cython.int = _scale_expansion(xtlen, xt, xto, two_head, t, 8)
    n8: cython.int = _scale_expansion(4, e2, e2o, tail, t, 0)
    n16b: cython.int = _scale_expansion(n8, t, 0, m2, t, 24)
    n8 = _scale_expansion(4, e3, e3o, tail, t, 0)
    n16c: cython.int = _scale_expansion(n8, t, 0, m3, t, 40)
    n32a: cython.int = _expansion_sum(n16a, t, 8, n16b, t, 24, t, 56)
    n48: cython.int = _expansion_sum(n16c, t, 40, n32a, t, 56, t, 88)
    base, flen = _fin_add(fin, base, flen, n48, t, 88)
    return xtlen, base, flen


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _tail_minors(
    pt: cython.double, q: cython.double, p: cython.double, qt: cython.double,
    rt: cython.double, s: cython.double, r: cython.double, st: cython.double, small: cython.p_double,
) -> tuple[cython.int, cython.int]:
    """First- and second-order tail parts of the minor (p+pt)(q+qt) - (r+rt)(s+st).

    ``small[0:8]`` (tct) gets ``pt*q + p*qt - rt*s - r*st`` and
    ``small[8:12]`` (tctt) gets ``pt*qt - rt*st`` (both as expansions);
    returns their lengths.  Both are [0] when all four tails are zero.
    ``small[12:20]`` is workspace."""
    if pt == 0.0 and qt == 0.0 and rt == 0.0 and st == 0.0:
        small[0] = 0.0
        small[8] = 0.0
        return 1, 1
    i1: cython.double
    i0: cython.double
    j1: cython.double
    j0: cython.double
    i1, i0 = _two_product(pt, q)
    j1, j0 = _two_product(p, qt)
    _store_two_two_sum(i1, i0, j1, j0, small, 12)
    i1, i0 = _two_product(rt, -s)
    j1, j0 = _two_product(r, -st)
    _store_two_two_sum(i1, i0, j1, j0, small, 16)
    n: cython.int = _expansion_sum(4, small, 12, 4, small, 16, small, 0)
    _product_diff4(pt, qt, rt, st, small, 8)
    return n, 4


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _second_order(
    fin: cython.p_double, base: cython.int, flen: cython.int,
    xt: cython.p_double, xto: cython.int, xtlen: cython.int,
    small: cython.p_double, tctlen: cython.int, tcttlen: cython.int,
    tail: cython.double, head: cython.double,
    c1e: cython.p_double, c1o: cython.int, c1s: cython.double, c1m: cython.double,
    c2e: cython.p_double, c2o: cython.int, c2s: cython.double, c2m: cython.double,
    t: cython.p_double,
) -> tuple[cython.int, cython.int]:
    """Add one tail's higher-order terms to fin[base:base + flen]:
    ``tail^2 * minor + (2 head tail + tail^2) * (tct + tctt)`` where ``xt`` is
    ``minor * tail`` and tct/tctt sit in ``small`` (see ``_tail_minors``), plus
    the cross terms ``c1e * c1s * c1m`` and ``c2e * c2s * c2m`` (skipped when
    the multiplier ``c?m`` is zero).  ``t`` (>= 256) is workspace.  Returns
    (new base, new length)."""
    n16a: cython.int = _scale_expansion(xtlen, xt, xto, tail, t, 8)
    nxtct: cython.int = _scale_expansion(tctlen, small, 0, tail, t, 232)
    n32a: cython.int = _scale_expansion(nxtct, t, 232, 2.0 * head, t, 56)
    n48: cython.int = _expansion_sum(n16a, t, 8, n32a, t, 56, t, 88)
    base, flen = _fin_add(fin, base, flen, n48, t, 88)
    n8: cython.int
    if c1m != 0.0:
        n8 = _scale_expansion(4, c1e, c1o, c1s, t, 0)
        n16a = _scale_expansion(n8, t, 0, c1m, t, 8)
        base, flen = _fin_add(fin, base, flen, n16a, t, 8)
    if c2m != 0.0:
        n8 = _scale_expansion(4, c2e, c2o, c2s, t, 0)
        n16a = _scale_expansion(n8, t, 0, c2m, t, 8)
        base, flen = _fin_add(fin, base, flen, n16a, t, 8)
    n32a = _scale_expansion(nxtct, t, 232, tail, t, 56)
    nxtctt: cython.int = _scale_expansion(tcttlen, small, 8, tail, t, 248)
    n16a = _scale_expansion(nxtctt, t, 248, 2.0 * head, t, 8)
    n16b: cython.int = _scale_expansion(nxtctt, t, 248, tail, t, 24)
    n32b: cython.int = _expansion_sum(n16a, t, 8, n16b, t, 24, t, 136)
    n64: cython.int = _expansion_sum(n32a, t, 56, n32b, t, 136, t, 168)
    return _fin_add(fin, base, flen, n64, t, 168)


@cython.cfunc
@cython.nogil
@cython.exceptval(check=False)
def _incircle_expansion_d(
    adx: cython.double, bdx: cython.double, cdx: cython.double,
    ady: cython.double, bdy: cython.double, cdy: cython.double,
    adxt: cython.double, bdxt: cython.double, cdxt: cython.double,
    adyt: cython.double, bdyt: cython.double, cdyt: cython.double,
    wb: cython.p_double, finlen: cython.int, fin: cython.p_double, t: cython.p_double,
    lifts: cython.p_double, xt: cython.p_double, xtlen: cython.p_int, small: cython.p_double,
) -> tuple[cython.int, cython.int]:
    """Stage D of incircle: add every term that involves a tail.

    The six tails are visited in Triangle's order (adx, ady, bdx, bdy, cdx, cdy),
    first for their first-order terms, then point by point for the higher-order
    ones. Point i's own minor is ``wb[4i:4i + 4]`` (bc, ca, ab) and its lift
    ``lifts[4i:4i + 4]``; j and k are the next two points in cyclic order.
    ``wb`` is stage B's workspace (its expansion of length ``finlen`` at
    ``wb[220:]``); ``fin`` (2 x 1152) holds the growing expansion in one half
    and receives each sum in the other; ``t`` (256), ``xt`` (6 x 8),
    ``xtlen`` (6) and ``small`` (20) are workspace.  Returns (base, n): the
    exact determinant is ``fin[base:base + n]``, its largest part last.
    """
    dxs = cython.declare(cython.double[3])
    dys = cython.declare(cython.double[3])
    xts = cython.declare(cython.double[3])
    yts = cython.declare(cython.double[3])
    dxs[0], dxs[1], dxs[2] = adx, bdx, cdx
    dys[0], dys[1], dys[2] = ady, bdy, cdy
    xts[0], xts[1], xts[2] = adxt, bdxt, cdxt
    yts[0], yts[1], yts[2] = adyt, bdyt, cdyt
    i: cython.int
    j: cython.int
    k: cython.int
    for i in range(3):
        _lift4(dxs[i], dys[i], lifts, 4 * i)
    _copy(finlen, wb, 220, fin, 0)
    base: cython.int = 0
    flen: cython.int = finlen
    for i in range(6):  # minor * tail, kept for the higher-order terms
        xtlen[i] = 0
        for j in range(8):
            xt[8 * i + j] = 0.0
    tail: cython.double
    head: cython.double
    is_y: cython.int
    for q in range(6):
        i = q // 2
        is_y = q % 2
        j = (i + 1) % 3
        k = (i + 2) % 3
        tail = yts[i] if is_y else xts[i]
        if tail == 0.0:
            continue
        if is_y:
            xtlen[q], base, flen = _first_order(
                fin, base, flen, wb, 4 * i, tail, 2.0 * dys[i], lifts, 4 * j, dxs[k], lifts, 4 * k, -dxs[j], xt, 8 * q, t
            )
        else:
            xtlen[q], base, flen = _first_order(
                fin, base, flen, wb, 4 * i, tail, 2.0 * dxs[i], lifts, 4 * k, dys[j], lifts, 4 * j, -dys[k], xt, 8 * q, t
            )
    n1: cython.int
    n2: cython.int
    for i in range(3):
        if xts[i] == 0.0 and yts[i] == 0.0:
            continue
        j = (i + 1) % 3
        k = (i + 2) % 3
        n1, n2 = _tail_minors(xts[j], dys[k], dxs[j], yts[k], xts[k], dys[j], dxs[k], yts[j], small)
        for is_y in range(2):
            tail = yts[i] if is_y else xts[i]
            if tail == 0.0:
                continue
            q = 2 * i + is_y
            if is_y:  # the x'y' cross terms all sit with the x tails
                base, flen = _second_order(
                    fin, base, flen, xt, 8 * q, xtlen[q], small, n1, n2, tail, dys[i],
                    lifts, 4 * k, 0.0, 0.0, lifts, 4 * j, 0.0, 0.0, t,
                )
            else:
                base, flen = _second_order(
                    fin, base, flen, xt, 8 * q, xtlen[q], small, n1, n2, tail, dxs[i],
                    lifts, 4 * k, tail, yts[j], lifts, 4 * j, -tail, yts[k], t,
                )
    return base, flen


# ---------------------------------------------------------------------------
# dot_sign
# ---------------------------------------------------------------------------
@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _dot_safe(w: cython.double) -> cython.bint:
    """0, or a magnitude whose products with others of [2^-480, 2^480] are normal."""
    return w == 0.0 or (fabs(w) >= 2.0**-480 and fabs(w) <= 2.0**480)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def dot_sign(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    cx: cython.double, cy: cython.double, dx: cython.double, dy: cython.double,
) -> cython.int:
    """The exact sign (-1, 0 or 1) of (b - a) . (d - c), for finite coordinates.

    The sum of two products of rounded differences has orient2d's stage A
    error bound; it is trusted where every nonzero difference lies in
    [2^-480, 2^480] (no product under- or overflows); otherwise, or when
    the bound cannot decide, the sign is computed with Python integers
    (the callers ask rarely: only about vertices within rounding of a
    segment crossing)."""
    ux: cython.double = bx - ax
    uy: cython.double = by - ay
    vx: cython.double = dx - cx
    vy: cython.double = dy - cy
    if _dot_safe(ux) and _dot_safe(uy) and _dot_safe(vx) and _dot_safe(vy):
        left: cython.double = ux * vx
        right: cython.double = uy * vy
        det: cython.double = left + right
        if fabs(det) > _CCWERRBOUNDA * (fabs(left) + fabs(right)) or left == 0.0 or right == 0.0:
            return 1 if det > 0.0 else (-1 if det < 0.0 else 0)
    with cython.gil:
        return _dot_integer(ax, ay, bx, by, cx, cy, dx, dy)


# ---------------------------------------------------------------------------
# The inlined fast paths: compiled, they come from predicates.pxd; these are
# the same functions for the pure-Python mode (tests compare the two).
# ---------------------------------------------------------------------------
if not cython.compiled:

    def orient2d(ax, ay, bx, by, cx, cy):
        """Exact-sign orientation of the triangle a, b, c (finite coordinates).

        Positive iff a, b, c are counter-clockwise, negative iff clockwise,
        zero iff collinear.  Approximately twice the signed area: exactly
        Triangle's ``det`` when the filter certifies it, else the adaptive
        stage's value."""
        detleft = (ax - cx) * (by - cy)
        detright = (ay - cy) * (bx - cx)
        det = detleft - detright
        detsum = abs(detleft) + abs(detright)
        if abs(det) >= CCWERRBOUNDA * detsum:
            if (detsum >= O_LO) & (detsum <= 1.7976931348623157e308):
                return det
        return orient2d_adaptive(ax, ay, bx, by, cx, cy)

    def incircle(ax, ay, bx, by, cx, cy, dx, dy):
        """Exact-sign in-circle test of d against the circle through the
        counter-clockwise a, b, c (finite coordinates): positive iff d is
        strictly inside, negative iff strictly outside, zero iff cocircular.
        Exactly Triangle's ``det`` when the filter certifies it, else the
        adaptive stage's value."""
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
        det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady)
        permanent = (
            (abs(bdxcdy) + abs(cdxbdy)) * alift
            + (abs(cdxady) + abs(adxcdy)) * blift
            + (abs(adxbdy) + abs(bdxady)) * clift
        )
        if abs(det) > ICC_A_SAFE * permanent:
            if (permanent >= I_LO) & (alift + blift + clift <= I_SMAX):
                return det
        return incircle_adaptive(ax, ay, bx, by, cx, cy, dx, dy)
