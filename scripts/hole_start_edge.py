#!/usr/bin/env python
"""At which hull vertices does Triangle ignore a hole point, and does that move?

Triangle locates a hole (or region) point only if it lies strictly left of
the hull edge its outer-space handle points at; a point on that edge's line
is ignored.  Ours takes that edge to be the counter-clockwise hull edge
leaving the least (x, y) vertex, where divide and conquer leaves it.  This
script measures, on the `triangle` package, which hull vertices Triangle
ignores a hole at, for random polygons with inner polygons (as the
differential family polygon-holes draws them) and for re-expressions of each
that change no geometry: ring numbering rotated, segment list reversed,
every segment reversed, far-away points (10, 10), (11, 13), ... appended.

A probe runs under ``pcQ`` (the hull is closed by segments, so nothing is
eaten from outside): a hole at a hull vertex that is located eats at least
the triangle it lands in; one that is ignored leaves the mesh as it is.
Under ``pQ`` each ignored vertex is checked to leave the mesh as it is too.

    python scripts/hole_start_edge.py                  # 40 polygons, seed 7
    python scripts/hole_start_edge.py --polygons 100 --seed 3 --verbose
    python scripts/hole_start_edge.py --regression     # the two holes of regressions/hole-at-two-vertices.json
    python scripts/hole_start_edge.py --pairs pQ       # two holes at two vertices, 12 pairs per polygon
    python scripts/hole_start_edge.py --without-segments   # the same vertices without their segments

``--pairs`` asks whether Triangle's mesh for two hole points at two vertices
is its mesh for some combination of choices made for each point alone:
moved just inside one of the triangles it touches (in Triangle's ``pc``
mesh) or, at a hull vertex, left out (moved beyond the bounding box), the
points left out together lying on one hull edge's line; and how often the
order in which the two are listed changes the mesh.

Triangle runs in child processes (it can crash the interpreter).
"""

from __future__ import annotations

import argparse
import math
import pickle
import subprocess
import sys
from collections import Counter
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]

_WORKER = r"""
import pickle, sys
import triangle
out = []
for inp, sw in pickle.load(sys.stdin.buffer):
    r = triangle.triangulate(inp, sw)
    out.append((r["vertices"], r.get("triangles")))
pickle.dump(out, sys.stdout.buffer)
"""


def run_triangle(jobs: list) -> list | None:
    """Triangle's (vertices, triangles) for each (input, switches), or None if it crashed."""
    p = subprocess.run([sys.executable, "-c", _WORKER], input=pickle.dumps(jobs), capture_output=True, timeout=600)
    return pickle.loads(p.stdout) if p.returncode == 0 else None


def kept(out) -> frozenset:
    """A mesh as a set of triangles, each a set of corner coordinates."""
    xy, tris = out
    if tris is None:
        return frozenset()
    xy = np.asarray(xy)
    return frozenset(frozenset(map(tuple, xy[t].tolist())) for t in np.asarray(tris).tolist())


def orient(a, b, c) -> int:
    from fractions import Fraction as F

    a, b, c = ([F(float(v)) for v in p] for p in (a, b, c))
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def hull_edges(tris) -> list[tuple[int, int]]:
    t = np.asarray(tris)
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]]).tolist()
    s = set(map(tuple, e))
    return [(a, b) for a, b in e if (b, a) not in s]


def dc_start_edge(xy, tris) -> tuple[int, int]:
    """The counter-clockwise hull edge leaving the least (x, y) vertex (ours' rule)."""
    used = sorted(set(np.asarray(tris).ravel().tolist()), key=lambda v: (xy[v, 0], xy[v, 1]))
    return next((a, b) for a, b in hull_edges(tris) if a == used[0])


# ------------------------------------------------------------------ inputs


def _star(rng, c, rmin, rmax, nmin, nmax):
    n = int(rng.integers(nmin, nmax + 1))
    ang = np.sort(rng.uniform(0, 2 * math.pi, n))
    r = rng.uniform(rmin, rmax, n)
    return [(c[0] + r[i] * math.cos(ang[i]), c[1] + r[i] * math.sin(ang[i])) for i in range(n)]


def _ring(first, n):
    return [(first + i, first + (i + 1) % n) for i in range(n)]


def polygon(rng) -> dict:
    """An outer star-shaped polygon and one or two inner ones, all bounded by
    segments (inner ones may poke out of a sparse outer one)."""
    r_out = float(rng.choice([0.3, 0.4, 0.5]))
    pts = _star(rng, (0.5, 0.5), 0.6 * r_out, r_out, 3, 12)
    segs = _ring(0, len(pts))
    nh = int(rng.integers(1, 3))
    r_in = 0.6 * r_out
    for h in range(nh):
        a = 2 * math.pi * h / nh
        c = (0.5 + 0.55 * r_in * math.cos(a), 0.5 + 0.55 * r_in * math.sin(a)) if nh > 1 else (0.5, 0.5)
        inner = _star(rng, c, 0.1 * r_in, 0.3 * r_in, 3, 8)
        segs += _ring(len(pts), len(inner))
        pts += inner
    return {"vertices": np.array(pts, float), "segments": np.array(segs, np.int32)}


def rotated(inp: dict, r: int) -> dict:
    """Each ring's vertex numbering rotated by r (same geometry)."""
    xy, segs = np.asarray(inp["vertices"]), np.asarray(inp["segments"])
    perm, start = np.arange(len(xy)), 0
    for a, b in segs.tolist():
        if b < a:  # the segment closing ring start..a
            n = a - start + 1
            perm[start:a + 1] = start + (np.arange(n) + r) % n
            start = a + 1
    inv = np.empty_like(perm)
    inv[perm] = np.arange(len(perm))
    return {"vertices": xy[perm], "segments": inv[segs].astype(np.int32)}


def variants(inp: dict):
    segs = np.asarray(inp["segments"])
    far = np.array([(10.0 + k, 10.0 + 3 * k) for k in range(3)])
    yield "as given", inp
    yield "ring numbering +1", rotated(inp, 1)
    yield "ring numbering +2", rotated(inp, 2)
    yield "segment list reversed", dict(inp, segments=segs[::-1].copy())
    yield "every segment reversed", dict(inp, segments=segs[:, ::-1].copy())
    for k in (1, 2, 3):
        yield f"{k} far point{'s' if k > 1 else ''}", dict(inp, vertices=np.vstack([inp["vertices"], far[:k]]))


def ignored_hull_vertices(inp: dict) -> tuple[set, set, bool] | None:
    """(coordinates of the hull vertices Triangle ignores a hole at (pcQ),
    the ends of ours' start edge, whether pQ agrees), or None on a crash."""
    cd = run_triangle([(inp, "pcQ"), (inp, "pQ")])
    if cd is None:
        return None
    (cxy, ctris), bare = cd
    cxy = np.asarray(cxy)
    hull_v = sorted({a for a, _ in hull_edges(ctris)})
    jobs = [(dict(inp, holes=cxy[v:v + 1].copy()), sw) for v in hull_v for sw in ("pcQ", "pQ")]
    res = run_triangle(jobs)
    if res is None:
        return None
    ign, pq_agrees = set(), True
    for k, v in enumerate(hull_v):
        c_out, p_out = res[2 * k], res[2 * k + 1]
        if c_out[1] is not None and len(c_out[1]) == len(ctris):
            ign.add(tuple(cxy[v].tolist()))
            pq_agrees &= kept(p_out) == kept(bare)
    se = dc_start_edge(cxy, ctris)
    return ign, {tuple(cxy[v].tolist()) for v in se}, pq_agrees


def survey(n_polygons: int, seed: int, verbose: bool) -> None:
    rng = np.random.default_rng(seed)
    tally = Counter()
    moved_by = Counter()
    for case in range(n_polygons):
        base = polygon(rng)
        seen, rule_ok, crashed = {}, True, False
        for name, inp in variants(base):
            got = ignored_hull_vertices(inp)
            if got is None:
                crashed = True
                break
            ign, ours, pq_agrees = got
            seen[name] = frozenset(ign)
            tally["probes"] += 1
            tally["ignored pair is one hull edge's ends"] += len(ign) == 2
            tally["pQ leaves the mesh whole at every ignored vertex"] += pq_agrees
            tally["ours' rule names the ignored pair"] += ign == ours
            rule_ok &= ign == ours
            if verbose:
                fmt = lambda s: sorted((round(x, 4), round(y, 4)) for x, y in s)  # noqa: E731
                print(f"polygon {case:3d} {name:24s} Triangle ignores {fmt(ign)}; ours' rule {fmt(ours)}")
        if crashed:
            tally["polygons Triangle crashed on"] += 1
            continue
        tally["polygons"] += 1
        tally["polygons where ours' rule always holds"] += rule_ok
        if len(set(seen.values())) > 1:
            tally["polygons whose ignored pair moves"] += 1
            for name, s in seen.items():
                moved_by[name] += s != seen["as given"]
    print(f"{n_polygons} polygons, seed {seed}, {len(list(variants(polygon(np.random.default_rng(0)))))} variants each")
    for k, v in tally.items():
        print(f"  {k}: {v}")
    print("  the pair differs from the input as given's under:", dict(moved_by))


def without_segments(n_polygons: int, seed: int) -> None:
    """The ignored pair for the vertices alone against the PSLG's: does segment insertion move it?"""
    rng = np.random.default_rng(seed)
    tally = Counter()
    for _ in range(n_polygons):
        base = polygon(rng)
        alone, pslg = ignored_hull_vertices({"vertices": base["vertices"]}), ignored_hull_vertices(base)
        if alone is None or pslg is None:
            tally["polygons Triangle crashed on"] += 1
            continue
        tally["polygons"] += 1
        tally["vertices alone: ours' rule names the ignored pair"] += alone[0] == alone[1]
        tally["with the segments: the ignored pair is another"] += pslg[0] != alone[0]
    print(f"{n_polygons} polygons, seed {seed}:")
    for k, v in tally.items():
        print(f"  {k}: {v}")


def touching(xy: np.ndarray, tris, p) -> list[np.ndarray]:
    """A point just inside each triangle whose closed interior holds ``p``."""
    out = []
    for tri in np.asarray(tris).tolist():
        a, b, c = (xy[k] for k in tri)
        if min(orient(a, b, p), orient(b, c, p), orient(c, a, p)) < 0:
            continue
        for step in (2.0**-20, 2.0**-10, 2.0**-4):
            q = np.asarray(p) + step * (xy[tri].mean(axis=0) - np.asarray(p))
            if min(orient(a, b, q), orient(b, c, q), orient(c, a, q)) > 0:
                out.append(q)
                break
    return out


def pairs(n_polygons: int, seed: int, switches: str) -> None:
    import itertools

    rng = np.random.default_rng(seed)
    tally = Counter()
    for _ in range(n_polygons):
        base = polygon(rng)
        xy = base["vertices"]
        cd = run_triangle([(base, switches.replace("Q", "cQ"))])
        if cd is None:
            tally["polygons Triangle crashed on"] += 1
            continue
        cxy, ctris = np.asarray(cd[0][0]), cd[0][1]
        hull = hull_edges(ctris)
        hull_v = {a for a, _ in hull}
        beyond = xy.max(axis=0) + (xy.max(axis=0) - xy.min(axis=0)) + 1.0
        candidates = list(itertools.combinations(range(len(xy)), 2))
        rng.shuffle(candidates)
        for a, b in candidates[:12]:
            choices = [([None] if v in hull_v else []) + touching(cxy, ctris, xy[v]) for v in (a, b)]
            # the points left out together lie on one hull edge's line
            one_line = any(orient(cxy[e], cxy[f], xy[a]) == 0 == orient(cxy[e], cxy[f], xy[b]) for e, f in hull)
            combos = [c for c in itertools.product(*choices) if one_line or sum(q is None for q in c) < 2]
            moved_both = [all(q is not None for q in c) for c in combos]
            holes = xy[[a, b]].copy()
            jobs = [(dict(base, holes=holes), switches), (dict(base, holes=holes[::-1].copy()), switches)]
            jobs += [(dict(base, holes=np.array([beyond if q is None else q for q in c])), switches) for c in combos]
            res = run_triangle(jobs)
            if res is None:
                tally["pairs Triangle crashed on"] += 1
                continue
            meshes = [kept(r) for r in res]
            explained = set(meshes[2:])
            moved_only = {m for both, m in zip(moved_both, meshes[2:]) if both}
            tally["pairs"] += 1
            tally["pairs with a hull vertex"] += (a in hull_v) or (b in hull_v)
            tally["explained (as listed)"] += meshes[0] in explained
            tally["explained (listed the other way round)"] += meshes[1] in explained
            tally["explained by moving both, none left out"] += meshes[0] in moved_only
            tally["the order changes the mesh"] += meshes[0] != meshes[1]
    print(f"{n_polygons} polygons, seed {seed}, {switches}:")
    for k, v in tally.items():
        print(f"  {k}: {v}")


def regression() -> None:
    """The two holes of regressions/hole-at-two-vertices.json, moved by 1e-9."""
    sys.path.insert(0, str(ROOT))
    from tests.differential.cases import read_case

    case, _ = read_case(ROOT / "tests/differential/regressions/hole-at-two-vertices.json")
    inp = {k: np.asarray(v) for k, v in case.input.items()}
    xy, (a, b) = inp["vertices"], inp["holes"]
    interior = {frozenset(map(tuple, xy[list(t)].tolist())) for t in
                [(6, 7, 3), (3, 5, 6), (3, 7, 8), (9, 10, 3), (4, 5, 3), (3, 8, 9)]}
    dirs = [(math.cos(k * math.pi / 8), math.sin(k * math.pi / 8)) for k in range(16)]
    a_in = a + 1e-9 * np.array([-0.71, -0.71])  # inside the 8-gon's triangle (4, 5, 3)
    far = np.array([(10.0 + k, 10.0 + 3 * k) for k in range(5)])
    rows = [("both at their vertices", [a, b], None), ("A (vertex 4) alone", [a], None), ("B (vertex 1) alone", [b], None),
            ("B listed first", [b, a], None), ("A inside (4, 5, 3), B at vertex 1", [a_in, b], None)]
    rows += [(f"both, {k} far point(s) appended", [a, b], far[:k]) for k in range(1, 6)]
    rows += [(f"A moved by 1e-9 ({dx:+.2f}, {dy:+.2f})", [a + 1e-9 * np.array([dx, dy]), b], None) for dx, dy in dirs]
    rows += [(f"A inside, B moved by 1e-9 ({dx:+.2f}, {dy:+.2f})", [a_in, b + 1e-9 * np.array([dx, dy])], None)
             for dx, dy in dirs]
    jobs = []
    for _, holes, extra in rows:
        d = dict(inp, holes=np.array(holes))
        if extra is not None:
            d["vertices"] = np.vstack([xy, extra])
        jobs.append((d, "pQ"))
    res = run_triangle(jobs)
    for (name, _, _), out in zip(rows, res):
        k = kept(out)
        print(f"{name:42s} {len(k):2d} triangles: 8-gon {len(k & interior)}/6, between the two {len(k - interior)}/11")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--polygons", type=int, default=40)
    ap.add_argument("--seed", type=int, default=7)
    ap.add_argument("--verbose", action="store_true")
    ap.add_argument("--regression", action="store_true")
    ap.add_argument("--pairs", metavar="SWITCHES")
    ap.add_argument("--without-segments", action="store_true")
    args = ap.parse_args()
    if args.regression:
        regression()
    elif args.without_segments:
        without_segments(args.polygons, args.seed)
    elif args.pairs:
        pairs(args.polygons, args.seed, args.pairs)
    else:
        survey(args.polygons, args.seed, args.verbose)


if __name__ == "__main__":
    main()
