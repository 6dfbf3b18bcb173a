"""The study's figures: work against n, the broom (the paper's Figure 3), Theorem 3's
steps (Figure 4), and the first splits of the script and of a strategy, all drawn
from the engine's own meshes.  Each is written as PNG and SVG.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

import instrument
from instrument import quadratic

from .fit import series
from .runs import REPLAY


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
