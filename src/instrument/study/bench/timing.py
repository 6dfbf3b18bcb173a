"""The in-process workloads: every engine on the same input, interleaved, best of the rounds.

Every engine runs on the same input in one process; each round runs ours,
then Triangle, then CGAL, and the best of ``repeat`` rounds counts.  Loading
our compiled kernels is not timed (each engine runs once on a tiny input
first, with the same switches and strategy).  Our engine always counts its
work; its counters (triangles created, incircle tests) go next to Triangle's
statistics, which come from one extra untimed run of Triangle with ``V``.

Only one input and at most one engine's output are alive at a time: each
output is counted and dropped before the next engine runs, and the input is
dropped before the peak-memory processes start (each of which makes its own),
which is what lets dt-1e7 run in a few GB.
"""

from __future__ import annotations

import gc
import math
import os

from . import engines
from .memory import engine_peak_mb
from .workloads import WORKLOADS, Workload

#: our counters shown beside Triangle's statistics
OUR_COUNTERS = ("triangles_created", "incircle_tests", "orient_tests", "circumcenters")
TRIANGLE_COUNTERS = ("incircle_tests", "orient_tests", "circumcenters")


def new_row(name: str, w: Workload, strategy: str, threads: int | None = None) -> dict:
    return {
        "workload": name,
        "input": w.label,
        "switches": w.opts,
        "strategy": strategy,
        "threads": threads,
        "load_avg": list(os.getloadavg()),  # the 1, 5 and 15-minute load averages when the row is begun
        "triangles": {},
        "ours_s": None,
        "triangle_s": None,
        "cgal_s": None,
        "ratio": None,  # ours / Triangle
        "cgal_ratio": None,  # ours / CGAL
        "goal": w.goal,
        "sweep": w.sweep,  # one row per strategy: the goal is the least-work row's
        "goal_met": None,
        "work": {},
        "note": "",
    }


def available_strategies() -> list[str]:
    from ..ours_engine import available_strategies as names

    return names()


def bench_in_process(name: str, repeat: int, memory: bool, *, strategies: list[str] | None = None,
                     cgal: bool = True, stats: bool = True, timeout: float = 60.0,
                     threads: int | None = None) -> list[dict]:
    """Time one in-process workload; one row per strategy of ours.

    On a strategy workload (``sweep``) with ``timeout > 0`` each of our runs
    happens in a process of its own (``instrument.study.ours_engine.run_ours_isolated``,
    timed inside the child like an in-process run) that is killed after
    ``timeout`` seconds; a strategy that times out is not run again."""
    from ..cgal_engine import has_cgal

    w = WORKLOADS[name]
    load = list(os.getloadavg())  # as the workload begins
    strategies = (strategies or available_strategies()) if w.sweep else ["triangle"]
    isolated = w.sweep and timeout > 0
    cgal = cgal and w.cgal and has_cgal()
    engine_list = [("ours", s) for s in strategies] + [("triangle", "")] + ([("cgal", "")] if cgal else [])
    for engine, strategy in engine_list:
        engines.warm_up(engine, w.opts, strategy or "triangle", threads)
    data = w.make()
    best = {e: math.inf for e in engine_list}
    size: dict = {}
    work: dict = {}
    failed: dict = {}
    for k in range(repeat):
        for e in engine_list:
            engine, strategy = e
            if e in failed:
                continue
            gc.collect()
            if engine == "ours" and isolated:
                from ..ours_engine import EngineTimeout, run_ours_isolated

                try:
                    out, counts, wall = run_ours_isolated(data, w.opts, strategy, repeat=1, timeout=timeout,
                                                          threads=threads)
                except EngineTimeout:
                    failed[e] = f"timeout: killed after {timeout:g} s"
                    continue
                best[e] = min(best[e], wall)
                size[e], work[e] = len(out.get("triangles", ())), counts
                del out
                continue
            call = engines.run_once(engine, data, w.opts, strategy or "triangle", threads)
            best[e] = min(best[e], call.wall_s)
            if engine != "cgal" or k == repeat - 1:  # CGAL's count iterates in Python: once
                size[e] = call.triangles()
            if engine == "ours":
                work[e] = call.work
            del call
    tri_stats = {}
    if stats:
        from ..triangle_engine import triangle_statistics

        gc.collect()
        tri_stats = triangle_statistics(data, w.opts)[1]
    del data
    gc.collect()
    mem, mem_failed = {}, {}
    if memory:
        for e in engine_list:
            if best[e] == math.inf:
                continue
            try:
                mem[e] = engine_peak_mb(name, e[0], e[1] or "triangle", threads if e[0] == "ours" else None,
                                        time_limit=timeout if isolated else None)
            except RuntimeError as exc:
                mem_failed[e] = str(exc)
    rows = []
    tri_e, cgal_e = ("triangle", ""), ("cgal", "")
    tri_s = best[tri_e]
    for s in strategies:
        e = ("ours", s)
        row = new_row(name, w, s, threads)
        row["load_avg"] = load
        row["triangles"] = {"ours": size.get(e), "triangle": size[tri_e]}
        row["triangle_s"] = tri_s
        if cgal:
            row["triangles"]["cgal"] = size[cgal_e]
            row["cgal_s"] = best[cgal_e]
        if best[e] == math.inf:  # not one round finished
            row["note"] = failed[e]
            rows.append(row)
            continue
        if e in failed:
            row["note"] = f"a later round: {failed[e]}"
        row["ours_s"], row["ratio"] = best[e], best[e] / tri_s
        if cgal:
            row["cgal_ratio"] = best[e] / best[cgal_e]
        row["work"] = {
            "ours": {c: work[e].get(c) for c in OUR_COUNTERS},
            "triangle": {c: tri_stats[c] for c in TRIANGLE_COUNTERS if c in tri_stats},
        }
        if memory:
            row["ours_mb"] = mem.get(e)
            row["triangle_mb"] = mem.get(tri_e)
            if row["ours_mb"] is not None and row["triangle_mb"]:
                row["memory_ratio"] = row["ours_mb"] / row["triangle_mb"]
            if cgal:
                row["cgal_mb"] = mem.get(cgal_e)
            problems = [f"{'/'.join(x for x in k if x)} memory: {v}" for k, v in mem_failed.items()
                        if k in (e, tri_e, cgal_e)]
            if problems:
                row["note"] = "; ".join(([row["note"]] if row["note"] else []) + problems)
        rows.append(row)
    mark_goals(w, rows)
    return rows


def mark_goals(w: Workload, rows: list[dict]) -> None:
    """Whether each row meets the workload's goal (a strategy workload: only
    the least-work strategy's row, the one with the fewest triangles created)."""
    if w.goal is None:
        return
    done = [r for r in rows if r["ours_s"] is not None]
    if w.sweep and done:
        least = min(done, key=lambda r: (r["work"]["ours"]["triangles_created"], r["ours_s"]))
        least["least_work"] = True
        least["goal_met"] = least["ratio"] <= w.goal
    else:
        for row in done:
            row["goal_met"] = row["ratio"] <= w.goal
