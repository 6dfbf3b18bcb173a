"""Hole and region points on the line of Triangle's start hull edge are ignored.

Triangle locates a hole or region point only if it lies strictly left of
the hull edge its point location starts from: after divide and conquer the
counter-clockwise hull edge leaving the least (x, y) vertex; after
incremental insertion the first hull edge its removal of the bounding
triangle meets (delaunay/incremental.py; on the square, the edge arriving
at vertex 0).  A hole point on that edge (or at its ends) eats nothing; on
any other hull edge it eats the domain.  The expected values
were read off the `triangle` package (20250106).
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument.check import check_mesh

SQUARE = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
SQUARE_SEGS = np.array([[0, 1], [1, 2], [2, 3], [3, 0]])


def _square(opts, holes=None, regions=None):
    tri = {"vertices": SQUARE, "segments": SQUARE_SEGS}
    if holes is not None:
        tri["holes"] = np.array(holes, dtype=float)
    if regions is not None:
        tri["regions"] = np.array(regions, dtype=float)
    r = instrument.triangulate(tri, opts)
    assert check_mesh(r, pslg=tri) == []
    return r


@pytest.mark.parametrize(
    "opts, kept_hole",
    [
        ("pQ", [0.5, 0]), ("plQ", [0.5, 0]), ("pQ", [0, 0]), ("pQ", [1, 0]),  # the bottom edge leaves (0, 0)
        ("piQ", [0, 0.5]),  # under i: the edge from (0, 1) to (0, 0)
    ],
)
def test_hole_on_the_start_edge_is_ignored(opts, kept_hole):
    assert len(_square(opts, holes=[kept_hole]).get("triangles", ())) == 2


@pytest.mark.parametrize("opts", ["pQ", "plQ", "piQ"])
@pytest.mark.parametrize("hole", [[1, 0.5], [0.5, 1], [1, 1]])
def test_hole_on_another_hull_edge_eats_the_square(opts, hole):
    assert len(_square(opts, holes=[hole]).get("triangles", ())) == 0


def test_region_on_the_start_edge_is_ignored():
    assert np.asarray(_square("pAQ", regions=[[0.5, 0, 5, 0.1]])["triangle_attributes"]).ravel().tolist() == [0, 0]
    assert np.asarray(_square("pAQ", regions=[[1, 0.5, 5, 0.1]])["triangle_attributes"]).ravel().tolist() == [5, 5]


def test_heptagon_hole_on_its_start_edge():
    """The differential case: a hole point exactly on the edge leaving the leftmost vertex."""
    v = np.array([[0.8134940853202921, 0.7277667852633334], [0.659930673584637, 0.7972009920016492],
                  [0.403432189257829, 0.7972051613422355], [0.1887580331264878, 0.4719877159676771],
                  [0.3051594369191457, 0.25567766172874073], [0.6158813728906052, 0.14335380638931738],
                  [0.7831559480312313, 0.2942751616976341]])
    tri = {"vertices": v, "segments": np.array([[i, (i + 1) % 7] for i in range(7)]),
           "holes": np.array([[0.24695873502281676, 0.3638326888482089]])}
    r = instrument.triangulate(tri, "pQ")
    assert check_mesh(r, pslg=tri) == []
    assert len(r["triangles"]) == 5
