"""One task of a sweep: one engine (and strategy) on one input under one switch string.

``execute`` is what a Dask worker runs: it hands the engine call to its
isolated child process (``instrument.study.isolate``) with the task's time
and memory limits and turns whatever happens (a result, an exception, a
kill at the limit, a dead process) into a row of the dataset's schema.  It
never raises for what the engine does.

Tasks of one ``series`` (the same grid cell at growing sizes, such as I(n)
for n = 100, 200, ...) run in ``order``: after one that did not finish (any
status but ``ok``) the larger ones are recorded as ``skipped``.
"""

from __future__ import annotations

import functools
import os
import socket
import time
from dataclasses import dataclass, field

from . import dataset, engines, isolate
from .inputs import Input

GiB = 2**30


@dataclass(frozen=True)
class Task:
    input: Input
    switches: str  # as asked (the key's)
    engine: str
    strategy: str = ""
    ran_switches: str = ""  # as run: a point set loses p
    seed: int = 0
    repeat: int = 1
    time_limit: float | None = 600.0
    memory_limit: int = 4 * GiB
    keep_mesh: bool = False
    series: str = ""
    order: float = 0.0
    input_counts: tuple = field(default=(None, None))  # vertices, segments
    note: str = ""

    @property
    def key(self) -> str:
        return dataset.row_key(self.input.label, self.input.digest, self.switches, self.engine, self.strategy,
                               self.seed, self.repeat)

    @property
    def label(self) -> str:
        return f"{self.engine}:{self.strategy}" if self.strategy else self.engine


def base_row(task: Task) -> dict:
    """The row's fields that the task itself determines."""
    inp = task.input
    return {
        "key": task.key, "input": inp.label, "family": inp.family, "source": inp.source, "digest": inp.digest,
        "params": {k: float(v) for k, v in inp.params}, "switches": task.switches,
        "ran_switches": task.ran_switches or task.switches, "engine": task.engine, "strategy": task.strategy,
        "seed": task.seed, "repeat": task.repeat, "input_vertices": task.input_counts[0],
        "input_segments": task.input_counts[1], "note": task.note,
        "time_limit_s": task.time_limit, "memory_limit_mb": task.memory_limit / 2**20 if task.memory_limit else None,
        "series": task.series, "order": task.order, "work": {}, "metrics": {},
    }


def skipped_row(task: Task, why: str) -> dict:
    return {**base_row(task), "status": "skipped", "message": why}


@functools.cache
def versions() -> str:
    from importlib.metadata import PackageNotFoundError, version

    out = []
    for name in ("ruppert", "triangle", "cgal"):
        try:
            out.append(f"{name} {version(name)}")
        except PackageNotFoundError:
            pass
    return "; ".join(out)


def _worker_name() -> str:
    try:
        from distributed import get_worker

        return get_worker().address
    except (ImportError, ValueError):
        return f"{socket.gethostname()}:{os.getpid()}"


def execute(task: Task, data: dict) -> dict:
    """Run ``task`` on ``data`` in this process's isolated child: its row."""
    t0 = time.perf_counter()
    kw = {"strategy": task.strategy, "seed": task.seed, "repeat": task.repeat, "family": task.input.family,
          "params": task.input.param_dict, "keep_mesh": task.keep_mesh}
    got = isolate.call(engines.measure, (task.engine, data, task.ran_switches or task.switches), kw,
                       time_limit=task.time_limit, memory_limit=task.memory_limit, initializer=engines.preload)
    row = base_row(task)
    if got.status == "ok":
        value = dict(got.value)
        note = "; ".join(x for x in (task.note, value.pop("note", "")) if x)
        row.update(value, note=note, peak_mb=got.peak_mb, base_mb=got.base_mb)
    else:
        row.update(status=got.status, message=got.message)
    row["task_s"] = time.perf_counter() - t0
    row["worker"] = _worker_name()
    row["versions"] = versions()
    return row
