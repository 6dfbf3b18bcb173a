"""A segment passing within a few ulps of another segment's end: Triangle's crossing.

Triangle's rule (scripts/crossing_beside_an_end.py, docs/differential.md):
an end exactly on the segment is a vertex of it; a segment that misses the
other one (the end on the far side) makes no vertex; one that crosses it,
however near the end, makes a vertex at Triangle's doubles point, beside
the end or, where that point is the end itself, a second copy of the end.
Here segment S2 passes k = -3..3 ulps beside the end E of S1, in random
directions at three scales, inside a box, under ``pcQ``: ours' vertices are
Triangle's bit for bit (a copy included, unused by ours' triangles), and
ours' mesh passes the checker.  The regressions of the harness
(tests/differential/regressions/crossing-beside-an-end-*.json) hold the
cases that found the rule.
"""

from __future__ import annotations

import pickle
import subprocess
import sys
from fractions import Fraction

import numpy as np

import instrument
from instrument.check import check_mesh

_TRIANGLE = r"""
import pickle, sys, triangle
runs = pickle.load(sys.stdin.buffer)
sys.stdout.buffer.write(pickle.dumps([triangle.triangulate(inp, sw)["vertices"] for inp, sw in runs]))
"""


def _inputs(seed: int = 31) -> list[dict]:
    rng = np.random.default_rng(seed)
    out = []
    for scale in (2.0**-20, 1.0, 2.0**20):
        for k in range(-3, 4):
            for _ in range(2):
                e = np.array([rng.uniform(0.3, 0.7), rng.uniform(0.3, 0.7)])
                ang = rng.uniform(0.2, 1.3)
                f = e + 0.25 * np.array([-np.cos(ang), np.sin(ang)])
                ang2 = rng.uniform(-0.6, 0.6)
                d = np.array([np.sin(ang2), np.cos(ang2)])
                g = e + np.array([k * np.spacing(e[0]), 0.0]) - 0.3 * d
                h = e + np.array([k * np.spacing(e[0]), 0.0]) + 0.3 * d
                box = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]])
                out.append({"vertices": np.vstack([e, f, g, h, box]) * scale,
                            "segments": np.array([[0, 1], [2, 3]], dtype=np.int32)})
    return out


def test_crossings_beside_an_end_are_triangles():
    inputs = _inputs()
    done = subprocess.run([sys.executable, "-c", _TRIANGLE], input=pickle.dumps([(i, "pcQ") for i in inputs]),
                          capture_output=True, timeout=120, check=True)
    theirs = pickle.loads(done.stdout)
    kinds = set()
    for inp, t_vertices in zip(inputs, theirs):
        ours = instrument.triangulate(inp, "pcQ")
        assert check_mesh(ours, pslg=inp) == []
        assert np.array_equal(ours["vertices"], t_vertices), (inp["vertices"][:4].tolist(), t_vertices[8:].tolist())
        extra = t_vertices[8:]
        kinds.add("none" if not len(extra) else "copy" if (extra == inp["vertices"][0]).all(axis=1).any() else "beside")
    assert kinds == {"none", "beside", "copy"}  # every outcome of the rule is met


# Campaign seed 3031, shrunk (regressions/crossing-beside-an-end-fold.json):
# segment S crosses the crossing-split segment D = E..C one ulp beside its
# input end E, where Triangle's point P (E's x less one ulp) rounds across
# D's line past vertex V, which lies within rounding of that line; in a box
# so that triangles stay.
_POCKET = [
    ("0x1.b7cdfd9d7bdbbp-34", "0x1.b7cdfd9d7bdbbp-34"),  # V
    ("0x1.49cb07f8325b7p-33", "0x1.ccf32718618f8p-34"),  # E
    ("0x1.b80bd69526012p-35", "0x1.a2a8d4229627ep-34"),  # D's other end
    ("0x1.920249d1f336dp-44", "0x1.aaab237f9802fp-34"),  # the segment that crosses D first, at C
    ("0x1.8df1b9a3f7acdp-34", "0x1.aaab237f9802fp-34"),
    ("0x1.b77d4c8a5bdeep-33", "0x1.546c1b8fb1162p-33"),  # S
    ("0x1.b83186cc11affp-34", "0x1.e21c2e22c1e5bp-35"),
]


def test_crossing_beside_an_end_past_a_pocket_vertex():
    """Triangle's flips for S leave a pocket (an inverted triangle at V)
    that waits for a vertex on S; the vertex that comes, P, splits C..E but
    lies on V's side of it, and V ends on the far side of C..P: Triangle's
    mesh is folded (its triangle (C, P, V) is clockwise).  Ours takes E for
    the crossing, decided before the flips (recover._beside_splits): S goes
    through E, and the mesh is valid."""
    s = 2.0**-30
    vertices = np.vstack([[[float.fromhex(x), float.fromhex(y)] for x, y in _POCKET],
                          [[-s, -s], [s, -s], [s, s], [-s, s]]])
    inp = {"vertices": vertices,
           "segments": np.array([[1, 2], [3, 4], [5, 6], [7, 8], [8, 9], [9, 10], [10, 7]], dtype=np.int32)}
    ours = instrument.triangulate(inp, "pQ")
    assert check_mesh(ours, pslg=inp) == []
    assert len(ours["vertices"]) == 12  # the input and C: S goes through E
    done = subprocess.run([sys.executable, "-c", _TRIANGLE_MESH], input=pickle.dumps(inp), capture_output=True,
                          timeout=60, check=True)
    t_vertices, t_triangles = pickle.loads(done.stdout)
    assert len(t_vertices) == 13  # C and P
    w = [[Fraction(c) for c in p] for p in t_vertices]

    def orient(a, b, c):
        return (w[b][0] - w[a][0]) * (w[c][1] - w[a][1]) - (w[b][1] - w[a][1]) * (w[c][0] - w[a][0])

    assert sum(orient(*t) <= 0 for t in t_triangles.tolist()) == 1  # Triangle's fold


_TRIANGLE_MESH = r"""
import pickle, sys, triangle
out = triangle.triangulate(pickle.load(sys.stdin.buffer), "pQ")
sys.stdout.buffer.write(pickle.dumps((out["vertices"], out["triangles"])))
"""
