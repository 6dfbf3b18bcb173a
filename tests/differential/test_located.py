"""located.alternatives: the placements a hole point at a vertex is judged
with (the triangles it touches, and on the hull leaving it out), on meshes
made in-process (small, valid inputs: the `triangle` package cannot crash)."""

from __future__ import annotations

import numpy as np
import pytest

from tests.differential.cases import Case
from tests.differential.harness import same_mesh
from tests.differential.located import alternatives, cdt_switches
from tests.differential.runners import Outcome

triangle = pytest.importorskip("triangle")

SQUARE = {"vertices": np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]], dtype=float),
          "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]], dtype=np.int32)}


def _alternatives(holes, switches):
    case = Case(family="t", switches=switches, input=dict(SQUARE, holes=np.array(holes, dtype=float)))
    cdt = triangle.triangulate(SQUARE, cdt_switches(switches))
    return alternatives(case, cdt)


def _left_out(alt, k):
    return bool((alt.input["holes"][k] > 1).all())


@pytest.mark.parametrize("switches", ["pQ", "piQ"])
def test_hull_vertices_on_one_edge_can_both_be_left_out(switches):
    alts = _alternatives([[0, 0], [1, 0]], switches)
    # four triangles round the centre, two at each corner: each corner is
    # moved into one of its two or left out
    assert any(_left_out(a, 0) and _left_out(a, 1) for a in alts)
    assert any(not _left_out(a, 0) and not _left_out(a, 1) for a in alts)


def test_hull_vertices_on_no_common_hull_line_are_not_both_left_out():
    # Triangle ignores only the points on its one start edge's line
    alts = _alternatives([[0, 0], [1, 1]], "pQ")
    assert not any(_left_out(a, 0) and _left_out(a, 1) for a in alts)
    assert any(_left_out(a, 0) for a in alts) and any(_left_out(a, 1) for a in alts)
    # under i the old rule stands: any hull point may be left out with any other
    assert any(_left_out(a, 0) and _left_out(a, 1) for a in _alternatives([[0, 0], [1, 1]], "piQ"))


def test_inner_vertex_is_only_moved():
    alts = _alternatives([[0.5, 0.5]], "pQ")
    assert len(alts) == 4  # the centre touches the four triangles
    assert not any(_left_out(a, 0) for a in alts)


def test_same_mesh_ignores_the_copied_hole_points():
    mesh = {"vertices": np.zeros((3, 2)), "triangles": np.array([[0, 1, 2]])}
    a = Outcome("ok", result=dict(mesh, holes=np.array([[0.1, 0.1]])))
    assert same_mesh(a, Outcome("ok", result=dict(mesh, holes=np.array([[5.0, 5.0]]))))
    other = dict(mesh, triangles=np.array([[0, 2, 1]]), holes=np.array([[0.1, 0.1]]))
    assert not same_mesh(a, Outcome("ok", result=other))
