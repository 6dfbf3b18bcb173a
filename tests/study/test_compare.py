"""The comparison (instrument.study.compare, its runners, scripts/compare.py): small and fast."""

from __future__ import annotations

import csv
import importlib.util
import inspect
import math
import subprocess
import sys
from pathlib import Path

import pytest

triangle = pytest.importorskip("triangle")

import instrument
from instrument.check import check_mesh
from instrument.study.cgal_engine import cgal_criteria
from instrument.study.compare import COLUMNS, Row, compare, flag_rows
from instrument.study.triangle_engine import parse_triangle_statistics, triangle_statistics, triangle_switches

ROOT = Path(__file__).resolve().parents[2]
TRIANGLE_DATA = Path(triangle.__file__).parent / "data"  # Triangle's samples (not shipped here)
HAS_CGAL = importlib.util.find_spec("CGAL") is not None


@pytest.fixture(scope="module")
def A():
    return triangle.get_data("A")


@pytest.fixture(scope="module")
def rows_p(A):
    return compare(A, "p", name="A", repeat=1, keep_meshes=True)


def by_engine(rows):
    return {r.label: r for r in rows}


def test_rows_for_p(rows_p, A):
    rows = by_engine(rows_p)
    assert {"triangle", "ours:triangle"} <= set(rows)
    for row in rows_p:
        assert isinstance(row, Row)
        assert set(COLUMNS) <= set(row.as_dict())
        assert "mesh" not in row.as_dict()
    tri, ours = rows["triangle"], rows["ours:triangle"]
    assert (tri.status, tri.vertices, tri.triangles) == ("ok", 29, 29)
    assert (ours.status, ours.vertices, ours.triangles) == ("ok", 29, 29)
    for row in (tri, ours):
        assert 0 < row.min_angle < 60 < row.max_angle < 180
        assert row.area == pytest.approx(0.08412736)
        assert row.wall_s > 0 and row.time_ratio > 0
    assert tri.time_ratio == 1.0
    # Triangle's statistics were captured from its C output
    assert tri.incircle_tests > 0 and tri.orient_tests > 0 and tri.circumcenters == 0
    assert tri.work["mesh_triangles"] == 29
    assert tri.work["orient_tests_printed"] == tri.orient_tests + 29
    # our counters
    assert ours.incircle_tests > 0 and ours.orient_tests > 0 and ours.triangles_created >= 29
    assert ours.work["triangles_created"] == ours.triangles_created
    assert ours.flags == []
    assert check_mesh(ours.mesh, pslg=A) == []


def test_pq30(A):
    rows = by_engine(compare(A, "pq30", name="A", strategies=["triangle"], repeat=1, keep_meshes=True))
    tri, ours = rows["triangle"], rows["ours:triangle"]
    assert (tri.vertices, tri.triangles, tri.circumcenters) == (76, 87, 38)
    assert tri.min_angle >= 30
    if ours.status == "unsupported":
        pytest.skip(f"our engine does not do pq30 yet: {ours.note}")
    assert ours.status == "ok", ours.note
    assert ours.min_angle >= 30 - 1e-6
    assert ours.area == pytest.approx(tri.area)
    assert ours.triangles_created > ours.triangles
    assert "angle" not in ours.flags and "area" not in ours.flags
    assert check_mesh(ours.mesh, pslg=A, min_angle=30) == []


def test_not_implemented_is_reported_as_unsupported(A, monkeypatch):
    def refuse(*args, **kwargs):
        raise NotImplementedError("not yet")

    monkeypatch.setattr(instrument, "triangulate", refuse)
    rows = by_engine(compare(A, "pq30", name="A", strategies=["triangle", "fifo"], engines=("ours", "triangle"),
                             repeat=1))
    for label in ("ours:triangle", "ours:fifo"):
        assert rows[label].status == "unsupported"
        assert "not yet" in rows[label].note
        assert rows[label].flags == []
    assert rows["triangle"].status == "ok"


def test_triangle_statistics_match_the_reference(A):
    """triangle-reference.md 3.8: A.poly -pq30V prints 428 incircle, 579 orient,
    38 circumcenter; 87 of those orientation tests are the statistics' own."""
    out, stats, raw = triangle_statistics(A, "pq30")
    assert "Algorithmic statistics" in raw
    assert len(out["triangles"]) == 87
    assert stats["incircle_tests"] == 428
    assert stats["orient_tests_printed"] == 579
    assert stats["orient_tests"] == 579 - 87
    assert stats["circumcenters"] == 38


def test_parse_statistics_without_circumcenters():
    text = "  Mesh triangles: 5\n  Number of incircle tests: 7\n  Number of 2D orientation tests: 20\n"
    stats = parse_triangle_statistics(text)
    assert stats == {"mesh_triangles": 5, "incircle_tests": 7, "orient_tests_printed": 20, "circumcenters": 0,
                     "orient_tests": 15}
    assert parse_triangle_statistics("nothing here") == {}


def test_switches_for_triangle_and_cgal():
    assert triangle_switches("pq30a1e-4") == "pq30a0.0001"
    assert triangle_switches("pq30a0.01e") == "pq30a0.01e"
    assert triangle_switches("pqa2.5E+2") == "pqa250"
    b, s, notes = cgal_criteria("pq30a0.01")
    assert b == pytest.approx(0.25)
    assert s == pytest.approx(math.sqrt(4 * 0.01 / math.sqrt(3)))
    assert notes == []
    b, s, notes = cgal_criteria("pqDa")
    assert b == pytest.approx(math.sin(math.radians(20)) ** 2) and s == 0
    assert any("D ignored" in n for n in notes) and any("areas ignored" in n for n in notes)
    assert cgal_criteria("p")[:2] == (0.0, 0.0)


def test_flags():
    def rows(ours_t, ours_angle, tri_angle):
        return [
            Row("x", "pq30", "triangle", vertices=100, triangles=180, min_angle=tri_angle, area=1.0),
            Row("x", "pq30", "ours", "triangle", vertices=100, triangles=ours_t, min_angle=ours_angle, area=1.0),
            Row("x", "pq30", "ours", "fifo", status="error"),
            Row("x", "pq30", "cgal", vertices=200, triangles=400, min_angle=10.0, area=2.0),
        ]

    r = rows(180, 30.5, 30.1)
    flag_rows(r, "pq30")
    assert [x.flags for x in r] == [[], [], ["error"], []]
    r = rows(190, 25.0, 30.1)
    flag_rows(r, "pq30")
    assert r[1].flags == ["size", "angle"]
    r = rows(183, 25.0, 4.0)  # Triangle misses the bound too: small input angles
    flag_rows(r, "pq30")
    assert r[1].flags == []


def test_importing_keeps_the_package_compare_function():
    """The harness lives in ``instrument.study``, so importing it leaves
    ``instrument.compare`` the `triangle` package's compare(plt, A, B)."""
    import instrument.study.compare  # noqa: F401

    assert callable(instrument.compare)
    assert inspect.signature(instrument.compare) == inspect.signature(triangle.compare)


@pytest.mark.skipif(not HAS_CGAL, reason="the cgal bindings are not installed")
def test_cgal(A, rows_p):
    cgal = by_engine(rows_p)["cgal"]
    assert (cgal.status, cgal.vertices, cgal.triangles) == ("ok", 29, 29)  # the CDT, holes as seeds
    assert cgal.area == pytest.approx(0.08412736)
    assert cgal.incircle_tests is None and cgal.triangles_created is None
    rows = by_engine(compare(A, "pq30", name="A", engines=("triangle", "cgal"), repeat=1))
    cgal = rows["cgal"]
    assert cgal.status == "ok", cgal.note
    assert cgal.min_angle >= 30 - 1e-6
    assert cgal.triangles > 29 and cgal.area == pytest.approx(0.08412736)
    assert cgal.time_ratio > 0


def test_command_writes_markdown_and_csv_through_the_embedded_cluster(tmp_path):
    """``python -m instrument.study.compare``, the default way: a sweep on an
    embedded Dask cluster, then the tables; ``--dataset`` keeps the rows."""
    md, table, data = tmp_path / "out.md", tmp_path / "out.csv", tmp_path / "rows"
    proc = subprocess.run(
        [sys.executable, "-m", "instrument.study.compare", str(TRIANGLE_DATA / "A.poly"), "--switches", "p",
         "--repeat", "1", "--workers", "2", "--markdown", str(md), "--csv", str(table), "--dataset", str(data)],
        check=False, capture_output=True, text=True, timeout=300, cwd=tmp_path,
    )
    assert proc.returncode == 0, proc.stderr
    assert "A.poly" in proc.stdout
    text = md.read_text()
    # a sample of the triangle package is labelled triangle/<name>
    assert text.startswith("# ruppert vs Triangle vs CGAL Mesh_2") and "| triangle/A.poly | p | triangle | ok |" in text
    with table.open() as f:
        rows = list(csv.DictReader(f))
    assert list(rows[0]) == list(COLUMNS)
    engines = {r["engine"]: r for r in rows}
    assert engines["triangle"]["triangles"] == "29" and engines["ours"]["triangles"] == "29"
    assert int(engines["triangle"]["incircle_tests"]) > 0
    assert list(data.glob("part-*.parquet"))


def test_script_is_a_thin_shell():
    proc = subprocess.run([sys.executable, str(ROOT / "scripts" / "compare.py"), "--help"], check=False,
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0 and "--scheduler" in proc.stdout and "--corpus" in proc.stdout
