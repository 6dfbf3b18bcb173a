"""``python -m instrument.study.quadratic``: one small run end to end, and its parts."""

from __future__ import annotations

import csv
import json
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
import triangle

from instrument import quadratic
from instrument.study.inputs import script_points
from instrument.study.quadratic import cli, fit, runs, tables

ROOT = Path(__file__).resolve().parents[2]


def test_small_run_writes_every_output(tmp_path):
    argv = ["--max-n", "200", "--strategy-max-n", "200", "--sweep-max-n", "100", "--alphas", "20,30",
            "--strategies", "triangle,worst-angle,smallest", "--repeat", "1", "--scan-max-n", "14",
            "--out", str(tmp_path), "--sequential", "--dataset", str(tmp_path / "runs")]
    assert cli.main(argv) == 0
    for name in ("results.md", "README-section.md", "replay.csv", "runs.csv", "slopes.csv", "summary.json"):
        assert (tmp_path / name).stat().st_size > 0
    for name in ("work", "broom", "steps", "orders"):
        for ext in ("png", "svg"):
            assert (tmp_path / f"{name}.{ext}").stat().st_size > 0
    rows = list(csv.DictReader((tmp_path / "runs.csv").open()))
    assert {(r["engine"], r["strategy"]) for r in rows} >= {("replay", "triangle"), ("triangle", ""), ("ours", "smallest")}
    assert all(r["status"] == "ok" for r in rows)
    for r in rows:
        if r["engine"] == "replay":
            n, alpha = int(r["n"]), float(r["alpha"])
            assert int(r["scripted_created"]) >= quadratic.theorem3_bound(n, alpha)
            assert int(r["steps"]) == quadratic.steps(n, alpha)
        if r["engine"] == "ours" and r["strategy"] == "smallest" and r["alpha"] == "20.0":
            assert int(r["script_points"]) == quadratic.steps(int(r["n"]))  # it plays the script
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["least_work"]["strategy"] in ("triangle", "worst-angle")
    assert "| 200 | 2 | 204 |" in (tmp_path / "README-section.md").read_text()
    assert "python -m instrument.study.quadratic" in (tmp_path / "results.md").read_text()


def test_script_points_counts_the_scripted_vertices():
    n = 100
    res = quadratic.replay(n, then=None)
    assert script_points(res["vertices"], n, 20.0) == quadratic.steps(n)
    assert script_points(res["vertices"][: n + 12], n, 20.0) == 0
    assert script_points(triangle.triangulate(quadratic.example(n), "pq20")["vertices"], n, 20.0) == quadratic.steps(n)


def test_fit_slope_and_ranges():
    ns = [100, 200, 400, 800]
    assert fit.fit_slope(ns, [3 * n * n for n in ns]) == pytest.approx(2.0)
    assert fit.fit_slope(ns, [5 * n for n in ns]) == pytest.approx(1.0)
    assert fit.fit_slope([100], [1]) is None
    assert tables.ranges([1, 2, 3, 7, 9, 10]) == "1–3, 7, 9–10"
    assert runs.sizes(1000) == [100, 200, 400, 800]


def test_timeout_and_error_are_reported():
    status, note = runs.isolated(time.sleep, (60,), 0.5)
    assert status == "timeout" and "killed" in note
    status, note = runs.isolated(np.log, ("x",), 10)
    assert status == "error"


def test_cgal_runs_are_left_out_without_its_bindings(monkeypatch, capsys):
    monkeypatch.setattr(cli, "has_cgal", lambda: False)
    assert cli.parse_args(["--quick"]).no_cgal
    assert "not installed" in capsys.readouterr().out


def test_module_and_script_answer_help():
    for cmd in ([sys.executable, "-m", "instrument.study.quadratic", "--help"],
                [sys.executable, str(ROOT / "scripts" / "quadratic.py"), "--help"]):
        proc = subprocess.run(cmd, check=False, capture_output=True, text=True, timeout=120)
        assert proc.returncode == 0 and "--scheduler" in proc.stdout, proc.stderr
    assert "docs/quadratic" in proc.stdout  # the script's default output directory
