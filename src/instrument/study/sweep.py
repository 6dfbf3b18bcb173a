"""A grid of inputs x switches x strategies x engines, run as tasks on dask.distributed.

    python -m instrument.study.sweep samples corpus/ --switches pq20,pq30 --strategies all \\
        --engines ours,triangle --dataset results/
    python -m instrument.study.sweep quadratic:n=100,200,400:alpha=20,30 --switches 'pq{alpha}' --dataset quad/
    python -m instrument.study.sweep ... --scheduler tcp://HOST:8786          # an existing cluster
    python -m instrument.study.sweep summary results/                          # tables and plots from a dataset

By default the tasks run on an embedded ``LocalCluster`` (process workers, one
per core, one thread each); ``--scheduler ADDRESS`` uses an existing cluster
instead, ``--workers N`` sets the embedded cluster's size, and ``--sequential``
runs the tasks one after the other in this process (no Dask), with the same
isolation.

Every task runs its engine in a separate process with a time limit and a
memory limit (``instrument.study.isolate`` says why and how): a task that
hangs becomes a ``timeout`` row, one that kills its process (Triangle
segfaults on some inputs) a ``crash`` row, one that outgrows its memory a
``memory`` row, and the sweep goes on.

Rows go to a Parquet dataset (``instrument.study.dataset``: the schema and
the row key) as they finish; running the same sweep again skips the rows
already there (``--redo timeout,crash`` runs those statuses again).  Sizes
of a generated family (I(n) for several n) form a series run smallest first:
after a size that did not finish, the larger ones are ``skipped``.  At the
end, ``summary`` tables and plots are written from the dataset.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import logging
import multiprocessing
import os
import sys
import time
from collections import Counter
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import dataset, engines, inputs, isolate, tasks
from .inputs import Input
from .isolate import describe
from .tasks import GiB, Task

DEFAULT_TIME_LIMIT = 600.0
DEFAULT_MEMORY_LIMIT = 4 * GiB
FLUSH_S = 1.0


class SweepError(RuntimeError):
    """A sweep that cannot start (no inputs, a cluster whose workers cannot isolate tasks)."""


@dataclass
class Grid:
    """The tasks of a sweep, the data of its inputs, and what was read."""

    tasks: list[Task] = field(default_factory=list)
    data: dict[str, dict] = field(default_factory=dict)  # input id -> PSLG
    catalog: list[dict] = field(default_factory=list)

    def add_input(self, inp: Input) -> dict | None:
        """Read ``inp``: its PSLG, or None (recorded as unreadable)."""
        entry = {"label": inp.label, "family": inp.family, "source": inp.source, "digest": inp.digest}
        try:
            data = inputs.load(inp)
        except Exception as exc:  # noqa: BLE001  (FormatError, OSError, ...: listed, not run)
            self.catalog.append({**entry, "status": "unreadable", "reason": describe(exc)})
            return None
        self.catalog.append({**entry, "status": "ok", **inputs.counts(data)})
        self.data[input_id(inp)] = data
        return data


def input_id(inp: Input) -> str:
    return f"{inp.label}\0{inp.digest}"


def grid(chosen: Iterable[Input], switches: Sequence[str], *, engine_names: Sequence[str] = ("ours", "triangle"),
         strategies: Sequence[str] = ("triangle",), seed: int = 0, repeat: int = 1,
         time_limit: float | None = DEFAULT_TIME_LIMIT, memory_limit: int = DEFAULT_MEMORY_LIMIT,
         keep_mesh: bool = False) -> Grid:
    """The Cartesian grid: every input x switches x engine (x strategy, for the
    engines that have strategies).  Switches with ``{name}`` take the input's
    parameter and skip inputs without it; a point set loses ``p``."""
    g = Grid()
    for inp in chosen:
        data = g.add_input(inp)
        if data is None:
            continue
        c = inputs.counts(data)
        for template in switches:
            sw = inputs.switches_for(template, inp)
            if sw is None:
                continue
            ran, note = inputs.effective_switches(data, sw)
            for engine in engine_names:
                for strategy in (strategies if engines.uses_strategies(engine) else [""]):
                    series, order = "", 0.0
                    params = inp.param_dict
                    if "n" in params:  # a family's sizes: one series per everything else
                        rest = {k: v for k, v in params.items() if k != "n"}
                        series = json.dumps([inp.family, sorted(rest.items()), template, engine, strategy])
                        order = float(params["n"])
                    g.tasks.append(Task(inp, sw, engine, strategy, ran_switches=ran, seed=seed, repeat=repeat,
                                        time_limit=time_limit, memory_limit=memory_limit, keep_mesh=keep_mesh,
                                        series=series, order=order, input_counts=(c["vertices"], c["segments"]),
                                        note=note))
    return g


# ---------------------------------------------------------------------------------------------
# what runs next


class Plan:
    """Which tasks run, in which order: the ones not in the dataset yet, each
    series smallest first and cut after a size that did not finish."""

    def __init__(self, all_tasks: Iterable[Task], existing: dict[str, str], redo: Iterable[str] = ()):
        self.existing = dict(existing)
        self.final = set(dataset.FINAL) - set(redo)
        self.ready: list[Task] = []
        self.skipped: list[dict] = []  # rows to record before anything runs
        self.already = 0
        self._series: dict[str, list[Task]] = {}
        for t in all_tasks:
            if t.series:
                self._series.setdefault(t.series, []).append(t)
            elif self.done(t):
                self.already += 1
            else:
                self.ready.append(t)
        for chain in self._series.values():
            chain.sort(key=lambda t: t.order)
            nxt, skipped = self._advance(chain, 0)
            self.ready += [nxt] if nxt is not None else []
            self.skipped += skipped

    def done(self, t: Task) -> bool:
        return self.existing.get(t.key) in self.final

    def _advance(self, chain: list[Task], i: int) -> tuple[Task | None, list[dict]]:
        """From position ``i`` of a series: pass what is done; the next task to
        run, or the rows of the sizes skipped after one that did not finish."""
        while i < len(chain) and self.done(chain[i]):
            self.already += 1
            if self.existing[chain[i].key] != "ok":
                return None, self._skip(chain[i + 1:], chain[i])
            i += 1
        return (chain[i] if i < len(chain) else None), []

    def _skip(self, rest: list[Task], failed: Task) -> list[dict]:
        why = f"{self.existing.get(failed.key)} at {failed.input.label}"
        rows = []
        for t in rest:
            if self.done(t):
                self.already += 1
            elif self.existing.get(t.key) != "skipped":
                rows.append(tasks.skipped_row(t, why))
        return rows

    def after(self, task: Task, status: str) -> tuple[Task | None, list[dict]]:
        """Once ``task`` ended with ``status``: the next task of its series, and rows to record as skipped."""
        if not task.series:
            return None, []
        self.existing[task.key] = status
        chain = self._series[task.series]
        i = chain.index(task)
        if status != "ok":
            return None, self._skip(chain[i + 1:], task)
        return self._advance(chain, i + 1)


# ---------------------------------------------------------------------------------------------
# writing rows as they finish


class Writer:
    """Buffers rows and appends them to the dataset about once a second."""

    def __init__(self, path: Path):
        self.path = Path(path)
        self.buffer: list[dict] = []
        self.last = time.monotonic()
        self.written = 0

    def add(self, row: dict) -> None:
        mesh = row.pop("mesh", None)
        if mesh is not None:
            f = dataset.mesh_path(self.path, row["key"])
            f.parent.mkdir(parents=True, exist_ok=True)
            np.savez_compressed(f, **mesh)
        self.buffer.append(dataset.normalized(row))
        if time.monotonic() - self.last >= FLUSH_S:
            self.flush()

    def flush(self) -> None:
        if self.buffer:
            dataset.append(self.path, self.buffer)
            self.written += len(self.buffer)
            self.buffer = []
        self.last = time.monotonic()


# ---------------------------------------------------------------------------------------------
# running


def _is_daemonic() -> bool:
    return multiprocessing.current_process().daemon


@contextlib.contextmanager
def connect(scheduler: str | None = None, workers: int | None = None):
    """A Dask client: of the cluster at ``scheduler``, or of an embedded
    ``LocalCluster`` with ``workers`` process workers (default: one per core)."""
    import dask
    from distributed import Client, LocalCluster

    if scheduler:
        with Client(scheduler) as client:
            daemonic = [w for w, d in client.run(_is_daemonic).items() if d]
            if daemonic:
                raise SweepError(
                    f"{len(daemonic)} worker(s) of {scheduler} are daemonic processes, which cannot start the "
                    "engine's isolated process: start them with DASK_DISTRIBUTED__WORKER__DAEMON=False"
                )
            yield client  # the workers keep their engines' processes, warm, for the next sweep
        return
    dask.config.set({"distributed.worker.daemon": False})  # global: a restarted worker reads it again
    n = workers or os.cpu_count() or 1
    with LocalCluster(n_workers=n, threads_per_worker=1, processes=True, dashboard_address=":0",
                      silence_logs=logging.ERROR) as cluster, Client(cluster) as client:
        try:
            yield client
        finally:
            client.run(isolate.shutdown)  # the engines' processes end before their workers do


class Progress:
    """A progress bar (rich) with the count of each status, or nothing."""

    def __init__(self, total: int, enabled: bool):
        self.counts: Counter = Counter()
        self.bar = None
        if enabled and total:
            from rich.console import Console
            from rich.progress import BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn

            self.bar = Progress(TextColumn("sweep"), BarColumn(), MofNCompleteColumn(), TimeElapsedColumn(),
                                TextColumn("{task.description}"), console=Console(stderr=True))
            self.task = self.bar.add_task("", total=total)
            self.bar.start()

    def add(self, row: dict) -> None:
        self.counts[row["status"]] += 1
        if self.bar is not None:
            text = "  ".join(f"{k} {v}" for k, v in sorted(self.counts.items()))
            self.bar.update(self.task, advance=1, description=text)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.stop()


@dataclass
class Outcome:
    """What one run of a sweep did."""

    ran: int = 0
    skipped: int = 0
    already: int = 0
    statuses: Counter = field(default_factory=Counter)
    wall_s: float = 0.0


def run(g: Grid, path: Path, *, scheduler: str | None = None, workers: int | None = None, sequential: bool = False,
        redo: Iterable[str] = (), progress: bool = False, on_row: Callable[[dict], None] | None = None) -> Outcome:
    """Run the tasks of ``g`` that ``path`` does not hold yet; rows go to ``path`` as they finish."""
    t0 = time.perf_counter()
    path = Path(path)
    dataset.write_inputs(path, g.catalog)
    plan = Plan(g.tasks, dataset.statuses(path), redo)
    out = Outcome(already=plan.already)
    writer = Writer(path)
    bar = Progress(sum(not plan.done(t) for t in g.tasks), progress)

    def record(row: dict) -> None:
        writer.add(row)  # takes the mesh out
        row = dataset.normalized(row)
        out.statuses[row["status"]] += 1
        if row["status"] == "skipped":
            out.skipped += 1
        else:
            out.ran += 1
        bar.add(row)
        if on_row is not None:
            on_row(row)

    try:
        for row in plan.skipped:
            record(row)
        if sequential:
            _run_here(g, plan, record)
        elif plan.ready:
            _run_on_dask(g, plan, record, scheduler, workers)
    finally:
        writer.flush()
        bar.close()
    dataset.compact(path)
    out.wall_s = time.perf_counter() - t0
    return out


def _followers(plan: Plan, task: Task, row: dict, record) -> Task | None:
    nxt, skipped = plan.after(task, row["status"])
    for s in skipped:
        record(s)
    return nxt


def _run_here(g: Grid, plan: Plan, record) -> None:
    queue = list(plan.ready)
    while queue:
        task = queue.pop(0)
        row = tasks.execute(task, g.data[input_id(task.input)])
        record(row)
        nxt = _followers(plan, task, row, record)
        if nxt is not None:
            queue.append(nxt)


def _run_on_dask(g: Grid, plan: Plan, record, scheduler: str | None, workers: int | None) -> None:
    from distributed import KilledWorker, as_completed

    with connect(scheduler, workers) as client:
        shared: dict[str, object] = {}
        pending: dict = {}
        done = as_completed()

        def submit(task: Task) -> None:
            iid = input_id(task.input)
            if iid not in shared:
                shared[iid] = client.scatter([g.data[iid]], hash=False)[0]  # one object: a dict would be scattered per key
            fut = client.submit(tasks.execute, task, shared[iid], pure=False, retries=0,
                                key=f"ruppert-{task.key}-{time.time_ns()}")
            pending[fut.key] = task
            done.add(fut)

        for task in plan.ready:
            submit(task)
        for fut in done:
            task = pending.pop(fut.key)
            try:
                row = fut.result()
            except KilledWorker as exc:  # the worker itself died: the isolation did not hold
                row = {**tasks.base_row(task), "status": "crash", "message": describe(exc)}
            except Exception as exc:  # noqa: BLE001  (a failure of the task's own code: a row)
                row = {**tasks.base_row(task), "status": "error", "message": describe(exc)}
            record(row)
            nxt = _followers(plan, task, row, record)
            if nxt is not None:
                submit(nxt)


# ---------------------------------------------------------------------------------------------
# command line


def add_cluster_options(ap: argparse.ArgumentParser) -> None:
    """The options of where tasks run and their limits (shared by compare and quadratic)."""
    g = ap.add_argument_group("where the tasks run")
    g.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler (default: an embedded LocalCluster)")
    g.add_argument("--workers", type=int, help="process workers of the embedded cluster (default: one per core)")
    g.add_argument("--sequential", action="store_true", help="no Dask: one task after the other in this process")
    g.add_argument("--memory-limit", default="4GiB", help="address-space limit of each task's engine process (default 4GiB; 0: none)")


def memory_bytes(text: str) -> int:
    from dask.utils import parse_bytes

    return 0 if text.strip() in ("0", "none") else int(parse_bytes(text))


def _run_cli(argv: list[str]) -> int:
    from .ours_engine import available_strategies

    ap = argparse.ArgumentParser(prog="python -m instrument.study.sweep", description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("inputs", nargs="+", help="files, folders, 'samples' (the triangle package's), "
                    "or families such as quadratic:n=100,200:alpha=20,30")
    ap.add_argument("--switches", default="pq30", help="comma list of switch strings (default pq30; {alpha} takes a family's angle)")
    ap.add_argument("--strategies", default="all", help="our strategies: all (default) or a comma list")
    ap.add_argument("--engines", default="ours,triangle",
                    help=f"comma list of {', '.join(engines.ENGINES)} or module:function (default ours,triangle)")
    ap.add_argument("--dataset", type=Path, default=Path("ruppert-sweep"), help="the Parquet dataset (default ./ruppert-sweep)")
    ap.add_argument("--time-limit", type=float, default=DEFAULT_TIME_LIMIT, help="seconds per task (default 600; 0: none)")
    ap.add_argument("--repeat", type=int, default=1, help="timed runs per task, the best counts (default 1)")
    ap.add_argument("--seed", type=int, default=0, help="seed of our engine (random strategy)")
    ap.add_argument("--redo", default="", help="comma list of statuses to run again (e.g. timeout,crash)")
    ap.add_argument("--keep-meshes", action="store_true", help="store every output mesh in DATASET/meshes/")
    ap.add_argument("--no-progress", action="store_true", help="no progress bar")
    ap.add_argument("--no-summary", action="store_true", help="do not write DATASET/summary at the end")
    add_cluster_options(ap)
    args = ap.parse_args(argv)
    try:
        chosen = inputs.parse_inputs(args.inputs)
        memory = memory_bytes(args.memory_limit)
    except ValueError as exc:
        ap.error(str(exc))
    names = available_strategies()
    strategies = names if args.strategies == "all" else [s for s in args.strategies.split(",") if s]
    bad = [s for s in strategies if s not in names]
    if bad:
        ap.error(f"unknown strategies {bad}; choose from {', '.join(names)}")
    engine_names = [e for e in args.engines.split(",") if e]
    g = grid(chosen, [s for s in args.switches.split(",") if s], engine_names=engine_names, strategies=strategies,
             seed=args.seed, repeat=args.repeat, time_limit=args.time_limit or None, memory_limit=memory,
             keep_mesh=args.keep_meshes)
    if not g.tasks:
        print("Error: no tasks (no readable input, or no switches apply)", file=sys.stderr)
        return 1
    try:
        got = run(g, args.dataset, scheduler=args.scheduler, workers=args.workers, sequential=args.sequential,
                  redo=[s for s in args.redo.split(",") if s], progress=not args.no_progress)
    except SweepError as exc:
        print(f"Error: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"Interrupted: the rows that finished are in {args.dataset}; the same command resumes.", file=sys.stderr)
        return 130
    statuses = ", ".join(f"{k} {v}" for k, v in sorted(got.statuses.items())) or "nothing to run"
    print(f"{len(g.tasks)} tasks: {got.already} already in {args.dataset}, ran {got.ran}, skipped {got.skipped} "
          f"({statuses}) in {got.wall_s:.1f} s", flush=True)
    for c in g.catalog:
        if c["status"] != "ok":
            print(f"  not read: {c['label']}: {c['reason']}")
    if not args.no_summary:
        from . import summary

        out = args.dataset / "summary"
        if got.ran or not summary.is_current(args.dataset, out):
            written = summary.write(args.dataset, out)
        else:  # nothing ran and the summary already reads every part: a second run does no work
            written = [out / "summary.md"]
        print((out / "summary.md").read_text() if written else "(no rows to summarize)")
    return 0


def main(argv: list[str] | None = None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if argv and argv[0] == "summary":
        from . import summary

        return summary.main(argv[1:])
    if argv and argv[0] == "run":
        argv = argv[1:]
    return _run_cli(argv)


if __name__ == "__main__":
    sys.exit(main())
