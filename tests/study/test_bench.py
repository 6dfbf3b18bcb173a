"""The benchmark (instrument.study.bench): every part runs end to end on tiny workloads.

No timing is asserted (the machine is shared); the cold workload's plumbing
runs with an environment that installs nothing, and the real one (a fresh
venv and a pip install that compiles the engine: minutes) only when
RUPPERT_TEST_COLD=1 asks for it.
"""

from __future__ import annotations

import ctypes
import importlib.util
import json
import mmap
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("triangle")

import instrument  # noqa: E402
import ruppert_io  # noqa: E402
from instrument.check import check_mesh  # noqa: E402
from instrument.study.bench import cold, commands, memory, timing, workloads  # noqa: E402
from instrument.study.bench.main import main  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
HAS_CGAL = importlib.util.find_spec("CGAL") is not None
HAS_PEBBLE = importlib.util.find_spec("pebble") is not None
needs_pebble = pytest.mark.skipif(not HAS_PEBBLE, reason="the study extra (pebble) is not installed")


def test_workloads_and_selection():
    W = workloads.WORKLOADS
    assert {"dt-1e5", "dt-1e6", "dt-1e7", "cdt-1e5", "square-q30a1e-6", "la-q30", "quad-12800", "cli-A",
            "cold"} <= set(W)
    assert W["quad-12800"].sweep and W["cold"].cold and W["dt-1e7"].opt_in and W["cold"].opt_in
    assert workloads.triangle_data_file(W["cli-A"].command).is_file()
    assert workloads.triangle_data_file("la.poly").is_file()
    assert workloads.select(["dt"]) == ["dt-1e5", "dt-1e6"]  # a prefix never picks an opt-in workload
    assert workloads.select(["dt-1e7", "dt"]) == ["dt-1e5", "dt-1e6", "dt-1e7"]
    everything = workloads.select([])
    assert "cold" not in everything and "dt-1e7" not in everything and "cli-A" in everything
    assert workloads.select([], cold=True) == everything + ["cold"]
    assert workloads.select(["cold"]) == ["cold"]
    assert workloads.select([], everything=True) == [n for n in W if not n.endswith("-tiny")]
    with pytest.raises(ValueError, match="no workload"):
        workloads.select(["nothing-like-it"])
    big = W["dt-1e7"]
    assert big.make is not None and big.opts == ""  # (not made here: 160 MB)


def test_in_process_rows_one_round():
    for name in ("dt-tiny", "cdt-tiny", "square-tiny"):
        (row,) = timing.bench_in_process(name, 1, False, cgal=False)
        assert row["ours_s"] > 0 and row["triangle_s"] > 0
        assert row["ratio"] == pytest.approx(row["ours_s"] / row["triangle_s"])
        t = row["triangles"]
        assert t["ours"] > 0 and t["triangle"] > 0
        assert abs(t["ours"] - t["triangle"]) <= 0.1 * t["triangle"]
        assert row["work"]["ours"]["triangles_created"] >= t["ours"]
        assert row["work"]["triangle"]["incircle_tests"] > 0
        assert len(row["load_avg"]) == 3 and row["threads"] is None
    assert row["goal_met"] in (True, False)


def test_the_tiny_workloads_mesh_validly():
    """The inputs the workloads make are meshed correctly by our engine (the bench only counts)."""
    for name in ("dt-tiny", "cdt-tiny", "square-tiny", "quad-tiny"):
        w = workloads.WORKLOADS[name]
        data = w.make()
        out = instrument.triangulate(data, w.opts)
        o = w.opts
        assert check_mesh(out, pslg=data if "p" in o else None, min_angle=30.0 if "q30" in o else
                          20.0 if "q20" in o else None, max_area=0.01 if "a0.01" in o else None) == []


@needs_pebble
def test_strategy_sweep_marks_the_least_work():
    rows = timing.bench_in_process("quad-tiny", 1, False, strategies=["triangle", "fifo"], cgal=False, stats=False,
                                   timeout=60)
    assert [r["strategy"] for r in rows] == ["triangle", "fifo"]
    least = [r for r in rows if r.get("least_work")]
    assert len(least) == 1
    assert least[0]["work"]["ours"]["triangles_created"] == min(r["work"]["ours"]["triangles_created"] for r in rows)
    assert least[0]["goal_met"] in (True, False)


@needs_pebble
def test_a_strategy_cut_by_the_time_limit(monkeypatch):
    """A strategy cut in every round is a timeout row; one cut only in a later
    round keeps its best time and says so."""
    from instrument.study import ours_engine

    real = ours_engine.run_ours_isolated
    calls: dict = {}

    def cut(data, opts, strategy, **kw):
        calls[strategy] = calls.get(strategy, 0) + 1
        if strategy == "lifo" or (strategy == "fifo" and calls[strategy] > 1):
            raise ours_engine.EngineTimeout("cut")
        return real(data, opts, strategy, **kw)

    monkeypatch.setattr(ours_engine, "run_ours_isolated", cut)
    rows = timing.bench_in_process("quad-tiny", 2, False, strategies=["triangle", "fifo", "lifo"], cgal=False,
                                   stats=False, timeout=60)
    fifo, lifo = rows[1], rows[2]
    assert fifo["ours_s"] > 0 and "later round" in fifo["note"] and calls["fifo"] == 2
    assert lifo["ours_s"] is None and lifo["note"].startswith("timeout") and calls["lifo"] == 1


@pytest.mark.skipif(not HAS_CGAL, reason="no CGAL bindings")
def test_cgal_counterparts():
    from instrument.study.bench import engines

    dt = engines.run_once("cgal", workloads.uniform(200), "")
    assert 0 < dt.triangles() <= 2 * 200 and dt.wall_s > 0
    mesh = engines.run_once("cgal", workloads.unit_square(), "pq30a0.01")
    assert mesh.triangles() > 50
    (row,) = timing.bench_in_process("dt-tiny", 1, False, stats=False)
    assert row["triangles"]["cgal"] == row["triangles"]["triangle"] and row["cgal_ratio"] > 0


@needs_pebble
def test_peak_memory_in_a_fresh_process():
    ours = memory.engine_peak_mb("square-tiny", "ours")
    tri = memory.engine_peak_mb("square-tiny", "triangle")
    assert 0 <= ours < 200 and 0 <= tri < 200
    (row,) = timing.bench_in_process("dt-tiny", 1, True, cgal=False, stats=False)
    assert row["ours_mb"] is not None and row["triangle_mb"] is not None


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="VmHWM is Linux's")
def test_peak_counts_memory_freed_inside_a_c_call():
    """The high-water mark sees what a C call allocates and frees while it
    holds the GIL (a sampling thread would not)."""
    assert memory.reset_peak_rss()
    base = memory.rss_mb()
    # fresh anonymous pages, every one touched in one C call, and unmapped
    # before the mark is read.  (A 64 MB bytes object, made and freed, did
    # not raise the mark once in a full suite run whose heap was 585 MB:
    # malloc may serve it from pages already resident)
    block = mmap.mmap(-1, 64 * 2**20)
    view = (ctypes.c_char * len(block)).from_buffer(block)
    ctypes.memset(view, 1, len(block))
    del view
    block.close()
    assert memory.peak_rss_mb() - base >= 60


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="ru_maxrss in kB and exec's mark: Linux")
def test_a_command_peak_is_its_own_not_the_benchmarks(tmp_path):
    hold = bytearray(300 * 2**20)  # this process is large ...
    hold[:: 4096] = b"x" * len(hold[:: 4096])
    small = memory.run_command([sys.executable, "-c", "pass"], tmp_path, timeout=120)
    assert small.peak_mb < 150 and small.wall_s > 0  # ... and the command's peak does not include it
    del hold
    big = memory.run_command([sys.executable, "-c", "b = bytearray(200 * 2**20)"], tmp_path, timeout=120)
    assert big.peak_mb >= 200
    with pytest.raises(memory.CommandFailed, match="exited with 3"):
        memory.run_command([sys.executable, "-c", "raise SystemExit(3)"], tmp_path, timeout=120)


def test_command_workload():
    (row,) = commands.bench_command("cli-A", 1, importtime_runs=1)
    assert row["triangles"]["ours"] == row["triangles"]["triangle"] == 87
    assert row["ours_s"] > 0 and row["triangle_s"] > 0 and row["ours_mb"] > 0 and row["triangle_mb"] > 0
    assert set(row["startup"]) == {"python -c pass", "python -c 'import numpy'", "python -c 'import ruppert_io.cli'"}
    assert all(v["s"] > 0 and v["mb"] > 0 for v in row["startup"].values())
    assert "numba" not in json.dumps(row)
    paths = [item["path"] for item in row["importtime"]]
    assert ["ruppert_io.cli"] in paths
    assert all(item["cumulative_ms"] >= 5 for item in row["importtime"])


def test_each_side_of_the_command_writes_a_valid_mesh(tmp_path):
    path = commands.prepare(tmp_path, "A.poly")
    pslg = ruppert_io.read(path)
    for engine in ("ours", "triangle"):
        run, n = commands.run_side(engine, commands.this_environment(), "-pq30", path)
        assert n == 87 and run.peak_mb > 0
        mesh = ruppert_io.read(tmp_path / "A.1")  # .node, .ele and .poly
        assert len(mesh["triangles"]) == 87
        assert check_mesh(mesh, pslg=pslg, min_angle=30.0) == []


def test_parse_importtime():
    text = """import time: self [us] | cumulative | imported package
import time:       100 |        100 |     c
import time:       200 |        300 |   b
import time:        50 |         50 |   d
import time:      1000 |       1350 | a
import time:        10 |         10 | e
"""
    roots = commands.parse_importtime(text)
    assert [r.name for r in roots] == ["a", "e"]
    a = roots[0]
    assert (a.self_us, a.cumulative_us) == (1000, 1350)
    assert [c.name for c in a.children] == ["b", "d"] and [c.name for c in a.children[0].children] == ["c"]


class NoInstall:
    """The cold workload's environment, without venv or pip: this interpreter
    and its ``ruppert``; every install step takes no time."""

    def __init__(self, root, source):
        self.root, self.source = root, source

    @property
    def environment(self):
        return commands.this_environment()

    def create(self):
        return 0.0

    def install_ruppert(self):
        assert Path(self.source, "pyproject.toml").is_file()  # the copy of the checkout
        return 0.0

    def install_triangle(self):
        return 0.0


def test_cold_plumbing_without_installing(tmp_path):
    # the checkout these tests are in: under a non-editable install (CI's
    # pip install .) the package cannot find one by itself
    checkout = Path(__file__).resolve().parents[2]
    (row,) = cold.bench_cold("cold", source=str(checkout), make_environment=NoInstall, workdir=tmp_path)
    c = row["cold"]
    assert c["venv_s"] == c["install_s"] == c["triangle_install_s"] == 0.0
    for step in ("first", "second", "triangle_first", "triangle_second"):
        assert c[step]["s"] > 0 and c[step]["mb"] > 0
    assert row["triangles"] == {"ours": 87, "triangle": 87}
    assert row["ours_s"] == c["first"]["s"] and row["ours_mb"] == c["first"]["mb"]
    assert list(tmp_path.iterdir()) == []  # the temporary directory is gone
    assert set(row["startup"]) == {"python -c pass", "python -c 'import numpy'", "python -c 'import ruppert_io.cli'"}
    assert ["ruppert_io.cli"] in [item["path"] for item in row["importtime"]]
    from instrument.study.bench import report

    md = tmp_path / "cold.md"
    report.write_markdown(md, [row], {"command": "test", "provenance": "test", "machine": report.machine(),
                                      "load_start": [0, 0, 0], "load_end": [0, 0, 0]})
    text = md.read_text()
    assert "Cold start (cold)" in text and "| first run |" in text and "Start-up of cold (in the fresh venv)" in text


def test_cold_copies_the_checkout_without_build_products(tmp_path):
    if cold.checkout_root() is None:
        pytest.skip("not installed from a checkout")
    copy = Path(cold.resolve_source(None, tmp_path))
    assert (copy / "pyproject.toml").is_file() and (copy / "setup.py").is_file()
    assert (copy / "src" / "instrument" / "pipeline.py").is_file()
    assert not list(copy.rglob("*.so")) and not (copy / ".git").exists()
    assert cold.resolve_source("ruppert==0.6.0", tmp_path) == "ruppert==0.6.0"
    env = cold.clean_environ()
    assert "PYTHONPATH" not in env and env["PIP_DISABLE_PIP_VERSION_CHECK"] == "1"


@pytest.mark.skipif(os.environ.get("RUPPERT_TEST_COLD") != "1", reason="minutes: set RUPPERT_TEST_COLD=1")
@pytest.mark.timeout(3600)
def test_cold_for_real(tmp_path):
    (row,) = cold.bench_cold("cold", workdir=tmp_path)
    c = row["cold"]
    assert c["install_s"] > 0 and c["first"]["s"] > 0 and c["second"]["s"] > 0
    assert row["triangles"] == {"ours": 87, "triangle": 87}


def test_threads_is_refused_by_an_engine_without_it(capsys):
    import inspect

    if "threads" in inspect.signature(instrument.triangulate).parameters:
        pytest.skip("this engine takes threads")
    with pytest.raises(SystemExit):
        main(["dt-tiny", "--threads", "2", "--no-memory"])
    assert "takes no 'threads' argument" in capsys.readouterr().err


def test_threads_reaches_an_engine_that_takes_it(monkeypatch):
    real = instrument.triangulate
    seen = []

    def triangulate(tri, opts="", *, threads=1, **kw):  # an engine with the keyword
        seen.append(threads)
        return real(tri, opts, **kw)

    monkeypatch.setattr(instrument, "triangulate", triangulate)
    (row,) = timing.bench_in_process("dt-tiny", 1, False, cgal=False, stats=False, threads=2)
    assert row["threads"] == 2 and seen and set(seen) == {2}


def test_command_line_writes_markdown_and_json(tmp_path, capsys):
    md, js = tmp_path / "b.md", tmp_path / "b.json"
    assert main(["dt-tiny", "square-tiny", "--repeat", "1", "--no-memory", "--no-cgal", "--profile",
                 "--markdown", str(md), "--json", str(js)]) == 0
    doc = json.loads(js.read_text())
    assert [r["workload"] for r in doc["rows"]] == ["dt-tiny", "square-tiny"]
    assert doc["profiles"] and doc["profiles"][0]["stages"][0]["stage"].startswith("total")
    assert len(doc["load_start"]) == 3 and len(doc["load_end"]) == 3 and "CPUs" in doc["machine"]
    text = md.read_text()
    assert "| dt-tiny |" in text and "| square-tiny |" in text and "Where our time goes" in text
    assert "load average" in text
    assert "square-tiny" in capsys.readouterr().out


def test_bad_arguments_are_refused():
    with pytest.raises(SystemExit):
        main(["quad", "--strategies", "no-such-strategy"])
    with pytest.raises(SystemExit):
        main(["no-such-workload"])


def test_module_and_script_answer():
    for cmd in ([sys.executable, "-m", "instrument.study.bench", "--help"],
                [sys.executable, str(ROOT / "scripts" / "bench.py"), "--list"]):
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120, check=False)
        assert proc.returncode == 0, proc.stderr
        assert "cli-A" in proc.stdout and "numba" not in proc.stdout
