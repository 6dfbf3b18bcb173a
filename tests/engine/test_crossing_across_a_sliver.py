"""A crossing an ulp beside a subsegment's end that rounds across the side of a sliver.

Campaign seed 3101 (tests/differential/regressions/through-vertex-after-crossing-count.json):
segment S = (0.678, 0.501) -> (0.291, -0.497) passes exactly through E =
(0.4845, 0.00205), the end of segment Y from (0.125, 0.125).  S crosses
another segment first, and its piece from that rounded crossing passes E by
5e-18 and crosses Y just before E.  Triangle's crossing vertex s (x one ulp
below E's, y 32 ulps above) lies outside the two triangles beside Y: across
the side (V, E) of the sliver (Y's start, V, E), V = (0.125, 0.1248) being
1.8e-4 off Y's line.  Triangle splits Y at s all the same, which leaves the
triangle (s, V, E) clockwise, and its flips around s flip that side (the far
vertex (0, 0) is in that triangle's circle by the incircle test a clockwise
triangle reverses): the mesh is a valid one, with s inside the triangle
(E, V, (0, 0)).  Ours took E for the crossing there, where s does not split
Y cleanly (one vertex and two triangles fewer; under o2 81 nodes against
77), and now splits Y at s where Triangle's flips leave such a valid mesh
(core/insert.splits_after_a_flip).

Here V, E and S's far end move by k ulps under pQ and pcQ: ours' mesh passes
the exact checker, and wherever Triangle's own mesh is not folded ours'
vertices are Triangle's bit for bit and the triangle counts equal.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

import instrument
from instrument.check import check_mesh
from triangle_runs import folded, triangle_meshes

CASE = Path(__file__).parents[1] / "differential" / "regressions" / "through-vertex-after-crossing-count.json"
E, V, FAR = 15, 18, 17



def _case() -> dict:
    d = json.loads(CASE.read_text())["input"]
    v = np.array([float.fromhex(h) for h in d["vertices"]["hex"]]).reshape(d["vertices"]["shape"])
    s = np.array(d["segments"]["int"]).reshape(d["segments"]["shape"])
    return {"vertices": v, "segments": s}


def _moved(base: dict, vertex: int, coord: int, k: int) -> dict:
    v = base["vertices"].copy()
    v[vertex, coord] += k * np.spacing(v[vertex, coord])
    return {"vertices": v, "segments": base["segments"]}




def test_campaign_case_splits_beside_the_end():
    """Triangle's 23 vertices bit for bit (its crossing vertex beside E, not E)."""
    inp = _case()
    (t_vertices, t_triangles, _), = triangle_meshes([(inp, "pQ")])
    ours = instrument.triangulate(inp, "pQ")
    assert check_mesh(ours, pslg=inp) == []
    assert np.array_equal(ours["vertices"], t_vertices)
    assert len(ours["triangles"]) == len(t_triangles) == 37
    s = ours["vertices"][21]
    assert s[0] == np.nextafter(inp["vertices"][E, 0], 0) and s[1] > inp["vertices"][E, 1]
    o2 = instrument.triangulate(inp, "po2niQ")
    assert len(o2["vertices"]) == 81


def test_moved_by_ulps_keeps_triangles_vertices():
    base = _case()
    moves = [(V, 0, k) for k in range(-32, 33, 8)] + [(V, 1, k) for k in range(-32, 33, 8)]
    moves += [(FAR, c, k) for c in (0, 1) for k in range(-16, 17, 4)] + [(E, 0, k) for k in range(-8, 9, 2)]
    runs = [(_moved(base, *mv), sw) for mv in moves for sw in ("pQ", "pcQ")]
    compared = 0
    for (inp, sw), (t_vertices, t_triangles, _) in zip(runs, triangle_meshes(runs)):
        ours = instrument.triangulate(inp, sw)
        assert check_mesh(ours, pslg=inp) == []
        if folded(t_vertices, t_triangles):
            continue  # no reference
        compared += 1
        assert np.array_equal(ours["vertices"], t_vertices), sw
        assert len(ours["triangles"]) == len(t_triangles), sw
    assert compared >= len(runs) - 8
