"""The engines the study runs, behind one interface, and what is measured on their output.

    python -m instrument.study.engines data/bracket.poly --switches pq30 --engines ours,triangle
    python -m instrument.study.engines samples --strategies all --time-limit 60

An engine is a function ``fn(data, switches, *, strategy, seed, repeat,
params) -> {"mesh", "wall_s", "work", "note"}`` (``mesh``: the output dict,
``wall_s``: best of ``repeat`` timed runs, ``work``: its counters by name).
The named ones: ``ours`` (``instrument.triangulate``, one row per strategy),
``triangle`` (the `triangle` package, with the statistics of its ``V``
switch), ``cgal`` (CGAL's Mesh_2, when the ``cgal`` bindings are installed)
and ``replay`` (Theorem 3's script on I(n), then a strategy; quadratic inputs
only).  Any other ``module:function`` names a plugin engine.

``measure`` turns one engine call into a row: status (``ok``,
``unsupported`` for switches an engine does not implement, ``unavailable``
when its package is missing, ``error``, ``memory``), output sizes, smallest and
largest angle, meshed area, the main counters and every counter, wall time.
"""

from __future__ import annotations

import argparse
import importlib
import json
import sys
from collections.abc import Mapping

import numpy as np

from .isolate import describe

ENGINES = {
    "ours": ("instrument.study.ours_engine:measure", "ruppert's engine (instrument.triangulate), per strategy"),
    "triangle": ("instrument.study.triangle_engine:measure", "Triangle 1.6 through the `triangle` package"),
    "cgal": ("instrument.study.cgal_engine:measure", "CGAL's Mesh_2 through the `cgal` bindings"),
    "replay": ("instrument.study.quadratic.replay_engine:measure",
               "Theorem 3's script on I(n) (instrument.quadratic.replay), then a strategy"),
}
#: engines whose rows differ per strategy
STRATEGY_ENGINES = ("ours", "replay")
#: the module an engine needs: without it the engine's rows are ``unavailable``
REQUIRES = {"triangle": "triangle", "cgal": "CGAL.CGAL_Mesh_2"}
#: counters with a column of their own (every counter is in ``work``)
MAIN_COUNTERS = ("triangles_created", "incircle_tests", "orient_tests", "circumcenters", "steiner_points")


def resolve(engine: str):
    """The function of a named engine or of a ``module:function`` plugin."""
    target = ENGINES[engine][0] if engine in ENGINES else engine
    module, sep, name = target.partition(":")
    if not sep:
        raise ValueError(f"unknown engine {engine!r}; choose from {', '.join(ENGINES)} or give module:function")
    return getattr(importlib.import_module(module), name)


def uses_strategies(engine: str) -> bool:
    return engine in STRATEGY_ENGINES or engine not in ENGINES


def preload() -> None:
    """Import the engines and load our compiled kernels: what a new isolated
    process does before its first task, outside the task's time limit."""
    import contextlib

    from .ours_engine import warm_up

    for module in ("triangle", "instrument"):
        with contextlib.suppress(ImportError):
            importlib.import_module(module)
    with contextlib.suppress(ImportError):
        warm_up("pq30", "triangle")


def mesh_stats(vertices, triangles) -> tuple[float | None, float | None, float | None]:
    """(smallest angle, largest angle, total area) of a triangle mesh, angles in
    degrees; ``None`` each when there are no triangles."""
    if triangles is None or len(triangles) == 0:
        return None, None, None
    xy = np.asarray(vertices, dtype=np.float64)
    t = np.asarray(triangles)[:, :3]
    p = xy[t]  # (T, 3, 2)
    e = np.roll(p, -1, axis=1) - p  # e[k] = p[k+1] - p[k]
    cross = e[:, 0, 0] * e[:, 1, 1] - e[:, 0, 1] * e[:, 1, 0]
    area = 0.5 * float(np.abs(cross).sum())
    # angle at corner k, between e[k] and -e[k-1]
    a = e
    b = -np.roll(e, 1, axis=1)
    dot = (a * b).sum(axis=2)
    crs = np.abs(a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0])
    ang = np.degrees(np.arctan2(crs, dot))
    return float(ang.min()), float(ang.max()), area


def measure(engine: str, data: dict, switches: str, *, strategy: str = "", seed: int = 0, repeat: int = 1,
            family: str = "file", params: Mapping | None = None, keep_mesh: bool = False) -> dict:
    """One engine on one input: a row (see the module's docstring).  Never raises
    for what the engine does; an engine that kills its process is the caller's
    to catch (``instrument.study.isolate``)."""
    from . import inputs

    params = dict(params or {})
    row: dict = {"status": "ok", "message": "", "note": ""}
    need = REQUIRES.get(engine)
    try:
        if need:
            importlib.import_module(need)
        fn = resolve(engine)
    except ImportError as exc:
        row.update(status="unavailable", message=describe(exc))
        return row
    try:
        got = fn(data, switches, strategy=strategy, seed=seed, repeat=repeat, params=params)
    except NotImplementedError as exc:
        row.update(status="unsupported", message=describe(exc))
        return row
    except MemoryError as exc:
        row.update(status="memory", message=describe(exc))
        return row
    except Exception as exc:  # noqa: BLE001  (Triangle's RuntimeError, a ValueError, ...: a row, not a crash)
        row.update(status="error", message=describe(exc))
        return row
    mesh = got["mesh"]
    verts, tris, segs = mesh.get("vertices"), mesh.get("triangles"), mesh.get("segments")
    row["vertices"] = 0 if verts is None else len(verts)
    row["triangles"] = 0 if tris is None else len(tris)
    row["segments"] = 0 if segs is None else len(segs)
    row["min_angle"], row["max_angle"], area = mesh_stats(verts, tris)
    row["area"] = 0.0 if area is None else area
    work = {k: int(v) for k, v in (got.get("work") or {}).items()}
    row["work"] = work
    for k in MAIN_COUNTERS:
        row[k] = work.get(k)
    row["wall_s"] = float(got["wall_s"])
    row["note"] = got.get("note", "") or ""
    row["metrics"] = inputs.metrics(family, params, mesh)
    if keep_mesh:
        row["mesh"] = {k: np.asarray(mesh[k]) for k in ("vertices", "triangles", "segments") if mesh.get(k) is not None}
    return row


# ---------------------------------------------------------------------------------------------


def main(argv: list[str] | None = None) -> int:
    from . import inputs, isolate
    from .ours_engine import available_strategies

    ap = argparse.ArgumentParser(prog="python -m instrument.study.engines",
                                 description=__doc__.split("\n\n")[0] + " One JSON row per line on standard output.",
                                 formatter_class=argparse.RawDescriptionHelpFormatter,
                                 epilog="engines: " + "; ".join(f"{k}: {v[1]}" for k, v in ENGINES.items()))
    ap.add_argument("inputs", nargs="+", help="files, folders, 'samples', or a family like quadratic:n=100:alpha=20")
    ap.add_argument("--switches", default="pq30", help="Triangle's switches, no dash (default pq30; {alpha} takes a family's angle)")
    ap.add_argument("--engines", default="ours,triangle", help="comma list (default ours,triangle)")
    ap.add_argument("--strategies", default="triangle", help="our strategies: a comma list or all (default triangle)")
    ap.add_argument("--repeat", type=int, default=1, help="timed runs, the best counts (default 1)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--time-limit", type=float, default=0,
                    help="seconds per run, each in a separate process killed at the limit (default 0: in this process)")
    args = ap.parse_args(argv)
    try:
        chosen = inputs.parse_inputs(args.inputs)
    except ValueError as exc:
        ap.error(str(exc))
    strategies = available_strategies() if args.strategies == "all" else args.strategies.split(",")
    for inp in chosen:
        try:
            data = inputs.load(inp)
        except Exception as exc:  # noqa: BLE001  (FormatError, OSError: one line, then the next input)
            print(json.dumps({"input": inp.label, "status": "unreadable", "message": describe(exc)}), flush=True)
            continue
        switches = inputs.switches_for(args.switches, inp)
        if switches is None:
            continue
        switches, _ = inputs.effective_switches(data, switches)
        for engine in args.engines.split(","):
            for strategy in (strategies if uses_strategies(engine) else [""]):
                kw = dict(strategy=strategy, seed=args.seed, repeat=args.repeat, family=inp.family, params=inp.param_dict)
                if args.time_limit > 0:
                    got = isolate.call(measure, (engine, data, switches), kw, time_limit=args.time_limit)
                    row = got.value if got.status == "ok" else {"status": got.status, "message": got.message}
                else:
                    row = measure(engine, data, switches, **kw)
                print(json.dumps({"input": inp.label, "switches": switches, "engine": engine, "strategy": strategy, **row},
                                 default=float), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
