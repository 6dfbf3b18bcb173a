"""Log-log slopes of work against n, and which strategy did the least work.

Every function reads the study's rows (``runs.study_rows``): dicts with
``alpha``, ``n``, ``engine``, ``strategy``, ``status`` and the measures.
"""

from __future__ import annotations

import numpy as np

from .runs import REPLAY


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
