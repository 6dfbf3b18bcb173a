"""Tests of instrument/core/predicates.py against exact rational arithmetic.

The oracle is `fractions.Fraction`: every double is a dyadic rational, so the
determinants below are computed exactly.
"""

from __future__ import annotations

import json
import math
import os
import pathlib
import subprocess
import sys
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from instrument import purepython
from instrument.core import predicates as P
from instrument.core.predicates import incircle, incircle_fast, orient2d, orient2d_fast

MODULE_PATH = pathlib.Path(P.__file__).with_suffix("").with_suffix(".py")
#: the module run as Python, whose internals (the exact stages) tests can call
SOURCE = purepython.load_source("instrument.core.predicates")


# ---------------------------------------------------------------------------
# Oracles
# ---------------------------------------------------------------------------
def exact_orient(ax, ay, bx, by, cx, cy) -> Fraction:
    ax, ay, bx, by, cx, cy = map(Fraction, (ax, ay, bx, by, cx, cy))
    return (ax - cx) * (by - cy) - (ay - cy) * (bx - cx)


def exact_incircle(ax, ay, bx, by, cx, cy, dx, dy) -> Fraction:
    ax, ay, bx, by, cx, cy, dx, dy = map(Fraction, (ax, ay, bx, by, cx, cy, dx, dy))
    adx, ady, bdx, bdy, cdx, cdy = ax - dx, ay - dy, bx - dx, by - dy, cx - dx, cy - dy
    return (
        (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
        + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
        + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady)
    )


def sign(x) -> int:
    return int(x > 0) - int(x < 0)


def check_orient(*c):
    got = orient2d(*c)
    assert sign(got) == sign(exact_orient(*c)), c
    return got


def check_incircle(*c):
    got = incircle(*c)
    assert sign(got) == sign(exact_incircle(*c)), c
    return got


def scaled(coords, k):
    """coords * 2^k, or None if that is not exact (underflow / overflow)."""
    out = tuple(v * 2.0**k for v in coords)
    if all(math.ldexp(w, -k) == v for v, w in zip(coords, out)):
        return out
    return None


def nudge(x: float, ulps: int) -> float:
    for _ in range(abs(ulps)):
        x = math.nextafter(x, math.inf if ulps > 0 else -math.inf)
    return x


# ---------------------------------------------------------------------------
# Conventions and constants
# ---------------------------------------------------------------------------
def test_constants_match_reference():
    table = {
        "EPSILON": 1.1102230246251565e-16,
        "SPLITTER": 134217729.0,
        "RESULTERRBOUND": 3.3306690738754706e-16,
        "CCWERRBOUNDA": 3.3306690738754716e-16,
        "CCWERRBOUNDB": 2.2204460492503146e-16,
        "CCWERRBOUNDC": 1.1093356479670487e-31,
        "ICCERRBOUNDA": 1.1102230246251577e-15,
        "ICCERRBOUNDB": 4.440892098500632e-16,
        "ICCERRBOUNDC": 5.423418723394464e-31,
    }
    for name, value in table.items():
        assert getattr(P, name) == value, name


def test_sign_convention():
    # orient2d > 0 iff counter-clockwise (Shewchuk's convention, not robust-predicates')
    assert orient2d(0.0, 0.0, 1.0, 0.0, 0.0, 1.0) > 0
    assert orient2d(0.0, 0.0, 0.0, 1.0, 1.0, 0.0) < 0
    assert orient2d(0.0, 0.0, 1.0, 1.0, 2.0, 2.0) == 0
    assert orient2d(0.0, 0.0, 1.0, 0.0, 0.0, 1.0) == 1.0  # twice the signed area
    # incircle > 0 iff d strictly inside the circle through ccw a, b, c
    ccw = (1.0, 0.0, 0.0, 1.0, -1.0, 0.0)
    assert incircle(*ccw, 0.0, 0.0) > 0
    assert incircle(*ccw, 2.0, 0.0) < 0
    assert incircle(*ccw, 0.0, -1.0) == 0
    cw = (1.0, 0.0, -1.0, 0.0, 0.0, 1.0)
    assert incircle(*cw, 0.0, 0.0) < 0
    for fast, exact, args in [
        (orient2d_fast, orient2d, (0.0, 0.0, 1.0, 0.0, 0.0, 1.0)),
        (incircle_fast, incircle, ccw + (0.1, 0.2)),
    ]:
        assert fast(*args) == exact(*args) > 0


def test_no_fastmath_in_module():
    assert "fastmath" not in MODULE_PATH.read_text()
    assert "-ffp-contract=off" in (pathlib.Path(__file__).resolve().parents[2] / "setup.py").read_text()


def test_fast_twins_and_common_path_return_triangles_det():
    rng = np.random.default_rng(1)
    for row in rng.uniform(-10, 10, size=(300, 8)):
        ax, ay, bx, by, cx, cy, dx, dy = (float(v) for v in row)
        det_o = (ax - cx) * (by - cy) - (ay - cy) * (bx - cx)
        assert orient2d_fast(ax, ay, bx, by, cx, cy) == det_o
        assert orient2d(ax, ay, bx, by, cx, cy) == det_o  # certified by stage A
        adx, ady, bdx, bdy, cdx, cdy = ax - dx, ay - dy, bx - dx, by - dy, cx - dx, cy - dy
        det_i = (
            (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy)
            + (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy)
            + (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady)
        )
        assert incircle_fast(ax, ay, bx, by, cx, cy, dx, dy) == det_i
        assert incircle(ax, ay, bx, by, cx, cy, dx, dy) == det_i


# ---------------------------------------------------------------------------
# Random and near-degenerate inputs against the rational oracle
# ---------------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["uniform", "small-integers", "wide-exponents"])
def test_random_inputs_match_fractions(kind):
    rng = np.random.default_rng(abs(hash(kind)) % 2**32)
    n = 400
    if kind == "uniform":
        data = rng.uniform(-1, 1, size=(n, 8))
    elif kind == "small-integers":  # many exact degeneracies
        data = rng.integers(-3, 4, size=(n, 8)).astype(float)
    else:
        data = rng.uniform(0.5, 1, size=(n, 8)) * np.exp2(rng.integers(-40, 40, size=(n, 8)))
        data *= rng.choice([-1.0, 1.0], size=(n, 8))
    for row in data:
        c = tuple(float(v) for v in row)
        check_orient(*c[:6])
        check_incircle(*c)


@pytest.mark.parametrize("step", [2.0**-53, 2.0**-43])
def test_orient2d_near_line_grid(step):
    # c walks a 64x64 grid of ulp-spaced points around the line y = x through (12,12),(24,24)
    signs = set()
    naive_wrong = 0
    for i in range(64):
        for j in range(64):
            c = (0.5 + i * step, 0.5 + j * step)
            s = sign(check_orient(12.0, 12.0, 24.0, 24.0, *c))
            signs.add(s)
            naive_wrong += sign(orient2d_fast(12.0, 12.0, 24.0, 24.0, *c)) != s
            # and with the roles permuted
            check_orient(*c, 12.0, 12.0, 24.0, 24.0)
    assert signs == {-1, 0, 1}
    if step == 2.0**-53:
        assert naive_wrong > 0  # the plain determinant really fails here


@pytest.mark.parametrize("shift", [(0.0, 0.0), (0.1, 0.3), (1e6 + 0.1, -3e5 + 0.7)])
def test_incircle_near_circle_grid(shift):
    # a, b, c, and the centre of the grid lie on x^2 + y^2 = 25 (exactly, before the shift)
    sx, sy = shift
    pts = [(5.0, 0.0), (0.0, 5.0), (-3.0, -4.0)]
    abc = tuple(v for x, y in pts for v in (x + sx, y + sy))
    x0, y0 = 3.0 + sx, 4.0 + sy
    ux, uy = math.ulp(x0), math.ulp(y0)
    signs = set()
    for i in range(-24, 24):
        for j in range(-24, 24):
            signs.add(sign(check_incircle(*abc, x0 + i * ux, y0 + j * uy)))
    assert {-1, 1} <= signs


def test_exact_collinear_and_cocircular():
    rng = np.random.default_rng(7)
    for _ in range(300):
        a = rng.integers(-1000, 1000, size=2).astype(float)
        b = rng.integers(-1000, 1000, size=2).astype(float)
        t = float(rng.integers(-8, 9)) / 8.0
        c = a + t * (b - a)
        k = int(rng.integers(-700, 700))
        pts = [math.ldexp(float(v), k) for v in (*a, *b, *c)]
        assert orient2d(*pts) == 0
        assert orient2d(*pts[2:], *pts[:2]) == 0
    # lattice points of the circle of radius 65 (Pythagorean triples)
    base = [(0, 65), (16, 63), (25, 60), (33, 56), (39, 52)]
    circle = sorted({(sx * x, sy * y) for x, y in base for x, y in ((x, y), (y, x))
                     for sx in (1, -1) for sy in (1, -1)})
    assert all(x * x + y * y == 65**2 for x, y in circle)
    for _ in range(300):
        idx = rng.choice(len(circle), size=4, replace=False)
        ox, oy = (float(v) for v in rng.integers(-10**6, 10**6, size=2))
        k = int(rng.integers(-200, 200))
        pts = [math.ldexp(float(v), k) for i in idx
               for v in (circle[i][0] + ox, circle[i][1] + oy)]
        assert incircle(*pts) == 0
        # a point just off the circle is classified exactly
        check_incircle(*pts[:6], nudge(pts[6], 1), pts[7])
        check_incircle(*pts[:6], nudge(pts[6], -1), pts[7])


def _near_degenerate_cases():
    """Some hard orient2d / incircle inputs (most reach stages C and D)."""
    rng = np.random.default_rng(3)
    ocases, icases = [], []
    for _ in range(60):
        a = rng.uniform(-1, 1, 2)
        b = rng.uniform(-1, 1, 2)
        t = rng.uniform(-1, 2)
        c = a + t * (b - a)
        c = (nudge(float(c[0]), int(rng.integers(-2, 3))), float(c[1]))
        ocases.append((*map(float, a), *map(float, b), *c))
        ctr = rng.uniform(-1, 1, 2)
        r = rng.uniform(0.1, 2)
        ang = rng.uniform(0, 2 * np.pi, 4)
        pts = [(float(ctr[0] + r * np.cos(t)), float(ctr[1] + r * np.sin(t))) for t in ang]
        icases.append(tuple(v for p in pts for v in p))
    return ocases, icases


@pytest.mark.parametrize("k", [600, -600, 1000, -1000, 0])
def test_power_of_two_scaling_keeps_signs(k):
    ocases, icases = _near_degenerate_cases()
    for c in ocases:
        s = sign(exact_orient(*c))
        cs = scaled(c, k)
        assert cs is not None
        assert sign(orient2d(*cs)) == s
    for c in icases:
        s = sign(exact_incircle(*c))
        cs = scaled(c, k)
        assert cs is not None
        assert sign(incircle(*cs)) == s


def test_underflow_and_overflow_inputs():
    tiny = 5e-324
    # products underflow to 0: the plain determinant says "collinear", wrongly
    assert orient2d_fast(0.0, 0.0, tiny, 0.0, 0.0, tiny) == 0.0
    assert orient2d(0.0, 0.0, tiny, 0.0, 0.0, tiny) > 0
    assert orient2d(0.0, 0.0, 0.0, tiny, tiny, 0.0) < 0
    assert incircle(tiny, 0.0, 0.0, tiny, -tiny, 0.0, 0.0, 0.0) > 0
    assert incircle(2 * tiny, 0.0, 0.0, 2 * tiny, -2 * tiny, 0.0, 3 * tiny, 0.0) < 0
    assert incircle(2 * tiny, 0.0, 0.0, 2 * tiny, -2 * tiny, 0.0, 0.0, -2 * tiny) == 0
    # differences overflow
    big = 1.7e308
    check_orient(-big, -big, big, -big, 0.0, big)
    check_orient(-big, -big, big, big, 0.0, 1e-300)
    check_incircle(big, 0.0, 0.0, big, -big, 0.0, 0.0, -big)
    check_incircle(big, 0.0, 0.0, big, -big, 0.0, 1e300, 1e300)
    check_incircle(big, 0.0, 0.0, big, -big, 0.0, 0.0, nudge(-big, 1))


def test_rescaled_values_keep_magnitude_and_saturate():
    assert orient2d(0.0, 0.0, 0.0, 0.0, 0.0, 0.0) == 0
    assert incircle(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0) == 0
    s = 2.0**-500  # products underflow the fast path's guard; exact after rescaling
    assert orient2d(0.0, 0.0, s, 0.0, 0.0, s) == 2.0**-1000
    assert orient2d(0.0, 0.0, 3 * s, s, s, 2 * s) == 5 * 2.0**-1000
    # the true values are out of the double range: saturate, never lose the sign
    big, small = 2.0**600, 2.0**-600
    assert orient2d(0.0, 0.0, big, 0.0, 0.0, big) == 1.7976931348623157e308
    assert orient2d(0.0, 0.0, small, 0.0, 0.0, small) == 5e-324
    assert orient2d(0.0, 0.0, 0.0, small, small, 0.0) == -5e-324
    assert incircle(small, 0.0, 0.0, small, -small, 0.0, 0.0, 0.0) == 5e-324
    assert incircle(big, 0.0, 0.0, big, -big, 0.0, 0.0, 0.0) == 1.7976931348623157e308
    # same through the rational fallback (coordinates span 2^2000)
    assert orient2d(0.0, 0.0, 1e300, 1e-300, -1e-300, 1e300) == 1.7976931348623157e308
    assert orient2d(0.0, 0.0, -1e-300, 1e300, 1e300, 1e-300) == -1.7976931348623157e308
    assert orient2d(0.0, 0.0, 1e-300, 0.0, 1e300, 1e-300) == 5e-324


def test_mixed_magnitudes_use_exact_fallback():
    big, small = 2.0**600, 2.0**-600
    # exactly collinear although the coordinates span 2^1201
    assert orient2d(0.0, 0.0, big, small, 2 * big, 2 * small) == 0
    check_orient(0.0, 0.0, big, small, 2 * big, nudge(2 * small, 1))
    check_orient(0.0, 0.0, big, small, nudge(2 * big, -1), 2 * small)
    check_orient(1e200, 1e-200, -1e-200, 1e200, 3e-300, 1e-300)
    rng = np.random.default_rng(11)
    for _ in range(100):
        c = rng.uniform(0.5, 1, 8) * np.exp2(rng.integers(-1000, 1000, 8))
        c *= rng.choice([-1.0, 1.0, 0.0], size=8, p=[0.45, 0.45, 0.1])
        c = tuple(float(v) for v in c)
        check_orient(*c[:6])
        check_incircle(*c)
    # cocircular points of the radius-65 circle, one coordinate huge apart
    assert incircle(65.0, 0.0, 0.0, 65.0, -65.0, 0.0, 0.0, -65.0) == 0
    check_incircle(65.0 * big, 0.0, 0.0, 65.0 * big, -65.0 * big, 0.0, small, -65.0 * big)


def _wide_lattice_values(rng, n):
    """Doubles from every part of the range: zeros, subnormals, powers of two,
    integers with trailing zero bits, and random ones at 2^-1074..2^1023."""
    special = [0.0, 5e-324, 1e-323, 2.0**-1022, 2.0**-500, 1.0, 3.0, 2.0**53 + 2.0, 2.0**1023,
               1.7976931348623157e308, float.fromhex("0x1.0000000004000p-1022"), float.fromhex("0x1.4430bep-73")]
    out = []
    for _ in range(n):
        if rng.random() < 0.4:
            v = special[int(rng.integers(len(special)))]
        else:
            v = math.ldexp(float(rng.uniform(0.5, 1.0)), int(rng.integers(-1073, 1025)))
        out.append(v if rng.random() < 0.5 else -v)
    return out


@pytest.mark.parametrize("module", [P, SOURCE], ids=["compiled", "python"])
def test_integer_fallback_matches_fractions(module):
    """The Python-integer fallback (calls whose coordinates span too much to
    scale): its integers are exact and as short as one denominator allows,
    and its determinants are the correctly rounded exact ones."""
    rng = np.random.default_rng(33)
    for _ in range(400):
        vals = _wide_lattice_values(rng, 8)
        xs, k = module._integers(vals)
        assert k >= 0 and all(Fraction(x, 2**k) == Fraction(v) for x, v in zip(xs, vals)), vals
        assert k == 0 or any(x % 2 for x in xs), (vals, k)
    lattice = 2.0**-1074
    cases = [tuple(_wide_lattice_values(rng, 8)) for _ in range(300)]
    # cocircular (the radius-65 circle's lattice points) and collinear, at
    # the bottom and top of the range, beside a far point that makes them wide
    for unit in (lattice, 2.0**-1000, 2.0**-500, 1.0, 2.0**900):
        ring = [(65.0, 0.0), (0.0, 65.0), (-65.0, 0.0), (0.0, -65.0), (63.0, 16.0), (-33.0, 56.0), (25.0, -60.0)]
        pts = [(x * unit, y * unit) for x, y in ring]
        cases.append(sum(pts[:4], ()))
        cases.append(sum(pts[3:7], ()))
        cases.append((0.0, 0.0, 3 * unit, unit, 6 * unit, 2 * unit, 1.0, 2.0**-1022))
    # the denormal case's shapes: a point at (2^-500, 2^-1022), halvings of a far point
    far = (float.fromhex("0x1.4430bep0"), float.fromhex("0x1.ef53c3e1deb1ep0"))
    near = (float.fromhex("0x1.d932f501d09a3p-2"), float.fromhex("0x1.e236340000000p-14"))
    for t in range(60, 80):
        fx, fy = math.ldexp(far[0], -t), math.ldexp(far[1], -t)
        cases.append((2 * fx, 2 * fy, 2.0**-500, 2.0**-1022, *near, fx, fy))
    for c in cases:
        exact = exact_incircle(*c)
        for got, want in ((module._incircle_integer(*c), exact),
                          (module._orient2d_integer(*c[:6]), exact_orient(*c[:6]))):
            assert sign(got) == sign(want), c
            if 2.0**-1022 <= abs(want) <= 1.7976931348623157e308:
                assert got == float(want), c
        assert sign(module.incircle(*c)) == sign(exact), c
        assert sign(module.orient2d(*c[:6])) == sign(exact_orient(*c[:6])), c


def test_wide_filter_clusters_match_fractions():
    """Three points in a cluster beside a far point, too wide to scale: the
    unbounded-exponent filter decides them from a translation to the
    cluster (its pairs normalized once, products by one doubling, the same
    pairs frexp gives); every sign against Fractions, in both modes."""
    rng = np.random.default_rng(34)
    for _ in range(300):
        size = 2.0 ** int(rng.integers(-1074, -400))
        far = 2.0 ** int(rng.integers(0, 1000))
        centre = rng.uniform(-1, 1, 2) * size * 2.0**60
        pts = [tuple(centre + rng.integers(-50, 51, 2) * size) for _ in range(3)]
        pts.append(tuple(rng.uniform(-1, 1, 2) * far))
        rng.shuffle(pts)
        c = tuple(float(v) for p in pts for v in p)
        exact = exact_incircle(*c)
        assert sign(incircle(*c)) == sign(exact) == sign(SOURCE.incircle(*c)), c
        assert sign(orient2d(*c[:6])) == sign(exact_orient(*c[:6])) == sign(SOURCE.orient2d(*c[:6])), c
    for _ in range(2000):
        am, bm = (float(v) for v in rng.uniform(0.5, 1.0, 2) * rng.choice([-1.0, 1.0], 2))
        ae, be = (int(v) for v in rng.integers(-3000, 3000, 2))
        m, e = SOURCE._wmul(am, ae, bm, be)
        assert (m, e) == SOURCE._norm(am * bm, ae + be)


def test_nonfinite_inputs_return():
    nan, inf = math.nan, math.inf
    for args in [(nan, 0.0, 1.0, 0.0, 0.0, 1.0), (inf, 0.0, 1.0, 0.0, 0.0, 1.0),
                 (inf, inf, -inf, 0.0, 0.0, nan)]:
        assert isinstance(orient2d(*args), float)
        assert isinstance(incircle(*args, 0.5, 0.5), float)


# ---------------------------------------------------------------------------
# The exact stages in isolation
# ---------------------------------------------------------------------------
def _heads_tails(coords, ref):
    heads = [v - r for v, r in zip(coords, ref)]
    tails = [float(Fraction(v) - Fraction(r) - Fraction(h)) for v, r, h in zip(coords, ref, heads)]
    assert all(Fraction(v) - Fraction(r) == Fraction(h) + Fraction(t)
               for v, r, h, t in zip(coords, ref, heads, tails))
    return heads, tails


def _assert_expansion(comps, exact):
    assert sum(map(Fraction, comps), Fraction(0)) == exact
    mags = [abs(c) for c in comps if c != 0]
    assert mags == sorted(mags)


def test_stage_d_expansions_are_exact():
    rng = np.random.default_rng(5)
    for trial in range(150):
        c = rng.uniform(0.5, 1, 8) * np.exp2(rng.integers(-30, 30, 8))
        c *= rng.choice([-1.0, 1.0], size=8)
        if trial % 3 == 0:  # some zero tails
            c[rng.integers(0, 8, 3)] = np.round(c[rng.integers(0, 8, 3)])
        c = tuple(float(v) for v in c)
        # orient2d: differences against c
        (acx, acy, bcx, bcy), (acxt, acyt, bcxt, bcyt) = _heads_tails(
            c[0:4], (c[4], c[5], c[4], c[5]))
        b1, b0 = SOURCE._two_product(acx, bcy)
        r1, r0 = SOURCE._two_product(acy, bcx)
        w = np.zeros(44)
        SOURCE._store_two_two_diff(b1, b0, r1, r0, w, 0)
        n = SOURCE._orient2d_expansion_d(acx, acy, bcx, bcy, acxt, acyt, bcxt, bcyt, w)
        _assert_expansion(w[28:28 + n], exact_orient(*c[:6]))
        # incircle: differences against d
        coords = (c[0], c[2], c[4], c[1], c[3], c[5])
        ref = (c[6], c[6], c[6], c[7], c[7], c[7])
        heads, tails = _heads_tails(coords, ref)
        wb = np.zeros(316)
        nb = SOURCE._incircle_expansion_b(*heads, wb)
        fin = np.empty(2304)
        base, m = SOURCE._incircle_expansion_d(
            *heads, *tails, wb, nb, fin, np.empty(256), np.empty(12), np.empty(48),
            np.empty(6, dtype=np.int64), np.empty(20))
        _assert_expansion(fin[base:base + m], exact_incircle(*c))


def test_adaptive_stages_match_oracle_when_forced():
    # an infinite error bound makes every stage defer to the next one
    ocases, icases = _near_degenerate_cases()
    rng = np.random.default_rng(9)
    extra = [tuple(float(v) for v in rng.uniform(-1, 1, 8)) for _ in range(50)]
    for c in ocases + [e[:6] for e in extra]:
        assert sign(SOURCE._orient2d_adapt(*c, math.inf)) == sign(exact_orient(*c))
    for c in icases + extra:
        assert sign(SOURCE._incircle_adapt(*c, math.inf)) == sign(exact_incircle(*c))


# ---------------------------------------------------------------------------
# Hypothesis: nearly degenerate inputs
# ---------------------------------------------------------------------------
coord = st.floats(min_value=-1e6, max_value=1e6, allow_nan=False, allow_infinity=False)
exponent = st.sampled_from([0, 0, 0, 600, -600, 900, -900])


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(ax=coord, ay=coord, bx=coord, by=coord,
       t=st.floats(min_value=-2, max_value=3), ux=st.integers(-3, 3),
       uy=st.integers(-3, 3), k=exponent)
def test_hypothesis_near_collinear(ax, ay, bx, by, t, ux, uy, k):
    cx = nudge(ax + t * (bx - ax), ux)
    cy = nudge(ay + t * (by - ay), uy)
    c = (ax, ay, bx, by, cx, cy)
    expected = sign(exact_orient(*c))
    assert sign(orient2d(*c)) == expected
    cs = scaled(c, k)
    if cs is not None:
        assert sign(orient2d(*cs)) == expected


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(x0=coord, y0=coord, r=st.floats(min_value=1e-3, max_value=1e3),
       angles=st.lists(st.floats(min_value=0, max_value=6.3), min_size=4, max_size=4),
       ux=st.integers(-2, 2), uy=st.integers(-2, 2), k=exponent)
def test_hypothesis_near_cocircular(x0, y0, r, angles, ux, uy, k):
    pts = [(x0 + r * math.cos(a), y0 + r * math.sin(a)) for a in angles]
    c = tuple(v for p in pts for v in p)
    c = c[:6] + (nudge(c[6], ux), nudge(c[7], uy))
    expected = sign(exact_incircle(*c))
    assert sign(incircle(*c)) == expected
    cs = scaled(c, k)
    if cs is not None:
        assert sign(incircle(*cs)) == expected


# ---------------------------------------------------------------------------
# Pure Python (RUPPERT_PURE_PYTHON=1) gives the same values as the compiled code,
# whose fast paths come from predicates.pxd (inlined into every kernel)
# ---------------------------------------------------------------------------
_PURE_SCRIPT = r"""
import json, sys
from instrument import purepython
from instrument.core import predicates as mod
cases = json.loads(sys.stdin.read())
out = {"orient": [mod.orient2d(*c[:6]).hex() for c in cases],
       "incircle": [mod.incircle(*c).hex() for c in cases],
       "orient_fast": [mod.orient2d_fast(*c[:6]).hex() for c in cases],
       "incircle_fast": [mod.incircle_fast(*c).hex() for c in cases],
       "compiled": purepython.is_compiled(mod)}
print(json.dumps(out))
"""


@pytest.mark.skipif(purepython.requested(), reason="compares the compiled kernels with a pure-Python run")
def test_same_results_in_pure_python():
    ocases, icases = _near_degenerate_cases()
    rng = np.random.default_rng(2)
    cases = [c + (0.25, -0.5) for c in ocases[:20]] + icases[:20]
    cases += [tuple(map(float, r)) for r in rng.uniform(-1, 1, (40, 8))]  # the fast paths
    cases += [tuple(map(float, r)) for r in rng.integers(-3, 4, (40, 8))]  # exact zeros
    cases += [
        (0.0, 0.0, 5e-324, 0.0, 0.0, 5e-324, 1e-323, 1e-323),  # rescaled path
        (0.0, 0.0, 2.0**600, 2.0**-600, 2.0**601, 2.0**-599, 1.0, 1.0),  # rational path
        (5.0, 0.0, 0.0, 5.0, -3.0, -4.0, 3.0, nudge(4.0, 1)),
    ]
    env = dict(os.environ, RUPPERT_PURE_PYTHON="1")
    proc = subprocess.run(
        [sys.executable, "-c", _PURE_SCRIPT], input=json.dumps(cases), capture_output=True, text=True, env=env, timeout=120
    )
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert not out["compiled"] and purepython.is_compiled(P)
    assert out["orient"] == [orient2d(*c[:6]).hex() for c in cases]
    assert out["incircle"] == [incircle(*c).hex() for c in cases]
    assert out["orient_fast"] == [orient2d_fast(*c[:6]).hex() for c in cases]
    assert out["incircle_fast"] == [incircle_fast(*c).hex() for c in cases]
    for c, h in zip(cases, out["incircle"]):
        assert sign(float.fromhex(h)) == sign(exact_incircle(*c))


# ---------------------------------------------------------------------------
# dot_sign (segment recovery's "is this vertex between the segment's ends")
# ---------------------------------------------------------------------------
def exact_dot(ax, ay, bx, by, cx, cy, dx, dy) -> Fraction:
    ax, ay, bx, by, cx, cy, dx, dy = map(Fraction, (ax, ay, bx, by, cx, cy, dx, dy))
    return (bx - ax) * (dx - cx) + (by - ay) * (dy - cy)


def _dot_cases() -> list[tuple]:
    """Random, exactly perpendicular, nearly perpendicular (an ulp off), and
    out of the filter's range (tiny and huge differences, both at once)."""
    rng = np.random.default_rng(11)
    cases = [tuple(map(float, r)) for r in rng.uniform(-1, 1, (200, 8))]
    cases += [tuple(map(float, r)) for r in rng.integers(-3, 4, (100, 8))]
    for ax, ay, bx, by, ox, oy in rng.uniform(-1, 1, (100, 6)).tolist():
        # d - c perpendicular to b - a, then nudged: the sign flips around 0
        for u in (-2, -1, 0, 1, 2):
            cases.append((ax, ay, bx, by, ox, oy, ox - (by - ay), nudge(oy + (bx - ax), u)))
    cases += [
        (2.0**-20, 2.0**-499, 0.125, 2.0**-20, 2.0**-20, 2.0**-499, 2.0**-20, 0.0),  # the recovery defect's
        (0.0, 0.0, 5e-324, 5e-324, 0.0, 0.0, -5e-324, 1e-323),
        (0.0, 0.0, 2.0**600, 2.0**-600, 0.0, 0.0, -(2.0**-600), 2.0**600),
        (1e300, -1e300, -1e300, 1e300, 1.0, 2.0, 3.0, 4.0),
        (0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 1.0, -1.0),
    ]
    return cases


def test_dot_sign_matches_fractions():
    for c in _dot_cases():
        assert P.dot_sign(*c) == sign(exact_dot(*c)), c


def test_dot_sign_same_in_pure_python():
    cases = _dot_cases()
    script = (
        "import json, sys\nfrom instrument import purepython\nfrom instrument.core import predicates as P\n"
        "cases = json.loads(sys.stdin.read())\n"
        "print(json.dumps({'signs': [P.dot_sign(*c) for c in cases], 'compiled': purepython.is_compiled(P)}))\n"
    )
    env = dict(os.environ, RUPPERT_PURE_PYTHON="1")
    proc = subprocess.run([sys.executable, "-c", script], input=json.dumps(cases), capture_output=True, text=True,
                          env=env, timeout=120)
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert not out["compiled"]
    assert out["signs"] == [sign(exact_dot(*c)) for c in cases]
