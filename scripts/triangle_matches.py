#!/usr/bin/env python
"""How many of the golden grid's cases give Triangle's own output.

For every input of tests/golden/make_golden.py (the `triangle` package's
samples, data/, and the shared corpus when RUPPERT_CORPUS names it) and each
of its switch strings under the default strategy, this runs the engine and
Triangle (the `triangle` package, in a child process: it can crash) and
counts the cases where

* ``count``: the vertex and triangle counts are Triangle's;
* ``mesh``: the vertices are Triangle's, bit for bit and in its order;
* ``order``: the triangles are Triangle's, row for row (corner order
  included), which happens only where ours keeps its triangles where
  Triangle keeps them in memory (its output order is its pool order).

Run it with another checkout's interpreter to compare two versions:

    RUPPERT_CORPUS=/work/shared/corpus python scripts/triangle_matches.py
    RUPPERT_CORPUS=/work/shared/corpus python scripts/triangle_matches.py --switches p pc pq30 --list

Slow-ish (each input is meshed twice per switch string): a few minutes with
the corpus.
"""

from __future__ import annotations

import argparse
import json
import pickle
import subprocess
import sys
from collections import Counter
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]

_CHILD = """
import pickle, sys
import numpy as np
import triangle
inp, sw = pickle.load(sys.stdin.buffer)
r = triangle.triangulate(inp, sw)
pickle.dump({k: np.asarray(v) for k, v in r.items()}, sys.stdout.buffer)
"""


def theirs(inp: dict, switches: str, timeout: float = 120) -> dict | None:
    try:
        p = subprocess.run([sys.executable, "-c", _CHILD], input=pickle.dumps((inp, switches)), capture_output=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return None
    return pickle.loads(p.stdout) if p.returncode == 0 else None


def verdicts(ours: dict, tri: dict) -> set[str]:
    """Which of count, mesh, order hold."""
    out = set()
    vo, vt = np.asarray(ours.get("vertices", ())), np.asarray(tri.get("vertices", ()))
    to = np.asarray(ours.get("triangles", np.zeros((0, 3), int)))
    tt = np.asarray(tri.get("triangles", np.zeros((0, 3), int)))
    if vo.shape == vt.shape and to.shape == tt.shape:
        out.add("count")
        if np.array_equal(vo, vt):
            out.add("mesh")
            if np.array_equal(to, tt):
                out.add("order")
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--switches", nargs="*", help="only these switch strings of the grid (default: all)")
    ap.add_argument("--list", action="store_true", help="name every case and its verdicts")
    ap.add_argument("--json", type=Path, help="write the verdicts per case here")
    args = ap.parse_args(argv)
    sys.path.insert(0, str(ROOT / "tests" / "golden"))
    import make_golden as grid  # the golden grid's inputs and switch strings

    import instrument

    tally: Counter = Counter()
    per_case = {}
    for name, path in sorted(grid.inputs().items()):
        try:
            inp = grid._read(Path(path))
        except ValueError:
            continue
        span = np.ptp(inp["vertices"], axis=0)
        area = f"{float(span[0] * span[1]) / 300:.3g}"
        for switches, strategy, steiner in grid.cases_for(name, Path(path)):
            if strategy != "triangle" or steiner != "offcenter" or (args.switches and switches not in args.switches):
                continue
            sw = switches.format(area=area) + "Q"
            tri = theirs(inp, sw)
            if tri is None:
                continue
            try:
                ours = instrument.triangulate(inp, sw)
            except Exception:  # an error where Triangle meshes: no match
                ours = {}
            v = verdicts(ours, tri)
            key = f"{name} | {switches}"
            per_case[key] = sorted(v)
            tally["cases"] += 1
            tally.update(v)
            if args.list:
                print(f"{key}: {' '.join(sorted(v)) or '-'}")
    print(f"{tally['cases']} cases: counts {tally['count']}, meshes (vertices) {tally['mesh']}, "
          f"triangle order {tally['order']}")
    if args.json:
        args.json.write_text(json.dumps(per_case, indent=1, sort_keys=True))
    return 0


if __name__ == "__main__":
    sys.exit(main())
