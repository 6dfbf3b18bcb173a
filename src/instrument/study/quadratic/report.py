"""The study's reports: results.md, README-section.md, the CSV files and summary.json.
"""

from __future__ import annotations

import csv
import datetime as dt
import json
import multiprocessing
import platform
import sys
from pathlib import Path

from instrument import quadratic

from .fit import find
from .runs import FIELDS, REPLAY, first_splits, isolated, triangle_scan
from .tables import largest_table, md_table, num, pivot, ranges, replay_table, secs, slope_table, sweep_table


def write_csv(path: Path, rows: list[dict], fields) -> None:
    with path.open("w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(fields), extrasaction="ignore")
        w.writeheader()
        for r in rows:
            w.writerow({k: r.get(k, "") for k in fields})


def environment() -> dict:
    env = {"date": dt.datetime.now().strftime("%Y-%m-%d %H:%M"), "python": platform.python_version(),
           "machine": f"{platform.machine()}, {platform.system()}", "cpus": multiprocessing.cpu_count()}
    from ...version import __version__

    env["ruppert"] = __version__
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
    return " ".join(["python -m instrument.study.quadratic", *args])


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


def write_reports(args, rows: list[dict], sl, best, out: Path, argv) -> None:
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
            f"ruppert {env.get('ruppert', '?')}, triangle {env['triangle package']}, cgal {env['cgal package']}).  "
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
        "python -m instrument.study.quadratic --out docs/quadratic   # regenerates docs/quadratic/ (tables, CSV, figures); --quick for a short run",
        "```",
        "",
        (
            "`instrument.quadratic.replay(n)` plays Theorem 3's adversary on the engine (Lemma 1 and 2 checked at every "
            f"step); `python -m instrument.study.quadratic` measures it, every strategy, Triangle 1.6 and CGAL on the same input I(n), "
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
