"""Quality refinement (-q, -a, -D, -S, strategies) against Triangle, through the shared checker."""

from __future__ import annotations

import numpy as np
import pytest
import triangle

import instrument
from instrument.check import check_mesh, mesh_area
from instrument.strategies import triangle_bucket

POLYS = ["A", "box", "face", "la", "double_hex", "double_hex2", "double_hex3", "square_circle_hole"]


def data(name: str) -> dict:
    return {k: v for k, v in triangle.get_data(name).items() if len(v)}


def min_angle(opts: str) -> float:
    return float(opts.split("q")[1][:2])


@pytest.mark.parametrize("name", POLYS)
@pytest.mark.parametrize("opts", ["pq20", "pq30", "pq30D"])
def test_quality_meshes_match_triangle(name, opts):
    d = data(name)
    r = instrument.triangulate(d, opts)
    t = triangle.triangulate(d, opts)
    assert check_mesh(r, min_angle=min_angle(opts)) == []
    assert mesh_area(r) == pytest.approx(mesh_area(t), rel=1e-9)
    ours, theirs = len(r["vertices"]), len(t["vertices"])
    # measured: within 5% of Triangle on these inputs (order details differ)
    assert abs(ours - theirs) <= max(3, 0.06 * theirs), (ours, theirs)
    w = r.work
    assert w["triangles_created"] - w["triangles_deleted"] == len(r.get("triangles", []))


def vertex_set(mesh: dict) -> set[tuple[float, float]]:
    return {(float(x), float(y)) for x, y in mesh["vertices"]}


@pytest.mark.parametrize(
    ("name", "opts"),
    [("box.2", "pq30"), ("double_hex3.1", "pq30"), ("face", "pq30D"), ("face", "pq20"), ("la", "pq30S50"), ("box.4", "pq30S100"), ("face", "pq30S50")],
)
def test_refinement_replays_triangle_bit_for_bit(name, opts):
    """Triangle's order, split arithmetic and walk: on these inputs (or for
    the first S Steiner points) our vertices are Triangle's, bit for bit."""
    d = data(name)
    assert vertex_set(instrument.triangulate(d, opts)) == vertex_set(triangle.triangulate(d, opts))


@pytest.mark.parametrize(("name", "opts"), [("box.2", "pq30"), ("face", "pq30D")])
def test_new_vertices_interpolate_attributes_as_triangle_does(name, opts):
    """Where our vertices are Triangle's, so are their attributes: segment
    splits interpolate along the segment, Steiner points barycentrically in
    the triangle split (a nonlinear attribute makes the weights show).  Up
    to rounding: a midpoint is the same point from either end of a
    subsegment, its attribute not always (one vertex of each mesh here,
    last bit), and our subsegments do not always run Triangle's way."""
    d = data(name)
    x, y = d["vertices"][:, 0], d["vertices"][:, 1]
    d["vertex_attributes"] = np.c_[x + 2 * y, x * y]
    ours, theirs = instrument.triangulate(d, opts), triangle.triangulate(d, opts)
    assert len(ours["vertices"]) > len(d["vertices"])
    attrs = {tuple(v): a for v, a in zip(theirs["vertices"], theirs["vertex_attributes"])}
    assert {tuple(v) for v in ours["vertices"]} == set(attrs)
    for v, a in zip(ours["vertices"], ours["vertex_attributes"]):
        assert a == pytest.approx(attrs[tuple(v)], rel=1e-15, abs=1e-15), v


@pytest.mark.parametrize("strategy", list(instrument.strategies()))
@pytest.mark.parametrize("steiner", ["offcenter", "circumcenter"])
def test_every_strategy_meets_the_bound(strategy, steiner):
    for name in ("A", "la"):
        r = instrument.triangulate(data(name), "pq30", strategy=strategy, steiner=steiner, seed=3)
        assert check_mesh(r, min_angle=30) == []
        w = r.work
        assert w["triangles_created"] - w["triangles_deleted"] == len(r.get("triangles", []))


def test_q33_terminates_everywhere():
    for name in POLYS:
        r = instrument.triangulate(data(name), "pq33")
        assert check_mesh(r, min_angle=33) == []


@pytest.mark.parametrize("budget", [0, 5, 20])
def test_steiner_budget_is_exact(budget):
    d = data("A")
    r = instrument.triangulate(d, f"pq30S{budget}")
    assert r.work["steiner_points"] == budget
    assert check_mesh(r) == []


def test_area_bounds_fixed_and_regional():
    d = data("la")
    r = instrument.triangulate(d, "pq30a0.01")
    areas = _areas(r)
    assert areas.max() <= 0.01
    assert check_mesh(r, min_angle=30) == []
    r = instrument.triangulate(d, "pq30Aa")
    assert check_mesh(r, min_angle=30) == []
    assert "triangle_attributes" in r


def test_point_set_refinement_encloses_the_hull():
    rng = np.random.default_rng(1)
    d = {"vertices": rng.random((200, 2))}
    r = instrument.triangulate(d, "q30")
    t = triangle.triangulate(d, "q30")
    assert check_mesh(r, min_angle=30) == []
    assert abs(len(r["vertices"]) - len(t["vertices"])) <= 0.06 * len(t["vertices"])


def test_trace_has_one_row_per_insertion_attempt():
    r = instrument.triangulate(data("A"), "pq30", trace=True)
    kinds = set(r.trace["kind"])
    assert kinds <= {"segment", "circumcenter", "offcenter", "rejected", "deleted"}
    done = r.trace[r.trace["kind"] != "rejected"]
    # every Steiner point and every deletion has its row
    assert (r.trace["kind"] == "deleted").sum() == r.work["deleted_vertices"]
    assert len(done) - (r.trace["kind"] == "deleted").sum() == r.work["steiner_points"]


def test_triangle_buckets_by_hand():
    # spec 4.8.4: L = key or 1/key = 2^e f, f in (1, 2]; x = 2e + [f > sqrt 2]
    assert triangle_bucket(1.0) == 2047  # L = 1: e = 0, f = 1
    assert triangle_bucket(2.0) == 2046  # 2 = 2^0 * 2: x = 0 + [2 > sqrt 2] = 1
    assert triangle_bucket(1.3) == 2047  # f = 1.3 <= sqrt 2
    assert triangle_bucket(1.5) == 2046  # f = 1.5 > sqrt 2
    assert triangle_bucket(0.5) == 2048 + 1  # L = 2 = 2^0 * 2: x = 1
    assert triangle_bucket(0.25) == 2048 + 3  # L = 4 = 2^1 * 2: x = 2 + 1
    # finer triangles (smaller keys) get higher buckets: served first
    assert triangle_bucket(1e-6) > triangle_bucket(1e-3) > triangle_bucket(1.0) > triangle_bucket(1e3)


def _queue(strategy: str, capacity: int = 64):
    """A refiner holding only a bad-triangle queue."""
    from instrument import refine as rf
    from instrument.strategies import strategy_id

    z = np.zeros(0, dtype=np.int64)
    ipar = np.zeros(rf.I_NPAR, dtype=np.int64)
    ipar[rf.I_STRATEGY] = strategy_id(strategy)
    r = rf.Refiner(
        ipar=ipar, par=np.zeros(rf.P_NPAR), vtype=np.zeros(0, dtype=np.int8), area=np.zeros(0), attr=np.zeros(0),
        hkey=np.zeros(capacity), hseq=np.zeros(capacity, dtype=np.int64), htri=np.zeros(capacity, dtype=np.int64),
        hstamp=np.zeros(capacity, dtype=np.int64), bucket=np.zeros((2, rf.NBUCKETS), dtype=np.int64),
        enc=np.zeros((0, 4), dtype=np.int64), cav=z, fan=z, seen=np.zeros(0, dtype=np.int8),
        bnd=np.zeros((0, 5), dtype=np.int64), bval=np.zeros((0, 2)), carry=np.zeros(0), vslot=z, trace=np.zeros((0, 5), dtype=np.int64),
    )
    rf.queue_clear(r)
    return rf, r


@pytest.mark.parametrize("strategy", ["triangle", "fifo"])
def test_bucket_queue_serves_finest_first_fifo_within_and_compacts_in_order(strategy):
    # Triangle's queue (spec 4.8.4): squared shortest edges 1.3 and 1.0 share
    # bucket 2047, 0.5 is in 2049, 0.25 in 2051; the highest bucket goes first.
    from collections import namedtuple

    rf, r = _queue(strategy)
    keys = [1.3, 0.5, 1.0, 0.25, 0.5, 2.0, 0.25]
    for t, key in enumerate(keys):
        rf.heap_push(r, -float(triangle_bucket(key)) if strategy == "triangle" else 0.0, t, 1)
    # triangles 4 and 0 die: compaction must drop them and keep the order of the rest
    Stamps = namedtuple("Stamps", "stamp")
    rf.heap_compact(r, Stamps(np.array([0, 1, 1, 1, 0, 1, 1], dtype=np.int32)))
    order = [int(r.htri[rf.heap_pop(r)]) for _ in range(int(r.ipar[rf.I_HSIZE]))]
    assert order == ([3, 6, 1, 2, 5] if strategy == "triangle" else [1, 2, 3, 5, 6])
    assert rf.queue_used(r) == (5 if strategy == "triangle" else 0)  # served entries stay in the log
    rf.heap_compact(r, Stamps(np.ones(7, dtype=np.int32)))  # until the next compaction
    assert rf.queue_used(r) == 0
    rf.heap_push(r, -2047.0 if strategy == "triangle" else 0.0, 9, 1)
    assert int(r.htri[rf.heap_pop(r)]) == 9 and r.ipar[rf.I_HSIZE] == 0


def _areas(r):
    p = r["vertices"][r["triangles"]]
    u, v = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    return 0.5 * np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])


UNIT_SQUARE = {"vertices": np.array([[0, 0], [1, 0], [1, 1], [0, 1.0]]), "segments": np.array([[0, 1], [1, 2], [2, 3], [3, 0]])}


def _builtin_unsuitable(org, dest, apex, area) -> bool:
    longest = max(np.sum((org - dest) ** 2), np.sum((dest - apex) ** 2), np.sum((apex - org) ** 2))
    return longest > 0.05 * (org @ org) + 0.02


def test_builtin_user_test_like_triangles():
    r = instrument.triangulate(UNIT_SQUARE, "pq30u")
    t = triangle.triangulate(UNIT_SQUARE, "pq30u")
    assert check_mesh(r, min_angle=30) == []
    # the built-in test depends on which corner is "org" (spec: 6 of Triangle's
    # 117 fail for some org), so only every triangle's best corner passes
    tris = r["vertices"][r["triangles"]]
    assert all(not all(_builtin_unsuitable(*np.roll(tri, k, axis=0), 0.0) for k in range(3)) for tri in tris)
    assert abs(len(r["triangles"]) - len(t["triangles"])) <= 0.15 * len(t["triangles"])


def test_python_user_test_is_met_everywhere():
    calls = []

    def small_near_origin(org, dest, apex, area):
        calls.append(area)
        centroid = (org + dest + apex) / 3
        return area > 0.0005 + 0.01 * (centroid @ centroid)

    r = instrument.triangulate(UNIT_SQUARE, "pq30u", triunsuitable=small_near_origin)
    assert check_mesh(r, min_angle=30) == []
    assert calls and min(calls) > 0  # counter-clockwise: positive areas
    tris = r["vertices"][r["triangles"]]
    areas = _areas(r)
    centroids = tris.mean(axis=1)
    assert np.all(areas <= 0.0005 + 0.01 * np.sum(centroids**2, axis=1) + 1e-15)
    # a user test that is never met leaves the quality mesh alone
    plain = instrument.triangulate(UNIT_SQUARE, "pq30")
    lazy = instrument.triangulate(UNIT_SQUARE, "pq30u", triunsuitable=lambda *a: False)
    assert len(lazy["vertices"]) == len(plain["vertices"])
