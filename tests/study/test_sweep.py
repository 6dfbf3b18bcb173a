"""The sweep on a real Dask cluster: a task that hangs is cut, one that kills its
process is a row, the workers survive, and a second run does no work."""

from __future__ import annotations

import dataclasses
import logging
import os
import time
from pathlib import Path

import numpy as np
import pytest

dask = pytest.importorskip("dask")
distributed = pytest.importorskip("distributed")
triangle = pytest.importorskip("triangle")

from instrument.check import check_mesh  # noqa: E402
from instrument.study import dataset, inputs, summary, sweep  # noqa: E402

TRIANGLE_DATA = Path(triangle.__file__).parent / "data"  # Triangle's samples (not shipped here)
HANG = "study_plugin_engines:hang"


@pytest.fixture(scope="module")
def cluster():
    """A LocalCluster of 2 process workers, as ``--scheduler`` users would run one."""
    dask.config.set({"distributed.worker.daemon": False})
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0",
                                  silence_logs=logging.ERROR) as c:
        yield c


def small_grid() -> sweep.Grid:
    A = inputs.file_input(TRIANGLE_DATA / "A.poly")
    # Triangle segfaults on a NaN coordinate (deterministically, here); our engine refuses it
    nan = inputs.data_input("nan-vertex", {"vertices": np.array([[0.0, 0.0], [1, 0], [0, 1], [np.nan, 0.5]])})
    g = sweep.grid([A, nan], ["pq30"], engine_names=["ours", "triangle", HANG], strategies=["triangle"],
                   time_limit=300, keep_mesh=True)
    g.tasks = [dataclasses.replace(t, time_limit=2.0) if t.engine == HANG else t for t in g.tasks
               if not (t.engine == HANG and t.input.label == "nan-vertex")]
    return g


def test_hang_and_crash_become_rows_and_a_second_run_does_nothing(cluster, tmp_path):
    path = tmp_path / "rows"
    with distributed.Client(cluster) as client:
        before = set(client.scheduler_info()["workers"])
        got = sweep.run(small_grid(), path, scheduler=cluster.scheduler_address)
        after = set(client.scheduler_info()["workers"])
    assert before == after  # no worker died or was restarted
    assert (got.ran, got.already) == (5, 0)
    rows = {(r["input"], r["engine"]): r for r in dataset.read(path)}
    assert len(rows) == 5
    assert rows[("A.poly", HANG)]["status"] == "timeout"
    assert "killed" in rows[("A.poly", HANG)]["message"]
    crash = rows[("nan-vertex", "triangle")]
    assert crash["status"] == "crash" and "SIGSEGV" in crash["message"]
    assert rows[("nan-vertex", "ours")]["status"] == "error" and "not finite" in rows[("nan-vertex", "ours")]["message"]
    ours, tri = rows[("A.poly", "ours")], rows[("A.poly", "triangle")]
    assert ours["status"] == tri["status"] == "ok"
    assert ours["input_vertices"] == tri["input_vertices"] == 29  # each task got its own input
    assert ours["vertices"] == tri["vertices"] and ours["min_angle"] >= 30 - 1e-6
    assert ours["work"]["triangles_created"] == ours["triangles_created"] > 0
    assert tri["incircle_tests"] > 0 and tri["peak_mb"] > 0 and ours["wall_s"] > 0
    with np.load(dataset.mesh_path(path, ours["key"])) as z:
        mesh = {k: z[k] for k in z.files}
    assert check_mesh(mesh, pslg=triangle.get_data("A"), min_angle=30) == []

    files = sorted(p.name for p in path.glob("part-*.parquet"))
    again = sweep.run(small_grid(), path, scheduler=cluster.scheduler_address)
    assert (again.ran, again.skipped, again.already) == (0, 0, 5)
    assert sorted(p.name for p in path.glob("part-*.parquet")) == files  # nothing written

    redo = sweep.run(small_grid(), path, sequential=True, redo=["crash"])
    assert (redo.ran, redo.already) == (1, 4) and redo.statuses == {"crash": 1}


def quad_tasks(statuses: dict[int, str] | None = None) -> tuple[list, dict]:
    g = sweep.grid([inputs.family_input("quadratic", n=n, alpha=20.0) for n in (100, 200, 400, 800)], ["pq{alpha}"],
                   engine_names=["ours"], strategies=["smallest"])
    existing = {t.key: statuses[int(t.order)] for t in g.tasks if statuses and int(t.order) in statuses}
    return g.tasks, existing


def test_a_series_runs_smallest_first_and_stops_after_a_failure():
    tasks, _ = quad_tasks()
    assert len({t.series for t in tasks}) == 1 and all(t.switches == "pq20" for t in tasks)
    plan = sweep.Plan(tasks, {})
    assert [t.order for t in plan.ready] == [100]
    nxt, skipped = plan.after(plan.ready[0], "ok")
    assert nxt.order == 200 and skipped == []
    nxt2, skipped = plan.after(nxt, "timeout")
    assert nxt2 is None and [r["params"]["n"] for r in skipped] == [400, 800]
    assert all(r["status"] == "skipped" and "timeout at I(n=200" in r["message"] for r in skipped)

    tasks, existing = quad_tasks({100: "ok", 200: "memory", 400: "skipped", 800: "skipped"})
    plan = sweep.Plan(tasks, existing)
    assert plan.ready == [] and plan.skipped == [] and plan.already == 2  # resumed: nothing new
    plan = sweep.Plan(tasks, existing, redo=["memory"])
    assert [t.order for t in plan.ready] == [200]


def test_switch_templates_and_point_sets():
    A = inputs.file_input(TRIANGLE_DATA / "A.poly")
    quad = inputs.family_input("quadratic", n=100, alpha=30.0)
    assert inputs.switches_for("pq{alpha}", quad) == "pq30"
    assert inputs.switches_for("pq{alpha}", A) is None
    g = sweep.grid([A, quad], ["pq{alpha}", "pq25"], engine_names=["triangle"])
    assert sorted((t.input.label, t.switches) for t in g.tasks) == [
        ("A.poly", "pq25"), ("I(n=100,alpha=30)", "pq25"), ("I(n=100,alpha=30)", "pq30")]
    dots = inputs.data_input("dots", {"vertices": np.array([[0.0, 0], [1, 0], [0, 1], [1, 1.2]])})
    (t,) = sweep.grid([dots], ["pq30"], engine_names=["triangle"]).tasks
    assert (t.switches, t.ran_switches, t.note) == ("pq30", "q30", "point set: p dropped")


def test_unreadable_inputs_are_listed_not_run(tmp_path):
    bad = tmp_path / "bad.poly"
    bad.write_text("3 2 0 0\n1 0 0\n")
    g = sweep.grid([inputs.file_input(bad)], ["p"], engine_names=["triangle"])
    assert g.tasks == []
    (entry,) = g.catalog
    assert entry["status"] == "unreadable" and "bad.poly" in entry["reason"]


def fake_row(**kw) -> dict:
    base = {"key": kw["input"] + kw["engine"] + kw.get("strategy", ""), "digest": "d", "switches": "pq30",
            "strategy": "", "status": "ok", "vertices": 100, "input_vertices": 20, "triangles_created": None,
            "incircle_tests": 500, "wall_s": 0.01, "task_s": 0.5, "peak_mb": 200.0}
    return {**base, **kw}


def test_summary_reads_the_dataset(tmp_path):
    path = tmp_path / "rows"
    rows = [fake_row(input="a", engine="triangle"), fake_row(input="b", engine="triangle", vertices=200),
            fake_row(input="a", engine="ours", strategy="fifo", vertices=110, triangles_created=600),
            fake_row(input="b", engine="ours", strategy="fifo", vertices=180, triangles_created=800),
            fake_row(input="c", engine="ours", strategy="fifo", status="crash", vertices=None, message="killed by SIGSEGV")]
    dataset.append(path, rows[:2])
    dataset.append(path, rows[2:])
    dataset.write_inputs(path, [{"label": "z.poly", "digest": "", "status": "unreadable", "reason": "FormatError: x"}])
    written = summary.write(path, tmp_path / "out")
    assert {p.name for p in written} == {"summary.md", "summary.csv", "rows.csv", "work-per-vertex.png",
                                         "sizes-vs-triangle.png"}
    agg = {a["engine"]: a for a in summary.aggregate(dataset.read(path))}
    fifo = agg["ours:fifo"]
    assert (fifo["rows"], fifo["ok"], fifo["crash"]) == (3, 2, 1)
    assert fifo["created/vertex"] == pytest.approx((600 / 110 + 800 / 180) / 2)
    assert fifo["vertices/Triangle's"] == pytest.approx((110 / 100 + 180 / 200) / 2)
    assert agg["triangle"]["vertices/Triangle's"] == 1
    text = (tmp_path / "out" / "summary.md").read_text()
    assert "| pq30 | ours:fifo | 3 | 2 | 1 |" in text
    assert "killed by SIGSEGV" in text and "`z.poly`: FormatError: x" in text

    # a second run with nothing new leaves the summary alone; a new part or input makes it stale
    assert summary.is_current(path, tmp_path / "out")
    dataset.write_inputs(path, [{"label": "z.poly", "digest": "", "status": "unreadable", "reason": "FormatError: x"}])
    assert summary.is_current(path, tmp_path / "out")  # the same catalog: inputs.json untouched
    later = time.time() + 5
    dataset.append(path, [fake_row(input="d", engine="triangle")])
    for part in dataset.parts(path):
        os.utime(part, (later, later))
    assert not summary.is_current(path, tmp_path / "out")


def test_newest_row_of_a_key_wins_and_compact_keeps_it(tmp_path):
    path = tmp_path / "rows"
    dataset.append(path, [fake_row(input="a", engine="ours", status="timeout")])
    dataset.append(path, [fake_row(input="a", engine="ours", status="ok")])
    assert [r["status"] for r in dataset.read(path)] == ["ok"]
    assert dataset.statuses(path) == {"aours": "ok"}
    dataset.compact(path)
    assert len(dataset.parts(path)) == 1 and [r["status"] for r in dataset.read(path)] == ["ok"]


def test_summary_command_on_an_empty_folder_is_one_error_line(tmp_path, capsys):
    assert sweep.main(["summary", str(tmp_path)]) == 1
    assert capsys.readouterr().err.startswith("Error:")


def test_memory_limit_makes_a_memory_outcome():
    from instrument.study import isolate

    got = isolate.call(np.ones, ((400_000_000,),), memory_limit=1024 * 2**20)  # 3.2 GB under a 1 GiB limit
    assert got.status == "memory" and "MemoryError" in got.message
    assert isolate.call(np.ones, ((1000,),), memory_limit=1024 * 2**20).status == "ok"  # the next call is fine


def test_a_cluster_of_daemonic_workers_is_refused(tmp_path):
    with dask.config.set({"distributed.worker.daemon": True}), \
            distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=":0",
                                     silence_logs=logging.ERROR) as daemonic:
        with pytest.raises(sweep.SweepError, match="DASK_DISTRIBUTED__WORKER__DAEMON=False"):
            sweep.run(small_grid(), tmp_path / "rows", scheduler=daemonic.scheduler_address)
