"""Chew's deletion of free vertices (instrument.refine.deletion):
``delete_free_vertex`` re-triangulates a free vertex's star, and
``chew_delete`` deletes the free vertices in a subsegment's diametral circle
before the subsegment is split.

The meshes are the quadrilateral 0 (0,0), 1 (4,0), 2 (5,4), 3 (0,3) with free
vertices inside.  Its Delaunay triangulation is {0,1,3} and {1,2,3}: vertex 3
lies inside the circle through 0, 1 and 2 (about (2, 2.625), radius 3.3), so
the diagonal 0-2 is not Delaunay.  The diametral circle of the side 0-1 is
about (2, 0), radius 2.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from instrument.check import check_mesh
from instrument.core.mesh import NO_EDGE, V_DEAD, V_FREE, V_INPUT
from instrument.core.navigate import build_vertex_edges, find_edge
from instrument.core.status import DONE, FAILED, NEED_ROOM
from instrument.core.subsegments import Subsegments, new_record
from instrument.counters import C_CREATED, C_DELETED, C_DELETED_VERTEX, C_INCIRCLE
from instrument.refine.cavity import mark_both
from instrument.refine.deletion import chew_delete, delete_free_vertex
from meshkit import as_result, corner_sets, problems, refiner, triangulated

QUAD = [[0, 0], [4, 0], [5, 4], [0, 3]]
DELAUNAY_QUAD = {frozenset({0, 1, 3}), frozenset({1, 2, 3})}


def _mesh(free_points):
    """QUAD with ``free_points`` (vertices 4, 5, ...) made free vertices."""
    m = triangulated(QUAD + [list(p) for p in free_points])
    m.add_constraint_tables()
    build_vertex_edges(m)
    m.vtype[4 : m.nvert] = V_FREE
    return m


def _snapshot(m):
    return {k: v.copy() for k, v in m.arrays().items()}


def _unchanged(m, before) -> list[str]:
    now = m.arrays()
    return [k for k, v in before.items() if not np.array_equal(now[k], v)]


def _min_angle(xy, tri) -> float:
    a, b, c = (np.asarray(xy[i], dtype=float) for i in tri)
    angles = []
    for p, q, s in ((a, b, c), (b, c, a), (c, a, b)):
        u, v = q - p, s - p
        angles.append(math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u @ v)))
    return min(angles)


def test_delete_free_vertex_fills_its_star_with_the_delaunay_triangles():
    m = _mesh([(2, 1)])
    assert len(corner_sets(m)) == 4  # vertex 4 sees all four corners
    r = refiner("q40")  # -q40: the new triangle {0,1,3} (min angle 36.87) is bad, {1,2,3} (48.2) is not
    before = m.work.copy()
    e0 = find_edge(m, 4, 0)  # from the vertex; the base is 0 -> 1, opposite it in e0's triangle
    assert delete_free_vertex(r, m, Subsegments(4), e0) == DONE
    work = np.asarray(m.work) - before
    assert work[C_DELETED] == 4 and work[C_CREATED] == 2 and work[C_DELETED_VERTEX] == 1
    # one incircle test: the base 0 -> 1 chooses between 3 and 2 (2 is outside the circle 0, 1, 3)
    assert work[C_INCIRCLE] == 1
    assert m.vtype[4] == V_DEAD
    assert corner_sets(m) == DELAUNAY_QUAD and m.nlive == 2
    # r.fan: the new triangles in Triangle's testing order, the base triangle
    # last, turned so that its handle 3 t runs new apex -> w0 (org, dest: 3 -> 0)
    corner = np.asarray(m.corner)
    fan = [int(t) for t in np.asarray(r.fan)[:2]]
    assert frozenset(corner[3 * fan[0] : 3 * fan[0] + 3].tolist()) == {1, 2, 3}
    assert tuple(corner[3 * fan[1] : 3 * fan[1] + 3]) == (1, 3, 0)
    # the new triangles were tested: exactly the bad one is queued
    bad = [t for t in fan if _min_angle(m.xy, corner[3 * t : 3 * t + 3]) < 40]
    assert bad == [fan[1]]
    assert r.hsize == 1 and int(r.htri[0]) == fan[1]
    assert problems(m) == []
    assert check_mesh(as_result(m)) == []  # vertex 4 is unused now, which the checker allows
    assert (np.asarray(m.vslot) == -1).all()


def test_delete_free_vertex_keeps_the_outside_links_and_subsegment_records():
    m = _mesh([(2, 1)])
    mark_both(m, find_edge(m, 1, 2), 7)
    assert delete_free_vertex(refiner(), m, Subsegments(8), find_edge(m, 4, 0)) == DONE
    e = find_edge(m, 1, 2)
    assert m.seg[e] == 7 and m.twin[e] == NO_EDGE
    assert [int(m.seg[find_edge(m, a, b)]) for a, b in ((0, 1), (3, 0), (2, 3), (1, 3), (3, 1))] == [-1] * 5
    assert problems(m) == []


def test_a_vertex_on_the_boundary_is_not_deleted():
    m = _mesh([(2, 1)])
    m.vtype[0] = V_FREE  # even if it were free: its star is not closed
    before = _snapshot(m)
    assert delete_free_vertex(refiner(), m, Subsegments(4), find_edge(m, 0, 4)) == FAILED
    assert _unchanged(m, before) == []


@pytest.mark.parametrize(("slots", "queue", "need"), [(16, 64, 16), (64, 4, 6)])
def test_short_of_room_it_changes_nothing_and_says_how_much(slots, queue, need):
    """Scratch for the star (a quarter of ``r.cav``) or room in the queue for
    the new triangles; after the driver grows them, the same call succeeds."""
    m = _mesh([(2, 1)])
    before = _snapshot(m)
    r = refiner(slots=slots, queue=queue)
    assert delete_free_vertex(r, m, Subsegments(4), find_edge(m, 4, 0)) == NEED_ROOM
    assert r.need == need
    assert _unchanged(m, before) == []
    assert delete_free_vertex(refiner(), m, Subsegments(4), find_edge(m, 4, 0)) == DONE
    assert corner_sets(m) == DELAUNAY_QUAD


def _subsegment_0_1(m):
    segs = Subsegments(4)
    rec = new_record(segs, 1, 0, 0, 1)
    mark_both(m, find_edge(m, 0, 1), rec)
    return segs, find_edge(m, 0, 1)


@pytest.mark.parametrize("free", [[(2, 1)], [(2, 0.8), (2, 1.5)]])
def test_chew_delete_empties_the_diametral_circle_on_a_free_side(free):
    """One free vertex, or two: after the first goes, the second is the apex
    over the subsegment and goes too; then the apex is an input vertex."""
    m = _mesh(free)
    segs, e = _subsegment_0_1(m)
    before = m.work.copy()
    assert chew_delete(refiner(), m, segs, e) is True
    assert m.work[C_DELETED_VERTEX] - before[C_DELETED_VERTEX] == len(free)
    assert list(m.vtype[4 : m.nvert]) == [V_DEAD] * len(free)
    assert corner_sets(m) == DELAUNAY_QUAD
    assert problems(m) == []
    assert check_mesh(as_result(m)) == []


@pytest.mark.parametrize(
    ("free", "why"),
    [
        ((2, 2.5), "outside the diametral circle"),
        ((2, 1), "another segment meets the side"),
        ((2, 1), "an input vertex"),
    ],
)
def test_chew_delete_leaves_a_vertex_alone(free, why):
    m = _mesh([free])
    segs, e = _subsegment_0_1(m)
    if why == "another segment meets the side":
        mark_both(m, find_edge(m, 1, 4), 3)
    if why == "an input vertex":
        m.vtype[4] = V_INPUT
    assert m.corner[e] == 4  # vertex 4 is the apex over the subsegment
    before = _snapshot(m)
    assert chew_delete(refiner(), m, segs, e) is True
    assert _unchanged(m, before) == [], why
