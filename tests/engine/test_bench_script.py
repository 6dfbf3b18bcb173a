"""scripts/bench.py: the benchmark runs end to end on small workloads (fast smoke test)."""

from __future__ import annotations

import importlib.util
import json
import sys
from pathlib import Path

import pytest

pytest.importorskip("triangle")

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def bench():
    spec = importlib.util.spec_from_file_location("bench", ROOT / "scripts" / "bench.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules["bench"] = mod  # peak_memory_mb's subprocess imports it by this name
    spec.loader.exec_module(mod)
    yield mod
    sys.modules.pop("bench", None)


@pytest.fixture
def tiny(bench, monkeypatch):
    """Small stand-ins for the real workloads, same kinds."""
    W = bench.Workload
    small = {
        "dt-tiny": W(lambda: bench.uniform(300), "", "300 points", goal=1.5),
        "cdt-tiny": W(lambda: bench.polygon_with_holes(400, holes=4), "p", "small polygon"),
        "square-tiny": W(bench.unit_square, "pq30a0.01", "unit square", goal=1.5),
        "quad-tiny": W(lambda: bench.quadratic(40), "pq20", "I(40)", goal=0.2, sweep=True),
    }
    monkeypatch.setattr(bench, "WORKLOADS", {**bench.WORKLOADS, **small})
    return small


def test_workloads_named_in_the_brief(bench):
    assert {"dt-1e5", "dt-1e6", "cdt-1e5", "square-q30a1e-6", "la-q30", "quad-12800", "cli-A"} <= set(bench.WORKLOADS)
    assert bench.WORKLOADS["quad-12800"].sweep
    assert (ROOT / bench.WORKLOADS["cli-A"].cli_file).is_file()
    assert bench.triangle_data_file("la.poly").is_file()


def test_rows_one_round(bench, tiny):
    for name in ("dt-tiny", "cdt-tiny", "square-tiny"):
        (row,) = bench.bench(name, 1, False, cgal=False)
        assert row["ours_s"] > 0 and row["triangle_s"] > 0
        assert row["ratio"] == pytest.approx(row["ours_s"] / row["triangle_s"])
        t = row["triangles"]
        assert t["ours"] > 0 and t["triangle"] > 0
        assert abs(t["ours"] - t["triangle"]) <= 0.1 * t["triangle"]
        assert row["work"]["ours"]["triangles_created"] >= t["ours"]
        assert row["work"]["triangle"]["incircle_tests"] > 0
    assert row["goal_met"] in (True, False)


def test_strategy_sweep_marks_the_least_work(bench, tiny):
    rows = bench.bench("quad-tiny", 1, False, strategies=["triangle", "fifo"], cgal=False, stats=False,
                       timeout=60)
    assert [r["strategy"] for r in rows] == ["triangle", "fifo"]
    least = [r for r in rows if r.get("least_work")]
    assert len(least) == 1
    assert least[0]["work"]["ours"]["triangles_created"] == min(r["work"]["ours"]["triangles_created"] for r in rows)
    assert least[0]["goal_met"] in (True, False)


@pytest.mark.skipif(importlib.util.find_spec("CGAL") is None, reason="no CGAL bindings")
def test_cgal_counterparts(bench):
    dt = bench.run_cgal(bench.uniform(200), "")
    assert 0 < dt.triangles() <= 2 * 200
    mesh = bench.run_cgal(bench.unit_square(), "pq30a0.01")
    assert mesh.triangles() > 50 and mesh.core_s >= 0


def test_memory_subprocess(bench):  # a fresh process sees only the real workloads: the smallest one
    assert bench.peak_memory_mb("la-q30", "ours") >= 0
    assert bench.peak_memory_mb("la-q30", "triangle") >= 0


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="VmHWM is Linux's")
def test_peak_counts_memory_freed_inside_a_c_call(bench):
    """The high-water mark sees what a C call allocates and frees while it
    holds the GIL (a sampling thread would not)."""
    assert bench.reset_peak_rss()
    base = bench.rss_mb()
    bytearray(64 * 2**20)  # touched (zeroed) and freed in one C call
    assert bench.peak_rss_mb() - base >= 60


def test_cli_workload(bench):
    (row,) = bench.bench("cli-A", 1, False)
    assert row["triangles"]["ours"] == row["triangles"]["triangle"] == 87
    assert row["ours_s"] > 0 and row["triangle_s"] > 0
    assert row["numba_floor_s"] > 0 and "numba's floor" in row["note"]


def test_command_line_writes_markdown_and_json(bench, tiny, tmp_path, capsys):
    md, js = tmp_path / "b.md", tmp_path / "b.json"
    assert bench.main(["dt-tiny", "square-tiny", "--repeat", "1", "--no-memory", "--no-cgal", "--profile",
                       "--markdown", str(md), "--json", str(js)]) == 0
    doc = json.loads(js.read_text())
    assert [r["workload"] for r in doc["rows"]] == ["dt-tiny", "square-tiny"]
    assert doc["profiles"] and doc["profiles"][0]["phases"][0]["phase"].startswith("total")
    text = md.read_text()
    assert "| dt-tiny |" in text and "| square-tiny |" in text and "Where our time goes" in text
    assert "square-tiny" in capsys.readouterr().out


def test_unknown_strategy_is_refused(bench):
    with pytest.raises(SystemExit):
        bench.main(["quad", "--strategies", "no-such-strategy"])
