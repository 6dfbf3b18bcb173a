"""Hole and region points exactly at an input vertex or on an input segment:
the inputs with each such point moved into one of the
triangles it touches, or, at a hull vertex (under ``i`` on a hull segment),
left out.

Which triangle point location returns for a point at a vertex follows the
walk, and Triangle's walk starts from triangles it samples at random: the
same polygon with a hole at one of its vertices eats the polygon or only a
triangle outside it depending on how many far-away points are appended to
the input (19 of 40 random star polygons under ``pQ`` changed their answer
over 0 to 5 appended points; docs/differential.md).  The same holds for a
point on a segment: after incremental insertion (``i``), and after divide
and conquer too (a 14-gon with a hole at the midpoint of one side, campaign
seed 2701, under ``pQ``: Triangle keeps 12, 0, 12, 0, 0, 0 triangles with 0
to 5 far-away points appended; ``regressions/hole-on-segment-divconq.json``).

A point is located at all only if it lies strictly left of the hull edge
Triangle's point location starts from; a point on that edge's line is
ignored.  Ours takes the edge leaving the least (x, y) vertex, where divide
and conquer leaves it, but in Triangle it moves during segment insertion:
in 40 random polygons with inner polygons, Triangle ignored a hole at the
two ends of one hull edge in each of 8 re-expressions, and that edge moved
in 9 polygons (with the segment list reversed in 4, every segment reversed
in 2, 1 to 3 far-away points appended in 6 to 7) and was another one than
ours' in all 8 in 2 more; for the vertices alone it was ours' in all 40
(``scripts/hole_start_edge.py``).  Under ``i`` it
moves with the vertex numbering too.  So for a point at a hull vertex
(under ``i`` also on a hull segment) Triangle's answer can also be that the
point is ignored.  ``regressions/hole-at-two-vertices.json`` needs it: one
hole at the triangle's least vertex, which Triangle ignores (in every
re-expression; so does ours), one at a vertex of the 8-gon inside, which
Triangle's walk puts outside the 8-gon (inside with one far point).

Triangle's answer for such points is therefore one of the answers for each
point moved into one of the triangles it touches or, on the hull, left out,
chosen for each point independently, and which one is not a function of the
geometry: ours is compared with Triangle's mesh of each moved input
(``harness.judge_outcomes``) and passes if it agrees with one of them in
every check.

Ours picks deterministically: the triangle through which its walk (from
the live triangle in the highest slot, turning by the mesh's seeded random
stream) first reaches the point (``instrument.carve``), and it ignores a
point on the line of the hull edge leaving the least (x, y) vertex.
"""

from __future__ import annotations

import itertools

import numpy as np

from instrument.check import orient_exact

from .cases import Case
from .oracles import read_switches

#: at most this many moved inputs per case (the product over the points;
#: two points at hull vertices with six triangles each make 49; three hole
#: points at the vertices of an inner pentagon with 4, 6 and 5 triangles
#: around them make 120, and the first placement Triangle's answer agrees
#: with was the 65th: regressions/holes-at-three-vertices.json, campaign
#: seed 2903).  Each costs one run of Triangle on a small input, and only
#: where ours and Triangle's own answer differ.
MAX_ALTERNATIVES = 256


def points_to_place(case: Case) -> list[tuple[str, int]]:
    """(key, row) of every hole or region point exactly at an input vertex
    or exactly on an input segment (``p`` without ``r``: only then are holes
    and regions located)."""
    sw = read_switches(case.switches)
    if not sw.p or sw.r:
        return []
    xy = np.asarray(case.input["vertices"], dtype=np.float64).reshape(-1, 2)
    v = {tuple(p) for p in xy.tolist()}
    segs = np.asarray(case.input.get("segments", np.zeros((0, 2))), dtype=np.int64).reshape(-1, 2)
    out = []
    for key in ("holes", "regions"):
        a = np.asarray(case.input.get(key, np.zeros((0, 2))), dtype=np.float64)
        for i, p in enumerate(a.reshape(-1, a.shape[-1] if a.ndim == 2 else 2).tolist() if a.size else []):
            q = (p[0], p[1])
            if q in v or any(_on_segment(xy, s, q) for s in np.asarray(segs).tolist()):
                out.append((key, i))
    return out


def _on_segment(xy: np.ndarray, seg, q) -> bool:
    a, b = seg
    if not (0 <= a < len(xy) and 0 <= b < len(xy)):
        return False
    u, w = xy[a].tolist(), xy[b].tolist()
    between = min(u[0], w[0]) <= q[0] <= max(u[0], w[0]) and min(u[1], w[1]) <= q[1] <= max(u[1], w[1])
    return between and orient_exact(u, w, list(q)) == 0


def cdt_switches(switches: str) -> str:
    """Triangle's switches for the constrained Delaunay triangulation the
    points are located in: ``p`` and ``c`` (given no holes and no regions,
    nothing is eaten), with the same triangulation method (``i``, ``l``)."""
    return "pc" + "".join(ch for ch in "il" if ch in switches) + "Q"


def _orients(xy: np.ndarray, tri, q) -> list[int]:
    a, b, c = (xy[k].tolist() for k in tri)
    return [orient_exact(a, b, q), orient_exact(b, c, q), orient_exact(c, a, q)]


def moved_into(xy: np.ndarray, triangles: np.ndarray, p) -> list[list[float]]:
    """A point strictly inside each triangle whose closed interior holds
    ``p`` (just off ``p``, towards the triangle's centroid)."""
    out = []
    q0 = [float(p[0]), float(p[1])]
    for t in range(len(triangles)):
        tri = triangles[t, :3].tolist()
        if min(_orients(xy, tri, q0)) < 0:
            continue
        centre = xy[tri].mean(axis=0)
        for step in (2.0**-20, 2.0**-10, 2.0**-4):
            q = (np.asarray(q0) + step * (centre - q0)).tolist()
            if min(_orients(xy, tri, q)) > 0:
                out.append(q)
                break
    return out


def hull_edges(triangles: np.ndarray) -> list[list[int]]:
    """The boundary edges of the triangulation (its convex hull), as vertex pairs."""
    t = triangles[:, :3]
    e = np.concatenate([t[:, [0, 1]], t[:, [1, 2]], t[:, [2, 0]]])
    key = np.sort(e, axis=1)
    uniq, count = np.unique(key, axis=0, return_counts=True)
    return uniq[count == 1].tolist()


def on_one_hull_line(xy: np.ndarray, hull: list[list[int]], points: list) -> bool:
    """Some hull edge's line passes through all of ``points``: the points
    Triangle ignores for lying on its start edge's line lie on one line."""
    if len(points) < 2:
        return True
    return any(all(orient_exact(xy[a].tolist(), xy[b].tolist(), [float(q[0]), float(q[1])]) == 0 for q in points)
               for a, b in hull)


def alternatives(case: Case, cdt: dict) -> list[Case]:
    """``case`` with its ``points_to_place`` moved, each into one of the
    triangles it touches in ``cdt`` (Triangle's ``cdt_switches`` mesh of the
    input), or, on the hull, also left out, in every combination (at most
    ``MAX_ALTERNATIVES``; leaving out comes first); without ``i`` the points
    left out together lie on the line of one hull edge."""
    at = points_to_place(case)
    if not at or not len(cdt.get("triangles", ())):
        return []
    incremental = read_switches(case.switches).i
    xy = np.asarray(cdt["vertices"], dtype=np.float64).reshape(-1, 2)
    triangles = np.asarray(cdt["triangles"], dtype=np.int64).reshape(len(cdt["triangles"]), -1)
    hull = hull_edges(triangles)
    points, choices = [], []
    for key, i in at:
        p = np.asarray(case.input[key], dtype=np.float64)[i, :2]
        moved = moved_into(xy, triangles, p)
        if any(_on_segment(xy, s, (float(p[0]), float(p[1]))) for s in hull):  # on the hull
            moved.insert(0, None)  # ignored when on the line of Triangle's start edge
        if not moved:
            return []
        points.append(p)
        choices.append(moved)
    # a point left out is put beyond the input's bounding box, where Triangle
    # ignores it silently (deleting it would drop the regions' attribute column)
    lo, hi = xy.min(axis=0), xy.max(axis=0)
    beyond = (hi + (hi - lo) + 1.0).tolist()
    combos = itertools.product(*choices)
    if not incremental:
        combos = (c for c in combos if on_one_hull_line(xy, hull, [p for p, q in zip(points, c) if q is None]))
    out = []
    for combo in itertools.islice(combos, MAX_ALTERNATIVES):
        inp = {k: np.array(v, copy=True) for k, v in case.input.items()}
        for (key, i), q in zip(at, combo):
            inp[key][i, :2] = beyond if q is None else q
        out.append(Case(family=case.family, switches=case.switches, input=inp, meta=dict(case.meta)))
    return out
