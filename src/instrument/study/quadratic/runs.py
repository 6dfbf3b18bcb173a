"""The study's runs: which engines on which I(n), as tasks of a sweep, and the rows they give.

For each angle (the first is the main one): Theorem 3's script (engine
``replay``, finished by ``--then``) for n = 100, 200, ... up to ``--max-n``;
Triangle, every strategy of ours and CGAL up to ``--strategy-max-n``; the
other angles up to ``--sweep-max-n``.  Each engine and strategy at one angle
is a series of the sweep (``instrument.study.sweep``): its sizes run smallest
first, and after a size that did not finish the larger ones are skipped.
Series run side by side on the sweep's workers.

``study_rows`` turns the sweep's dataset rows into the study's rows: dicts
with ``alpha``, ``n``, ``engine``, ``strategy``, ``status`` and the
measures named in ``FIELDS``.
"""

from __future__ import annotations

import json
from pathlib import Path

import instrument
from instrument import quadratic

from .. import dataset, inputs, isolate, sweep
from ..inputs import script_points
from ..tasks import GiB, Task

REPLAY = "replay"  # engine name of Theorem 3's scripted run
MAIN_ALPHA = 20.0
FIELDS = (
    "alpha",
    "n",
    "engine",
    "strategy",
    "status",
    "vertices",
    "triangles",
    "steiner_points",
    "triangles_created",
    "scripted_created",
    "incircle_tests",
    "orient_tests",
    "circumcenters",
    "script_points",
    "steps",
    "wall_s",
    "note",
)
ENGINE_ORDER = {REPLAY: 0, "triangle": 1, "ours": 2, "cgal": 3}


def opts(alpha: float) -> str:
    return f"pq{alpha:g}"


def sizes(max_n: int, min_n: int = 100) -> list[int]:
    out, n = [], min_n
    while n <= max_n:
        out.append(n)
        n *= 2
    return out


def grid(args) -> sweep.Grid:
    """The study's tasks (``args`` as ``cli.parse_args`` makes them)."""
    g = sweep.Grid()
    memory = int(args.memory_gib * GiB) if args.memory_gib > 0 else 0
    for alpha in args.alphas:
        main = alpha == args.alphas[0]
        replay_ns = sizes(args.max_n if main else args.sweep_max_n)
        strategy_ns = sizes(args.strategy_max_n if main else args.sweep_max_n)
        print(f"alpha = {alpha:g} degrees: replay n = {replay_ns[0]}..{replay_ns[-1]}, "
              f"strategies n = {strategy_ns[0]}..{strategy_ns[-1]}", flush=True)
        for n in sorted(set(replay_ns) | set(strategy_ns)):
            inp = inputs.family_input("quadratic", n=n, alpha=alpha)
            data = g.add_input(inp)
            runs = []
            if n in replay_ns:
                runs.append((REPLAY, args.then, args.long_timeout, 1))
            if n in strategy_ns:
                if not args.no_triangle:
                    runs.append(("triangle", "", args.long_timeout, args.repeat))
                runs += [("ours", s, args.timeout, args.repeat) for s in args.strategies]
                if not args.no_cgal:
                    runs.append(("cgal", "", args.long_timeout, args.repeat))
            for engine, strategy, limit, repeat in runs:
                g.tasks.append(Task(inp, opts(alpha), engine, strategy, repeat=repeat, time_limit=limit or None,
                                    memory_limit=memory, series=json.dumps([alpha, engine, strategy]), order=n,
                                    input_counts=(len(data["vertices"]), len(data["segments"]))))
    return g


def progress_line(row: dict) -> None:
    """One line per finished run, as it finishes."""
    p = row["params"]
    label = row["engine"] if not row["strategy"] else f"{row['engine']}:{row['strategy']}"
    extra = row.get("triangles_created") or row.get("incircle_tests") or row.get("message") or ""
    print(f"  alpha {p['alpha']:g}  n {int(p['n']):6d}  {label:22s} {row['status']:8s} {row.get('task_s') or 0:8.2f} s  {extra}",
          flush=True)


def measure(args, path: Path) -> list[dict]:
    """Run the study's grid through the sweep (rows in the dataset ``path``); the study's rows."""
    g = grid(args)
    sweep.run(g, path, scheduler=args.scheduler, workers=args.workers, sequential=args.sequential,
              on_row=progress_line)
    by_key = {r["key"]: r for r in dataset.read(path)}
    rows = [study_row(by_key[t.key]) for t in g.tasks if t.key in by_key]
    alphas = {a: i for i, a in enumerate(args.alphas)}
    rows.sort(key=lambda r: (alphas.get(r["alpha"], 99), r["n"], ENGINE_ORDER.get(r["engine"], 9),
                             args.strategies.index(r["strategy"]) if r["engine"] == "ours" else 0))
    return rows


def study_row(rec: dict) -> dict:
    """The study's row for one dataset row."""
    p = rec["params"]
    row = {"alpha": float(p["alpha"]), "n": int(p["n"]), "engine": rec["engine"], "strategy": rec["strategy"] or "",
           "status": rec["status"]}
    if rec["status"] != "ok":
        row["note"] = rec["message"] or rec["status"]
        return row
    work, met = rec["work"], rec["metrics"]
    row.update(vertices=rec["vertices"], triangles=rec["triangles"],
               steiner_points=work.get("steiner_points", int(met.get("steiner_points", 0))),
               triangles_created=rec["triangles_created"], incircle_tests=rec["incircle_tests"],
               orient_tests=rec["orient_tests"], circumcenters=rec["circumcenters"],
               script_points=int(met["script_points"]) if "script_points" in met else None,
               wall_s=rec["wall_s"], note=rec["note"] or "")
    if rec["engine"] == REPLAY:
        row.update(scripted_created=work["scripted_created"], steps=work["steps"],
                   scripted_incircle=work["scripted_incircle"], scripted_orient=work["scripted_orient"])
    return row


# ---------------------------------------------------------------------------------------------
# runs the report makes besides the grid


def isolated(fn, args: tuple, timeout: float, memory_gib: float = 0.0) -> tuple[str, object]:
    """``fn(*args)`` in a process of its own (``instrument.study.isolate``),
    killed after ``timeout`` seconds: ("ok", result) or (status, message)."""
    got = isolate.call(fn, args, time_limit=timeout or None,
                       memory_limit=int(memory_gib * GiB) if memory_gib > 0 else None)
    return ("ok", got.value) if got.status == "ok" else (got.status, got.message)


def first_splits(n: int, alpha: float, strategy: str, count: int = 16) -> list[dict]:
    """Where ``strategy``'s first insertions land on I(n) and what each created."""
    res = instrument.triangulate(quadratic.example(n, alpha), opts(alpha), strategy=strategy, trace=True)
    tr = res.trace
    xy = res["vertices"]
    rows, v = [], n + 12
    for kind, created in zip(tr["kind"], tr["created"], strict=True):
        if kind == "deleted":  # vertex numbers shift: stop here
            break
        if kind == "rejected":
            continue
        rows.append({"kind": str(kind), "x": float(xy[v, 0]), "y_times_n": float(xy[v, 1] * n), "created": int(created)})
        v += 1
        if len(rows) == count:
            break
    return rows


def triangle_scan(alpha: float, lo: int, hi: int) -> tuple[list[int], list[int]]:
    """The n in lo..hi for which Triangle's output holds every scripted point, and the others."""
    import triangle

    yes, no = [], []
    for n in range(max(lo, quadratic.smallest_r(alpha) + 1), hi + 1):
        out = triangle.triangulate(quadratic.example(n, alpha), opts(alpha))
        (yes if script_points(out["vertices"], n, alpha) == quadratic.steps(n, alpha) else no).append(n)
    return yes, no
