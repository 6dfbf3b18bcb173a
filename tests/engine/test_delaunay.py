"""Delaunay triangulation of point sets, compared with Triangle itself."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh

SHARED = Path(__file__).resolve().parents[3] / "shared"
TRIANGLE_DATA = Path(triangle.__file__).parent / "data"


def triangle_set(tris) -> set[tuple[int, ...]]:
    """Triangles as a set of vertex triples, each rotated to start at its smallest id."""
    out = set()
    for t in np.asarray(tris):
        k = int(np.argmin(t))
        out.add(tuple(int(v) for v in np.roll(t, -k)))
    return out


def assert_good(result, points):
    problems = check_mesh(result)
    assert problems == [], problems[:5]
    w = result.work
    ntri = len(result.get("triangles", []))
    assert w["triangles_created"] - w["triangles_deleted"] == ntri
    assert result["vertices"].shape == (len(points), 2)


def point_sets():
    rng = np.random.default_rng(7)
    yield "uniform", rng.random((3000, 2))
    yield "gaussian", rng.normal(size=(3000, 2))
    centers = rng.random((20, 2))
    yield "clustered", (centers[rng.integers(0, 20, 3000)] + 1e-3 * rng.normal(size=(3000, 2)))


@pytest.mark.parametrize("name,points", list(point_sets()), ids=lambda x: x if isinstance(x, str) else "")
def test_random_sets_equal_triangle(name, points):
    ours = instrument.triangulate({"vertices": points})
    theirs = triangle.triangulate({"vertices": points})
    assert triangle_set(ours["triangles"]) == triangle_set(theirs["triangles"])
    assert_good(ours, points)


def quadratic_points(n: int, alpha_deg: float = 20.0) -> np.ndarray:
    """The n + 4 points of Barbic and Miller's equation (2)."""
    tan2 = math.tan(math.radians(alpha_deg)) ** 2
    r = 1
    while not 1.0 / ((2 * r + 1) * (2 * r - 1)) < tan2:
        r += 1
    h = math.sqrt((2 * r + 1) * (2 * r - 1)) / (2 * n)
    a = h + 1 / h
    base = [(i / n, 0.0) for i in range(n + 1)]
    return np.array(base + [(0.0, a), (1.0, a), (1 / (2 * n), h)])


def degenerate_sets():
    g = np.arange(30, dtype=float)
    yield "grid", np.array([(x, y) for x in g for y in g])
    ang = 2 * np.pi * np.arange(64) / 64
    yield "circle", np.c_[np.cos(ang), np.sin(ang)]
    # exactly cocircular: Pythagorean triples on the circle of radius 5*13*17
    R = 5 * 13 * 17
    trip = [(3, 4, 5), (5, 12, 13), (8, 15, 17), (7, 24, 25)]
    pts = set()
    for a, b, c in trip:
        if R % c == 0:
            k = R // c
            for sx in (-1, 1):
                for sy in (-1, 1):
                    pts.add((sx * a * k, sy * b * k))
                    pts.add((sx * b * k, sy * a * k))
    yield "cocircular", np.array(sorted(pts), dtype=float)
    row = np.c_[np.arange(50.0), np.zeros(50)]
    yield "row+apex", np.vstack([row, [[24.5, 3.0]]])
    yield "quadratic", quadratic_points(200)
    yield "grid+dups", np.vstack([np.array([(x, y) for x in g[:10] for y in g[:10]])] * 2)


@pytest.mark.parametrize("name,points", list(degenerate_sets()), ids=lambda x: x if isinstance(x, str) else "")
def test_degenerate_sets_equal_triangle_ties_included(name, points):
    """Divide and conquer picks Triangle's diagonals between cocircular points;
    the incremental method (-i) picks its own, so only its size is compared."""
    ours = instrument.triangulate({"vertices": points})
    theirs = triangle.triangulate({"vertices": points})
    same_point = np.unique(points, axis=0, return_inverse=True)[1].ravel()  # Triangle may keep another copy
    assert triangle_set(same_point[ours["triangles"]]) == triangle_set(same_point[theirs["triangles"]])
    assert_good(ours, points)
    incremental = instrument.triangulate({"vertices": points}, "i")
    assert len(incremental["triangles"]) == len(theirs["triangles"])
    assert_good(incremental, points)


@pytest.mark.parametrize("exponent", [-500, 500])
def test_scaled_sets_give_the_same_triangulation(exponent):
    points = np.random.default_rng(3).random((2000, 2))
    points = np.vstack([points, np.array([(x, y) for x in range(8) for y in range(8)]) / 8.0])  # cocircular too
    plain = instrument.triangulate({"vertices": points})
    scaled = instrument.triangulate({"vertices": np.ldexp(points, exponent)})
    assert triangle_set(scaled["triangles"]) == triangle_set(plain["triangles"])
    assert check_mesh(scaled) == []


def test_duplicates_are_kept_in_numbering_but_not_meshed():
    pts = np.array([[0, 0], [1, 0], [0, 1], [1, 1], [1, 0], [0.5, 0.5], [0, 0]], dtype=float)
    r = instrument.triangulate({"vertices": pts})
    assert r["vertices"].shape == (7, 2)
    used = set(np.unique(r["triangles"]))
    assert 4 not in used and 6 not in used  # the later copies
    assert {0, 1} <= used
    assert r.work["duplicate_vertices"] == 2
    j = instrument.triangulate({"vertices": pts}, "j")
    assert j["vertices"].shape == (5, 2)
    assert check_mesh(j) == []


def test_collinear_input_gives_no_triangles_and_no_error():
    r = instrument.triangulate({"vertices": np.c_[np.arange(10.0), 2 * np.arange(10.0)]})
    assert "triangles" not in r
    assert r["vertices"].shape == (10, 2)


@pytest.mark.parametrize("pts", [[], [[0, 0]], [[0, 0], [1, 1]]])
def test_fewer_than_three_points_is_triangles_error(pts):
    with pytest.raises(ValueError, match="at least three vertices"):
        instrument.triangulate({"vertices": pts})


def test_non_finite_coordinates_are_rejected():
    with pytest.raises(ValueError, match="not finite"):
        instrument.triangulate({"vertices": [[0, 0], [1, 0], [np.nan, 1]]})


def test_package_golden_delaunay_example():
    # from the triangle package's own tests
    pts = np.array([[0, 0], [0, 1], [0.5, 0.5], [1, 1], [1, 0]])
    r = instrument.triangulate({"vertices": pts})
    assert triangle_set(r["triangles"]) == triangle_set([[1, 0, 2], [2, 4, 3], [4, 2, 0], [2, 3, 1]])


def test_output_keys_match_the_triangle_package():
    pts = np.random.default_rng(1).random((40, 2))
    for opts in ["", "e", "n", "c", "ce", "B", "N", "E", "cP", "en"]:
        ours = instrument.triangulate({"vertices": pts}, opts)
        theirs = triangle.triangulate({"vertices": pts}, opts)
        assert sorted(ours) == sorted(theirs), opts
        for k in theirs:
            assert ours[k].shape == theirs[k].shape, (opts, k)
            assert ours[k].dtype == theirs[k].dtype, (opts, k)
    ours = instrument.triangulate({"vertices": pts}, "cen")
    theirs = triangle.triangulate({"vertices": pts}, "cen")
    assert np.array_equal(ours["vertex_markers"], theirs["vertex_markers"])
    assert sorted(map(sorted, ours["segments"].tolist())) == sorted(map(sorted, theirs["segments"].tolist()))
    em_ours = {tuple(sorted(e)): m for e, m in zip(ours["edges"].tolist(), ours["edge_markers"].ravel())}
    em_theirs = {tuple(sorted(e)): m for e, m in zip(theirs["edges"].tolist(), theirs["edge_markers"].ravel())}
    assert em_ours == em_theirs
    # neighbours: neighbour k lies across the edge opposite corner k
    tris, nb = ours["triangles"], ours["neighbors"]
    for t in range(len(tris)):
        for k in range(3):
            if nb[t, k] >= 0:
                edge = {tris[t, (k + 1) % 3], tris[t, (k + 2) % 3]}
                assert edge <= set(tris[nb[t, k]])


def node_files():
    files = sorted(TRIANGLE_DATA.glob("*.node")) + sorted((SHARED / "corpus").glob("*.node"))
    return [f for f in files if ".v." not in f.name]


@pytest.mark.parametrize("path", node_files(), ids=lambda p: p.name)
def test_every_node_file_triangulates_like_triangle(path):
    ruppert_io = pytest.importorskip("ruppert_io")
    data = ruppert_io.read(path)
    pts = data["vertices"]
    ours = instrument.triangulate({"vertices": pts})
    theirs = triangle.triangulate({"vertices": pts})
    assert len(ours.get("triangles", [])) == len(theirs.get("triangles", []))
    assert check_mesh(ours) == []


@pytest.mark.parametrize("opts", ["", "l", "i"])
def test_counters_are_counted(opts):
    pts = np.random.default_rng(5).random((500, 2))
    w = instrument.triangulate({"vertices": pts}, opts).work
    assert w["incircle_tests"] > 0 and w["orient_tests"] > 0 and w["triangles_deleted"] > 0
    # divide and conquer neither walks nor flips: it deletes edges while merging
    assert (w["walk_steps"] > 0 and w["flips"] > 0) == (opts == "i")
    assert w["triangles_created"] - w["triangles_deleted"] == 2 * 500 - 2 - len(
        instrument.triangulate({"vertices": pts}, "c")["segments"]
    )


@pytest.mark.parametrize("opts", ["en", "ien", "len"])
def test_kernels_run_as_python(opts):
    """RUPPERT_PURE_PYTHON=1 runs the kernels from source: the same mesh."""
    code = (
        "import json, sys, numpy as np, instrument\n"
        "from instrument.check import check_mesh\n"
        "from instrument import purepython\n"
        "from instrument.core import mesh\n"
        "p = np.random.default_rng(0).random((60, 2))\n"
        "p = np.vstack([p, p[:5], [[x, y] for x in range(4) for y in range(4)]])\n"
        f"r = instrument.triangulate({{'vertices': p}}, {opts!r})\n"
        "assert check_mesh(r) == [], check_mesh(r)\n"
        "assert not purepython.is_compiled(mesh)\n"
        "print(json.dumps({k: np.asarray(v).tolist() for k, v in r.items()}))\n"
    )
    env = dict(os.environ, NUMBA_DISABLE_JIT="1", RUPPERT_PURE_PYTHON="1")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    p = np.random.default_rng(0).random((60, 2))
    p = np.vstack([p, p[:5], [[x, y] for x in range(4) for y in range(4)]])
    compiled = instrument.triangulate({"vertices": p}, opts)
    pure = json.loads(out.stdout)
    assert sorted(pure) == sorted(compiled)
    for key, value in compiled.items():
        np.testing.assert_array_equal(np.asarray(pure[key]), value, err_msg=key)
