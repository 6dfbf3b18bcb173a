"""Boundary markers and -j on inputs whose points are all collinear (no triangle).

Triangle's empty triangulation still marks vertices: after divide and
conquer every vertex but the last in (x, y) order gets 1, after incremental
insertion (-i) every vertex in the mesh; duplicates keep their input
marker, and -j leaves them out even though there is no triangle.  The
expected values were read off the `triangle` package (20250106).
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh


def _run(points, opts, markers=None):
    tri = {"vertices": np.array(points, dtype=float)}
    if markers is not None:
        tri["vertex_markers"] = np.array(markers, dtype=np.int32)
    r = instrument.triangulate(tri, opts)
    assert check_mesh(r) == []
    assert len(r.get("triangles", ())) == 0
    return np.asarray(r["vertex_markers"]).ravel().tolist(), np.asarray(r["vertices"]).tolist()


@pytest.mark.parametrize(
    "points, expected",
    [
        ([[0, 0], [1, 1], [2, 2]], [1, 1, 0]),
        ([[2, 2], [0, 0], [1, 1]], [0, 1, 1]),
        ([[5, 0], [3, 0], [1, 0], [0, 0], [2, 0], [4, 0], [6, 0], [9, 0], [8, 0], [7, 0]], [1] * 7 + [0, 1, 1]),
        ([[0, 3], [0, 1], [0, 2], [0, 0]], [0, 1, 1, 1]),
        ([[1, 1], [0, 0], [1, 1]], [0, 1, 0]),  # the last point's copies both stay 0
    ],
)
def test_divide_and_conquer_marks_all_but_the_last(points, expected):
    assert _run(points, "Q")[0] == expected
    assert _run(points, "lQ")[0] == expected


def test_incremental_marks_every_vertex_in_the_mesh():
    assert _run([[0, 0], [1, 1], [2, 2]], "iQ")[0] == [1, 1, 1]
    assert _run([[1, 1], [0, 0], [1, 1]], "iQ")[0] == [1, 1, 0]


def test_markers_given_stay_and_p_marks_nothing():
    pts = [[0, 0], [1, 1], [2, 2], [1, 1]]
    assert _run(pts, "Q", [0, 0, 0, 3])[0] == [1, 1, 0, 3]
    assert _run(pts, "pQ", [0, 0, 0, 3])[0] == [0, 0, 0, 3]


def test_j_leaves_out_duplicates_without_triangles():
    markers, verts = _run([[0, 0], [0, 0], [0, 0]], "jiQ")
    assert verts == [[0.0, 0.0]] and markers == [1]
    markers, verts = _run([[0, 0], [1, 1], [1, 1], [2, 2]], "ijQ")
    assert verts == [[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]] and markers == [1, 1, 1]
