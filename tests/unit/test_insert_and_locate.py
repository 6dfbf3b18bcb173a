"""Splits, flips and walks (instrument.core.insert, locate, navigate)."""

from __future__ import annotations

import numpy as np
import pytest

from instrument.core.insert import flip, lawson, should_flip, split_edge, split_triangle, star_edges
from instrument.core.locate import (
    LOC_BLOCKED, LOC_INSIDE, LOC_ON_EDGE, LOC_ON_VERTEX, LOC_OUTSIDE, line_walk, precise_walk, walk,
)
from instrument.core.mesh import NO_EDGE
from instrument.core.navigate import build_vertex_edges, edge_around, find_edge, vertex_edge
from instrument.counters import C_CREATED, C_DELETED, C_FLIP
from meshkit import problems, triangulated

SQUARE = [[0, 0], [2, 0], [2, 2], [0, 2]]


def _add_vertex(m, x, y):
    v = m.nvert
    m.arrays()["xy"][v] = (x, y)
    m.nvert = v + 1
    return v


def test_split_triangle_makes_three_around_the_new_vertex():
    m = triangulated([[0, 0], [3, 0], [0, 3]])
    t = m.live_triangles()[0]
    v = _add_vertex(m, 1.0, 1.0)
    created = m.work[C_CREATED]
    first = split_triangle(m, t, v)
    assert m.work[C_CREATED] - created == 3 and m.work[C_DELETED] == 1
    corner = m.arrays()["corner"]
    assert corner[3 * first] == v  # the new vertex at corner 0
    assert sorted(int(corner[3 * s]) for s in m.live_triangles()) == [v, v, v]
    assert problems(m) == []
    stack = np.zeros(16, dtype=np.int64)
    assert star_edges(m, first, stack) == 3


def test_split_edge_splits_both_sides_and_keeps_the_subsegment():
    m = triangulated(SQUARE)
    e = next(e for e in range(3 * m.nslot) if m.arrays()["twin"][e] != NO_EDGE and m.arrays()["stamp"][e // 3] > 0)
    m.arrays()["seg"][e] = m.arrays()["seg"][m.arrays()["twin"][e]] = 7
    corner = m.arrays()["corner"]
    o, d = corner[e - e % 3 + (e % 3 + 1) % 3], corner[e - e % 3 + (e % 3 + 2) % 3]
    xy = m.arrays()["xy"]
    v = _add_vertex(m, *(0.5 * (xy[o] + xy[d])))
    on_line = split_edge(m, e, v)
    assert m.nlive == 4 and problems(m) == []
    assert m.arrays()["seg"][on_line] == 7  # both halves keep the record
    build_vertex_edges(m)
    assert m.arrays()["seg"][find_edge(m, v, o)] == 7 and m.arrays()["seg"][find_edge(m, v, d)] == 7


def test_flip_turns_the_diagonal_and_counts_one_flip():
    m = triangulated([[0, 0], [2, 0], [2.1, 2], [0, 2]])
    build_vertex_edges(m)
    # the Delaunay diagonal is one of the two; flip it to the other
    e = next(e for e in range(3 * m.nslot) if m.arrays()["twin"][e] != NO_EDGE and m.arrays()["stamp"][e // 3] > 0)
    corner = m.arrays()["corner"]
    apexes = {int(corner[e]), int(corner[m.arrays()["twin"][e]])}
    t1 = flip(m, e)
    assert m.work[C_FLIP] == 1 and problems(m) == []
    build_vertex_edges(m)
    a, b = sorted(apexes)
    assert find_edge(m, a, b) >= 0  # the new diagonal joins the old apexes
    # the new diagonal (edge 1 of the first new triangle) is not Delaunay: the
    # points are not cocircular and the old one was; it wants back
    assert should_flip(m, 3 * t1 + 1)
    flip(m, 3 * t1 + 1)
    assert problems(m) == [] and m.work[C_FLIP] == 2


def test_lawson_restores_delaunay_after_an_insertion():
    rng = np.random.default_rng(4)
    pts = rng.random((40, 2))
    m = triangulated(pts)
    v = _add_vertex(m, 0.5, 0.5)
    status, e = walk(m, m.live_triangles()[0], 0.5, 0.5, 1000)
    assert status == LOC_INSIDE
    first = split_triangle(m, e // 3, v)
    stack = np.zeros(256, dtype=np.int64)
    n = star_edges(m, first, stack)
    lawson(m, stack, n)
    assert problems(m) == []
    for t in m.live_triangles():  # every edge is locally Delaunay again
        for k in range(3):
            assert not should_flip(m, 3 * t + k)


@pytest.mark.parametrize(("x", "y", "want"), [(0.5, 0.5, LOC_INSIDE), (1.0, 0.0, LOC_ON_EDGE), (2.0, 2.0, LOC_ON_VERTEX), (3.0, 1.0, LOC_OUTSIDE)])
def test_walk_classifies_points(x, y, want):
    m = triangulated(SQUARE)
    status, e = walk(m, m.live_triangles()[0], x, y, 100)
    assert status == want
    corner, xy = m.arrays()["corner"], m.arrays()["xy"]
    if want == LOC_ON_VERTEX:
        assert tuple(xy[corner[e - e % 3 + (e % 3 + 1) % 3]]) == (x, y)  # origin of e


def test_line_walk_stops_at_a_subsegment():
    m = triangulated([[0, 0], [4, 0], [4, 2], [0, 2], [2, 0], [2, 2]])
    build_vertex_edges(m)
    e = find_edge(m, 4, 5)  # the middle line x = 2
    m.arrays()["seg"][e] = m.arrays()["seg"][m.arrays()["twin"][e]] = 0
    left = next(t for t in m.live_triangles() if m.arrays()["xy"][m.arrays()["corner"][3 * t : 3 * t + 3]][:, 0].max() <= 2)
    status, f = line_walk(m, left, 3.0, 1.0, 100)
    assert status == LOC_BLOCKED and m.arrays()["seg"][f] == 0
    status, _ = precise_walk(m, 3 * left, 0.5, 1.0, 100)
    assert status in (LOC_INSIDE, LOC_ON_EDGE, LOC_BLOCKED)


def test_edge_finding_by_vertices():
    m = triangulated(SQUARE + [[1, 1]])
    build_vertex_edges(m)
    for u, v in [(0, 4), (4, 2), (1, 4)]:
        e = find_edge(m, u, v)
        corner = m.arrays()["corner"]
        assert e >= 0 and corner[e - e % 3 + (e % 3 + 1) % 3] == u and corner[e - e % 3 + (e % 3 + 2) % 3] == v
        assert edge_around(m, vertex_edge(m, u), v) == e
    assert find_edge(m, 0, 2) < 0  # the square's diagonal through the centre vertex is two edges
