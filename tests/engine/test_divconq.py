"""Divide and conquer (instrument/divconq.py) against Triangle's own, tie for tie.

Cocircular points have more than one Delaunay triangulation; Triangle's
divide and conquer picks one by its cut order and tie rules, and ours must
pick the same.  The oracle is the `triangle` package: default options
(alternating cuts) and `l` (vertical cuts only).  Triangles are compared by
their corners' coordinates, so that which copy of a duplicate point is kept
does not matter.
"""

from __future__ import annotations

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh


def by_coordinates(xy, tris) -> set[tuple]:
    out = set()
    for t in np.asarray(tris):
        corners = [(float(xy[v, 0]), float(xy[v, 1])) for v in t]
        k = corners.index(min(corners))
        out.add(tuple(corners[k:] + corners[:k]))
    return out


def tie_sets():
    for a, b in [(2, 2), (2, 7), (3, 3), (4, 9), (5, 5), (7, 3), (8, 8), (12, 11)]:
        yield f"grid{a}x{b}", np.array([(i, j) for i in range(a) for j in range(b)], float)
    rng = np.random.default_rng(11)
    for k in range(12):  # random points of a small lattice: collinear and cocircular sets, duplicates
        side = int(rng.integers(2, 9))
        yield f"lattice{k}", rng.integers(0, side, (int(rng.integers(4, 80)), 2)).astype(float)
    for k in (4, 5, 8, 12, 17, 32):  # regular polygons, with and without the centre
        th = 2 * np.pi * np.arange(k) / k
        yield f"polygon{k}", np.c_[np.cos(th), np.sin(th)]
        yield f"polygon{k}+centre", np.r_[np.c_[np.cos(th), np.sin(th)], [[0.0, 0.0]]]
    pythagorean = [(5, 0), (4, 3), (3, 4), (0, 5), (-3, 4), (-4, 3), (-5, 0), (-4, -3), (-3, -4), (0, -5), (3, -4), (4, -3)]
    for k in range(6):  # exactly cocircular subsets of the circle of radius 5
        pick = rng.choice(len(pythagorean), size=int(rng.integers(4, 12)), replace=False)
        yield f"pythagorean{k}", np.array([pythagorean[i] for i in pick], float)
    yield "rectangle", np.array([[0, 0], [210, 0], [210, 297], [0, 297]], float)
    yield "rotated lattice", rng.integers(0, 30, (2000, 2)).astype(float) @ np.array([[0.6, 0.8], [-0.8, 0.6]])


@pytest.mark.parametrize("opts", ["", "l"])
@pytest.mark.parametrize("name,points", list(tie_sets()), ids=lambda x: x if isinstance(x, str) else "")
def test_ties_are_broken_as_triangle_breaks_them(name, points, opts):
    ours = instrument.triangulate({"vertices": points}, opts)
    theirs = triangle.triangulate({"vertices": points}, opts)
    assert by_coordinates(points, ours["triangles"]) == by_coordinates(points, theirs["triangles"])
    assert check_mesh(ours) == []
    w = ours.work
    assert w["triangles_created"] - w["triangles_deleted"] == len(ours["triangles"])


def test_large_lattice_with_both_cut_orders():
    """Thousands of collinear and cocircular points: many merges meet ties."""
    points = np.random.default_rng(4).integers(0, 70, (5000, 2)).astype(float)
    for opts in ("", "l"):
        ours = instrument.triangulate({"vertices": points}, opts)
        theirs = triangle.triangulate({"vertices": points}, opts)
        assert by_coordinates(points, ours["triangles"]) == by_coordinates(points, theirs["triangles"])


@pytest.mark.parametrize("exponent", [-1000, 1000])
def test_huge_and_tiny_lattices_keep_the_ties(exponent):
    """Triangle's predicates overflow or underflow here (it returns fewer or no
    triangles); ours are exact at any scale, so the scaled lattice gets the
    triangulation Triangle gives the unscaled one."""
    points = np.random.default_rng(6).integers(0, 12, (300, 2)).astype(float)
    scaled = np.ldexp(points, exponent)
    ours = instrument.triangulate({"vertices": scaled})
    theirs = triangle.triangulate({"vertices": points})
    assert by_coordinates(points, ours["triangles"]) == by_coordinates(points, theirs["triangles"])
    assert check_mesh(ours) == []


@pytest.mark.parametrize("n", [3, 4, 5, 6, 7, 9, 13, 40, 257, 2000])
def test_triangles_come_out_in_triangles_memory_order(n):
    """Output lists triangles in memory order with their stored rotation, in
    Triangle as here; on random points ours are Triangle's, row for row, so
    refinement's first sweep over the triangles meets them in Triangle's order."""
    for seed in range(8):
        points = np.random.default_rng(seed).random((n, 2))
        for opts in ("", "l"):
            ours = instrument.triangulate({"vertices": points}, opts)["triangles"]
            theirs = triangle.triangulate({"vertices": points}, opts)["triangles"]
            np.testing.assert_array_equal(ours, theirs)
