"""Triangle's meshes of many inputs, made in one subprocess (Triangle can
crash on the inputs these tests probe), and whether a mesh is folded."""

from __future__ import annotations

import pickle
import subprocess
import sys
from fractions import Fraction

import numpy as np

_TRIANGLE = r"""
import pickle, sys, triangle
runs = pickle.load(sys.stdin.buffer)
out = [triangle.triangulate(inp, sw) for inp, sw in runs]
sys.stdout.buffer.write(pickle.dumps([(r["vertices"], r.get("triangles", []), r.get("segments", [])) for r in out]))
"""


def triangle_meshes(runs: list[tuple[dict, str]]) -> list[tuple[np.ndarray, list, list]]:
    """(vertices, triangles, segments) of Triangle's mesh for each (input, switches)."""
    done = subprocess.run([sys.executable, "-c", _TRIANGLE], input=pickle.dumps(runs), capture_output=True,
                          timeout=120, check=True)
    return pickle.loads(done.stdout)


def folded(vertices, triangles) -> bool:
    """Has the mesh a triangle that is clockwise or flat (exact arithmetic)?"""
    w = [[Fraction(c) for c in p] for p in np.asarray(vertices).tolist()]

    def orient(a, b, c):
        return (w[b][0] - w[a][0]) * (w[c][1] - w[a][1]) - (w[b][1] - w[a][1]) * (w[c][0] - w[a][0])

    return any(orient(*t) <= 0 for t in np.asarray(triangles).tolist())
