"""Chew's randomized triangulation of a deleted vertex's star
(instrument.refine.star_delaunay) makes the scan's triangles.

The scan (``_scan_apex`` per base edge, recursing on both sides, as
``deletion._fill_polygon`` does) is the reference: on every star of the
Delaunay triangulations below, ``delaunay_star`` gives the same triangles,
cocircular ties included, or leaves the star to the scan (-1); on the
Delaunay stars of points in general position it never leaves one.

What each costs, in incircle tests per star vertex (this module's stars;
the randomized count includes its checks, and it also makes about 2
orientation tests per vertex): a noisy ring of degree 24 scans in 6.3 and
takes 3.5 randomized, degree 41 7.3 and 3.9, a circle of degree 800 14.9
and 5.0; a sliver's zigzag of degree n scans in about n / 2 (quadratic in
all) and takes about 5. Below ``deletion.SCAN_DEGREE`` (24) the scan is
the cheaper, and ordinary free vertices have degree 5 to 8.
"""

from __future__ import annotations

import math
import random

import numpy as np
import pytest

from instrument import counters
from instrument.check import check_mesh
from instrument.core.mesh import V_DEAD, V_FREE
from instrument.core.navigate import build_vertex_edges, find_edge
from instrument.core.predicates import incircle, orient2d
from instrument.core.status import DONE
from instrument.core.subsegments import Subsegments
from instrument.counters import C_INCIRCLE
from instrument.refine.deletion import SCAN_DEGREE, delete_free_vertex
from instrument.refine.star_delaunay import delaunay_star
from meshkit import as_result, corner_sets, problems, refiner, triangulated


def _chain(star: list[int]) -> np.ndarray:
    """The deletion's chain of a counter-clockwise star w0 .. w[d-1]: w0,
    then the others clockwise."""
    d = len(star)
    return np.array([star[0]] + [star[d - i] for i in range(1, d)], dtype=np.int64)


def _scan_apex(xy, chain, i, j, work) -> int:
    """The scan's choice over the base chain[i] -> chain[j] (the deletion's
    loop): the last position whose circle through the base holds none of
    the other positions i + 1 .. j - 1 strictly inside (Triangle's choice
    among cocircular ones)."""
    k = i + 1
    for q in range(i + 2, j):
        work[C_INCIRCLE] += 1
        if incircle(*xy[chain[i]], *xy[chain[j]], *xy[chain[k]], *xy[chain[q]]) >= 0:
            k = q
    return k


def _scanned(xy, chain, work) -> tuple[set, bool]:
    """The scan's triangles (as sets of chain positions), and whether they
    are all counter-clockwise."""
    out, valid, pending = set(), True, [(0, len(chain) - 1)]
    while pending:
        i, j = pending.pop()
        if j == i + 1:
            continue
        k = _scan_apex(xy, chain, i, j, work)
        valid &= orient2d(*xy[chain[k]], *xy[chain[i]], *xy[chain[j]]) > 0
        out.add(frozenset((i, j, k)))
        pending += [(i, k), (k, j)]
    return out, valid


def _randomized(xy, chain, v, work) -> set | None:
    n = len(chain)
    tv, nb, links, aux, rim = (np.full(4 * n, -9, dtype=np.int64) for _ in range(5))
    base = delaunay_star(xy, chain, n, xy[v, 0], xy[v, 1], tv, nb, links, aux, rim, work)
    if base < 0:
        return None
    t, side = divmod(base, 3)
    assert (tv[3 * t + (side + 1) % 3], tv[3 * t + (side + 2) % 3]) == (0, n - 1)  # the base's org and dest
    tris = {frozenset(tv[3 * t : 3 * t + 3].tolist()) for t in range(n - 2)}
    assert len(tris) == n - 2
    return tris


def _stars(points) -> tuple[np.ndarray, dict[int, list[int]]]:
    """The Delaunay triangulation's coordinates and its inner vertices'
    stars, counter-clockwise."""
    m = triangulated(points)
    xy, corner, twin = np.asarray(m.xy), np.asarray(m.corner), np.asarray(m.twin)
    out = {}
    for t in range(m.nslot):
        if m.stamp[t] <= 0:
            continue
        for s in range(3):
            e = 3 * t + s
            v = int(corner[3 * t + (s + 1) % 3])  # the origin of edge e
            if v < 0 or v in out:
                continue
            star, f = [], e
            while True:  # the next edge out of v is the twin of this one's lprev
                prev = 3 * (f // 3) + (f % 3 + 2) % 3
                star.append(int(corner[prev]))
                f = int(twin[prev])
                if f < 0 or f == e:
                    break
            if f == e and min(star) >= 0:
                out[v] = star
    return xy, out


def _ring(rng, k):
    return [(0.0, 0.0)] + [(r * math.cos(a), r * math.sin(a))
                           for a, r in ((rng.uniform(0, 2 * math.pi), rng.uniform(0.9, 1.1)) for _ in range(k))]


def _lattice_circle(rng, n2):
    """The integer points of the circle x^2 + y^2 = n2 (exactly cocircular),
    its centre, and a quarter of them moved out by 5/4."""
    r = math.isqrt(n2)
    on = [(float(x), float(y)) for x in range(-r, r + 1) for y in range(-r, r + 1) if x * x + y * y == n2]
    return [(0.0, 0.0)] + on + [(1.25 * x, 1.25 * y) for x, y in rng.sample(on, len(on) // 4)]


def _sliver(rng, k, height, scale):
    pts = [(0.0, height / 2)] + [(rng.uniform(-1, 1), 0.0) for _ in range(k)]
    pts += [(rng.uniform(-1, 1), height) for _ in range(k)]
    return [(x * scale, y * scale) for x, y in pts]


def _grid(rng, g):
    pts = [(float(x), float(y)) for x in range(-g, g + 1) for y in range(-g, g + 1) if (x, y) != (0, 0)]
    return [(0.0, 0.0)] + [p for p in pts if rng.random() < 0.5]


INPUTS = {
    "ring-30": lambda rng: _ring(rng, 30),
    "ring-120": lambda rng: _ring(rng, 120),
    "lattice-circle-1105": lambda rng: _lattice_circle(rng, 1105),
    "lattice-circle-32045": lambda rng: _lattice_circle(rng, 32045),
    "sliver-1e-9": lambda rng: _sliver(rng, 40, 1e-9, 1.0),
    "sliver-1e300": lambda rng: _sliver(rng, 40, 1e-200, 1e300),
    "sliver-1e-300": lambda rng: _sliver(rng, 40, 1e-3, 1e-300),
    "grid": lambda rng: _grid(rng, 6),
}


@pytest.mark.parametrize("name", sorted(INPUTS))
def test_every_star_gets_the_scans_triangles(name):
    rng = random.Random(name)
    general = not name.startswith(("lattice", "grid"))
    for _ in range(3):
        xy, stars = _stars(INPUTS[name](rng))
        for v, star in stars.items():
            for turn in range(min(3, len(star))):  # other bases
                chain = _chain(star[turn:] + star[:turn])
                work = counters.new_work()
                scanned, valid = _scanned(xy, chain, work)
                assert valid
                got = _randomized(xy, chain, v, work)
                if got is None:  # left to the scan: only a degenerate star
                    assert not general, (name, v, len(star))
                    continue
                assert got == scanned, (name, v, len(star))


def test_a_cocircular_star_is_a_fan_from_its_first_position():
    """The 64 integer points of x^2 + y^2 = 32045 around the origin: one
    cocircular face, which the scan fans from chain position 0."""
    xy, stars = _stars(_lattice_circle(random.Random(0), 32045)[:65])
    star = stars[0]
    assert len(star) == 64
    chain = _chain(star)
    work = counters.new_work()
    got = _randomized(xy, chain, 0, work)
    assert got == _scanned(xy, chain, counters.new_work())[0]
    assert all(0 in t for t in got)


@pytest.mark.parametrize("scale", [1.0, 1e300, 1e-300])
def test_a_slivers_zigzag_takes_linear_work(scale):
    """Two rows of 400 points, 1e-9 apart (times ``scale``), around a vertex
    between them: the scan takes one vertex off per base edge (n^2 / 4
    incircle tests), the randomized algorithm a few per vertex."""
    k = 400
    bottom = [(float(i), 0.0) for i in range(k)]
    top = [(i + 0.5, 1e-9) for i in range(k - 1, -1, -1)]
    pts = np.array([(k / 2 + 0.25, 0.5e-9)] + bottom + top) * scale
    star = list(range(1, 2 * k + 1))  # counter-clockwise around vertex 0
    chain = _chain(star)
    scan_work, work = counters.new_work(), counters.new_work()
    scanned, valid = _scanned(pts, chain, scan_work)
    assert valid
    assert _randomized(pts, chain, 0, work) == scanned
    assert scan_work[C_INCIRCLE] > 2 * k * k / 4
    assert work[C_INCIRCLE] < 8 * 2 * k


def test_a_star_without_a_way_in_is_left_to_the_scan():
    """The centre of a square lies on both diagonals: no corner can go
    while it stays strictly inside, so the scan has the star."""
    pts = np.array([(0.0, 0.0), (-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)])
    assert _randomized(pts, _chain([1, 2, 3, 4]), 0, counters.new_work()) is None


def test_delete_free_vertex_with_a_large_star():
    """A free vertex of degree 40 (the centre of a ring of 40 points, radii
    1 +- 0.02): the deletion takes the randomized path and leaves the
    Delaunay triangulation of the ring."""
    rng = random.Random(7)
    pts = [(0.0, 0.0)] + [(r * math.cos(a), r * math.sin(a))
                          for a, r in ((2 * math.pi * i / 40, rng.uniform(0.98, 1.02)) for i in range(40))]
    m = triangulated(pts, extra_triangles=256)
    m.add_constraint_tables()
    build_vertex_edges(m)
    m.vtype[0] = V_FREE
    xy, stars = _stars(pts)
    star = stars[0]
    assert len(star) >= SCAN_DEGREE
    e0 = find_edge(m, 0, star[0])
    expected_chain = _chain(star)
    scanned = _scanned(xy, expected_chain, counters.new_work())[0]
    expected = {frozenset(int(expected_chain[i]) for i in t) for t in scanned}
    before_sets = corner_sets(m)
    before = np.asarray(m.work).copy()
    r = refiner(slots=1024)
    assert delete_free_vertex(r, m, Subsegments(4), e0) == DONE
    assert m.vtype[0] == V_DEAD
    after = corner_sets(m)
    assert after == {t for t in before_sets if 0 not in t} | expected
    assert np.asarray(m.work)[C_INCIRCLE] - before[C_INCIRCLE] < 10 * len(star)
    # r.fan: the testing order (counting sorts above SCAN_DEGREE): by the
    # place (w0 = d, w[i] = i) of the base org ascending, then of the base
    # dest descending; the base triangle (w1, new apex, w0) last
    d = len(star)
    place = {w: i for i, w in enumerate(star)} | {star[0]: d}
    corner = np.asarray(m.corner)
    fan = np.asarray(r.fan)[: d - 2]
    keys = [(place[int(corner[3 * t + 1])], -place[int(corner[3 * t + 2])]) for t in fan[:-1]]
    assert keys == sorted(keys) and len(set(keys)) == len(keys)
    assert (corner[3 * fan[-1]], corner[3 * fan[-1] + 2]) == (star[1], star[0])  # handle: new apex -> w0
    assert problems(m) == []
    assert check_mesh(as_result(m)) == []
    assert (np.asarray(m.vslot) == -1).all()
