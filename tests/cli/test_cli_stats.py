"""Triangle's statistics block and -V quality statistics (ruppert_io.stats)."""

from __future__ import annotations

import math

import numpy as np
import pytest
import triangle
from clihelpers import (
    A_PQ30_ALGORITHMIC,
    A_PQ30_QUALITY,
    A_PQ30_STATISTICS,
    section,
    triangle_console,
)

from ruppert_io import stats

def test_spec_golden_A_pq30():
    """Triangle's own pq30 mesh of A gives exactly the block printed in reference §3.8."""
    data = triangle.get_data("A")
    mesh = triangle.triangulate(data, "pq30")
    assert stats.format_quality(stats.quality_statistics(mesh)) == A_PQ30_QUALITY
    block = stats.statistics_block(
        stats.mesh_counts(mesh),
        input_vertices=len(data["vertices"]),
        input_segments=len(data["segments"]),
        input_holes=len(data["holes"]),
        poly=True,
    )
    assert block == A_PQ30_STATISTICS
    # Triangle's orientation count = 492 before the statistics + 1 per triangle.
    work = {"incircle_tests": 428, "orient_tests": 492, "circumcenters": 38}
    assert stats.format_algorithmic(work, 87) == A_PQ30_ALGORITHMIC


@pytest.mark.parametrize(
    "name, opts",
    [
        ("dots", ""),
        ("dots", "q"),
        ("A", "pq30"),
        ("la", "pq30"),
        ("face", "pq30a50"),
        ("box", "pqc"),
        ("greenland", "r"),
        ("spiral", "o2"),
    ],
)
def test_same_text_as_triangle(name, opts):
    """On Triangle's own output mesh, our statistics and quality sections are the
    text Triangle printed for it, character for character."""
    data = triangle.get_data(name)
    text, mesh = triangle_console(data, opts)
    ours = stats.format_quality(stats.quality_statistics(mesh))
    assert ours == section(text, "Mesh quality statistics:", "Memory allocation statistics:")
    poly, refine = "p" in opts, "r" in opts
    block = stats.statistics_block(
        stats.mesh_counts(mesh, refine=refine),
        input_vertices=len(data["vertices"]),
        input_triangles=len(data.get("triangles", ())),
        input_segments=len(data.get("segments", ())),
        input_holes=len(data.get("holes", ())),
        poly=poly,
        refine=refine,
    )
    assert block == "\n" + section(text, "Statistics:", "Mesh quality statistics:")


def test_right_isosceles_by_hand():
    mesh = {"vertices": np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]), "triangles": [[0, 1, 2]]}
    q = stats.quality_statistics(mesh)
    assert q.smallest_area == q.largest_area == 0.5
    assert q.shortest_edge == 1.0
    assert q.longest_edge == pytest.approx(math.sqrt(2))
    assert q.shortest_altitude == pytest.approx(1 / math.sqrt(2))  # 2 * area / longest edge
    assert q.largest_aspect_ratio == pytest.approx(2.0)  # longest edge / shortest altitude
    assert q.aspect_histogram == [0, 1] + [0] * 14  # 1.5 < 2 <= 2
    assert q.smallest_angle == pytest.approx(45.0)
    assert q.largest_angle == pytest.approx(90.0)  # no obtuse corner: largest acute one
    expected = [0] * 18
    expected[4] = 2  # two 45-degree corners: 40-50
    expected[8] = 1  # the right angle counts as acute (dot product 0): 80-90
    assert q.angle_histogram == expected


def test_obtuse_triangle_by_hand():
    mesh = {"vertices": np.array([[0.0, 0.0], [4.0, 0.0], [2.0, 1.0]]), "triangles": [[0, 1, 2]]}
    q = stats.quality_statistics(mesh)
    assert q.smallest_area == 2.0
    base_angle = math.degrees(math.atan(0.5))
    assert q.smallest_angle == pytest.approx(base_angle)
    assert q.largest_angle == pytest.approx(180 - 2 * base_angle)
    expected = [0] * 18
    expected[2] = 2  # 26.57 degrees
    expected[12] = 1  # 126.87 degrees
    assert q.angle_histogram == expected
    assert q.largest_aspect_ratio == pytest.approx(4.0 / (2 * 2.0 / 4.0))


def test_corner_order_and_triangle_order_do_not_matter():
    data = triangle.get_data("dots")
    mesh = triangle.triangulate(data, "")
    rolled = dict(mesh, triangles=np.roll(mesh["triangles"], 1, axis=1))
    shuffled = dict(mesh, triangles=mesh["triangles"][::-1])
    a = stats.quality_statistics(mesh)
    assert stats.format_quality(a) == stats.format_quality(stats.quality_statistics(shuffled))
    b = stats.quality_statistics(rolled)
    assert b.angle_histogram == a.angle_histogram
    assert b.smallest_area == pytest.approx(a.smallest_area, rel=1e-12)  # rounding only


def test_empty_mesh():
    mesh = {"vertices": np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]])}
    counts = stats.mesh_counts(mesh)
    assert (counts.vertices, counts.triangles, counts.edges, counts.hull_edges) == (3, 0, 0, 0)
    q = stats.quality_statistics(mesh)
    assert q.aspect_histogram == [0] * 16 and q.angle_histogram == [0] * 18
    assert q.smallest_area == 0.5 * 16.0  # Triangle's sentinel (xspan + yspan)^2
    assert "Mesh quality statistics:" in stats.format_quality(q)


def test_work_section_lists_every_counter_first_two_fixed():
    work = {"orient_tests": 3, "incircle_tests": 5, "triangles_created": 7, "new_counter": 1}
    lines = stats.format_work(work).splitlines()
    assert lines[:4] == ["Work statistics:", "", "  Triangles created: 7", "  Incircle tests: 5"]
    assert "  Orientation tests: 3" in lines and "  New counter: 1" in lines


def test_voronoi_adds_one_circumcenter_per_triangle():
    """Reference §3.7: -v raises A's circumcenter count from 38 to 125 (87 triangles)."""
    work = {"incircle_tests": 428, "orient_tests": 492, "circumcenters": 38}
    text = stats.format_algorithmic(work, 87, voronoi=True)
    assert "  Number of triangle circumcenter computations: 125\n" in text
