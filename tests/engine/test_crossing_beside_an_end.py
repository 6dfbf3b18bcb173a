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
