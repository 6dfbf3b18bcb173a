"""Divide and conquer on several threads (delaunay/parallel.py) gives the
one-thread run's mesh slot for slot, and the same work counts.

The leaves are made tiny (``MIN_LEAF``) so that small inputs exercise deep
trees: odd sizes, collinear runs, duplicates, lattices full of ties.
"""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument import counters
from instrument.check import check_mesh
from instrument.delaunay import delaunay, divconq, parallel

from meshkit import problems


def run(points, method: str, threads: int):
    work = counters.new_work()
    m, dup = delaunay(points, work, method=method, threads=threads)
    a = m.arrays()
    return {
        "corner": a["corner"][: 3 * m.nslot].copy(),
        "twin": a["twin"][: 3 * m.nslot].copy(),
        "counts": (m.nslot, m.nlive, m.nfree),
        "work": work.copy(),
        "dup": dup,
        "problems": problems(m),
    }


def inputs():
    rng = np.random.default_rng(5)
    for n in (4, 5, 7, 8, 9, 31, 64, 100, 257):
        yield f"uniform{n}", rng.random((n, 2))
        yield f"lattice{n}", rng.integers(0, 6, (n, 2)).astype(float)
        yield f"line{n}", np.c_[np.arange(n), 3.0 * np.arange(n)]
    yield "grid", np.mgrid[0:23, 0:19].reshape(2, -1).T.astype(float)
    yield "mixed scales", np.r_[rng.random((60, 2)) * 1e-8, rng.random((60, 2)) * 1e8]


@pytest.mark.parametrize("method", ["divconq", "vertical"])
@pytest.mark.parametrize("name,points", list(inputs()), ids=lambda x: x if isinstance(x, str) else "")
def test_threads_change_nothing(monkeypatch, name, points, method):
    monkeypatch.setattr(parallel, "MIN_LEAF", 2)
    one = run(points, method, 1)
    assert one["problems"] == []
    for threads in (2, 3, 8):
        many = run(points, method, threads)
        for key in ("corner", "twin", "work", "dup"):
            assert np.array_equal(many[key], one[key]), (threads, key)
        assert many["counts"] == one["counts"], threads


@pytest.mark.parametrize("n", [2, 3, 4, 5, 6, 7, 12, 13, 100, 1001])
def test_slot_count_is_known_in_advance(n):
    """``group_slots`` is what a run really uses: the plan's slot offsets rest on it."""
    points = np.random.default_rng(n).random((n, 2))
    m, _ = delaunay(points, counters.new_work(), threads=1)
    assert m.nslot == divconq.group_slots(n)


def test_plan_covers_the_points_with_disjoint_slots():
    top = parallel.plan(1 << 17, True, 4)
    leaves = []

    def walk(g, depth):
        if g.halves is None:
            leaves.append((g, depth))
            return
        left, right = g.halves
        assert (left.lo, left.hi, right.hi) == (g.lo, right.lo, g.hi)
        assert right.first_slot == left.first_slot + divconq.group_slots(left.hi - left.lo)
        walk(left, depth + 1)
        walk(right, depth + 1)

    walk(top, 0)
    assert [d for _, d in leaves] == [2, 2, 2, 2]
    assert [g.frame for g, _ in leaves] == [0, 0, 0, 0]  # frames alternate: 0 at the top, 1, then 0
    assert parallel.plan(1000, True, 4).halves is None  # too small to split


def test_the_api_takes_threads_and_the_mesh_does_not_change():
    points = np.random.default_rng(3).random((3 * parallel.MIN_LEAF, 2))
    one = instrument.triangulate({"vertices": points}, "", threads=1)
    two = instrument.triangulate({"vertices": points}, "", threads=2)
    assert np.array_equal(one["triangles"], two["triangles"])
    assert one.work == two.work
    assert check_mesh(two) == []
    with pytest.raises(ValueError, match="threads"):
        instrument.triangulate({"vertices": points}, "", threads=0)
