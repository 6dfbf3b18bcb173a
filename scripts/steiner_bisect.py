#!/usr/bin/env python
"""The first Steiner point where ours' refinement parts from Triangle's, by -S.

``scripts/queue_trace.py`` compares the two refinements' split sequences as
Triangle's ``-VVV`` prints them (``%.12g``), which cannot tell apart the
vertices of a cluster finer than that.  Here Triangle's and ours' meshes
under the case's switches with ``-Sk`` (at most k Steiner points) are
compared bit for bit (vertex coordinates and triangles as sets of corner
coordinates) and k is bisected between a k where they agree and one where
they do not; Triangle runs in a subprocess (it can crash).  For the first
k that differs the script prints the vertices and triangles of one mesh
only, and whether each mesh passes the exact checker (``check_mesh`` with
the Delaunay test): Triangle's refinement can pass through meshes that are
not constrained Delaunay, or folded, and later repair them, which ours does
not do (tests/differential/known.py's ``split-off-line-size``).

    python scripts/steiner_bisect.py tests/differential/regressions/crossing-bypass-refined-size.json
    python scripts/steiner_bisect.py CASE.json --low 300 --high 400

Bisection assumes one parting: meshes that agree at k agree below it.
"""

from __future__ import annotations

import argparse
import pickle
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

_TRIANGLE = r"""
import pickle, sys, triangle
inp, sw = pickle.load(sys.stdin.buffer)
sys.stdout.buffer.write(pickle.dumps(dict(triangle.triangulate(inp, sw))))
"""


def triangle_mesh(inp: dict, switches: str) -> dict:
    done = subprocess.run([sys.executable, "-c", _TRIANGLE], input=pickle.dumps((inp, switches)),
                          capture_output=True, timeout=120, check=True)
    return pickle.loads(done.stdout)


def shape(mesh: dict) -> tuple[set, set]:
    """The vertices (coordinate pairs) and triangles (sets of them) of a mesh."""
    v = mesh["vertices"]
    tris = mesh.get("triangles", ())
    return ({tuple(p) for p in v.tolist()},
            {frozenset(tuple(v[i]) for i in t) for t in getattr(tris, "tolist", lambda: tris)()})


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("case", type=Path, help="a differential case file")
    ap.add_argument("--switches", help="the switches (default: the case's)")
    ap.add_argument("--low", type=int, default=0, help="a Steiner budget where the meshes agree")
    ap.add_argument("--high", type=int, help="one where they differ (default: found by doubling)")
    args = ap.parse_args(argv)
    sys.path.insert(0, str(ROOT))
    import instrument
    from instrument.check import check_mesh
    from tests.differential.cases import read_case

    case, _ = read_case(args.case)
    inp = case.input
    base = (args.switches or case.switches).replace("Q", "")

    def meshes(k: int) -> tuple[dict, dict]:
        sw = f"{base}S{k}Q"
        return triangle_mesh(inp, sw), instrument.triangulate(inp, sw)

    def agree(k: int) -> bool:
        theirs, ours = meshes(k)
        return shape(theirs) == shape(ours)

    lo = args.low
    if not agree(lo):
        print(f"the meshes differ at -S{lo} already")
        return 1
    hi = args.high
    if hi is None:
        hi = max(2 * lo, 16)
        while agree(hi):
            if hi > 10**7:
                print("no parting found")
                return 0
            lo, hi = hi, 2 * hi
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if agree(mid):
            lo = mid
        else:
            hi = mid
    theirs, ours = meshes(hi)
    (tv, tt), (ov, ot) = shape(theirs), shape(ours)
    print(f"the same mesh through -S{lo}; they part at Steiner point {hi}")
    print("  Triangle's vertices only:", [tuple(repr(float(c)) for c in p) for p in sorted(tv - ov)])
    print("  ours' vertices only:     ", [tuple(repr(float(c)) for c in p) for p in sorted(ov - tv)])
    for name, only in (("Triangle's", tt - ot), ("ours'", ot - tt)):
        for t in sorted(sorted(x) for x in only):
            print(f"  {name} triangle only: {[tuple(repr(float(c)) for c in p) for p in t]}")
    pslg = inp if "p" in base else None
    for k in (lo, hi):
        theirs, ours = meshes(k)
        for name, mesh in (("Triangle", theirs), ("ours", ours)):
            problems = check_mesh(mesh, pslg=pslg, delaunay=True)
            print(f"  -S{k} {name}: {'valid' if not problems else problems[0]}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
