# cython: language_level=3
"""Exact rescaling by powers of two, for the kernels' non-predicate arithmetic.

The predicates are exact for any finite coordinates, but lengths, areas,
circumcentres and crossing points are plain floating point: squared lengths
overflow once coordinates pass about 2^511 (1e154) and lose every bit below
about 2^-537 (1e-162), where products fall under the subnormal range.  A
kernel that meets such magnitudes (a cheap range test first, written where
the products are: 2^+-240 for degree-4 products in segment recovery, 2^+-160
in the quality test, so ordinary inputs pay nothing) multiplies its operands by ``unit_scale(m)``, a power of
two that brings the largest magnitude ``m`` into [0.5, 1): the scaling is
exact (barring subnormal operands, which only gain bits), every ratio and
sign it computes is unchanged, and a point computed in scaled coordinates is
mapped back exactly by dividing by the same power of two.
"""

from __future__ import annotations

import math

import cython
from cython.cimports.instrument.core.mesh import Index
from cython.cimports.libc.math import fabs, frexp, isfinite, ldexp

@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def unit_scale(m: cython.double) -> cython.double:
    """The power of two f with ``m * f`` in [0.5, 1) (1 for 0, infinity or
    NaN); at most 2^1000, so for subnormal m ``m * f`` is only at least
    2^-74 (a factor above 2^1023 is not a double)."""
    if not (m > 0.0 and m <= 1.7976931348623157e308):
        return 1.0
    e: cython.int = 0
    biased: cython.ulonglong
    if cython.compiled:
        # m = mantissa 2^e with the mantissa in [0.5, 1): a normal m's biased
        # exponent is e + 1022, and where 2^-e is normal and e >= -1000 its
        # bits are written at once (frexp and ldexp, library calls, took four
        # times as many instructions; splits._collapsed asks on every split
        # point outside its own triangle)
        biased = (double_bits(m) >> 52) & 0x7FF
        if 22 <= biased <= 2044:
            return bits_double((2045 - biased) << 52)
        frexp(m, cython.address(e))
    else:
        e = math.frexp(m)[1]
    if e < -1000:
        e = -1000
    return ldexp(1.0, -e) if cython.compiled else math.ldexp(1.0, -e)



if not cython.compiled:  # compiled, scaling.pxd's inline definition is used

    def scaled_pair(ux, uy, vx, vy, limit):
        """The vectors u and v, times ``unit_scale`` of their largest component
        when that lies outside [1/limit, limit] (limit a power of two)."""
        big = max(abs(ux), abs(uy), abs(vx), abs(vy))
        if not (big <= limit and big >= 1.0 / limit) and big > 0.0:
            f = unit_scale(big)
            return ux * f, uy * f, vx * f, vy * f
        return ux, uy, vx, vy

    def scaled_triple(ux, uy, vx, vy, wx, wy, limit):
        """``scaled_pair`` for three vectors (a triangle's edges, say)."""
        big = max(abs(ux), abs(uy), abs(vx), abs(vy), abs(wx), abs(wy))
        if not (big <= limit and big >= 1.0 / limit) and big > 0.0:
            f = unit_scale(big)
            return ux * f, uy * f, vx * f, vy * f, wx * f, wy * f
        return ux, uy, vx, vy, wx, wy


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def scaled_dot(ux: cython.double, uy: cython.double, vx: cython.double, vy: cython.double) -> cython.double:
    """``ux vx + uy vy``, or that times a power of two where the products
    would over- or underflow (components beyond 2^+-500): its sign is right
    at any scale, its magnitude only in range."""
    ux, uy, vx, vy = scaled_pair(ux, uy, vx, vy, 2.0**500)
    return ux * vx + uy * vy


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def crossing_terms(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    rx: cython.double, ry: cython.double, lx: cython.double, ly: cython.double,
    ox: cython.double, oy: cython.double,
) -> tuple[cython.double, cython.double]:
    """``(num, den)`` with ``t = num / den`` where the line a -> b crosses the
    line r -> l, as a parameter along r -> l: ``num = ey wx - ex wy`` and
    ``den = ty ex - tx ey`` for ``e = b - a``, ``T = l - r`` and ``w = r - o``
    (o is a or b: the caller's choice fixes the rounding it reproduces).

    Both are of degree 2 in the coordinate differences: near 2^512 they
    overflow, and below about 2^-537 they vanish.  Where the largest
    difference leaves [2^-240, 2^240] all six are scaled by one power of two
    (quartered first where a difference overflowed), which leaves their
    ratio and signs unchanged."""
    ex: cython.double = bx - ax
    ey: cython.double = by - ay
    tx: cython.double = lx - rx
    ty: cython.double = ly - ry
    wx: cython.double = rx - ox
    wy: cython.double = ry - oy
    mx: cython.double = max(max(max(fabs(ex), fabs(ey)), max(fabs(tx), fabs(ty))), max(fabs(wx), fabs(wy)))
    f: cython.double
    if not (mx <= 2.0**240 and mx >= 2.0**-240):
        if not mx <= 1.7976931348623157e308:
            ex = 0.25 * bx - 0.25 * ax
            ey = 0.25 * by - 0.25 * ay
            tx = 0.25 * lx - 0.25 * rx
            ty = 0.25 * ly - 0.25 * ry
            wx = 0.25 * rx - 0.25 * ox
            wy = 0.25 * ry - 0.25 * oy
            mx = max(max(max(fabs(ex), fabs(ey)), max(fabs(tx), fabs(ty))), max(fabs(wx), fabs(wy)))
        f = unit_scale(mx)
        ex *= f
        ey *= f
        tx *= f
        ty *= f
        wx *= f
        wy *= f
    return ey * wx - ex * wy, ty * ex - tx * ey


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def half_extent(xy: cython.double[:, ::1], n: Index) -> cython.double:
    """Half the larger side of the bounding box of rows ``0 .. n-1`` of
    ``xy`` (finite coordinates), from the halves of its ends, as the side
    itself can be beyond the doubles; 0 for no rows.  (One pass: numpy's
    four reductions over the columns cost six times as much on la.poly.)"""
    if n <= 0:
        return 0.0
    x0: cython.double = xy[0, 0]
    x1: cython.double = x0
    y0: cython.double = xy[0, 1]
    y1: cython.double = y0
    for i in range(1, n):
        x0 = min(x0, xy[i, 0])
        x1 = max(x1, xy[i, 0])
        y0 = min(y0, xy[i, 1])
        y1 = max(y1, xy[i, 1])
    return max(x1 / 2 - x0 / 2, y1 / 2 - y0 / 2)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def all_finite(xy: cython.double[:, ::1]) -> cython.bint:
    """Every entry of ``xy`` is finite (no infinity, no NaN), as the
    rescaling here and the predicates assume of the input's coordinates.
    (One pass: numpy's isfinite and all cost some 11k instructions even on
    three vertices.)"""
    for i in range(xy.shape[0]):
        for k in range(xy.shape[1]):
            if not isfinite(xy[i, k]):
                return False
    return True
