#!/usr/bin/env python
"""Where Triangle puts the crossing of a segment that passes within a few
ulps of another segment's endpoint, and whether ours puts it there too.

Segment S1 runs from its end E to F; segment S2, inserted second, is S2's
line shifted by k units in the last place of E's x (k = -3..3, before
rounding its ends), so it passes 0..3 ulps beside E, on either side, at
scales 2^-1000..2^1000, in random directions.  Each input is meshed under
``pcQ`` by Triangle (the `triangle` package, one process per input: it can
crash) and by ours, and the vertices beyond the input's (the crossing
vertices) are compared, with the rule read off Triangle's output:

* exactly on S2's line (orient2d = 0), E is a vertex of S2: no new vertex;
* S2 passes E on the side where the segments do not meet: no new vertex;
* otherwise the segments cross, however near E: Triangle adds a vertex at
  its doubles point r + t (l - r) along S1 (``segments/crossing.py``'s
  ``scouted_crossing``, t from S2's far end), one or two ulps beside E or,
  where t rounds to 0 or 1, at E's very coordinates: the point is output
  twice.

Each input is tallied under what Triangle did (``on``: no vertex, E on S2;
``miss``; ``beside``: a vertex of its own beside E; ``copy``: a vertex at
E's coordinates) and whether ours' vertices are Triangle's bit for bit.

    python scripts/crossing_beside_an_end.py              # 7 scales x 7 offsets x 6 directions
    python scripts/crossing_beside_an_end.py --directions 20 -v
"""

from __future__ import annotations

import argparse
import pickle
import subprocess
import sys
from collections import Counter
from fractions import Fraction

import numpy as np

import instrument

_TRIANGLE = r"""
import pickle, sys, triangle
inp, sw = pickle.load(sys.stdin.buffer)
out = triangle.triangulate(inp, sw)
sys.stdout.buffer.write(pickle.dumps({k: v for k, v in out.items()}))
"""


def triangle_run(inp: dict, switches: str) -> dict | None:
    """Triangle's output in a child process (None if it crashed or hung)."""
    try:
        p = subprocess.run([sys.executable, "-c", _TRIANGLE], input=pickle.dumps((inp, switches)),
                           capture_output=True, timeout=30)
    except subprocess.TimeoutExpired:
        return None
    return pickle.loads(p.stdout) if p.returncode == 0 else None


def orient(a, b, c) -> Fraction:
    a, b, c = ([Fraction(x) for x in p] for p in (a, b, c))
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def make_input(rng, scale_exp: int, k: int) -> dict:
    """E, F (S1 = E F) and G, H (S2), S2's line k ulps of E's x beside E."""
    s = 2.0**scale_exp
    e = np.array([rng.uniform(0.3, 0.7), rng.uniform(0.3, 0.7)])
    ang = rng.uniform(0.2, 1.3)  # S1 leaves E up and to the left
    f = e + 0.25 * np.array([-np.cos(ang), np.sin(ang)])
    ang2 = rng.uniform(-0.6, 0.6)  # S2: roughly vertical, across S1's start
    d = np.array([np.sin(ang2), np.cos(ang2)])
    shift = k * np.spacing(e[0])
    g = e + np.array([shift, 0.0]) - 0.3 * d
    h = e + np.array([shift, 0.0]) + 0.3 * d
    pts = np.array([e, f, g, h]) * s
    # the box around them, so that pcQ keeps a mesh
    box = np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]) * s
    return {"vertices": np.vstack([pts, box]), "segments": np.array([[0, 1], [2, 3]], dtype=np.int32)}


def kind_of(inp: dict, tri: dict) -> str:
    """What Triangle did (see the module's text)."""
    v = inp["vertices"]
    extra = tri["vertices"][len(v):]
    if len(extra) == 0:
        return "on" if orient(v[2], v[3], v[0]) == 0 else "miss"
    if any((p == v[0]).all() for p in extra):
        return "copy"
    return "beside"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--directions", type=int, default=6, help="random directions per scale and offset")
    ap.add_argument("--seed", type=int, default=30)
    ap.add_argument("-v", "--verbose", action="store_true")
    args = ap.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    tally: Counter = Counter()
    for scale_exp in (-1000, -500, -20, 0, 20, 500, 1000):
        for k in range(-3, 4):
            for _ in range(args.directions):
                inp = make_input(rng, scale_exp, k)
                tri = triangle_run(inp, "pcQ")
                if tri is None:
                    tally[(f"2^{scale_exp}", "triangle crashed")] += 1
                    continue
                kind = kind_of(inp, tri)
                try:
                    ours = instrument.triangulate(inp, "pcQ")
                except instrument.TriangleError as exc:
                    tally[(f"2^{scale_exp}", kind, "ours raised")] += 1
                    if args.verbose:
                        print(scale_exp, k, kind, "ours raised", exc)
                    continue
                n = len(inp["vertices"])
                same = np.array_equal(tri["vertices"], ours["vertices"])
                tally[(f"2^{scale_exp}", kind, "same vertices" if same else "other vertices")] += 1
                if args.verbose and not same:
                    pickle.dump(inp, open(f"/tmp/beside-{scale_exp}-{k}.pkl", "wb"))
                    print(scale_exp, k, kind, [p.hex() for p in tri["vertices"][n:].ravel()],
                          [p.hex() for p in ours["vertices"][n:].ravel()])
    for key, count in sorted(tally.items(), key=str):
        print(f"{key}: {count}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
