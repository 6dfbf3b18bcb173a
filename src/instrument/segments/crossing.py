# cython: language_level=3
"""Where two segments cross, correctly rounded.

A segment that crosses another gets a vertex at the crossing, which is
rounded to doubles; the rounding moves the two pieces' lines, and a vertex
closer to a line than that error can change sides (a vertex 2.1e-17 from a
segment in the unit square did, which closed a gap of 2e-17 and enclosed
another domain).  The crossing point was r + t (l - r) with t from a ratio
of cross products: a few units in the last place off, so whether a near
vertex kept its side was an accident of the formula.  Here it is the exact
intersection of the two lines rounded once to the nearest double per
coordinate, so the answer depends on the geometry alone.

A filter evaluates the point in long double (taken to have at least a
64-bit significand where it is wider than double: x87 or quad; and a range
that no product of doubles leaves) with a forward error bound; when the
bound cannot certify the rounding (or long double is no wider than double,
or the kernels run uncompiled) the point is computed in exact rational
arithmetic.

``scouted_crossing`` is the other way, Triangle's, measured from its output
(tests/differential/known.py's former ``star-size``): the crossing as the
crossed subsegment's end ``r`` plus t times the subsegment, t a ratio of
cross products taken against the inserted piece's far end, all in doubles.
It depends on which end the piece is walked from (that end is e1), so two
meshers that round the same crossing each its own way start refinement
from points a few units in the last place apart and part.  Segment recovery
uses it where it is well conditioned and the exact rounding elsewhere, and
beside an input vertex that ends the crossed subsegment, where Triangle's
point decides whether the crossing is a vertex of its own an ulp or two
beside that end, or the end itself (recover.py's ``_split_at_crossing``).
"""

from __future__ import annotations

from fractions import Fraction

import cython
from cython.cimports.instrument.core.scaling import crossing_terms, unit_scale
from cython.cimports.libc.math import fabs, nextafter

# The filter's slack over its first-order error terms (covers the
# second-order ones, which are below 2^-100 relative).
_SLACK = cython.declare(cython.double, 1.25)


def _nearest(x: Fraction) -> float:
    try:
        return float(x)
    except OverflowError:
        return 1.7976931348623157e308 if x > 0 else -1.7976931348623157e308


def _exact_point(ax, ay, bx, by, rx, ry, lx, ly) -> tuple[float, float]:
    """The crossing in rational arithmetic; t clamped to [0, 1] along r -> l,
    0.5 where the lines are parallel."""
    ax, ay, bx, by, rx, ry, lx, ly = (Fraction(v) for v in (ax, ay, bx, by, rx, ry, lx, ly))
    ex, ey, tx, ty, wx, wy = bx - ax, by - ay, lx - rx, ly - ry, rx - ax, ry - ay
    den = ty * ex - tx * ey
    t = Fraction(1, 2)
    if den != 0:
        t = min(max((ey * wx - ex * wy) / den, Fraction(0)), Fraction(1))
    return _nearest(rx + t * tx), _nearest(ry + t * ty)


@cython.cfunc
@cython.inline
@cython.nogil
@cython.exceptval(check=False)
def _certain(v: cython.longdouble, err: cython.longdouble, p: cython.double) -> cython.bint:
    """Is p the nearest double to every value within err of v?  (Strictly
    inside p's rounding interval, so no tie either.)"""
    if not (fabs(p) <= 1.7976931348623157e308):
        return False
    lo: cython.double = nextafter(p, -2.0e308)
    hi: cython.double = nextafter(p, 2.0e308)
    half_down: cython.longdouble = (cython.cast(cython.longdouble, p) - lo) * 0.5
    half_up: cython.longdouble = (cython.cast(cython.longdouble, hi) - p) * 0.5
    d: cython.longdouble = v - p
    return d + err < half_up and -d + err < half_down


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def crossing_point(
    ax: cython.double, ay: cython.double, bx: cython.double, by: cython.double,
    rx: cython.double, ry: cython.double, lx: cython.double, ly: cython.double,
) -> tuple[cython.double, cython.double]:
    """The point where the line a -> b crosses the segment r -> l, each
    coordinate the nearest double to the exact one (t clamped to [0, 1]
    along r -> l; the midpoint where the lines are parallel)."""
    ex: cython.longdouble
    ey: cython.longdouble
    tx: cython.longdouble
    ty: cython.longdouble
    wx: cython.longdouble
    wy: cython.longdouble
    n1: cython.longdouble
    n2: cython.longdouble
    d1: cython.longdouble
    d2: cython.longdouble
    num: cython.longdouble
    den: cython.longdouble
    num_err: cython.longdouble
    den_err: cython.longdouble
    t: cython.longdouble
    rel: cython.longdouble
    vx: cython.longdouble
    vy: cython.longdouble
    errx: cython.longdouble
    erry: cython.longdouble
    px: cython.double
    py: cython.double
    u: cython.longdouble = 2.0**-64  # unit roundoff of an x87 long double (or better)
    if cython.compiled and cython.sizeof(cython.longdouble) > 8:
        ex = cython.cast(cython.longdouble, bx) - ax
        ey = cython.cast(cython.longdouble, by) - ay
        tx = cython.cast(cython.longdouble, lx) - rx
        ty = cython.cast(cython.longdouble, ly) - ry
        wx = cython.cast(cython.longdouble, rx) - ax
        wy = cython.cast(cython.longdouble, ry) - ay
        # each difference within u of itself, each product within u: a
        # product of two within 3u, the difference of two within 4u of the
        # sum of their magnitudes (to first order; _SLACK covers the rest)
        n1 = ey * wx
        n2 = ex * wy
        d1 = ty * ex
        d2 = tx * ey
        num = n1 - n2
        den = d1 - d2
        num_err = 4.0 * u * (fabs(n1) + fabs(n2))
        den_err = 4.0 * u * (fabs(d1) + fabs(d2))
        if fabs(den) > 2.0 * den_err and fabs(num) > 2.0 * num_err and (num > 0) == (den > 0):
            t = num / den
            # t within rel * t (1 / (1 - den's error) <= 1 + 4 (...) here)
            rel = (num_err / fabs(num) + den_err / fabs(den) + u) * (
                1.0 + 4.0 * (num_err / fabs(num) + den_err / fabs(den)))
            if t > 2.0 * rel and t < 1.0 - 2.0 * rel:  # no clamping near
                # t * tx within (rel + 2u) |t tx|; the sum within u more
                vx = t * tx
                vy = t * ty
                errx = _SLACK * ((rel + 2.0 * u) * fabs(vx) + u * fabs(rx + vx))
                erry = _SLACK * ((rel + 2.0 * u) * fabs(vy) + u * fabs(ry + vy))
                vx = rx + vx
                vy = ry + vy
                px = cython.cast(cython.double, vx)
                py = cython.cast(cython.double, vy)
                if _certain(vx, errx, px) and _certain(vy, erry, py):
                    return px, py
    with cython.gil:
        return _exact_point(ax, ay, bx, by, rx, ry, lx, ly)


@cython.ccall
@cython.nogil
@cython.exceptval(check=False)
def scouted_crossing(
    e1x: cython.double, e1y: cython.double, e2x: cython.double, e2y: cython.double,
    rx: cython.double, ry: cython.double, lx: cython.double, ly: cython.double,
) -> tuple[cython.double, cython.double, cython.double]:
    """``(t, x, y)``: where the piece e1 -> e2 crosses the subsegment r -> l
    (``r`` right of e1 -> e2), computed in doubles as Triangle does:
    ``t = (ey wx - ex wy) / (ty ex - tx ey)`` with ``e = e2 - e1``,
    ``T = l - r``, ``w = r - e2``, and the point ``r + t T``.  ``t`` is -1
    where the lines are parallel or t is outside [0, 1] (the caller rounds
    the exact crossing then).  t can round to exactly 0 or 1 where the
    segments cross within rounding of an end of ``r l``: Triangle then
    inserts a vertex at (or an ulp beside) that end, which the caller
    decides about.

    The differences are scaled by a power of two where they leave
    [2^-240, 2^240], so that the products of two neither overflow nor
    vanish; t (a ratio) is then what the unscaled formula gives wherever
    that does not overflow or underflow, and the result stays the scaled
    copy of the result at another scale."""
    num: cython.double
    den: cython.double
    num, den = crossing_terms(e1x, e1y, e2x, e2y, rx, ry, lx, ly, e2x, e2y)
    if not (den != 0.0):
        return -1.0, 0.0, 0.0
    t: cython.double = num / den
    if not (t >= 0.0 and t <= 1.0):
        return -1.0, 0.0, 0.0
    return t, rx + t * (lx - rx), ry + t * (ly - ry)
