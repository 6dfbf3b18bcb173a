"""Refining a given mesh (-r) against Triangle, through the shared checker."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh, mesh_area

# Meshes Triangle made, shipped with the `triangle` package.
MESHES = [
    "A.1", "bbox.1", "box.1", "box.2", "box.3", "box.4", "diamond_02_00009.1", "double_hex.1",
    "double_hex.2", "double_hex2.1", "double_hex3.1", "ell", "face.1", "greenland", "la.1",
    "spiral.1", "spiral.q.1", "spiral.r.1", "square_circle_hole.1",
]  # fmt: skip
MESH_KEYS = ("vertices", "vertex_markers", "vertex_attributes", "triangles")
PSLG_KEYS = ("segments", "segment_markers", "holes")


def mesh(name: str, *, pslg: bool = False) -> dict:
    keys = MESH_KEYS + (PSLG_KEYS if pslg else ())
    return {k: v for k, v in triangle.get_data(name).items() if k in keys and len(v)}


def areas(r: dict) -> np.ndarray:
    p = np.asarray(r["vertices"])[np.asarray(r["triangles"])[:, :3]]
    u, v = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    return 0.5 * (u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])


def close(ours: int, theirs: int, rel: float = 0.02, least: int = 3) -> bool:
    return abs(ours - theirs) <= max(least, rel * theirs)


def edge_markers(r: dict) -> dict:
    return {frozenset(s): int(m) for s, m in zip(r["segments"].tolist(), np.ravel(r["segment_markers"]))}


def same_work_balance(r) -> bool:
    w = r.work
    return w["triangles_created"] - w["triangles_deleted"] == len(r.get("triangles", []))


# ---------------------------------------------------------------- no refinement


@pytest.mark.parametrize("name", MESHES)
def test_plain_r_gives_back_the_mesh(name):
    d = mesh(name)
    r = instrument.triangulate(d, "r")
    t = triangle.triangulate(d, "r")
    np.testing.assert_array_equal(r["triangles"], d["triangles"])
    np.testing.assert_array_equal(r["vertices"], d["vertices"])
    # boundary vertices get marker 1 where theirs is 0, as in Triangle
    np.testing.assert_array_equal(r["vertex_markers"], t["vertex_markers"])
    assert "segments" not in r and "segments" not in t
    assert same_work_balance(r)


@pytest.mark.parametrize("name", [n for n in MESHES if "segments" in triangle.get_data(n)])
def test_rp_attaches_the_segments_as_triangle_does(name):
    d = mesh(name, pslg=True)
    r = instrument.triangulate(d, "rp")
    t = triangle.triangulate(d, "rp")
    np.testing.assert_array_equal(r["triangles"], d["triangles"])
    assert edge_markers(r) == edge_markers(t)
    np.testing.assert_array_equal(r["vertex_markers"], t["vertex_markers"])
    # holes are copied, not carved (Triangle ignores them with -r)
    np.testing.assert_array_equal(r.get("holes", []), t.get("holes", []))
    assert r.warnings == []


def test_rc_writes_the_boundary_as_segments():
    d = mesh("spiral.r.1")
    r = instrument.triangulate(d, "rc")
    t = triangle.triangulate(d, "rc")
    assert edge_markers(r) == edge_markers(t)
    assert set(np.ravel(r["segment_markers"])) == {1}


def test_cocircular_diagonals_are_kept():
    """A grid of squares with alternating diagonals: every quad is cocircular,
    and a re-triangulation would pick its own diagonals."""
    n = 8
    xs, ys = np.meshgrid(np.arange(n + 1.0), np.arange(n + 1.0))
    v = np.c_[xs.ravel(), ys.ravel()]
    at = lambda i, j: j * (n + 1) + i
    tris = []
    for j in range(n):
        for i in range(n):
            a, b, c, d = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
            tris += [[a, b, c], [a, c, d]] if (i + j) % 2 else [[a, b, d], [b, c, d]]
    tris = np.array(tris)
    r = instrument.triangulate({"vertices": v, "triangles": tris}, "r")
    np.testing.assert_array_equal(r["triangles"], tris)
    # already good at 30 degrees: refining changes nothing either
    r = instrument.triangulate({"vertices": v, "triangles": tris}, "rq30")
    np.testing.assert_array_equal(r["triangles"], tris)
    r = instrument.triangulate({"vertices": v, "triangles": tris}, "rq30a0.2")
    t = triangle.triangulate({"vertices": v, "triangles": tris}, "rq30a0.2")
    assert check_mesh(r, min_angle=30, max_area=0.2) == []
    assert close(len(r["vertices"]), len(t["vertices"]))


# ---------------------------------------------------------------- refinement


# measured (vertices, ours vs Triangle): equal on all but face.1 rq30 (96 vs 95),
# double_hex.1 rq (147 vs 146) and rq30 (216 vs 217)
CLOSE = ["A.1", "box.1", "box.2", "diamond_02_00009.1", "double_hex.1", "double_hex.2", "double_hex2.1",
         "double_hex3.1", "ell", "face.1", "greenland", "spiral.1", "spiral.r.1", "square_circle_hole.1"]  # fmt: skip


@pytest.mark.parametrize("name", CLOSE)
@pytest.mark.parametrize("opts", ["rq", "rq30", "rpq30"])
def test_refined_meshes_match_triangle(name, opts):
    d = mesh(name, pslg="p" in opts)
    if "p" in opts and "segments" not in d:
        pytest.skip("no segments")
    r = instrument.triangulate(d, opts)
    t = triangle.triangulate(d, opts)
    assert check_mesh(r, min_angle=30 if "q30" in opts else 20) == []
    assert mesh_area(r) == pytest.approx(mesh_area(d), rel=1e-9)
    assert close(len(r["vertices"]), len(t["vertices"])), (len(r["vertices"]), len(t["vertices"]))
    assert same_work_balance(r)


# Here the refiner's order (not the reconstruction) makes the counts drift
# apart, as it does for the first mesh (test_quality allows 6% there).
# measured: box.3 416 vs 400, box.4 886 vs 918, la.1 rpq30 1751 vs 1826,
# spiral.q.1 34 vs 38
@pytest.mark.parametrize(("name", "opts"), [("box.3", "rq30"), ("box.4", "rpq30"), ("la.1", "rpq30"), ("spiral.q.1", "rq30")])
def test_refined_meshes_near_triangle(name, opts):
    d = mesh(name, pslg="p" in opts)
    r = instrument.triangulate(d, opts)
    t = triangle.triangulate(d, opts)
    assert check_mesh(r, min_angle=30) == []
    assert close(len(r["vertices"]), len(t["vertices"]), rel=0.05, least=5)


@pytest.mark.parametrize("first", ["triangle", "ours"])
@pytest.mark.parametrize("opts", ["rq30a0.5", "rq30a0.001", "rpq30", "rpq30a0.0003", "rq30D"])
def test_A_refined_in_both_engines(first, opts):
    """Mesh A.poly with pq30 (Triangle's or ours), then refine that mesh."""
    a = triangle.get_data("A")
    made = triangle.triangulate(a, "pq30") if first == "triangle" else instrument.triangulate(a, "pq30")
    d = {k: np.asarray(made[k]) for k in MESH_KEYS + PSLG_KEYS if k in made}
    if "p" not in opts:
        d = {k: v for k, v in d.items() if k not in PSLG_KEYS}
    r = instrument.triangulate(d, opts)
    t = triangle.triangulate(d, opts)
    max_area = float(opts.split("a")[1][:6]) if "a" in opts else None
    assert check_mesh(r, min_angle=30, max_area=max_area) == []
    # measured: equal except rpq30a0.0003 (229 vs 226 on Triangle's mesh)
    assert close(len(r["vertices"]), len(t["vertices"])), (len(r["vertices"]), len(t["vertices"]))
    if "p" in opts:  # the hole is copied, not carved again
        np.testing.assert_array_equal(r["holes"], d["holes"])


def _smooth_bounds(d: dict, scale: float) -> np.ndarray:
    """An area bound for every triangle, growing from left to right."""
    x = np.asarray(d["vertices"])[np.asarray(d["triangles"])].mean(axis=1)[:, 0]
    lo, hi = x.min(), x.max()
    return scale * (1.0 + 3.0 * (x - lo) / (hi - lo))


@pytest.mark.parametrize(("name", "scale"), [("A.1", 3e-4), ("face.1", 25.0), ("double_hex.1", 2e-3), ("la.1", 0.5)])
def test_per_triangle_area_bounds(name, scale):
    d = mesh(name, pslg=True)
    d["triangle_max_area"] = _smooth_bounds(d, scale)
    # the bound as an attribute too: both travel with the triangles together
    d["triangle_attributes"] = np.c_[d["triangle_max_area"], np.arange(len(d["triangles"]))]
    for opts in ("ra", "rpq30a"):
        r = instrument.triangulate(d, opts)
        t = triangle.triangulate(d, opts)
        assert check_mesh(r, min_angle=30 if "q" in opts else None) == []
        # The bounds travel as in Triangle (reconstruct.py): an insertion's
        # flips average them, so a triangle's bound is a mean of input
        # bounds near it, not its ancestor's (up to 1.29 times it here).
        assert (areas(r) <= d["triangle_max_area"].max() * (1 + 1e-12)).all()
        # descendants of input triangle i carry its attribute row (ours: no averaging)
        anc = r["triangle_attributes"][:, 1].astype(int)
        np.testing.assert_array_equal(r["triangle_attributes"][:, 0], d["triangle_max_area"][anc])
        # measured (vertices, ours vs Triangle, ra / rpq30a): A.1 129/129,
        # 150/150; face.1 345/351, 358/359; double_hex.1 233/233, 255/255;
        # la.1 979/981, 1906/1906.  face.1 under rpq30a was 373/359 while a
        # rejected Steiner point left the bounds as they were; Triangle's
        # flips, undone on rejection, leave their means behind
        # (ghosts.rejected_bounds), and with them its first 341 splits are
        # Triangle's (scripts/queue_trace.py), against 81 before
        assert close(len(r["vertices"]), len(t["vertices"])), (opts, len(r["vertices"]), len(t["vertices"]))


def test_bounds_constant_between_segments_are_met_everywhere():
    """Flips never cross a subsegment, so a bound that is constant on each
    part of the domain the segments enclose stays that part's bound: every
    triangle must meet it."""
    two = {
        "vertices": [[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0], [0.5, 1]],
        "segments": [[0, 4], [4, 1], [1, 2], [2, 5], [5, 3], [3, 0], [4, 5]],
        "regions": [[0.25, 0.5, 1, 0], [0.75, 0.5, 2, 0]],
    }
    made = triangle.triangulate(two, "pqA")
    d = {k: made[k] for k in ("vertices", "vertex_markers", "triangles", "segments", "segment_markers")}
    left = np.asarray(made["triangle_attributes"]).ravel() == 1
    d["triangle_max_area"] = np.where(left, 0.002, 0.02)
    for opts in ("rpa", "rpq30a", "rpqa0.01a"):
        r = instrument.triangulate(d, opts)
        t = triangle.triangulate(d, opts)
        x = np.asarray(r["vertices"])[np.asarray(r["triangles"])].mean(axis=1)[:, 0]
        bound = np.where(x < 0.5, 0.002, 0.01 if "0.01" in opts else 0.02)
        assert (areas(r) <= bound * (1 + 1e-12)).all()
        assert check_mesh(r, min_angle=30 if "q30" in opts else None) == []
        assert close(len(r["vertices"]), len(t["vertices"]), rel=0.03), (opts, len(r["vertices"]), len(t["vertices"]))


def test_area_file_sample():
    """bbox.1 ships with a .area file: one bounded triangle among -1s."""
    d = {k: v for k, v in triangle.get_data("bbox.1").items()}
    for opts in ("ra", "rqa", "rq30a"):
        r = instrument.triangulate(d, opts)
        assert check_mesh(r, min_angle=30 if "q30" in opts else None) == []
    # a bare a without bounds: no area test (Triangle crashes here)
    r = instrument.triangulate({k: v for k, v in d.items() if k != "triangle_max_area"}, "ra")
    np.testing.assert_array_equal(r["triangles"], d["triangles"])


def test_attributes_survive_without_refinement():
    d = mesh("box.2")
    d["triangle_attributes"] = np.arange(2 * len(d["triangles"]), dtype=float).reshape(-1, 2)
    r = instrument.triangulate(d, "r")
    t = triangle.triangulate(d, "r")
    np.testing.assert_array_equal(r["triangle_attributes"], t["triangle_attributes"])
    r = instrument.triangulate(d, "rq30")
    assert r["triangle_attributes"].shape == (len(r["triangles"]), 2)
    assert set(r["triangle_attributes"][:, 0]) <= set(d["triangle_attributes"][:, 0])


def test_second_order_input_drops_the_extra_nodes():
    made = triangle.triangulate(triangle.get_data("A"), "pq30o2")
    d = {k: made[k] for k in ("vertices", "vertex_markers", "vertex_attributes", "triangles")}
    assert d["triangles"].shape[1] == 6
    for opts in ("r", "rq30a0.002"):
        r = instrument.triangulate(d, opts)
        t = triangle.triangulate(d, opts)
        assert check_mesh(r) == []
        assert len(r["vertices"]) == len(t["vertices"])
        if opts == "r":
            for key in ("vertices", "triangles", "vertex_markers", "vertex_attributes"):
                np.testing.assert_array_equal(r[key], t[key])


def test_unused_vertices_stay_even_with_j():
    d = mesh("box.2")
    d["vertices"] = np.vstack([d["vertices"], [[1.5, 1.5], [10.0, 10.0]]])
    d["vertex_markers"] = np.r_[np.ravel(d["vertex_markers"]), 7, 8]
    for opts in ("r", "rj", "rq30a0.05j"):
        r = instrument.triangulate(d, opts)
        t = triangle.triangulate(d, opts)
        np.testing.assert_array_equal(r["vertices"][40:42], d["vertices"][40:])
        assert check_mesh(r) == []
        assert close(len(r["vertices"]), len(t["vertices"]))
    assert list(instrument.triangulate(d, "r")["vertex_markers"][40:, 0]) == [7, 8]


def test_non_delaunay_input_is_made_delaunay_before_refining():
    """Bowyer-Watson insertion needs a Delaunay mesh: a valid but non-Delaunay
    triangulation is flipped first (only when refining)."""
    rng = np.random.default_rng(3)
    p = rng.random((200, 2))
    tris = triangle.triangulate({"vertices": p}, "")["triangles"]
    for _ in range(1500):  # move vertices while every triangle stays ccw
        i = rng.integers(len(p))
        old = p[i].copy()
        p[i] += rng.normal(0, 0.02, 2)
        q = p[tris]
        u, v = q[:, 1] - q[:, 0], q[:, 2] - q[:, 0]
        if not (u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0] > 1e-9).all():
            p[i] = old
    d = {"vertices": p, "triangles": tris}
    r = instrument.triangulate(d, "r")
    np.testing.assert_array_equal(r["triangles"], tris)
    assert check_mesh(r, delaunay=False) == []
    assert check_mesh(r) != []  # the input is not Delaunay
    r = instrument.triangulate(d, "rq30")
    assert r.work["flips"] > 0
    assert check_mesh(r, min_angle=30) == []


def test_segments_that_are_not_edges():
    d = mesh("box.1", pslg=True)
    extra = np.array([[0, 3], [0, 4], [0, 7], [1, 5]])  # 0-3 and 0-7 cross the hole
    d["segments"] = np.vstack([d["segments"], extra])
    d["segment_markers"] = np.r_[np.ravel(d["segment_markers"]), 9, 10, 11, 12]
    r = instrument.triangulate(d, "rp")
    assert r.warnings == [
        "Warning:  Segment 8 does not lie in the mesh; it was ignored.",
        "Warning:  Segment 10 does not lie in the mesh; it was ignored.",
    ]
    marks = edge_markers(r)
    assert marks[frozenset((0, 4))] == 10 and marks[frozenset((1, 5))] == 12
    assert check_mesh(r) == []
    # one across a convex mesh: recovered by flips, then refined
    p = np.random.default_rng(5).random((60, 2))
    d = {"vertices": p, "triangles": triangle.triangulate({"vertices": p}, "")["triangles"]}
    hull = triangle.triangulate({"vertices": p}, "c")["segments"]
    a, b = hull[0, 0], hull[len(hull) // 2, 0]
    d["segments"], d["segment_markers"] = np.array([[a, b]]), np.array([4])
    for opts in ("rp", "rpq30"):
        r = instrument.triangulate(d, opts)
        assert r.warnings == ["Warning:  Segment 0 is not an edge of the mesh; it was inserted."]
        assert check_mesh(r, pslg=d, min_angle=30 if "q" in opts else None) == []
        assert 4 in np.ravel(r["segment_markers"])


@pytest.mark.parametrize(
    ("triangles", "message"),
    [
        ([[0, 1, 9]], "triangle 0 has an invalid vertex index 9"),
        ([[0, 1, -1]], "invalid vertex index -1"),
        ([[0, 1, 1]], "uses the same vertex twice"),
        ([[0, 4, 2]], "collinear"),
        ([[0, 2, 1]], "clockwise"),
        ([[0, 1, 4], [1, 4, 0]], "triangle 1 repeats triangle 0"),
        ([[0, 1, 4], [0, 1, 2]], "triangles 0 and 1 overlap"),
        ([[0, 1, 4], [1, 0, 5], [1, 0, 6]], "shared by more than two triangles"),
        ([[0, 1.5, 4]], "integer"),
        ([[0, 1]], "shape"),
    ],
)
def test_bad_triangles_are_rejected(triangles, message):
    v = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [2, 2], [2, -2], [1, -3.0]])
    with pytest.raises(ValueError, match=message):
        instrument.triangulate({"vertices": v, "triangles": triangles}, "r")


def test_folded_and_other_bad_input():
    # eight triangles winding twice around vertex 0
    ring = [[np.cos(a), np.sin(a)] for a in np.linspace(0, 2 * np.pi, 5)[:-1]]
    ring2 = [[2 * np.cos(a + 0.3), 2 * np.sin(a + 0.3)] for a in np.linspace(0, 2 * np.pi, 5)[:-1]]
    v = np.array([[0.0, 0.0], *ring, *ring2])
    fan = [[0, i, i % 8 + 1] for i in range(1, 9)]
    with pytest.raises(ValueError, match="wind around it more than once"):
        instrument.triangulate({"vertices": v, "triangles": fan}, "r")
    sq = np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]])
    with pytest.raises(ValueError, match="needs the mesh's 'triangles'"):
        instrument.triangulate({"vertices": sq}, "r")
    with pytest.raises(ValueError, match="triangle_max_area has 2 rows for 1 triangles"):
        instrument.triangulate({"vertices": sq, "triangles": [[0, 1, 2]], "triangle_max_area": [1, 2]}, "ra")
    with pytest.raises(ValueError, match="Segment 0 has an invalid vertex index"):
        instrument.triangulate({"vertices": sq, "triangles": [[0, 1, 2]], "segments": [[0, 7]]}, "rp")
    r = instrument.triangulate({"vertices": sq, "triangles": [[0, 1, 2]], "segments": [[0, 3], [1, 1]]}, "rp")
    assert [w.split(";")[0] for w in r.warnings] == [
        "Warning:  Segment 0 has an endpoint that is in no triangle",
        "Warning:  Endpoints of segment 1 are coincident in input.",
    ]
    r = instrument.triangulate({"vertices": sq, "triangles": np.zeros((0, 3), int)}, "rq")
    assert "triangles" not in r and len(r["vertices"]) == 4


def test_a_million_triangles_quickly():
    """Linking is linear (a counting sort by origin); 10^6 triangles of random
    points: about 0.4 s here, Triangle's own -r about 0.3 s (measured)."""
    p = np.random.default_rng(0).random((500_000, 2))
    made = triangle.triangulate({"vertices": p}, "")
    d = {"vertices": made["vertices"], "triangles": made["triangles"]}
    r = instrument.triangulate(d, "r")
    np.testing.assert_array_equal(r["triangles"], made["triangles"])


def test_kernels_run_without_the_jit():
    code = (
        "import numpy as np, triangle, instrument\n"
        "from instrument.check import check_mesh\n"
        "d = {k: v for k, v in triangle.get_data('box.2').items()}\n"
        "r = instrument.triangulate(d, 'rpq30')\n"
        "assert check_mesh(r, min_angle=30) == [], check_mesh(r)\n"
        "try:\n"
        "    instrument.triangulate({'vertices': d['vertices'], 'triangles': d['triangles'][:, ::-1]}, 'r')\n"
        "except ValueError as e:\n"
        "    assert 'clockwise' in str(e)\n"
        "print(len(r['vertices']))\n"
    )
    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    out = subprocess.run([sys.executable, "-c", code], check=False, env=env, capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr[-2000:]
    d = triangle.get_data("box.2")
    assert int(out.stdout.strip()) == len(instrument.triangulate(d, "rpq30")["vertices"])
