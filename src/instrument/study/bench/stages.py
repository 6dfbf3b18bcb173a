"""``--profile``: where our time goes on one workload, stage by stage.

Compiled kernels are opaque to cProfile, so the pipeline's stages are timed
by wrapping the module attributes ``instrument.triangulate`` calls them
through, for the duration of the profiled runs only (a name a later engine
no longer has is skipped).  Each stage's time is exclusive: a wrapped call
inside another counts once.
"""

from __future__ import annotations

import gc
import importlib
import math
import time

from .engines import warm_up
from .workloads import WORKLOADS

STAGES = {
    # module attribute -> stage
    ("instrument.pipeline", "validate"): "validate input (Python)",
    ("instrument.pipeline", "delaunay"): "Delaunay triangulation (sort + kernel)",
    ("instrument.pipeline", "clean_segments"): "clean segments (Python)",
    ("instrument.pipeline", "recover_segments"): "segment recovery (kernel)",
    ("instrument.pipeline", "carve"): "holes, concavities, regions",
    ("instrument.pipeline", "enclose_hull"): "enclose hull",
    ("instrument.pipeline", "mark_hull_vertices"): "mark hull vertices",
    ("instrument.refine", "new_refiner"): "refinement setup (allocate arrays)",
    ("instrument.refine", "build_vertex_edges"): "refinement setup (vertex -> edge map kernel)",
    ("instrument.refine", "tally_encroached"): "refinement setup (encroached subsegments kernel)",
    ("instrument.refine", "refine"): "refinement kernel",
    ("instrument.refine", "grow_refiner"): "refinement: growing arrays",
    ("instrument.pipeline", "assemble"): "output assembly",
}


def profile(name: str, strategy: str = "triangle", repeat: int = 3,
            threads: int | None = None) -> list[tuple[str, float, int]]:
    """Stages of ``instrument.triangulate`` on one workload, best of ``repeat``
    runs: [(stage, seconds, calls)], the total first, then each stage, then
    what no wrapper saw."""
    import instrument

    from ..ours_engine import engine_options

    w = WORKLOADS[name]
    data = w.make()
    warm_up("ours", w.opts, strategy, threads)
    kw = engine_options(threads)
    spent: dict[str, float] = {}
    calls: dict[str, int] = {}
    nested = [0.0]  # time spent in wrapped calls inside the current one

    def timed(stage, fn):
        def wrapper(*a, **k):
            outer, nested[0] = nested[0], 0.0
            t0 = time.perf_counter()
            try:
                return fn(*a, **k)
            finally:
                elapsed = time.perf_counter() - t0
                spent[stage] = spent.get(stage, 0.0) + elapsed - nested[0]
                calls[stage] = calls.get(stage, 0) + 1
                nested[0] = outer + elapsed

        return wrapper

    saved = []
    for (mod, attr), stage in STAGES.items():
        m = importlib.import_module(mod)
        if hasattr(m, attr):
            saved.append((m, attr, getattr(m, attr)))
            setattr(m, attr, timed(stage, getattr(m, attr)))
    best: dict[str, float] = {}
    ncalls: dict[str, int] = {}
    try:
        for _ in range(repeat):
            spent.clear()
            calls.clear()
            gc.collect()
            t0 = time.perf_counter()
            out = instrument.triangulate(data, w.opts, strategy=strategy, **kw)
            total = time.perf_counter() - t0
            del out
            if total < best.get("total", math.inf):
                best = {"total": total, **spent}
                ncalls = dict(calls)
    finally:
        for m, attr, fn in saved:
            setattr(m, attr, fn)
    total = best.pop("total")
    rows = [("total (instrument.triangulate)", total, 1)]
    rows += [(p, s, ncalls.get(p, 0)) for p, s in best.items()]
    rows.append(("other (unwrapped Python)", total - sum(best.values()), 0))
    return rows
