#!/usr/bin/env python
"""Reproduce Barbič and Miller's quadratic example I(n), and measure every strategy on it.

    python scripts/quadratic.py                  # the full run (docs/quadratic/, about 15 minutes)
    python scripts/quadratic.py --quick          # n <= 1600, a minute or two
    python scripts/quadratic.py --max-n 3200 --alphas 20 --strategies triangle,worst-angle --no-cgal

For n = 100, 200, 400, ... at alpha = 20 degrees (``--max-n``, default 25,600) and
a shorter sweep at the other ``--alphas`` (default 10, 30, 33; ``--sweep-max-n``):

* Theorem 3's adversary on our engine (``instrument.quadratic.replay``: the
  scripted splits of Δ_0, Δ_1, ..., checked against Lemmas 1 and 2 at every
  step, then finished with strategy ``triangle``): n, r, input size, Steiner
  points, output size, triangles created in the scripted phase and in total,
  the bound n²/(2r) - 2n, incircle and orientation tests;
* the same input (``quadratic.example``, switches ``pq<alpha>``) meshed by
  our engine with every strategy (``--strategies``), up to
  ``--strategy-max-n`` (default 51,200);
* Triangle 1.6 (the ``triangle`` package) on the same input: its size, time
  and its own statistics (incircle and orientation tests, captured from its
  ``V`` output as ``instrument.comparison`` does), and how many of the
  scripted points P_1 .. P_s its output holds (all of them: it played the
  script);
* CGAL's Mesh_2 (``cgal`` package, if installed): size and time.

Every run happens in a forked child killed after ``--timeout`` seconds (our
strategies) or ``--long-timeout`` (the replay and Triangle, which are
quadratic); a series that timed out is not run at larger n.

Writes to ``--out`` (default docs/quadratic): ``results.md`` (every table and
the findings), ``README-section.md`` (the section the project README shows),
``replay.csv``, ``runs.csv``, ``slopes.csv``, ``summary.json``, and the
figures ``work``, ``broom``, ``steps`` and ``orders`` as PNG and SVG.
"""

from __future__ import annotations

import argparse
import csv
import datetime as dt
import json
import math
import multiprocessing
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import instrument
from instrument import quadratic
from instrument.comparison import has_cgal, run_cgal, run_triangle, triangle_statistics

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


# ---------------------------------------------------------------------------------------------
# one run each (these execute in a forked child)


def opts(alpha: float) -> str:
    return f"pq{alpha:g}"


def script_points(vertices, n: int, alpha: float) -> int:
    """How many of the scripted points P_1 .. P_s (equation (9)) are vertices of
    a mesh, to 1e-9 of the spacing: all of them means the mesher played Theorem 3."""
    p = quadratic.params(n, alpha)
    if p.steps == 0:
        return 0
    want = (2.0 * np.arange(1, p.steps + 1) * p.r + 1.0) / (2.0 * n)
    v = np.asarray(vertices, dtype=np.float64).reshape(-1, 2)
    xs = np.sort(v[np.abs(v[:, 1] - p.h) <= 1e-9 * p.h, 0])
    if xs.size == 0:
        return 0
    i = np.clip(np.searchsorted(xs, want), 1, max(1, xs.size - 1))
    gap = np.minimum(np.abs(xs[i - 1] - want), np.abs(xs[np.minimum(i, xs.size - 1)] - want))
    return int((gap <= 1e-9 / n).sum())


def _best_of(repeat: int, fn):
    """Best wall time of up to ``repeat`` calls (one if a call takes over 5 s) and the last result."""
    best, out = math.inf, None
    for _ in range(max(1, repeat)):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
        if best > 5.0:
            break
    return out, best


def _our_counts(res, n: int, alpha: float) -> dict:
    """Output size and work counters of one of our runs."""
    w = res.work
    return {
        "vertices": len(res["vertices"]),
        "triangles": len(res["triangles"]),
        "steiner_points": w["steiner_points"],
        "triangles_created": w["triangles_created"],
        "incircle_tests": w["incircle_tests"],
        "orient_tests": w["orient_tests"],
        "circumcenters": w["circumcenters"],
        "script_points": script_points(res["vertices"], n, alpha),
    }


def row_replay(n: int, alpha: float, then: str) -> dict:
    res, wall = _best_of(1, lambda: quadratic.replay(n, alpha, then=then))
    return {
        **_our_counts(res, n, alpha),
        "scripted_created": int(res.steps.sum()),
        "steps": len(res.steps),
        "wall_s": wall,
        "note": f"then={then}; time includes the per-step checks",
        "scripted_incircle": res.scripted_work["incircle_tests"],
        "scripted_orient": res.scripted_work["orient_tests"],
    }


def row_ours(n: int, alpha: float, strategy: str, repeat: int) -> dict:
    d = quadratic.example(n, alpha)
    res, wall = _best_of(repeat, lambda: instrument.triangulate(d, opts(alpha), strategy=strategy))
    return {
        **_our_counts(res, n, alpha),
        "wall_s": wall,
    }


def row_triangle(n: int, alpha: float, repeat: int) -> dict:
    d = quadratic.example(n, alpha)
    out, wall = run_triangle(d, opts(alpha), repeat=repeat)
    _, stats, _ = triangle_statistics(d, opts(alpha))
    return {
        "vertices": len(out["vertices"]),
        "triangles": len(out["triangles"]),
        "steiner_points": len(out["vertices"]) - (n + 12),
        "incircle_tests": stats.get("incircle_tests"),
        "orient_tests": stats.get("orient_tests"),
        "circumcenters": stats.get("circumcenters"),
        "script_points": script_points(out["vertices"], n, alpha),
        "wall_s": wall,
        "note": "" if "incircle_tests" in stats else "statistics not captured",
    }


def row_cgal(n: int, alpha: float, repeat: int) -> dict:
    mesh, wall, notes = run_cgal(quadratic.example(n, alpha), opts(alpha), repeat=repeat)
    return {
        "vertices": len(mesh["vertices"]),
        "triangles": len(mesh["triangles"]),
        "steiner_points": len(mesh["vertices"]) - (n + 12),
        "script_points": script_points(mesh["vertices"], n, alpha),
        "wall_s": wall,
        "note": "; ".join(notes),
    }


def _limit_memory(gib: float) -> None:
    """Cap this process's address space, so that a run that grows without bound
    fails with MemoryError instead of waking the system's out-of-memory killer
    (measured: the lazy-deletion heap of `smallest` holds Θ(n²) stale entries on
    I(n), 18 GB at n = 12,800)."""
    try:
        import resource
    except ImportError:  # pragma: no cover - not on this platform
        return
    if gib > 0:
        limit = int(gib * 2**30)
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))


def isolated(fn, args: tuple, timeout: float, memory_gib: float = 0.0) -> tuple[str, object]:
    """``fn(*args)`` in a forked child killed after ``timeout`` seconds (numba and
    C code cannot be interrupted in-process) and limited to ``memory_gib`` of
    address space (0: no limit): ("ok", result), ("timeout", note) or ("error",
    message).  Without fork it runs here, with no limit."""
    try:
        ctx = multiprocessing.get_context("fork")
    except ValueError:  # pragma: no cover - no fork on this platform
        try:
            return "ok", fn(*args)
        except Exception as exc:  # noqa: BLE001  (reported in the row)
            return "error", f"{type(exc).__name__}: {exc}"
    recv, send = ctx.Pipe(duplex=False)

    def child():
        try:
            _limit_memory(memory_gib)
            send.send(("ok", fn(*args)))
        except BaseException as exc:  # noqa: BLE001  (reported to the parent)
            send.send(("error", f"{type(exc).__name__}: {str(exc).splitlines()[0] if str(exc) else ''}"))
        finally:
            send.close()

    proc = ctx.Process(target=child, daemon=True)
    proc.start()
    send.close()
    try:
        if not recv.poll(timeout):
            proc.kill()
            return "timeout", f"no result within {timeout:g} s (killed)"
        try:
            return recv.recv()
        except EOFError:
            proc.join()
            return "error", f"the child died (exit code {proc.exitcode})"
    finally:
        recv.close()
        proc.join()


# ---------------------------------------------------------------------------------------------
# the measurements


def sizes(max_n: int, min_n: int = 100) -> list[int]:
    out, n = [], min_n
    while n <= max_n:
        out.append(n)
        n *= 2
    return out


class Runner:
    """Runs the series, skipping a series at larger n after it timed out or failed."""

    def __init__(self, args):
        self.args = args
        self.rows: list[dict] = []
        self.stopped: dict[tuple, str] = {}

    def run(self, alpha: float, n: int, engine: str, strategy: str, fn, fargs: tuple, timeout: float) -> dict:
        key = (alpha, engine, strategy)
        row = {"alpha": alpha, "n": n, "engine": engine, "strategy": strategy}
        if key in self.stopped:
            row.update(status="skipped", note=self.stopped[key])
        else:
            t0 = time.perf_counter()
            status, out = isolated(fn, fargs, timeout, self.args.memory_gib)
            row["status"] = status
            if status == "ok":
                row.update(out)
            else:
                row["note"] = str(out)
                self.stopped[key] = f"{status} at n = {n}"
            label = engine if not strategy else f"{engine}:{strategy}"
            extra = row.get("triangles_created") or row.get("incircle_tests") or row.get("note", "")
            print(f"  alpha {alpha:g}  n {n:6d}  {label:22s} {status:8s} {time.perf_counter() - t0:8.2f} s  {extra}", flush=True)
        self.rows.append(row)
        return row


def warm_up(strategies: list[str]) -> None:
    """Compile (or load) the kernels once here, so the forked children inherit them."""
    quadratic.replay(20, then="triangle")
    d = quadratic.example(20)
    for s in strategies:
        instrument.triangulate(d, "pq20", strategy=s)


def measure(args) -> Runner:
    run = Runner(args)
    strategies = args.strategies
    warm_up(strategies)
    for alpha in args.alphas:
        main = alpha == args.alphas[0]
        replay_ns = sizes(args.max_n if main else args.sweep_max_n)
        strategy_ns = sizes(args.strategy_max_n if main else args.sweep_max_n)
        print(f"alpha = {alpha:g} degrees: replay n = {replay_ns[0]}..{replay_ns[-1]}, "
              f"strategies n = {strategy_ns[0]}..{strategy_ns[-1]}", flush=True)
        for n in sorted(set(replay_ns) | set(strategy_ns)):
            if n in replay_ns:
                run.run(alpha, n, REPLAY, args.then, row_replay, (n, alpha, args.then), args.long_timeout)
            if n not in strategy_ns:
                continue
            if not args.no_triangle:
                run.run(alpha, n, "triangle", "", row_triangle, (n, alpha, args.repeat), args.long_timeout)
            for s in strategies:
                run.run(alpha, n, "ours", s, row_ours, (n, alpha, s, args.repeat), args.timeout)
            if not args.no_cgal:
                run.run(alpha, n, "cgal", "", row_cgal, (n, alpha, args.repeat), args.long_timeout)
    return run


# ---------------------------------------------------------------------------------------------
# analysis


def fit_slope(ns, ys) -> float | None:
    """Least-squares slope of log y against log n (None with fewer than 2 points)."""
    pts = [(n, y) for n, y in zip(ns, ys, strict=True) if y and y > 0]
    if len(pts) < 2:
        return None
    x = np.log([p[0] for p in pts])
    y = np.log([p[1] for p in pts])
    return float(np.polyfit(x, y, 1)[0])


def series(rows, alpha, engine, strategy, key) -> tuple[list[int], list[float]]:
    sel = [r for r in rows if r["alpha"] == alpha and r["engine"] == engine and r["strategy"] == strategy
           and r["status"] == "ok" and r.get(key) is not None]
    sel.sort(key=lambda r: r["n"])
    return [r["n"] for r in sel], [r[key] for r in sel]


def slopes(rows, alphas, strategies, then) -> list[dict]:
    out = []
    for alpha in alphas:
        specs = [(REPLAY, then, "scripted_created", "Theorem 3's script: scripted phase"),
                 (REPLAY, then, "triangles_created", f"Theorem 3's script, then {then}: total"),
                 (REPLAY, then, "incircle_tests", f"Theorem 3's script, then {then}: incircle tests")]
        specs += [("ours", s, "triangles_created", f"ours, {s}") for s in strategies]
        specs += [("ours", s, "incircle_tests", f"ours, {s}: incircle tests") for s in strategies]
        specs += [("triangle", "", "incircle_tests", "Triangle 1.6: incircle tests"),
                  ("triangle", "", "orient_tests", "Triangle 1.6: orientation tests"),
                  ("triangle", "", "wall_s", "Triangle 1.6: wall time"),
                  ("cgal", "", "wall_s", "CGAL Mesh_2: wall time")]
        for engine, strategy, key, label in specs:
            ns, ys = series(rows, alpha, engine, strategy, key)
            s = fit_slope(ns, ys)
            if s is not None:
                out.append({"alpha": alpha, "series": label, "engine": engine, "strategy": strategy, "measure": key,
                            "n_min": ns[0], "n_max": ns[-1], "points": len(ns), "slope": round(s, 3)})
    return out


def find(rows, **kw) -> dict | None:
    for r in rows:
        if all(r.get(k) == v for k, v in kw.items()):
            return r
    return None


def least_work(rows, alpha, strategies) -> dict | None:
    """The strategy with the fewest triangles created at the largest n where it
    and Triangle both finished (every smaller n finished too)."""
    best = None
    for s in strategies:
        ns, ys = series(rows, alpha, "ours", s, "triangles_created")
        if not ns:
            continue
        cand = {"strategy": s, "n": ns[-1], "created": ys[-1], "slope": fit_slope(ns, ys), "n_min": ns[0]}
        if best is None or (cand["n"], -cand["created"]) > (best["n"], -best["created"]):
            best = cand
    if best is None:
        return None
    n = best["n"]
    mine = find(rows, alpha=alpha, n=n, engine="ours", strategy=best["strategy"])
    tri = find(rows, alpha=alpha, n=n, engine="triangle", status="ok")
    cg = find(rows, alpha=alpha, n=n, engine="cgal", status="ok")
    best.update(vertices=mine["vertices"], triangles=mine["triangles"], wall_s=mine["wall_s"],
                created_per_n=mine["triangles_created"] / n)
    if tri:
        best.update(triangle_vertices=tri["vertices"], triangle_triangles=tri["triangles"],
                    triangle_wall_s=tri["wall_s"], size_ratio=mine["vertices"] / tri["vertices"],
                    triangles_ratio=mine["triangles"] / tri["triangles"], time_ratio_triangle=mine["wall_s"] / tri["wall_s"])
    if cg:
        best.update(cgal_vertices=cg["vertices"], cgal_wall_s=cg["wall_s"], time_ratio_cgal=mine["wall_s"] / cg["wall_s"])
    return best


# ---------------------------------------------------------------------------------------------
# tables


def num(v, digits: int | None = None) -> str:
    """Integers with thousands separators; floats with ``digits`` decimals (three significant digits by default)."""
    if v is None or (isinstance(v, float) and math.isnan(v)):
        return "—"
    if isinstance(v, float) and digits is not None:
        return f"{v:,.{digits}f}"
    if isinstance(v, (int, np.integer)) or (isinstance(v, float) and v.is_integer()):
        return f"{int(v):,}"
    return f"{v:.3g}"


def secs(v) -> str:
    if v is None:
        return "—"
    return f"{v:.3f}" if v < 10 else f"{v:.1f}"


def md_table(header: list[str], body: list[list[str]]) -> str:
    lines = ["| " + " | ".join(header) + " |", "|" + "|".join("---:" if i else "---" for i in range(len(header))) + "|"]
    lines += ["| " + " | ".join(row) + " |" for row in body]
    return "\n".join(lines)


def replay_table(rows, alpha) -> str:
    header = ["n", "r", "input points", "scripted steps", "Steiner points", "output vertices", "output triangles",
              "created: scripted", "bound n²/(2r)−2n", "created: total", "incircle tests", "orientation tests", "time (s)"]
    body = []
    for r in sorted((r for r in rows if r["alpha"] == alpha and r["engine"] == REPLAY), key=lambda r: r["n"]):
        p = quadratic.params(r["n"], alpha)
        if r["status"] != "ok":
            body.append([num(r["n"]), str(p.r), num(r["n"] + 4)] + [r["status"]] + ["—"] * 9)
            continue
        body.append([num(r["n"]), str(p.r), num(r["n"] + 4), num(r["steps"]), num(r["steiner_points"]), num(r["vertices"]),
                     num(r["triangles"]), num(r["scripted_created"]), num(quadratic.theorem3_bound(r["n"], alpha), 0),
                     num(r["triangles_created"]), num(r["incircle_tests"]), num(r["orient_tests"]), secs(r["wall_s"])])
    return md_table(header, body)


def pivot(rows, alpha, key, strategies, *, with_triangle: bool, with_cgal: bool = False, fmt=num) -> str:
    cols = [("ours", s, s) for s in strategies]
    if with_triangle:
        cols.insert(0, ("triangle", "", "Triangle 1.6"))
    if with_cgal:
        cols.append(("cgal", "", "CGAL"))
    ns = sorted({r["n"] for r in rows if r["alpha"] == alpha and r["engine"] != REPLAY})
    body = []
    for n in ns:
        line = [num(n)]
        for engine, s, _ in cols:
            r = find(rows, alpha=alpha, n=n, engine=engine, strategy=s)
            if r is None:
                line.append("")
            elif r["status"] != "ok":
                line.append(r["status"])
            else:
                line.append(fmt(r.get(key)))
        body.append(line)
    return md_table(["n"] + [c[2] for c in cols], body)


def sweep_table(rows, alphas) -> str:
    header = ["α", "r", "n", "created: scripted", "bound", "scripted / bound", "replay total", "Triangle: incircle tests",
              "Triangle: P_k in output", "Triangle: vertices", "least created (ours)", "Δ_k's new point (Triangle's rule)"]
    body = []
    for alpha in alphas:
        for r in sorted((r for r in rows if r["alpha"] == alpha and r["engine"] == REPLAY and r["status"] == "ok"),
                        key=lambda r: r["n"]):
            n = r["n"]
            p = quadratic.params(n, alpha)
            b = quadratic.theorem3_bound(n, alpha)
            tri = find(rows, alpha=alpha, n=n, engine="triangle", status="ok")
            ours = [x for x in rows if x["alpha"] == alpha and x["n"] == n and x["engine"] == "ours" and x["status"] == "ok"]
            low = min(ours, key=lambda x: x["triangles_created"]) if ours else None
            body.append([f"{alpha:g}°", str(p.r), num(n), num(r["scripted_created"]), num(b, 0),
                         f"{r['scripted_created'] / b:.3f}" if b > 0 else "—", num(r["triangles_created"]),
                         num(tri["incircle_tests"]) if tri else "—",
                         f"{tri['script_points']}/{r['steps']}" if tri else "—", num(tri["vertices"]) if tri else "—",
                         f"{num(low['triangles_created'])} ({low['strategy']})" if low else "—", delta_point(alpha)])
    return md_table(header, body)


def largest_table(rows, alpha, strategies, sl) -> tuple[int | None, str]:
    """Every engine at the largest n Triangle finished: size, work, time, slope."""
    done = [r["n"] for r in rows if r["alpha"] == alpha and r["engine"] == "triangle" and r["status"] == "ok"]
    if not done:
        done = [r["n"] for r in rows if r["alpha"] == alpha and r["engine"] == "ours" and r["status"] == "ok"]
    if not done:
        return None, ""
    n = max(done)
    slope_of = {(x["engine"], x["strategy"], x["measure"]): x for x in sl if x["alpha"] == alpha}
    tri = find(rows, alpha=alpha, n=n, engine="triangle", status="ok")
    cols = [("triangle", "", "Triangle 1.6", "incircle_tests"), ("cgal", "", "CGAL Mesh_2", None)]
    cols += [("ours", s, f"ours, {s}", "triangles_created") for s in strategies]
    body = []
    for engine, strategy, label, measure in cols:
        r = find(rows, alpha=alpha, n=n, engine=engine, strategy=strategy)
        fit = slope_of.get((engine, strategy, measure)) if measure else None
        slope = f"{fit['slope']:.2f} ({'incircle tests' if engine == 'triangle' else 'created'}, n ≤ {fit['n_max']:,})" if fit else "—"
        if r is None:
            continue
        if r["status"] != "ok":
            stopped = [x for x in rows if x["alpha"] == alpha and x["engine"] == engine and x["strategy"] == strategy
                       and x["status"] not in ("ok", "skipped")]
            why = f"{stopped[0]['status']} at n = {stopped[0]['n']:,}" if stopped else r["status"]
            body.append([label, why] + ["—"] * 7 + [slope])
            continue
        ratio = f"{r['wall_s'] / tri['wall_s']:.3f}" if tri and r.get("wall_s") else "—"
        body.append([label, num(r["vertices"]), num(r["triangles"]), num(r.get("triangles_created")),
                     num(r.get("incircle_tests")), num(r.get("orient_tests")), f"{r.get('script_points', 0):,}",
                     secs(r.get("wall_s")), ratio, slope])
    header = ["engine", "vertices", "triangles", "triangles created", "incircle tests", "orientation tests",
              "P_k in output", "time (s)", "time / Triangle's", "log-log slope"]
    return n, md_table(header, body)


def delta_point(alpha: float) -> str:
    """Which point Triangle's rule (spec 4.8.5) takes for Δ_k: its circumcenter, at
    distance h = sqrt(4r²-1)/(2n) from the middle of CD, or the off-center, at
    0.475·cot(α/2)/n, whichever is closer."""
    p = quadratic.params(1000, alpha)
    circ = p.h * p.n
    off = 0.475 / math.tan(math.radians(alpha) / 2.0)
    which = "circumcenter" if circ <= off else "off-center"
    return f"{which} ({circ:.3f}/n against {off:.3f}/n)"


def slope_table(sl, alpha) -> str:
    body = [[s["series"], f"{s['n_min']:,}–{s['n_max']:,}", str(s["points"]), f"{s['slope']:.2f}"]
            for s in sl if s["alpha"] == alpha]
    return md_table(["series", "n", "sizes", "log-log slope"], body)


# ---------------------------------------------------------------------------------------------
# figures


def _save(fig, out: Path, name: str) -> list[Path]:
    paths = []
    for ext in ("png", "svg"):
        p = out / f"{name}.{ext}"
        fig.savefig(p, dpi=130 if ext == "png" else None, bbox_inches="tight")
        paths.append(p)
    return paths


def plot_work(rows, sl, alpha, strategies, then, out: Path) -> list[Path]:
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(13, 5.2))
    slope_of = {(s["engine"], s["strategy"], s["measure"]): s["slope"] for s in sl if s["alpha"] == alpha}
    markers = "osD^v<>ph*X"
    for ax, key, title in ((axes[0], "triangles_created", "triangles created"), (axes[1], "incircle_tests", "incircle tests")):
        if key == "triangles_created":
            ns, ys = series(rows, alpha, REPLAY, then, "scripted_created")
            if ns:
                ax.plot(ns, ys, "k-", lw=2.2, label=f"Theorem 3's script (scripted phase), slope {slope_of.get((REPLAY, then, 'scripted_created'), float('nan')):.2f}")
                b = [quadratic.theorem3_bound(n, alpha) for n in ns]
                ax.plot(ns, b, "k:", lw=1.5, label="bound n²/(2r) − 2n")
        ns, ys = series(rows, alpha, REPLAY, then, key)
        if ns:
            ax.plot(ns, ys, "-", color="0.45", lw=1.5, label=f"script, then {then}: total, slope {slope_of.get((REPLAY, then, key), float('nan')):.2f}")
        if key == "incircle_tests":
            ns, ys = series(rows, alpha, "triangle", "", key)
            if ns:
                ax.plot(ns, ys, "r-", lw=2.2, label=f"Triangle 1.6 (its own count), slope {slope_of.get(('triangle', '', key), float('nan')):.2f}")
        for i, s in enumerate(strategies):
            ns, ys = series(rows, alpha, "ours", s, key)
            if ns:
                ax.plot(ns, ys, marker=markers[i % len(markers)], ms=4, lw=1, ls="--",
                        label=f"ours, {s}: slope {slope_of.get(('ours', s, key), float('nan')):.2f}")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("n (input I(n) has n + 4 points)")
        ax.set_ylabel(title)
        ax.set_title(f"{title} on I(n), q = {alpha:g}°")
        ax.grid(True, which="both", alpha=0.25)
        ax.legend(fontsize=7, loc="upper left")
    fig.suptitle("Work against n, log-log; slopes are least-squares fits over the sizes shown", fontsize=10)
    fig.tight_layout()
    paths = _save(fig, out, "work")
    plt.close(fig)
    return paths


def _draw_mesh(ax, res, *, shade=(), shade_color="#9ecae1", dashed_from=None, lw=0.6):
    """Draw the triangles of ``res``; edges with an end at index >= ``dashed_from``
    or among the far points are dashed (they leave the window)."""
    from matplotlib.collections import LineCollection, PolyCollection

    xy = res["vertices"]
    tris = res["triangles"]
    shade = {tuple(sorted(t)) for t in shade}
    polys = [xy[t] for t in tris if tuple(sorted(map(int, t))) in shade]
    if polys:
        ax.add_collection(PolyCollection(polys, facecolors=shade_color, edgecolors="none", zorder=1))
    edges = {tuple(sorted((int(t[i]), int(t[(i + 1) % 3])))) for t in tris for i in range(3)}
    far = set(dashed_from or ())
    solid = [xy[list(e)] for e in edges if not (far & set(e))]
    dash = [xy[list(e)] for e in edges if far & set(e)]
    ax.add_collection(LineCollection(solid, colors="0.15", linewidths=lw, zorder=2))
    ax.add_collection(LineCollection(dash, colors="0.45", linewidths=lw * 0.8, linestyles=(0, (3, 3)), zorder=2))


def _circle(xy3):
    (ax, ay), (bx, by), (cx, cy) = xy3
    d = 2 * (ax * (by - cy) + bx * (cy - ay) + cx * (ay - by))
    ux = ((ax * ax + ay * ay) * (by - cy) + (bx * bx + by * by) * (cy - ay) + (cx * cx + cy * cy) * (ay - by)) / d
    uy = ((ax * ax + ay * ay) * (cx - bx) + (bx * bx + by * by) * (ax - cx) + (cx * cx + cy * cy) * (bx - ax)) / d
    return ux, uy, math.hypot(ax - ux, ay - uy)


def plot_broom(out: Path) -> list[Path]:
    """Figure 3 of the paper from the engine's mesh: r = 2, n = 10, k = 2."""
    import matplotlib.pyplot as plt
    from matplotlib.patches import Circle

    n, k, alpha = 10, 2, 20.0
    res = quadratic.replay(n, alpha, stop_after=k, then=None)
    p = res.params
    xy = res["vertices"]
    broom = quadratic.broom(n, k, alpha)
    far = [n + 1, n + 2] + list(range(n + 4, n + 12))
    fig, ax = plt.subplots(figsize=(8, 7.2))
    _draw_mesh(ax, res, shade=broom, dashed_from=far, lw=0.8)
    m = n - 2
    cx, cy, rad = _circle(xy[[m, m + 1, quadratic.apex_index(n, k)]])
    ax.add_patch(Circle((cx, cy), rad, fill=False, ec="tab:red", lw=1.2, zorder=3))
    ax.plot([cx], [cy], "+", color="tab:red")
    ax.annotate(f"empty circumcircle of ({m}/n, {m + 1}/n, P_{k})", (cx, cy + rad), xytext=(0.02, cy + rad + 0.05), color="tab:red", fontsize=9)
    pts = xy[: n + 1]
    ax.plot(pts[:, 0], pts[:, 1], "ko", ms=3, zorder=4)
    for j in range(k + 1):
        v = quadratic.apex_index(n, j)
        ax.plot(*xy[v], "o", color="tab:blue", ms=5, zorder=4)
        ax.annotate(f"P_{j}", xy[v], xytext=(xy[v][0] - 0.02, xy[v][1] + 0.04), fontsize=9, color="tab:blue")
    ax.set_xlim(-0.1, 1.1)
    ax.set_ylim(-0.12, cy + rad + 0.15)
    ax.set_aspect("equal")
    ax.set_title(f"Lemma 2 on the engine's mesh: n = {n}, r = {p.r}, k = {k} (after two scripted splits)\n"
                 f"shaded: the broom (m/n, (m+1)/n, P_{k}), {k * p.r} ≤ m < n; dashed: edges to (0, a), (1, a) and the box "
                 f"(a = {p.a:.2f}); true scale", fontsize=9)
    paths = _save(fig, out, "broom")
    plt.close(fig)
    return paths


def plot_steps(out: Path) -> list[Path]:
    """Figure 4 of the paper from the engine's meshes: r = 2, n = 19, the first four splits."""
    import matplotlib.pyplot as plt

    n, alpha = 19, 20.0
    p = quadratic.params(n, alpha)
    fig, axes = plt.subplots(4, 1, figsize=(11, 12), sharex=True)
    far = [n + 1, n + 2] + list(range(n + 4, n + 12))
    for k, ax in enumerate(axes):
        res = quadratic.replay(n, alpha, stop_after=k, then=None)
        xy = res["vertices"]
        _draw_mesh(ax, res, shade=[quadratic.delta(n, k, alpha)], shade_color="#fdae6b", dashed_from=far)
        ax.plot(xy[: n + 1, 0], xy[: n + 1, 1], "ko", ms=2.5, zorder=4)
        for j in range(k + 1):
            v = quadratic.apex_index(n, j)
            ax.plot(*xy[v], "o", color="tab:blue", ms=4, zorder=4)
            ax.annotate(f"P_{j}", xy[v], xytext=(xy[v][0] - 0.012, xy[v][1] + 0.25 * p.h), fontsize=8, color="tab:blue")
        s = quadratic.new_point(n, k, alpha)
        cx, cy, rad = _circle(xy[list(quadratic.delta(n, k, alpha))])
        th = np.linspace(0, 2 * np.pi, 400)
        ax.plot(cx + rad * np.cos(th), cy + rad * np.sin(th), ":", color="tab:red", lw=1)
        ax.plot(*s, "*", color="tab:red", ms=9, zorder=5)
        ax.annotate(f"circumcenter of Δ_{k} = P_{k + 1}", s, xytext=(s[0] + 0.01, s[1] + 0.35 * p.h), fontsize=8, color="tab:red")
        ax.set_ylim(-0.4 * p.h, 2.6 * p.h)
        ax.set_xlim(-0.03, 1.03)
        ax.set_ylabel("y")
        made = int(quadratic.replay(n, alpha, stop_after=k + 1, then=None).steps[-1])
        ax.set_title(f"step {k}: split Δ_{k} (shaded; dotted: its circumcircle); it creates {made} triangles", fontsize=9)
    axes[-1].set_xlabel("x")
    fig.suptitle(f"Theorem 3 on the engine's meshes, n = {n}, r = {p.r}, h = {p.h:.4f}: true coordinates, "
                 f"y stretched (the paper's Figure 4 draws the points higher still)", fontsize=10)
    fig.tight_layout()
    paths = _save(fig, out, "steps")
    plt.close(fig)
    return paths


def plot_orders(out: Path, strategy: str) -> list[Path]:
    """The first splits of the script and of ``strategy``, from the engine's meshes
    (``replay(stop_after=k)`` and ``triangulate(..., "pq20S<k>")``: a budget of k
    Steiner points)."""
    import matplotlib.pyplot as plt

    n, alpha = 19, 20.0
    p = quadratic.params(n, alpha)
    far = [n + 1, n + 2] + list(range(n + 4, n + 12))
    d = quadratic.example(n, alpha)
    budgets = (2, 4, 8)
    fig, axes = plt.subplots(2, len(budgets), figsize=(15, 6.5), sharey=True)
    for j, budget in enumerate(budgets):
        res = quadratic.replay(n, alpha, stop_after=budget, then=None)
        other = instrument.triangulate(d, f"pq{alpha:g}S{budget}", strategy=strategy, trace=True)
        made = int(other.trace["created"].sum())
        for row, mesh, text in ((0, res, f"Theorem 3's script after {budget} splits: {int(res.steps.sum())} triangles created"),
                                (1, other, f"ours, {strategy}, after {budget} splits: {made} triangles created")):
            ax = axes[row, j]
            xy = mesh["vertices"]
            newest = len(xy) - 1
            shade = [t for t in mesh["triangles"] if newest in set(map(int, t)) and not set(map(int, t)) & set(far)]
            _draw_mesh(ax, mesh, shade=shade, shade_color="#9ecae1" if row == 0 else "#a1d99b", dashed_from=far)
            ax.plot(xy[: n + 1, 0], xy[: n + 1, 1], "ko", ms=2, zorder=4)
            extra = xy[n + 12:]
            ax.plot(*xy[n + 3], "o", color="tab:blue", ms=4, zorder=5)
            ax.plot(extra[:, 0], extra[:, 1], "o", color="tab:red", ms=4, zorder=5)
            ax.set_title(text, fontsize=9)
            ax.set_xlim(-0.05, 1.05)
            ax.set_ylim(-3.2 * p.h, 3.2 * p.h)
    for ax in axes[:, 0]:
        ax.set_ylabel("y")
    fig.suptitle(f"n = {n}, r = {p.r}, h = {p.h:.3f}: blue P_0, red the Steiner points, shaded the triangles at the newest "
                 "one, except those at the box and at (0, a), (1, a) (true coordinates, y stretched; points outside the window are not shown)", fontsize=10)
    fig.tight_layout()
    paths = _save(fig, out, "orders")
    plt.close(fig)
    return paths


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


# ---------------------------------------------------------------------------------------------
# reports


def write_csv(path: Path, rows: list[dict], fields) -> None:
    with path.open("w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(fields), extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in fields})


def environment() -> dict:
    env = {"date": dt.datetime.now().strftime("%Y-%m-%d %H:%M"), "python": platform.python_version(),
           "machine": f"{platform.machine()}, {platform.system()}", "cpus": multiprocessing.cpu_count()}
    try:
        import numba

        env["numba"] = numba.__version__
    except ImportError:  # pragma: no cover
        pass
    try:
        from importlib.metadata import version

        env["triangle package"] = version("triangle")
    except Exception:  # noqa: BLE001
        env["triangle package"] = "not installed"
    try:
        from importlib.metadata import version

        env["cgal package"] = version("cgal")
    except Exception:  # noqa: BLE001
        env["cgal package"] = "not installed"
    return env


def command_line(argv: list[str] | None) -> str:
    args = sys.argv[1:] if argv is None else argv
    return " ".join(["python scripts/quadratic.py", *args])


def findings(rows, alpha, best, then) -> list[str]:
    """The measured facts the text states, as sentences (each computed from the rows)."""
    out = []
    rep = sorted((r for r in rows if r["alpha"] == alpha and r["engine"] == REPLAY and r["status"] == "ok"), key=lambda r: r["n"])
    if rep:
        ok = all(r["scripted_created"] >= quadratic.theorem3_bound(r["n"], alpha) for r in rep)
        out.append(f"The scripted phase creates at least n²/(2r) − 2n triangles at every n measured: **{'yes' if ok else 'NO'}** "
                   f"(ratio to the bound {min(r['scripted_created'] / quadratic.theorem3_bound(r['n'], alpha) for r in rep):.3f} "
                   f"to {max(r['scripted_created'] / quadratic.theorem3_bound(r['n'], alpha) for r in rep):.3f}).")
    tri = sorted((r for r in rows if r["alpha"] == alpha and r["engine"] == "triangle" and r["status"] == "ok"), key=lambda r: r["n"])
    if tri:
        played = [r["n"] for r in tri if r["script_points"] == quadratic.steps(r["n"], alpha)]
        measured = [r["n"] for r in tri]
        if played == measured:
            listed = f"every n measured ({measured[0]:,} … {measured[-1]:,})"
        else:
            listed = (f"n = {', '.join(f'{n:,}' for n in played) or 'none'} of "
                      f"{', '.join(f'{n:,}' for n in measured)}")
        out.append(f"Triangle 1.6's output holds every scripted point P_1 … P_s (it played Theorem 3's script) at {listed}.")
        pairs = []
        for r in tri:
            rr = find(rows, alpha=alpha, n=r["n"], engine=REPLAY, status="ok")
            if rr and r.get("incircle_tests"):
                pairs.append(f"{r['n']:,}: {r['incircle_tests'] / rr['incircle_tests']:.3f}")
        if pairs:
            out.append("Triangle's incircle tests divided by the replay's (script, then our `triangle` strategy): " + "; ".join(pairs) + ".")
    if best:
        out.append(
            f"Least work among our strategies at n = {best['n']:,}: **{best['strategy']}**, {best['created']:,} triangles created "
            f"({best['created_per_n']:.1f} per input point), log-log slope {best['slope']:.3f} over n = {best['n_min']:,}–{best['n']:,}."
        )
        if "size_ratio" in best:
            out.append(
                f"Its output: {best['vertices']:,} vertices, {best['triangles']:,} triangles, {best['size_ratio']:.3f} × Triangle's "
                f"vertices ({best['triangle_vertices']:,}) and {best['triangles_ratio']:.3f} × its triangles; wall time "
                f"{secs(best['wall_s'])} s against Triangle's {secs(best['triangle_wall_s'])} s "
                f"({best['time_ratio_triangle']:.3f} ×)"
                + (f" and CGAL's {secs(best['cgal_wall_s'])} s ({best['time_ratio_cgal']:.3f} ×)." if "cgal_wall_s" in best else ".")
            )
    return out


EXPLANATION = """\
### Why the script is quadratic, and who plays it

After step k the newest point P_k sees every bottom edge to its right: the broom
(m/n, (m+1)/n, P_k), kr ≤ m < n, is Delaunay (Lemma 2).  Its skinny triangles all
have the same shortest edge, 1/n, and their angle at P_k shrinks as m grows.  Δ_k
(m = kr + r) is the *least* skinny of them and has the *smallest* circumradius, and
its circumcenter lies at height h, the height of P_k, only r/n to the right: the
next point again sees every bottom edge to its right, and its broom of
n − r(k+1) triangles is built again, n/r times over.

* **Triangle 1.6** keeps bad triangles in 4096 buckets by shortest edge, finest
  first, first-in first-out inside a bucket, and inserts a vertex by flipping
  outward from it, testing each triangle as the flips make it.  Every skinny
  broom triangle sits in the finest bucket and the new broom enters it from left
  to right, so the first one out is Δ_{k+1}: once Δ_0 leaves the queue first,
  Triangle's order *is* Theorem 3's adversary.  The measurements say so directly:
  its output mesh contains every scripted point P_1 … P_s (the column "P_k in
  output") and its incircle count is the replay's to a few per cent.  Whether Δ_0
  comes out first depends on Triangle's initial queue order (the pool order of
  its divide-and-conquer triangulation), so it depends on n (the scan below).
  Where Δ_k's off-center is closer than its circumcenter (the sweep table's last
  column; at 30°: 2θ = 28.96° < 30°), Triangle inserts the off-center, the new
  point is not at height h, and the script breaks.  At 33° (r = 1) Triangle takes
  the circumcenter but still does not follow the script at the n measured; why
  was not investigated here.
* **Our `smallest`** (smallest circumradius first) picks Δ_k every time: it
  plays the script, and is quadratic.  Our **`triangle`** strategy has
  Triangle's keys and, for the triangles refinement makes, its order among
  equal keys (a new vertex's triangles are queued counter-clockwise from the
  edge Triangle's flips start at); only the initial triangles are queued in
  slot order instead of Triangle's pool order.  It does not insert the scripted
  points (the column "P_k in output"), yet its work is quadratic too (the
  slopes table); how its order rebuilds long fans without the scripted
  points was not investigated.
* **The least-work strategy** serves the far end of a fan first.  The skinniest
  triangle of a fan is the one whose bottom edge is farthest from the apex; its
  new point (the off-center, 0.475·cot(α/2)/n above that edge, far closer than
  the circumcenter) lands at the far end of the fan, and the fan's bottom edges
  are then shared between two apexes, each fan reaching only to the nearest point
  at that height.  Repeated, the points land in a bisection-like order (the
  table of first splits below, measured), the fans shrink, and Δ_k, the least
  skinny triangle of its broom, is served last, when no broom is left.  What
  remains above linear is the first splits, whose fans reach across the whole
  bottom: the work per input point grows slowly with n.
"""


def triangle_scan(alpha: float, lo: int, hi: int) -> tuple[list[int], list[int]]:
    """The n in lo..hi for which Triangle's output holds every scripted point, and the others."""
    import triangle

    yes, no = [], []
    for n in range(max(lo, quadratic.smallest_r(alpha) + 1), hi + 1):
        out = triangle.triangulate(quadratic.example(n, alpha), opts(alpha))
        (yes if script_points(out["vertices"], n, alpha) == quadratic.steps(n, alpha) else no).append(n)
    return yes, no


def ranges(ns: list[int]) -> str:
    if not ns:
        return "none"
    out, start, prev = [], ns[0], ns[0]
    for n in ns[1:] + [None]:
        if n is not None and n == prev + 1:
            prev = n
            continue
        out.append(f"{start}" if start == prev else f"{start}–{prev}")
        if n is not None:
            start = prev = n
    return ", ".join(out)


def write_reports(args, run: Runner, sl, best, out: Path, argv) -> None:
    rows = run.rows
    alpha = args.alphas[0]
    env = environment()
    cmd = command_line(argv)
    rep_csv = [r for r in rows if r["engine"] == REPLAY]
    write_csv(out / "replay.csv", rep_csv, FIELDS + ("scripted_incircle", "scripted_orient"))
    write_csv(out / "runs.csv", rows, FIELDS)
    write_csv(out / "slopes.csv", sl, ("alpha", "series", "engine", "strategy", "measure", "n_min", "n_max", "points", "slope"))
    (out / "summary.json").write_text(json.dumps({"command": cmd, "environment": env, "least_work": best, "slopes": sl,
                                                  "rows": rows}, indent=1, default=float) + "\n")
    strategies = args.strategies
    facts = findings(rows, alpha, best, args.then)
    extra = []
    if best:
        fs_n = max(r["n"] for r in rows if r["alpha"] == alpha and r["engine"] == "ours" and r["strategy"] == best["strategy"]
                   and r["status"] == "ok")
        status, fs = isolated(first_splits, (fs_n, alpha, best["strategy"]), args.timeout, args.memory_gib)
        if status != "ok":
            print(f"first splits of {best['strategy']} at n = {fs_n}: {status} {fs}", flush=True)
            fs = []
        extra += [(f"First splits of `{best['strategy']}` at n = {fs_n:,}, α = {alpha:g}° (x, height times n: Δ_k's circumcenters "
                  f"are at height h = {quadratic.params(fs_n, alpha).h * fs_n:.3f}/n; negative heights lie below the bottom line, "
                  "in the fans from the box):"), "",
                  md_table(["#", "kind", "x", "y · n", "triangles created"],
                           [[str(i), f["kind"], f"{f['x']:.5f}", f"{f['y_times_n']:.3f}", num(f["created"])] for i, f in enumerate(fs)]),
                  ""]
    if not args.no_triangle and args.scan_max_n >= 10:
        status, scan = isolated(triangle_scan, (alpha, 10, args.scan_max_n), args.long_timeout, args.memory_gib)
        yes, no = scan if status == "ok" else ([], [])
        extra += [(f"Triangle 1.6 on I(n) for every n = 10…{args.scan_max_n} at α = {alpha:g}°: its output holds every scripted "
                  f"point (it played the script) for n = {ranges(yes)}; not for n = {ranges(no)}."), ""]
    scripted_slope = next((s["slope"] for s in sl if s["alpha"] == alpha and s["engine"] == REPLAY
                           and s["measure"] == "scripted_created"), None)
    big_n, big = largest_table(rows, alpha, strategies, sl)
    big_part = ([(f"Every engine on I({big_n:,}), q = {alpha:g}° (slopes: least-squares fits of log work against log n over "
                 "the sizes each finished):"), "", big, ""] if big else [])
    parts = [
        "# Barbič and Miller's quadratic example, measured",
        "",
        (
            f"Generated by `{cmd}` on {env['date']} ({env['machine']}, {env['cpus']} CPUs; Python {env['python']}, "
            f"numba {env.get('numba', '?')}, triangle {env['triangle package']}, cgal {env['cgal package']}).  "
            "Every number below is from that run; the files beside this one hold the same rows (`runs.csv`, "
            "`replay.csv`, `slopes.csv`, `summary.json`)."
        ),
        "",
        (
            "Input: `instrument.quadratic.example(n, α)`, the paper's extended input (the n + 4 points of I(n), the box "
            "of side 3a with its corners and side midpoints, its 8 subsegments), meshed with switches `pq<α>`.  Work: "
            "triangles created (the paper's measure: every triangle that appears), incircle and orientation tests "
            "(counted as Triangle counts them)."
        ),
        "",
        "## Findings",
        "",
        *[f"* {f}" for f in facts],
        *([f"* Log-log slope of the scripted phase's triangles against n: **{scripted_slope:.3f}**."] if scripted_slope else []),
        "",
        f"## Theorem 3's script on the engine, α = {alpha:g}°",
        "",
        (
            f"`quadratic.replay(n, {alpha:g}, then=\"{args.then}\")`: split Δ_0, Δ_1, … (Lemma 1 and Lemma 2 checked at "
            f"every step), then finish with strategy `{args.then}`.  As printed, Theorem 3 runs k to ⌊n/r⌋ − 1, but Δ_k "
            "needs the vertex kr + r + 1 ≤ n: when r divides n (every n here) the last printed step does not exist, and "
            "the replay makes ⌊(n−1)/r⌋ steps; the missing step would add n − r(k+1) = 0 to sum (14), so bound (12) "
            "stands.  Input points: the n + 4 of I(n) (the extended input adds the 8 box points).  Time includes the "
            "per-step checks."
        ),
        "",
        replay_table(rows, alpha),
        "",
        f"## Every strategy on the same input, α = {alpha:g}°",
        "",
        *big_part,
        "Triangles created (ours; Triangle does not count them):",
        "",
        pivot(rows, alpha, "triangles_created", strategies, with_triangle=False),
        "",
        "Incircle tests (Triangle 1.6: its own statistics, switch `V`):",
        "",
        pivot(rows, alpha, "incircle_tests", strategies, with_triangle=True),
        "",
        "Orientation tests (Triangle: its printed count minus the one test per output triangle its statistics make):",
        "",
        pivot(rows, alpha, "orient_tests", strategies, with_triangle=True),
        "",
        "Output vertices:",
        "",
        pivot(rows, alpha, "vertices", strategies, with_triangle=True, with_cgal=True),
        "",
        "Scripted points P_1 … P_s present in the output (all of them: the mesher played Theorem 3's script):",
        "",
        pivot(rows, alpha, "script_points", strategies, with_triangle=True, with_cgal=True),
        "",
        "Wall time in seconds (best of the repeated runs; one run when a run takes over 5 s):",
        "",
        pivot(rows, alpha, "wall_s", strategies, with_triangle=True, with_cgal=True, fmt=secs),
        "",
        "Fitted log-log slopes:",
        "",
        slope_table(sl, alpha),
        "",
        "![work against n](work.png)",
        "",
        EXPLANATION,
        *extra,
        "![the first splits of the script and of the least-work strategy](orders.png)",
        "",
        "## The broom, from the engine's meshes",
        "",
        "Lemma 2 (the paper's Figure 3): ![broom](broom.png)",
        "",
        "Theorem 3's first four steps (the paper's Figure 4): ![steps](steps.png)",
        "",
    ]
    if len(args.alphas) > 1:
        intro = "Scripted phase against the bound, and Triangle on the same input, at every α (the first one has the long table above):"
        parts += ["## The sweep over α", "", intro, "", sweep_table(rows, args.alphas), ""]
        for a in args.alphas[1:]:
            parts += [f"Triangles created at α = {a:g}° (ours):", "", pivot(rows, a, "triangles_created", strategies,
                                                                         with_triangle=False), ""]
    timeouts = [r for r in rows if r["status"] not in ("ok", "skipped")]
    if timeouts:
        parts += ["## Runs that did not finish", ""]
        parts += [f"* α = {r['alpha']:g}°, n = {r['n']:,}, {r['engine']}{':' + r['strategy'] if r['strategy'] else ''}: "
                  f"{r['status']} ({r.get('note', '')}); larger n skipped" for r in timeouts]
        parts.append("")
    (out / "results.md").write_text("\n".join(parts))

    # the README's section
    sec = [
        "## The quadratic example (Barbič and Miller)",
        "",
        "```bash",
        "python scripts/quadratic.py          # regenerates docs/quadratic/ (tables, CSV, figures); --quick for a short run",
        "```",
        "",
        (
            "`instrument.quadratic.replay(n)` plays Theorem 3's adversary on the engine (Lemma 1 and 2 checked at every "
            f"step); `scripts/quadratic.py` measures it, every strategy, Triangle 1.6 and CGAL on the same input I(n), "
            f"q = {alpha:g}°.  Full tables, the sweep over α and the explanation: "
            "[docs/quadratic/results.md](docs/quadratic/results.md)."
        ),
        "",
        replay_table(rows, alpha),
        "",
        *big_part,
        *[f"* {f}" for f in facts],
        *([f"* Log-log slope of the scripted phase: {scripted_slope:.3f}."] if scripted_slope else []),
        "",
        "![work against n](docs/quadratic/work.png)",
        "",
        "![the broom of Lemma 2](docs/quadratic/broom.png)",
        "",
    ]
    (out / "README-section.md").write_text("\n".join(sec))


def print_summary(args, sl, best) -> None:
    try:
        from rich.console import Console
        from rich.table import Table
    except ImportError:  # pragma: no cover
        for s in sl:
            print(f"{s['alpha']:g}  {s['series']:55s} {s['n_min']}-{s['n_max']}  slope {s['slope']:.3f}")
        print("least work:", best)
        return
    t = Table(title="log-log slopes")
    for c in ("α", "series", "n", "slope"):
        t.add_column(c)
    for s in sl:
        t.add_row(f"{s['alpha']:g}", s["series"], f"{s['n_min']:,}–{s['n_max']:,}", f"{s['slope']:.3f}")
    Console().print(t)
    if best:
        Console().print(f"least work: {best}")


# ---------------------------------------------------------------------------------------------


def parse_args(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--max-n", type=int, default=25_600, help="largest n of the replay table at the first angle (default 25600)")
    ap.add_argument("--strategy-max-n", type=int, default=51_200,
                    help="largest n of the strategy, Triangle and CGAL runs at the first angle (default 51200)")
    ap.add_argument("--sweep-max-n", type=int, default=3_200, help="largest n at the other angles (default 3200)")
    ap.add_argument("--alphas", default="20,10,30,33", help="minimum angles in degrees, the first is the main one (default 20,10,30,33)")
    ap.add_argument("--strategies", default="all", help="comma-separated strategies of ours, or 'all' (default)")
    ap.add_argument("--then", default="triangle", help="strategy that finishes the replay (default triangle)")
    ap.add_argument("--timeout", type=float, default=60.0, help="seconds per run of our strategies (default 60)")
    ap.add_argument("--long-timeout", type=float, default=1200.0, help="seconds per replay or Triangle run (default 1200)")
    ap.add_argument("--memory-gib", type=float, default=6.0,
                    help="address-space limit of each run's process in GiB, 0 for none (default 6)")
    ap.add_argument("--repeat", type=int, default=3, help="timed runs per engine, the best counts (default 3)")
    ap.add_argument("--scan-max-n", type=int, default=200,
                    help="run Triangle for every n = 10..this at the first angle: which n does it play the script for (default 200)")
    ap.add_argument("--no-cgal", action="store_true", help="skip CGAL")
    ap.add_argument("--no-triangle", action="store_true", help="skip Triangle")
    ap.add_argument("--no-figures", action="store_true", help="skip the figures")
    ap.add_argument("--quick", action="store_true", help="a short run: n <= 1600 (800 in the sweep), one timed run")
    ap.add_argument("--out", type=Path, default=ROOT / "docs" / "quadratic", help="output directory (default docs/quadratic)")
    args = ap.parse_args(argv)
    if args.quick:
        args.max_n = min(args.max_n, 1600)
        args.strategy_max_n = min(args.strategy_max_n, 1600)
        args.sweep_max_n = min(args.sweep_max_n, 800)
        args.repeat = 1
    args.strategy_max_n = max(args.strategy_max_n, 100)
    if not args.no_cgal and not has_cgal():
        print("CGAL's bindings are not installed (pip install cgal): no CGAL runs", flush=True)
        args.no_cgal = True
    try:
        args.alphas = [float(a) for a in args.alphas.split(",") if a.strip()]
        for a in args.alphas:
            quadratic.params(1000, a)
    except ValueError as exc:
        ap.error(f"--alphas: {exc}")
    names = list(instrument.strategies())
    args.strategies = names if args.strategies == "all" else [s.strip() for s in args.strategies.split(",") if s.strip()]
    bad = [s for s in args.strategies + [args.then] if s not in names]
    if bad:
        ap.error(f"unknown strategies {bad}; choose from {', '.join(names)}")
    return args


def main(argv: list[str] | None = None) -> int:
    args = parse_args(argv)
    out = args.out
    out.mkdir(parents=True, exist_ok=True)
    _limit_memory(args.memory_gib)  # this process too: a MemoryError, not the system's OOM killer
    t0 = time.perf_counter()
    run = measure(args)
    alpha = args.alphas[0]
    sl = slopes(run.rows, args.alphas, args.strategies, args.then)
    best = least_work(run.rows, alpha, args.strategies)
    if not args.no_figures:
        import matplotlib

        matplotlib.use("Agg")
        plot_work(run.rows, sl, alpha, args.strategies, args.then, out)
        plot_broom(out)
        plot_steps(out)
        plot_orders(out, best["strategy"] if best else "worst-angle")
    write_reports(args, run, sl, best, out, argv)
    print_summary(args, sl, best)
    print(f"wrote {out} in {time.perf_counter() - t0:.0f} s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
