"""The study's Markdown tables, and how numbers are written in them.
"""

from __future__ import annotations

import math

import numpy as np

from instrument import quadratic

from .fit import find
from .runs import REPLAY


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
