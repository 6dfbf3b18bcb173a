#!/usr/bin/env python
"""Refining meshes that carry an area bound per triangle: ours against Triangle.

Each of the `triangle` package's sample meshes (A.1, face.1, double_hex.1,
la.1, bbox.1) gets bounds per triangle (``triangle_max_area``, read under a
bare ``a``), a fraction of each triangle's area: one fraction for every
triangle, or one drawn per triangle, in turn.  Each is refined under
``ra``, ``rpq30a``, ``rpq25a`` and ``rpqa`` by ours and by Triangle, and
by Triangle again on the input's exact re-expressions
(tests/differential/reexpress.py).  The script prints ours' vertex count,
Triangle's, and its largest over the re-expressions, and counts the runs
where ours equals Triangle and those above the size rule (the largest plus
1 % or 2 vertices).  How the bounds travel through splits, flips and
rejected insertions decides which triangles are too large, so this is the
measure of that model (reconstruct/__init__.py).

    python scripts/area_bound_sweep.py [--trials 6] [--seed 7]
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
import triangle

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import instrument  # noqa: E402
from tests.differential.reexpress import KINDS, transformed  # noqa: E402

MESHES = ("A.1", "face.1", "double_hex.1", "la.1", "bbox.1")
SWITCHES = ("ra", "rpq30a", "rpq25a", "rpqa")
KEYS = ("vertices", "vertex_markers", "triangles", "segments", "segment_markers", "holes")


def with_bounds(name: str, trial: int, rng: np.random.Generator) -> dict:
    d = {k: np.asarray(v) for k, v in triangle.get_data(name).items() if k in KEYS and len(v)}
    p = d["vertices"][d["triangles"]]
    u, v = p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]
    area = 0.5 * np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
    fraction = rng.uniform(0.05, 0.6, len(area)) if trial % 2 else np.full(len(area), rng.uniform(0.1, 0.5))
    d["triangle_max_area"] = area * fraction
    return d


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trials", type=int, default=6)
    ap.add_argument("--seed", type=int, default=7)
    args = ap.parse_args()
    rng = np.random.default_rng(args.seed)
    runs = equal = over = 0
    print(f"{'mesh':<13} {'trial':>5} {'switches':<8} {'ours':>6} {'Triangle':>8} {'largest':>7}")
    for name in MESHES:
        for trial in range(args.trials):
            d = with_bounds(name, trial, rng)
            for sw in SWITCHES:
                ours = len(instrument.triangulate(d, sw)["vertices"])
                theirs = [len(triangle.triangulate(d if k is None else transformed(d, k), sw)["vertices"])
                          for k in (None,) + KINDS]
                above = ours > max(1.01 * max(theirs), max(theirs) + 2)
                runs += 1
                equal += ours == theirs[0]
                over += above
                print(f"{name:<13} {trial:>5} {sw:<8} {ours:>6} {theirs[0]:>8} {max(theirs):>7}"
                      + ("  above the size rule" if above else ""))
    print(f"{runs} runs: ours equals Triangle on {equal}, above the size rule on {over}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
