"""Segment recovery at extreme scales and next to nearly collinear input
vertices (issue 18, item 8).

Three mechanisms, each once broke a promise of exact results:

* Recovery's tolerance for rounded crossing vertices multiplied the squared
  length of a segment out: at 2^512 it overflowed to infinity, every vertex
  was "on" every segment, and the unit square scaled by 2^512 lost its
  centre vertex (segments bent through it, half the square eaten).
* The same tolerance, relative to the coordinates, applied to input vertices
  too: a vertex 2^-126 of a side's length from a side of a square bent that
  side through itself.  Input vertices are exact; the tolerance now applies
  only where a rounded crossing vertex is involved, and then only to an
  input vertex exactly on the piece's input segment.
* Exactly collinear input has no triangle; recovering segments in it failed
  ("could not recover segment") where Triangle outputs the vertices alone.
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh
from instrument.segments.recover import crossing_parameter

SQUARE = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
SIDES = [[0, 1], [1, 2], [2, 3], [3, 0]]


def _mesh(pslg: dict, switches: str) -> dict:
    result = instrument.triangulate(pslg, switches)
    assert check_mesh(result, pslg=pslg) == []
    return result


def _area(result: dict) -> float:
    v, t = result["vertices"], result["triangles"]
    a, b, c = v[t[:, 0]], v[t[:, 1]], v[t[:, 2]]
    return float(np.sum(0.5 * ((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0]))))


@pytest.mark.parametrize("exponent", [-1000, -512, -300, 0, 300, 511, 512, 900, 1000])
def test_square_with_centre_at_any_scale(exponent):
    s = 2.0**exponent
    pslg = {"vertices": np.array(SQUARE + [[0.5, 0.5]]) * s, "segments": np.array(SIDES)}
    result = _mesh(pslg, "pQ")
    assert len(result["vertices"]) == 5
    assert len(result["triangles"]) == 4  # the centre is in the mesh, no side bent through it
    assert len(result["segments"]) == 4
    if 2.0**-500 < s < 2.0**500:  # the area itself is a double
        assert _area(result) == pytest.approx(s * s, rel=1e-12)


@pytest.mark.parametrize("exponent", [-100, 0, 100])
def test_vertex_near_a_side_does_not_bend_it(exponent):
    s = 1.5 * 2.0**exponent
    pslg = {"vertices": np.array([[0.0, 0.0], [s, 0.0], [s, s], [0.0, s], [s * 2.0**-126, s / 1.5]]),
            "segments": np.array(SIDES)}
    result = _mesh(pslg, "pQ")
    assert len(result["triangles"]) == 4
    assert len(result["segments"]) == 4  # the left side is one subsegment
    assert int(result["vertex_markers"].ravel()[4]) == 0  # the vertex is on no segment


def test_crossing_vertex_still_ends_at_input_vertices_on_the_segment():
    # three segments through (0.5, 0.5): the second crosses the first at a
    # rounded point, and the input vertex on it still ends its pieces
    pslg = {"vertices": np.array(SQUARE + [[0.1, 0.3], [0.9, 0.7], [0.2, 0.8], [0.8, 0.2], [0.5, 0.5]]),
            "segments": np.array(SIDES + [[4, 5], [6, 7]])}
    result = _mesh(pslg, "pQ")
    assert len(result["vertices"]) == 9


@pytest.mark.parametrize("switches", ["pQ", "pcQ", "pq30Q"])
def test_exactly_collinear_input_with_segments(switches):
    points = [[0.25, 0.175], [0.5, 0.25], [0.75, 0.325], [1.0, 0.4]]  # exactly on one line in doubles
    pslg = {"vertices": np.array(points), "segments": np.array([[0, 1], [1, 2], [2, 3]])}
    result = instrument.triangulate(pslg, switches)
    assert len(result["vertices"]) == 4
    assert len(result.get("triangles", [])) == 0
    assert len(result.get("segments", [])) == 0  # as Triangle: the vertices alone


@pytest.mark.parametrize("exponent", [-1070, -600, -300, 0, 300, 600, 1000])
def test_crossing_parameter_is_scale_free(exponent):
    s = 2.0**exponent
    # a -> b crosses r -> l a third of the way along
    t = crossing_parameter(0.0, 1.0 * s, 3.0 * s, 1.0 * s, 1.0 * s, 0.0, 1.0 * s, 3.0 * s)
    assert t == pytest.approx(1.0 / 3.0, rel=1e-15)


def test_crossing_parameter_near_dbl_max():
    big = 1.7e308
    t = crossing_parameter(-big, 0.0, big, 0.0, 0.0, -big, 0.0, big)
    assert t == 0.5
