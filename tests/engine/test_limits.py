"""Clear limits instead of memory exhaustion: the angle warning, the vertex
limit (default and ``max_vertices``), area bounds beyond it, the progress hook."""

from __future__ import annotations

import numpy as np
import pytest

import instrument
from instrument import limits
from instrument.check import check_mesh
from instrument.errors import SizeLimitError, TriangleError

A = instrument.get_data("square_hole")
LETTER_A = instrument.get_data("A")  # Triangle's A.poly (from the triangle package): q36 and up never end
SQUARE = {"vertices": [[0, 0], [1, 0], [1, 1], [0, 1]], "segments": [[0, 1], [1, 2], [2, 3], [3, 0]]}


def test_the_documented_formula():
    ceiling = 10**9
    assert limits.vertex_limit(n_input=8, domain_area=15.0, area_bound=None, ceiling=ceiling) == 1_000_000
    assert limits.vertex_limit(n_input=5_000, domain_area=15.0, area_bound=None, ceiling=ceiling) == 5_000_000
    assert limits.vertex_limit(n_input=8, domain_area=15.0, area_bound=1e-4, ceiling=ceiling) == 1_000_000 + 600_000
    assert limits.vertex_limit(n_input=8, domain_area=1.0, area_bound=None, steiner_budget=3_000_000, ceiling=ceiling) == 3_000_008
    assert limits.vertex_limit(n_input=8, domain_area=1.0, area_bound=1e-30, ceiling=ceiling) == ceiling
    assert limits.vertex_limit(n_input=8, domain_area=15.0, area_bound=None, angle_bound=False, ceiling=ceiling) == 4_000_000
    assert limits.memory_ceiling() >= limits.MIN_LIMIT


@pytest.mark.parametrize("angle", [40])
def test_steep_angles_stop_at_the_limit(angle):
    with pytest.raises(SizeLimitError) as info:
        instrument.triangulate(LETTER_A, f"pq{angle}", max_vertices=5_000)
    text = str(info.value)
    assert text.startswith("Refinement stopped at ") and "(limit 5,000; set by max_vertices" in text
    assert f"a minimum angle of {angle} degrees is above 34" in text
    assert "use -S, a smaller angle, or --max-vertices" in text
    n = int(text.split()[3].replace(",", ""))
    assert 5_000 < n < 5_000 + 3 * 2**14  # stopped within one slice of the kernel's work
    assert isinstance(info.value, RuntimeError) and isinstance(info.value, ValueError)


# Six points within rounding of the line y = x / 3 (a chain of five
# segments): the domain is a sliver whose every subsegment its opposite side
# encroaches, so refinement only splits subsegments (the input's, before any
# bad triangle is listed) and never ends (differential regression
# regressions/sliver-hull-limit.json).
SLIVER = {
    "vertices": [[float.fromhex(x), float.fromhex(y)] for x, y in (
        ("0x1.e000000000000p-3", "0x1.3ffffffffffa0p-4"), ("0x1.6000000000000p-1", "0x1.d55555555558dp-3"),
        ("0x1.8000000000000p-1", "0x1.ffffffffffff8p-3"), ("0x1.a000000000000p-1", "0x1.155555555554dp-2"),
        ("0x1.e000000000000p-1", "0x1.3ffffffffffecp-2"), ("0x1.f000000000000p-1", "0x1.4aaaaaaaaaac2p-2"))],
    "segments": [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5]],
}


def test_splitting_subsegments_alone_stops_at_the_limit():
    """The kernel hands back control (and the driver sees the limit) after
    every slice of subsegment splits too, not only when its arrays grow:
    the sliver, one vertex a split, stopped at 1,372,556 vertices for the
    default limit of 1,000,000."""
    seen = [0]
    with pytest.raises(SizeLimitError) as info:
        instrument.triangulate(SLIVER, "pq34a0.000899cviQ", max_vertices=110_000, progress=lambda n, limit: seen.append(n))
    n = int(str(info.value).split()[3].replace(",", ""))
    assert 110_000 < n <= 110_000 + 2**14 + 64
    assert max(np.diff(seen)) <= 2**14 + 64


@pytest.mark.parametrize("angle", [36, 60])
def test_a_steeper_angle_may_run_out_of_precision_first_and_says_why(angle):
    """At 60 degrees refinement splits towards one corner of A until the
    pieces are too short for doubles; at 36 its off-centers close in on a
    point inside A (0.5966, -0.4447) within 3,040 vertices until a bad
    triangle's split point rounds onto its shortest edge (since stop 30 an
    error, no longer a duplicate skipped while the mesh kept a 0-degree
    needle).  The spiral is Triangle's own: with -S500 .. -S3000 its vertex
    sets equal ours, the shortest edge near that point 1.3e-3, 4.6e-6,
    1.3e-7, 2.0e-8, 4.8e-12, 1.9e-15 at 500, 1,000, 1,500, 2,000, 2,500,
    2,700 Steiner points; the last triangle, (0.5966478037457632,
    -0.44471094670422673) and its neighbours one ulp away on each axis, has
    no double inside it (Triangle, given -S4000, returns a mesh whose
    smallest angle is 2.09 degrees; unbounded, it runs on).  Either way a clear error that names the cause."""
    with pytest.raises(TriangleError) as info:
        instrument.triangulate(LETTER_A, f"pq{angle}", max_vertices=5_000)
    text = str(info.value)
    assert text.startswith("Refinement stopped at ") or text.startswith("Ran out of precision at ")
    assert f"{angle} degrees is above 34" in text and "a smaller angle" in text


#: Five points within rounding of y = 0.1, a chain of four segments (campaign seed 3203): under
#: pa0.000000000000000199cjz its encroached subsegments grade it to 1,546,668 vertices in Triangle
#: (1,546,667 in ours), far more than its area of 5e-16 predicts.
SLIVER_CHAIN = {
    "vertices": [[0.359375, float.fromhex("0x1.999999999994ap-4")], [0.75, float.fromhex("0x1.999999999995ap-4")],
                 [0.875, float.fromhex("0x1.999999999992ap-4")], [0.890625, float.fromhex("0x1.999999999999ap-4")],
                 [1.0, float.fromhex("0x1.999999999996ap-4")]],
    "segments": [[0, 1], [1, 2], [2, 3], [3, 4]],
}


@pytest.mark.parametrize("switches, floor", [("pa0.000000000000000199cjzQ", 8_000), ("pq20a0.000000000000000199cjzQ", 2_000)])
def test_the_floor_is_higher_without_an_angle_bound(monkeypatch, switches, floor):
    """A run without q ends on every input, so its floor is MIN_LIMIT_WITHOUT_ANGLE (scaled down here)."""
    monkeypatch.setattr(limits, "MIN_LIMIT", 2_000)
    monkeypatch.setattr(limits, "MIN_LIMIT_WITHOUT_ANGLE", 8_000)
    monkeypatch.setattr(limits, "VERTICES_PER_INPUT", 100)
    # the floor, plus the area bound's few vertices (4 x 5e-16 / 2e-16)
    with pytest.raises(SizeLimitError, match=rf"\(limit {floor // 1000},0\d\d; derived from"):
        instrument.triangulate(SLIVER_CHAIN, switches)


def test_the_default_limit_stops_too(monkeypatch):
    monkeypatch.setattr(limits, "MIN_LIMIT", 20_000)
    monkeypatch.setattr(limits, "VERTICES_PER_INPUT", 100)
    with pytest.raises(SizeLimitError, match=r"\(limit 20,000; derived from the input's size and area bound"):
        instrument.triangulate(LETTER_A, "pq40")


def test_an_area_bound_beyond_the_limit_fails_at_once():
    with pytest.raises(SizeLimitError, match="A maximum area of 1e-30 over a domain of area 1 needs about 8e"):
        instrument.triangulate(SQUARE, "pq30a1e-30")
    with pytest.raises(SizeLimitError, match="more than the limit of 1,000"):
        instrument.triangulate(SQUARE, "pq30a1e-5", max_vertices=1_000)


def test_regional_and_per_triangle_bounds_count():
    d = {**SQUARE, "regions": [[0.5, 0.5, 1, 1e-30]]}
    with pytest.raises(SizeLimitError, match="maximum area of 1e-30"):
        instrument.triangulate(d, "pq30a")
    mesh = instrument.triangulate(SQUARE, "pq30a0.1")
    mesh = {k: mesh[k] for k in ("vertices", "vertex_markers", "triangles")}
    mesh["triangle_max_area"] = np.full(len(mesh["triangles"]), 1e-30)
    with pytest.raises(SizeLimitError, match="maximum area of 1e-30"):
        instrument.triangulate(mesh, "rq30a")


def test_under_the_limit_nothing_changes():
    r = instrument.triangulate(A, "pq30a0.001")
    assert check_mesh(r, A, min_angle=30, max_area=0.001) == []
    assert r.warnings == []
    # the limit counts every vertex made, deleted ones too: room for those
    same = instrument.triangulate(A, "pq30a0.001", max_vertices=2 * len(r["vertices"]))
    np.testing.assert_array_equal(same["vertices"], r["vertices"])


def test_angle_warning_is_in_the_result():
    r = instrument.triangulate(A, "pq38S300")
    assert check_mesh(r, A) == []
    assert len(r["vertices"]) <= 8 + 300
    assert [w for w in r.warnings if w.startswith("Warning:  A minimum angle of 38 degrees is above 34")]
    assert instrument.triangulate(A, "pq34").warnings == []
    assert limits.angle_warning(34.0) is None and limits.angle_warning(34.5) is not None


def test_progress_hook():
    calls = []
    r = instrument.triangulate(SQUARE, "pq30a0.00002", progress=lambda n, limit: calls.append((n, limit)))
    assert check_mesh(r, SQUARE, min_angle=30, max_area=0.00002) == []
    assert calls, "the kernel handed back control at least once"
    assert all(0 < n <= 2 * len(r["vertices"]) and limit >= 1_000_000 for n, limit in calls)
    assert [n for n, _ in calls] == sorted(n for n, _ in calls)


def test_a_progress_hook_may_stop_the_run():
    class Stop(Exception):
        pass

    def stop(n, limit):
        raise Stop

    with pytest.raises(Stop):
        instrument.triangulate(SQUARE, "pq30a0.00002", progress=stop)


def test_size_limit_error_is_a_triangle_error():
    assert issubclass(SizeLimitError, TriangleError)
