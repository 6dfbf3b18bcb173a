#!/usr/bin/env python
"""Do ours' incremental records (-i) hold what Triangle's hold?

Triangle (the `triangle` package) prints under -VVVV every triangle record
its incremental method writes ("Creating triangle x...", "Updating top
triangle ...", "Edge flip results in ..."), with the record's address and
its three corners.  This script runs it in a subprocess, keeps the last
content of every record before "Removing triangular bounding box.", and
compares it with the same slot of ours after ``delaunay(method=
"incremental")`` (freed slots keep their corners): record i of Triangle is
the i-th it created (nothing is freed before the box goes), its corners
(v0, v1, v2) are ours (v1, v2, v0), and the box corners are ours n, n+1,
n+2.  It also compares the output triangle lists under iQ.

    python scripts/incremental_trace.py --random 500 --seed 3
    python scripts/incremental_trace.py --grid 40 --side 4     # duplicates, collinear, on-edge points
    python scripts/incremental_trace.py --node A.node

This is how delaunay/incremental.py's rules were read off (see its
docstring); Triangle's -VVVV output is large (about 1 kB per point).
"""

from __future__ import annotations

import argparse
import math
import pickle
import re
import subprocess
import sys
from functools import reduce

import numpy as np

_TRIANGLE = """
import pickle, sys, triangle
pts = pickle.load(sys.stdin.buffer)
out = triangle.triangulate({'vertices': pts}, 'iQVVVV')
sys.stdout.flush()
sys.stderr.buffer.write(pickle.dumps(out.get('triangles')))
"""

HEADER = re.compile(r"^  (Creating|Updating|Edge flip results in|and) .*?triangle x([0-9a-f]+) with orientation \d:$")
CORNER = re.compile(r"^    (?:Origin|Dest  |Apex  )\[(\d)\] = x([0-9a-f]+)  \(")


def triangle_trace(pts: np.ndarray) -> tuple[list, np.ndarray | None]:
    """Triangle's records before the box goes, as (address, {slot: vertex address})
    in order of writing, and its iQ triangles."""
    p = subprocess.run([sys.executable, "-c", _TRIANGLE], input=pickle.dumps(pts), capture_output=True, timeout=600)
    if p.returncode:
        raise RuntimeError(f"triangle failed: {p.stderr[-300:]!r}")
    text = p.stdout.decode().split("Removing triangular bounding box.")[0]
    writes, current = [], None
    for line in text.splitlines():
        h = HEADER.match(line)
        if h:
            current = (h.group(1), int(h.group(2), 16), {})
            writes.append(current)
            continue
        c = CORNER.match(line)
        if c and current is not None:
            current[2][int(c.group(1)) - 3] = int(c.group(2), 16)
    return writes, pickle.loads(p.stderr[p.stderr.index(b"\x80") :])


def triangle_records(writes: list, n: int) -> np.ndarray:
    """Each record's last corners, in our numbering and our corner order."""
    slot: dict[int, int] = {}
    for kind, addr, _ in writes:
        if kind == "Creating" and addr not in slot:
            slot[addr] = len(slot)
    box = writes[0][2]  # the bounding triangle, orientation 0: v1 = B1, v2 = B2, v0 = B3
    vid = {box[1]: n, box[2]: n + 1, box[0]: n + 2}
    real = sorted({a for _, _, v in writes for a in v.values() if a not in vid})
    size = reduce(math.gcd, (b - a for a, b in zip(real, real[1:])), 0) or 1
    rec = np.full((len(slot), 3), -1, dtype=np.int64)
    for _, addr, v in writes:
        ids = [vid[v[k]] if v[k] in vid else (v[k] - real[0]) // size for k in range(3)]
        rec[slot[addr]] = (ids[1], ids[2], ids[0])
    return rec


def ours(pts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Ours' records after the incremental stage, and its iQ triangles."""
    import instrument
    from instrument.counters import new_work
    from instrument.delaunay import delaunay

    m = delaunay(pts, new_work(), method="incremental")[0]
    rec = np.asarray(m.corner)[: 3 * m.nslot].reshape(-1, 3).astype(np.int64)
    return rec, instrument.triangulate({"vertices": pts}, "iQ").get("triangles", np.zeros((0, 3), np.int32))


def compare(pts: np.ndarray, verbose: bool = False) -> bool:
    writes, theirs_out = triangle_trace(pts)
    theirs = triangle_records(writes, len(pts))
    mine, mine_out = ours(pts)
    same = theirs.shape == mine.shape and (theirs == mine).all()
    theirs_out = np.zeros((0, 3), np.int32) if theirs_out is None else theirs_out
    same_out = theirs_out.shape == mine_out.shape and (theirs_out == mine_out).all()
    if verbose or not (same and same_out):
        print(f"  {len(pts)} points: records {'equal' if same else 'DIFFER'} ({len(theirs)} Triangle, {len(mine)} ours), "
              f"output {'equal' if same_out else 'DIFFERS'}")
        if not same:
            k = next((i for i in range(min(len(theirs), len(mine))) if (theirs[i] != mine[i]).any()), None)
            if k is not None:
                print(f"  first differing record {k}: Triangle {theirs[k].tolist()}, ours {mine[k].tolist()}")
    return same and same_out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--random", type=int, help="random points in the unit square, this many")
    ap.add_argument("--grid", type=int, help="points of an integer grid (with duplicates), this many")
    ap.add_argument("--side", type=int, default=4, help="the grid's side (default 4)")
    ap.add_argument("--node", help="a .node or .poly file (its vertices)")
    ap.add_argument("--seed", type=int, default=0)
    ap.add_argument("--runs", type=int, default=1, help="inputs to draw (seeds seed, seed+1, ...)")
    a = ap.parse_args()
    good = 0
    for run in range(a.runs):
        rng = np.random.default_rng(a.seed + run)
        if a.node:
            import ruppert_io

            pts = np.asarray(ruppert_io.read(a.node)["vertices"], dtype=float)
        elif a.grid:
            pts = rng.integers(0, a.side, (a.grid, 2)).astype(float)
        else:
            pts = rng.random((a.random or 100, 2))
        print(f"input {run + 1} (seed {a.seed + run}):")
        good += compare(pts, verbose=True)
    print(f"{good} of {a.runs} agree")


if __name__ == "__main__":
    main()
