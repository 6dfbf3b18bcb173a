"""-i makes Triangle's triangulation record for record (delaunay/incremental.py).

Ours' iQ triangle list, in order and corner for corner, is compared with
the `triangle` package's on a few hundred generated inputs: random points,
small integer grids (duplicates, collinear runs, points on edges, exact
cocircular ties), collinear sets, repeated points, points on the edges
that join the first point to the bounding triangle's corners, and one set
large enough that Triangle's pool has a second block (its point location
samples block by block).  Triangle runs once, in a child process (it can
crash the interpreter).  Not covered, and documented in docs/fidelity.md:
four exactly cocircular points whose coordinate differences are inexact
(mirror-symmetric trapezoids), where Triangle's adaptive incircle test does
not return 0 and ours, exact, does.

Also checked against Triangle's -VVVV trace (scripts/incremental_trace.py):
every record's corners, the freed bounding-triangle records included; and
the hull edge Triangle's outer-space handle holds afterwards, read off the
order in which -c lists the hull's segments.
"""

from __future__ import annotations

import pickle
import subprocess
import sys

import numpy as np
import pytest
from scripthelpers import load_script

import instrument
from instrument.check import check_mesh
from instrument.counters import new_work
from instrument.delaunay import delaunay

pytest.importorskip("triangle")

_TRIANGLE = """
import pickle, sys, triangle
jobs = pickle.load(sys.stdin.buffer)
out = [triangle.triangulate({'vertices': p}, sw) for p, sw in jobs]
pickle.dump([{k: r[k] for k in ('triangles', 'segments') if k in r} for r in out], sys.stdout.buffer)
"""


def triangle_runs(jobs: list) -> list:
    p = subprocess.run([sys.executable, "-c", _TRIANGLE], input=pickle.dumps(jobs), capture_output=True, timeout=300)
    assert p.returncode == 0, p.stderr[-2000:]
    return pickle.loads(p.stdout)


def point_sets() -> list[np.ndarray]:
    rng = np.random.default_rng(2028)
    sets = []
    for _ in range(120):
        sets.append(rng.random((int(rng.integers(3, 40)), 2)))
    for side in (2, 3, 4, 6):
        for _ in range(25):
            sets.append(rng.integers(0, side, (int(rng.integers(3, 45)), 2)).astype(float))
    for _ in range(20):  # dyadic steps: exact differences, exact ties
        sets.append(rng.integers(0, 9, (int(rng.integers(3, 30)), 2)) / 8.0 + rng.integers(-4, 4))
    for k in range(16):
        t = rng.integers(0, 6, int(rng.integers(3, 12))).astype(float)
        line = np.c_[t, 2 * t + 1] if k % 2 else np.c_[t, np.full_like(t, 3.0)]
        sets.append(np.vstack([line, [[0.5, 7.0]]]) if k % 4 < 2 else line)
    sets += [np.ones((3, 2)), np.ones((5, 2)), np.array([[1.0, 1.0], [1.0, 1.0], [2.0, 3.0]])]  # (Triangle wants 3 points)
    # second points on the edges from the first to a box corner: B1 = (xmin - 50w, ymin - 40w) lies on
    # the ray from (0, 0) through (-5, -4); B2 on the ray through (5, -4)
    sets += [np.array(p, dtype=float) for p in (
        [[0, 0], [-5, -4], [1, 3]], [[0, 0], [5, -4], [-1, 3]], [[0, 0], [-1, 3], [-5, -4]],
        [[0, 0], [-5, -4], [1, 3], [2, -1], [-3, -2.4], [0.5, 0.5]], [[0, 0], [5, -4], [-5, -4], [0, -4], [1, 3]],
    )]  # fmt: skip
    sets.append(rng.random((2100, 2)))  # 4,201 records: Triangle's first block holds 2n - 2
    return sets


SETS = point_sets()


@pytest.fixture(scope="module")
def theirs():
    return triangle_runs([(p, "iQ") for p in SETS])


def test_triangle_lists_are_triangles(theirs):
    differ = []
    for i, (pts, t) in enumerate(zip(SETS, theirs)):
        r = instrument.triangulate({"vertices": pts}, "iQ")
        assert check_mesh(r) == [], i
        ours = np.asarray(r.get("triangles", np.zeros((0, 3), np.int32)))
        want = np.asarray(t.get("triangles", np.zeros((0, 3), np.int32)))
        if ours.shape != want.shape or not np.array_equal(ours, want):
            differ.append(i)
    assert differ == [], f"{len(differ)} of {len(SETS)} differ, the first: {SETS[differ[0]].tolist()}"


@pytest.mark.parametrize("seed", [0, 1])
def test_records_are_triangles_records(seed):
    """Every record Triangle writes holds what ours' slot holds, freed box records included."""
    trace = load_script("incremental_trace")
    rng = np.random.default_rng(seed)
    pts = rng.random((200, 2)) if seed == 0 else rng.integers(0, 5, (60, 2)).astype(float)
    writes, _ = trace.triangle_trace(pts)
    mine, _ = trace.ours(pts)
    assert np.array_equal(trace.triangle_records(writes, len(pts)), mine)


def test_outer_space_handle_is_where_c_starts():
    """Triangle encloses the hull (-c) walking from its outer-space handle and
    lists the subsegment made on edge a -> b as b -> a: its segment list is
    the hull walk from the edge delaunay() names."""
    rng = np.random.default_rng(7)
    sets = [rng.random((int(rng.integers(3, 30)), 2)) for _ in range(30)]
    sets += [rng.integers(0, 5, (int(rng.integers(4, 30)), 2)).astype(float) for _ in range(30)]
    sets = [p for p in sets if np.linalg.matrix_rank(p[1:] - p[0]) == 2]
    for pts, t in zip(sets, triangle_runs([(p, "icQ") for p in sets])):
        m, _ = delaunay(pts, new_work(), method="incremental")
        e = m.outer_space_edge
        start = int(m.corner[3 * (e // 3) + (e + 1) % 3])  # its origin
        corner = np.asarray(m.corner)[: 3 * m.nslot].reshape(-1, 3)
        twin = np.asarray(m.twin)[: 3 * m.nslot].reshape(-1, 3)
        alive = np.asarray(m.stamp)[: m.nslot] > 0
        nxt = {int(corner[s, (k + 1) % 3]): int(corner[s, (k + 2) % 3])
               for s in np.flatnonzero(alive) for k in range(3) if twin[s, k] < 0}  # fmt: skip
        walk, v = [], start
        for _ in range(len(nxt)):
            walk.append([nxt[v], v])
            v = nxt[v]
        assert walk == t["segments"].tolist()
