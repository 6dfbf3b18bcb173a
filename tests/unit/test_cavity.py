"""Refinement's Bowyer-Watson insertion (instrument.refine.cavity): which
triangles make the cavity, the rim and its order, and the fan that fills it.

Every test starts from the square (0,0) (4,0) (4,4) (0,4) with its centre
(2,2), vertices 0 to 4: four triangles around the centre, each with a
circumcircle of radius 2 through the centre,

    bottom {0,1,4}, circle about (2,0);   right {1,2,4}, about (4,2);
    top    {2,3,4}, about (2,4);          left  {3,0,4}, about (0,2).

The point P = (2.2, 1.7) lies in the bottom triangle, inside the circles of
bottom and right (distances 1.71 and 1.83) and outside those of top and left
(2.31 and 2.22), so its cavity is {bottom, right} and its rim the polygon
0 -> 1 -> 2 -> 4 -> 0.
"""

from __future__ import annotations

import numpy as np

from instrument.check import check_mesh
from instrument.core.mesh import NO_EDGE, V_FREE, Mesh
from instrument.core.navigate import build_vertex_edges, find_edge
from instrument.counters import C_CREATED, C_DELETED, C_INCIRCLE
from instrument.refine.cavity import collect_cavity, fill_cavity, forget_cavity, mark_both, new_vertex, order_rim
from meshkit import as_result, corner_sets, problems, refiner, slot_of, triangulated

SQUARE_AND_CENTRE = [[0, 0], [4, 0], [4, 4], [0, 4], [2, 2]]
P = (2.2, 1.7)


def _square():
    m = triangulated(SQUARE_AND_CENTRE)
    m.add_constraint_tables()
    build_vertex_edges(m)
    assert corner_sets(m) == {frozenset(s) for s in ({0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4})}
    return m


def _rim(r, nb: int) -> list[tuple[int, int]]:
    """The rim edges (org, dest) in the order they are in ``r.bnd``."""
    bnd = np.asarray(r.bnd)
    return [(int(bnd[j, 1]), int(bnd[j, 2])) for j in range(nb)]


def test_cavity_is_the_triangles_whose_circle_holds_the_point():
    m = _square()
    r = refiner()
    bottom, right, top, left = (slot_of(m, s) for s in ({0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}))
    tests = m.work[C_INCIRCLE]
    n, nb = collect_cavity(r, m, *P, bottom, -1, -1)
    assert (n, nb) == (2, 4)
    assert list(np.asarray(r.cav)[:n]) == [bottom, right]  # the start first, then as reached
    # one test per neighbour reached across a non-boundary edge: right (in), left and top (out)
    assert m.work[C_INCIRCLE] - tests == 3
    assert set(_rim(r, nb)) == {(0, 1), (1, 2), (2, 4), (4, 0)}
    bnd = np.asarray(r.bnd)[:nb]
    corner, twin = np.asarray(m.corner), np.asarray(m.twin)
    for outer, org, dest, record, edge in bnd.tolist():
        # the rim edge is the cavity triangle's own edge, and column 0 is its twin outside
        assert edge // 3 in (bottom, right)
        assert (corner[edge - edge % 3 + (edge + 1) % 3], corner[edge - edge % 3 + (edge + 2) % 3]) == (org, dest)
        assert outer == twin[edge]
        assert record == -1
        if (org, dest) in ((0, 1), (1, 2)):  # the square's sides: nothing outside
            assert outer == NO_EDGE
        else:
            assert outer // 3 == (top if (org, dest) == (2, 4) else left)
    flags = np.asarray(m.tflag)
    assert flags[bottom] == 1 and flags[right] == 1  # kept for fill_cavity or forget_cavity
    assert flags[top] == 0 and flags[left] == 0  # tested outside: cleared again


def test_forget_cavity_clears_the_marks_and_leaves_the_mesh_alone():
    m = _square()
    r = refiner()
    before = {k: v.copy() for k, v in m.arrays().items() if k != "work"}
    n, nb = collect_cavity(r, m, *P, slot_of(m, {0, 1, 4}), -1, -1)
    forget_cavity(r, m, n)
    after = m.arrays()
    for key, value in before.items():
        assert np.array_equal(after[key], value), key
    assert problems(m) == []


def test_a_subsegment_stops_the_cavity_and_its_record_goes_on_the_rim():
    m = _square()
    r = refiner()
    bottom, right = slot_of(m, {0, 1, 4}), slot_of(m, {1, 2, 4})
    mark_both(m, find_edge(m, 1, 4), 5)
    tests = m.work[C_INCIRCLE]
    n, nb = collect_cavity(r, m, *P, bottom, -1, -1)
    assert (n, nb) == (1, 3)
    assert m.work[C_INCIRCLE] - tests == 1  # only left: right lies across the subsegment
    rows = {(o, d): (outer, record) for outer, o, d, record, _ in np.asarray(r.bnd)[:nb].tolist()}
    assert set(rows) == {(0, 1), (1, 4), (4, 0)}
    assert rows[(1, 4)] == (find_edge(m, 4, 1), 5) and find_edge(m, 4, 1) // 3 == right
    forget_cavity(r, m, n)


def test_order_rim_starts_at_the_given_vertex_and_goes_counter_clockwise():
    m = _square()
    m.add_area_bounds(np.arange(1.0, m.nslot + 1.0))  # a distinct bound per slot, to follow the rows
    r = refiner()
    n, nb = collect_cavity(r, m, *P, slot_of(m, {0, 1, 4}), -1, -1)
    rows = _rim(r, nb)
    value = {edge: tuple(np.asarray(r.bval)[j]) for j, edge in enumerate(rows)}
    for first, expected in ((2, [(2, 4), (4, 0), (0, 1), (1, 2)]), (0, [(0, 1), (1, 2), (2, 4), (4, 0)])):
        order_rim(r, m, nb, first)
        order = [int(k) for k in np.asarray(r.fan)[:nb]]  # the rows, listed in order
        assert [rows[k] for k in order] == expected
        assert _rim(r, nb) == rows  # the rows themselves stay where they are, values and all
        assert [tuple(np.asarray(r.bval)[k]) for k in order] == [value[e] for e in expected]
        assert (np.asarray(m.vslot) == -1).all()  # its scratch is clear again
    forget_cavity(r, m, n)


def _swapped_order(orgs: list[int], dests: list[int], first: int) -> list[int]:
    """The rows' order as order_rim once made it, by moving whole rows: each
    position takes the row leaving the previous one's destination, until
    no row leaves it; the rest stay as the swaps left them."""
    rows = list(range(len(orgs)))
    for pos in range(len(rows)):
        want = first if pos == 0 else dests[rows[pos - 1]]
        at = [orgs[rows[j]] for j in range(len(rows))]
        if want not in at:
            break
        j = at.index(want)
        rows[j], rows[pos] = rows[pos], rows[j]
    return rows


def test_order_rim_lists_a_rim_it_cannot_walk_as_the_swaps_did():
    """A rim that is no single chain from ``first`` (a path from elsewhere,
    two cycles, a cycle and a path) makes the walk give up, and the
    positions are swapped instead, which lists the rows as moving them
    whole did; a single chain is listed by the walk, the same way."""
    rng = np.random.default_rng(7)
    m = Mesh(rng.random((64, 2)), 8)
    r = refiner()
    walked = swapped = 0
    for case in range(400):
        fresh = iter(int(v) for v in rng.permutation(64))
        orgs: list[int] = []
        dests: list[int] = []
        for _ in range(int(rng.integers(1, 4))):  # components: paths and cycles on fresh vertices
            chain = [next(fresh) for _ in range(int(rng.integers(2, 6)))]
            if rng.random() < 0.5:
                chain.append(chain[0])
            orgs += chain[:-1]
            dests += chain[1:]
        nb = len(orgs)
        shuffle = rng.permutation(nb)
        orgs = [orgs[k] for k in shuffle]
        dests = [dests[k] for k in shuffle]
        bnd = np.asarray(r.bnd)
        bnd[:nb, 1] = orgs
        bnd[:nb, 2] = dests
        first = orgs[int(rng.integers(nb))]
        expected = _swapped_order(orgs, dests, first)
        chained = all(dests[expected[k]] == orgs[expected[k + 1]] for k in range(nb - 1))
        walked += chained
        swapped += not chained
        order_rim(r, m, nb, first)
        assert [int(k) for k in np.asarray(r.fan)[:nb]] == expected, case
        assert (np.asarray(m.vslot) == -1).all()
    assert walked > 50 and swapped > 50  # both ways were taken


def test_rim_values_area_bound_folded_along_the_flips_attribute_of_the_inner_triangle():
    m = _square()
    bottom, right, top, left = (slot_of(m, s) for s in ({0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}))
    bounds = np.full(m.nslot, -1.0)
    bounds[[bottom, right, top, left]] = [1.0, 3.0, 5.0, 7.0]
    attributes = np.zeros(m.nslot)
    attributes[[bottom, right, top, left]] = [10.0, 20.0, 30.0, 40.0]
    m.add_area_bounds(bounds)
    m.add_attributes(attributes)
    r = refiner()
    n, nb = collect_cavity(r, m, *P, bottom, -1, -1)
    got = {edge: tuple(np.asarray(r.bval)[j]) for j, edge in enumerate(_rim(r, nb))}
    # bottom's edges keep bottom's bound; right's get the mean of both, as
    # Triangle's flip across bottom-right leaves it; the attribute is the inner triangle's
    assert got == {(0, 1): (1.0, 10.0), (4, 0): (1.0, 10.0), (1, 2): (2.0, 20.0), (2, 4): (2.0, 20.0)}
    forget_cavity(r, m, n)
    # a triangle without a bound passes none on through the flip
    m.area_bound[right] = -1.0
    n, nb = collect_cavity(r, m, *P, bottom, -1, -1)
    got = {edge: np.asarray(r.bval)[j, 0] for j, edge in enumerate(_rim(r, nb))}
    assert got == {(0, 1): 1.0, (4, 0): 1.0, (1, 2): -1.0, (2, 4): -1.0}
    forget_cavity(r, m, n)


def test_fill_cavity_makes_the_fan_from_the_new_vertex():
    m = _square()
    m.add_area_bounds(np.full(m.nslot, 2.5))
    r = refiner()
    created, deleted = m.work[C_CREATED], m.work[C_DELETED]
    p = new_vertex(m, *P, V_FREE, 0, -1, -1, -1, 0.0, 0.0)
    assert p == 5 and m.nvert == 6
    n, nb = collect_cavity(r, m, *P, slot_of(m, {0, 1, 4}), -1, -1)
    order_rim(r, m, nb, 0)
    fill_cavity(r, m, p, n, nb)
    assert m.work[C_CREATED] - created == 4  # the new vertex's degree
    assert m.work[C_DELETED] - deleted == 2  # the cavity
    assert m.nlive == 6
    assert corner_sets(m) == {frozenset(s) for s in ({5, 0, 1}, {5, 1, 2}, {5, 2, 4}, {5, 4, 0}, {2, 3, 4}, {3, 0, 4})}
    fan = np.asarray(r.fan)[:nb]
    corner = np.asarray(m.corner)
    # r.fan lists the new triangles in rim order, each (p, org, dest)
    assert [tuple(corner[3 * t : 3 * t + 3]) for t in fan] == [(5, 0, 1), (5, 1, 2), (5, 2, 4), (5, 4, 0)]
    assert [m.area_bound[t] for t in fan] == [2.5] * 4
    assert problems(m) == []
    assert check_mesh(as_result(m)) == []  # Delaunay again
    assert not np.asarray(m.tflag).any() and (np.asarray(m.vslot) == -1).all()


def test_a_point_on_an_edge_takes_both_sides_and_the_edge_goes():
    """Splitting edge 1-4 at (3, 1): both triangles start the cavity and the
    edge between them is skipped (not a rim edge, not tested)."""
    m = _square()
    r = refiner()
    bottom, right = slot_of(m, {0, 1, 4}), slot_of(m, {1, 2, 4})
    skip = find_edge(m, 1, 4)
    assert skip // 3 == bottom
    tests = m.work[C_INCIRCLE]
    p = new_vertex(m, 3.0, 1.0, V_FREE, 0, -1, -1, -1, 0.0, 0.0)
    n, nb = collect_cavity(r, m, 3.0, 1.0, bottom, right, skip)
    assert (n, nb) == (2, 4)
    assert m.work[C_INCIRCLE] - tests == 2  # top and left, both outside
    order_rim(r, m, nb, 0)
    rows = _rim(r, nb)
    assert [rows[k] for k in np.asarray(r.fan)[:nb]] == [(0, 1), (1, 2), (2, 4), (4, 0)]  # listed in order
    fill_cavity(r, m, p, n, nb)
    assert corner_sets(m) == {frozenset(s) for s in ({5, 0, 1}, {5, 1, 2}, {5, 2, 4}, {5, 4, 0}, {2, 3, 4}, {3, 0, 4})}
    assert find_edge(m, 1, 4) < 0
    assert problems(m) == []
    assert check_mesh(as_result(m)) == []
